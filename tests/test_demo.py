"""``andoyer demo``: the report folder, its sections and its numbers."""

import re
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

    def broken(ctx):
        raise KeyboardInterrupt

    monkeypatch.setattr(demo_report, "SECTIONS", (demo_report.section_body, broken))
    with pytest.raises(KeyboardInterrupt):
        write_report("earth", folder, progress=False)
    assert (folder / "README.md").read_text(encoding="utf-8") == "previous"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]


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
