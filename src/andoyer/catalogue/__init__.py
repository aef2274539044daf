r"""One cited catalogue of bodies, the unit constants, and bodies of the user's own.

The catalogue (``data/bodies.json``, read with the standard library) holds the Sun, the planets,
Pluto, the Moon, the Galilean satellites, Titan, Enceladus, Uranus' five major satellites, Triton
and Eros: ``GM``, radius,
``J2``, ``C22``, ``C/MR²``, moment ratios, spin (the IAU WGCCRE 2015 pole and prime meridian,
Archinal et al. 2018), the measured precession rate, and the orbit (Standish's J2000 mean
elements for the planets; JPL's mean elements on the local Laplace plane for the satellites).
**Every value carries its source**, its uncertainty where the source gives one, and a note where a
digit could not be confirmed (search the notes for ``UNVERIFIED``). Lara's (2013) Table 1 moment
ratios are kept as the named moment set ``"lara2013"``.

A body of the user's own is the same :class:`Body`, read from a JSON or TOML file with the keys
``andoyer bodies NAME --format json`` prints (:func:`read_body`, ``--body-file PATH``) or built
from a mapping (:func:`body_from_dict`); it is checked like any input.

The unit constants (:mod:`andoyer.catalogue.units`: ``ARCSEC``, ``DEGREE``, ``DAY``,
``JULIAN_YEAR``, ``AU``, ...) are defined here once.

Why a JSON file and not Python literals: the user's body files and ``andoyer bodies --format
json`` use the same keys, so one reader (:func:`body_from_dict`) checks the shipped catalogue and
the user's files alike, and the data can be read and diffed without importing the package.

Examples
--------
>>> from andoyer import catalogue
>>> catalogue.names()[:4]
('sun', 'mercury', 'venus', 'earth')
>>> titan = catalogue.get("Titan")
>>> titan.primary, titan.rotation_rate.value, titan.rotation_rate.unit
('saturn', 22.5769768, 'deg/d')
>>> catalogue.get("vulcan")  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
ValueError: expected a body among sun, mercury, ..., eros (or a body file), got 'vulcan'
"""

from __future__ import annotations

import json
from functools import cache
from importlib import resources
from typing import Any

from andoyer.catalogue import units
from andoyer.catalogue.entry import Body, Quantity
from andoyer.catalogue.read import body_from_dict, read_body
from andoyer.catalogue.schema import FIELDS

__all__ = ["FIELDS", "Body", "Quantity", "body_from_dict", "get", "names", "read_body", "units"]


def _expand_sources(body: dict[str, Any], sources: dict[str, str]) -> dict[str, Any]:
    """The entry with every ``source`` key replaced by its citation."""

    def cite(quantity: dict[str, Any]) -> dict[str, Any]:
        key = quantity.get("source")
        if key not in sources:
            msg = f"expected a source key among the catalogue's sources, got {key!r} in {body.get('name')}"
            raise ValueError(msg)
        return {**quantity, "source": sources[key]}

    out = {k: cite(v) if isinstance(v, dict) and k in FIELDS else v for k, v in body.items()}
    if "moment_sets" in body:
        out["moment_sets"] = {
            s: {k: cite(v) for k, v in vals.items()} for s, vals in body["moment_sets"].items()
        }
    return out


@cache
def _catalogue() -> dict[str, Body]:
    """The shipped catalogue, read and checked once."""
    text = resources.files("andoyer.catalogue").joinpath("data/bodies.json").read_text(encoding="utf-8")
    raw = json.loads(text)
    origin = "the shipped catalogue (andoyer/catalogue/data/bodies.json)"
    out: dict[str, Body] = {}
    for entry in raw["bodies"]:
        body = body_from_dict(_expand_sources(entry, raw["sources"]), origin=origin, default_source="")
        out[body.key] = body
    return out


def names() -> tuple[str, ...]:
    """The catalogued bodies' names, lower case, Sun outwards (satellites after the planets).

    Examples
    --------
    >>> len(names()), names()[-1]
    (24, 'eros')
    """
    return tuple(_catalogue())


def get(name: str | Body) -> Body:
    """A catalogued body by name (case-insensitive); a :class:`Body` is returned as it is.

    Parameters
    ----------
    name : str or Body

    Returns
    -------
    Body

    Examples
    --------
    >>> get("EARTH").dynamical_ellipticity.value
    0.00327379492
    """
    if isinstance(name, Body):
        return name
    bodies = _catalogue()
    key = name.strip().lower() if isinstance(name, str) else None
    if key not in bodies:
        msg = f"expected a body among {', '.join(bodies)} (or a body file), got {name!r}"
        raise ValueError(msg)
    return bodies[key]
