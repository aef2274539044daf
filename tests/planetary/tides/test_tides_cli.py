"""``andoyer tides``: the JSON keys and values are the API's; refusals are one line, exit 2."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from andoyer.cli import main
from andoyer.planetary.tides import tidal_history


def test_tides_cli_json_matches_the_api(tmp_path):
    out = tmp_path / "tides.json"
    argv = ["tides", "earth", "--span", "-1e9", "0", "--step", "2.5e8", "--format", "json"]
    argv += ["--output", str(out)]
    code = main(argv)
    assert code == 0
    fields = json.loads(out.read_text())
    assert {"t", "day_length", "lunar_distance", "precession_constant", "obliquity"} <= set(fields)
    h = tidal_history(np.array(fields["t"]), "ocean")
    assert fields["t"] == [-1e9, -7.5e8, -5e8, -2.5e8, 0.0]
    assert np.allclose(fields["lunar_distance"], h.lunar_distance, rtol=1e-15)
    assert np.allclose(fields["day_length"], h.day_length, rtol=1e-15)
    assert np.allclose(fields["precession_constant"], h.precession_constant, rtol=1e-15)
    assert np.allclose(fields["obliquity"], np.degrees(h.obliquity), rtol=1e-15)


def test_tides_cli_options_reach_the_model(capsys):
    code = main(["tides", "earth", "--model", "constant-lag", "--span", "-1e8", "0", "--step", "1e8",
                 "--no-solar-tide", "--obliquity", "10", "--format", "csv"])
    assert code == 0
    rows = capsys.readouterr().out.strip().splitlines()
    first = dict(zip(rows[0].split(","), map(float, rows[1].split(",")), strict=True))
    h = tidal_history([-1e8, 0.0], "constant-lag", solar_tide=False, obliquity=math.radians(10.0))
    assert first["lunar_distance_km"] == pytest.approx(h.lunar_distance[0], rel=1e-15)
    assert first["obliquity_deg"] == pytest.approx(np.degrees(h.obliquity[0]), rel=1e-15)


def test_tides_cli_span_past_validity_is_one_line(capsys):
    code = main(["tides", "earth", "--model", "constant-lag", "--span", "-2e9", "0", "--step", "1e9"])
    err = capsys.readouterr().err
    assert code == 2
    assert err.count("\n") == 1
    assert "Laplace-plane transition" in err


def test_tides_cli_plot(tmp_path):
    png = tmp_path / "t.png"
    assert main(["tides", "earth", "--span", "-1e9", "0", "--step", "5e8", "--plot", str(png)]) == 0
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
