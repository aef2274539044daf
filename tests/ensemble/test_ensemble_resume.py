"""Interrupted ensembles resume from what they wrote: identical numbers, only missing chunks recomputed."""

from __future__ import annotations

import os

import numpy as np
import pytest
import xarray as xr

from andoyer import bodies
from andoyer.ensemble import AndoyerSampler, completed_chunks, run_ensemble

EROS = bodies.get("eros")
TIMES = np.array([0.0, 1.5, 40.0])
N, CHUNK = 77, 4  # 20 chunks, the last one short
N_CHUNKS = 20
IN_FLIGHT = 4 * 2  # documented bound: four chunks per worker thread (two workers of one thread)


class SimulatedKillError(Exception):
    """Raised from the chunk callback to simulate a kill."""


def stop_after(k):
    done = []

    def on_chunk(index):
        done.append(index)
        if len(done) >= k:
            raise SimulatedKillError

    return on_chunk


def chunk_files(store, chunks):
    """Modification times of every file holding the given chunks' data and markers."""
    found = {}
    for root, _, files in os.walk(store):
        rel = os.path.relpath(root, store).split(os.sep)
        # zarr v3 keys: <variable>/c/<sample-chunk>/... (sample is the first dimension everywhere)
        if len(rel) >= 3 and rel[1] == "c" and int(rel[2]) in chunks:
            found.update({os.path.join(root, f): os.stat(os.path.join(root, f)).st_mtime_ns for f in files})
        if len(rel) == 2 and rel[1] == "c":  # one-dimensional arrays: the file name is the chunk
            found.update(
                {
                    os.path.join(root, f): os.stat(os.path.join(root, f)).st_mtime_ns
                    for f in files
                    if f.isdigit() and int(f) in chunks
                }
            )
    return found


def run_settings(out, scheduler):
    """The keyword arguments of this module's ensemble, written to ``out`` on ``scheduler``."""
    return {"body": EROS, "chunk": CHUNK, "seed": 9, "out": out, "scheduler": scheduler, "progress": False}


def reference():
    return run_ensemble(
        AndoyerSampler(), N, TIMES, body=EROS, chunk=CHUNK, seed=9, scheduler="synchronous", progress=False
    )


@pytest.mark.parametrize("where", ["synchronous", "loopback"])
@pytest.mark.parametrize("k", [1, 3])
def test_ensemble_zarr_resume_recomputes_only_missing_chunks(where, k, tmp_path, loopback_cluster):
    scheduler = "synchronous" if where == "synchronous" else loopback_cluster.scheduler_address
    store = tmp_path / "e.zarr"
    kwargs = run_settings(store, scheduler)
    with pytest.raises(SimulatedKillError):
        run_ensemble(AndoyerSampler(), N, TIMES, on_chunk=stop_after(k), **kwargs)
    done = set(np.flatnonzero(completed_chunks(store)).tolist())
    assert k <= len(done) <= (k if where == "synchronous" else k + IN_FLIGHT) < N_CHUNKS
    stamps = chunk_files(store, done)
    assert len(stamps) >= 5 * len(done)  # 4 variables and the marker per chunk
    again = []
    ds = run_ensemble(AndoyerSampler(), N, TIMES, on_chunk=again.append, **kwargs)
    assert sorted(again) == sorted(set(range(N_CHUNKS)) - done)
    assert chunk_files(store, done) == stamps  # completed chunks were not rewritten
    assert completed_chunks(store).all()
    ref = reference()
    for name in ("quaternion", "m_body", "quaternion0", "m_body0"):
        np.testing.assert_array_equal(ds[name].values, ref[name].values)
    third = []
    run_ensemble(AndoyerSampler(), N, TIMES, on_chunk=third.append, **kwargs)
    assert third == []  # a complete store is left as it is


def test_ensemble_zarr_partial_chunk_without_marker_is_recomputed(tmp_path):
    import zarr

    store = tmp_path / "e.zarr"
    kwargs = run_settings(store, "synchronous")
    run_ensemble(AndoyerSampler(), N, TIMES, **kwargs)
    group = zarr.open_group(store, mode="r+")
    group["quaternion"][8:12] = 0.5  # a worker killed half-way through chunk 2: data, no marker
    group["chunk_digest"][2:3] = np.zeros((1, 32), dtype=np.uint8)  # its ledger entry not yet written
    del group.attrs["andoyer_finished"]  # and the run not finished
    again = []
    ds = run_ensemble(AndoyerSampler(), N, TIMES, on_chunk=again.append, **kwargs)
    assert again == [2]
    np.testing.assert_array_equal(ds.quaternion.values, reference().quaternion.values)


def test_ensemble_netcdf_is_atomic_and_resumes(tmp_path, loopback_cluster):
    out = tmp_path / "e.nc"
    parts = tmp_path / "e.nc.parts.zarr"
    kwargs = run_settings(out, loopback_cluster.scheduler_address)
    with pytest.raises(SimulatedKillError):
        run_ensemble(AndoyerSampler(), N, TIMES, on_chunk=stop_after(2), **kwargs)
    assert not out.exists()  # nothing half-written under the final name
    assert parts.is_dir()
    done = set(np.flatnonzero(completed_chunks(parts)).tolist())
    again = []
    ds = run_ensemble(AndoyerSampler(), N, TIMES, on_chunk=again.append, **kwargs)
    assert sorted(again) == sorted(set(range(N_CHUNKS)) - done)
    assert not parts.exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["e.nc"]  # no temporary file left
    with xr.open_dataset(out, engine="scipy") as on_disk:
        ref = reference()
        for name in ("quaternion", "m_body", "quaternion0", "m_body0", "time"):
            np.testing.assert_array_equal(on_disk[name].values, ref[name].values)
            np.testing.assert_array_equal(ds[name].values, ref[name].values)
    third = []
    run_ensemble(AndoyerSampler(), N, TIMES, on_chunk=third.append, **kwargs)
    assert third == []


@pytest.mark.parametrize(
    "change",
    [{"seed": 10}, {"chunk": 5}, {"times": [0.0, 1.5, 41.0]}, {"n_samples": 30}, {"output": "euler"}],
)
def test_ensemble_refuses_to_resume_with_other_settings(change, tmp_path):
    out = tmp_path / "e.zarr"
    args = {
        "n_samples": N,
        "times": TIMES,
        "body": EROS,
        "chunk": CHUNK,
        "seed": 9,
        "out": out,
        "scheduler": "synchronous",
        "progress": False,
    }
    run_ensemble(AndoyerSampler(), **args)
    args.update(change)
    with pytest.raises(ValueError, match="expected the settings of the ensemble already in"):
        run_ensemble(AndoyerSampler(), **args)


def test_ensemble_refuses_a_netcdf_file_with_other_settings(tmp_path):
    args = {
        "body": EROS,
        "chunk": CHUNK,
        "out": tmp_path / "e.nc",
        "scheduler": "synchronous",
        "progress": False,
    }
    run_ensemble(AndoyerSampler(), N, TIMES, seed=9, **args)
    with pytest.raises(ValueError, match="expected the settings of the ensemble already in"):
        run_ensemble(AndoyerSampler(), N, TIMES, seed=10, **args)


def test_ensemble_refuses_a_foreign_store(tmp_path):
    (tmp_path / "x.zarr").mkdir()
    (tmp_path / "x.zarr" / "notes.txt").write_text("not a store")
    with pytest.raises(ValueError, match="expected an andoyer ensemble Zarr store"):
        run_ensemble(
            AndoyerSampler(),
            4,
            TIMES,
            body=EROS,
            out=tmp_path / "x.zarr",
            scheduler="synchronous",
            progress=False,
        )


def test_ensemble_store_data_are_uncompressed_and_markers_start_unset(tmp_path):
    import zarr

    from andoyer.ensemble.layout import EnsembleSpec
    from andoyer.ensemble.propagators import FreePropagator
    from andoyer.ensemble.store import create_or_check_store

    spec = EnsembleSpec.build(AndoyerSampler(), FreePropagator(EROS), N, TIMES, CHUNK, 9)
    create_or_check_store(tmp_path / "e.zarr", spec)
    group = zarr.open_group(tmp_path / "e.zarr", mode="r")
    for name in ("quaternion", "m_body", "quaternion0", "m_body0"):
        assert group[name].compressors == ()
        assert group[name].chunks[0] == CHUNK
        assert np.isnan(group[name][:]).all()
    np.testing.assert_array_equal(group["time"][:], TIMES)
    np.testing.assert_array_equal(completed_chunks(tmp_path / "e.zarr"), np.zeros(N_CHUNKS, dtype=bool))
    ds = xr.open_zarr(tmp_path / "e.zarr", consolidated=False)
    assert ds.quaternion.dims == ("sample", "time", "quaternion_component")
    assert ds.m_body0.dims == ("sample", "axis")
