"""The charts the command line can read and write, with their column names."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from andoyer.state import State


@dataclass(frozen=True)
class ChartColumns:
    """How one chart maps to and from the state on the command line."""

    columns: tuple[str, ...]
    angles: tuple[str, ...]
    to_state: Callable[[Sequence[np.ndarray]], State]
    from_state: Callable[[State], Sequence[np.ndarray]]


CHARTS: dict[str, ChartColumns] = {
    "state": ChartColumns(
        ("qx", "qy", "qz", "qw", "m1", "m2", "m3"),
        (),
        lambda v: State.from_quaternion(np.stack(v[:4], -1), np.stack(v[4:], -1)),
        lambda s: (*np.moveaxis(s.quaternion, -1, 0), *np.moveaxis(s.m_body, -1, 0)),
    ),
    "euler": ChartColumns(
        ("phi", "theta", "psi", "Phi", "Theta", "Psi"),
        ("phi", "theta", "psi"),
        lambda v: State.from_euler(*v),
        lambda s: tuple(s.as_euler()),
    ),
    "andoyer": ChartColumns(
        ("l", "g", "h", "L", "G", "H"),
        ("l", "g", "h"),
        lambda v: State.from_andoyer(*v),
        lambda s: tuple(s.as_andoyer()),
    ),
}
