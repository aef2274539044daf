"""The numeric nutation: the spin-averaged torque integrated with RK4, the mean pole removed.

``ṁ = (3H/ω)(S m) × m + p ẑ × m`` in the frame of date (see the package
docstring), ``S`` tabulated on a half-step grid, RK4 at a quarter day in plain
floats, from the forced state at the start; the axes from
``m + c m × ṁ + d m̈⊥``.

**Memory.** The quarter-day grid of a long span is large (1461 points a year): it is never
held. The integration runs :data:`BLOCK_STEPS` steps at a time (the torque tabulated, the
axis described, the fit's rows added to a running QR factorisation, the output times within
the block interpolated), so that a run holds one block (about 40 MB) and its outputs, whatever
its span: 1000 years took 4.7 GB when the whole grid was held (issue 26). The outputs are
interpolated by a cubic spline of the grid within :data:`SPLINE_MARGIN` points on either side
(the spline of the whole grid differs from it by ``0.27⁶⁴`` of the values: nothing). The
cost of a request is :func:`nutation_cost`, checked by :func:`nutation` before the work.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._limits import check_size
from andoyer.catalogue.units import DAY, JULIAN_YEAR
from andoyer.perturbations.lunar_theory import (
    check_span,
    delaunay_arguments,
    ecliptic_vector,
    moon_ecliptic,
    sun_ecliptic,
)
from andoyer.perturbations.solar_system import GM_MOON, GM_SUN
from andoyer.planetary.nutation.analytic import NutationSeries, nutation_series
from andoyer.planetary.nutation.fit import _large, _resolved, minimum_span
from andoyer.planetary.nutation.model import (
    ARCSEC,
    EARTH_ROTATION,
    H_MHB2000,
    MEAN_OBLIQUITY,
    _axis,
    _axis_coefficients,
)
from andoyer.planetary.precession import check_dynamical_ellipticity

__all__ = ["BLOCK_STEPS", "SPLINE_MARGIN", "STEP_SECONDS", "nutation", "nutation_cost"]

Array = NDArray[np.float64]

_STEP_DAYS = 0.25
#: RK4 steps integrated at once (a multiple of 8, the sampling of the fits).
BLOCK_STEPS = 2**14
#: Grid points on each side of an output time in the spline that interpolates it.
SPLINE_MARGIN = 64
#: Seconds per RK4 step with its torque (two samples of the lunar theory, 41 µs) and the rest
#: (11 µs of RK4, the axes and the fits): measured 52-60 µs on the shared 2-core machine.
STEP_SECONDS = 6e-5
#: Bytes of one block (the torque tabulated and its Python floats, the lunar theory's arrays,
#: the block's axes and fit rows): measured about 40 MB at 2¹⁴ steps; a bound.
BLOCK_BYTES = 128 * 2**20
#: Bytes per output time: its time, the interpolated angles, their order and the answer.
OUTPUT_BYTES = 96


def _pole(psi: float, eps: float) -> Array:
    h = -np.pi - psi
    return np.array([np.sin(eps) * np.sin(h), -np.sin(eps) * np.cos(h), np.cos(eps)])


def _angles(vectors: Array) -> tuple[Array, Array]:
    """``(ψ, ε)`` of unit vectors (..., 3), ``ψ = −(h + π)`` wrapped to ``(−π, π]``."""
    h = np.arctan2(vectors[..., 0], -vectors[..., 1])
    psi = -np.angle(np.exp(1j * (h + np.pi)))
    eps = np.arctan2(np.hypot(vectors[..., 0], vectors[..., 1]), vectors[..., 2])
    return psi, eps


def _gradient_matrices(t: Array, H: float) -> Array:
    """``(3H/ω) S`` (rad per Julian year), shape (T, 3, 3), in the frame of date."""
    out = np.empty((t.size, 3, 3))
    block = 20000  # the lunar series makes (block, 60) arrays: keep them small
    for start in range(0, t.size, block):
        times = t[start : start + block]
        total = 0.0
        places = ((GM_MOON, moon_ecliptic(times, planetary=False)), (GM_SUN, sun_ecliptic(times)))
        for gm, (lon, lat, r) in places:
            u = ecliptic_vector(lon, lat, np.ones_like(r))
            total = total + (gm / r**3)[:, None, None] * u[:, :, None] * u[:, None, :]
        out[start : start + block] = total
    return 3 * H / EARTH_ROTATION * JULIAN_YEAR * out


def _rk4(S: Array, m0: Array, h: float, p: float) -> Array:
    """RK4 for ``ṁ = (S m) × m + p ẑ × m`` with ``S`` given at half steps (2N+1, 3, 3); returns (N+1, 3)."""
    steps = (S.shape[0] - 1) // 2
    out = np.empty((steps + 1, 3))
    s = S.reshape(S.shape[0], 9).tolist()
    x, y, z = (float(v) for v in m0)
    out[0] = x, y, z

    def rate(k: list[float], x: float, y: float, z: float) -> tuple[float, float, float]:
        a = k[0] * x + k[1] * y + k[2] * z
        b = k[3] * x + k[4] * y + k[5] * z
        c = k[6] * x + k[7] * y + k[8] * z
        return b * z - c * y - p * y, c * x - a * z + p * x, a * y - b * x

    for i in range(steps):
        k0, k1, k2 = s[2 * i], s[2 * i + 1], s[2 * i + 2]
        a1 = rate(k0, x, y, z)
        a2 = rate(k1, x + 0.5 * h * a1[0], y + 0.5 * h * a1[1], z + 0.5 * h * a1[2])
        a3 = rate(k1, x + 0.5 * h * a2[0], y + 0.5 * h * a2[1], z + 0.5 * h * a2[2])
        a4 = rate(k2, x + h * a3[0], y + h * a3[1], z + h * a3[2])
        x += h / 6 * (a1[0] + 2 * a2[0] + 2 * a3[0] + a4[0])
        y += h / 6 * (a1[1] + 2 * a2[1] + 2 * a3[1] + a4[1])
        z += h / 6 * (a1[2] + 2 * a2[2] + 2 * a3[2] + a4[2])
        out[i + 1] = x, y, z
    return out


@dataclass(frozen=True)
class _Integration:
    t: Array  # grid, Julian years
    m: Array  # unit angular momentum (T, 3), frame of date
    mdot: Array  # inertial dm/dt (T, 3), rad per year
    precession: float  # frame rate p, rad per year


@dataclass(frozen=True)
class _Window:
    """One integration window: its grid ``t0 + i h`` (``i = 0 … steps``), start and frame rate."""

    t0: float
    steps: int
    h: float
    H: float
    eps: float
    p: float  # frame rate, rad per year
    start: tuple[float, float]  # (ψ, ε) of m at t0
    series: NutationSeries  # of the momentum axis, at the window's middle

    @property
    def end(self) -> float:
        """The last grid time."""
        return float(self.t0 + 0.5 * self.h * (2 * self.steps))

    def times(self, first: int, stop: int) -> Array:
        """Grid times ``first ≤ i < stop`` (the even points of the half-step grid, as tabulated)."""
        return self.t0 + 0.5 * self.h * np.arange(2 * first, 2 * stop, 2)


def _steps(t0: float, end: float) -> tuple[int, float]:
    h = _STEP_DAYS * DAY / JULIAN_YEAR
    return max(math.ceil((end - t0) / h), 1), h


def _window(t0: float, end: float, H: float, eps: float) -> _Window:
    """The window ``[t0, end]``, started from the forced state of the analytic series at ``t0``.

    The start sets only the free constants (where the mean pole lies); the analytic series
    supplies them, which spares a second pass.
    """
    steps, h = _steps(t0, end)
    series = nutation_series(H, "momentum", 0.5 * (t0 + end), eps)
    dpsi0, deps0 = series(t0)
    start = (float(dpsi0) * ARCSEC, eps + float(deps0) * ARCSEC)
    return _Window(t0, steps, h, H, eps, series.precession * ARCSEC, start, series)


def _sweep(w: _Window) -> Iterator[tuple[int, Array, Array, Array]]:
    """``(first, t, m, mdot)`` of the grid, a block of :data:`BLOCK_STEPS` steps at a time, in order."""
    m0 = _pole(*w.start)
    for k0 in range(0, w.steps, BLOCK_STEPS):
        k1 = min(k0 + BLOCK_STEPS, w.steps)
        half = w.t0 + 0.5 * w.h * np.arange(2 * k0, 2 * k1 + 1)
        S = _gradient_matrices(half, w.H)
        m = _rk4(S, m0, w.h, w.p)
        mdot = np.cross(np.einsum("tij,tj->ti", S[::2], m), m)
        m0 = m[-1]
        skip = 1 if k0 else 0  # a block's first point is the one before's last
        yield k0 + skip, half[::2][skip:], m[skip:], mdot[skip:]


def _axis_vectors(run: _Integration, axis: str, H: float) -> Array:
    c, d = _axis_coefficients(axis, H)
    vectors = run.m + c * np.cross(run.m, run.mdot)
    if d:
        # m̈ by central differences of the torque's ṁ on the quarter-day grid (its own error is
        # (hσ)²/6 ≈ 1 % of a term that is itself 0.5 mas at 13.66 days).
        mdd = np.gradient(run.mdot, run.t, axis=0)
        vectors += d * (mdd - run.m * np.sum(run.m * mdd, axis=-1, keepdims=True))
    return vectors / np.linalg.norm(vectors, axis=-1, keepdims=True)


def _angle_blocks(w: _Window, axis: str) -> Iterator[tuple[int, Array, Array, Array]]:
    """``(first, t, ψ, ε)`` of ``axis`` on the grid, block by block (:func:`_axis_vectors` of each).

    ``m̈`` (the figure axis) takes central differences, so a block's last point waits for the
    next block: each window holds the point before it (already given) and that one.
    """
    held = None  # (first, t, m, mdot) of the last two points of the window before
    for start, *new in _sweep(w):
        last = start + new[0].size == w.steps + 1
        first = start if held is None else held[0]
        before = [np.zeros((0, *a.shape[1:])) for a in new] if held is None else held[1:]
        t, m, mdot = (np.concatenate([a, b]) for a, b in zip(before, new, strict=True))
        vectors = _axis_vectors(_Integration(t, m, mdot, w.p), axis, w.H)
        given = 1 if held is not None else 0
        stop = t.size if last else t.size - 1
        if stop > given:
            psi, eps = _angles(vectors[given:stop])
            yield first + given, t[given:stop], psi, eps
        held = (first + t.size - 2, t[-2:], m[-2:], mdot[-2:])


class _LeastSquares:
    """Least squares ``X c ≈ Y`` from rows given a block at a time: a running QR factorisation."""

    def __init__(self, columns: int, values: int) -> None:
        self.columns = columns
        self.r = np.zeros((0, columns + values))
        self.rows = 0

    def add(self, X: Array, Y: Array) -> None:
        self.rows += X.shape[0]
        self.r = np.linalg.qr(np.vstack([self.r, np.hstack([X, Y])]), mode="r")

    def solve(self) -> Array:
        """``c`` (columns, values): the least-squares solution (``numpy.linalg.lstsq`` on ``R``)."""
        p = self.columns
        r = self.r[:p]
        # the cutoff lstsq would apply to the whole design (its largest dimension is the rows')
        cutoff = np.finfo(float).eps * max(self.rows, p)
        return np.linalg.lstsq(r[:, :p], r[:, p:], rcond=cutoff)[0]


class _Spline:
    """Cubic-spline values at ``times`` of grid values arriving in order, a window at a time.

    An output time is answered once :data:`SPLINE_MARGIN` grid points follow it, from the not-a-knot
    spline of the grid from ``SPLINE_MARGIN`` points before it on (or from the grid's start).
    """

    def __init__(self, times: Array) -> None:
        self.order = np.argsort(times, kind="stable")
        self.sorted = times[self.order]
        self.values = np.empty((times.size, 2))
        self.done = 0  # outputs answered, in sorted order
        self.t = np.zeros(0)
        self.v = np.zeros((0, 2))

    def add(self, t: Array, v: Array, last: bool) -> None:
        from scipy.interpolate import CubicSpline

        self.t = np.concatenate([self.t, t])
        self.v = np.concatenate([self.v, v])
        if last:
            ready = self.sorted.size
        elif self.t.size > SPLINE_MARGIN:
            ready = int(np.searchsorted(self.sorted, self.t[-1 - SPLINE_MARGIN], "right"))
        else:
            ready = self.done
        if ready > self.done:
            knot = int(np.searchsorted(self.t, self.sorted[self.done], "right")) - 1
            begin = max(knot - SPLINE_MARGIN, 0)
            spline = CubicSpline(self.t[begin:], self.v[begin:])
            self.values[self.done : ready] = spline(self.sorted[self.done : ready])
            self.done = ready
        if self.done < self.sorted.size:  # keep what the next outputs need
            knot = int(np.searchsorted(self.t, self.sorted[self.done], "right")) - 1
            keep = max(knot - SPLINE_MARGIN, 0)
            self.t, self.v = self.t[keep:], self.v[keep:]
        else:
            self.t, self.v = self.t[-1:], self.v[-1:]

    def result(self) -> Array:
        out = np.empty_like(self.values)
        out[self.order] = self.values
        return out


def _mean_pole_terms(w: _Window) -> Array:
    """The terms fitted with the mean pole (a constant and a drift): those the window resolves."""
    return _resolved(_large(w.series), w.end - w.t0, 0.5 * (w.t0 + w.end))


def _design(t: Array, t0: float, n: Array) -> Array:
    theta = delaunay_arguments(t) @ n.T
    return np.concatenate([np.ones((t.size, 1)), (t - t0)[:, None], np.sin(theta), np.cos(theta)], 1)


def _residuals_at(times: Array, w: _Window, axis: str) -> tuple[Array, Array]:
    """``Δψ, Δε`` (arcsec) of ``axis`` at ``times``: the angles minus their mean pole (constant + trend).

    The mean pole is fitted with the resolved periodic terms on every eighth grid point.
    """
    n = _mean_pole_terms(w)
    fit = _LeastSquares(2 + 2 * n.shape[0], 2)
    spline = _Spline(times)
    for first, t, psi, eps in _angle_blocks(w, axis):
        rows = np.flatnonzero((first + np.arange(t.size)) % 8 == 0)
        fit.add(_design(t[rows], w.t0, n), np.stack([psi[rows], eps[rows]], -1))
        spline.add(t, np.stack([psi, eps], -1), first + t.size == w.steps + 1)
    coefficients = fit.solve()
    values = spline.result()
    trend = coefficients[0] + (times - w.t0)[:, None] * coefficients[1]
    residual = (values - trend) / ARCSEC
    return residual[:, 0], residual[:, 1]


def _integrate(t0: float, t1: float, H: float, p: float, start: tuple[float, float]) -> _Integration:
    """The whole grid of one integration from ``start`` (for tests and benchmarks: it holds every point)."""
    steps, h = _steps(t0, t1)
    w = _Window(t0, steps, h, H, 0.0, p, start, None)  # type: ignore[arg-type]
    parts = list(_sweep(w))
    t, m, mdot = (np.concatenate([part[k] for part in parts]) for k in (1, 2, 3))
    return _Integration(t, m, mdot, p)


def _window_run(t0: float, end: float, H: float, eps: float) -> tuple[_Integration, NutationSeries]:
    """The whole grid of the window ``[t0, end]`` and its series (for benchmarks: it holds every point)."""
    w = _window(t0, end, H, eps)
    return _integrate(t0, end, H, w.p, w.start), w.series


def nutation_cost(t: ArrayLike, method: str = "numeric", passes: int = 1) -> tuple[float, float]:
    """Seconds and bytes of :func:`nutation` at times ``t``, known before the work.

    ``numeric``: the RK4 steps of the window (at least :func:`minimum_span`; :data:`STEP_SECONDS`
    each), one block (:data:`BLOCK_BYTES`) and :data:`OUTPUT_BYTES` per output time;
    ``analytic``: the series' terms at every time, a block of times at a time.

    Parameters
    ----------
    t : array_like, shape (T,)
        Julian years TT from J2000.
    method : {"numeric", "analytic"}
    passes : int
        Integrations of the window (the command line's ``--terms`` fits the terms in a second).

    Returns
    -------
    seconds, nbytes : float

    Examples
    --------
    >>> seconds, nbytes = nutation_cost([0.0, 1000.0])
    >>> round(seconds), round(nbytes / 2**20)  # 1.46 million steps of 60 µs; one block
    (88, 128)
    """
    times = np.asarray(t, dtype=float).ravel()
    if not np.all(np.isfinite(times)):
        msg = "expected finite times, got NaN or infinity"
        raise ValueError(msg)
    if method not in ("numeric", "analytic"):
        msg = f"expected method 'numeric' or 'analytic', got {method!r}"
        raise ValueError(msg)
    if times.size == 0:
        return 0.0, 0.0
    outputs = times.size * OUTPUT_BYTES
    if method == "analytic":
        return times.size * 2e-5, outputs + BLOCK_BYTES
    t0, t1 = float(times.min()), float(times.max())
    steps = _steps(t0, max(t1, t0 + minimum_span() * 1.001))[0]
    return passes * steps * STEP_SECONDS, outputs + BLOCK_BYTES


def nutation(
    t: ArrayLike,
    dynamical_ellipticity: float = H_MHB2000,
    axis: str = "figure",
    method: str = "numeric",
    obliquity: float = MEAN_OBLIQUITY,
) -> tuple[Array, Array]:
    """The rigid-Earth luni-solar nutation ``Δψ, Δε`` (arcsec) at times ``t``.

    Parameters
    ----------
    t : array_like, shape (T,)
        Julian years TT from J2000 (any order; one value is fine).
    dynamical_ellipticity : float
        ``H = (C − (A+B)/2)/C``, ``0 < H < 1/2``.
    axis : {"figure", "momentum", "rotation"}
    method : {"numeric", "analytic"}
        ``"numeric"`` integrates the torque over ``[min t, max t]`` (at least
        :func:`minimum_span` of the principal terms, so that the mean pole can
        be separated); ``"analytic"`` sums :func:`nutation_series`.
    obliquity : float
        Mean obliquity ``ε₀``, radians.

    Returns
    -------
    dpsi, deps : numpy.ndarray, shape (T,)

    Raises
    ------
    ValueError
        For bad arguments, and for a request that cannot fit in memory or time
        (:func:`nutation_cost`, :func:`andoyer._limits.check_size`): the integration's
        memory does not grow with the span, its time does (about 90 s per thousand years).

    Examples
    --------
    >>> dpsi, deps = nutation([0.0, 0.5], method="analytic")
    >>> dpsi.round(3).tolist(), deps.round(3).tolist()  # IAU 2000A at J2000: -13.932, -5.769
    ([-13.98, -15.193], [-5.794, -4.517])
    """
    H = check_dynamical_ellipticity(dynamical_ellipticity)
    key = _axis(axis)
    times = np.atleast_1d(np.asarray(t, dtype=float))
    if times.ndim != 1 or times.size == 0 or not np.all(np.isfinite(times)):
        msg = f"expected finite times (T,), got shape {np.shape(t)}"
        raise ValueError(msg)
    check_span(float(times.min()), float(times.max()))  # the user's times, before any epoch of theirs
    if method not in ("numeric", "analytic"):
        msg = f"expected method 'numeric' or 'analytic', got {method!r}"
        raise ValueError(msg)
    seconds, nbytes = nutation_cost(times, method)
    check_size(f"a nutation run at {times.size} times", nbytes=nbytes, seconds=seconds)
    if method == "analytic":
        series = nutation_series(H, key, float(np.mean(times)), obliquity)
        return series(times)
    t0, t1 = float(times.min()), float(times.max())
    w = _window(t0, max(t1, t0 + minimum_span() * 1.001), H, float(obliquity))
    return _residuals_at(times, w, key)
