"""The rigid-Earth nutation in longitude and obliquity against time (:mod:`andoyer.planetary.nutation`)."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure
from numpy.typing import ArrayLike

__all__ = ["nutation_plot"]


def nutation_plot(t: ArrayLike, dpsi: ArrayLike, deps: ArrayLike, title: str = "") -> Figure:
    """Two stacked panels, ``Δψ(t)`` and ``Δε(t)`` in arcseconds against Julian years from J2000.

    Parameters
    ----------
    t, dpsi, deps : array_like, shape (T,)
    title : str

    Returns
    -------
    matplotlib.figure.Figure
        With ``andoyer_data = (t, dpsi, deps)`` as arrays.

    Examples
    --------
    >>> fig = nutation_plot([0.0, 1.0], [0.0, 1.0], [1.0, 0.0])
    >>> [ax.get_ylabel() for ax in fig.axes]
    ['Δψ (arcsec)', 'Δε (arcsec)']
    """
    t, dpsi, deps = (np.asarray(v, dtype=float) for v in (t, dpsi, deps))
    figure = Figure(figsize=(8, 5), layout="constrained")
    top, bottom = figure.subplots(2, 1, sharex=True)
    top.plot(t, dpsi, lw=0.8)
    top.set_ylabel("Δψ (arcsec)")
    bottom.plot(t, deps, lw=0.8, color="C1")
    bottom.set_ylabel("Δε (arcsec)")
    bottom.set_xlabel("Julian years TT from J2000")
    if title:
        top.set_title(title)
    figure.andoyer_data = (t, dpsi, deps)  # type: ignore[attr-defined]
    return figure
