"""Named solar-system bodies.

The principal-moment ratios are Lara's Table 1 (M. Lara, *Short-axis-mode
rotation of a free rigid body by perturbation series*, 2013), which cites
Mars [Konopliv et al.], Earth and Moon [the IERS/JPL values quoted there] and
Eros [Souchay et al.]. Moments are normalised to ``C = 1``; the body axes are
``(b1, b2, b3) = (A, B, C)``. Sidereal rotation periods are the IAU WGCCRE
(Archinal et al. 2018) values, and ``J0`` is Lara's Table 1 estimate of the
angle between the angular momentum and the figure axis.

Examples
--------
>>> from andoyer import bodies
>>> earth = bodies.get("Earth")
>>> earth.A, earth.B, earth.C
(0.99672, 0.9967222, 1.0)
>>> bodies.names()
('earth', 'mars', 'moon', 'eros')
"""

from __future__ import annotations

from dataclasses import dataclass

from andoyer.body import RigidBody

__all__ = ["BodyInfo", "get", "info", "names"]

ARCSEC = 3.141592653589793 / 648000.0


@dataclass(frozen=True)
class BodyInfo:
    """Catalogue entry of a named body.

    Attributes
    ----------
    body : RigidBody
        Normalised moments (``C = 1``).
    rotation_period : float
        Sidereal rotation period in seconds.
    J0 : float
        Lara's Table 1 angle between the angular momentum and the figure axis, radians.
    source : str
        Where the numbers come from.
    """

    body: RigidBody
    rotation_period: float
    J0: float
    source: str


_CATALOGUE: dict[str, BodyInfo] = {
    "earth": BodyInfo(
        RigidBody.from_ratios(0.9967200, 0.9967222, name="Earth"),
        86164.0905,
        1.0 * ARCSEC,
        "Lara (2013) Table 1, ref. [32]; IAU WGCCRE 2015 sidereal day",
    ),
    "mars": BodyInfo(
        RigidBody.from_ratios(0.9942917, 0.9949813, name="Mars"),
        88642.6632,
        0.1 * ARCSEC,
        "Lara (2013) Table 1, refs. [14, 31]; IAU WGCCRE 2015 (350.891982443297 deg/day)",
    ),
    "moon": BodyInfo(
        RigidBody.from_ratios(0.999368, 0.999601, name="Moon"),
        27.321661 * 86400.0,
        6.2 * ARCSEC,
        "Lara (2013) Table 1, refs. [32, 33]; sidereal month 27.321661 d",
    ),
    "eros": BodyInfo(
        RigidBody.from_ratios(0.229427, 0.963754, name="Eros"),
        5.27025547 * 3600.0,
        55.0 * ARCSEC,
        "Lara (2013) Table 1, ref. [17]; IAU WGCCRE 2015 (1639.38864745 deg/day)",
    ),
}


def names() -> tuple[str, ...]:
    """Names of the catalogued bodies, lower case."""
    return tuple(_CATALOGUE)


def info(name: str) -> BodyInfo:
    """Catalogue entry of ``name`` (case-insensitive).

    Examples
    --------
    >>> round(info("mars").rotation_period / 3600, 4)
    24.6230
    """
    key = str(name).strip().lower()
    if key not in _CATALOGUE:
        msg = f"expected one of {', '.join(_CATALOGUE)}, got {name!r}"
        raise ValueError(msg)
    return _CATALOGUE[key]


def get(name: str) -> RigidBody:
    """The :class:`~andoyer.RigidBody` of a named body (case-insensitive).

    Examples
    --------
    >>> round(get("eros").beta, 4)
    0.9779
    """
    return info(name).body
