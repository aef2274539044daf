"""The (l, L) phase portrait (Gurfil Fig. 4): separatrix through the saddles, exact contours."""

import numpy as np
import pytest

from andoyer import RigidBody, bodies
from andoyer.plot import phase_portrait, phase_portrait_data
from andoyer.state import andoyer_hamiltonian

ABC = RigidBody(1.0, 2.0, 3.0)  # b2 intermediate: saddles at l = 0, ±π
BAC = RigidBody(2.0, 1.0, 2.5)  # b1 intermediate: saddles at l = ±π/2


def _points(curves):
    p = np.concatenate(curves)
    return p[np.isfinite(p[:, 0])]


def _hessian(body, l, L, G, h=1e-4):
    def H(a, b):
        return float(andoyer_hamiltonian(body, a, b, G))

    Hll = (H(l + h, L) - 2 * H(l, L) + H(l - h, L)) / h**2
    HLL = (H(l, L + h) - 2 * H(l, L) + H(l, L - h)) / h**2
    HlL = (H(l + h, L + h) - H(l + h, L - h) - H(l - h, L + h) + H(l - h, L - h)) / (4 * h * h)
    grad = ((H(l + h, L) - H(l - h, L)) / (2 * h), (H(l, L + h) - H(l, L - h)) / (2 * h))
    return np.array(grad), Hll * HLL - HlL**2


@pytest.mark.parametrize(
    ("body", "saddles"),
    [(ABC, [(-np.pi, 0.0), (0.0, 0.0), (np.pi, 0.0)]), (BAC, [(-np.pi / 2, 0.0), (np.pi / 2, 0.0)])],
    ids=["b2-intermediate", "b1-intermediate"],
)
@pytest.mark.parametrize("G", [1.0, 3.0])
def test_separatrix_passes_through_the_saddle_points(body, saddles, G):
    data = phase_portrait_data(body, G)
    np.testing.assert_allclose(data.saddles, saddles, atol=0)
    assert data.separatrix_energy == G * G / (2 * body.B)
    sep = _points(data.separatrix)
    for l0, L0 in saddles:
        # Independent: grad H = 0 and det Hess H < 0 (a saddle) by finite differences of eq. 89.
        grad, det = _hessian(body, l0, L0, G)
        assert np.max(np.abs(grad)) < 1e-9 * G * G
        assert det < 0
        assert float(andoyer_hamiltonian(body, l0, L0, G)) == pytest.approx(data.separatrix_energy, rel=1e-15)
        # The separatrix goes through the point (both branches: the curve is sampled through it).
        dist = np.hypot(np.angle(np.exp(1j * (sep[:, 0] - l0))), sep[:, 1] - L0)
        assert np.sum(dist < 1e-12) >= 2
    # Every separatrix point at the saddle energy, by the library's Hamiltonian (Gurfil eq. 89).
    np.testing.assert_allclose(
        andoyer_hamiltonian(body, sep[:, 0], sep[:, 1], G), G * G / (2 * body.B), rtol=1e-14
    )


def test_separatrix_width_matches_closed_form():
    # From eq. 89 at H = G²/2B: L² = G² (f − 1/B)/(f − 1/C), f = sin²l/A + cos²l/B; at l = ±π/2
    # (f = 1/A) the separatrix reaches |L| = G √((1/A − 1/B)/(1/A − 1/C)).
    data = phase_portrait_data(ABC, 1.0, n_points=4001)
    sep = _points(data.separatrix)
    near = np.abs(np.abs(sep[:, 0]) - np.pi / 2) < 2e-3
    expected = np.sqrt((1 - 1 / 2) / (1 - 1 / 3))
    np.testing.assert_allclose(np.abs(sep[near, 1]), expected, rtol=1e-5)
    f = np.sin(sep[:, 0]) ** 2 / 1.0 + np.cos(sep[:, 0]) ** 2 / 2.0
    np.testing.assert_allclose(sep[:, 1] ** 2, (f - 1 / 2) / (f - 1 / 3), atol=1e-14)


@pytest.mark.parametrize(
    "body", [ABC, BAC, RigidBody(3.0, 1.0, 2.0), bodies.get("eros"), bodies.get("earth")]
)
def test_phase_contours_are_at_their_energies(body):
    data = phase_portrait_data(body, 2.0, n_points=241)
    for energy, curves in zip(data.energies, data.contours, strict=True):
        p = _points(curves)
        assert np.all(np.abs(p[:, 0]) <= np.pi)
        assert np.all(np.abs(p[:, 1]) <= 2.0)
        np.testing.assert_allclose(andoyer_hamiltonian(body, p[:, 0], p[:, 1], 2.0), energy, rtol=1e-13)


def test_phase_contours_break_at_the_wrap():
    data = phase_portrait_data(ABC, 1.0)
    for curves in data.contours:
        for curve in curves:
            steps = np.abs(np.diff(curve[:, 0]))
            assert np.nanmax(steps) < 0.1  # no line drawn across the plane at l = ±π


def test_phase_portrait_figure_content():
    fig = phase_portrait(ABC, 1.0, n_points=361)
    data = fig.andoyer_data
    ax = fig.axes[0]
    assert ax.get_xlim() == (-np.pi, np.pi)
    assert ax.get_xlabel() == "$l$ (rad)"
    red = [ln for ln in ax.get_lines() if ln.get_color() == "tab:red"]
    assert len(red) == 6  # two circles, each drawn at l, l ± 2π
    for line in red:
        l, L = line.get_xdata(), line.get_ydata()
        ok = np.isfinite(l) & (np.abs(l) <= np.pi)
        np.testing.assert_allclose(andoyer_hamiltonian(ABC, l[ok], L[ok], 1.0), 0.25, rtol=1e-14)
    marks = [ln for ln in ax.get_lines() if ln.get_marker() == "x"]
    np.testing.assert_allclose(np.column_stack(marks[0].get_data()), data.saddles)
    contours = [ln for ln in ax.get_lines() if ln.get_color() in ("tab:blue", "tab:green")]
    assert len(contours) == 3 * 2 * len(data.energies)
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert labels == ["SAM", "LAM", "separatrix $\\mathcal{H} = G^2/2B$", "saddle points"]


def test_phase_portrait_draws_into_given_axes():
    from matplotlib.figure import Figure

    fig = Figure()
    left, right = fig.subplots(1, 2)
    assert phase_portrait(ABC, ax=right) is fig
    assert not left.get_lines()
    assert right.get_lines()
    with pytest.raises(ValueError, match="matplotlib Axes"):
        phase_portrait(ABC, ax="not an axes")


@pytest.mark.parametrize(
    ("unit", "expected"), [(None, "inertia × rad per unit time"), ("C rad/s", "C rad/s")]
)
def test_phase_portrait_momentum_axis_has_a_unit(unit, expected):
    ax = phase_portrait(ABC, 2.0, n_points=61, momentum_unit=unit).axes[0]
    assert ax.get_ylabel() == f"$L = G\\cos J$ ({expected})"
    assert ax.get_xlabel() == "$l$ (rad)"
