"""The heavy top in Pavlov's coordinates (l, g, L, G; H): Hamiltonian and Hamilton's equations.

Independent references: the Lie–Poisson bracket ż = {z, K} of e(3) with the gradients of the
inverse chart differentiated by sympy, and the Euler–Poisson flow in (m, γ) mapped through the chart.
"""

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from andoyer import RigidBody
from andoyer.integrate.reference.euler_poisson import euler_poisson_integrals, integrate_euler_poisson
from andoyer.liepoisson import andoyer_coordinates, e3_from_andoyer, e3_to_andoyer, get_algebra
from andoyer.liepoisson.heavy_top import (
    LeafRates,
    heavy_top_equations,
    heavy_top_hamiltonian,
    heavy_top_rhs,
)
from andoyer.perturbations import HeavyTop, kovalevskaya_top, lagrange_top
from andoyer.perturbations.heavy_top import kovalevskaya_integral_e3

TOPS = {
    "generic": (RigidBody(1.0, 1.6, 2.1), HeavyTop(1.1, [0.3, -0.2, 0.5])),
    "lagrange": lagrange_top(1.0, 0.6, 1.5, 0.4),
    "kovalevskaya": kovalevskaya_top(1.0, 1.3, 0.7),
}
# (m, γ) at t = 0: a generic point of the chart (sin J ≈ 0.24, sin I ≈ 0.8)
M0 = np.array([0.4, -0.3, 2.0])
GAMMA0 = np.array([0.2, 0.8, 0.4]) / np.linalg.norm([0.2, 0.8, 0.4])


@pytest.fixture(scope="module")
def chart_gradients():
    """∇_x of l, g, L, G(x) from the sympy inverse chart, as numpy functions of x (n, 6)."""
    coords = andoyer_coordinates("e3")
    xs = get_algebra("e3").symbols()
    names = ("l", "g", "L", "G")
    by_name = {str(k): v for k, v in coords.inverse.items()}
    grads = {}
    for name in names:
        f = sp.lambdify(xs, [sp.diff(by_name[name], x) for x in xs], "numpy")
        grads[name] = lambda x, f=f: np.stack(np.broadcast_arrays(*f(*x.T)), axis=-1)
    return grads


def sample(rng, n):
    l, L, g, G, H = andoyer_coordinates("e3").sampler(rng, n).T
    return l, g, L, G, H


@pytest.mark.parametrize("name", list(TOPS))
def test_heavy_top_rates_equal_lie_poisson_bracket(name, chart_gradients):
    body, top = TOPS[name]
    l, g, L, G, H = sample(np.random.default_rng(61), 500)
    m, gamma = e3_from_andoyer(l, g, L, G, H)
    x = np.concatenate([m, gamma], axis=-1)
    grad_k = np.concatenate([m / body.moments, np.broadcast_to(top.weight * top.center_of_mass, m.shape)], -1)
    rates = heavy_top_equations(body, top, l, g, L, G, H)
    e3 = get_algebra("e3")
    for field in LeafRates._fields:
        expected = e3.bracket(x, chart_gradients[field](x), grad_k)
        scale = np.maximum(1.0, np.abs(expected))
        assert np.max(np.abs(getattr(rates, field) - expected) / scale) <= 1e-12, field


@pytest.mark.parametrize("name", list(TOPS))
def test_heavy_top_hamiltonian_equals_energy(name):
    body, top = TOPS[name]
    z = sample(np.random.default_rng(62), 1000)
    m, gamma = e3_from_andoyer(*z)
    energy = euler_poisson_integrals(body, top, m, gamma)["energy"]
    np.testing.assert_allclose(heavy_top_hamiltonian(body, top, *z), energy, rtol=1e-14, atol=1e-14)


@pytest.mark.parametrize("name", list(TOPS))
def test_heavy_top_andoyer_flow_matches_euler_poisson(name):
    body, top = TOPS[name]
    periods = 4
    t = np.linspace(0.0, periods * 2 * np.pi * body.moments[2] / M0[2], 41)
    m_ref, gamma_ref = integrate_euler_poisson(body, top, M0, GAMMA0, t)
    z0 = e3_to_andoyer(M0, GAMMA0)
    sol = solve_ivp(
        heavy_top_rhs(body, top, z0.H),
        (t[0], t[-1]),
        [z0.l, z0.g, z0.L, z0.G],
        t_eval=t,
        method="DOP853",
        rtol=1e-13,
        atol=1e-14,
    )
    assert sol.success
    l, g, L, G = sol.y
    m, gamma = e3_from_andoyer(l, g, L, G, z0.H)
    assert np.abs(m - m_ref).max() <= 1e-9
    assert np.abs(gamma - gamma_ref).max() <= 1e-9
    z_ref = e3_to_andoyer(m_ref, gamma_ref)
    for ours, ref in ((l, z_ref.l), (g, z_ref.g)):
        assert np.abs(np.angle(np.exp(1j * (ours - ref)))).max() <= 1e-9
    np.testing.assert_allclose(L, z_ref.L, rtol=0, atol=1e-9)
    np.testing.assert_allclose(G, z_ref.G, rtol=0, atol=1e-9)
    assert np.ptp(G) > 1e-2  # gravity exchanges momentum: G is not a constant here
    if name == "lagrange":
        assert np.ptp(L) == 0.0
    if name == "kovalevskaya":
        K = kovalevskaya_integral_e3(body, top, m, gamma)
        assert np.ptp(K) / K.max() <= 1e-10


def test_heavy_top_equations_broadcast_and_scalars():
    body, top = TOPS["generic"]
    l, g, L, G, H = sample(np.random.default_rng(63), 6)
    rates = heavy_top_equations(body, top, *(v.reshape(2, 3) for v in (l, g, L, G, H)))
    one = heavy_top_equations(body, top, l[4], g[4], L[4], G[4], H[4])
    assert all(np.shape(r) == (2, 3) for r in rates)
    assert all(np.shape(r) == () for r in one)
    assert [float(r[1, 1]) for r in rates] == [float(r) for r in one]
    assert np.shape(heavy_top_hamiltonian(body, top, l, g, L, G, H)) == (6,)
    batch = heavy_top_rhs(body, top, H[0])(0.0, np.stack([l, g, L, G + abs(H[0])]))
    assert batch.shape == (4, 6)


@pytest.mark.parametrize(
    ("point", "match"),
    [
        ((0.1, 0.2, 1.0, 1.0, 0.3), r"^expected a regular point of the chart \(sin J"),
        ((0.1, 0.2, 0.3, 1.0, -1.0), r"^expected a regular point of the chart \(sin I"),
        ((0.1, 0.2, 1.5, 1.0, 0.3), r"^expected \|L\| ≤ G"),
        ((0.1, 0.2, 0.3, -1.0, 0.3), r"^expected G > 0"),
        ((np.nan, 0.2, 0.3, 1.0, 0.3), r"^expected finite"),
    ],
)
def test_heavy_top_equations_reject_bad_points(point, match):
    body, top = TOPS["generic"]
    with pytest.raises(ValueError, match=match):
        heavy_top_equations(body, top, *point)


def test_heavy_top_rejects_bad_models():
    body, top = TOPS["generic"]
    with pytest.raises(ValueError, match=r"^expected an andoyer RigidBody"):
        heavy_top_hamiltonian("moon", top, 0.1, 0.2, 0.3, 1.0, 0.3)
    with pytest.raises(ValueError, match=r"^expected an andoyer HeavyTop"):
        heavy_top_rhs(body, None, 0.3)


def test_leaf_rates_old_name_deprecated():
    import andoyer.liepoisson as lp

    with pytest.warns(DeprecationWarning, match="use LeafRates"):
        old = lp.AndoyerRates
    assert old is LeafRates
