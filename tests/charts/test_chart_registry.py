"""The chart registry: one signature per chart, the State methods, the CLI table and the docs table."""

from __future__ import annotations

import inspect
import re
from pathlib import Path

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from andoyer import RigidBody, State
from andoyer.charts.registry import Chart, charts, charts_markdown
from andoyer.cli import chart_table

DOCS = Path(__file__).resolve().parents[2] / "docs" / "charts.md"
BODY = RigidBody(1.0, 2.0, 3.0)
NAMES = tuple(charts())
METHOD_CHARTS = tuple(name for name, chart in charts().items() if chart.method)
# The command line's chart table as it was before the registry (andoyer convert --help lists it).
CLI_COLUMNS = {
    "state": ("qx", "qy", "qz", "qw", "m1", "m2", "m3"),
    "euler": ("phi", "theta", "psi", "Phi", "Theta", "Psi"),
    "andoyer": ("l", "g", "h", "L", "G", "H"),
    "sadov": ("phi_l", "phi_g", "phi_h", "I_l", "I_g", "I_h"),
    "serret": ("g0", "h", "t0", "G", "H", "T", "sign"),
}


def _parameters(method: object) -> list[inspect.Parameter]:
    return list(inspect.signature(method).parameters.values())


def test_state_slots_no_dict():
    s = State.from_andoyer(0.3, 0.4, 0.5, 0.9, 1.0, 0.2)
    assert State.__slots__ == ("_m", "_q")
    assert all("__slots__" in vars(c) for c in State.__mro__ if c is not object)
    assert not hasattr(s, "__dict__")
    with pytest.raises(AttributeError):
        s.extra = 1.0


@pytest.mark.parametrize("name", METHOD_CHARTS)
def test_state_methods_match_registry(name):
    chart = charts()[name]
    body = ["body"] if chart.needs_body else []
    params = _parameters(getattr(State, f"from_{name}"))
    # The columns are positional (body first, when a converter takes it positionally), options keyword.
    positional = [p.name for p in params if p.kind is p.POSITIONAL_OR_KEYWORD]
    keyword = [p.name for p in params if p.kind is p.KEYWORD_ONLY]
    assert [n for n in positional if n not in chart.options and n not in body] == list(chart.columns)
    assert set(positional + keyword) - set(chart.columns) - set(chart.options) == set(body)
    out = [p.name for p in _parameters(getattr(State, f"as_{name}"))[1:]]
    assert set(out) - set(chart.options) == set(body)
    assert {n for n in positional + keyword + out if n in chart.options} == set(chart.options)


def _states():
    rng = np.random.default_rng(16)
    q = Rotation.random(5, random_state=rng).as_quat()
    # Momenta of BODY (G = 1) about either stable axis, one 2% from the separatrix (2T G^-2 = 0.51 vs 1/I2).
    m = np.array(
        [
            [0.3, 0.2, 0.93],
            [0.9, 0.3, 0.31],
            [0.2, 0.95, 0.24],
            [0.55, 0.1, 0.83],
            [0.85, 0.2, 0.48],
        ]
    )
    m /= np.linalg.norm(m, axis=-1, keepdims=True)
    return State.from_quaternion(q, m)


# Options away from their defaults where a chart has them (the modified Andoyer set needs an epoch).
OPTIONS = {"initial_andoyer": {"epoch": 1.5, "t": 0.25}, "serret": {"t": 2.0}}


@pytest.mark.parametrize("name", NAMES)
def test_registry_round_trip_returns_state(name):
    chart, s = charts()[name], _states()
    options = OPTIONS.get(name, {})
    values = chart.from_state(s, BODY, **options)
    assert len(values) == len(chart.columns)
    back = chart.to_state(State, values, BODY, **options)
    # Same rotation (q and -q alike) and momentum: compared through scipy's matrices.
    assert np.abs(back.rotation.as_matrix() - s.rotation.as_matrix()).max() < 1e-12
    assert np.abs(back.m_body - s.m_body).max() < 1e-12


def test_registry_hub_columns_values():
    q = Rotation.from_rotvec([0.1, -0.2, 0.3]).as_quat()
    s = State.from_quaternion(q, [0.4, 0.5, 0.6])
    values = charts()["state"].from_state(s, None)
    sign = np.sign(q[3]) * np.sign(values.qw)
    np.testing.assert_allclose(sign * np.array(values[:4]), q, rtol=0, atol=1e-15)
    assert [float(x) for x in values[4:]] == [0.4, 0.5, 0.6]


@pytest.mark.parametrize("name", tuple(CLI_COLUMNS))
def test_cli_table_is_registry_view(name):
    view, chart = chart_table.CHARTS[name], charts()[name]
    assert view.columns == CLI_COLUMNS[name] == chart.columns
    assert view.angles == chart.angles
    assert view.needs_body == chart.needs_body
    s = _states()
    body = BODY if chart.needs_body else None
    for got, want in zip(view.from_state(s, body), chart.from_state(s, body), strict=True):
        np.testing.assert_array_equal(got, want)


def test_cli_table_names_order():
    assert tuple(chart_table.CHARTS) == tuple(CLI_COLUMNS)


def test_docs_table_equals_registry():
    text = DOCS.read_text(encoding="utf-8")
    found = re.search(r"<!-- charts table: start -->\n(.*?)<!-- charts table: end -->", text, re.S)
    assert found is not None
    assert found.group(1) == charts_markdown()


def test_chart_angles_outside_columns_raises():
    with pytest.raises(ValueError, match="expected angles among the columns"):
        Chart("bad", ("a", "b"), ("c",), "bad", lambda *a: None, lambda *a: None)
