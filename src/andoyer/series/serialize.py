"""JSON serialisation of Poisson series with exact ``"p/q"`` coefficients."""

from __future__ import annotations

import json
import re
from typing import TYPE_CHECKING, Any

from andoyer.series.ring import PoissonRing, as_rational

if TYPE_CHECKING:
    from andoyer.series.poisson import PoissonSeries

__all__ = ["FORMAT", "series_from_json", "series_to_json"]

FORMAT = "andoyer.poisson-series"
_RATIONAL = re.compile(r"-?\d+(/\d+)?")


def series_to_json(f: PoissonSeries, indent: int | None = None) -> str:
    """Serialise a series and its ring to JSON.

    The document is ``{"format": "andoyer.poisson-series", "version": 1, "ring": {...},
    "terms": [{"coeff": "p/q", "exponents": [...], "kind": "cos", "harmonics": [...]}]}``
    with exponents over ``ring.poly_names`` and terms in canonical order.

    Parameters
    ----------
    f : PoissonSeries
    indent : int, optional

    Returns
    -------
    str

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> text = series_to_json(PoissonRing(["q"], ["p"])("-3/2*p**-1*cos(q)"))
    >>> text[text.index('"terms"'):]
    '"terms": [{"coeff": "-3/2", "exponents": [-1], "kind": "cos", "harmonics": [1]}]}'
    """
    doc = {
        "format": FORMAT,
        "version": 1,
        "ring": f.ring.spec(),
        "terms": [
            {
                "coeff": str(t.coeff),
                "exponents": list(t.exponents),
                "kind": t.kind,
                "harmonics": list(t.harmonics),
            }
            for t in f.terms()
        ],
    }
    return json.dumps(doc, indent=indent, ensure_ascii=False)


def series_from_json(text: str, ring: PoissonRing | None = None) -> PoissonSeries:
    """Read a series written by :func:`series_to_json`.

    Parameters
    ----------
    text : str
    ring : PoissonRing, optional
        Expected ring; the stored declaration must equal it.

    Returns
    -------
    PoissonSeries

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> f = PoissonRing(["q"], ["p"], ["b", "s"], relations={"b": "1 - s**2"})("b*s*sin(q)")
    >>> series_from_json(series_to_json(f)) == f
    True
    """
    try:
        doc: Any = json.loads(text)
    except json.JSONDecodeError as exc:
        msg = f"expected JSON text, got an error at position {exc.pos}: {exc.msg}"
        raise ValueError(msg) from None
    if not isinstance(doc, dict) or doc.get("format") != FORMAT or doc.get("version") != 1:
        msg = f"expected a {FORMAT} version 1 document, got {str(text)[:80]!r}"
        raise ValueError(msg)
    stored = PoissonRing.from_spec(doc.get("ring", {}))
    if ring is None:
        ring = stored
    elif ring != stored:
        msg = f"expected a series of {ring!r}, got one of {stored!r}"
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
    return ring.from_terms(terms)
