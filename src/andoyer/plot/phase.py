r"""The ``(l, L)`` phase portrait of the free body with its separatrix (Gurfil Fig. 4).

In Andoyer variables the free Hamiltonian (Gurfil eq. 89) depends on ``(l, L)`` only,

.. math:: \mathcal{H}(l, L; G) = \tfrac12\Big[(G^2 - L^2)\Big(\frac{\sin^2 l}{I_1}
          + \frac{\cos^2 l}{I_2}\Big) + \frac{L^2}{I_3}\Big],

with ``m_body = (√(G²−L²) sin l, √(G²−L²) cos l, L)``, so ``l = atan2(m1, m2)`` and ``L = m3``
map the exact energy contours of the momentum sphere (:mod:`andoyer.plot.contours`) onto the
plane without any contouring on a grid.  The hyperbolic (saddle) points are the intermediate
axis ``±G b_B`` at energy ``G²/(2B)``: ``(l, L) = (±π/2, 0)`` when ``b_B = b1`` and
``(0, 0), (±π, 0)`` when ``b_B = b2`` (for a body with ``(b1, b2, b3) = (A, B, C)`` the
saddles sit at ``l = 0, ±π``).  When ``b3`` is the intermediate axis the saddles are the lines
``L = ±G``, where ``l`` is undefined, and no saddle points are listed.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from numpy.typing import ArrayLike, NDArray

from andoyer.body import RigidBody, Symmetry
from andoyer.plot.projection import math_number, new_axes
from andoyer.plot.sphere import LAM_COLOR, SAM_COLOR, SEPARATRIX_COLOR, momentum_sphere_data

__all__ = ["PhasePortrait", "andoyer_plane", "phase_portrait", "phase_portrait_data"]

Array = NDArray[np.float64]


def andoyer_plane(m_body: ArrayLike) -> Array:
    """``(l, L)`` of body momenta (n, 3), with NaN rows where ``l`` jumps (wraps at ±π, poles).

    Examples
    --------
    >>> import numpy as np
    >>> andoyer_plane([[1.0, 0.0, 0.5], [0.0, 1.0, 0.2]]).round(12).tolist()
    [[1.570796326795, 0.5], [0.0, 0.2]]
    """
    m = np.asarray(m_body, dtype=float)
    lL = np.stack([np.arctan2(m[:, 0], m[:, 1]), m[:, 2]], -1)
    # A step over π/2 in l is a wrap at ±π or a pass through a pole (l undefined): break there.
    jumps = np.flatnonzero(np.abs(np.diff(lL[:, 0])) > np.pi / 2) + 1
    return np.insert(lL, jumps, np.nan, axis=0)


@dataclass(frozen=True)
class PhasePortrait:
    """What :func:`phase_portrait` draws.

    Attributes
    ----------
    body : RigidBody
    G : float
    energies : numpy.ndarray, shape (k,)
    contours : tuple of k tuples of numpy.ndarray (n, 2)
        ``(l, L)`` points of each energy contour; NaN rows separate pieces, ``l`` in ``[−π, π]``.
    separatrix_energy : float
        ``G²/(2B)``.
    separatrix : tuple of numpy.ndarray (n, 2)
        ``(l, L)`` of the separatrix.
    saddles : numpy.ndarray, shape (s, 2)
        The hyperbolic points ``(l, L)`` in ``[−π, π] × [−G, G]`` (empty unless the body is
        triaxial with ``b1`` or ``b2`` intermediate).
    """

    body: RigidBody
    G: float
    energies: Array
    contours: tuple[tuple[Array, ...], ...]
    separatrix_energy: float
    separatrix: tuple[Array, ...]
    saddles: Array


def _saddles(body: RigidBody) -> Array:
    if body.symmetry is not Symmetry.TRIAXIAL:
        return np.empty((0, 2))
    middle = body.axis_order[1]
    if middle == 0:
        return np.array([[-np.pi / 2, 0.0], [np.pi / 2, 0.0]])
    if middle == 1:
        return np.array([[-np.pi, 0.0], [0.0, 0.0], [np.pi, 0.0]])
    return np.empty((0, 2))


def phase_portrait_data(
    body: RigidBody, G: float = 1.0, energies: ArrayLike | None = None, n_points: int = 721
) -> PhasePortrait:
    """Energy contours, separatrix and saddle points of the ``(l, L)`` plane (exact).

    Parameters
    ----------
    body : RigidBody
        Any non-spherical body.
    G : float
        Angular-momentum magnitude.
    energies : array_like, shape (k,), optional
        Contour energies in ``[G²/2C, G²/2A]``; default five SAM and five LAM levels.
    n_points : int
        Points per contour.

    Returns
    -------
    PhasePortrait

    Examples
    --------
    >>> import numpy as np
    >>> from andoyer.state.andoyer import andoyer_hamiltonian
    >>> body = RigidBody(1.0, 2.0, 3.0)
    >>> data = phase_portrait_data(body)
    >>> data.saddles.tolist()                           # (l, L) of the intermediate axis b2
    [[-3.141592653589793, 0.0], [0.0, 0.0], [3.141592653589793, 0.0]]
    >>> l, L = np.concatenate(data.separatrix).T
    >>> ok = np.isfinite(l)
    >>> bool(np.allclose(andoyer_hamiltonian(body, l[ok], L[ok], 1.0), 1 / (2 * body.B), rtol=1e-13))
    True
    """
    sphere = momentum_sphere_data(body, G, energies, n_points)
    contours = tuple(tuple(andoyer_plane(c) for c in curves) for curves in sphere.contours)
    separatrix = tuple(andoyer_plane(c) for c in sphere.separatrix)
    return PhasePortrait(
        body, sphere.G, sphere.energies, contours, sphere.separatrix_energy, separatrix, _saddles(body)
    )


def _set_pi_ticks(ax: Axes) -> None:
    ax.set_xticks(np.pi * np.array([-1.0, -0.5, 0.0, 0.5, 1.0]), ["−π", "−π/2", "0", "π/2", "π"])


def phase_portrait(
    body: RigidBody,
    G: float = 1.0,
    energies: ArrayLike | None = None,
    *,
    n_points: int = 721,
    momentum_unit: str | None = None,
    ax: Axes | None = None,
) -> Figure:
    r"""Draw the ``(l, L)`` phase portrait: energy contours, separatrix (red), saddles (×).

    ``l`` is shown on ``[−π, π]``; contours that cross ``l = ±π`` are drawn on both sides.

    Parameters
    ----------
    body, G, energies, n_points
        As in :func:`phase_portrait_data`.
    momentum_unit : str, optional
        Unit of ``G`` and ``L`` for the axis label (e.g. ``"kg m² rad/s"``); default the user's
        consistent units, "inertia × rad per unit time".
    ax : matplotlib.axes.Axes, optional
        Where to draw; default a new figure.

    Returns
    -------
    matplotlib.figure.Figure
        With the drawn :class:`PhasePortrait` as ``figure.andoyer_data``.

    Examples
    --------
    >>> fig = phase_portrait(RigidBody(1.0, 2.0, 3.0), G=2.0)
    >>> fig.andoyer_data.separatrix_energy
    1.0
    >>> print(fig.axes[0].get_ylabel())
    $L = G\cos J$ (inertia × rad per unit time)
    """
    data = phase_portrait_data(body, G, energies, n_points)
    fig, ax = new_axes(ax, figsize=(8.5, 4.5))
    shifts = (-2 * np.pi, 0.0, 2 * np.pi)
    seen: set[str] = set()
    for energy, curves in zip(data.energies, data.contours, strict=True):
        sam = 2 * energy * body.B < data.G**2
        name = "SAM" if sam else "LAM"
        for curve in curves:
            for shift in shifts:
                label = None if name in seen else name
                seen.add(name)
                ax.plot(
                    curve[:, 0] + shift,
                    curve[:, 1],
                    color=SAM_COLOR if sam else LAM_COLOR,
                    lw=1.0,
                    label=label,
                )
    for k, curve in enumerate(data.separatrix):
        for j, shift in enumerate(shifts):
            label = "separatrix $\\mathcal{H} = G^2/2B$" if k == j == 0 else None
            ax.plot(curve[:, 0] + shift, curve[:, 1], color=SEPARATRIX_COLOR, lw=1.8, label=label)
    if len(data.saddles):
        ax.plot(data.saddles[:, 0], data.saddles[:, 1], "x", color="k", ms=8, mew=2, label="saddle points")
    ax.set_xlim(-np.pi, np.pi)
    ax.set_ylim(-1.05 * data.G, 1.05 * data.G)
    _set_pi_ticks(ax)
    ax.set_xlabel("$l$ (rad)")
    ax.set_ylabel(f"$L = G\\cos J$ ({momentum_unit or 'inertia × rad per unit time'})")
    ax.set_title(f"Andoyer phase plane $(l, L)$ of the free body, $G = {math_number(data.G)}$")
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize="small", frameon=False)
    fig.andoyer_data = data  # type: ignore[attr-defined]
    return fig
