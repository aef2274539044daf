"""Every ``andoyer …`` line of the README's shell examples runs as written and exits 0."""

from __future__ import annotations

import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from andoyer.cli import main

ROOT = Path(__file__).resolve().parents[2]

#: Commands too slow for the default run (a local Dask cluster of worker processes).
SLOW = ("ensemble", "nutation")


def readme_commands() -> list[list[str]]:
    """The ``andoyer`` command lines of the README's ```bash blocks, continuations joined."""
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    lines = []
    for block in re.findall(r"```bash\n(.*?)```", text, flags=re.DOTALL):
        for line in block.replace("\\\n", " ").splitlines():
            words = shlex.split(line)
            if words and words[0] == "andoyer":
                lines.append(words[1:])
    return lines


COMMANDS = readme_commands()


def _params():
    for argv in COMMANDS:
        marks = [pytest.mark.slow] if argv[0] in SLOW else []
        yield pytest.param(argv, marks=marks, id=" ".join(argv[:2]))


def test_readme_commands_found():
    names = {argv[0] for argv in COMMANDS}
    # The README's tour names these commands; the parser must still find them all.
    assert {"bodies", "convert", "propagate", "precession", "series", "brackets", "portrait"} <= names
    assert (
        next(a for a in COMMANDS if "--input" in a)[:7]
    ) == ["convert", "--from", "euler", "--to", "andoyer", "--input", "examples/states.csv"]


@pytest.fixture
def user_dir(tmp_path, monkeypatch):
    """A working folder as a user's clone would have it: the shipped examples, outputs land here."""
    shutil.copytree(ROOT / "examples", tmp_path / "examples")
    monkeypatch.chdir(tmp_path)
    return tmp_path


@pytest.mark.parametrize("argv", list(_params()))
def test_readme_command_exits_0(argv, user_dir, capsys):
    for flag in ("--output", "--out"):
        if flag in argv:
            assert "/" not in argv[argv.index(flag) + 1]  # relative: written into user_dir
    if argv[0] in SLOW:  # worker processes need a real __main__: run it as the user does
        env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
        proc = subprocess.run(
            [sys.executable, "-m", "andoyer", *argv], cwd=user_dir, env=env, capture_output=True, check=False
        )
        assert proc.returncode == 0, proc.stderr.decode()[-2000:]
    else:
        assert main(argv) == 0
        assert capsys.readouterr().err == ""
    for flag in ("--output", "--out"):
        if flag in argv:
            assert (user_dir / argv[argv.index(flag) + 1]).exists()
