r"""The protocol every orbit history answers, and its time check.

Frame: the J2000 ecliptic and equinox, ``x`` towards the J2000 mean equinox,
``z`` towards the J2000 ecliptic pole (IAU 2006, ``ε₀ = 84381.406″``). Times are
Julian years TT from J2000.0 (``t = (JD_TT − 2451545.0)/365.25``).
"""

from __future__ import annotations

from typing import Protocol, runtime_checkable

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._validation import as_finite

__all__ = ["OrbitHistory", "check_times"]

Array = NDArray[np.float64]


@runtime_checkable
class OrbitHistory(Protocol):
    """A moving orbit: its plane's normal and, where known, its eccentricity vector.

    Attributes
    ----------
    name : str
        Short name of the source (``"vondrak"``, ``"nbody"``, ...).
    span : tuple of float
        ``(t_min, t_max)``, Julian years from J2000, where the source is valid.
    has_eccentricity : bool
        Whether :meth:`eccentricity_vector` is available.
    """

    name: str
    span: tuple[float, float]
    has_eccentricity: bool

    def normal(self, t: ArrayLike) -> Array:
        """Unit orbit normal ``n(t)``, shape ``t.shape + (3,)``, J2000 ecliptic frame."""
        ...

    def eccentricity_vector(self, t: ArrayLike) -> Array:
        """``e(t)`` times the unit vector to perihelion, shape ``t.shape + (3,)``."""
        ...


def check_times(t: ArrayLike, span: tuple[float, float], source: str) -> Array:
    """Validate times (Julian years from J2000) against a source's span of validity.

    Parameters
    ----------
    t : array_like, shape (...)
        Julian years TT from J2000.
    span : tuple of float
        ``(t_min, t_max)``.
    source : str
        Named in the error.

    Returns
    -------
    numpy.ndarray, shape (...)
        ``t`` as float64.

    Examples
    --------
    >>> check_times([0.0, 1e3], (-2e5, 2e5), "vondrak").tolist()
    [0.0, 1000.0]
    >>> check_times(3e5, (-2e5, 2e5), "vondrak")
    Traceback (most recent call last):
    ...
    ValueError: expected times within the vondrak orbit's span -200000 to 200000 years from J2000, got 300000
    """
    times = as_finite(t, "times")
    lo, hi = span
    if times.size and (times.min() < lo or times.max() > hi):
        bad = float(times.min()) if times.min() < lo else float(times.max())
        msg = (
            f"expected times within the {source} orbit's span {lo:g} to {hi:g} years from J2000, got {bad:g}"
        )
        raise ValueError(msg)
    return times
