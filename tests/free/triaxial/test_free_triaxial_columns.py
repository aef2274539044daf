"""The named columns of the compiled triaxial table (:mod:`andoyer.free.triaxial.columns`).

The layout must tile the table and match the constants of the numpy set-up
(:func:`andoyer.free.triaxial.setup_numpy.triaxial`) field by field; and no code that reads or writes
the table may index its columns with a bare number, which a syntax-tree scan of the
modules that touch it checks.
"""

import ast
import inspect

import numpy as np
import pytest

from andoyer.free import motion
from andoyer.free.common.polhode_numpy import polhode_frame
from andoyer.free.common.scaling_numpy import normalise
from andoyer.free.triaxial import columns as table
from andoyer.free.triaxial import evaluate_compiled as compiled_eval
from andoyer.free.triaxial import periodic_numpy as periodic
from andoyer.free.triaxial import setup_compiled as compiled_setup
from andoyer.free.triaxial.setup_compiled import as_triaxial, triaxial_table
from andoyer.free.triaxial.setup_numpy import triaxial

# the variable that holds the table in each module that indexes it as ``[row, column]``
# (a renamed variable makes the scan find nothing there, and the test fail)
HOLDERS = {compiled_eval: {"c"}, compiled_setup: {"out"}, periodic: {"table"}, motion: set()}
NAMES = {name for name in table.__all__ if name.isupper()}


def _numpy_constants():
    moments, m0 = np.array([[1.0, 1.7, 2.3], [1.0, 1.7, 2.3]]), np.array([[0.3, 0.2, 1.0], [1.0, 0.9, 0.2]])
    moments, m0, _, _ = normalise(moments, m0)
    lam = np.array([False, True])
    return moments, m0, lam, triaxial(polhode_frame(moments, m0, lam), np.array([[0.0, 0.0, 0.0, 1.0]] * 2))


def test_table_fields_tile_the_columns():
    columns = [c for _, start, width in table.FIELDS for c in range(start, start + width)]
    assert columns == list(range(table.NCOLUMNS))
    for name, start, _ in table.FIELDS:
        assert getattr(table, name.upper()) == start, name


def test_table_fields_match_the_numpy_constants():
    *_, const = _numpy_constants()
    fields = [(name, width) for name, _, width in table.FIELDS if name != "flat"]
    assert [name for name, _ in fields] == list(const._fields)
    for name, width in fields:
        value = getattr(const, name)
        rows = len(value) if isinstance(value, tuple) else (1 if np.ndim(value) == 1 else len(value))
        assert rows == width, name


def test_table_columns_hold_the_numpy_constants():
    moments, m0, lam, const = _numpy_constants()
    got, _ = triaxial_table(moments, m0, lam, np.array([[0.0, 0.0, 0.0, 1.0]] * 2))
    # scalar fields read by name agree with the numpy set-up (a swapped column would not)
    for name in ("frac0", "q", "c_sn", "c_cn", "c_dn", "kk", "s", "slope", "G", "a3", "period"):
        np.testing.assert_allclose(got[:, getattr(table, name.upper())], getattr(const, name), rtol=1e-14)
    np.testing.assert_allclose(got[:, table.NU + table.HI], const.nu.hi, rtol=1e-15)
    np.testing.assert_allclose(got[:, table.MU_SN : table.MU_SN + 3], const.mu_sn.T, rtol=1e-14, atol=1e-15)
    assert np.array_equal(got[:, table.CIRCULAR] > 0, const.circular)
    assert np.all(got[:, table.FLAT] == 0.0)
    assert np.array_equal(as_triaxial(got).wb, got[:, table.WB : table.WB + table.NWA].T)


def _bare_columns(source, holders):
    """``(line, text)`` of each ``holder[row, column]`` whose column holds a number but no table name.

    Also counts the subscripts inspected, and checks ``triaxial_table(...)[k][:, column]``.
    """
    found, seen = [], 0
    for node in ast.walk(ast.parse(source)):
        if not isinstance(node, ast.Subscript) or not isinstance(node.slice, ast.Tuple):
            continue
        value = node.value
        on_call = (
            isinstance(value, ast.Subscript)
            and isinstance(value.value, ast.Call)
            and getattr(value.value.func, "id", None) == "triaxial_table"
        )
        if not (on_call or (isinstance(value, ast.Name) and value.id in holders)):
            continue
        seen += 1
        column = node.slice.elts[-1]
        parts = [column.lower, column.upper] if isinstance(column, ast.Slice) else [column]
        for part in parts:
            inner = list(ast.walk(part)) if part is not None else []
            number = any(isinstance(n, ast.Constant) and isinstance(n.value, int) for n in inner)
            named = {n.id for n in inner if isinstance(n, ast.Name)} & NAMES
            if number and not named:
                found.append((node.lineno, ast.unparse(node)))
    return found, seen


@pytest.mark.parametrize("module", list(HOLDERS), ids=lambda m: m.__name__.rsplit(".", 1)[-1])
def test_table_is_indexed_by_name_only(module):
    found, seen = _bare_columns(inspect.getsource(module), HOLDERS[module])
    assert seen > 0  # the scan found the table's subscripts in this module
    assert found == []


@pytest.mark.parametrize(
    ("line", "bare"),
    [
        ("x = c[r, 6]", True),
        ("x = c[r, 25 + n]", True),
        ("out[i, 11 + perm[0]] = a", True),
        ("w = out[i, WA:31]", True),
        ("x = triaxial_table(a)[0][:, 56]", True),
        ("x = c[r, WA + 1]", False),
        ("w = out[i, WA : WA + NWA]", False),
        ("x = c[r, col]", False),  # a column passed in by the caller
        ("x = m[k, 2]", False),  # not the table
    ],
)
def test_table_scan_catches_a_bare_column(line, bare):
    found, _ = _bare_columns(line, {"c", "out"})
    assert bool(found) == bare
