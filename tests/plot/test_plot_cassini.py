"""``andoyer.plot.cassini``: the portrait's data (states, grid, exact separatrix), the geometry, the CLI."""

from __future__ import annotations

import math

import numpy as np
import pytest

from andoyer import plot
from andoyer.cli import main
from andoyer.planetary import cassini
from andoyer.planetary.cassini import ColomboTop


def written_out_hamiltonian(theta, phi, alpha, beta, g, i):
    """𝓗(θ, φ) with k the pole and K = (sin i, 0, cos i), written out again."""
    s = np.stack([np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi), np.cos(theta)], -1)
    K = np.array([math.sin(i), 0.0, math.cos(i)])
    return -0.5 * alpha * s[..., 2] ** 2 - beta * s[..., 2] - g * (s @ K)


@pytest.mark.parametrize("top", [ColomboTop(1.0, 0.3, -0.3, 0.3), ColomboTop(1.0, 0.0, -2.0, 0.3)])
def test_cassini_portrait_data_grid_and_separatrix(top):
    data = plot.cassini_portrait_data(top, n_phi=61, n_theta=31)
    assert data.energy.shape == (31, 61)
    P, T = np.meshgrid(data.phi, data.theta)
    expected = written_out_hamiltonian(T, P, top.alpha, top.beta, top.node_rate, top.inclination)
    assert np.allclose(data.energy, expected, atol=1e-14)
    ok = np.isfinite(data.separatrix)
    if data.separatrix_energy is None:
        assert not ok.any()
    else:
        phi = np.broadcast_to(data.phi[:, None], data.separatrix.shape)[ok]
        level = written_out_hamiltonian(
            data.separatrix[ok], phi, top.alpha, top.beta, top.node_rate, top.inclination
        )
        assert np.allclose(level, data.separatrix_energy, atol=1e-10)


def test_cassini_portrait_marks_every_state(tmp_path):
    fig = plot.cassini_portrait(cassini.get("mercury"), n_phi=91, n_theta=46, levels=5)
    data = fig.andoyer_data
    assert [s.number for s in data.states] == [1, 2, 3, 4]
    drawn = {
        (round(float(line.get_xdata()[0]), 9), round(float(line.get_ydata()[0]), 9))
        for line in fig.axes[0].lines
        if len(line.get_xdata()) == 1
    }
    for state in data.states:
        x = 0.0 if state.theta > 0 else 180.0
        assert (x, round(state.obliquity_deg, 9)) in drawn
    fig.savefig(tmp_path / "m.png", dpi=30)


def test_cassini_geometry_arrows_to_scale():
    fig = plot.cassini_geometry(cassini.get("moon"))
    ends = [a.xy for a in fig.axes[0].texts if a.arrow_patch is not None]
    i = cassini.get("moon").inclination
    # K up, k at angle i, then each state at angle i - θ from K (length 0.8).
    assert ends[0] == pytest.approx((0.0, 1.0), abs=1e-15)
    assert ends[1] == pytest.approx((math.sin(i), math.cos(i)), abs=1e-15)
    for end, state in zip(ends[2:], fig.andoyer_data, strict=True):
        inclination = math.atan2(abs(end[0]), end[1])
        assert inclination == pytest.approx(state.inclination_to_laplace, abs=1e-12)


@pytest.mark.parametrize(("system", "n"), [("moon", 5), (cassini.get("moon"), 2)])
def test_cassini_portrait_bad_input(system, n):
    with pytest.raises(ValueError, match="expected"):
        plot.cassini_portrait_data(system, n_phi=n, n_theta=n)


MERCURY = [
    *("--j2", "5.03e-5", "--c22", "0.81e-5", "--orbital-period", "87.97", "--eccentricity", "0.2056"),
    *("--node-period", "325000", "--inclination", "8.6", "--mass-ratio", "1.66e-7", "--resonance", "1.5"),
]


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        ([*MERCURY, "--moment-of-inertia", "2"], "expected a polar moment of inertia 0 < C/MR^2 <= 1 ("),
        (["--moment-of-inertia", "0.3"], "expected every value option or none"),
        (["--body", "titan", "--node", "catalogue"], "expected Titan to have node_period"),
    ],
)
def test_portrait_cassini_cli_bad_input_exit_2(tmp_path, capsys, argv, message):
    try:
        code = main(["portrait", "cassini", *argv, "--out", str(tmp_path / "x.png")])
    except SystemExit as exc:  # refused as the arguments are read
        code = exc.code
    err = capsys.readouterr().err
    assert code == 2
    (line,) = err.strip().splitlines()
    assert line.startswith("andoyer portrait")
    assert message in line
    assert list(tmp_path.iterdir()) == []


def test_portrait_cassini_cli_titan(tmp_path):
    assert (
        main(
            [
                "portrait",
                "cassini",
                "--body",
                "titan",
                "--levels",
                "3",
                "--dpi",
                "20",
                "--out",
                str(tmp_path / "t.png"),
            ]
        )
        == 0
    )
    assert (tmp_path / "t.png").stat().st_size > 0
