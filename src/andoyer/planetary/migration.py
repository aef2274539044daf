r"""A satellite's tidal migration turned into the precession constant ``α(t)`` of its planet.

A satellite inside its planet's Laplace radius is a ring the equator carries along
(:mod:`andoyer.planetary.precession_constant`): it adds ``q_k ∝ a_k²`` to ``J2`` and
``l_k ∝ a_k² n_k ∝ a_k^{1/2}`` to ``λ = C/MR²``, so that as it migrates outwards the planet's
axis precesses faster,

.. math:: \frac{\alpha(t)}{\alpha_0} = \frac{J_2 + q' + q_k x^2}{\lambda + l' + l_k \sqrt{x}}
   \Big/ \frac{J_2 + q' + q_k}{\lambda + l' + l_k}, \qquad x = \frac{a_k(t)}{a_k(0)},

``q'``, ``l'`` the other satellites' shares (held fixed) and ``q_k``, ``l_k`` the migrating one's
at J2000 (its Laplace-plane tilt factors held at their J2000 values). A slowly growing ``α`` can
carry the precession across a secular frequency ``s_k`` of the orbit, or capture it there and
raise the obliquity: Saturn and ``s8`` as Titan migrates (Saillenfest, Lari & Boué 2021,
Nature Astron. 5, 345; Saillenfest, Lari, Boué & Courtot 2021, A&A 647, A92), Jupiter and
``s7`` as the Galilean satellites do (Saillenfest, Lari & Courtot 2020, A&A 640, A11).

**The migration law** is a power law in the time since the satellites formed (the form
Saillenfest et al. 2021 give Titan's migration),

.. math:: a_k(t) = a_k(0) \Big(1 + \frac{t}{T_0}\Big)^{b},

``t`` Julian years from J2000 and ``T_0`` the time since the satellites formed (default the
solar system's age, 4.5673 Gyr: Connelly et al. 2012, the Sun's catalogued ``age``): ``a_k ∝
τ^b`` in the time ``τ = T_0 + t`` since formation. The index ``b`` sets today's rate,
``ȧ_k(0) = b a_k(0)/T_0``; by default it is taken from the satellite's measured rate
(catalogue ``migration_rate``: Titan's 11.3 ± 2.0 cm/yr, Lainey et al. 2020, Nature Astron. 4,
1053), ``b = ȧ_k(0) T_0 / a_k(0)`` = 0.42 for Titan.

**Validity.** The ring picture needs the satellite inside the Laplace radius: a span over which
``a_k(t)`` reaches ``r_L`` is refused, as is one reaching back before the satellites formed
(``t ≤ −T_0``). The Laplace plane's own tilt, growing as the satellite moves out, is held at its
J2000 value; near ``r_L`` the satellite's plane and the planet's axis no longer separate
(Saillenfest & Lari 2021, A&A 654, A83), which this model does not follow.

Examples
--------
>>> law = satellite_migration("saturn", "titan")
>>> round(law.index, 4), round(law.age / 1e9, 4)  # b from Titan's 11.3 cm/yr; T0 in Gyr
(0.4224, 4.5673)
>>> round(float(law.factor(-1e9)), 4), round(float(law.factor(1e9)), 4)  # α(t)/α(0)
(0.8601, 1.1352)
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer import catalogue
from andoyer.catalogue import Body
from andoyer.catalogue.units import JULIAN_YEAR
from andoyer.planetary.parameters import check
from andoyer.planetary.precession_constant import precession_constant
from andoyer.planetary.spin_axis.model import SpinAxisModel

__all__ = ["MigratingSpinAxisModel", "SatelliteMigration", "satellite_migration"]

Array = NDArray[np.float64]


@dataclass(frozen=True)
class SatelliteMigration:
    """The power-law migration of one satellite and the ``α(t)/α(0)`` it gives (module docstring).

    Used as ``coupling`` of :func:`andoyer.planetary.spin_axis.spin_axis_history`: called with the
    model built for the planet and the span, it returns the :class:`MigratingSpinAxisModel`.

    Attributes
    ----------
    planet, satellite : str
    index : float
        ``b`` (``a ∝ (T0 + t)^b``).
    age : float
        ``T0``, years since the satellites formed, at J2000.
    j2, moment_of_inertia : float
        The planet's ``J2`` and ``λ``.
    quadrupole, angular_momentum : float
        The migrating satellite's ``q_k``, ``l_k`` at J2000.
    other_quadrupole, other_angular_momentum : float
        The other satellites' ``q'``, ``l'``.
    laplace_ratio : float
        ``a_k(0)/r_L``.
    """

    planet: str
    satellite: str
    index: float
    age: float
    j2: float
    moment_of_inertia: float
    quadrupole: float
    angular_momentum: float
    other_quadrupole: float
    other_angular_momentum: float
    laplace_ratio: float

    def semi_major_axis_ratio(self, t: ArrayLike) -> Array:
        """``x = a_k(t)/a_k(0) = (1 + t/T0)^b``, shape of ``t`` (years from J2000, ``t > −T0``)."""
        t = np.asarray(t, dtype=np.float64)
        return (1.0 + t / self.age) ** self.index

    def _figure(self, x: Array) -> Array:
        num = self.j2 + self.other_quadrupole + self.quadrupole * x**2
        den = self.moment_of_inertia + self.other_angular_momentum + self.angular_momentum * np.sqrt(x)
        return num / den

    def factor(self, t: ArrayLike) -> Array:
        """``α(t)/α(0)``, shape of ``t`` (years from J2000)."""
        return self._figure(self.semi_major_axis_ratio(t)) / self._figure(np.float64(1.0))

    def check_span(self, t0: float, t1: float) -> None:
        """Refuse a span reaching back to the satellites' formation or out to the Laplace radius."""
        lo, hi = min(float(t0), 0.0), max(float(t1), 0.0)
        if not lo > -self.age:
            msg = (
                f"expected a span after the satellites formed (t > -{self.age:g} years, the migration's "
                f"age), got {lo:g}"
            )
            raise ValueError(msg)
        far = self.laplace_ratio * float(self.semi_major_axis_ratio(hi if self.index >= 0 else lo))
        if not far < 1:
            msg = (
                f"expected {self.satellite} to stay inside {self.planet}'s Laplace radius over the span (the "
                f"ring picture of the precession constant), got a/r_L = {far:.3g}"
            )
            raise ValueError(msg)

    def __call__(self, model: SpinAxisModel, span: tuple[float, float]) -> MigratingSpinAxisModel:
        """``model`` with its ``α`` following the migration over ``span`` (checked)."""
        if not isinstance(model, SpinAxisModel) or isinstance(model, MigratingSpinAxisModel):
            msg = f"expected a SpinAxisModel to drive with the migration, got {type(model).__name__}"
            raise ValueError(msg)
        if not model.satellite_rings:
            msg = (
                f"expected the model of {self.planet} from its figure and satellites (no precession rate "
                f"or dynamical ellipticity given), got one of {model.body!r} without satellites"
            )
            raise ValueError(msg)
        self.check_span(*span)
        fields = {name: getattr(model, name) for name in model.__dataclass_fields__}
        return MigratingSpinAxisModel(**fields, migration=self)

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready fields."""
        return {
            "satellite": self.satellite,
            "index": self.index,
            "age_years": self.age,
            "laplace_ratio": self.laplace_ratio,
        }


@dataclass(frozen=True, eq=False)
class MigratingSpinAxisModel(SpinAxisModel):
    """A :class:`~andoyer.planetary.spin_axis.SpinAxisModel` whose ``α`` follows a satellite's migration.

    ``α(t, e) = SpinAxisModel.rate(t, e) · migration.factor(t)``.

    Attributes
    ----------
    migration : SatelliteMigration
    """

    migration: Any = None

    def __post_init__(self) -> None:
        super().__post_init__()
        if not isinstance(self.migration, SatelliteMigration):
            msg = f"expected a SatelliteMigration, got {type(self.migration).__name__}"
            raise ValueError(msg)

    def rate(self, t: ArrayLike, e: ArrayLike | None = None) -> Array:
        """``α(t, e)``, radians per Julian year.

        Parameters
        ----------
        t : array_like, shape (...)
            Julian years from J2000, after the satellites formed.
        e : array_like, shape (...), optional

        Returns
        -------
        numpy.ndarray, shape (...)
        """
        return super().rate(t, e) * self.migration.factor(t)

    def check_span(self, t0: float, t1: float) -> None:
        """The base model's checks and the migration's (:meth:`SatelliteMigration.check_span`)."""
        super().check_span(t0, t1)
        self.migration.check_span(t0, t1)


def _finite(name: str, value: float) -> float:
    if (
        isinstance(value, bool)
        or not isinstance(value, int | float | np.floating)
        or not math.isfinite(value)
    ):
        msg = f"expected a finite real {name}, got {value!r}"
        raise ValueError(msg)
    return float(value)


def satellite_migration(
    planet: str | Body, satellite: str, index: float | None = None, age: float | None = None
) -> SatelliteMigration:
    """The power-law migration of ``satellite`` about ``planet`` (module docstring).

    Parameters
    ----------
    planet : str or Body
        A catalogued planet with satellites inside its Laplace radius.
    satellite : str
        One of them (:func:`~andoyer.planetary.precession_constant.satellites_of`).
    index : float, optional
        ``b``, finite (negative: an inward migration). Default: from the satellite's catalogued
        ``migration_rate``, ``b = ȧ T0 / a``.
    age : float, optional
        ``T0`` in years, ``0 < T0 ≤`` 13.787 Gyr (:mod:`andoyer.planetary.parameters`). Default: the
        Sun's catalogued ``age`` (Connelly et al. 2012).

    Returns
    -------
    SatelliteMigration

    Raises
    ------
    ValueError
        For a planet without such a satellite, a satellite outside the Laplace radius, a
        default index for a satellite without a catalogued ``migration_rate``, or an ``index``
        or ``age`` out of range.

    Examples
    --------
    >>> law = satellite_migration("jupiter", "callisto", index=0.5)
    >>> round(law.laplace_ratio, 3)
    0.932
    >>> satellite_migration("saturn", "enceladus")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: expected Enceladus to have migration_rate for the index b of its migration, got none ...
    """
    constant = precession_constant(planet)
    entry = catalogue.get(planet)
    wanted = str(satellite).strip().lower()
    shares = {s.name.lower(): s for s in constant.satellites}
    if wanted not in shares or shares[wanted].regime != "ring":
        rings = [s.name for s in constant.satellites if s.regime == "ring"]
        msg = (
            f"expected a satellite of {entry.name} inside its Laplace radius, among "
            f"{', '.join(rings) or 'none'}, got {satellite!r}"
        )
        raise ValueError(msg)
    share = shares[wanted]
    moon = catalogue.get(wanted)
    if age is None:
        age = catalogue.get("sun").require("age", "the migration's age").to("yr")
    age = check("migration_age", age)
    if index is None:
        rate = moon.require("migration_rate", "the index b of its migration").si()
        a = moon.require("semi_major_axis", "the index b of its migration").si()
        index = rate * age * JULIAN_YEAR / a
    index = _finite("index b", index)
    j2 = entry.require("j2", "the migration").value
    lam = entry.require("moment_of_inertia", "the migration").value
    others = [s for s in constant.satellites if s is not share and s.regime == "ring"]
    return SatelliteMigration(
        entry.name,
        moon.name,
        index,
        age,
        j2,
        lam,
        share.quadrupole,
        share.angular_momentum,
        sum(s.quadrupole for s in others),
        sum(s.angular_momentum for s in others),
        share.laplace_ratio,
    )
