r"""Orthographic view of a sphere: curves on it drawn solid in front and dotted behind.

The viewer looks at the origin from the direction
``v = (cos e cos a, cos e sin a, sin e)`` (elevation ``e``, azimuth ``a``, as in matplotlib's
3-D axes).  A point ``p`` is drawn at ``(p·r, p·u)`` with ``r = (−sin a, cos a, 0)`` and
``u = v × r``; it is in front of the sphere when ``p·v ≥ 0``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Circle
from numpy.typing import ArrayLike, NDArray

from andoyer._validation import as_finite, as_vectors

__all__ = ["Orthographic", "math_number", "new_axes"]

Array = NDArray[np.float64]


def math_number(value: float, digits: int = 6) -> str:
    r"""``value`` as mathtext (without the dollars): ``7.29212 \times 10^{-5}`` rather than ``7.29212e-05``.

    Plain ``%g`` notation where ``%g`` has no exponent (from 1e-4 to below 10**digits).

    Examples
    --------
    >>> math_number(7.2921e-05), math_number(0.25), math_number(-3e8, 3)
    ('7.2921 \\times 10^{-5}', '0.25', '-3 \\times 10^{8}')
    """
    text = f"{float(value):.{digits}g}"
    if "e" not in text:
        return text
    mantissa, exponent = text.split("e")
    return f"{mantissa} \\times 10^{{{int(exponent)}}}"


def new_axes(ax: Axes | None, **figure_kw: object) -> tuple[Figure, Axes]:
    """``ax`` and its figure, or a new pyplot-free figure with one axes.

    The new figure is not registered with pyplot (nothing to close); save it with
    ``figure.savefig`` or display it in a notebook.

    Examples
    --------
    >>> fig, ax = new_axes(None)
    >>> ax.figure is fig
    True
    """
    if ax is None:
        fig = Figure(layout="constrained", **figure_kw)
        return fig, fig.add_subplot()
    if not isinstance(ax, Axes):
        msg = f"expected a matplotlib Axes, got {type(ax).__name__}"
        raise ValueError(msg)
    return ax.figure, ax


@dataclass(frozen=True)
class Orthographic:
    """An orthographic view from elevation ``elev`` and azimuth ``azim`` (radians).

    Examples
    --------
    >>> view = Orthographic(0.0, 0.0)           # looking down the x axis
    >>> view.project([[0.0, 1.0, 2.0]]).tolist()
    [[1.0, 2.0]]
    >>> view.depth([[1.0, 0.0, 0.0], [-1.0, 0.0, 0.0]]).tolist()
    [1.0, -1.0]
    """

    elev: float
    azim: float

    def __post_init__(self) -> None:
        for name in ("elev", "azim"):
            object.__setattr__(self, name, float(as_finite(getattr(self, name), name)))

    @property
    def basis(self) -> tuple[Array, Array, Array]:
        """``(r, u, v)``: screen right, screen up and the direction towards the viewer."""
        ce, se, ca, sa = np.cos(self.elev), np.sin(self.elev), np.cos(self.azim), np.sin(self.azim)
        v = np.array([ce * ca, ce * sa, se])
        r = np.array([-sa, ca, 0.0])
        return r, np.cross(v, r), v

    def project(self, points: ArrayLike) -> Array:
        """Screen coordinates (..., 2) of points (..., 3)."""
        p = as_vectors(points, "points")
        r, u, _ = self.basis
        return np.stack([p @ r, p @ u], -1)

    def depth(self, points: ArrayLike) -> Array:
        """Distance towards the viewer, ``p·v`` (..., ): positive in front."""
        return as_vectors(points, "points") @ self.basis[2]

    def draw_sphere(self, ax: Axes, radius: float, labels: tuple[str, str, str]) -> None:
        """Outline of the sphere and its three axes, labelled where they point to the viewer."""
        ax.add_patch(Circle((0.0, 0.0), radius, fill=False, color="0.3", lw=1.0))
        for k, label in enumerate(labels):
            tip = np.zeros(3)
            tip[k] = radius
            for sign in (1.0, -1.0):
                end = sign * tip
                x, y = self.project(end)
                front = self.depth(end) >= 0
                ax.plot([0.0, x], [0.0, y], color="0.5", lw=0.6, ls="-" if front else ":")
                if front:
                    text = label if sign > 0 else f"−{label}"
                    ax.annotate(text, (x, y), xytext=(3, 3), textcoords="offset points", color="0.2")
        ax.set_aspect("equal")
        pad = 1.12 * radius
        ax.set_xlim(-pad, pad)
        ax.set_ylim(-pad, pad)
        ax.set_xticks([])
        ax.set_yticks([])

    def draw_curve(self, ax: Axes, points: ArrayLike, hidden: bool = True, **style: object) -> list[Line2D]:
        """Draw a curve (n, 3): solid where it faces the viewer, dotted (or not at all) behind.

        Returns the lines drawn: the visible part first (NaN where hidden), then the hidden part.
        """
        p = as_vectors(points, "points")
        xy = self.project(p)
        front = self.depth(p) >= 0
        # A segment belongs to the side of its first point; the break point is shared so that
        # the two parts join on the outline.
        vis = np.where(front[:, None] | np.r_[False, front[:-1]][:, None], xy, np.nan)
        lines = ax.plot(vis[:, 0], vis[:, 1], **style)
        if hidden:
            back = np.where(~front[:, None] | np.r_[False, ~front[:-1]][:, None], xy, np.nan)
            faint = {**style, "ls": ":", "alpha": 0.45, "label": None}
            lines += ax.plot(back[:, 0], back[:, 1], **faint)
        return lines
