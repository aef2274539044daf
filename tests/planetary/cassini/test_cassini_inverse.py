"""The inverse problem: an observed obliquity to ``C/MR²`` (``andoyer.planetary.cassini.inverse``).

Independent checks: Peale's relation in closed form (one mode) written out here; a round trip
through the forward model with several modes; the analytic derivatives against central finite
differences of the solved root; the propagated uncertainty against a seeded Monte Carlo through
the closed form; Mercury against Margot et al. (2012).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from andoyer import catalogue
from andoyer.planetary import cassini
from andoyer.planetary.cassini import CassiniBody, ForcedObliquity, NodeMode, moment_of_inertia_from_obliquity
from andoyer.planetary.cassini.inverse import obliquity_and_derivatives

DEG = math.pi / 180
ARCMIN = DEG / 60


def peale(body, theta, j2=None, c22=None, g=None, i=None):
    """C/MR² from a signed state-1 obliquity θ < 0, closed form: C = −(a₁cos θ + b₁) sin θ/(g sin(θ − i))."""
    j2 = body.j2 if j2 is None else j2
    c22 = body.c22 if c22 is None else c22
    g = body.node_rate if g is None else g
    i = body.inclination if i is None else i
    scale = 1.5 * body.mean_motion**2 / (1 + body.mass_ratio) / body.rotation_rate
    x = (1 - body.eccentricity**2) ** 1.5
    gp = body.eccentricity_factor
    a1, b1 = scale * (j2 / x + c22 * gp), scale * c22 * gp
    return -(a1 * np.cos(theta) + b1) * np.sin(theta) / (g * np.sin(theta - i))


@pytest.mark.parametrize(("name", "obliquity"), [("mercury", 2.04 * ARCMIN), ("titan", 0.32 * DEG)])
def test_inverse_one_mode_is_peales_relation(name, obliquity):
    body = cassini.get(name)
    (estimate,) = moment_of_inertia_from_obliquity(body, obliquity)
    assert estimate.moment_of_inertia == pytest.approx(peale(body, -obliquity), rel=1e-10)


def test_inverse_mercury_margot_2012():
    """Margot et al. (2012, JGR 117, E00L09): obliquity (2.04 ± 0.08)′ gives C/MR² = 0.346 ± 0.014
    (their J2, C22 and orbit; with the catalogue's 8.6° and 325 kyr it is 0.343)."""
    (estimate,) = moment_of_inertia_from_obliquity("mercury", 2.04 * ARCMIN, 0.08 * ARCMIN)
    assert estimate.moment_of_inertia == pytest.approx(0.346, abs=0.014)
    assert estimate.error == pytest.approx(0.014, rel=0.1)
    assert set(estimate.contributions) == {"obliquity"}  # the catalogue gives no σ for J2, C22


def test_inverse_round_trip_several_modes():
    # Europa's four modes: the forward obliquity at C/MR² = 0.30, then back.
    forced = cassini.forced_obliquity("europa")
    c0 = 0.30
    shifted = ForcedObliquity(forced.body.replace(moment_of_inertia=c0), forced.modes, forced.source)
    observed = float(shifted.obliquity(0.0))
    solutions = moment_of_inertia_from_obliquity(shifted, observed)
    assert any(abs(s.moment_of_inertia - c0) < 1e-9 for s in solutions)


def _solve(system, theta, near):
    """The solution nearest ``near`` (a mode near resonance can give several)."""
    solutions = moment_of_inertia_from_obliquity(system, theta)
    return min(solutions, key=lambda s: abs(s.moment_of_inertia - near))


@pytest.mark.parametrize("name", ["titan", "europa"])
def test_inverse_derivatives_match_finite_differences(name):
    forced = cassini.forced_obliquity(name)
    body = forced.body
    theta = float(forced.obliquity(0.0))  # so that the catalogue's C/MR² is a solution
    estimate = _solve(forced, theta, body.moment_of_inertia)
    assert estimate.moment_of_inertia == pytest.approx(body.moment_of_inertia, rel=1e-10)
    c0 = estimate.moment_of_inertia
    main = forced.dominant()

    def with_changes(**changes):
        modes = list(forced.modes)
        mode = modes[main]
        modes[main] = NodeMode(
            changes.pop("node_rate", mode.node_rate), changes.pop("inclination", mode.inclination), mode.phase
        )
        return ForcedObliquity(body.replace(**changes), tuple(modes), forced.source)

    steps = {"j2": 1e-3 * body.j2, "c22": 1e-3 * body.c22, "node_rate": 1e-4 * forced.modes[main].node_rate}
    steps["inclination"] = 1e-4 * forced.modes[main].inclination
    for key, h in steps.items():
        base = getattr(body, key) if key in ("j2", "c22") else getattr(forced.modes[main], key)
        plus = _solve(with_changes(**{key: base + h}), theta, c0).moment_of_inertia
        minus = _solve(with_changes(**{key: base - h}), theta, c0).moment_of_inertia
        assert estimate.derivatives[key] == pytest.approx((plus - minus) / (2 * h), rel=1e-5), key
    d = 1e-4 * theta
    numeric = (
        _solve(forced, theta + d, c0).moment_of_inertia - _solve(forced, theta - d, c0).moment_of_inertia
    ) / (2 * d)
    assert estimate.derivatives["obliquity"] == pytest.approx(numeric, rel=1e-5)


def test_obliquity_derivative_by_moment_matches_finite_difference():
    forced = cassini.forced_obliquity("ganymede")
    value, slopes = obliquity_and_derivatives(forced)
    h = 1e-6
    up = ForcedObliquity(
        forced.body.replace(moment_of_inertia=forced.body.moment_of_inertia + h), forced.modes
    )
    down = ForcedObliquity(
        forced.body.replace(moment_of_inertia=forced.body.moment_of_inertia - h), forced.modes
    )
    numeric = (float(up.obliquity()) - float(down.obliquity())) / (2 * h)
    assert value == pytest.approx(float(forced.obliquity()), rel=1e-12)
    assert slopes["moment_of_inertia"] == pytest.approx(numeric, rel=1e-5)


def test_inverse_uncertainty_matches_monte_carlo():
    """Titan's 0.32° ± 0.02° with the catalogue's σ(J2), σ(C22): the linear propagation against
    20000 seeded draws through Peale's closed form."""
    body = cassini.get("titan")
    titan = catalogue.get("titan")
    sigma_j2, sigma_c22 = titan.j2.uncertainty, titan.c22.uncertainty
    (estimate,) = moment_of_inertia_from_obliquity("titan", 0.32 * DEG, 0.02 * DEG)
    assert set(estimate.contributions) == {"obliquity", "j2", "c22"}
    rng = np.random.default_rng(23)
    size = 20000
    samples = peale(
        body,
        -(0.32 * DEG + 0.02 * DEG * rng.standard_normal(size)),
        j2=body.j2 + sigma_j2 * rng.standard_normal(size),
        c22=body.c22 + sigma_c22 * rng.standard_normal(size),
    )
    assert np.std(samples) == pytest.approx(estimate.error, rel=0.03)
    assert np.mean(samples) == pytest.approx(estimate.moment_of_inertia, rel=0.01)
    parts = estimate.contributions
    assert math.hypot(parts["obliquity"], parts["j2"], parts["c22"]) == pytest.approx(
        estimate.error, rel=1e-12
    )


def test_inverse_errors_override_and_state():
    body = cassini.get("titan")
    (plain,) = moment_of_inertia_from_obliquity(body, 0.32 * DEG, 0.0, errors={"inclination": 0.02 * DEG})
    assert set(plain.contributions) == {"obliquity", "inclination"}
    assert plain.contributions["inclination"] == pytest.approx(
        abs(plain.derivatives["inclination"]) * 0.02 * DEG
    )
    # the Moon is in state 2: its 6.688° gives its C/MR² there; far from any state-1 solution
    (moon,) = moment_of_inertia_from_obliquity("moon", 6.688 * DEG, 0.001 * DEG)
    assert moon.moment_of_inertia == pytest.approx(catalogue.get("moon").moment_of_inertia.value, abs=0.003)
    # no rigid Titan in state 1 has an obliquity of 80°
    assert moment_of_inertia_from_obliquity(body, 80 * DEG) == ()


@pytest.mark.parametrize(
    ("args", "kwargs"),
    [
        ((0.0,), {}),
        ((2.0,), {}),
        ((float("nan"),), {}),
        ((0.005, -1.0), {}),
        ((0.005, 0.001), {"errors": {"e": 0.1}}),
        ((0.005, 0.001), {"errors": {"j2": -1.0}}),
        ((0.005,), {"state": 3}),
        ((0.005,), {"t": float("inf")}),
    ],
)
def test_inverse_bad_input(args, kwargs):
    with pytest.raises(ValueError, match="expected"):
        moment_of_inertia_from_obliquity(cassini.get("titan"), *args, **kwargs)


def test_inverse_bad_system():
    with pytest.raises(ValueError, match="expected a ForcedObliquity"):
        moment_of_inertia_from_obliquity(3.0, 0.005)


def test_inverse_body_without_a_moment():
    # a body file that leaves C/MR² out: the inverse problem does not need it
    entry = catalogue.get("titan")
    data = entry.to_dict()
    data.pop("moment_of_inertia")
    body = catalogue.body_from_dict(data)
    with pytest.raises(ValueError, match="to have moment_of_inertia"):
        cassini.forced_obliquity(body)
    (estimate,) = moment_of_inertia_from_obliquity(body, 0.32 * DEG)
    (reference,) = moment_of_inertia_from_obliquity("titan", 0.32 * DEG)
    assert estimate.moment_of_inertia == pytest.approx(reference.moment_of_inertia, rel=1e-12)


def test_cassini_body_single_mode_matches_closed_form_body():
    # the CassiniBody given directly is one mode at its own node rate and inclination
    body = CassiniBody("x", 3.18e-5, 1.0e-5, 0.34, 143.9, 0.029, 0.3 * DEG, -0.009)
    (estimate,) = moment_of_inertia_from_obliquity(body, 0.2 * DEG)
    assert estimate.moment_of_inertia == pytest.approx(peale(body, -0.2 * DEG), rel=1e-10)
