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

import warnings
from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field, replace

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer import catalogue
from andoyer._limits import ToleranceWarning, caller_stacklevel, check_size
from andoyer._validation import as_finite, as_vectors
from andoyer.catalogue.units import ARCSEC
from andoyer.compositions import COMPOSITIONS
from andoyer.planetary.orbits.protocol import OrbitHistory
from andoyer.planetary.spin_axis.insolation import daily_insolation
from andoyer.planetary.spin_axis.model import DEFAULT_PRECESSION_RATE, SpinAxisModel
from andoyer.planetary.spin_axis.stepping import rotate_on_samples, rotate_stages, stage_times

__all__ = [
    "AXIS_ROW_BYTES",
    "BLOCK_ROWS",
    "BLOCK_STEPS",
    "CONTROL_WINDOW",
    "DEFAULT_TOLERANCE",
    "EPSILON_0",
    "HISTORY_ROW_BYTES",
    "ORBIT_SAMPLE_BYTES",
    "PERIHELION_E_FLOOR",
    "SpinAxisHistory",
    "build_model",
    "check_run",
    "check_tolerance",
    "controlled_outputs",
    "equinox",
    "evolve_axes",
    "general_precession",
    "history_blocks",
    "integrate_axis",
    "integrate_axis_dop853",
    "mean_pole_j2000",
    "orbit_sample_seconds",
    "output_times",
    "resolve_stepping",
    "run_cost",
    "step_count",
]

Array = NDArray[np.float64]

#: IAU 2006 obliquity of the ecliptic at J2000, radians (84381.406″).
EPSILON_0 = catalogue.get("earth").obliquity.si()
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
#: Default accuracy of the axis (radians: 0.01″) of a run given no step: the largest angle between
#: the axis and its converged value over the output times, estimated by step doubling
#: (:func:`controlled_outputs`). The model's own error is far larger: the averaging leaves out the
#: forced nutation (the Earth's largest term, 18.6 years, is 9.205″ in obliquity: IAU 2000A,
#: IERS Conventions 2010, ch. 5), and the N-body orbit's spline its short-period terms (0.2″ for
#: the Earth's normal, 0.3″ for Mars', :mod:`andoyer.planetary.orbits.nbody`).
DEFAULT_TOLERANCE = 0.01 * ARCSEC
#: The smallest tolerance taken, radians: the round-off of the axis over a run. Measured: runs at
#: 1 and 2 years (order 8, Mars on the N-body orbit over 1 Myr, 10⁶ steps) differ by 3e-13 rad.
SMALLEST_TOLERANCE = 1e-12
#: The largest tolerance taken, radians (one degree): an axis known no better is no answer, and
#: the step doubling starts from steps that already meet it.
LARGEST_TOLERANCE = float(np.pi / 180.0)
#: Fraction of the largest eccentricity of a run's outputs below which the perihelion's turn between
#: two outputs is not counted in ``largest_turn``: there ``e sin ϖ`` is below a tenth of its amplitude,
#: and ``ϖ`` turns as fast as ``1/e`` (every output step would alias it as ``e`` passes near zero).
PERIHELION_E_FLOOR = 0.1
#: Years from J2000 over which a tolerance is met by step doubling (:func:`controlled_outputs`): a
#: longer span takes the step chosen over this window. Two Lyapunov times of the inner planets'
#: orbits (about 5 Myr, Laskar 1989) and of Mars' axis in its chaotic zone.
CONTROL_WINDOW = 1.0e7
#: Halvings of the step tried before a tolerance is given up (with a ToleranceWarning):
#: 1000 years down to a quarter of a year.
MAX_HALVINGS = 12


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
    >>> from andoyer.catalogue.units import ARCSEC
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


#: Output times described at once (orbit normal, obliquity, ϖ).
BLOCK_ROWS = 65536
#: Integration steps handled at once (each with its S stages, 15 at order 8): the orbit is
#: sampled and the axis turned a block at a time, so that a run's memory is this block's
#: (about 20 MB at order 8) plus its outputs, whatever its span (issue 26: 10 Gyr at 1000-year
#: steps were 1.5·10⁸ stages held at once, 24 GB).
BLOCK_STEPS = 4096


def _step_counts(knots: Array, step: float, refine: int = 1) -> tuple[Array, Array]:
    """Steps in each gap between successive knots (at least one, at most ``step`` long), and their sum.

    ``refine``: that many times as many steps in every gap (the fine runs of
    :func:`controlled_outputs`).
    """
    counts = np.diff(knots)  # the gaps, turned into counts in place: no temporaries of the knots' size
    np.abs(counts, out=counts)
    counts /= step
    counts -= 1e-12
    np.ceil(counts, out=counts)
    np.maximum(counts, 1.0, out=counts)
    if refine != 1:
        counts *= refine
    if not np.all(counts < 2.0**53):  # an integer count, exactly
        msg = f"expected at most 2^53 integration steps, got {float(np.sum(counts)):.3g}"
        raise ValueError(msg)
    counts = counts.astype(np.int64)
    return counts, np.cumsum(counts)


def step_count(times: ArrayLike, step: float = DEFAULT_STEP) -> int:
    """The integration steps of a run from J2000 to ``times`` (both ways), each at most ``step`` years.

    Every output time ends a step; a gap between two of them (or J2000) longer than ``step``
    is cut into equal steps. This is what a run costs: each step has the composition's
    stages (15 at order 8), one orbit sample each.

    Parameters
    ----------
    times : array_like, shape (N,)
        Increasing output times (Julian years from J2000).
    step : float
        Largest step, years.

    Returns
    -------
    int

    Examples
    --------
    >>> step_count([-2500.0, 0.0, 1000.0, 1500.0])  # 3 steps back, 1 + 1 forward
    5
    """
    t = np.asarray(times, dtype=float).ravel()
    # The gaps of both ways are those between successive times with J2000 among them; a block
    # of them at a time, so that the estimate of a run allocates nothing of the run's size.
    k = int(np.searchsorted(t, 0.0))
    if k == t.size or t[k] != 0.0:
        t = np.concatenate([t[:k], [0.0], t[k:]]) if t.size <= BLOCK_ROWS else _WithZero(t, k)
    total = 0
    for first in range(0, t.size - 1, BLOCK_ROWS):
        total += int(_step_counts(t[first : first + BLOCK_ROWS + 1], step)[1][-1])
    return total


class _WithZero:
    """``t[:k] + [0.0] + t[k:]`` without copying ``t``: slices only."""

    def __init__(self, t: Array, k: int) -> None:
        self.t, self.k, self.size = t, k, t.size + 1

    def __getitem__(self, part: slice) -> Array:
        start, stop = part.start, min(part.stop, self.size)
        pieces = [self.t[start : min(stop, self.k)]]
        if start <= self.k < stop:
            pieces.append(np.zeros(1))
        pieces.append(self.t[max(start, self.k + 1) - 1 : stop - 1])
        return np.concatenate(pieces)


def _step_blocks(knots: Array, step: float, size: int, refine: int = 1):  # type: ignore[no-untyped-def]
    """Steps from ``knots[0]`` through every knot, ``size`` at a time.

    Yields ``(starts, sizes, ends, last)`` for each block: the steps' start times, signed
    sizes and end times (a knot's own value where a step ends on it), and for every step
    the knot it ends on (its index in ``knots``), or ``-1``. The steps of one gap are equal
    (``gap / count``), started at ``knot + j · (gap / count)``.
    """
    gaps = np.diff(knots)
    counts, ends_at = _step_counts(knots, step, refine)
    total = int(ends_at[-1])
    for first in range(0, total, size):
        index = np.arange(first, min(first + size, total))
        gap = np.searchsorted(ends_at, index, side="right")
        sizes = gaps[gap] / counts[gap]
        starts = knots[gap] + (index - (ends_at[gap] - counts[gap])) * sizes
        ends = starts + sizes
        last = np.where(index == ends_at[gap] - 1, gap + 1, -1)
        on_knot = last >= 0
        ends[on_knot] = knots[last[on_knot]]  # a gap's equal steps end on its knot, exactly
        yield starts, sizes, ends, last


def _sweep(orbit, model, knots, s0, step, order, refine=1):  # type: ignore[no-untyped-def]
    """Integrate from ``knots[0]`` (J2000, axes ``s0`` (M, 3)) through ``knots``, a block at a time.

    Yields ``(ends, axes, last)``: the end times of the block's steps, the axes (M, B, 3)
    after each, and the knot each step ends on (or ``-1``), as :func:`_step_blocks`.
    """
    s = np.ascontiguousarray(s0, dtype=float)
    parameters = _run_parameters(model, len(s))
    # an orbit that hands over its samples is interpolated inside the compiled pass (no stage arrays)
    samples = getattr(orbit, "hermite_samples", None) if parameters is not None else None
    gamma = np.ascontiguousarray(COMPOSITIONS[order]) if order in COMPOSITIONS else None
    for starts, sizes, ends, last in _step_blocks(knots, step, BLOCK_STEPS, refine):
        out = np.empty((len(s), len(starts), 3))
        if callable(samples) and gamma is not None:
            rotate_on_samples(s, starts, sizes, gamma, *samples(float(ends[-1])), parameters, out)
        else:
            mid, dur = stage_times(starts, sizes, order)
            normals, e = _normal_and_eccentricity(orbit, mid)
            factor, parameters_or_unit = _rate_terms(orbit, model, mid, len(s), e)
            rotate_stages(s, normals, mid, factor, parameters_or_unit, dur, len(dur) // len(starts), out)
        s = np.ascontiguousarray(out[:, -1])
        yield ends, out, last


def _check_step(step: float) -> None:
    if not (np.isfinite(step) and step > 0):
        msg = f"expected a positive finite integration step in years, got {step!r}"
        raise ValueError(msg)


def _rate_terms(
    orbit: OrbitHistory,
    model: SpinAxisModel | Sequence[SpinAxisModel],
    t: Array,
    runs: int,
    e: Array | None = None,
) -> tuple[Array, Array]:
    """The orbit's factor ``(1 − e²)^{−3/2}`` at ``t``, (T, 1) or (T, M), and the runs' (5, M) parameters.

    The two halves of :meth:`SpinAxisModel.rate` that :func:`rotate_stages` joins: the orbit's
    is computed once for all runs where the orbit knows its eccentricity. A model with another
    ``rate`` gives ``α`` itself (T, M) with the parameters ``(1, 0, 0, 0, 0)``.
    """
    parameters = _run_parameters(model, runs)
    if parameters is None:
        # another law of α (a migrating satellite's): α itself as the per-run factor, unit parameters
        unit = np.zeros((5, runs))
        unit[0] = 1.0
        return np.ascontiguousarray(_alpha(orbit, model, t, runs).T), unit
    models = [model] * runs if isinstance(model, SpinAxisModel) else list(model)
    if orbit.has_eccentricity:
        e = _eccentricity(orbit, t) if e is None else e
        return (((1 - e) * (1 + e)) ** -1.5)[:, None], parameters
    e = np.array([m.eccentricity for m in models], dtype=float)
    return np.broadcast_to(((1 - e) * (1 + e)) ** -1.5, (t.size, runs)), parameters


def _run_parameters(model: SpinAxisModel | Sequence[SpinAxisModel], runs: int) -> Array | None:
    """The runs' (5, M) parameters of :func:`~andoyer.planetary.spin_axis.stepping.stage_rate`.

    ``None`` where a run's ``α`` follows another law (:meth:`SpinAxisModel.rate` overridden).
    """
    models = [model] * runs if isinstance(model, SpinAxisModel) else list(model)
    if any(type(m).rate is not SpinAxisModel.rate for m in models):
        return None
    names = ("alpha_sun", "beta", "tide_spin", "tide_moon", "ellipticity_drift")
    parameters = np.array([[getattr(m, name) for m in models] for name in names], dtype=float)
    return np.ascontiguousarray(parameters.reshape(5, runs))


def _normal_and_eccentricity(orbit: OrbitHistory, t: Array) -> tuple[Array, Array | None]:
    """The normal (contiguous) and ``e`` (or ``None``) at ``t``, in one pass where the orbit offers one."""
    both = getattr(orbit, "normal_and_eccentricity", None)
    if callable(both):
        normal, e = both(t)
        return np.ascontiguousarray(normal), e
    return np.ascontiguousarray(orbit.normal(t)), None


def _eccentricity(orbit: OrbitHistory, t: Array) -> Array:
    """``e`` at ``t``: the orbit's own ``eccentricity`` if it has one (no angles), else the vector's norm."""
    own = getattr(orbit, "eccentricity", None)
    return own(t) if callable(own) else np.linalg.norm(orbit.eccentricity_vector(t), axis=-1)


def _alpha(orbit: OrbitHistory, model: SpinAxisModel | Sequence[SpinAxisModel], t: Array, runs: int) -> Array:
    """``α`` of every run at the times ``t`` (the orbit's eccentricity where it knows it), shape (M, T)."""
    e = _eccentricity(orbit, t) if orbit.has_eccentricity else None
    if isinstance(model, SpinAxisModel):
        return np.broadcast_to(model.rate(t, e), (runs, t.size))
    return np.stack([m.rate(t, e) for m in model])


def _largest_step(
    orbit: OrbitHistory, model: SpinAxisModel | Sequence[SpinAxisModel], times: Array, runs: int, step: float
) -> float:
    """``step``, shortened where ``α`` would turn the axis by more than :data:`MAX_TURN_PER_STEP`.

    The axis turns about ``n`` at ``α (s·n) ≤ α``; ``α`` is sampled at the middle of every step
    of ``step`` (it changes over the orbit's and the tides' slow times, not within a step), a
    block of steps at a time.
    """
    times = np.asarray(times, dtype=float)
    alpha = 0.0
    for side in (times[times > 0], times[times < 0][::-1]):
        if side.size == 0:
            continue
        for starts, sizes, _, _ in _step_blocks(np.concatenate([[0.0], side]), step, BLOCK_STEPS * 16):
            rate = _alpha(orbit, model, starts + 0.5 * sizes, runs)
            alpha = max(alpha, float(np.max(np.abs(rate), initial=0.0)))
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

    Every step's axis is returned (for tests and comparisons); :func:`evolve_axes` keeps
    only the output times, in memory bounded by :data:`BLOCK_STEPS`.

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
    _check_step(step)
    chains = []
    for side in (times[times > 0], times[times < 0][::-1]):
        if side.size == 0:
            chains.append((np.zeros(0), np.zeros((len(s0), 0, 3)), np.zeros(0, dtype=np.int64)))
            continue
        blocks = list(_sweep(orbit, model, np.concatenate([[0.0], side]), s0, step, order))
        ends = np.concatenate([b[0] for b in blocks])
        out = np.concatenate([b[1] for b in blocks], axis=1)
        at = np.flatnonzero(np.concatenate([b[2] for b in blocks]) >= 0)
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
        the precession (Nyquist) and a table or a picture of them aliases it. ``ϖ`` counts only
        between outputs where ``e`` is at least :data:`PERIHELION_E_FLOOR` of its largest value
        over the outputs: near ``e = 0`` the perihelion turns as fast as ``1/e`` (Mars' passes
        close to circular every few Myr), and there the climatic precession ``e sin ϖ`` is below
        a tenth of its amplitude.
    error_estimate : float or None
        The largest error of the axis over the output times (radians) that the step doubling
        of a run chosen from a tolerance estimates (:func:`controlled_outputs`); ``None`` for a
        run at a step given without a tolerance.
    integration_step : float or None
        The largest integration step taken, years.
    order : int or None
        The order of the composition.
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
    error_estimate: float | None = None
    integration_step: float | None = None
    order: int | None = None

    @classmethod
    def concatenate(cls, blocks: Sequence[SpinAxisHistory]) -> SpinAxisHistory:
        """One history from consecutive blocks of it (:func:`history_blocks`).

        Examples
        --------
        >>> from andoyer.planetary.orbits import VondrakEcliptic
        >>> from andoyer.planetary.spin_axis import spin_axis_blocks
        >>> blocks = list(spin_axis_blocks(VondrakEcliptic(), "earth", [-1e3, 0.0, 1e3], rows=2))
        >>> SpinAxisHistory.concatenate(blocks).t.tolist()
        [-1000.0, 0.0, 1000.0]
        """
        first = blocks[0]

        def join(name: str) -> Array | None:
            parts = [getattr(b, name) for b in blocks]
            return None if parts[0] is None else np.concatenate(parts)

        fields = ("t", "axis", "orbit_normal", "obliquity", "precession", "eccentricity", "perihelion")
        return cls(
            *(join(name) for name in fields),
            first.precession_rate,
            first.model,
            first.orbit_name,
            first.largest_turn,
            first.error_estimate,
            first.integration_step,
            first.order,
        )

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
    return n, obliquity, np.linalg.norm(ev, axis=-1), _perihelion(s, n, ev)


def _perihelion(s: Array, n: Array, ev: Array) -> Array:
    """``ϖ`` in [0, 2π) of the eccentricity vectors ``ev`` from the equinox of ``(s, n)``."""
    g = equinox(s, n)
    return np.mod(np.arctan2(np.sum(ev * np.cross(n, g), -1), np.sum(ev * g, -1)), 2 * np.pi)


def history_blocks(
    orbit: OrbitHistory,
    model: SpinAxisModel,
    times: Array,
    s0: Array,
    step: float = DEFAULT_STEP,
    order: int = 8,
    rows: int = BLOCK_ROWS,
    tolerance: float | None = None,
) -> Iterator[SpinAxisHistory]:
    """The history of :func:`history`, ``rows`` output times at a time (for streamed tables).

    The axes are integrated first (:func:`evolve_axes`, ``40 N`` bytes with ``ϖ`` for the
    history's ``largest_turn``; with a ``tolerance``, at the step that meets it,
    :func:`controlled_outputs`, and ``step`` the largest tried); the orbit is then sampled and
    described a block at a time, so that nothing else grows with ``N``. Every block carries the
    ``largest_turn`` and the ``error_estimate`` of the whole.

    Yields
    ------
    SpinAxisHistory
        Of consecutive output times, at most ``rows`` of them.
    """
    s0 = as_vectors(s0, "initial axis")
    s0 = s0 / np.linalg.norm(s0)
    error = None
    if tolerance is None:
        axes, p, varpi = _evolve_outputs(orbit, model, times, s0, step, order, orbit.has_eccentricity)
    else:
        (axes, p, varpi), error, step = controlled_outputs(
            orbit, model, times, s0, step, order, orbit.has_eccentricity, tolerance
        )
    # the largest turn of p_A or ϖ between consecutive outputs, both unwrapped step by step; ϖ's
    # only where e is at least PERIHELION_E_FLOOR of its largest over the outputs
    largest = float(np.max(np.abs(np.diff(p[0])), initial=0.0))
    if varpi is not None and times.size > 1:
        e = _eccentricity(orbit, times)
        kept = np.minimum(e[:-1], e[1:]) >= PERIHELION_E_FLOOR * float(np.max(e))
        largest = max(largest, float(np.max(np.abs(np.diff(varpi))[kept], initial=0.0)))
    del varpi
    n0 = orbit.normal(0.0)
    e0 = np.linalg.norm(orbit.eccentricity_vector(0.0)) if orbit.has_eccentricity else None
    eps0 = float(np.arctan2(np.linalg.norm(np.cross(s0, n0)), s0 @ n0))
    rate = model.precession_rate(eps0, e0)
    for first in range(0, len(times), rows):
        part = slice(first, first + rows)
        t, s = times[part], axes[0, part]
        n, obliquity, e, perihelion = describe_orbit(orbit, t, s)
        yield SpinAxisHistory(
            *(t, s, n, obliquity, p[0, part], e, perihelion, rate, model, orbit.name, largest),
            *(error, step, order),
        )


def history(
    orbit: OrbitHistory,
    model: SpinAxisModel,
    times: Array,
    s0: Array,
    step: float = DEFAULT_STEP,
    order: int = 8,
) -> SpinAxisHistory:
    """Integrate and describe (the work of :func:`andoyer.planetary.spin_axis.spin_axis_history`)."""
    return SpinAxisHistory.concatenate(list(history_blocks(orbit, model, times, s0, step, order)))


#: Bytes an orbit source may use per time it is sampled at (a bound: measured at most 304 for
#: the secular theory's modes, 104 for VCW 2011, 168 for an N-body spline, with what
#: :func:`describe_orbit` adds).
ORBIT_SAMPLE_BYTES = 1024
#: Bytes per output time of :func:`evolve_axes` and one run: the axis and ``p_A`` (32), the
#: step counts (16) and the times (8), with a margin for numpy's temporaries (measured 72).
AXIS_ROW_BYTES = 96
#: Bytes per output time of a :class:`SpinAxisHistory`: t, axis, normal, obliquity, p_A,
#: e and ϖ (11 float64).
HISTORY_ROW_BYTES = 88


def orbit_sample_seconds(orbit: OrbitHistory) -> float:
    """Seconds to sample ``orbit``'s normal and eccentricity at one time, measured now on a probe.

    A probe of 4096 times within a year of J2000 (any orbit source, the user's included):
    0.14 µs for an N-body spline, 0.3 µs for VCW 2011, 4 µs for the secular theory on the
    shared 2-core machine. The probe of an N-body orbit integrates its first thousand years
    if they are not cached.

    Examples
    --------
    >>> from andoyer.planetary.orbits import VondrakEcliptic
    >>> 0.0 < orbit_sample_seconds(VondrakEcliptic()) < 1e-3
    True
    """
    import time

    lo, hi = orbit.span
    probe = np.linspace(max(lo, -1.0), min(hi, 1.0), 4096)
    orbit.normal(probe[:2])  # a first call may set things up (an N-body orbit's first chunk)
    if orbit.has_eccentricity:
        orbit.eccentricity_vector(probe[:2])
    start = time.perf_counter()
    orbit.normal(probe)
    if orbit.has_eccentricity:
        orbit.eccentricity_vector(probe)
    return (time.perf_counter() - start) / probe.size


def run_cost(
    orbit: OrbitHistory,
    times: ArrayLike,
    runs: int = 1,
    step: float = DEFAULT_STEP,
    order: int = 8,
    sample_seconds: float | None = None,
) -> tuple[float, float]:
    """Seconds and bytes of :func:`evolve_axes` and the description of its output, before the work.

    Seconds: every step's stages and its end sample the orbit (:func:`step_count`,
    :func:`orbit_sample_seconds`); bytes: :data:`AXIS_ROW_BYTES` per output time and run, and
    one block of :data:`BLOCK_STEPS` steps (or :data:`BLOCK_ROWS` rows) of orbit samples,
    :data:`ORBIT_SAMPLE_BYTES` each. What a caller keeps of the output (a
    :class:`SpinAxisHistory`: :data:`HISTORY_ROW_BYTES` per time) is the caller's to add.

    Parameters
    ----------
    orbit : OrbitHistory
    times : array_like, shape (N,)
    runs : int
        ``M``, the runs sharing the orbit.
    step : float
    order : {2, 4, 6, 8}
    sample_seconds : float, optional
        The orbit's cost per sample (default: :func:`orbit_sample_seconds`).

    Returns
    -------
    seconds, nbytes : float

    Examples
    --------
    >>> from andoyer.planetary.orbits import VondrakEcliptic
    >>> seconds, nbytes = run_cost(VondrakEcliptic(), [-1e5, 0.0], sample_seconds=1e-6)
    >>> seconds, nbytes  # 100 steps of 15 stages and their ends, and 2 output times: 1602 samples
    (0.001602, 1651392)
    """
    _check_step(step)
    t = as_finite(times, "times").ravel()
    if t.size > 1 and not np.all(t[1:] > t[:-1]):
        msg = "expected increasing output times, got times out of order"
        raise ValueError(msg)
    stages = len(stage_times(np.zeros(1), np.ones(1), order)[0])
    steps = step_count(t, step)
    per_sample = orbit_sample_seconds(orbit) if sample_seconds is None else float(sample_seconds)
    samples = steps * (stages + 1) + t.size
    samples_at_once = max(min(steps, BLOCK_STEPS) * (stages + 1), min(t.size, BLOCK_ROWS))
    block = samples_at_once * (ORBIT_SAMPLE_BYTES + 8 * runs)
    return samples * per_sample, t.size * runs * AXIS_ROW_BYTES + block


def check_run(
    orbit: OrbitHistory,
    times: ArrayLike,
    what: str,
    runs: int = 1,
    step: float = DEFAULT_STEP,
    order: int = 8,
    row_bytes: float = 0.0,
    row_seconds: float = 0.0,
    fixed_bytes: float = 0.0,
    model: SpinAxisModel | Sequence[SpinAxisModel] | None = None,
) -> tuple[float, float]:
    """Refuse a run that cannot fit (:func:`run_cost`), have the orbit ready, announce a long one.

    In this order: the memory (which needs no measurement) is checked; the orbit is then
    asked for the whole span once (an N-body orbit integrates what it lacks there, checked
    and announced by itself); the time is measured (:func:`orbit_sample_seconds`) and
    checked, at ``step`` and, with ``model``, again at the step the model's precession
    allows (:data:`MAX_TURN_PER_STEP`; scanning the model's rate over the span costs a
    sixteenth of the run, after the first check); a run past
    :data:`andoyer._limits.ANNOUNCE_SECONDS` is announced.

    Parameters
    ----------
    orbit : OrbitHistory
    times : array_like, shape (N,)
        Increasing output times.
    what : str
        The run, for the messages (``"a spin-axis history"``).
    runs, step, order
        As :func:`run_cost`.
    row_bytes, row_seconds : float
        What the caller adds per output time (what it keeps, formatting).
    fixed_bytes : float
        What the caller adds once.
    model : SpinAxisModel or sequence of them, optional
        The run's model: the step is shortened as :func:`evolve_axes` will.

    Returns
    -------
    seconds, step : float
        The estimated seconds, and the step the run will take.

    Raises
    ------
    ValueError
        Naming what the run would need.
    """
    from andoyer._limits import announce, check_size

    t = np.asarray(times, dtype=float)
    _, nbytes = run_cost(orbit, t, runs, step, order, sample_seconds=0.0)
    nbytes += t.size * row_bytes + fixed_bytes
    check_size(what, nbytes=nbytes)
    if t.size:
        orbit.normal(np.array([min(float(t[0]), 0.0), max(float(t[-1]), 0.0)]))
    sample = orbit_sample_seconds(orbit)
    seconds = run_cost(orbit, t, runs, step, order, sample)[0] + t.size * row_seconds
    check_size(what, nbytes=nbytes, seconds=seconds)
    if model is not None:
        step = _largest_step(orbit, model, t, runs, step)
        seconds = run_cost(orbit, t, runs, step, order, sample)[0] + t.size * row_seconds
        check_size(what, nbytes=nbytes, seconds=seconds)
    announce(seconds, f"integrating the spin axis to {t.size} output times")
    return seconds, step


def evolve_axes(
    orbit: OrbitHistory,
    model: SpinAxisModel | Sequence[SpinAxisModel],
    times: Array,
    s0: Array,
    step: float = DEFAULT_STEP,
    order: int = 8,
) -> tuple[Array, Array]:
    """Axes and general precession ``p_A`` of ``M`` runs from one J2000 axis at ``times``.

    The integration runs outward from J2000 a block of :data:`BLOCK_STEPS` steps at a time,
    keeping only the output times: memory ``M · N · 32`` bytes and a block's, whatever the
    span. ``p_A`` is unwrapped step by step (every step is shorter than half a precession
    period) by counting its turns, so that it is exact to its last bit however many turns it
    makes.

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
    axes, p, _ = _evolve_outputs(orbit, model, times, s0, step, order, perihelion=False)
    return axes, p


def _evolve_outputs(
    orbit: OrbitHistory,
    model: SpinAxisModel | Sequence[SpinAxisModel],
    times: Array,
    s0: Array,
    step: float,
    order: int,
    perihelion: bool,
    refine: int = 1,
) -> tuple[Array, Array, Array | None]:
    """:func:`evolve_axes`, and ``ϖ`` of the first run (unwrapped step by step) at the times, or ``None``."""
    times = as_finite(times, "times")
    runs = 1 if isinstance(model, SpinAxisModel) else len(model)
    s0 = np.broadcast_to(as_finite(s0, "s0"), (runs, 3)) if np.ndim(s0) == 1 else np.asarray(s0)
    s0 = np.ascontiguousarray(s0, dtype=float)
    _check_step(step)
    if times.size:  # one request for the whole span: an N-body orbit integrates it in one run
        orbit.normal(np.array([min(float(times[0]), 0.0), max(float(times[-1]), 0.0)]))
    step = _largest_step(orbit, model, times, runs, step)
    n0 = orbit.normal(0.0)
    start = general_precession(s0[:, None, :], n0, s0, n0)[:, 0]  # p_A of J2000 itself: 0 to round-off
    axes = np.empty((runs, times.size, 3))
    p = np.empty((runs, times.size))
    at_zero = times == 0
    axes[:, at_zero] = s0[:, None, :]
    p[:, at_zero] = 0.0
    varpi = None
    if perihelion:
        varpi0 = _perihelion(s0[:1], n0[None, :], orbit.eccentricity_vector(np.zeros(1)))
        varpi = np.empty(times.size)
        varpi[at_zero] = varpi0[0]
    for side in (np.flatnonzero(times > 0), np.flatnonzero(times < 0)[::-1]):
        if side.size == 0:
            continue
        knots = np.concatenate([[0.0], times[side]])
        previous, turns = start[:, None], np.zeros((runs, 1))
        if perihelion:
            previous = np.concatenate([previous, varpi0[None, :]])
            turns = np.zeros((runs + 1, 1))
        for ends, out, last in _sweep(orbit, model, knots, s0, step, order, refine):
            n = orbit.normal(ends)
            raw = general_precession(out, n, s0, n0)
            if perihelion:
                raw = np.concatenate([raw, _perihelion(out[0], n, orbit.eccentricity_vector(ends))[None, :]])
            jumps = np.diff(np.concatenate([previous, raw], axis=1), axis=1)
            # a wrap from +π to −π (or 2π to 0) is a turn forward: count it, add whole turns at the end
            total = turns + np.cumsum(np.round(-jumps / (2 * np.pi)), axis=1)
            previous, turns = raw[:, -1:], total[:, -1:]
            hit = last >= 0
            rows = side[last[hit] - 1]
            axes[:, rows] = out[:, hit]
            p[:, rows] = raw[:runs, hit] + 2 * np.pi * total[:runs, hit] - start[:, None]
            if perihelion:
                varpi[rows] = raw[runs, hit] + 2 * np.pi * total[runs, hit]
    return axes, p, varpi


def check_tolerance(tolerance: float) -> float:
    """``tolerance`` (radians) as a float, refused outside [SMALLEST_TOLERANCE, LARGEST_TOLERANCE].

    Examples
    --------
    >>> check_tolerance(1e-9)
    1e-09
    >>> check_tolerance(0.0)
    Traceback (most recent call last):
    ...
    ValueError: expected a positive finite tolerance in radians, got 0.0
    """
    try:
        value = float(tolerance)
    except (TypeError, ValueError):
        value = np.nan
    if isinstance(tolerance, bool) or not (np.isfinite(value) and value > 0):
        msg = f"expected a positive finite tolerance in radians, got {tolerance!r}"
        raise ValueError(msg)
    if value < SMALLEST_TOLERANCE:
        msg = (
            f"expected a tolerance of at least {SMALLEST_TOLERANCE:g} rad (the axis' round-off over a run), "
            f"got {tolerance!r}"
        )
        raise ValueError(msg)
    if value > LARGEST_TOLERANCE:
        msg = f"expected a tolerance of at most {LARGEST_TOLERANCE:.6g} rad (one degree), got {tolerance!r}"
        raise ValueError(msg)
    return value


def resolve_stepping(
    step: float | None, order: int | None, tolerance: float | None
) -> tuple[float, int, float | None]:
    """The largest step, the order and the tolerance of a run, from what its caller gave.

    A ``step`` without a ``tolerance`` is a run at that step (order 8 unless given), as before
    tolerances existed: no estimate. Otherwise the step is chosen from the tolerance (default
    :data:`DEFAULT_TOLERANCE`) by :func:`controlled_outputs`, from ``step`` (default
    :data:`DEFAULT_STEP`) down.

    Examples
    --------
    >>> resolve_stepping(500.0, None, None)
    (500.0, 8, None)
    >>> step, order, tolerance = resolve_stepping(None, None, None)
    >>> from andoyer.catalogue.units import ARCSEC
    >>> step, order, round(tolerance / ARCSEC, 6)
    (1000.0, 8, 0.01)
    """
    order = 8 if order is None else order
    if tolerance is None and step is not None:
        return step, order, None
    tolerance = check_tolerance(DEFAULT_TOLERANCE if tolerance is None else tolerance)
    step = DEFAULT_STEP if step is None else step
    _check_step(step)
    return step, order, tolerance


def controlled_outputs(
    orbit: OrbitHistory,
    model: SpinAxisModel | Sequence[SpinAxisModel],
    times: Array,
    s0: Array,
    step: float,
    order: int,
    perihelion: bool,
    tolerance: float,
) -> tuple[tuple[Array, Array, Array | None], float, float]:
    r"""The outputs of :func:`evolve_axes` (and ``ϖ``) at the step that meets ``tolerance``.

    Step doubling: a run at steps ``h`` (at most ``step``, shortened as :func:`evolve_axes`
    does, every output time ending one) and a run with every step halved are compared at the
    output times; while the largest distance between their axes, ``max |s_h − s_{h/2}|`` over
    the runs and the times, exceeds ``tolerance`` (radians), the steps are halved again (the
    last fine run becomes the coarse one), at most :data:`MAX_HALVINGS` times (then a
    :class:`~andoyer._limits.ToleranceWarning`).

    That distance is the **error estimate** of the fine run, and a conservative one: the
    coarse run's error is the distance plus the fine run's, so the fine run's error is below
    the distance whenever halving the step at least halves the error.

    **Long spans.** Over more than :data:`CONTROL_WINDOW` (10 Myr) from J2000 the step is
    chosen on the window alone (the outputs within it and its ends), then the whole span is run
    once at that step, and the error reported is the window's: the tolerance holds per window
    of 10 Myr, not over the whole span. Where the axis is chaotic (Mars: its obliquity wanders
    through secular spin–orbit resonances, Laskar & Robutel 1993, *Nature* 361, 608; Touma &
    Wisdom 1993, *Science* 259, 1294) two runs at any two steps part exponentially, so a
    tolerance over 10⁸ years is met by no step (halving the step only delays the parting by a
    Lyapunov time); such a history is one of the possible ones, and its statistics are what
    carry information (:mod:`andoyer.planetary.spin_axis.members`). The composition is of
    order 8 on a smooth orbit (an error ratio of 256 per halving); on an orbit interpolated by
    a cubic spline, such as the N-body one (100-year knots), the ratio measured for Mars over
    1 Myr is 12–22 (an order near 4): the estimate is then 11–21 times the error.

    Parameters
    ----------
    orbit, model, times, s0, order
        As :func:`evolve_axes`.
    step : float
        The largest step tried, years.
    perihelion : bool
        Whether ``ϖ`` is integrated too (:func:`history_blocks`).
    tolerance : float
        Radians (:func:`check_tolerance`).

    Returns
    -------
    outputs : tuple
        ``(axes, precession, ϖ or None)`` of the fine run.
    error : float
        Its estimated error, radians.
    step : float
        Its largest step, years.

    Examples
    --------
    >>> from andoyer.planetary.orbits import VondrakEcliptic
    >>> from andoyer.planetary.spin_axis.model import SpinAxisModel
    >>> model = SpinAxisModel.from_precession_rate("earth", 50.3848, EPSILON_0)
    >>> (axes, p, _), error, step = controlled_outputs(
    ...     VondrakEcliptic(), model, np.array([-2e5, 2e5]), mean_pole_j2000(), 1000.0, 8, False, 1e-9)
    >>> bool(error <= 1e-9), step
    (True, 500.0)
    """
    times = as_finite(times, "times")
    runs = 1 if isinstance(model, SpinAxisModel) else len(model)
    if times.size:  # the whole span at once (an N-body orbit integrates it in one run)
        orbit.normal(np.array([min(float(times[0]), 0.0), max(float(times[-1]), 0.0)]))
    reach = float(np.max(np.abs(times), initial=0.0))
    if reach > CONTROL_WINDOW:
        # the step from the window, then one run over the whole span at that step
        ends = [side * CONTROL_WINDOW for side in (-1.0, 1.0) if np.any(side * times > CONTROL_WINDOW)]
        probe = np.unique(np.concatenate([times[np.abs(times) <= CONTROL_WINDOW], ends]))
        _, error, chosen = _doubled(orbit, model, probe, s0, step, order, perihelion, tolerance, runs)
        what = (
            f"a spin-axis run at the step of {chosen:.3g} years that met a tolerance of {tolerance:.3g} rad"
        )
        check_size(what, seconds=run_cost(orbit, times, runs, chosen, order, orbit_sample_seconds(orbit))[0])
        return _evolve_outputs(orbit, model, times, s0, chosen, order, perihelion), error, chosen
    return _doubled(orbit, model, times, s0, step, order, perihelion, tolerance, runs)


def _doubled(orbit, model, times, s0, step, order, perihelion, tolerance, runs):  # type: ignore[no-untyped-def]
    """:func:`controlled_outputs`' step doubling over ``times``: (outputs, error, step)."""
    step = _largest_step(orbit, model, times, runs, step)
    knots = np.unique(np.concatenate([[0.0], times]))
    # the largest step the coarse run takes: every gap is then cut in twice as many steps
    if knots.size > 1:
        step = float(np.max(np.abs(np.diff(knots)) / _step_counts(knots, step)[0]))
    sample = orbit_sample_seconds(orbit)
    coarse = _evolve_outputs(orbit, model, times, s0, step, order, perihelion)
    error, refine = np.inf, 1
    for _ in range(MAX_HALVINGS):
        refine *= 2
        seconds = refine * run_cost(orbit, times, runs, step, order, sample)[0]
        what = f"a spin-axis run at the step that meets a tolerance of {tolerance:.3g} rad"
        check_size(what, seconds=seconds)
        fine = _evolve_outputs(orbit, model, times, s0, step, order, perihelion, refine)
        error = float(np.max(np.linalg.norm(fine[0] - coarse[0], axis=-1), initial=0.0))
        if error <= tolerance:
            return fine, error, step / refine
        coarse = fine
    msg = (
        f"the spin axis met no tolerance of {tolerance:.3g} rad down to a step of {step / refine:.3g} years: "
        f"its estimated error is {error:.3g} rad"
    )
    warnings.warn(msg, ToleranceWarning, stacklevel=caller_stacklevel())
    return coarse, error, step / refine


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
    matched with the obliquity ``∠(s0, n(0))`` and the orbit's ``e(0)`` where it knows it; a
    planet other than the Earth and Mars (or a body of the user's own) given neither takes its
    catalogued figure and satellites (:meth:`SpinAxisModel.from_precession_constant`).

    Parameters
    ----------
    orbit : OrbitHistory
    body : str or Body
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
    key = str(body).strip().lower() if isinstance(body, str) else body
    named = isinstance(key, str) and key in DEFAULT_PRECESSION_RATE
    if rate is None and not named:  # any other planet or a body file: its figure and satellites
        SpinAxisModel._tides(body, tidal_dissipation)  # refuses tides without a moon
        return SpinAxisModel.from_precession_constant(body, ellipticity_drift, e0)
    if rate is None:
        rate = DEFAULT_PRECESSION_RATE[key]
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
        sol = solve_ivp(rhs, (0.0, end), s0, method="DOP853", t_eval=targets[order], rtol=rtol, atol=rtol)
        values = np.empty((targets.size, 3))
        values[order] = sol.y.T
        out[side] = values
    return out
