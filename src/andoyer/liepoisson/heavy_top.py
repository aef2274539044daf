r"""The heavy top in Pavlov's Andoyer–Deprit coordinates on an e(3) leaf.

On the leaf ``{|γ| = 1, m·γ = H}`` the coordinates ``(l, L; g, G)`` of
:func:`~andoyer.liepoisson.e3_from_andoyer` are canonical (``{l, L} = {g, G} = 1``),
so the Euler–Poisson equations of a top with moments ``I`` about the fixed
point, weight ``w = m g0`` and centre of mass ``r_c`` (body axes) become
Hamilton's equations of

.. math::

    K(l, g, L, G; H) = \tfrac12\Big[(G^2-L^2)\Big(\frac{\sin^2 l}{I_1}
        + \frac{\cos^2 l}{I_2}\Big) + \frac{L^2}{I_3}\Big]
        + w\, \mathbf r_c\cdot\boldsymbol\gamma(l, g, L, G; H),

with ``γ`` of Pavlov eq. 1.7 (``cos I = H/G``, ``cos J = L/G``):

.. math::

    \dot l = \frac{\partial K}{\partial L} = L\Big(\sin^2 l\,\frac{I_1-I_3}{I_1 I_3}
        + \cos^2 l\,\frac{I_2-I_3}{I_2 I_3}\Big) + w\,\mathbf r_c\cdot\partial_L\boldsymbol\gamma,
    \qquad
    \dot L = -\frac{\partial K}{\partial l} = (G^2-L^2)\sin l\cos l\,\frac{I_1-I_2}{I_1 I_2}
        - w\,(x_c\gamma_2 - y_c\gamma_1),

    \dot g = \frac{\partial K}{\partial G} = G\Big(\frac{\sin^2 l}{I_1}
        + \frac{\cos^2 l}{I_2}\Big) + w\,\mathbf r_c\cdot\partial_G\boldsymbol\gamma,
    \qquad
    \dot G = -\frac{\partial K}{\partial g} = -w\,\mathbf r_c\cdot\partial_g\boldsymbol\gamma,

(``∂_l γ = (γ2, −γ1, 0)``), and ``H`` is constant. With ``ρ_J = √(G²−L²)``,
``ρ_I = √(G²−H²)``, ``N = H ρ_J + L ρ_I cos g`` and ``D = H L − ρ_I ρ_J cos g``
(so ``γ1 = (N sin l)/G² + (ρ_I/G) sin g cos l``, ``γ3 = D/G²``):

.. math::

    \partial_L(N, D) &= (-H L/ρ_J + ρ_I \cos g,\; H + L ρ_I \cos g/ρ_J),\\
    \partial_G(N, D) &= (G H/ρ_J + G L \cos g/ρ_I,\; -G \cos g\,(ρ_I^2 + ρ_J^2)/(ρ_I ρ_J)),\\
    \partial_G(ρ_I/G) &= H^2/(G^2 ρ_I),\qquad
    \partial_g γ = \tfrac{ρ_I}{G}\,(\cos g\cos l - \tfrac LG \sin g \sin l,\;
        -\cos g \sin l - \tfrac LG \sin g\cos l,\; \tfrac{ρ_J}{G}\sin g).

The chart is singular where ``sin J = 0`` (``m`` along ``b3``) or ``sin I = 0``
(``m`` along ``γ``); the rates are rejected there. The equations are checked
against the Lie–Poisson bracket ``ż = {z, K}`` of :func:`get_algebra` ("e3") and
against the Euler–Poisson flow (``tests/liepoisson/test_liepoisson_heavy_top.py``).
"""

from __future__ import annotations

import warnings
from collections.abc import Callable
from typing import Any, NamedTuple

import numpy as np

from andoyer._validation import broadcast
from andoyer.body import RigidBody
from andoyer.liepoisson._domain import SINGULAR_TOL, as_scalars, momenta
from andoyer.perturbations.heavy_top import HeavyTop

__all__ = ["LeafRates", "heavy_top_equations", "heavy_top_hamiltonian", "heavy_top_rhs"]


class LeafRates(NamedTuple):
    """Time derivatives ``(dl/dt, dg/dt, dL/dt, dG/dt)`` on an e(3) leaf (arrays of equal shape).

    Named ``AndoyerRates`` before 0.1 (a second class of that name, with the six rates of the
    full Andoyer chart, is :class:`andoyer.state.andoyer.AndoyerRates`); the old name still works,
    with a :class:`DeprecationWarning`.
    """

    l: np.ndarray
    g: np.ndarray
    L: np.ndarray
    G: np.ndarray


def _check_models(body: Any, top: Any) -> None:
    if not isinstance(body, RigidBody):
        raise ValueError(f"expected an andoyer RigidBody, got {type(body).__name__}")
    if not isinstance(top, HeavyTop):
        raise ValueError(f"expected an andoyer HeavyTop, got {type(top).__name__}")


def _leaf_point(l: Any, g: Any, L: Any, G: Any, H: Any) -> tuple[np.ndarray, ...]:
    L, G, H = momenta(L, G, H)
    ell, g, L, G, H = broadcast(
        ("l", as_scalars("l", l)), ("g", as_scalars("g", g)), ("L", L), ("G", G), ("H", H)
    )
    return ell, g, L, G, H


class _Trig(NamedTuple):
    sl: np.ndarray
    cl: np.ndarray
    sg: np.ndarray
    cg: np.ndarray
    rho_j: np.ndarray
    rho_i: np.ndarray
    gamma: np.ndarray


def _trig(ell: np.ndarray, g: np.ndarray, L: np.ndarray, G: np.ndarray, H: np.ndarray) -> _Trig:
    sl, cl, sg, cg = np.sin(ell), np.cos(ell), np.sin(g), np.cos(g)
    rho_j = np.sqrt((G - L) * (G + L))
    rho_i = np.sqrt((G - H) * (G + H))
    G2 = G * G
    N = H * rho_j + L * rho_i * cg
    sin_i = rho_i / G
    gamma = np.stack(
        [N * sl / G2 + sin_i * sg * cl, N * cl / G2 - sin_i * sg * sl, (H * L - rho_i * rho_j * cg) / G2],
        axis=-1,
    )
    return _Trig(sl, cl, sg, cg, rho_j, rho_i, gamma)


def heavy_top_hamiltonian(
    body: RigidBody, top: HeavyTop, l: Any, g: Any, L: Any, G: Any, H: Any
) -> np.ndarray:
    """The heavy-top Hamiltonian ``K(l, g, L, G; H)`` on the e(3) leaf labelled by ``H``.

    Parameters
    ----------
    body : RigidBody
        Moments about the fixed point.
    top : HeavyTop
        Weight and centre of mass.
    l, g, L, G, H : array_like, broadcastable
        Pavlov's coordinates (:class:`~andoyer.liepoisson.E3Coordinates`);
        ``G > 0``, ``|L| ≤ G``, ``|H| ≤ G``.

    Returns
    -------
    numpy.ndarray, shape (...)
        ``½ Σ m_i²/I_i + w r_c·γ`` at the point.

    Examples
    --------
    Equal to the energy on ``(m, γ)``:

    >>> import numpy as np
    >>> from andoyer.liepoisson import e3_from_andoyer
    >>> from andoyer.perturbations import lagrange_top
    >>> body, top = lagrange_top(1.0, 0.5, 2.0, 0.3)
    >>> z = (0.4, 1.3, 0.5, 1.5, -0.7)
    >>> m, gamma = e3_from_andoyer(*z)
    >>> energy = 0.5 * np.sum(m**2 / body.moments) + top.weight * gamma @ top.center_of_mass
    >>> bool(np.isclose(heavy_top_hamiltonian(body, top, *z), energy, rtol=1e-15))
    True
    """
    _check_models(body, top)
    ell, g, L, G, H = _leaf_point(l, g, L, G, H)
    tr = _trig(ell, g, L, G, H)
    i1, i2, i3 = body.inverse_moments
    kinetic = 0.5 * (tr.rho_j**2 * (tr.sl**2 * i1 + tr.cl**2 * i2) + L * L * i3)
    return (kinetic + top.weight * tr.gamma @ top.center_of_mass)[()]


def heavy_top_equations(
    body: RigidBody, top: HeavyTop, l: Any, g: Any, L: Any, G: Any, H: Any
) -> LeafRates:
    """Hamilton's equations of the heavy top in ``(l, g, L, G)`` on the leaf ``H``.

    Parameters
    ----------
    body : RigidBody
        Moments about the fixed point.
    top : HeavyTop
        Weight and centre of mass.
    l, g, L, G, H : array_like, broadcastable
        Pavlov's coordinates; ``G > 0``, ``|L| < G``, ``|H| < G``.

    Returns
    -------
    LeafRates
        ``(dl/dt, dg/dt, dL/dt, dG/dt) = (∂K/∂L, ∂K/∂G, −∂K/∂l, −∂K/∂g)``, each (...).

    Raises
    ------
    ValueError
        For bad input, or at a singular point of the chart
        (``sin J ≤ SINGULAR_TOL`` or ``sin I ≤ SINGULAR_TOL``).

    Examples
    --------
    The Lagrange top keeps ``L = m3``; with no gravity ``G`` is constant and
    ``dg/dt = G (sin² l/I1 + cos² l/I2)``.

    >>> from andoyer.perturbations import HeavyTop, lagrange_top
    >>> body, top = lagrange_top(1.0, 0.5, 2.0, 0.3)
    >>> rates = heavy_top_equations(body, top, 0.4, 1.3, 0.5, 1.5, -0.7)
    >>> float(rates.L), round(float(rates.G), 12)
    (0.0, -0.482078773161)
    >>> float(heavy_top_equations(body, HeavyTop(1e-300, [0, 0, 1.0]), 0.4, 1.3, 0.5, 1.5, -0.7).g)
    1.5
    """
    _check_models(body, top)
    ell, g, L, G, H = _leaf_point(l, g, L, G, H)
    tr = _trig(ell, g, L, G, H)
    sl, cl, sg, cg, rho_j, rho_i = tr.sl, tr.cl, tr.sg, tr.cg, tr.rho_j, tr.rho_i
    for name, rho in (("sin J", rho_j), ("sin I", rho_i)):
        bad = rho <= SINGULAR_TOL * G
        if np.any(bad):
            i = np.argmax(bad.ravel())
            value = float((rho / G).ravel()[i])
            raise ValueError(
                f"expected a regular point of the chart ({name} > {SINGULAR_TOL:g}), got {name} = {value!r}"
            )
    I1, I2, I3 = body.moments
    i1, i2, _ = body.inverse_moments
    x, y, z = top.center_of_mass
    G2 = G * G
    N = H * rho_j + L * rho_i * cg
    D = H * L - rho_i * rho_j * cg
    # ∂γ/∂L at fixed (G, H): only N and D move.
    N_L = (rho_i * cg - H * L / rho_j) / G2
    D_L = (H + L * rho_i * cg / rho_j) / G2
    dV_dL = (x * sl + y * cl) * N_L + z * D_L
    # ∂γ/∂G at fixed (L, H): N/G², D/G² and sin I = ρ_I/G move.
    N_G = (G * H / rho_j + G * L * cg / rho_i) / G2 - 2 * N / (G2 * G)
    D_G = -cg * (rho_i**2 + rho_j**2) / (G * rho_i * rho_j) - 2 * D / (G2 * G)
    sin_i_G = H * H / (G2 * rho_i)
    dV_dG = (x * sl + y * cl) * N_G + (x * cl - y * sl) * sg * sin_i_G + z * D_G
    sin_i, cos_j, sin_j = rho_i / G, L / G, rho_j / G
    dV_dg = sin_i * (x * (cg * cl - cos_j * sg * sl) - y * (cg * sl + cos_j * sg * cl) + z * sin_j * sg)
    gamma = tr.gamma
    w = top.weight
    l_dot = L * (sl * sl * (I1 - I3) / (I1 * I3) + cl * cl * (I2 - I3) / (I2 * I3)) + w * dV_dL
    g_dot = G * (sl * sl * i1 + cl * cl * i2) + w * dV_dG
    L_dot = rho_j**2 * sl * cl * (I1 - I2) / (I1 * I2) - w * (x * gamma[..., 1] - y * gamma[..., 0])
    G_dot = -w * dV_dg
    return LeafRates(l_dot[()], g_dot[()], L_dot[()], G_dot[()])


def heavy_top_rhs(body: RigidBody, top: HeavyTop, H: float) -> Callable[[float, np.ndarray], np.ndarray]:
    """Right-hand side ``f(t, y)``, ``y = (l, g, L, G)``, for ``scipy.integrate.solve_ivp``.

    Parameters
    ----------
    body : RigidBody
    top : HeavyTop
    H : float
        The leaf, ``H = m·γ``.

    Returns
    -------
    callable
        ``f(t, y)`` with ``y`` of shape (4,) or (4, k) (``vectorized=True``).

    Examples
    --------
    >>> import numpy as np
    >>> from scipy.integrate import solve_ivp
    >>> from andoyer.perturbations import lagrange_top
    >>> body, top = lagrange_top(1.0, 0.5, 2.0, 0.3)
    >>> sol = solve_ivp(heavy_top_rhs(body, top, -0.7), (0, 2), [0.4, 1.3, 0.5, 1.5],
    ...                 method="DOP853", rtol=1e-12, atol=1e-12)
    >>> K = heavy_top_hamiltonian(body, top, *sol.y, -0.7)
    >>> bool(np.ptp(K) < 1e-11), float(np.ptp(sol.y[2]))  # energy and L = m3 conserved
    (True, 0.0)
    """
    _check_models(body, top)
    H = float(as_scalars("H", H))

    def rhs(_t: float, y: np.ndarray) -> np.ndarray:
        ell, g, L, G = y
        return np.stack(heavy_top_equations(body, top, ell, g, L, G, H))

    return rhs


def __getattr__(name: str) -> Any:
    if name == "AndoyerRates":
        warnings.warn(
            "andoyer.liepoisson.AndoyerRates is deprecated: use LeafRates (the four rates on an e(3) leaf)",
            DeprecationWarning,
            stacklevel=2,
        )
        return LeafRates
    msg = f"module {__name__!r} has no attribute {name!r}"
    raise AttributeError(msg)
