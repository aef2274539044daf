r"""Spin-axis histories under a moving orbit: obliquity, general precession, climatic precession.

Conventions (frame: the J2000 ecliptic and equinox, :mod:`andoyer.planetary.orbits`; ``t`` in Julian
years TT from J2000):

* the **axis** ``s(t)`` is integrated from ``s(0) = s₀`` (default, for the Earth, the IAU 2006
  mean pole of J2000, ``s₀ = (0, sin ε₀, cos ε₀)`` with ``ε₀ = 84381.406″``);
* the **obliquity** ``ε = ∠(s, n) = atan2(|s×n|, s·n)``, ``n(t)`` the orbit normal of date;
* the **equinox of date** ``γ = s×n / |s×n|``, the ascending node of the orbit on the
  equator, where the Sun crosses the equator northward (``γ(0) = +x`` for the Earth);
* the **general precession in longitude** ``p_A``: with the frame of date
  ``F(t) = [γ, n×γ, n]`` (rows) and ``R = F(t) F(0)ᵀ = R₃(−(Π_A + p_A)) R₁(π_A) R₃(Π_A)``
  (Lieske et al. 1977; ``Π_A, π_A`` the node and inclination of the ecliptic of date on that
  of J2000), ``p_A = −atan2(R₀₁ − R₁₀, R₀₀ + R₁₁)``, which needs no node (it is regular at
  ``π_A = 0``), unwrapped along the history and zero at J2000. It is the accumulated motion of
  the equinox along the moving ecliptic, IAU 2006's ``p_A`` (5028.796195″/cy);
* the **longitude of perihelion** ``ϖ`` (heliocentric, from the moving equinox along the
  orbit of date, as in Laskar et al. 2004 and Berger & Loutre 1991: ``ϖ ≈ 102.9°`` at J2000):
  ``ϖ = atan2(ê·(n×γ), ê·γ)``, ``ê`` the unit vector to perihelion; the **climatic
  precession** is ``e sin ϖ`` (≈ +0.0163 at J2000).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field, replace

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._validation import as_finite, as_vectors
from andoyer.planetary.orbits.protocol import OrbitHistory
from andoyer.planetary.spin_axis.insolation import daily_insolation
from andoyer.planetary.spin_axis.model import ARCSEC, DEFAULT_PRECESSION_RATE, SpinAxisModel
from andoyer.planetary.spin_axis.stepping import rotate_stages, stage_times

__all__ = [
    "EPSILON_0",
    "SpinAxisHistory",
    "build_model",
    "equinox",
    "evolve_axes",
    "general_precession",
    "integrate_axis",
    "integrate_axis_dop853",
    "mean_pole_j2000",
    "output_times",
]

Array = NDArray[np.float64]

#: IAU 2006 obliquity of the ecliptic at J2000, radians (84381.406″).
EPSILON_0 = 84381.406 * ARCSEC
#: Default largest step (Julian years) of the order-8 composition. Measured against DOP853
#: (rtol 1e-13) on the Earth and the Vondrák ecliptic over ±200 kyr: 7.4e-13 rad at 1000 years
#: (DOP853's own level), 6.7e-12 at 2000. p_A is unwrapped between steps, so a step must stay
#: below half a precession period.
DEFAULT_STEP = 1000.0
#: Largest turn of the axis about the orbit normal in one step (turns): a faster precession
#: shortens the step to fit. Measured against DOP853 (rtol 1e-13, Vondrák ecliptic, order 8):
#: at 1/16 turn per step the error is 1.1e-12 rad at 50″/yr, 1.9e-12 at 500″/yr and 1.9e-12
#: at 5000″/yr (DOP853's own level there; the Earth's default, 1000 years, is 1/26 turn);
#: at 1/4 turn it grows to 3e-8 rad. p_A, unwrapped between steps, needs less than 1/2 turn.
MAX_TURN_PER_STEP = 1.0 / 16.0


def mean_pole_j2000() -> Array:
    """The IAU 2006 mean celestial pole of J2000 in the J2000 ecliptic frame, ``(0, sin ε₀, cos ε₀)``.

    Returns
    -------
    numpy.ndarray, shape (3,)

    Examples
    --------
    >>> np.round(mean_pole_j2000(), 6).tolist()
    [0.0, 0.397777, 0.917482]
    """
    return np.array([0.0, np.sin(EPSILON_0), np.cos(EPSILON_0)])


def output_times(t0: float, t1: float, dt: float) -> Array:
    """``t0, t0 + dt, …`` up to ``t1`` (included when it falls on the grid, to 1e-9 steps).

    Parameters
    ----------
    t0, t1, dt : float
        Julian years; ``dt > 0``, ``t1 ≥ t0``.

    Returns
    -------
    numpy.ndarray, shape (N,)

    Examples
    --------
    >>> output_times(-1000.0, 1000.0, 500.0).tolist()
    [-1000.0, -500.0, 0.0, 500.0, 1000.0]
    >>> output_times(0.0, 1.0, 0.0)
    Traceback (most recent call last):
    ...
    ValueError: expected a positive finite output step, got 0.0
    """
    if not (np.isfinite(dt) and dt > 0):
        msg = f"expected a positive finite output step, got {dt!r}"
        raise ValueError(msg)
    if not (np.isfinite(t0) and np.isfinite(t1) and t1 >= t0):
        msg = f"expected a span T0 <= T1 (finite), got {t0!r} to {t1!r}"
        raise ValueError(msg)
    if t1 > t0 and dt > t1 - t0:
        msg = f"expected an output step no longer than the span {t1 - t0!r}, got {dt!r}"
        raise ValueError(msg)
    steps = (t1 - t0) / dt
    if not steps < 1e7:  # also catches an overflow to inf
        msg = f"expected at most 10 million output times, got {steps:.3g}"
        raise ValueError(msg)
    count = int(np.floor(steps + 1e-9)) + 1
    return t0 + dt * np.arange(count)


def equinox(s: ArrayLike, n: ArrayLike) -> Array:
    """Unit vector to the equinox of date, ``γ = s×n/|s×n|``, shape (..., 3).

    Parameters
    ----------
    s, n : array_like, shape (..., 3)
        Unit spin axis and orbit normal.

    Returns
    -------
    numpy.ndarray, shape (..., 3)

    Examples
    --------
    >>> equinox(mean_pole_j2000(), [0.0, 0.0, 1.0]).tolist()
    [1.0, 0.0, 0.0]
    """
    g = np.cross(as_finite(s, "s"), as_finite(n, "n"))
    size = np.linalg.norm(g, axis=-1, keepdims=True)
    if np.any(size == 0):
        msg = "expected a spin axis off the orbit normal (the equinox is s × n), got s parallel to n"
        raise ValueError(msg)
    return g / size


def _frames(s: Array, n: Array) -> Array:
    g = equinox(s, n)
    n = np.broadcast_to(n, g.shape)
    return np.stack([g, np.cross(n, g), n], axis=-2)


def general_precession(s: ArrayLike, n: ArrayLike, s0: ArrayLike, n0: ArrayLike) -> Array:
    """``p_A`` (radians, wrapped to (−π, π]) of the frames of date against the frame of ``(s0, n0)``.

    Parameters
    ----------
    s, n : array_like, shape (..., 3)
    s0 : array_like, shape (3,) or (M, 3)
        Axis at J2000 (one per run when ``s`` has shape (M, K, 3)).
    n0 : array_like, shape (3,)
        Orbit normal at J2000.

    Returns
    -------
    numpy.ndarray, shape (...)

    Examples
    --------
    The IAU 2006 frame of date one century after J2000 (pyerfa): ``p_A`` = 5028.796″ + 1.105″.

    >>> import erfa
    >>> rb, rp, rbp = erfa.bp06(2451545.0, 36525.0)
    >>> c, s = np.cos(EPSILON_0), np.sin(EPSILON_0)
    >>> ecl = np.array([[1, 0, 0], [0, c, s], [0, -s, c]])  # J2000 equator -> ecliptic
    >>> pole = ecl @ rp[2]  # mean pole of date, J2000 ecliptic frame
    >>> eps_a = erfa.obl06(2451545.0, 36525.0)
    >>> normal = ecl @ erfa.ecm06(2451545.0, 36525.0)[2] @ rb.T  # ecliptic pole of date
    >>> p = general_precession(pole, normal, mean_pole_j2000(), [0, 0, 1])
    >>> round(float(p / ARCSEC), 3)
    5029.9
    """
    start = _frames(as_finite(s0, "s0"), as_finite(n0, "n0"))
    if start.ndim == 3:  # one J2000 frame per run (M, 3, 3), against dates (M, K, 3, 3)
        start = start[:, None]
    r = _frames(as_finite(s, "s"), as_finite(n, "n")) @ np.swapaxes(start, -1, -2)
    return -np.arctan2(r[..., 0, 1] - r[..., 1, 0], r[..., 0, 0] + r[..., 1, 1])


def _segments(knots: Array, step: float) -> tuple[Array, Array, Array]:
    """Steps from ``knots[0]`` through every knot: starts, sizes, and each knot's step index."""
    gaps = np.diff(knots)
    counts = np.maximum(np.ceil(np.abs(gaps) / step - 1e-12).astype(np.int64), 1)
    sizes = np.repeat(gaps / counts, counts)
    ends = np.cumsum(counts)
    within = np.arange(counts.sum()) - np.repeat(ends - counts, counts)
    starts = np.repeat(knots[:-1], counts) + within * sizes
    return starts, sizes, ends - 1


def _alpha(orbit: OrbitHistory, model: SpinAxisModel | Sequence[SpinAxisModel], t: Array, runs: int) -> Array:
    """``α`` of every run at the times ``t`` (the orbit's eccentricity where it knows it), shape (M, T)."""
    e = np.linalg.norm(orbit.eccentricity_vector(t), axis=-1) if orbit.has_eccentricity else None
    if isinstance(model, SpinAxisModel):
        return np.broadcast_to(model.rate(t, e), (runs, t.size))
    return np.stack([m.rate(t, e) for m in model])


def _largest_step(
    orbit: OrbitHistory, model: SpinAxisModel | Sequence[SpinAxisModel], times: Array, runs: int, step: float
) -> float:
    """``step``, shortened where ``α`` would turn the axis by more than :data:`MAX_TURN_PER_STEP`.

    The axis turns about ``n`` at ``α (s·n) ≤ α``; ``α`` is sampled at the middle of every step
    of ``step`` (it changes over the orbit's and the tides' slow times, not within a step).
    """
    knots = np.concatenate([[0.0], times])
    starts, sizes, _ = _segments(np.sort(knots), step)
    alpha = float(np.max(np.abs(_alpha(orbit, model, starts + 0.5 * sizes, runs)), initial=0.0))
    most = 2 * np.pi * MAX_TURN_PER_STEP / alpha if alpha > 0 else np.inf
    return min(step, most)


def integrate_axis(
    orbit: OrbitHistory,
    model: SpinAxisModel | Sequence[SpinAxisModel],
    times: Array,
    s0: Array,
    step: float = DEFAULT_STEP,
    order: int = 8,
) -> tuple[Array, Array, Array]:
    """Integrate ``s`` from ``s0`` at ``t = 0`` to ``times`` (both ways), densely in steps ≤ ``step``.

    Parameters
    ----------
    orbit : OrbitHistory
    model : SpinAxisModel or sequence of M of them
        One model for every run, or one per run.
    times : ndarray, shape (N,)
        Increasing output times (years from J2000).
    s0 : ndarray, shape (M, 3)
        Unit axes at J2000 (``M`` runs sharing the orbit).
    step : float
        Largest step, years (taken as it is: :func:`evolve_axes` shortens it where the axis
        would turn by more than :data:`MAX_TURN_PER_STEP` in one).
    order : {2, 4, 6, 8}

    Returns
    -------
    grid : ndarray, shape (K,)
        Every step's end time, increasing (includes 0 and ``times``).
    axes : ndarray, shape (M, K, 3)
    index : ndarray, shape (N,)
        Position of each output time in ``grid``.
    """
    if not (np.isfinite(step) and step > 0):
        msg = f"expected a positive finite integration step in years, got {step!r}"
        raise ValueError(msg)
    chains = []
    for side in (times[times > 0], times[times < 0][::-1]):
        if side.size == 0:
            chains.append((np.zeros(0), np.zeros((len(s0), 0, 3)), np.zeros(0, dtype=np.int64)))
            continue
        starts, sizes, at = _segments(np.concatenate([[0.0], side]), step)
        mid, dur = stage_times(starts, sizes, order)
        normals = np.ascontiguousarray(orbit.normal(mid))
        alpha = _alpha(orbit, model, mid, len(s0))
        out = np.empty((len(s0), len(starts), 3))
        stages = len(dur) // len(starts)
        rotate_stages(np.ascontiguousarray(s0), normals, np.ascontiguousarray(alpha), dur, stages, out)
        ends = starts + sizes
        ends[at] = side  # a segment's equal steps end on its knot, exactly
        chains.append((ends, out, at))
    (tf, sf, af), (tb, sb, ab) = chains
    grid = np.concatenate([tb[::-1], [0.0], tf])
    axes = np.concatenate([sb[:, ::-1], s0[:, None, :], sf], axis=1)
    nb = len(tb)
    index = np.concatenate([(nb - 1 - ab)[::-1], np.full(np.count_nonzero(times == 0), nb), nb + 1 + af])
    return grid, axes, index


@dataclass(frozen=True)
class SpinAxisHistory:
    """The spin axis of a planet along a moving orbit, at the output times.

    Attributes
    ----------
    t : ndarray, shape (N,)
        Julian years from J2000.
    axis : ndarray, shape (N, 3)
        Unit spin axis ``s``, J2000 ecliptic frame.
    orbit_normal : ndarray, shape (N, 3)
        Unit orbit normal ``n``.
    obliquity : ndarray, shape (N,)
        ``ε`` (radians).
    precession : ndarray, shape (N,)
        ``p_A`` (radians, accumulated since J2000).
    eccentricity : ndarray, shape (N,), or None
    perihelion : ndarray, shape (N,), or None
        ``ϖ`` (radians, in [0, 2π)), heliocentric, from the moving equinox.
    precession_rate : float
        ``ψ̇`` at J2000 used, ″/yr.
    model : SpinAxisModel
    orbit_name : str
    largest_turn : float
        The largest angle (radians) by which ``p_A`` or ``ϖ`` turns between two consecutive
        output times, measured on the integration grid: from ``π`` on, the outputs undersample
        the precession (Nyquist) and a table or a picture of them aliases it.
    """

    t: Array
    axis: Array
    orbit_normal: Array
    obliquity: Array
    precession: Array
    eccentricity: Array | None
    perihelion: Array | None
    precession_rate: float
    model: SpinAxisModel
    orbit_name: str = field(default="")
    largest_turn: float = 0.0

    @property
    def climatic_precession(self) -> Array | None:
        """``e sin ϖ``, shape (N,), or None without an eccentricity."""
        if self.eccentricity is None or self.perihelion is None:
            return None
        return self.eccentricity * np.sin(self.perihelion)

    def insolation(self, latitude: float, solar_longitude: float, solar_constant: float = 1361.0) -> Array:
        """Daily-mean insolation (W/m²) at ``latitude`` and true solar longitude (radians), shape (N,).

        See :func:`andoyer.planetary.spin_axis.daily_insolation` (needs the eccentricity).

        Parameters
        ----------
        latitude, solar_longitude : float
            Radians (``solar_longitude = π/2``: the northern summer solstice).
        solar_constant : float
            W/m² at 1 au (1361, Kopp & Lean 2011).

        Returns
        -------
        numpy.ndarray, shape (N,)
        """
        if self.eccentricity is None or self.perihelion is None:
            msg = f"expected an orbit source with the eccentricity for insolation, got {self.orbit_name}"
            raise ValueError(msg)
        return daily_insolation(
            latitude, solar_longitude, self.obliquity, self.eccentricity, self.perihelion, solar_constant
        )


def describe_orbit(
    orbit: OrbitHistory, t: Array, s: Array
) -> tuple[Array, Array, Array | None, Array | None]:
    """Orbit normal, obliquity, and (where known) eccentricity and ``ϖ`` along ``(t, s)``."""
    n = orbit.normal(t)
    obliquity = np.arctan2(np.linalg.norm(np.cross(s, n), axis=-1), np.sum(s * n, axis=-1))
    if not orbit.has_eccentricity:
        return n, obliquity, None, None
    ev = orbit.eccentricity_vector(t)
    e = np.linalg.norm(ev, axis=-1)
    g = equinox(s, n)
    perihelion = np.mod(np.arctan2(np.sum(ev * np.cross(n, g), -1), np.sum(ev * g, -1)), 2 * np.pi)
    return n, obliquity, e, perihelion


def history(
    orbit: OrbitHistory,
    model: SpinAxisModel,
    times: Array,
    s0: Array,
    step: float = DEFAULT_STEP,
    order: int = 8,
) -> SpinAxisHistory:
    """Integrate and describe (the work of :func:`andoyer.planetary.spin_axis.spin_axis_history`)."""
    s0 = as_vectors(s0, "initial axis")
    s0 = s0 / np.linalg.norm(s0)
    grid, axes, p, index = _evolve(orbit, model, times, s0, step, order)
    s = axes[0, index]
    n0 = orbit.normal(0.0)
    n, obliquity, e, perihelion = describe_orbit(orbit, times, s)
    e0 = np.linalg.norm(orbit.eccentricity_vector(0.0)) if orbit.has_eccentricity else None
    eps0 = float(np.arctan2(np.linalg.norm(np.cross(s0, n0)), s0 @ n0))
    turns = [p[0]]
    if orbit.has_eccentricity:  # ϖ from the moving equinox, on the grid
        turns.append(np.unwrap(describe_orbit(orbit, grid, axes[0])[3]))
    largest = max(float(np.max(np.abs(np.diff(angle[index])), initial=0.0)) for angle in turns)
    return SpinAxisHistory(
        times,
        s,
        n,
        obliquity,
        p[0, index],
        e,
        perihelion,
        model.precession_rate(eps0, e0),
        model,
        orbit.name,
        largest,
    )


def _evolve(
    orbit: OrbitHistory,
    model: SpinAxisModel | Sequence[SpinAxisModel],
    times: Array,
    s0: Array,
    step: float,
    order: int,
) -> tuple[Array, Array, Array, Array]:
    """:func:`evolve_axes` on the whole integration grid: the grid, the axes, ``p_A`` and ``index``.

    Shapes (K,), (M, K, 3), (M, K) and (N,): ``index`` gives the outputs' places in the grid.
    """
    times = as_finite(times, "times")
    runs = 1 if isinstance(model, SpinAxisModel) else len(model)
    s0 = np.broadcast_to(as_finite(s0, "s0"), (runs, 3)) if np.ndim(s0) == 1 else np.asarray(s0)
    s0 = np.ascontiguousarray(s0, dtype=float)
    if not (np.isfinite(step) and step > 0):
        msg = f"expected a positive finite integration step in years, got {step!r}"
        raise ValueError(msg)
    step = _largest_step(orbit, model, times, runs, step)
    grid, axes, index = integrate_axis(orbit, model, times, s0, step, order)
    p = np.unwrap(general_precession(axes, orbit.normal(grid), s0, orbit.normal(0.0)), axis=-1)
    p = p - p[:, np.searchsorted(grid, 0.0)][:, None]
    return grid, axes, p, index


def evolve_axes(
    orbit: OrbitHistory,
    model: SpinAxisModel | Sequence[SpinAxisModel],
    times: Array,
    s0: Array,
    step: float = DEFAULT_STEP,
    order: int = 8,
) -> tuple[Array, Array]:
    """Axes and general precession ``p_A`` of ``M`` runs from one J2000 axis at ``times``.

    Parameters
    ----------
    orbit : OrbitHistory
    model : SpinAxisModel or sequence of M of them
    times : ndarray, shape (N,)
    s0 : ndarray, shape (3,) or (M, 3)
        Unit axis at J2000 (shared, or one per run).
    step : float
        Largest step, years, shortened where the axis would turn by more than
        :data:`MAX_TURN_PER_STEP` in one (the unwrapping of ``p_A`` needs less than half a turn).
    order : {2, 4, 6, 8}

    Returns
    -------
    axes : ndarray, shape (M, N, 3)
    precession : ndarray, shape (M, N)
        ``p_A`` (radians), unwrapped between integration steps, zero at J2000.
    """
    _, axes, p, index = _evolve(orbit, model, times, s0, step, order)
    return axes[:, index], p[:, index]


def build_model(
    orbit: OrbitHistory,
    body: str,
    s0: Array,
    precession_rate: float | None = None,
    dynamical_ellipticity: float | None = None,
    tidal_dissipation: float = 0.0,
    ellipticity_drift: float = 0.0,
) -> SpinAxisModel:
    """The model of ``body`` on ``orbit`` from a precession rate (default) or an ellipticity.

    The precession rate (″/yr, ``ψ̇`` at J2000; default ``DEFAULT_PRECESSION_RATE[body]``) is
    matched with the obliquity ``∠(s0, n(0))`` and the orbit's ``e(0)`` where it knows it.

    Parameters
    ----------
    orbit : OrbitHistory
    body : str
    s0 : ndarray, shape (3,)
        Unit axis at J2000.
    precession_rate, dynamical_ellipticity : float, optional
        At most one.
    tidal_dissipation, ellipticity_drift : float

    Returns
    -------
    SpinAxisModel
    """
    if precession_rate is not None and dynamical_ellipticity is not None:
        msg = "expected a precession rate or a dynamical ellipticity, got both"
        raise ValueError(msg)
    e0 = float(np.linalg.norm(orbit.eccentricity_vector(0.0))) if orbit.has_eccentricity else None
    if dynamical_ellipticity is not None:
        model = SpinAxisModel.from_dynamical_ellipticity(
            body, dynamical_ellipticity, tidal_dissipation, ellipticity_drift
        )
        return model if e0 is None else replace(model, eccentricity=e0)
    rate = precession_rate
    if rate is None:
        rate = DEFAULT_PRECESSION_RATE.get(str(body).strip().lower(), np.nan)
    n0 = orbit.normal(0.0)
    eps0 = float(np.arctan2(np.linalg.norm(np.cross(s0, n0)), s0 @ n0))
    return SpinAxisModel.from_precession_rate(body, rate, eps0, e0, tidal_dissipation, ellipticity_drift)


def integrate_axis_dop853(
    orbit: OrbitHistory, model: SpinAxisModel, times: Array, s0: Array, rtol: float = 1e-13
) -> Array:
    """The reference: scipy's DOP853 on ``ṡ = α (s·n)(s×n)`` from ``s0`` at J2000, shape (N, 3).

    The orbit is evaluated at every right-hand-side call (scalar time). For comparisons and
    benchmarks; :func:`integrate_axis` is the production path.

    Parameters
    ----------
    orbit : OrbitHistory
    model : SpinAxisModel
    times : ndarray, shape (N,)
        Increasing output times (years from J2000).
    s0 : ndarray, shape (3,)
    rtol : float
        DOP853's relative tolerance (``atol = rtol``: ``|s| = 1``).

    Returns
    -------
    numpy.ndarray, shape (N, 3)
    """
    from scipy.integrate import solve_ivp

    def rhs(t: float, s: Array) -> Array:
        n = orbit.normal(t)
        e = np.linalg.norm(orbit.eccentricity_vector(t)) if orbit.has_eccentricity else None
        return model.rate(t, e) * (s @ n) * np.cross(s, n)

    out = np.empty((len(times), 3))
    for side in (times >= 0, times < 0):
        targets = times[side]
        if targets.size == 0:
            continue
        order = np.argsort(np.abs(targets))
        end = float(targets[order[-1]])
        if end == 0.0:
            out[side] = s0
            continue
        sol = solve_ivp(
            rhs, (0.0, end), s0, method="DOP853", t_eval=targets[order], rtol=rtol, atol=rtol
        )
        values = np.empty((targets.size, 3))
        values[order] = sol.y.T
        out[side] = values
    return out
