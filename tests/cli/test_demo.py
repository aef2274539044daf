"""``andoyer demo``: the report folder, its sections and its numbers."""

import os
import re
import stat
import subprocess
import sys

import numpy as np
import pytest

from andoyer import bodies
from andoyer.cli import demo_report, main
from andoyer.cli.demo_report import demo_state, write_report


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    folder = tmp_path_factory.mktemp("demo") / "andoyer-demo"
    summary = write_report("earth", folder, progress=False)
    return folder, summary


def test_demo_report_has_every_section(report):
    folder, summary = report
    assert (folder / "README.md").read_text(encoding="utf-8") == summary
    for heading in (
        "## Earth's precession",
        "## Phase portraits",
        "### state",
        "### euler",
        "### andoyer",
        "### sadov",
        "## Exact torque-free",
        "SAM series",
    ):
        assert heading in summary


def test_demo_report_free_wobble_period_matches_the_axisymmetric_estimate(report):
    # Independent estimate: Euler's period 2π/ω_w with ω_w = ω √((C−A)(C−B)/(AB)) (the
    # small-amplitude limit of the exact solution), in rotation periods.
    _, summary = report
    A, B, C = bodies.get("earth").moments
    expected = 1 / np.sqrt((C - A) * (C - B) / (A * B))
    got = float(re.search(r"= ([0-9.]+) rotation periods", summary).group(1))
    assert got == pytest.approx(expected, rel=1e-5)


def test_demo_report_sam_error_falls_with_order(report):
    _, summary = report
    rows = [line for line in summary.splitlines() if line.startswith("| 0.2 |")]
    errors = [float(x) for x in rows[-1].strip("|").split("|")[1:]]
    assert errors[0] > 1e-10
    assert errors[0] > 30 * errors[1] > 30 * errors[2]


def test_demo_state_spins_once_per_rotation_period():
    entry = bodies.info("mars")
    state = demo_state("mars")
    omega = np.linalg.norm(state.omega(entry.body))
    assert omega * entry.rotation_period / (2 * np.pi) == pytest.approx(1, rel=1e-5)


def test_demo_interrupted_leaves_previous_report_untouched(tmp_path, monkeypatch):
    folder = tmp_path / "out"
    folder.mkdir()
    (folder / "README.md").write_text("previous", encoding="utf-8")
    (folder / demo_report.MARKER).write_text(f"{demo_report.MARKER_HEADER}\nformat 1\n", encoding="utf-8")

    def broken(ctx):
        raise KeyboardInterrupt

    monkeypatch.setattr(demo_report, "SECTIONS", (demo_report.section_body, broken))
    with pytest.raises(KeyboardInterrupt):
        write_report("earth", folder, progress=False)
    assert (folder / "README.md").read_text(encoding="utf-8") == "previous"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]
    assert sorted(p.name for p in folder.iterdir()) == [demo_report.MARKER, "README.md"]


def test_demo_cli_writes_the_folder(tmp_path, capsys):
    code = main(["demo", "--body", "moon", "--out", str(tmp_path / "r"), "--quiet"])
    assert code == 0
    assert capsys.readouterr().out == ""
    assert "# andoyer demo: Moon" in (tmp_path / "r" / "README.md").read_text(encoding="utf-8")


@pytest.mark.parametrize(
    "argv",
    [["demo", "--body", "pluto"], ["demo", "--out", "/nonexistent/dir/report"]],
    ids=["unknown-body", "missing-parent"],
)
def test_demo_cli_bad_arguments_one_line_exit_2(argv):
    proc = subprocess.run(
        [sys.executable, "-m", "andoyer", *argv], capture_output=True, text=True, check=False
    )
    assert proc.returncode == 2
    assert len(proc.stderr.strip().splitlines()) == 1
    assert "Traceback" not in proc.stderr


def test_demo_report_pictures_exist_and_are_linked(report):
    folder, summary = report
    for name in (
        "phase-portrait.png",
        "momentum-sphere.png",
        "lara-figure-1.png",
        "poinsot.png",
        "earth-precession.png",
    ):
        assert f"]({name})" in summary
        assert (folder / name).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_demo_report_precession_in_the_issue_band(report):
    # Issue band for a rigid Earth torqued by the Sun and the Moon: 50.0–50.8″/yr, from both
    # the secular model and the splitting integration (observed 50.38″/yr).
    _, summary = report
    rows = [line for line in summary.splitlines() if line.startswith(("| secular", "| splitting"))]
    rates = [float(row.strip("|").split("|")[-1]) for row in rows]
    assert len(rates) == 2
    assert all(50.0 <= rate <= 50.8 for rate in rates)


# --- the report folder: never delete or overwrite what the user made ---


def _tiny(ctx):
    (ctx.folder / "picture.png").write_bytes(b"\x89PNG tiny")
    return "## tiny\n"


@pytest.fixture
def quick_demo(monkeypatch):
    """The demo with one cheap section, so that only the folder handling is under test."""
    monkeypatch.setattr(demo_report, "SECTIONS", (_tiny,))


def _tree(folder):
    return {
        str(p.relative_to(folder)): (p.read_bytes() if p.is_file() and not p.is_symlink() else None)
        for p in sorted(folder.rglob("*"))
    }


def _user_project(folder):
    (folder / "src").mkdir(parents=True)
    (folder / "src" / "main.py").write_text("print('mine')\n")
    (folder / ".git").mkdir()
    (folder / ".git" / "HEAD").write_text("ref: refs/heads/main\n")
    (folder / "README.md").write_text("my project\n")


@pytest.mark.parametrize("absolute", [False, True], ids=["relative", "absolute"])
def test_demo_refuses_a_users_folder_and_names_force(absolute, quick_demo, tmp_path, monkeypatch, capsys):
    project = tmp_path / "p"
    _user_project(project)
    before = _tree(tmp_path)
    monkeypatch.chdir(tmp_path)
    code = main(["demo", "--quiet", "--out", str(project) if absolute else "p"])
    err = capsys.readouterr().err
    assert code == 2
    assert len(err.splitlines()) == 1
    assert "--force" in err
    assert _tree(tmp_path) == before


def test_demo_force_writes_beside_the_users_files(quick_demo, tmp_path, capsys):
    project = tmp_path / "p"
    _user_project(project)
    user_files = {k: v for k, v in _tree(project).items() if k != "README.md"}
    assert main(["demo", "--quiet", "--force", "--out", str(project)]) == 0
    after = _tree(project)
    assert {k: after[k] for k in user_files} == user_files  # nothing of theirs deleted or changed
    assert after["README.md"].startswith(b"# andoyer demo: Earth")  # only the report's own names
    assert set(after) == {*user_files, "README.md", "picture.png", demo_report.MARKER}


def test_demo_replaces_a_previous_report_and_keeps_other_files(quick_demo, tmp_path, capsys):
    folder = tmp_path / "r"
    assert main(["demo", "--quiet", "--out", str(folder)]) == 0
    marker = (folder / demo_report.MARKER).read_text(encoding="utf-8").splitlines()
    assert marker[:2] == [demo_report.MARKER_HEADER, "format 1"]
    assert marker[-1].split()[1:] == ["README.md", "picture.png", demo_report.MARKER]
    (folder / "notes.txt").write_text("mine\n")
    assert main(["demo", "--quiet", "--body", "mars", "--out", str(folder)]) == 0
    assert (folder / "README.md").read_text(encoding="utf-8").startswith("# andoyer demo: Mars")
    assert (folder / "notes.txt").read_text() == "mine\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["r"]


def test_demo_out_dot_and_dotdot(quick_demo, tmp_path, monkeypatch, capsys):
    empty = tmp_path / "empty"
    empty.mkdir()
    monkeypatch.chdir(empty)
    assert main(["demo", "--quiet", "--out", "."]) == 0  # was "PosixPath('.') has an empty name"
    assert (empty / "README.md").is_file()
    assert (empty / demo_report.MARKER).is_file()
    (tmp_path / "other.txt").write_text("mine\n")
    code = main(["demo", "--quiet", "--out", ".."])  # holds "empty" and other.txt: not a report
    err = capsys.readouterr().err
    assert code == 2
    assert len(err.splitlines()) == 1
    assert "--force" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["empty", "other.txt"]


def test_demo_through_a_link_to_a_folder(quick_demo, tmp_path, capsys):
    real = tmp_path / "real"
    real.mkdir()
    (tmp_path / "link").symlink_to("real")
    assert main(["demo", "--quiet", "--out", str(tmp_path / "link")]) == 0
    assert (tmp_path / "link").is_symlink()
    assert (real / "README.md").is_file()


@pytest.mark.parametrize(
    "out",
    ["/proc/andoyer-demo", "/proc", "{file}/report", "{file}", "{dangling}", "{device}"],
    ids=["read-only", "read-only-force", "under-a-file", "a-file", "dangling-link", "device"],
)
def test_demo_unwritable_places_one_line_exit_2(out, quick_demo, tmp_path, capsys, make_device):
    (tmp_path / "file").write_text("mine\n")
    (tmp_path / "dangling").symlink_to(tmp_path / "nowhere")
    make_device(tmp_path / "device")
    out = out.format(file=tmp_path / "file", dangling=tmp_path / "dangling", device=tmp_path / "device")
    before = _tree(tmp_path)
    code = main(["demo", "--quiet", "--force", "--out", out])
    err = capsys.readouterr().err
    assert code == 2
    assert len(err.splitlines()) == 1
    assert _tree(tmp_path) == before


@pytest.mark.parametrize(("mask", "dir_mode", "file_mode"), [(0o022, 0o755, 0o644), (0o077, 0o700, 0o600)])
@pytest.mark.parametrize("existing", [False, True], ids=["new-folder", "empty-folder"])
def test_demo_modes_follow_umask(mask, dir_mode, file_mode, existing, quick_demo, tmp_path, capsys):
    folder = tmp_path / "r"
    if existing:
        folder.mkdir()
    previous = os.umask(mask)
    try:
        assert main(["demo", "--quiet", "--out", str(folder)]) == 0
    finally:
        os.umask(previous)
    if not existing:
        assert stat.S_IMODE(folder.stat().st_mode) == dir_mode
    for name in ("README.md", "picture.png", demo_report.MARKER):
        assert stat.S_IMODE((folder / name).stat().st_mode) == file_mode
