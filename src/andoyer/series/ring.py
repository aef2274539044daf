"""Rings of Poisson series: the declared variables, canonical pairs, relations and weights.

A :class:`PoissonRing` fixes what a family of series may contain: angles (which enter only
through ``cos`` and ``sin`` of integer combinations), polynomial variables (momenta, or
polynomial coordinates paired with momenta) and symbolic parameters.  Polynomial variables and
parameters may carry negative exponents (Laurent monomials), except the generators of a
quadratic relation ``x² = D``.

Internally a series is ``m · Σ_c g^c P_c`` where ``m`` is a Laurent monomial (the *shift*),
``P_c`` are python-flint ``fmpq_mpoly`` polynomials in the polynomial variables, the free
parameters and one variable ``z_j = exp(i θ_j)`` per angle, and ``g^c`` runs over square-free
products of the imaginary unit and the relation generators (a bit mask ``c``).  The free-module
basis ``{g^c}`` and the shift normalised to a zero minimum exponent make the representation
canonical.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from fractions import Fraction
from typing import TYPE_CHECKING, Any

import flint

from andoyer.series.constructors import RingConstructorsMixin
from andoyer.series.rationals import as_rational
from andoyer.series.text import parse_series

if TYPE_CHECKING:
    pass

__all__ = ["PoissonRing"]

# lex, not deglex: flint multiplies lex polynomials with dense arrays when the product's
# bounding box is small, 3-8x faster than its heap on series of a few hundred terms with small
# denominators (benchmarks/bench_series.py); nothing else depends on flint's term order.
_FLINT_ORDER = "lex"


def _check_names(kind: str, names: Iterable[str]) -> tuple[str, ...]:
    out = tuple(names)
    for name in out:
        if not isinstance(name, str) or not name.isidentifier() or name in ("cos", "sin"):
            msg = f"expected {kind} names to be identifiers other than cos/sin, got {name!r}"
            raise ValueError(msg)
    return out


class PoissonRing(RingConstructorsMixin):
    """The variables, canonical pairs, relations and weights shared by a family of series.

    Parameters
    ----------
    angles : sequence of str
        Angle names ``θ_j``; series are 2π-periodic in each and contain them only through
        ``cos(k·θ)`` and ``sin(k·θ)`` with integer ``k``.
    momenta : sequence of str
        Polynomial canonical variables: momenta, or polynomial coordinates that a pair
        declares conjugate to a momentum.  Negative exponents are allowed.
    params : sequence of str, optional
        Symbolic parameters (constants): not part of any canonical pair.
    pairs : sequence of (str, str), optional
        Canonical pairs ``(q, p)``, ``q`` an angle or a polynomial variable and ``p`` a
        polynomial variable, defining ``{f, g} = Σ (∂f/∂q ∂g/∂p − ∂f/∂p ∂g/∂q)``.  Default:
        ``angles[j]`` paired with ``momenta[j]``.
    relations : mapping of str to str, optional
        Quadratic relations ``x² = D``: ``x`` a parameter and ``D`` a polynomial (a string such
        as ``"1 - s**2"``) in the other parameters that are not relation generators.  Powers
        ``x^n`` are reduced to ``x^(n mod 2) D^(n // 2)``; ``x`` itself may not take negative
        exponents.  To use ``β`` and ``s = √(1−β²)`` with ``1/s`` allowed, declare
        ``relations={"beta": "1 - s**2"}``.
    weights : mapping of str to rational, optional
        Weight of each polynomial variable or parameter; the *order* of a monomial is the
        weighted sum of its exponents (default weight 0).  Used by truncation.

    Examples
    --------
    >>> R = PoissonRing(["l", "g"], ["L", "G"], ["beta", "s"], relations={"beta": "1 - s**2"})
    >>> R.pairs
    (('l', 'L'), ('g', 'G'))
    >>> R("beta**3 * cos(2*l)")
    beta*cos(2*l) - beta*s**2*cos(2*l)
    """

    def __init__(
        self,
        angles: Sequence[str] = (),
        momenta: Sequence[str] = (),
        params: Sequence[str] = (),
        *,
        pairs: Sequence[Sequence[str]] | None = None,
        relations: Mapping[str, str] | None = None,
        weights: Mapping[str, Any] | None = None,
    ) -> None:
        self.angles = _check_names("angle", angles)
        self.momenta = _check_names("momentum", momenta)
        self.params = _check_names("parameter", params)
        every = self.angles + self.momenta + self.params
        if len(set(every)) != len(every):
            msg = f"expected distinct variable names, got {list(every)}"
            raise ValueError(msg)
        relations = dict(relations or {})
        for name, text in relations.items():
            if name not in self.params or not isinstance(text, str):
                msg = f"expected relations {{parameter: 'polynomial'}}, got {name!r}: {text!r}"
                raise ValueError(msg)
        self.relations = {p: relations[p] for p in self.params if p in relations}
        self._rel = tuple(self.relations)
        self._free = self.momenta + tuple(p for p in self.params if p not in relations)
        self._ctx = flint.fmpq_mpoly_ctx.get(self._free + self.angles, _FLINT_ORDER)
        self._nfree = len(self._free)
        self._index = {name: i for i, name in enumerate(self._free + self.angles)}
        self._zero_shift = (0,) * (self._nfree + len(self.angles))
        self.pairs = self._make_pairs(pairs)
        self.poly_names = self.momenta + self.params
        self.weights = self._make_weights(weights or {})
        self._w = tuple(self.weights.get(n, Fraction(0)) for n in self._free) + (Fraction(0),) * len(
            self.angles
        )
        self._w_rel = tuple(self.weights.get(n, Fraction(0)) for n in self._rel)
        # Where each name of poly_names lives: ("ctx", index) or ("rel", bit).
        self._slots = tuple(
            ("rel", 1 << (self._rel.index(n) + 1)) if n in self.relations else ("ctx", self._index[n])
            for n in self.poly_names
        )
        self._rel_polys = self._parse_relations()
        self._overlap_cache: dict[int, Any] = {}

    # ------------------------------------------------------------------ construction helpers
    def _make_pairs(self, pairs: Sequence[Sequence[str]] | None) -> tuple[tuple[str, str], ...]:
        if pairs is None:
            out = tuple(zip(self.angles, self.momenta, strict=False))
        else:
            out = tuple((str(q), str(p)) for q, p in pairs)
        used: list[str] = []
        for q, p in out:
            if q not in self.angles + self.momenta or p not in self.momenta:
                msg = f"expected pairs (angle or momentum, momentum) of declared names, got ({q!r}, {p!r})"
                raise ValueError(msg)
            used += [q, p]
        if len(set(used)) != len(used):
            msg = f"expected each variable in at most one canonical pair, got {list(out)}"
            raise ValueError(msg)
        return out

    def _make_weights(self, weights: Mapping[str, Any]) -> dict[str, Fraction]:
        out = {}
        for name, w in weights.items():
            if name not in self.poly_names:
                msg = f"expected weights for momenta or parameters, got {name!r}"
                raise ValueError(msg)
            out[name] = as_rational(w, "a rational weight")
        return out

    def _parse_relations(self) -> tuple[Any, ...]:
        if not self._rel:
            return ()
        base = PoissonRing(self.angles, self.momenta, [p for p in self.params if p not in self._rel])
        polys = []
        for name, text in self.relations.items():
            d = parse_series(base, text)
            allowed = set(self._free) - set(self.momenta)
            if (
                set(d.variables()) - allowed
                or any(e < 0 for e in d._shift)
                or set(d._comps) - {0}
                or d.is_zero()
            ):
                msg = (
                    f"expected relation {name}² = D with D a nonzero polynomial in the "
                    f"non-relation parameters, got {text!r}"
                )
                raise ValueError(msg)
            polys.append(d._comps[0] * self._ctx.term(exp_vec=d._shift))
        return tuple(polys)

    def overlap_factor(self, mask: int) -> Any:
        """Return ``g^c · g^c`` reduced: the polynomial factor for overlapping basis bits.

        Parameters
        ----------
        mask : int
            Bit mask of basis generators (bit 0: imaginary unit; bit j+1: relation j).

        Returns
        -------
        flint.fmpq_mpoly
            ``(−1)^(bit 0) Π D_j`` over the set relation bits.

        Examples
        --------
        >>> R = PoissonRing([], [], ["b", "s"], relations={"b": "1 - s**2"})
        >>> R.overlap_factor(0b11)
        s^2 - 1
        """
        fac = self._overlap_cache.get(mask)
        if fac is None:
            fac = self._ctx.constant(-1 if mask & 1 else 1)
            for j, d in enumerate(self._rel_polys):
                if mask >> (j + 1) & 1:
                    fac = fac * d
            self._overlap_cache[mask] = fac
        return fac

    # ------------------------------------------------------------------ identity
    def spec(self) -> dict[str, Any]:
        """Return the JSON-ready declaration of this ring.

        Returns
        -------
        dict
            Keys ``angles``, ``momenta``, ``params``, ``pairs``, ``relations``, ``weights``.

        Examples
        --------
        >>> PoissonRing(["q"], ["p"]).spec()["pairs"]
        [['q', 'p']]
        """
        return {
            "angles": list(self.angles),
            "momenta": list(self.momenta),
            "params": list(self.params),
            "pairs": [list(p) for p in self.pairs],
            "relations": dict(self.relations),
            "weights": {k: str(v) for k, v in self.weights.items()},
        }

    @classmethod
    def from_spec(cls, spec: Mapping[str, Any]) -> PoissonRing:
        """Build a ring from :meth:`spec` output.

        Parameters
        ----------
        spec : mapping
            As returned by :meth:`spec`.

        Returns
        -------
        PoissonRing

        Examples
        --------
        >>> R = PoissonRing(["q"], ["p"], weights={"p": 1})
        >>> PoissonRing.from_spec(R.spec()) == R
        True
        """
        try:
            return cls(
                spec["angles"],
                spec["momenta"],
                spec.get("params", ()),
                pairs=spec.get("pairs"),
                relations=spec.get("relations"),
                weights=spec.get("weights"),
            )
        except (KeyError, TypeError) as exc:
            msg = f"expected a ring specification mapping, got {spec!r}"
            raise ValueError(msg) from exc

    def _key(self) -> tuple[Any, ...]:
        return (
            self.angles,
            self.momenta,
            self.params,
            self.pairs,
            tuple(self.relations.items()),
            tuple(sorted(self.weights.items())),
        )

    def __eq__(self, other: object) -> bool:
        return isinstance(other, PoissonRing) and self._key() == other._key()

    def __hash__(self) -> int:
        return hash(self._key())

    def __repr__(self) -> str:
        return (
            f"PoissonRing(angles={self.angles}, momenta={self.momenta}, params={self.params}, "
            f"pairs={self.pairs}, relations={self.relations}, weights="
            f"{ {k: str(v) for k, v in self.weights.items()} })"
        )

    @property
    def variables(self) -> tuple[str, ...]:
        """All names in evaluation order: angles, momenta, parameters.

        Examples
        --------
        >>> PoissonRing(["q"], ["p"], ["a"]).variables
        ('q', 'p', 'a')
        """
        return self.angles + self.momenta + self.params
