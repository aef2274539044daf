r"""The splitting's error model: the order and step of a run chosen from short probe runs.

:func:`andoyer.integrate.splitting.integrate_splitting` with an ``rtol`` runs the model over
a *probe* of length ``L`` (much shorter than the span ``T`` of the outputs) at steps ``h``
and ``h/2`` and models the distance between the two reference-frame momenta,

.. math::
   d(t) = \frac{\lVert \mathbf M_h(t) - \mathbf M_{h/2}(t) \rVert}{\lVert \mathbf M(t_0) \rVert},

as a **bounded part** ``B`` plus a **secular drift** ``D t``:

.. math::
   B = \max_{t_j \le L} d(t_j), \qquad
   D = \max\bigl(\lVert \mathbf b \rVert,\ \beta\bigr), \quad
   \boldsymbol\Delta(t_j) \approx \mathbf a + \mathbf b\, t_j, \quad
   d(t_j) \approx \alpha + \beta\, t_j \ \text{(least squares over the probe)},

   E(h, T) = s\,\bigl(B + D \max(T - L, 0)\bigr), \qquad s = 2,

with ``Δ`` the vector difference (relative to ``|M(t₀)|``) sampled at ``t_j`` (grid points
of both runs, about :data:`SAMPLES` of them), and ``E`` the estimate of the run at step
``h``. The vector's slope ``b`` is a drift of fixed direction; the norm's slope ``β`` one
whose direction the slow motion of ``M`` turns. Why this shape: a symmetric splitting is the
exact flow of a modified Hamiltonian seen through a near-identity change of variables, so
its error is an oscillation of bounded size (the change of variables; it follows the forcing
and so saturates after the longest forcing period) plus a slow drift (the modified
frequencies). The safety factor ``s = 2`` turns the distance into a bound of the error of
the ``h`` run: ``err(h) ≤ d + err(h/2) ≤ d + err(h)/2`` whenever halving the step at least
halves the error. The drift fitted over a probe of a few forcing periods is an
over-estimate: an oscillation of period longer than the probe counts as drift (the Earth's
18.6-year lunar node over a 16-year probe: the estimate is then ~7× the error after 1000
years).

The probe's length is :func:`probe_length`: :data:`PROBE_PERIODS` times the longest orbital
period of the perturbers and the frames' periods, at least :data:`PROBE_STEPS` steps and
four beat periods of the nearest resonance, and :data:`SLOW_PERIODS` periods of the slow
motion of ``M`` when that is shorter than :data:`TURNING_SPANS` spans; at most the span
(then ``E = s B`` is measured, not extrapolated). For each order (2, 4, 6 unless one is
asked) the step is halved from the first step, each rung moved off resonance
(:func:`detune`), until ``E ≤ rtol``; the order and step with the fewest Strang substeps
over the span win (:func:`choose`), and one full run at that step follows.

**Assumptions and failures.** The model assumes the error grows at most linearly after the
probe: it can fail for chaotic motion (errors grow exponentially), near separatrices of the
free or the forced motion, for slow resonances that the probe does not reach (a step close to
a rational fraction of a forcing period beats with it, and the beat's growth is linear only
over a fraction of its period), and for forcings whose period is longer than the span of the
probe and not declared by the model (then it is counted as drift, which over-estimates).
The output times do not matter: each output is a short step from the run's grid, which goes
on undisturbed. The estimate is of the momentum ``M`` only, not of the spin phase.

Examples
--------
A distance that drifts by ``1e-7`` per unit of time, sampled over four units:

>>> t = np.linspace(1.0, 4.0, 4)
>>> delta = np.stack([1e-7 * t, 0 * t, 0 * t], axis=-1)[:, None, :]  # (N, S=1, 3)
>>> bounded, drift = distance_model(t, delta)
>>> round(bounded, 12), round(drift, 12)
(4e-07, 1e-07)
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

__all__ = [
    "DETUNE_GRID",
    "PROBE_PERIODS",
    "PROBE_STEPS",
    "SAFETY",
    "SAMPLES",
    "SLOW_PERIODS",
    "TURNING_SPANS",
    "Choice",
    "choose",
    "detune",
    "distance_model",
    "probe_length",
]

Array = NDArray[np.float64]

#: The error of the run at ``h`` over the distance to ``h/2``: ``err(h) ≤ 2 d`` when halving
#: the step at least halves the error.
SAFETY = 2.0
#: The probe's length in longest forcing periods: the bounded part saturates within a few of
#: them (4 to 8 years for the Earth under the Sun and the Moon; ``benchmarks/RESULTS.md``).
PROBE_PERIODS = 16
#: The probe's least length in steps of the pair's coarse run (models without an orbit).
PROBE_STEPS = 64
#: Samples of the distance over the probe (the maximum and the fit are taken over them).
SAMPLES = 64


@dataclass(frozen=True)
class Choice:
    """One order and step, with the parts of its error estimate.

    Attributes
    ----------
    order : int
    step : float
    bounded : float
        ``B``: the largest relative distance over the probe.
    drift : float
        ``D``: the fitted drift of the distance per unit time.
    probe_length : float
        ``L``: the probe's length.
    error : float
        ``E = SAFETY (B + D max(T − L, 0))``.
    substeps : float
        Strang substeps of the full run, ``stages(order) T / h`` (its cost).
    """

    order: int
    step: float
    bounded: float
    drift: float
    probe_length: float
    error: float
    substeps: float


def distance_model(times: Array, delta: Array) -> tuple[float, float]:
    """``(B, D)``: the bounded part and the drift of the relative distances ``delta``.

    Parameters
    ----------
    times : ndarray, shape (N,)
        Times from the start of the probe, ``N ≥ 2`` distinct.
    delta : ndarray, shape (N, S, 3)
        ``(M_h − M_{h/2}) / |M(t₀)|`` of each of ``S`` states at those times.

    Returns
    -------
    bounded, drift : float
        ``max |delta|`` and the largest norm over states of the least-squares slope of ``delta``.
    """
    t = np.asarray(times, dtype=np.float64)
    d = np.asarray(delta, dtype=np.float64).reshape(t.size, -1)
    size = np.linalg.norm(d.reshape(t.size, -1, 3), axis=-1)  # (N, S)
    design = np.stack([np.ones_like(t), t - t.mean()], axis=1)
    coef = np.linalg.lstsq(design, np.concatenate([d, size], axis=1), rcond=None)[0][1]
    # the vector's slope (a drift of fixed direction) and the norm's (one the motion turns)
    along = np.linalg.norm(coef[: d.shape[1]].reshape(-1, 3), axis=-1)
    turning = coef[d.shape[1] :]
    return float(np.max(size)), float(np.max(np.maximum(along, turning)))


#: Tried steps per rung of the ladder when moving a step off resonance (:func:`detune`).
DETUNE_GRID = 256


def detune(step: float, frequencies: Array) -> tuple[float, float]:
    """The step in ``[step/√2, step]`` farthest from resonance with ``frequencies``; ``(h, margin)``.

    A step ``h`` with ``f h / 2π`` an integer for a frequency ``f`` of the kicks samples that
    term at one phase: it aliases to a constant and its error grows secularly, at steps ``h``
    and ``h/2`` alike when both are multiples, where step doubling cannot see it. The margin
    ``min_f dist(f h / 2π, ℤ)`` is maximised on a grid of :data:`DETUNE_GRID` steps; every
    term then beats with a period of at most ``h / margin``, which the probe covers.
    Without frequencies the step is kept (margin 0.5).

    Examples
    --------
    >>> h, margin = detune(1.0, np.array([2 * np.pi]))  # one turn per unit of time
    >>> round(h, 3), round(margin, 3)  # half a turn less is as far as the range allows
    (0.707, 0.293)
    """
    f = np.asarray(frequencies, dtype=np.float64).ravel()
    if f.size == 0:
        return float(step), 0.5
    steps = step * np.exp2(-0.5 * np.linspace(0.0, 1.0, DETUNE_GRID))
    phase = np.abs(np.outer(steps, f)) / (2 * np.pi)
    margins = np.min(np.abs(phase - np.round(phase)), axis=1)
    best = int(np.argmax(margins))  # the largest step among equal margins: the first
    return float(steps[best]), float(margins[best])


#: The slow motion of ``M`` is ignored when its period is this many spans or more: the error's
#: direction then turns by less than an eighth of a turn over the run.
TURNING_SPANS = 8
#: Periods of the slow motion of ``M`` a probe covers otherwise: the error vector turns with
#: ``M``, and its growth shows over whole turns only.
SLOW_PERIODS = 2


def probe_length(span: float, step: float, margin: float, period: float, slow: float) -> float:
    """The probe's length ``L`` for a run at ``step`` over ``span``.

    The longest of :data:`PROBE_PERIODS` forcing periods ``period``, :data:`PROBE_STEPS`
    steps, four beat periods ``step / margin`` of the nearest resonance (:func:`detune`) and,
    when ``slow`` (the period ``2π|M|/|τ|`` of the momentum's motion under the torque) is
    shorter than :data:`TURNING_SPANS` spans, :data:`SLOW_PERIODS` of it; the whole span when
    that reaches half of it (the error is then measured, not extrapolated).

    Examples
    --------
    >>> probe_length(1000.0, 0.25, 0.5, 1.0, 1e9)  # 16 periods
    16.0
    >>> probe_length(1000.0, 0.25, 0.5, 1.0, 300.0)  # two turns of M: more than half the span
    1000.0
    """
    needed = max(PROBE_PERIODS * period, PROBE_STEPS * step, 4.0 * step / max(margin, 1e-300))
    if slow < TURNING_SPANS * span:
        needed = max(needed, SLOW_PERIODS * slow)
    return span if needed >= 0.5 * span else needed


Run = Callable[[int, float, Array], Array]


def choose(
    run: Run,
    rtol: float,
    span: float,
    first_step: float,
    orders: tuple[int, ...],
    stages: dict[int, int],
    period: float,
    slow: float,
    frequencies: Array,
    max_halvings: int,
) -> tuple[Choice, bool]:
    """The order and step of least cost whose estimate meets ``rtol``; ``(choice, met)``.

    ``run(order, h, times)`` returns the relative reference-frame momenta ``M / |M(t₀)|``
    (N, S, 3) of a run at step ``h`` at the probe's ``times`` (N,, multiples of ``h``),
    measured from ``t₀`` along the direction of the run. ``period`` is the longest forcing
    period (0: none known), ``slow`` the period of the momentum's motion under the torque
    (:func:`probe_length`), ``frequencies`` those of the kicks (:func:`detune`). The ladder
    of each order is ``first_step / 2^k``, each rung moved off resonance. When no step meets
    ``rtol`` the one with the smallest estimate comes back with ``met`` false.
    """
    best: Choice | None = None
    closest: Choice | None = None
    for order in orders:
        rung = first_step
        for _ in range(max_halvings + 1):
            h, margin = detune(rung, frequencies)
            rung *= 0.5
            substeps = stages[order] * span / h
            if best is not None and substeps >= best.substeps:
                break  # a smaller step at this order costs more still
            length = probe_length(span, h, margin, period, slow)
            count = max(1, math.floor(length / h + 1e-9))
            every = max(1, math.ceil(count / SAMPLES))
            times = h * every * np.arange(1, count // every + 1)
            coarse = run(order, h, times)
            fine = run(order, 0.5 * h, times)
            bounded, drift = distance_model(times, coarse - fine)
            error = SAFETY * (bounded + drift * max(span - length, 0.0))
            choice = Choice(order, h, bounded, drift, length, error, substeps)
            if closest is None or error < closest.error:
                closest = choice
            if error <= rtol:
                best = choice
                break
    if best is None:
        assert closest is not None
        return closest, False
    return best, True
