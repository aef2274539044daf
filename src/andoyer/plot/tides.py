"""The tidal history of the Earth–Moon system against the geological constraints."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from matplotlib.figure import Figure

from andoyer.planetary.tides import TidalHistory
from andoyer.planetary.tides.constraints import CONSTRAINTS

__all__ = ["tidal_history_plot"]

_PANELS = (
    ("lunar_distance", "lunar distance (km)"),
    ("day_length", "length of day (h)"),
    ("precession_constant", "precession constant (″/yr)"),
    ("obliquity", "obliquity (deg)"),
)


def tidal_history_plot(
    histories: TidalHistory | Sequence[TidalHistory], labels: Sequence[str] | None = None
) -> Figure:
    """Draw distance, day length, precession constant and obliquity against time in Gyr.

    The constraints of :mod:`andoyer.planetary.tides.constraints` are drawn as points (with
    their uncertainties where known).

    Parameters
    ----------
    histories : TidalHistory or sequence of them
    labels : sequence of str, optional
        Legend entries (default: the models' names).

    Returns
    -------
    matplotlib.figure.Figure
        With ``figure.andoyer_data`` the histories drawn.

    Examples
    --------
    >>> from andoyer.planetary.tides import tidal_history
    >>> fig = tidal_history_plot(tidal_history([-1e9, -5e8, 0.0], "ocean"))
    >>> [ax.get_ylabel() for ax in fig.axes][:2]
    ['lunar distance (km)', 'length of day (h)']
    """
    items = [histories] if isinstance(histories, TidalHistory) else list(histories)
    if not items or not all(isinstance(h, TidalHistory) for h in items):
        msg = "expected one or more TidalHistory objects, got something else"
        raise ValueError(msg)
    names = [h.model for h in items] if labels is None else list(labels)
    if len(names) != len(items):
        msg = f"expected one label per history ({len(items)}), got {len(names)}"
        raise ValueError(msg)
    fig = Figure(layout="constrained", figsize=(7.5, 8.0))
    axes = fig.subplots(4, 1, sharex=True)
    for ax, (key, label) in zip(axes, _PANELS, strict=True):
        for h, name in zip(items, names, strict=True):
            values = getattr(h, key)
            ax.plot(h.t / 1e9, np.degrees(values) if key == "obliquity" else values, lw=1.2, label=name)
        points = [c for c in CONSTRAINTS if c.quantity == key]
        if points:
            ages = np.array([-c.age / 1e9 for c in points])
            values = np.array([c.value for c in points])
            errors = np.array([np.nan if c.uncertainty is None else c.uncertainty for c in points])
            ax.errorbar(ages, values, yerr=np.nan_to_num(errors), fmt="o", ms=4, color="k",
                        label="constraints")
        ax.set_ylabel(label)
        if key == "precession_constant":
            ax.set_yscale("log")  # it grows twentyfold as the Moon approaches
    axes[0].legend(loc="best", fontsize="small")
    axes[-1].set_xlabel("time from J2000 (Gyr)")
    fig.andoyer_data = items
    return fig
