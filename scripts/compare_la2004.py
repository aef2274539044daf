r"""Measure andoyer's spin-axis histories against La2004 and VCW 2011 (docs/spin-axis.md, issue 14).

The La2004 solutions (Laskar et al. 2004, A&A 428, 261 for the Earth; Laskar et al. 2004,
Icarus 170, 343 for Mars) are *not* shipped: pass the paths of the IMCCE files, as
distributed at https://vo.imcce.fr/insola/earth/online/ (``INSOLN.LA2004.BTL.ASC`` or its
``.100.ASC`` variant, ``INSOLP.LA2004.BTL.ASC``; ``INSOLN.LA2004.MARS.ASC``,
``INSOLP.LA2004.MARS.ASC``). Their rows are ``t`` (kyr from J2000), ``e``, the obliquity
(rad) and ``ϖ`` (rad, heliocentric, from the moving equinox); Fortran ``D`` exponents and
``%`` comment lines are read.

For each file given, the script integrates the body's axis along the ``nbody`` orbit (with
the settings given; ``--orbit secular`` for the secular model; for the Earth ``--earth-td``
or ``--earth-tides MODEL``) on the file's 1-kyr grid within
``--span`` and prints the largest differences in obliquity, ``e`` and ``e sin ϖ`` over
|t| ≤ 20 kyr, 250 kyr, 1 Myr and the span, the values at J2000, the Mars obliquity range, and
(``--fit-rate``) the precession rate that best fits La2004's obliquity over 250 kyr.
``--vondrak`` adds the Earth's obliquity against the ``vondrak`` source and the VCW 2011
equator (``erfa.ltpequ``/``ltpecl``) over ±200 kyr;
``--secular`` the ``secular`` source against ``nbody``; ``--reference-cache DIR`` a second
``nbody`` run (its cache folder, e.g. one without GR or with half the step) against this one.

Run (the N-body integration costs about 84 CPU s per Myr and direction, cached under
``$ANDOYER_CACHE_DIR``)::

    python3 scripts/compare_la2004.py --earth INSOLN.LA2004.BTL.100.ASC INSOLP.LA2004.BTL.ASC \\
        --mars INSOLN.LA2004.MARS.ASC INSOLP.LA2004.MARS.ASC --span -1000000 1000000 \\
        --vondrak --secular --fit-rate
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from andoyer.planetary.orbits import NBodyOrbit, SecularOrbit, VondrakEcliptic  # noqa: E402
from andoyer.planetary.spin_axis import DEFAULT_PRECESSION_RATE, spin_axis_history  # noqa: E402
from andoyer.planetary.tides import tidal_spin_axis_history  # noqa: E402

WINDOWS = (20000.0, 250000.0, 1.0e6)


def read_la2004(paths: list[str]) -> np.ndarray:
    """Rows ``(t [yr], e, obliquity [rad], ϖ [rad])`` of La2004 files, merged, sorted, unique in t.

    Each file is read by the library's checked reader of the format's columns
    (:mod:`andoyer.planetary.orbits.imcce`: Fortran exponents, comments, a damaged line named).
    """
    from andoyer.planetary.orbits.imcce import KYR, LA2004_COLUMNS
    from andoyer.planetary.orbits.numeric_text import read_table

    data = np.concatenate([read_table(path, LA2004_COLUMNS, min_rows=1).values for path in paths])
    data[:, 0] *= KYR
    _, keep = np.unique(data[:, 0], return_index=True)
    return data[keep]


def windows(t: np.ndarray, diff: np.ndarray) -> dict[str, float]:
    """Largest ``|diff|`` over |t| ≤ each window and over the span (past and future separately)."""
    out = {}
    span = max(float(np.abs(t).max(initial=0.0)), WINDOWS[-1])
    for w in sorted({*WINDOWS, span}):
        for side, mask in (("past", (t <= 0) & (t >= -w)), ("future", (t >= 0) & (t <= w))):
            if np.count_nonzero(mask) > 1 and (np.abs(t[mask]).max() >= w - 1.0):
                out[f"{side} {w / 1000:g} kyr"] = float(np.abs(diff[mask]).max())
    return out


def nbody(body: str, args: argparse.Namespace) -> NBodyOrbit:
    """The ``nbody`` orbit of ``body`` with the command line's settings (cache: ``$ANDOYER_CACHE_DIR``)."""
    return NBodyOrbit(body, step_days=args.step_days, gr=not args.no_gr, progress=True)


def compared_orbit(body: str, args: argparse.Namespace) -> NBodyOrbit | SecularOrbit:
    """The orbit compared with La2004: ``nbody`` (:func:`nbody`) or ``secular`` (``--orbit``)."""
    return SecularOrbit(body) if args.orbit == "secular" else nbody(body, args)


def compare(body: str, paths: list[str], args: argparse.Namespace, rate: float, td: float) -> dict:
    """``body``'s history on ``nbody`` against the La2004 files ``paths``, on their grid within the span."""
    data = read_la2004(paths)
    lo, hi = args.span
    data = data[(data[:, 0] >= lo) & (data[:, 0] <= hi)]
    t = data[:, 0]
    orbit = compared_orbit(body, args)
    if body == "earth" and args.earth_tides:  # α(t) from the Earth–Moon tidal history instead of T_d
        h = tidal_spin_axis_history(orbit, body, t, args.earth_tides, precession_rate=rate)
    else:
        h = spin_axis_history(orbit, body, t, precession_rate=rate, tidal_dissipation=td)
    obl = np.degrees(h.obliquity)
    ref_obl = np.degrees(data[:, 2])
    cp, ref_cp = h.climatic_precession, data[:, 1] * np.sin(data[:, 3])
    j0 = int(np.argmin(np.abs(t)))
    result = {
        "body": body,
        "precession_rate": rate,
        "tidal_dissipation": td,
        "orbit": args.orbit,
        "tides": args.earth_tides if body == "earth" else None,
        "gr": not args.no_gr,
        "step_days": args.step_days,
        "at J2000": {
            "obliquity deg": [float(obl[j0]), float(ref_obl[j0])],
            "e": [float(h.eccentricity[j0]), float(data[j0, 1])],
            "e sin varpi": [float(cp[j0]), float(ref_cp[j0])],
        },
        "obliquity deg": windows(t, obl - ref_obl),
        "e": windows(t, h.eccentricity - data[:, 1]),
        "e sin varpi": windows(t, cp - ref_cp),
    }
    past = t <= 0
    result["obliquity range past deg"] = {
        "andoyer": [float(obl[past].min()), float(obl[past].max())],
        "La2004": [float(ref_obl[past].min()), float(ref_obl[past].max())],
    }
    if args.fit_rate:
        near = np.abs(t) <= 250000.0
        rates = rate * (1.0 + np.linspace(-0.02, 0.02, 161))  # ±2 %
        misfit = []
        for r in rates:
            hr = spin_axis_history(
                compared_orbit(body, args), body, t[near], precession_rate=r, tidal_dissipation=td
            )
            misfit.append(np.abs(np.degrees(hr.obliquity) - ref_obl[near]).max())
        best = int(np.argmin(misfit))
        result["best rate over 250 kyr"] = {"rate": float(rates[best]), "obliquity diff deg": misfit[best]}
    return result


def angle(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Angle between unit vectors (..., 3), accurate when small."""
    return 2.0 * np.arcsin(np.clip(np.linalg.norm(a - b, axis=-1) / 2.0, 0.0, 1.0))


def vondrak(args: argparse.Namespace) -> dict:
    """The Earth's obliquity with ``nbody`` against ``vondrak`` and against VCW 2011's own equator."""
    import erfa

    t = np.arange(-200000.0, 200000.0 + 1.0, 500.0)
    h_nb = spin_axis_history(nbody("earth", args), "earth", t)
    h_v = spin_axis_history(VondrakEcliptic(), "earth", t)
    epj = 2000.0 + t
    eps_vcw = np.degrees(angle(erfa.ltpequ(epj), erfa.ltpecl(epj)))
    o_nb, o_v = np.degrees(h_nb.obliquity), np.degrees(h_v.obliquity)
    out = {}
    for w in (20000.0, 50000.0, 100000.0, 200000.0):
        m = np.abs(t) <= w
        out[f"{w / 1000:g} kyr"] = {
            "nbody - vondrak": float(np.abs(o_nb - o_v)[m].max()),
            "nbody - VCW equator": float(np.abs(o_nb - eps_vcw)[m].max()),
            "vondrak - VCW equator": float(np.abs(o_v - eps_vcw)[m].max()),
        }
    return out


def secular(args: argparse.Namespace) -> dict:
    """``secular`` against ``nbody``: obliquity and climatic precession."""
    lo, hi = args.span
    t = np.arange(lo, hi + 1.0, 1000.0)
    out = {}
    for body in ("earth", "mars"):
        h_nb = spin_axis_history(nbody(body, args), body, t)
        h_s = spin_axis_history(SecularOrbit(body), body, t)
        out[body] = {
            "obliquity deg": windows(t, np.degrees(h_s.obliquity - h_nb.obliquity)),
            "e sin varpi": windows(t, h_s.climatic_precession - h_nb.climatic_precession),
        }
    return out


def reference(args: argparse.Namespace) -> dict:
    """The ``nbody`` run of these settings against another cached one (GR off, half step, …)."""
    lo, hi = args.span
    t = np.arange(lo, hi + 1.0, 1000.0)
    here = {b: spin_axis_history(nbody(b, args), b, t) for b in ("earth", "mars")}
    os.environ["ANDOYER_CACHE_DIR"] = args.reference_cache
    ref_args = argparse.Namespace(**vars(args))
    ref_args.no_gr = args.reference_no_gr
    ref_args.step_days = args.reference_step_days
    out = {}
    for b, h in here.items():
        r = spin_axis_history(nbody(b, ref_args), b, t)
        out[b] = {
            "obliquity deg": windows(t, np.degrees(h.obliquity - r.obliquity)),
            "e sin varpi": windows(t, h.climatic_precession - r.climatic_precession),
            "precession deg": windows(t, np.degrees(h.precession - r.precession)),
        }
    return out


def main(argv: list[str] | None = None) -> None:
    """Parse the arguments, run the comparisons asked for and print (or save) them as JSON."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--earth", nargs="+", default=[], help="La2004 Earth files (past and/or future)")
    parser.add_argument("--mars", nargs="+", default=[], help="La2004 Mars files (past and/or future)")
    parser.add_argument("--span", nargs=2, type=float, default=(-1.0e6, 0.0), metavar=("T0", "T1"))
    parser.add_argument("--mars-rate", type=float, default=DEFAULT_PRECESSION_RATE["mars"], help="″/yr")
    parser.add_argument("--earth-rate", type=float, default=DEFAULT_PRECESSION_RATE["earth"], help="″/yr")
    parser.add_argument("--earth-td", type=float, default=0.0, help="tidal dissipation T_d (Earth)")
    parser.add_argument("--earth-tides", choices=("ocean", "constant-lag"), help="Earth: tides, not T_d")
    parser.add_argument("--orbit", choices=("nbody", "secular"), default="nbody", help="orbit against La2004")
    parser.add_argument("--step-days", type=float, default=4.0)
    parser.add_argument("--no-gr", action="store_true", help="leave out general relativity")
    parser.add_argument("--fit-rate", action="store_true", help="best-fitting precession rate over 250 kyr")
    parser.add_argument("--vondrak", action="store_true", help="Earth: nbody against vondrak over ±200 kyr")
    parser.add_argument("--secular", action="store_true", help="secular against nbody over the span")
    parser.add_argument("--reference-cache", help="cache folder of another nbody run to compare with")
    parser.add_argument("--reference-no-gr", action="store_true")
    parser.add_argument("--reference-step-days", type=float, default=4.0)
    parser.add_argument("--json", help="also write the results to this file")
    args = parser.parse_args(argv)
    results = {}
    if args.earth:
        results["earth"] = compare("earth", args.earth, args, args.earth_rate, args.earth_td)
    if args.mars:
        results["mars"] = compare("mars", args.mars, args, args.mars_rate, 0.0)
    if args.vondrak:
        results["vondrak"] = vondrak(args)
    if args.secular:
        results["secular"] = secular(args)
    if args.reference_cache:
        results["reference"] = reference(args)
    text = json.dumps(results, indent=1)
    print(text)
    if args.json:
        Path(args.json).write_text(text + "\n", encoding="utf-8")


if __name__ == "__main__":
    main()
