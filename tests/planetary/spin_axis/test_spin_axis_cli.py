"""``andoyer obliquity``: JSON keys and values, tables, the plot, and bad input (exit 2, nothing written)."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import erfa
import numpy as np
import pytest

from andoyer.cli import main


def _run(*argv):
    env = {**os.environ, "MPLBACKEND": "Agg"}
    return subprocess.run([sys.executable, "-m", "andoyer", *argv], capture_output=True, text=True, env=env,
                          timeout=120, check=False)


def test_obliquity_json_keys_and_iau_values(capsys):
    assert main(["obliquity", "earth", "--span", "-1000", "1000", "--step", "500", "--format", "json",
                 "--precession-rate", "50.3848"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert set(out) == {"t", "obliquity", "precession", "axis", "orbit_normal", "eccentricity",
                        "climatic_precession", "precession_rate", "resonances", "error_estimate",
                        "integration_step"}
    assert out["t"] == [-1000.0, -500.0, 0.0, 500.0, 1000.0]
    assert 0.0 <= out["error_estimate"] <= 0.01  # arcsec: the default tolerance
    assert out["integration_step"] <= 500.0
    assert np.shape(out["axis"]) == (5, 3)
    assert np.shape(out["orbit_normal"]) == (5, 3)
    assert out["eccentricity"] is None
    assert out["climatic_precession"] is None
    assert out["precession_rate"] == pytest.approx(50.3848, abs=1e-12)
    # IAU 2006 (ERFA) obliquity and p_A a millennium away, within 1″ and 2″
    eps = np.degrees([erfa.obl06(2451545.0, t * 365.25) for t in out["t"]])
    pa = np.degrees([erfa.p06e(2451545.0, t * 365.25)[12] for t in out["t"]])
    assert np.abs(np.array(out["obliquity"]) - eps).max() * 3600 <= 1.0
    assert np.abs(np.array(out["precession"]) - pa).max() * 3600 <= 2.0
    # the orbit normal is the Vondrák ecliptic pole (erfa.ltpecl) in the J2000 ecliptic frame
    pole = erfa.ltpecl(2000.0 + np.array(out["t"]))
    e0 = np.radians(84381.406 / 3600)
    pole_ecl = np.stack([pole[:, 0], np.cos(e0) * pole[:, 1] + np.sin(e0) * pole[:, 2],
                         -np.sin(e0) * pole[:, 1] + np.cos(e0) * pole[:, 2]], -1)
    assert np.abs(np.array(out["orbit_normal"]) - pole_ecl).max() <= 1e-12


@pytest.mark.parametrize("fmt", ["csv", "table"])
def test_obliquity_tables_have_one_row_per_time(fmt, capsys):
    assert main(["obliquity", "earth", "--span", "-300", "0", "--step", "100", "--format", fmt]) == 0
    lines = capsys.readouterr().out.strip().splitlines()
    assert lines[0].split(",")[0].strip() == "t_yr" if fmt == "csv" else lines[0].split()[0] == "t_yr"
    assert len(lines) == 5 + (fmt == "table")


def test_obliquity_writes_output_and_plot(tmp_path):
    out, png = tmp_path / "e.json", tmp_path / "e.png"
    assert main(["obliquity", "earth", "--span", "-20000", "0", "--step", "1000", "--format", "json",
                 "--output", str(out), "--plot", str(png)]) == 0
    assert len(json.loads(out.read_text())["t"]) == 21
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["mercury"], "invalid choice: 'mercury'"),
        (["earth", "--step", "0"], "expected --step DT > 0 years, got 0.0"),
        (["earth", "--step", "-5"], "expected --step DT > 0 years"),
        (["earth", "--span", "10", "-10"], "expected --span T0 T1 with T1 >= T0"),
        (["earth", "--span", "0", "300000"], "expected --span T0 T1 within the vondrak orbit's span"),
        (["earth", "--precession-rate", "-1"], "expected a precession rate P > 0 arcsec/yr"),
        (["earth", "--precession-rate", "50", "--dynamical-ellipticity", "0.003"], "not allowed with"),
        (["mars", "--orbit", "vondrak"], "vondrak"),
    ],
)
def test_obliquity_bad_input_exits_2_one_line_nothing_written(argv, message, tmp_path, capsys):
    out, png = tmp_path / "o.json", tmp_path / "o.png"
    try:
        code = main(["obliquity", *argv, "--output", str(out), "--plot", str(png)])
    except SystemExit as exc:  # argparse's own errors
        code = exc.code
    assert code == 2
    lines = capsys.readouterr().err.strip().splitlines()
    assert len(lines) == 1
    assert message in lines[0]
    assert list(tmp_path.iterdir()) == []


def test_obliquity_bad_input_in_a_process_has_no_traceback(tmp_path):
    result = _run("obliquity", "earth", "--span", "0", "300000", "--output", str(tmp_path / "x.csv"))
    assert result.returncode == 2
    assert result.stderr.count("\n") == 1
    assert "Traceback" not in result.stderr
    assert list(tmp_path.iterdir()) == []


def test_spin_axis_figure_script_writes_png(tmp_path, capsys):
    import importlib.util
    from pathlib import Path

    path = Path(__file__).resolve().parents[3] / "scripts" / "spin_axis_figure.py"
    spec = importlib.util.spec_from_file_location("spin_axis_figure_script", path)
    script = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(script)
    script.main(["--orbit", "vondrak", "--span", "-3000", "0", "--step", "500", "--out", str(tmp_path)])
    assert (tmp_path / "spin-axis.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    out = capsys.readouterr().out
    assert "wrote" in out
