"""A satellite's power-law migration drives the precession constant: the law, the axis, the CLI.

Independent computations: the figure ratio from the catalogue's ``J2``, ``λ`` and Titan's mass and
orbit written out here (Ward & Hamilton 2004's ring terms); ``scipy.integrate.quad`` of ``α(t)``
for the node on a fixed orbit; scipy's DOP853 on ``ṡ = α(t)(s·n)(s×n)`` through a resonance.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp
from spin_cases import FixedOrbit, PrecessingOrbit

from andoyer import catalogue
from andoyer.planetary.migration import MigratingSpinAxisModel, satellite_migration
from andoyer.planetary.precession_constant import obliquity
from andoyer.planetary.spin_axis import SpinAxisModel, spin_axis_history

#: Titan's rate (Lainey et al. 2020, 11.3 cm/yr), Titan's catalogued a and the solar system's age
#: (Connelly et al. 2012, 4567.30 Myr): b = ȧ T0 / a.
TITAN_INDEX = 0.113 * 4.5673e9 / 1221900e3


def _titan_ratio(x):
    """α(x)/α(1) for Saturn with Titan at x times its a: Titan's q ∝ a², l ∝ a²n ∝ √a, Enceladus fixed."""
    saturn, titan, enceladus = (catalogue.get(n) for n in ("saturn", "titan", "enceladus"))
    M, R = saturn.gm.si(), saturn.radius.si()
    omega = 2 * math.pi / saturn.rotation_period.si()
    eps = obliquity("saturn")  # the IAU pole to the orbit (tested in test_spin_axis_planets)

    def ring(moon, scale):
        m, a = moon.gm.si(), moon.semi_major_axis.si() * scale
        tilt = 0.0 if moon.laplace_tilt is None else moon.laplace_tilt.si()
        i = moon.inclination.si()
        size = m / M * (a / R) ** 2
        q = 0.5 * size * (1.5 * math.cos(i) ** 2 - 0.5) * math.sin(2 * (eps - tilt)) / math.sin(2 * eps)
        n = math.sqrt((M + m) / a**3)
        l = size * n / omega * math.cos(i) * math.sin(eps - tilt) / math.sin(eps)
        return q, l

    def figure(scale):
        qt, lt = ring(titan, scale)
        qe, le = ring(enceladus, 1.0)
        return (saturn.j2.value + qt + qe) / (saturn.moment_of_inertia.value + lt + le)

    return figure(x) / figure(1.0)


def test_migration_titan_index_from_its_measured_rate():
    law = satellite_migration("saturn", "titan")
    assert law.index == pytest.approx(TITAN_INDEX, rel=1e-12)
    assert law.age == pytest.approx(4.5673e9, rel=1e-12)
    # today's rate back from the law: b a0 / T0 = 11.3 cm/yr
    assert law.index * 1221900e5 / law.age == pytest.approx(11.3, rel=1e-12)


@pytest.mark.parametrize("t", [-3e9, -1e9, -1e6, 0.0, 1e8, 2e9])
def test_migration_factor_is_the_ring_ratio_at_the_power_law_distance(t):
    law = satellite_migration("saturn", "titan")
    x = (1 + t / 4.5673e9) ** TITAN_INDEX
    assert float(law.semi_major_axis_ratio(t)) == pytest.approx(x, rel=1e-13)
    assert float(law.factor(t)) == pytest.approx(_titan_ratio(x), rel=1e-9)


def test_migration_node_on_a_fixed_orbit_is_the_integral_of_alpha():
    """On a fixed orbit the obliquity stays and the node moves by cos ε ∫α(t) dt (quad, apart)."""
    law = satellite_migration("saturn", "titan", index=30.0)  # fast, to see the growth in 3 Myr
    orbit = FixedOrbit(e=0.0)
    eps, T = 0.45, 3e6
    h = spin_axis_history(
        orbit,
        "saturn",
        np.linspace(0.0, T, 301),
        axis=[np.sin(eps), 0.0, np.cos(eps)],
        step=2000.0,
        coupling=law,
    )
    assert isinstance(h.model, MigratingSpinAxisModel)
    alpha0 = SpinAxisModel.from_precession_constant("saturn").rate(0.0, 0.0)
    integral, _ = quad(
        lambda t: alpha0 * _titan_ratio((1 + t / 4.5673e9) ** 30.0), 0.0, T, epsabs=0, epsrel=1e-12
    )
    node = np.unwrap(np.arctan2(h.axis[:, 1], h.axis[:, 0]))
    assert abs(node[-1] - node[0]) == pytest.approx(np.cos(eps) * integral, rel=1e-8)
    assert integral > 1.01 * alpha0 * T  # α grew: the test sees the law, not a constant
    assert np.abs(h.obliquity - eps).max() <= 1e-12


def test_migration_resonance_crossing_matches_dop853():
    """Through a resonance: the orbit's node regresses at g with ψ̇ = α cos ε climbing past |g| as the
    satellite moves out; the history and scipy's DOP853 (rtol 1e-12) on the same equation agree."""
    law = satellite_migration("saturn", "titan", index=40.0)
    alpha0 = SpinAxisModel.from_precession_constant("saturn").rate(0.0, 0.0)
    eps0 = 0.1
    g = -1.03 * alpha0 * np.cos(eps0)  # ψ̇ reaches |g| once α has grown by 3 %
    orbit = PrecessingOrbit(inclination=0.02, node0=0.3, node_rate=g, e=0.0, omega0=0.0, apsidal_rate=0.0)
    T = 1.2e7
    times = np.linspace(0.0, T, 61)
    s0 = np.array([np.sin(eps0), 0.0, np.cos(eps0)])
    h = spin_axis_history(orbit, "saturn", times, axis=s0, coupling=law, tolerance=1e-10)

    def rhs(t, s):
        n = orbit.normal(t)
        alpha = alpha0 * _titan_ratio((1 + t / 4.5673e9) ** 40.0)
        return alpha * (s @ n) * np.cross(s, n)

    ref = solve_ivp(rhs, (0.0, T), s0, method="DOP853", t_eval=times, rtol=1e-12, atol=1e-14).y.T
    assert np.abs(h.axis - ref).max() < 1e-7
    eps = np.degrees(np.arccos(np.clip(np.sum(ref * orbit.normal(times), axis=1), -1, 1)))
    assert eps.max() - eps.min() > 1.0  # the resonance moved the obliquity: the run is a crossing


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (
            ("saturn", "rhea"),
            "expected a satellite of Saturn inside its Laplace radius, among Titan, Enceladus",
        ),
        (("venus", "titan"), "among none"),
        (("saturn", "enceladus"), "expected Enceladus to have migration_rate"),
        (("saturn", "titan", math.nan), "expected a finite real index b"),
        (("saturn", "titan", 0.4, -1.0), "expected a migration age 0 < T0 <= "),
    ],
)
def test_migration_bad_input(args, message):
    with pytest.raises(ValueError, match=message):
        satellite_migration(*args)


def test_migration_refuses_spans_before_formation_and_past_the_laplace_radius():
    law = satellite_migration("saturn", "titan")
    with pytest.raises(ValueError, match="expected a span after the satellites formed"):
        law.check_span(-5e9, 0.0)
    # Titan at 0.561 r_L reaches it at x = 1/0.561: (1 + t/T0)^0.4224 = 1.78 -> t = 13.5 Gyr
    law.check_span(0.0, 1.3e10)
    with pytest.raises(ValueError, match="expected Titan to stay inside Saturn's Laplace radius"):
        law.check_span(0.0, 1.4e10)
    with pytest.raises(ValueError, match="expected the model of Saturn from its figure and satellites"):
        law(SpinAxisModel.from_dynamical_ellipticity("saturn", 0.1), (0.0, 1.0))


def test_cli_obliquity_migration_runs_and_grows_the_precession(run_cli):
    """The CLI's --migration is the API's law: the precession after 1 Myr is α(t)'s integral."""
    argv = ("obliquity", "saturn", "--span", "0", "1e6", "--step", "5000", "--format", "json")
    _, plain, _ = run_cli(*argv)
    code, moved, err = run_cli(*argv, "--migration", "titan", "--migration-index", "40")
    assert code == 0, err
    plain, moved = json.loads(plain), json.loads(moved)
    assert moved["precession_rate"] == pytest.approx(plain["precession_rate"], rel=1e-12)
    mean, _ = quad(lambda t: _titan_ratio((1 + t / 4.5673e9) ** 40.0), 0.0, 1e6, epsrel=1e-12)
    # the precession (from the moving equinox) is ψ̇'s integral, α cos ε to 1e-3 over 1 Myr
    assert moved["precession"][-1] == pytest.approx(plain["precession"][-1] * mean / 1e6, rel=2e-3)


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (
            ["saturn", "--migration-index", "0.4"],
            "expected --migration-index only with --migration SATELLITE",
        ),
        (["saturn", "--migration", "titan", "--drift-timescale", "1e9"], "expected --drift-timescale or"),
        (["saturn", "--migration", "mimas"], "expected a satellite of Saturn inside its Laplace radius"),
        (["venus", "--migration", "titan"], "among none"),
        (
            ["saturn", "--migration", "titan", "--migration-age", "5e8", "--span", "-6e8", "0"],
            "expected a span after the satellites formed",
        ),
        (["saturn", "--migration", "titan", "--migration-age", "-1"], "expected a migration age 0 < T0 <= "),
        (
            ["saturn", "--migration", "titan", "--precession-rate", "0.7"],
            "expected the planet's figure and satellites with --migration",
        ),
    ],
)
def test_cli_obliquity_migration_refusals(run_cli, tmp_path, argv, message):
    code, out, err = run_cli("obliquity", *argv, "--output", str(tmp_path / "out.csv"))
    assert (code, out) == (2, "")
    assert len(err.strip().splitlines()) == 1
    assert message in err
    assert list(tmp_path.iterdir()) == []


def test_migration_titan_over_the_last_gyr_alpha_grew_by_16_percent():
    """α 1 Gyr ago was 0.860 α₀: Saturn's ψ̇ = 0.73″/yr today was 0.63″/yr, below |s8| = 0.69″/yr,
    so Titan's migration carried the precession up through s8 (Saillenfest, Lari & Boué 2021 put
    the encounter about 1 Gyr ago)."""
    law = satellite_migration("saturn", "titan")
    assert float(law.factor(-1e9)) == pytest.approx(
        _titan_ratio((1 - 1e9 / 4.5673e9) ** TITAN_INDEX), rel=1e-9
    )
    rate = SpinAxisModel.from_precession_constant("saturn").precession_rate(math.radians(26.73))
    assert rate * float(law.factor(-1e9)) < 0.6917 < rate
