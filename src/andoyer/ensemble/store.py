"""Resumable ensemble storage: a Zarr store written chunk by chunk with a completion marker per chunk.

The store is created (metadata, the ``time`` coordinate, every variable filled
with NaN) in a temporary directory renamed into place, so it exists complete or
not at all. Workers then write chunk ``k`` into its own region — Zarr chunks
are aligned with ensemble chunks, so no two workers touch one file, and the
local store replaces each file atomically — and only afterwards set
``completed[k] = 1``. A chunk whose marker is set is therefore fully written;
anything else is recomputed on restart (its region may be rewritten at will:
the numbers depend on ``(seed, chunk size, k)`` only).

A NetCDF output is assembled at the end from such a store (``FILE.nc.parts.zarr``
beside it), written to a temporary file and renamed: an interrupted NetCDF run
resumes from the parts store.
"""

from __future__ import annotations

import contextlib
import dataclasses
import json
import os
import shutil
import tempfile
import uuid
from pathlib import Path

import numpy as np

from andoyer._files import new_file_mode
from andoyer.ensemble.layout import Arrays, EnsembleSpec, compute_chunk, variable_dims

__all__ = [
    "completed_chunks",
    "create_or_check_store",
    "finalize_netcdf",
    "netcdf_matches",
    "parts_path",
    "write_chunk",
]

MARKER = "completed"


def parts_path(netcdf: Path) -> Path:
    """The Zarr store that holds the chunks of a NetCDF output until it is assembled."""
    return netcdf.with_name(netcdf.name + ".parts.zarr")


def variable_shapes(spec: EnsembleSpec) -> dict[str, tuple[int, ...]]:
    """Full shapes of every variable, from one sample of chunk 0 computed here."""
    probe = dataclasses.replace(spec, n_samples=1, chunk=1)
    return {name: (spec.n_samples, *a.shape[1:]) for name, a in compute_chunk(probe, 0).items()}


def _create(path: Path, spec: EnsembleSpec) -> None:
    import zarr

    shapes = variable_shapes(spec)
    tmp = path.with_name(f".{path.name}.{uuid.uuid4().hex}.tmp")
    try:
        # Metadata only (plus the time coordinate): unwritten chunks read as the fill value,
        # NaN for data and 0 for the markers. Written with zarr directly, in constant time:
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
        group.create_array(
            MARKER,
            shape=(spec.n_chunks,),
            chunks=(1,),
            dtype=np.uint8,
            fill_value=0,
            compressors=None,
            dimension_names=("chunk",),
        )
        os.rename(tmp, path)
    finally:
        if tmp.exists():
            shutil.rmtree(tmp, ignore_errors=True)


def _check(path: Path, spec: EnsembleSpec) -> None:
    import zarr

    try:
        group = zarr.open_group(path, mode="r")
        stored = json.loads(group.attrs["andoyer_ensemble"])
        times = np.asarray(group["time"][:])
    except Exception as exc:  # any reason it cannot be read: not one of our stores
        msg = f"expected an andoyer ensemble Zarr store at {str(path)!r}, got an unreadable one ({exc})"
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


def create_or_check_store(path: str | os.PathLike[str], spec: EnsembleSpec) -> Path:
    """Create the store for ``spec`` at ``path``, or check that the one there has the same settings."""
    path = Path(path)
    if not path.parent.is_dir():
        msg = f"expected an existing directory for the ensemble output, got {str(path.parent)!r}"
        raise ValueError(msg)
    if not path.exists():
        with contextlib.suppress(FileExistsError, OSError):
            _create(path, spec)
    if not path.exists():  # pragma: no cover - creation failed for a reason _check reports
        msg = f"expected to create the ensemble store {str(path)!r}, got nothing there"
        raise ValueError(msg)
    _check(path, spec)
    return path


def completed_chunks(path: str | os.PathLike[str]) -> np.ndarray:
    """Boolean array, one entry per chunk: ``True`` where the chunk is fully written.

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
    import zarr

    return np.asarray(zarr.open_group(Path(path), mode="r")[MARKER][:]) == 1


def write_chunk(path: str | os.PathLike[str], spec: EnsembleSpec, index: int, arrays: Arrays) -> None:
    """Write chunk ``index`` into its region, then set its completion marker."""
    import zarr

    group = zarr.open_group(Path(path), mode="r+")
    region = spec.bounds(index)
    for name, values in arrays.items():
        group[name][region] = values
    group[MARKER][index : index + 1] = np.ones(1, dtype=np.uint8)


def netcdf_matches(path: Path, spec: EnsembleSpec) -> bool:
    """Whether the NetCDF file at ``path`` holds this ensemble (``ValueError`` if it holds another)."""
    import xarray as xr

    try:
        with xr.open_dataset(path, engine="scipy") as ds:
            stored = json.loads(ds.attrs["andoyer_ensemble"])
            times = ds["time"].values
    except Exception as exc:  # any reason it cannot be read: not one of ours
        msg = f"expected an andoyer ensemble NetCDF file at {str(path)!r}, got an unreadable file ({exc})"
        raise ValueError(msg) from exc
    if stored != spec.fingerprint() or not np.array_equal(times, spec.times):
        msg = (
            f"expected the settings of the ensemble already in {str(path)!r}, got different settings; "
            "remove it or choose another output"
        )
        raise ValueError(msg)
    return True


def finalize_netcdf(parts: Path, path: Path) -> None:
    """Assemble the NetCDF file from a complete parts store: temporary file, rename, remove the parts."""
    import xarray as xr

    with xr.open_zarr(parts, consolidated=False) as ds:
        data = ds.drop_vars(MARKER).load()
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".part", dir=path.parent)
    os.close(fd)
    try:
        # NetCDF3 with 64-bit offsets (scipy engine): variables beyond 2 GiB are allowed.
        data.to_netcdf(tmp, engine="scipy", format="NETCDF3_64BIT")
        os.chmod(tmp, new_file_mode())  # mkstemp made it 0600: give it the umask's mode
        os.replace(tmp, path)
    finally:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
    shutil.rmtree(parts)
