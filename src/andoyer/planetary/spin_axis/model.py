r"""The averaged torque on a planet's spin axis: strengths, precession rate, tides.

**Derivation.** :class:`~andoyer.perturbations.averaged_gravity.SecularGravityGradient` averages the
gravity-gradient disturbance of a perturber ``p`` (gravitational parameter ``μ_p``, orbit
``a_p, e_p``, normal ``k_p``) over the body's rotation and the perturber's mean anomaly:
``⟨ΔH⟩ = κ_p (m̂·k_p)²`` with ``κ_p = −3μ_p (C − (A+B)/2)(3cos²J − 1)/(8 a_p³(1−e_p²)^{3/2})``
and ``dM/dt = 2κ_p (M·k_p) k_p×M / G²``. For a planet spinning about its figure axis
(``J = 0``, ``M = G s``, ``G = C ω``) this is, for the unit spin axis ``s``,

.. math:: \dot{\mathbf s} = \alpha_p\,(1-e_p^2)^{-3/2}\,(\mathbf s\cdot\mathbf k_p)
   \,(\mathbf s\times\mathbf k_p),
   \qquad \alpha_p = \frac{3}{2}\frac{\mu_p}{a_p^3\,\omega}\,H, \qquad H = \frac{C - (A+B)/2}{C},

``H`` the dynamical ellipticity. For the Sun ``k_p`` is the planet's own orbit normal
``n``, and ``e_p`` its eccentricity ``e(t)``. The Moon's orbit is inclined by
``i_M = 5.145°`` to the ecliptic and its node regresses in 18.6 years; averaging
``(s·k)(s×k)`` over the node (``k = n cos i_M + u sin i_M``, ``⟨u uᵀ⟩ = (1 − n nᵀ)/2``)
gives ``(1 − 3/2 sin² i_M)(s·n)(s×n)``. The total is

.. math:: \dot{\mathbf s} = \alpha(t)\,(\mathbf s\cdot\mathbf n)\,(\mathbf s\times\mathbf n), \qquad
   \alpha(t) = \alpha_\odot\Big[(1-e(t)^2)^{-3/2} + \beta\Big], \qquad
   \beta = \frac{\mu_M a^3}{\mu_\odot a_M^3}\,\frac{1 - \tfrac32\sin^2 i_M}{(1-e_M^2)^{3/2}},

with ``β ≈ 2.16`` for the Earth (the Moon's share is 68 %) and ``β = 0`` for Mars. With
``s·n > 0`` the axis turns about ``n`` at the angular velocity ``−α (s·n) n``: westward
(retrograde), the luni-solar precession.

**The precession rate.** At J2000 the axis turns about the ecliptic of J2000 at
``ψ̇ = α(0) cos ε₀`` (``ε₀`` the obliquity at J2000): the rate of the IAU 2006 angle ``ψ_A``
(luni-solar precession of the equator on the *fixed* ecliptic of J2000; 5038.481507″/cy,
Capitaine, Wallace & Chapront 2003, A&A 412, 567, eq. 37). A user's precession rate ``P`` (″/yr)
is that ``ψ̇``, from which ``α_⊙ = P / (cos ε₀ [(1−e(0)²)^{-3/2} + β])``. It absorbs
everything that acts like a constant precession at J2000: the geodetic precession
(−0.0191″/yr in ``ψ_A``) and the second-order nutation terms are in the IAU value and hence in
``α``; their (tiny) changes with the obliquity over time are not modelled.

**Tidal dissipation** (Zeebe & Lourens 2022, Paleoceanography and Paleoclimatology 37,
e2021PA004349, their C code ``snvec``; after Quinn, Tremaine & Duncan 1991, AJ 101, 2287,
eqs. 3 and 11, and Lambeck 1980): ``T_d`` scales the modern tidal rates linearly, the Moon's
mean motion by ``ṅ_M/n_M = −4.6×10⁻¹⁸ s⁻¹ · T_d`` and the Earth's spin by
``ω̇/ω = 51 (n_M/ω) ṅ_M/n_M`` (Lambeck 1980). With a hydrostatic ellipticity ``H ∝ ω²``
the constant ``α ∝ H/ω ∝ ω``, and the Moon's torque ``∝ a_M^{−3} ∝ n_M²``; to first order in
``t`` (years from J2000)

.. math:: \alpha(t) = \alpha_\odot\,(1 + W T_d t)\,(1 + \dot H_r t)\,
   \Big[(1-e^2)^{-3/2} + \beta\,(1 + 2 N T_d t)\Big],

``N = ṅ_M/n_M`` and ``W = ω̇/ω`` per year at ``T_d = 1``, and ``Ḣ_r`` an optional linear
drift of ``H`` (fraction per year). ``T_d = 0`` (the default) is no tidal change.

Sources of the constants: :mod:`andoyer.perturbations.solar_system` (the Sun's and the
Moon's mean orbits); :mod:`andoyer.catalogue` (rotation periods, the default precession rates
and the Earth's ``H`` = 0.00327379492 of MHB2000, Bourda & Capitaine 2004 Table 2; IERS
Conventions 2010 Table 1.1 round it to 0.0032737949).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer import catalogue
from andoyer.catalogue import Body
from andoyer.catalogue.units import ARCSEC, JULIAN_YEAR
from andoyer.perturbations.solar_system import mean_perturbers
from andoyer.planetary.parameters import PARAMETERS, check

__all__ = [
    "ARCSEC",
    "DEFAULT_PRECESSION_RATE",
    "EARTH_DYNAMICAL_ELLIPTICITY",
    "MOON_MEAN_MOTION_RATE",
    "SpinAxisModel",
]

Array = NDArray[np.float64]

#: Default ``ψ̇`` at J2000, ″/yr, the catalogue's ``precession_rate``: the Earth's IAU 2006
#: ``dψ_A/dt`` (5038.481507″/cy, Capitaine et al. 2003, eq. 37); Mars 7.597″/yr (radio tracking of
#: landers and orbiters gives 7.59–7.61″/yr: Konopliv et al. 2016, Icarus 274, 253; Le Maistre et
#: al. 2023, Nature 619, 733).
DEFAULT_PRECESSION_RATE = {
    key: catalogue.get(key).require("precession_rate", "the spin axis").to("arcsec/yr")
    for key in ("earth", "mars")
}
#: The Earth's dynamical ellipticity ``H = (C − (A+B)/2)/C``, the catalogue's (MHB2000).
EARTH_DYNAMICAL_ELLIPTICITY = catalogue.get("earth").require("dynamical_ellipticity", "the spin axis").value
#: ``ṅ_M/n_M`` of the Moon at ``T_d = 1``, per second (Quinn et al. 1991, eq. 3; Zeebe & Lourens 2022).
MOON_MEAN_MOTION_RATE = -4.6e-18
#: ``ω̇/ω = 51 (n_M/ω) ṅ_M/n_M`` (Lambeck 1980, as in Zeebe & Lourens 2022).
_LAMBECK = 51.0


def _solar_terms(body: str | Body) -> tuple[float, float, float, float, float]:
    """``(n_⊙² [rad²/s²], e(J2000), β, ω [rad/s], n_M/ω)`` of a planet.

    The Earth and Mars: their mean perturbers (:mod:`andoyer.perturbations.solar_system`); any
    other body (a catalogued planet or a body of the user's own): the catalogue's orbit and
    rotation and its satellites outside the Laplace radius
    (:func:`andoyer.planetary.precession_constant.precession_constant`).
    """
    if isinstance(body, Body) or body not in DEFAULT_PRECESSION_RATE:
        from andoyer.planetary.precession_constant import precession_constant

        c = precession_constant(body)
        if c.resonance is not None:
            msg = (
                f"expected a body out of spin-orbit resonance for the spin axis (its obliquity is a Cassini "
                f"state: andoyer cassini), got {c.body} in a {c.resonance:g}:1 resonance"
            )
            raise ValueError(msg)
        return c.mean_motion_squared, c.eccentricity, c.outer_torque, c.spin_rate, 0.0
    return _named_solar_terms(body)


@functools.cache
def _named_solar_terms(body: str) -> tuple[float, float, float, float, float]:
    """:func:`_solar_terms` of the Earth or Mars, once per process: every member of an ensemble needs them."""
    perturbers = mean_perturbers(body)
    sun = perturbers[0]
    n2 = sun.gm / sun.orbit.semi_major_axis**3
    entry = catalogue.get(body)
    if entry.rotation_period is not None:
        omega = 2 * np.pi / entry.rotation_period.si()
    else:
        omega = abs(entry.require("rotation_rate", "the spin axis").si())
    beta = 0.0
    ratio = 0.0
    for moon in perturbers[1:]:
        o = moon.orbit
        beta += (
            moon.gm
            / o.semi_major_axis**3
            / n2
            * (1 - 1.5 * np.sin(o.inclination) ** 2)
            / ((1 - o.eccentricity) * (1 + o.eccentricity)) ** 1.5
        )
        ratio = o.mean_motion / omega
    return n2, sun.orbit.eccentricity, beta, omega, ratio


@dataclass(frozen=True)
class SpinAxisModel:
    r"""Strength of the averaged solar (and lunar) torque on a spin axis, and its slow changes.

    ``α(t, e) = alpha_sun (1 + tide_spin·t)(1 + ellipticity_drift·t)
    [(1−e²)^{−3/2} + beta (1 + tide_moon·t)]`` in radians per Julian year, ``t`` in Julian
    years from J2000 (see the module docstring).

    Parameters
    ----------
    body : str
    alpha_sun : float
        ``α_⊙``, rad/yr.
    beta : float
        The Moon's share relative to a circular-orbit Sun (0 without a moon).
    eccentricity : float
        The orbit's eccentricity used when the orbit source does not know it.
    tide_spin, tide_moon : float
        ``W T_d`` and ``2 N T_d``, per year.
    ellipticity_drift : float
        ``Ḣ/H``, per year: for a planet with satellites, the drift of its effective ellipticity
        ``(J2 + q)/(λ + l)``, that is of ``α`` (satellite migration, ``α(t) = α₀ (1 + t/τ)``).
    entry : Body, optional
        A body of the user's own (its orbit and rotation); ``None`` for a catalogued body.
    satellite_rings : bool
        Whether satellites inside the Laplace radius are in the figure (the effective
        ellipticity is then bounded only below, :meth:`check_span`).

    Examples
    --------
    >>> model = SpinAxisModel.from_precession_rate("earth", 50.38481507, np.radians(84381.406 / 3600))
    >>> round(model.precession_rate(np.radians(84381.406 / 3600)), 8)
    50.38481507
    >>> round(model.beta, 3)
    2.161
    """

    body: str
    alpha_sun: float
    beta: float
    eccentricity: float
    tide_spin: float = 0.0
    tide_moon: float = 0.0
    ellipticity_drift: float = 0.0
    entry: Body | None = field(default=None, compare=False, repr=False)
    satellite_rings: bool = field(default=False, compare=False, repr=False)

    def __post_init__(self) -> None:
        numbers = {
            "alpha_sun": self.alpha_sun,
            "beta": self.beta,
            "tide_spin": self.tide_spin,
            "tide_moon": self.tide_moon,
            "ellipticity_drift": self.ellipticity_drift,
        }
        for name, value in numbers.items():
            if not (isinstance(value, int | float | np.floating) and np.isfinite(value)):
                msg = f"expected a finite real {name}, got {value!r}"
                raise ValueError(msg)
        if self.alpha_sun <= 0 or self.beta < 0:
            msg = f"expected alpha_sun > 0 and beta >= 0, got {self.alpha_sun!r}, {self.beta!r}"
            raise ValueError(msg)
        check("eccentricity", self.eccentricity)

    @staticmethod
    def _tides(body: str | Body, tidal_dissipation: float) -> tuple[float, float]:
        tidal_dissipation = check("tidal_dissipation", tidal_dissipation)
        _, _, beta, _, ratio = _solar_terms(body)
        if tidal_dissipation != 0 and beta == 0:
            msg = f"expected tidal dissipation 0 for a planet without a moon, got {tidal_dissipation!r}"
            raise ValueError(msg)
        nu = MOON_MEAN_MOTION_RATE * JULIAN_YEAR * tidal_dissipation
        return _LAMBECK * ratio * nu, 2 * nu

    @classmethod
    def from_dynamical_ellipticity(
        cls,
        body: str,
        ellipticity: float,
        tidal_dissipation: float = 0.0,
        ellipticity_drift: float = 0.0,
    ) -> SpinAxisModel:
        """The model of ``body`` from its dynamical ellipticity ``H = (C − (A+B)/2)/C``.

        ``α_⊙ = (3/2) n_⊙² H / ω`` with the project's mean orbits and rotation periods.

        Parameters
        ----------
        body : {"earth", "mars"}
        ellipticity : float
            ``H``, positive.
        tidal_dissipation : float
            ``T_d`` (Zeebe & Lourens 2022), 1 = modern rates.
        ellipticity_drift : float
            ``Ḣ/H`` per Julian year.

        Returns
        -------
        SpinAxisModel

        Examples
        --------
        >>> model = SpinAxisModel.from_dynamical_ellipticity("earth", EARTH_DYNAMICAL_ELLIPTICITY)
        >>> round(model.precession_rate(np.radians(84381.406 / 3600)), 2)  # ″/yr; IAU 2006: 50.38
        50.4
        """
        key, entry = _body(body)
        ellipticity = check("dynamical_ellipticity", ellipticity)
        drift = check("ellipticity_drift", ellipticity_drift)
        n2, e0, beta, omega, _ = _solar_terms(entry or key)
        alpha = 1.5 * n2 * ellipticity / omega * JULIAN_YEAR
        spin, moon = cls._tides(entry or key, tidal_dissipation)
        return cls(key, float(alpha), float(beta), float(e0), spin, moon, drift, entry)

    @classmethod
    def from_precession_rate(
        cls,
        body: str,
        rate: float,
        obliquity: float,
        eccentricity: float | None = None,
        tidal_dissipation: float = 0.0,
        ellipticity_drift: float = 0.0,
    ) -> SpinAxisModel:
        """The model whose precession rate ``ψ̇ = α(0) cos ε₀`` at J2000 is ``rate`` (″/yr).

        Parameters
        ----------
        body : {"earth", "mars"}
        rate : float
            ``ψ̇`` at J2000, arcseconds per Julian year (positive: westward).
        obliquity : float
            ``ε₀``, the obliquity at J2000 (radians).
        eccentricity : float, optional
            The orbit's ``e`` at J2000 (default: the body's mean orbit).
        tidal_dissipation, ellipticity_drift : float
            As in :meth:`from_dynamical_ellipticity`.

        Returns
        -------
        SpinAxisModel

        Examples
        --------
        >>> model = SpinAxisModel.from_precession_rate("mars", 7.597, np.radians(25.19))
        >>> round(model.dynamical_ellipticity(), 5)
        0.00537
        """
        key, entry = _body(body)
        rate = check("precession_rate", rate)
        obliquity = check("obliquity", obliquity)
        drift = check("ellipticity_drift", ellipticity_drift)
        n2, e0, beta, omega, _ = _solar_terms(entry or key)
        e = e0 if eccentricity is None else check("eccentricity", eccentricity)
        alpha = rate * ARCSEC / (np.cos(obliquity) * (((1 - e) * (1 + e)) ** -1.5 + beta))
        # The rate and the ellipticity are one parameter (α_⊙ = (3/2) n_⊙² H / ω): H's bound
        # A + B ≥ C is the rate's bound, for this body at this obliquity and eccentricity.
        H = float(alpha / JULIAN_YEAR * omega / (1.5 * n2))
        if not PARAMETERS["dynamical_ellipticity"].contains(H):
            top = rate * PARAMETERS["dynamical_ellipticity"].high / H
            msg = (
                f"expected a precession rate P < {top:.6g} arcsec/yr for {key} at an obliquity of "
                f"{np.degrees(obliquity):.4g} deg (the rate of H = 1/2: A + B >= C bounds the dynamical "
                f"ellipticity H = (C - (A+B)/2)/C by 1/2), got {rate!r} (H = {H:.4g})"
            )
            raise ValueError(msg)
        spin, moon = cls._tides(entry or key, tidal_dissipation)
        return cls(key, float(alpha), float(beta), e, spin, moon, drift, entry)

    @classmethod
    def from_precession_constant(
        cls, body: str | Body, ellipticity_drift: float = 0.0, eccentricity: float | None = None
    ) -> SpinAxisModel:
        """The model of any planet from its catalogued figure and satellites.

        ``α_⊙ = (3/2)(μ_⊙/a³ω)(J2 + q)/(λ + l)`` and ``β = Σ β_k``
        (:func:`andoyer.planetary.precession_constant.precession_constant`: the satellites inside
        the Laplace radius in the figure, those outside as perturbers).

        Parameters
        ----------
        body : str or Body
            A catalogued planet or a body of the user's own.
        ellipticity_drift : float
            ``1/τ`` per Julian year: ``α(t) = α₀ (1 + t/τ)`` (satellite migration).
        eccentricity : float, optional
            The orbit's ``e`` at J2000 (default: the catalogue's).

        Returns
        -------
        SpinAxisModel

        Examples
        --------
        >>> model = SpinAxisModel.from_precession_constant("saturn")
        >>> round(model.precession_rate(np.radians(26.73)), 3)  # ″/yr, Titan's ring included
        0.73
        """
        from andoyer.planetary.precession_constant import precession_constant

        key, entry = _body(body)
        drift = check("ellipticity_drift", ellipticity_drift)
        c = precession_constant(entry or key)
        n2, e0, beta, omega, _ = _solar_terms(entry or key)
        e = e0 if eccentricity is None else check("eccentricity", eccentricity)
        alpha = 1.5 * n2 * c.figure / omega * JULIAN_YEAR
        rings = any(s.regime == "ring" for s in c.satellites)
        return cls(key, float(alpha), float(beta), float(e), 0.0, 0.0, drift, entry, rings)

    def check_span(self, t0: float, t1: float) -> None:
        """Refuse a span over which the model's linear drifts leave their ranges.

        ``H (1 + ellipticity_drift · t)`` must stay within the dynamical ellipticity's range
        (``0 < H < 1/2``; only positive for a planet whose satellites' rings make its effective
        ``(J2 + q)/(λ + l)``, which ``A + B ≥ C`` does not bound) and the tidal factors
        ``1 + tide_spin · t``, ``1 + tide_moon · t`` positive, from J2000 (where the axis starts)
        to either end; all are linear in ``t``, so the ends decide.

        Parameters
        ----------
        t0, t1 : float
            Julian years from J2000.

        Examples
        --------
        >>> model = SpinAxisModel.from_dynamical_ellipticity("earth", 0.00327, ellipticity_drift=1e-6)
        >>> model.check_span(-1000.0, 1000.0)
        >>> model.check_span(-2e6, 0.0)  # doctest: +ELLIPSIS
        Traceback (most recent call last):
        ...
        ValueError: expected an ellipticity drift that keeps 0 < H < 0.5 over the span, got H = -0.00327 ...
        """
        H = self.dynamical_ellipticity()
        for t in (float(t0), float(t1)):
            Ht = H * (1 + self.ellipticity_drift * t)
            if self.satellite_rings and not Ht > 0:
                msg = (
                    f"expected a drift that keeps the precession constant positive over the span, got "
                    f"1 + t/TAU = {1 + self.ellipticity_drift * t:.4g} at t = {t:g} years (drift "
                    f"{self.ellipticity_drift!r} per year)"
                )
                raise ValueError(msg)
            if not self.satellite_rings and not PARAMETERS["dynamical_ellipticity"].contains(Ht):
                bounds = PARAMETERS["dynamical_ellipticity"].describe()
                msg = (
                    f"expected an ellipticity drift that keeps {bounds} over the span, got H = {Ht:.4g} "
                    f"at t = {t:g} years (drift {self.ellipticity_drift!r} per year)"
                )
                raise ValueError(msg)
            factors = (1 + self.tide_spin * t, 1 + self.tide_moon * t)
            if not min(factors) > 0:
                # 1 + k t vanishes at t = -1/k: the model's horizon on that side of J2000
                edge = min(
                    (-1 / k for k in (self.tide_spin, self.tide_moon) if k != 0 and -1 / k * t > 0),
                    key=abs,
                )
                msg = (
                    f"expected a span within the linear tidal model's range (its factors 1 + k t reach "
                    f"zero at t = {edge:.4g} years), got t = {t:g} years; a smaller tidal dissipation "
                    f"(0: none) or the Earth-Moon tidal model (obliquity --tides) reaches further"
                )
                raise ValueError(msg)

    def rate(self, t: ArrayLike, e: ArrayLike | None = None) -> Array:
        """``α(t, e)``, radians per Julian year.

        Parameters
        ----------
        t : array_like, shape (...)
            Julian years from J2000.
        e : array_like, shape (...), optional
            The orbit's eccentricity (default: ``self.eccentricity``).

        Returns
        -------
        numpy.ndarray, shape (...)

        Examples
        --------
        >>> model = SpinAxisModel("mars", 1.0, 0.0, 0.0)
        >>> float(model.rate(0.0, 0.6))  # (1 - 0.36)^(-3/2)
        1.953125
        """
        t = np.asarray(t, dtype=np.float64)
        e = self.eccentricity if e is None else np.asarray(e, dtype=np.float64)
        factor = (1 + self.tide_spin * t) * (1 + self.ellipticity_drift * t)
        return self.alpha_sun * factor * (((1 - e) * (1 + e)) ** -1.5 + self.beta * (1 + self.tide_moon * t))

    def precession_rate(self, obliquity: float, e: float | None = None) -> float:
        """``ψ̇ = α(0) cos ε`` in arcseconds per Julian year.

        Parameters
        ----------
        obliquity : float
            Radians.
        e : float, optional

        Returns
        -------
        float
        """
        return float(self.rate(0.0, e) * np.cos(obliquity) / ARCSEC)

    def dynamical_ellipticity(self) -> float:
        """``H = 2 α_⊙ ω / (3 n_⊙²)`` implied by ``α_⊙``.

        Returns
        -------
        float
        """
        n2, _, _, omega, _ = _solar_terms(self.entry or self.body)
        return float(self.alpha_sun / JULIAN_YEAR * omega / (1.5 * n2))


def _body(body: str | Body) -> tuple[str, Body | None]:
    """The body's key and, for a body of the user's own, the body itself (unknown names refused)."""
    if isinstance(body, Body):
        if body.key in catalogue.names() and catalogue.get(body.key) is body:
            return body.key, None
        return body.name, body
    key = str(body).strip().lower()
    if key not in DEFAULT_PRECESSION_RATE and key not in catalogue.names():
        msg = f"expected a body in {', '.join(DEFAULT_PRECESSION_RATE)} or the catalogue, got {body!r}"
        raise ValueError(msg)
    return key, None
