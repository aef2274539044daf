"""Run an ensemble on Dask: a local cluster, any scheduler by address, or in-process."""

from __future__ import annotations

import contextlib
import itertools
import os
import shutil
import uuid
import warnings
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import dask
import numpy as np

from andoyer.body import RigidBody
from andoyer.ensemble.layout import EnsembleSpec, compute_chunk, dataset_from_arrays
from andoyer.ensemble.propagators import FreePropagator
from andoyer.ensemble.sampling import Sampler
from andoyer.ensemble.store import (
    DamagedChunkWarning,
    check_netcdf,
    check_store,
    create_or_check_store,
    finalize_netcdf,
    mark_finished,
    parts_path,
    require_kind,
    write_chunk,
)

__all__ = ["local_client", "run_ensemble"]

TASK_PREFIX = "andoyer_ensemble_chunk"  # dask groups tasks by this prefix (key_split)


def _store_chunk(spec: EnsembleSpec, index: int, path: str | None) -> Any:
    """Worker task: compute chunk ``index``; write it (and return its index) or return its arrays."""
    arrays = compute_chunk(spec, index)
    if path is None:
        return arrays
    write_chunk(path, spec, index, arrays)
    return index


def _worker_environ() -> dict[str, Any]:
    """Dask's environment for new worker processes, without ``MALLOC_TRIM_THRESHOLD_``.

    Dask sets it to 64 KiB so that workers hand memory back to the OS; glibc then stops
    adapting its mmap threshold, every large temporary array of the free-flow kernel
    becomes a fresh ``mmap`` with page faults, and the kernel runs about 4 times slower
    (measured: 1.4 s user + 0.2 s system without it, 2.0 s + 3.8 s with it). Chunks are
    bounded, so the default allocator is kept.
    """
    environ = dask.config.get("distributed.nanny.pre-spawn-environ", default={}) or {}
    return {k: v for k, v in environ.items() if k != "MALLOC_TRIM_THRESHOLD_"}


#: Dask settings of :func:`local_client`. Idle, Dask's defaults cost a local cluster of two
#: workers about 18 % of one core (measured: 8 % in the client and scheduler, 5 % in each
#: worker): the statistical profiler samples each worker's stack every 10 ms, the GIL and
#: system monitors poll every 1 ms and 500 ms, the event-loop tick runs every 20 ms. On a
#: machine with a core per worker that is taken from the workers (with these settings: 2.5 %).
#: The dashboard's profile page stays empty; pass your own ``Client`` to keep it.
QUIET_CLUSTER_CONFIG: dict[str, Any] = {
    "distributed.worker.profile.enabled": False,
    "distributed.admin.system-monitor.interval": "2s",
    "distributed.admin.system-monitor.gil.enabled": False,
    "distributed.admin.tick.interval": "200ms",
    "distributed.worker.memory.monitor-interval": "1s",
}


@contextlib.contextmanager
def local_client(n_workers: int = 2, processes: bool = True) -> Iterator[Any]:
    """A ``distributed.Client`` on a ``LocalCluster`` set up for ensembles, closed on exit.

    ``n_workers`` single-threaded workers (processes, or threads of this process with
    ``processes=False``), the dashboard on a free loopback port, worker processes
    started without Dask's ``MALLOC_TRIM_THRESHOLD_`` (see :func:`_worker_environ`), and
    Dask's profiler and monitors quietened (:data:`QUIET_CLUSTER_CONFIG`).
    Pass it as ``scheduler=`` to run several ensembles on one cluster.

    Parameters
    ----------
    n_workers : int
    processes : bool

    Yields
    ------
    distributed.Client

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> from andoyer.ensemble import MomentumSampler
    >>> with local_client(1, processes=False) as client:
    ...     ds = run_ensemble(MomentumSampler(), 3, [0.0], body=RigidBody(1, 2, 3), scheduler=client,
    ...                       progress=False)
    >>> ds.m_body.shape
    (3, 1, 3)
    """
    from distributed import Client, LocalCluster

    _check_workers(n_workers)
    # One thread per worker: the kernel is numpy-bound and holds the GIL part of the
    # time, so processes (not threads) are what scale.
    with (
        dask.config.set({**QUIET_CLUSTER_CONFIG, "distributed.nanny.pre-spawn-environ": _worker_environ()}),
        LocalCluster(
            n_workers=int(n_workers),
            threads_per_worker=1,
            processes=processes,
            # Port 0: the HTTP server always starts, and a fixed port may be taken.
            dashboard_address="127.0.0.1:0",
        ) as cluster,
        Client(cluster) as client,
    ):
        yield client


def _check_workers(n_workers: Any) -> None:
    if isinstance(n_workers, bool) or not isinstance(n_workers, int | np.integer) or n_workers < 1:
        msg = f"expected a positive integer number of workers, got {n_workers!r}"
        raise ValueError(msg)


@contextlib.contextmanager
def _client(scheduler: Any, n_workers: int, processes: bool) -> Iterator[Any]:
    from distributed import Client

    if isinstance(scheduler, Client):
        yield scheduler
        return
    if scheduler is None:
        with local_client(n_workers, processes) as client:
            yield client
        return
    if not isinstance(scheduler, str) or not scheduler:
        msg = f"expected a scheduler address such as 'tcp://host:8786', got {scheduler!r}"
        raise ValueError(msg)
    try:
        client = Client(scheduler, timeout="10s")
    except (OSError, ValueError) as exc:  # refused or timed out (OSError), malformed address (ValueError)
        msg = f"expected a reachable Dask scheduler at {scheduler!r}, got {exc}"
        raise ValueError(msg) from exc
    with client:
        yield client


def _output_kind(out: str | os.PathLike[str] | None) -> str | None:
    if out is None:
        return None
    suffix = Path(out).suffix.lower()
    if suffix not in (".zarr", ".nc"):
        msg = f"expected an output path ending in .zarr or .nc, got {str(out)!r}"
        raise ValueError(msg)
    return suffix[1:]


def run_ensemble(
    sampler: Sampler,
    n_samples: int,
    times: Any,
    *,
    body: RigidBody | None = None,
    propagator: Callable[..., Any] | None = None,
    out: str | os.PathLike[str] | None = None,
    chunk: int | None = None,
    seed: int = 0,
    output: str = "state",
    scheduler: Any = None,
    n_workers: int = 2,
    processes: bool = True,
    progress: bool = True,
    on_chunk: Callable[[int], None] | None = None,
):
    """Propagate ``n_samples`` sampled states to every time in ``times``, chunk by chunk on Dask.

    Chunk ``k`` (samples ``k·chunk`` to ``(k+1)·chunk``) draws its initial states from
    ``chunk_rng(seed, k)``, propagates them with ``propagator(state, times, **parameters)``
    and converts them to the ``output`` chart. With ``out`` the workers write their chunks
    straight into a Zarr store (or a parts store assembled into NetCDF at the end), so
    memory stays bounded by a few chunks per worker, and a rerun with the same arguments
    resumes an interrupted ensemble: it checks every stored chunk against its checksum in
    the store's ledger and computes only the chunks not written or no longer matching.

    Parameters
    ----------
    sampler : Sampler
        e.g. :class:`AndoyerSampler`, :class:`MomentumSampler`, :class:`InertiaSampler`.
    n_samples : int
        Number of initial states.
    times : array_like, shape (T,)
        Epochs, measured from the initial states.
    body : RigidBody, optional
        Shortcut for ``propagator=FreePropagator(body)`` (the exact free flow).
    propagator : callable, optional
        ``(state (n,), times (T,), **parameters) -> State (n, T)``; give ``body`` or this.
    out : path, optional
        ``*.zarr`` (written chunk by chunk) or ``*.nc`` (NetCDF3 via scipy, written at the
        end, atomically). ``None``: keep the result in memory (not resumable).
    chunk : int, optional
        Samples per chunk; default about 2¹⁸ (sample, epoch) pairs per chunk. Part of the
        numbers' identity: the same ``(seed, chunk)`` gives the same samples.
    seed : int
        Non-negative seed.
    output : {"state", "andoyer", "euler", "obliquity"}
        Variables written: ``quaternion``/``m_body``, or the chart's six fields.
    scheduler : None, "synchronous", str or distributed.Client
        ``None``: a ``distributed.LocalCluster`` of ``n_workers`` single-threaded workers
        (processes unless ``processes=False``; no more workers than chunks to run, and none,
        this process, for a single chunk), closed at the end; ``"synchronous"``: this
        process, no Dask; an address such as ``"tcp://10.0.0.1:8786"``: that scheduler's
        workers (they must import ``andoyer`` and reach ``out``); a ``Client``: used as is.
    n_workers : int
        Workers of the local cluster.
    processes : bool
        Local cluster of processes (``True``) or threads in this process.
    progress : bool
        Show a tqdm progress bar (chunks) on standard error.
    on_chunk : callable, optional
        Called with each chunk index once that chunk is stored (in this process).

    Returns
    -------
    xarray.Dataset
        Dims ``sample``, ``time`` (and ``quaternion_component``/``axis``); lazily read
        from Zarr, loaded from NetCDF, or in memory.

    Raises
    ------
    ValueError
        Bad arguments; ``out`` holds another ensemble, unreadable metadata, links or special
        files, or is of the wrong kind (a file for ``*.zarr``, not a regular file for ``*.nc``).

    Warns
    -----
    DamagedChunkWarning
        Some chunks of ``out`` had been written but are missing, damaged or do not match
        their checksum; they are computed again (the warning names them).

    Examples
    --------
    >>> import numpy as np
    >>> from andoyer import FreeRotation, RigidBody
    >>> from andoyer.ensemble import AndoyerSampler, chunk_rng
    >>> body = RigidBody(1.0, 2.0, 3.0)
    >>> ds = run_ensemble(AndoyerSampler(), 6, [0.0, 5.0], body=body, chunk=3, seed=1,
    ...                   scheduler="synchronous", progress=False)
    >>> ds.quaternion.shape, ds.m_body.dims
    ((6, 2, 4), ('sample', 'time', 'axis'))
    >>> chunk1 = AndoyerSampler().sample(chunk_rng(1, 1), 3)  # samples 3-5 are chunk 1
    >>> direct = FreeRotation(body).propagate(chunk1[:, None], [0.0, 5.0])
    >>> bool((ds.m_body.values[3:] == direct.m_body).all())
    True
    """
    if (body is None) == (propagator is None):
        msg = "expected exactly one of body= or propagator=, got " + ("both" if body else "neither")
        raise ValueError(msg)
    _check_workers(n_workers)
    spec = EnsembleSpec.build(
        sampler, propagator or FreePropagator(body), n_samples, times, chunk, seed, output
    )
    kind = _output_kind(out)
    # Written through a symbolic link, never replacing it: work on the path it points to.
    target = None if out is None else Path(os.path.realpath(out))
    store = target
    intact = None  # a NetCDF file to repair: (its dataset, its check)
    if kind == "nc":
        require_kind(target, "regular file")
        store = parts_path(target)
        if target.exists():
            intact = check_netcdf(target, spec)
            if store.exists():  # a crash between the rename and the clean-up, or an interrupted repair
                shutil.rmtree(store)
            if intact[1].done.all():
                return intact[0]
    if store is not None:
        create_or_check_store(store, spec)
        if intact is None:
            check = check_store(store)
        else:
            # Rebuild from the intact chunks: the parts store gets them (and their ledger
            # entries) from the file; only the damaged ones are computed.
            ds, check = intact
            for index in map(int, np.flatnonzero(check.done)):
                write_chunk(store, spec, index, {n: ds[n].values[spec.bounds(index)] for n in ds.data_vars})
        damaged = check.damaged
        todo = [int(i) for i in np.flatnonzero(~check.done)]
    else:
        damaged, todo = (), list(range(spec.n_chunks))
    if damaged:
        shown = ", ".join(map(str, damaged[:20])) + (", ..." if len(damaged) > 20 else "")
        msg = (
            f"{len(damaged)} chunk(s) of the ensemble in {str(target)!r} were written but are missing, "
            f"damaged or do not match their checksum: computing them again (chunk(s) {shown})"
        )
        warnings.warn(msg, DamagedChunkWarning, stacklevel=2)
    results = _run(
        spec, todo, None if store is None else str(store), scheduler, n_workers, processes, progress, on_chunk
    )
    if kind is None:
        return _assemble(spec, results)
    mark_finished(store)
    if kind == "nc":
        finalize_netcdf(store, target)
        return _load_netcdf(target)
    import xarray as xr

    return xr.open_zarr(store, consolidated=False)


def _load_netcdf(path: Path):
    import xarray as xr

    return xr.load_dataset(path, engine="scipy")


def _run(
    spec: EnsembleSpec,
    todo: list[int],
    store: str | None,
    scheduler: Any,
    n_workers: int,
    processes: bool,
    progress: bool,
    on_chunk: Callable[[int], None] | None,
) -> dict[int, Any]:
    from tqdm.auto import tqdm

    results: dict[int, Any] = {}
    bar = tqdm(total=len(todo), disable=not progress or not todo, unit="chunk", desc="ensemble")
    with bar:
        if not todo:
            return results
        # One chunk left and no cluster named: a local cluster would only add its start-up (workers
        # importing andoyer and loading the compiled kernels: 6 s of a 15-s, 1-Gyr Mars member).
        if (isinstance(scheduler, str) and scheduler == "synchronous") or (
            scheduler is None and len(todo) == 1
        ):
            for index in todo:
                results[index] = _store_chunk(spec, index, store)
                bar.update()
                if on_chunk is not None:
                    on_chunk(index)
            return results
        with _client(scheduler, min(n_workers, len(todo)), processes) as client:
            _submit_windowed(client, spec, todo, store, results, bar, on_chunk)
    return results


def _submit_windowed(
    client: Any,
    spec: EnsembleSpec,
    todo: list[int],
    store: str | None,
    results: dict[int, Any],
    bar: Any,
    on_chunk: Callable[[int], None] | None,
) -> None:
    """Keep a few chunks per worker thread in flight, topping the window up in batches.

    The window (four chunks per worker thread when writing to a store, whose results are
    mere indices; two when the arrays come back here) bounds the memory of the scheduler
    and of an in-memory result, and makes an interruption clean: on any exception (a
    failed chunk, the callback, Ctrl-C) no new chunk starts, the few in flight are allowed
    to finish writing (a second Ctrl-C abandons them), and the exception propagates.
    Nothing is written after this returns. Refilling half a window at a time with one
    ``client.map`` costs the client about 2 ms of CPU per chunk instead of 5 ms for one
    ``submit`` per chunk (measured on a local cluster): on a machine with no spare core
    that CPU is taken from the workers.
    """
    from distributed import as_completed, wait

    run_id = uuid.uuid4().hex[:12]
    threads = sum(client.nthreads().values())
    window = max(4, (4 if store is not None else 2) * threads)
    batch = window // 2  # window >= 4
    queue = iter(todo)
    index_of: dict[Any, int] = {}

    def submit(n: int) -> list[Any]:
        indices = list(itertools.islice(queue, n))
        if not indices:
            return []
        keys = [f"{TASK_PREFIX}-{index}-{run_id}" for index in indices]
        futures = client.map(_store_chunk, [spec] * len(indices), indices, [store] * len(indices), key=keys)
        index_of.update(zip(keys, indices, strict=True))
        return futures

    in_flight = set(submit(window))
    stream = as_completed(list(in_flight))
    try:
        for future in stream:
            in_flight.discard(future)
            index = index_of.pop(future.key)
            # A stored chunk's result is only its index: fetching it would cost a round
            # trip to the worker per chunk. A failed task raises here either way.
            if store is None or future.status != "finished":
                results[index] = future.result()
            future.release()
            if len(in_flight) <= window - batch:
                more = submit(window - len(in_flight))
                in_flight.update(more)
                stream.update(more)
            bar.update()
            if on_chunk is not None:
                on_chunk(index)
    except BaseException:
        try:
            wait(list(in_flight))
        finally:
            client.cancel(list(in_flight))
        raise


def _assemble(spec: EnsembleSpec, results: dict[int, Any]):
    first = results[0]
    full = {k: np.empty((spec.n_samples, *v.shape[1:])) for k, v in first.items()}
    for index, arrays in results.items():
        region = spec.bounds(index)
        for k, v in arrays.items():
            full[k][region] = v
    return dataset_from_arrays(spec, full)
