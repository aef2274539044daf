"""``andoyer precession``: text and JSON output, the full integration, one-line errors with exit code 2."""

from __future__ import annotations

import functools
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

BANDS = {"earth": (50.0, 50.8), "mars": (7.4, 7.8)}


@pytest.fixture
def cli(run_cli):
    """``andoyer precession ARGV`` in process: (exit code, stdout, stderr)."""
    return functools.partial(run_cli, "precession")


@pytest.mark.parametrize("body", list(BANDS))
def test_cli_precession_json_secular_only(cli, body):
    code, out, _ = cli(body, "--format", "json")
    assert code == 0
    fields = json.loads(out)
    assert fields["body"] == body
    assert fields["perturbers"] == (["Sun", "Moon"] if body == "earth" else ["Sun"])
    assert fields["obliquity_deg"] == pytest.approx(23.4392794 if body == "earth" else 25.19, abs=1e-6)
    low, high = BANDS[body]
    assert low <= fields["secular_arcsec_per_year"] <= high
    assert fields["integrated_arcsec_per_year"] is None


def test_cli_precession_text_names_the_rates(cli):
    code, out, _ = cli("EARTH")
    assert code == 0
    assert "perturbers: Sun, Moon" in out
    assert "obliquity: 23.4393 deg" in out
    assert "secular model: 50.4" in out
    assert "full integration" not in out


def test_cli_precession_integrate_mars_to_file(cli, tmp_path):
    target = tmp_path / "mars.json"
    code, out, _ = cli("mars", "--integrate", "1.9", "--format", "json", "--output", str(target))
    assert code == 0
    assert out == ""
    fields = json.loads(target.read_text())
    assert 7.4 <= fields["integrated_arcsec_per_year"] <= 7.8
    assert abs(fields["integrated_arcsec_per_year"] - fields["secular_arcsec_per_year"]) <= 0.01
    assert fields["integration_years"] >= 1.9
    # The default step: an odd number of quarter rotations of Mars (88642.66 s), under 1/12 of its year.
    quarters = fields["step_days"] * 86400 / (88642.6632 / 4)
    assert quarters == pytest.approx(round(quarters), abs=1e-6)
    assert round(quarters) % 2 == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["mars.json"]


def test_cli_precession_integrate_text_with_step(cli):
    code, out, _ = cli("mars", "--integrate", "1.9", "--step", "40.7817808125")  # 159 quarter rotations
    assert code == 0
    line = next(x for x in out.splitlines() if x.startswith("full integration"))
    assert "step 40.7818 d" in line
    assert 7.4 <= float(line.split(": ")[1].split()[0]) <= 7.8


BAD_ARGS = {
    "unknown body": (["venus"], "invalid choice: 'venus'"),
    "negative years": (["mars", "--integrate", "-1"], "expected a positive number, got '-1'"),
    "not a number": (["mars", "--integrate", "ten"], "expected a positive number, got 'ten'"),
    "step without integrate": (["mars", "--step", "5"], "expected --step only with --integrate YEARS"),
    "bad order": (["mars", "--order", "3"], "invalid choice: 3"),
    "bad format": (["mars", "--format", "xml"], "invalid choice: 'xml'"),
    "missing directory": (
        ["mars", "--output", "/nonexistent/dir/out.json"],
        "expected an existing directory",
    ),
}


@pytest.mark.parametrize("name", list(BAD_ARGS))
def test_cli_precession_bad_arguments_exit_2(cli, name):
    argv, message = BAD_ARGS[name]
    code, out, err = cli(*argv)
    assert code == 2
    assert out == ""
    assert len(err.strip().splitlines()) == 1
    assert message in err


def test_cli_precession_bad_arguments_no_traceback_in_a_process():
    proc = subprocess.run(
        [sys.executable, "-m", "andoyer", "precession", "mars", "--integrate", "nan"],
        capture_output=True,
        text=True,
        check=False,
        env={**os.environ, "PYTHONPATH": str(Path(__file__).resolve().parents[2] / "src")},
    )
    assert proc.returncode == 2
    assert "Traceback" not in proc.stderr
    assert proc.stderr.strip().splitlines() == [
        "andoyer precession: error: argument --integrate: expected a positive number, got 'nan'"
    ]
