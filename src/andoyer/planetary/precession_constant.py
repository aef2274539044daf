r"""The precession constant ``α`` of any body, its satellites' share included (``ψ̇ = α cos ε``).

**The Sun alone.** The orbit-averaged torque of the Sun (gravitational parameter ``μ_⊙``, the
body's orbit ``a, e``) on an oblate body spinning at ``ω`` about its figure axis turns the unit
spin axis ``s`` about the orbit normal ``n`` as ``ṡ = α (s·n)(s×n)``
(:mod:`andoyer.planetary.spin_axis.model` derives it), with

.. math:: \alpha_\odot = \frac{3}{2}\,\frac{\mu_\odot}{a^3\,\omega}\,(1-e^2)^{-3/2}\,\frac{J_2}{\lambda},
   \qquad \frac{J_2}{\lambda} = \frac{C - (A+B)/2}{C} = H,

``J2`` and ``λ = C/MR²`` referred to the same radius ``R``. The axis then precesses at
``ψ̇ = α cos ε`` (``ε`` the obliquity, the angle from ``n`` to the spin angular momentum:
``ε > 90°`` for a retrograde rotator such as Venus or Uranus, whose ``ψ̇`` is then negative:
the axis precesses the other way).

**Satellites inside the Laplace radius** (Goldreich 1965; Ward & Hamilton 2004, AJ 128, 2501;
French et al. 1993, Icarus 103, 163; Saillenfest, Lari & Courtot 2020, A&A 640, A11). A
satellite ``k`` of mass ``m_k`` on an orbit ``a_k`` well inside the Laplace radius

.. math:: r_L^5 = J_2 R^2 a^3 (1-e^2)^{3/2}\, \frac{M}{M_\odot}

(Tremaine, Touma & Namouni 2009, AJ 137, 3706) has its node precess about its Laplace plane,
close to the planet's equator, much faster than the planet's axis precesses: averaged over its
node, it is a ring of mass ``m_k`` and radius ``a_k`` that the planet's ``J2`` carries along. The
Sun torques the ring as it torques the planet's bulge, and the ring's angular momentum moves
with the spin: the system precesses with

.. math:: \alpha = \frac{3}{2}\,\frac{\mu_\odot}{a^3\,\omega}\,(1-e^2)^{-3/2}\,
   \frac{J_2 + q}{\lambda + l}, \qquad
   q = \frac12\sum_k \frac{m_k}{M}\Big(\frac{a_k}{R}\Big)^2 P_2(\cos i_k)\,
        \frac{\sin 2(\varepsilon - L_k)}{\sin 2\varepsilon}, \qquad
   l = \sum_k \frac{m_k}{M}\Big(\frac{a_k}{R}\Big)^2 \frac{n_k}{\omega}\cos i_k\,
        \frac{\sin(\varepsilon - L_k)}{\sin\varepsilon},

``n_k² a_k³ = G(M + m_k)``, ``i_k`` the satellite's inclination to its Laplace plane (the ring
averaged over its node is the quadrupole ``P₂(cos i_k) = (3cos²i_k − 1)/2`` of a ring in that
plane, and its angular momentum along the plane's pole is ``cos i_k`` of the orbit's: Triton's
retrograde orbit, ``i = 157°``, has ``l < 0``), and ``L_k`` the tilt of the Laplace plane from
the equator towards the orbit (catalogue ``laplace_tilt``; zero where not catalogued): the Sun's
torque on a quadrupole tilted by ``ε − L_k`` from the orbit normal is ``∝ sin 2(ε − L_k)``, and the
ring's angular momentum that precesses with the spin ``∝ sin(ε − L_k)``. With ``L_k = 0`` and
``i_k = 0`` this is Ward & Hamilton's ``α = 3n²/(2ω) (J2 + q)/(λ + l)``.

**Satellites outside the Laplace radius** (the Moon: ``r_L`` = 8.4 Earth radii) keep their orbit
plane near the planet's orbit and torque the planet directly, as the Sun does: each adds
``β_k = (μ_k/a_k³)(1 − e_k²)^{-3/2}(1 − ³⁄₂ sin² i_k) / (μ_⊙/a³)`` (averaged over its regressing
node, ``i_k`` to the planet's orbit) to the Sun's ``(1 − e²)^{-3/2}``:
``α = (3/2)(μ_⊙/(a³ω)) (J2 + q)/(λ + l) [(1 − e²)^{-3/2} + Σ β_k]``.

**A body in spin-orbit resonance** (``resonance`` ``p``: the Moon, the Galilean satellites,
Titan, Mercury) rotates at ``ω = p n`` and its ``C22`` is not averaged out:
``α = (3/2)(μ_p/(a³ω)) [J2 (1 − e²)^{-3/2} + C22 G_p(e)]/λ`` (Peale 1969;
:mod:`andoyer.planetary.cassini.body`, whose states it enters).

**What is left out.** The planets' direct torques (a few 10⁻³ of the Sun's for the Earth), the
satellites not in the catalogue (Saturn: Rhea adds 0.3 % to ``q``, Iapetus, near the Laplace
radius, is left out; Jupiter: the small inner satellites), Callisto's position near Jupiter's
Laplace radius (0.93 ``r_L``: the ring picture is approximate), the satellites' own mutual
forcing, the dissipative core-mantle and atmospheric torques (Venus), relativity.
``moment_of_inertia`` of the giant planets comes from interior models (catalogue notes).

Examples
--------
>>> from andoyer.catalogue.units import ARCSEC
>>> earth = precession_constant("earth")
>>> round(earth.alpha / ARCSEC, 3), round(earth.precession_rate, 3)  # ″/yr; ψ̇ = α cos ε
(54.933, 50.4)
>>> [(s.name, s.regime) for s in earth.satellites]
[('Moon', 'outer')]
>>> saturn = precession_constant("saturn")
>>> round(saturn.precession_rate, 3), [s.name for s in saturn.satellites]
(0.73, ['Titan', 'Enceladus'])
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from andoyer import catalogue
from andoyer.catalogue import Body
from andoyer.catalogue.units import ARCSEC, JULIAN_YEAR

__all__ = [
    "PrecessionConstant",
    "SatelliteShare",
    "obliquity",
    "precession_constant",
    "satellites_of",
    "spin_axis_ecliptic",
]


@dataclass(frozen=True)
class SatelliteShare:
    """One satellite's share of a planet's precession constant.

    Attributes
    ----------
    name : str
    regime : {"ring", "outer"}
        Inside the Laplace radius (a ring carried by the equator: ``quadrupole`` and
        ``angular_momentum``) or outside (a perturber torquing the planet: ``torque``).
    quadrupole : float
        Its term of ``q`` (0 for an outer satellite).
    angular_momentum : float
        Its term of ``l`` (0 for an outer satellite).
    torque : float
        ``β_k``, its torque over the Sun's on a circular orbit (0 for a ring).
    laplace_ratio : float
        ``a_k / r_L``.
    """

    name: str
    regime: str
    quadrupole: float
    angular_momentum: float
    torque: float
    laplace_ratio: float

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready fields."""
        return {
            "name": self.name,
            "regime": self.regime,
            "quadrupole": self.quadrupole,
            "angular_momentum": self.angular_momentum,
            "torque": self.torque,
            "laplace_ratio": self.laplace_ratio,
        }


@dataclass(frozen=True)
class PrecessionConstant:
    """A body's precession constant and what it is made of (rates in radians per Julian year).

    Attributes
    ----------
    body : str
    alpha : float
        ``α`` at the catalogue's eccentricity, satellites included.
    solar : float
        ``α`` of the primary's torque on the body alone (no satellite; for a body in spin-orbit
        resonance, its ``J2`` part).
    obliquity : float or None
        ``ε`` (radians), from the catalogue's ``obliquity`` or the IAU pole and the orbit; ``None``
        where neither is known (a satellite's orbit on its Laplace plane).
    eccentricity : float
    figure : float
        ``(J2 + q)/(λ + l)``, the effective dynamical ellipticity (``H`` without satellites).
    laplace_radius : float or None
        ``r_L`` (km) where the planet's ``J2`` and radius are known.
    satellites : tuple of SatelliteShare
    resonance : float or None
        The spin-orbit ratio of a resonant body.
    mean_motion_squared : float
        ``μ_p/a³`` of the primary's torque (s⁻²).
    spin_rate : float
        ``|ω|`` (rad/s).
    """

    body: str
    alpha: float
    solar: float
    obliquity: float | None
    eccentricity: float
    figure: float
    laplace_radius: float | None
    satellites: tuple[SatelliteShare, ...] = ()
    resonance: float | None = None
    mean_motion_squared: float = 0.0
    spin_rate: float = 0.0

    @property
    def outer_torque(self) -> float:
        """``Σ β_k`` of the satellites outside the Laplace radius."""
        return sum(s.torque for s in self.satellites)

    @property
    def precession_rate(self) -> float | None:
        """``ψ̇ = α cos ε`` in ″/yr (negative: the axis precesses the other way; ``None`` without ``ε``)."""
        if self.obliquity is None:
            return None
        return self.alpha * math.cos(self.obliquity) / ARCSEC

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready fields: constants and rates in ″/yr, the obliquity in degrees."""
        return {
            "precession_constant": self.alpha / ARCSEC,
            "solar_precession_constant": self.solar / ARCSEC,
            "precession_rate": self.precession_rate,
            "obliquity_deg": None if self.obliquity is None else math.degrees(self.obliquity),
            "effective_ellipticity": self.figure,
            "laplace_radius_km": self.laplace_radius,
            "resonance": self.resonance,
            "satellites": [s.as_dict() for s in self.satellites],
        }


def _si(body: Body, key: str, computation: str) -> float:
    return body.require(key, computation).si()


def _primary(body: Body, computation: str) -> Body:
    if not body.primary:
        msg = (
            f"expected {body.name} to have a primary (the body it orbits) for {computation}, got none "
            "(give 'primary' in the body file)"
        )
        raise ValueError(msg)
    return catalogue.get(body.primary)


def _spin_rate(body: Body, computation: str) -> float:
    """``|ω|`` in rad/s from the rotation period, else the IAU rotation rate."""
    if body.rotation_period is not None:
        return 2 * math.pi / body.rotation_period.si()
    return abs(_si(body, "rotation_rate", computation))


def _retrograde(body: Body) -> bool:
    return body.rotation_rate is not None and body.rotation_rate.value < 0


def satellites_of(body: str | Body) -> tuple[Body, ...]:
    """The catalogued satellites of a catalogued body (none for a body of the user's own).

    Examples
    --------
    >>> [s.name for s in satellites_of("uranus")]
    ['Miranda', 'Ariel', 'Umbriel', 'Titania', 'Oberon']
    """
    entry = catalogue.get(body)
    names = catalogue.names()
    if entry.key not in names or catalogue.get(entry.key) is not entry:
        return ()
    return tuple(
        s for s in (catalogue.get(n) for n in names) if s.primary == entry.key and s.kind == "satellite"
    )


def obliquity(body: str | Body) -> float | None:
    """The obliquity ``ε`` (radians) of a body's spin angular momentum to its orbit normal.

    The catalogue's ``obliquity`` where it has one; else, for a body on a heliocentric orbit in
    the mean ecliptic of J2000, the angle between the IAU pole (``pole_ra``, ``pole_dec`` at J2000,
    turned to the ecliptic by the Earth's ``ε₀`` = 84381.406″) and the orbit normal (``inclination``,
    ``node``); the spin angular momentum is opposite the IAU pole for a retrograde rotator
    (``rotation_rate < 0``). ``None`` when neither is known.

    Examples
    --------
    >>> [round(math.degrees(obliquity(b)), 2) for b in ("venus", "jupiter", "saturn", "uranus", "neptune")]
    [177.36, 3.12, 26.73, 97.77, 28.32]
    """
    entry = catalogue.get(body)
    if entry.obliquity is not None:
        return entry.obliquity.si()
    needed = (entry.pole_ra, entry.pole_dec, entry.inclination, entry.node)
    if any(v is None for v in needed) or "ecliptic" not in entry.orbit_frame:
        return None
    s = spin_axis_ecliptic(entry)
    i, node = entry.inclination.si(), entry.node.si()
    n = (math.sin(i) * math.sin(node), -math.sin(i) * math.cos(node), math.cos(i))
    dot = sum(a * b for a, b in zip(s, n, strict=True))
    return math.acos(max(-1.0, min(1.0, dot)))


def spin_axis_ecliptic(body: str | Body) -> tuple[float, float, float]:
    """The unit spin angular momentum at J2000 in the J2000 ecliptic frame, from the IAU pole.

    The pole at J2000 is ``(pole_ra + pole_ra_periodic, pole_dec + pole_dec_periodic)`` (the IAU
    WGCCRE 2015 model with its periodic terms where the catalogue has them: Mars, Jupiter,
    Neptune), turned from the ICRF equator to the ecliptic by ``ε₀``; opposite the IAU (north)
    pole for a retrograde rotator.

    Examples
    --------
    >>> [round(x, 6) for x in spin_axis_ecliptic("earth")]  # the ICRF pole: (0, sin ε₀, cos ε₀)
    [0.0, 0.397777, 0.917482]
    """
    entry = catalogue.get(body)
    ra = _si(entry, "pole_ra", "the spin axis")
    dec = _si(entry, "pole_dec", "the spin axis")
    if entry.pole_ra_periodic is not None:  # the IAU model's periodic terms at J2000
        ra += entry.pole_ra_periodic.si()
    if entry.pole_dec_periodic is not None:
        dec += entry.pole_dec_periodic.si()
    eps0 = catalogue.get("earth").require("obliquity", "the J2000 ecliptic").si()
    x, y, z = math.cos(dec) * math.cos(ra), math.cos(dec) * math.sin(ra), math.sin(dec)
    c, s = math.cos(eps0), math.sin(eps0)
    v = (x, c * y + s * z, -s * y + c * z)
    return tuple(-u for u in v) if _retrograde(entry) else v  # type: ignore[return-value]


def _figure(body: Body, computation: str) -> tuple[float, float | None, float | None]:
    """``(H, J2, λ)``: ``H`` from the moments or ``J2/λ``; ``J2``, ``λ`` where catalogued."""
    j2 = None if body.j2 is None else body.j2.value
    lam = None if body.moment_of_inertia is None else body.moment_of_inertia.value
    if body.dynamical_ellipticity is not None or (body.a_over_c is not None and body.b_over_c is not None):
        a, b = body.moments()
        return 1 - (a + b) / 2, j2, lam
    if j2 is None or lam is None:
        missing = [k for k, v in (("j2", j2), ("moment_of_inertia", lam)) if v is None]
        msg = (
            f"expected {body.name} to have dynamical_ellipticity, a_over_c and b_over_c, or j2 and "
            f"moment_of_inertia for {computation}, got none of {', '.join(missing)} (give them in a body "
            f"file: andoyer bodies {body.key} --format json shows the keys)"
        )
        raise ValueError(msg)
    return j2 / lam, j2, lam


def _resonant(body: Body, computation: str) -> PrecessionConstant:
    """``α`` of a body in a ``p:1`` spin-orbit resonance (``C22`` not averaged out)."""
    from andoyer.planetary.cassini.body import eccentricity_function

    p = body.resonance.value  # type: ignore[union-attr]
    primary = _primary(body, computation)
    mu = _si(primary, "gm", computation)
    a = _si(body, "semi_major_axis", computation)
    e = body.require("eccentricity", computation).value
    j2 = body.require("j2", computation).value
    c22 = body.require("c22", computation).value
    lam = body.require("moment_of_inertia", computation).value
    gm = 0.0 if body.gm is None else body.gm.si()
    n = math.sqrt((mu + gm) / a**3)
    scale = 1.5 * (mu / a**3) / (p * n) / lam * JULIAN_YEAR
    x = (1 - e * e) ** -1.5
    g = float(eccentricity_function(e, p))
    alpha = scale * (j2 * x + c22 * g)
    return PrecessionConstant(
        body.name,
        alpha,
        scale * j2 * x,
        obliquity(body),
        e,
        (j2 + c22 * g / x) / lam,
        None,
        (),
        p,
        mu / a**3,
        p * n,
    )


def precession_constant(
    body: str | Body, satellites: bool = True, dynamical_ellipticity: float | None = None
) -> PrecessionConstant:
    """The precession constant ``α`` of a catalogued body or a body of the user's own.

    Parameters
    ----------
    body : str or Body
        A catalogue name or a :class:`~andoyer.catalogue.Body` (:func:`andoyer.catalogue.read_body`).
    satellites : bool
        Include the catalogued satellites (a body of the user's own has none).
    dynamical_ellipticity : float, optional
        ``H`` in place of the body's figure (``0 < H < 1/2``); refused for a body whose satellites
        inside its Laplace radius need ``J2`` and ``λ`` apart (give those in a body file).

    Returns
    -------
    PrecessionConstant

    Raises
    ------
    ValueError
        Naming the body and the first value it lacks (``gm`` of its primary, ``semi_major_axis``,
        ``eccentricity``, the rotation, ``j2`` and ``moment_of_inertia`` or ``H``; the satellites'
        ``gm``, ``semi_major_axis``, the planet's ``radius`` and ``gm`` where it has satellites).

    Examples
    --------
    >>> from andoyer.catalogue.units import ARCSEC
    >>> jupiter = precession_constant("jupiter")
    >>> round(jupiter.alpha / ARCSEC, 3), round(jupiter.solar / ARCSEC, 3)
    (2.604, 0.907)
    >>> precession_constant("pluto")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: expected Pluto to have dynamical_ellipticity, ... got none of j2, moment_of_inertia ...
    """
    entry = catalogue.get(body)
    computation = "the precession constant"
    if dynamical_ellipticity is not None:
        from andoyer.planetary.parameters import check

        check("dynamical_ellipticity", dynamical_ellipticity)
        if entry.resonance is not None:
            msg = (
                f"expected no dynamical ellipticity for {entry.name}, a body in spin-orbit resonance (its "
                "constant needs j2, c22 and moment_of_inertia: give them in a body file), "
                f"got {dynamical_ellipticity!r}"
            )
            raise ValueError(msg)
    if entry.resonance is not None:
        return _resonant(entry, computation)
    primary = _primary(entry, computation)
    mu_sun = _si(primary, "gm", computation)
    a = _si(entry, "semi_major_axis", computation)
    e = entry.require("eccentricity", computation).value
    omega = _spin_rate(entry, computation)
    if dynamical_ellipticity is None:
        H, j2, lam = _figure(entry, computation)
    else:
        H, j2, lam = float(dynamical_ellipticity), None, None
    eps = obliquity(entry)
    base = 1.5 * mu_sun / (a**3 * omega) * JULIAN_YEAR  # rad/yr per unit of figure
    x = (1 - e * e) ** -1.5
    moons = satellites_of(entry) if satellites else ()
    r_l = None
    if entry.j2 is not None and entry.radius is not None and entry.gm is not None:
        R = entry.radius.si()
        r_l = (entry.j2.value * R**2 * a**3 * (1 - e * e) ** 1.5 * entry.gm.si() / mu_sun) ** 0.2
    shares = []
    q = l = beta = 0.0
    for moon in moons:
        what = f"{entry.name}'s precession constant (its satellite {moon.name})"
        m = _si(moon, "gm", what)
        ak = _si(moon, "semi_major_axis", what)
        ik = 0.0 if moon.inclination is None else moon.inclination.si()
        ek = 0.0 if moon.eccentricity is None else moon.eccentricity.value
        if r_l is None:
            entry.require("j2", what)
            entry.require("radius", what)
            entry.require("gm", what)
        ratio = ak / r_l  # type: ignore[operator]
        if ratio < 1:
            if dynamical_ellipticity is not None:
                msg = (
                    f"expected no dynamical ellipticity for {entry.name}, whose satellite {moon.name} inside "
                    f"the Laplace radius needs j2 and moment_of_inertia apart (give them in a body file), "
                    f"got {dynamical_ellipticity!r}"
                )
                raise ValueError(msg)
            if j2 is None or lam is None:
                entry.require("moment_of_inertia" if j2 is not None else "j2", what)
            M = entry.gm.si()  # type: ignore[union-attr]
            R = entry.radius.si()  # type: ignore[union-attr]
            tilt = 0.0 if moon.laplace_tilt is None else moon.laplace_tilt.si()
            along, across = 1.0, 1.0
            if tilt and eps is not None and math.sin(2 * eps) != 0:
                along = math.sin(2 * (eps - tilt)) / math.sin(2 * eps)
                across = math.sin(eps - tilt) / math.sin(eps)
            size = m / M * (ak / R) ** 2
            nk = math.sqrt((M + m) / ak**3)
            qk = 0.5 * size * (1.5 * math.cos(ik) ** 2 - 0.5) * along
            lk = size * nk / omega * math.cos(ik) * across
            q, l = q + qk, l + lk
            shares.append(SatelliteShare(moon.name, "ring", qk, lk, 0.0, ratio))
        else:
            bk = m / ak**3 / (mu_sun / a**3) * (1 - 1.5 * math.sin(ik) ** 2) * (1 - ek * ek) ** -1.5
            beta += bk
            shares.append(SatelliteShare(moon.name, "outer", 0.0, 0.0, bk, ratio))
    figure = H if not (q or l) else (j2 + q) / (lam + l)  # type: ignore[operator]
    alpha = base * figure * (x + beta)
    return PrecessionConstant(
        entry.name,
        alpha,
        base * H * x,
        eps,
        e,
        figure,
        None if r_l is None else r_l / 1e3,
        tuple(shares),
        None,
        mu_sun / a**3,
        omega,
    )
