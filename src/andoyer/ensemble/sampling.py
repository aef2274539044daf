"""Seeded sampling of initial conditions and parameters, reproducible chunk by chunk.

Chunk ``k`` of an ensemble draws its samples from its own generator,
``chunk_rng(seed, k)``, so its numbers depend on ``(seed, chunk size, k)`` only:
never on the number of workers, on the order in which chunks run, or on which
chunks an interrupted run had already written.

A sampler is any object with a method ``sample(rng, n)`` returning ``n`` states
(a :class:`~andoyer.State` of shape ``(n,)``) or a :class:`Draw` (states plus
per-sample parameters handed to the propagator as keyword arguments).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import NamedTuple, Protocol, runtime_checkable

import numpy as np
from numpy.typing import NDArray

from andoyer._validation import describe
from andoyer.state import State

__all__ = ["AndoyerSampler", "Draw", "InertiaSampler", "MomentumSampler", "Sampler", "chunk_rng"]

TWO_PI = 2.0 * np.pi
_MAX_ROUNDS = 200  # rejection rounds before a nearly infeasible box of moments is reported


class Draw(NamedTuple):
    """``n`` initial states and their per-sample parameters.

    Attributes
    ----------
    state : State, shape (n,)
    parameters : mapping of str to ndarray, each of shape (n, ...)
        Passed to the propagator as keyword arguments and stored in the ensemble.
    """

    state: State
    parameters: Mapping[str, NDArray[np.float64]]


@runtime_checkable
class Sampler(Protocol):
    """What the ensemble runner needs from a sampler."""

    def sample(self, rng: np.random.Generator, n: int) -> State | Draw:
        """Draw ``n`` samples from ``rng``."""
        ...  # pragma: no cover - protocol


def chunk_rng(seed: int, index: int) -> np.random.Generator:
    """The generator of chunk ``index`` of an ensemble seeded with ``seed``.

    It is ``SeedSequence(seed).spawn(index + 1)[index]`` (a ``SeedSequence`` with
    ``spawn_key=(index,)``): independent streams per chunk, identical on every
    machine and for any number of workers.

    Parameters
    ----------
    seed : int
        Non-negative ensemble seed.
    index : int
        Non-negative chunk index.

    Returns
    -------
    numpy.random.Generator

    Examples
    --------
    >>> import numpy as np
    >>> a = chunk_rng(7, 3).random(2)
    >>> b = np.random.default_rng(np.random.SeedSequence(7).spawn(4)[3]).random(2)
    >>> bool((a == b).all())
    True
    """
    for name, value in (("seed", seed), ("chunk index", index)):
        if isinstance(value, bool) or not isinstance(value, int | np.integer) or value < 0:
            msg = f"expected a non-negative integer {name}, got {value!r}"
            raise ValueError(msg)
    return np.random.default_rng(np.random.SeedSequence(int(seed), spawn_key=(int(index),)))


def _interval(value: object, name: str, lo: float = -np.inf, hi: float = np.inf) -> tuple[float, float]:
    arr = np.asarray(value, dtype=float) if np.ndim(value) else np.array([value, value], dtype=float)
    if arr.shape != (2,) or not np.isfinite(arr).all() or arr[0] > arr[1] or arr[0] < lo or arr[1] > hi:
        msg = f"expected {name} as a finite (low, high) pair with {lo} <= low <= high <= {hi}, got {value!r}"
        raise ValueError(msg)
    return float(arr[0]), float(arr[1])


def _box(value: object, name: str) -> tuple[float, float, float]:
    arr = np.asarray(value, dtype=float)
    if arr.shape != (3,) or not np.isfinite(arr).all():
        msg = f"expected {name} as three finite numbers, got {describe(value)}"
        raise ValueError(msg)
    return (float(arr[0]), float(arr[1]), float(arr[2]))


def _check_n(n: int) -> int:
    if isinstance(n, bool) or not isinstance(n, int | np.integer) or n < 0:
        msg = f"expected a non-negative integer number of samples, got {n!r}"
        raise ValueError(msg)
    return int(n)


@dataclass(frozen=True)
class AndoyerSampler:
    r"""Andoyer variables drawn uniformly, each within its own range.

    ``l, g, h`` uniform in their intervals (default the full circle),
    ``G`` uniform in its interval, ``L = G cos J`` and ``H = G cos I`` with
    ``cos J`` and ``cos I`` uniform in theirs. With the defaults the momentum
    direction is uniform on the sphere both in the body frame and in the
    reference frame (uniform ``cos J`` with uniform ``l``; uniform ``cos I``
    with uniform ``h``).

    Parameters
    ----------
    G : float or (low, high)
        Magnitude of the angular momentum, ``0 < low``.
    cos_J : (low, high)
        ``L/G``, within ``[-1, 1]``.
    cos_I : (low, high)
        ``H/G``, within ``[-1, 1]``.
    l, g, h : (low, high)
        Angles in radians.

    Examples
    --------
    >>> s = AndoyerSampler(G=(1.0, 2.0), cos_J=(0.9, 1.0)).sample(chunk_rng(0, 0), 5)
    >>> s.shape
    (5,)
    >>> a = s.as_andoyer()
    >>> bool(((a.G >= 1.0) & (a.G <= 2.0) & (a.L >= 0.9 * a.G)).all())
    True
    """

    G: tuple[float, float] = (1.0, 1.0)
    cos_J: tuple[float, float] = (-1.0, 1.0)
    cos_I: tuple[float, float] = (-1.0, 1.0)
    l: tuple[float, float] = (0.0, TWO_PI)
    g: tuple[float, float] = (0.0, TWO_PI)
    h: tuple[float, float] = (0.0, TWO_PI)

    def __post_init__(self) -> None:
        G = _interval(self.G, "G")
        if G[0] <= 0:
            msg = f"expected G > 0, got the range {self.G!r}"
            raise ValueError(msg)
        object.__setattr__(self, "G", G)
        for name in ("cos_J", "cos_I"):
            object.__setattr__(self, name, _interval(getattr(self, name), name, -1.0, 1.0))
        for name in ("l", "g", "h"):
            object.__setattr__(self, name, _interval(getattr(self, name), name))

    def sample(self, rng: np.random.Generator, n: int) -> State:
        """``n`` states, shape (n,), from ``rng.random((n, 6))`` (columns l, g, h, G, cos J, cos I)."""
        u = rng.random((_check_n(n), 6))
        lo = np.array([self.l[0], self.g[0], self.h[0], self.G[0], self.cos_J[0], self.cos_I[0]])
        hi = np.array([self.l[1], self.g[1], self.h[1], self.G[1], self.cos_J[1], self.cos_I[1]])
        x = lo + (hi - lo) * u
        G = x[:, 3]
        return State.from_andoyer(x[:, 0], x[:, 1], x[:, 2], G * x[:, 4], G, G * x[:, 5])


@dataclass(frozen=True)
class MomentumSampler:
    """Body angular momenta uniform in a box and attitudes uniform on SO(3).

    Attitudes are normalised standard-normal quaternions (Haar measure on SO(3)).

    Parameters
    ----------
    low, high : sequence of 3 floats
        Corners of the box of ``m_body`` components, ``low <= high``.

    Examples
    --------
    >>> s = MomentumSampler(low=(0.0, 0.0, 1.0), high=(0.1, 0.1, 1.0)).sample(chunk_rng(0, 0), 4)
    >>> s.m_body[:, 2].tolist()
    [1.0, 1.0, 1.0, 1.0]
    """

    low: tuple[float, float, float] = (-1.0, -1.0, -1.0)
    high: tuple[float, float, float] = (1.0, 1.0, 1.0)

    def __post_init__(self) -> None:
        low, high = _box(self.low, "low"), _box(self.high, "high")
        if any(a > b for a, b in zip(low, high, strict=True)):
            msg = f"expected low <= high component by component, got low={low!r}, high={high!r}"
            raise ValueError(msg)
        object.__setattr__(self, "low", low)
        object.__setattr__(self, "high", high)

    def sample(self, rng: np.random.Generator, n: int) -> State:
        """``n`` states, shape (n,): ``rng.random((n, 3))`` momenta, then ``rng.standard_normal((n, 4))``."""
        n = _check_n(n)
        low, high = np.array(self.low), np.array(self.high)
        m = low + (high - low) * rng.random((n, 3))
        q = rng.standard_normal((n, 4))
        q /= np.linalg.norm(q, axis=-1, keepdims=True)
        return State.from_quaternion(q, m)


@dataclass(frozen=True)
class InertiaSampler:
    """Monte-Carlo over the body too: principal moments drawn per sample, beside the states.

    The moments ``(I1, I2, I3)`` are uniform in the box ``[low, high]``,
    conditioned on the triangle inequality (rejected draws are redrawn from
    the same generator). They reach the propagator as the keyword argument
    ``moments`` (shape (n, 3)) and are stored as the ensemble variable
    ``moments``.

    Parameters
    ----------
    states : Sampler
        Draws the initial states (first, from the same generator).
    low, high : sequence of 3 floats
        Box of the moments, ``0 < low <= high``.

    Examples
    --------
    >>> d = InertiaSampler(AndoyerSampler(), (0.5, 0.9, 1.0), (0.6, 1.0, 1.2)).sample(chunk_rng(1, 0), 3)
    >>> d.state.shape, d.parameters["moments"].shape
    ((3,), (3, 3))
    """

    states: Sampler = field(default_factory=AndoyerSampler)
    low: tuple[float, float, float] = (1.0, 1.0, 1.0)
    high: tuple[float, float, float] = (1.0, 1.0, 1.0)

    def __post_init__(self) -> None:
        low, high = _box(self.low, "low"), _box(self.high, "high")
        if any(a > b or a <= 0 for a, b in zip(low, high, strict=True)):
            msg = f"expected 0 < low <= high component by component, got low={low!r}, high={high!r}"
            raise ValueError(msg)
        if any(low[k] > high[k - 1] + high[k - 2] for k in range(3)):
            msg = f"expected a box of moments that meets the triangle inequality, got {low!r} to {high!r}"
            raise ValueError(msg)
        if not isinstance(self.states, Sampler):
            msg = f"expected a sampler with a sample(rng, n) method, got {type(self.states).__name__}"
            raise ValueError(msg)
        object.__setattr__(self, "low", low)
        object.__setattr__(self, "high", high)

    def sample(self, rng: np.random.Generator, n: int) -> Draw:
        """``n`` states from ``states`` then ``n`` admissible moment triples, shape (n, 3)."""
        n = _check_n(n)
        state = self.states.sample(rng, n)
        if isinstance(state, Draw):
            msg = "expected InertiaSampler.states to draw plain states, got a Draw with parameters"
            raise ValueError(msg)
        low, high = np.array(self.low), np.array(self.high)
        moments = np.empty((n, 3))
        todo = np.arange(n)
        for _ in range(_MAX_ROUNDS):
            if not todo.size:
                break
            trial = low + (high - low) * rng.random((todo.size, 3))
            s = np.sort(trial, axis=-1)
            ok = s[:, 0] + s[:, 1] >= s[:, 2]
            moments[todo[ok]] = trial[ok]
            todo = todo[~ok]
        if todo.size:
            msg = (
                f"expected a box of moments where the triangle inequality holds often, got {todo.size} "
                f"of {n} draws still rejected after {_MAX_ROUNDS} rounds"
            )
            raise ValueError(msg)
        return Draw(state, {"moments": moments})
