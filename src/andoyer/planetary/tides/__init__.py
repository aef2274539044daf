r"""The tidal evolution of the Earth–Moon system: lunar distance, day length, obliquity, precession.

The Moon's semi-major axis ``a``, the Earth's spin ``ω`` and its obliquity ``ε`` evolve
together under the tides the Moon and the Sun raise on the Earth
(:mod:`andoyer.planetary.tides.equations`), for a choice of the Earth's tidal response
(:mod:`andoyer.planetary.tides.response`): a constant time lag calibrated to lunar laser
ranging, or a resonant ocean after Farhat et al. (2022). From the state follow the day length,
the hydrostatic dynamical ellipticity ``H ∝ ω²`` and the precession constant ``α cos ε`` in
the convention of Laskar et al. (2004) (:mod:`andoyer.planetary.tides.evolution`), and the
spin-axis model's strength ``α(t)`` (:func:`tidal_spin_axis_model`). Times are Julian years
from J2000 (negative: past). The numbers of the bodies are :class:`EarthMoonSystem`'s.

Examples
--------
>>> h = tidal_history([-1.4e9, 0.0], "ocean")
>>> [round(float(d)) for d in h.lunar_distance]  # km; Meyers & Malinverno 2018: 340,900 ± 2,600 at 1.4 Ga
[336881, 384399]
"""

from __future__ import annotations

from typing import Any

from andoyer.planetary.tides.evolution import (
    LUNAR_AGE,
    MEASURED_RECESSION,
    TidalHistory,
    calibrate,
    present_rates,
    tidal_history,
    tidal_model,
)
from andoyer.planetary.tides.response import ConstantPhaseLag, ConstantTimeLag, OceanTides, TidalResponse
from andoyer.planetary.tides.system import EarthMoonSystem

__all__ = [
    "LUNAR_AGE",
    "MEASURED_RECESSION",
    "ConstantPhaseLag",
    "ConstantTimeLag",
    "EarthMoonSystem",
    "OceanTides",
    "TidalHistory",
    "TidalResponse",
    "TidalSpinAxisModel",
    "calibrate",
    "present_rates",
    "tidal_history",
    "tidal_model",
    "tidal_spin_axis_history",
    "tidal_spin_axis_model",
]

#: Loaded on first use: the coupling imports the spin-axis package, which a tidal history alone
#: does not need.
_COUPLING = ("TidalSpinAxisModel", "tidal_spin_axis_history", "tidal_spin_axis_model")


def __getattr__(name: str) -> Any:
    if name not in _COUPLING:
        msg = f"module 'andoyer.planetary.tides' has no attribute {name!r}"
        raise AttributeError(msg)
    from andoyer.planetary.tides import coupling

    value = getattr(coupling, name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
