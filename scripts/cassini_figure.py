"""The Cassini-state figures of ``docs/cassini.md``: the geometry and Colombo's top for the Moon and Mercury.

Drawn by :func:`andoyer.plot.cassini_geometry` and :func:`andoyer.plot.cassini_portrait` from the
named bodies of :mod:`andoyer.planetary.cassini` (cited parameters, nothing fitted).

Run: ``python3 scripts/cassini_figure.py --out docs/images`` (writes ``cassini-moon.png`` and
``cassini-mercury.png``).
"""

from __future__ import annotations

from _common import output_folder
from matplotlib.figure import Figure

from andoyer import plot
from andoyer.planetary import cassini


def main(argv: list[str] | None = None) -> None:
    """Save one two-panel figure per body."""
    out = output_folder(__doc__.splitlines()[0], argv)
    for name in ("moon", "mercury"):
        body = cassini.get(name)
        fig = Figure(figsize=(15.0, 5.5), layout="constrained")
        left, right = fig.subplots(1, 2, width_ratios=(1.0, 1.6))
        plot.cassini_geometry(body, ax=left)
        plot.cassini_portrait(body, ax=right)
        path = out / f"cassini-{name}.png"
        fig.savefig(path, dpi=110)
        print(f"wrote {path}")


if __name__ == "__main__":
    main()
