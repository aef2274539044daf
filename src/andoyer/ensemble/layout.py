"""What an ensemble is (its settings), how one chunk is computed, and its xarray layout.

Dataset layout (dimensions ``sample``, ``time``, ``component``/``axis``):

* ``time`` (time): the epochs, a coordinate;
* output ``"state"``: ``quaternion`` (sample, time, quaternion_component = x, y, z, w, scalar
  last, body → reference) and ``m_body`` (sample, time, axis = b1, b2, b3);
  output ``"andoyer"``: ``l, g, h, L, G, H`` (sample, time); output ``"euler"``:
  ``phi, theta, psi, Phi, Theta, Psi`` (sample, time); output ``"obliquity"``: ``obliquity``
  (sample, time, radians), from a propagator that returns it by name (a mapping, not a State:
  a member that stopped has ``NaN`` there, which no State holds);
* the initial states ``quaternion0`` (sample, quaternion_component) and ``m_body0`` (sample, axis);
* the sampler's per-sample parameters under their own names (sample, ...), e.g. ``moments``
  (sample, axis);
* in a Zarr store, the ledger ``chunk_digest`` (chunk, digest_byte): the checksum of chunk
  ``k``'s values once it is written, zeros before (see :mod:`andoyer.ensemble.ledger`); in a
  NetCDF file the same digests as the attribute ``andoyer_chunk_digests``.
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from andoyer.ensemble.sampling import Draw, Sampler, chunk_rng
from andoyer.state import State

__all__ = [
    "LEDGER",
    "OUTPUTS",
    "EnsembleSpec",
    "compute_chunk",
    "dataset_from_arrays",
    "describe_object",
]

Arrays = dict[str, NDArray[np.float64]]
QUAT_DIM = "quaternion_component"
AXIS_DIM = "axis"
#: The ledger variable of a Zarr store: one checksum per chunk.
LEDGER = "chunk_digest"

#: Output charts: name → function of a State (n, T) giving {variable: array (n, T, ...)}.
OUTPUTS: dict[str, Callable[[State], Arrays]] = {
    "state": lambda s: {"quaternion": s.quaternion, "m_body": s.m_body},
    "andoyer": lambda s: dict(s.as_andoyer()._asdict()),
    "euler": lambda s: dict(s.as_euler()._asdict()),
    "obliquity": lambda s: {"obliquity": s.as_euler().theta},
}
OUTPUT_VARIABLES: dict[str, tuple[str, ...]] = {
    "state": ("quaternion", "m_body"),
    "andoyer": ("l", "g", "h", "L", "G", "H"),
    "euler": ("phi", "theta", "psi", "Phi", "Theta", "Psi"),
    "obliquity": ("obliquity",),
}

# ~15 MB of output and ~0.25 s of free-flow work per chunk: enough chunks for a few workers to
# finish together (the last chunk is the only idle time), few enough that the ~5 ms of Dask
# overhead per chunk stays near 2 %.
DEFAULT_PAIRS_PER_CHUNK = 2**18


def describe_object(obj: object) -> str:
    """A stable text description of a sampler or propagator (its repr without memory addresses).

    Examples
    --------
    >>> describe_object(lambda s, t: s).startswith("<function <lambda>")
    True
    >>> "0x" in describe_object(object())
    False
    """
    return re.sub(r" at 0x[0-9a-fA-F]+", "", repr(obj))


def _trailing_dim(name: str, size: int) -> str:
    if size == 4 and "quaternion" in name:
        return QUAT_DIM
    if size == 3:
        return AXIS_DIM
    return f"{name}_component"


def dims_of(name: str, shape: tuple[int, ...], leading: tuple[str, ...]) -> tuple[str, ...]:
    """Dimension names of a variable whose leading axes are ``leading``."""
    rest = shape[len(leading) :]
    return (*leading, *(_trailing_dim(name, n) if i == 0 else f"{name}_dim{i}" for i, n in enumerate(rest)))


@dataclass(frozen=True)
class EnsembleSpec:
    """The settings that determine every number of an ensemble.

    Parameters
    ----------
    sampler : Sampler
        Draws the initial states (and parameters) of each chunk.
    propagator : callable
        ``(state (n,), times (T,), **parameters) -> State (n, T)``.
    n_samples : int
    times : ndarray, shape (T,)
    chunk : int
        Samples per chunk.
    seed : int
    output : {"state", "andoyer", "euler", "obliquity"}
    """

    sampler: Sampler
    propagator: Callable[..., State]
    n_samples: int
    times: NDArray[np.float64]
    chunk: int
    seed: int
    output: str = "state"

    @classmethod
    def build(
        cls,
        sampler: Sampler,
        propagator: Callable[..., State],
        n_samples: int,
        times: Any,
        chunk: int | None = None,
        seed: int = 0,
        output: str = "state",
    ) -> EnsembleSpec:
        """Validated settings; ``chunk=None`` picks about 2¹⁸ (sample, epoch) pairs per chunk."""
        if not isinstance(sampler, Sampler):
            msg = f"expected a sampler with a sample(rng, n) method, got {type(sampler).__name__}"
            raise ValueError(msg)
        if not callable(propagator):
            msg = f"expected a callable propagator (state, times, **parameters) -> State, got {propagator!r}"
            raise ValueError(msg)
        try:
            t = np.array(times, dtype=np.float64, ndmin=1)
        except (TypeError, ValueError) as exc:
            msg = f"expected the times as real numbers, got {times!r}"
            raise ValueError(msg) from exc
        if t.ndim != 1 or t.size == 0 or not np.isfinite(t).all():
            msg = f"expected a non-empty one-dimensional array of finite times, got {t.tolist()!r}"
            raise ValueError(msg)
        for name, value in (("n_samples", n_samples), ("chunk", chunk), ("seed", seed)):
            if value is None and name == "chunk":
                continue
            bad = isinstance(value, bool) or not isinstance(value, int | np.integer)
            if bad or value < (0 if name == "seed" else 1):
                kind = "non-negative" if name == "seed" else "positive"
                msg = f"expected a {kind} integer {name}, got {value!r}"
                raise ValueError(msg)
        if chunk is None:
            chunk = max(1, DEFAULT_PAIRS_PER_CHUNK // t.size)
        if output not in OUTPUTS:
            msg = f"expected output in {sorted(OUTPUTS)}, got {output!r}"
            raise ValueError(msg)
        t.setflags(write=False)
        return cls(sampler, propagator, int(n_samples), t, int(min(chunk, n_samples)), int(seed), output)

    @property
    def n_chunks(self) -> int:
        """Number of chunks, ``ceil(n_samples / chunk)``."""
        return math.ceil(self.n_samples / self.chunk)

    def bounds(self, index: int) -> slice:
        """The samples of chunk ``index``."""
        return slice(index * self.chunk, min((index + 1) * self.chunk, self.n_samples))

    def fingerprint(self) -> dict[str, Any]:
        """JSON-able description checked before resuming (the times are compared separately)."""
        return {
            "format": "andoyer-ensemble/2",
            "n_samples": self.n_samples,
            "n_times": int(self.times.size),
            "chunk": self.chunk,
            "seed": self.seed,
            "output": self.output,
            "sampler": describe_object(self.sampler),
            "propagator": describe_object(self.propagator),
        }

    def attrs(self) -> dict[str, str]:
        """Dataset attributes recording the settings."""
        return {"andoyer_ensemble": json.dumps(self.fingerprint(), sort_keys=True)}


def compute_chunk(spec: EnsembleSpec, index: int) -> Arrays:
    """All the variables of chunk ``index``: sample, propagate, convert to the output chart.

    Returns
    -------
    dict of str to ndarray
        Every variable of the layout, leading axis the chunk's samples.
    """
    n = spec.bounds(index).stop - spec.bounds(index).start
    draw = spec.sampler.sample(chunk_rng(spec.seed, index), n)
    state, parameters = (draw.state, dict(draw.parameters)) if isinstance(draw, Draw) else (draw, {})
    if not isinstance(state, State) or state.shape != (n,):
        got = state.shape if isinstance(state, State) else type(state).__name__
        msg = f"expected the sampler to return a State of shape ({n},), got {got}"
        raise ValueError(msg)
    out = spec.propagator(state, spec.times, **parameters)
    want = (n, spec.times.size)
    if isinstance(out, Mapping) and set(out) == set(OUTPUT_VARIABLES[spec.output]):
        # The output's variables by name (values a State cannot hold, such as NaN).
        arrays: Arrays = {k: np.asarray(v, dtype=np.float64) for k, v in out.items()}
        if any(a.shape[:2] != want for a in arrays.values()):
            shapes = {k: a.shape for k, a in arrays.items()}
            msg = f"expected the propagator's arrays with leading shape {want}, got {shapes}"
            raise ValueError(msg)
    elif not isinstance(out, State) or out.shape != want:
        got = out.shape if isinstance(out, State) else type(out).__name__
        msg = f"expected the propagator to return a State of shape {want}, got {got}"
        raise ValueError(msg)
    else:
        arrays = {k: np.asarray(v, dtype=np.float64) for k, v in OUTPUTS[spec.output](out).items()}
    arrays["quaternion0"] = state.quaternion
    arrays["m_body0"] = state.m_body
    for name, given in parameters.items():
        if name in arrays or name in ("time", LEDGER):
            msg = f"expected sampler parameters not named like ensemble variables, got {name!r}"
            raise ValueError(msg)
        value = np.asarray(given, dtype=np.float64)
        if value.shape[:1] != (n,):
            msg = f"expected parameter {name!r} with leading axis {n}, got shape {value.shape}"
            raise ValueError(msg)
        arrays[name] = value
    return arrays


def variable_dims(spec: EnsembleSpec, name: str, shape: tuple[int, ...]) -> tuple[str, ...]:
    """Dimensions of variable ``name`` with full shape ``shape`` (leading axis: samples)."""
    leading = ("sample", "time") if name in OUTPUT_VARIABLES[spec.output] else ("sample",)
    return dims_of(name, shape, leading)


def dataset_from_arrays(spec: EnsembleSpec, arrays: Mapping[str, Any]):
    """An :class:`xarray.Dataset` from full arrays (numpy or dask) of every variable."""
    import xarray as xr

    data_vars = {name: (variable_dims(spec, name, tuple(a.shape)), a) for name, a in arrays.items()}
    return xr.Dataset(data_vars, coords={"time": ("time", np.array(spec.times))}, attrs=spec.attrs())
