"""Gurfil et al., Fig. 4: the (l, L) phase plane, isoenergetic curves of the Andoyer Hamiltonian.

Drawn by :func:`andoyer.plot.phase_portrait`: exact level curves of the Andoyer Hamiltonian
(Gurfil eq. 89) with the separatrix ``K = G²/(2 I2)`` through the saddles. The paper does not
state the body; this uses ``I = (1, 2, 3)``, ``G = 1``.

Run: ``python3 scripts/gurfil_figure4.py --out reproduced`` (writes ``gurfil_figure4.png``).
"""

from __future__ import annotations

from _common import output_folder

from andoyer import RigidBody, plot

BODY = RigidBody(1.0, 2.0, 3.0, name="I = (1, 2, 3)")


def main(argv: list[str] | None = None) -> None:
    """Save the figure as ``gurfil_figure4.png``."""
    out = output_folder(__doc__.splitlines()[0], argv)
    path = out / "gurfil_figure4.png"
    plot.phase_portrait(BODY, 1.0).savefig(path, dpi=150, bbox_inches="tight")
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
