r"""Statistics of an ensemble of obliquity histories: moments, extremes, density, exceedance, first passage.

Given ``M`` histories ``ε_m(t_k)`` on common output times (radians; ``NaN`` where a member had
stopped, :mod:`andoyer.planetary.spin_axis.members`):

* per time, over the members present there: ``members(t_k)`` (how many), ``mean``, ``std``
  (population, ``ddof = 0``), ``min``, ``max``;
* the **density** over all members and times: with bin edges ``b_0 < … < b_J``,
  ``pdf_j = count_j / (C (b_{j+1} − b_j))``, ``C`` the number of finite values, so that
  ``Σ_j pdf_j (b_{j+1} − b_j) = 1`` when every value lies within the edges (values outside
  count in ``C`` and in no bin: the sum is then the fraction within);
* the **first passage** of a threshold ``θ``: for each member, the first output time, counting
  outward from J2000 (``|t|`` increasing), at which ``ε ≥ θ``; ``NaN`` if it never does;
* the **exceedance** ``P(θ)``: the fraction of all ``M`` members whose obliquity reaches ``θ``
  at some output time of the span (a member stopped before reaching it counts as not
  reaching it) — the probability, over the ensemble, that the obliquity exceeded ``θ`` within
  the span; non-increasing in ``θ``;
* the **fraction of time** above ``θ``: of all finite (member, time) values, the fraction
  ``≥ θ``.

Examples
--------
>>> t = np.array([0.0, -1.0, -2.0])
>>> eps = np.radians([[10.0, 30.0, 50.0], [10.0, 20.0, 30.0]])
>>> s = obliquity_statistics(t, eps, thresholds=np.radians([25.0, 40.0]))
>>> np.degrees(s.mean).round(6).tolist(), s.exceedance.tolist()
([10.0, 25.0, 40.0], [1.0, 0.5])
>>> s.first_passage.tolist()
[[-1.0, -2.0], [-2.0, nan]]
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["DEFAULT_BINS", "DEFAULT_THRESHOLDS", "ObliquityStatistics", "obliquity_statistics"]

Array = NDArray[np.float64]

#: Default density bins: 1° wide from 0° to 180° (radians).
DEFAULT_BINS = np.radians(np.arange(0.0, 181.0, 1.0))
#: Default thresholds (radians): 40°, 50°, 60° (Laskar et al. 2004 quote the probability of 60°).
DEFAULT_THRESHOLDS = np.radians([40.0, 50.0, 60.0])


@dataclass(frozen=True)
class ObliquityStatistics:
    """The statistics of :func:`obliquity_statistics` (angles in radians).

    Attributes
    ----------
    t : numpy.ndarray, shape (N,)
    members : numpy.ndarray of int, shape (N,)
        Members with a value at each time.
    mean, std, min, max : numpy.ndarray, shape (N,)
        Over the members present (``NaN`` where none is).
    bins : numpy.ndarray, shape (J + 1,)
        Density bin edges.
    pdf : numpy.ndarray, shape (J,)
    thresholds : numpy.ndarray, shape (K,)
    exceedance : numpy.ndarray, shape (K,)
    fraction_of_time : numpy.ndarray, shape (K,)
    first_passage : numpy.ndarray, shape (K, M)
        Years from J2000, ``NaN``: never.
    """

    t: Array
    members: NDArray[np.int64]
    mean: Array
    std: Array
    min: Array
    max: Array
    bins: Array
    pdf: Array
    thresholds: Array
    exceedance: Array
    fraction_of_time: Array
    first_passage: Array

    def to_dataset(self, obliquity: ArrayLike | None = None):
        """The statistics as an :class:`xarray.Dataset` (degrees), with the histories if given.

        Dimensions ``time``, ``bin`` (centres; edges in ``bin_edges`` over ``bin_edge``),
        ``threshold`` (degrees) and ``sample``. Needs xarray (the ``ensemble`` extra).

        Parameters
        ----------
        obliquity : array_like, shape (M, N), optional
            The histories (radians), stored as ``obliquity`` (degrees).

        Returns
        -------
        xarray.Dataset
        """
        import xarray as xr

        deg = np.degrees

        def tidy(radians: Array) -> Array:
            # degrees to 12 significant digits: 60° and not 59.99999999999999 after the round trip
            return np.array([float(f"{v:.12g}") for v in deg(radians)])

        centres = 0.5 * (self.bins[1:] + self.bins[:-1])
        data = {
            "members": ("time", self.members),
            "mean": ("time", deg(self.mean)),
            "std": ("time", deg(self.std)),
            "min": ("time", deg(self.min)),
            "max": ("time", deg(self.max)),
            "pdf": ("bin", self.pdf / deg(1.0)),
            "bin_edges": ("bin_edge", tidy(self.bins)),
            "exceedance": ("threshold", self.exceedance),
            "fraction_of_time": ("threshold", self.fraction_of_time),
            "first_passage": (("threshold", "sample"), self.first_passage),
        }
        if obliquity is not None:
            data["obliquity"] = (("sample", "time"), deg(np.asarray(obliquity, dtype=float)))
        ds = xr.Dataset(
            data,
            coords={
                "time": ("time", self.t),
                "bin": ("bin", tidy(centres)),
                "threshold": tidy(self.thresholds),
            },
        )
        ds["pdf"].attrs["units"] = "1/deg"
        for name in ("mean", "std", "min", "max", "bin_edges", "obliquity"):
            if name in ds:
                ds[name].attrs["units"] = "deg"
        ds["first_passage"].attrs["units"] = "Julian years from J2000"
        return ds


def _first_passage(t: Array, obliquity: Array, threshold: float) -> Array:
    """The first output time outward from J2000 with ``ε ≥ threshold``, per member."""
    order = np.argsort(np.abs(t), kind="stable")
    above = obliquity[:, order] >= threshold
    hit = above.any(axis=1)
    first = np.argmax(above, axis=1)
    return np.where(hit, t[order][first], np.nan)


def obliquity_statistics(
    t: ArrayLike,
    obliquity: ArrayLike,
    bins: ArrayLike | None = None,
    thresholds: ArrayLike | None = None,
) -> ObliquityStatistics:
    """The statistics of ``M`` obliquity histories over ``N`` common times (see the module).

    Parameters
    ----------
    t : array_like, shape (N,)
        Julian years from J2000.
    obliquity : array_like, shape (M, N)
        Radians; ``NaN`` where a member has no value.
    bins : array_like, shape (J + 1,), optional
        Increasing bin edges, radians (default :data:`DEFAULT_BINS`).
    thresholds : array_like, shape (K,), optional
        Radians (default :data:`DEFAULT_THRESHOLDS`).

    Returns
    -------
    ObliquityStatistics

    Raises
    ------
    ValueError
        For shapes that do not match, non-finite times, infinite obliquities, bins not
        increasing, or non-finite thresholds.

    Examples
    --------
    >>> s = obliquity_statistics([0.0, 1.0], np.radians([[10.0, 20.0]]), bins=np.radians([0.0, 15.0, 30.0]))
    >>> (s.pdf * np.diff(s.bins)).tolist()
    [0.5, 0.5]
    """
    t = np.asarray(t, dtype=float)
    eps = np.asarray(obliquity, dtype=float)
    if t.ndim != 1 or t.size == 0 or not np.all(np.isfinite(t)):
        msg = f"expected finite times of shape (N,), N >= 1, got shape {t.shape}"
        raise ValueError(msg)
    if eps.ndim != 2 or eps.shape[1] != t.size or eps.shape[0] == 0:
        msg = f"expected obliquities of shape (M, {t.size}), M >= 1, got shape {eps.shape}"
        raise ValueError(msg)
    if np.any(np.isinf(eps)):
        msg = "expected finite obliquities (NaN for a member with no value), got inf"
        raise ValueError(msg)
    edges = DEFAULT_BINS if bins is None else np.asarray(bins, dtype=float)
    if edges.ndim != 1 or edges.size < 2 or not np.all(np.isfinite(edges)) or np.any(np.diff(edges) <= 0):
        msg = f"expected at least two increasing finite bin edges, got {bins!r}"
        raise ValueError(msg)
    levels = DEFAULT_THRESHOLDS if thresholds is None else np.atleast_1d(np.asarray(thresholds, dtype=float))
    if levels.ndim != 1 or levels.size == 0 or not np.all(np.isfinite(levels)):
        msg = f"expected one or more finite thresholds, got {thresholds!r}"
        raise ValueError(msg)
    present = np.isfinite(eps)
    members = present.sum(axis=0)
    safe = np.where(present, eps, 0.0)
    with np.errstate(invalid="ignore", divide="ignore"):
        mean = np.where(members > 0, safe.sum(axis=0) / members, np.nan)
        deviation = np.where(present, eps - mean, 0.0)
        std = np.where(members > 0, np.sqrt((deviation**2).sum(axis=0) / members), np.nan)
    low = np.where(members > 0, np.where(present, eps, np.inf).min(axis=0), np.nan)
    high = np.where(members > 0, np.where(present, eps, -np.inf).max(axis=0), np.nan)
    values = eps[present]
    counts, _ = np.histogram(values, bins=edges)
    pdf = counts / (max(values.size, 1) * np.diff(edges))
    passage = np.stack([_first_passage(t, np.where(present, eps, -np.inf), float(v)) for v in levels])
    exceedance = np.isfinite(passage).mean(axis=1)
    fraction = np.array([np.count_nonzero(values >= v) / max(values.size, 1) for v in levels])
    return ObliquityStatistics(
        t, members.astype(np.int64), mean, std, low, high, edges, pdf, levels, exceedance, fraction, passage
    )
