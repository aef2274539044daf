"""The branch and loop helpers of kernels written once for compiled scalars and numpy arrays."""

import numpy as np
import pytest

from andoyer._jit import every, jit, select


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
