"""Exact Poisson series: the ring that declares the variables and the series built in it.

A :class:`PoissonRing` fixes what a family of series may contain: angles (which enter only
through ``cos`` and ``sin`` of integer combinations), polynomial variables (momenta, or
polynomial coordinates paired with momenta) and symbolic parameters.  Polynomial variables and
parameters may carry negative exponents (Laurent monomials), except the generators of a
quadratic relation ``x² = D``.  A :class:`PoissonSeries` is a finite sum
``Σ c · x^e · cos(k·θ)`` or ``… sin(k·θ)`` with rational ``c``, Laurent monomials ``x^e`` in
the momenta and parameters and integer harmonics ``k``.

The two classes live together because each is defined through the other (a ring builds its
series; a series knows its ring, and reading one from JSON rebuilds the ring), as a polynomial
ring and its elements do in sympy's ``rings`` module.  The operations on the internal form are
below them: :mod:`~andoyer.series.components` (the representation), ``bracket``,
``averaging``, ``substitution`` (calculus), ``text``, ``symbolic``, ``numeric`` and
``serialize`` (conversions).

Internally a series is ``m · Σ_c g^c P_c`` where ``m`` is a Laurent monomial (the *shift*),
``P_c`` are python-flint ``fmpq_mpoly`` polynomials in the polynomial variables, the free
parameters and one variable ``z_j = exp(i θ_j)`` per angle, and ``g^c`` runs over square-free
products of the imaginary unit and the relation generators (a bit mask ``c``).  The free-module
basis ``{g^c}`` and the shift normalised to a zero minimum exponent make the representation
canonical, so that a product is a handful of C-level polynomial products.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping, Sequence
from fractions import Fraction
from typing import Any

import flint

from andoyer.series.averaging import average
from andoyer.series.bracket import derivative, poisson_bracket
from andoyer.series.components import Comps, Shift, add_into, aligned, normalized, product_comps
from andoyer.series.numeric import CompiledSeries
from andoyer.series.rationals import EXACT_TYPES, as_rational, to_fmpq
from andoyer.series.serialize import decode as decode_json
from andoyer.series.serialize import encode as encode_json
from andoyer.series.substitution import substitute, taylor_shift, term_order, truncate
from andoyer.series.symbolic import series_from_sympy, series_to_latex, series_to_sympy
from andoyer.series.terms import Term, decompose, harmonic_sign, real_terms
from andoyer.series.text import parse_series, series_to_text

__all__ = ["PoissonRing", "PoissonSeries", "make_series"]

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
        for name, expression in self.relations.items():
            d = parse_series(base, expression)
            allowed = set(self._free) - set(self.momenta)
            if (
                set(d.variables()) - allowed
                or any(e < 0 for e in d._shift)
                or set(d._comps) - {0}
                or d.is_zero()
            ):
                msg = (
                    f"expected relation {name}² = D with D a nonzero polynomial in the "
                    f"non-relation parameters, got {expression!r}"
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

    # ------------------------------------------------------------------ series constructors
    def __call__(self, value: Any) -> PoissonSeries:
        """Make a series from a rational, a string expression or a series of this ring."""
        if isinstance(value, PoissonSeries):
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
        >>> from andoyer.series import PoissonRing
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
        >>> from andoyer.series import PoissonRing
        >>> PoissonRing(["q"], ["p"]).constant("3/4")
        3/4
        """
        c = to_fmpq(value)
        return make_series(self, self._zero_shift, {0: self._ctx.constant(c)})

    @property
    def zero(self) -> PoissonSeries:
        """The zero series.

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> PoissonRing(["q"], ["p"]).zero.is_zero()
        True
        """
        return self.constant(0)

    @property
    def one(self) -> PoissonSeries:
        """The unit series.

        Examples
        --------
        >>> from andoyer.series import PoissonRing
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
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"], ["a"])
        >>> R.gen("p") * R.gen("a") ** -2
        p*a**-2
        """
        if name in self._rel:
            bit = 1 << (self._rel.index(name) + 1)
            return make_series(self, self._zero_shift, {bit: self._ctx.constant(1)})
        if name not in self._free:
            msg = f"expected a momentum or parameter of {self.poly_names}, got {name!r}"
            raise ValueError(msg)
        shift = list(self._zero_shift)
        shift[self._index[name]] = 1
        return make_series(self, tuple(shift), {0: self._ctx.constant(1)})

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
        >>> from andoyer.series import PoissonRing
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
        >>> from andoyer.series import PoissonRing
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
        >>> from andoyer.series import PoissonRing
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
        return make_series(self, shift, comps)

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
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"])
        >>> R.from_terms([("1/2", [2], "cos", [1]), (3, {"p": -1}, "sin", [2])])
        1/2*p**2*cos(q) + 3*p**-1*sin(2*q)
        """
        shift, comps = decompose(self, terms)
        return PoissonSeries(self, shift, comps)

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
        >>> from andoyer.series import PoissonRing
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
        >>> from andoyer.series import PoissonRing
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


def make_series(ring: PoissonRing, shift: Shift, comps: Comps) -> PoissonSeries:
    """Canonical series from a decomposition ``x^shift · Σ g^c P_c``.

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> R = PoissonRing(["q"], ["p"])
    >>> make_series(R, (-1, 0), {0: R._ctx.gens()[0] ** 3})
    p**2
    """
    shift, comps = normalized(ring, shift, comps)
    return PoissonSeries(ring, shift, comps)


class PoissonSeries:
    """An exact Poisson series ``Σ c · x^e · {cos, sin}(k·θ)``; immutable.

    Build series from a :class:`~andoyer.series.PoissonRing` (``R("L**2*cos(2*l)")``,
    :meth:`~andoyer.series.PoissonRing.gen`, :meth:`~andoyer.series.PoissonRing.cos`, ...)
    and combine them with ``+ - *``, ``/`` (by a rational or a monomial) and ``**``.
    Equal series compare equal: the representation is canonical.

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> R = PoissonRing(["q"], ["p"])
    >>> f = R("p*cos(q)")
    >>> f * f
    1/2*p**2 + 1/2*p**2*cos(2*q)
    >>> f.bracket(R("p**2/2")) == f.diff("q") * R("p")
    True
    """

    __slots__ = ("_comps", "_ring", "_shift", "_terms")

    def __init__(self, ring: PoissonRing, shift: tuple[int, ...], comps: Comps) -> None:
        self._ring = ring
        self._shift = shift
        self._comps = comps
        self._terms: tuple[Term, ...] | None = None

    def _new(self, shift: Shift, comps: Comps) -> PoissonSeries:
        return make_series(self._ring, shift, comps)

    # ------------------------------------------------------------------ basic protocol
    @property
    def ring(self) -> PoissonRing:
        """The :class:`~andoyer.series.PoissonRing` of this series.

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> PoissonRing(["q"], ["p"])("p").ring.momenta
        ('p',)
        """
        return self._ring

    def is_zero(self) -> bool:
        """Whether the series is zero.

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"])
        >>> (R("p") - R("p")).is_zero()
        True
        """
        return not self._comps

    def _coerce(self, other: Any) -> PoissonSeries | None:
        if isinstance(other, PoissonSeries):
            self._ring.check(other)
            return other
        if isinstance(other, EXACT_TYPES) and not isinstance(other, bool):
            return self._ring.constant(other)
        return None

    def __eq__(self, other: object) -> bool:
        if isinstance(other, PoissonSeries) and other._ring != self._ring:
            return False
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        return (
            self._shift == o._shift
            and self._comps.keys() == o._comps.keys()
            and all(p == o._comps[m] for m, p in self._comps.items())
        )

    def __hash__(self) -> int:
        return hash((self._shift, tuple(sorted((m, str(p)) for m, p in self._comps.items()))))

    def __bool__(self) -> bool:
        return bool(self._comps)

    def __len__(self) -> int:
        return len(self.terms())

    def __repr__(self) -> str:
        return series_to_text(self)

    __str__ = __repr__

    # ------------------------------------------------------------------ arithmetic
    def __add__(self, other: Any) -> PoissonSeries:
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        if not o._comps:
            return self
        if not self._comps:
            return o
        shift, ca, cb = aligned(self._ring, (self._shift, self._comps), (o._shift, o._comps))
        out = dict(ca)
        add_into(out, cb)
        return make_series(self._ring, shift, out)

    __radd__ = __add__

    def __neg__(self) -> PoissonSeries:
        return PoissonSeries(self._ring, self._shift, {m: -p for m, p in self._comps.items()})

    def __pos__(self) -> PoissonSeries:
        return self

    def __sub__(self, other: Any) -> PoissonSeries:
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        return self + (-o)

    def __rsub__(self, other: Any) -> PoissonSeries:
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        return o + (-self)

    def __mul__(self, other: Any) -> PoissonSeries:
        if isinstance(other, EXACT_TYPES) and not isinstance(other, bool):
            c = to_fmpq(other)
            if c == 0:
                return self._ring.zero
            return PoissonSeries(self._ring, self._shift, {m: p * c for m, p in self._comps.items()})
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        if not self._comps or not o._comps:
            return self._ring.zero
        shift = tuple(a + b for a, b in zip(self._shift, o._shift, strict=True))
        return make_series(self._ring, shift, product_comps(self._ring, self._comps, o._comps))

    __rmul__ = __mul__

    def is_unit(self) -> bool:
        """Whether the series is a nonzero rational times a Laurent monomial (invertible).

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"], ["a"])
        >>> R("3*p**-2*a").is_unit(), R("p + a").is_unit(), R("cos(q)").is_unit()
        (True, False, False)
        """
        nf = self._ring._nfree
        return (
            list(self._comps) == [0]
            and len(self._comps[0]) == 1
            and not any(self._shift[nf:])
            and self._comps[0].is_constant()
        )

    def inverse(self) -> PoissonSeries:
        """Return ``1/self`` for a unit (rational times Laurent monomial).

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> PoissonRing(["q"], ["p"], ["a"])("2*p*a**-1").inverse()
        1/2*p**-1*a
        """
        if not self.is_unit():
            msg = f"expected a rational times a Laurent monomial to invert, got {self}"
            raise ValueError(msg)
        c = self._comps[0].coeffs()[0]
        return PoissonSeries(self._ring, tuple(-a for a in self._shift), {0: self._ring._ctx.constant(1 / c)})

    def __truediv__(self, other: Any) -> PoissonSeries:
        if isinstance(other, EXACT_TYPES) and not isinstance(other, bool):
            c = to_fmpq(other)
            if c == 0:
                msg = "expected a nonzero divisor, got 0"
                raise ValueError(msg)
            return self * (1 / c)
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        return self * o.inverse()

    def __rtruediv__(self, other: Any) -> PoissonSeries:
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        return o * self.inverse()

    def __pow__(self, n: int) -> PoissonSeries:
        if not isinstance(n, int) or isinstance(n, bool):
            msg = f"expected an integer exponent, got {n!r}"
            raise ValueError(msg)
        if n < 0:
            return self.inverse() ** (-n)
        result = self._ring.one
        base = self
        while n:
            if n & 1:
                result = result * base
            n >>= 1
            if n:
                base = base * base
        return result

    # ------------------------------------------------------------------ structure
    def terms(self) -> tuple[Term, ...]:
        """Return the real terms in canonical order.

        Each :class:`Term` holds ``coeff`` (Fraction), ``exponents`` (over
        ``ring.poly_names``: momenta then parameters), ``kind`` (``"cos"`` or ``"sin"``) and
        ``harmonics`` (first nonzero entry positive).  Terms are sorted by harmonic, then
        kind, then total degree.

        Returns
        -------
        tuple of Term

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"])
        >>> R("p*sin(-q) + 1").terms()
        (Term(coeff=Fraction(1, 1), exponents=(0,), kind='cos', harmonics=(0,)),
         Term(coeff=Fraction(-1, 1), exponents=(1,), kind='sin', harmonics=(1,)))
        """
        if self._terms is None:
            self._terms = real_terms(self._ring, self._shift, self._comps)
        return self._terms

    def variables(self) -> tuple[str, ...]:
        """Names of the variables and parameters that occur, in ring order.

        Returns
        -------
        tuple of str

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> PoissonRing(["l", "g"], ["L", "G"])("L*cos(g)").variables()
        ('g', 'L')
        """
        ring = self._ring
        used = set()
        for t in self.terms():
            used.update(a for a, v in zip(ring.angles, t.harmonics, strict=True) if v)
            used.update(n for n, v in zip(ring.poly_names, t.exponents, strict=True) if v)
        return tuple(n for n in ring.variables if n in used)

    def trig_coefficient(self, kind: str, harmonics: Sequence[int] | Mapping[str, int]) -> PoissonSeries:
        """Return the angle-free coefficient of ``cos(k·θ)`` or ``sin(k·θ)``.

        Parameters
        ----------
        kind : {"cos", "sin"}
        harmonics : sequence of int or mapping of str to int
            The harmonic ``k``; its sign is normalised (``sin(−x) = −sin x``).

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"])
        >>> R("3*p*sin(2*q) + cos(q)").trig_coefficient("sin", [-2])
        -3*p
        """
        k = self._ring.harmonic_vector(harmonics)
        if kind not in ("cos", "sin"):
            msg = f"expected kind 'cos' or 'sin', got {kind!r}"
            raise ValueError(msg)
        factor = 1
        if harmonic_sign(k) < 0:
            k = tuple(-v for v in k)
            factor = -1 if kind == "sin" else 1
        zero = (0,) * len(k)
        picked = [
            (t.coeff * factor, t.exponents, "cos", zero)
            for t in self.terms()
            if t.kind == kind and t.harmonics == k
        ]
        return self._ring.from_terms(picked)

    def __iter__(self) -> Iterator[Term]:
        return iter(self.terms())

    # ------------------------------------------------------------------ calculus
    def diff(self, name: str) -> PoissonSeries:
        """Partial derivative with respect to an angle, momentum or free parameter.

        Parameters
        ----------
        name : str
            Variable name; relation generators and the parameters in a relation are refused
            (they are not independent).

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"])
        >>> R("p**-1*cos(2*q)").diff("q"), R("p**-1*cos(2*q)").diff("p")
        (-2*p**-1*sin(2*q), -p**-2*cos(2*q))
        """
        return derivative(self, name)

    def bracket(self, other: PoissonSeries) -> PoissonSeries:
        """Poisson bracket ``{self, other} = Σ (∂self/∂q ∂other/∂p − ∂self/∂p ∂other/∂q)``.

        Parameters
        ----------
        other : PoissonSeries

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"])
        >>> R("cos(q)").bracket(R("p"))
        -sin(q)
        """
        return poisson_bracket(self, other)

    def average(self, angles: Sequence[str] | None = None) -> PoissonSeries:
        """Average over the given angles (default: all angles).

        Parameters
        ----------
        angles : sequence of str, optional

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["l", "g"], ["L", "G"])
        >>> R("L + cos(l) + cos(g)").average(["l"])
        L + cos(g)
        """
        return average(self, angles)

    def truncate(self, order: Any) -> PoissonSeries:
        """Drop the terms whose weighted order (ring weights) exceeds ``order``.

        Parameters
        ----------
        order : rational

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"], ["eps"], weights={"eps": 1})
        >>> R("(1 + eps)**3 * cos(q)").truncate(1)
        cos(q) + 3*eps*cos(q)
        """
        return truncate(self, order)

    def order(self) -> Fraction | None:
        """Lowest weighted order among the terms (``None`` for the zero series).

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"], ["eps"], weights={"eps": 1})
        >>> R("eps**2 + eps**3*p").order()
        Fraction(2, 1)
        """
        if not self._comps:
            return None
        return min(term_order(self._ring, t) for t in self.terms())

    def subs(self, values: Mapping[str, Any]) -> PoissonSeries:
        """Substitute momenta or parameters by rationals or series (exactly, no truncation).

        Parameters
        ----------
        values : mapping of str to rational or PoissonSeries
            A negative power of a substituted variable needs a unit (monomial) value.

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"], ["a"])
        >>> R("a*p**2*cos(q)").subs({"a": "1/2", "p": R("p + 1")})
        1/2*cos(q) + p*cos(q) + 1/2*p**2*cos(q)
        """
        return substitute(self, values)

    def shifted(self, deltas: Mapping[str, PoissonSeries], order: Any) -> PoissonSeries:
        """Taylor-expand ``f(x + Δ)`` for angles or momenta ``x``, truncated at ``order``.

        Parameters
        ----------
        deltas : mapping of str to PoissonSeries
            Increments ``Δ_x``; each must have weighted order larger than the weight of ``x``.
        order : rational
            Truncation order (ring weights).

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"], ["eps"], weights={"eps": 1})
        >>> R("cos(q)").shifted({"q": R("eps")}, order=2)
        cos(q) - 1/2*eps**2*cos(q) - eps*sin(q)
        """
        return taylor_shift(self, deltas, order)

    # ------------------------------------------------------------------ conversions
    def to_json(self, indent: int | None = None) -> str:
        """Serialise to JSON with exact ``"p/q"`` coefficients and the ring declaration.

        Parameters
        ----------
        indent : int, optional

        Returns
        -------
        str

        Examples
        --------
        >>> from andoyer.series import PoissonRing, PoissonSeries
        >>> f = PoissonRing(["q"], ["p"])("p/3*sin(q)")
        >>> PoissonSeries.from_json(f.to_json()) == f
        True
        """
        return encode_json(self._ring.spec(), self.terms(), indent=indent)

    @staticmethod
    def from_json(text: str, ring: PoissonRing | None = None) -> PoissonSeries:
        """Read a series written by :meth:`to_json`.

        Parameters
        ----------
        text : str
        ring : PoissonRing, optional
            If given, the stored ring must equal it (and the series uses this object).

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> from andoyer.series import PoissonRing, PoissonSeries
        >>> PoissonSeries.from_json(PoissonRing(["q"], ["p"])("p").to_json())
        p
        """
        spec, terms = decode_json(text)
        stored = PoissonRing.from_spec(spec)
        if ring is None:
            ring = stored
        elif ring != stored:
            msg = f"expected a series of {ring!r}, got one of {stored!r}"
            raise ValueError(msg)
        return ring.from_terms(terms)

    def to_sympy(self, symbols: Mapping[str, Any] | None = None) -> Any:
        """Convert to a sympy expression.

        Parameters
        ----------
        symbols : mapping of str to sympy.Symbol, optional
            Symbols to use; default ``sympy.Symbol(name)``.

        Returns
        -------
        sympy.Expr

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> PoissonRing(["q"], ["p"])("p**2/2*cos(q)").to_sympy()
        p**2*cos(q)/2
        """
        return series_to_sympy(self, symbols)

    def to_latex(self) -> str:
        r"""Return a LaTeX string, grouping terms by trigonometric argument.

        Returns
        -------
        str

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> PoissonRing(["l"], ["L"], ["beta"])("beta*L**2*cos(2*l)/2").to_latex()
        '\\frac{L^{2} \\beta}{2} \\cos{\\left(2 l \\right)}'
        """
        return series_to_latex(self)

    def compile(self) -> CompiledSeries:
        """Compile to a vectorised numpy function of ``ring.variables``.

        Returns
        -------
        CompiledSeries
            Callable with positional (in ``ring.variables`` order) or keyword arrays; all
            arguments broadcast together.

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> f = PoissonRing(["q"], ["p"])("p**2*cos(q)").compile()
        >>> f(q=[0.0, 3.141592653589793], p=2.0)
        array([ 4., -4.])
        """
        return CompiledSeries(self)


def _looks_rational(text: str) -> bool:
    try:
        Fraction(text)
    except ValueError:
        return False
    return True
