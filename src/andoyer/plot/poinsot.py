r"""Poinsot's construction: the polhode and the herpolhode of a torque-free state.

The state is propagated exactly with :class:`andoyer.FreeRotation`.

* Polhode: the path of the body angular momentum ``m(t)`` (and of ``ω = I⁻¹m``) in the body
  frame.  It lies on the momentum sphere ``|m| = G`` and on the energy ellipsoid
  ``½ m·I⁻¹m = T``; it is drawn on the sphere.
* Herpolhode: the path of the tip of ``ω`` in the reference frame, ``ω_ref = 𝓡 ω``.  Since
  ``ω·m = 2T`` and ``m_ref`` is fixed, it lies in the invariable plane
  ``ω_ref · n̂ = 2T/G``, ``n̂ = m_ref/G``; it is drawn in that plane with the in-plane axes
  ``e₁ = (s3 × n̂)/|s3 × n̂|`` (the node of the invariable plane; ``s1`` when ``n̂ = ±s3``) and
  ``e₂ = n̂ × e₁``, centred on the foot ``(2T/G) n̂`` of the perpendicular from the fixed point.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from numpy.typing import NDArray

from andoyer._validation import as_finite
from andoyer.body import RigidBody
from andoyer.free_rotation import FreeRotation
from andoyer.plot.contours import separatrix_contour
from andoyer.plot.projection import Orthographic, math_number, new_axes
from andoyer.plot.sphere import DEFAULT_VIEW, SEPARATRIX_COLOR
from andoyer.state import State

__all__ = ["Herpolhode", "Polhode", "herpolhode", "herpolhode_data", "poinsot", "polhode", "polhode_data"]

Array = NDArray[np.float64]


@dataclass(frozen=True)
class Polhode:
    """What :func:`polhode` draws.

    Attributes
    ----------
    body : RigidBody
    t : numpy.ndarray, shape (n,)
        Times since the state.
    m_body : numpy.ndarray, shape (n, 3)
        Body angular momentum along the path.
    omega_body : numpy.ndarray, shape (n, 3)
        Body angular velocity ``ω = I⁻¹m``.
    G : float
        ``|m|`` of the state.
    energy : float
        ``½ m·I⁻¹m`` of the state.
    """

    body: RigidBody
    t: Array
    m_body: Array
    omega_body: Array
    G: float
    energy: float


@dataclass(frozen=True)
class Herpolhode:
    """What :func:`herpolhode` draws.

    Attributes
    ----------
    t : numpy.ndarray, shape (n,)
    omega_reference : numpy.ndarray, shape (n, 3)
        ``ω`` in reference components.
    normal : numpy.ndarray, shape (3,)
        ``n̂ = m_ref/G``, the normal of the invariable plane.
    distance : float
        ``2T/G``, the distance of the invariable plane from the fixed point.
    basis : numpy.ndarray, shape (2, 3)
        The in-plane axes ``e₁, e₂``.
    xy : numpy.ndarray, shape (n, 2)
        ``(ω_ref·e₁, ω_ref·e₂)``.
    """

    t: Array
    omega_reference: Array
    normal: Array
    distance: float
    basis: Array
    xy: Array


#: Points per turn of ω about the momentum that the default herpolhode duration keeps (chords of
#: 2π/100 of the radius: a curve, not a zig-zag).
HERPOLHODE_POINTS_PER_TURN = 100


def _times(
    body: RigidBody,
    state: State,
    duration: float | None,
    periods: float,
    n_points: int,
    points_per_turn: float | None = None,
) -> Array:
    if not isinstance(state, State) or state.shape != ():
        msg = (
            f"expected a single andoyer State (shape ()), got {getattr(state, 'shape', type(state).__name__)}"
        )
        raise ValueError(msg)
    if int(n_points) != n_points or n_points < 2:
        msg = f"expected an integer n_points >= 2, got {n_points!r}"
        raise ValueError(msg)
    if duration is None:
        free = FreeRotation(body).periods(state)
        period, turn_rate = float(free.period), abs(float(free.precession_rate))
        speed = float(np.linalg.norm(state.omega(body)))
        if np.isfinite(period):
            duration = periods * period
        elif speed > 0:  # separatrix or a sphere: turns of the body instead
            duration = 10 * periods * 2 * np.pi / speed
        else:
            duration = 1.0  # at rest: nothing moves
        if points_per_turn is not None and np.isfinite(turn_rate) and turn_rate > 0:
            # ω turns about the momentum at the mean rate of the node (FreeRotation.periods): a
            # nearly axisymmetric body (the Earth: once a day, wobble period 305 days) makes
            # hundreds of turns per period of m(t); keep the samples dense enough to draw them.
            duration = min(duration, n_points / points_per_turn * 2 * np.pi / turn_rate)
    d = float(as_finite(duration, "duration"))
    if d <= 0:
        msg = f"expected duration > 0, got {d!r}"
        raise ValueError(msg)
    return np.linspace(0.0, d, int(n_points))


def polhode_data(
    body: RigidBody, state: State, duration: float | None = None, n_points: int = 721
) -> Polhode:
    """Propagate ``state`` and return its polhode.

    Parameters
    ----------
    body : RigidBody
    state : State, shape ()
    duration : float, optional
        Time span; default one period of ``m(t)`` (a closed curve), or ten turns of the body
        where that period is infinite (separatrix, sphere).
    n_points : int

    Returns
    -------
    Polhode

    Examples
    --------
    >>> import numpy as np
    >>> from andoyer import State
    >>> body = RigidBody(1.0, 2.0, 3.0)
    >>> p = polhode_data(body, State.from_quaternion([0, 0, 0, 1.0], [0.3, 0.2, 1.0]))
    >>> bool(np.allclose(p.m_body[-1], p.m_body[0], atol=1e-12))    # one period: closed
    True
    """
    t = _times(body, state, duration, 1.0, n_points)
    path = FreeRotation(body).propagate(state, t)
    m = path.m_body
    return Polhode(
        body, t, m, path.omega(body), float(np.linalg.norm(state.m_body)), float(state.energy(body))
    )


def _plane_basis(normal: Array) -> Array:
    node = np.cross([0.0, 0.0, 1.0], normal)
    size = np.linalg.norm(node)
    e1 = np.array([1.0, 0.0, 0.0]) if size < 1e-12 else node / size
    e1 = e1 - (e1 @ normal) * normal
    e1 /= np.linalg.norm(e1)
    return np.stack([e1, np.cross(normal, e1)])


def herpolhode_data(
    body: RigidBody, state: State, duration: float | None = None, n_points: int = 2001
) -> Herpolhode:
    """Propagate ``state`` and return its herpolhode in the invariable plane.

    Parameters
    ----------
    body : RigidBody
    state : State, shape ()
        A state with ``m ≠ 0``.
    duration : float, optional
        Time span; default three periods of ``m(t)`` (thirty turns of the body where that
        period is infinite), cut to ``n_points / 100`` turns of ``ω`` about the momentum (at the
        mean rate ``FreeRotation(body).periods(state).precession_rate``) so that every turn gets
        at least 100 points.
    n_points : int

    Returns
    -------
    Herpolhode

    Examples
    --------
    >>> import numpy as np
    >>> from andoyer import State
    >>> body = RigidBody(1.0, 2.0, 3.0)
    >>> h = herpolhode_data(body, State.from_quaternion([0, 0, 0, 1.0], [0.3, 0.2, 1.0]))
    >>> bool(np.allclose(h.omega_reference @ h.normal, h.distance, rtol=1e-12))
    True
    """
    t = _times(body, state, duration, 3.0, n_points, HERPOLHODE_POINTS_PER_TURN)
    G = float(np.linalg.norm(state.m_body))
    if G == 0:
        msg = "expected a state with nonzero angular momentum, got m = 0"
        raise ValueError(msg)
    path = FreeRotation(body).propagate(state, t)
    omega_ref = path.rotation.apply(path.omega(body))
    normal = state.m_reference / G
    basis = _plane_basis(normal)
    distance = 2 * float(state.energy(body)) / G
    return Herpolhode(t, omega_ref, normal, distance, basis, omega_ref @ basis.T)


def polhode(
    body: RigidBody,
    state: State,
    duration: float | None = None,
    *,
    n_points: int = 721,
    elev: float = DEFAULT_VIEW[0],
    azim: float = DEFAULT_VIEW[1],
    ax: Axes | None = None,
) -> Figure:
    """Draw the polhode of ``state`` on its momentum sphere, with the separatrix for reference.

    Parameters
    ----------
    body, state, duration, n_points
        As in :func:`polhode_data`.
    elev, azim : float
        Viewing direction, radians.
    ax : matplotlib.axes.Axes, optional

    Returns
    -------
    matplotlib.figure.Figure
        With the :class:`Polhode` as ``figure.andoyer_data``.

    Examples
    --------
    >>> from andoyer import State
    >>> fig = polhode(RigidBody(1.0, 2.0, 3.0), State.from_quaternion([0, 0, 0, 1.0], [0.3, 0.2, 1.0]))
    >>> fig.andoyer_data.m_body.shape
    (721, 3)
    """
    data = polhode_data(body, state, duration, n_points)
    fig, ax = new_axes(ax, figsize=(5.5, 5.5))
    view = Orthographic(elev, azim)
    view.draw_sphere(ax, data.G, ("$m_1$", "$m_2$", "$m_3$"))
    if data.G > 0 and body.A < body.C:
        for k, curve in enumerate(separatrix_contour(body, data.G)):
            label = "separatrix" if k == 0 else None
            view.draw_curve(ax, curve, color=SEPARATRIX_COLOR, lw=0.8, alpha=0.6, label=label)
    view.draw_curve(ax, data.m_body, color="k", lw=2.0, label=f"polhode, $T = {math_number(data.energy)}$")
    x, y = view.project(data.m_body[0])
    ax.plot([x], [y], "o", color="k", ms=4)
    ax.set_title(f"Polhode: body angular momentum on the sphere\n$|m| = G = {math_number(data.G)}$")
    ax.legend(loc="lower left", fontsize="small", frameon=False)
    fig.andoyer_data = data  # type: ignore[attr-defined]
    return fig


def herpolhode(
    body: RigidBody,
    state: State,
    duration: float | None = None,
    *,
    n_points: int = 2001,
    ax: Axes | None = None,
) -> Figure:
    """Draw the herpolhode of ``state``: the tip of ``ω`` on the invariable plane.

    Parameters
    ----------
    body, state, duration, n_points
        As in :func:`herpolhode_data`.
    ax : matplotlib.axes.Axes, optional

    Returns
    -------
    matplotlib.figure.Figure
        With the :class:`Herpolhode` as ``figure.andoyer_data``.

    Examples
    --------
    >>> from andoyer import State
    >>> fig = herpolhode(RigidBody(1.0, 2.0, 3.0), State.from_quaternion([0, 0, 0, 1.0], [0.3, 0.2, 1.0]))
    >>> fig.andoyer_data.xy.shape
    (2001, 2)
    """
    data = herpolhode_data(body, state, duration, n_points)
    fig, ax = new_axes(ax, figsize=(5.5, 5.5))
    ax.plot(data.xy[:, 0], data.xy[:, 1], color="tab:purple", lw=1.0, label="herpolhode")
    ax.plot([0.0], [0.0], "+", color="k", ms=10, label="foot of the fixed point")
    ax.plot(data.xy[:1, 0], data.xy[:1, 1], "o", color="k", ms=4)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("$\\omega \\cdot e_1$ (rad per unit time)")
    ax.set_ylabel("$\\omega \\cdot e_2$ (rad per unit time)")
    ax.set_title(
        f"Herpolhode on the invariable plane\n$\\omega\\cdot\\hat n = 2T/G = {math_number(data.distance)}$, "
        f"$0 \\leq t \\leq {math_number(data.t[-1], 4)}$"
    )
    ax.legend(loc="upper right", fontsize="small", framealpha=0.8)
    fig.andoyer_data = data  # type: ignore[attr-defined]
    return fig


def poinsot(body: RigidBody, state: State, duration: float | None = None) -> Figure:
    """Polhode (left) and herpolhode (right) of ``state`` side by side.

    ``duration`` applies to both panels (default: one period for the polhode, three for the
    herpolhode).  ``figure.andoyer_data`` is the pair ``(Polhode, Herpolhode)``.

    Examples
    --------
    >>> from andoyer import State
    >>> fig = poinsot(RigidBody(1.0, 2.0, 3.0), State.from_quaternion([0, 0, 0, 1.0], [0.3, 0.2, 1.0]))
    >>> [type(d).__name__ for d in fig.andoyer_data]
    ['Polhode', 'Herpolhode']
    """
    fig = Figure(layout="constrained", figsize=(11.0, 5.5))
    left, right = fig.subplots(1, 2)
    polhode(body, state, duration, ax=left)
    first = fig.andoyer_data  # type: ignore[attr-defined]
    herpolhode(body, state, duration, ax=right)
    fig.andoyer_data = (first, fig.andoyer_data)  # type: ignore[attr-defined]
    return fig
