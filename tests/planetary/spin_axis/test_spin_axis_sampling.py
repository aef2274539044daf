"""A fast precession: the integration step follows it, and outputs that alias it are refused.

Issue 26 item 4: ``--precession-rate 1e10`` printed precession angles that aliased (+35°, +99°):
``p_A`` is unwrapped between integration steps, so a step of half a precession period or more
folds it.
"""

from __future__ import annotations

import numpy as np
import pytest
from spin_cases import angle

from andoyer.cli import main
from andoyer.planetary.orbits import VondrakEcliptic
from andoyer.planetary.spin_axis import (
    EPSILON_0,
    SpinAxisModel,
    general_precession,
    mean_pole_j2000,
    output_times,
    spin_axis_history,
)
from andoyer.planetary.spin_axis.history import integrate_axis_dop853


def _dense_reference(model, end, count):
    """DOP853 (rtol 1e-13) at ``count`` times to ``end``: axes and p_A unwrapped between them."""
    t = np.linspace(0.0, end, count)
    orbit = VondrakEcliptic()
    s = integrate_axis_dop853(orbit, model, t, mean_pole_j2000(), rtol=1e-13)
    p = np.unwrap(general_precession(s, orbit.normal(t), mean_pole_j2000(), orbit.normal(0.0)))
    return s, p - p[0]


def test_fast_precession_accumulates_p_a_at_coarse_outputs():
    """P = 5000″/yr turns the axis once in 259 years: p_A at 1000 years needs the short step."""
    model = SpinAxisModel.from_precession_rate("earth", 5000.0, EPSILON_0)
    s_ref, p_ref = _dense_reference(model, 1000.0, 401)  # 2.5-year spacing: 1/100 turn
    h = spin_axis_history(VondrakEcliptic(), "earth", [0.0, 1000.0], precession_rate=5000.0)
    assert angle(h.axis[1], s_ref[-1]) <= 1e-10
    assert h.precession[1] == pytest.approx(p_ref[-1], abs=1e-9)
    assert abs(h.precession[1]) > 2 * np.pi * 3  # over three turns, not folded into one


def test_largest_turn_is_the_precession_between_outputs():
    """Earth, Vondrák ecliptic: p_A turns between outputs as IAU 2006's p_A (erfa.p06e) does."""
    import erfa

    times = output_times(-1000.0, 1000.0, 500.0)
    h = spin_axis_history(VondrakEcliptic(), "earth", times)
    p_a = np.array([erfa.p06e(2451545.0, t * 365.25)[12] for t in times])
    assert h.largest_turn == pytest.approx(np.max(np.abs(np.diff(p_a))), rel=1e-4)
    single = spin_axis_history(VondrakEcliptic(), "earth", [500.0])
    assert single.largest_turn == 0.0


def test_largest_turn_counts_the_perihelion_from_the_equinox():
    """With an eccentricity, ϖ from the moving equinox turns faster than p_A (ϖ̇ = p + g)."""
    from andoyer.planetary.orbits import SecularOrbit

    times = output_times(-20000.0, 20000.0, 2000.0)
    with_e = spin_axis_history(SecularOrbit("earth"), "earth", times)
    assert with_e.perihelion is not None
    cycles = np.unwrap(with_e.perihelion)
    assert with_e.largest_turn >= np.max(np.abs(np.diff(cycles))) - 1e-12
    assert with_e.largest_turn > np.max(np.abs(np.diff(with_e.precession)))


@pytest.mark.parametrize(
    ("argv", "refused"),
    [
        (["--precession-rate", "7000", "--span", "-1000", "1000", "--step", "500"], True),
        (["--precession-rate", "7000", "--span", "-1000", "1000", "--step", "50"], False),
        (["--span", "-200000", "200000", "--step", "20000"], True),  # half of 25.7 kyr is 12.9 kyr
        (["--span", "-200000", "200000", "--step", "10000"], False),
    ],
)
def test_obliquity_refuses_outputs_that_alias_the_precession(argv, refused, tmp_path, capsys):
    out = tmp_path / "o.csv"
    code = main(["obliquity", "earth", *argv, "--format", "csv", "--output", str(out)])
    err = capsys.readouterr().err
    if refused:
        assert code == 2
        assert "expected --step DT below half the period of the fastest angle printed" in err
        assert len(err.splitlines()) == 1
        assert not out.exists()
    else:
        assert code == 0, err
        assert out.exists()


def test_obliquity_refuses_a_precession_rate_no_body_can_have(capsys):
    argv = ["obliquity", "earth", "--precession-rate", "1e10", "--span", "-1000", "1000", "--step", "500"]
    code = main(argv)
    assert code == 2
    assert "expected a precession rate P < 7" in capsys.readouterr().err


def test_obliquity_refuses_a_coarse_step_before_the_integration(tmp_path, capsys):
    """Mars over 1 Gyr every Myr: refused at once from the J2000 rates, not after 30 CPU s of run.

    The perihelion from the equinox turns at about ψ̇ + ϖ̇ = 7.6 + 16.0″/yr (Mars' precession rate,
    Konopliv et al. 2016; its perihelion's advance, 0.44°/century in the J2000 mean elements of
    Simon et al. 1994): about 18 turns per Myr, so the step must stay below ~27 kyr.
    """
    out = tmp_path / "m.json"
    argv = ["obliquity", "mars", "--orbit", "secular", "--span", "-1e9", "0", "--step", "1e6"]
    code = main([*argv, "--format", "json", "--output", str(out)])
    err = capsys.readouterr().err
    assert code == 2
    assert len(err.splitlines()) == 1
    assert "at its J2000 rate" in err  # the check before the run, not the one after it
    most = float(err.split("take DT below ")[1].split()[0])
    assert 2.4e4 < most < 3.0e4
    assert not out.exists()


def test_largest_turn_skips_the_perihelion_where_the_orbit_is_nearly_circular(monkeypatch):
    """ϖ turns like 1/e near e = 0: those output pairs do not count (PERIHELION_E_FLOOR).

    e e^{iϖ} = A e^{i g₁ t} + B e^{i g₂ t} with B = 0.98 A: e beats down to 0.02 A once per
    beat period (75 kyr), where ϖ turns by nearly π within a few centuries; elsewhere it turns by
    about (g₁ + g₂)/2 · 1000 yr = 0.17 rad per 1000-year output step, plus the axis' precession.
    """
    from andoyer.planetary.orbits.table import TableOrbit
    from andoyer.planetary.spin_axis import history

    t = np.arange(-2e5, 1.0, 100.0)
    g1, g2 = 2 * np.pi / 5e4, 2 * np.pi / 3e4
    z = 0.05 * np.exp(1j * g1 * t) + 0.049 * np.exp(1j * g2 * t)
    ecc = np.stack([z.real, z.imag, np.zeros_like(t)], axis=-1)
    normal = np.tile([0.0, 0.0, 1.0], (t.size, 1))
    orbit = TableOrbit(t, normal, ecc, name="beating")
    times = output_times(-2e5, 0.0, 1000.0)
    counted = spin_axis_history(orbit, "mars", times, step=250.0)
    e = np.abs(0.05 * np.exp(1j * g1 * times) + 0.049 * np.exp(1j * g2 * times))
    assert e.min() < 0.1 * e.max()  # the beat passes near zero within the span
    assert counted.largest_turn < 0.3
    monkeypatch.setattr(history, "PERIHELION_E_FLOOR", 0.0)
    every = spin_axis_history(orbit, "mars", times, step=250.0)
    assert every.largest_turn > 2.0  # counted at the beat's minimum: most of π in one step
