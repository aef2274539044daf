"""The Earth's (and Mars') obliquity and climatic precession along an orbit source (docs/spin-axis.md).

Drawn by :func:`andoyer.plot.obliquity_history` from :func:`andoyer.planetary.spin_axis.spin_axis_history`
with the default precession rates (Earth 50.38481507″/yr, IAU 2006; Mars 7.597″/yr). With
``--orbit vondrak`` only the Earth over ±200 kyr is possible;
with ``--orbit nbody`` or ``secular`` the script also draws Mars, over ``--span``.

Run: ``python3 scripts/spin_axis_figure.py --orbit vondrak --span -200000 200000 --out docs/images``
(writes ``spin-axis.png``), or ``--orbit nbody --span -1000000 0 --step 1000 --name
spin-axis-nbody.png`` for the 1-Myr figure of docs/spin-axis.md.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from andoyer.cli.obliquity_cmd import orbit_source  # noqa: E402
from andoyer.planetary.spin_axis import output_times, spin_axis_history  # noqa: E402
from andoyer.plot import obliquity_history  # noqa: E402


def main(argv: list[str] | None = None) -> None:
    """Integrate the bodies the orbit source knows and save the figure (``--name``, ``spin-axis.png``)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--orbit", default="vondrak", help="vondrak, nbody, secular or a table path")
    parser.add_argument("--span", nargs=2, type=float, default=(-200000.0, 0.0), metavar=("T0", "T1"))
    parser.add_argument("--step", type=float, default=500.0, help="output step, years")
    parser.add_argument("--out", default="reproduced", help="folder for the figure (created)")
    parser.add_argument("--name", default="spin-axis.png", help="file name of the figure")
    args = parser.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    times = output_times(*args.span, args.step)
    histories = []
    for body in ("earth", "mars"):
        try:
            orbit = orbit_source(args.orbit, body)
        except ValueError as exc:
            print(f"skipping {body}: {exc}")
            continue
        histories.append(spin_axis_history(orbit, body, times))
    path = out / args.name
    obliquity_history(histories).savefig(path, dpi=110)
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
