r"""Read and check a body: from a mapping (:func:`body_from_dict`) or a JSON/TOML file (:func:`read_body`).

The keys are those ``andoyer bodies NAME --format json`` prints (the schema in
``docs/catalogue.md``): text keys ``name`` (required), ``kind``, ``primary``, ``orbit_frame``,
``orbit_epoch``, ``note``; numeric keys of :data:`~andoyer.catalogue.schema.FIELDS`, each either
a number in the key's catalogue unit or a table ``{value, unit, uncertainty, source, note}``
(only ``value`` required); and ``moment_sets``. Every value is checked like any input: a finite
number, a unit of the key's dimension, within the key's bounds (``C/MR²`` in ``(0, 2/3]``,
``e < 1``, ``J2 ≥ 0``, ``|δ₀| ≤ 90°``, ...), and the moments ordered (``A ≤ B ≤ C``,
``A + B ≥ C``). A refusal is ``ValueError("expected …, got …")`` naming the key and the file.

Examples
--------
>>> body = body_from_dict({"name": "Kepler-x b", "gm": 1.2e5, "radius": {"value": 7000, "unit": "km"},
...                        "j2": 0.01, "c22": 0.0, "moment_of_inertia": 0.3})
>>> body.gm.unit, body.gm.source
('km3/s2', 'given in a mapping')
>>> body_from_dict({"name": "x", "eccentricity": 1.2})
Traceback (most recent call last):
...
ValueError: expected eccentricity in [0, 1), got 1.2 (key 'eccentricity' in a mapping)
"""

from __future__ import annotations

import json
import math
import os
import sys
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from andoyer.catalogue import units
from andoyer.catalogue.entry import Body, Quantity
from andoyer.catalogue.schema import FIELDS, KINDS, MOMENT_SET_FIELDS, TEXT_FIELDS

__all__ = ["body_from_dict", "read_body"]

_QUANTITY_KEYS = ("value", "unit", "uncertainty", "source", "note")


def _where(key: str, origin: str) -> str:
    return f"(key {key!r} in {origin})"


def _number(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def _quantity(key: str, raw: Any, origin: str, default_source: str, unit_of: str) -> Quantity:
    """One checked value of the numeric key ``key`` (bounds checked in ``unit_of``'s field)."""
    spec = FIELDS[unit_of]
    if _number(raw):
        raw = {"value": raw}
    if not isinstance(raw, Mapping):
        msg = f"expected a number or a table with a value, got {raw!r} {_where(key, origin)}"
        raise ValueError(msg)
    extra = sorted(set(raw) - set(_QUANTITY_KEYS))
    if extra:
        msg = f"expected the keys {', '.join(_QUANTITY_KEYS)}, got {extra[0]!r} {_where(key, origin)}"
        raise ValueError(msg)
    value = raw.get("value")
    if not _number(value) or not math.isfinite(value):
        msg = f"expected a finite number as value, got {value!r} {_where(key, origin)}"
        raise ValueError(msg)
    unit = raw.get("unit", spec.unit)
    if unit not in units.UNITS or units.UNITS[unit][0] != spec.dimension:
        allowed = ", ".join(u for u, (d, _) in units.UNITS.items() if d == spec.dimension)
        msg = f"expected a unit of {spec.dimension} ({allowed}), got {unit!r} {_where(key, origin)}"
        raise ValueError(msg)
    in_unit = units.convert(value, unit, spec.unit)
    if not spec.contains(in_unit):
        shown = f"{value!r}" if unit == spec.unit else f"{value!r} {unit} = {in_unit!r} {spec.unit}"
        msg = f"expected {unit_of} {spec.describe_bounds()}, got {shown} {_where(key, origin)}"
        raise ValueError(msg)
    uncertainty = raw.get("uncertainty")
    if uncertainty is not None and not (
        _number(uncertainty) and math.isfinite(uncertainty) and uncertainty >= 0
    ):
        msg = f"expected a finite uncertainty >= 0 or none, got {uncertainty!r} {_where(key, origin)}"
        raise ValueError(msg)
    source = raw.get("source", default_source)
    note = raw.get("note", "")
    for name, text in (("source", source), ("note", note)):
        if not isinstance(text, str):
            msg = f"expected text as {name}, got {text!r} {_where(key, origin)}"
            raise ValueError(msg)
    if not source.strip():
        msg = f"expected a source, got an empty one {_where(key, origin)}"
        raise ValueError(msg)
    return Quantity(
        value if isinstance(value, float) else float(value),
        unit,
        None if uncertainty is None else float(uncertainty),
        source,
        note,
    )


def _check_moments(body: Body, origin: str) -> None:
    """``0 < A ≤ B ≤ C`` and ``A + B ≥ C`` for the default moments and every named set."""
    for name in (None, *body.moment_sets):
        try:
            a, b = body.moments(name)
        except ValueError:
            continue  # no moments to check: a computation that needs them says so
        label = "moments" if name is None else f"moment set {name!r}"
        if not (0 < a <= b <= 1):
            msg = f"expected 0 < A/C <= B/C <= 1, got A/C = {a!r}, B/C = {b!r} ({label} in {origin})"
            raise ValueError(msg)
        if a + b < 1:
            msg = (
                f"expected A + B >= C (triangle inequality), got A/C + B/C = {a + b!r} ({label} in {origin})"
            )
            raise ValueError(msg)


def body_from_dict(
    data: Mapping[str, Any], origin: str = "a mapping", default_source: str | None = None
) -> Body:
    """A checked :class:`~andoyer.catalogue.Body` from the keys ``andoyer bodies NAME --format json`` prints.

    Parameters
    ----------
    data : mapping
        One body (module docstring).
    origin : str
        Where it came from, for error messages (a file name).
    default_source : str, optional
        The source of a value that gives none (default ``"given in <origin>"``).

    Returns
    -------
    Body

    Examples
    --------
    >>> body_from_dict({"name": "x", "a_over_c": 0.9, "b_over_c": 0.8})
    Traceback (most recent call last):
    ...
    ValueError: expected 0 < A/C <= B/C <= 1, got A/C = 0.9, B/C = 0.8 (moments in a mapping)
    """
    if not isinstance(data, Mapping):
        msg = f"expected a table of keys (one body), got {type(data).__name__} in {origin}"
        raise ValueError(msg)
    known = (*TEXT_FIELDS, *FIELDS, "moment_sets")
    unknown = sorted(k for k in data if k not in known)
    if unknown:
        msg = f"expected keys among {', '.join(known)}, got {unknown[0]!r} in {origin}"
        raise ValueError(msg)
    name = data.get("name")
    if not isinstance(name, str) or not name.strip():
        msg = f"expected a non-empty name, got {name!r} {_where('name', origin)}"
        raise ValueError(msg)
    text: dict[str, Any] = {}
    for key in TEXT_FIELDS[1:]:
        if key in data and data[key] is not None:
            if not isinstance(data[key], str):
                msg = f"expected text, got {data[key]!r} {_where(key, origin)}"
                raise ValueError(msg)
            text[key] = data[key]
    if text.get("kind", "user") not in KINDS:
        msg = f"expected a kind among {', '.join(KINDS)}, got {text['kind']!r} {_where('kind', origin)}"
        raise ValueError(msg)
    source = default_source or f"given in {origin}"
    values = {
        k: _quantity(k, data[k], origin, source, k) for k in FIELDS if k in data and data[k] is not None
    }
    sets: dict[str, dict[str, Quantity]] = {}
    raw_sets = data.get("moment_sets") or {}
    if not isinstance(raw_sets, Mapping):
        msg = f"expected a table of named moment sets, got {raw_sets!r} {_where('moment_sets', origin)}"
        raise ValueError(msg)
    for set_name, raw in raw_sets.items():
        where = f"moment_sets.{set_name}"
        if not isinstance(raw, Mapping) or not {"a_over_c", "b_over_c"} <= set(raw):
            msg = f"expected a table with a_over_c and b_over_c, got {raw!r} {_where(where, origin)}"
            raise ValueError(msg)
        bad = sorted(set(raw) - set(MOMENT_SET_FIELDS))
        if bad:
            msg = (
                f"expected keys among {', '.join(MOMENT_SET_FIELDS)}, got {bad[0]!r} {_where(where, origin)}"
            )
            raise ValueError(msg)
        sets[str(set_name)] = {k: _quantity(f"{where}.{k}", raw[k], origin, source, k) for k in raw}
    body = Body(name=name.strip(), **text, **values, moment_sets=sets)
    _check_moments(body, origin)
    return body


def _load(path: Path) -> Any:
    """The parsed content of a JSON or TOML file (by suffix; JSON otherwise)."""
    try:
        raw = path.read_bytes()
    except OSError as err:
        msg = f"expected a readable body file, got {str(path)!r} ({err.strerror or err})"
        raise ValueError(msg) from None
    if path.suffix.lower() == ".toml":
        if sys.version_info >= (3, 11):
            import tomllib
        else:  # pragma: no cover - Python 3.10 only
            import tomli as tomllib
        try:
            return tomllib.loads(raw.decode("utf-8"))
        except (UnicodeDecodeError, tomllib.TOMLDecodeError) as err:
            msg = f"expected a TOML body file, got {str(path)!r} ({err})"
            raise ValueError(msg) from None
    try:
        return json.loads(raw.decode("utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError) as err:
        msg = f"expected a JSON body file, got {str(path)!r} ({err})"
        raise ValueError(msg) from None


def read_body(path: str | os.PathLike[str]) -> Body:
    """A checked body from a JSON or TOML file (``--body-file PATH`` of the commands).

    The file holds one body with the keys ``andoyer bodies NAME --format json`` prints (a JSON
    list of exactly one such body is accepted too); ``.toml`` files are read as TOML, others as
    JSON. Values without a source are cited as ``"given in <path>"``.

    Parameters
    ----------
    path : str or path-like

    Returns
    -------
    Body

    Examples
    --------
    >>> import json, os, tempfile
    >>> folder = tempfile.mkdtemp()
    >>> path = os.path.join(folder, "titanish.json")
    >>> with open(path, "w") as f:
    ...     json.dump({"name": "Titan-like", "j2": 3.18e-5, "c22": 1.0e-5, "moment_of_inertia": 0.34}, f)
    >>> body = read_body(path)
    >>> a, b = body.moments()
    >>> round((b - a) * 0.34 / 4, 12)   # C22 = (B - A)/4MR²
    1e-05
    """
    file = Path(os.fspath(path))
    data = _load(file)
    if isinstance(data, list) and len(data) == 1:
        data = data[0]
    return body_from_dict(data, origin=str(file))
