"""Serret's elements (g0, h, -t0; G, H, T): constants of the free flow, round trips, canonicity.

Independent references: the exact free flow (:class:`andoyer.FreeRotation`, theta series), an
mpmath quadrature of ``dt = dl / l̇`` and ``dg = G p(l) dt`` along the level set, and the
elliptic-function solution of Gurfil Appendix A.2 (scipy ``ellipj``).
"""

from __future__ import annotations

import mpmath as mp
import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from scipy import special as sc
from test_sadov_support import (
    BODIES,
    CASES,
    REPRESENTATIVE,
    circle,
    inverse_moments,
    sample,
    separatrix_distance,
)

from andoyer import FreeRotation, RigidBody, State, bodies
from andoyer.state import Serret, SingularChartWarning, andoyer_to_serret, serret_to_andoyer
from andoyer.state.sadov import andoyer_to_sadov, sadov_frequencies
from conftest import rotation_distance

EPS = np.finfo(float).eps
J6 = np.block([[np.zeros((3, 3)), np.eye(3)], [-np.eye(3), np.zeros((3, 3))]])
BODIES_HERE = {**BODIES, "earth-table1": bodies.get("earth")}
CASES_HERE = [*CASES, ("earth-table1", "circulation")]
WELL_CONDITIONED = [c for c in CASES_HERE if c[1] != "near-separatrix" and not c[0].startswith("earth")]


def energy_ratio(body, a):
    """How well a float64 ``T`` fixes the orbit: ``k = e/|e − a_i| + e/√(|e − e_c| w)``.

    ``e = 2T/G²``; ``e_c`` is the region's centre (``a3``, the pole, in circulation; ``a_e``
    in libration) and ``w`` the region's width. The first term is the separatrix, the second
    the small orbits about the centre, whose radius ``r`` the energy fixes only to ``eps/r``.
    """
    _, _, a3, a_i, a_e = inverse_moments(body)
    l, L, G = a[0], a[3], a[4]
    e = (np.sin(l) ** 2 / body.I1 + np.cos(l) ** 2 / body.I2) * (G - L) * (G + L) / G**2 + a3 * (L / G) ** 2
    circulates = (e - a_i) * (a3 - a_i) > 0
    centre, width = np.where(circulates, a3, a_e), np.abs(np.where(circulates, a_i - a3, a_e - a_i))
    with np.errstate(divide="ignore", invalid="ignore"):
        return e / np.abs(e - a_i) + np.where(width > 0, e / np.sqrt(np.abs(e - centre) * width), 0.0)


def frequencies(body, a):
    """``(ω_ℓ, ω_g)`` from Sadov's chart (closed form, verified in test_sadov_*)."""
    s = andoyer_to_sadov(body, *a)
    return sadov_frequencies(body, s.I_l, s.I_g)


# --------------------------------------------------------------- reference by quadrature
def reference_elapsed(body, l, L, G, dps=30):
    """``(t − t₀, g(t) − g(t₀), P_ℓ)`` by mpmath quadrature of ``dt = dl/|l̇|``, ``dg = G p dt``.

    ``l̇ = L (a3 − p(l))``, ``p = sin²l/I1 + cos²l/I2``, ``|L|`` from the energy. The origin is
    the crossing of the (b3, +b_i) half-plane (circulation) or of the meridian of the lobe's
    axis with ``L > 0`` (libration); ``t − t₀ ∈ [0, P_ℓ)``. Librations use ``l = c + w sin θ``.
    """
    with mp.workdps(dps):
        a1, a2, a3 = (1 / mp.mpf(body.I1), 1 / mp.mpf(body.I2), 1 / mp.mpf(body.I3))
        l, L, G = mp.mpf(l), mp.mpf(L), mp.mpf(G)

        def p(t):
            return mp.sin(t) ** 2 * a1 + mp.cos(t) ** 2 * a2

        e = (p(l) * (G - L) * (G + L) + a3 * L * L) / (G * G)

        def dt_dl(t):
            return 1 / (G * mp.sqrt(abs((p(t) - e) / (p(t) - a3))) * abs(a3 - p(t)))

        s2 = (e - a2) / (a1 - a2) if a1 != a2 else mp.mpf(-1)
        if not 0 < s2 < 1:  # circulation: l̇ keeps the sign of L (a3 − p)
            l_ref = 0 if body.B == body.I2 else mp.pi / 2
            d = mp.sign(L) * mp.sign(a3 - p(l_ref))
            arc = mp.fmod(d * (l - l_ref), 2 * mp.pi)
            arc = arc + 2 * mp.pi if arc < 0 else arc

            def along(f):
                return lambda u: f(l_ref + d * u) * dt_dl(l_ref + d * u)

            full = [k * mp.pi / 2 for k in range(5)]
            nodes = [0, *[x for x in full[1:-1] if x < arc], arc]
            dt = mp.quad(along(lambda t: 1), nodes)
            dg = mp.quad(along(lambda t: G * p(t)), nodes)
            period = mp.quad(along(lambda t: 1), full)
            return float(dt), float(dg), float(period)
        t1 = mp.asin(mp.sqrt(s2))
        if (p(mp.pi / 2) - e) * (p(mp.pi / 2) - a3) > 0:
            centre, half = (mp.pi / 2 if mp.sin(l) > 0 else 3 * mp.pi / 2), mp.pi / 2 - t1
        else:
            centre, half = (0 if mp.cos(l) > 0 else mp.pi), t1
        d = mp.sign(a3 - p(centre))  # direction of l at the origin (L > 0)
        offset = mp.fmod(l - centre + 3 * mp.pi, 2 * mp.pi) - mp.pi

        def along(f):
            def g(theta):
                t = centre + half * mp.sin(theta)
                return 0 if p(t) == e else f(t) * dt_dl(t) * half * mp.cos(theta)

            return g

        theta = mp.asin(max(-1, min(1, abs(offset) / half)))
        tq, gq = (
            mp.quad(along(lambda t: 1), [0, mp.pi / 2]),
            mp.quad(along(lambda t: G * p(t)), [0, mp.pi / 2]),
        )
        tl, gl = mp.quad(along(lambda t: 1), [0, theta]), mp.quad(along(lambda t: G * p(t)), [0, theta])
        first_side = mp.sign(offset) == d
        if first_side:
            k, s = (0, 1) if L > 0 else (2, -1)
        else:
            k, s = (2, 1) if L < 0 else (4, -1)
        return float(k * tq + s * tl), float(k * gq + s * gl), float(4 * tq)


QUADRATURE_CASES = [*REPRESENTATIVE, ("b3-max", "near-separatrix"), ("strongly-triaxial", "libration")]


def check_quadrature(name, regime, rng, n):
    body = BODIES_HERE[name]
    a = sample(body, rng, n, regime)
    s = andoyer_to_serret(body, *a, t=0.0)
    k = energy_ratio(body, a)
    w = frequencies(body, a)
    for i in range(n):
        dt, dg, period = reference_elapsed(body, a[0][i], a[3][i], a[4][i])
        assert period == pytest.approx(2 * np.pi / abs(w.omega_l[i]), rel=1e-13 + 1e-14 * k[i])
        # Both in [0, P): compare on the circle of length P.
        err_t = abs((-s.t0[i] - dt + period / 2) % period - period / 2) / period
        assert err_t <= 1e-14 * k[i] + 1e-14
        g_err = abs(circle(s.g0[i] - (a[1][i] - dg)))
        assert g_err <= (1e-14 * k[i] + 1e-14) * (1 + abs(w.omega_g[i]) * period)


@pytest.mark.slow
@pytest.mark.parametrize(("name", "regime"), QUADRATURE_CASES)
def test_t0_and_g0_match_quadrature(name, regime, rng):
    """``t − t0`` and ``g(t) − g0`` against an mpmath quadrature along the level set."""
    check_quadrature(name, regime, rng, 2)


@pytest.mark.slow
@pytest.mark.parametrize(("name", "regime"), CASES_HERE)
def test_t0_and_g0_match_quadrature_every_case(name, regime, rng):
    check_quadrature(name, regime, rng, 8)


# ------------------------------------------------------------------- the free flow
@pytest.mark.parametrize(("name", "regime"), CASES_HERE)
def test_elements_are_constant_along_the_exact_free_flow(name, regime, rng):
    """Over ~60 periods, with the branch fixed by ``epoch``: G, H, T, h constant to 1e-12; t0 to
    2e-13 P_ℓ and g0 to 2e-13 (1 + |ω_g| P_ℓ) (the chart's own conditioning: ∂g0/∂t0 = ω_g),
    both times ``k`` in the near-separatrix regime."""
    body = BODIES_HERE[name]
    a = sample(body, rng, 40, regime)
    state = State.from_andoyer(*a)
    w = frequencies(body, a)
    period = 2 * np.pi / np.abs(w.omega_l)
    times = np.array([0.0, 0.37, 1.9, 7.3, 23.1, 61.7])[None, :] * period[:, None]
    later = FreeRotation(body).propagate(state[:, None], times)
    ref = state.as_serret(body, t=0.0)
    s = later.as_serret(body, t=times, epoch=0.0)
    for x, y in ((s.G, ref.G), (s.T, ref.T)):
        assert np.abs(x / y[:, None] - 1).max() <= 1e-12
    assert np.abs(s.H - ref.H[:, None]).max() <= 1e-12 * a[4].max()
    assert np.abs(circle(s.h - ref.h[:, None])).max() <= 1e-12
    assert np.all(s.sign == ref.sign[:, None])
    k = energy_ratio(body, a) if regime == "near-separatrix" else 1.0
    scale = (1 + np.abs(w.omega_g) * period) * k
    err_t = np.abs(s.t0 - ref.t0[:, None]) / period[:, None]
    err_g = np.abs(circle(s.g0 - ref.g0[:, None]))
    # Measured: t0/P to ~5e-14 and g0 to ~1e-12 over 60 periods for the generic bodies (t0
    # carries eps·|t|, and g0 = φ_g − ω_g (t − t0) multiplies it by ω_g).
    assert np.all(err_t.max(axis=1) <= 2e-13 * k)
    assert np.all(err_g.max(axis=1) <= 2e-13 * scale)


@pytest.mark.parametrize(("name", "regime"), REPRESENTATIVE)
def test_default_branch_is_the_last_passage_before_t(name, regime, rng):
    """With ``epoch = t`` (default), ``t − P < t0 <= t``; the pair (t0, g0) moves by whole periods,
    ``(n P, n ω_g P)``, against the elements with a fixed epoch. P from the free flow's own period."""
    body = BODIES_HERE[name]
    a = sample(body, rng, 20, regime)
    state = State.from_andoyer(*a)
    period = FreeRotation(body).periods(state).period
    w = frequencies(body, a)
    times = np.array([0.0, 0.6, 3.2, 11.45])[None, :] * period[:, None]
    later = FreeRotation(body).propagate(state[:, None], times)
    fixed = later.as_serret(body, t=times, epoch=0.0)
    moving = later.as_serret(body, t=times)
    assert np.all(moving.t0 <= times)
    assert np.all(moving.t0 > times - period[:, None] * (1 + 1e-12))
    n = (moving.t0 - fixed.t0) / period[:, None]
    assert np.abs(n - np.round(n)).max() <= 1e-9
    assert np.array_equal(np.round(n), np.floor((times - fixed.t0) / period[:, None]))
    assert np.all(np.round(n[:, -1]) >= 11)
    shift = np.round(n) * (w.omega_g * period)[:, None]
    # The shift is tens of thousands of radians for the Earth (ω_g P ≈ 7e3): the free flow's
    # period and the chart's 2π/ω_ℓ agree to ~1e-14 relative, an error the shift multiplies.
    assert np.all(np.abs(circle(moving.g0 - fixed.g0 - shift)) <= 1e-9 + 1e-13 * np.abs(shift))


def test_relation_to_serrets_own_time_origin(rng):
    """Gurfil A.2 (I1 < I2 < I3, L > 0): with Serret's n (eq. 59) and κ² (eq. 167),
    ``u = n (t − t0) + K(κ)`` gives ``α' = a cn u, β' = b sn u, γ' = √(1−a²) dn u`` and ``4K/n = P``:
    our origin is a quarter period after Serret's ``u = 0``."""
    body = BODIES["b3-max"]
    I1, I2, I3 = body.moments
    a = sample(body, rng, 200, "circulation")
    keep = a[3] > 0
    state = State.from_andoyer(*(x[keep] for x in a))
    t = 2.7
    s = state.as_serret(body, t=t)
    m, G = state.m_body, np.linalg.norm(state.m_body, axis=-1)
    T = 0.5 * np.sum(m**2 / body.moments, axis=-1)
    P2 = 2 * T / G**2
    a2, b2 = (P2 - 1 / I3) / (1 / I1 - 1 / I3), (P2 - 1 / I3) / (1 / I2 - 1 / I3)
    kappa2 = (b2 - a2) / (1 - a2)
    n = np.sqrt((G**2 / I1 - 2 * T) * (1 / I2 - 1 / I3))
    K = sc.ellipk(kappa2)
    sn, cn, dn, _ = sc.ellipj(n * (t - s.t0) + K, kappa2)
    expected = np.stack([np.sqrt(a2) * cn, np.sqrt(b2) * sn, np.sqrt(1 - a2) * dn], axis=-1)
    assert np.abs(m / G[:, None] - expected).max() <= 1e-13
    period = FreeRotation(body).periods(state).period
    assert np.abs(4 * K / n / period - 1).max() <= 1e-13


# ------------------------------------------------------------------------ round trips
@pytest.mark.parametrize(("name", "regime"), WELL_CONDITIONED)
def test_round_trip_state_serret_state(name, regime, rng):
    body = BODIES_HERE[name]
    state = State.from_andoyer(*sample(body, rng, 300, regime, G=2.0))
    back = State.from_serret(body, *state.as_serret(body, t=5.0), t=5.0)
    assert rotation_distance(back.quaternion, state.quaternion).max() <= 1e-13
    assert np.abs(back.m_body - state.m_body).max() <= 1e-13 * 2.0


@pytest.mark.parametrize(("name", "regime"), CASES_HERE)
def test_round_trip_is_bounded_by_the_energy_conditioning(name, regime, rng):
    """Everywhere (Earth, near the separatrix): error <= 1e-13 + 32 eps k (``k`` of
    :func:`energy_ratio`): a float64 ``T`` resolves the orbit only to ``eps·k`` (Sadov's
    ``I_ℓ`` does not have this limitation)."""
    body = BODIES_HERE[name]
    a = sample(body, rng, 300, regime)
    state = State.from_andoyer(*a)
    back = State.from_serret(body, *state.as_serret(body))
    bound = 1e-13 + 32 * EPS * energy_ratio(body, a)
    assert np.all(rotation_distance(back.quaternion, state.quaternion) <= bound)
    assert np.all(np.abs(back.m_body - state.m_body).max(axis=-1) <= bound)


@pytest.mark.parametrize(("name", "regime"), WELL_CONDITIONED)
def test_round_trip_serret_state_serret(name, regime, rng):
    body = BODIES_HERE[name]
    a = sample(body, rng, 200, regime)
    s = andoyer_to_serret(body, *a, t=1.0)
    again = State.from_serret(body, *s, t=1.0).as_serret(body, t=1.0)
    period = 2 * np.pi / np.abs(frequencies(body, a).omega_l)
    err_t = np.abs((again.t0 - s.t0 + period / 2) % period - period / 2) / period
    assert err_t.max() <= 1e-13
    assert np.abs(circle(again.g0 - s.g0)).max() <= 1e-12
    assert np.abs(again.T / s.T - 1).max() <= 1e-14
    assert np.array_equal(again.sign, s.sign)


@settings(max_examples=120, deadline=None)
@given(
    st.sampled_from(sorted(n for n in BODIES if n != "earth")),
    st.floats(0.0, 2 * np.pi),
    st.floats(0.0, 2 * np.pi),
    st.floats(-0.999, 0.999),
    st.floats(-0.99, 0.99),
    st.floats(-50.0, 50.0),
)
def test_round_trip_hypothesis(name, l, g, x, y, t):
    """Any state with ``k = e/|e − a_i| <= 50`` comes back to 1e-13 (every body but the Earth).

    (``H = ±G`` is excluded: the Andoyer chart itself is singular there.)"""
    body = BODIES[name]
    a = (l, g, 0.4, x, 1.0, y)
    k = energy_ratio(body, tuple(np.asarray(v, float) for v in a))
    assume(k <= 50)
    assume(x != 0.0 or abs(np.sin(2 * l)) > 1e-100)  # exactly a libration centre: warns
    state = State.from_andoyer(*a)
    back = State.from_serret(body, *state.as_serret(body, t=t), t=t)
    assert rotation_distance(back.quaternion, state.quaternion) <= 1e-13
    assert np.abs(back.m_body - state.m_body).max() <= 1e-13


def test_initial_andoyer_round_trip_and_constancy(rng):
    body = BODIES["strongly-triaxial"]
    a = sample(body, rng, 50, "circulation")
    state = State.from_initial_andoyer(body, *a, epoch=0.5, t=3.0)
    back = state.as_initial_andoyer(body, 0.5, t=3.0)
    assert max(np.abs(circle(x - y)).max() for x, y in zip(back[:3], a[:3], strict=True)) <= 1e-12
    assert max(np.abs(x - y).max() for x, y in zip(back[3:], a[3:], strict=True)) <= 1e-13
    direct = FreeRotation(body).propagate(State.from_andoyer(*a), 2.5)
    assert rotation_distance(direct.quaternion, state.quaternion).max() <= 1e-14


# ---------------------------------------------------------------------------- canonicity
def jacobians(f, x, step):
    """Richardson central differences of the vectorised ``f`` at the rows of ``x`` (n, 6);
    outputs 0 and 1 (g0, h) are angles, differenced on the circle."""
    n = x.shape[0]
    offsets = np.array([1.0, -1.0, 0.5, -0.5])[:, None, None, None] * np.eye(6)[None, :, None, :] * step
    values = f((x[None, None] + offsets).reshape(-1, 6)).reshape(4, 6, n, 6)

    def diff(i, j, h):
        d = values[i] - values[j]
        d[..., :2] = circle(d[..., :2])
        return d / (2 * h)

    h = step.T[:, :, None]
    D = (4 * diff(2, 3, h / 2) - diff(0, 1, h)) / 3
    return np.transpose(D, (1, 2, 0))


def serret_map(body, t=0.37):
    """Andoyer (l, g, h, L, G, H) -> Serret (g0, h, -t0, G, H, T) at the fixed time ``t``."""

    def f(v):
        s = andoyer_to_serret(body, *v.T, t=t)
        return np.stack([s.g0, s.h, -s.t0, s.G, s.H, s.T], axis=-1)

    return f


def canonical_points(body, regime, rng, n):
    """States away from the branch cut of t0 (Δ/P in [0.15, 0.85]), the separatrix and the poles."""
    a = sample(body, rng, 40 * n, regime)
    s = andoyer_to_serret(body, *a, t=0.37)
    period = 2 * np.pi / np.abs(frequencies(body, a).omega_l)
    frac = (0.37 - s.t0) / period
    d = separatrix_distance(body, a[0], a[3], a[4])
    keep = (frac > 0.15) & (frac < 0.85) & (d > 0.1) & (np.abs(a[3]) < 0.95)
    idx = np.flatnonzero(keep)[:n]
    assert len(idx) == n
    x = np.stack([v[idx] for v in a], axis=-1)
    step = 1e-4 * np.ones_like(x)
    step[:, 3:] *= np.minimum(np.maximum(np.abs(x[:, 3:4]), 0.05), 1 - np.abs(x[:, 3:4]))
    return x, step


def symplectic_error(M):
    return np.abs(np.transpose(M, (0, 2, 1)) @ J6 @ M - J6).max(axis=(1, 2))


@pytest.mark.parametrize(("name", "regime"), [c for c in REPRESENTATIVE if c != ("earth", "libration")])
def test_andoyer_to_serret_is_symplectic(name, regime, rng):
    """``Mᵀ J M = J`` to 1e-7 for the map ``(l, g, h, L, G, H) → (g0, h, −t0, G, H, T)`` at fixed t.

    (The Earth's librations are left out: there ``|∂g0/∂l| ~ 1e6`` and double-precision
    differences cannot resolve the condition.)"""
    body = BODIES[name]
    x, step = canonical_points(body, regime, rng, 4)
    M = jacobians(serret_map(body), x, step)
    assert symplectic_error(M).max() <= 1e-7


@pytest.mark.parametrize("broken", ["g0 is the current g", "t0 instead of -t0", "T scaled"])
def test_symplectic_check_detects_a_broken_map(broken, rng):
    body = BODIES["b3-max"]
    x, step = canonical_points(body, "circulation", rng, 3)
    good = serret_map(body)

    def f(v):
        y = good(v)
        if broken == "g0 is the current g":
            y[:, 0] = v[:, 1]
        elif broken == "t0 instead of -t0":
            y[:, 2] = -y[:, 2]
        else:
            y[:, 5] *= 1.001
        return y

    assert symplectic_error(jacobians(f, x, step)).min() > 1e-4
    assert symplectic_error(jacobians(good, x, step)).max() <= 1e-7


# ------------------------------------------------------------- degenerate bodies and states
def test_axisymmetric_body_round_trip_and_constancy(rng):
    """I1 = I2: φ_ℓ = l, ω_ℓ = (1/I3 − 1/I1) L; t0 from the uniform rotation of l."""
    body = RigidBody(1.0, 1.0, 1.5)
    L = rng.uniform(0.1, 0.9, 20) * rng.choice([-1.0, 1.0], 20)
    l, g, h = rng.uniform(0, 2 * np.pi, (3, 20))
    state = State.from_andoyer(l, g, h, L, 1.0, 0.3)
    s = state.as_serret(body)
    omega_l = (1 / 1.5 - 1.0) * L
    expected = np.where(omega_l > 0, l, (2 * np.pi - l) % (2 * np.pi)) / np.abs(omega_l)
    assert np.abs(-s.t0 - expected).max() <= 1e-13 * np.abs(expected).max()
    later = FreeRotation(body).propagate(state, 13.0)
    s2 = later.as_serret(body, t=13.0, epoch=0.0)
    assert np.abs(s2.t0 - s.t0).max() <= 1e-12
    assert np.abs(circle(s2.g0 - s.g0)).max() <= 1e-12
    back = State.from_serret(body, *s)
    assert rotation_distance(back.quaternion, state.quaternion).max() <= 1e-13


def test_libration_centre_warns_at_the_caller_and_round_trips():
    body = BODIES["b3-max-b1-intermediate"]  # b_e = b2: the centre +b2 is l = 0, L = 0
    state = State.from_andoyer(0.0, 0.3, 0.2, 0.0, 1.0, 0.4)
    with pytest.warns(SingularChartWarning, match="libration centre") as record:
        s = state.as_serret(body, t=2.0)
    assert record[0].filename == __file__  # stacklevel points at the caller
    assert float(s.sign) == 1.0
    assert float(s.t0) == 2.0
    assert float(s.g0) == pytest.approx(0.3, abs=1e-15)
    back = State.from_serret(body, *s, t=2.0)
    assert rotation_distance(back.quaternion, state.quaternion) <= 1e-14


@pytest.mark.parametrize(
    ("body", "andoyer", "match"),
    [
        (BODIES["b3-max"], (0.0, 0.1, 0.2, 0.0, 1.0, 0.5), "separatrix"),  # m along +b2
        (BODIES["b1-symmetric"], (0.0, 0.1, 0.2, 0.6, 1.0, 0.5), "separatrix"),  # circle of equilibria
        (RigidBody(1.0, 1.0, 1.5), (0.3, 0.1, 0.2, 0.0, 1.0, 0.5), "L = 0"),
        (RigidBody(2.0, 2.0, 2.0), (0.3, 0.1, 0.2, 0.5, 1.0, 0.5), "not a sphere"),
        (RigidBody(1.0, 3.0, 2.0), (0.3, 0.1, 0.2, 0.5, 1.0, 0.5), "smallest or the largest"),
    ],
)
def test_undefined_states_raise(body, andoyer, match):
    with pytest.raises(ValueError, match=match):
        andoyer_to_serret(body, *andoyer)


def test_from_serret_on_the_separatrix_raises():
    body = BODIES["b3-max"]
    with pytest.raises(ValueError, match="separatrix"):
        serret_to_andoyer(body, 0.0, 0.0, 0.0, 1.0, 0.5, 0.5 / body.I2)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"T": 0.9}, r"expected G²/\(2 I_max\) <= T"),
        ({"T": 0.1}, r"expected G²/\(2 I_max\) <= T"),
        ({"sign": 0.5}, "expected sign = [+]1 or -1"),
        ({"sign": 0.0}, "expected sign"),
        ({"G": -1.0}, "expected G > 0"),
        ({"H": 1.5}, r"expected \|H\| <= G"),
        ({"t0": np.nan}, "expected finite t0"),
        ({"g0": np.zeros(2), "h": np.zeros(3)}, "expected shapes that broadcast"),
    ],
)
def test_bad_serret_input_raises(kwargs, match):
    args = {"g0": 0.1, "h": 0.2, "t0": 0.0, "G": 1.0, "H": 0.5, "T": 0.3, "sign": 1.0} | kwargs
    with pytest.raises(ValueError, match=match):
        State.from_serret(BODIES["b3-max"], **args)


def test_bad_body_raises():
    state = State.from_andoyer(0.3, 0.1, 0.2, 0.5, 1.0, 0.5)
    with pytest.raises(ValueError, match=r"expected an andoyer\.RigidBody"):
        state.as_serret("earth")
    with pytest.raises(ValueError, match=r"expected an andoyer\.RigidBody"):
        serret_to_andoyer(None, 0.1, 0.2, 0.0, 1.0, 0.5, 0.3)


def test_scalar_and_broadcast_shapes():
    body = BODIES["b3-max"]
    s = State.from_andoyer(0.3, 0.1, 0.2, 0.5, 1.0, 0.5).as_serret(body)
    assert isinstance(s, Serret)
    assert all(np.shape(v) == () for v in s)
    grid = State.from_andoyer(np.linspace(0.1, 1.0, 4)[:, None], 0.1, 0.2, 0.5, 1.0, 0.5).as_serret(
        body, t=np.arange(3.0)
    )
    assert all(np.shape(v) == (4, 3) for v in grid)
    back = State.from_serret(body, s.g0, s.h, s.t0, s.G, s.H, s.T, [1.0, 1.0], t=[0.0, 1.0])
    assert back.shape == (2,)
