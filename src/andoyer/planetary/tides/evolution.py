r"""Tidal histories of the Earth–Moon system: integration, outputs, calibration, validity.

The state ``(a, ω, ε)`` starts from today's (:class:`EarthMoonSystem`) at J2000 and is
integrated forward and backward to the requested times by a compiled Dormand–Prince 5(4)
(:func:`andoyer.planetary.tides.equations.advance`; steps end on the output times). From it:

* ``lunar_distance`` = ``a`` (km), the semi-major axis of the circular relative orbit;
* ``day_length`` = ``2π/(ω − n_⊙)`` (hours), the mean solar day (24 h today);
* ``dynamical_ellipticity`` ``H(ω) = H₀ (ω/ω₀)²``: the hydrostatic flattening scales with the
  centrifugal potential, ``J₂ = k_f ω² R³/(3GM)`` at first order (Lambeck 1980, *The Earth's
  variable rotation*; Néron de Surgy & Laskar 1997; Farhat et al. 2022 scale ``C`` the same way);
* ``precession_constant`` ``p = α cos ε`` (″/yr), with the precession constant of Laskar et
  al. (2004, §7, their Eq. for ``α``)

  .. math:: \alpha = \frac{3}{2}\frac{H(\omega)}{\omega}\Big[\frac{GM_\odot}{a_\odot^3(1-e_\odot^2)^{3/2}}
            + \frac{GM_M}{a^3(1-e_M^2)^{3/2}}\big(1 - \tfrac32\sin^2 i_M\big)\Big],

  ``e_M``, ``i_M``, ``e_⊙`` held at today's values. ``p`` is the frequency of the axial
  precession that cyclostratigraphy measures (``k`` of Meyers & Malinverno 2018); La2004 give
  50.475838″/yr for today's mean value (see the docs for how this model's 50.40″/yr compares).

**Validity.** The averaging over the lunar node about the ecliptic pole holds while the Moon is
outside the Laplace-plane transition, ``a > r_L``, ``r_L⁵ = J₂(ω) R² a_⊙³ (1 − e_⊙²)^{3/2} M_E/M_⊙``
(Tremaine, Touma & Namouni 2009; Goldreich 1966): 8.4 Earth radii today, more when the Earth
spun faster. A history that would cross it raises ``ValueError`` naming the time.
Times are limited to ±4.425 Gyr, the age of the Moon (Maurice et al. 2020).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._validation import as_finite
from andoyer.catalogue.units import ARCSEC, HOUR, JULIAN_YEAR
from andoyer.planetary.parameters import check
from andoyer.planetary.tides import equations
from andoyer.planetary.tides.response import ConstantTimeLag, OceanTides, TidalResponse
from andoyer.planetary.tides.system import EarthMoonSystem

__all__ = [
    "LUNAR_AGE",
    "MEASURED_RECESSION",
    "TidalHistory",
    "calibrate",
    "kernel_constants",
    "present_rates",
    "tidal_history",
    "tidal_model",
]

Array = NDArray[np.float64]

#: The age of the Moon, years: 4.425 ± 0.025 Gyr (Maurice et al. 2020, Sci. Adv. 6, eaba8949),
#: the constraint of Farhat et al. (2022); no history reaches further.
LUNAR_AGE = 4.425e9
#: The lunar recession measured by lunar laser ranging, m/yr: 38.30 ± 0.08 mm/yr (Williams &
#: Boggs 2016, Celest. Mech. Dyn. Astr. 126, 89; the value of Farhat et al. 2022).
MEASURED_RECESSION = 0.03830
#: Default relative tolerance of the integrator (per step, on ``a/a₀``, ``ω/ω₀``, ``ε``).
DEFAULT_RTOL = 1e-11
#: The named models of :func:`tidal_model`.
MODELS = ("ocean", "constant-lag")


def kernel_constants(response: TidalResponse, system: EarthMoonSystem) -> Array:
    """The constants vector of the compiled kernels (:data:`equations.SIZE` numbers, SI).

    Parameters
    ----------
    response : TidalResponse
    system : EarthMoonSystem

    Returns
    -------
    numpy.ndarray, shape (SIZE,)
    """
    if not isinstance(response, TidalResponse):
        msg = f"expected a tidal response (ConstantTimeLag, ConstantPhaseLag, OceanTides), got {response!r}"
        raise ValueError(msg)
    if not isinstance(system, EarthMoonSystem):
        msg = f"expected an EarthMoonSystem, got {type(system).__name__}"
        raise ValueError(msg)
    s = system
    c = np.zeros(equations.SIZE)
    c[equations.A0] = s.lunar_semi_major_axis
    c[equations.W0] = s.spin_rate
    c[equations.MU] = s.gm_earth + s.gm_moon
    c[equations.MRED] = s.reduced_mass
    c[equations.C0] = s.polar_moment
    c[equations.CC] = s.centrifugal_moment
    c[equations.PMOON] = 1.5 * s.gm_moon**2 * s.equatorial_radius**5 / s.gravitational_constant
    c[equations.PSUN] = (
        1.5 * s.gm_sun**2 * s.equatorial_radius**5 / s.gravitational_constant / s.solar_semi_major_axis**6
    )
    c[equations.NSUN] = s.solar_mean_motion
    c[equations.KIND] = response.kind
    c[equations.P1 : equations.P4 + 1] = response.kernel_parameters(s)
    orbit = s.solar_semi_major_axis**3 * (1.0 - s.solar_eccentricity**2) ** 1.5
    c[equations.LAPLACE] = s.j2 * s.equatorial_radius**2 * orbit * s.gm_earth / s.gm_sun
    return c


def _start(system: EarthMoonSystem, obliquity: float | None) -> tuple[float, float, float]:
    eps = system.obliquity if obliquity is None else check("obliquity", obliquity)
    return 1.0, 1.0, float(eps)


def present_rates(
    response: str | TidalResponse, system: EarthMoonSystem | None = None, solar_tide: bool = True
) -> dict[str, float]:
    """Today's tidal rates from the model's own equations.

    Parameters
    ----------
    response : str or TidalResponse
        A model's name (:func:`tidal_model`) or a response.
    system : EarthMoonSystem, optional
    solar_tide : bool
        Include the Sun's tide on the Earth (it slows the spin, not the Moon).

    Returns
    -------
    dict
        ``recession`` (cm/yr), ``day_length_rate`` (ms per century, of the mean solar day),
        ``spin_acceleration`` (rad/s², ``dω/dt``), ``obliquity_rate`` (″ per Myr).

    Examples
    --------
    >>> rates = present_rates("constant-lag")
    >>> round(rates["recession"], 3)  # cm/yr: the calibration (LLR, Williams & Boggs 2016)
    3.83
    """
    s = EarthMoonSystem() if system is None else system
    c = kernel_constants(tidal_model(response, s) if isinstance(response, str) else response, s)
    x, w, e = _start(s, None)
    dx, dw, de = equations.rates(x, w, e, c, 1 if solar_tide else 0)
    omega_dot = dw * s.spin_rate / JULIAN_YEAR  # rad/s²
    synodic = s.spin_rate - s.solar_mean_motion
    century_ms = JULIAN_YEAR * 100 * 1e3
    return {
        "recession": dx * s.lunar_semi_major_axis * 100.0,
        "day_length_rate": -2 * math.pi / synodic**2 * omega_dot * century_ms,
        "spin_acceleration": omega_dot,
        "obliquity_rate": de / ARCSEC * 1e6,
    }


def calibrate(
    system: EarthMoonSystem | None = None, recession: float = MEASURED_RECESSION
) -> ConstantTimeLag:
    """The constant time lag whose lunar recession today is ``recession`` (m/yr).

    ``da/dt`` is linear in ``k₂Δt``, so the calibration is one division.

    Parameters
    ----------
    system : EarthMoonSystem, optional
    recession : float
        m/yr (default: LLR, 3.830 cm/yr).

    Returns
    -------
    ConstantTimeLag

    Examples
    --------
    >>> round(calibrate().k2_time_lag, 1)  # seconds; k2 = 0.30 gives Δt ≈ 660 s
    198.7
    """
    if not (isinstance(recession, int | float) and math.isfinite(recession) and 0 < recession < 1):
        msg = f"expected a lunar recession in (0, 1) m/yr, got {recession!r}"
        raise ValueError(msg)
    s = EarthMoonSystem() if system is None else system
    unit = present_rates(ConstantTimeLag(1.0), s)["recession"] / 100.0
    return ConstantTimeLag(recession / unit)


def tidal_model(name: str, system: EarthMoonSystem | None = None) -> TidalResponse:
    """The named model: ``"ocean"`` or ``"constant-lag"``.

    ``"ocean"`` is the reference, :class:`OceanTides` with its fitted parameters;
    ``"constant-lag"`` the constant time lag calibrated to the LLR recession.

    Parameters
    ----------
    name : {"ocean", "constant-lag"}
    system : EarthMoonSystem, optional

    Returns
    -------
    TidalResponse

    Examples
    --------
    >>> tidal_model("ocean").name
    'ocean'
    >>> tidal_model("darwin")
    Traceback (most recent call last):
    ...
    ValueError: expected a tidal model in ocean, constant-lag, got 'darwin'
    """
    key = str(name).strip().lower()
    if key == "ocean":
        return OceanTides()
    if key == "constant-lag":
        return calibrate(system)
    msg = f"expected a tidal model in {', '.join(MODELS)}, got {name!r}"
    raise ValueError(msg)


@dataclass(frozen=True, eq=False)
class TidalHistory:
    """The Earth–Moon system at the output times (arrays of shape (N,)).

    Attributes
    ----------
    t : ndarray
        Julian years from J2000 (negative: past).
    lunar_distance : ndarray
        ``a``, km.
    day_length : ndarray
        The mean solar day ``2π/(ω − n_⊙)``, hours.
    spin_rate : ndarray
        ``ω``, rad/s.
    obliquity : ndarray
        ``ε``, radians.
    dynamical_ellipticity : ndarray
        ``H = H₀(ω/ω₀)²``.
    precession_constant : ndarray
        ``p = α cos ε``, ″/yr.
    model : str
        The response's name.
    """

    t: Array
    lunar_distance: Array
    day_length: Array
    spin_rate: Array
    obliquity: Array
    dynamical_ellipticity: Array
    precession_constant: Array
    model: str

    def as_dict(self) -> dict[str, object]:
        """The JSON fields of ``andoyer tides``: lists, angles in degrees.

        Returns
        -------
        dict
            ``t``, ``day_length``, ``lunar_distance``, ``precession_constant``, ``obliquity``
            (deg), ``dynamical_ellipticity``, ``model``.
        """
        return {
            "t": self.t.tolist(),
            "day_length": self.day_length.tolist(),
            "lunar_distance": self.lunar_distance.tolist(),
            "precession_constant": self.precession_constant.tolist(),
            "obliquity": np.degrees(self.obliquity).tolist(),
            "dynamical_ellipticity": self.dynamical_ellipticity.tolist(),
            "model": self.model,
        }


def _describe(states: Array, system: EarthMoonSystem) -> dict[str, Array]:
    s = system
    x, w, eps = states[:, 0], states[:, 1], states[:, 2]
    a = x * s.lunar_semi_major_axis
    omega = w * s.spin_rate
    ellipticity = s.dynamical_ellipticity * w * w
    sun = s.gm_sun / s.solar_semi_major_axis**3 / (1.0 - s.solar_eccentricity**2) ** 1.5
    moon = (
        s.gm_moon / a**3 * (1.0 - 1.5 * math.sin(s.lunar_inclination) ** 2)
        / (1.0 - s.lunar_eccentricity**2) ** 1.5
    )
    alpha = 1.5 * ellipticity / omega * (sun + moon)
    return {
        "lunar_distance": a / 1e3,
        "day_length": 2 * math.pi / (omega - s.solar_mean_motion) / HOUR,
        "spin_rate": omega,
        "obliquity": eps,
        "dynamical_ellipticity": ellipticity,
        "precession_constant": alpha * np.cos(eps) * JULIAN_YEAR / ARCSEC,
    }


def integrate_states(
    times: Array, c: Array, start: tuple[float, float, float], solar_tide: bool, rtol: float, name: str
) -> Array:
    """``(a/a₀, ω/ω₀, ε)`` at ``times`` (increasing), from ``start`` at J2000; ValueError past validity."""
    out = np.empty((times.size, 3))
    for side in (times > 0, times < 0):
        targets = times[side]
        if targets.size == 0:
            continue
        ordered = targets if targets[0] > 0 else targets[::-1]
        buffer = np.empty((ordered.size, 3))
        _, status, t_stop = equations.advance(
            *start, np.ascontiguousarray(ordered), c, 1 if solar_tide else 0, rtol, buffer
        )
        if status == 1:
            bound, side_word = ("after", "before") if t_stop < 0 else ("before", "after")
            got = targets.min() if t_stop < 0 else targets.max()
            msg = (
                f"expected times {bound} {t_stop:.4g} years: the {name} model brings the Moon to the "
                f"Laplace-plane transition there (a = r_L, 8 to 14 Earth radii), {side_word} which its "
                f"averaging over the lunar node does not hold; got {got:.4g}"
            )
            raise ValueError(msg)
        if status != 0:
            msg = f"expected a history the integrator can follow, got status {status} at {t_stop:.4g} years"
            raise ValueError(msg)
        out[side] = buffer if targets[0] > 0 else buffer[::-1]
    out[times == 0] = start
    return out


def tidal_history(
    times: ArrayLike,
    model: str | TidalResponse = "ocean",
    system: EarthMoonSystem | None = None,
    *,
    solar_tide: bool = True,
    obliquity: float | None = None,
    rtol: float = DEFAULT_RTOL,
) -> TidalHistory:
    """The lunar distance, day length, obliquity, ``H`` and precession constant at ``times``.

    Parameters
    ----------
    times : array_like, shape (N,)
        Increasing Julian years from J2000 (negative: past), within ±:data:`LUNAR_AGE`.
    model : str or TidalResponse
        ``"ocean"`` (default, after Farhat et al. 2022), ``"constant-lag"`` (calibrated to
        lunar laser ranging), or a response object.
    system : EarthMoonSystem, optional
        Today's numbers (default :class:`EarthMoonSystem()`).
    solar_tide : bool
        The Sun's tide on the Earth (on by default; off, the Earth–Moon angular momentum is
        conserved).
    obliquity : float, optional
        The obliquity at J2000 (radians; default the system's, IAU 2006).
    rtol : float
        Relative tolerance per step, in [1e-13, 1e-4].

    Returns
    -------
    TidalHistory

    Raises
    ------
    ValueError
        Times out of range or past the model's validity (the Moon below the Laplace-plane
        transition), bad parameters.

    Examples
    --------
    >>> h = tidal_history([-2.46e9, -6.2e8, 0.0], "constant-lag")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: expected times after -1.145e+09 years: the constant-lag model brings the Moon ...
    >>> h = tidal_history([-6.2e8, 0.0], "ocean")
    >>> [round(float(v), 1) for v in h.day_length]  # hours; Elatina rhythmites (620 Ma): 21.9 ± 0.4
    [20.7, 24.0]
    """
    s = EarthMoonSystem() if system is None else system
    response = tidal_model(model, s) if isinstance(model, str) else model
    t = as_finite(times, "times")
    if t.ndim != 1 or t.size == 0 or np.any(np.diff(t) <= 0):
        msg = f"expected increasing output times (1-D, non-empty), got shape {t.shape}"
        raise ValueError(msg)
    if t[0] < -LUNAR_AGE or t[-1] > LUNAR_AGE:
        msg = f"expected times within ±{LUNAR_AGE:.4g} years (the Moon's age), got {t[0]:.4g} to {t[-1]:.4g}"
        raise ValueError(msg)
    if not (isinstance(rtol, int | float) and 1e-13 <= rtol <= 1e-4):
        msg = f"expected a relative tolerance in [1e-13, 1e-4], got {rtol!r}"
        raise ValueError(msg)
    c = kernel_constants(response, s)
    states = integrate_states(t, c, _start(s, obliquity), solar_tide, float(rtol), response.name)
    return TidalHistory(t=t, model=response.name, **_describe(states, s))
