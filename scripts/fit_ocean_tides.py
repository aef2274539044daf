r"""Fit the two free parameters of the ocean tide model to the two constraints of Farhat et al. (2022).

:class:`andoyer.planetary.tides.OceanTides` has two free parameters, the ocean's effective
depth ``H`` and its Rayleigh drag frequency ``σ_R`` (the solid Earth's and the ocean's other
numbers are cited in its docstring). Farhat et al. (2022, A&A 665, L1) determine theirs by two
constraints, which this script imposes on this model:

1. today's lunar recession, 3.830 cm/yr (lunar laser ranging; Williams & Boggs 2016);
2. the age of the Moon, 4.425 Gyr (Maurice et al. 2020): integrated backwards, the Moon reaches
   the end of the model's validity (the Laplace-plane transition, 13.8 Earth radii then; inside
   it the remaining time to the Roche limit is about a Myr) 4.425 Gyr ago.

For each ``H``, (1) fixes ``σ_R`` (the larger of the two roots: the smaller one, a narrow
resonance, never brings the Moon close); (2) then fixes ``H`` by a bracketed root search. The
result goes into ``FITTED_DEPTH``/``FITTED_DRAG`` of ``andoyer.planetary.tides.response``.

Run::

    python3 scripts/fit_ocean_tides.py
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from andoyer.planetary.tides import equations
from andoyer.planetary.tides.evolution import LUNAR_AGE, MEASURED_RECESSION, kernel_constants, present_rates
from andoyer.planetary.tides.response import OceanTides
from andoyer.planetary.tides.system import EarthMoonSystem

SYSTEM = EarthMoonSystem()


def drag_for(depth: float) -> float:
    """The larger ``σ_R`` giving today's recession at ``depth`` (NaN if none)."""

    def miss(log_drag: float) -> float:
        rates = present_rates(OceanTides(depth=depth, drag=10.0**log_drag), SYSTEM)
        return rates["recession"] / 100.0 - MEASURED_RECESSION

    grid = np.linspace(-7.0, -2.0, 401)
    values = [miss(x) for x in grid]
    roots = [brentq(miss, grid[i], grid[i + 1], xtol=1e-13) for i in range(len(grid) - 1)
             if values[i] * values[i + 1] < 0]
    return 10.0 ** roots[-1] if roots else math.nan


def age_at(depth: float, drag: float) -> float:
    """Years before J2000 at which the Moon reaches the Laplace-plane transition (inf if never)."""
    c = kernel_constants(OceanTides(depth=depth, drag=drag), SYSTEM)
    out = np.empty((1, 3))
    _, status, t_stop = equations.advance(1.0, 1.0, SYSTEM.obliquity, np.array([-6.0e9]), c, 1, 1e-11, out)
    return -t_stop if status == 1 else math.inf


def main() -> None:
    """Print the scan, the fit and its check."""

    def miss(depth: float) -> float:
        return age_at(depth, drag_for(depth)) / LUNAR_AGE - 1.0

    for depth in (7850.0, 7900.0, 8000.0, 8500.0):
        drag = drag_for(depth)
        age = age_at(depth, drag) / 1e9
        print(f"H = {depth:7.1f} m: sigma_R = {drag:.6e} 1/s, Moon at r_L {age:.4f} Gyr ago")
    depth = brentq(miss, 7850.0, 8000.0, xtol=1e-3)
    drag = drag_for(depth)
    print(f"fit: FITTED_DEPTH = {depth:.2f} m, FITTED_DRAG = {drag:.5e} 1/s")
    depth, drag = round(depth, 2), float(f"{drag:.5e}")
    recession = present_rates(OceanTides(depth=depth, drag=drag))["recession"]
    print(f"check: recession {recession:.5f} cm/yr, age {age_at(depth, drag) / 1e9:.5f} Gyr")


if __name__ == "__main__":
    main()
