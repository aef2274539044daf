"""Compare the fundamental frequencies of the secular model with the N-body solution's (and La2004's).

Both orbit sources are sampled every ``--every`` years over ``[−span, 0]``
(``--samples`` samples, a power of two), turned into the invariable frame of the secular model,
and every planet's ``z = e_x + i e_y`` and ``ζ = −n_y + i n_x`` (``≈ e e^{iϖ}`` and
``sin i e^{iΩ}``) analysed by the frequency-modified Fourier transform
(:mod:`andoyer.planetary.orbits.frequencies`). ``g_j`` and ``s_j`` are named by the nearest
strong line to La2004's values. The N-body run (:class:`~andoyer.planetary.orbits.nbody.NBodyOrbit`,
4-day step) is cached on disk: 20 Myr cost about 30 CPU minutes once.

Run from the repository root:
``python3 scripts/secular_frequencies.py [--samples 65536 --every 300] [--json out.json]``;
``--nbody-samples PATH`` reads a stored backward run (an ``.npz`` of the N-body cache's
``t``, ``normal``, ``ecc``) instead of integrating one.
"""

from __future__ import annotations

import argparse
import json

import numpy as np

from andoyer.planetary.orbits import NBodyOrbit, SecularOrbit
from andoyer.planetary.orbits.frequencies import fundamental_frequencies
from andoyer.planetary.orbits.laplace_lagrange import LA2004_G, LA2004_S
from andoyer.planetary.orbits.planets import PLANETS
from andoyer.planetary.orbits.secular import secular_model


def signals(orbit_of, t: np.ndarray, rotation: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``z`` and ``ζ`` of every planet (invariable frame) from an orbit source factory."""
    z = np.empty((len(PLANETS), t.size), complex)
    zeta = np.empty_like(z)
    for j, body in enumerate(PLANETS):
        orbit = orbit_of(body)
        n = orbit.normal(t) @ rotation.T
        e = orbit.eccentricity_vector(t) @ rotation.T
        z[j] = e[:, 0] + 1j * e[:, 1]
        zeta[j] = -n[:, 1] + 1j * n[:, 0]
    return z, zeta


class _Stored:
    """One planet's samples of a stored N-body run, read at the sample times only."""

    def __init__(self, t: np.ndarray, normal: np.ndarray, ecc: np.ndarray) -> None:
        self.t, self._normal, self._ecc = t, normal, ecc

    def _index(self, t: np.ndarray) -> np.ndarray:
        index = np.clip(np.rint(-np.asarray(t) / self.sample).astype(int), 0, self.t.size - 1)
        if not np.allclose(self.t[index], t, atol=1e-3 * self.sample):
            msg = f"expected times on the stored run's {self.sample:g}-yr samples, got others"
            raise ValueError(msg)
        return index

    @property
    def sample(self) -> float:
        return float(abs(self.t[1] - self.t[0]))

    def normal(self, t: np.ndarray) -> np.ndarray:
        return self._normal[self._index(t)]

    def eccentricity_vector(self, t: np.ndarray) -> np.ndarray:
        return self._ecc[self._index(t)]


def stored_samples(path: str):
    """A factory body → orbit over the samples of a stored N-body run (no interpolation)."""
    with np.load(path) as f:
        t, normal, ecc = f["t"], f["normal"], f["ecc"]
    return lambda body: _Stored(t, normal[:, PLANETS.index(body)], ecc[:, PLANETS.index(body)])


def distances() -> None:
    """Largest angle between the normals and difference of the e vectors, secular − nbody, for t ≤ 0."""
    for body in ("earth", "mars"):
        secular, nbody = SecularOrbit(body), NBodyOrbit(body, max_span=5e7, progress=True)
        for span in (2e4, 2e5, 1e6, 4e6):
            t = np.linspace(-span, 0.0, 4001)
            angle = np.arccos(np.clip(np.sum(secular.normal(t) * nbody.normal(t), axis=-1), -1.0, 1.0))
            de = np.abs(secular.eccentricity_vector(t) - nbody.eccentricity_vector(t)).max()
            print(
                f"{body:6s} -{span:9.0f}..0 yr: normal {np.degrees(angle).max():.4f} deg, e vector {de:.2e}"
            )


def main() -> None:
    """Analyse both sources and print the table (″/yr)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, default=65536)
    parser.add_argument("--every", type=float, default=300.0, help="sampling interval, years")
    parser.add_argument("--json", help="write the frequencies to this file")
    parser.add_argument("--no-nbody", action="store_true", help="analyse the secular model only")
    parser.add_argument(
        "--distances", action="store_true", help="also the Earth's and Mars' distances from nbody"
    )
    parser.add_argument(
        "--nbody-samples",
        help=(
            "read the N-body solution from this .npz (arrays t, years from J2000 going back every "
            "100 yr; normal and ecc, shape (len(t), 8, 3)), e.g. a backward run saved by an "
            "earlier cache format, instead of integrating it"
        ),
    )
    args = parser.parse_args()
    if args.distances:
        distances()
    t = -args.every * np.arange(args.samples)[::-1]
    rotation = secular_model().rotation
    results = {}
    sources = {"secular": SecularOrbit}
    if args.nbody_samples:
        sources["nbody"] = stored_samples(args.nbody_samples)
    elif not args.no_nbody:
        span = float(-t[0]) + 1000.0
        sources["nbody"] = lambda body: NBodyOrbit(body, max_span=max(span, 5e7), progress=True)
    for name, factory in sources.items():
        z, zeta = signals(factory, t, rotation)
        g, s = fundamental_frequencies(z, zeta, args.every, LA2004_G, LA2004_S)
        results[name] = {"g": g.tolist(), "s": s.tolist()}
    results["la2004"] = {"g": LA2004_G.tolist(), "s": LA2004_S.tolist()}
    print(f"span {-t[0] / 1e6:.2f} Myr, {args.samples} samples every {args.every:g} yr")
    for key in ("g", "s"):
        for j in range(len(PLANETS)):
            row = [f"{key}{j + 1}"] + [f"{results[name][key][j]:10.4f}" for name in results]
            if "nbody" in results:
                row.append(f"{results['secular'][key][j] - results['nbody'][key][j]:+9.4f}")
            print(" ".join(row))
    print("columns:", ", ".join(results), "and secular - nbody" if "nbody" in results else "")
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump(results, f, indent=1)


if __name__ == "__main__":
    main()
