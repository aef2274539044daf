r"""The coupling point: a tidal history turned into the spin-axis model's strength ``α(t)``.

:class:`~andoyer.planetary.spin_axis.SpinAxisModel` turns the Earth's axis with
``α(t) = α_⊙[(1 − e²)^{−3/2} + β]`` (:mod:`andoyer.planetary.spin_axis.model`), ``α_⊙ ∝ H/ω``
and ``β ∝ a_M^{−3}``, calibrated at J2000 by the precession rate. Along a tidal history
``H ∝ ω²`` (:mod:`andoyer.planetary.tides.evolution`), so

.. math:: \alpha(t) = \alpha_\odot\,\frac{\omega(t)}{\omega_0}\,
          \Big[(1-e(t)^2)^{-3/2} + \beta\,\Big(\frac{a_0}{a(t)}\Big)^3\Big]
          \,(1 + \dot H_r t),

the J2000 calibration untouched. The two factors are taken from the history on knots at most
1 Myr apart and interpolated by cubic Hermite polynomials with the equations' own derivatives
(error ``~h⁴``: below 10⁻¹⁰ of ``α``). The history's own secular obliquity drift (the tidal
torque on the axis, 11″ per Myr today: 2″ over 200 kyr) is not passed to the axis: only ``α`` is.

This replaces the linear ``T_d`` scaling of Zeebe & Lourens (2022) (``tidal_dissipation``),
which stays available on its own; the two are not combined.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._validation import as_finite
from andoyer.planetary.orbits.protocol import OrbitHistory
from andoyer.planetary.spin_axis.history import SpinAxisHistory
from andoyer.planetary.spin_axis.model import SpinAxisModel
from andoyer.planetary.tides import equations
from andoyer.planetary.tides.evolution import (
    DEFAULT_RTOL,
    _start,
    integrate_states,
    kernel_constants,
    tidal_model,
)
from andoyer.planetary.tides.response import TidalResponse
from andoyer.planetary.tides.system import EarthMoonSystem

__all__ = ["TidalSpinAxisModel", "tidal_spin_axis_history", "tidal_spin_axis_model"]

Array = NDArray[np.float64]

#: Largest spacing of the knots of the tidal factors, years.
KNOT_SPACING = 1.0e6


@dataclass(frozen=True, eq=False)
class TidalSpinAxisModel(SpinAxisModel):
    """A :class:`SpinAxisModel` whose ``α(t)`` follows a tidal history (module docstring).

    Attributes
    ----------
    spin_factor, moon_factor : callable
        ``ω(t)/ω₀`` and ``(a₀/a(t))³`` (cubic Hermite interpolants, ``t`` in years).
    span : tuple of float
        The years the factors cover.
    tides : str
        The tidal model's name.
    """

    spin_factor: Any = None
    moon_factor: Any = None
    span: tuple[float, float] = (0.0, 0.0)
    tides: str = ""

    def __post_init__(self) -> None:
        super().__post_init__()
        if self.spin_factor is None or self.moon_factor is None:
            msg = "expected the tidal factors of a history (use tidal_spin_axis_model), got None"
            raise ValueError(msg)
        if self.tide_spin != 0 or self.tide_moon != 0:
            msg = (
                "expected no linear tidal dissipation T_d with a tidal history (one or the other), got "
                f"{self.tide_spin!r}, {self.tide_moon!r}"
            )
            raise ValueError(msg)

    def rate(self, t: ArrayLike, e: ArrayLike | None = None) -> Array:
        """``α(t, e)``, radians per Julian year (module docstring).

        Parameters
        ----------
        t : array_like, shape (...)
            Julian years from J2000, within :attr:`span`.
        e : array_like, shape (...), optional

        Returns
        -------
        numpy.ndarray, shape (...)
        """
        t = np.asarray(t, dtype=np.float64)
        lo, hi = self.span
        if np.any(t < lo) or np.any(t > hi):
            msg = (
                f"expected times within the tidal history's span {lo:g} to {hi:g} years, "
                f"got {t.min():g} to {t.max():g}"
            )
            raise ValueError(msg)
        e = self.eccentricity if e is None else np.asarray(e, dtype=np.float64)
        sun = ((1 - e) * (1 + e)) ** -1.5
        drift = 1 + self.ellipticity_drift * t
        return self.alpha_sun * self.spin_factor(t) * drift * (sun + self.beta * self.moon_factor(t))


def _knots(lo: float, hi: float) -> Array:
    lo, hi = min(lo, 0.0), max(hi, 0.0)
    if lo == hi:  # J2000 alone: a year of history keeps the interpolants defined
        hi = 1.0
    parts = []
    if lo < 0:
        count = max(math.ceil(-lo / KNOT_SPACING), 16)
        parts.append(np.linspace(lo, 0.0, count + 1)[:-1])
    parts.append(np.zeros(1))
    if hi > 0:
        count = max(math.ceil(hi / KNOT_SPACING), 16)
        parts.append(np.linspace(0.0, hi, count + 1)[1:])
    return np.concatenate(parts)


def tidal_spin_axis_model(
    base: SpinAxisModel,
    span: tuple[float, float],
    tides: str | TidalResponse = "ocean",
    system: EarthMoonSystem | None = None,
    *,
    solar_tide: bool = True,
) -> TidalSpinAxisModel:
    """``base`` (calibrated at J2000) with its ``α`` following a tidal history over ``span``.

    Parameters
    ----------
    base : SpinAxisModel
        The Earth's model (``beta > 0``), without ``tidal_dissipation``.
    span : tuple of float
        ``(T0, T1)``, Julian years; the history covers it and J2000.
    tides : str or TidalResponse
        As in :func:`andoyer.planetary.tides.tidal_history`.
    system : EarthMoonSystem, optional
    solar_tide : bool

    Returns
    -------
    TidalSpinAxisModel

    Examples
    --------
    >>> from andoyer.planetary.spin_axis import SpinAxisModel
    >>> base = SpinAxisModel.from_precession_rate("earth", 50.38481507, 0.4090926)
    >>> model = tidal_spin_axis_model(base, (-1e8, 0.0), "constant-lag")
    >>> round(float(model.rate(-1e8) / model.rate(0.0)), 4)  # α 100 Myr ago, relative to today
    1.0535
    """
    if not isinstance(base, SpinAxisModel) or isinstance(base, TidalSpinAxisModel):
        msg = f"expected a SpinAxisModel to couple, got {type(base).__name__}"
        raise ValueError(msg)
    if base.beta <= 0:
        msg = f"expected a planet with a moon (beta > 0) for the Earth–Moon tides, got {base.body!r}"
        raise ValueError(msg)
    if base.tide_spin != 0 or base.tide_moon != 0:
        msg = "expected tidal dissipation T_d = 0 with a tidal history (one or the other), got T_d != 0"
        raise ValueError(msg)
    lo, hi = (float(v) for v in as_finite(span, "span"))
    if not lo <= hi:
        msg = f"expected a span T0 <= T1, got {lo!r} to {hi!r}"
        raise ValueError(msg)
    s = EarthMoonSystem() if system is None else system
    response = tidal_model(tides, s) if isinstance(tides, str) else tides
    knots = _knots(lo, hi)
    c = kernel_constants(response, s)
    start = _start(s, None)
    states = integrate_states(knots, c, start, solar_tide, DEFAULT_RTOL, response.name)
    solar = 1 if solar_tide else 0
    slopes = np.array([equations.rates(x, w, e, c, solar) for x, w, e in states])
    from scipy.interpolate import CubicHermiteSpline

    x, w = states[:, 0], states[:, 1]
    spin = CubicHermiteSpline(knots, w, slopes[:, 1])
    moon = CubicHermiteSpline(knots, x**-3, -3 * x**-4 * slopes[:, 0])
    fields = {name: getattr(base, name) for name in base.__dataclass_fields__}
    covered = (float(knots[0]), float(knots[-1]))
    return TidalSpinAxisModel(**fields, spin_factor=spin, moon_factor=moon, span=covered, tides=response.name)


def tidal_spin_axis_history(
    orbit: OrbitHistory,
    body: str,
    times: ArrayLike,
    tides: str | TidalResponse = "ocean",
    *,
    precession_rate: float | None = None,
    dynamical_ellipticity: float | None = None,
    axis: ArrayLike | None = None,
    system: EarthMoonSystem | None = None,
    step: float | None = None,
    order: int | None = None,
    tolerance: float | None = None,
) -> SpinAxisHistory:
    """The Earth's spin axis along ``orbit`` with ``α(t)`` from a tidal history.

    What ``andoyer obliquity earth --tides MODEL`` runs:
    :func:`andoyer.planetary.spin_axis.spin_axis_history` (the model built from the precession
    rate, or ``H``, at J2000), coupled by :func:`tidal_spin_axis_model` over the output times.

    Parameters
    ----------
    orbit : OrbitHistory
    body : {"earth"}
    times : array_like, shape (N,)
        Increasing Julian years from J2000, within ``orbit.span``.
    tides : str or TidalResponse
    precession_rate, dynamical_ellipticity : float, optional
        At most one (default: the IAU 2006 rate).
    axis : array_like, shape (3,), optional
    system : EarthMoonSystem, optional
    step, order, tolerance : optional
        As in :func:`andoyer.planetary.spin_axis.spin_axis_history`: by default the step is chosen
        from the requested accuracy (``tolerance``, radians; default 0.01″) and reported in
        ``error_estimate``; a ``step`` given alone runs at that step (order 8).

    Returns
    -------
    SpinAxisHistory

    Examples
    --------
    >>> from andoyer.planetary.orbits import VondrakEcliptic
    >>> h = tidal_spin_axis_history(VondrakEcliptic(), "earth", [-2e5, 0.0], "constant-lag")
    >>> round(float(np.degrees(h.obliquity[0])), 4)  # 200 kyr ago; with α constant: 23.1077
    23.1101
    """
    from andoyer.planetary.spin_axis import spin_axis_history

    if str(body).strip().lower() != "earth":
        msg = f"expected the body 'earth' for the Earth–Moon tides, got {body!r}"
        raise ValueError(msg)

    def coupled(base: SpinAxisModel, span: tuple[float, float]) -> SpinAxisModel:
        return tidal_spin_axis_model(base, span, tides, system)

    return spin_axis_history(
        orbit,
        "earth",
        times,
        precession_rate=precession_rate,
        dynamical_ellipticity=dynamical_ellipticity,
        axis=axis,
        step=step,
        order=order,
        tolerance=tolerance,
        coupling=coupled,
    )
