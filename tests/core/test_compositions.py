"""andoyer.compositions: the exact rotation about an axis and the composition schemes, checked independently.

The rotation against scipy's ``Rotation.from_rotvec`` (another formula for the same map); the
composition weights by the local error of composed Strang steps of two random matrix flows in
mpmath (its order is the scheme's order plus one).
"""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from andoyer.compositions import COMPOSITIONS, splitting_coefficients, turn_about, turn_about_series


def _local_error(weights, A, B, h):
    """``|S(γ_s h)⋯S(γ_1 h) − exp((A + B) h)|`` with ``S(x) = exp(A x/2) exp(B x) exp(A x/2)``."""
    step = mpmath.eye(3)
    for gamma in weights:
        x = mpmath.mpf(float(gamma)) * h
        step = mpmath.expm(A * x / 2) * mpmath.expm(B * x) * mpmath.expm(A * x / 2) * step
    return mpmath.mnorm(step - mpmath.expm((A + B) * h), 1)


def _random_flows():
    rng = np.random.default_rng(7)
    A = mpmath.matrix(rng.standard_normal((3, 3)).tolist())
    B = mpmath.matrix(rng.standard_normal((3, 3)).tolist())
    return A, B


@pytest.mark.parametrize(("order", "h"), [(4, "0.1"), (6, "0.2"), (8, "0.4")])
def test_compositions_order_conditions(order, h):
    """Strang steps of exp(A), exp(B) composed with γ: local error ∝ h^(order+1), in mpmath.

    At h = 0.01 all that is left for orders 6 and 8 is the rounding of γ to doubles
    (~1e-16 h): a wrong digit of a published coefficient would show there (the order-4
    triple jump is computed in closed form).
    """
    with mpmath.workdps(50):
        A, B = _random_flows()
        h = mpmath.mpf(h)
        weights = COMPOSITIONS[order]
        slope = float(mpmath.log(_local_error(weights, A, B, h) / _local_error(weights, A, B, h / 2), 2))
        assert order + 1 - 0.35 < slope < order + 1 + 0.1
        assert order == 4 or _local_error(weights, A, B, mpmath.mpf("0.01")) < 1e-16


@pytest.mark.parametrize(("order", "h"), [(4, "0.1"), (6, "0.2")])
def test_compositions_splitting_coefficients_order_conditions(order, h):
    """Yoshida's triple jump and solution A: local error ∝ h^(order+1), as for :data:`COMPOSITIONS`."""
    weights = splitting_coefficients(order)
    with mpmath.workdps(50):
        A, B = _random_flows()
        h = mpmath.mpf(h)
        slope = float(mpmath.log(_local_error(weights, A, B, h) / _local_error(weights, A, B, h / 2), 2))
    assert order + 1 - 0.35 < slope < order + 1 + 0.1


@pytest.mark.parametrize("order", [2, 4, 6])
def test_splitting_coefficients_sum_and_symmetry(order):
    w = np.array(splitting_coefficients(order))
    assert w.sum() == pytest.approx(1.0, abs=1e-14)
    assert np.allclose(w, w[::-1])


def test_compositions_splitting_coefficients_other_order_raises():
    with pytest.raises(ValueError, match="expected a splitting order of 2, 4 or 6, got 8"):
        splitting_coefficients(8)


def _axes_and_vectors(n):
    rng = np.random.default_rng(11)
    k = rng.standard_normal((n, 3))
    k /= np.linalg.norm(k, axis=-1, keepdims=True)
    return k, rng.standard_normal((n, 3)), rng.uniform(-3.0, 3.0, n)


def test_compositions_turn_about_is_the_rotation_by_rate_times_projection():
    """``x`` turned about ``k`` by ``φ = rate (k·x)``: scipy's rotation vector ``φ k`` gives the same."""
    k, x, rate = _axes_and_vectors(200)
    turned = np.stack(turn_about(*x.T, *k.T, rate), axis=-1)
    angle = rate * np.sum(k * x, axis=-1)
    expected = Rotation.from_rotvec(angle[:, None] * k).apply(x)
    scale = np.linalg.norm(x, axis=-1)
    assert np.max(np.linalg.norm(turned - expected, axis=-1) / scale) <= 4e-15
    # the flow conserves k·x and |x|
    assert np.max(np.abs(np.sum(k * turned, axis=-1) - np.sum(k * x, axis=-1)) / scale) <= 4e-15
    assert np.max(np.abs(np.linalg.norm(turned, axis=-1) - scale) / scale) <= 4e-15


@pytest.mark.parametrize("size", [1e-6, 1e-3, 0.0078, 0.0079, 0.5, 2.5])
def test_compositions_turn_about_series_equals_turn_about(size):
    """Below 1/128 rad the series of ``sin φ`` and ``1 − cos φ``, above it libm: both the rotation."""
    k, x, _ = _axes_and_vectors(50)
    for kk, xx in zip(k, x, strict=True):
        d = float(kk @ xx)
        angle = size / d  # φ = angle (k·x) = size, on both sides of the switch to libm
        series = np.array(turn_about_series(*xx.tolist(), *kk.tolist(), angle))
        exact = Rotation.from_rotvec(size * kk).apply(xx)
        assert np.linalg.norm(series - exact) <= 4e-15 * np.linalg.norm(xx)
        plain = np.array(turn_about(*xx.tolist(), *kk.tolist(), angle))
        assert np.linalg.norm(series - plain) <= 2e-15 * np.linalg.norm(xx)
