"""The JSON document of a Poisson series, with exact ``"p/q"`` coefficients.

The document is ``{"format": "andoyer.poisson-series", "version": 1, "ring": {...},
"terms": [{"coeff": "p/q", "exponents": [...], "kind": "cos", "harmonics": [...]}]}``: the
ring's declaration (:meth:`~andoyer.series.PoissonRing.spec`) and the real terms in canonical
order, exponents over ``ring.poly_names``.  This module only encodes and decodes that document;
:meth:`~andoyer.series.PoissonSeries.to_json` and
:meth:`~andoyer.series.PoissonSeries.from_json` build it from and into series.
"""

from __future__ import annotations

import json
import re
from collections.abc import Iterable, Mapping
from fractions import Fraction
from typing import Any

from andoyer.series.rationals import as_rational

__all__ = ["FORMAT", "decode", "encode"]

FORMAT = "andoyer.poisson-series"
_RATIONAL = re.compile(r"-?\d+(/\d+)?")

#: One real term as it is read back: ``(coeff, exponents, kind, harmonics)``.
RealTerm = tuple[Fraction, list[int], str, list[int]]


def encode(spec: Mapping[str, Any], terms: Iterable[Any], indent: int | None = None) -> str:
    """The JSON document of a ring declaration and real terms.

    Parameters
    ----------
    spec : mapping
        The ring's :meth:`~andoyer.series.PoissonRing.spec`.
    terms : iterable of Term
        Objects with ``coeff``, ``exponents``, ``kind`` and ``harmonics``.
    indent : int, optional

    Returns
    -------
    str

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> f = PoissonRing(["q"], ["p"])("-3/2*p**-1*cos(q)")
    >>> text = encode(f.ring.spec(), f.terms())
    >>> text[text.index('"terms"'):]
    '"terms": [{"coeff": "-3/2", "exponents": [-1], "kind": "cos", "harmonics": [1]}]}'
    """
    doc = {
        "format": FORMAT,
        "version": 1,
        "ring": dict(spec),
        "terms": [
            {
                "coeff": str(t.coeff),
                "exponents": list(t.exponents),
                "kind": t.kind,
                "harmonics": list(t.harmonics),
            }
            for t in terms
        ],
    }
    return json.dumps(doc, indent=indent, ensure_ascii=False)


def decode(text: str) -> tuple[dict[str, Any], list[RealTerm]]:
    """Read the ring declaration and the real terms of a document written by :func:`encode`.

    Parameters
    ----------
    text : str

    Returns
    -------
    spec : dict
        The ring declaration, for :meth:`~andoyer.series.PoissonRing.from_spec`.
    terms : list of (Fraction, list of int, str, list of int)
        For :meth:`~andoyer.series.PoissonRing.from_terms`.

    Examples
    --------
    >>> spec, terms = decode('{"format": "andoyer.poisson-series", "version": 1, "ring": '
    ...     '{"angles": ["q"], "momenta": ["p"]}, "terms": '
    ...     '[{"coeff": "1/3", "exponents": [1], "kind": "sin", "harmonics": [1]}]}')
    >>> spec["angles"], terms
    (['q'], [(Fraction(1, 3), [1], 'sin', [1])])
    >>> decode("[]")
    Traceback (most recent call last):
    ...
    ValueError: expected a andoyer.poisson-series version 1 document, got '[]'
    """
    try:
        doc: Any = json.loads(text)
    except json.JSONDecodeError as exc:
        msg = f"expected JSON text, got an error at position {exc.pos}: {exc.msg}"
        raise ValueError(msg) from None
    if not isinstance(doc, dict) or doc.get("format") != FORMAT or doc.get("version") != 1:
        msg = f"expected a {FORMAT} version 1 document, got {str(text)[:80]!r}"
        raise ValueError(msg)
    spec = doc.get("ring", {})
    if not isinstance(spec, dict):
        msg = f"expected a ring specification mapping, got {spec!r}"
        raise ValueError(msg)
    terms = []
    for t in doc.get("terms", []):
        if not isinstance(t, dict) or set(t) != {"coeff", "exponents", "kind", "harmonics"}:
            msg = f"expected term objects with coeff, exponents, kind, harmonics, got {t!r}"
            raise ValueError(msg)
        if not isinstance(t["coeff"], str) or not _RATIONAL.fullmatch(t["coeff"]):
            msg = f"expected a 'p/q' coefficient string, got {t['coeff']!r}"
            raise ValueError(msg)
        terms.append((as_rational(t["coeff"]), t["exponents"], t["kind"], t["harmonics"]))
    return spec, terms
