"""Gurfil et al., Fig. 4: the (l, L) phase plane, isoenergetic curves of the Andoyer Hamiltonian.

The free-body Hamiltonian in Andoyer variables (Gurfil eq. 89),
``K = ½ (sin²l/I1 + cos²l/I2)(G² − L²) + L²/(2 I3)``, evaluated by
``andoyer.hamiltonians.andoyer_hamiltonian`` on a grid of ``(l, L/G)`` and contoured; the
separatrix ``K = G²/(2 I2)`` (the energy of a spin about the intermediate axis) is drawn
thick. The paper does not state the body; this uses ``I = (1, 2, 3)``.

Run: ``python3 scripts/gurfil_figure4.py --out reproduced`` (writes ``gurfil_figure4.png``).
"""

from __future__ import annotations

import matplotlib as mpl

mpl.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from _common import output_folder

from andoyer import RigidBody
from andoyer.hamiltonians import andoyer_hamiltonian

BODY = RigidBody(1.0, 2.0, 3.0, name="I = (1, 2, 3)")


def figure() -> plt.Figure:
    """Contours of the Andoyer Hamiltonian on ``l ∈ [0, 2π]``, ``L/G ∈ [−1, 1]`` (``G = 1``)."""
    l, x = np.meshgrid(np.linspace(0.0, 2 * np.pi, 401), np.linspace(-1.0, 1.0, 301))
    energy = andoyer_hamiltonian(BODY, l, x, 1.0)
    separatrix = 1.0 / (2 * BODY.I2)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    levels = np.linspace(energy.min(), energy.max(), 24)[1:-1]
    ax.contour(l, x, energy, levels=levels, colors="0.35", linewidths=0.7)
    ax.contour(l, x, energy, levels=[separatrix], colors="C3", linewidths=1.8)
    ax.set(xlabel="l (rad)", ylabel="L / G", title=f"Andoyer phase plane, {BODY.name}; separatrix in red")
    return fig


def main(argv: list[str] | None = None) -> None:
    """Save the figure as ``gurfil_figure4.png``."""
    out = output_folder(__doc__.splitlines()[0], argv)
    path = out / "gurfil_figure4.png"
    figure().savefig(path, dpi=150, bbox_inches="tight")
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
