r"""The splitting method: the exact free flow composed with the flow of ``ΔH``, symplectically.

``andoyer.propagate(..., method="splitting")`` is :func:`integrate_splitting`; its compiled
loop for tabulated kicks is :mod:`andoyer.integrate.splitting.kernel`, its compositions
:func:`~andoyer.compositions.splitting_coefficients`.

``K = T + V + F`` with ``T`` the free Hamiltonian, ``V(t, q)`` the
attitude-only terms and ``F = -μ·M`` a precessing frame. Their flows are
exact:

* ``T``: the closed-form torque-free motion (:class:`andoyer.free.FreeMotion`);
* ``V``: a kick of the body momentum, ``m → m + τ(t, q) h`` (``q`` fixed);
* ``F``: a rotation of the attitude about the frame's axis,
  ``q → exp(-μ h/2) ⊗ q`` (``m`` fixed) — exact for a constant ``μ``; a
  time-dependent ``μ(t)`` is taken at the substep's midpoint, which keeps the
  scheme second order in the frame term.

``F`` commutes with ``T`` (the free flow conserves the inertial momentum
``M``), so a step of the symmetric Strang scheme is
``S(h) = V(h/2) ∘ F(h) ∘ T(h) ∘ V(h/2)``; orders 4 and 6 are Yoshida's
triple-jump compositions of ``S`` (Yoshida 1990, solution A for order 6).
Time enters the kicks at the substep's time, the free flow advancing it.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer import _quaternion as quat
from andoyer._limits import MAX_STEPS, STEP_SECONDS, ToleranceWarning, caller_stacklevel, check_size, progress
from andoyer._validation import as_finite
from andoyer.compositions import splitting_coefficients
from andoyer.free.step_scalar import NUMBA, free_step
from andoyer.integrate.output import gather_states, output_times
from andoyer.integrate.splitting.kernel import run_tabulated
from andoyer.integrate.splitting.probe import Choice, choose
from andoyer.perturbations.base import Perturbation
from andoyer.perturbations.model import Model
from andoyer.state import State

__all__ = [
    "COMPOSITIONS",
    "DEFAULT_RTOL",
    "LARGEST_RTOL",
    "SMALLEST_RTOL",
    "SplittingState",
    "exact_free_flow",
    "integrate_splitting",
    "split_step",
    "splitting_coefficients",
    "splitting_parts",
]

Array = NDArray[np.float64]


#: The Strang-step weights of each order (:func:`~andoyer.compositions.splitting_coefficients`).
COMPOSITIONS = {order: splitting_coefficients(order) for order in (2, 4, 6)}


def splitting_parts(model: Model) -> tuple[list[Perturbation], list[Perturbation]]:
    """The kicks (attitude-only Hamiltonian terms) and precessing frames of ``model``.

    Each term says which it is (:attr:`~andoyer.perturbations.Perturbation.splitting_flow`).
    Raises ``ValueError`` for any other term: its flow is not a kick or a frame rotation.
    """
    kicks, frames = [], []
    for part in model.parts:
        if part.splitting_flow == "frame":
            frames.append(part)
        elif part.splitting_flow == "kick":
            kicks.append(part)
        else:
            msg = (
                "expected Hamiltonian attitude-only models or precessing frames for method='splitting', "
                f"got {part!r} (use method='reference')"
            )
            raise ValueError(msg)
    return kicks, frames


FreeFlow = Callable[[Array, Array, Array, float], tuple[Array, Array]]


def exact_free_flow(moments: Array, q: Array, m: Array, h: float) -> tuple[Array, Array]:
    """The closed-form torque-free flow over ``h`` of attitudes (N, 4) and momenta (N, 3).

    :func:`andoyer.free.step_scalar.free_step`: the scalar kernel (compiled with numba when
    installed) for one step, :class:`~andoyer.free.FreeMotion` for separatrix states
    and for large batches without numba.

    Examples
    --------
    >>> q, m = exact_free_flow(np.array([1.0, 2.0, 3.0]), np.array([[0.0, 0.0, 0.0, 1.0]]),
    ...                        np.array([[0.0, 0.0, 3.0]]), np.pi)
    >>> q.round(12).tolist(), m.tolist()  # half a turn about b3
    ([[0.0, 0.0, 1.0, 0.0]], [[0.0, 0.0, 3.0]])
    """
    return free_step(moments, q, m, h)


def split_step(
    model: Model,
    free_flow: FreeFlow | None,
    t: float,
    q: Array,
    m: Array,
    h: float,
    order: int = 2,
) -> tuple[Array, Array]:
    """Advance attitudes ``q`` (N, 4) and momenta ``m`` (N, 3) from ``t`` by one step ``h``.

    The generic (Python) step: kicks through the models' torques, so any attitude-only
    Hamiltonian model works. ``free_flow(moments, q, m, h) -> (q, m)`` is the exact
    torque-free flow (``None``: :func:`exact_free_flow`).

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> from andoyer.perturbations import HeavyTop
    >>> model = Model(RigidBody(1.0, 1.0, 1.5), HeavyTop(1.0, [0.0, 0.0, 0.1]))
    >>> q0, m0 = np.array([[0.0, 0.0, 0.0, 1.0]]), np.array([[0.0, 0.0, 1.0]])
    >>> q, m = split_step(model, None, 0.0, q0, m0, 0.1)
    >>> m.round(15).tolist()  # upright: no torque
    [[0.0, 0.0, 1.0]]
    """
    flow = exact_free_flow if free_flow is None else free_flow
    kicks, frames = splitting_parts(model)
    moments = model.body.moments
    time = t
    for weight in COMPOSITIONS[order]:
        sub = weight * h
        for kick in kicks:
            m = m + kick.kick(np.asarray(time), q, m) * (0.5 * sub)
        q, m = flow(moments, q, m, sub)
        if frames:
            mu = sum(np.asarray(frame.frame_rate(np.asarray(time + 0.5 * sub))) for frame in frames)
            q = quat.multiply(np.broadcast_to(_frame_quaternion(mu, sub), q.shape), q)
        time = time + sub
        for kick in kicks:
            m = m + kick.kick(np.asarray(time), q, m) * (0.5 * sub)
    return q, m


def _frame_quaternion(mu: Array, sub: float) -> Array:
    """``exp(−μ sub/2)``: the exact flow of ``−μ·M`` over ``sub``, as a quaternion (..., 4)."""
    angle = -np.asarray(mu, dtype=np.float64) * sub
    norm = np.linalg.norm(angle, axis=-1, keepdims=True)
    axis = np.divide(angle, norm, out=np.zeros_like(angle), where=norm > 0)
    return np.concatenate([np.sin(0.5 * norm) * axis, np.cos(0.5 * norm)], axis=-1)


def _tabulable(kicks: list[Perturbation]) -> bool:
    return NUMBA and all(kick.tabulable for kick in kicks)


_CHUNK = 4096


class _Tables:
    """Perturber positions and frame rates of one chunk of steps, for :func:`run_tabulated`."""

    def __init__(self, kicks: list[Perturbation], frames: list[Perturbation], order: int) -> None:
        weights = np.array(COMPOSITIONS[order])
        self.weights = weights
        self.nodes = np.concatenate([[0.0], np.cumsum(weights)])
        self.mids = 0.5 * (self.nodes[:-1] + self.nodes[1:])
        self.sources = [source for kick in kicks for source in kick.point_masses()]
        self.gm = np.array([p.gm for p, _ in self.sources], dtype=np.float64)
        self.inertia = np.array([moments for _, moments in self.sources], dtype=np.float64).reshape(-1, 3)
        heavy = np.zeros(3)
        for kick in kicks:
            field = kick.uniform_field()
            if field is not None:
                heavy += field
        self.heavy = heavy
        self.frames = frames

    def build(self, starts: Array, hs: Array) -> tuple[Array, Array]:
        times = starts[:, None] + hs[:, None] * self.nodes  # (S, K+1)
        positions = np.zeros((*times.shape, len(self.sources), 3))
        for j, (p, _) in enumerate(self.sources):
            positions[:, :, j] = p.orbit.position(times)
        rates = np.zeros((hs.size, self.weights.size, 3))
        mids = starts[:, None] + hs[:, None] * self.mids
        for frame in self.frames:
            rates += np.asarray(frame.frame_rate(mids), dtype=np.float64)
        return positions, rates


def _run_steps(
    model: Model,
    tables: _Tables | None,
    q: Array,
    m: Array,
    now: float,
    step: float,
    n_full: int,
    last: float,
    order: int,
    bar: Any = None,
    record: NDArray[np.int64] | None = None,
) -> tuple[Array, Array]:
    """``n_full`` steps of ``step`` from ``now`` then one of ``last`` (may be 0), all states.

    ``bar.update(k)`` is told of every ``k`` steps done (a progress bar). With ``record``
    (sorted step counts in ``1..n_full``, and ``last = 0``) the states after those steps are
    returned instead, stacked: (R, N, 4) and (R, N, 3).
    """
    moments = model.body.moments
    kept_q: list[Array] = []
    kept_m: list[Array] = []
    marks = np.zeros(0, dtype=np.int64) if record is None else np.asarray(record, dtype=np.int64)
    if tables is None:
        counts = np.bincount(marks, minlength=n_full + 1)
        for n in range(n_full):
            q, m = split_step(model, None, now + n * step, q, m, step, order)
            kept_q.extend([q] * counts[n + 1])
            kept_m.extend([m] * counts[n + 1])
            if bar is not None:
                bar.update(1)
        if last != 0.0:
            q, m = split_step(model, None, now + n_full * step, q, m, last, order)
        return (np.array(kept_q), np.array(kept_m)) if record is not None else (q, m)
    q, m = np.ascontiguousarray(q, dtype=np.float64).copy(), np.ascontiguousarray(m, dtype=np.float64).copy()
    total = n_full + (last != 0.0)
    for lo in range(0, total, _CHUNK):
        # the steps of this chunk only: memory stays O(_CHUNK) however long the run
        index = np.arange(lo, min(lo + _CHUNK, total), dtype=np.float64)
        hs = np.full(index.size, step)
        if last != 0.0 and lo + index.size == total:
            hs[-1] = last
        starts = now + step * index
        positions, rates = tables.build(starts, hs)
        # the chunk cut where states are kept: the kernel runs whole slices of steps
        inside = marks[(marks > lo) & (marks <= lo + hs.size)] - lo
        a = 0
        for b in inside.tolist():
            if b > a:
                _run_slice(moments, tables, q, m, hs[a:b], positions[a:b], rates[a:b])
                a = b
            kept_q.append(q.copy())
            kept_m.append(m.copy())
        if a < hs.size:
            _run_slice(moments, tables, q, m, hs[a:], positions[a:], rates[a:])
        if bar is not None:
            bar.update(hs.size)
    return (np.array(kept_q), np.array(kept_m)) if record is not None else (q, m)


def _run_slice(
    moments: Array, tables: _Tables, q: Array, m: Array, hs: Array, positions: Array, rates: Array
) -> None:
    """Every state through the tabulated steps ``hs`` in place: the compiled loop, separatrix states aside."""
    stages = tables.weights.size
    weights, gm, inertia, heavy = tables.weights, tables.gm, tables.inertia, tables.heavy
    begin = np.zeros(q.shape[0], dtype=np.int64)
    status = np.full(q.shape[0], -1, dtype=np.int64)
    while True:
        run_tabulated(moments, q, m, hs, weights, positions, gm, inertia, heavy, rates, begin, status)
        stuck = np.nonzero(status >= 0)[0]
        if stuck.size == 0:
            return
        # separatrix states: this free substep by FreeMotion, then resume at the next kick
        for i in stuck:
            n, k = divmod(int(status[i]), stages + 1)
            sub = weights[k] * hs[n]
            qi, mi = free_step(moments, q[i : i + 1], m[i : i + 1], sub)
            q[i], m[i] = quat.multiply(_frame_quaternion(rates[n, k], sub), qi[0]), mi[0]
            begin[i] = status[i] + 1
        done = status < 0
        begin[done] = hs.size * (stages + 1)


def _outputs(
    model: Model,
    tables: _Tables | None,
    q0: Array,
    m0: Array,
    t0: float,
    step: float,
    targets: Array,
    order: int,
    bar: Any = None,
) -> dict[float, tuple[Array, Array]]:
    """The states at ``targets`` (sorted away from ``t0`` along ``step``'s sign) of one run.

    The run keeps its grid ``t0 + k·step``: an output between grid points is one short step
    from the grid point before it, and the run goes on from that grid point, so its error does
    not depend on where the output times fall.
    """
    distance = np.abs(targets - t0)
    size = abs(step)
    tiny = 1e-12 * np.maximum(size, distance)
    k = np.floor(distance / size).astype(np.int64)
    rest = distance - k * size
    up = size - rest <= tiny  # on the grid point after, to round-off
    k[up] += 1
    rest[up | (np.abs(rest) <= tiny)] = 0.0
    marks = np.unique(k[k > 0])
    values: dict[float, tuple[Array, Array]] = {}
    grid_q, grid_m = {0: q0}, {0: m0}
    if marks.size:
        q, m = _run_steps(model, tables, q0, m0, t0, step, int(marks[-1]), 0.0, order, bar, record=marks)
        grid_q.update(zip(marks.tolist(), q, strict=True))
        grid_m.update(zip(marks.tolist(), m, strict=True))
    short = np.nonzero(rest > 0)[0]
    sign = math.copysign(1.0, step)
    if short.size and tables is not None:
        # every output's short step tabulated at once, each then run from its grid point
        hs = sign * rest[short]
        positions, rates = tables.build(t0 + step * k[short].astype(np.float64), hs)
    for j, target in enumerate(targets.tolist()):
        q, m = grid_q[int(k[j])], grid_m[int(k[j])]
        if rest[j] > 0:
            start = t0 + step * float(k[j])
            if tables is None:
                q, m = split_step(model, None, start, q, m, sign * float(rest[j]), order)
            else:
                i = int(np.searchsorted(short, j))
                q, m = q.copy(), m.copy()
                one = slice(i, i + 1)
                _run_slice(model.body.moments, tables, q, m, hs[one], positions[one], rates[one])
        values[float(target)] = (q, m)
    return values


#: Seconds per Strang substep of the Python path (:func:`split_step`): a fixed cost plus one
#: per state (measured with a heavy top: 55 µs for one state, 1.4 µs a state for 100).
_PYTHON_SUBSTEP_SECONDS = (5.5e-5, 1.0e-6)


def _count_steps(unique: Array, t0: float, step: float) -> float:
    """Steps from ``t0`` to the sorted times ``unique``, both ways: span/step plus one per output."""
    ahead, behind = unique[unique > t0], unique[unique < t0]
    steps = 0.0
    for targets, far in ((ahead, unique[-1] - t0), (behind, t0 - unique[0])):
        if targets.size:
            steps += float(far) / step + targets.size
    return steps


#: The smallest ``rtol`` taken: the round-off of the momentum over a long run of substeps.
SMALLEST_RTOL = 1e-13
#: The largest ``rtol`` taken: step doubling estimates the error only while it is small, and a
#: relative error of ten per cent leaves no digit of the momentum.
LARGEST_RTOL = 0.1
#: The ``rtol`` of a run given neither a step nor an ``rtol``: a default for speed, as
#: ``scipy.integrate.solve_ivp``'s ``rtol=1e-3``; the estimate is a bound, and the error it
#: bounds is often ten times smaller (``benchmarks/RESULTS.md``).
DEFAULT_RTOL = 1e-3
#: Halvings of the step tried before an ``rtol`` is given up (with a ToleranceWarning).
MAX_HALVINGS = 24


class SplittingState(State):
    """The :class:`~andoyer.state.State` of a splitting run chosen from an ``rtol``, with its estimate.

    Attributes
    ----------
    error_estimate : float
        ``E``: the estimated bound of the relative error of the reference-frame momentum,
        ``max |M − M_exact| / |M(t₀)|`` over the output times and states, from the probe
        (:mod:`andoyer.integrate.splitting.probe`).
    step : float
        The step of the run (an output between grid points is one shorter step away).
    order : int
        Its order.
    bounded : float
        ``B``: the bounded part of the step-doubling distance, the largest over the probe.
    drift : float
        ``D``: its fitted drift per unit of time.
    probe_length : float
        ``L``: the probe's length (``E = 2 (B + D max(T − L, 0))`` for a span ``T``).
    """

    __slots__ = ("bounded", "drift", "error_estimate", "order", "probe_length", "step")


def _check_rtol(rtol: float) -> float:
    try:
        value = float(rtol)
    except (TypeError, ValueError):
        value = np.nan
    if isinstance(rtol, bool) or not (np.isfinite(value) and value > 0):
        msg = f"expected a positive finite rtol, got {rtol!r}"
        raise ValueError(msg)
    if value < SMALLEST_RTOL:
        msg = f"expected an rtol of at least {SMALLEST_RTOL:g} (the momentum's round-off), got {rtol!r}"
        raise ValueError(msg)
    if value > LARGEST_RTOL:
        msg = f"expected an rtol of at most {LARGEST_RTOL:g} (a relative error of the momentum), got {rtol!r}"
        raise ValueError(msg)
    return value


def _periods(kicks: list[Perturbation], frames: list[Perturbation]) -> list[float]:
    """The orbital periods of the perturbers and the periods of the frames' rotations (at ``t = 0``)."""
    periods = []
    for kick in kicks:
        for mass, _ in kick.point_masses() if kick.tabulable else ():
            motion = abs(float(getattr(mass.orbit, "mean_motion", 0.0)))
            if motion > 0:
                periods.append(2 * np.pi / motion)
    for frame in frames:
        rate = float(np.linalg.norm(np.asarray(frame.frame_rate(np.asarray(0.0)), dtype=float)))
        if rate > 0:
            periods.append(2 * np.pi / rate)
    return periods


def _frequencies(model: Model, m: Array, periods: list[float]) -> Array:
    r"""The angular frequencies of the kicks' variation: their resonances are what the step avoids.

    The spin rates ``ω = |I⁻¹ m|`` of the states and their harmonic ``2ω`` (the quadrupole
    torque of a triaxial body), ``2ω ± 2n`` for each forcing frequency ``n = 2π/P``, and the
    harmonics ``k n``, ``k ≤ 4``, of the forcings (the quadrupole's ``2n`` and the
    eccentricity's neighbours).
    """
    spins = np.unique(np.linalg.norm(m / model.body.moments, axis=-1))
    forcing = 2 * np.pi / np.array(periods, dtype=np.float64)
    beats = [(2 * spins[:, None] + sign * 2 * forcing[None, :]).ravel() for sign in (1.0, -1.0)]
    parts = [spins, 2 * spins, np.outer(forcing, np.arange(1, 5)).ravel(), *beats]
    values = np.abs(np.concatenate(parts))
    return values[values > 0]


def _torque_sizes(kicks: list[Perturbation], t0: float, q: Array, m: Array) -> Array:
    """``max |τ(t₀)|`` of each state (S,) over its attitude turned about the body axes.

    The torque is taken at the states' attitudes and at those turned by a quarter and an
    eighth of a turn about each body axis, so that an attitude where it happens to vanish
    does not hide it.
    """
    turns = [np.array([0.0, 0.0, 0.0, 1.0])]
    halves = (0.125 * np.pi, 0.25 * np.pi)  # half the angles of an eighth and a quarter turn
    turns += [np.append(np.sin(half) * axis, np.cos(half)) for half in halves for axis in np.eye(3)]
    size = np.zeros(m.shape[0])
    # a torque beyond the floats is judged by the caller (an infinite size), not warned here
    with np.errstate(over="ignore", invalid="ignore"):
        for turn in turns:
            attitude = quat.multiply(q, np.broadcast_to(turn, q.shape))
            torque = np.zeros_like(m)
            for kick in kicks:
                torque = torque + np.asarray(kick.kick(np.asarray(t0), attitude, m), dtype=np.float64)
            size = np.maximum(size, np.linalg.norm(torque, axis=-1))
    return size


def _slow_period(size: Array, m: Array) -> float:
    """``2π |M| / max |τ(t₀)|``, the shortest over the states: the time scale of the momentum's motion.

    ``size`` is :func:`_torque_sizes`. (A frame turns ``M`` at its rate ``|μ|``: its period
    is a forcing period.)
    """
    rates = size / np.linalg.norm(m, axis=-1)
    return float(2 * np.pi / np.max(rates)) if np.any(rates > 0) else math.inf


def _torque_period(size: Array, m: Array, moments: Array) -> float:
    r"""The longest time scale the torque can set, shortest over the states: no step can exceed it.

    ``2π max(|M| / |τ|, \sqrt{I_max / |τ|})``: the period of the momentum's turn under the
    torque (a fast top) or of the swing that the torque drives from rest (a pendulum),
    whichever is longer. A splitting step longer than it leaves no digit of the motion.
    """
    if np.any(np.isnan(size)):
        msg = "expected a torque that is a number at the initial states, got nan"
        raise ValueError(msg)
    pushed = size > 0
    safe = np.where(pushed, size, 1.0)
    turn = np.where(pushed, np.linalg.norm(m, axis=-1) / safe, math.inf)
    swing = np.where(pushed, np.sqrt(float(np.max(moments)) / safe), math.inf)
    return float(2 * np.pi * np.min(np.maximum(turn, swing), initial=math.inf))


def _first_step(kicks: list[Perturbation], frames: list[Perturbation], span: float) -> float:
    """A quarter of the shortest period of the perturbers' orbits and the frames, at most ``span / 4``.

    The splitting's error comes from the kicks' variation along the orbits (the free flow is
    exact), so a step of a quarter orbit is the largest worth trying.
    """
    return min([span / 4.0] + [0.25 * period for period in _periods(kicks, frames)])


def _controlled(
    model: Model, state: State, t: ArrayLike, step: float | None, order: int | None, t0: float, rtol: float
) -> SplittingState:
    """:func:`integrate_splitting` at the order and step chosen by the probe (:mod:`.probe`)."""
    rtol = _check_rtol(rtol)
    if order is not None:
        splitting_coefficients(order)
    if step is not None and not (np.isfinite(step) and step > 0):
        msg = f"expected a positive finite step, got {step!r}"
        raise ValueError(msg)
    kicks, frames = splitting_parts(model)
    t0 = float(as_finite(t0, "t0"))
    times = as_finite(t, "t").ravel()
    ahead = float(np.max(times, initial=t0)) - t0
    behind = t0 - float(np.min(times, initial=t0))
    span = max(ahead, behind)
    if span == 0:
        out = integrate_splitting(model, state, t, 1.0, order or 2, t0)
        return _estimated(out, Choice(order or 2, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0))
    direction = 1.0 if ahead >= behind else -1.0
    tables = {k: _Tables(kicks, frames, k) if _tabulable(kicks) else None for k in COMPOSITIONS}
    q0 = np.ascontiguousarray(state.quaternion.reshape(-1, 4), dtype=np.float64)
    m0 = np.ascontiguousarray(state.m_body.reshape(-1, 3), dtype=np.float64)
    scale = np.linalg.norm(m0, axis=-1)[:, None]
    spent = 0.0  # estimated seconds of the probe's runs so far: the ladder's total is bounded too

    def run(k: int, h: float, probe: Array) -> Array:
        nonlocal spent
        every = max(1, round(float(probe[0]) / h))
        marks = every * np.arange(1, probe.size + 1)
        n = q0.shape[0]
        fixed, per_state = _PYTHON_SUBSTEP_SECONDS
        steps = float(marks[-1]) * len(COMPOSITIONS[k]) * n
        step_seconds = STEP_SECONDS if tables[k] is not None else fixed / n + per_state
        check_size("the splitting's probe", steps=steps, step_seconds=step_seconds, seconds=spent)
        spent += steps * step_seconds
        q, m = _run_steps(model, tables[k], q0, m0, t0, direction * h, int(marks[-1]), 0.0, k, record=marks)
        return quat.rotate(q, m) / scale

    periods = _periods(kicks, frames)
    first = _first_step(kicks, frames, span) if step is None else float(step)
    orders = tuple(COMPOSITIONS) if order is None else (order,)
    stages = {k: len(COMPOSITIONS[k]) for k in COMPOSITIONS}
    frequencies = _frequencies(model, m0, periods)
    longest = max(periods, default=0.0)
    sizes = _torque_sizes(kicks, t0, q0, m0)
    slow = _slow_period(sizes, m0)
    # a torque too strong for any step over the span is refused before the probe tries 24 halvings
    resolved = _torque_period(sizes, m0, model.body.moments)
    needed = (span / resolved if resolved > 0 else math.inf) * min(stages.values()) * q0.shape[0]
    if not needed <= MAX_STEPS:
        msg = (
            f"expected a torque whose time scale a splitting run over a span of {span:.3g} resolves "
            f"in at most {MAX_STEPS:.3g} steps, got a time scale of {resolved:.3g} "
            f"(torque up to {np.max(sizes):.3g}): {needed:.3g} steps"
        )
        raise ValueError(msg)
    choice, met = choose(run, rtol, span, first, orders, stages, longest, slow, frequencies, MAX_HALVINGS)
    if not met:
        msg = (
            f"the splitting met no rtol of {rtol:.3g} down to a step of {choice.step:.3g}: "
            f"estimated error {choice.error:.3g}"
        )
        warnings.warn(msg, ToleranceWarning, stacklevel=caller_stacklevel())
    out = integrate_splitting(model, state, t, choice.step, choice.order, t0)
    return _estimated(out, choice)


def _estimated(out: State, choice: Choice) -> SplittingState:
    result = SplittingState.from_unit_quaternion(out.quaternion, out.m_body)
    result.error_estimate, result.step, result.order = choice.error, choice.step, choice.order
    result.bounded, result.drift, result.probe_length = choice.bounded, choice.drift, choice.probe_length
    return result


def integrate_splitting(
    model: Model,
    state: State,
    t: ArrayLike,
    step: float | None = None,
    order: int | None = None,
    t0: float = 0.0,
    rtol: float | None = None,
) -> State:
    """Propagate ``state`` (at ``t0``) under ``model`` to times ``t`` by symmetric splitting.

    Fixed steps of length ``step`` on the grid ``t0 ± k·step``, each a composition of Strang
    steps ``V(h/2) ∘ F(h) ∘ T(h) ∘ V(h/2)`` of order 2, 4 or 6; an output time between grid
    points is reached by one shorter step from the grid point before it, and the run goes on
    from that grid point (the output times do not change the run). Gravity-gradient,
    heavy-top and precessing-frame models run in a compiled loop when numba is
    installed (:mod:`andoyer.integrate.splitting.kernel`); other attitude-only models and
    the no-numba case step through :func:`split_step`. The output broadcasts the
    state's shape with ``t``'s.

    Parameters
    ----------
    model : Model
        Body plus attitude-only Hamiltonian models and/or precessing frames.
    state : State, shape (S...)
    t : array_like, shape (T...)
    step : float, optional
        Step length (> 0, at most the torque's time scale ``2π max(|M|/|τ|, √(I_max/|τ|))``
        at the start): without ``rtol`` the run takes it. With ``rtol``, the first step
        tried (default: a quarter of the shortest orbital period of the perturbers and of the
        frames' rotation, at most a quarter of the span).
    order : {2, 4, 6}, optional
        With a step, default 4. With ``rtol``, the order is chosen among 2, 4 and 6 unless given.
    t0 : float
    rtol : float, optional
        The relative error wanted in the reference-frame angular momentum ``M`` over the
        outputs, ``max |M − M_exact| / |M(t₀)|`` (from 1e-13 to 0.1; default
        :data:`DEFAULT_RTOL` when no step is given either). Short probe runs at ``h`` and
        ``h/2`` give the estimate ``E(h, T) = 2 (B + D max(T − L, 0))`` of the error of a run
        at ``h`` over a span ``T`` (``B`` the largest distance ``|M_h − M_{h/2}| / |M(t₀)|``
        over a probe of length ``L``, ``D`` its fitted drift); the order and step of least
        cost with ``E ≤ rtol`` are run once. The model, its assumptions and where it fails:
        :mod:`andoyer.integrate.splitting.probe`. The spin phase is not in the estimate.
        A torque whose time scale ``2π max(|M|/|τ|, √(I_max/|τ|))`` would take more than
        ``MAX_STEPS`` steps over the span is refused before the probe, and the probe's runs
        together are held to the time limit of one run.

    Returns
    -------
    State, shape broadcast(S..., T...)
        A :class:`SplittingState` (the estimate, the order and step chosen) unless a step
        alone was given.

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> from andoyer.perturbations import HeavyTop
    >>> model = Model(RigidBody(1.0, 1.2, 1.5), HeavyTop(1.0, [0.0, 0.0, 0.1]))
    >>> s = State.from_quaternion([0.0, 0.0, 0.0, 1.0], [0.0, 0.0, 5.0])
    >>> out = integrate_splitting(model, s, [0.0, 1.0], step=0.05)
    >>> out.shape, out.m_body[1].round(12).tolist()  # upright spinning top: steady
    ((2,), [0.0, 0.0, 5.0])
    >>> tilted = State.from_quaternion([0.1, 0.0, 0.0, 0.99498743710662], [0.0, 0.0, 5.0])
    >>> out = integrate_splitting(model, tilted, [0.0, 1.0], rtol=1e-8)
    >>> bool(out.error_estimate <= 1e-8), out.order, round(out.step, 4)
    (True, 4, 0.0625)
    """
    if not isinstance(model, Model):
        msg = f"expected an andoyer Model, got {type(model).__name__}"
        raise ValueError(msg)
    if rtol is not None or step is None:
        return _controlled(model, state, t, step, order, t0, DEFAULT_RTOL if rtol is None else rtol)
    if not (np.isfinite(step) and step > 0):
        msg = f"expected a positive finite step, got {step!r}"
        raise ValueError(msg)
    order = 4 if order is None else order
    splitting_coefficients(order)
    kicks, frames = splitting_parts(model)
    tables = _Tables(kicks, frames, order) if _tabulable(kicks) else None
    t0 = float(as_finite(t0, "t0"))
    times, unique, shape = output_times(state, t, model.body.moments, t0)
    q0 = state.quaternion.reshape(-1, 4)
    m0 = state.m_body.reshape(-1, 3)
    resolved = _torque_period(_torque_sizes(kicks, t0, q0, m0), m0, model.body.moments)
    if not step <= resolved:
        msg = (
            f"expected a step of at most the torque's time scale 2π max(|M|/|τ|, √(I_max/|τ|)) = "
            f"{resolved:.3g} (a longer one leaves no digit of the motion), got {step!r}"
        )
        raise ValueError(msg)
    steps = _count_steps(unique, t0, step)
    n = max(q0.shape[0], 1)
    fixed, per_state = _PYTHON_SUBSTEP_SECONDS
    check_size(
        "a splitting run",
        steps=steps * len(COMPOSITIONS[order]) * n,
        step_seconds=STEP_SECONDS if tables is not None else fixed / n + per_state,
    )
    values: dict[float, tuple[Array, Array]] = {}
    with progress(math.ceil(steps), "splitting") as bar:
        for direction in (1.0, -1.0):
            targets = np.sort(unique[(unique - t0) * direction > 0])[:: int(direction)]
            if targets.size:
                values.update(_outputs(model, tables, q0, m0, t0, direction * step, targets, order, bar))
    for time in unique:
        if time == t0:
            values[float(time)] = (q0, m0)
    return gather_states(state, times, unique, shape, values)
