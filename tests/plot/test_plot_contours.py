"""Exact energy contours on the momentum sphere: on both surfaces, and the actual polhodes."""

import numpy as np
import pytest

from andoyer import FreeRotation, RigidBody, State, bodies
from andoyer.plot import (
    default_energies,
    energy_contour,
    momentum_sphere,
    momentum_sphere_data,
    separatrix_contour,
)
from andoyer.plot.projection import Orthographic

BODIES = {
    "ABC": RigidBody(1.0, 2.0, 3.0),
    "CAB": RigidBody(3.0, 1.0, 2.0),  # b2 is the minimum, b3 intermediate
    "BAC": RigidBody(2.0, 1.0, 2.5),  # b1 intermediate
    "earth": bodies.get("earth"),  # A ≈ B to 2e-6: cancellation-prone
    "eros": bodies.get("eros"),
    "oblate": RigidBody(1.0, 1.0, 1.5),
    "prolate": RigidBody(0.5, 1.0, 1.0),
}


def _levels(body, G):
    A, B, C = body.sorted_moments
    extra = [G * G / (2 * C), G * G / (2 * A)]
    if A < B < C:  # just either side of the separatrix
        extra += [G * G / (2 * B) * (1 - 1e-9), G * G / (2 * B) * (1 + 1e-9)]
    return np.concatenate([default_energies(body, G, 4), extra])


@pytest.mark.parametrize("name", BODIES)
@pytest.mark.parametrize("G", [1.0, 37.5])
def test_energy_contour_lies_on_sphere_and_ellipsoid(name, G):
    body = BODIES[name]
    for energy in _levels(body, G):
        curves = energy_contour(body, G, energy, n_points=181)
        assert len(curves) == 2
        for m in curves:
            assert m.shape == (181, 3)
            np.testing.assert_allclose(np.linalg.norm(m, axis=-1), G, rtol=2e-15)
            # Energy recomputed from the components in exact Fraction-free long form.
            T = 0.5 * (m[:, 0] ** 2 / body.I1 + m[:, 1] ** 2 / body.I2 + m[:, 2] ** 2 / body.I3)
            np.testing.assert_allclose(T, energy, rtol=2e-15)
            np.testing.assert_array_equal(m[0], m[-1])  # closed


@pytest.mark.parametrize("name", ["ABC", "CAB", "eros", "earth"])
@pytest.mark.parametrize("regime", ["SAM", "LAM"])
def test_energy_contour_is_the_polhode_of_the_exact_motion(name, regime):
    # The exact free motion (andoyer.free, elliptic functions) must run along the closed-form
    # curve: every propagated m(t) is within a chord of some curve point.
    body = BODIES[name]
    B = body.B
    lo, mid, hi = body.axis_order
    # The extreme axis opposite the circulation axis gets a component well inside the regime
    # (the separatrix planes have slope κ, Gurfil eq. 139).
    axis, other, scale = (hi, lo, 1 / body.kappa) if regime == "SAM" else (lo, hi, body.kappa)
    m0 = np.zeros(3)
    m0[[axis, mid, other]] = 1.0, 0.4, 0.3 * min(1.0, scale)
    state = State.from_quaternion([0, 0, 0, 1.0], m0)
    G, energy = float(np.linalg.norm(m0)), float(state.energy(body))
    assert (2 * energy * B < G * G) == (regime == "SAM")
    free = FreeRotation(body)
    T = float(free.periods(state).period)
    path = free.momentum(state, np.linspace(0.0, T, 97))
    curve = np.concatenate(energy_contour(body, G, energy, n_points=2001))
    gaps = np.min(np.linalg.norm(path[:, None, :] - curve[None, :, :], axis=-1), axis=1)
    chord = np.max(np.linalg.norm(np.diff(curve, axis=0), axis=-1)[np.isfinite(curve[1:, 0])])
    assert np.max(gaps) <= chord


@pytest.mark.parametrize("name", BODIES)
def test_separatrix_is_two_great_circles_through_the_intermediate_axis(name):
    body = BODIES[name]
    G = 2.0
    circles = separatrix_contour(body, G, n_points=721)
    B = body.B
    e_mid = np.zeros(3)
    e_mid[body.axis_order[1]] = G
    for m in circles:
        np.testing.assert_allclose(body.energy(m), G * G / (2 * B), rtol=2e-15)
        # A great circle: its points span a plane through the origin (rank 2).
        assert np.linalg.svd(m, compute_uv=False)[2] < 1e-12 * G
        assert (
            min(np.min(np.linalg.norm(m - e_mid, axis=-1)), np.min(np.linalg.norm(m + e_mid, axis=-1)))
            < 1e-12
        )


def test_separatrix_plane_angle_is_sadov_kappa():
    # Gurfil eq. 139: tan χ = κ with the circles in the planes x sin χ = ±z cos χ.
    body = RigidBody(1.0, 2.0, 3.0)
    m = separatrix_contour(body, 1.0)[0]
    x, z = m[:, 0], m[:, 2]
    ok = np.abs(x) > 0.1
    np.testing.assert_allclose(np.abs(z[ok] / x[ok]), body.kappa, rtol=1e-14)


def test_default_energies_split_evenly_about_the_separatrix():
    body = RigidBody(1.0, 2.0, 3.0)
    e = 2 * default_energies(body, 1.0, 3)  # 2T/G²
    np.testing.assert_allclose(e[:3], 1 / 3 + np.array([1, 2, 3]) / 4 * (1 / 2 - 1 / 3), rtol=1e-15)
    np.testing.assert_allclose(e[3:], 1 / 2 + np.array([1, 2, 3]) / 4 * (1 - 1 / 2), rtol=1e-15)
    assert len(default_energies(RigidBody(1.0, 1.0, 1.5), 1.0, 3)) == 3  # oblate: SAM only


@pytest.mark.parametrize(
    ("args", "match"),
    [
        ((RigidBody(1.0, 1.0, 1.0), 1.0, 0.5), "unequal moments"),
        ((RigidBody(1.0, 2.0, 3.0), 1.0, 0.6), "energy <="),
        ((RigidBody(1.0, 2.0, 3.0), 1.0, 0.1), "energy <="),
        ((RigidBody(1.0, 2.0, 3.0), -1.0, 0.2), "G > 0"),
        ((RigidBody(1.0, 2.0, 3.0), 1.0, float("nan")), "finite"),
    ],
)
def test_energy_contour_rejects_bad_input(args, match):
    with pytest.raises(ValueError, match=match):
        energy_contour(*args)


def test_momentum_sphere_rejects_energy_outside_the_sphere():
    with pytest.raises(ValueError, match="expected energies"):
        momentum_sphere_data(RigidBody(1.0, 2.0, 3.0), 1.0, [0.2, 0.9])


def test_momentum_sphere_draws_the_data_in_projection():
    body = RigidBody(1.0, 2.0, 3.0)
    elev, azim = 0.3, 1.1
    fig = momentum_sphere(body, 2.0, elev=elev, azim=azim, n_points=181)
    data = fig.andoyer_data
    assert data.separatrix_energy == 2.0**2 / (2 * 2.0)
    assert len(data.energies) == 10
    for energy, curves in zip(data.energies, data.contours, strict=True):
        for m in curves:
            np.testing.assert_allclose(np.linalg.norm(m, axis=-1), 2.0, rtol=1e-14)
            np.testing.assert_allclose(body.energy(m), energy, rtol=1e-14)
    # Drawn lines: visible part (solid) then hidden part (dotted) of each curve, in that order.
    view = Orthographic(elev, azim)
    r, u, v = view.basis
    ax = fig.axes[0]
    solid = [ln for ln in ax.get_lines() if ln.get_linestyle() == "-" and len(ln.get_xdata()) == 181]
    assert len(solid) == 2 * len(data.energies) + 2
    first = data.contours[0][0]
    xy = np.column_stack([solid[0].get_xdata(), solid[0].get_ydata()])
    front = first @ v >= 0
    np.testing.assert_allclose(xy[front], np.column_stack([first @ r, first @ u])[front], rtol=0, atol=1e-15)
    # The projection is orthographic: screen basis orthonormal, all curve points inside the disc.
    np.testing.assert_allclose(np.array([r, u, v]) @ np.array([r, u, v]).T, np.eye(3), atol=1e-15)
    assert np.nanmax(np.hypot(xy[:, 0], xy[:, 1])) <= 2.0 + 1e-12
    labels = {t.get_text() for t in ax.get_legend().get_texts()}
    assert labels == {"SAM", "LAM", "separatrix $T = G^2/2B$"}
