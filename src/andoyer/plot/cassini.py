r"""Colombo's top: the phase portrait with the Cassini states, and the geometry of the states.

The portrait is drawn in the frame that turns with the orbit's node (:mod:`andoyer.planetary.cassini`):
the spin axis ``s = (sin θ cos φ, sin θ sin φ, cos θ)`` with the orbit normal ``k`` as the pole
and the Laplace pole at ``φ = 0``, ``θ = i``. The level curves of

.. math:: \mathcal H(\theta, \varphi) = -\frac\alpha2\cos^2\theta - \beta\cos\theta
   - g\,(\cos i\cos\theta + \sin i\sin\theta\cos\varphi)

are contoured on a ``(φ, θ)`` grid; the separatrix (the level of state 4) is the exact
solution of :meth:`andoyer.planetary.cassini.ColomboTop.separatrix`. A state with signed obliquity
``θ > 0`` sits at ``φ = 0``, one with ``θ < 0`` at ``φ = ±180°``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from numpy.typing import NDArray

from andoyer.planetary.cassini import CassiniBody, CassiniState, ColomboTop
from andoyer.plot.projection import new_axes
from andoyer.plot.sphere import SEPARATRIX_COLOR

__all__ = ["CassiniPortrait", "cassini_geometry", "cassini_portrait", "cassini_portrait_data"]

Array = NDArray[np.float64]


@dataclass(frozen=True)
class CassiniPortrait:
    """What :func:`cassini_portrait` draws.

    Attributes
    ----------
    name : str
    top : ColomboTop
    phi : numpy.ndarray, shape (m,)
        Longitudes of the grid (radians, ``[−π, π]``).
    theta : numpy.ndarray, shape (k,)
        Obliquities of the grid (radians, ``[0, π]``).
    energy : numpy.ndarray, shape (k, m)
        ``𝓗(θ, φ)`` on the grid.
    states : list of CassiniState
    separatrix_energy : float or None
        ``𝓗`` of state 4, ``None`` without one.
    separatrix : numpy.ndarray, shape (m, 4)
        Exact obliquities of the separatrix at each ``phi`` (NaN-padded).
    """

    name: str
    top: ColomboTop
    phi: Array
    theta: Array
    energy: Array
    states: list[CassiniState]
    separatrix_energy: float | None
    separatrix: Array


def _top(system: CassiniBody | ColomboTop) -> tuple[str, ColomboTop]:
    if isinstance(system, CassiniBody):
        return system.name, system.top()
    if isinstance(system, ColomboTop):
        return "Colombo's top", system
    msg = f"expected a CassiniBody or a ColomboTop, got {type(system).__name__}"
    raise ValueError(msg)


def cassini_portrait_data(
    system: CassiniBody | ColomboTop, n_phi: int = 721, n_theta: int = 361
) -> CassiniPortrait:
    """The energy grid, the states and the separatrix of Colombo's top.

    Parameters
    ----------
    system : CassiniBody or ColomboTop
    n_phi, n_theta : int
        Grid sizes (at least 3 each).

    Returns
    -------
    CassiniPortrait

    Examples
    --------
    >>> from andoyer.planetary import cassini
    >>> data = cassini_portrait_data(cassini.get("mercury"), n_phi=5, n_theta=5)
    >>> [s.number for s in data.states], data.energy.shape
    ([1, 2, 3, 4], (5, 5))
    """
    if n_phi < 3 or n_theta < 3:
        msg = f"expected grids of at least 3 points, got n_phi={n_phi}, n_theta={n_theta}"
        raise ValueError(msg)
    name, top = _top(system)
    phi = np.linspace(-np.pi, np.pi, n_phi)
    theta = np.linspace(0.0, np.pi, n_theta)
    energy = top.hamiltonian(theta[:, None], phi[None, :])
    return CassiniPortrait(
        name, top, phi, theta, energy, top.states(), top.separatrix_energy(), top.separatrix(phi)
    )


def _state_points(state: CassiniState) -> list[tuple[float, float]]:
    """Where a state sits in the ``(φ, θ)`` plane, degrees (twice when at ``φ = ±180°``)."""
    obliquity = math.degrees(state.obliquity)
    if state.theta > 0:
        return [(0.0, obliquity)]
    return [(-180.0, obliquity), (180.0, obliquity)]


def cassini_portrait(
    system: CassiniBody | ColomboTop,
    *,
    levels: int = 24,
    n_phi: int = 721,
    n_theta: int = 361,
    ax: Axes | None = None,
) -> Figure:
    """Draw the phase portrait of Colombo's top with the Cassini states and the separatrix.

    Parameters
    ----------
    system : CassiniBody or ColomboTop
    levels : int
        Number of energy contours.
    n_phi, n_theta : int
        Grid sizes, as in :func:`cassini_portrait_data`.
    ax : matplotlib.axes.Axes, optional
        Where to draw; default a new figure.

    Returns
    -------
    matplotlib.figure.Figure
        With the drawn :class:`CassiniPortrait` as ``figure.andoyer_data``.

    Examples
    --------
    >>> from andoyer.planetary import cassini
    >>> fig = cassini_portrait(cassini.get("moon"), n_phi=91, n_theta=46)
    >>> [s.number for s in fig.andoyer_data.states]
    [2, 3]
    """
    data = cassini_portrait_data(system, n_phi, n_theta)
    fig, ax = new_axes(ax, figsize=(8.5, 5.0))
    phi_deg, theta_deg = np.degrees(data.phi), np.degrees(data.theta)
    # Evenly spaced levels miss the small loops about a state near a pole: add the levels of
    # points 1°, 2° and 4° from each stable state.
    even = np.linspace(data.energy.min(), data.energy.max(), levels + 2)[1:-1]
    near = [
        data.top.hamiltonian(s.theta + np.radians(d) * np.array([-1.0, 1.0]))
        for s in data.states
        if s.stable
        for d in (1.0, 2.0, 4.0)
    ]
    values = np.unique(np.concatenate([even, *near]))
    style = {"colors": "0.55", "linewidths": 0.8, "linestyles": "solid"}
    ax.contour(phi_deg, theta_deg, data.energy, levels=values, **style)
    if data.separatrix_energy is not None:
        points = np.degrees(data.separatrix)
        for column in range(points.shape[1]):
            label = "separatrix $\\mathcal{H} = \\mathcal{H}_4$" if column == 0 else None
            ax.plot(phi_deg, points[:, column], ".", ms=1.5, color=SEPARATRIX_COLOR, label=label)
    for state in data.states:
        for x, y in _state_points(state):
            stable = {"marker": "o", "mfc": "k", "mec": "k"}
            marker = stable if state.stable else {"marker": "x", "mec": "k", "mew": 2}
            ax.plot([x], [y], ms=8, ls="none", clip_on=False, zorder=5, **marker)
            ax.annotate(
                str(state.number),
                (x, y),
                xytext=(6 if x < 180 else -12, 6),
                textcoords="offset points",
                fontsize="large",
                fontweight="bold",
            )
    ax.plot([], [], "o", color="k", label="stable Cassini state")
    ax.plot([], [], "x", color="k", mew=2, label="unstable Cassini state")
    laplace = math.degrees(data.top.inclination)
    ax.plot([0.0], [laplace], "*", color="tab:blue", ms=10, label="Laplace pole")
    ax.set_xlim(-180.0, 180.0)
    ax.set_ylim(180.0, 0.0)
    ax.set_xticks([-180, -90, 0, 90, 180])
    ax.set_xlabel("$\\varphi$: longitude of the spin axis from the Laplace pole (deg)")
    ax.set_ylabel("$\\theta$: obliquity to the orbit normal (deg)")
    top = data.top
    ax.set_title(
        f"Colombo's top: {data.name.capitalize()}, $|g|/\\alpha = {abs(top.node_rate) / top.alpha:.3g}$, "
        f"$\\beta/\\alpha = {top.beta / top.alpha:.3g}$, $i = {laplace:.4g}°$"
    )
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize="small", frameon=False)
    fig.andoyer_data = data  # type: ignore[attr-defined]
    return fig


def cassini_geometry(system: CassiniBody | ColomboTop, *, ax: Axes | None = None) -> Figure:
    """Draw the Laplace pole, the orbit normal and the spin axis of each state in their common plane.

    Angles are to scale; each state is labelled with its number, obliquity and inclination to
    the Laplace pole.

    Parameters
    ----------
    system : CassiniBody or ColomboTop
    ax : matplotlib.axes.Axes, optional

    Returns
    -------
    matplotlib.figure.Figure
        With the list of :class:`~andoyer.planetary.cassini.CassiniState` as ``figure.andoyer_data``.

    Examples
    --------
    >>> from andoyer.planetary import cassini
    >>> fig = cassini_geometry(cassini.get("moon"))
    >>> round(fig.andoyer_data[0].inclination_to_laplace_deg, 3)
    1.549
    """
    name, top = _top(system)
    states = top.states()
    fig, ax = new_axes(ax, figsize=(5.5, 5.5))
    i = top.inclination

    def arrow(angle: float, color: str, text: str, length: float = 1.0, right: bool | None = None) -> None:
        # ``angle`` from the Laplace pole (up), positive towards the orbit normal (right).
        x, y = length * math.sin(angle), length * math.cos(angle)
        ax.annotate("", (x, y), (0.0, 0.0), arrowprops={"arrowstyle": "-|>", "color": color, "lw": 1.8})
        right = x > 0 if right is None else right
        ax.annotate(
            text,
            (x, y),
            xytext=(6 if right else -6, 2),
            textcoords="offset points",
            color=color,
            fontsize="small",
            ha="left" if right else "right",
        )

    for angle, colour, label in ((0.0, "tab:blue", "Laplace plane"), (i, "tab:green", "orbit plane")):
        ends = np.array([-1.15, 1.15])
        ax.plot(ends * math.cos(angle), -ends * math.sin(angle), color=colour, lw=0.8, ls="--", label=label)
    arrow(0.0, "tab:blue", "Laplace pole $K$", right=False)
    arrow(i, "tab:green", f"orbit normal $k$ ($i = {math.degrees(i):.4g}°$)", right=True)
    for state in states:
        colour = "k" if state.stable else "tab:red"
        text = (
            f"state {state.number}: $\\theta = {state.obliquity_deg:.4g}°$, "
            f"$\\angle(s, K) = {state.inclination_to_laplace_deg:.4g}°$"
        )
        arrow(i - state.theta, colour, text, length=0.8)
    circle = np.linspace(0.0, 2 * np.pi, 361)
    ax.plot(np.cos(circle), np.sin(circle), color="0.85", lw=0.8)
    ax.set_xlim(-1.6, 1.6)
    ax.set_ylim(-1.25, 1.25)
    ax.set_aspect("equal")
    ax.axis("off")
    ax.legend(loc="lower left", fontsize="x-small", frameon=False)
    ax.set_title(f"Cassini states of {name.capitalize()}\n(the plane of $K$ and $k$, angles to scale)")
    fig.andoyer_data = states  # type: ignore[attr-defined]
    return fig
