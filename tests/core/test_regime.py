"""The one regime classification (andoyer.regime): compiled, on arrays, per scalar and by the body.

The reference is exact rational arithmetic (:class:`fractions.Fraction`) on the definition
``P₂ = G²/B − 2T``, not the kernel's rearranged double-double form.
"""

from __future__ import annotations

import ast
import functools
import math
import warnings
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import andoyer
from andoyer._jit import jit
from andoyer.body import NonPhysicalInertiaWarning, RigidBody
from andoyer.free.common.scaling_compiled import classify_and_scale
from andoyer.regime import Regime, classify, regime_code, regime_names


def exact_regime(moments, m):
    """The regime from the definitions, in exact rational arithmetic."""
    inertia = [Fraction(float(x)) for x in moments]
    mom = [Fraction(float(x)) for x in m]
    if all(x == 0 for x in mom):
        return Regime.REST
    A, B, C = sorted(inertia)
    if A == C:
        return Regime.SPHERE
    if B in (A, C):
        return Regime.AXISYMMETRIC
    g2 = sum(x * x for x in mom)
    two_t = sum(x * x / i for x, i in zip(mom, inertia, strict=True))
    p2 = g2 / B - two_t
    return Regime.SAM if p2 > 0 else Regime.LAM if p2 < 0 else Regime.SEPARATRIX


def _quiet_body(moments):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", NonPhysicalInertiaWarning)
        return RigidBody(*moments)


@jit
def _compiled_loop(moments, m, out):
    for k in range(moments.shape[0]):
        out[k] = regime_code(moments[k, 0], moments[k, 1], moments[k, 2], m[k, 0], m[k, 1], m[k, 2])


def _compiled(moments, m):
    out = np.empty(moments.shape[0], dtype=np.int64)
    _compiled_loop(np.ascontiguousarray(moments), np.ascontiguousarray(m), out)
    return out


# Each path takes moments (N, 3) and momenta (N, 3) and returns N regime codes.
PATHS = {
    "compiled": _compiled,
    "arrays": classify,
    "scalar": lambda moments, m: np.array(
        [int(regime_code(*map(float, i), *map(float, x))) for i, x in zip(moments, m, strict=True)]
    ),
    "body": lambda moments, m: np.array([_quiet_body(i).regime(x) for i, x in zip(moments, m, strict=True)]),
}

UP, DOWN = np.nextafter(1.0, 2.0), np.nextafter(1.0, 0.0)
TINY, HUGE = 2.0**-1000, 2.0**900
# (3, 4, 6) with |m1| = |m3|: m_C² (C − B) A = m_A² (B − A) C = 6, exactly on the separatrix.
CASES = {
    "sam": ((1.0, 2.0, 3.0), (0.1, 0.2, 1.0), Regime.SAM),
    "lam": ((1.0, 2.0, 3.0), (1.0, 0.2, 0.1), Regime.LAM),
    "sam_pure_spin": ((1.0, 2.0, 3.0), (0.0, 0.0, 5.0), Regime.SAM),
    "lam_pure_spin": ((1.0, 2.0, 3.0), (5.0, 0.0, 0.0), Regime.LAM),
    "separatrix_middle_axis": ((1.0, 2.0, 3.0), (0.0, 1.0, 0.0), Regime.SEPARATRIX),
    "separatrix": ((3.0, 4.0, 6.0), (1.0, 0.7, 1.0), Regime.SEPARATRIX),
    "separatrix_relabelled": ((6.0, 3.0, 4.0), (-1.0, 1.0, 0.7), Regime.SEPARATRIX),
    "separatrix_plus_ulp_mc": ((3.0, 4.0, 6.0), (1.0, 0.7, UP), Regime.SAM),
    "separatrix_minus_ulp_mc": ((3.0, 4.0, 6.0), (1.0, 0.7, DOWN), Regime.LAM),
    "separatrix_plus_ulp_ma": ((3.0, 4.0, 6.0), (UP, 0.7, 1.0), Regime.LAM),
    "separatrix_minus_ulp_ma": ((3.0, 4.0, 6.0), (DOWN, 0.7, 1.0), Regime.SAM),
    "separatrix_plus_ulp_b": ((3.0, np.nextafter(4.0, 5.0), 6.0), (1.0, 0.7, 1.0), None),
    "separatrix_minus_ulp_b": ((3.0, np.nextafter(4.0, 3.0), 6.0), (1.0, 0.7, 1.0), None),
    "near_oblate": ((2.0, np.nextafter(2.0, 3.0), 3.0), (0.3, 0.1, 1.0), Regime.SAM),
    "oblate": ((2.0, 2.0, 3.0), (0.3, 0.1, 1.0), Regime.AXISYMMETRIC),
    "prolate": ((2.0, 3.0, 3.0), (0.3, 0.1, 1.0), Regime.AXISYMMETRIC),
    "prolate_relabelled": ((3.0, 2.0, 3.0), (1.0, 0.0, 0.0), Regime.AXISYMMETRIC),
    "sphere": ((2.0, 2.0, 2.0), (0.3, 0.1, 1.0), Regime.SPHERE),
    "rest": ((1.0, 2.0, 3.0), (0.0, 0.0, 0.0), Regime.REST),
    "rest_sphere": ((2.0, 2.0, 2.0), (0.0, -0.0, 0.0), Regime.REST),
    "separatrix_scaled": ((3 * TINY, 4 * TINY, 6 * TINY), (1 / TINY, 0.7, 1 / TINY), None),
    "separatrix_ulp_scaled": ((3 * HUGE, 4 * HUGE, 6 * HUGE), (1 / HUGE, 0.0, UP / HUGE), None),
    "huge_moments_tiny_momentum": ((1e300, 2e300, 2.5e300), (1e-300, 2e-301, 3e-300), None),
    "tiny_moments_huge_momentum": ((1e-300, 2e-300, 2.5e-300), (3e300, 2e299, 1e300), None),
    "subnormal_momentum": ((1.0, 2.0, 3.0), (5e-324, 0.0, 0.0), Regime.LAM),
    "wide_momentum_range": ((1.0, 2.0, 3.0), (1e-200, 0.0, 1.0), Regime.SAM),
    # m_C² underflows beside m_B² when the state is scaled as a whole (found by Hypothesis)
    "subnormal_mc_beside_mb": ((0.75, 1.0, 0.5), (1.0, 2.2250738585e-309, 0.0), Regime.SAM),
    "tiny_ma_beside_mb": ((1.0, 2.0, 3.0), (1e-170, 1.0, 0.0), Regime.LAM),
    "tiny_moment": ((1e-300, 2.0, 3.0), (1e-200, 0.0, 1.0), None),
}


@pytest.mark.parametrize("path", PATHS)
@pytest.mark.parametrize("case", CASES)
def test_regime_paths_match_exact_arithmetic(path, case):
    moments, m, expected = CASES[case]
    want = exact_regime(moments, m)
    if expected is not None:  # the hand-derived value, where there is one, agrees with Fraction
        assert want == expected
    got = PATHS[path](np.array([moments]), np.array([m]))
    assert got.tolist() == [want]


def _check_scaled(moments, m):
    """classify_and_scale (FreeMotion's compiled set-up) gives the exact regime of the state it scaled.

    That is the regime of the input too, unless scaling rounded a component below 2⁻¹⁰²²
    times the largest (a subnormal).
    """
    regime, scaled_i, scaled_m, a, b = classify_and_scale(moments, m)
    assert np.array_equal(scaled_i, np.ldexp(moments, -a[:, None]))
    assert np.array_equal(scaled_m, np.ldexp(m, -b[:, None]))
    assert regime.tolist() == [exact_regime(i, x) for i, x in zip(scaled_i, scaled_m, strict=True)]
    exact_scaling = np.all(np.ldexp(scaled_m, b[:, None]) == m, axis=-1)
    assert np.array_equal(regime[exact_scaling], classify(moments, m)[exact_scaling])


@pytest.mark.parametrize("case", CASES)
def test_regime_of_scaled_states_is_exact(case):
    moments, m, _ = CASES[case]
    _check_scaled(np.array([moments]), np.array([m]))


@pytest.mark.parametrize("extreme", [False, True])
@pytest.mark.parametrize("path", PATHS)
def test_regime_paths_agree_on_random_and_near_separatrix_states(path, extreme):
    rng = np.random.default_rng(2026)
    moments = rng.uniform(1.0, 2.0, (300, 3)) * 2.0 ** rng.integers(-60, 60, (300, 1))
    m = rng.normal(size=(300, 3)) * 2.0 ** rng.integers(-60, 60, (300, 1))
    for i in range(150):  # to within a few ulps of the separatrix
        order = np.argsort(moments[i])
        A, B, C = moments[i][order]
        ratio = math.sqrt((1 / A - 1 / B) / (1 / B - 1 / C))
        m[i, order[2]] = m[i, order[0]] * ratio * (1 + rng.integers(-3, 4) * 2.2e-16)
    if extreme:  # one state beyond 2^±150: on arrays every state then takes the rescaled branch
        moments[-1] *= 2.0**700
    want = [exact_regime(moments[i], m[i]) for i in range(300)]
    assert PATHS[path](moments, m).tolist() == want
    _check_scaled(moments, m)


def test_regime_code_on_arrays_broadcasts_and_is_the_scalar_decision():
    m = np.array([[0.1, 0.2, 1.0], [1.0, 0.2, 0.1], [0.0, 1.0, 0.0], [0.0, 0.0, 0.0]])
    got = regime_code(1.0, 2.0, 3.0, m[:, 0], m[:, 1], m[:, 2])
    assert got.tolist() == [Regime.SAM, Regime.LAM, Regime.SEPARATRIX, Regime.REST]
    assert [int(regime_code(1.0, 2.0, 3.0, *row)) for row in m] == got.tolist()
    assert classify(np.ones((4, 1, 3)) * [1.0, 2.0, 2.5], np.ones((5, 3))).shape == (4, 5)
    assert regime_names(got).tolist() == ["SAM", "LAM", "SEPARATRIX", "REST"]


finite = st.floats(min_value=0.25, max_value=4.0)
exponents = st.integers(-300, 300)


@st.composite
def states(draw):
    """A body and momentum, half of them within a few ulps of the separatrix, at any scale."""
    moments = np.array([draw(finite) for _ in range(3)]) * 2.0 ** draw(exponents)
    m = np.array([draw(st.floats(-4.0, 4.0)) for _ in range(3)]) * 2.0 ** draw(exponents)
    order = np.argsort(moments)
    A, B, C = moments[order]
    if draw(st.booleans()) and A < B < C:
        ratio = math.sqrt((1 / A - 1 / B) / (1 / B - 1 / C))
        mc = m[order[0]] * ratio
        for _ in range(draw(st.integers(0, 3))):
            mc = np.nextafter(mc, draw(st.sampled_from([-np.inf, np.inf])))
        m[order[2]] = mc
    return moments, m


@pytest.mark.slow
@settings(max_examples=300, deadline=None)
@given(state=states())
def test_regime_matches_fraction_arithmetic_everywhere(state):
    moments, m = state
    want = exact_regime(moments, m)
    for path in PATHS.values():
        assert path(moments[None], m[None]).tolist() == [want]
    _check_scaled(moments[None], m[None])


# -- one place decides: no other module of the package produces a regime


SOURCE = Path(andoyer.__file__).parent


@functools.cache
def _trees():
    """The parsed modules that name a regime at all (the others cannot decide one)."""
    texts = {str(p.relative_to(SOURCE)): p.read_text(encoding="utf-8") for p in sorted(SOURCE.rglob("*.py"))}
    return {name: ast.parse(text) for name, text in texts.items() if "Regime" in text or "SAM" in text}


def _regime_productions(tree):
    """``Regime.X`` attributes used as values (not in a comparison): where a regime is decided."""
    compared = {
        id(sub)
        for node in ast.walk(tree)
        if isinstance(node, ast.Compare)
        for sub in ast.walk(node)
    }
    return [
        node.attr
        for node in ast.walk(tree)
        if isinstance(node, ast.Attribute)
        and isinstance(node.value, ast.Name)
        and node.value.id == "Regime"
        and node.attr in Regime.__members__
        and id(node) not in compared
    ]


def test_regime_only_andoyer_regime_produces_regime_codes():
    deciders = {name: found for name, tree in _trees().items() if (found := _regime_productions(tree))}
    assert list(deciders) == ["regime.py"]


def test_regime_vocabulary_is_defined_once():
    enums = []
    for name, tree in _trees().items():
        for node in ast.walk(tree):
            if isinstance(node, ast.ClassDef):
                members = {
                    target.id
                    for stmt in node.body
                    if isinstance(stmt, ast.Assign)
                    for target in stmt.targets
                    if isinstance(target, ast.Name)
                }
                if {"SAM", "LAM"} <= members:
                    enums.append(f"{name}:{node.name}")
    # RotationMode: deprecated, a view of Regime (RigidBody.rotation_mode)
    assert enums == ["body.py:RotationMode", "regime.py:Regime"]
