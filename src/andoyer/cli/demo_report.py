"""The ``andoyer demo`` report: a folder with a Markdown summary and its pictures.

Each section is a function ``(context) -> str`` returning Markdown; sections that draw write
their pictures (plain files, no sub-folders) into the report folder and link them. The report
is assembled in a temporary folder and moved into place at the end, so an interrupted demo
never leaves a half-written report; it writes only into a new or empty folder, a previous
report (marked by a :data:`MARKER` file) or, when forced, beside what a folder holds, and
deletes nothing of the user's (see :func:`write_report`).
"""

from __future__ import annotations

import os
import shutil
import stat
import tempfile
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from andoyer import bodies
from andoyer._files import new_dir_mode
from andoyer.body import RigidBody
from andoyer.catalogue.units import DAY
from andoyer.cli.chart_table import CHARTS
from andoyer.cli.output import CliError, atomic_output, output_target
from andoyer.free_rotation import FreeRotation
from andoyer.regime import Regime
from andoyer.state import State

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from andoyer.planetary.precession import PrecessionRates

#: Illustrative inclination of the angular momentum on the reference axis (radians).
DEMO_INCLINATION = 0.4

#: Angles of the angular momentum off the figure axis for the SAM-series section (radians).
SAM_NUTATIONS = (0.05, 0.1, 0.2)

#: Deprit orders shown in the SAM-series section.
SAM_ORDERS = (1, 2, 4, 6)

#: Years of full splitting integration behind the demo's precession rate.
PRECESSION_YEARS = 2.0

#: Years of the demo's precession and obliquity time series: two lunar nodal periods (2 × 18.61 yr),
#: so that the fit separates the 18.6-year nutation from the trend.
PRECESSION_SERIES_YEARS = 37.2

#: Samples of that series (every 13.6 days).
PRECESSION_SERIES_POINTS = 1001


@dataclass
class DemoContext:
    """What every section sees: the body, its demo state and the report folder."""

    name: str
    folder: Path
    entry: bodies.BodyInfo = field(init=False)
    body: RigidBody = field(init=False)
    state: State = field(init=False)

    def __post_init__(self) -> None:
        self.entry = bodies.info(self.name)
        self.body = self.entry.body
        self.state = demo_state(self.name)


def demo_state(name: str, nutation: float | None = None) -> State:
    """One spin per sidereal period, the momentum ``nutation`` (default ``J0``) off the figure axis.

    Examples
    --------
    >>> state = demo_state("earth")
    >>> round(float(state.as_andoyer().G / bodies.get("earth").C * 86164.0905 / (2 * np.pi)), 6)
    1.0
    """
    entry = bodies.info(name)
    J = entry.J0 if nutation is None else nutation
    G = entry.body.C * 2 * np.pi / entry.rotation_period
    return State.from_andoyer(0.3, 1.0, 0.5, G * np.cos(J), G, G * np.cos(DEMO_INCLINATION))


def _table(header: list[str], rows: list[list[str]]) -> str:
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return "\n".join(lines) + "\n"


def section_body(ctx: DemoContext) -> str:
    """The body, its parameters and the demo state in every chart."""
    body, entry, state = ctx.body, ctx.entry, ctx.state
    text = [
        f"## {body.name}: the body and its state in every chart\n",
        f"Moments `{body!r}` ({entry.source}).",
        (
            f"α = {body.alpha:.10g}, β = {body.beta:.10g}, κ = {body.kappa:.10g}, "
            f"symmetry: {body.symmetry.value}.\n"
        ),
        (
            f"State: one spin per {entry.rotation_period:.10g} s, angular momentum {entry.J0:.3g} rad "
            f"from the figure axis, inclination I = {DEMO_INCLINATION} rad on the reference axis; "
            f"regime {Regime(int(body.regime(state.m_body))).name}, "
            f"energy T = {float(state.energy(body)):.17g}.\n"
        ),
    ]
    for name, chart in CHARTS.items():
        values = [f"{float(v):.15g}" for v in chart.from_state(state, body)]
        text += [f"### {name}\n", _table(list(chart.columns), [values])]
    return "\n".join(text)


def section_exact(ctx: DemoContext) -> str:
    """The closed-form torque-free motion: regime, period, conservation after 100 periods."""
    body, state = ctx.body, ctx.state
    free = FreeRotation(body)
    period = float(free.periods(state).period)
    later = free.propagate(state, 100 * period)
    drift = float(np.abs(later.m_body - state.m_body).max() / np.abs(state.m_body).max())
    energy = abs(float(later.energy(body) / state.energy(body)) - 1)
    momentum = float(np.abs(later.m_reference - state.m_reference).max() / np.abs(state.m_reference).max())
    return "\n".join(
        [
            "## Exact torque-free propagation\n",
            (
                f"Regime {free.regime(state)}; the body momentum returns after {period:.10g} s "
                f"= {period / ctx.entry.rotation_period:.6g} rotation periods (the free wobble).\n"
            ),
            _table(
                ["after 100 periods", "value"],
                [
                    ["‖m − m₀‖ / ‖m₀‖ (body)", f"{drift:.2e}"],
                    ["relative energy change", f"{energy:.2e}"],
                    ["‖M − M₀‖ / ‖M₀‖ (reference)", f"{momentum:.2e}"],
                ],
            ),
        ]
    )


def section_sam(ctx: DemoContext) -> str:
    """Lara's SAM series against the exact solution, over one period of the momentum."""
    from andoyer.theories import SAMRotation

    body = ctx.body
    free = FreeRotation(body)
    mode = "LAM" if body.regime(ctx.state.m_body) == Regime.LAM else "SAM"
    theories = [SAMRotation(body, order=order, mode=mode) for order in SAM_ORDERS]
    rows = []
    for nutation in SAM_NUTATIONS:
        state = demo_state(ctx.name, nutation)
        t = float(free.periods(state).period)
        exact = free.propagate(state, t)
        row = [f"{nutation:g}"]
        for theory in theories:
            series = theory.propagate(state, t)
            err = np.linalg.norm(series.m_body - exact.m_body) / np.linalg.norm(exact.m_body)
            row.append(f"{float(err):.1e}")
        rows.append(row)
    return "\n".join(
        [
            f"## Lara's {mode} series against the exact solution\n",
            (
                "Relative error of the body angular momentum after one period of the exact motion, "
                "for states whose momentum is J rad off the figure axis; the error falls as "
                "δ^(N+1) with δ ≈ 2 sin²(J/2) / √(1 − β²).\n"
            ),
            _table(["J (rad)", *[f"N = {n}" for n in SAM_ORDERS]], rows),
        ]
    )


def section_pictures(ctx: DemoContext) -> str:
    """The phase portraits: (l, L) with its separatrix, the momentum sphere, Lara's Fig. 1, Poinsot."""
    from andoyer import plot

    body, state = ctx.body, ctx.state
    G = float(state.as_andoyer().G)
    figures = {
        "phase-portrait.png": (
            plot.phase_portrait(body, G, momentum_unit="$C$ rad/s"),  # moments in units of C
            "The (l, L) phase portrait with the separatrix through the saddles (Gurfil Fig. 4).",
        ),
        "momentum-sphere.png": (
            plot.momentum_sphere(body, G),
            "Energy contours on the angular-momentum sphere |m| = G (Gurfil Fig. 1).",
        ),
        "lara-figure-1.png": (
            plot.lara_portrait(),
            (
                "The reduced phase space of the free body against the main problem of SAM rotation, "
                "β = 0.8 (Lara Fig. 1)."
            ),
        ),
        "poinsot.png": (
            plot.poinsot(body, demo_state(ctx.name, SAM_NUTATIONS[-1])),
            "Polhode and herpolhode of the body spinning 0.2 rad off its figure axis.",
        ),
    }
    text = ["## Phase portraits\n"]
    for name, (figure, caption) in figures.items():
        figure.savefig(ctx.folder / name, dpi=110)
        text.append(f"![{caption}]({name})\n\n{caption}\n")
    return "\n".join(text)


def precession_figure() -> tuple[Figure, PrecessionRates]:
    """The Earth's precession rates and the picture of one state's node over the series years.

    The picture's trend is fitted with the nutation frequencies of the perturbers (harmonics
    ``k n_p``, ``k = 1, 2, 3``, of their mean motions and ``k Ω̇_p``, ``k = 1, 2``, of their node
    rates, Moon's 18.6 years), so that its rate ``p = −⟨ḣ⟩`` is the mean rate of the table.
    """
    from andoyer import plot
    from andoyer.integrate.propagation import propagate
    from andoyer.perturbations.solar_system import JULIAN_YEAR, mean_perturbers
    from andoyer.planetary.precession import default_step, precession_problem, precession_rates

    rates = precession_rates("earth", integrate=PRECESSION_YEARS)
    model, states = precession_problem("earth")
    times = np.linspace(0.0, PRECESSION_SERIES_YEARS * JULIAN_YEAR, PRECESSION_SERIES_POINTS)
    series = propagate(model, states[0], times, method="splitting", step=default_step("earth"), order=2)
    frequencies = [
        k * rate * JULIAN_YEAR  # radians per year
        for p in mean_perturbers("earth")
        for rate, harmonics in ((p.orbit.mean_motion, (1, 2, 3)), (p.orbit.node_rate, (1, 2)))
        if rate
        for k in harmonics
    ]
    figure = plot.precession(
        times / JULIAN_YEAR,
        series,
        "momentum",
        frequencies=frequencies,
        regression=True,
        degrees=True,
        time_unit="yr",
    )
    return figure, rates


def section_precession(ctx: DemoContext) -> str:
    """Earth's luni-solar precession: secular model, full splitting integration, time series."""
    from andoyer.planetary.precession import ARCSEC

    figure, rates = precession_figure()
    figure.savefig(ctx.folder / "earth-precession.png", dpi=110)
    return "\n".join(
        [
            "## Earth's precession\n",
            (
                f"A rigid Earth (Lara Table 1 moments, one spin per sidereal day, obliquity "
                f"{np.degrees(rates.obliquity):.2f}°) torqued by the Sun and the Moon on their mean orbits "
                "(observed luni-solar precession 50.38″/yr). The precession rate is p = −⟨ḣ⟩, "
                "positive for the regressing node h of the angular momentum on the ecliptic:\n"
            ),
            _table(
                ["model", "precession rate p = −⟨ḣ⟩ (″/yr)"],
                [
                    ["secular (averaged) model", f"{rates.secular:.4f}"],
                    [
                        f"splitting integration, {rates.years:.3g} yr, step {rates.step / DAY:.3g} d",
                        f"{rates.integrated:.4f}",
                    ],
                ],
            ),
            "![Precession and obliquity of the angular momentum](earth-precession.png)\n",
            (
                f"Node h and obliquity I of the angular momentum over {PRECESSION_SERIES_YEARS} years (two "
                "lunar nodal periods) from the splitting integration of one of those states: the "
                "18.6-year lunar nutation rides on the steady precession. The trend is fitted together "
                "with the nutation frequencies (the Moon's node, the orbital harmonics of the Sun and "
                f"the Moon): p = {-figure.andoyer_data.precession_rate / ARCSEC:.4f}″/yr.\n"
            ),
        ]
    )


SECTIONS: tuple[Callable[[DemoContext], str], ...] = (
    section_body,
    section_exact,
    section_sam,
    section_precession,
    section_pictures,
)


#: The file that marks a folder as an andoyer demo report (its first line is :data:`MARKER_HEADER`).
MARKER = ".andoyer-demo"
MARKER_HEADER = "andoyer demo report"
#: Version of the marker's format (its second line, ``format 1``).
MARKER_FORMAT = 1


def is_demo_report(folder: str | Path) -> bool:
    r"""Whether ``folder`` holds a report of ``andoyer demo`` (its marker file says so).

    Examples
    --------
    >>> import tempfile
    >>> folder = Path(tempfile.mkdtemp())
    >>> is_demo_report(folder)
    False
    >>> _ = (folder / MARKER).write_text(f"{MARKER_HEADER}\nformat 1\n", encoding="utf-8")
    >>> is_demo_report(folder)
    True
    """
    marker = Path(folder) / MARKER
    try:
        if not marker.is_file() or marker.is_symlink():
            return False
        with marker.open(encoding="utf-8", errors="replace") as stream:
            return stream.readline().rstrip("\n") == MARKER_HEADER
    except OSError:
        return False


def write_report(name: str, folder: str | Path, progress: bool | None = None, force: bool = False) -> str:
    """Run every section for body ``name`` and write ``folder/README.md`` (plus pictures).

    Returns the Markdown summary. The folder is resolved (``.``, ``..`` and links), then:

    - missing: the report is built in a temporary sibling renamed into place at the end, so an
      interrupted demo leaves nothing behind;
    - empty, or holding a previous report (see :func:`is_demo_report`), or anything else with
      ``force=True``: the report is built in a temporary folder inside it, and each of its files
      then replaces the file of that name (atomically, through links); nothing else in the
      folder is touched and nothing is ever deleted but the temporary folder;
    - otherwise (a non-empty folder that is not a report, a file, a device): :class:`CliError`
      naming ``--force``, before any work is done.

    Each report holds a marker file :data:`MARKER` (first line :data:`MARKER_HEADER`, then its
    format version, the andoyer version, the body and the report's files). New folders and
    files get the modes the umask gives.
    """
    from tqdm import tqdm

    target, fresh = _report_folder(folder, force)
    staging = _staging_folder(target.parent if fresh else target, target.name, folder)
    try:
        ctx = DemoContext(name, staging)
        parts = [f"# andoyer demo: {ctx.body.name}\n"]
        disable = None if progress is None else not progress  # None: a bar only on a terminal
        parts.extend(
            section(ctx) for section in tqdm(SECTIONS, desc="andoyer demo", unit="section", disable=disable)
        )
        summary = "\n".join(parts)
        (staging / "README.md").write_text(summary, encoding="utf-8")
        _write_marker(staging, ctx.name)
        if fresh:
            _rename_into_place(staging, target, folder)
        else:
            _copy_into(staging, target)
    finally:
        shutil.rmtree(staging, ignore_errors=True)  # ours; gone already once renamed into place
    return summary


def _report_folder(folder: str | Path, force: bool) -> tuple[Path, bool]:
    """The resolved report folder and whether it is new; :class:`CliError` where writing is refused."""
    given = os.fspath(folder)
    target = Path(os.path.realpath(given))  # ".", ".." and links name a real folder
    try:
        mode = os.stat(target).st_mode
    except FileNotFoundError:
        mode = None
    except OSError as exc:
        msg = f"expected a usable folder for the report, got {given!r} ({exc.strerror})"
        raise CliError(msg) from exc
    if mode is None:
        if os.path.islink(given):
            msg = f"expected a folder for the report, got the dangling symbolic link {given!r}"
            raise CliError(msg)
        if not target.parent.is_dir():
            msg = f"expected an existing parent directory for the report, got {str(target.parent)!r}"
            raise CliError(msg)
        return target, True
    if not stat.S_ISDIR(mode):
        msg = f"expected a directory for the report, got {given!r}, which is not one"
        raise CliError(msg)
    try:
        empty = not os.listdir(target)
    except OSError as exc:
        msg = f"expected a readable folder for the report, got {given!r} ({exc.strerror})"
        raise CliError(msg) from exc
    if not (empty or force or is_demo_report(target)):
        msg = (
            f"expected a new or empty folder or a previous demo report for the report, got {given!r} "
            "(not empty; --force writes the report's files into it, replacing only those)"
        )
        raise CliError(msg)
    return target, False


def _staging_folder(parent: Path, name: str, given: str | Path) -> Path:
    try:
        staging = Path(tempfile.mkdtemp(prefix=f".{name}.", suffix=".part", dir=parent))
    except OSError as exc:
        msg = f"expected a writable place for the report, got {os.fspath(given)!r} ({exc.strerror})"
        raise CliError(msg) from exc
    os.chmod(staging, new_dir_mode())  # mkdtemp makes it 0700 whatever the umask
    return staging


def _write_marker(staging: Path, name: str) -> None:
    from andoyer import __version__

    files = sorted(p.name for p in staging.iterdir())
    lines = [MARKER_HEADER, f"format {MARKER_FORMAT}", f"andoyer {__version__}", f"body {name}"]
    lines.append("files " + " ".join([*files, MARKER]))
    (staging / MARKER).write_text("\n".join(lines) + "\n", encoding="utf-8")


def _rename_into_place(staging: Path, target: Path, given: str | Path) -> None:
    try:
        # Replaces at most an empty folder made meanwhile; a non-empty one makes it fail.
        staging.rename(target)
    except OSError as exc:
        msg = f"expected the report folder {str(given)!r} to stay free while writing, got {exc.strerror}"
        raise CliError(msg) from exc


def _copy_into(staging: Path, target: Path) -> None:
    # The marker last: until then a previous report's marker still stands for the folder.
    files = sorted(staging.iterdir(), key=lambda p: (p.name == MARKER, p.name))
    for path in files:  # every destination checked before the first is replaced
        output_target(target / path.name)
    for path in files:
        with atomic_output(target / path.name, binary=True) as stream:
            stream.write(path.read_bytes())
