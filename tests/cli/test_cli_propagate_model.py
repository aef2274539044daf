"""``andoyer propagate --model NAME --method M``: named models, integrators, one-line errors, exit 2."""

from __future__ import annotations

import functools

import numpy as np
import pytest

from andoyer import RigidBody, State
from andoyer.perturbations.solar_system import JULIAN_YEAR, OBLIQUITY
from conftest import rotation_distance

START = ("0.1", "0.2", "0.3", "0.9", "1.0", "0.5")  # Andoyer l, g, h, L, G, H
HEAVY_TOP = ("--model", "heavy-top", "--weight", "0.5", "--center-of-mass", "0", "0.1", "0.3")


@pytest.fixture
def cli(run_cli):
    """``andoyer propagate ARGV`` in process: (exit code, stdout, stderr)."""
    return functools.partial(run_cli, "propagate")


@pytest.fixture
def rows(cli):
    """Run with ``--format csv`` and return the numeric table (one row per time)."""

    def run(*argv):
        code, out, err = cli(*argv, "--format", "csv")
        assert code == 0, err
        return np.loadtxt(out.splitlines()[1:], delimiter=",", ndmin=2)

    return run


@pytest.fixture
def heavy_top(rows):
    """The heavy top from START on a triaxial body, written as states, at t = 0, 0.5, 1."""

    def run(*argv):
        return rows(
            *HEAVY_TOP, "--moments", "1", "1.2", "1.5", "--values", *START, "--range", "0", "1", "3", *argv
        )

    return run


def energy(table, body, weight, center):
    """T + weight r_c·γ from state rows (t, state, qx, qy, qz, qw, m1, m2, m3)."""
    s = State.from_quaternion(table[:, 2:6], table[:, 6:9])
    return s.energy(body) + weight * s.gamma @ np.asarray(center)


def test_cli_propagate_heavy_top_splitting_agrees_with_reference(heavy_top):
    ref = heavy_top("--to", "state")
    split = heavy_top("--to", "state", "--method", "splitting", "--step", "0.05", "--order", "4")
    assert np.abs(split[:, 6:] - ref[:, 6:]).max() <= 1e-6
    assert rotation_distance(split[:, 2:6], ref[:, 2:6]).max() <= 1e-6
    body = RigidBody(1, 1.2, 1.5)
    for table in (ref, split):
        e = energy(table, body, 0.5, [0, 0.1, 0.3])
        assert np.ptp(e) <= 1e-9


def test_cli_propagate_splitting_without_step_chooses_from_the_default_rtol(heavy_top, cli):
    ref = heavy_top("--to", "state")
    split = heavy_top("--to", "state", "--method", "splitting")
    assert np.abs(split[:, 6:] - ref[:, 6:]).max() <= 1e-3 * np.linalg.norm(ref[0, 6:])
    argv = ("--moments", "1", "1.2", "1.5", "--values", *START, "--range", "0", "1", "3")
    code, _, err = cli(*HEAVY_TOP, *argv, "--method", "splitting")
    assert code == 0
    assert "estimated relative error" in err
    assert "(rtol 0.001)" in err


def test_cli_propagate_heavy_top_conserves_the_vertical_momentum(heavy_top):
    """Gravity along s3 exerts no torque about s3: Andoyer's H is an integral."""
    table = heavy_top("--to", "andoyer", "--method", "splitting", "--step", "0.1")
    assert np.abs(table[:, 7] - 0.5).max() <= 1e-12
    assert np.ptp(table[:, 6]) > 1e-4  # while G changes


@pytest.mark.parametrize("method", ["reference", "splitting", "secular"])
def test_cli_propagate_precessing_frame_regresses_the_node(rows, method):
    """A frame turning at μ3 about s3: the inertial momentum is fixed, so h(t) = h0 - μ3 t, H constant."""
    options = ("--step", "0.5") if method == "splitting" else ()
    table = rows(
        "--model", "precessing-frame", "--frame-rate", "0", "0", "0.02", "--moments", "1", "1.2", "1.5",
        "--values", *START, "--range", "0", "4", "5", "--to", "andoyer", "--method", method, *options,
    )  # fmt: skip
    assert np.abs(table[:, 4] - (0.3 - 0.02 * table[:, 0])).max() <= 1e-9
    assert np.abs(table[:, 7] - 0.5).max() <= 1e-12


def test_cli_propagate_free_reference_matches_the_exact_default(rows):
    args = ("--moments", "1", "2", "3", "--values", *START, "--range", "-2", "3", "6", "--to", "state")
    exact = rows(*args)
    reference = rows(*args, "--method", "reference")
    assert np.abs(reference[:, 6:] - exact[:, 6:]).max() <= 1e-9
    assert rotation_distance(reference[:, 2:6], exact[:, 2:6]).max() <= 1e-9


def test_cli_propagate_mars_solar_secular_rate(rows):
    """Mars' default body, J = 0.01, I = ε: the mean node regresses at the closed-form solar rate."""
    G = 2 * np.pi / 88642.6632
    eps = float(OBLIQUITY["mars"])
    table = rows(
        "--model", "mars-solar", "--method", "secular",
        "--values", "0", "0", "1.0", *(repr(float(x)) for x in (G * np.cos(0.01), G, G * np.cos(eps))),
        "--range", "0", repr(100 * JULIAN_YEAR), "3", "--to", "andoyer",
    )  # fmt: skip
    C, AB = 1.0, 0.9942917 + 0.9949813
    # the Sun's mean orbit about Mars (andoyer.perturbations.solar_system): DE440's GMS and GM4 (m³/s²),
    # the Mars Fact Sheet's sidereal period 686.980 d with Kepler's a, Standish's e = 0.0933941
    gm, gm_mars, period = 1.32712440041279419e20, 4.2828375816e13, 686.980 * 86400.0
    a, e = ((gm + gm_mars) * (period / (2 * np.pi)) ** 2) ** (1 / 3), 0.0933941
    rate = -1.5 * gm / (a**3 * (1 - e * e) ** 1.5 * G) * (C - AB / 2) / C * np.cos(eps)
    rate *= (3 * np.cos(0.01) ** 2 - 1) / 2
    assert table[:, 4] == pytest.approx(1.0 + rate * table[:, 0], abs=1e-10)


def test_cli_propagate_model_output_file_is_atomic(cli, tmp_path):
    target = tmp_path / "out.csv"
    target.write_text("previous\n")
    code, _, err = cli(
        *HEAVY_TOP, "--moments", "1", "1", "2",
        "--values", *START, "--times", "1", "--method", "secular", "--output", str(target),
    )  # fmt: skip
    assert code == 2
    assert "expected gravity-gradient models on Kepler orbits or precessing frames" in err
    assert target.read_text() == "previous\n"
    code, _, _ = cli(
        *HEAVY_TOP, "--moments", "1", "1", "2", "--values", *START, "--times", "1", "--output", str(target)
    )
    assert code == 0
    assert (
        target.read_text().startswith("t,state,l,g,h,L,G,H") or "state" in target.read_text().splitlines()[0]
    )
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.csv"]


BAD_ARGS = {
    "unknown model": (["--model", "pluto"], "invalid choice: 'pluto'"),
    "heavy top without parameters": (["--model", "heavy-top"], "expected --weight and --center-of-mass"),
    "parameter of another model": (
        ["--frame-rate", "0", "0", "1"],
        "expected only the parameters of --model free",
    ),
    "exact with a model": (
        [*HEAVY_TOP, "--method", "exact"],
        "expected --method reference, splitting or secular for --model heavy-top, got exact",
    ),
    "bad rtol": ([*HEAVY_TOP, "--method", "splitting", "--rtol", "0.5"], "expected an --rtol"),
    "negative step": ([*HEAVY_TOP, "--method", "splitting", "--step", "-1"], "expected a positive --step"),
    "step with reference": ([*HEAVY_TOP, "--step", "0.1"], "expected --step only with --method splitting"),
    "order with exact": (["--order", "4"], "expected --order only with --method splitting"),
    "bad order": (
        [*HEAVY_TOP, "--method", "splitting", "--step", "0.1", "--order", "5"],
        "invalid choice: 5",
    ),
    "bad method": (["--method", "rk4"], "invalid choice: 'rk4'"),
}


@pytest.mark.parametrize("name", list(BAD_ARGS))
def test_cli_propagate_model_bad_arguments_exit_2(cli, name):
    argv, message = BAD_ARGS[name]
    code, out, err = cli("--moments", "1", "1.2", "1.5", "--values", *START, "--times", "1", *argv)
    assert code == 2
    assert out == ""
    assert len(err.strip().splitlines()) == 1
    assert message in err
