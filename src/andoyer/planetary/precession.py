r"""Precession of a planet's spin axis about its ecliptic pole (Gurfil et al. §4.4.5–4.4.6).

The Sun (and, for the Earth, the Moon) torque the oblate planet
(:class:`~andoyer.perturbations.GravityGradient` on the mean orbits of
:func:`~andoyer.perturbations.solar_system.mean_perturbers`; reference plane
the planet's ecliptic of J2000). The angular momentum
``M = G (sin I sin h, -sin I cos h, cos I)`` then regresses about the ecliptic
pole ``s3``: the Andoyer node ``h`` decreases at the *precession rate*

.. math:: p = -\langle \dot h \rangle \approx \sum_p \frac{3\mu_p}{2 a_p^3 (1-e_p^2)^{3/2}\,\omega}
   \,\frac{C - (A+B)/2}{C}\,\cos\varepsilon\,\Big(1 - \frac32 \sin^2 i_p\Big),

(``μ_p`` the perturber's gravitational parameter, ``a_p, e_p, i_p`` its
orbit, the last factor the average over a regressing node; ``J = 0``),
reported in arcseconds per Julian year (the observed luni-solar precession
of the Earth is 50.38″/yr; Mars' 7.58″/yr; this model gives 50.40″/yr with the catalogue's
IAU MHB2000 ``H`` = 0.00327379492, 50.48″/yr with Lara's ``H`` = 0.0032789). Two computations:

* **secular**: the averaged model (``method="secular"`` of
  :func:`andoyer.integrate.propagation.propagate`) over ``secular_years``;
* **integrated**: the full torque (``method="splitting"``) over ``integrate``
  years, resolving the orbital motion of the perturbers and the daily
  rotation exactly in the free flow.

Both start ``NODE_PHASES`` states at initial nodes ``h₀ = 2πk/4``
(``J = 0``, ``I₀ = ε``) and average ``h(t) - h₀`` over them: every periodic
term of ``h`` depends on ``h`` through ``h - λ_p`` (``λ_p`` a perturber's
longitude or node) and appears with period 1 or 2 in ``h₀``, so the average
cancels the 18.6-year and semi-annual nutations that would otherwise swamp
a fit over a few years. The slope of ``h̄(t)`` is then fitted by least squares
together with the first three harmonics of each perturber's mean motion
(whose orbit covers at least 90% of the span, so that one Julian year keeps the
Sun's sidereal year): those absorb the modulation of the torque by
the orbital eccentricity, which does not depend on ``h₀``.

**Splitting step.** Successive kicks sample the body-fixed (triaxial) part of
the torque, which turns at twice the spin rate ``ω``: a step near a multiple
of half a rotation aliases it to a slow, spurious torque. :func:`default_step`
therefore takes an odd number of quarter rotations, so that successive kicks
alternate in sign, and at most 1/12 of the shortest orbital period (2.244
days for the Earth, 57.20 days for Mars). The precession is a first-order
effect of the torque, so order 2 suffices (the default). The span is
honoured exactly: the last step is shortened to end on it. Measured rates
(″/yr; one year for the Earth, 1.9 years for Mars, both rounded up to whole
steps when measured), with Lara's (2013) moments (``moments="lara2013"``; the
catalogue's default IAU ``H`` scales the Earth's rates by 0.998443: secular model
50.4002, full integration at the default step 50.4003): secular model 50.4788 and
7.5909; with the exact span, Mars at the default step gives 7.5886, the Earth 50.4789:

=====  ==========================  ======  =======  ========
body   step (rotations)            days    order 2  order 4
=====  ==========================  ======  =======  ========
Earth  2.25 (default)              2.244   50.4789  50.4789
Earth  8.25                        8.227   50.4790  50.4791
Earth  16.25                       16.21            50.4771
Mars   9.75                        10.00            7.5906
Mars   19.75                       20.26            7.5907
Mars   39.75                       40.78            7.5913
Mars   55.75 (default)             57.20   7.5904   7.5904
Mars   111.25                      114.1            7.5868
Mars   19.5 (resonant)             20.01            6.874
Mars   20.0 (resonant)             20.52            7.094
=====  ==========================  ======  =======  ========
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from andoyer import bodies, catalogue
from andoyer._limits import STEP_SECONDS, announce, check_size
from andoyer.body import RigidBody
from andoyer.catalogue.units import ARCSEC, DAY, JULIAN_YEAR
from andoyer.integrate.output import OUTPUT_BYTES
from andoyer.integrate.propagation import propagate
from andoyer.integrate.splitting import splitting_coefficients
from andoyer.perturbations.gravity import GravityGradient, PointMass
from andoyer.perturbations.model import Model
from andoyer.perturbations.solar_system import OBLIQUITY, mean_perturbers
from andoyer.planetary.parameters import check
from andoyer.state import State

__all__ = [
    "ARCSEC",
    "MOMENT_SETS",
    "NODE_PHASES",
    "PLANETS",
    "PrecessionRates",
    "check_dynamical_ellipticity",
    "default_step",
    "fit_trend",
    "mean_node_rate",
    "planet_body",
    "precession_problem",
    "precession_rates",
]

Array = NDArray[np.float64]

#: Initial nodes ``h₀ = 2πk/NODE_PHASES`` averaged over (cancels terms in ``h`` and ``2h``).
NODE_PHASES = 4
#: The planets with mean perturbers and an obliquity.
PLANETS = tuple(OBLIQUITY)
#: The named moment sets: the catalogue's (IAU MHB2000 ``H`` for the Earth) and Lara's (2013) Table 1.
MOMENT_SETS = ("catalogue", bodies.LARA_SET)
#: CPU seconds of one stage of one state of the full integration: the free flow and the kick of
#: the Sun's and the Moon's gravity gradient on their mean orbits (measured 160 µs with
#: ``time.process_time`` over 20 years of the Earth at the default step, 4 states; the free
#: splitting alone takes ``andoyer._limits.STEP_SECONDS``, 120 times less).
STAGE_SECONDS = 1.6e-4


def _planet(body: str) -> str:
    key = str(body).strip().lower()
    if key not in OBLIQUITY:
        msg = f"expected one of {', '.join(PLANETS)}, got {body!r}"
        raise ValueError(msg)
    return key


def check_dynamical_ellipticity(value: float) -> float:
    """``H = (C − (A+B)/2)/C`` as a float, or ``ValueError`` unless ``0 < H < 1/2``.

    The range of :data:`andoyer.planetary.parameters.PARAMETERS` (``"dynamical_ellipticity"``):
    ``A + B ≥ C`` (the triangle inequality) bounds ``H`` by one half; ``H ≤ 0`` is a prolate or
    spherical body, which does not precess this way.

    Examples
    --------
    >>> check_dynamical_ellipticity(0.0032737949)
    0.0032737949
    """
    return check("dynamical_ellipticity", value)


def _with_ellipticity(planet: RigidBody, dynamical_ellipticity: float | None) -> RigidBody:
    """``planet`` with ``(A + B)/2 = C (1 − H)`` and its ``B − A`` kept (unchanged when ``H`` is ``None``)."""
    if dynamical_ellipticity is None:
        return planet
    H = check_dynamical_ellipticity(dynamical_ellipticity)
    I1, I2, I3 = planet.moments
    mean = I3 * (1 - H)
    return RigidBody(mean - 0.5 * (I2 - I1), mean + 0.5 * (I2 - I1), I3, name=planet.name)


def _moment_set(moments: str | None) -> str | None:
    """``None`` for the catalogue's own moments, else the named set (refused unless known)."""
    if moments is None or moments == "catalogue":
        return None
    if moments not in MOMENT_SETS:
        msg = f"expected a moment set among {', '.join(MOMENT_SETS)}, got {moments!r}"
        raise ValueError(msg)
    return moments


def planet_body(body: str, moments: str | None = None) -> tuple[RigidBody, float]:
    """The planet's normalised :class:`~andoyer.RigidBody` (``C = 1``) and sidereal rotation period (s).

    The catalogue's moments and rotation by default (the Earth: the IAU MHB2000 ``H`` =
    0.00327379492 with Lara's ``B − A``, the IAU rotation rate); ``moments="lara2013"``: Lara's
    (2013) Table 1 moments and period (:mod:`andoyer.bodies`).

    Parameters
    ----------
    body : {"earth", "mars"}
    moments : {"catalogue", "lara2013"}, optional

    Returns
    -------
    planet : RigidBody
    rotation_period : float

    Examples
    --------
    >>> planet, period = planet_body("earth")
    >>> round(1 - (planet.A + planet.B) / 2, 11), round(period, 3)
    (0.00327379492, 86164.096)
    >>> planet, period = planet_body("earth", "lara2013")
    >>> round(1 - (planet.A + planet.B) / 2, 7), period
    (0.0032789, 86164.0905)
    """
    key = _planet(body)
    chosen = _moment_set(moments)
    if chosen is not None:
        info = bodies.info(key)
        return info.body, info.rotation_period
    entry = catalogue.get(key)
    if entry.rotation_period is not None:
        period = entry.rotation_period.si()
    else:
        period = 2 * np.pi / abs(entry.require("rotation_rate", "the precession rate").si())
    return entry.rigid_body(), float(period)


def precession_problem(
    body: str, dynamical_ellipticity: float | None = None, moments: str | None = None
) -> tuple[Model, State]:
    """The torqued planet and its ``NODE_PHASES`` initial states (shape (4,)).

    The planet spins about its figure axis ``b3`` (``J = 0``) at its sidereal
    rate, ``G = C ω``, at its obliquity ``I₀ = ε`` to the ecliptic, with nodes
    ``h₀ = 0, π/2, π, 3π/2``. Moments (normalised, ``C = 1``) and rotation period are the
    catalogue's (:func:`planet_body`; Lara's with ``moments="lara2013"``); the perturbers are
    :func:`~andoyer.perturbations.solar_system.mean_perturbers`.

    Parameters
    ----------
    body : {"earth", "mars"}
    dynamical_ellipticity : float, optional
        ``H = (C − (A+B)/2)/C`` to use instead of the named body's (its
        ``B − A`` kept).
    moments : {"catalogue", "lara2013"}, optional
        The moment set (default the catalogue's).

    Returns
    -------
    model : Model
    states : State, shape (4,)

    Examples
    --------
    >>> model, states = precession_problem("mars")
    >>> states.shape, model.perturbation
    ((4,), GravityGradient(RigidBody(I1=0.9942917, I2=0.9949813, I3=1.0, name='Mars'), [Sun]))
    """
    key = _planet(body)
    planet, period = planet_body(key, moments)
    planet = _with_ellipticity(planet, dynamical_ellipticity)
    G = planet.C * 2 * np.pi / period
    h0 = 2 * np.pi * np.arange(NODE_PHASES) / NODE_PHASES
    states = State.from_andoyer(0.0, 0.0, h0, G, G, G * np.cos(OBLIQUITY[key]))
    return Model(planet, GravityGradient(mean_perturbers(key))), states


def default_step(body: str, moments: str | None = None) -> float:
    """The splitting step (seconds) of :func:`precession_rates`: ``(2k+1)/4`` rotations, ≤ 1/12 orbit.

    The rotation is that of the moment set ``moments`` (:func:`planet_body`).

    Examples
    --------
    >>> round(default_step("earth") / 86400, 4), round(default_step("mars") / 86400, 4)
    (2.2439, 57.1971)
    """
    key = _planet(body)
    rotation = planet_body(key, moments)[1]
    shortest = min(2 * np.pi / p.orbit.mean_motion for p in mean_perturbers(key))
    quarters = int(4 * (shortest / 12) / rotation)
    quarters -= 1 - quarters % 2
    return quarters * rotation / 4


def fit_trend(t: Array, y: Array, frequencies: Any = ()) -> tuple[float, float, Array, Array]:
    r"""Least-squares trend of ``y(t)`` fitted together with periodic terms of known frequencies.

    Fits

    .. math:: y(t) \approx a + b\,t + \sum_j \big[c_j \cos \nu_j (t - t_0) + s_j \sin \nu_j (t - t_0)\big]

    (``t₀ = t[0]``), keeping only the frequencies ``ν_j`` of which the span holds at least 90%
    of a period (``ν_j (t_{-1} - t_0) ≥ 0.9 · 2π``): a much shorter arc of a sinusoid is nearly
    a straight line and would trade places with the trend, while the 10% margin keeps the Sun's
    orbit (a sidereal year, 365.256 d) in a fit over one Julian year.  Without the periodic
    terms a slope fitted over a span that is not a whole number of their periods is biased by
    them.

    Parameters
    ----------
    t : array_like, shape (T,)
        Times, at least ``2 + 2 × (number of kept frequencies)``.
    y : array_like, shape (T,)
    frequencies : array_like, shape (F,)
        Angular frequencies ``ν_j`` (radians per unit of ``t``; the sign does not matter).

    Returns
    -------
    offset : float
        ``a``, the trend's value at ``t = 0``.
    rate : float
        ``b``.
    periodic : numpy.ndarray, shape (T,)
        The fitted periodic terms at ``t``.
    kept : numpy.ndarray, shape (K,)
        The frequencies fitted (``|ν_j|`` of which the span holds 90% of a period or more).

    Examples
    --------
    >>> t = np.linspace(0.0, 10.0, 201)
    >>> y = 1.0 - 0.5 * t + 0.1 * np.sin(2 * np.pi * t / 3)
    >>> round(fit_trend(t, y)[1], 4)                          # a straight line alone is biased
    -0.501
    >>> offset, rate, periodic, kept = fit_trend(t, y, [2 * np.pi / 3, 0.1])  # 0.1: period > span
    >>> round(offset, 12), round(rate, 12), round(float(np.max(np.abs(periodic))), 6), kept.size
    (1.0, -0.5, 0.1, 1)
    """
    t = np.asarray(t, dtype=float)
    y = np.asarray(y, dtype=float)
    nu = np.abs(np.asarray(frequencies, dtype=float).reshape(-1))
    if t.ndim != 1 or y.shape != t.shape:
        msg = f"expected times (T,) and values (T,), got shapes {t.shape} and {y.shape}"
        raise ValueError(msg)
    for name, value in (("times", t), ("values", y), ("frequencies", nu)):
        if not np.all(np.isfinite(value)):
            msg = f"expected finite {name}, got {value[~np.isfinite(value)][:3]}"
            raise ValueError(msg)
    span = t[-1] - t[0] if t.size else 0.0
    if span == 0:
        msg = f"expected times spanning a nonzero interval, got {t.size} times from {t[:1]} to {t[-1:]}"
        raise ValueError(msg)
    nu = nu[nu * abs(span) >= 0.9 * 2 * np.pi]
    if t.size < 2 + 2 * nu.size:
        msg = f"expected at least {2 + 2 * nu.size} times for the fit, got {t.size}"
        raise ValueError(msg)
    # Time in units of the span from t₀: the columns are then all of order one.
    x = (t - t[0]) / span
    waves = [f(w * span * x) for w in nu for f in (np.cos, np.sin)]
    design = np.stack([np.ones_like(x), x, *waves], axis=-1)
    coefficients = np.linalg.lstsq(design, y, rcond=None)[0]
    rate = coefficients[1] / span
    return float(coefficients[0] - rate * t[0]), float(rate), design[:, 2:] @ coefficients[2:], nu


def mean_node_rate(t: Array, h: Array, perturbers: list[PointMass] | tuple[PointMass, ...] = ()) -> float:
    """Least-squares mean rate of the node ``h`` (rad per unit of ``t``), short-period terms removed.

    Fits ``h̄(t) = a + b t + Σ_p Σ_{k=1..3} [c_pk cos(k n_p t) + s_pk sin(k n_p t)]`` to the
    average ``h̄`` over the last axis of ``h`` (the initial-node phases), keeping
    the harmonics of each perturber that covers at least 90% of its orbit in the span
    (:func:`fit_trend`).

    Parameters
    ----------
    t : array_like, shape (T,)
    h : array_like, shape (T,) or (T, P)
        Unwrapped node longitudes (radians) minus their initial values.
    perturbers : sequence of PointMass
        Their ``orbit.mean_motion`` gives the harmonics.

    Returns
    -------
    float
        ``b``.

    Examples
    --------
    >>> from andoyer.perturbations import CircularOrbit
    >>> moon = PointMass(1.0, CircularOrbit(1.0, 2 * np.pi / 3))  # mean motion 2π/3
    >>> t = np.linspace(0.0, 10.0, 201)
    >>> h = -0.5 * t + 0.1 * np.sin(2 * np.pi * t / 3) + 0.02 * np.cos(4 * np.pi * t / 3)
    >>> round(mean_node_rate(t, h), 4), round(mean_node_rate(t, h, [moon]), 12)  # trend alone is biased
    (-0.5014, -0.5)
    """
    t = np.asarray(t, dtype=float)
    mean = np.asarray(h, dtype=float)
    if mean.ndim == 2:
        mean = mean.mean(axis=-1)
    if t.ndim != 1 or mean.shape != t.shape or t.size < 3:
        msg = (
            f"expected times (T,) with T >= 3 and node values (T,) or (T, P), got {t.shape} and {np.shape(h)}"
        )
        raise ValueError(msg)
    # A perturber's overtones are fitted only with its fundamental: alone they would fit the
    # part of an unresolved orbit that is its motion's trend.
    span = float(t[-1] - t[0])
    harmonics = [
        k * p.orbit.mean_motion
        for p in perturbers
        if p.orbit.mean_motion * span >= 0.9 * 2 * np.pi
        for k in (1, 2, 3)
    ]
    return fit_trend(t, mean, harmonics)[1]


def _node(states: State, h0: Array | float) -> Array:
    """Andoyer's node ``h = atan2(M1, -M2)`` minus ``h0``, unwrapped along the first (time) axis."""
    M = states.m_reference
    return np.unwrap(np.arctan2(M[..., 0], -M[..., 1]) - h0, axis=0)


def _integration_steps(years: float, step: float, order: int, n_states: int) -> int:
    """Whole steps of the full integration, refused when the step or the size is not sensible."""
    if not (np.isfinite(step) and step > 0):
        msg = f"expected a positive finite step in seconds, got {step!r}"
        raise ValueError(msg)
    span = years * JULIAN_YEAR
    if not step <= span / 2:
        msg = (
            f"expected a step of at most half the span so that the fit has three points "
            f"({span / 2:.6g} s for integrate={years!r} years), got step={step!r} s"
        )
        raise ValueError(msg)
    steps = np.floor(span / step)
    # one output per step (each holds every state), refused before anything is allocated; the
    # time at the measured cost of a stage of this model, in elementary steps of the free splitting
    stages = (steps + 1) * len(splitting_coefficients(order)) * n_states
    check_size(
        "a precession integration",
        steps=stages * STAGE_SECONDS / STEP_SECONDS,
        nbytes=(steps + 2) * (8 + 2 * OUTPUT_BYTES * n_states),
    )
    return int(steps)


@dataclass(frozen=True)
class PrecessionRates:
    """Precession rates of a planet's angular momentum about its ecliptic pole, arcseconds per Julian year.

    Attributes
    ----------
    body : str
    perturbers : tuple of str
    obliquity : float
        Radians.
    secular : float
        From the averaged model.
    integrated : float or None
        From the full splitting integration (``None`` when not asked).
    years : float or None
        Span of the full integration, Julian years.
    step : float or None
        Its splitting step, seconds.
    """

    body: str
    perturbers: tuple[str, ...]
    obliquity: float
    secular: float
    integrated: float | None = None
    years: float | None = None
    step: float | None = None

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready fields (obliquity in degrees, step in days)."""
        return {
            "body": self.body,
            "perturbers": list(self.perturbers),
            "obliquity_deg": float(np.degrees(self.obliquity)),
            "secular_arcsec_per_year": self.secular,
            "integrated_arcsec_per_year": self.integrated,
            "integration_years": self.years,
            "step_days": None if self.step is None else self.step / DAY,
        }


def precession_rates(
    body: str,
    integrate: float | None = None,
    step: float | None = None,
    order: int = 2,
    secular_years: float = 100.0,
    dynamical_ellipticity: float | None = None,
    moments: str | None = None,
) -> PrecessionRates:
    """Precession rate of ``body``'s angular momentum: secular model, and optionally a full integration.

    Parameters
    ----------
    body : {"earth", "mars"}
    integrate : float, optional
        Years of full (splitting) integration, honoured exactly (the last step is
        shortened to end there); none by default. At least one orbit of the slowest
        perturber is needed to remove its eccentricity modulation (one year for the
        Earth, 1.9 for Mars).
    step : float, optional
        Splitting step in seconds (default :func:`default_step`), at most half the span.
    order : {2, 4, 6}
        Splitting order (2 suffices for the mean rate; see the module docstring).
    secular_years : float
        Span of the secular integration.
    dynamical_ellipticity : float, optional
        ``H = (C − (A+B)/2)/C`` instead of the named body's; the rates are
        proportional to it.
    moments : {"catalogue", "lara2013"}, optional
        The moment set: the catalogue's (default; the Earth's IAU MHB2000 ``H`` =
        0.00327379492 gives 50.40″/yr on the mean orbits) or Lara's (2013) Table 1
        (``H = 0.0032789``: 50.48″/yr).

    Returns
    -------
    PrecessionRates

    Raises
    ------
    ValueError
        For a step longer than half the span, or a run that cannot fit in memory or
        time (:func:`andoyer._limits.check_size`).

    Examples
    --------
    >>> rates = precession_rates("earth")
    >>> rates.perturbers, round(rates.secular, 2)
    (('Sun', 'Moon'), 50.4)
    >>> round(precession_rates("earth", moments="lara2013").secular, 2)
    50.48
    >>> precession_rates("earth", integrate=1.0, step=1e8)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: expected a step of at most half the span ... got step=100000000.0 s
    """
    key = _planet(body)
    model, states = precession_problem(key, dynamical_ellipticity, moments)
    perturbers = mean_perturbers(key)
    M0 = states.m_reference
    h0 = np.arctan2(M0[:, 0], -M0[:, 1])
    for name, value in (("integrate", integrate), ("secular_years", secular_years)):
        if value is not None and not (np.isfinite(value) and value > 0):
            msg = f"expected a positive number of years for {name}, got {value!r}"
            raise ValueError(msg)
    if integrate is not None:  # every refusal before the secular run
        step = default_step(key, moments) if step is None else float(step)
        count = _integration_steps(integrate, step, order, states.size)
        seconds = (count + 1) * len(splitting_coefficients(order)) * states.size * STAGE_SECONDS
        announce(seconds, f"integrating the full torque on {key.capitalize()} over {integrate:g} years")
    t = np.linspace(0.0, secular_years * JULIAN_YEAR, 401)
    mean = propagate(model, states, t[:, None], method="secular")
    secular = -mean_node_rate(t, _node(mean, h0)) * JULIAN_YEAR / ARCSEC
    rates = PrecessionRates(key, tuple(p.name for p in perturbers), float(OBLIQUITY[key]), secular)
    if integrate is None:
        return rates
    span = integrate * JULIAN_YEAR
    t = step * np.arange(count + 1)
    if span - t[-1] > 1e-9 * step:  # the span exactly: the last step is shortened to end there
        t = np.append(t, span)
    full = propagate(model, states, t[:, None], method="splitting", step=step, order=order)
    integrated = -mean_node_rate(t, _node(full, h0), perturbers) * JULIAN_YEAR / ARCSEC
    return PrecessionRates(key, rates.perturbers, rates.obliquity, secular, integrated, integrate, step)
