"""Issue 26 items 1 and 2 at the command line: requests under a memory limit, Ctrl-C, long outputs.

Every planetary command knows the memory of a request before the work
(:func:`andoyer._limits.check_size`; :func:`~andoyer._limits.memory_limit` honours ``ulimit -v``).
The test of that: in a process of its own, with the address space limited
(``RLIMIT_AS``) to what the process maps plus the command's own estimate of a request, the
request runs to the end (the estimate bounds what it allocates), and a larger one is refused
in one line naming what it would need. The commands whose work is bounded by a constant
(Cassini states, the portraits' levels) run their largest request under 2.5 GB.
"""

from __future__ import annotations

import io
import json
import os
import signal
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import andoyer
from andoyer._limits import memory_limit
from andoyer.cli.output import format_rows, write_json, write_rows

SRC = str(Path(andoyer.__file__).resolve().parents[1])

#: The child: a warm-up request (imports, compiled kernels, fonts), the estimate of ``big`` read
#: from its refusal under a zero limit, then ``big`` and ``bigger`` under RLIMIT_AS = what the
#: process maps + that estimate + 64 MiB of slack.
BOUNDARY = """
import contextlib, io, json, re, resource, sys
import andoyer._limits as limits
from andoyer.cli import main

def run(argv):
    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        code = main(argv)
    return code, err.getvalue()

def mapped():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[0]) * resource.getpagesize()

units = {"B": 1, "KiB": 2**10, "MiB": 2**20, "GiB": 2**30}
warm, big, bigger = json.loads(sys.argv[1])
assert run(warm)[0] == 0
real = limits.memory_limit
limits.memory_limit = lambda: 0
code, err = run(big)
limits.memory_limit = real
need = re.search(r"would need ([0-9.]+) (B|KiB|MiB|GiB)", err)
need = float(need[1]) * units[need[2]]
limit = int(mapped() + need * 1.01 + 64 * 2**20)
resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
print(json.dumps({"need": need, "limit": limit, "big": run(big), "bigger": run(bigger)}))
"""


def _boundary(tmp_path: Path, warm: str, big: str, bigger: str) -> dict:
    env = {**os.environ, "PYTHONPATH": SRC, "ANDOYER_CACHE_DIR": str(tmp_path / "cache")}
    argvs = json.dumps([line.split() for line in (warm, big, bigger)])
    done = subprocess.run(
        [sys.executable, "-c", BOUNDARY, argvs], env=env, cwd=tmp_path, capture_output=True, text=True,
        timeout=1800, check=False,
    )
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout.splitlines()[-1])


CASES = {
    # the aligned table: the history held (two passes of formatting), 50 000 rows; then a million
    "obliquity-table": (
        "obliquity earth --span -1000 0 --step 100 --format table --output w.txt",
        "obliquity earth --span -1000 0 --step 0.02 --format table --output big.txt",
        "obliquity earth --span -20000 0 --step 0.02 --format table --output bigger.txt",
    ),
}
SLOW_CASES = {
    "obliquity-json-plot": (
        "obliquity earth --span -1000 0 --step 100 --format json --output w.json --plot w.png",
        "obliquity earth --span -20000 0 --step 0.02 --format json --output big.json --plot big.png",
        "obliquity earth --span -190000 0 --step 0.02 --format json --output bigger.json",
    ),
    "obliquity-laplace-lagrange-csv": (  # streamed: the memory of the output times only (an unbounded orbit)
        "obliquity earth --orbit laplace-lagrange --span -1000 0 --step 100 --format csv --output w.csv",
        "obliquity earth --orbit laplace-lagrange --span -1e8 0 --step 500 --format csv --output big.csv",
        (
            "obliquity earth --orbit laplace-lagrange --span -4.9e9 0 --step 500 "
            "--format csv --output bigger.csv"
        ),
    ),
    "nutation-json-plot": (
        "nutation earth --span 0 1 --step 0.5 --format json --output w.json --plot w.png",
        "nutation earth --span 0 19 --step 0.00002 --format json --output big.json --plot big.png",
        "nutation earth --span 0 38 --step 0.00002 --format json --output bigger.json --plot bigger.png",
    ),
    "nutation-terms-table": (
        "nutation earth --span 0 19 --step 1 --terms --format table --output w.txt",
        "nutation earth --span 0 39.9 --step 0.00008 --format table --output big.txt",
        "nutation earth --span 0 39.9 --step 0.00002 --format table --output bigger.txt",
    ),
    "precession": (
        "precession earth --integrate 0.2 --step 1 --output w.txt",
        "precession earth --integrate 20 --output big.txt",
        "precession earth --integrate 2000 --output bigger.txt",
    ),
    "portrait-precession": (
        "portrait precession --moments 1 1 1.5 --steps 10 --out w.png",
        "portrait precession --moments 1 1 1.5 --steps 200000 --out big.png",
        "portrait precession --moments 1 1 1.5 --steps 1000000 --out bigger.png",
    ),
}


def _check_boundary(tmp_path, name, cases):
    warm, big, bigger = cases[name]
    result = _boundary(tmp_path, warm, big, bigger)
    code, err = result["big"]
    assert code == 0, err  # within the limit its own estimate set
    assert (tmp_path / big.split()[-1]).exists()
    code, err = result["bigger"]
    assert code == 2, err
    assert err.count("\n") == 1, err
    assert "would need" in err
    assert not (tmp_path / bigger.split()[-1]).exists()


@pytest.mark.parametrize("name", sorted(CASES))
def test_cli_memory_limit_request_fits_its_estimate(tmp_path, name):
    _check_boundary(tmp_path, name, CASES)


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(SLOW_CASES))
def test_cli_memory_limit_request_fits_its_estimate_slow(tmp_path, name):
    _check_boundary(tmp_path, name, SLOW_CASES)


LIMITED = """
import resource, sys
limit = int(sys.argv[1])
resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
from andoyer.cli import main
raise SystemExit(main(sys.argv[2:]))
"""


@pytest.mark.slow
@pytest.mark.parametrize(
    "argv",
    [
        "cassini mercury --format json --output out.json",
        "portrait cassini --body mercury --levels 1000 --out out.png",
        "portrait phase --body eros --levels 500 --out out.png",
        "portrait sphere --body eros --levels 500 --out out.png",
    ],
)
def test_cli_memory_limit_bounded_commands_fit_2_5_gib(tmp_path, argv):
    env = {**os.environ, "PYTHONPATH": SRC}
    done = subprocess.run(
        [sys.executable, "-c", LIMITED, str(int(2.5 * 2**30)), *argv.split()],
        env=env, cwd=tmp_path, capture_output=True, text=True, timeout=900, check=False,
    )
    assert done.returncode == 0, done.stderr
    assert (tmp_path / argv.split()[-1]).stat().st_size > 0


def test_memory_limit_honours_the_address_space_limit():
    # 300 MiB above what the process maps: memory_limit says about that much is left.
    script = """
import resource, sys
from andoyer._limits import memory_limit
def mapped():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[0]) * resource.getpagesize()
resource.setrlimit(resource.RLIMIT_AS, (mapped() + 300 * 2**20, resource.RLIM_INFINITY))
print(memory_limit() / 2**20)
"""
    env = {**os.environ, "PYTHONPATH": SRC}
    done = subprocess.run([sys.executable, "-c", script], env=env, capture_output=True, text=True, check=True)
    assert 290 < float(done.stdout) <= 300
    assert memory_limit() > 2**20


CHILD = """
import signal, sys
signal.signal(signal.SIGINT, signal.default_int_handler)
from andoyer.cli import main
raise SystemExit(main(sys.argv[1:]))
"""


def test_cli_precession_interrupted_one_line_exit_130(tmp_path):
    env = {**os.environ, "PYTHONPATH": SRC}
    argv = ["precession", "earth", "--integrate", "500", "--format", "json", "--output", "out.json"]
    with subprocess.Popen(
        [sys.executable, "-c", CHILD, *argv], env=env, cwd=tmp_path, stderr=subprocess.PIPE, text=True
    ) as child:
        announced = child.stderr.readline()  # said before the long work starts
        child.send_signal(signal.SIGINT)
        rest = child.stderr.read()
        assert child.wait(timeout=120) == 130
    assert announced.startswith("andoyer precession: integrating the full torque on Earth over 500 years")
    assert rest == "andoyer precession: interrupted\n"
    assert list(tmp_path.iterdir()) == []


# -- long outputs are the same text, written a block at a time ----------------------------------

numbers = st.floats(allow_nan=True, allow_infinity=True, width=64)


@settings(max_examples=60, deadline=None)
@given(
    columns=st.integers(1, 4).flatmap(
        lambda k: st.integers(0, 12).flatmap(lambda n: st.lists(st.lists(numbers, min_size=n, max_size=n),
                                                               min_size=k, max_size=k))
    ),
    rows=st.integers(1, 5),
    fmt=st.sampled_from(["csv", "table"]),
)
def test_write_rows_is_format_rows_block_by_block(columns, rows, fmt):
    header = [f"c{k}" for k in range(len(columns))]
    out = io.StringIO()
    write_rows(out, header, columns, fmt, rows=rows)
    assert out.getvalue() == format_rows(header, [list(r) for r in zip(*columns, strict=True)], fmt)


@settings(max_examples=60, deadline=None)
@given(
    values=st.lists(numbers, min_size=0, max_size=30),
    width=st.integers(1, 3),
    rows=st.integers(1, 7),
    extra=st.one_of(st.none(), st.floats(allow_nan=False), st.text(max_size=5)),
)
def test_write_json_is_json_dumps_block_by_block(values, width, rows, extra):
    vector = np.array(values, dtype=float)
    matrix = np.resize(vector, (len(values) // width, width)) if values else np.zeros((0, width))
    fields = {"t": vector, "axis": matrix, "extra": extra, "scalar": np.float64(1.5)}
    out = io.StringIO()
    write_json(out, fields, rows=rows)
    expected = {k: v.tolist() if isinstance(v, np.ndarray | np.floating) else v for k, v in fields.items()}
    assert out.getvalue() == json.dumps(expected) + "\n"
