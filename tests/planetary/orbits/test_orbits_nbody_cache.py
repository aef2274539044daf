"""Issue 26 items 2 and 3: the N-body cache in pieces, Ctrl-C, damaged files, concurrent runs.

An interrupted run keeps what it integrated and the next run goes on from there, giving the
same numbers to the last bit as a run that was never interrupted; a damaged piece is found on
loading, removed with one warning and recomputed; two concurrent runs never shrink the cache;
a cache folder that cannot be written costs one warning line.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import andoyer.planetary.orbits.nbody as nbody_module
from andoyer.planetary.orbits import NBodyOrbit

SRC = str(Path(nbody_module.__file__).resolve().parents[3])

#: The command line in a child process, answering SIGINT as Python does by default (a shell's
#: background job starts with SIGINT ignored, and a child inherits that), with small pieces.
CHILD = """
import signal, sys
signal.signal(signal.SIGINT, signal.default_int_handler)
import andoyer.planetary.orbits.nbody as nb
nb.PIECE_YEARS = float(sys.argv[1])
from andoyer.cli import main
raise SystemExit(main(sys.argv[2:]))
"""


def _child(cache: Path, piece_years: float, *argv: str) -> subprocess.Popen:
    env = {**os.environ, "ANDOYER_CACHE_DIR": str(cache), "PYTHONPATH": SRC}
    return subprocess.Popen(
        [sys.executable, "-c", CHILD, str(piece_years), *argv],
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )


def _pieces(cache: Path, direction: str = "backward") -> dict[str, int]:
    """Piece files of one direction, by name, with their modification times (ns)."""
    return {p.name: p.stat().st_mtime_ns for p in cache.glob(f"nbody-*-{direction}-*.npz")}


OBLIQUITY = ("obliquity", "mars", "--span", "-20000", "0", "--step", "500", "--format", "csv")
#: Long enough (about 8 CPU s of orbit) that the run cannot end while the polling parent waits
#: for its turn on a machine whose every core runs tests (20 kyr ended first once, under xdist).
LONG_OBLIQUITY = ("obliquity", "mars", "--span", "-100000", "0", "--step", "500", "--format", "csv")


@pytest.mark.slow
def test_nbody_cache_interrupted_run_resumes_bit_for_bit(tmp_path):
    cache, output = tmp_path / "cache", tmp_path / "mars.csv"
    child = _child(cache, 2000.0, *LONG_OBLIQUITY, "--output", str(output))
    deadline = time.monotonic() + 300
    # A piece beyond the first thousand years: the run is inside its integration.
    while all(name.rsplit("-", 2)[1] == "0" for name in _pieces(cache)):
        assert child.poll() is None, child.communicate()
        assert time.monotonic() < deadline
        time.sleep(0.05)
    child.send_signal(signal.SIGINT)
    _, err = child.communicate(timeout=120)
    assert child.returncode == 130, err
    assert err.count("\n") == 1, err
    assert err.startswith("andoyer obliquity: interrupted; kept ")
    assert f"kyr of the N-body orbit, backward from J2000, in {cache}" in err
    assert not output.exists()
    assert [p.name for p in tmp_path.iterdir() if p.name != "cache"] == []
    kept = _pieces(cache)
    kept_years = float(err.split("kept ")[1].split(" kyr")[0]) * 1000
    assert max(int(name.rsplit("-", 1)[1][:-4]) for name in kept) * 100.0 == pytest.approx(kept_years, abs=1)

    again = _child(cache, 2000.0, *LONG_OBLIQUITY, "--output", str(output))
    _, err = again.communicate(timeout=300)
    assert again.returncode == 0, err
    after = _pieces(cache)
    assert {name: after[name] for name in kept} == kept  # resumed from them, left untouched
    assert len(after) > len(kept)

    whole, reference = tmp_path / "whole", tmp_path / "reference.csv"
    single = _child(whole, nbody_module.PIECE_YEARS, *LONG_OBLIQUITY, "--output", str(reference))
    _, err = single.communicate(timeout=300)
    assert single.returncode == 0, err
    assert output.read_bytes() == reference.read_bytes()


def _write_piece(path: Path, **changes) -> None:
    with np.load(path) as f:
        fields = {name: f[name].copy() for name in f.files}
    for name, change in changes.items():
        fields[name] = change(fields[name])
    np.savez(path, **fields)


def _nan_at(index):
    def change(a):
        a[index] = np.nan
        return a

    return change


DAMAGE = {
    "zero-normals": ({"normal": np.zeros_like}, "normals not finite|normals not of unit length"),
    "nan-last-state": ({"last_state": _nan_at((3, 1))}, "last state not finite"),
    "eccentricity-one": ({"ecc": lambda e: e * 1e6}, "an eccentricity of 1 or more"),
    "times-reversed": ({"t": lambda t: t[::-1].copy()}, "times not those of its samples"),
    "other-state": ({"last_state": lambda s: s * (1 + 1e-9)}, "a last state that does not give its last"),
    "short": ({"t": lambda t: t[:-1]}, "shapes"),
}


@pytest.mark.slow
@pytest.mark.parametrize("kind", sorted(DAMAGE))
def test_nbody_cache_damaged_piece_removed_and_recomputed(tmp_path, monkeypatch, kind):
    monkeypatch.setenv("ANDOYER_CACHE_DIR", str(tmp_path))
    t = np.linspace(-2500.0, 500.0, 31)
    good = NBodyOrbit("mars", gr=False, progress=False).normal(t)
    piece = sorted(_pieces(tmp_path))[-1]
    changes, message = DAMAGE[kind]
    _write_piece(tmp_path / piece, **changes)
    with pytest.warns(RuntimeWarning, match=f"the N-body cache file .*{piece} was damaged \\(({message})"):
        again = NBodyOrbit("mars", gr=False, progress=False).normal(t)
    np.testing.assert_array_equal(again, good)
    with np.load(tmp_path / piece) as f:  # recomputed and written again
        assert np.all(np.isfinite(f["normal"]))


def test_nbody_cache_damaged_normals_one_warning_line_at_the_cli(tmp_path, monkeypatch, run_cli):
    # The issue: a cache whose normals are all zero failed every later run ("got nan").
    monkeypatch.setenv("ANDOYER_CACHE_DIR", str(tmp_path))
    argv = ("obliquity", "mars", "--span", "-2000", "0", "--step", "1000", "--format", "csv")
    code, first, _ = run_cli(*argv)
    assert code == 0
    for name in _pieces(tmp_path) | _pieces(tmp_path, "forward"):
        _write_piece(tmp_path / name, normal=np.zeros_like)
    damaged = _pieces(tmp_path) | _pieces(tmp_path, "forward")
    code, out, err = run_cli(*argv)
    assert code == 0, err
    assert out == first
    # One line per damaged file: each is found when the run reaches it, removed and integrated again.
    lines = err.splitlines()
    assert len(lines) == len(damaged) == 3, err
    assert all(line.startswith("andoyer obliquity: warning: the N-body cache file ") for line in lines)
    assert all(line.endswith("was damaged (normals not of unit length): removed, its span is recomputed")
               for line in lines)
    for name in _pieces(tmp_path) | _pieces(tmp_path, "forward"):
        with np.load(tmp_path / name) as f:
            np.testing.assert_allclose(np.linalg.norm(f["normal"], axis=-1), 1.0, rtol=1e-12)


def test_nbody_cache_stale_part_files_removed(tmp_path, monkeypatch):
    monkeypatch.setenv("ANDOYER_CACHE_DIR", str(tmp_path))
    stale = tmp_path / ".nbody-abc-backward-0-10.npz.x1y2.part"
    fresh = tmp_path / ".nbody-abc-backward-0-10.npz.z3w4.part"
    other = tmp_path / ".notes.part"
    for path in (stale, fresh, other):
        path.write_bytes(b"half a piece")
    old = time.time() - nbody_module.STALE_PART_SECONDS - 60
    os.utime(stale, (old, old))
    os.utime(other, (old, old))
    NBodyOrbit("earth", gr=False, progress=False)
    assert not stale.exists()
    assert fresh.exists()  # it may be a live write of another run
    assert other.exists()  # not ours


RUN = """
import sys, numpy as np
from andoyer.planetary.orbits import NBodyOrbit
NBodyOrbit("earth", gr=False, progress=False).normal(-float(sys.argv[1]))
"""


@pytest.mark.slow
def test_nbody_cache_concurrent_runs_never_shrink(tmp_path, monkeypatch):
    env = {**os.environ, "ANDOYER_CACHE_DIR": str(tmp_path), "PYTHONPATH": SRC}
    long = subprocess.Popen([sys.executable, "-c", RUN, "8000"], env=env)
    time.sleep(2.0)  # the short run starts later and ends about when the long one does
    short = subprocess.Popen([sys.executable, "-c", RUN, "2500"], env=env)
    assert long.wait(timeout=300) == 0
    assert short.wait(timeout=300) == 0

    def no_integration(*args, **kwargs):
        raise AssertionError("integrated although the cache holds the span")

    monkeypatch.setenv("ANDOYER_CACHE_DIR", str(tmp_path))
    monkeypatch.setattr(nbody_module, "make_simulation", no_integration)
    orbit = NBodyOrbit("earth", gr=False, progress=False)
    orbit.normal(-8000.0)  # read from the pieces of both runs, nothing integrated
    assert orbit._segments[-1].reach >= 8000.0


def test_nbody_cache_read_only_folder_warns_once(tmp_path, monkeypatch, run_cli):
    (tmp_path / "a-file").write_text("not a folder\n")
    folder = tmp_path / "a-file" / "cache"
    monkeypatch.setenv("ANDOYER_CACHE_DIR", str(folder))
    code, out, err = run_cli("obliquity", "mars", "--span", "-3000", "0", "--step", "1000", "--format", "csv")
    assert code == 0, err
    assert out.count("\n") == 5
    assert err.count("\n") == 1, err
    assert err.startswith(f"andoyer obliquity: warning: could not write the N-body cache in {folder} (")


def test_nbody_long_run_announced_once_without_a_terminal(tmp_path, monkeypatch, run_cli):
    # Estimated past ten seconds: one line, although standard error is not a terminal here.
    monkeypatch.setenv("ANDOYER_CACHE_DIR", str(tmp_path))
    # The orbit at J2000 first (the model's obliquity there): a thousand years each way, 6 s, quiet;
    # then the span asked for (and two samples of margin): 5 kyr more, 15 s, announced.
    monkeypatch.setattr(nbody_module, "SECONDS_PER_MYR", 3e3)
    code, _, err = run_cli("obliquity", "mars", "--span", "-5000", "0", "--step", "1000", "--format", "csv")
    assert code == 0, err
    expected = "integrating 5 kyr of the Solar System (N-body), about 15 s"
    assert err == f"andoyer obliquity: {expected} (kept in {tmp_path})\n"


def _fabricate_backward_cache(folder: Path, body: str, years: float) -> None:
    """Pieces of a made-up orbit back to ``years``: the J2000 state turned about x a little more each
    sample (unit normals, the shipped eccentricities, a last state that gives the last sample)."""
    orbit = NBodyOrbit(body, progress=False, cache=False)
    sim, _ = nbody_module.make_simulation(orbit.step_years, gr=False)
    state = np.empty((9, 6))
    sim.serialize_particle_data(xyzvxvyvz=state)
    per_piece = round(nbody_module.PIECE_YEARS / orbit.sample_years)
    count = round(years / orbit.sample_years) + 1
    folder.mkdir(parents=True, exist_ok=True)
    for first in range(0, count, per_piece):
        index = np.arange(first, min(first + per_piece, count))
        angle = 1e-6 * index
        c, s = np.cos(angle), np.sin(angle)
        turn = np.zeros((index.size, 3, 3))
        turn[:, 0, 0], turn[:, 1, 1], turn[:, 2, 2], turn[:, 1, 2], turn[:, 2, 1] = 1, c, c, -s, s
        states = np.concatenate([state[None, :, :3] @ np.swapaxes(turn, 1, 2),
                                 state[None, :, 3:] @ np.swapaxes(turn, 1, 2)], axis=-1)
        normal, ecc = nbody_module._vectors(states)
        name = f"nbody-{orbit.key}-backward-{index[0]}-{index[-1]}.npz"
        np.savez(folder / name, t=-orbit.sample_years * index.astype(float), normal=normal, ecc=ecc,
                 last_state=states[-1])


LIMITED = """
import resource, sys
limit = int(sys.argv[1])
resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
from andoyer.cli import main
raise SystemExit(main(sys.argv[2:]))
"""


@pytest.mark.slow
def test_nbody_largest_span_fits_2_5_gib(tmp_path):
    # The largest request of the N-body source: Mars over the whole 50 Myr it may reach, read from
    # a cache of 500 000 samples (made up here, so that the test does not integrate for an hour).
    cache = tmp_path / "cache"
    _fabricate_backward_cache(cache, "mars", 5e7)
    env = {**os.environ, "ANDOYER_CACHE_DIR": str(cache), "PYTHONPATH": SRC}
    argv = "obliquity mars --orbit nbody --span -50000000 0 --step 10000 --format csv --output out.csv"
    done = subprocess.run(
        [sys.executable, "-c", LIMITED, str(int(2.5 * 2**30)), *argv.split()],
        env=env, cwd=tmp_path, capture_output=True, text=True, timeout=1800, check=False,
    )
    assert done.returncode == 0, done.stderr
    assert done.stderr == ""  # read, not integrated: nothing to announce, nothing damaged
    assert (tmp_path / "out.csv").read_text().count("\n") == 5002
