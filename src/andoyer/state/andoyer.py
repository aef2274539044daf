r"""Andoyer variables ``(l, g, h, L, G, H)`` (Gurfil et al. §3.2; Deprit & Elipe 1993).

Convention: the attitude taking body vectors to the reference frame is the
3-1-3-1-3 sequence (Gurfil eq. 70, here as active rotations)

.. math:: \mathcal{R} = R_z(h)\, R_x(I)\, R_z(g)\, R_x(J)\, R_z(l),
   \qquad \cos I = H/G, \quad \cos J = L/G,

with ``0 <= I, J <= π``. ``G = |m|``; ``H`` is the projection of the angular
momentum on the reference axis ``s3``; ``L`` its projection on the body axis
``b3``. The body and reference components of the angular momentum are

.. math::
   \mathbf{m} = (\sqrt{G^2-L^2}\sin l,\ \sqrt{G^2-L^2}\cos l,\ L), \qquad
   \mathbf{M} = G\,(\sin I \sin h,\ -\sin I \cos h,\ \cos I).

The chart is singular where ``sin J = 0`` (conventions: ``l = 0``) and where
``sin I = 0`` (``h = 0``); there a :class:`SingularChartWarning` is issued.
States within ``4ε G`` of a pole are snapped onto it (``L`` or ``H = ±G``).
Near those points the momenta ``L`` or ``H`` determine ``J`` or ``I`` only to
``ε / sin J`` or ``ε / sin I``: this is the chart's conditioning, not round-off.

The chart's dynamics are here too: the free-body Hamiltonian (Gurfil eq. 89,
:func:`andoyer_hamiltonian`) and Hamilton's equations of ``K = T + ΔH``
(:func:`andoyer_equations`; Gurfil eqs. 97–102 for the free body), registered with the
chart. ``ΔH`` is given on the hub, ``ΔH(t, q, m)``, with its torque ``τ`` and its momentum
gradient ``∂ΔH/∂m``. The Andoyer attitude turns, per unit change of each angle, about a
body-frame axis ``e_a``: ``b3`` for ``l``, the node ``j = (cos l, -sin l, 0)`` for ``J``, the
momentum direction ``m/G`` for ``g``, the node ``i`` for ``I`` and the vertical
``γ = Rᵀ s3`` for ``h``. Since ``δΔH = -τ·δθ`` for a body-frame rotation ``δθ``,

.. math::
   \frac{\partial\Delta H}{\partial a} = -\boldsymbol\tau\cdot\mathbf e_a
   + \frac{\partial\Delta H}{\partial\mathbf m}\cdot\frac{\partial\mathbf m}{\partial a},

with ``I(H, G)`` and ``J(L, G)`` entering through
``∂I/∂H = -1/(G sin I)``, ``∂I/∂G = cos I/(G sin I)`` and likewise for ``J``.
The chart is singular at ``sin I = 0`` and ``sin J = 0``, and so are these
equations there.
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer import _quaternion as quat
from andoyer._fastmath import chunked, wrap_2pi
from andoyer._validation import (
    MAX_ANGLE,
    MAX_MOMENTUM,
    as_finite,
    broadcast,
    broadcast_finite,
    check_angle,
    check_magnitude,
    check_momenta,
)
from andoyer.body import RigidBody
from andoyer.state import _kernels
from andoyer.state.euler import Euler, compiled_conversions, scalars, transverse_momentum
from andoyer.state.hub import State, check_body
from andoyer.state.registry import Chart, register
from andoyer.state.singular import warn_if_singular

__all__ = [
    "Andoyer",
    "AndoyerRates",
    "andoyer_equations",
    "andoyer_from_euler",
    "andoyer_hamiltonian",
    "andoyer_matrix",
    "andoyer_to_hub",
    "euler_from_andoyer",
    "hub_to_andoyer",
    "inclinations",
]

Array = NDArray[np.float64]


class Andoyer(NamedTuple):
    """Andoyer angles and momenta; each field has the state's shape."""

    l: Array
    g: Array
    h: Array
    L: Array
    G: Array
    H: Array


def _momenta(L: ArrayLike, G: ArrayLike, H: ArrayLike) -> tuple[Array, Array, Array]:
    L, G, H = broadcast(("L", as_finite(L, "L")), ("G", as_finite(G, "G")), ("H", as_finite(H, "H")))
    check_momenta(L, G, H)
    return np.clip(L, -G, G), G, np.clip(H, -G, G)


def _sin_cos(P: Array, G: Array) -> tuple[Array, Array]:
    """``G sin X`` and ``G cos X`` for ``cos X = P/G``, ``sin X >= 0``, without cancellation."""
    return np.sqrt((G - P) * (G + P)), P


def inclinations(L: ArrayLike, G: ArrayLike, H: ArrayLike) -> tuple[Array, Array]:
    """The auxiliary angles ``I = arccos(H/G)`` and ``J = arccos(L/G)``.

    Computed as ``atan2(sqrt((G-H)(G+H)), H)``, accurate at both ends of ``[0, π]``.

    Parameters
    ----------
    L, G, H : array_like, shape (...)
        Andoyer momenta with ``G > 0``, ``|L| <= G``, ``|H| <= G``; they broadcast.

    Returns
    -------
    I, J : numpy.ndarray, shape (...)
        Inclination of the angular momentum on the reference axis, and on the body axis ``b3``.

    Examples
    --------
    >>> I, J = inclinations(0.5, 1.0, 0.0)
    >>> round(float(I), 12), round(float(J), 12)
    (1.570796326795, 1.047197551197)
    """
    L, G, H = _momenta(L, G, H)
    return np.arctan2(*_sin_cos(H, G)), np.arctan2(*_sin_cos(L, G))


def andoyer_matrix(h: ArrayLike, I: ArrayLike, g: ArrayLike, J: ArrayLike, l: ArrayLike) -> Array:
    """Gurfil's matrix ``R(h, I, g, J, l)`` (eqs. 70–74, corrected), reference → body.

    ``R = R3(l) R1(J) R3(g) R1(I) R3(h)`` with passive elementary rotations;
    the printed eqs. 72–74 lack brackets and factors (see ``docs/errata.md``).

    Parameters
    ----------
    h, I, g, J, l : array_like, shape (...)
        Angles in radians; they broadcast together.

    Returns
    -------
    numpy.ndarray, shape (..., 3, 3)

    Examples
    --------
    >>> import numpy as np
    >>> from scipy.spatial.transform import Rotation
    >>> R = andoyer_matrix(0.1, 0.2, 0.3, 0.4, 0.5)
    >>> rot = Rotation.from_euler("ZXZ", [0.1, 0.2, 0.3]) * Rotation.from_euler("XZ", [0.4, 0.5])
    >>> np.allclose(R, rot.as_matrix().T, atol=1e-15)
    True
    """
    arrays = broadcast_finite("hIgJl", (h, I, g, J, l))
    ch, sh = np.cos(arrays[0]), np.sin(arrays[0])
    cI, sI = np.cos(arrays[1]), np.sin(arrays[1])
    cg, sg = np.cos(arrays[2]), np.sin(arrays[2])
    cJ, sJ = np.cos(arrays[3]), np.sin(arrays[3])
    cl, sl = np.cos(arrays[4]), np.sin(arrays[4])
    a1 = cl * cg - sl * cJ * sg
    b1 = (cl * sg + sl * cJ * cg) * cI - sl * sJ * sI
    a2 = -sl * cg - cl * cJ * sg
    b2 = (-sl * sg + cl * cJ * cg) * cI - cl * sJ * sI
    a3 = sJ * sg
    b3 = sJ * cg * cI + cJ * sI
    rows = [
        [a1 * ch - b1 * sh, a1 * sh + b1 * ch, (cl * sg + sl * cJ * cg) * sI + sl * sJ * cI],
        [a2 * ch - b2 * sh, a2 * sh + b2 * ch, (-sl * sg + cl * cJ * cg) * sI + cl * sJ * cI],
        [a3 * ch + b3 * sh, a3 * sh - b3 * ch, -sJ * cg * sI + cJ * cI],
    ]
    return np.stack([np.stack(row, axis=-1) for row in rows], axis=-2)


def andoyer_to_hub(
    l: ArrayLike,
    g: ArrayLike,
    h: ArrayLike,
    L: ArrayLike,
    G: ArrayLike,
    H: ArrayLike,
    *,
    unit: bool = False,
) -> tuple[Array, Array]:
    """Attitude quaternions (..., 4) and body angular momenta (..., 3) of Andoyer states.

    The quaternions come divided by their norm as :class:`~andoyer.State` stores them
    (``unit``, kept for the callers that ask for it, changes nothing), from the kernel
    :func:`andoyer.state._kernels.andoyer_to_hub_one`: as Python for one state, compiled
    for arrays (numba), or on whole arrays (numpy).
    """
    del unit  # every path normalises
    one = scalars((l, g, h, L, G, H))
    if one is not None:
        L1, G1, H1 = one[3:]
        slack = 4 * _kernels.EPS * G1
        # Anything else (G out of range, |L| or |H| above G) takes the array path, which names it.
        angles_ok = max(map(abs, one[:3])) <= MAX_ANGLE
        if angles_ok and 0 < G1 <= MAX_MOMENTUM and abs(L1) - G1 <= slack and abs(H1) - G1 <= slack:
            *r, mz = _kernels.andoyer_to_hub_floats(*one)
            return np.array(r[:4]), np.array([*r[4:], mz])
    l, g, h = (as_finite(v, n) for n, v in zip("lgh", (l, g, h), strict=True))
    for name, angle in (("l", l), ("g", g), ("h", h)):
        check_angle(angle, name)
    L, G, H = _momenta(L, G, H)
    l, g, h, L, G, H = broadcast(("l", l), ("g", g), ("h", h), ("L", L), ("G", G), ("H", H))
    compiled = compiled_conversions(l.size)
    if compiled is not None:
        q, m = compiled.andoyer_to_hub((l, g, h, L, G, H))
    else:
        flat = [np.ascontiguousarray(v).reshape(-1) for v in (l, g, h, L, G, H)]
        columns = chunked(_kernels.andoyer_to_hub_arrays, flat, 7)
        q, m = np.stack(columns[:4], axis=-1), np.stack(columns[4:], axis=-1)
    return q.reshape(*l.shape, 4), m.reshape(*l.shape, 3)


_ZERO_MOMENTUM = "expected a non-zero angular momentum, got |m| = 0 (the Andoyer chart needs G > 0)"
_SINGULAR_J = "Andoyer chart at sin(J) = 0: set l = 0"
_SINGULAR_I = "Andoyer chart at sin(I) = 0: set h = 0"


def hub_to_andoyer(q: Array, m: Array, stacklevel: int = 2) -> Andoyer:
    """Andoyer variables of attitude quaternions (..., 4) and body momenta (..., 3).

    ``l = atan2(m1, m2)``, ``h = atan2(M1, -M2)`` and ``g`` is the angle, about
    the angular momentum, from the node ``i = (cos h, sin h, 0)`` (reference
    frame) to the node ``j = (cos l, -sin l, 0)`` (body frame). Building ``i``
    and ``j`` from the same ``h`` and ``l`` that are returned keeps the
    attitude round trip exact even where ``h`` or ``l`` is ill-conditioned.
    One state goes through the kernel :func:`andoyer.state._kernels.hub_to_andoyer_one`
    as Python (fields are numpy scalars), arrays through it compiled when numba is
    there, else through it on whole arrays (numpy).
    """
    if q.shape == (4,) and m.shape == (3,):
        m1, m2, m3 = m.tolist()
        if m1 * m1 + m2 * m2 + m3 * m3 <= 0:
            raise ValueError(_ZERO_MOMENTUM)
        *r, on_pole_j, on_pole_i = _kernels.hub_to_andoyer_floats(*q.tolist(), m1, m2, m3)
        if on_pole_j:
            warn_if_singular(True, _SINGULAR_J, stacklevel + 1)
        if on_pole_i:
            warn_if_singular(True, _SINGULAR_I, stacklevel + 1)
        return Andoyer(*map(np.float64, r))
    shape = np.broadcast_shapes(q.shape[:-1], m.shape[:-1])
    q, m = np.broadcast_to(q, (*shape, 4)).reshape(-1, 4), np.broadcast_to(m, (*shape, 3)).reshape(-1, 3)
    compiled = compiled_conversions(m.shape[0])
    if compiled is not None:
        columns, on_pole_j, on_pole_i, zero = compiled.hub_to_andoyer(q, m)
        if zero:
            raise ValueError(_ZERO_MOMENTUM)
    else:
        if np.any(np.sum(m * m, axis=-1) <= 0):
            raise ValueError(_ZERO_MOMENTUM)
        *columns, on_pole_j, on_pole_i = chunked(_kernels.hub_to_andoyer_arrays, [*q.T, *m.T], 8)
    warn_if_singular(on_pole_j != 0, _SINGULAR_J, stacklevel + 1)
    warn_if_singular(on_pole_i != 0, _SINGULAR_I, stacklevel + 1)
    return Andoyer(*(v.reshape(shape) for v in columns))


def andoyer_from_euler(
    phi: ArrayLike,
    theta: ArrayLike,
    psi: ArrayLike,
    Phi: ArrayLike,
    Theta: ArrayLike,
    Psi: ArrayLike,
) -> Andoyer:
    """Andoyer variables from Euler angles and momenta by direct formulas (eqs. 83–88, 25–32).

    ``H = Φ``, ``L = Ψ``, ``G² = Θ² + X² + Ψ²`` with ``X = (Φ - Ψ cos θ)/sin θ``;
    ``l = atan2(m1, m2)`` from eqs. 25–26; ``h = atan2(M1, -M2)`` from eqs. 30–31;
    and ``g = atan2(-G Θ sin θ, L H - G² cos θ)`` from the spherical triangle of
    the three nodes (laws of sines and cosines). Requires ``sin θ ≠ 0``; use
    :meth:`andoyer.State.as_andoyer` for the route through the state, which
    handles every configuration.

    Parameters
    ----------
    phi, theta, psi, Phi, Theta, Psi : array_like, shape (...)
        Euler angles (radians) and conjugate momenta; they broadcast together.

    Returns
    -------
    Andoyer

    Examples
    --------
    >>> a = andoyer_from_euler(0.1, 0.7, 0.3, 0.5, 0.2, 0.8)
    >>> e = euler_from_andoyer(*a)
    >>> [round(float(x), 12) for x in e]
    [0.1, 0.7, 0.3, 0.5, 0.2, 0.8]
    """
    names = ("phi", "theta", "psi", "Phi", "Theta", "Psi")
    phi, theta, psi, Phi, Theta, Psi = broadcast_finite(names, (phi, theta, psi, Phi, Theta, Psi))
    for name, momentum in (("Phi", Phi), ("Theta", Theta), ("Psi", Psi)):
        check_magnitude(momentum, name)
    numerator_x, st = transverse_momentum(Phi, Psi, theta)
    numerator_y, _ = transverse_momentum(Psi, Phi, theta)
    if np.any(st == 0):
        msg = "expected sin(theta) != 0 for the direct Euler -> Andoyer formulas, got sin(theta) = 0"
        raise ValueError(msg)
    X, Y = numerator_x / st, numerator_y / st
    cp, sp = np.cos(psi), np.sin(psi)
    cf, sf = np.cos(phi), np.sin(phi)
    m1, m2 = Theta * cp + X * sp, -Theta * sp + X * cp
    M1, M2 = Theta * cf + Y * sf, Theta * sf - Y * cf
    G = np.sqrt(Theta * Theta + X * X + Psi * Psi)
    g = np.arctan2(-G * Theta * st, Psi * Phi - G * G * np.cos(theta))
    return Andoyer(
        wrap_2pi(np.arctan2(m1, m2)),
        wrap_2pi(g),
        wrap_2pi(np.arctan2(M1, -M2)),
        Psi,
        G,
        Phi,
    )


def euler_from_andoyer(
    l: ArrayLike,
    g: ArrayLike,
    h: ArrayLike,
    L: ArrayLike,
    G: ArrayLike,
    H: ArrayLike,
) -> Euler:
    """Euler angles and momenta from Andoyer variables by direct formulas (eqs. 83–88, corrected).

    ``Φ = H``, ``Ψ = L``; ``cos θ`` is eq. 85; ``ψ = atan2(R13, R23)`` and
    ``φ = atan2(R31, -R32)`` from the entries of Gurfil's matrix (eqs. 86–87;
    eq. 86's denominator carries a sign typo, see ``docs/errata.md``); and
    ``Θ = sqrt(G² - L²) sin(l - ψ)`` (eq. 41; eq. 88 has the sign reversed). At ``sin θ = 0`` the convention
    ``ψ = 0`` applies with a :class:`SingularChartWarning`.

    Parameters
    ----------
    l, g, h, L, G, H : array_like, shape (...)
        Andoyer angles (radians) and momenta; they broadcast together.

    Returns
    -------
    Euler

    Examples
    --------
    >>> e = euler_from_andoyer(0.5, 0.0, 0.2, 0.6, 1.0, 0.8)
    >>> round(float(e.theta), 12)  # I + J when g = 0
    1.570796326795
    """
    l, g, h = (as_finite(v, n) for n, v in zip("lgh", (l, g, h), strict=True))
    for name, angle in (("l", l), ("g", g), ("h", h)):
        check_angle(angle, name)
    L, G, H = _momenta(L, G, H)
    l, g, h, L, G, H = broadcast(("l", l), ("g", g), ("h", h), ("L", L), ("G", G), ("H", H))
    I, J = inclinations(L, G, H)
    R = andoyer_matrix(h, I, g, J, l)
    st = np.hypot(R[..., 0, 2], R[..., 1, 2])
    theta = np.arctan2(st, R[..., 2, 2])
    singular = st == 0
    warn_if_singular(singular, "Euler chart at sin(theta) = 0: set psi = 0", 2)
    psi = np.where(singular, 0.0, np.arctan2(R[..., 0, 2], R[..., 1, 2]))
    phi = np.where(singular, np.arctan2(R[..., 0, 1], R[..., 0, 0]), np.arctan2(R[..., 2, 0], -R[..., 2, 1]))
    Theta = np.sqrt((G - L) * (G + L)) * np.sin(l - psi)
    return Euler(wrap_2pi(phi), theta, wrap_2pi(psi), H, Theta, L)


# The chart's methods of State (installed when the chart registers, below): their signatures
# are the chart's, written once here. ``cls`` and ``self`` are the State class and a state.


def _from_andoyer(
    cls: type[State],
    l: ArrayLike,
    g: ArrayLike,
    h: ArrayLike,
    L: ArrayLike,
    G: ArrayLike,
    H: ArrayLike,
) -> State:
    r"""State from Andoyer variables (Gurfil §3.2).

    The attitude is ``Rz(h) Rx(I) Rz(g) Rx(J) Rz(l)`` with ``cos I = H/G``,
    ``cos J = L/G``, and ``m_body = (√(G²-L²) sin l, √(G²-L²) cos l, L)``.

    Parameters
    ----------
    l, g, h : array_like, shape (...)
        Andoyer angles in radians.
    L, G, H : array_like, shape (...)
        Momenta with ``G > 0``, ``|L| <= G``, ``|H| <= G``. All six broadcast.

    Returns
    -------
    State, shape (...)
        The states (the broadcast shape of the six).

    Examples
    --------
    >>> from andoyer import State
    >>> s = State.from_andoyer(0.0, 0.0, 0.0, [0.5, 1.0], 1.0, 1.0)
    >>> s.shape
    (2,)
    """
    return cls.from_unit_quaternion(*andoyer_to_hub(l, g, h, L, G, H, unit=True))


def _as_andoyer(self) -> Andoyer:
    """Andoyer variables ``(l, g, h, L, G, H)``; angles in ``[0, 2π)``.

    At ``sin J = 0`` (``l = 0``) and ``sin I = 0`` (``h = 0``) a
    :class:`~andoyer.state.SingularChartWarning` is issued. A state with
    zero angular momentum has no Andoyer chart and raises ``ValueError``.

    Returns
    -------
    Andoyer of arrays, each of shape (...)
        The six coordinates, of the state's shape (numpy floats for a single state).

    Examples
    --------
    >>> from andoyer import State
    >>> s = State.from_andoyer(0.3, 0.4, 0.5, 0.6, 1.0, -0.2)
    >>> round(float(s.as_andoyer().g), 12)
    0.4
    """
    return hub_to_andoyer(self._q, self._m, stacklevel=2)


# ---------------------------------------------------------------- the chart's dynamics


class AndoyerRates(NamedTuple):
    """Time derivatives of the Andoyer variables."""

    l: Array
    g: Array
    h: Array
    L: Array
    G: Array
    H: Array


def andoyer_hamiltonian(body: RigidBody, l: ArrayLike, L: ArrayLike, G: ArrayLike) -> Array:
    """Gurfil eq. 89 (Lara eq. 1): the free Hamiltonian in Andoyer variables.

    ``½ (s_l²/I1 + c_l²/I2)(G² - L²) + L²/(2 I3)``. Only ``l``, ``L`` and ``G`` enter: ``g``
    and ``h`` are cyclic.

    Parameters
    ----------
    body : RigidBody
    l, L, G : array_like, shape (...)
        Andoyer angle ``l`` and momenta ``L``, ``G`` (``|L| <= G``); they broadcast.

    Returns
    -------
    numpy.ndarray, shape (...)

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> float(andoyer_hamiltonian(RigidBody(1.0, 2.0, 2.5), 0.0, 0.0, 2.0))  # G²/(2 I2)
    1.0
    """
    l, L, G = broadcast(("l", as_finite(l, "l")), ("L", as_finite(L, "L")), ("G", as_finite(G, "G")))
    check_momenta(L, G, np.zeros_like(G))
    I1, I2, I3 = body.moments
    sl, cl = np.sin(l), np.cos(l)
    return 0.5 * (sl * sl / I1 + cl * cl / I2) * (G - L) * (G + L) + L * L / (2 * I3)


def _free_rates(body: RigidBody, l: Any, g: Any, h: Any, L: Any, G: Any, H: Any) -> AndoyerRates:
    """Gurfil eqs. 97–102, written without cancellation (see :func:`andoyer_equations`)."""
    names = ("l", "g", "h", "L", "G", "H")
    l, g, h, L, G, H = broadcast_finite(names, (l, g, h, L, G, H))
    check_momenta(L, G, H)
    I1, I2, I3 = body.moments
    s2, c2 = np.sin(l) ** 2, np.cos(l) ** 2
    zero = np.zeros_like(G)
    return AndoyerRates(
        L * (s2 * (I1 - I3) / (I1 * I3) + c2 * (I2 - I3) / (I2 * I3)),
        G * (s2 / I1 + c2 / I2),
        zero,
        -(G - L) * (G + L) * np.sin(l) * np.cos(l) * (I2 - I1) / (I1 * I2),
        zero.copy(),
        zero.copy(),
    )


def andoyer_equations(
    body: RigidBody,
    l: ArrayLike,
    g: ArrayLike,
    h: ArrayLike,
    L: ArrayLike,
    G: ArrayLike,
    H: ArrayLike,
    *,
    perturbation: Any = None,
    t: ArrayLike = 0.0,
) -> AndoyerRates:
    r"""Hamilton's equations of ``T + ΔH`` in Andoyer variables (Gurfil eqs. 97–102 for ``ΔH = 0``).

    The free part is written without cancellation:
    ``dl/dt = L (s_l² (I1 - I3)/(I1 I3) + c_l² (I2 - I3)/(I2 I3))``,
    ``dg/dt = G (s_l²/I1 + c_l²/I2)``, ``dh/dt = 0``,
    ``dL/dt = -(G - L)(G + L) s_l c_l (I2 - I1)/(I1 I2)``, ``dG/dt = dH/dt = 0``.
    A perturbation ``ΔH(t, q, m)`` given on the hub adds ``∂ΔH/∂(L, G, H)`` to the angles' rates
    and ``-∂ΔH/∂(l, g, h)`` to the momenta's, through its torque and momentum gradient (see
    :mod:`andoyer.state.andoyer`).

    Parameters
    ----------
    body : RigidBody
    l, g, h, L, G, H : array_like, shape (...)
        Andoyer variables; they broadcast (off the singular set ``sin I sin J = 0`` where a
        perturbation is given).
    perturbation : optional
        A Hamiltonian term of the perturbation protocol (:class:`andoyer.perturbations.base.Perturbation`:
        its ``hamiltonian`` flag, ``torque(t, q, m)`` and ``momentum_gradient(t, q, m)``), bound
        to ``body``; ``None``: the free body.
    t : array_like, shape (...)
        The time of the perturbation; broadcast with the variables.

    Returns
    -------
    AndoyerRates

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> rates = andoyer_equations(RigidBody(1.0, 2.0, 2.5), 0.0, 0.0, 0.0, 1.0, 2.0, 1.0)
    >>> float(rates.g), float(rates.l)
    (1.0, -0.1)
    """
    free = _free_rates(body, l, g, h, L, G, H)
    if perturbation is None:
        return free
    if not perturbation.hamiltonian:
        msg = "expected Hamiltonian perturbations for the Andoyer-form equations, got a dissipative torque"
        raise ValueError(msg)
    t, l, g, h, L, G, H = broadcast_finite("tlghLGH", (t, l, g, h, L, G, H))
    check_momenta(L, G, H)
    q, m = andoyer_to_hub(l, g, h, L, G, H)
    tau = perturbation.torque(t, q, m)
    grad_m = perturbation.momentum_gradient(t, q, m)
    GsJ, GsI = np.sqrt((G - L) * (G + L)), np.sqrt((G - H) * (G + H))
    if np.any((GsJ == 0) | (GsI == 0)):
        msg = "expected sin I != 0 and sin J != 0 for the Andoyer-form equations, got a singular state"
        raise ValueError(msg)
    sl, cl = np.sin(l), np.cos(l)
    zero = np.zeros_like(l)
    e_l = np.stack([zero, zero, zero + 1.0], -1)
    e_J = np.stack([cl, -sl, zero], -1)
    e_g = m / G[..., None]
    gamma = quat.rotate(quat.conjugate(q), np.array([0.0, 0.0, 1.0]))
    e_h = gamma
    node_i = quat.rotate(quat.conjugate(q), np.stack([np.cos(h), np.sin(h), zero], -1))
    e_I = node_i

    def along(axis: Array) -> Array:
        return -np.sum(tau * axis, axis=-1)

    dm_dl = np.stack([GsJ * cl, -GsJ * sl, zero], -1)
    dm_dL = np.stack([-L / GsJ * sl, -L / GsJ * cl, zero + 1.0], -1)
    dm_dG = np.stack([G / GsJ * sl, G / GsJ * cl, zero], -1)

    def dot_m(d: Array) -> Array:
        return np.sum(grad_m * d, axis=-1)

    dI_dH, dI_dG = -G / (G * GsI), H / (G * GsI)
    dJ_dL, dJ_dG = -G / (G * GsJ), L / (G * GsJ)
    d_l = along(e_l) + dot_m(dm_dl)
    d_g = along(e_g)
    d_h = along(e_h)
    d_L = along(e_J) * dJ_dL + dot_m(dm_dL)
    d_G = along(e_I) * dI_dG + along(e_J) * dJ_dG + dot_m(dm_dG)
    d_H = along(e_I) * dI_dH
    return AndoyerRates(
        free.l + d_L,
        free.g + d_G,
        free.h + d_H,
        free.L - d_l,
        free.G - d_g,
        free.H - d_h,
    )


def _hamiltonian(
    body: RigidBody, l: ArrayLike, g: ArrayLike, h: ArrayLike, L: ArrayLike, G: ArrayLike, H: ArrayLike
) -> Array:
    """The registry's form of :func:`andoyer_hamiltonian`: the six columns in (``g``, ``h`` cyclic)."""
    l, g, h, L, G, H = broadcast_finite(Andoyer._fields, (l, g, h, L, G, H))
    check_momenta(L, G, H)
    return andoyer_hamiltonian(check_body(body), l, L, G)


register(
    Chart(
        "andoyer",
        Andoyer._fields,
        ("l", "g", "h"),
        "Serret–Andoyer angles and momenta (Gurfil §3)",
        _from_andoyer,
        _as_andoyer,
        source="andoyer.state.andoyer",
        hamiltonian=_hamiltonian,
        equations=andoyer_equations,
    ),
    State,
)
