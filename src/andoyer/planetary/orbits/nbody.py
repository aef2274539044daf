r"""The Sun and the eight planets integrated with REBOUND: osculating orbits, cached on disk.

**Model.** Nine point masses (the Earth–Moon barycentre as one body; each planet with the
GM of its system, JPL DE440), started at J2000 from the shipped heliocentric states
(:mod:`andoyer.planetary.orbits.planets`: the JPL DE421 ephemeris' states at JD 2451545.0 TDB; see
``scripts/make_nbody_initial_conditions.py``), integrated forwards and
backwards from J2000 with WHFast (Wisdom–Holman in Jacobi coordinates, symplectic corrector
of order 17) at a step of about 4 days (``step_days``; Mercury's 88-day orbit in 22 steps;
the step is adjusted so that a whole number of steps fills each sampling interval).
General relativity: the Sun's post-Newtonian potential of Nobili & Roxburgh (1986) through
REBOUNDx ``gr_potential`` (the one of REBOUNDx's GR models meant for symplectic
integrators: it gives the right perihelion precession; the tests measure 42.80″/cy for
Mercury against Einstein's 42.98″/cy). Without REBOUNDx (``gr=False``, or not installed)
the orbits leave out GR: the perihelia then precess too slowly by
``3 (GM)^{3/2}/(c² a^{5/2} (1−e²))``, 43.0″/cy for Mercury, 3.8″/cy for the Earth,
1.35″/cy for Mars.

**Output.** The heliocentric *osculating* orbit of the chosen planet, from ``h = r × v``
(the normal) and ``e = v × h/μ − r/|r|``, ``μ = G(M_☉ + m)``, sampled every
``sample_years`` (default 100 yr) and interpolated by a cubic spline. The osculating
elements are not averaged: their short-period terms (measured over 1 kyr at 0.05-yr
sampling) are 0.2″ (Earth) and 0.3″ (Mars) in the normal and 2×10⁻⁵ (Earth),
7×10⁻⁵ (Mars) in ``e``, far below the secular motion the spin axis responds to; sampling
below Nyquist aliases these terms but cannot enlarge them.

**Errors and cost** (measured on this project's shared 2-core machine): energy conserved
to 5e-13 relatively over 1 kyr; halving the step moves the Earth's and Mars' normals by
less than 0.5″ over ±20 kyr; the Earth's normal is within 0.9″ of
:class:`~andoyer.planetary.orbits.vondrak.VondrakEcliptic` over ±1 kyr, 0.009° over ±20 kyr, 0.054°
over ±100 kyr and 0.106° over ±200 kyr (VCW 2011 state a few tenths of a degree of their
own error there). Cost: 84 CPU seconds per Myr integrated (one direction, one core,
``benchmarks/bench_orbits.py``; GR adds 2–3 %; REBOUND's IAS15 is 31× slower), 250–290 s of
wall time per Myr on the shared machine; a cached span is read in milliseconds.
The initial states are DE421's osculating states, so the mean motions and the
Jupiter–Saturn great inequality start right: the giant planets' secular frequencies from
them are within 0.02″/yr of La2004's (``g5`` 4.2454, ``g6`` 28.2583, ``g7`` 3.0880,
``g8`` 0.6727, ``s6`` −26.3384, ``s7`` −2.9941, ``s8`` −0.6924 ″/yr over 8.2 Myr,
``scripts/check_outer_frequencies.py``; from Standish's mean elements taken as osculating,
as before 2026-11-25, Saturn ran 0.7% fast and ``g6`` came out 26.05″/yr).
The Moon's action on the Earth–Moon barycentre's orbit, the
Sun's J2 and oblateness, asteroids and tides are left out. What each costs in obliquity and
climatic precession over 1 Myr, and the distance from La2004, are measured in
docs/spin-axis.md (``scripts/nbody_variants.py``, ``scripts/compare_la2004.py``).

**Cache.** Results are stored under ``$ANDOYER_CACHE_DIR``, else ``$XDG_CACHE_HOME/andoyer``,
else ``~/.cache/andoyer``, in files named by a SHA-256 of the initial conditions, the
integrator settings and the REBOUND(x) versions (not the span): one file per direction,
holding every planet's normal and eccentricity vector, and the last state so that a later
request for a longer span extends the run instead of repeating it. Writes are atomic; an
unreadable or inconsistent file is recomputed. A progress bar (tqdm, on standard error)
shows on long runs when standard error is a terminal.
"""

from __future__ import annotations

import hashlib
import io
import json
import os
import sys
from pathlib import Path

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._files import atomic_write_bytes
from andoyer.planetary.orbits.elements import state_to_vectors
from andoyer.planetary.orbits.planets import PLANETS, check_planet, planet_data
from andoyer.planetary.orbits.protocol import check_times

__all__ = ["NBodyOrbit", "cache_directory", "make_simulation"]

Array = NDArray[np.float64]

#: Speed of light, au per Julian year (299 792.458 km/s, au = 149 597 870.700 km).
C_AU_PER_YEAR = 299792.458 * 365.25 * 86400.0 / 149597870.700
#: Integrations are extended in chunks of this many years (whole sampling intervals).
CHUNK_YEARS = 1000.0
CACHE_FORMAT = 2  # 2: samples at the times reached (aimed half a step short)


def cache_directory() -> Path:
    """The folder of the N-body cache (see the module's notes).

    Returns
    -------
    pathlib.Path

    Examples
    --------
    >>> cache_directory().name in ("andoyer",) or "ANDOYER_CACHE_DIR" in os.environ
    True
    """
    if os.environ.get("ANDOYER_CACHE_DIR"):
        return Path(os.environ["ANDOYER_CACHE_DIR"])
    base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(base) / "andoyer"


def _has_reboundx() -> bool:
    try:
        import reboundx  # noqa: F401
    except ImportError:
        return False
    return True


def make_simulation(step_years: float, gr: bool, state: Array | None = None, t: float = 0.0) -> tuple:
    """The Sun and the eight planets in a REBOUND simulation (WHFast, G = 1, au, yr).

    Parameters
    ----------
    step_years : float
        The WHFast step (years; negative integrates backwards).
    gr : bool
        Add the Sun's post-Newtonian potential (REBOUNDx ``gr_potential``).
    state : array_like, shape (9, 6), optional
        Barycentric positions and velocities of the Sun and the planets at ``t``;
        default: the shipped J2000 states, moved to the barycentre.
    t : float
        The time of ``state`` (years from J2000).

    Returns
    -------
    rebound.Simulation, and the REBOUNDx extras (or ``None``), which must stay alive with it.

    Examples
    --------
    >>> sim, extras = make_simulation(4.0 / 365.25, gr=False)
    >>> sim.N, extras is None
    (9, True)
    """
    import rebound

    data = planet_data()
    sim = rebound.Simulation()
    sim.G = 1.0  # masses are GM in au³/yr²
    masses = [data.sun_gm, *data.gm]
    if state is None:
        rows = np.concatenate([np.zeros((1, 6)), np.concatenate([data.position, data.velocity], axis=1)])
    else:
        rows = np.asarray(state, dtype=float)
    for m, (x, y, z, vx, vy, vz) in zip(masses, rows, strict=True):
        sim.add(m=m, x=x, y=y, z=z, vx=vx, vy=vy, vz=vz)
    if state is None:
        sim.move_to_com()
    sim.t = t
    sim.integrator = "whfast"
    sim.integrator.corrector = 17
    sim.integrator.safe_mode = 0  # synchronised only at the end of each integrate()
    sim.dt = step_years
    extras = None
    if gr:
        import reboundx

        extras = reboundx.Extras(sim)
        force = extras.load_force("gr_potential")
        extras.add_force(force)
        force.params["c"] = C_AU_PER_YEAR
    return sim, extras


def _vectors(states: Array) -> tuple[Array, Array]:
    """Heliocentric osculating normals and eccentricity vectors of the 8 planets from (..., 9, 6) states."""
    data = planet_data()
    rel = states[..., 1:, :] - states[..., :1, :]
    return state_to_vectors(data.sun_gm + data.gm, rel[..., :3], rel[..., 3:])


class _Segment:
    """Samples of one direction of integration (``sign = ±1``), cached in one file."""

    def __init__(self, path: Path | None, sign: int, step: float, sample: float, gr: bool) -> None:
        self.path, self.sign, self.step, self.sample, self.gr = path, sign, step, sample, gr
        self.t = np.zeros(0)
        self.normal = np.zeros((0, 8, 3))
        self.ecc = np.zeros((0, 8, 3))
        self.last_state = np.zeros((9, 6))
        if path is not None:
            self._load()

    def _load(self) -> None:
        try:
            # Read the bytes first: np.load on a truncated file leaves its handle open.
            with np.load(io.BytesIO(self.path.read_bytes()), allow_pickle=False) as f:
                t, normal, ecc, last = f["t"], f["normal"], f["ecc"], f["last_state"]
            ok = (
                t.ndim == 1
                and normal.shape == ecc.shape == (t.size, 8, 3)
                and last.shape == (9, 6)
                and t.size > 0
                and np.all(np.isfinite(normal))
                and np.all(np.isfinite(ecc))
                and np.all(np.diff(self.sign * t) > 0)
            )
        except Exception:  # any unreadable cache file is recomputed, never trusted
            ok = False
        if ok:
            self.t, self.normal, self.ecc, self.last_state = t, normal, ecc, last

    @property
    def reach(self) -> float:
        """How far from J2000 (years, ≥ 0) the samples go."""
        return float(abs(self.t[-1])) if self.t.size else -1.0

    def extend(self, reach: float, progress: bool | None) -> None:
        """Integrate until the samples cover ``reach`` years from J2000 in this direction."""
        if self.reach >= reach:
            return
        from tqdm import tqdm

        if self.t.size:  # resume from the last synchronised state
            sim, extras = make_simulation(self.sign * self.step, self.gr, self.last_state, float(self.t[-1]))
            start, first = self.reach, 1
        else:
            sim, extras = make_simulation(self.sign * self.step, self.gr)
            start, first = 0.0, 0
        target = np.ceil(reach / CHUNK_YEARS) * CHUNK_YEARS
        count = round((target - start) / self.sample)
        times = self.sign * (start + self.sample * np.arange(first, count + 1))
        show = (sys.stderr.isatty() if progress is None else progress) and (target - start) > 20000.0
        states = np.empty((times.size, 9, 6))
        reached = np.empty(times.size)
        buf = np.empty((9, 6))
        for k, t in enumerate(tqdm(times, disable=not show, unit="sample", desc="nbody", file=sys.stderr)):
            if k or first:
                # Aim half a step short: the run stops on the step that lands on t (a whole number of
                # steps per sample), never one step later because the summed steps fell short by round-off.
                sim.integrate(float(t) - 0.5 * sim.dt, exact_finish_time=0)
            sim.serialize_particle_data(xyzvxvyvz=buf)
            states[k], reached[k] = buf, sim.t
        del extras
        normal, ecc = _vectors(states)
        self.t = np.concatenate([self.t, reached])
        self.normal = np.concatenate([self.normal, normal])
        self.ecc = np.concatenate([self.ecc, ecc])
        self.last_state = states[-1].copy()
        self._save()

    def _save(self) -> None:
        if self.path is None:
            return
        stream = io.BytesIO()
        np.savez(stream, t=self.t, normal=self.normal, ecc=self.ecc, last_state=self.last_state)
        try:
            self.path.parent.mkdir(parents=True, exist_ok=True)
            atomic_write_bytes(self.path, stream.getvalue())
        except OSError as exc:  # a read-only cache costs a recomputation next time, not a failure now
            import warnings

            msg = f"could not write the N-body cache {self.path}: {exc}"
            warnings.warn(msg, RuntimeWarning, stacklevel=4)


class NBodyOrbit:
    """A planet's osculating heliocentric orbit from a REBOUND integration of the Solar System.

    Parameters
    ----------
    body : str
        One of :data:`~andoyer.planetary.orbits.planets.PLANETS` (``"earth"`` = Earth–Moon barycentre).
    step_days : float
        Approximate WHFast step (days).
    sample_years : float
        Sampling interval of the stored orbit (years; a divisor of 1000).
    gr : bool or None
        General relativity through REBOUNDx; ``None``: where REBOUNDx is installed (a
        :class:`UserWarning` says so where it is not).
    max_span : float
        The largest ``|t|`` (years) that may be asked for: ``span = (−max_span, max_span)``.
        The integration only runs as far as the times asked for, and is cached.
    cache : bool
        Read and write the on-disk cache.
    progress : bool or None
        Progress bar on long runs; ``None``: when standard error is a terminal.

    Examples
    --------
    >>> orbit = NBodyOrbit("mars", cache=False)
    >>> orbit.span, orbit.has_eccentricity
    ((-50000000.0, 50000000.0), True)
    """

    name = "nbody"
    has_eccentricity = True

    def __init__(
        self,
        body: str = "earth",
        step_days: float = 4.0,
        sample_years: float = 100.0,
        gr: bool | None = None,
        max_span: float = 5.0e7,
        cache: bool = True,
        progress: bool | None = None,
    ) -> None:
        self.body = PLANETS[check_planet(body)]
        self._index = PLANETS.index(self.body)
        if not (np.isfinite(step_days) and 0.01 <= step_days <= 30.0):
            msg = f"expected step_days between 0.01 and 30, got {step_days!r}"
            raise ValueError(msg)
        ratio = CHUNK_YEARS / sample_years if sample_years > 0 else 0.0
        if not (np.isfinite(ratio) and ratio >= 1 and abs(ratio - round(ratio)) < 1e-9):
            msg = f"expected sample_years dividing {CHUNK_YEARS:g} years, got {sample_years!r}"
            raise ValueError(msg)
        if not (np.isfinite(max_span) and max_span > 0):
            msg = f"expected a positive max_span, got {max_span!r}"
            raise ValueError(msg)
        if gr is None:
            gr = _has_reboundx()
            if not gr:
                import warnings

                msg = (
                    "reboundx is not installed: the N-body orbits leave out general relativity "
                    "(perihelia 43.0″/cy slow for Mercury, 3.8″/cy for the Earth; pip install 'andoyer[gr]')"
                )
                warnings.warn(msg, UserWarning, stacklevel=2)
        elif gr and not _has_reboundx():
            msg = "expected reboundx to be installed for gr=True (pip install 'andoyer[gr]'), got no reboundx"
            raise ValueError(msg)
        self.gr = bool(gr)
        self.sample_years = float(sample_years)
        # A whole number of steps per sample, so that every sample falls on a step.
        steps_per_sample = max(1, round(sample_years * 365.25 / step_days))
        self.step_years = self.sample_years / steps_per_sample
        self.span = (-float(max_span), float(max_span))
        self.progress = progress
        self.cache = cache
        self.key = self._key()
        folder = cache_directory()
        self._segments = {
            sign: _Segment(
                folder / f"nbody-{self.key}-{'forward' if sign > 0 else 'backward'}.npz" if cache else None,
                sign,
                self.step_years,
                self.sample_years,
                self.gr,
            )
            for sign in (1, -1)
        }
        self._spline_reach = (-1.0, -1.0)
        self._splines = None

    def _key(self) -> str:
        import rebound

        settings = {
            "format": CACHE_FORMAT,
            "data": planet_data().digest,
            "integrator": "whfast-corrector17-jacobi",
            "step_years": self.step_years,
            "sample_years": self.sample_years,
            "chunk_years": CHUNK_YEARS,
            "gr": "gr_potential" if self.gr else None,
            "c": C_AU_PER_YEAR if self.gr else None,
            "rebound": rebound.__version__,
        }
        if self.gr:
            import reboundx

            settings["reboundx"] = reboundx.__version__
        return hashlib.sha256(json.dumps(settings, sort_keys=True).encode()).hexdigest()[:24]

    def _ensure(self, times: Array) -> None:
        from scipy.interpolate import CubicSpline

        # Two samples of margin keep the spline's end conditions away from the times asked for.
        margin = 2.0 * self.sample_years
        need_forward = float(max(times.max(), 0.0)) + margin if times.size else margin
        need_backward = float(max(-times.min(), 0.0)) + margin if times.size else margin
        forward, backward = self._segments[1], self._segments[-1]
        forward.extend(need_forward, self.progress)
        backward.extend(need_backward, self.progress)
        reach = (forward.reach, backward.reach)
        if reach != self._spline_reach:
            t = np.concatenate([backward.t[::-1], forward.t[1:]])
            j = self._index
            normal = np.concatenate([backward.normal[::-1, j], forward.normal[1:, j]])
            ecc = np.concatenate([backward.ecc[::-1, j], forward.ecc[1:, j]])
            self._splines = (CubicSpline(t, normal, axis=0), CubicSpline(t, ecc, axis=0))
            self._spline_reach = reach

    def normal(self, t: ArrayLike) -> Array:
        """Unit normal of the osculating heliocentric orbit, J2000 ecliptic frame.

        Parameters
        ----------
        t : array_like, shape (...)
            Julian years TT from J2000, within ``span`` (integrates as far as needed).

        Returns
        -------
        numpy.ndarray, shape (..., 3)
        """
        times = check_times(t, self.span, self.name)
        self._ensure(times)
        n = self._splines[0](times)
        return n / np.linalg.norm(n, axis=-1, keepdims=True)

    def eccentricity_vector(self, t: ArrayLike) -> Array:
        """Osculating eccentricity vector (``e`` times the unit vector to perihelion).

        Parameters
        ----------
        t : array_like, shape (...)
            Julian years TT from J2000, within ``span``.

        Returns
        -------
        numpy.ndarray, shape (..., 3)
        """
        times = check_times(t, self.span, self.name)
        self._ensure(times)
        return self._splines[1](times)

    def __repr__(self) -> str:
        return f"NBodyOrbit({self.body!r}, gr={self.gr})"
