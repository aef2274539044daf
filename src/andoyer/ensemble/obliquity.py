r"""Chaotic-obliquity ensembles: many spin axes on perturbed secular orbits, and their statistics.

:func:`obliquity_ensemble` draws ``N`` members (:class:`MemberSampler`: a seeded perturbation
of the secular model's J2000 state, and a precession rate or dynamical ellipticity within a
documented range), integrates each (:class:`MemberPropagator`:
:func:`andoyer.planetary.spin_axis.members.member_obliquities`) chunk by chunk through the
ensemble runner (:func:`andoyer.ensemble.run_ensemble`: Dask, a Zarr or NetCDF store with its
ledger, resumable after an interruption), and returns the histories with their statistics
(:func:`andoyer.planetary.spin_axis.statistics.obliquity_statistics`) as one
:class:`xarray.Dataset`, in degrees.

Default spin-parameter ranges (:data:`DEFAULT_RATES`): Mars' precession rate ``ψ̇`` uniform in
7.590–7.610″/yr, the spread of the radio-tracking determinations (Konopliv et al. 2016, Icarus
274, 253; Le Maistre et al. 2023, Nature 619, 733: 7.59–7.61″/yr, which carries the
uncertainty of ``C/MR²`` into the torque); the Earth's IAU 2006 rate and the moonless Earth's
ellipticity fixed (the spread then comes from the orbits alone).

**Orbits shared by several spin axes.** With ``orbits = K < N`` the ``N`` members are ``K``
perturbed orbits, each carrying ``N/K`` spin axes that differ by their spin parameter (drawn in
its range as above): an orbit is integrated once for all its axes, in the same compiled pass
(:func:`~andoyer.planetary.spin_axis.members.member_obliquities`), so the cost is about ``K``
orbits plus ``N`` spin axes (an axis costs about a tenth of an orbit). Both sources of the spread
are sampled: the orbits' chaos (the inner planets) and the spin's own (Mars' axis in its chaotic
zone parts from a neighbour within a few Myr; Laskar & Robutel 1993).

Examples
--------
>>> ds = obliquity_ensemble("mars", 2, -2e5, 1e5, scheduler="synchronous", progress=False)
>>> ds.obliquity.dims, ds.sizes["time"], float(ds.exceedance.sel(threshold=60.0))
(('sample', 'time'), 3, 0.0)
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer.ensemble.sampling import Draw, _interval
from andoyer.planetary.spin_axis.members import (
    MEMBER_BODIES,
    PERTURBATION,
    member_cost,
    member_obliquities,
    member_times,
    perturbed_states,
)
from andoyer.state import State

__all__ = ["DEFAULT_RATES", "MemberPropagator", "MemberSampler", "obliquity_ensemble"]

Array = NDArray[np.float64]

#: Default range of ``ψ̇`` at J2000 (″/yr) per body; a body not listed keeps its own fixed value.
DEFAULT_RATES = {"mars": (7.590, 7.610)}


def _axis(body: str) -> Array:
    from andoyer.planetary.spin_axis import default_axis

    return default_axis("earth" if body == "moonless-earth" else body)


@dataclass(frozen=True)
class MemberSampler:
    """Per member: a perturbation of the J2000 secular state, and a precession rate or ellipticity.

    Parameters
    ----------
    body : {"mars", "earth", "moonless-earth"}
    perturbation : float
        Size of the perturbation (:func:`~andoyer.planetary.spin_axis.members.perturbed_states`).
    precession_rate : float or (low, high), optional
        ``ψ̇`` at J2000, ″/yr, uniform in the range (default :data:`DEFAULT_RATES`, else the
        body's). Not with ``dynamical_ellipticity``.
    dynamical_ellipticity : float or (low, high), optional
        ``H``, uniform in the range.
    per_orbit : int
        Consecutive members sharing one orbit (default 1: each its own); with more than one, the
        spin parameter must have a range (members sharing an orbit and a parameter would be equal).

    Examples
    --------
    >>> from andoyer.ensemble import chunk_rng
    >>> draw = MemberSampler("mars").sample(chunk_rng(0, 0), 3)
    >>> sorted(draw.parameters), draw.parameters["orbit_perturbation"].shape
    (['orbit_perturbation', 'precession_rate'], (3, 32))
    >>> shared = MemberSampler("mars", per_orbit=2).sample(chunk_rng(0, 0), 4).parameters
    >>> p = shared["orbit_perturbation"]
    >>> bool((p[0] == p[1]).all() and (p[2] == p[3]).all() and (p[1] != p[2]).any())
    True
    """

    body: str = "mars"
    perturbation: float = PERTURBATION
    precession_rate: float | tuple[float, float] | None = None
    dynamical_ellipticity: float | tuple[float, float] | None = None
    per_orbit: int = 1

    def _ranges(self) -> tuple[str, str | None, tuple[float, float] | None]:
        key = str(self.body).strip().lower()
        if key not in MEMBER_BODIES:
            msg = f"expected a body in {', '.join(MEMBER_BODIES)}, got {self.body!r}"
            raise ValueError(msg)
        if self.precession_rate is not None and self.dynamical_ellipticity is not None:
            msg = "expected a precession rate or a dynamical ellipticity range, got both"
            raise ValueError(msg)
        if self.dynamical_ellipticity is not None:
            span = _interval(self.dynamical_ellipticity, "dynamical_ellipticity", 0.0, 0.5)
            return self._varied(key, "dynamical_ellipticity", span)
        rate = self.precession_rate if self.precession_rate is not None else DEFAULT_RATES.get(key)
        if rate is None:
            return self._varied(key, None, None)
        return self._varied(key, "precession_rate", _interval(rate, "precession_rate", 0.0))

    def _varied(
        self, key: str, name: str | None, span: tuple[float, float] | None
    ) -> tuple[str, str | None, tuple[float, float] | None]:
        """The ranges, once ``per_orbit`` is checked against them."""
        per = self.per_orbit
        if isinstance(per, bool) or not isinstance(per, int | np.integer) or per < 1:
            msg = f"expected a positive whole number of members per orbit, got {per!r}"
            raise ValueError(msg)
        if per > 1 and (span is None or not span[1] > span[0]):
            what = "a fixed spin parameter" if span is not None else "no spin-parameter range"
            msg = (
                f"expected a spin-parameter range (low, high) for {per} members per orbit (members sharing "
                f"an orbit and a spin parameter would be equal), got {what} for {key}"
            )
            raise ValueError(msg)
        return key, name, span

    def sample(self, rng: np.random.Generator, n: int) -> Draw:
        """``n`` members: the J2000 spin axis as states (n,), and the parameters.

        Parameters
        ----------
        rng : numpy.random.Generator
        n : int

        Returns
        -------
        Draw
            ``orbit_perturbation`` (n, 32): real and imaginary parts of the (n, 16) displacement;
            ``precession_rate`` or ``dynamical_ellipticity`` (n,) where one varies or is given.
        """
        key, name, span = self._ranges()
        orbits = -(-n // self.per_orbit)
        delta = np.repeat(perturbed_states(orbits, self.perturbation, rng), self.per_orbit, axis=0)[:n]
        parameters: dict[str, Array] = {
            "orbit_perturbation": np.concatenate([delta.real, delta.imag], axis=1)
        }
        if name is not None and span is not None:
            lo, hi = span
            parameters[name] = rng.uniform(lo, hi, n) if hi > lo else np.full(n, lo)
        s0 = _axis(key)
        h0 = np.arctan2(s0[0], -s0[1])
        state = State.from_andoyer(0.0, 0.0, np.full(n, h0), 1.0, 1.0, np.full(n, s0[2]))
        return Draw(state, parameters)


@dataclass(frozen=True)
class MemberPropagator:
    """Each member's obliquity on its own perturbed secular orbit, as an ensemble kernel.

    Times must be ``0, Δt, 2Δt, …`` (or their negatives): the output grid of
    :func:`~andoyer.planetary.spin_axis.members.member_obliquities`. Returns
    ``{"obliquity": (n, T)}`` (radians, ``NaN`` after a member left the secular model's domain),
    for the ensemble output ``"obliquity"``.

    Parameters
    ----------
    body : {"mars", "earth", "moonless-earth"}
    spin_step : float
        Largest spin-axis step, years.
    """

    body: str = "mars"
    spin_step: float = 1000.0

    def __call__(
        self,
        state: State,
        times: ArrayLike,
        orbit_perturbation: ArrayLike,
        precession_rate: ArrayLike | None = None,
        dynamical_ellipticity: ArrayLike | None = None,
    ) -> dict[str, Array]:
        """Obliquities (n, T) of the members."""
        t = np.asarray(times, dtype=float)
        if t.size < 2 or t[0] != 0.0:
            msg = f"expected output times 0, DT, 2 DT, ... (at least two), got {t[:3].tolist()} ..."
            raise ValueError(msg)
        end, interval = float(t[-1]), float(abs(t[1]))
        n = state.size
        m = state.reshape(-1).m_reference
        axes = m / np.linalg.norm(m, axis=-1, keepdims=True)
        p = np.asarray(orbit_perturbation, dtype=float).reshape(n, 32)
        delta = p[:, :16] + 1j * p[:, 16:]
        # members with equal perturbations share their orbit's integration
        run = member_obliquities(
            self.body, end, interval, delta, axes,
            precession_rate=None if precession_rate is None else np.ravel(precession_rate),
            dynamical_ellipticity=None if dynamical_ellipticity is None else np.ravel(dynamical_ellipticity),
            spin_step=self.spin_step,
        )  # fmt: skip
        if run.t.size != t.size or not np.allclose(run.t, t, rtol=0.0, atol=1e-9 * abs(end)):
            msg = f"expected output times 0, DT, 2 DT, ... to {end:g}, got others"
            raise ValueError(msg)
        return {"obliquity": run.obliquity}


def _chunk(members: int, workers: int, per_orbit: int = 1) -> int:
    """A few chunks per worker, at most 8 orbits each (the unit of resumption), whole orbits."""
    orbits = members // per_orbit
    return per_orbit * max(1, min(8, math.ceil(orbits / (2 * max(workers, 1)))))


def obliquity_ensemble(
    body: str,
    members: int,
    end: float,
    interval: float,
    *,
    perturbation: float = PERTURBATION,
    precession_rate: float | tuple[float, float] | None = None,
    dynamical_ellipticity: float | tuple[float, float] | None = None,
    spin_step: float = 1000.0,
    orbits: int | None = None,
    bins: ArrayLike | None = None,
    thresholds: ArrayLike | None = None,
    seed: int = 0,
    chunk: int | None = None,
    out: str | os.PathLike[str] | None = None,
    scheduler: Any = None,
    n_workers: int = 2,
    progress: bool = True,
):
    r"""The obliquity of ``members`` members from J2000 to ``end``, and its statistics.

    Parameters
    ----------
    body : {"mars", "earth", "moonless-earth"}
    members : int
        ``N ≥ 1``.
    end, interval : float
        The last output time (years from J2000, ``0 < |end| ≤ 10⁹``) and the output step.
    perturbation : float
        Size of each member's perturbation of the J2000 secular state (default 10⁻⁶).
    precession_rate, dynamical_ellipticity : float or (low, high), optional
        The spin parameter's range (:class:`MemberSampler`).
    spin_step : float
        Largest spin-axis step, years.
    orbits : int, optional
        How many distinct orbits the members have (default: ``members``, each its own); a divisor
        of ``members``: each orbit then carries ``members / orbits`` spin axes, which differ by their
        spin parameter (a range is needed). The cost is about ``orbits`` orbits plus ``members``
        spin axes.
    bins, thresholds : array_like, optional
        Radians (:func:`~andoyer.planetary.spin_axis.statistics.obliquity_statistics`).
    seed : int
    chunk : int, optional
        Members per chunk, a multiple of ``members / orbits`` (default: a few chunks per worker, at
        most 8 orbits each).
    out : path, optional
        ``*.zarr`` or ``*.nc``: the histories, resumable (:func:`andoyer.ensemble.run_ensemble`).
    scheduler, n_workers, progress
        As :func:`andoyer.ensemble.run_ensemble`.

    Returns
    -------
    xarray.Dataset
        ``obliquity`` (sample, time, degrees), the members' parameters, and the statistics:
        ``members``, ``mean``, ``std``, ``min``, ``max`` (time), ``pdf`` (bin, 1/deg) with
        ``bin_edges``, ``exceedance``, ``fraction_of_time`` (threshold, degrees) and
        ``first_passage`` (threshold, sample, years).

    Raises
    ------
    ValueError
        Bad arguments, or a run that cannot fit in memory or time (:func:`andoyer._limits.check_size`).
    """
    from andoyer._limits import announce, check_size
    from andoyer.ensemble.runner import run_ensemble
    from andoyer.planetary.spin_axis.statistics import obliquity_statistics

    if isinstance(members, bool) or not isinstance(members, int | np.integer) or members < 1:
        msg = f"expected a positive whole number of members, got {members!r}"
        raise ValueError(msg)
    orbits = int(members) if orbits is None else orbits
    if isinstance(orbits, bool) or not isinstance(orbits, int | np.integer) or not 1 <= orbits <= members:
        msg = f"expected a whole number of orbits from 1 to the {members} members, got {orbits!r}"
        raise ValueError(msg)
    if members % orbits:
        msg = f"expected a number of orbits dividing the {members} members, got {orbits}"
        raise ValueError(msg)
    per_orbit = int(members) // int(orbits)
    sampler = MemberSampler(body, perturbation, precession_rate, dynamical_ellipticity, per_orbit)
    sampler._ranges()  # the body, the ranges and the members per orbit, before any work
    if chunk is not None and (
        isinstance(chunk, bool) or not isinstance(chunk, int | np.integer) or chunk % per_orbit
    ):
        msg = f"expected a chunk of whole orbits (a multiple of {per_orbit} members), got {chunk!r}"
        raise ValueError(msg)
    key = str(body).strip().lower()
    seconds, nbytes = member_cost(int(members), float(end), float(interval), float(spin_step), int(orbits))
    workers = 1 if isinstance(scheduler, str) and scheduler == "synchronous" else max(int(n_workers), 1)
    chunk = _chunk(int(members), workers, per_orbit) if chunk is None else chunk
    # no more workers than chunks run at once (run_ensemble starts no idle ones)
    busy = min(workers, math.ceil(int(members) / int(chunk)))
    # the histories in memory (and their statistics' temporaries: a few copies)
    check_size(f"an obliquity ensemble of {members} members", nbytes=4 * nbytes, seconds=seconds / busy)
    announce(seconds / busy, f"integrating {members} members of {abs(end):g} years")
    times = member_times(end, interval)
    ds = run_ensemble(
        sampler, int(members), times, propagator=MemberPropagator(key, float(spin_step)), out=out,
        chunk=chunk, seed=seed, output="obliquity",
        scheduler=scheduler, n_workers=n_workers, progress=progress,
    )  # fmt: skip
    eps = np.asarray(ds["obliquity"].values)
    stats = obliquity_statistics(times, eps, bins, thresholds).to_dataset(eps)
    extra = ds.drop_vars(["obliquity", "quaternion0", "m_body0"], errors="ignore").load()
    result = stats.merge(extra.drop_vars("time", errors="ignore"), compat="override")
    result.attrs.update(ds.attrs)
    result.attrs["body"] = key
    result.attrs["orbits"] = int(orbits)
    return result
