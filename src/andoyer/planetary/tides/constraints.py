"""Geological and present-day constraints on the Earth–Moon history, with their sources.

Each :class:`Constraint` is one published estimate at one age: the lunar distance, the length of
the (solar) day or the precession constant, with its uncertainty where the source gives one and
where this project could confirm it (``None`` otherwise). The docs page ``docs/tides.md`` and
the plot of ``andoyer tides --plot`` compare the models with them; the tests assert the
comparisons the docs state.

How each number was confirmed (2026): Meyers & Malinverno (2018) and the Nanfen study from
their abstracts; Williams (2000), Sonett & Chan (1998), Lantink et al. (2022) and Zhou et al.
(2022) as compiled in the code of Eulenfeld & Heubeck (2023, JGR Planets 128, e2022JE007466,
``github.com/trichter/archean_moon_orbit``, ``moon_orbit.py``: ``WILLIAMS2000``,
``ORBIT_TIME_DATA``), with Williams' Elatina day length and its ±0.4 h from the issue's brief
(Williams 2000, Rev. Geophys. 38, 37).

Examples
--------
>>> [c.site for c in CONSTRAINTS if c.quantity == "precession_constant"]
['Xiamaling']
"""

from __future__ import annotations

from dataclasses import dataclass

from andoyer import catalogue

__all__ = ["CONSTRAINTS", "Constraint"]


@dataclass(frozen=True)
class Constraint:
    """One estimate of the Earth–Moon system at one age.

    Attributes
    ----------
    age : float
        Years before present (positive).
    quantity : {"lunar_distance", "day_length", "precession_constant"}
        In km, hours (the solar day) and ″/yr.
    value : float
    uncertainty : float or None
        As the source gives it (``sigma`` says which), None where not confirmed here.
    sigma : str
        What ``uncertainty`` is ("2σ", "1σ", "range" or "").
    site : str
    source : str
    """

    age: float
    quantity: str
    value: float
    uncertainty: float | None
    sigma: str
    site: str
    source: str


_R_E = catalogue.get("earth").radius.to("km")  # Williams (2000) gives distances in equatorial Earth radii
_A0 = 60.27 * _R_E  # his present mean distance, 60.27 R_E

#: The constraints, oldest last within each quantity.
CONSTRAINTS: tuple[Constraint, ...] = (
    Constraint(6.2e8, "day_length", 21.9, 0.4, "1σ", "Elatina–Reynella",
               "Williams 2000, Rev. Geophys. 38, 37 (tidal rhythmites)"),
    Constraint(6.2e8, "lunar_distance", 58.34 * _R_E, None, "", "Elatina–Reynella",
               "Williams 2000, Table 3 (58.34 R_E)"),
    Constraint(9.0e8, "day_length", 18.9, None, "", "Big Cottonwood",
               "Sonett & Chan 1998, via Williams 2000 (tidal rhythmites)"),
    Constraint(9.0e8, "lunar_distance", 54.7 * _R_E, None, "", "Big Cottonwood",
               "Sonett & Chan 1998, via Williams 2000 (54.7 R_E)"),
    Constraint(1.1e9, "day_length", 18.94, 0.39, "", "Nanfen",
               "Nanfen Formation cyclostratigraphy, J. Geol. Soc. 2022, doi:10.1144/jgs2022-022"),
    Constraint(1.1e9, "lunar_distance", 343000.0, 4000.0, "", "Nanfen",
               "Nanfen Formation cyclostratigraphy, J. Geol. Soc. 2022, doi:10.1144/jgs2022-022"),
    Constraint(1.4e9, "precession_constant", 85.79, 2.72, "2σ", "Xiamaling",
               "Meyers & Malinverno 2018, PNAS 115, 6363 (cyclostratigraphy, TimeOpt)"),
    Constraint(1.4e9, "lunar_distance", 340900.0, 2600.0, "2σ", "Xiamaling",
               "Meyers & Malinverno 2018, PNAS 115, 6363"),
    Constraint(1.4e9, "day_length", 18.68, 0.25, "2σ", "Xiamaling",
               "Meyers & Malinverno 2018, PNAS 115, 6363"),
    Constraint(2.45e9, "day_length", 18.8, None, "", "Weeli Wolli",
               "Williams 1989, 1999, via Williams 2000 (banded iron formation rhythmites)"),
    Constraint(2.45e9, "lunar_distance", 54.6 * _R_E, None, "", "Weeli Wolli",
               "Williams 1989, 1999, via Williams 2000 (54.6 R_E)"),
    Constraint(2.46e9, "lunar_distance", 321800.0, None, "", "Joffre Gorge",
               "Lantink et al. 2022, PNAS (cyclostratigraphy of banded iron formations)"),
    Constraint(2.59e8, "lunar_distance", 376110.0, None, "", "Zhou et al.",
               "Zhou et al. 2022 (cyclostratigraphy)"),
    Constraint(4.55e8, "lunar_distance", 370640.0, None, "", "Zhou et al.",
               "Zhou et al. 2022 (cyclostratigraphy)"),
    Constraint(6.55e8, "lunar_distance", 357310.0, None, "", "Zhou et al.",
               "Zhou et al. 2022 (cyclostratigraphy)"),
    Constraint(2.465e9, "lunar_distance", 324320.0, None, "", "Zhou et al.",
               "Zhou et al. 2022 (cyclostratigraphy)"),
)
