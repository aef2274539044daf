"""Regime classification (exact for the floating-point inputs) and input validation."""

import math
from fractions import Fraction

import numpy as np
import pytest

from andoyer.free import Regime, classify
from andoyer.free.common.scaling import scale_exponents
from andoyer.free.common.scaling_numpy import normalise
from andoyer.regime import check_inputs


def _exact_regime(moments, m0):
    """SAM/LAM/separatrix from the sign of G²/B − D in exact rational arithmetic."""
    A, B, C = sorted(Fraction(float(x)) for x in moments)
    order = np.argsort(moments, kind="stable")
    ma, mb, mc = (Fraction(float(m0[i])) for i in order)
    p2 = (ma**2 + mb**2 + mc**2) / B - (ma**2 / A + mb**2 / B + mc**2 / C)
    return Regime.SAM if p2 > 0 else Regime.LAM if p2 < 0 else Regime.SEPARATRIX


@pytest.mark.parametrize(
    ("moments", "m0", "regime"),
    [
        ([1.0, 2.0, 3.0], [0.1, 0.2, 1.0], Regime.SAM),
        ([1.0, 2.0, 3.0], [1.0, 0.2, 0.1], Regime.LAM),
        ([1.0, 2.0, 3.0], [0.0, 1.0, 0.0], Regime.SEPARATRIX),
        ([3.0, 4.0, 6.0], [1.0, 0.3, 1.0], Regime.SEPARATRIX),
        ([3.0, 4.0, 6.0], [1.0, 0.3, -1.0], Regime.SEPARATRIX),
        ([1.0, 2.0, 3.0], [0.0, 0.0, 5.0], Regime.SAM),
        ([1.0, 2.0, 3.0], [5.0, 0.0, 0.0], Regime.LAM),
        ([2.0, 2.0, 3.0], [0.3, 0.1, 1.0], Regime.AXISYMMETRIC),
        ([2.0, 3.0, 3.0], [0.3, 0.1, 1.0], Regime.AXISYMMETRIC),
        ([2.0, 2.0, 2.0], [0.3, 0.1, 1.0], Regime.SPHERE),
        ([1.0, 2.0, 3.0], [0.0, 0.0, 0.0], Regime.REST),
    ],
)
def test_classify_canonical_states(moments, m0, regime):
    assert classify(moments, m0) == regime


def test_classify_is_exact_one_ulp_from_the_separatrix():
    # (3, 4, 6) with m1 = m3 is exactly on the separatrix; one ulp either way decides
    base = np.array([1.0, 0.7, 1.0])
    up, down = base.copy(), base.copy()
    up[2] = np.nextafter(1.0, 2.0)
    down[2] = np.nextafter(1.0, 0.0)
    moments = [3.0, 4.0, 6.0]
    got = classify(moments, np.array([base, up, down])).tolist()
    assert got == [Regime.SEPARATRIX, Regime.SAM, Regime.LAM]
    assert got == [_exact_regime(moments, m) for m in (base, up, down)]


def test_classify_matches_exact_arithmetic_on_random_and_near_separatrix_states():
    rng = np.random.default_rng(12)
    moments = rng.uniform(1.0, 2.0, (400, 3))
    m0 = rng.normal(size=(400, 3))
    # push half of them to within a few ulps of the separatrix
    for i in range(200):
        order = np.argsort(moments[i])
        A, B, C = moments[i][order]
        ratio = np.sqrt((1 / A - 1 / B) / (1 / B - 1 / C))
        m0[i, order[2]] = m0[i, order[0]] * ratio * (1 + rng.integers(-3, 4) * 2.2e-16)
    got = classify(moments, m0)
    want = [_exact_regime(moments[i], m0[i]) for i in range(400)]
    assert got.tolist() == want


def test_classify_is_invariant_under_axis_relabelling():
    rng = np.random.default_rng(3)
    moments = rng.uniform(1.0, 2.0, (50, 3))
    m0 = rng.normal(size=(50, 3))
    base = classify(moments, m0)
    for perm in ([1, 2, 0], [2, 0, 1], [0, 2, 1]):
        assert np.array_equal(classify(moments[:, perm], m0[:, perm]), base)


def test_classify_broadcasts_and_scalar_shape():
    assert classify([1.0, 2.0, 3.0], [0.1, 0.2, 1.0]).shape == ()
    moments = np.array([1.0, 2.0, 2.5]) * np.ones((4, 1, 3))
    assert classify(moments, np.ones((5, 3))).shape == (4, 5)


@pytest.mark.parametrize(
    ("moments", "m0", "message"),
    [
        ([1.0, 2.0], [0.0, 0.0, 1.0], r"moments with shape \(\.\.\., 3\)"),
        ([1.0, 2.0, 3.0], [0.0, 1.0], r"m0 with shape \(\.\.\., 3\)"),
        ([1.0, -2.0, 3.0], [0.0, 0.0, 1.0], "positive moments"),
        ([1.0, 0.0, 1.0], [0.0, 0.0, 1.0], "positive moments"),
        ([1.0, np.nan, 2.0], [0.0, 0.0, 1.0], "finite moments"),
        ([1.0, 2.0, 2.0], [0.0, np.inf, 1.0], "finite m0"),
    ],
)
def test_bad_inputs_raise(moments, m0, message):
    with pytest.raises(ValueError, match=message):
        check_inputs(moments, m0)


def test_flat_body_is_allowed():
    # A + B = C (a lamina) satisfies the triangle inequality
    assert classify([1.0, 2.0, 3.0], [0.1, 0.2, 1.0]) == Regime.SAM


@pytest.mark.parametrize(
    ("moments", "m", "a", "b"),
    [
        ((3.0, 4.0, 6.0), (0.0, 48.0, 0.0), 3, 6),  # 6 = 0.75·2³, 48 = 0.75·2⁶
        ((0.5, 0.25, 0.75), (-1.0, 0.0, 0.5), 0, 1),
        ((1.0, 1.0, 1.0), (0.0, 0.0, 0.0), 1, 1),  # rest: the exponent of 1
        ((1e300, 1.0, 1.0), (5e-324, 0.0, 0.0), 997, -1073),
    ],
)
def test_scale_exponents_put_the_largest_in_half_open_unit(moments, m, a, b):
    got = scale_exponents(*moments, *m)
    assert (int(got[0]), int(got[1])) == (a, b)
    assert 0.5 <= max(moments) / 2.0**a < 1.0
    assert max(map(abs, m)) == 0 or 0.5 <= math.ldexp(max(map(abs, m)), -b) < 1.0
    i, x, a2, b2 = normalise(np.array(moments), np.array(m))
    assert (int(a2), int(b2)) == (a, b)
    assert np.array_equal(i, np.ldexp(moments, -a))
    assert np.array_equal(x, np.ldexp(m, -b))
