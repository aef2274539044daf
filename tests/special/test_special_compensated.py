"""Double-double arithmetic against exact rational arithmetic."""

from fractions import Fraction

import mpmath as mp
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from andoyer.special.agm import agm_dd, ellipk_dd, ellippi_dd, ellippi_k_dd
from andoyer.special.compensated import (
    PI_DD,
    dd_add,
    dd_div,
    dd_mul,
    dd_sqrt,
    split,
    two_prod,
    two_sum,
)

finite = st.floats(min_value=-1e100, max_value=1e100, allow_nan=False, allow_subnormal=False)


def _exact(hi, lo):
    return Fraction(float(hi)) + Fraction(float(lo))


@given(finite, finite)
@settings(max_examples=300, deadline=None)
def test_two_sum_is_error_free(a, b):
    s, e = two_sum(a, b)
    assert Fraction(float(s)) + Fraction(float(e)) == Fraction(a) + Fraction(b)


@given(finite, finite)
@settings(max_examples=300, deadline=None)
def test_two_prod_is_error_free(a, b):
    p, e = two_prod(a, b)
    if abs(a * b) > 1e-290:  # below, the error term itself underflows
        assert Fraction(float(p)) + Fraction(float(e)) == Fraction(a) * Fraction(b)


@given(finite)
@settings(max_examples=200, deadline=None)
def test_split_halves_are_exact_and_short(a):
    hi, lo = split(a)
    assert float(hi) + float(lo) == a
    for h in (float(hi), float(lo)):
        mantissa = Fraction(h).numerator if h else 0
        while mantissa and mantissa % 2 == 0:
            mantissa //= 2
        assert abs(mantissa) < 2**27


@pytest.mark.parametrize("op", ["add", "mul", "div", "sqrt"])
def test_dd_operations_have_106_bit_accuracy(op):
    rng = np.random.default_rng(4)
    a = rng.uniform(0.1, 10.0, 200)
    b = rng.uniform(0.1, 10.0, 200)
    al, bl = a * 1e-17 * rng.uniform(-1, 1, 200), b * 1e-17 * rng.uniform(-1, 1, 200)
    fn = {"add": dd_add, "mul": dd_mul, "div": dd_div}.get(op)
    hi, lo = fn(a, al, b, bl) if fn else dd_sqrt(a, al)
    for i in range(a.size):
        x, y = _exact(a[i], al[i]), _exact(b[i], bl[i])
        got = _exact(hi[i], lo[i])
        if op == "sqrt":
            # compare squares: |got² − x| / x
            assert abs(got * got - x) / x < Fraction(1, 2**102)
            continue
        want = {"add": x + y, "mul": x * y, "div": x / y}[op]
        assert abs(got - want) / abs(want) < Fraction(1, 2**102)


def test_pi_double_double_matches_mpmath():
    with mp.workdps(50):
        assert abs(mp.mpf(PI_DD[0]) + mp.mpf(PI_DD[1]) - mp.pi) < mp.mpf(10) ** -32


@pytest.mark.parametrize(
    ("mc", "digits"),
    [
        (0.5, 30),
        (1e-3, 30),
        (1e-10, 30),
        (1e-40, 30),
        (2.0, 30),
        (1.0, 30),
        (1e-300, 25),
    ],  # the low parts underflow below 1e-290
)
def test_ellipk_dd_has_double_double_accuracy(mc, digits):
    hi, lo = ellipk_dd(mc)
    with mp.workdps(400):
        ref = mp.ellipk(1 - mp.mpf(mc))
        got = mp.mpf(float(hi)) + mp.mpf(float(lo))
        assert abs(got - ref) / ref < mp.mpf(10) ** -digits


def test_ellipk_dd_is_infinite_at_m_one():
    hi, lo = ellipk_dd(0.0)
    assert np.isinf(hi)
    assert lo == 0


@pytest.mark.parametrize(
    ("n", "mc"), [(-0.5, 0.5), (-30.0, 0.1), (-1e-4, 0.9), (0.7, 0.3), (-3.0, 1e-12), (0.0, 0.5)]
)
def test_ellippi_dd_has_double_double_accuracy(n, mc):
    hi, lo = ellippi_dd(n, 0.0, mc)
    with mp.workdps(60):
        ref = mp.ellippi(n, 1 - mp.mpf(mc))
        got = mp.mpf(float(hi)) + mp.mpf(float(lo))
        assert abs(got - ref) / abs(ref) < mp.mpf(10) ** -29


def test_agm_of_zero_is_zero():
    hi, lo = agm_dd(1.0, 0.0, 0.0, 0.0)
    assert hi == 0
    assert lo == 0


def _dd_kernel_loop():
    from andoyer._jit import jit

    @jit
    def loop(ah, al, bh, bl, out):
        for i in range(ah.shape[0]):
            out[i, 0], out[i, 1] = dd_add(ah[i], al[i], bh[i], bl[i])
            out[i, 2], out[i, 3] = dd_mul(ah[i], al[i], bh[i], bl[i])
            out[i, 4], out[i, 5] = dd_div(ah[i], al[i], bh[i], bl[i])
            out[i, 6], out[i, 7] = dd_sqrt(abs(ah[i]), abs(ah[i]) * 1e-17)
            out[i, 8], out[i, 9] = two_prod(ah[i], bh[i])
            n, mc = -abs(al[i]) * 1e16, abs(bh[i]) / 10.0
            out[i, 10], out[i, 11], out[i, 12], out[i, 13] = ellippi_k_dd(n, 0.0, mc, 0.0)

    return loop


def test_dd_kernels_per_element_equal_array_evaluation_bit_for_bit():
    """One text, two paths: per element (compiled when numba is) and over whole numpy arrays."""
    rng = np.random.default_rng(11)
    n = 500
    ah = rng.uniform(-10.0, 10.0, n)
    al = ah * rng.uniform(-1e-17, 1e-17, n)
    bh = rng.uniform(0.1, 10.0, n)
    bl = bh * rng.uniform(-1e-17, 1e-17, n)
    out = np.empty((n, 14))
    _dd_kernel_loop()(ah, al, bh, bl, out)
    expected = [
        *dd_add(ah, al, bh, bl),
        *dd_mul(ah, al, bh, bl),
        *dd_div(ah, al, bh, bl),
        *dd_sqrt(np.abs(ah), np.abs(ah) * 1e-17),
        *two_prod(ah, bh),
        *ellippi_k_dd(-np.abs(al) * 1e16, 0.0, bh / 10.0, 0.0),
    ]
    np.testing.assert_array_equal(out, np.stack(expected, axis=-1))


def test_dd_operations_defined_once():
    """No module other than special.compensated / special.agm defines a double-double operation."""
    import ast
    import pathlib

    import andoyer

    names = {"two_sum", "fast_two_sum", "_fast_two_sum", "two_prod", "split", "dd_add", "dd_mul", "dd_div"}
    names |= {"dd_sqrt", "agm_dd", "ellipk_dd", "ellippi_dd", "ellippi_k_dd", "product_error"}
    root = pathlib.Path(andoyer.__file__).parent
    owners = {}
    for path in root.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.FunctionDef) and node.name in names:
                owners.setdefault(node.name, set()).add(path.relative_to(root).as_posix())
    allowed = {"special/compensated.py", "special/agm.py"}
    assert {name: paths for name, paths in owners.items() if not paths <= allowed} == {}
    assert all(len(paths) == 1 for paths in owners.values()), owners
