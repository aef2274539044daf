"""Issue 26 items 5 and 6: each refusal says what is wrong, and every option says what it is.

Each case reproduced a message that misled (an eccentricity for a span, a midpoint for the span
typed, a codec error without the file, "No such file or directory" for a special file system,
"cannot write empty image") or a silent overwrite; the help test walks every sub-command.
"""

from __future__ import annotations

import argparse
import os
from pathlib import Path

import pytest

from andoyer.cli import build_parser, main
from andoyer.planetary.orbits import read_orbit_csv

ROOT = Path(__file__).resolve().parents[2]
OBLIQUITY = ["obliquity", "earth", "--span", "-1000", "1000", "--step", "500"]
ELEMENTS = "t_years,e,inclination_deg,node_deg,varpi_deg\n"
ROWS = "-2000,0.017,0.02,170,101\n-1000,0.017,0.01,172,102\n0,0.0167,0,174,103\n1000,0.0166,0.01,176,104\n"


def run(argv, capsys) -> tuple[int, str]:
    try:
        code = main(list(argv))
    except SystemExit as exc:
        code = exc.code
    err = capsys.readouterr().err
    if code == 2:
        assert len(err.splitlines()) == 1, err
    return code, err


@pytest.mark.parametrize(
    ("span", "said"),
    [
        (("0", "100000"), "got 0 to 100000"),  # was: expected 0 <= eccentricity < 1, got 0.0043
        (("0", "250000"), "got 0 to 250000"),  # was: ... got 125000 (the window's middle)
        (("-150000", "-149000"), "got -150000 to -149000"),
    ],
)
def test_nutation_names_the_span_typed_and_its_validity(span, said, capsys):
    code, err = run(["nutation", "earth", "--span", *span, "--step", "1000"], capsys)
    assert code == 2
    assert "expected --span T0 T1 within the lunar theory's span of validity -100000 to 39747 years" in err
    assert said in err
    assert "eccentricity <" not in err


def test_nutation_span_ends_where_the_suns_eccentricity_polynomial_turns_negative():
    """Meeus eq. 25.4: e = 0.016708634 − 0.000042037 T vanishes at T = 397.47 centuries."""
    from andoyer.perturbations.lunar_theory import LUNAR_THEORY_SPAN, sun_ecliptic

    assert LUNAR_THEORY_SPAN[1] == pytest.approx(0.016708634 / 0.000042037 * 100, abs=1e-6)
    sun_ecliptic(LUNAR_THEORY_SPAN[1])  # the last year of validity still works
    with pytest.raises(ValueError, match="lunar theory's span of validity"):
        sun_ecliptic(LUNAR_THEORY_SPAN[1] + 1.0)


def test_obliquity_span_outside_vondrak_points_to_the_other_sources(capsys):
    code, err = run(["obliquity", "earth", "--span", "-1000000", "0"], capsys)
    assert code == 2
    assert "within the vondrak orbit's span -200000 to 200000 years" in err
    assert "--orbit nbody or --orbit secular or --orbit laplace-lagrange reach it" in err
    argv = ["obliquity", "earth", "--orbit", "secular", "--span", "-1e6", "0", "--step", "1e5"]
    code, err = run(argv, capsys)
    assert code == 2  # 1e5 years aliases the precession, but the span is the secular theory's
    assert "span" not in err.split("got")[0]


def test_orbit_table_with_a_byte_order_mark_is_read(tmp_path):
    path = tmp_path / "sheet.csv"
    path.write_bytes(b"\xef\xbb\xbf" + (ELEMENTS + ROWS).encode())
    assert read_orbit_csv(path).span == (-2000.0, 1000.0)


def test_binary_orbit_table_is_named(tmp_path, capsys):
    path = tmp_path / "orbit.csv"
    path.write_bytes(b"\x89PNG\r\n\x1a\n\x00\x00" + bytes(range(256)))
    code, err = run([*OBLIQUITY, "--orbit", str(path)], capsys)
    assert code == 2
    assert "expected a UTF-8 text file, got byte 0x89 on line 1 of" in err
    assert "orbit.csv" in err
    assert "codec" not in err


@pytest.mark.parametrize(
    ("column", "value"), [("inclination_deg", "500"), ("inclination_deg", "-1"), ("e", "1.2")]
)
def test_orbit_table_elements_out_of_range_are_refused(column, value, tmp_path, capsys):
    rows = ROWS.splitlines()
    fields = rows[1].split(",")
    fields[ELEMENTS.strip().split(",").index(column)] = value
    rows[1] = ",".join(fields)
    path = tmp_path / "orbit.csv"
    path.write_text(ELEMENTS + "\n".join(rows) + "\n")
    code, err = run([*OBLIQUITY, "--orbit", str(path)], capsys)
    assert code == 2
    assert f"got {float(value)!r} in column {column} on line 3 of" in err


def test_csv_input_with_a_byte_order_mark_is_read(tmp_path, capsys):
    path = tmp_path / "states.csv"
    path.write_bytes(b"\xef\xbb\xbf" + (ROOT / "examples" / "states.csv").read_bytes())
    code, err = run(["convert", "--from", "euler", "--to", "andoyer", "--input", str(path)], capsys)
    assert code == 0, err


def test_csv_input_not_utf8_is_named(tmp_path, capsys):
    path = tmp_path / "states.csv"
    path.write_bytes(b"phi,theta\n\xff\xfe,1\n")
    code, err = run(["convert", "--from", "euler", "--to", "andoyer", "--input", str(path)], capsys)
    assert code == 2
    assert "expected a UTF-8 CSV file" in err


@pytest.mark.parametrize(
    ("output", "plot"),
    [
        ("same.png", "same.png"),
        ("same.png", "./sub/../same.png"),  # a relative path to the same file
        ("link.png", "same.png"),  # a symbolic link to it
        ("hard.png", "same.png"),  # a hard link to it
        ("-", "-"),  # standard output twice
    ],
)
def test_two_outputs_naming_one_file_are_refused(output, plot, tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "sub").mkdir()
    (tmp_path / "same.png").write_bytes(b"mine")
    (tmp_path / "link.png").symlink_to("same.png")
    os.link(tmp_path / "same.png", tmp_path / "hard.png")
    code, err = run([*OBLIQUITY, "--output", output, "--plot", plot], capsys)
    assert code == 2
    assert "expected different files for --output and --plot" in err
    assert (tmp_path / "same.png").read_bytes() == b"mine"


def test_output_on_a_special_file_system_says_so(capsys):
    for path in ("/proc/version", "/proc/andoyer-new.csv"):
        code, err = run([*OBLIQUITY, "--output", path], capsys)
        assert code == 2
        assert "takes no new files: a special file system, like /proc or /sys" in err
        assert "No such file or directory" not in err


def test_output_in_a_folder_without_write_permission_says_so(tmp_path, capsys):
    if os.geteuid() == 0:  # root writes anywhere: a read-only mount stands in
        folder = Path("/sys")
    else:
        folder = tmp_path / "locked"
        folder.mkdir()
        folder.chmod(0o500)
    code, err = run([*OBLIQUITY, "--output", str(folder / "x.csv")], capsys)
    assert code == 2
    assert "expected a writable place for the output" in err
    reasons = ("no permission to write in", "cannot be written", "special file system")
    assert any(why in err for why in reasons)


@pytest.mark.parametrize("dpi", ["1e-3", "0.2"])
def test_portrait_dpi_too_small_for_a_pixel_is_refused(dpi, tmp_path, capsys):
    out = tmp_path / "p.png"
    argv = ["portrait", "phase", "--body", "eros", "--levels", "1", "--dpi", dpi, "--out", str(out)]
    code, err = run(argv, capsys)
    assert code == 2
    assert "expected --dpi of at least" in err
    assert "empty image" not in err
    assert not out.exists()


def _commands(parser: argparse.ArgumentParser, prefix: str = "") -> dict[str, argparse.ArgumentParser]:
    found = {}
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                key = f"{prefix} {name}".strip()
                found |= _commands(sub, key) or {key: sub}
    return found


@pytest.mark.parametrize(("name", "parser"), sorted(_commands(build_parser()).items()))
def test_help_every_option_says_what_it_is(name, parser):
    silent = [
        action.option_strings[0] if action.option_strings else action.dest
        for action in parser._actions
        if not action.help and not isinstance(action, argparse._HelpAction)
    ]
    assert silent == [], f"andoyer {name}: options without help text {silent}"


def test_help_cassini_says_what_it_does_today(capsys):
    with pytest.raises(SystemExit):
        main(["--help"])
    top = capsys.readouterr().out
    with pytest.raises(SystemExit):
        main(["cassini", "--help"])
    text = top + capsys.readouterr().out
    assert "any body" not in text
    assert "the Moon or Mercury" in " ".join(text.split())


def test_readme_demo_years_and_ensemble_extra():
    from andoyer.cli.demo_report import PRECESSION_SERIES_YEARS

    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert f"over {PRECESSION_SERIES_YEARS} years" in readme
    lines = readme.splitlines()
    at = next(k for k, line in enumerate(lines) if line.startswith("andoyer ensemble"))
    assert '".[ensemble]"' in lines[at - 1]
