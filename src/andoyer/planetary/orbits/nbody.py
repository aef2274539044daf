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
else ``~/.cache/andoyer``, named by a SHA-256 of the initial conditions, the integrator
settings and the REBOUND(x) versions (not the span), in *pieces*: each file
``nbody-KEY-DIRECTION-FIRST-LAST.npz`` holds samples ``FIRST`` to ``LAST`` of one direction
(sample ``i`` at ``±i · sample_years``) of every planet's normal and eccentricity vector, and
the state at its last sample, from which a later request for a longer span goes on instead
of starting again. A piece is written (atomically) every :data:`PIECE_YEARS` of integration
and when a run ends or is interrupted (Ctrl-C: the run raises
:class:`~andoyer._limits.Interrupted` saying how much it kept), so that no more than a
thousand years of work is lost to Ctrl-C, and no more than a piece to ``kill -9``.

Every thousand years (:data:`CHUNK_YEARS`) the integration starts again from the state it
saved, exactly as a later run resuming from the cache does: an orbit is the same to the last
bit however its span was reached (in one run, in several, or interrupted and resumed), and
the pieces of concurrent runs agree wherever they overlap. Pieces are only ever added (a
run reads the longest chain of pieces from J2000), so two concurrent runs of different
spans never shrink the cache.

On loading, each piece is checked (shapes; finite values; unit normals to 10⁻⁹;
eccentricities below 1; times strictly increasing away from J2000, each within a step of
its sample's; the saved state finite and giving the piece's last sample): a piece that
fails is removed with a warning and its span recomputed. A temporary ``.part`` file left by
a killed write is removed once it is older than :data:`STALE_PART_SECONDS` (15 minutes; a
piece is written in well under a second, so no live writer holds one that old). A cache
folder that cannot be written costs a recomputation next time, with one warning. A run
estimated past ten seconds says so once on standard error (the command line), with where
it is cached; a progress bar (tqdm) shows on a terminal.
"""

from __future__ import annotations

import contextlib
import hashlib
import io
import json
import os
import re
import sys
import time
import warnings
from pathlib import Path

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._files import atomic_write_bytes
from andoyer._limits import Interrupted, announce, check_size
from andoyer.catalogue.units import AU, DAY, JULIAN_YEAR, SPEED_OF_LIGHT
from andoyer.planetary.orbits.elements import state_to_vectors
from andoyer.planetary.orbits.planets import PLANETS, check_planet, planet_data
from andoyer.planetary.orbits.protocol import check_times

__all__ = ["NBodyOrbit", "cache_directory", "make_simulation"]

Array = NDArray[np.float64]

#: Speed of light, au per Julian year (:data:`andoyer.catalogue.units.SPEED_OF_LIGHT`, ``AU``).
C_AU_PER_YEAR = SPEED_OF_LIGHT * JULIAN_YEAR / AU
#: Integrations are extended in chunks of this many years (whole sampling intervals), each
#: started from the state saved at the end of the one before.
CHUNK_YEARS = 1000.0
#: A piece of the cache is written every this many years of integration (a whole number of chunks).
PIECE_YEARS = 500_000.0
#: A ``.part`` file of the cache folder older than this (seconds) belongs to no live writer.
STALE_PART_SECONDS = 900.0
#: Seconds per Myr integrated, one direction (84 CPU s on one core, GR 3 % more; measured with
#: ``benchmarks/bench_orbits.py``), for the estimate announced before a run.
SECONDS_PER_MYR = 87.0
#: Bytes held per sample and direction: its time, the planet's normal and eccentricity vector
#: (56), the two cubic splines (192) and their construction (a bound of the measured ~100).
SAMPLE_BYTES = 400
# 3: in pieces, each chunk started from the saved state; 2: samples at the times reached
CACHE_FORMAT = 3


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


_PIECE = re.compile(
    r"^nbody-(?P<key>[0-9a-f]+)-(?P<direction>forward|backward)-(?P<first>\d+)-(?P<last>\d+)\.npz$"
)
_UNWRITABLE: set[str] = set()  # cache folders already warned about (one warning per folder)


def _clean_stale_parts(folder: Path) -> None:
    """Remove what killed writes left: ``.nbody-*.part`` files older than :data:`STALE_PART_SECONDS`."""
    try:
        names = list(folder.glob(".nbody-*.part"))
    except OSError:
        return
    now = time.time()

    def stale(path: Path) -> bool:
        try:
            return now - path.stat().st_mtime > STALE_PART_SECONDS
        except OSError:
            return False

    for path in filter(stale, names):
        with contextlib.suppress(OSError):
            path.unlink()


def _years(years: float) -> str:
    """``12 kyr``, ``1.35 Myr``."""
    return f"{years / 1e6:.3g} Myr" if years >= 1e5 else f"{years / 1e3:.3g} kyr"


class _Segment:
    """Samples of one direction of integration (``sign = ±1``) of planet ``index``, cached in pieces."""

    def __init__(
        self, folder: Path | None, key: str, sign: int, step: float, sample: float, gr: bool, index: int
    ) -> None:
        self.folder, self.key, self.sign, self.index = folder, key, sign, index
        self.step, self.sample, self.gr = step, sample, gr
        self.initial: Array | None = None  # J2000 barycentric states (9, 6); None: the shipped ones
        self.direction = "forward" if sign > 0 else "backward"
        self.t = np.zeros(0)
        self.normal = np.zeros((0, 3))
        self.ecc = np.zeros((0, 3))
        self.last_state = np.zeros((9, 6))
        self._parts: list[tuple] = []  # pieces read and not yet joined to the arrays above
        if folder is not None:
            _clean_stale_parts(folder)

    # -- reading ------------------------------------------------------------------------------

    def _pieces(self) -> list[tuple[int, int, Path]]:
        try:
            names = list(self.folder.iterdir())
        except OSError:
            return []
        found = []
        for path in names:
            match = _PIECE.match(path.name)
            if match and match["key"] == self.key and match["direction"] == self.direction:
                found.append((int(match["first"]), int(match["last"]), path))
        return found

    def _check(self, first: int, last: int, t, normal, ecc, state) -> str | None:
        """What is wrong with a piece's contents, or ``None``."""
        count = last - first + 1
        shapes = (t.shape, normal.shape, ecc.shape, state.shape)
        if shapes != ((count,), (count, 8, 3), (count, 8, 3), (9, 6)):
            return f"shapes {shapes} for samples {first} to {last}"
        named = (("times", t), ("normals", normal), ("eccentricities", ecc), ("last state", state))
        bad = [name for name, values in named if not np.all(np.isfinite(values))]
        if bad:
            return f"{bad[0]} not finite"
        if not np.all(np.abs(np.linalg.norm(normal, axis=-1) - 1.0) <= 1e-9):
            return "normals not of unit length"
        if not np.all(np.linalg.norm(ecc, axis=-1) < 1.0):
            return "an eccentricity of 1 or more"
        nominal = self.sign * self.sample * np.arange(first, last + 1)
        if not (np.all(np.diff(self.sign * t) > 0) and np.all(np.abs(t - nominal) <= self.step)):
            return "times not those of its samples"
        n_last, e_last = _vectors(state[None])
        if not (np.array_equal(n_last[0], normal[-1]) and np.array_equal(e_last[0], ecc[-1])):
            return "a last state that does not give its last sample"
        return None

    def _read(self, first: int, last: int, path: Path) -> tuple | None:
        """A checked piece ``(t, normal_j, ecc_j, state)``, or ``None`` (a bad one is removed, warned)."""
        try:
            # Read the bytes first: np.load on a truncated file leaves its handle open.
            with np.load(io.BytesIO(path.read_bytes()), allow_pickle=False) as f:
                t, normal, ecc, state = f["t"], f["normal"], f["ecc"], f["last_state"]
            problem = self._check(first, last, t, normal, ecc, state)
        except FileNotFoundError:  # removed by a concurrent run since it was listed
            return None
        except Exception as exc:  # any unreadable file is recomputed, never trusted
            problem = f"unreadable ({type(exc).__name__})"
        if problem is not None:
            msg = f"the N-body cache file {path} was damaged ({problem}): removed, its span is recomputed"
            warnings.warn(msg, RuntimeWarning, stacklevel=2)
            with contextlib.suppress(OSError):
                path.unlink()
            return None
        j = self.index
        return t, normal[:, j].copy(), ecc[:, j].copy(), state

    def _load(self, reach: float) -> None:
        """Read the chain of good pieces from where the samples end until they cover ``reach`` years.

        At each end, the piece that goes furthest; only what a request needs is read (a 10 kyr
        request does not read a 50 Myr cache).
        """
        if self.folder is None or self.reach >= reach:
            return
        pieces = self._pieces()
        end = self.t.size - 1  # index of the last sample held
        while self.reach_of(end) < reach:
            usable = sorted((p for p in pieces if p[0] <= end + 1 <= p[1]), key=lambda p: -p[1])
            for first, last, path in usable:
                read = self._read(first, last, path)
                pieces.remove((first, last, path))
                if read is not None:
                    t, normal, ecc, state = read
                    skip = end + 1 - first
                    self._parts.append((t[skip:], normal[skip:], ecc[skip:]))
                    self.last_state = state
                    end = last
                    break
            else:
                break
        if self._parts:
            self.t = np.concatenate([self.t, *(p[0] for p in self._parts)])
            self.normal = np.concatenate([self.normal, *(p[1] for p in self._parts)])
            self.ecc = np.concatenate([self.ecc, *(p[2] for p in self._parts)])
            self._parts = []

    def reach_of(self, index: int) -> float:
        """Years from J2000 of sample ``index`` (``-1``: none)."""
        return index * self.sample if index >= 0 else -1.0

    def cached_reach(self) -> float:
        """How far (years) the pieces on disk go from J2000 along one chain, by their names only."""
        if self.folder is None:
            return max(self.reach, 0.0)
        end = self.t.size - 1
        pieces = self._pieces()
        while True:
            further = [p[1] for p in pieces if p[0] <= end + 1 <= p[1]]
            if not further or max(further) <= end:
                return self.reach_of(end)
            end = max(further)

    # -- integrating --------------------------------------------------------------------------

    @property
    def reach(self) -> float:
        """How far from J2000 (years, ≥ 0) the samples go."""
        return float(abs(self.t[-1])) if self.t.size else -1.0

    def years_to(self, reach: float) -> float:
        """Years this direction must integrate to cover ``reach`` years from J2000 (cache by its names)."""
        cached = max(self.reach, self.cached_reach())
        if cached >= reach:
            return 0.0
        return float(np.ceil(reach / CHUNK_YEARS) * CHUNK_YEARS) - max(cached, 0.0)

    def extend(self, reach: float, progress: bool | None) -> None:
        """Read the cache, then integrate, until the samples cover ``reach`` years from J2000."""
        self._load(reach)
        if self.reach >= reach:
            return
        from tqdm import tqdm

        # Whole chunks, counted as integers: the samples' times are those reached, a hair off.
        first_chunk = round(max(self.reach, 0.0) / CHUNK_YEARS) if self.t.size else 0
        last_chunk = int(np.ceil(reach / CHUNK_YEARS))
        per_piece = round(PIECE_YEARS / CHUNK_YEARS)
        per_chunk = round(CHUNK_YEARS / self.sample)
        new: list[tuple] = []  # chunks (t, normal, ecc, state) not yet in self
        unsaved = 0  # of which the last ones not yet written in a piece
        years = (last_chunk - first_chunk) * CHUNK_YEARS
        show = (sys.stderr.isatty() if progress is None else progress) and years > 20000.0
        bar = tqdm(total=years / CHUNK_YEARS, disable=not show, unit="kyr", desc="nbody", file=sys.stderr)
        try:
            state, t_state = (self.last_state, float(self.t[-1])) if self.t.size else (None, 0.0)
            for c in range(first_chunk, last_chunk):
                first = c * per_chunk + 1
                times = self.sign * self.sample * np.arange(first, first + per_chunk)
                if state is None:  # the very first chunk also holds J2000 itself
                    times = np.concatenate([[0.0], times])
                chunk = self._chunk(times, state, t_state)
                new.append(chunk)
                unsaved += 1
                state, t_state = chunk[3], float(chunk[0][-1])
                bar.update(1)
                if (c + 1) % per_piece == 0 or c + 1 == last_chunk:
                    self._save(new[len(new) - unsaved :])
                    unsaved = 0
        except KeyboardInterrupt:
            if unsaved:
                self._save(new[len(new) - unsaved :])
            self._append(new)
            if self.folder is None or self.folder in _UNWRITABLE:
                raise
            kept = f"kept {_years(max(self.reach, 0.0))} of the N-body orbit, {self.direction} from J2000,"
            raise Interrupted(f"{kept} in {self.folder}") from None
        finally:
            bar.close()
        self._append(new)

    def _chunk(self, times: Array, state: Array | None, t_state: float) -> tuple[Array, Array, Array, Array]:
        """Integrate one chunk from ``state`` at ``t_state`` (``None``: J2000); its samples and end state."""
        if state is None and self.initial is not None:
            state = self.initial
        sim, extras = make_simulation(self.sign * self.step, self.gr, state, t_state)
        states = np.empty((times.size, 9, 6))
        reached = np.empty(times.size)
        buf = np.empty((9, 6))
        for k, t in enumerate(times):
            if t != 0.0:
                # Aim half a step short: the run stops on the step that lands on t (a whole number of
                # steps per sample), never one step later because the summed steps fell short by round-off.
                sim.integrate(float(t) - 0.5 * sim.dt, exact_finish_time=0)
            sim.serialize_particle_data(xyzvxvyvz=buf)
            states[k], reached[k] = buf, sim.t
        del extras
        normal, ecc = _vectors(states)
        return reached, normal, ecc, states[-1].copy()

    def _append(self, chunks: list[tuple]) -> None:
        if not chunks:
            return
        j = self.index
        self.t = np.concatenate([self.t, *(c[0] for c in chunks)])
        self.normal = np.concatenate([self.normal, *(c[1][:, j] for c in chunks)])
        self.ecc = np.concatenate([self.ecc, *(c[2][:, j] for c in chunks)])
        self.last_state = chunks[-1][3]

    def _save(self, chunks: list[tuple]) -> None:
        """Write the samples of ``chunks`` (consecutive, every planet) as one piece."""
        if self.folder is None or not chunks or str(self.folder) in _UNWRITABLE:
            return
        t = np.concatenate([c[0] for c in chunks])
        first = round(abs(float(t[0])) / self.sample)
        name = f"nbody-{self.key}-{self.direction}-{first}-{first + t.size - 1}.npz"
        stream = io.BytesIO()
        np.savez(
            stream,
            t=t,
            normal=np.concatenate([c[1] for c in chunks]),
            ecc=np.concatenate([c[2] for c in chunks]),
            last_state=chunks[-1][3],
        )
        try:
            self.folder.mkdir(parents=True, exist_ok=True)
            atomic_write_bytes(self.folder / name, stream.getvalue())
        except OSError as exc:  # a read-only cache costs a recomputation next time, not a failure now
            _UNWRITABLE.add(str(self.folder))
            reason = exc.strerror or type(exc).__name__
            msg = f"could not write the N-body cache in {self.folder} ({reason}): recomputed next time"
            warnings.warn(msg, RuntimeWarning, stacklevel=2)


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
    initial_state : array_like, shape (9, 6), optional
        Barycentric positions (au) and velocities (au/yr) of the Sun and the planets at J2000,
        in place of the shipped ones (an ensemble's perturbed member,
        :mod:`andoyer.ensemble.nbody`); part of the cache's key.

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
        initial_state: ArrayLike | None = None,
    ) -> None:
        self.body = PLANETS[check_planet(body)]
        self._index = PLANETS.index(self.body)
        self.initial_state = None
        if initial_state is not None:
            self.initial_state = np.array(initial_state, dtype=float)
            if self.initial_state.shape != (9, 6) or not np.isfinite(self.initial_state).all():
                msg = f"expected a finite initial_state of shape (9, 6), got shape {self.initial_state.shape}"
                raise ValueError(msg)
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
        steps_per_sample = max(1, round(sample_years * (JULIAN_YEAR / DAY) / step_days))
        self.step_years = self.sample_years / steps_per_sample
        self.span = (-float(max_span), float(max_span))
        self.progress = progress
        self.cache = cache
        self.key = self._key()
        folder = cache_directory() if cache else None
        self._segments = {
            sign: _Segment(folder, self.key, sign, self.step_years, self.sample_years, self.gr, self._index)
            for sign in (1, -1)
        }
        for segment in self._segments.values():
            segment.initial = self.initial_state
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
        if self.initial_state is not None:
            settings["initial_state"] = hashlib.sha256(self.initial_state.tobytes()).hexdigest()
        return hashlib.sha256(json.dumps(settings, sort_keys=True).encode()).hexdigest()[:24]

    def _ensure(self, times: Array) -> None:
        from scipy.interpolate import CubicSpline

        # Two samples of margin keep the spline's end conditions away from the times asked for.
        margin = 2.0 * self.sample_years
        need_forward = float(max(times.max(), 0.0)) + margin if times.size else margin
        need_backward = float(max(-times.min(), 0.0)) + margin if times.size else margin
        forward, backward = self._segments[1], self._segments[-1]
        if forward.reach < need_forward or backward.reach < need_backward:
            # Refused before anything is read or integrated: the samples held (read from the cache
            # or integrated, to whole chunks, and a piece's worth read beyond), and the time.
            years = forward.years_to(need_forward) + backward.years_to(need_backward)
            seconds = years / 1e6 * SECONDS_PER_MYR
            reach = sum(
                max(segment.reach, np.ceil(need / CHUNK_YEARS) * CHUNK_YEARS) + PIECE_YEARS
                for segment, need in ((forward, need_forward), (backward, need_backward))
            )
            nbytes = reach / self.sample_years * SAMPLE_BYTES
            check_size(f"an N-body orbit of {_years(reach)}", nbytes=nbytes, seconds=seconds)
            where = cache_directory() if self.cache else None
            announce(seconds, f"integrating {_years(years)} of the Solar System (N-body)", where)
        forward.extend(need_forward, self.progress)
        backward.extend(need_backward, self.progress)
        reach = (forward.reach, backward.reach)
        if reach != self._spline_reach:
            t = np.concatenate([backward.t[::-1], forward.t[1:]])
            normal = np.concatenate([backward.normal[::-1], forward.normal[1:]])
            ecc = np.concatenate([backward.ecc[::-1], forward.ecc[1:]])
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
