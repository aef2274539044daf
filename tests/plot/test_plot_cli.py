"""``andoyer portrait``: PNG and SVG files written atomically; bad arguments give one line, exit 2."""

import numpy as np
import pytest
from matplotlib.image import imread

from andoyer.cli import main

KINDS = {
    "phase": ["--body", "eros"],
    "sphere": ["--moments", "1", "2", "3", "--levels", "2"],
    "lara": [],
    "polhode": ["--moments", "1", "2", "3", "--values", "0.5", "0", "0", "0.9", "1", "0.9"],
    "precession": ["--moments", "1", "1", "1.5", "--values", "0", "0", "0", "0.9", "2", "2", "--steps", "51"],
    "cassini": ["--body", "mercury", "--levels", "6"],
}


@pytest.mark.parametrize("kind", KINDS)
def test_portrait_writes_png(kind, tmp_path, capsys):
    out = tmp_path / f"{kind}.png"
    code = main(["portrait", kind, *KINDS[kind], "--out", str(out), "--dpi", "40"])
    assert code == 0, capsys.readouterr().err
    image = imread(out)
    assert image.ndim == 3
    assert min(image.shape[:2]) > 100
    assert np.ptp(image[..., :3]) > 0.5  # something drawn, not a blank canvas
    assert [p.name for p in tmp_path.iterdir()] == [f"{kind}.png"]  # no temporary left behind


def test_portrait_writes_svg_with_the_title(tmp_path):
    out = tmp_path / "lara.svg"
    assert main(["portrait", "lara", "--beta", "0.5", "--out", str(out)]) == 0
    text = out.read_text()
    assert text.lstrip().startswith("<?xml")
    assert "<svg" in text


def test_portrait_lara_takes_beta_from_a_body(tmp_path, monkeypatch):
    seen = {}
    import andoyer.plot

    real = andoyer.plot.lara_portrait

    def spy(beta, **kwargs):
        seen["beta"] = beta
        return real(beta, **kwargs)

    monkeypatch.setattr(andoyer.plot, "lara_portrait", spy)
    assert main(["portrait", "lara", "--body", "eros", "--out", str(tmp_path / "x.png"), "--dpi", "20"]) == 0
    assert seen["beta"] == pytest.approx(0.977853, abs=6e-7)  # Lara Table 1, as in test_cli


def test_portrait_to_stdout(capsysbinary):
    assert main(["portrait", "phase", "--moments", "1", "2", "3", "--out", "-", "--format", "svg"]) == 0
    out = capsysbinary.readouterr().out
    assert b"<svg" in out


def test_portrait_default_file_name(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(["portrait", "sphere", "--moments", "1", "2", "3", "--dpi", "20"]) == 0
    assert (tmp_path / "portrait-sphere.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize(
    ("argv", "match"),
    [
        (["phase", "--body", "eros", "--out", "x.jpg"], "expected --out ending in .png or .svg"),
        (["phase", "--body", "eros", "--out", "x.png", "--format", "svg"], "expected a .svg file"),
        (["phase", "--out", "x.png"], "expected --body NAME or --moments"),
        (["phase", "--moments", "1", "1", "1", "--out", "x.png"], "unequal moments"),
        (["sphere", "--body", "eros", "--levels", "-1", "--out", "x.png"], "0 <= --levels"),
        (
            ["polhode", "--body", "eros", "--values", "0", "0", "0", "2", "1", "0.5", "--out", "x.png"],
            "expected",
        ),
        (["precession", "--body", "eros", "--steps", "1", "--out", "x.png"], "2 <= --steps"),
        (["precession", "--body", "eros", "--duration", "-2", "--out", "x.png"], "--duration > 0"),
        (["lara", "--beta", "1.5", "--out", "x.png"], "beta"),
        (["lara", "--out", "x.png", "--dpi", "0"], "--dpi > 0"),
        (["phase", "--body", "eros", "--out", "no/such/dir/x.png"], "existing directory"),
    ],
)
def test_portrait_bad_arguments_one_line_exit_2(argv, match, tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    code = main(["portrait", *argv])
    err = capsys.readouterr().err
    assert code == 2
    assert err.count("\n") == 1
    assert err.startswith("andoyer portrait: error: ")
    assert match in err
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("argv", [["nosuch"], ["phase", "--body", "pluto"], ["phase", "--format", "gif"]])
def test_portrait_argparse_errors_exit_2(argv, capsys):
    with pytest.raises(SystemExit) as info:
        main(["portrait", *argv])
    assert info.value.code == 2
    assert capsys.readouterr().err.count("\n") == 1
