"""The chart registry: one signature per chart, the State methods, the CLI table and the docs table."""

from __future__ import annotations

import inspect
import pydoc
import re
from pathlib import Path
from typing import Any, NamedTuple

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from andoyer import RigidBody, State
from andoyer.cli import chart_table
from andoyer.free.motion import FreeMotion
from andoyer.state import registry
from andoyer.state.andoyer import Andoyer, hub_to_andoyer
from andoyer.state.euler import hub_to_euler
from andoyer.state.registry import Chart, charts, charts_markdown, install
from andoyer.state.sadov import andoyer_to_sadov
from andoyer.state.sam import hub_to_sam
from andoyer.state.serret import andoyer_to_serret
from conftest import rotation_distance

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


# The public signatures of the chart methods as they were hand-written in state.py before they were
# generated from the registry (parameter names, defaults, keyword-only-ness; annotations aside).
SIGNATURES = {
    "from_euler": "(phi, theta, psi, Phi, Theta, Psi)",
    "as_euler": "(self)",
    "from_andoyer": "(l, g, h, L, G, H)",
    "as_andoyer": "(self)",
    "from_initial_andoyer": "(body, l0, g0, h, L0, G, H, epoch, t=0.0)",
    "as_initial_andoyer": "(self, body, epoch, t=0.0)",
    "from_sadov": "(body, phi_l, phi_g, phi_h, I_l, I_g, I_h)",
    "as_sadov": "(self, body)",
    "from_serret": "(body, g0, h, t0, G, H, T, sign=1.0, *, t=0.0)",
    "as_serret": "(self, body, t=0.0, *, epoch=None)",
    "from_sam": "(sam_l, sam_g, h, sam_L, sam_G, H, sign=1.0, *, body, mode='SAM')",
    "as_sam": "(self, body, mode='SAM')",
}
# The constructors State defines itself (not charts of the registry).
OWN_CONSTRUCTORS = {"from_quaternion", "from_unit_quaternion", "from_attitude", "from_angular_velocity"}


def _bare(signature: inspect.Signature) -> str:
    params = [p.replace(annotation=p.empty) for p in signature.parameters.values()]
    return str(signature.replace(parameters=params, return_annotation=signature.empty))


def test_state_slots_no_dict():
    s = State.from_andoyer(0.3, 0.4, 0.5, 0.9, 1.0, 0.2)
    assert State.__slots__ == ("_m", "_q")
    assert all("__slots__" in vars(c) for c in State.__mro__ if c is not object)
    assert not hasattr(s, "__dict__")
    with pytest.raises(AttributeError):
        s.extra = 1.0


@pytest.mark.parametrize("name", METHOD_CHARTS)
def test_state_methods_generated_from_registry(name):
    chart = charts()[name]
    build, read = vars(State)[f"from_{name}"], vars(State)[f"as_{name}"]
    assert isinstance(build, classmethod)
    # Copies of the chart module's functions: the same code (no wrapper), State's names.
    assert build.__func__.__code__ is chart.from_method.__code__
    assert read.__code__ is chart.as_method.__code__
    pairs = ((build.__func__, chart.from_method, "from"), (read, chart.as_method, "as"))
    for method, function, prefix in pairs:
        assert method.__name__ == f"{prefix}_{name}"
        assert method.__qualname__ == f"State.{prefix}_{name}"
        assert method.__module__ == State.__module__ == "andoyer.state.hub"
        assert method.__doc__ == function.__doc__
        assert "Examples\n" in method.__doc__
        assert ">>> " in method.__doc__
    assert "Parameters\n" in build.__func__.__doc__
    assert "Returns\n" in read.__doc__


@pytest.mark.parametrize("method", tuple(SIGNATURES))
def test_state_method_signatures_unchanged(method):
    signature = inspect.signature(getattr(State, method))
    assert _bare(signature) == SIGNATURES[method]
    # help(State.<method>) shows the signature and the docstring.
    text = pydoc.render_doc(getattr(State, method), renderer=pydoc.plaintext)
    assert text.splitlines()[2].startswith(f"{method}(")
    assert inspect.getdoc(getattr(State, method)).splitlines()[0] in text
    assert "in module andoyer.state" in text.splitlines()[0]


def test_state_chart_methods_are_the_registry():
    names = {n for n in vars(State) if n.startswith(("from_", "as_"))}
    generated = {f"{p}_{n}" for n in METHOD_CHARTS for p in ("from", "as")}
    assert names == generated | OWN_CONSTRUCTORS
    assert generated == set(SIGNATURES)


@pytest.mark.parametrize("name", METHOD_CHARTS)
def test_chart_options_and_body_from_signatures(name):
    chart = charts()[name]
    params = [*inspect.signature(getattr(State, f"from_{name}")).parameters]
    params += [*inspect.signature(getattr(State, f"as_{name}")).parameters][1:]
    assert chart.needs_body == ("body" in params)
    assert set(chart.options) == set(params) - set(chart.columns) - {"body"}


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


def _build_ab(cls, a, b, *, body, t=0.0):
    return (cls, a, b, body, t)


def _read_ab(self, body):
    return (self, body)


def _read_ab_no_body(self):
    return self


@pytest.mark.parametrize(
    ("columns", "build", "read", "match"),
    [
        (("b", "a"), _build_ab, _read_ab, "to take the columns"),
        (("a", "b", "c"), _build_ab, _read_ab, "to take the columns"),
        (("a", "b"), _build_ab, _read_ab_no_body, "both to take the body or neither"),
        (("a", "b"), lambda k, a, b, *, body: None, _read_ab, "to take 'cls' first"),
        (("a", "b"), _build_ab, lambda s, body: None, "to take 'self' first"),
    ],
)
def test_chart_signature_mismatch_raises(columns, build, read, match):
    with pytest.raises(ValueError, match=match):
        Chart("bad", columns, (), "bad", build, read)


def test_chart_options_read_from_signatures():
    chart = Chart("ab", ("a", "b"), ("a",), "two columns", _build_ab, _read_ab)
    assert chart.needs_body is True
    assert chart.options == ("t",)


def test_chart_to_state_wrong_column_count_raises():
    with pytest.raises(ValueError, match=r"expected 6 columns .*, got 5"):
        charts()["euler"].to_state(State, (0.1, 0.2, 0.3, 0.4, 0.5), None)


def test_install_refuses_defined_name():
    with pytest.raises(ValueError, match="expected no attribute from_euler on State before install"):
        install(State, {"euler": charts()["euler"]})


# ---------------------------------------------------------------- a chart registered in a test

class Rotvec(NamedTuple):
    """The rotation vector of the attitude (radians) and the body momentum."""

    rx: Any
    ry: Any
    rz: Any
    m1: Any
    m2: Any
    m3: Any


def _from_rotvec(cls, rx, ry, rz, m1, m2, m3, *, degrees=False):
    """State from the rotation vector of its attitude and its body momentum."""
    rotation = Rotation.from_rotvec(np.stack([rx, ry, rz], -1), degrees=degrees)
    return cls.from_attitude(rotation, np.stack([m1, m2, m3], -1))


def _as_rotvec(self, degrees=False):
    """The rotation vector of the attitude and the body momentum."""
    r = np.moveaxis(self.rotation.as_rotvec(degrees=degrees), -1, 0)
    return Rotvec(*r, *np.moveaxis(self.m_body, -1, 0))


@pytest.fixture
def scratch_registry(monkeypatch):
    """A throw-away copy of the registry: a chart registered in it is gone after the test."""
    monkeypatch.setattr(registry, "CHARTS", dict(registry.CHARTS))
    return registry


def test_registered_chart_yields_state_methods(scratch_registry):
    chart = scratch_registry.register(
        Chart("rotvec", Rotvec._fields, ("rx", "ry", "rz"), "rotation vector", _from_rotvec, _as_rotvec)
    )
    assert chart.options == ("degrees",)
    assert not chart.needs_body
    assert list(scratch_registry.charts())[-1] == "rotvec"
    assert "| `rotvec` | `rx`, `ry`, `rz`, `m1`, `m2`, `m3` |" in scratch_registry.charts_markdown()

    class Sub(State):
        __slots__ = ()

    install(Sub, scratch_registry.charts())
    assert not hasattr(State, "from_rotvec")
    assert "__dict__" not in vars(Sub)
    assert str(inspect.signature(Sub.from_rotvec)) == "(rx, ry, rz, m1, m2, m3, *, degrees=False)"
    assert str(inspect.signature(Sub.as_rotvec)) == "(self, degrees=False)"
    assert Sub.from_rotvec.__qualname__ == f"{Sub.__qualname__}.from_rotvec"
    assert Sub.as_rotvec.__name__ == "as_rotvec"
    assert Sub.as_rotvec.__doc__ == _as_rotvec.__doc__
    # The values against scipy directly (the chart's own formulas are scipy's rotation vector).
    rotvec = np.array([0.3, -1.2, 2.0])
    s = Sub.from_rotvec(*rotvec, 0.4, 0.5, 0.6, degrees=False)
    assert type(s) is Sub
    want = Rotation.from_rotvec(rotvec).as_quat()
    np.testing.assert_allclose(s.quaternion * np.sign(s.quaternion[3] * want[3]), want, rtol=0, atol=1e-15)
    np.testing.assert_allclose(s.as_rotvec(degrees=True)[:3], np.degrees(rotvec), rtol=1e-13)
    np.testing.assert_array_equal(s.as_rotvec()[3:], [0.4, 0.5, 0.6])
    # The registry's generic converters reach it too, options included.
    back = chart.to_state(Sub, chart.from_state(s, None, degrees=True), None, degrees=True)
    assert np.abs(back.m_body - s.m_body).max() == 0.0
    assert rotation_distance(back.quaternion, s.quaternion) < 1e-15


def test_scratch_registry_left_nothing():
    assert "rotvec" not in charts()
    assert not hasattr(State, "from_rotvec")


# ------------------------------------------------- the generated methods: round trips and values

@st.composite
def regular_states(draw):
    """One state of BODY away from every chart's singular set.

    A random attitude and a momentum of magnitude G in [0.1, 10] whose direction keeps 2% in
    ``2T/G²`` from BODY's separatrix (1/2) and stays 0.99 G off each body axis (Andoyer's
    ``sin J = 0``, SAM's and LAM's poles), off the reference axis (``sin I = 0``) and with the
    body axis 3 off the reference axis (Euler's ``sin θ = 0``).
    """
    rotvec = np.array(draw(st.tuples(*[st.floats(-3.0, 3.0)] * 3)))
    theta = draw(st.floats(0.0, np.pi))
    phi = draw(st.floats(0.0, 2 * np.pi))
    G = draw(st.floats(0.1, 10.0))
    u = np.array([np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi), np.cos(theta)])
    attitude = Rotation.from_rotvec(rotvec)
    assume(abs(float(u @ (u / BODY.moments)) - 0.5) > 0.01)
    assume(np.abs(u).max() < 0.99)
    assume(abs(attitude.apply(u)[2]) < 0.99)
    assume(abs(attitude.as_matrix()[2, 2]) < 0.99)
    return State.from_attitude(attitude, G * u)


def _options(name, data):
    """Options of chart ``name`` drawn away from their defaults."""
    times = st.floats(-5.0, 5.0)
    if name == "initial_andoyer":
        return {"epoch": data.draw(times), "t": data.draw(times)}
    if name == "serret":
        return {"t": data.draw(times)}
    if name == "sam":
        return {"mode": data.draw(st.sampled_from(["SAM", "LAM"]))}
    return {}


def _call_options(name, options, data):
    """The options split as each method takes them (as_serret also takes an epoch for t0)."""
    build, read = dict(options), dict(options)
    if name == "serret":
        read["epoch"] = options["t"] - data.draw(st.floats(0.0, 5.0))
    return build, read


@pytest.mark.parametrize("name", METHOD_CHARTS)
@settings(max_examples=20)
@given(s=regular_states(), data=st.data())
def test_state_chart_methods_round_trip(name, s, data):
    chart = charts()[name]
    build, read = _call_options(name, _options(name, data), data)
    body = {"body": BODY} if chart.needs_body else {}
    values = getattr(s, f"as_{name}")(**body, **read)
    # The modified Andoyer set comes as Andoyer variables (fields l, g, ... for l0, g0, ...).
    assert values._fields == (Andoyer._fields if name == "initial_andoyer" else chart.columns)
    columns = dict(zip(chart.columns, values, strict=True))
    back = getattr(State, f"from_{name}")(**columns, **body, **build)
    scale = float(np.linalg.norm(s.m_body))
    assert rotation_distance(back.quaternion, s.quaternion) < 1e-10
    assert np.abs(back.m_body - s.m_body).max() < 1e-10 * scale


def _direct_as(name, s, options):
    """The chart's coordinates of ``s`` from the chart functions, called without State's methods."""
    q, m = s.quaternion, s.m_body
    if name == "euler":
        return hub_to_euler(q, m, stacklevel=1)
    if name == "andoyer":
        return hub_to_andoyer(q, m, stacklevel=1)
    if name == "initial_andoyer":
        m1, q1 = FreeMotion(BODY.moments, m, q).propagate(options["epoch"] - options["t"])
        return hub_to_andoyer(q1, m1, stacklevel=1)
    if name == "sadov":
        return andoyer_to_sadov(BODY, *hub_to_andoyer(q, m, stacklevel=1))
    if name == "serret":
        return andoyer_to_serret(BODY, *hub_to_andoyer(q, m, stacklevel=1), t=options["t"], stacklevel=1)
    return hub_to_sam(q, m, BODY, options["mode"], stacklevel=1)


@pytest.mark.parametrize("name", METHOD_CHARTS)
@settings(max_examples=10)
@given(s=regular_states(), data=st.data())
def test_state_chart_methods_match_chart_functions(name, s, data):
    chart = charts()[name]
    options = _options(name, data)
    body = {"body": BODY} if chart.needs_body else {}
    got = getattr(s, f"as_{name}")(**body, **options)
    want = _direct_as(name, s, options)
    assert type(got) is type(want)
    # Bit for bit, but for the modified Andoyer set: its method builds a State of the flowed
    # quaternions, which normalises them again (an ulp or two).
    atol = 1e-14 * max(1.0, float(np.linalg.norm(s.m_body))) if name == "initial_andoyer" else 0.0
    for a, b in zip(got, want, strict=True):
        np.testing.assert_allclose(a, b, rtol=0, atol=atol)


def test_state_euler_andoyer_match_scipy_and_momenta():
    """Independent values: scipy's ZXZ angles, and G = |m|, H = m_ref·s3, L = m3 (Gurfil §2–3)."""
    s = _states()
    e, a = s.as_euler(), s.as_andoyer()
    angles = np.mod(s.rotation.as_euler("ZXZ"), 2 * np.pi)
    np.testing.assert_allclose(np.mod(np.stack(e[:3], -1), 2 * np.pi), angles, rtol=0, atol=1e-12)
    m, M = s.m_body, s.m_reference
    np.testing.assert_allclose(e.Phi, M[:, 2], rtol=0, atol=1e-14)
    np.testing.assert_allclose(e.Psi, m[:, 2], rtol=0, atol=1e-14)
    np.testing.assert_allclose(a.G, np.linalg.norm(m, axis=-1), rtol=1e-15)
    np.testing.assert_allclose(a.H, M[:, 2], rtol=0, atol=1e-14)
    np.testing.assert_allclose(a.L, m[:, 2], rtol=0, atol=1e-15)
