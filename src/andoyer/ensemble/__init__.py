"""Monte-Carlo ensembles: millions of states propagated on Dask, resumable, as xarray datasets.

:func:`run_ensemble` samples initial conditions (and optionally parameters) chunk by
chunk from seeds derived from ``(seed, chunk index)``, propagates them with the exact
free flow (:class:`FreePropagator`), the secular spin-axis flow along an orbit
history (:class:`SpinAxisPropagator`, with :class:`SpinParameterSampler`), or any callable
``(State (n,), times (T,), **parameters) -> State (n, T)``, and writes an
:class:`xarray.Dataset` with dims ``sample`` and ``time`` to Zarr (chunk by chunk, with a
checksum per chunk in a ledger, so an interrupted or damaged run resumes where it stopped
and recomputes what does not match) or to NetCDF (assembled atomically at the end). Work
runs on a ``distributed.LocalCluster`` by default, or on any Dask scheduler given by address.
See ``docs/ensembles.md``.

Requires the ``ensemble`` extra (dask[distributed], xarray, zarr, google-crc32c).

Examples
--------
>>> from andoyer import RigidBody
>>> from andoyer.ensemble import MomentumSampler, run_ensemble
>>> ds = run_ensemble(MomentumSampler(), 4, [0.0, 1.0, 2.0], body=RigidBody(1, 2, 3),
...                   output="andoyer", scheduler="synchronous", progress=False)
>>> sorted(ds.data_vars)
['G', 'H', 'L', 'g', 'h', 'l', 'm_body0', 'quaternion0']
>>> ds.G.dims
('sample', 'time')
"""

from andoyer.ensemble.layout import OUTPUTS, EnsembleSpec
from andoyer.ensemble.obliquity import MemberPropagator, MemberSampler, obliquity_ensemble
from andoyer.ensemble.propagators import FreePropagator, Propagator
from andoyer.ensemble.runner import local_client, run_ensemble
from andoyer.ensemble.sampling import (
    AndoyerSampler,
    Draw,
    InertiaSampler,
    MomentumSampler,
    Sampler,
    chunk_rng,
)
from andoyer.ensemble.spin_axis import SpinAxisPropagator, SpinParameterSampler
from andoyer.ensemble.store import DamagedChunkWarning, completed_chunks

__all__ = [
    "OUTPUTS",
    "AndoyerSampler",
    "DamagedChunkWarning",
    "Draw",
    "EnsembleSpec",
    "FreePropagator",
    "InertiaSampler",
    "MemberPropagator",
    "MemberSampler",
    "MomentumSampler",
    "Propagator",
    "Sampler",
    "SpinAxisPropagator",
    "SpinParameterSampler",
    "chunk_rng",
    "completed_chunks",
    "local_client",
    "obliquity_ensemble",
    "run_ensemble",
]
