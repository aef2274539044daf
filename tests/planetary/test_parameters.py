"""The physical parameters' ranges: one table, the same answer from the API and from every command.

Issue 26 item 4: ``obliquity`` accepted ``--tidal-dissipation -5`` and ``1e6`` and
``--dynamical-ellipticity 0.9`` (which ``precession`` refused), and ``--precession-rate 1e10``.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from andoyer.cli import main
from andoyer.planetary import parameters
from andoyer.planetary.cassini import get as cassini_body
from andoyer.planetary.orbits import VondrakEcliptic
from andoyer.planetary.parameters import PARAMETERS, check
from andoyer.planetary.precession import precession_rates
from andoyer.planetary.spin_axis import SpinAxisModel, spin_axis_history

#: The IERS Conventions 2010 (Table 1.1) dynamical ellipticity and the IAU 2006 rate of psi_A
#: (Capitaine et al. 2003, eq. 37, 5038.481507″/cy): independent of the model's constants.
H_IERS = 0.0032737949
PSI_A_RATE = 50.38481507
EPS0 = math.radians(84381.406 / 3600)


def _inside_outside(p):
    """Values just inside and just outside each finite bound of ``p``."""
    inside, outside = [], []
    for bound, closed, sign in ((p.low, p.low_closed, -1), (p.high, p.high_closed, 1)):
        if not math.isfinite(bound):
            continue
        step = 1e-9 * max(1.0, abs(bound))
        (inside if closed else outside).append(bound)
        inside.append(bound - sign * step)
        outside.append(bound + sign * step)
    return inside, outside


def test_parameters_docstring_lists_every_parameter():
    table = parameters.__doc__.split("=====", 1)[1]
    for name in PARAMETERS:
        assert f"\n{name} " in table


@pytest.mark.parametrize("name", sorted(PARAMETERS))
def test_parameters_bounds_are_kept_open_or_closed(name):
    p = PARAMETERS[name]
    inside, outside = _inside_outside(p)
    for x in inside:
        assert check(name, x) == x
    for x in [*outside, math.nan, math.inf, -math.inf, True, "0.1", [0.1]]:
        with pytest.raises(ValueError, match=f"^expected an? {p.name} .*, got "):
            check(name, x)


def test_parameters_angles_in_degrees_use_the_same_bounds():
    assert check("inclination", 180.0, degrees=True) == 180.0
    with pytest.raises(ValueError, match=r"0 <= i <= 180 deg .*got 500.0"):
        check("inclination", 500.0, degrees=True)
    with pytest.raises(ValueError, match=r"0 < i < 90 deg"):
        check("laplace_inclination", 90.0, degrees=True)
    with pytest.raises(ValueError, match="expected a parameter among"):
        check("colour", 1.0)


def test_precession_rate_bound_is_the_rate_of_half_ellipticity():
    """P_max/P = (1/2)/H: against the IERS H and the IAU rate, which the model matches to 5e-4."""
    with pytest.raises(ValueError, match=r"expected a precession rate P < [0-9.]+ arcsec/yr") as info:
        SpinAxisModel.from_precession_rate("earth", 1e10, EPS0)
    top = float(str(info.value).split("P < ")[1].split()[0])
    assert top == pytest.approx(PSI_A_RATE * 0.5 / H_IERS, rel=1e-3)
    below = SpinAxisModel.from_precession_rate("earth", top * (1 - 1e-5), EPS0)
    assert 0.49 < below.dynamical_ellipticity() < 0.5
    with pytest.raises(ValueError, match="expected a precession rate P <"):
        SpinAxisModel.from_precession_rate("earth", top * (1 + 1e-5), EPS0)


@pytest.mark.parametrize(
    ("kwargs", "flag", "value", "name"),
    [
        ({"tidal_dissipation": -5.0}, "--tidal-dissipation", "-5", "tidal_dissipation"),
        ({"tidal_dissipation": 1e6}, "--tidal-dissipation", "1e6", "tidal_dissipation"),
        ({"dynamical_ellipticity": 0.9}, "--dynamical-ellipticity", "0.9", "dynamical_ellipticity"),
        ({"precession_rate": -1.0}, "--precession-rate", "-1", "precession_rate"),
    ],
)
def test_obliquity_and_api_refuse_a_parameter_with_the_same_words(kwargs, flag, value, name, capsys):
    with pytest.raises(ValueError, match=r"^expected") as info:
        spin_axis_history(VondrakEcliptic(), "earth", [0.0, 100.0], **kwargs)
    words = str(info.value)
    with pytest.raises(ValueError, match=r"^expected") as direct:
        check(name, float(value))
    assert words == str(direct.value)
    code = _code(["obliquity", "earth", "--span", "0", "100", "--step", "100", flag, value])
    err = capsys.readouterr().err
    assert code == 2
    assert err.strip().endswith(words)


def test_precession_nutation_and_obliquity_answer_one_ellipticity_alike(capsys):
    answers = set()
    for argv in (
        ["precession", "earth", "--dynamical-ellipticity", "0.9"],
        ["nutation", "earth", "--span", "0", "1", "--step", "0.5", "--dynamical-ellipticity", "0.9"],
        ["obliquity", "earth", "--dynamical-ellipticity", "0.9"],
    ):
        assert _code(argv) == 2
        answers.add(capsys.readouterr().err.split(": error: ", 1)[1])
    with pytest.raises(ValueError, match=r"^expected a dynamical ellipticity") as info:
        precession_rates("earth", dynamical_ellipticity=0.9)
    assert answers == {f"argument --dynamical-ellipticity: {info.value}\n"}


def test_cassini_command_and_api_share_the_ranges(capsys):
    moon = cassini_body("moon")
    for field, value, flag, text in (
        ("inclination", math.radians(95.0), "--inclination", "95"),
        ("moment_of_inertia", 1.5, "--moment-of-inertia", "1.5"),
        ("j2", -1e-4, "--j2", "-1e-4"),
        ("c22", -1e-5, "--c22", "-1e-5"),
    ):
        with pytest.raises(ValueError, match=r"^expected an? ") as info:
            moon.replace(**{field: value})
        assert _code(["cassini", "moon", flag, text]) == 2
        err = capsys.readouterr().err
        core = str(info.value).split(", got")[0]
        core = core.replace("1.570796327 rad", "90 deg")  # the command line's unit
        assert core in err


def test_ellipticity_drift_must_keep_the_ellipticity_in_range():
    """H (1 + drift t) crosses 0 at t = -1/drift: a span reaching it is refused; one short of it is not."""
    drift = 1e-6  # per year: H vanishes 1e6 years ago
    h = spin_axis_history(VondrakEcliptic(), "earth", [-1000.0, 0.0], ellipticity_drift=drift)
    assert h.model.ellipticity_drift == drift
    with pytest.raises(ValueError, match=r"expected an ellipticity drift that keeps 0 < H < 0\.5"):
        SpinAxisModel.from_precession_rate("earth", PSI_A_RATE, EPS0, ellipticity_drift=drift).check_span(
            -1.0e6, 0.0
        )
    with pytest.raises(ValueError, match="expected an ellipticity drift"):
        spin_axis_history(VondrakEcliptic(), "earth", [0.0, 100.0], ellipticity_drift=-1.0)


def test_model_eccentricity_and_obliquity_ranges():
    with pytest.raises(ValueError, match=r"expected an eccentricity 0 <= e < 1 "):
        SpinAxisModel.from_precession_rate("mars", 7.597, 0.44, eccentricity=1.5)
    with pytest.raises(ValueError, match=r"expected an obliquity at J2000 0 <= eps0 < 1\.570796327 rad"):
        SpinAxisModel.from_precession_rate("mars", 7.597, np.pi / 2)


def _code(argv):
    try:
        return main(argv)
    except SystemExit as exc:
        return exc.code
