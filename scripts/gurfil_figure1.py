"""Gurfil et al., Fig. 1: the phase flow of the Euler–Poinsot problem on the momentum sphere.

Polhodes (paths of the body angular momentum on the sphere ``|m| = G``) computed with the exact
free solution (``andoyer.FreeRotation.momentum``) over one period each: short-axis-mode orbits
about ``±b3`` (maximum inertia) started on the ``b2–b3`` meridian, long-axis-mode orbits about
``±b1`` started on the equator. The separatrix — two great circles through ``±b2`` on the
planes ``m3 = ±m1 √((1/I1 − 1/I2)/(1/I2 − 1/I3))`` — is drawn in red. The paper does not
state the body; this uses ``I = (1, 2, 3)``.

Run: ``python3 scripts/gurfil_figure1.py --out reproduced`` (writes ``gurfil_figure1.png``).
"""

from __future__ import annotations

import matplotlib as mpl

mpl.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from _common import output_folder

from andoyer import FreeRotation, RigidBody, State

BODY = RigidBody(1.0, 2.0, 3.0)


def polhodes(n_per_family: int = 6, samples: int = 200) -> list[np.ndarray]:
    """Paths ``m(t)`` over one period, shape ``(samples, 3)`` each, ``G = 1``."""
    free = FreeRotation(BODY)
    a = np.linspace(0.15, 1.35, n_per_family)
    starts = [np.stack([0 * a, np.sin(a), np.cos(a)], -1), np.stack([np.cos(a), np.sin(a), 0 * a], -1)]
    paths = []
    for m0 in np.concatenate([*starts, *(-s for s in starts)]):
        state = State.from_quaternion([0.0, 0.0, 0.0, 1.0], m0)
        period = float(free.periods(state).period)
        paths.append(free.momentum(state, np.linspace(0.0, period, samples)))
    return paths


def separatrix(samples: int = 400) -> list[np.ndarray]:
    """The two great circles of the separatrix, shape ``(samples, 3)`` each."""
    w1, w2, w3 = 1 / BODY.I1, 1 / BODY.I2, 1 / BODY.I3
    slope = np.sqrt((w1 - w2) / (w2 - w3))
    t = np.linspace(0.0, 2 * np.pi, samples)
    circles = []
    for sign in (1.0, -1.0):
        u = np.array([1.0, 0.0, sign * slope]) / np.hypot(1.0, slope)  # unit vector in the plane, ⟂ b2
        circles.append(np.outer(np.cos(t), u) + np.outer(np.sin(t), [0.0, 1.0, 0.0]))
    return circles


def figure() -> plt.Figure:
    """The momentum sphere with polhodes and the separatrix."""
    fig = plt.figure(figsize=(6, 6))
    ax = fig.add_subplot(projection="3d")
    for path in polhodes():
        ax.plot(*path.T, color="0.3", linewidth=0.8)
    for circle in separatrix():
        ax.plot(*circle.T, color="C3", linewidth=1.6)
    ax.set(xlabel="m1 / G", ylabel="m2 / G", zlabel="m3 / G", title="Euler–Poinsot flow, I = (1, 2, 3)")
    ax.set_box_aspect((1, 1, 1))
    return fig


def main(argv: list[str] | None = None) -> None:
    """Save the figure as ``gurfil_figure1.png``."""
    out = output_folder(__doc__.splitlines()[0], argv)
    path = out / "gurfil_figure1.png"
    figure().savefig(path, dpi=150, bbox_inches="tight")
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
