"""``--moments`` that break the triangle inequality: accepted with a one-line warning on stderr."""

from __future__ import annotations

import numpy as np
import pytest

from andoyer.cli import main

DISK = ["--moments", "3", "3", "9"]  # A + B = 6 < C = 9
STATE = ["--from", "state", "--values", "0", "0", "0", "1", "0.5", "-0.2", "0.7"]


def test_cli_nonphysical_moments_propagate_with_one_warning_line(capsys):
    code = main(["propagate", *DISK, *STATE, "--times", "2.5", "--format", "csv"])
    out, err = capsys.readouterr()
    assert code == 0, err
    assert err.count("\n") == 1
    assert err.startswith("andoyer propagate: warning: moments with A + B = 6.0 < C = 9.0")
    # Euler's equations with A = B: d(m₁ + i m₂)/dt = iΩ (m₁ + i m₂), Ω = (1/A − 1/C) m₃ constant.
    header, row = out.strip().splitlines()
    m = dict(zip(header.split(","), map(float, row.split(",")), strict=True))
    expected = (0.5 - 0.2j) * np.exp(1j * (1 / 3 - 1 / 9) * 0.7 * 2.5)
    assert m["m1"] == pytest.approx(expected.real, abs=1e-14)
    assert m["m2"] == pytest.approx(expected.imag, abs=1e-14)
    assert m["m3"] == pytest.approx(0.7, abs=1e-15)


def test_cli_nonphysical_moments_convert_with_one_warning_line(capsys):
    # Under pytest's filterwarnings = error an uncaught warning would fail the command: the CLI
    # catches it and prints it as one line, not Python's two-line "file:line: Warning" display.
    code = main(["convert", *DISK, *STATE, "--to", "sadov", "--format", "csv"])
    out, err = capsys.readouterr()
    assert code == 0, err
    (line,) = err.splitlines()
    assert line.startswith("andoyer convert: warning: ")
    assert "triangle inequality" in line
    assert len(out.strip().splitlines()) == 2


def test_cli_physical_moments_print_no_warning(capsys):
    assert main(["propagate", "--moments", "1", "2", "3", *STATE, "--times", "1", "--format", "csv"]) == 0
    assert capsys.readouterr().err == ""
