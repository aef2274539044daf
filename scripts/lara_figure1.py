"""Lara (2013), Fig. 1: reduced phase space of the free body and of the main problem of SAM rotation.

Drawn by :func:`andoyer.plot.lara_portrait`: contours in the ``(ν, N/M)`` plane for
``β = 0.8``, ``0.88 ≤ N/M ≤ 1`` and Lara's levels ``q = 0.002 … 0.38`` (given after eq. 8),
the free body (full lines) against the main problem of SAM rotation (dashed).

Run: ``python3 scripts/lara_figure1.py --out reproduced`` (writes ``lara_figure1.png``).
"""

from __future__ import annotations

from _common import output_folder

from andoyer import plot


def main(argv: list[str] | None = None) -> None:
    """Save the figure as ``lara_figure1.png``."""
    out = output_folder(__doc__.splitlines()[0], argv)
    path = out / "lara_figure1.png"
    plot.lara_portrait(beta=0.8).savefig(path, dpi=150, bbox_inches="tight")
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
