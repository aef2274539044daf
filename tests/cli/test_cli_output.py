"""Output files of the command line: through links, atomic, umask modes, one-line file-system errors."""

from __future__ import annotations

import errno
import os
import stat
import subprocess
import sys
from pathlib import Path

import pytest

from andoyer.cli import build_parser, main, output

STATE = ["0.1", "0.2", "0.3", "0.9", "1.0", "0.5"]
CONVERT = ["convert", "--from", "andoyer", "--to", "euler", "--values", *STATE]
ROOT = Path(__file__).resolve().parents[2]


def run(capsys, argv):
    try:
        code = main(argv)
    except SystemExit as exc:
        code = exc.code
    captured = capsys.readouterr()
    run.out = captured.out
    return code, captured.err


@pytest.fixture
def umask():
    """Set the umask for one test, and put the previous one back."""
    previous = os.umask(0o022)
    yield os.umask
    os.umask(previous)


def test_output_through_symlink_replaces_target_and_keeps_link(tmp_path, capsys):
    target = tmp_path / "data" / "table.csv"
    target.parent.mkdir()
    target.write_text("old\n")
    link = tmp_path / "link.csv"
    link.symlink_to(Path("data") / "table.csv")  # relative, as users make them
    code, err = run(capsys, [*CONVERT, "--format", "csv", "--output", str(link)])
    assert (code, err) == (0, "")
    assert link.is_symlink()
    assert os.readlink(link) == os.path.join("data", "table.csv")
    assert target.read_text().startswith("phi,theta,psi,Phi,Theta,Psi\n")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["data", "link.csv"]
    assert sorted(p.name for p in target.parent.iterdir()) == ["table.csv"]


@pytest.mark.parametrize(("mask", "mode"), [(0o022, 0o644), (0o077, 0o600), (0o002, 0o664)])
@pytest.mark.parametrize(
    "argv",
    [
        [*CONVERT, "--output", "{out}"],
        ["portrait", "lara", "--format", "svg", "--out", "{out}"],
        ["series", "sam", "--order", "1", "--output", "{out}"],
    ],
    ids=["convert", "portrait", "series"],
)
def test_output_new_file_mode_follows_umask(argv, mask, mode, tmp_path, umask, capsys):
    out = tmp_path / "out.svg"
    umask(mask)
    code, err = run(capsys, [str(out) if a == "{out}" else a for a in argv])
    assert (code, err) == (0, "")
    assert stat.S_IMODE(out.stat().st_mode) == mode


def test_output_replaced_file_keeps_its_mode(tmp_path, umask, capsys):
    out = tmp_path / "out.csv"
    out.write_text("old\n")
    out.chmod(0o640)
    umask(0o077)
    code, _ = run(capsys, [*CONVERT, "--output", str(out)])
    assert code == 0
    assert stat.S_IMODE(out.stat().st_mode) == 0o640
    assert out.read_text() != "old\n"


@pytest.mark.parametrize(
    ("make", "expected"),
    [
        (lambda p: p.mkdir(), "the directory"),
        (os.mkfifo, "the FIFO"),
        ("device", "the character device"),
        (lambda p: p.symlink_to(p.with_name("missing.csv")), "dangling symbolic link"),
    ],
    ids=["directory", "fifo", "device", "dangling-link"],
)
def test_output_non_regular_refused_before_any_work(make, expected, tmp_path, capsys, make_device):
    out = tmp_path / "out.csv"
    (make_device if make == "device" else make)(out)
    code, err = run(capsys, [*CONVERT, "--output", str(out)])
    assert code == 2
    assert len(err.splitlines()) == 1
    assert expected in err
    assert [p.name for p in tmp_path.iterdir()] == ["out.csv"]


def test_output_directory_one_line_no_traceback(tmp_path):
    # The IsADirectoryError traceback, run as a user runs it (the bad-input table
    # tries a folder as the output of every command, in this process).
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    argv = ["propagate", "--body", "eros", "--values", "0.1", "0.2", "0.3", "0.9", "1", "0.5", "--times", "0"]
    argv += ["--output", str(tmp_path)]
    proc = subprocess.run(
        [sys.executable, "-m", "andoyer", *argv], capture_output=True, text=True, env=env, check=False
    )
    assert proc.returncode == 2
    assert len(proc.stderr.splitlines()) == 1
    assert "Traceback" not in proc.stderr
    assert list(tmp_path.iterdir()) == []


def test_output_read_only_file_is_not_replaced(tmp_path, monkeypatch, capsys):
    # As root every file is writable: the permission answer is simulated.
    out = tmp_path / "out.csv"
    out.write_text("protected\n")
    out.chmod(0o444)
    monkeypatch.setattr(output.os, "access", lambda path, how: Path(path) != out)
    code, err = run(capsys, [*CONVERT, "--output", str(out)])
    assert code == 2
    assert "read-only file" in err
    assert out.read_text() == "protected\n"


@pytest.mark.parametrize("code", [errno.ENOSPC, errno.EROFS, errno.EACCES])
def test_output_write_failure_one_line_and_no_temporary_left(code, tmp_path, monkeypatch, capsys):
    out = tmp_path / "out.csv"
    out.write_text("previous\n")

    def refuse(src, dst):
        raise OSError(code, os.strerror(code), str(dst))

    monkeypatch.setattr(output.os, "replace", refuse)
    status, err = run(capsys, [*CONVERT, "--output", str(out)])
    assert status == 2
    assert len(err.splitlines()) == 1
    assert os.strerror(code) in err
    assert out.read_text() == "previous\n"
    assert [p.name for p in tmp_path.iterdir()] == ["out.csv"]


def test_main_turns_oserror_into_one_line_but_not_bugs(monkeypatch, capsys):
    from andoyer.cli import bodies_cmd

    def full(args):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), "somewhere.csv")

    monkeypatch.setattr(bodies_cmd, "run", full)
    assert main(["bodies"]) == 2
    err = capsys.readouterr().err
    assert err == f"andoyer bodies: error: {os.strerror(errno.ENOSPC)} (somewhere.csv)\n"

    def bug(args):
        raise ZeroDivisionError

    monkeypatch.setattr(bodies_cmd, "run", bug)
    with pytest.raises(ZeroDivisionError):
        main(["bodies"])


@pytest.mark.parametrize("value", ["-1e300", "-2.5E-3", "-.5", "-1", "-1.", "-inf", "-NaN", "-1e+3"])
def test_cli_negative_numbers_are_values(value):
    parser = build_parser()
    args = parser.parse_args(["propagate", "--body", "eros", "--values", value, "0", "0", "0.9", "1", "0.5",
                              "--times", value, "0"])  # fmt: skip
    assert args.times[0] == pytest.approx(float(value), nan_ok=True)
    assert args.values[0] == pytest.approx(float(value), nan_ok=True)
    args = parser.parse_args(["portrait", "sphere", "--body", "eros", "--elev-deg", value])
    assert args.elev_deg == pytest.approx(float(value), nan_ok=True)


def test_cli_negative_time_propagates_backwards(capsys):
    # Independent check: the exact flow run back by 1 then forward by 1 returns the start.
    base = ["propagate", "--body", "eros", "--format", "csv"]
    code, _ = run(capsys, [*base, "--values", "0.1", "0.2", "0.3", "0.9", "1.0", "0.5", "--times", "-1e0"])
    assert code == 0
    back = run.out.splitlines()[1].split(",")[2:]
    assert float(back[0]) != pytest.approx(0.1)  # it moved
    code, _ = run(capsys, [*base, "--values", *back, "--times", "1"])
    again = [float(x) for x in run.out.splitlines()[1].split(",")[2:]]
    assert again == pytest.approx([0.1, 0.2, 0.3, 0.9, 1.0, 0.5], abs=1e-12)


ENSEMBLE = ["ensemble", "--moments", "1", "2", "3", "--samples", "4", "--times", "0", "1"]
ENSEMBLE += ["--scheduler", "synchronous", "--quiet", "--out"]


@pytest.mark.parametrize(("mask", "mode"), [(0o022, 0o644), (0o077, 0o600)])
def test_ensemble_netcdf_mode_follows_umask(mask, mode, tmp_path, umask, capsys):
    umask(mask)
    code, err = run(capsys, [*ENSEMBLE, str(tmp_path / "e.nc")])
    assert (code, err) == (0, "")
    assert stat.S_IMODE((tmp_path / "e.nc").stat().st_mode) == mode


def test_ensemble_store_through_a_link_is_resumed_where_it_lies(tmp_path, capsys):
    assert run(capsys, [*ENSEMBLE, str(tmp_path / "real.zarr")]) == (0, "")
    (tmp_path / "link.zarr").symlink_to("real.zarr")
    assert run(capsys, [*ENSEMBLE, str(tmp_path / "link.zarr")]) == (0, "")
    assert (tmp_path / "link.zarr").is_symlink()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link.zarr", "real.zarr"]


@pytest.mark.parametrize("make", [lambda p: p.write_text("mine\n"), os.mkfifo], ids=["file", "fifo"])
def test_ensemble_zarr_out_must_be_a_folder(make, tmp_path, capsys):
    out = tmp_path / "e.zarr"
    make(out)
    code, err = run(capsys, [*ENSEMBLE, str(out)])
    assert code == 2
    assert len(err.splitlines()) == 1
    assert [p.name for p in tmp_path.iterdir()] == ["e.zarr"]
