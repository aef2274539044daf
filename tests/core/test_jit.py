"""A kernel written once runs on floats, compiled and on arrays (``andoyer._jit``)."""

from __future__ import annotations

import subprocess
import sys
from math import atan2, sqrt

import numpy as np
import pytest

from andoyer._jit import NUMBA, every, jit, on_arrays, on_floats, select


def polar(x, y):
    """Radius and angle of ``(x, y)``, with a guarded division: the shape of a chart kernel."""
    r = sqrt(x * x + y * y)
    on_origin = r == 0
    return r, select(on_origin, 0.0, atan2(y, x)), select(on_origin, 1.0, x / select(on_origin, 1.0, r))


def radius_squared(x, y):
    """A kernel calling another kernel."""
    return polar(x, y)[0] * polar(x, y)[0] + select(x < 0, 0.0, min(x, y) - min(x, y))


POINTS = [(3.0, 4.0), (-3.0, 4.0), (0.0, 0.0), (0.0, -2.0), (1e-300, 1e-300), (-5.0, -1e-17)]


def test_select_on_bools_returns_the_operand_itself():
    a, b = object(), object()
    assert select(True, a, b) is a
    assert select(False, a, b) is b
    # anything else (numpy booleans, arrays) through numpy.where
    assert select(np.bool_(True), 1.0, 2.0) == 1.0
    assert select(np.array([True, False]), 1.0, 2.0).tolist() == [1.0, 2.0]


@pytest.mark.parametrize(("x", "y"), POINTS)
def test_on_floats_same_bits_as_written_kernel(x, y):
    polar_floats, _ = on_floats(polar, radius_squared)
    assert polar_floats(x, y) == polar(x, y)
    # only the chosen operand runs: no select call is left in the copy's code
    assert "select" not in polar_floats.__code__.co_names


def test_on_floats_calls_the_float_copy_of_another_kernel():
    polar_floats, radius_floats = on_floats(polar, radius_squared)
    assert radius_floats.__globals__["polar"] is polar_floats
    assert radius_floats(3.0, 4.0) == radius_squared(3.0, 4.0) == 25.0


def test_on_arrays_matches_the_kernel_elementwise():
    polar_arrays, radius_arrays = on_arrays(polar, radius_squared)
    x, y = np.array(POINTS).T
    r, angle, cosine = polar_arrays(x, y)
    # numpy's sqrt is correctly rounded as math's; arctan2 within an ulp of atan2
    expected = np.array([polar(*p) for p in POINTS]).T
    assert np.array_equal(r, expected[0])
    assert np.abs(angle - expected[1]).max() <= np.spacing(np.pi)
    assert np.array_equal(cosine, expected[2])
    assert radius_arrays.__globals__["polar"] is polar_arrays
    assert radius_arrays.__globals__["min"] is np.minimum
    assert np.allclose(radius_arrays(x, y), r * r, rtol=2e-16, atol=0)
    # the module's own names are untouched
    assert polar.__globals__["sqrt"] is sqrt


def test_jit_compiles_the_written_kernel_with_select():
    compiled = jit(polar)
    for point in POINTS:
        assert compiled(*point) == polar(*point)
    assert hasattr(compiled, "py_func") == NUMBA


def test_import_jit_loads_no_numba():
    # numba (~0.6 s) loads on the first jit or jitable call, not with the module.
    code = "import sys, andoyer._jit as j; print('numba' in sys.modules, j.NUMBA)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.split()[0] == "False"


def test_single_state_conversions_load_no_numba():
    code = (
        "import sys\n"
        "from andoyer import State\n"
        "s = State.from_euler(0.1, 0.5, 0.2, 1.0, 0.3, 0.8)\n"
        "State.from_andoyer(*s.as_andoyer()).as_euler()\n"
        "print('numba' in sys.modules)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "False"


def test_jitable_waits_for_numba_then_compiles(tmp_path):
    # A module of jitable kernels loads no numba; the first jit loads it and registers them.
    script = tmp_path / "kernels.py"
    script.write_text(
        "import sys\n"
        "from andoyer._jit import NUMBA, jit, jitable\n"
        "@jitable\n"
        "def twice(x):\n"
        "    return 2.0 * x\n"
        "before = 'numba' in sys.modules\n"
        "def caller(x):\n"
        "    return twice(x) + 1.0\n"
        "compiled = jit(caller)\n"
        "print(before, compiled(3.0), hasattr(compiled, 'py_func') == NUMBA)\n"
    )
    out = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, check=True).stdout
    assert out.split() == ["False", "7.0", "True"]

@jit
def _all_true(condition):
    return every(condition)


@jit
def _three_branches(x, flag):
    # several selects in one kernel (numba once warned on the second inlined conditional)
    a = select(flag, x / 2.0, x / 3.0)
    b = select(x > 1.0, a * a, -a)
    c = select(flag, b + 1.0, b - 1.0)
    return a, b, c


def _expected(x, flag):
    a = x / 2.0 if flag else x / 3.0
    b = a * a if x > 1.0 else -a
    return a, b, (b + 1.0 if flag else b - 1.0)


@pytest.mark.parametrize(("x", "flag"), [(0.5, True), (0.5, False), (3.0, True), (3.0, False)])
def test_select_several_in_one_kernel_on_floats(x, flag):
    assert _three_branches(x, flag) == _expected(x, flag)


def test_select_several_in_one_kernel_on_arrays():
    x = np.array([0.5, 0.5, 3.0, 3.0])
    flag = np.array([True, False, True, False])
    kernel = getattr(_three_branches, "py_func", _three_branches)  # the Python function under numba
    got = kernel(x, flag)
    want = np.array([_expected(float(a), bool(f)) for a, f in zip(x, flag, strict=True)]).T
    np.testing.assert_array_equal(np.array(got), want)


def test_every_is_all_on_arrays_and_the_condition_on_scalars():
    assert every(np.array([True, True]))
    assert not every(np.array([True, False]))
    assert _all_true(True)
    assert not _all_true(False)


def square_minus(x, c):
    """``x x − c``: a product and the sum that uses it."""
    return x * x - c


def square_minus_fused(x, c):
    """The same text, compiled with ``contract`` (a function of its own: numba caches per function)."""
    return x * x - c


def test_jit_contract_fuses_a_product_and_its_sum():
    # x = 1 + 2⁻³⁰: x² = 1 + 2⁻²⁹ + 2⁻⁶⁰ exactly; rounded once (fused) x² − (1 + 2⁻²⁹) is 2⁻⁶⁰,
    # rounded twice the 2⁻⁶⁰ is lost; without numba both run as Python and round twice
    from fractions import Fraction

    x, c = 1.0 + 2.0**-30, 1.0 + 2.0**-29
    exact = float(Fraction(x) * Fraction(x) - Fraction(c))
    assert exact == 2.0**-60
    assert jit(square_minus)(x, c) == 0.0
    assert jit(contract=True)(square_minus_fused)(x, c) == (exact if NUMBA else 0.0)
