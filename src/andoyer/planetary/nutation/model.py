"""The model of :mod:`andoyer.planetary.nutation`: constants, axes, and the right-hand sides of the angles.

``ψ̇`` and ``ε̇`` of the Earth's angular-momentum axis under the Moon's and the
Sun's spin-averaged torque, as functions of the Delaunay arguments (see the
package docstring for the equations).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from andoyer import catalogue
from andoyer.catalogue.units import ARCSEC, JULIAN_YEAR
from andoyer.perturbations.lunar_theory import moon_ecliptic, sun_ecliptic
from andoyer.perturbations.solar_system import GM_MOON, GM_SUN

__all__ = ["ARCSEC", "AXES", "EARTH_ROTATION", "H_MHB2000", "MEAN_OBLIQUITY", "PRINCIPAL_TERMS"]

Array = NDArray[np.float64]

_EARTH = catalogue.get("earth")
#: Earth's nominal mean (inertial) angular velocity, rad/s: the catalogue's ``spin_rate``, 7.292115e-5
#: (GRS80; IERS Conventions 2010, Table 1.2).
EARTH_ROTATION = _EARTH.spin_rate.si()
#: Dynamical ellipticity ``(C − (A+B)/2)/C`` of MHB2000 (Mathews et al. 2002): the catalogue's.
H_MHB2000 = _EARTH.dynamical_ellipticity.value
#: Mean obliquity of the ecliptic at J2000.0, IAU 2006: 84381.406″ (the catalogue's).
MEAN_OBLIQUITY = _EARTH.obliquity.si()
#: The axes whose nutation is offered.
AXES = ("figure", "momentum", "rotation")
#: The principal terms: name -> multipliers of ``(l, l′, F, D, Ω)``.
PRINCIPAL_TERMS = {
    "Ω": (0, 0, 0, 0, 1),
    "2Ω": (0, 0, 0, 0, 2),
    "2(F−D+Ω)": (0, 0, 2, -2, 2),
    "2(F+Ω)": (0, 0, 2, 0, 2),
    "l′": (0, 1, 0, 0, 0),
    "l": (1, 0, 0, 0, 0),
}


def _axis(axis: str) -> str:
    key = str(axis).strip().lower()
    if key not in AXES:
        msg = f"expected axis one of {', '.join(AXES)}, got {axis!r}"
        raise ValueError(msg)
    return key


def _forcing(t: float, args: Array, H: float, eps: float) -> tuple[Array, Array]:
    """``ψ̇, ε̇`` (rad per Julian year) of the first-order equations at Delaunay arguments ``args``."""
    P = Q = R = Pl = Ql = 0.0
    bodies = ((GM_MOON, moon_ecliptic(t, args, planetary=False)), (GM_SUN, sun_ecliptic(t, args)))
    for gm, (lon, lat, r) in bodies:
        w = gm / r**3
        cb, sb = np.cos(lat), np.sin(lat)
        sl, cl = np.sin(lon), np.cos(lon)
        P = P + w * cb * cb * sl * sl
        Q = Q + 2 * w * sb * cb * sl
        R = R + w * sb * sb
        Pl = Pl + w * cb * cb * 2 * sl * cl
        Ql = Ql + 2 * w * sb * cb * cl
    scale = 3 * H / (2 * EARTH_ROTATION * np.sin(eps)) * JULIAN_YEAR
    dpsi = scale * ((P - R) * np.sin(2 * eps) + Q * np.cos(2 * eps))
    deps = -scale * (Pl * np.sin(eps) ** 2 + Ql * np.sin(eps) * np.cos(eps))
    return dpsi, deps


def _axis_coefficients(axis: str, H: float) -> tuple[float, float]:
    """``(c, d)`` of ``axis = m + c m × ṁ + d m̈⊥`` (time in Julian years; see the module docstring)."""
    a = (1 - H) / (EARTH_ROTATION * JULIAN_YEAR)
    return {"momentum": (0.0, 0.0), "figure": (-a, -a * a), "rotation": (H / (1 - H) * a, 0.0)}[axis]
