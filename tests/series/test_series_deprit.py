"""Deprit's Lie transforms: known normal forms, an independent sympy implementation, the exact
action of the Duffing oscillator, direct∘inverse identity and canonicity."""

from __future__ import annotations

from fractions import Fraction
from math import comb, factorial

import mpmath
import numpy as np
import pytest
import sympy
from sympy.simplify.fu import TR8

from andoyer.series import LieTransform, PoissonRing, deprit, lie_sum

OSC = PoissonRing(["th"], ["J"])
DUFFING_H1 = OSC("J**2*sin(th)**4")  # q⁴/4 with q = √(2J) sin θ
SAM = PoissonRing(["l", "g"], ["L", "G"], ["alpha", "beta", "s", "C"], relations={"beta": "1 - s**2"})
SAM_H = [SAM("G**2/(2*C) + alpha*s*G*L/C"), SAM("-alpha*L**2/(2*C)*(1 + beta*cos(2*l))")]


def _binomial_half(n: int) -> Fraction:
    out = Fraction(1)
    for i in range(n):
        out *= Fraction(1, 2) - i
    return out / factorial(n)


@pytest.mark.parametrize("order", [1, 4, 8])
def test_deprit_exact_normal_form_of_squeezed_oscillator(order):
    # H = p²/2 + (1 + ε) q²/2 = J + ε J (1 − cos 2θ)/2 has K = J √(1 + ε) exactly.
    T = deprit([OSC("J"), OSC("J*(1 - cos(2*th))/2")], order)
    for n, k in enumerate(T.new_hamiltonian):
        assert k == OSC("J") * (factorial(n) * _binomial_half(n))


def _sympy_deprit(h1, order: int):
    """Plain-sympy Deprit normalisation of J + ε h1(θ, J) (frequency 1), written independently."""
    th, J = sympy.symbols("th J")

    def bracket(f, g):
        return sympy.diff(f, th) * sympy.diff(g, J) - sympy.diff(f, J) * sympy.diff(g, th)

    def lin(f):
        return sympy.expand(TR8(sympy.expand(f)))

    def avg(f):
        return lin(sympy.integrate(lin(f), (th, 0, 2 * sympy.pi)) / (2 * sympy.pi))

    H = [J, h1] + [sympy.Integer(0)] * (order - 1)
    table = {(0, m): H[m] for m in range(order + 1)}
    W, K = {}, [J]
    for n in range(1, order + 1):
        for q in range(1, n + 1):
            m = n - q
            acc = table[(q - 1, m + 1)]
            for k in range(m + 1):
                if k + 1 < n:
                    acc += comb(m, k) * bracket(table[(q - 1, m - k)], W[k + 1])
            table[(q, m)] = lin(acc)
        tilde = table[(n, 0)]
        kn = avg(tilde)
        # {J, W} = −∂W/∂θ must equal kn − tilde
        wn = lin(sympy.integrate(lin(tilde - kn), th))
        wn = lin(wn - avg(wn))
        correction = lin(-sympy.diff(wn, th))
        for q in range(1, n + 1):
            table[(q, n - q)] = lin(table[(q, n - q)] + correction)
        W[n], K = wn, [*K, kn]
    return K, [W[n] for n in range(1, order + 1)]


def test_deprit_duffing_matches_independent_sympy_implementation():
    order = 3
    T = deprit([OSC("J"), DUFFING_H1], order)
    K_ref, W_ref = _sympy_deprit(DUFFING_H1.to_sympy(), order)
    assert list(T.new_hamiltonian) == [OSC.from_sympy(k) for k in K_ref]
    assert list(T.generator) == [OSC.from_sympy(w) for w in W_ref]


def _duffing_action(energy: float, eps: float) -> mpmath.mpf:
    """Exact action (1/2π)∮p dq of p²/2 + q²/2 + ε q⁴/4 = E, by quadrature (q = q_max sin φ)."""
    with mpmath.workdps(40):
        E, e = mpmath.mpf(energy), mpmath.mpf(eps)
        qmax = mpmath.sqrt((-1 + mpmath.sqrt(1 + 4 * e * E)) / e)

        def integrand(phi):
            q = qmax * mpmath.sin(phi)
            return mpmath.sqrt(2 * E - q**2 - e * q**4 / 2) * qmax * mpmath.cos(phi)

        return 2 / mpmath.pi * mpmath.quad(integrand, [0, mpmath.pi / 2])


@pytest.mark.parametrize("order", [2, 4])
def test_deprit_duffing_energy_in_exact_action_error_scales(order):
    T = deprit([OSC("J"), DUFFING_H1], order)
    energy = 0.5
    errors = []
    epsilons = [0.02, 0.01, 0.005]
    for eps in epsilons:
        action = _duffing_action(energy, eps)
        with mpmath.workdps(40):
            K = sum(
                mpmath.mpf(eps) ** n / factorial(n) * _poly_value(k, action)
                for n, k in enumerate(T.new_hamiltonian)
            )
            errors.append(abs(K - energy))
    slopes = [float(mpmath.log(errors[i] / errors[i + 1], 2)) for i in range(2)]
    assert all(abs(slope - (order + 1)) < 0.3 for slope in slopes), slopes
    assert float(errors[-1]) < 1e-8


def _poly_value(series, J):
    total = mpmath.mpf(0)
    for t in series.terms():
        assert t.kind == "cos"
        assert not any(t.harmonics)
        total += mpmath.mpf(t.coeff.numerator) / t.coeff.denominator * J ** t.exponents[0]
    return total


@pytest.mark.parametrize(
    ("hamiltonian", "angles", "order"),
    [((OSC("J"), DUFFING_H1), None, 5), (tuple(SAM_H), ["l"], 4)],
    ids=["duffing", "sam"],
)
def test_deprit_new_hamiltonian_is_averaged_and_direct_reproduces_it(hamiltonian, angles, order):
    T = deprit(list(hamiltonian), order, angles)
    for k in T.new_hamiltonian:
        assert k.average(angles) == k
    # the direct transformation of H (old variables) is the new Hamiltonian
    assert T.direct(list(hamiltonian)) == T.new_hamiltonian


@pytest.mark.parametrize(
    ("hamiltonian", "angles", "order", "functions"),
    [
        ((OSC("J"), DUFFING_H1), None, 5, ["J", "J**2*cos(3*th)"]),
        (tuple(SAM_H), ["l"], 4, ["L", "G", "L*sin(2*l) + G**-1*cos(l - g)"]),
    ],
    ids=["duffing", "sam"],
)
def test_deprit_direct_inverse_identity_triangle(hamiltonian, angles, order, functions):
    T = deprit(list(hamiltonian), order, angles)
    ring = hamiltonian[0].ring
    for text in functions:
        f = ring(text)
        zeros = (ring.zero,) * order
        assert T.direct(T.inverse(f)) == (f, *zeros)
        assert T.inverse(T.direct(f)) == (f, *zeros)


def _with_eps(ring: PoissonRing) -> PoissonRing:
    return PoissonRing(
        ring.angles,
        ring.momenta,
        [*ring.params, "eps"],
        relations=ring.relations,
        weights={"eps": 1},
    )


def _lift(series, ring_eps: PoissonRing):
    return ring_eps.from_terms((t.coeff, [*t.exponents, 0], t.kind, t.harmonics) for t in series)


def _coordinates(T: LieTransform, ring_eps: PoissonRing, inverse: bool):
    """Old (direct) or new (inverse) coordinates as ε-series: angle corrections and momenta."""
    eps = ring_eps.gen("eps")
    angle = T.inverse_angle if inverse else T.direct_angle
    moment = T.inverse if inverse else T.direct
    deltas = {a: lie_sum([_lift(s, ring_eps) for s in angle(a)], eps) for a in ring_eps.angles}
    momenta = {p: lie_sum([_lift(s, ring_eps) for s in moment(p)], eps) for p in ring_eps.momenta}
    return deltas, momenta


@pytest.mark.parametrize(
    ("hamiltonian", "angles", "order"),
    [((OSC("J"), DUFFING_H1), None, 4), (tuple(SAM_H), ["l"], 3)],
    ids=["duffing", "sam"],
)
def test_deprit_transformation_is_canonical_to_order(hamiltonian, angles, order):
    T = deprit(list(hamiltonian), order, angles)
    ring_eps = _with_eps(hamiltonian[0].ring)
    deltas, momenta = _coordinates(T, ring_eps, inverse=False)
    pairs = dict(ring_eps.pairs)
    # {θ_a, F} = ∂F/∂p_a, so {θ_a + Δ_a, θ_b + Δ_b} = ∂Δ_b/∂p_a − ∂Δ_a/∂p_b + {Δ_a, Δ_b} = 0,
    # {θ_a + Δ_a, P} = ∂P/∂p_a + {Δ_a, P} = δ and {P, P'} = 0, all through ε^N.
    for a in ring_eps.angles:
        for b in ring_eps.angles:
            value = deltas[b].diff(pairs[a]) - deltas[a].diff(pairs[b])
            value = value + deltas[a].bracket(deltas[b])
            assert value.truncate(order).is_zero()
        for p in ring_eps.momenta:
            value = momenta[p].diff(pairs[a]) + deltas[a].bracket(momenta[p])
            expected = 1 if pairs[a] == p else 0
            assert (value.truncate(order) - expected).is_zero()
    for p in ring_eps.momenta:
        for r in ring_eps.momenta:
            assert momenta[p].bracket(momenta[r]).truncate(order).is_zero()


@pytest.mark.parametrize(
    ("hamiltonian", "angles", "order"),
    [((OSC("J"), DUFFING_H1), None, 4), (tuple(SAM_H), ["l"], 3)],
    ids=["duffing", "sam"],
)
def test_deprit_direct_inverse_identity_by_composition(hamiltonian, angles, order):
    # y(X(y)) = y: compose the inverse (new in old) with the direct (old in new) map
    T = deprit(list(hamiltonian), order, angles)
    ring_eps = _with_eps(hamiltonian[0].ring)
    old_deltas, old_momenta = _coordinates(T, ring_eps, inverse=False)
    new_deltas, new_momenta = _coordinates(T, ring_eps, inverse=True)
    shift = dict(old_deltas)
    shift.update({p: old_momenta[p] - ring_eps.gen(p) for p in ring_eps.momenta})
    for a in ring_eps.angles:
        composed = old_deltas[a] + new_deltas[a].shifted(shift, order)
        assert composed.truncate(order).is_zero()
    for p in ring_eps.momenta:
        composed = new_momenta[p].shifted(shift, order)
        assert (composed - ring_eps.gen(p)).truncate(order).is_zero()


def test_deprit_squeezed_oscillator_transformation_matches_closed_form():
    # The normalising map is linear: q = q' (1 + ε)^(−1/4), p = p' (1 + ε)^(1/4).  Hence
    # J = (p² + q²)/2 = J' [ (1+ε)^(1/2) cos²θ' + (1+ε)^(−1/2) sin²θ' ] with q' = √(2J') sin θ'.
    order = 5
    T = deprit([OSC("J"), OSC("J*(1 - cos(2*th))/2")], order)
    eps = sympy.Symbol("eps")
    J, th = sympy.symbols("J th")
    closed = J * (sympy.sqrt(1 + eps) * sympy.cos(th) ** 2 + sympy.sin(th) ** 2 / sympy.sqrt(1 + eps))
    taylor = sympy.series(closed, eps, 0, order + 1).removeO()
    for n, term in enumerate(T.direct("J")):
        coeff = taylor.coeff(eps, n) * factorial(n)
        assert term == OSC.from_sympy(sympy.expand(coeff))


def test_deprit_numerical_transformation_round_trip():
    # Evaluate direct then inverse numerically with ε small: identity to O(ε^(N+1)).
    order = 4
    T = deprit([OSC("J"), DUFFING_H1], order)
    eps = 1e-2
    th, J = np.linspace(0.1, 6.0, 7), np.linspace(0.2, 1.0, 7)
    d_th = sum(eps**n / factorial(n) * s.compile()(th=th, J=J) for n, s in enumerate(T.direct_angle("th")))
    d_J = sum(eps**n / factorial(n) * s.compile()(th=th, J=J) for n, s in enumerate(T.direct("J")))
    old_th, old_J = th + d_th, d_J
    i_th = sum(
        eps**n / factorial(n) * s.compile()(th=old_th, J=old_J) for n, s in enumerate(T.inverse_angle("th"))
    )
    i_J = sum(eps**n / factorial(n) * s.compile()(th=old_th, J=old_J) for n, s in enumerate(T.inverse("J")))
    assert np.max(np.abs(old_th + i_th - th)) < 50 * eps ** (order + 1)
    assert np.max(np.abs(i_J - J)) < 50 * eps ** (order + 1)


def test_deprit_errors():
    with pytest.raises(ValueError, match="order >= 1"):
        deprit([OSC("J")], 0)
    with pytest.raises(ValueError, match="independent of the angles"):
        deprit([OSC("J*cos(th)")], 2)
    with pytest.raises(ValueError, match="at most order"):
        deprit([OSC("J")] * 4, 2)
    T = LieTransform([OSC("J")])
    with pytest.raises(ValueError, match="use direct_angle"):
        T.direct("th")
    with pytest.raises(ValueError, match="expected an angle"):
        T.direct_angle("J")
    with pytest.raises(ValueError, match="at most 2"):
        T.direct([OSC("J")] * 3)
    with pytest.raises(ValueError, match="empty"):
        lie_sum([])
