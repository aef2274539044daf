"""``andoyer convert`` with Serret's elements (the chart needs the body)."""

from __future__ import annotations

import numpy as np
import pytest

from andoyer.cli import main


def run_cli(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def convert(capsys, source, target, values, *extra):
    code, out, err = run_cli(
        capsys,
        "convert",
        "--from",
        source,
        "--to",
        target,
        "--moments",
        "1",
        "2",
        "2.5",
        "--values",
        *(repr(float(v)) for v in values),
        "--format",
        "csv",
        *extra,
    )
    assert code == 0, err
    header, row = out.strip().splitlines()
    return header.split(","), np.array([float(x) for x in row.split(",")])


def test_cli_convert_andoyer_to_serret_on_the_reference_point(capsys):
    """A circulating state on the half-plane (b3, +b2) (l = 0, the origin for this body) is at its
    passage: t0 = 0 and g0 = g; T = ½ Σ m_i²/I_i from m = (√(G²−L²) sin l, √(G²−L²) cos l, L)."""
    l, g, h, L, G, H = 0.0, 0.7, 0.2, 0.9, 1.0, 0.4
    header, got = convert(capsys, "andoyer", "serret", [l, g, h, L, G, H])
    assert header == ["g0", "h", "t0", "G", "H", "T", "sign"]
    m = np.array([np.sqrt(G**2 - L**2) * np.sin(l), np.sqrt(G**2 - L**2) * np.cos(l), L])
    T = 0.5 * np.sum(m**2 / np.array([1.0, 2.0, 2.5]))
    assert got == pytest.approx([g, h, 0.0, G, H, T, 1.0], abs=1e-15)


def test_cli_convert_serret_round_trip_in_degrees(capsys):
    andoyer = [20.0, 100.0, 250.0, -1.1, 1.3, 0.5]  # circulation (2T/G² = 0.445 < 1/I2)
    _, serret = convert(capsys, "andoyer", "serret", andoyer, "--degrees")
    assert serret[-1] == -1.0  # sign of L: circulation
    assert serret[2] <= 0.0  # the last passage before the state's instant
    _, back = convert(capsys, "serret", "andoyer", serret, "--degrees")
    assert np.abs((back[:3] - andoyer[:3] + 180) % 360 - 180).max() <= 1e-10
    assert back[3:] == pytest.approx(andoyer[3:], abs=1e-13)


def test_cli_convert_serret_needs_a_body(capsys):
    code, _, err = run_cli(
        capsys, "convert", "--from", "andoyer", "--to", "serret", "--values", "0", "0", "0", "0.5", "1", "0"
    )
    assert code == 2
    assert "expected --body NAME or --moments" in err


def test_cli_convert_serret_bad_sign_is_one_line_error(capsys):
    code, _, err = run_cli(
        capsys,
        "convert",
        "--from",
        "serret",
        "--to",
        "andoyer",
        "--body",
        "earth",
        "--values",
        "0",
        "0",
        "0",
        "1",
        "0.5",
        "0.5",
        "0.5",
    )
    assert code == 2
    assert "expected sign = +1 or -1, got 0.5" in err
    assert len(err.strip().splitlines()) == 1


def test_cli_propagate_to_serret_elements_are_constant(capsys):
    code = main(
        [
            "propagate", "--moments", "1", "2", "3",
            "--values", "0.1", "0.2", "0.3", "0.9", "1.0", "0.5",
            "--range", "0", "40", "9", "--to", "serret", "--format", "csv",
        ]
    )  # fmt: skip
    out = capsys.readouterr().out
    assert code == 0
    rows = np.loadtxt(out.splitlines()[1:], delimiter=",")
    elements = rows[:, 2:8]  # g0, h, t0, G, H, T
    assert np.ptp(elements, axis=0).max() <= 1e-11
