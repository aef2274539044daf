"""The completed-chunk ledger: a checksum per chunk, written after the chunk, verified before resuming.

Chunk ``k`` of a store counts as done only if its ledger entry ``chunk_digest[k]`` is set
(not all zero) **and** the chunk's values read back from the store hash to that entry.
The digest is SHA-256 over every variable of the chunk in name order, each as its name,
its shape and its values as little-endian float64 bytes:

    digest_k = SHA256( ‖_{name sorted} name · shape · bytes_LE(values[k·chunk : (k+1)·chunk]) )

so a deleted chunk file (read back as the NaN fill value), garbled or truncated bytes, a
chunk moved to another place, or a damaged ledger entry all fail the check, and the chunk
is computed again (its numbers depend on ``(seed, chunk size, k)`` only, so the repaired
store is identical bit for bit to an undamaged one). SHA-256 rather than BLAKE2b: with
the processors' SHA extensions it hashes about 2 GB/s against 1.5 GB/s (measured on the
development machine), about 3 % of a worker's time per chunk of the free flow.
"""

from __future__ import annotations

import hashlib
from collections.abc import Callable, Mapping
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from andoyer.ensemble.layout import LEDGER

__all__ = [
    "DIGEST_SIZE",
    "LedgerCheck",
    "check_ledger",
    "chunk_digest",
    "digests_from_hex",
    "digests_to_hex",
    "verify",
]

DIGEST_SIZE = 32


def chunk_digest(arrays: Mapping[str, NDArray[np.float64]]) -> NDArray[np.uint8]:
    """The ledger entry of one chunk: SHA-256 of its variables (name, shape, little-endian values).

    Parameters
    ----------
    arrays : mapping of str to ndarray
        Every variable of the chunk, leading axis its samples.

    Returns
    -------
    ndarray of uint8, shape (32,)

    Examples
    --------
    >>> import numpy as np
    >>> a = chunk_digest({"x": np.arange(3.0), "y": np.ones((3, 2))})
    >>> a.shape, bool((a == chunk_digest({"y": np.ones((3, 2)), "x": np.arange(3.0)})).all())
    ((32,), True)
    >>> bool((a == chunk_digest({"x": np.arange(3.0), "y": np.zeros((3, 2))})).all())
    False
    """
    h = hashlib.sha256()
    for name in sorted(arrays):
        values = np.ascontiguousarray(arrays[name], dtype="<f8")
        h.update(f"{name}{values.shape}".encode())
        h.update(values)
    return np.frombuffer(h.digest(), dtype=np.uint8)


def digests_to_hex(entries: NDArray[np.uint8]) -> str:
    """Ledger entries (n_chunks, 32) as one line of space-separated hexadecimal digests."""
    return " ".join(bytes(row).hex() for row in np.asarray(entries, dtype=np.uint8))


def digests_from_hex(text: str, n_chunks: int) -> NDArray[np.uint8]:
    """Inverse of :func:`digests_to_hex`; an entry that does not parse reads as unset (zeros)."""
    entries = np.zeros((n_chunks, DIGEST_SIZE), dtype=np.uint8)
    words = text.split() if isinstance(text, str) else []
    for k, word in enumerate(words[:n_chunks]):
        try:
            raw = bytes.fromhex(word)
        except ValueError:
            continue
        if len(raw) == DIGEST_SIZE:
            entries[k] = np.frombuffer(raw, dtype=np.uint8)
    return entries


@dataclass(frozen=True)
class LedgerCheck:
    """What a store's ledger says, checked against its data.

    Attributes
    ----------
    done : ndarray of bool, shape (n_chunks,)
        Ledger entry set and matching the data read back.
    damaged : tuple of int
        Chunks whose entry is set but does not match (or cannot be read, or whose data
        cannot be read); in a finished store also the chunks with no entry.
    """

    done: NDArray[np.bool_]
    damaged: tuple[int, ...]


def _read_ledger(group, n_chunks: int) -> tuple[NDArray[np.uint8], set[int]]:
    """The ledger entries, and the chunks whose entry cannot be read (a truncated file, ...)."""
    array = group[LEDGER]
    try:
        return np.asarray(array[:], dtype=np.uint8), set()
    except Exception:  # one bad entry spoils the bulk read: read them one by one
        entries = np.zeros((n_chunks, DIGEST_SIZE), dtype=np.uint8)
        rows = {k: _entry(array, k) for k in range(n_chunks)}
        for k, row in rows.items():
            if row is not None:
                entries[k] = row
        return entries, {k for k, row in rows.items() if row is None}


def _entry(array, k: int) -> NDArray[np.uint8] | None:
    try:
        return np.asarray(array[k], dtype=np.uint8)
    except Exception:  # any reason a ledger file does not decode: damage, recompute its chunk
        return None


def verify(
    entries: NDArray[np.uint8],
    read: Callable[[int], Mapping[str, NDArray[np.float64]]],
    finished: bool,
    unreadable: set[int] | None = None,
) -> LedgerCheck:
    """Check each chunk's values, ``read(k)``, against its ledger entry ``entries[k]``.

    Parameters
    ----------
    entries : ndarray of uint8, shape (n_chunks, 32)
        The ledger; an all-zero row is an unset entry.
    read : callable
        ``read(k)`` gives chunk ``k``'s variables; any exception means its data are damaged.
    finished : bool
        The store was marked finished: a chunk without a ledger entry is damage, not
        work still to do.
    unreadable : set of int, optional
        Chunks whose ledger entry could not be read.

    Returns
    -------
    LedgerCheck

    Examples
    --------
    >>> import numpy as np
    >>> chunks = [{"x": np.full(2, float(k))} for k in range(3)]
    >>> entries = np.stack([chunk_digest(c) for c in chunks])
    >>> entries[2] = 0  # never written
    >>> chunks[0]["x"][1] = np.nan  # damaged after its entry was written
    >>> check = verify(entries, chunks.__getitem__, finished=False)
    >>> check.done.tolist(), check.damaged
    ([False, True, False], (0,))
    """
    unreadable = unreadable or set()
    n_chunks = entries.shape[0]
    done = np.zeros(n_chunks, dtype=bool)
    damaged = set(unreadable)
    for k in range(n_chunks):
        if k in unreadable:
            continue
        if not entries[k].any():
            if finished:
                damaged.add(k)
            continue
        try:
            values = read(k)
        except Exception:  # a truncated or replaced chunk file: damage, recompute it
            damaged.add(k)
            continue
        if np.array_equal(chunk_digest(values), entries[k]):
            done[k] = True
        else:
            damaged.add(k)
    return LedgerCheck(done, tuple(sorted(damaged)))


def check_ledger(group, finished: bool) -> LedgerCheck:
    """Verify every chunk of an open Zarr ensemble store against its ledger (see :func:`verify`).

    Parameters
    ----------
    group : zarr.Group
        An ensemble store: data variables whose first chunk size is the ensemble chunk,
        ``time``, and the ledger.
    finished : bool
        The store was marked finished.

    Returns
    -------
    LedgerCheck
    """
    n_chunks = group[LEDGER].shape[0]
    entries, unreadable = _read_ledger(group, n_chunks)
    arrays = {name: group[name] for name in group.array_keys() if name not in (LEDGER, "time")}
    first = next(iter(arrays.values()))
    n_samples, chunk = first.shape[0], first.chunks[0]

    def read(k: int) -> dict[str, NDArray[np.float64]]:
        region = slice(k * chunk, min((k + 1) * chunk, n_samples))
        return {name: a[region] for name, a in arrays.items()}

    return verify(entries, read, finished, unreadable)
