r"""The angular-momentum sphere ``|m| = G`` with the energy contours of the free body (Gurfil Fig. 1).

Each contour is a polhode: the intersection of the sphere with the energy ellipsoid
``½ m·I⁻¹m = T`` (:mod:`andoyer.plot.contours`).  Contours with ``2T/G² < 1/B`` circle the axis
of maximum inertia (SAM), those with ``2T/G² > 1/B`` the axis of minimum inertia (LAM); the
separatrix ``T = G²/(2B)`` is the pair of great circles through the intermediate axis.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from numpy.typing import ArrayLike, NDArray

from andoyer.body import RigidBody
from andoyer.plot.contours import check_energy, default_energies, energy_contour, separatrix_contour
from andoyer.plot.projection import Orthographic, math_number, new_axes

__all__ = ["MomentumSphere", "momentum_sphere", "momentum_sphere_data"]

Array = NDArray[np.float64]
SAM_COLOR, LAM_COLOR, SEPARATRIX_COLOR = "tab:blue", "tab:green", "tab:red"
DEFAULT_VIEW = (np.radians(25.0), np.radians(35.0))


@dataclass(frozen=True)
class MomentumSphere:
    """What :func:`momentum_sphere` draws.

    Attributes
    ----------
    body : RigidBody
    G : float
        Radius of the sphere (magnitude of the angular momentum).
    energies : numpy.ndarray, shape (k,)
        Energy of each contour.
    contours : tuple of k tuples of numpy.ndarray (n, 3)
        The curves of each energy in body components (two per energy).
    separatrix_energy : float
        ``G²/(2B)``.
    separatrix : tuple of numpy.ndarray (n, 3)
        The two great circles of the separatrix.
    """

    body: RigidBody
    G: float
    energies: Array
    contours: tuple[tuple[Array, ...], ...]
    separatrix_energy: float
    separatrix: tuple[Array, ...]


def momentum_sphere_data(
    body: RigidBody, G: float = 1.0, energies: ArrayLike | None = None, n_points: int = 361
) -> MomentumSphere:
    """Energy contours on the momentum sphere and its separatrix, exact (closed form).

    Parameters
    ----------
    body : RigidBody
        Any non-spherical body, axes in any order.
    G : float
        Angular-momentum magnitude.
    energies : array_like, shape (k,), optional
        Contour energies in ``[G²/2C, G²/2A]``; default
        :func:`~andoyer.plot.contours.default_energies` (five SAM and five LAM levels).
    n_points : int
        Points per curve.

    Returns
    -------
    MomentumSphere

    Examples
    --------
    >>> import numpy as np
    >>> body = RigidBody(1.0, 2.0, 3.0)
    >>> data = momentum_sphere_data(body, G=2.0)
    >>> len(data.energies), data.separatrix_energy
    (10, 1.0)
    >>> m = np.concatenate(data.contours[3])
    >>> bool(np.allclose(body.energy(m), data.energies[3], rtol=1e-14))
    True
    """
    values = default_energies(body, G) if energies is None else check_energy(body, float(G), energies)
    contours = tuple(energy_contour(body, G, float(E), n_points) for E in values)
    return MomentumSphere(
        body, float(G), values, contours, float(G) ** 2 / (2 * body.B), separatrix_contour(body, G, n_points)
    )


def momentum_sphere(
    body: RigidBody,
    G: float = 1.0,
    energies: ArrayLike | None = None,
    *,
    elev: float = DEFAULT_VIEW[0],
    azim: float = DEFAULT_VIEW[1],
    n_points: int = 361,
    ax: Axes | None = None,
) -> Figure:
    """Draw the momentum sphere with its energy contours, in an orthographic view.

    Contours are solid on the visible hemisphere and dotted behind it; SAM contours blue, LAM
    contours green, the separatrix red.  The axes drawn are the body axes ``m1, m2, m3``.

    Parameters
    ----------
    body, G, energies, n_points
        As in :func:`momentum_sphere_data`.
    elev, azim : float
        Viewing direction, radians (default 25° and 35°).
    ax : matplotlib.axes.Axes, optional
        Where to draw; default a new figure.

    Returns
    -------
    matplotlib.figure.Figure
        With the drawn :class:`MomentumSphere` as ``figure.andoyer_data``.

    Examples
    --------
    >>> fig = momentum_sphere(RigidBody(1.0, 2.0, 3.0))
    >>> fig.andoyer_data.G
    1.0
    """
    data = momentum_sphere_data(body, G, energies, n_points)
    fig, ax = new_axes(ax, figsize=(5.5, 5.5))
    view = Orthographic(elev, azim)
    view.draw_sphere(ax, data.G, ("$m_1$", "$m_2$", "$m_3$"))
    seen: set[str] = set()
    for energy, curves in zip(data.energies, data.contours, strict=True):
        sam = 2 * energy * body.B < data.G**2
        name = "SAM" if sam else "LAM"
        for curve in curves:
            label = None if name in seen else name
            seen.add(name)
            view.draw_curve(ax, curve, color=SAM_COLOR if sam else LAM_COLOR, lw=1.0, label=label)
    for k, curve in enumerate(data.separatrix):
        view.draw_curve(
            ax, curve, color=SEPARATRIX_COLOR, lw=1.8, label="separatrix $T = G^2/2B$" if k == 0 else None
        )
    ax.set_title(f"Energy contours on the angular-momentum sphere\n$|m| = G = {math_number(data.G)}$")
    ax.legend(loc="lower left", fontsize="small", frameon=False)
    fig.andoyer_data = data  # type: ignore[attr-defined]
    return fig
