"""The bad-input table: every sub-command against every class of bad input.

The commands are found in :func:`andoyer.cli.build_parser` (sub-commands of sub-commands
too, e.g. ``portrait phase``), and each must have an entry in :data:`VALID`: argument lists
that succeed. The table mutates those: each number in turn replaced by NaN, ±inf, ±1e300;
each choice by an unknown one; the input file by a missing file or a folder; the output by a
folder, a dangling link, a character device (and a link to it), a FIFO, a path under a regular file, a
place that cannot be written. Each case must exit 2 with exactly one line on standard error
(no traceback) and leave the folder it ran in exactly as it was: nothing written, replaced or
deleted, links, devices and FIFOs untouched. A new command without an entry fails
:func:`test_bad_input_every_command_has_valid_arguments`.
"""

from __future__ import annotations

import argparse
import math
import os
import stat
from dataclasses import dataclass
from pathlib import Path

import pytest

from andoyer.cli import build_parser, main

STATE = "0.1 0.2 0.3 0.9 1.0 0.5"  # l g h L G H: a valid Andoyer state


@dataclass(frozen=True)
class Valid:
    """Command lines of one command that succeed; ``{out}`` is the output, ``{input}`` an input CSV."""

    lines: tuple[str, ...]
    output: str | None = None  # the flag naming the output, if any
    suffix: str = ".csv"  # of the output file ("" for a folder)

    @property
    def argvs(self) -> list[tuple[str, ...]]:
        return [tuple(line.split()) for line in self.lines]


VALID: dict[str, Valid] = {
    "demo": Valid(("demo --body moon --quiet --out {out}",), "--out", ""),
    "bodies": Valid(
        ("bodies --format csv", "bodies titan --format json", "bodies --moments lara2013 --format table")
    ),
    "convert": Valid(
        (
            f"convert --from andoyer --to euler --values {STATE} --output {{out}}",
            "convert --from euler --to sadov --moments 1 2 3 --input {input}",
        ),
        "--output",
    ),
    "propagate": Valid(
        (
            f"propagate --body eros --values {STATE} --times 0 10 --output {{out}}",
            "propagate --moments 1 2 3 --from euler --input {input} --range 0 5 3",
            (
                "propagate --model heavy-top --weight 0.5 --center-of-mass 0 0 0.3 --moments 1 1 0.5 "
                f"--values {STATE} --range 0 1 3 --method splitting --step 0.1 --order 2"
            ),
            (
                "propagate --model heavy-top --weight 0.5 --center-of-mass 0 0 0.3 --moments 1 1 0.5 "
                f"--values {STATE} --range 0 1 3 --method splitting --rtol 1e-6"
            ),
        ),
        "--output",
    ),
    "precession": Valid(
        (
            "precession earth --format json --output {out}",
            "precession mars --dynamical-ellipticity 0.0054 --format json --output {out}",
            "precession earth --moments lara2013 --format json --output {out}",
            "precession saturn --format json --output {out}",
            "precession venus --dynamical-ellipticity 0.00002 --output {out}",
        ),
        "--output",
    ),
    "ensemble": Valid(
        (
            (
                "ensemble --moments 1 2 3 --samples 4 --chunk 2 --times 0 1 --scheduler synchronous "
                "--quiet --G 0.5 1 --cos-J -1 1 --cos-I -0.5 0.5 --seed 3 --out {out}"
            ),
            (
                "ensemble --body eros --samples 2 --range 0 1 2 --sampler momentum --m-low -1 -1 -1 "
                "--m-high 1 1 1 --scheduler synchronous --quiet --out {out}"
            ),
        ),
        "--out",
        ".nc",
    ),
    "cassini": Valid(
        (
            "cassini moon --format json --output {out}",
            (
                "cassini --j2 5.03e-5 --c22 0.81e-5 --moment-of-inertia 0.346 --orbital-period 87.97 "
                "--eccentricity 0.2056 --node-period 325000 --inclination 8.6 --mass-ratio 1.66e-7 "
                "--resonance 1.5 --format table"
            ),
            "cassini titan --node model --obliquity 0.32 --obliquity-error 0.02 --format json",
        ),
        "--output",
    ),
    "nutation": Valid(
        (
            "nutation earth --span 0 1 --step 0.5 --format json --output {out}",
            "nutation earth --span 0 1 --step 0.5 --dynamical-ellipticity 0.0032737949 --output {out}",
        ),
        "--output",
    ),
    "obliquity": Valid(
        (
            "obliquity earth --span -1000 1000 --step 500 --format json --output {out}",
            (
                "obliquity earth --span -1000 1000 --step 500 --dynamical-ellipticity 0.0033 "
                "--tidal-dissipation 0.5 --output {out}"
            ),
            "obliquity earth --span -1000 1000 --step 100 --precession-rate 500 --output {out}",
            "obliquity saturn --span -100000 100000 --step 10000 --drift-timescale 4e9 --output {out}",
            (
                "obliquity saturn --span -20000 20000 --step 10000 --migration titan --migration-index 0.5 "
                "--migration-age 4e9 --output {out}"
            ),
            "obliquity earth --span -1000 1000 --step 500 --tolerance 0.001 --format json --output {out}",
            "obliquity earth --span -2000 0 --step 1000 --tides constant-lag --format json --output {out}",
            (
                "obliquity mars --ensemble 2 --span -20000 0 --step 10000 --seed 1 --perturbation 1e-7 "
                "--thresholds 30 --scheduler synchronous --format json --output {out}"
            ),
        ),
        "--output",
    ),
    "tides": Valid(
        (
            "tides earth --span -1e8 0 --step 5e7 --obliquity 23 --format json --output {out}",
            "tides earth --model constant-lag --span -2e8 1e8 --step 1e8 --no-solar-tide --format csv",
        ),
        "--output",
    ),
    "orbit": Valid(
        (
            "orbit laplace-lagrange --span -1000 0 --step 500 --format json --output {out}",
            "orbit secular --planets mars earth --span 0 10000 --step 5000 --format csv --output {out}",
            "orbit vondrak --span -1000 1000 --step 1000 --format table",
        ),
        "--output",
    ),
    "brackets": Valid(("brackets --algebra so3 --format json --output {out}",), "--output"),
    "series sam": Valid(("series sam --order 2 --format tex --output {out}",), "--output"),
    "portrait phase": Valid(
        ("portrait phase --body eros --G 1 --levels 1 --dpi 20 --out {out}",), "--out", ".png"
    ),
    "portrait sphere": Valid(
        ("portrait sphere --moments 1 2 3 --levels 1 --elev-deg 30 --azim-deg 10 --dpi 20 --out {out}",),
        "--out",
        ".png",
    ),
    "portrait lara": Valid(
        ("portrait lara --beta 0.8 --ratio-min 0.9 --format svg --out {out}",), "--out", ".svg"
    ),
    "portrait polhode": Valid(
        (f"portrait polhode --moments 1 2 3 --values {STATE} --duration 5 --dpi 20 --out {{out}}",),
        "--out",
        ".png",
    ),
    "portrait cassini": Valid(
        (
            "portrait cassini --body moon --levels 3 --dpi 20 --out {out}",
            (
                "portrait cassini --j2 5.03e-5 --c22 0.81e-5 --moment-of-inertia 0.346 "
                "--orbital-period 87.97 --eccentricity 0.2056 --node-period 325000 --inclination 8.6 "
                "--mass-ratio 1.66e-7 --resonance 1.5 --levels 3 --dpi 20 --out {out}"
            ),
        ),
        "--out",
        ".png",
    ),
    "portrait precession": Valid(
        (
            (
                f"portrait precession --moments 1 1 1.5 --values {STATE} --duration 10 --steps 5 "
                "--axis momentum --dpi 20 --out {out}"
            ),
        ),
        "--out",
        ".png",
    ),
}

#: A huge moment of inertia is not bad input since moments that break A + B >= C are accepted
#: (issue 18 item 11): the command either refuses it in one line (a chart that needs the
#: triangle inequality) or runs, with one warning line naming the triangle inequality.
WARNS = {("--moments", "1e300")}

#: The chaotic-obliquity ensemble's options out of place or out of range (issue 22 item 3).
ENSEMBLE = "obliquity mars --span -20000 0 --scheduler synchronous --output {out}"
ENSEMBLE_BAD = (
    ("members", f"{ENSEMBLE} --ensemble 0"),
    ("span", "obliquity mars --ensemble 2 --span -20000 20000 --scheduler synchronous --output {out}"),
    ("seed-alone", "obliquity mars --seed 3 --span -2000 0 --output {out}"),
    ("seed", f"{ENSEMBLE} --ensemble 2 --seed -1"),
    ("no-moon-mars", f"{ENSEMBLE} --ensemble 2 --no-moon"),
    ("orbit", f"{ENSEMBLE} --ensemble 2 --orbit nbody"),
    ("tides", f"{ENSEMBLE} --ensemble 2 --tidal-dissipation 0.5"),
    ("perturbation", f"{ENSEMBLE} --ensemble 2 --perturbation 1"),
    ("out-suffix", f"{ENSEMBLE} --ensemble 2 --out members.txt"),
    ("thresholds", f"{ENSEMBLE} --ensemble 2 --thresholds 200"),
    ("workers", "obliquity mars --span -20000 0 --ensemble 2 --workers 0 --output {out}"),
    ("step", f"{ENSEMBLE} --ensemble 2 --step 1e6"),
    ("size", "obliquity mars --span -1e9 0 --step 1 --ensemble 100000 --output {out}"),
    ("body-file", "obliquity --body-file saturn.json --ensemble 2 --span -20000 0 --output {out}"),
    ("no-body", "obliquity --ensemble 2 --span -20000 0 --output {out}"),
    ("planet", f"{ENSEMBLE.replace('mars', 'saturn')} --ensemble 2"),
    ("drift", f"{ENSEMBLE} --ensemble 2 --drift-timescale 1e9"),
    ("orbits-alone", "obliquity mars --orbits 2 --span -2000 0 --output {out}"),
    ("orbits-divisor", f"{ENSEMBLE} --ensemble 4 --orbits 3"),
    ("orbits-zero", f"{ENSEMBLE} --ensemble 4 --orbits 0"),
    ("orbits-fixed-rate", f"{ENSEMBLE.replace('mars', 'earth')} --ensemble 4 --orbits 2"),
)

#: Requests refused for their size (issue 26): (command, case, argument line).
REFUSALS = (
    (
        "obliquity",
        "steps",
        "obliquity earth --orbit laplace-lagrange --span -1e12 0 --step 1e10 --output {out}",
    ),
    ("obliquity", "rows", "obliquity earth --span -190000 0 --step 0.0001 --format table --output {out}"),
    ("orbit", "rows", "orbit laplace-lagrange --span -1e9 0 --step 1 --output {out}"),
    ("nutation", "time", "nutation earth --span 0 200000 --step 1000 --output {out}"),
    ("precession", "memory", "precession earth --integrate 1e9 --output {out}"),
    ("portrait cassini", "levels", "portrait cassini --levels 100000000 --out {out}"),
    ("portrait phase", "levels", "portrait phase --body eros --levels 100000 --out {out}"),
    ("portrait sphere", "levels", "portrait sphere --body eros --levels 100000 --out {out}"),
    ("portrait precession", "points", "portrait precession --moments 1 1 1.5 --steps 100000000 --out {out}"),
)

#: Options that contradict each other, refused before any work: (command, case, argument line).
CONFLICTS = (
    ("obliquity", "tides-mars", "obliquity mars --tides ocean --span -2000 0 --step 1000 --output {out}"),
    (
        "obliquity",
        "tides-dissipation",
        "obliquity earth --tides ocean --tidal-dissipation 0 --span -2000 0 --step 1000 --output {out}",
    ),
    (
        "obliquity",
        "tides-ensemble",
        "obliquity mars --ensemble 2 --tides ocean --span -2e4 0 --step 1e4 --output {out}",
    ),
    (
        "obliquity",
        "tides-ellipticity",
        "obliquity earth --tides ocean --dynamical-ellipticity 0.003 --span -2e3 0 --step 1e3 --output {out}",
    ),
)

INPUT_CSV = "phi,theta,psi,Phi,Theta,Psi\n0.3,0.8,1.2,0.5,0.2,0.9\n1.0,0.41,0.0,0.9,0.0,0.98\n"
BAD_NUMBERS = ("nan", "inf", "-inf", "-1e300", "1e300")
PATH_FLAGS = ("--out", "--output", "--input")


def commands(parser: argparse.ArgumentParser, prefix: str = "") -> dict[str, argparse.ArgumentParser]:
    """Every leaf sub-command of ``parser``, as ``"portrait phase"`` -> its parser."""
    found = {}
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                found |= commands(sub, f"{prefix} {name}".strip()) or {f"{prefix} {name}".strip(): sub}
    return found


PARSERS = commands(build_parser())


def actions_by_flag(parser: argparse.ArgumentParser) -> dict[str, argparse.Action]:
    return {flag: a for a in parser._actions for flag in a.option_strings}


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def mutations() -> list:
    """A ``pytest.param(command, argv)`` for every bad input the table tries.

    In the default run: every class but numbers, and NaN in place of each number of the first list
    of each command; the rest (and the known open cases, which compute) are ``slow``.
    """
    cases = []

    def add(name, kind, case, argv, slow=False):
        marks = [pytest.mark.slow] if slow else []
        cases.append(pytest.param(name, tuple(argv), id=f"{name}-{kind}-{case}", marks=marks))

    for name, valid in VALID.items():
        parser = PARSERS.get(name)
        if parser is None:
            continue  # reported by test_bad_input_every_command_has_valid_arguments
        flags = actions_by_flag(parser)
        for k, argv in enumerate(valid.argvs):
            flag, start = None, 0
            for i, token in enumerate(argv):
                if token.startswith("--") and not _is_number(token):
                    flag, start = token, i + 1
                    continue
                if flag in PATH_FLAGS or not _is_number(token):
                    continue
                for bad in BAD_NUMBERS:
                    kind = "warns" if (flag, bad) in WARNS else "number"
                    slow = k > 0 or bad != "nan"
                    mutated = (*argv[:i], bad, *argv[i + 1 :])
                    add(name, kind, f"{k}:{flag}#{i - start}={bad}", mutated, slow)
            for option, action in flags.items():
                if action.choices is not None and option in argv:
                    i = argv.index(option) + 1
                    add(name, "choice", f"{k}:{option}", (*argv[:i], "nope", *argv[i + 1 :]))
            if "{input}" in argv:
                i = argv.index("{input}")
                for case, path in (("missing", "missing.csv"), ("folder", "afolder.csv")):
                    add(name, "input", f"{k}:{case}", (*argv[:i], path, *argv[i + 1 :]))
            if valid.output is not None and "{out}" in argv:
                i = argv.index("{out}")
                s = valid.suffix
                for case, path in (
                    ("folder", f"afolder{s}"),
                    ("dangling-link", f"dangling{s}"),
                    ("device", f"device{s}"),
                    ("device-link", f"device-link{s}"),
                    ("fifo", f"fifo{s}"),
                    ("under-a-file", f"keep.txt/out{s}"),
                    ("missing-folder", f"nowhere/out{s}"),
                    ("read-only", f"/proc/andoyer-out{s}"),
                    ("empty", ""),
                ):
                    add(name, "output", f"{k}:{case}", (*argv[:i], path, *argv[i + 1 :]))
    # Requests too large for memory or time, or drawing without bound (issue 26), refused before
    # any work with what they would need.
    for name, case, line in REFUSALS:
        add(name, "size", case, tuple(line.split()))
    for name, case, line in CONFLICTS:
        add(name, "conflict", case, tuple(line.split()))
    for case, line in ENSEMBLE_BAD:
        add("obliquity", "ensemble", case, tuple(line.split()))
    # Positional choices (precession's body) and an unknown sub-command.
    add("precession", "choice", "body", ("precession", "pluto"))
    add("bodies", "choice", "name", ("bodies", "vulcan"))
    add("", "choice", "command", ("frobnicate",))
    return cases


MUTATIONS = mutations()


def out_of_range() -> list:
    """A ``pytest.param(command, argv)`` for each physical parameter of each command, just out of range.

    The options are those whose type is :func:`andoyer.cli.numbers.physical`; the values lie just
    outside each finite bound of the parameter's range in :mod:`andoyer.planetary.parameters`
    (the bound itself where it is excluded), in the command line's unit.
    """
    cases = []
    for name, valid in VALID.items():
        flags = actions_by_flag(PARSERS[name]) if name in PARSERS else {}
        seen = set()
        for argv in valid.argvs:
            for i, token in enumerate(argv):
                action = flags.get(token)
                p = getattr(getattr(action, "type", None), "parameter", None)
                if p is None or token in seen:
                    continue
                seen.add(token)
                scale = 180 / math.pi if action.type.degrees and p.unit == "rad" else 1.0
                for bound, closed, sign in ((p.low, p.low_closed, -1), (p.high, p.high_closed, 1)):
                    if not math.isfinite(bound):
                        continue
                    for x in ([] if closed else [bound]) + [bound + sign * 1e-6 * max(1.0, abs(bound))]:
                        value = repr(x * scale)
                        mutated = (*argv[: i + 1], value, *argv[i + 2 :])
                        cases.append(pytest.param(name, mutated, id=f"{name}-{token}={value}"))
    return cases


OUT_OF_RANGE = out_of_range()


@pytest.fixture
def workdir(tmp_path, monkeypatch, make_device):
    """A folder holding the user's things the table must not touch; the commands run in it."""
    (tmp_path / "keep.txt").write_text("the user's file\n")
    (tmp_path / "in.csv").write_text(INPUT_CSV)
    for suffix in {v.suffix for v in VALID.values()} | {".csv"}:
        folder = tmp_path / f"afolder{suffix}"
        folder.mkdir(exist_ok=True)
        (folder / "inside.txt").write_text("inside\n")
        (tmp_path / f"dangling{suffix}").symlink_to(tmp_path / f"target-missing{suffix}")
        make_device(tmp_path / f"device{suffix}")
        (tmp_path / f"device-link{suffix}").symlink_to(f"device{suffix}")
        os.mkfifo(tmp_path / f"fifo{suffix}")
    monkeypatch.chdir(tmp_path)
    return tmp_path


def snapshot(folder: Path) -> dict[str, tuple]:
    """Everything under ``folder``: kind, mode, link target and contents, links not followed."""
    seen = {}
    for root, dirs, files in os.walk(folder):
        for name in dirs + files:
            path = Path(root) / name
            info = path.lstat()
            entry: tuple = (stat.S_IFMT(info.st_mode), stat.S_IMODE(info.st_mode))
            if path.is_symlink():
                entry += (os.readlink(path),)
            elif stat.S_ISREG(info.st_mode):
                entry += (path.read_bytes(),)
            seen[str(path.relative_to(folder))] = entry
    return seen


def run(argv, capsys) -> tuple[int, str]:
    try:
        code = main(list(argv))
    except SystemExit as exc:  # argparse
        code = exc.code
    return code, capsys.readouterr().err


def test_bad_input_every_command_has_valid_arguments():
    missing = sorted(set(PARSERS) - set(VALID))
    assert not missing, f"add the commands {missing} to VALID in {__file__}"
    assert not sorted(set(VALID) - set(PARSERS))


@pytest.mark.parametrize(
    ("name", "k"),
    [
        pytest.param(n, k, id=f"{n}-{k}", marks=[pytest.mark.slow] if n == "demo" else [])
        for n, v in VALID.items()
        for k in range(len(v.argvs))
    ],
)
def test_bad_input_valid_arguments_succeed(name, k, workdir, capsys):
    # The mutations below are only meaningful if the unmutated arguments work.
    valid = VALID[name]
    argv = [a.replace("{out}", f"out{valid.suffix}").replace("{input}", "in.csv") for a in valid.argvs[k]]
    code, err = run(argv, capsys)
    assert code == 0, err
    if "{out}" in valid.argvs[k]:
        assert (workdir / f"out{valid.suffix}").exists()


def _warns(argv: list[str]) -> bool:
    """Whether ``argv`` holds one of the :data:`WARNS` values among its flag's values."""
    for flag, value in WARNS:
        if flag in argv:
            i = argv.index(flag) + 1
            values = argv[i : next((j for j in range(i, len(argv)) if argv[j].startswith("--")), len(argv))]
            if value in values:
                return True
    return False


def test_bad_input_out_of_range_covers_the_physical_options():
    """Every command with a physical parameter has its out-of-range cases (issue 26 item 4)."""
    commands = {case.values[0] for case in OUT_OF_RANGE}
    assert {"obliquity", "precession", "nutation", "cassini", "portrait cassini"} <= commands
    flags = {case.id.split("=")[0] for case in OUT_OF_RANGE}
    assert {"obliquity---tidal-dissipation", "obliquity---precession-rate", "cassini---inclination"} <= flags


@pytest.mark.parametrize(("name", "argv"), OUT_OF_RANGE)
def test_bad_input_out_of_range_one_line_exit_2_nothing_touched(name, argv, workdir, capsys):
    suffix = VALID[name].suffix
    argv = [a.replace("{out}", f"out{suffix}").replace("{input}", "in.csv") for a in argv]
    before = snapshot(workdir)
    code, err = run(argv, capsys)
    assert code == 2, err
    assert len(err.splitlines()) == 1, err
    assert "expected a" in err
    assert snapshot(workdir) == before


@pytest.mark.parametrize(("name", "argv"), MUTATIONS)
def test_bad_input_one_line_exit_2_nothing_touched(name, argv, workdir, capsys):
    suffix = VALID[name].suffix if name in VALID else ""
    argv = [a.replace("{out}", f"out{suffix}").replace("{input}", "in.csv") for a in argv]
    before = snapshot(workdir)
    code, err = run(argv, capsys)
    if code == 0 and _warns(argv):
        # a valid run: its one warning on one line (an --rtol run also reports its step)
        warnings = [line for line in err.splitlines() if "warning: " in line]
        assert len(warnings) == 1, err
        assert "triangle inequality" in warnings[0], err
        assert "Traceback" not in err
        return
    assert code == 2, err
    assert len(err.splitlines()) == 1, err
    assert "Traceback" not in err
    assert err.startswith("andoyer")
    assert snapshot(workdir) == before
