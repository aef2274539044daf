"""The canonicity checker: project coordinates, Euler angles, wrong coordinates."""

import json

import numpy as np
import pytest
import sympy as sp
from scipy.spatial.transform import Rotation

from andoyer.liepoisson import (
    CanonicalCoordinates,
    andoyer_coordinates,
    andoyer_momenta,
    bracket_table,
    check_coordinates,
    check_poisson_map,
    euler_coordinates,
    euler_momenta,
    get_algebra,
)
from andoyer.liepoisson._identity import vanishes

FIELDS = {"left", "right", "value", "expected", "symbolic_ok", "numeric_ok", "max_error"}


def all_ok(records):
    return all(r.symbolic_ok and r.numeric_ok for r in records)


@pytest.mark.parametrize("algebra", ["so3", "e3"])
def test_andoyer_coordinates_are_canonical(algebra):
    records = check_coordinates(andoyer_coordinates(algebra))
    assert all_ok(records)
    assert max(r.max_error for r in records) <= 1e-12
    c = andoyer_coordinates(algebra)
    n = len(c.symbols)
    assert len(records) == n * (n - 1) // 2
    for r in records:
        assert r.value == r.expected
        pair = [s for s in c.symbols if str(s) in (r.left, r.right)]
        assert int(r.expected) == c.canonical_value(*pair)


@pytest.mark.slow
def test_andoyer_coordinates_are_canonical_l7():
    records = check_coordinates(andoyer_coordinates("l7"))
    assert all_ok(records)
    assert len(records) == 15
    assert max(r.max_error for r in records) <= 1e-12


def test_andoyer_coordinates_l7_fast_symbolic_pairs():
    """A fast subset of the l(7) proofs for the default run (the full table is slow)."""
    c = andoyer_coordinates("l7")
    alg = get_algebra("l7")
    sub = dict(zip(alg.symbols(), (c.forward[n] for n in alg.generators), strict=True))
    sym = {str(s): s for s in c.symbols}
    for a, b, expected in (("l", "L", 1), ("L", "H", 0), ("G", "H", 0), ("l", "G", 0)):
        bracket = alg.bracket_sym_unexpanded(c.inverse[sym[a]], c.inverse[sym[b]])
        assert vanishes(bracket - expected, substitution=sub)


@pytest.mark.parametrize("algebra", ["so3", "e3", "l7"])
def test_euler_angles_realise_the_algebra(algebra):
    """Gurfil eqs. 25–28 and the pinned rotation: the Euler chart is a Poisson map."""
    records = check_poisson_map(euler_coordinates(algebra))
    assert all_ok(records)
    assert max(r.max_error for r in records) <= 1e-12


@pytest.mark.parametrize("algebra", ["so3", "e3"])
def test_andoyer_forward_map_is_poisson(algebra):
    assert all_ok(check_poisson_map(andoyer_coordinates(algebra)))


@pytest.mark.slow
def test_andoyer_forward_map_is_poisson_l7():
    records = check_poisson_map(andoyer_coordinates("l7"))
    assert all_ok(records)
    assert len(records) == 21


def test_forward_map_has_full_rank_on_the_leaf():
    """With Poisson-ness, full rank of the Jacobian makes the forward map a chart."""
    for algebra in ("so3", "e3", "l7"):
        c = andoyer_coordinates(algebra)
        alg = get_algebra(algebra)
        zs = c.symbols
        jac = sp.lambdify([zs], sp.Matrix([c.forward[n] for n in alg.generators]).jacobian(zs), cse=True)
        for z in c.sampler(np.random.default_rng(20), 20):
            assert np.linalg.matrix_rank(np.array(jac(z), float), tol=1e-10) == len(zs)


def test_wrong_coordinates_are_reported():
    so3 = get_algebra("so3")
    m1, m2, m3 = so3.symbols()
    ell, L = sp.symbols("l L", real=True)
    G = sp.Symbol("G", positive=True)
    bad = CanonicalCoordinates(
        "so3",
        ((ell, L),),
        (G,),
        inverse={ell: -sp.atan2(m1, m2), L: m3, G: sp.sqrt(m1**2 + m2**2 + m3**2)},
    )
    records = {(r.left, r.right): r for r in check_coordinates(bad)}
    r = records["l", "L"]
    assert not r.symbolic_ok
    assert not r.numeric_ok
    assert r.max_error == pytest.approx(2.0)
    assert r.expected == "1"
    assert records["l", "G"].symbolic_ok
    assert records["l", "G"].numeric_ok


def test_wrong_forward_map_is_reported():
    c = andoyer_coordinates("e3")
    forward = dict(c.forward)
    forward["gamma1"] = -forward["gamma1"]
    bad = CanonicalCoordinates("e3", c.pairs, c.casimirs, forward, None, c.sampler)
    failing = {(r.left, r.right) for r in check_poisson_map(bad) if not (r.symbolic_ok or r.numeric_ok)}
    assert failing == {("m2", "gamma1"), ("m2", "gamma3"), ("m3", "gamma1"), ("m3", "gamma2")}
    assert ("m1", "m2") not in failing


def test_l7_h_has_the_right_orientation():
    """{h, H} = +1 only for h measured from the node; Pavlov's azimuth h − π/2 also passes,
    but a reversed angle fails."""
    c = andoyer_coordinates("l7")
    sym = {str(s): s for s in c.symbols}
    inverse = dict(c.inverse)
    inverse[sym["h"]] = -inverse[sym["h"]]
    bad = CanonicalCoordinates("l7", c.pairs, (), None, inverse)
    records = {(r.left, r.right): r for r in check_coordinates(bad, symbolic=False)}
    assert not records["h", "H"].numeric_ok
    assert records["l", "L"].numeric_ok


def test_bracket_table_fields_and_json():
    rows = bracket_table("so3")
    assert [set(r) for r in rows] == [FIELDS] * 3
    assert json.loads(json.dumps(rows)) == rows
    rows = bracket_table("e3")
    assert all(r["symbolic_ok"] and r["numeric_ok"] for r in rows)
    assert {(r["left"], r["right"]): r["value"] for r in rows}[("g", "G")] == "1"


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda: bracket_table("so4"), "expected one of"),
        (lambda: CanonicalCoordinates("so3", (), ()), "expected a forward or an inverse map"),
        (lambda: CanonicalCoordinates("so3", (), (), forward={"m1": 0}), "expected forward expressions"),
        (lambda: check_coordinates(euler_coordinates("so3")), "expected coordinates with an inverse"),
        (
            lambda: check_poisson_map(
                CanonicalCoordinates(
                    "so3",
                    andoyer_coordinates("so3").pairs,
                    andoyer_coordinates("so3").casimirs,
                    andoyer_coordinates("so3").forward,
                )
            ),
            "expected a sampler or an inverse map",
        ),
    ],
)
def test_bad_inputs_raise(call, message):
    with pytest.raises(ValueError, match=message):
        call()


def test_andoyer_method_momenta():
    """Gurfil A.5: J_h = G cos I, J_I = 0, J_g = G, J_J = 0, J_l = G cos J."""
    J = andoyer_momenta()
    G = sp.Symbol("G", positive=True)
    inc, Jang = sp.symbols("I J", real=True)
    expected = {"h": G * sp.cos(inc), "I": 0, "g": G, "J": 0, "l": G * sp.cos(Jang)}
    assert set(J) == set(expected)
    for k, v in expected.items():
        assert sp.simplify(J[k] - v) == 0


def test_andoyer_method_momenta_numerically():
    """J_α = m_body·ω_α with hat(ω_α) = rotᵀ ∂rot/∂α by finite differences of scipy rotations."""
    rng = np.random.default_rng(21)
    for _ in range(20):
        h, inc, g, J, ell = rng.uniform(0.1, 3.0, 5)
        G = rng.uniform(0.5, 2.0)

        def rot(*a):
            rot = Rotation.from_euler("ZXZ", a[:3]) * Rotation.from_euler("XZ", a[3:])
            return rot.as_matrix()

        base = np.array([h, inc, g, J, ell])
        m_ref = G * np.array([np.sin(inc) * np.sin(h), -np.sin(inc) * np.cos(h), np.cos(inc)])
        m_body = rot(*base).T @ m_ref
        got = []
        for k in range(5):
            d = np.zeros(5)
            d[k] = 1e-6
            W = rot(*base).T @ (rot(*(base + d)) - rot(*(base - d))) / 2e-6
            got.append(m_body @ np.array([W[2, 1], W[0, 2], W[1, 0]]))
        want = [G * np.cos(inc), 0.0, G, 0.0, G * np.cos(J)]
        np.testing.assert_allclose(got, want, atol=1e-8)


def test_euler_momenta_invert_gurfil_25_27():
    """Φ = m·γ, Θ = m1 cψ − m2 sψ, Ψ = m3 (Gurfil 40–42), composed with eqs. 25–27."""
    J = euler_momenta()
    c = euler_coordinates("so3")
    sub = dict(zip(get_algebra("so3").symbols(), (c.forward[n] for n in ("m1", "m2", "m3")), strict=True))
    for name, (_, p) in zip(("phi", "theta", "psi"), c.pairs, strict=True):
        assert vanishes(J[name] - p, substitution=sub)
