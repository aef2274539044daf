"""The rigid bodies of Lara's (2013) Table 1: the Earth, Mars, the Moon and Eros.

The SAM theory's reproduction of Lara's tables needs his moment ratios, so this module keeps
them, read from the catalogue's named moment set ``"lara2013"``
(:func:`andoyer.catalogue.get`). Moments are normalised to ``C = 1``; the body axes are
``(b1, b2, b3) = (A, B, C)``; ``J0`` is Lara's estimate of the angle between the angular
momentum and the figure axis, and ``rotation_period`` the sidereal period he uses.

``bodies.get("earth")`` is Lara's Earth (``H = 0.0032789``), not the catalogue's default
(``andoyer.catalogue.get("earth").rigid_body()``, the IAU/MHB2000 ``H = 0.00327379492`` with
Lara's ``B − A``): the four bodies here are the test set of Lara's paper, and every result
computed from them (the SAM series, the demo, Lara's figures) is his. Every other catalogued
body is reached through :mod:`andoyer.catalogue`.

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
from functools import cache

from andoyer import catalogue
from andoyer.body import RigidBody

__all__ = ["BodyInfo", "get", "info", "names"]

#: The catalogue's name of Lara's (2013) Table 1 moment set.
LARA_SET = "lara2013"
_NAMES = ("earth", "mars", "moon", "eros")


@dataclass(frozen=True)
class BodyInfo:
    """A body of Lara's Table 1.

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


def names() -> tuple[str, ...]:
    """Names of Lara's Table 1 bodies, lower case."""
    return _NAMES


def info(name: str) -> BodyInfo:
    """Lara's Table 1 entry of ``name`` (case-insensitive).

    Examples
    --------
    >>> round(info("mars").rotation_period / 3600, 4)
    24.623
    """
    key = str(name).strip().lower()
    if key not in _NAMES:
        msg = (
            f"expected one of {', '.join(_NAMES)} (Lara's Table 1; andoyer.catalogue.get(name)"
            f".rigid_body() for the other catalogued bodies), got {name!r}"
        )
        raise ValueError(msg)
    return _info(key)


@cache
def _info(key: str) -> BodyInfo:
    """The entry of ``key``, built once: every call gives the same body object."""
    entry = catalogue.get(key)
    values = entry.moment_sets[LARA_SET]
    a, b = entry.moments(LARA_SET)
    sources = dict.fromkeys(q.source for q in values.values())
    return BodyInfo(
        RigidBody.from_ratios(a, b, name=entry.name),
        values["rotation_period"].si(),
        values["j0"].si(),
        "; ".join(sources),
    )


def get(name: str) -> RigidBody:
    """The :class:`~andoyer.RigidBody` of a body of Lara's Table 1 (case-insensitive).

    Examples
    --------
    >>> round(get("eros").beta, 4)
    0.9779
    """
    return info(name).body
