"""Lara (2013), Fig. 1: reduced phase space of the free body and of the main problem of SAM rotation.

Contours ``H₀* = A* = q`` in the ``(ν, N/M)`` plane for ``β = 0.8``, ``0.88 ≤ N/M ≤ 1`` and
Lara's levels ``q = 0.002 … 0.38``, where (Lara eqs. 4 and 8, scaled by α)
``H₀* = (2C H₀/M² − 1)/α = sin²J (1 − β cos 2ν)`` (full lines; ``H₀`` from
``andoyer.hamiltonians.andoyer_hamiltonian``) and ``A* = 4 sin²(J/2)(1 − β cos 2ν)`` (dashed),
``cos J = N/M``. The scaled contours do not depend on α; the body has α = 0.1.

Run: ``python3 scripts/lara_figure1.py --out reproduced`` (writes ``lara_figure1.png``).
"""

from __future__ import annotations

import matplotlib as mpl

mpl.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from _common import output_folder

from andoyer import RigidBody
from andoyer.hamiltonians import andoyer_hamiltonian

ALPHA, BETA = 0.1, 0.8
LEVELS = (0.002, 0.007, 0.015, 0.023, 0.035, 0.048, 0.08, 0.12, 0.18, 0.25, 0.32, 0.38)


def body() -> RigidBody:
    """A body with Andoyer's (α, β) = (0.1, 0.8): ``C/A = 1 + α(1 + β)``, ``C/B = 1 + α(1 − β)``."""
    return RigidBody(1 / (1 + ALPHA * (1 + BETA)), 1 / (1 + ALPHA * (1 - BETA)), 1.0)


def figure() -> plt.Figure:
    """Both families of contours on ``ν ∈ [0, π]``, ``N/M ∈ [0.88, 1]``."""
    b = body()
    nu, x = np.meshgrid(np.linspace(0.0, np.pi, 361), np.linspace(0.88, 1.0, 241))
    free = (2 * b.C * andoyer_hamiltonian(b, nu, x, 1.0) - 1) / b.alpha
    main_problem = 2 * (1 - x) * (1 - BETA * np.cos(2 * nu))
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.contour(nu, x, free, levels=LEVELS, colors="k", linewidths=0.9)
    ax.contour(nu, x, main_problem, levels=LEVELS, colors="k", linewidths=0.9, linestyles="dashed")
    ax.set(xlabel="ν (rad)", ylabel="N / M", title="β = 0.8: free body (full), main problem (dashed)")
    return fig


def main(argv: list[str] | None = None) -> None:
    """Save the figure as ``lara_figure1.png``."""
    out = output_folder(__doc__.splitlines()[0], argv)
    path = out / "lara_figure1.png"
    figure().savefig(path, dpi=150, bbox_inches="tight")
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
