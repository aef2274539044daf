"""Where charts break down, and the warning that says a convention was applied."""

from __future__ import annotations

import warnings

import numpy as np
from numpy.typing import NDArray

__all__ = ["SingularChartWarning", "warn_if_singular"]


class SingularChartWarning(UserWarning):
    """A state sits exactly on a chart singularity and a documented convention fixed its angles.

    The Euler chart is singular at ``sin θ = 0`` (only ``φ ± ψ`` is defined;
    the library sets ``ψ = 0``); the Andoyer chart at ``sin J = 0`` (only
    ``g ± l`` is defined; ``l = 0``) and ``sin I = 0`` (only ``h ± g``; ``h = 0``).
    The rotation round trip stays exact; the momenta that the chart cannot
    represent there are noted in the message.
    """


def warn_if_singular(mask: NDArray[np.bool_], message: str, stacklevel: int) -> None:
    """Warn once if any entry of ``mask`` is set; ``stacklevel`` counts from the caller."""
    count = int(np.count_nonzero(mask))
    if count:
        warnings.warn(
            f"{count} state(s) on a chart singularity: {message}",
            SingularChartWarning,
            stacklevel=stacklevel + 1,
        )
