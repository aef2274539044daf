r"""Action–angle variables of Lara's main problem of SAM rotation (Lara 2013, eqs. 18–25).

Axes.  For body axes ``(b1, b2, b3)`` with any positive moments ``(I1, I2, I3)`` the free-body
Hamiltonian in Andoyer variables (Gurfil eq. 89) is, exactly,

.. math:: \mathcal{H} = \frac{G^2}{2 I_3}\Big[1 + \alpha\Big(1 - \frac{L^2}{G^2}\Big)
          (1 - \beta\cos 2l)\Big], \qquad \alpha(1+\beta) = \frac{I_3}{I_1} - 1,\quad
          \alpha(1-\beta) = \frac{I_3}{I_2} - 1,

(Lara's eq. 3 for any axis labelling; ``α < 0`` when ``I3`` is below the harmonic mean of
``I1, I2``, and ``sign β = sign(α) sign(I2 − I1)``).  The SAM chart of a body is taken about
its axis of maximum inertia, the LAM chart about its axis of minimum inertia: the body axes are
first relabelled cyclically (a proper rotation of the body frame) so that this axis becomes
the third.  For LAM this is Lara's interchange of ``A`` and ``C`` (eqs. 37–39): with body axes
``(A, B, C)`` the relabelled moments are ``(B, C, A)``, ``α' = α*`` and ``β' = −β*`` with
``β* = (1 − β)/(1 + 3β)`` (eq. 38).

Chart.  With Andoyer ``(ν, μ, N, M) = (l, g, L, G)`` of the relabelled frame and
``s = √(1 − β²)`` (valid for ``|β| < 1``), the SAM variables ``(ℓ, g, L, G)`` (code names
``sam_l, sam_g, sam_L, sam_G``) are

.. math:: \tan\ell = -\sqrt{\frac{1+\beta}{1-\beta}}\tan\nu,\quad g = \mu + \nu,\quad G = M,\quad
          L = (M - N)\frac{1 - \beta\cos 2\nu}{s},

with ``cos ℓ`` of the sign of ``cos ν`` (eq. 22); inversely ``N = G − L (1 + β cos 2ℓ)/s``
(eq. 21).  The map is a Mathieu transformation: ``N dν + M dμ = L dℓ + G dg``, so
``(h, H)`` are carried unchanged and the whole 6-dimensional map is symplectic.  The free
Hamiltonian becomes (eq. 27) ``G²/(2I3) [1 + 2αs L/G − α L²(1 + β cos 2ℓ)/G²]``.

Hemispheres.  The chart is built on ``N ≥ 0``.  A state with ``N < 0`` (rotation about
``−b3``) is charted in the body frame turned by π about ``b1``, i.e. Andoyer
``(π − ν, μ + π, −N)`` (a canonical map), and the SAM tuple records ``sign = −1``.

Singularity.  At ``L = 0`` (``N = ±M``, rotation exactly about ``±b3``) ``ℓ`` is undefined:
the convention is ``sam_l = 0`` (``sam_g`` then carries the whole rotation angle ``μ + ν``),
announced by a :class:`SingularChartWarning`.  Near it ``ℓ`` is ill-conditioned like Andoyer's
``l``; ``M − N`` is computed from the hub as ``(m1² + m2²)/(M + |N|)``, without cancellation.

Dynamics, registered with the chart: the Hamiltonian is eq. 27 (:func:`sam_energy`) and
Hamilton's equations follow from it by differentiation, with ``s = √(1 − β²)``:

.. math:: \dot\ell = \frac{\alpha}{I_3}\big(sG - L(1 + \beta\cos 2\ell)\big),\quad
          \dot g = \frac{G + \alpha s L}{I_3},\quad
          \dot L = -\frac{\alpha\beta L^2 \sin 2\ell}{I_3},\quad
          \dot h = \dot G = \dot H = 0,

in either hemisphere (its chart is the same function of its own canonical variables).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer import _quaternion as quat
from andoyer._fastmath import atan2_2pi, chunked, wrap_2pi
from andoyer._validation import as_finite, as_vectors, broadcast, check_momenta
from andoyer.body import RigidBody
from andoyer.state import _kernels
from andoyer.state.andoyer import Andoyer
from andoyer.state.hub import State, check_body
from andoyer.state.registry import Chart, register
from andoyer.state.sam_axes import SAMAxes, andoyer_parameters, sam_axes
from andoyer.state.singular import warn_if_singular

__all__ = [
    "SAM",
    "SAMAxes",
    "andoyer_from_sam",
    "andoyer_parameters",
    "hub_to_sam",
    "sam_axes",
    "sam_energy",
    "sam_from_andoyer",
    "sam_to_hub",
]

Array = NDArray[np.float64]
_POLE_MESSAGE = "SAM chart at sam_L = 0 (rotation about ±b3): set sam_l = 0"


class SAM(NamedTuple):
    """SAM action–angle variables, ``(h, H)`` carried along, and the hemisphere ``sign`` of N."""

    sam_l: Array
    sam_g: Array
    h: Array
    sam_L: Array
    sam_G: Array
    H: Array
    sign: Array


def _check_beta(beta: ArrayLike) -> Array:
    b = as_finite(beta, "beta")
    if np.any(np.abs(b) >= 1):
        msg = f"expected -1 < beta < 1, got beta = {float(b[np.abs(b) >= 1].flat[0])!r}"
        raise ValueError(msg)
    return b


def _from_andoyer_core(nu: Array, mu: Array, gap: Array, beta: Array) -> tuple[Array, Array, Array]:
    """``(ℓ, g, L)`` from ``ν, μ`` and ``M − N ≥ 0`` (eqs. 22, 23, 25)."""
    p2, m2 = 1 + beta, 1 - beta
    cn, sn = np.cos(nu), np.sin(nu)
    w = m2 * cn * cn + p2 * sn * sn  # 1 − β cos 2ν > 0
    L = gap * w / np.sqrt(p2 * m2)
    pole = gap == 0
    ell = np.where(pole, 0.0, atan2_2pi(-np.sqrt(p2) * sn, np.sqrt(m2) * cn))
    return ell, wrap_2pi(mu + nu), L


def _to_andoyer_core(ell: Array, sam_g: Array, sam_L: Array, beta: Array) -> tuple[Array, Array, Array]:
    """``(ν, μ, M − N)`` from the SAM variables (eqs. 18, 19, 21)."""
    p2, m2 = 1 + beta, 1 - beta
    cl, sl = np.cos(ell), np.sin(ell)
    nu = np.arctan2(-np.sqrt(m2) * sl, np.sqrt(p2) * cl)
    gap = sam_L * (p2 * cl * cl + m2 * sl * sl) / np.sqrt(p2 * m2)  # L (1 + β cos 2ℓ)/s
    return nu, sam_g - nu, gap


def _hemisphere(N: Array) -> Array:
    return np.where(N >= 0, 1.0, -1.0)


def sam_from_andoyer(
    l: ArrayLike, g: ArrayLike, h: ArrayLike, L: ArrayLike, G: ArrayLike, H: ArrayLike, *, beta: ArrayLike
) -> SAM:
    """SAM variables of Andoyer variables ``(ν, μ, λ, N, M, Λ) = (l, g, h, L, G, H)`` (eqs. 22–25).

    Parameters
    ----------
    l, g, h, L, G, H : array_like, shape (...)
        Andoyer variables of the (relabelled) body frame, ``G > 0``, ``|L|, |H| <= G``.
    beta : array_like
        Andoyer's ``β`` about ``b3`` (:func:`andoyer_parameters`), ``|β| < 1``; broadcasts.

    Returns
    -------
    SAM
        Angles in ``[0, 2π)``; ``sign = ±1`` is the sign of ``L`` (``+1`` at ``L = 0``).

    Examples
    --------
    >>> s = sam_from_andoyer(0.3, 0.2, 0.1, 0.99, 1.0, 0.5, beta=0.5)
    >>> [round(float(x), 12) for x in s]
    [5.791320331925, 0.5, 0.1, 0.006781927989, 1.0, 0.5, 1.0]
    >>> a = andoyer_from_sam(*s, beta=0.5)
    >>> [round(float(x), 12) for x in a]
    [0.3, 0.2, 0.1, 0.99, 1.0, 0.5]
    """
    names = ("l", "g", "h", "L", "G", "H")
    values = zip(names, (l, g, h, L, G, H), strict=True)
    l, g, h, L, G, H = broadcast(*((n, as_finite(v, n)) for n, v in values))
    check_momenta(L, G, H)
    beta = _check_beta(beta)
    sign = _hemisphere(L)
    nu = np.where(sign > 0, l, np.pi - l)
    mu = np.where(sign > 0, g, g + np.pi)
    gap = np.maximum(G - np.abs(L), 0.0)
    ell, sam_g, sam_L = _from_andoyer_core(nu, mu, gap, beta)
    warn_if_singular(gap == 0, _POLE_MESSAGE, 2)
    out = np.broadcast_arrays(ell, sam_g, wrap_2pi(h), sam_L, G, H, sign)
    return SAM(*(np.array(v) for v in out))


def _check_sam(
    sam_l: ArrayLike,
    sam_g: ArrayLike,
    h: ArrayLike,
    sam_L: ArrayLike,
    sam_G: ArrayLike,
    H: ArrayLike,
    sign: ArrayLike,
) -> list[Array]:
    names = ("sam_l", "sam_g", "h", "sam_L", "sam_G", "H", "sign")
    values = broadcast(
        *((n, as_finite(v, n)) for n, v in zip(names, (sam_l, sam_g, h, sam_L, sam_G, H, sign), strict=True))
    )
    sam_L, sam_G, H, sign = values[3], values[4], values[5], values[6]
    if np.any(sam_G <= 0):
        msg = f"expected sam_G > 0, got sam_G = {float(np.min(sam_G))!r}"
        raise ValueError(msg)
    if np.any(sam_L < 0):
        msg = f"expected sam_L >= 0, got sam_L = {float(np.min(sam_L))!r}"
        raise ValueError(msg)
    if np.any(np.abs(H) > sam_G * (1 + 4 * np.finfo(float).eps)):
        msg = "expected |H| <= sam_G, got |H| > sam_G"
        raise ValueError(msg)
    if np.any(np.abs(sign) != 1):
        msg = f"expected sign = +1 or -1, got {float(sign[np.abs(sign) != 1].flat[0])!r}"
        raise ValueError(msg)
    return values


def _gap_in_range(gap: Array, G: Array) -> Array:
    # L (1 + β cos 2ℓ)/s = M − N lies in [0, 2M]; beyond it no state exists.
    if np.any(gap > 2 * G * (1 + 4 * np.finfo(float).eps)):
        msg = "expected sam_L <= 2 sam_G s/(1 + beta cos 2 sam_l) (N >= -G), got a larger sam_L"
        raise ValueError(msg)
    return np.minimum(gap, 2 * G)


def andoyer_from_sam(
    sam_l: ArrayLike,
    sam_g: ArrayLike,
    h: ArrayLike,
    sam_L: ArrayLike,
    sam_G: ArrayLike,
    H: ArrayLike,
    sign: ArrayLike = 1.0,
    *,
    beta: ArrayLike,
) -> Andoyer:
    """Andoyer variables of SAM variables (eqs. 18–21), the inverse of :func:`sam_from_andoyer`.

    Parameters
    ----------
    sam_l, sam_g, h, sam_L, sam_G, H : array_like, shape (...)
        SAM variables with ``sam_G > 0``, ``0 <= sam_L``, ``|H| <= sam_G``.
    sign : array_like, optional
        Hemisphere ``±1`` (default ``+1``: ``N >= 0``).
    beta : array_like
        ``|β| < 1``.

    Returns
    -------
    Andoyer
        Angles in ``[0, 2π)``.

    Examples
    --------
    >>> a = andoyer_from_sam(0.0, 1.0, 0.0, 0.0, 2.0, 1.0, beta=0.3)   # steady spin about b3
    >>> float(a.L), float(a.l + a.g)
    (2.0, 1.0)
    """
    sam_l, sam_g, h, sam_L, G, H, sign = _check_sam(sam_l, sam_g, h, sam_L, sam_G, H, sign)
    beta = _check_beta(beta)
    nu, mu, gap = _to_andoyer_core(sam_l, sam_g, sam_L, beta)
    gap = _gap_in_range(gap, G)
    N = G - gap
    l = np.where(sign > 0, nu, np.pi - nu)
    g = np.where(sign > 0, mu, mu - np.pi)
    out = np.broadcast_arrays(wrap_2pi(l), wrap_2pi(g), wrap_2pi(h), sign * N, G, H)
    return Andoyer(*(np.array(v) for v in out))


def _sam_of_hub(q: Array, m: Array, axes: SAMAxes) -> tuple[SAM, Array, Array]:
    """SAM variables of hub arrays in the frame of ``axes``, and the masks of the singular charts."""
    q, m = as_vectors(q, "quaternion", 4), as_vectors(m, "m_body", 3)
    try:
        shape = np.broadcast_shapes(q.shape[:-1], m.shape[:-1])
    except ValueError as exc:
        msg = f"expected quaternions and momenta with broadcastable shapes, got {q.shape} and {m.shape}"
        raise ValueError(msg) from exc
    q, m = np.broadcast_to(q, (*shape, 4)), np.broadcast_to(m, (*shape, 3))
    if np.any(np.sum(m * m, axis=-1) <= 0):
        msg = "expected a non-zero angular momentum, got |m| = 0 (the SAM chart needs G > 0)"
        raise ValueError(msg)
    q = quat.multiply(q, axes.quaternion)
    m = m[..., list(axes.permutation)]
    columns = [*q.reshape(-1, 4).T, *m.reshape(-1, 3).T]
    l, g, h, L, G, H, on_pole_j, on_pole_i = chunked(_kernels.hub_to_andoyer_arrays, columns, 8)
    m1, m2 = columns[4], columns[5]
    gap = np.where(on_pole_j != 0, 0.0, (m1 * m1 + m2 * m2) / (G + np.abs(L)))
    sign = _hemisphere(L)
    nu = np.where(sign > 0, l, np.pi - l)
    mu = np.where(sign > 0, g, g + np.pi)
    ell, sam_g, sam_L = _from_andoyer_core(nu, mu, gap, np.asarray(axes.beta))
    sam = SAM(*(v.reshape(shape) for v in (ell, sam_g, h, sam_L, G, H, sign)))
    return sam, (gap == 0).reshape(shape), (on_pole_i != 0).reshape(shape)


def hub_to_sam(q: Array, m: Array, body: RigidBody, mode: str = "SAM", stacklevel: int = 2) -> SAM:
    """SAM (or LAM) variables of attitude quaternions and body momenta.

    The body frame is relabelled by :func:`sam_axes`; ``M − N = (m1'² + m2'²)/(M + |N|)`` is
    formed without cancellation.  Warnings (:class:`SingularChartWarning`) at ``sam_L = 0``
    (``sam_l = 0``) and at ``sin I = 0`` (``h = 0``, ``sam_g`` carries ``h ± g``).

    Parameters
    ----------
    q : array_like, shape (..., 4)
        Attitude quaternions (body → reference), scalar last.
    m : array_like, shape (..., 3)
        Body angular momenta (non-zero); leading shapes broadcast with ``q``.
    body : RigidBody
    mode : {"SAM", "LAM"}
    stacklevel : int
        Warnings point ``stacklevel`` frames above the caller (2 suits a method wrapping this
        function, as ``State.as_sam``; use 1 for a direct call).

    Returns
    -------
    SAM
        Fields of the broadcast leading shape.

    Examples
    --------
    >>> from andoyer.state.andoyer import andoyer_to_hub
    >>> body = RigidBody(0.5, 0.75, 1.0)
    >>> q, m = andoyer_to_hub(0.3, 0.2, 0.1, 0.99, 1.0, 0.5)
    >>> round(float(hub_to_sam(q, m, body).sam_L), 12)
    0.006781927989
    """
    sam, on_pole, on_pole_i = _sam_of_hub(q, m, sam_axes(body, mode))
    warn_if_singular(on_pole, _POLE_MESSAGE, stacklevel + 1)
    warn_if_singular(on_pole_i, "SAM chart at sin(I) = 0: set h = 0", stacklevel + 1)
    return sam


def sam_to_hub(
    sam_l: ArrayLike,
    sam_g: ArrayLike,
    h: ArrayLike,
    sam_L: ArrayLike,
    sam_G: ArrayLike,
    H: ArrayLike,
    sign: ArrayLike = 1.0,
    *,
    body: RigidBody,
    mode: str = "SAM",
) -> tuple[Array, Array]:
    """Attitude quaternions and body momenta of SAM (or LAM) variables.

    ``sin J = √((M − N)(M + N))/M`` is built from ``M − N = L (1 + β cos 2ℓ)/s`` directly, so
    states close to the pole keep their transverse momentum to full relative precision.

    Parameters
    ----------
    sam_l, sam_g, h, sam_L, sam_G, H : array_like, shape (...)
        SAM variables, ``sam_G > 0``, ``sam_L >= 0``, ``|H| <= sam_G``; they broadcast.
    sign : array_like, optional
        Hemisphere ``±1`` of the angular momentum on the chart's axis (default ``+1``).
    body : RigidBody
    mode : {"SAM", "LAM"}

    Returns
    -------
    q : numpy.ndarray, shape (..., 4)
    m : numpy.ndarray, shape (..., 3)

    Examples
    --------
    >>> body = RigidBody(0.5, 0.75, 1.0)
    >>> q, m = sam_to_hub(0.0, 0.0, 0.0, 0.0, 2.0, 2.0, body=body, mode="LAM")
    >>> m.tolist()                       # steady spin about the axis of minimum inertia b1
    [2.0, 0.0, 0.0]
    """
    axes = sam_axes(body, mode)
    sam_l, sam_g, h, sam_L, G, H, sign = _check_sam(sam_l, sam_g, h, sam_L, sam_G, H, sign)
    nu, mu, gap = _to_andoyer_core(sam_l, sam_g, sam_L, np.asarray(axes.beta))
    gap = _gap_in_range(gap, G)
    l = np.where(sign > 0, nu, np.pi - nu)
    g = np.where(sign > 0, mu, mu - np.pi)
    N = sign * (G - gap)
    GsJ = np.sqrt(gap * (2 * G - gap))
    GsI = np.sqrt(np.maximum((G - H) * (G + H), 0.0))
    q = quat.multiply(quat.from_zxz(h, np.arctan2(GsI, H), g), quat.from_xz(np.arctan2(GsJ, N), l))
    m_new = np.stack([GsJ * np.sin(l), GsJ * np.cos(l), N], axis=-1)
    m = np.empty_like(m_new)
    m[..., list(axes.permutation)] = m_new
    return quat.multiply(q, quat.conjugate(axes.quaternion)), m


def sam_energy(
    sam_l: ArrayLike, sam_L: ArrayLike, sam_G: ArrayLike, alpha: ArrayLike, beta: ArrayLike, I3: ArrayLike
) -> Array:
    """The free-body Hamiltonian in SAM variables (eq. 27), for either hemisphere.

    ``K = G²/(2 I3) [1 + 2 α s L/G − α (L/G)² (1 + β cos 2ℓ)]``, ``s = √(1 − β²)``, with
    ``I3`` the moment of the chart's axis.

    Parameters
    ----------
    sam_l, sam_L, sam_G : array_like, shape (...)
    alpha, beta, I3 : array_like
        :attr:`SAMAxes.alpha`, :attr:`SAMAxes.beta` and ``SAMAxes.moments[2]``; all broadcast.

    Returns
    -------
    numpy.ndarray, shape (...)

    Examples
    --------
    >>> float(sam_energy(0.0, 0.0, 2.0, 0.3, 0.5, 1.0))       # G²/(2 I3) on the axis
    2.0
    """
    names = ("sam_l", "sam_L", "sam_G", "alpha", "beta", "I3")
    ell, L, G, alpha, beta, I3 = broadcast(
        *((n, as_finite(v, n)) for n, v in zip(names, (sam_l, sam_L, sam_G, alpha, beta, I3), strict=True))
    )
    beta = _check_beta(beta)
    x = L / G
    s = np.sqrt((1 - beta) * (1 + beta))
    return G * G / (2 * I3) * (1 + alpha * x * (2 * s - x * (1 + beta * np.cos(2 * ell))))


# The chart's methods of State (installed when the chart registers, below): their signatures
# are the chart's, written once here. ``cls`` and ``self`` are the State class and a state.


def _as_sam(self, body: RigidBody, mode: str = "SAM"):
    """Lara's SAM (or LAM) action–angle chart ``(sam_l, sam_g, h, sam_L, sam_G, H, sign)``.

    See :mod:`andoyer.state.sam` (Lara eqs. 18–25, any axis labelling).

    Parameters
    ----------
    body : RigidBody
        The body.
    mode : {"SAM", "LAM"}
        The chart about the body's axis of maximum inertia (SAM) or of minimum inertia (LAM).

    Returns
    -------
    SAM of arrays, each of shape (...)
        The seven coordinates, of the state's shape.

    Examples
    --------
    >>> from andoyer import RigidBody, State
    >>> body = RigidBody(1.0, 2.0, 3.0)
    >>> s = State.from_andoyer(0.3, 0.4, 0.5, 0.99, 1.0, 0.2)
    >>> back = State.from_sam(*s.as_sam(body), body=body)
    >>> bool(abs(back.m_body - s.m_body).max() < 1e-13)
    True
    """
    return hub_to_sam(self._q, self._m, check_body(body), mode, stacklevel=2)


def _from_sam(
    cls: type[State],
    sam_l: ArrayLike,
    sam_g: ArrayLike,
    h: ArrayLike,
    sam_L: ArrayLike,
    sam_G: ArrayLike,
    H: ArrayLike,
    sign: ArrayLike = 1.0,
    *,
    body: RigidBody,
    mode: str = "SAM",
) -> State:
    """State from Lara's SAM (or LAM) action–angle chart; inverse of :meth:`as_sam`.

    Parameters
    ----------
    sam_l, sam_g, h : array_like, shape (...)
        The angles in radians.
    sam_L, sam_G, H : array_like, shape (...)
        The actions.
    sign : array_like, shape (...)
        ``±1``, as :meth:`as_sam` records it.
    body : RigidBody
        The body.
    mode : {"SAM", "LAM"}
        The chart about the body's axis of maximum inertia (SAM) or of minimum inertia (LAM).

    Returns
    -------
    State, shape (...)
        The states (the broadcast shape of the coordinates).

    Examples
    --------
    >>> from andoyer import RigidBody, State
    >>> body = RigidBody(1.0, 2.0, 3.0)
    >>> s = State.from_sam(0.3, 0.4, 0.5, 0.9, 1.0, 0.2, body=body, mode="LAM")
    >>> [round(float(x), 12) for x in s.as_sam(body, mode="LAM")]
    [0.3, 0.4, 0.5, 0.9, 1.0, 0.2, 1.0]
    """
    return cls(*sam_to_hub(sam_l, sam_g, h, sam_L, sam_G, H, sign, body=check_body(body), mode=mode))


def _dynamics_columns(
    body: RigidBody, values: tuple[ArrayLike, ...], mode: str
) -> tuple[list[Array], SAMAxes]:
    """The seven columns broadcast, checked as :func:`sam_to_hub` checks them, and the chart's axes."""
    columns = _check_sam(*values)
    return columns, sam_axes(check_body(body), mode)


def _hamiltonian(
    body: RigidBody,
    sam_l: ArrayLike,
    sam_g: ArrayLike,
    h: ArrayLike,
    sam_L: ArrayLike,
    sam_G: ArrayLike,
    H: ArrayLike,
    sign: ArrayLike = 1.0,
    *,
    mode: str = "SAM",
) -> Array:
    """The registry's form of :func:`sam_energy` (eq. 27): the chart's columns and the body in."""
    (ell, _, _, L, G, _, _), axes = _dynamics_columns(body, (sam_l, sam_g, h, sam_L, sam_G, H, sign), mode)
    return sam_energy(ell, L, G, axes.alpha, axes.beta, axes.moments[2])


def _equations(
    body: RigidBody,
    sam_l: ArrayLike,
    sam_g: ArrayLike,
    h: ArrayLike,
    sam_L: ArrayLike,
    sam_G: ArrayLike,
    H: ArrayLike,
    sign: ArrayLike = 1.0,
    *,
    mode: str = "SAM",
) -> SAM:
    """Hamilton's equations of eq. 27 in the SAM (or LAM) chart (see :mod:`andoyer.state.sam`)."""
    (ell, _, _, L, G, _, _), axes = _dynamics_columns(body, (sam_l, sam_g, h, sam_L, sam_G, H, sign), mode)
    alpha, beta, I3 = axes.alpha, _check_beta(axes.beta), axes.moments[2]
    s = np.sqrt((1 - beta) * (1 + beta))
    zero = np.zeros_like(ell)
    return SAM(
        alpha / I3 * (s * G - L * (1 + beta * np.cos(2 * ell))),
        (G + alpha * s * L) / I3,
        zero,
        -alpha * beta * L * L * np.sin(2 * ell) / I3,
        zero.copy(),
        zero.copy(),
        zero.copy(),
    )


register(
    Chart(
        "sam",
        SAM._fields,
        ("sam_l", "sam_g", "h"),
        "Lara's SAM (or LAM, `mode`) action–angle chart (Lara eqs. 18–25)",
        _from_sam,
        _as_sam,
        source="andoyer.state.sam",
        hamiltonian=_hamiltonian,
        equations=_equations,
    ),
    State,
)
