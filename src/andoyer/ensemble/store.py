"""Resumable ensemble storage: a Zarr store written chunk by chunk, with a checksum ledger.

The store is created (metadata, the ``time`` coordinate, every variable filled
with NaN, an empty ledger) in a temporary directory renamed into place, so it
exists complete or not at all. Workers then write chunk ``k`` into its own region
— Zarr chunks are aligned with ensemble chunks, so no two workers touch one file,
and the local store replaces each file atomically — and only afterwards its ledger
entry, a checksum of the chunk's values (:mod:`andoyer.ensemble.ledger`).
Once every chunk is stored the group is marked finished. On a rerun a chunk counts
as done only if its entry is set and its data read back hash to it; anything else
is computed again (its region may be rewritten at will: the numbers depend on
``(seed, chunk size, k)`` only), with a :class:`DamagedChunkWarning` naming the
chunks that had been written and no longer match.

A NetCDF output is assembled at the end from such a store (``FILE.nc.parts.zarr``
beside it), with the digests as the attribute ``andoyer_chunk_digests``, written to
a temporary file and renamed: an interrupted NetCDF run resumes from the parts
store, and a damaged NetCDF file is rebuilt from its intact chunks.
"""

from __future__ import annotations

import contextlib
import dataclasses
import json
import os
import shutil
import stat
import uuid
from pathlib import Path
from typing import Any

import numpy as np

from andoyer._files import atomic_replace
from andoyer.ensemble.layout import LEDGER, Arrays, EnsembleSpec, compute_chunk, variable_dims
from andoyer.ensemble.ledger import (
    DIGEST_SIZE,
    LedgerCheck,
    check_ledger,
    chunk_digest,
    digests_from_hex,
    digests_to_hex,
    verify,
)

__all__ = [
    "DamagedChunkWarning",
    "check_netcdf",
    "check_store",
    "completed_chunks",
    "create_or_check_store",
    "finalize_netcdf",
    "mark_finished",
    "parts_path",
    "write_chunk",
]

FINISHED = "andoyer_finished"  # group attribute, set once every chunk is stored
DIGESTS_ATTR = "andoyer_chunk_digests"  # the ledger in a NetCDF file


class DamagedChunkWarning(UserWarning):
    """Chunks of an ensemble store were written but no longer match their checksum: recomputed."""


def parts_path(netcdf: Path) -> Path:
    """The Zarr store that holds the chunks of a NetCDF output until it is assembled."""
    return netcdf.with_name(netcdf.name + ".parts.zarr")


def variable_shapes(spec: EnsembleSpec) -> dict[str, tuple[int, ...]]:
    """Full shapes of every variable, from one sample of chunk 0 computed here."""
    probe = dataclasses.replace(spec, n_samples=1, chunk=1)
    return {name: (spec.n_samples, *a.shape[1:]) for name, a in compute_chunk(probe, 0).items()}


def _kind(mode: int) -> str:
    if stat.S_ISLNK(mode):
        return "symbolic link"
    if stat.S_ISDIR(mode):
        return "directory"
    if stat.S_ISREG(mode):
        return "regular file"
    return "special file (device, pipe or socket)"


def require_kind(path: Path, want: str) -> None:
    """``ValueError`` unless ``path`` is absent or (after following links) of kind ``want``."""
    with contextlib.suppress(FileNotFoundError):
        got = _kind(os.stat(path).st_mode)
        if got != want:
            msg = f"expected a {want} (or nothing) at the ensemble output {str(path)!r}, got a {got}"
            raise ValueError(msg)


def _create(path: Path, spec: EnsembleSpec, shapes: dict[str, tuple[int, ...]]) -> None:
    import zarr

    tmp = path.with_name(f".{path.name}.{uuid.uuid4().hex}.tmp")
    try:
        # Metadata only (plus the time coordinate): unwritten chunks read as the fill value,
        # NaN for data and 0 for the ledger. Written with zarr directly, in constant time:
        # xarray's lazy to_zarr built a Dask graph with a task per chunk and variable.
        group = zarr.create_group(tmp, zarr_format=3, attributes=spec.attrs())
        for name, shape in shapes.items():
            # Uncompressed: propagated states are incompressible floats (zstd saves ~6 %),
            # and compressing them cost about a fifth of a worker's time per chunk.
            group.create_array(
                name,
                shape=shape,
                chunks=(spec.chunk, *shape[1:]),
                dtype=np.float64,
                fill_value=np.nan,
                compressors=None,
                dimension_names=variable_dims(spec, name, shape),
            )
        group.create_array("time", data=np.array(spec.times), dimension_names=("time",))
        # One file per entry: each worker writes only its own chunks' entries.
        group.create_array(
            LEDGER,
            shape=(spec.n_chunks, DIGEST_SIZE),
            chunks=(1, DIGEST_SIZE),
            dtype=np.uint8,
            fill_value=0,
            compressors=None,
            dimension_names=("chunk", "digest_byte"),
        )
        os.rename(tmp, path)
    finally:
        if tmp.exists():
            shutil.rmtree(tmp, ignore_errors=True)


def _expected_arrays(spec: EnsembleSpec, shapes: dict[str, tuple[int, ...]]) -> dict[str, tuple[Any, ...]]:
    """(shape, first chunk size, dtype) of every array of the store of ``spec``."""
    want: dict[str, tuple[Any, ...]] = {n: (s, spec.chunk, np.dtype(np.float64)) for n, s in shapes.items()}
    want["time"] = ((spec.times.size,), spec.times.size, np.dtype(np.float64))
    want[LEDGER] = ((spec.n_chunks, DIGEST_SIZE), 1, np.dtype(np.uint8))
    return want


def _check(path: Path, spec: EnsembleSpec, shapes: dict[str, tuple[int, ...]]) -> None:
    import zarr

    _check_files(path)  # first: even reading the metadata would block on a pipe
    try:
        group = zarr.open_group(path, mode="r")
        stored = json.loads(group.attrs["andoyer_ensemble"])
        times = np.asarray(group["time"][:])
        layout = {name: (a.shape, a.chunks[0], a.dtype) for name, a in group.arrays()}
    except Exception as exc:  # any reason it cannot be read: not one of our stores, or damaged metadata
        msg = (
            f"expected an andoyer ensemble Zarr store at {str(path)!r}, got an unreadable one ({exc}); "
            "remove it or choose another output"
        )
        raise ValueError(msg) from exc
    want = spec.fingerprint()
    if stored != want or times.shape != spec.times.shape or not np.array_equal(times, spec.times):
        diff = {k: stored.get(k) for k in want if stored.get(k) != want[k]}
        if not np.array_equal(times, spec.times):
            diff["times"] = "differ"
        msg = (
            f"expected the settings of the ensemble already in {str(path)!r} to resume it, got different "
            f"settings (stored {diff}); remove it or choose another output"
        )
        raise ValueError(msg)
    expected = _expected_arrays(spec, shapes)
    if layout != expected:
        bad = sorted(n for n in set(layout) | set(expected) if layout.get(n) != expected.get(n))
        got = {n: layout.get(n, "missing") for n in bad}
        msg = (
            f"expected the arrays of this ensemble, (shape, chunk, dtype) = "
            f"{ {n: expected.get(n, 'none') for n in bad} } in {str(path)!r}, got {got}; "
            "remove it or choose another output"
        )
        raise ValueError(msg)


def _check_files(path: Path) -> None:
    """Refuse links and special files inside a store: reading a pipe blocks, a link leads elsewhere."""
    for root, dirs, files in os.walk(path):
        for name in (*dirs, *files):
            entry = Path(root) / name
            kind = _kind(os.lstat(entry).st_mode)
            if kind not in ("directory", "regular file"):
                msg = (
                    f"expected only regular files and directories inside the ensemble store {str(path)!r}, "
                    f"got a {kind} at {str(entry)!r}"
                )
                raise ValueError(msg)


def create_or_check_store(path: str | os.PathLike[str], spec: EnsembleSpec) -> Path:
    """Create the store for ``spec`` at ``path``, or check that the one there has the same settings.

    The settings (the fingerprint and the times) and the layout of every array must match;
    links and special files inside the store are refused. ``ValueError`` otherwise.
    """
    path = Path(path)
    if not path.parent.is_dir():
        msg = f"expected an existing directory for the ensemble output, got {str(path.parent)!r}"
        raise ValueError(msg)
    require_kind(path, "directory")
    shapes = variable_shapes(spec)
    if not path.exists():
        with contextlib.suppress(FileExistsError, OSError):
            _create(path, spec, shapes)
    if not path.exists():  # pragma: no cover - creation failed for a reason _check reports
        msg = f"expected to create the ensemble store {str(path)!r}, got nothing there"
        raise ValueError(msg)
    _check(path, spec, shapes)
    return path


def check_store(path: str | os.PathLike[str]) -> LedgerCheck:
    """Each chunk of the store at ``path`` checked against its ledger (see :func:`.ledger.verify`)."""
    import zarr

    group = zarr.open_group(Path(path), mode="r")
    return check_ledger(group, finished=bool(group.attrs.get(FINISHED, False)))


def completed_chunks(path: str | os.PathLike[str]) -> np.ndarray:
    """Boolean array, one entry per chunk: ``True`` where the chunk is written and matches its checksum.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> from andoyer import RigidBody
    >>> from andoyer.ensemble import AndoyerSampler, run_ensemble
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "e.zarr"
    >>> _ = run_ensemble(AndoyerSampler(), 10, [0.0, 1.0], body=RigidBody(1, 2, 3), chunk=4,
    ...                  out=out, scheduler="synchronous", progress=False)
    >>> completed_chunks(out).tolist()
    [True, True, True]
    """
    return check_store(path).done


def write_chunk(path: str | os.PathLike[str], spec: EnsembleSpec, index: int, arrays: Arrays) -> None:
    """Write chunk ``index`` into its region, then its ledger entry (the digest of ``arrays``)."""
    import zarr

    group = zarr.open_group(Path(path), mode="r+")
    region = spec.bounds(index)
    for name, values in arrays.items():
        group[name][region] = values
    group[LEDGER][index : index + 1] = chunk_digest(arrays)[None, :]


def mark_finished(path: str | os.PathLike[str]) -> None:
    """Record that every chunk was stored: from now on a missing ledger entry is damage."""
    import zarr

    group = zarr.open_group(Path(path), mode="r+")
    if not group.attrs.get(FINISHED, False):
        group.attrs[FINISHED] = True


def _is_ours(path: Path, spec: EnsembleSpec) -> bool:
    """Whether an unreadable file is a NetCDF file whose header records exactly these settings."""
    with contextlib.suppress(OSError), open(path, "rb") as f:
        head = f.read(1 << 20)  # the header (dimensions, attributes) comes first
        return head.startswith(b"CDF") and spec.attrs()["andoyer_ensemble"].encode() in head
    return False


def check_netcdf(path: Path, spec: EnsembleSpec) -> tuple[Any, LedgerCheck]:
    """The NetCDF file at ``path``, loaded, and each of its chunks checked against its digest.

    Returns ``(dataset, check)``; ``(None, nothing done)`` for a file that cannot be read but
    whose header records these settings (e.g. truncated). ``ValueError`` for another
    ensemble's file, an unreadable file that is not one of ours, or a non-regular file.
    """
    import xarray as xr

    require_kind(path, "regular file")
    try:
        ds = xr.load_dataset(path, engine="scipy")
        stored = json.loads(ds.attrs["andoyer_ensemble"])
        times = ds["time"].values
    except Exception as exc:  # any reason it cannot be read
        if _is_ours(path, spec):
            return None, LedgerCheck(np.zeros(spec.n_chunks, dtype=bool), tuple(range(spec.n_chunks)))
        msg = (
            f"expected an andoyer ensemble NetCDF file at {str(path)!r}, got an unreadable file ({exc}); "
            "remove it or choose another output"
        )
        raise ValueError(msg) from exc
    if stored != spec.fingerprint() or not np.array_equal(times, spec.times):
        msg = (
            f"expected the settings of the ensemble already in {str(path)!r}, got different settings; "
            "remove it or choose another output"
        )
        raise ValueError(msg)
    entries = digests_from_hex(ds.attrs.get(DIGESTS_ATTR, ""), spec.n_chunks)
    names = list(ds.data_vars)
    return ds, verify(entries, lambda k: {n: ds[n].values[spec.bounds(k)] for n in names}, finished=True)


def finalize_netcdf(parts: Path, path: Path) -> None:
    """Assemble the NetCDF file from a complete parts store: temporary file, rename, remove the parts."""
    import xarray as xr
    import zarr

    digests = digests_to_hex(zarr.open_group(parts, mode="r")[LEDGER][:])
    with xr.open_zarr(parts, consolidated=False) as ds:
        # Variables in name order: zarr lists them in no fixed order, and the file's bytes
        # (its header) would depend on it.
        data = ds.drop_vars(LEDGER).load()
    data = data[sorted(data.data_vars)]
    data.attrs.pop(FINISHED, None)
    data.attrs[DIGESTS_ATTR] = digests
    with atomic_replace(path) as part:
        # NetCDF3 with 64-bit offsets (scipy engine): variables beyond 2 GiB are allowed.
        data.to_netcdf(part, engine="scipy", format="NETCDF3_64BIT")
    shutil.rmtree(parts)
