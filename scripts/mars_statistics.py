r"""Mars' obliquity against the published numbers (docs/chaotic-obliquity.md, issue 22 item 3).

Three measurements, each printed as one JSON object (``--json PATH`` also writes it):

``regular``
    The regular (linear) theory, as Ward (1973, *Science* 181, 260) had it: the spin axis
    along the Laplace–Lagrange orbit (``orbit_history("laplace-lagrange", "mars")``, the
    secular theory of Brouwer & van Woerkom's kind) over ``--span`` (default the last 10 Myr,
    1-kyr samples): the range, the two strongest lines of the obliquity's spectrum and their
    beat. Ward's abstract: oscillation on ~1.2×10⁵ yr, its amplitude modulated on ~1.2×10⁶ yr,
    "maximum possible variation" 14.9°–35.5°.

``la2004 FILE...``
    La2004's Mars solution (Laskar et al. 2004, Icarus 170, 343; the IMCCE files
    ``INSOLN.LA2004.MARS.ASC`` and ``INSOLP.LA2004.MARS.ASC``, also ``…LA2003…``; *not*
    shipped: see docs/spin-axis.md for the copies used) against the nominal secular member
    (no perturbation) at ``--rates`` (″/yr): the mean, extremes and fraction of time at or above
    40° over 0–4 Myr and 4–10 Myr before J2000, and the largest difference within 20 kyr …
    10 Myr; ``--nbody END`` adds the axis along the N-body orbit (8-day step, about 48 CPU s
    per Myr, cached) to ``END``; ``--plot PNG`` draws the histories over the last 10 Myr.

``ensemble``
    ``--members N`` members (:func:`andoyer.ensemble.obliquity_ensemble`, seed ``--seed``,
    the default perturbation and precession-rate range) from J2000 to ``--end`` every
    ``--step`` years: the mean, standard deviation, median and extremes over all (member,
    time) values, the fraction of time at or above 40°, 50°, 60°, the probability of reaching
    each, the members' own means and extremes, and the same over the windows ``--windows`` (years back).

Run (2 cores; a member costs about 27 CPU s per Gyr; negative values as ``--end=-1e9``)::

    python3 scripts/mars_statistics.py regular
    python3 scripts/mars_statistics.py la2004 INSOLN.LA2004.MARS.ASC INSOLP.LA2004.MARS.ASC \
        --rates 7.597 7.576 7.565 --nbody=-6e6
    python3 scripts/mars_statistics.py ensemble --members 30 --end=-2.5e8 --step 1e4 --windows 1e7 1e8 2.5e8
    python3 scripts/mars_statistics.py ensemble --members 20 --end=-1e9 --step 2e4 --seed 1 \
        --windows 1e7 1e8 2.5e8 5e8 1e9
    python3 scripts/mars_statistics.py ensemble --body moonless-earth --members 8 \
        --end=-5e8 --step 1e4
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

THRESHOLDS = (40.0, 50.0, 60.0)


def _summary(values: np.ndarray) -> dict[str, float]:
    """Moments, extremes and time fractions of a flat array of obliquities (degrees, NaN dropped)."""
    v = values[np.isfinite(values)]
    out = {
        "mean": float(v.mean()), "std": float(v.std()), "median": float(np.median(v)),
        "min": float(v.min()), "max": float(v.max()),
    }  # fmt: skip
    for theta in THRESHOLDS:
        out[f"fraction_of_time_ge_{theta:g}"] = float(np.mean(v >= theta))
    return out


def spectrum_lines(t: np.ndarray, eps: np.ndarray, count: int = 2) -> list[float]:
    """Periods (years) of the ``count`` strongest local maxima of the Hann-windowed spectrum of ``eps``."""
    x = (eps - eps.mean()) * np.hanning(eps.size)
    power = np.abs(np.fft.rfft(x))
    freq = np.fft.rfftfreq(eps.size, d=abs(t[1] - t[0]))
    peaks = np.flatnonzero((power[1:-1] > power[:-2]) & (power[1:-1] > power[2:])) + 1
    peaks = peaks[np.argsort(power[peaks])[::-1]][:count]
    return [float(1.0 / freq[p]) for p in peaks]


def regular(span: float, step: float, rate: float) -> dict:
    """Ward-style regular range and periods along the Laplace–Lagrange orbit."""
    from andoyer.planetary.orbits import orbit_history
    from andoyer.planetary.spin_axis import spin_axis_history

    t = np.arange(span, step / 2, step)
    orbit = orbit_history("laplace-lagrange", "mars")
    eps = np.degrees(spin_axis_history(orbit, "mars", t, precession_rate=rate).obliquity)
    p1, p2 = spectrum_lines(t, eps)
    return {
        "orbit": "laplace-lagrange", "precession_rate": rate, "span": [float(span), 0.0], "step": step,
        "min": float(eps.min()), "max": float(eps.max()), "mean": float(eps.mean()),
        "strongest_periods_yr": [p1, p2], "beat_period_yr": 1.0 / abs(1.0 / p1 - 1.0 / p2),
        "last_myr": {"min": float(eps[t >= -1e6].min()), "max": float(eps[t >= -1e6].max())},
    }  # fmt: skip


def read_la(paths: list[str]) -> tuple[np.ndarray, np.ndarray]:
    """Times (years) and obliquities (degrees) of IMCCE Mars files, merged and sorted."""
    from andoyer.planetary.orbits.imcce import KYR, LA2004_COLUMNS
    from andoyer.planetary.orbits.numeric_text import read_table

    data = np.concatenate([read_table(p, LA2004_COLUMNS, min_rows=1).values for p in paths])
    t, keep = np.unique(data[:, 0] * KYR, return_index=True)
    return t, np.degrees(data[keep, 2])


WINDOWS_LA = ((-4e6, 0.0), (-6e6, -4e6), (-10e6, -4e6), (-10e6, 0.0), (-20e6, 0.0))


def _against(
    t: np.ndarray, eps: np.ndarray, t_la: np.ndarray, eps_la: np.ndarray, reach: float = 1e7
) -> dict[str, float]:
    """Largest |ε − ε_La| (degrees) on the common 1-kyr epochs within 20 kyr … ``reach`` of J2000."""
    common = np.isin(np.round(t), np.round(t_la))
    t_c = t[common]
    diff = np.abs(eps[common] - np.interp(t_c, t_la, eps_la))
    reaches = sorted({w for w in (2e4, 2.5e5, 1e6, 2e6, 4e6) if w < reach} | {reach})
    return {f"{w / 1e6:g} Myr": float(diff[np.abs(t_c) <= w].max()) for w in reaches}


def la2004(
    paths: list[str], rates: list[float], nbody_end: float | None = None, plot: str | None = None
) -> dict:
    """La2004's Mars obliquity over windows of the last 20 Myr, and the nominal secular member's.

    With ``nbody_end``, also the spin axis (7.597″/yr) along the N-body orbit (8-day step, cached)
    from J2000 to ``nbody_end``; with ``plot``, a figure of the histories over the last 10 Myr.
    """
    curves: list[tuple[str, np.ndarray, np.ndarray]] = []
    from andoyer.planetary.spin_axis import default_axis
    from andoyer.planetary.spin_axis.members import member_obliquities

    t_la, eps_la = read_la(paths)
    out: dict = {
        "files": [Path(p).name for p in paths],
        "windows_myr": [[a / 1e6, b / 1e6] for a, b in WINDOWS_LA],
    }

    def windows(t: np.ndarray, eps: np.ndarray) -> list[dict]:
        return [_summary(eps[(t >= a) & (t <= b)]) for a, b in WINDOWS_LA]

    out["la"] = windows(t_la, eps_la)
    curves.append(("La2004", t_la, eps_la))
    end = max(-20e6, float(t_la.min()))
    run = member_obliquities(
        "mars", end, 1000.0, np.zeros((len(rates), 16), complex), default_axis("mars"),
        precession_rate=np.asarray(rates, float),
    )  # fmt: skip
    out["secular"] = {}
    for rate, eps in zip(rates, np.degrees(run.obliquity), strict=True):
        out["secular"][f"{rate:g}"] = {
            "windows": windows(run.t, eps),
            "max_abs_difference_deg": _against(run.t, eps, t_la, eps_la),
        }
        curves.append((f"secular orbit, {rate:g}″/yr", run.t, eps))
    if nbody_end is not None:
        from andoyer.planetary.orbits import NBodyOrbit
        from andoyer.planetary.spin_axis import spin_axis_history

        t = np.arange(nbody_end, 500.0, 1000.0)
        orbit = NBodyOrbit("mars", step_days=8.0, progress=False)
        eps = np.degrees(spin_axis_history(orbit, "mars", t, precession_rate=7.597).obliquity)
        spans = [(a, b) for a, b in ((-4e6, 0.0), (nbody_end, -4e6), (nbody_end, 0.0)) if nbody_end <= a < b]
        out["nbody_7.597"] = {
            "end": nbody_end,
            "windows": {f"[{a / 1e6:g},{b / 1e6:g}]": _summary(eps[(t >= a) & (t <= b)]) for a, b in spans},
            "la_same_windows": {
                f"[{a / 1e6:g},{b / 1e6:g}]": _summary(eps_la[(t_la >= a) & (t_la <= b)]) for a, b in spans
            },
            "max_abs_difference_deg": _against(t, eps, t_la, eps_la, reach=abs(nbody_end)),
        }
        curves.insert(1, ("nbody orbit, 7.597″/yr", t, eps))
    if plot:
        _plot(curves, plot)
    return out


def _plot(curves: list[tuple[str, np.ndarray, np.ndarray]], path: str) -> None:
    """One panel per history over the last 10 Myr, La2004 drawn under each."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(9.0, 1.6 * len(curves)), layout="constrained")
    axes = fig.subplots(len(curves), 1, sharex=True, sharey=True)
    _, t_la, eps_la = curves[0]
    keep = (t_la >= -1e7) & (t_la <= 0.0)
    for ax, (label, t, eps) in zip(axes, curves, strict=True):
        if label != "La2004":
            ax.plot(t_la[keep] / 1e6, eps_la[keep], color="0.75", lw=0.6, label="La2004")
        m = (t >= -1e7) & (t <= 0.0)
        ax.plot(t[m] / 1e6, eps[m], lw=0.6, color="C0" if label == "La2004" else "C3", label=label)
        ax.legend(loc="upper right", fontsize=8, framealpha=0.9, ncols=2)
        ax.set_ylabel("ε (deg)")
        ax.set_ylim(5.0, 60.0)
    axes[-1].set_xlabel("time from J2000 (Myr)")
    fig.savefig(path, dpi=110)
    print(f"wrote {path}", file=sys.stderr)


def ensemble(body: str, members: int, end: float, step: float, seed: int, windows: list[float]) -> dict:
    """An ensemble's statistics over all (member, time) values, whole and by window."""
    from andoyer.ensemble import obliquity_ensemble

    wall, cpu = time.perf_counter(), time.process_time()
    ds = obliquity_ensemble(
        body, members, end, step, seed=seed, thresholds=np.radians(THRESHOLDS), progress=False
    )
    wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    t = ds["time"].values if "time" in ds else ds["t"].values
    eps = np.asarray(ds["obliquity"].values, float)
    out = {
        "body": body, "members": members, "end": end, "step": step, "seed": seed,
        "command": f"obliquity_ensemble({body!r}, {members}, {end:g}, {step:g}, seed={seed})",
        "wall_s": round(wall, 1), "parent_cpu_s": round(cpu, 1),
        "left_domain": int(np.sum(~np.isfinite(eps[:, -1]))),
        "all": _summary(eps.ravel()),
        "exceedance": {f"{th:g}": float(ds["exceedance"].sel(threshold=th)) for th in THRESHOLDS},
        "member_means": [float(np.nanmean(row)) for row in eps],
        "member_min": [float(np.nanmin(row)) for row in eps],
        "member_max": [float(np.nanmax(row)) for row in eps],
    }  # fmt: skip
    if "precession_rate" in ds:
        out["precession_rates"] = [float(r) for r in np.asarray(ds["precession_rate"].values).ravel()]
    out["windows"] = {}
    for w in windows:
        m = np.abs(t) <= w
        sub = eps[:, m]
        out["windows"][f"{w:g}"] = _summary(sub.ravel()) | {
            f"reached_{th:g}": float(np.mean(np.nanmax(sub, axis=1) >= th)) for th in THRESHOLDS
        }
    return out


def main(argv: list[str] | None = None) -> None:
    """Parse the sub-command and print (and optionally save) its JSON."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="what", required=True)
    r = sub.add_parser("regular")
    r.add_argument("--span", type=float, default=-1e7)
    r.add_argument("--step", type=float, default=1000.0)
    r.add_argument("--rate", type=float, default=7.597)
    la = sub.add_parser("la2004")
    la.add_argument("files", nargs="+")
    la.add_argument("--rates", type=float, nargs="+", default=[7.597, 7.576])
    la.add_argument("--nbody", type=float, help="also along the N-body orbit to this time (years)")
    la.add_argument("--plot", help="a PNG of the histories over the last 10 Myr")
    e = sub.add_parser("ensemble")
    e.add_argument("--body", default="mars")
    e.add_argument("--members", type=int, default=30)
    e.add_argument("--end", type=float, default=-2.5e8)
    e.add_argument("--step", type=float, default=1e4)
    e.add_argument("--seed", type=int, default=0)
    e.add_argument("--windows", type=float, nargs="*", default=[])
    for p in (r, la, e):
        p.add_argument("--json", help="also write the result here")
    args = parser.parse_args(argv)
    if args.what == "regular":
        result = regular(args.span, args.step, args.rate)
    elif args.what == "la2004":
        result = la2004(args.files, args.rates, args.nbody, args.plot)
    else:
        result = ensemble(args.body, args.members, args.end, args.step, args.seed, args.windows)
    text = json.dumps(result, indent=1)
    print(text)
    if args.json:
        Path(args.json).write_text(text + "\n", encoding="utf-8")


if __name__ == "__main__":
    main()
