"""The numeric nutation: the spin-averaged torque integrated with RK4, the mean pole removed.

``ṁ = (3H/ω)(S m) × m + p ẑ × m`` in the frame of date (see the package
docstring), ``S`` tabulated on a half-step grid, RK4 at a quarter day in plain
floats, from the forced state at the start; the axes from
``m + c m × ṁ + d m̈⊥``.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer.perturbations.lunar_theory import (
    check_span,
    delaunay_arguments,
    ecliptic_vector,
    moon_ecliptic,
    sun_ecliptic,
)
from andoyer.perturbations.solar_system import DAY, GM_MOON, GM_SUN, JULIAN_YEAR
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

__all__ = ["nutation"]

Array = NDArray[np.float64]

_STEP_DAYS = 0.25


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


def _integrate(t0: float, t1: float, H: float, p: float, start: tuple[float, float]) -> _Integration:
    h = _STEP_DAYS * DAY / JULIAN_YEAR
    steps = max(int(np.ceil((t1 - t0) / h)), 1)
    half = t0 + 0.5 * h * np.arange(2 * steps + 1)
    S = _gradient_matrices(half, H)
    m = _rk4(S, _pole(*start), h, p)
    Sg = S[::2]
    mdot = np.cross(np.einsum("tij,tj->ti", Sg, m), m)
    return _Integration(half[::2], m, mdot, p)


def _axis_vectors(run: _Integration, axis: str, H: float) -> Array:
    c, d = _axis_coefficients(axis, H)
    vectors = run.m + c * np.cross(run.m, run.mdot)
    if d:
        # m̈ by central differences of the torque's ṁ on the quarter-day grid (its own error is
        # (hσ)²/6 ≈ 1 % of a term that is itself 0.5 mas at 13.66 days).
        mdd = np.gradient(run.mdot, run.t, axis=0)
        vectors += d * (mdd - run.m * np.sum(run.m * mdd, axis=-1, keepdims=True))
    return vectors / np.linalg.norm(vectors, axis=-1, keepdims=True)


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
    if method == "analytic":
        series = nutation_series(H, key, float(np.mean(times)), obliquity)
        return series(times)
    if method != "numeric":
        msg = f"expected method 'numeric' or 'analytic', got {method!r}"
        raise ValueError(msg)
    t0, t1 = float(times.min()), float(times.max())
    grid, dpsi, deps = _window_residuals(t0, max(t1, t0 + minimum_span() * 1.001), H, float(obliquity), key)
    from scipy.interpolate import CubicSpline

    return CubicSpline(grid, dpsi)(times), CubicSpline(grid, deps)(times)


@functools.lru_cache(maxsize=4)
def _window_residuals(t0: float, end: float, H: float, eps: float, axis: str) -> tuple[Array, Array, Array]:
    """The grid and ``Δψ, Δε`` of ``axis`` on it for one integration window (cached with the run)."""
    run, series = _window_run(t0, end, H, eps)
    return (run.t, *_residuals(run, axis, H, series))


def _numeric_run(t0: float, t1: float, H: float, eps: float) -> tuple[_Integration, NutationSeries]:
    """Integrate over ``[t0, max(t1, t0 + span)]`` from the forced state at ``t0`` (mean pole ``ε₀``).

    The start sets only the free constants (where the mean pole lies); the
    analytic series supplies them, which spares a second pass. Runs are cached
    per window, so the series and the terms of one span share one integration.
    """
    return _window_run(t0, max(t1, t0 + minimum_span() * 1.001), H, eps)


@functools.lru_cache(maxsize=2)
def _window_run(t0: float, end: float, H: float, eps: float) -> tuple[_Integration, NutationSeries]:
    series = nutation_series(H, "momentum", 0.5 * (t0 + end), eps)
    dpsi0, deps0 = series(t0)
    start = (float(dpsi0) * ARCSEC, eps + float(deps0) * ARCSEC)
    return _integrate(t0, end, H, series.precession * ARCSEC, start), series


def _residuals(run: _Integration, axis: str, H: float, series: NutationSeries) -> tuple[Array, Array]:
    """``Δψ, Δε`` (arcsec) of ``axis`` on the grid: the angles minus their mean pole (constant + trend)."""
    psi, eps = _angles(_axis_vectors(run, axis, H))
    n = _resolved(_large(series), run.t[-1] - run.t[0], float(run.t.mean()))
    theta = delaunay_arguments(run.t) @ n.T
    dt = run.t - run.t[0]
    design = np.concatenate([np.ones((dt.size, 1)), dt[:, None], np.sin(theta), np.cos(theta)], 1)
    values = np.stack([psi, eps], -1)
    coefficients = np.linalg.lstsq(design[::8], values[::8], rcond=None)[0]
    trend = design[:, :2] @ coefficients[:2]
    return (psi - trend[:, 0]) / ARCSEC, (eps - trend[:, 1]) / ARCSEC
