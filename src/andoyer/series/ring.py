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

# Module import (not names): poisson imports this module back through serialize.
from andoyer.series import poisson as _poisson
from andoyer.series.rationals import as_rational, to_fmpq
from andoyer.series.symbolic import series_from_sympy
from andoyer.series.terms import decompose
from andoyer.series.text import parse_series

if TYPE_CHECKING:
    from andoyer.series.poisson import PoissonSeries

__all__ = ["PoissonRing"]

_FLINT_ORDER = "deglex"


def _check_names(kind: str, names: Iterable[str]) -> tuple[str, ...]:
    out = tuple(names)
    for name in out:
        if not isinstance(name, str) or not name.isidentifier() or name in ("cos", "sin"):
            msg = f"expected {kind} names to be identifiers other than cos/sin, got {name!r}"
            raise ValueError(msg)
    return out


class PoissonRing:
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
        self._w = tuple(self.weights.get(n, Fraction(0)) for n in self._free) + (
            Fraction(0),
        ) * len(self.angles)
        self._w_rel = tuple(self.weights.get(n, Fraction(0)) for n in self._rel)
        # Where each name of poly_names lives: ("ctx", index) or ("rel", bit).
        self._slots = tuple(
            ("rel", 1 << (self._rel.index(n) + 1))
            if n in self.relations
            else ("ctx", self._index[n])
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
                msg = (
                    "expected pairs (angle or momentum, momentum) of declared names, "
                    f"got ({q!r}, {p!r})"
                )
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
        base = PoissonRing(
            self.angles, self.momenta, [p for p in self.params if p not in self._rel]
        )
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

    # ------------------------------------------------------------------ series constructors
    def __call__(self, value: Any) -> PoissonSeries:
        """Make a series from a rational, a string expression or a series of this ring."""
        if isinstance(value, _poisson.PoissonSeries):
            self.check(value)
            return value
        if isinstance(value, str) and not _looks_rational(value):
            return parse_series(self, value)
        return self.constant(value)

    def check(self, series: PoissonSeries) -> None:
        """Raise ``ValueError`` unless ``series`` belongs to this ring.

        Parameters
        ----------
        series : PoissonSeries

        Examples
        --------
        >>> R = PoissonRing(["q"], ["p"])
        >>> R.check(R("p"))
        """
        if series.ring is not self and series.ring != self:
            msg = f"expected a series of {self!r}, got one of {series.ring!r}"
            raise ValueError(msg)

    def constant(self, value: Any) -> PoissonSeries:
        """Return the constant series ``value`` (an exact rational).

        Parameters
        ----------
        value : int, Fraction, fmpq or "p/q" string

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> PoissonRing(["q"], ["p"]).constant("3/4")
        3/4
        """
        c = to_fmpq(value)
        return _poisson.make_series(self, self._zero_shift, {0: self._ctx.constant(c)})

    @property
    def zero(self) -> PoissonSeries:
        """The zero series.

        Examples
        --------
        >>> PoissonRing(["q"], ["p"]).zero.is_zero()
        True
        """
        return self.constant(0)

    @property
    def one(self) -> PoissonSeries:
        """The unit series.

        Examples
        --------
        >>> PoissonRing(["q"], ["p"]).one
        1
        """
        return self.constant(1)

    def gen(self, name: str) -> PoissonSeries:
        """Return the series of one polynomial variable or parameter.

        Parameters
        ----------
        name : str
            A momentum or parameter name.

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> R = PoissonRing(["q"], ["p"], ["a"])
        >>> R.gen("p") * R.gen("a") ** -2
        p*a**-2
        """
        if name in self._rel:
            bit = 1 << (self._rel.index(name) + 1)
            return _poisson.make_series(self, self._zero_shift, {bit: self._ctx.constant(1)})
        if name not in self._free:
            msg = f"expected a momentum or parameter of {self.poly_names}, got {name!r}"
            raise ValueError(msg)
        shift = list(self._zero_shift)
        shift[self._index[name]] = 1
        return _poisson.make_series(self, tuple(shift), {0: self._ctx.constant(1)})

    def harmonic_vector(self, k: Sequence[int] | Mapping[str, int]) -> tuple[int, ...]:
        """Normalise a harmonic given as a sequence (angle order) or ``{angle: int}``.

        Parameters
        ----------
        k : sequence of int or mapping of str to int

        Returns
        -------
        tuple of int

        Examples
        --------
        >>> PoissonRing(["l", "g"], ["L", "G"]).harmonic_vector({"g": -1})
        (0, -1)
        """
        if isinstance(k, Mapping):
            bad = set(k) - set(self.angles)
            if bad:
                msg = f"expected harmonics keyed by angles {self.angles}, got {sorted(bad)}"
                raise ValueError(msg)
            vec = [k.get(a, 0) for a in self.angles]
        else:
            vec = list(k)
        if len(vec) != len(self.angles) or not all(
            isinstance(v, int) and not isinstance(v, bool) for v in vec
        ):
            msg = f"expected {len(self.angles)} integer harmonics, got {k!r}"
            raise ValueError(msg)
        return tuple(vec)

    def cos(self, k: Sequence[int] | Mapping[str, int]) -> PoissonSeries:
        """Return ``cos(k·θ)``.

        Parameters
        ----------
        k : sequence of int or mapping of str to int
            Integer harmonic, one entry per angle.

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> R = PoissonRing(["l", "g"], ["L", "G"])
        >>> R.cos([-2, 1])
        cos(2*l - g)
        """
        return self._trig(self.harmonic_vector(k), sine=False)

    def sin(self, k: Sequence[int] | Mapping[str, int]) -> PoissonSeries:
        """Return ``sin(k·θ)``.

        Parameters
        ----------
        k : sequence of int or mapping of str to int
            Integer harmonic, one entry per angle.

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> R = PoissonRing(["l", "g"], ["L", "G"])
        >>> R.sin({"l": -1})
        -sin(l)
        """
        return self._trig(self.harmonic_vector(k), sine=True)

    def _trig(self, k: tuple[int, ...], *, sine: bool) -> PoissonSeries:
        if not any(k):
            return self.constant(0 if sine else 1)
        nf = self._nfree
        shift = (0,) * nf + tuple(min(v, -v) for v in k)
        plus = (0,) * nf + tuple(v - s for v, s in zip(k, shift[nf:], strict=True))
        minus = (0,) * nf + tuple(-v - s for v, s in zip(k, shift[nf:], strict=True))
        half = flint.fmpq(1, 2)
        if sine:  # sin x = (−i/2) e^{ix} + (i/2) e^{−ix}
            comps = {1: self._ctx.from_dict({plus: -half, minus: half})}
        else:
            comps = {0: self._ctx.from_dict({plus: half, minus: half})}
        return _poisson.make_series(self, shift, comps)

    def from_terms(self, terms: Iterable[Sequence[Any]]) -> PoissonSeries:
        """Build a series from real terms ``(coeff, exponents, kind, harmonics)``.

        Parameters
        ----------
        terms : iterable of (rational, sequence of int or mapping, {"cos", "sin"}, harmonics)
            ``exponents`` follow :attr:`poly_names` (momenta then parameters) or are a
            ``{name: int}`` mapping; ``harmonics`` as in :meth:`cos`.

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> R = PoissonRing(["q"], ["p"])
        >>> R.from_terms([("1/2", [2], "cos", [1]), (3, {"p": -1}, "sin", [2])])
        1/2*p**2*cos(q) + 3*p**-1*sin(2*q)
        """
        shift, comps = decompose(self, terms)
        return _poisson.PoissonSeries(self, shift, comps)

    def from_sympy(self, expr: Any) -> PoissonSeries:
        """Convert a sympy expression (or a string for ``sympy.sympify``) to a series.

        Parameters
        ----------
        expr : sympy.Expr or str
            Built from rationals, the ring's symbols (matched by name), ``+``, ``*``, integer
            powers and ``cos``/``sin`` of integer combinations of angles.

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> R = PoissonRing(["q"], ["p"])
        >>> R.from_sympy("cos(q)**3")
        3/4*cos(q) + 1/4*cos(3*q)
        """
        return series_from_sympy(self, expr)

    def exponent_vector(self, e: Sequence[int] | Mapping[str, int]) -> tuple[int, ...]:
        """Normalise monomial exponents given in :attr:`poly_names` order or by name.

        Parameters
        ----------
        e : sequence of int or mapping of str to int

        Returns
        -------
        tuple of int

        Examples
        --------
        >>> PoissonRing(["q"], ["p"], ["a"]).exponent_vector({"a": 2})
        (0, 2)
        """
        if isinstance(e, Mapping):
            bad = set(e) - set(self.poly_names)
            if bad:
                msg = f"expected exponents keyed by {self.poly_names}, got {sorted(bad)}"
                raise ValueError(msg)
            vec = [e.get(n, 0) for n in self.poly_names]
        else:
            vec = list(e)
        if len(vec) != len(self.poly_names) or not all(
            isinstance(v, int) and not isinstance(v, bool) for v in vec
        ):
            msg = f"expected {len(self.poly_names)} integer exponents, got {e!r}"
            raise ValueError(msg)
        for name, v in zip(self.poly_names, vec, strict=True):
            if v < 0 and name in self.relations:
                msg = f"expected a nonnegative exponent of relation generator {name}, got {v}"
                raise ValueError(msg)
        return tuple(vec)


def _looks_rational(text: str) -> bool:
    try:
        Fraction(text)
    except ValueError:
        return False
    return True
