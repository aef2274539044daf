"""Lara's Fig. 1: free body vs. the main problem of SAM rotation, checked against the library."""

import numpy as np
import pytest

from andoyer import RigidBody
from andoyer.plot import LARA_LEVELS, lara_portrait, lara_portrait_data
from andoyer.state import andoyer_hamiltonian
from andoyer.state.sam import sam_from_andoyer

BETA = 0.8


def test_lara_levels_are_the_papers():
    # Lara (2013) §3: "contours H0* = A* = q for q = 0.002, 0.007, ..., 0.32, and 0.38".
    assert LARA_LEVELS == (0.002, 0.007, 0.015, 0.023, 0.035, 0.048, 0.08, 0.12, 0.18, 0.25, 0.32, 0.38)


@pytest.mark.parametrize("alpha", [0.05, 0.3])
def test_free_contours_are_level_sets_of_the_free_hamiltonian(alpha):
    # H0* = (2C H0/M² − 1)/α with H0 the library's Andoyer Hamiltonian (Gurfil eq. 89) of a body
    # with Andoyer parameters (α, β): independent of the closed form used for the curves.
    body = RigidBody.from_alpha_beta(alpha, BETA)
    data = lara_portrait_data()
    G = 1.7
    for q, x in zip(data.levels, data.free, strict=True):
        ok = np.isfinite(x)
        H = andoyer_hamiltonian(body, data.nu[ok], G * x[ok], G)
        scaled = (2 * body.C * H / G**2 - 1) / alpha
        np.testing.assert_allclose(scaled, q, rtol=1e-11)


def test_main_problem_contours_are_level_sets_of_the_sam_action():
    # In Lara's SAM action-angle variables the main problem is A = G²/2C (1 + 2αs L/G) (eqs. 6,
    # 21, 27), so A* = 2 s L/G with L from the library's SAM chart (andoyer.state.sam).
    data = lara_portrait_data()
    s = np.sqrt(1 - BETA**2)
    G = 1.0
    for q, x in zip(data.levels, data.main, strict=True):
        ok = x > 0
        sam = sam_from_andoyer(data.nu[ok], 0.0, 0.0, G * x[ok], G, 0.5, beta=BETA)
        np.testing.assert_allclose(2 * s * sam.sam_L / G, q, rtol=1e-12)


def test_free_and_main_contours_agree_to_second_order_in_delta():
    # The contours differ by the dropped perturbation εP (eq. 7), O(δ²) with δ = L/(G√(1−β²))
    # Lara's small parameter: 1 − N/M = (1 − β²) δ / (1 − β cos 2ν) ≤ (1 + β) δ, and at equal ν
    # x_A − x_H = ½u² + ½u³ + ..., u = 1 − x_A, bounded by ½ (1 + β)² δ² (1 + 2 (1 + β) δ).
    data = lara_portrait_data(n_points=181)
    s = np.sqrt(1 - BETA**2)
    worst = 0.0
    for x_h, x_a in zip(data.free, data.main, strict=True):
        ok = np.isfinite(x_h) & (x_a >= data.ratio_min)
        delta = sam_from_andoyer(data.nu[ok], 0.0, 0.0, x_a[ok], 1.0, 0.5, beta=BETA).sam_L / s
        bound = 0.5 * (1 + BETA) ** 2 * delta**2 * (1 + 2 * (1 + BETA) * delta)
        gap = x_a[ok] - x_h[ok]
        assert np.all(gap >= 0)  # the main problem lies above: εP < 0
        assert np.all(gap <= bound)
        # ... and the second order is sharp: gap / (½u²) → 1 as u → 0.
        u = 1 - x_a[ok]
        small = u < 0.01
        np.testing.assert_allclose(gap[small] / (0.5 * u[small] ** 2), 1.0, atol=0.011)
        worst = max(worst, float(np.max(gap)))
    assert worst < 0.012  # visible at the bottom of the window, as in Lara's figure


def test_lara_portrait_figure_content():
    fig = lara_portrait(n_points=241)
    ax = fig.axes[0]
    data = fig.andoyer_data
    assert ax.get_ylim() == (0.88, 1.0)
    assert ax.get_xlim() == (0.0, np.pi)
    solid = [ln for ln in ax.get_lines() if ln.get_linestyle() == "-"]
    dashed = [ln for ln in ax.get_lines() if ln.get_linestyle() == "--"]
    assert len(solid) == len(dashed) == 12
    np.testing.assert_array_equal(solid[3].get_ydata(), data.free[3])
    np.testing.assert_array_equal(dashed[3].get_ydata(), data.main[3])
    assert "0.8" in ax.get_title()


def test_lara_portrait_uses_a_bodys_beta():
    body = RigidBody.from_alpha_beta(0.1, 0.5)
    data = lara_portrait_data(body.beta, [0.01])
    k = 1 - 0.5 * np.cos(2 * data.nu)
    np.testing.assert_allclose(data.main[0], 1 - 0.01 / (2 * k), rtol=1e-15)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"beta": 1.0}, "beta"),
        ({"beta": -0.1}, "beta"),
        ({"levels": [0.1, -0.2]}, "positive levels"),
        ({"ratio_min": 1.0}, "ratio_min"),
        ({"nu_range": (1.0, 0.0)}, "nu_range"),
        ({"n_points": 1}, "n_points"),
    ],
)
def test_lara_portrait_rejects_bad_input(kwargs, match):
    with pytest.raises(ValueError, match=match):
        lara_portrait_data(**kwargs)
