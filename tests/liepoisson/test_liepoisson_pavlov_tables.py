"""Pavlov's tables 1.3–1.6 and 2.10–2.13 (as corrected) and his solutions 1.7, 2.14."""

import numpy as np
import pytest
import sympy as sp

from andoyer.liepoisson import (
    CanonicalCoordinates,
    andoyer_coordinates,
    check_pavlov_table,
    check_poisson_map,
    e3_from_andoyer,
    gamma_from_quaternion,
    l7_from_andoyer,
    pavlov_table,
)
from andoyer.liepoisson._identity import vanishes


def test_table_sizes_and_equations():
    e3, l7 = pavlov_table("e3"), pavlov_table("l7")
    assert [e.equation for e in e3] == ["1.3"] * 6 + ["1.4"] * 3 + ["1.5"] * 3 + ["1.6"] * 3
    assert [e.equation for e in l7] == [f"2.1{i}" for i in range(4) for _ in range(4)]
    with pytest.raises(ValueError, match="expected 'e3' or 'l7', got 'so3'"):
        pavlov_table("so3")


@pytest.mark.parametrize("via", ["lie-poisson", "canonical"])
def test_e3_table_symbolic_and_numeric(via):
    records = check_pavlov_table("e3", via=via)
    assert len(records) == 15
    assert all(r.symbolic_ok and r.numeric_ok for r in records)
    assert max(r.max_error for r in records) <= 1e-12


@pytest.mark.parametrize("via", ["lie-poisson", "canonical"])
def test_l7_table_symbolic_and_numeric(via):
    records = check_pavlov_table("l7", via=via)
    assert len(records) == 16
    assert all(r.symbolic_ok and r.numeric_ok for r in records)
    assert max(r.max_error for r in records) <= 1e-12


def test_printed_2_12_is_wrong_and_the_rest_as_printed():
    for via in ("lie-poisson", "canonical"):
        records = check_pavlov_table("l7", via=via, printed=True, symbolic=False)
        failing = [(r.left, r.right) for r in records if not r.numeric_ok]
        assert failing == [("l", "lambda1")]
    entry = next(e for e in pavlov_table("l7") if e.printed is not None)
    ell, L, G = sp.Symbol("l", real=True), sp.Symbol("L", real=True), sp.Symbol("G", positive=True)
    q0, q3 = sp.symbols("lambda0 lambda3", real=True)
    rho = sp.sqrt(G - L) * sp.sqrt(G + L)
    assert sp.simplify(entry.rhs + (q0 * sp.cos(ell) + q3 * sp.sin(ell)) / (2 * rho)) == 0
    assert sp.simplify(entry.printed + (q3 * sp.cos(ell) + q0 * sp.sin(ell)) / (2 * rho)) == 0


# ---- Pavlov eq. 2.14 as printed, with his ζ = arcsin H/G, τ = arcsin L/G ----

SQRT2 = np.sqrt(2)


def pavlov_2_14(ell, L, g, G, h, H, *, sin=np.sin, cos=np.cos, asin=np.arcsin, sqrt2=SQRT2):
    zeta, tau = asin(H / G), asin(L / G)
    xp, xm, yp, ym = (zeta + tau) / 2, (zeta - tau) / 2, (ell + h) / 2, (ell - h) / 2
    s, c = sin(g / 2), cos(g / 2)
    lam0 = (
        s * sin(yp) * cos(xm) + s * cos(yp) * cos(xm) + c * sin(yp) * sin(xp) - c * cos(yp) * sin(xp)
    ) / sqrt2
    lam1 = (
        s * cos(ym) * sin(xm) - s * sin(ym) * sin(xm) - c * sin(ym) * cos(xp) - c * cos(ym) * cos(xp)
    ) / sqrt2
    lam2 = (
        -s * sin(ym) * sin(xm) - s * cos(ym) * sin(xm) + c * sin(ym) * cos(xp) - c * cos(ym) * cos(xp)
    ) / sqrt2
    lam3 = (
        s * sin(yp) * cos(xm) - s * cos(yp) * cos(xm) - c * sin(yp) * sin(xp) - c * cos(yp) * sin(xp)
    ) / sqrt2
    return lam0, lam1, lam2, lam3


def test_printed_2_14_is_minus_ours_with_h_shifted_by_quarter_turn():
    rng = np.random.default_rng(30)
    n = 1000
    G = rng.uniform(0.5, 2.0, n)
    L, H = G * rng.uniform(-1, 1, (2, n))
    ell, g, h = rng.uniform(0, 2 * np.pi, (3, n))
    printed = np.stack(pavlov_2_14(ell, L, g, G, h, H), -1)
    _, ours_shifted = l7_from_andoyer(ell, g, h + np.pi / 2, L, G, H)
    _, ours = l7_from_andoyer(ell, g, h, L, G, H)
    assert np.max(np.abs(printed + ours_shifted)) <= 1e-14
    assert np.min(np.max(np.abs(np.abs(printed) - np.abs(ours)), -1)) > 1e-6
    # γ (eq. 2.2) does not see h: printed 2.14 and eq. 1.7 agree
    gamma = e3_from_andoyer(ell, g, L, G, H)[1]
    assert np.max(np.abs(gamma_from_quaternion(printed) - gamma)) <= 1e-14


def test_printed_2_14_symbolically():
    """Identity in the angles ζ = π/2 − I, τ = π/2 − J (no arcsin left for the zero test)."""
    ell, g, h, zeta, tau = sp.symbols("l g h zeta tau", real=True)
    xp, xm, yp, ym = (zeta + tau) / 2, (zeta - tau) / 2, (ell + h) / 2, (ell - h) / 2
    s, c = sp.sin(g / 2), sp.cos(g / 2)
    S, C = sp.sin, sp.cos
    printed = [
        (s * S(yp) * C(xm) + s * C(yp) * C(xm) + c * S(yp) * S(xp) - c * C(yp) * S(xp)),
        (s * C(ym) * S(xm) - s * S(ym) * S(xm) - c * S(ym) * C(xp) - c * C(ym) * C(xp)),
        (-s * S(ym) * S(xm) - s * C(ym) * S(xm) + c * S(ym) * C(xp) - c * C(ym) * C(xp)),
        (s * S(yp) * C(xm) - s * C(yp) * C(xm) - c * S(yp) * S(xp) - c * C(yp) * S(xp)),
    ]
    printed = [p / sp.sqrt(2) for p in printed]

    def q(axis, a):
        out = [sp.cos(a / 2), 0, 0, 0]
        out[{"x": 1, "z": 3}[axis]] = sp.sin(a / 2)
        return out

    def mul(a, b):
        aw, av = a[0], sp.Matrix(a[1:])
        bw, bv = b[0], sp.Matrix(b[1:])
        return [aw * bw - av.dot(bv), *(aw * bv + bw * av + av.cross(bv))]

    inc, J = sp.pi / 2 - zeta, sp.pi / 2 - tau
    ours = mul(mul(mul(mul(q("z", h + sp.pi / 2), q("x", inc)), q("z", g)), q("x", J)), q("z", ell))
    for p, o in zip(printed, ours, strict=True):
        assert vanishes(p + o)


def test_printed_2_14_is_still_canonical():
    """A shift of h is canonical: Pavlov's λ(l, L, g, G, h, H) passes the Poisson-map check."""
    c = andoyer_coordinates("l7")
    s = {str(z): z for z in c.symbols}
    lam = pavlov_2_14(
        s["l"], s["L"], s["g"], s["G"], s["h"], s["H"], sin=sp.sin, cos=sp.cos, asin=sp.asin, sqrt2=sp.sqrt(2)
    )
    forward = dict(c.forward)
    forward.update({f"lambda{i}": lam[i] for i in range(4)})
    records = check_poisson_map(
        CanonicalCoordinates("l7", c.pairs, (), forward, None, c.sampler), symbolic=False
    )
    assert all(r.numeric_ok for r in records)


def test_corrected_2_14_closed_form():
    """The closed form given in docs/errata-pavlov.md equals l7_from_andoyer (same sign)."""
    rng = np.random.default_rng(31)
    n = 1000
    G = rng.uniform(0.5, 2.0, n)
    L, H = G * rng.uniform(-1, 1, (2, n))
    ell, g, h = rng.uniform(0, 4 * np.pi, (3, n))
    zeta, tau = np.arcsin(H / G), np.arcsin(L / G)
    xp, xm, yp, ym = (zeta + tau) / 2, (zeta - tau) / 2, (ell + h) / 2, (ell - h) / 2
    s, c = np.sin(g / 2), np.cos(g / 2)
    closed = np.stack(
        [
            c * np.sin(xp) * np.cos(yp) - s * np.cos(xm) * np.sin(yp),
            c * np.cos(xp) * np.cos(ym) + s * np.sin(xm) * np.sin(ym),
            s * np.sin(xm) * np.cos(ym) - c * np.cos(xp) * np.sin(ym),
            s * np.cos(xm) * np.cos(yp) + c * np.sin(xp) * np.sin(yp),
        ],
        -1,
    )
    assert np.max(np.abs(closed - l7_from_andoyer(ell, g, h, L, G, H)[1])) <= 1e-14
