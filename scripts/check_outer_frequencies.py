"""Measure the giant planets' secular frequencies from the shipped J2000 data (a review check).

Integrates the Sun (carrying the inner planets' GM) and Jupiter, Saturn, Uranus and Neptune with
REBOUND's WHFast (step 0.5 yr, Newtonian) for ``--samples`` × ``--every`` years, and prints the four
strongest lines (″/yr, amplitude) of each planet's ``z = e exp(iϖ)`` and ``ζ = sin i exp(iΩ)`` by the
frequency-modified Fourier transform (Šidlichovský & Nesvorný 1996; ``rebound.frequency_analysis``).

Two starts: ``--start helio`` uses the shipped heliocentric states (what ``andoyer.planetary.orbits.nbody``
integrates: DE421's states at J2000 since 2026-11-25, before that the Keplerian conversion of
Standish's mean elements); ``--start jacobi`` reads Standish's elements as Jacobi elements instead.
Measured (32768 samples every 250 yr, 8.2 Myr, about 40 s):

============  ==========  ==========  ==========  ==========  ==========  ===========  ===========
start         g5          g6          g7          g8          s6          s7           s8
============  ==========  ==========  ==========  ==========  ==========  ===========  ===========
helio, DE421  4.2454      28.2583     3.0880      0.6727      −26.3384    −2.9941      −0.6924
helio, old    4.2588      26.0545     3.1314      0.6755      −26.9336    −2.9964      −0.6919
jacobi        4.2614      29.3539     3.1002      0.6729      −26.3245    −2.9962      −0.6923
La2004        4.257452    28.2450     3.087951    0.673021    −26.347855  −2.9925259   −0.691736
============  ==========  ==========  ==========  ==========  ==========  ===========  ===========

``g6`` and ``s6`` hang on the distance of Jupiter and Saturn from their 5:2 near-resonance: from the
old heliocentric start (Standish's mean elements taken as osculating) Saturn's mean motion was
44320″/yr (Standish's rate: 44010″/yr) and the great inequality's period 431 yr; from the Jacobi
start 43983″/yr and 988 yr. From DE421's states every frequency is within 0.02″/yr of La2004 (the
rest is the inner planets lumped into the Sun here and La2004's own model).

Run from the repository root: ``python3 scripts/check_outer_frequencies.py [--start jacobi]``.
"""

from __future__ import annotations

import argparse

import numpy as np

from andoyer.planetary.orbits.planets import planet_data

GIANTS = ("jupiter", "saturn", "uranus", "neptune")
ARCSEC_PER_RAD = 180.0 * 3600.0 / np.pi


def build(start: str):  # -> rebound.Simulation (rebound is imported lazily)
    """The Sun (with the inner planets' GM) and the four giant planets at J2000, G = 1 (au, yr)."""
    import json
    from importlib import resources

    import rebound

    data_file = resources.files("andoyer.planetary.orbits").joinpath("data/planets_j2000.json")
    text = data_file.read_text(encoding="utf-8")
    raw = json.loads(text)
    data = planet_data()
    sim = rebound.Simulation()
    sim.G = 1.0
    inner = sum(raw["planets"][p]["gm"] for p in ("mercury", "venus", "earth", "mars"))
    sim.add(m=data.sun_gm + inner)
    for name in GIANTS:
        planet = raw["planets"][name]
        if start == "helio":
            (x, y, z), (vx, vy, vz) = planet["position"], planet["velocity"]
            sim.add(m=planet["gm"], x=x, y=y, z=z, vx=vx, vy=vy, vz=vz)
        else:  # REBOUND's default for orbital elements: Jacobi coordinates
            el = planet["elements"]
            sim.add(m=planet["gm"], a=el["a"], e=el["e"], inc=np.radians(el["inclination_deg"]),
                    Omega=np.radians(el["node_deg"]), pomega=np.radians(el["varpi_deg"]),
                    l=np.radians(el["mean_longitude_deg"]))
    sim.move_to_com()
    sim.integrator = "whfast"
    sim.dt = 0.5
    return sim


def lines(signal: np.ndarray, every: float, count: int = 4) -> list[tuple[float, float]]:
    """The ``count`` strongest lines of a complex signal sampled every ``every`` years (″/yr, amplitude)."""
    import rebound

    data = np.empty(2 * signal.size)
    data[0::2], data[1::2] = signal.real, signal.imag
    limit = 60.0 / ARCSEC_PER_RAD * every  # ±60″/yr in radians per sample
    nu, amplitude, _ = rebound.frequency_analysis(
        data, type="fmft", nfreq=count, minfreq=-limit, maxfreq=limit
    )
    return [
        (round(float(f) / every * ARCSEC_PER_RAD, 4), round(float(a), 5))
        for f, a in zip(nu, amplitude, strict=True)
    ]


def main() -> None:
    """Integrate, analyse and print the lines of every giant planet."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--start", choices=("helio", "jacobi"), default="helio")
    parser.add_argument("--samples", type=int, default=32768, help="number of samples (a power of two)")
    parser.add_argument("--every", type=float, default=250.0, help="sampling interval (years)")
    args = parser.parse_args()
    sim = build(args.start)
    z = np.zeros((len(GIANTS), args.samples), complex)
    zeta = np.zeros_like(z)
    for k in range(args.samples):
        sim.integrate(k * args.every, exact_finish_time=0)
        for j in range(len(GIANTS)):
            orbit = sim.particles[j + 1].orbit(primary=sim.particles[0])
            z[j, k] = orbit.e * np.exp(1j * orbit.pomega)
            zeta[j, k] = np.sin(orbit.inc) * np.exp(1j * orbit.Omega)
    for j, name in enumerate(GIANTS):
        print(f"{name:8s} z:    {lines(z[j], args.every)}")
        print(f"{name:8s} zeta: {lines(zeta[j], args.every)}")


if __name__ == "__main__":
    main()
