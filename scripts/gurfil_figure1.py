"""Gurfil et al., Fig. 1: the phase flow of the Euler–Poinsot problem on the momentum sphere.

Drawn by :func:`andoyer.plot.momentum_sphere`: exact energy contours (polhodes) on the sphere
``|m| = G`` with the separatrix through ``±b2``. The paper does not state the body; this uses
``I = (1, 2, 3)``, ``G = 1``.

Run: ``python3 scripts/gurfil_figure1.py --out reproduced`` (writes ``gurfil_figure1.png``).
"""

from __future__ import annotations

from _common import output_folder

from andoyer import RigidBody, plot

BODY = RigidBody(1.0, 2.0, 3.0, name="I = (1, 2, 3)")


def main(argv: list[str] | None = None) -> None:
    """Save the figure as ``gurfil_figure1.png``."""
    out = output_folder(__doc__.splitlines()[0], argv)
    path = out / "gurfil_figure1.png"
    plot.momentum_sphere(BODY, 1.0).savefig(path, dpi=150, bbox_inches="tight")
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
