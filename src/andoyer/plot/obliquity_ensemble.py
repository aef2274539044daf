r"""A chaotic-obliquity ensemble: a few histories with the ensemble's spread, and the density.

Left panel: the obliquity (degrees) of a few members against time (Myr), over the ensemble's
mean ± one standard deviation and its minimum–maximum envelope; right panel: the density of the
obliquity over all members and times (per degree). Takes the dataset of
:func:`andoyer.ensemble.obliquity_ensemble`.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

__all__ = ["obliquity_ensemble_figure"]


def obliquity_ensemble_figure(ds, histories: int = 4) -> Figure:
    """Draw a few histories and the density of an obliquity ensemble; return the figure.

    Parameters
    ----------
    ds : xarray.Dataset
        From :func:`andoyer.ensemble.obliquity_ensemble` (``obliquity``, ``mean``, ``std``,
        ``min``, ``max``, ``pdf``, ``bin_edges``).
    histories : int
        Members drawn (the first ones).

    Returns
    -------
    matplotlib.figure.Figure
        With ``figure.andoyer_data`` the dataset.

    Examples
    --------
    >>> from andoyer.ensemble import obliquity_ensemble
    >>> ds = obliquity_ensemble("mars", 2, -2e5, 1e5, scheduler="synchronous", progress=False)
    >>> [ax.get_xlabel() for ax in obliquity_ensemble_figure(ds).axes]
    ['time (Myr from J2000)', 'obliquity (deg)']
    """
    needed = ("obliquity", "mean", "std", "min", "max", "pdf", "bin_edges")
    if any(name not in getattr(ds, "data_vars", ()) for name in needed):
        msg = f"expected an obliquity_ensemble dataset ({', '.join(needed)}), got {type(ds)}"
        raise ValueError(msg)
    if not (isinstance(histories, int) and histories >= 0):
        msg = f"expected a non-negative whole number of histories, got {histories!r}"
        raise ValueError(msg)
    t = ds.time.values / 1e6
    fig = Figure(layout="constrained", figsize=(10.0, 4.5))
    left, right = fig.subplots(1, 2, width_ratios=(2.2, 1.0))
    mean, std = ds["mean"].values, ds["std"].values
    left.fill_between(t, ds["min"].values, ds["max"].values, color="0.88", label="min–max")
    left.fill_between(t, mean - std, mean + std, color="0.7", label="mean ± std")
    eps = ds["obliquity"].values
    for m in range(min(histories, eps.shape[0])):
        left.plot(t, eps[m], lw=0.7, label=f"member {m}")
    left.plot(t, mean, color="k", lw=1.2, label="mean")
    left.set_xlabel("time (Myr from J2000)")
    left.set_ylabel("obliquity (deg)")
    left.legend(loc="upper left", fontsize="small", ncols=2)
    edges = ds.bin_edges.values
    right.stairs(ds.pdf.values, edges, fill=True, color="C0", alpha=0.6)
    finite = eps[np.isfinite(eps)]
    if finite.size:
        right.set_xlim(max(0.0, float(finite.min()) - 5.0), min(180.0, float(finite.max()) + 5.0))
    right.set_xlabel("obliquity (deg)")
    right.set_ylabel("density (1/deg)")
    fig.suptitle(f"{ds.attrs.get('body', '')}: {eps.shape[0]} members")
    fig.andoyer_data = ds
    return fig
