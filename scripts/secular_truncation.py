"""How much of each pair's averaged interaction the degree-4 expansion leaves out, at J2000.

For a pair of planets at their mean elements of J2000 (``data/secular_model.json``), the
directly averaged ``−G m_j m_k ⟨1/|r_j − r_k|⟩`` (a double trapezoid on exact Kepler orbits,
256 × 256 mean longitudes) minus the expansion's terms of degree 0, 2 and 4
(:func:`andoyer.planetary.orbits.disturbing.pair_expansion`): the remainder, of degree ≥ 6,
against the quadratic and the quartic parts. Measured (2026-11-28):

=================  ================  ================
pair               remainder/deg 2   remainder/deg 4
=================  ================  ================
Mercury–Venus      −2.9e-3           0.091
Mercury–Earth      −6.4e-4           0.019
Venus–Earth        2.1e-4            −0.017
Earth–Mars         4.5e-4            0.016
Mars–Jupiter       −2.9e-6           0.004
Jupiter–Saturn     3.3e-5            0.006
Saturn–Uranus      −4.4e-5           0.026
Uranus–Neptune     −1.3e-6           −0.001
=================  ================  ================

Run from the repository root: ``python3 scripts/secular_truncation.py``.
"""

from __future__ import annotations

import numpy as np

from andoyer.planetary.orbits.disturbing import pair_expansion
from andoyer.planetary.orbits.elements import elements_to_state
from andoyer.planetary.orbits.jets import JetSpace
from andoyer.planetary.orbits.planets import PLANETS
from andoyer.planetary.orbits.secular import secular_model

PAIRS = ((0, 1), (0, 2), (1, 2), (2, 3), (3, 4), (4, 5), (5, 6), (6, 7))


def main() -> None:
    """Print each pair's remainder."""
    model = secular_model()
    w = model.w0
    space = JetSpace(8, 4)
    lam = 2.0 * np.pi * np.arange(256) / 256

    def elements(j: int) -> tuple[float, float, float, float]:
        x, y, L = w[j], w[8 + j], model.Lambda[j]
        root = 1.0 - abs(x) ** 2 / (2.0 * L)
        e = np.sqrt(1.0 - root**2)
        return e, np.arccos(1.0 - abs(y) ** 2 / (2.0 * L * root)), np.angle(x), np.angle(y)

    for j, k in PAIRS:
        (ej, ij, wj, Oj), (ek, ik, wk, Ok) = elements(j), elements(k)
        rj, _ = elements_to_state(model.sun + model.gm[j], model.a[j], ej, ij, Oj, wj, lam)
        rk, _ = elements_to_state(model.sun + model.gm[k], model.a[k], ek, ik, Ok, wk, lam)
        distance = np.linalg.norm(rj[:, None] - rk[None], axis=-1)
        exact = -model.gm[j] * model.gm[k] * np.mean(1.0 / distance)
        expansion = pair_expansion(model.sun, (model.gm[j], model.gm[k]), (model.a[j], model.a[k]), 4)
        u = [w[i] / np.sqrt(model.Lambda[i]) for i in (j, 8 + j, k, 8 + k)]
        point = np.array([u[0], np.conj(u[0]), u[1], np.conj(u[1]), u[2], np.conj(u[2]), u[3], np.conj(u[3])])
        terms = expansion.mean * np.prod(point[None, :] ** space.exponents, axis=1)
        parts = {d: terms[space.degrees == d].sum().real for d in (0, 2, 4)}
        rest = exact - sum(parts.values())
        print(
            f"{PLANETS[j]:8s} {PLANETS[k]:8s} remainder/deg 2 {rest / parts[2]:+.1e}, "
            f"remainder/deg 4 {rest / parts[4]:+.3f}"
        )


if __name__ == "__main__":
    main()
