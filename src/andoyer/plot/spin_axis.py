r"""Obliquity and climatic precession of spin-axis histories against time (kyr).

Top panel: the obliquity ``ε`` (degrees) of each history; bottom panel: the climatic
precession ``e sin ϖ`` (dimensionless) of those that know the eccentricity
(:class:`~andoyer.planetary.spin_axis.SpinAxisHistory`). Time in thousands of Julian years from J2000.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from matplotlib.figure import Figure

from andoyer.planetary.spin_axis import SpinAxisHistory

__all__ = ["obliquity_history"]


def obliquity_history(
    histories: SpinAxisHistory | Sequence[SpinAxisHistory], labels: Sequence[str] | None = None
) -> Figure:
    """Draw obliquity and climatic precession against time in kyr; return the figure.

    Parameters
    ----------
    histories : SpinAxisHistory or sequence of them
    labels : sequence of str, optional
        Legend entries (default: body and orbit source).

    Returns
    -------
    matplotlib.figure.Figure
        With ``figure.andoyer_data`` the histories drawn.

    Examples
    --------
    >>> from andoyer.planetary.orbits import VondrakEcliptic
    >>> from andoyer.planetary.spin_axis import output_times, spin_axis_history
    >>> h = spin_axis_history(VondrakEcliptic(), "earth", output_times(-5000.0, 0.0, 1000.0))
    >>> fig = obliquity_history(h)
    >>> [ax.get_ylabel() for ax in fig.axes]
    ['obliquity (deg)', 'climatic precession e sin ϖ']
    """
    items = [histories] if isinstance(histories, SpinAxisHistory) else list(histories)
    if not items or not all(isinstance(h, SpinAxisHistory) for h in items):
        msg = "expected one or more SpinAxisHistory objects, got something else"
        raise ValueError(msg)
    names = [f"{h.model.body} ({h.orbit_name})" for h in items] if labels is None else list(labels)
    fig = Figure(layout="constrained", figsize=(7.5, 5.5))
    top, bottom = fig.subplots(2, 1, sharex=True)
    for h, name in zip(items, names, strict=True):
        top.plot(h.t / 1000.0, np.degrees(h.obliquity), lw=1.0, label=name)
        cp = h.climatic_precession
        if cp is not None:
            bottom.plot(h.t / 1000.0, cp, lw=1.0, label=name)
    if not any(h.climatic_precession is not None for h in items):
        bottom.text(0.5, 0.5, "orbit source without eccentricity", ha="center", va="center",
                    transform=bottom.transAxes)
        bottom.set_yticks([])
    top.set_ylabel("obliquity (deg)")
    bottom.set_ylabel("climatic precession e sin ϖ")
    bottom.set_xlabel("time from J2000 (kyr)")
    if len(items) > 1:
        top.legend(loc="best", fontsize="small")
    fig.andoyer_data = items
    return fig
