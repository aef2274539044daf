r"""N-body ensembles: the Solar System integrated from perturbed initial conditions, one member per Dask task.

The planets' orbits are chaotic (the inner planets' Lyapunov time is about 5 Myr), so beyond
~50 Myr a single N-body orbit is one possible history among many. As Laskar & Gastineau
(2009, Nature 459, 817), who shifted Mercury's initial position by multiples of 0.38 mm, an
ensemble here is made of members whose J2000 state differs from the shipped one
(:func:`~andoyer.planetary.orbits.planets.planet_data`, DE421) by a tiny displacement:

* member 0 is the nominal orbit itself (the same cache as :class:`NBodyOrbit` with no options);
* member ``k ≥ 1`` moves the heliocentric position of one planet (``perturb``, default Mercury)
  by ``delta`` au (default :data:`DEFAULT_DELTA` = 10⁻¹⁰ au, 15 m: far below the ephemeris'
  own uncertainty) along a unit vector drawn uniformly on the sphere by
  ``numpy.random.default_rng([seed, k])``, the velocities unchanged, and the whole system
  then moved to its barycentre:

  .. math:: r_p \leftarrow r_p + \delta\,\hat u_k, \qquad
     (r, v)_i \leftarrow (r, v)_i - \frac{\sum_j m_j (r, v)_j}{\sum_j m_j}.

Each member is an :class:`~andoyer.planetary.orbits.nbody.NBodyOrbit` with that
``initial_state``: its orbit is integrated and cached in the N-body cache format (pieces
every 500 kyr, keyed by the initial state), so a run interrupted (Ctrl-C, a lost worker, a
killed process) resumes each member where its cache stopped, and a finished member costs only
the reading of its cache. :func:`run_nbody_ensemble` integrates the members on Dask (a local
cluster, any scheduler by address, or in this process), one member per task, and
:func:`nbody_member` gives a member's orbit of any planet afterwards (read from the cache).

Cost, known before the work: :data:`~andoyer.planetary.orbits.nbody.SECONDS_PER_MYR` (87 s) per
Myr and direction per member on one core; memory per worker that of one N-body orbit
(400 bytes per sample).
"""

from __future__ import annotations

import math
import uuid
from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import NDArray

from andoyer.planetary.orbits.nbody import NBodyOrbit
from andoyer.planetary.orbits.planets import check_planet, planet_data

__all__ = ["DEFAULT_DELTA", "nbody_member", "perturbed_state", "run_nbody_ensemble"]

Array = NDArray[np.float64]

#: The default displacement of the perturbed planet (au): 10⁻¹⁰ au = 14.96 m.
DEFAULT_DELTA = 1.0e-10


def _check_member(member: int, seed: int) -> None:
    for name, value in (("member", member), ("seed", seed)):
        if isinstance(value, bool) or not isinstance(value, int | np.integer) or value < 0:
            msg = f"expected a non-negative integer {name}, got {value!r}"
            raise ValueError(msg)


def perturbed_state(
    member: int, seed: int = 0, delta: float = DEFAULT_DELTA, perturb: str = "mercury"
) -> Array | None:
    r"""The J2000 barycentric state of ensemble member ``member`` (module notes); ``None`` for member 0.

    Parameters
    ----------
    member : int
        0 (the nominal orbit) or more.
    seed : int
        Non-negative; with ``member``, seeds the direction of the displacement.
    delta : float
        Displacement of the perturbed planet's heliocentric position (au), ``0 < delta ≤ 1e-3``.
    perturb : str
        The planet displaced.

    Returns
    -------
    numpy.ndarray, shape (9, 6), or None
        Positions (au) and velocities (au/yr) of the Sun and the eight planets, barycentric.

    Examples
    --------
    >>> state = perturbed_state(3, seed=1)
    >>> shipped = planet_data()
    >>> moved = (state[1, :3] - state[0, :3]) - shipped.position[0]  # Mercury, heliocentric
    >>> round(float(np.linalg.norm(moved)) / 1e-10, 6), perturbed_state(0) is None
    (1.0, True)
    """
    _check_member(member, seed)
    if not (isinstance(delta, int | float | np.floating) and math.isfinite(delta) and 0.0 < delta <= 1e-3):
        msg = f"expected a displacement 0 < delta <= 1e-3 au, got {delta!r}"
        raise ValueError(msg)
    j = check_planet(perturb)
    if member == 0:
        return None
    data = planet_data()
    rng = np.random.default_rng([int(seed), int(member)])
    direction = rng.normal(size=3)
    direction /= np.linalg.norm(direction)
    rows = np.zeros((9, 6))
    rows[1:, :3], rows[1:, 3:] = data.position, data.velocity
    rows[1 + j, :3] += float(delta) * direction
    masses = np.array([data.sun_gm, *data.gm])
    return rows - masses @ rows / masses.sum()


def nbody_member(
    member: int,
    body: str = "earth",
    seed: int = 0,
    delta: float = DEFAULT_DELTA,
    perturb: str = "mercury",
    **options: Any,
) -> NBodyOrbit:
    """The orbit of ``body`` in ensemble member ``member`` (read from the cache, or integrated).

    Parameters
    ----------
    member, seed, delta, perturb
        As :func:`perturbed_state`.
    body : str
        A planet of :data:`~andoyer.planetary.orbits.planets.PLANETS`.
    **options
        Passed to :class:`~andoyer.planetary.orbits.nbody.NBodyOrbit` (``step_days``,
        ``sample_years``, ``gr``, ``max_span``, ``cache``, ``progress``).

    Returns
    -------
    NBodyOrbit

    Examples
    --------
    >>> nbody_member(2, "mars", seed=7, cache=False, gr=False).key == nbody_member(
    ...     2, "mars", seed=8, cache=False, gr=False).key
    False
    """
    if "initial_state" in options:
        msg = "expected the member's initial state from member, seed, delta and perturb, got initial_state="
        raise ValueError(msg)
    return NBodyOrbit(body, initial_state=perturbed_state(member, seed, delta, perturb), **options)


def _integrate_member(member: int, span: tuple[float, float], settings: dict[str, Any]) -> str:
    """Dask task: integrate (or read) member ``member`` over ``span``; its cache key."""
    orbit = nbody_member(member, **settings)
    orbit.normal(np.array(span))
    return orbit.key


def run_nbody_ensemble(
    members: int,
    span: tuple[float, float],
    *,
    seed: int = 0,
    delta: float = DEFAULT_DELTA,
    perturb: str = "mercury",
    scheduler: Any = None,
    n_workers: int = 2,
    processes: bool = True,
    progress: bool = False,
    on_member: Callable[[int], None] | None = None,
    **options: Any,
) -> list[str]:
    """Integrate ``members`` N-body members over ``span``, one Dask task each, into the N-body cache.

    Parameters
    ----------
    members : int
        Number of members (member 0 is the nominal orbit).
    span : tuple of float
        ``(t0, t1)``, Julian years from J2000, ``t0 ≤ 0 ≤ t1`` not required: each member is
        integrated from J2000 to both ends.
    seed, delta, perturb
        As :func:`perturbed_state`.
    scheduler : None, "synchronous", str or distributed.Client
        As :func:`andoyer.ensemble.run_ensemble`.
    n_workers : int
        Workers of the local cluster.
    processes : bool
        Local cluster of processes or threads.
    progress : bool
        A progress bar over the members (standard error).
    on_member : callable, optional
        Called with each member's index once it is integrated (in this process).
    **options
        Passed to each member's :class:`~andoyer.planetary.orbits.nbody.NBodyOrbit`
        (``step_days``, ``sample_years``, ``gr``, ``cache``); ``max_span`` is set from ``span``.

    Returns
    -------
    list of str
        The members' cache keys, in member order.

    Raises
    ------
    ValueError
        Bad arguments, or a member longer than one may run (:func:`andoyer._limits.check_size`).

    Examples
    --------
    >>> keys = run_nbody_ensemble(2, (-200.0, 0.0), scheduler="synchronous", cache=False, gr=False)
    >>> len(keys), keys[0] != keys[1]
    (2, True)
    """
    from tqdm.auto import tqdm

    from andoyer._limits import announce, check_size
    from andoyer.planetary.orbits.nbody import CHUNK_YEARS, SAMPLE_BYTES, SECONDS_PER_MYR, cache_directory

    if isinstance(members, bool) or not isinstance(members, int | np.integer) or members < 1:
        msg = f"expected a positive integer number of members, got {members!r}"
        raise ValueError(msg)
    t0, t1 = (float(x) for x in span)
    if not (math.isfinite(t0) and math.isfinite(t1) and t0 <= t1):
        msg = f"expected a finite span T0 <= T1 (years from J2000), got {span!r}"
        raise ValueError(msg)
    perturbed_state(0, seed, delta, perturb)  # the arguments checked here, not in a worker
    reach = max(abs(t0), abs(t1))
    settings = {
        "seed": seed,
        "delta": delta,
        "perturb": perturb,
        **options,
        "max_span": max(reach, CHUNK_YEARS),
    }
    first = nbody_member(0, **{**settings, "progress": False})  # the options checked here
    # Whole chunks each way, with the spline's margin: what one member integrates at most.
    years = sum(
        math.ceil((abs(x) + 2 * first.sample_years) / CHUNK_YEARS) * CHUNK_YEARS
        for x in (min(t0, 0), max(t1, 0))
    )
    seconds = years / 1e6 * SECONDS_PER_MYR
    check_size(
        f"one N-body member of {years / 1e6:.3g} Myr",
        nbytes=years / first.sample_years * SAMPLE_BYTES,
        seconds=seconds,
    )
    workers = 1 if scheduler == "synchronous" else max(1, int(n_workers))
    where = cache_directory() if options.get("cache", True) else None
    announce(seconds * math.ceil(members / workers), f"integrating {members} N-body members", where)
    settings["progress"] = False
    keys: dict[int, str] = {}
    with tqdm(total=members, disable=not progress, unit="member", desc="nbody ensemble") as bar:
        if scheduler == "synchronous":
            for k in range(members):
                keys[k] = _integrate_member(k, (t0, t1), settings)
                bar.update()
                if on_member is not None:
                    on_member(k)
        else:
            from distributed import as_completed

            from andoyer.ensemble.runner import _client

            run_id = uuid.uuid4().hex[:12]
            with _client(scheduler, n_workers, processes) as client:
                futures = {
                    client.submit(
                        _integrate_member, k, (t0, t1), settings, key=f"andoyer_nbody_member-{k}-{run_id}"
                    ): k
                    for k in range(members)
                }
                try:
                    for future in as_completed(list(futures)):
                        k = futures[future]
                        keys[k] = future.result()
                        bar.update()
                        if on_member is not None:
                            on_member(k)
                except BaseException:
                    # What each member integrated is in its cache (a piece every 500 kyr).
                    client.cancel(list(futures))
                    raise
    return [keys[k] for k in range(members)]
