r"""The tidal models against the present rates, the geological constraints and Farhat et al. (2022).

Prints the tables of docs/tides.md and draws ``docs/images/tides.png``:

* today's rates from each model's equations (recession, spin deceleration, day-length rate,
  obliquity rate, precession constant) against the measured ones;
* each model at the ages of :data:`andoyer.planetary.tides.constraints.CONSTRAINTS`;
* with ``--farhat PATH``, the reference ocean model against the published curve of Farhat et
  al. (2022): the file ``data/orbit_models.npz`` of ``github.com/trichter/archean_moon_orbit``
  (Eulenfeld & Heubeck 2023; key ``"Farhat et al. 2022"``: age in Gyr, ``a/a0``), which holds
  the curve as distributed by the authors at astrogeo.eu; not shipped, no download here;
* the precession constant against the polynomial that astrochron (Meyers; R package,
  ``dotFUNCTIONS-timeOptBMCMC``, ``pmeank``) fits to Farhat et al.'s Figure 6 over 0–3.3 Ga.

Run::

    python3 scripts/tides_comparisons.py --out docs/images [--farhat orbit_models.npz]
"""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from andoyer.planetary.tides import present_rates, tidal_history, tidal_model  # noqa: E402
from andoyer.planetary.tides.constraints import CONSTRAINTS  # noqa: E402
from andoyer.plot import tidal_history_plot  # noqa: E402

#: astrochron's fit to Farhat et al. (2022) Fig. 6: k(T) = Σ c_i T^(4-i), T in Gyr before present.
FARHAT_PRECESSION_FIT = (2.4322, -11.2346, 13.0658, 23.1305, 50.4677)
#: Farhat et al.'s present distance in Earth radii (the normalisation of their file).
FARHAT_A0 = 60.142611


def _value(history, quantity: str, k: int) -> float:
    value = getattr(history, quantity)[k]
    return float(np.degrees(value)) if quantity == "obliquity" else float(value)


def present_table() -> None:
    """Today's rates of each model."""
    print("| quantity | measured | constant-lag | ocean |")
    print("| --- | --- | --- | --- |")
    rates = {name: present_rates(tidal_model(name)) for name in ("constant-lag", "ocean")}
    lunar = {name: present_rates(tidal_model(name), solar_tide=False) for name in ("constant-lag", "ocean")}
    rows = [
        ("recession (cm/yr)", "3.830 ± 0.008", lambda n: f"{rates[n]['recession']:.4f}"),
        ("dω/dt (10⁻²² rad/s²)", "−6.39 ± 0.03", lambda n: f"{rates[n]['spin_acceleration'] * 1e22:.3f}"),
        ("of which the Moon's", "", lambda n: f"{lunar[n]['spin_acceleration'] * 1e22:.3f}"),
        ("day-length rate (ms/cy)", "+2.3 (tidal)", lambda n: f"{rates[n]['day_length_rate']:.3f}"),
        ("obliquity rate (″/Myr)", "", lambda n: f"{rates[n]['obliquity_rate']:.2f}"),
    ]
    for label, measured, cell in rows:
        print(f"| {label} | {measured} | {cell('constant-lag')} | {cell('ocean')} |")
    p0 = tidal_history([0.0], "ocean").precession_constant[0]
    print(f"\nprecession constant today: {p0:.4f} ″/yr (La2004: 50.475838)")


def constraints_table() -> None:
    """Each constraint against the two models (the constant lag only where it reaches)."""
    ages = sorted({c.age for c in CONSTRAINTS})
    ocean = tidal_history(-np.array(ages[::-1]), "ocean")
    reach = [a for a in ages if a < 1.1e9]
    lag = tidal_history(-np.array(reach[::-1]), "constant-lag")
    print("| age (Ga) | site | quantity | estimate | ocean | constant-lag | source |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for c in sorted(CONSTRAINTS, key=lambda c: (c.age, c.quantity)):
        k = ages[::-1].index(c.age)
        model = _value(ocean, c.quantity, k)
        other = "—"
        if c.age in reach:
            other = f"{_value(lag, c.quantity, reach[::-1].index(c.age)):.5g}"
        spread = "" if c.uncertainty is None else f" ± {c.uncertainty:.3g} {c.sigma}".rstrip()
        estimate = f"{c.value:.5g}{spread}"
        cells = [f"{c.age / 1e9:.3g}", c.site, c.quantity, estimate, f"{model:.5g}", other, c.source]
        print("| " + " | ".join(cells) + " |")


def farhat_table(path: str) -> None:
    """The ocean model's a/a0 against Farhat et al.'s published curve."""
    curve = np.load(path)["Farhat et al. 2022"]
    ages = np.array([0.25, 0.62, 0.9, 1.1, 1.4, 2.0, 2.46, 3.0, 3.2, 3.5, 4.0, 4.3])
    ocean = tidal_history(np.append(-ages[::-1] * 1e9, 0.0), "ocean")
    ratio = ocean.lunar_distance[-2::-1] / ocean.lunar_distance[-1]
    poly = np.polyval(FARHAT_PRECESSION_FIT, ages)
    print("| age (Ga) | a/a0 Farhat | a/a0 ocean | difference | p Farhat Fig. 6 fit | p ocean |")
    print("| --- | --- | --- | --- | --- | --- |")
    for age, mine, p_fit, p_mine in zip(ages, ratio, poly, ocean.precession_constant[-2::-1], strict=True):
        theirs = float(np.interp(age, curve[0], curve[1]))
        fit = f"{p_fit:.1f}" if age <= 3.3 else "—"
        change = 100 * (mine / theirs - 1)
        print(f"| {age:g} | {theirs:.4f} | {mine:.4f} | {change:+.1f} % | {fit} | {p_mine:.1f} |")


def main(argv: list[str] | None = None) -> None:
    """Print the tables, draw the figure."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="reproduced", help="folder for tides.png (created)")
    parser.add_argument("--farhat", help="orbit_models.npz of trichter/archean_moon_orbit")
    args = parser.parse_args(argv)
    present_table()
    print()
    constraints_table()
    if args.farhat:
        print()
        farhat_table(args.farhat)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    ocean = tidal_history(np.linspace(-4.3e9, 0.0, 861), "ocean")
    lag = tidal_history(np.linspace(-1.14e9, 0.0, 229), "constant-lag")
    fig = tidal_history_plot([ocean, lag], ["ocean (after Farhat et al. 2022)", "constant time lag"])
    fig.savefig(out / "tides.png", dpi=110)
    print(f"\nwrote {out / 'tides.png'}; obliquity 4.3 Ga ago {math.degrees(ocean.obliquity[0]):.2f} deg")


if __name__ == "__main__":
    main()
