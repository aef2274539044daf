r"""A catalogue entry: :class:`Quantity` (a value with its unit, uncertainty and source) and :class:`Body`.

A :class:`Body` holds one optional :class:`Quantity` per key of
:data:`~andoyer.catalogue.schema.FIELDS`, a few text keys (``name``, ``kind``, ``primary``,
``orbit_frame``, ``orbit_epoch``, ``note``) and named moment sets (``moment_sets``: Lara's
Table 1 ratios as ``"lara2013"``). :meth:`Body.to_dict` is the JSON ``andoyer bodies --format json``
prints for one body, and :func:`andoyer.catalogue.body_from_dict` reads it back.

**Moments from the figure.** :meth:`Body.moments` gives ``(A/C, B/C)`` from, in this order, the
entry's own ratios; its dynamical ellipticity ``H`` with ``(A + B)/2C = 1 − H`` and
``(B − A)/C = 4 C22/(C/MR²)`` (or a named set's ``B − A`` when ``C22`` is not catalogued, an
axisymmetric body when neither is); or ``J2``, ``C22`` and ``C/MR²`` with
``(C − A)/MR² = J2 + 2C22`` and ``(C − B)/MR² = J2 − 2C22``.

Examples
--------
>>> from andoyer import catalogue
>>> moon = catalogue.get("moon")
>>> moon.gm.value, moon.gm.unit
(4902.80007, 'km3/s2')
>>> a, b = moon.moments()
>>> round((b - a) * 1e6, 4)  # γ = (B - A)/C, Williams et al. (2014)
227.7317
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from andoyer.catalogue import units
from andoyer.catalogue.schema import FIELDS

if TYPE_CHECKING:
    from andoyer.body import RigidBody

__all__ = ["Body", "Quantity"]


@dataclass(frozen=True)
class Quantity:
    """A value with its unit, its uncertainty (one sigma, same unit) and where it comes from.

    Attributes
    ----------
    value : float
    unit : str
        A key of :data:`andoyer.catalogue.units.UNITS`.
    uncertainty : float or None
        ``None`` when the source gives none.
    source : str
        A citation a reader can find.
    note : str
        How the value was obtained or checked, and what is not confirmed.

    Examples
    --------
    >>> q = Quantity(1.0, "au", None, "IAU 2012 Resolution B2")
    >>> q.to("km")
    149597870.7
    """

    value: float
    unit: str
    uncertainty: float | None
    source: str
    note: str = ""

    def to(self, unit: str) -> float:
        """The value in ``unit`` (same dimension)."""
        return units.convert(self.value, self.unit, unit)

    def si(self) -> float:
        """The value in SI (metres, seconds, radians; m³/s² for ``GM``)."""
        return float(self.value) * units.UNITS[self.unit][1]

    def to_dict(self) -> dict[str, Any]:
        """``{"value", "unit", "uncertainty", "source"}`` and ``"note"`` when there is one."""
        out: dict[str, Any] = {
            "value": self.value,
            "unit": self.unit,
            "uncertainty": self.uncertainty,
            "source": self.source,
        }
        if self.note:
            out["note"] = self.note
        return out


Q = Quantity | None


@dataclass(frozen=True)
class Body:
    """One body: its values (each a :class:`Quantity` or ``None``), text keys and moment sets.

    The numeric attributes are the keys of :data:`~andoyer.catalogue.schema.FIELDS` (see that
    module for their meaning); build one with :func:`andoyer.catalogue.body_from_dict` or
    :func:`andoyer.catalogue.read_body`, which check every value.

    Examples
    --------
    >>> from andoyer import catalogue
    >>> mars = catalogue.get("Mars")
    >>> mars.name, mars.kind, mars.primary
    ('Mars', 'planet', 'sun')
    >>> round(mars.rotation_period.to("h"), 6)
    24.622962
    >>> catalogue.get("pluto").require("j2", "the precession constant")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: expected Pluto to have j2 for the precession constant, got none ...
    """

    name: str
    kind: str = "user"
    primary: str | None = None
    orbit_frame: str = ""
    orbit_epoch: str = ""
    note: str = ""
    gm: Q = None
    radius: Q = None
    j2: Q = None
    c22: Q = None
    moment_of_inertia: Q = None
    dynamical_ellipticity: Q = None
    a_over_c: Q = None
    b_over_c: Q = None
    j0: Q = None
    rotation_period: Q = None
    rotation_rate: Q = None
    spin_rate: Q = None
    prime_meridian: Q = None
    pole_ra: Q = None
    pole_ra_rate: Q = None
    pole_dec: Q = None
    pole_dec_rate: Q = None
    pole_ra_periodic: Q = None
    pole_dec_periodic: Q = None
    age: Q = None
    obliquity: Q = None
    precession_rate: Q = None
    resonance: Q = None
    semi_major_axis: Q = None
    eccentricity: Q = None
    inclination: Q = None
    node: Q = None
    periapsis_longitude: Q = None
    argument_of_periapsis: Q = None
    mean_longitude: Q = None
    mean_anomaly: Q = None
    orbital_period: Q = None
    node_period: Q = None
    apsis_period: Q = None
    migration_rate: Q = None
    laplace_inclination: Q = None
    laplace_pole_ra: Q = None
    laplace_pole_dec: Q = None
    laplace_tilt: Q = None
    moment_sets: dict[str, dict[str, Quantity]] = field(default_factory=dict)

    @property
    def key(self) -> str:
        """The name in lower case (how :func:`andoyer.catalogue.get` finds it)."""
        return self.name.strip().lower()

    def values(self) -> dict[str, Quantity]:
        """The numeric keys this entry has, in :data:`FIELDS` order."""
        return {k: getattr(self, k) for k in FIELDS if getattr(self, k) is not None}

    def require(self, key: str, computation: str) -> Quantity:
        """The value of ``key``, or ``ValueError`` naming the body, the key and ``computation``.

        Parameters
        ----------
        key : str
            A key of :data:`FIELDS`.
        computation : str
            What needs it, for the message ("the Cassini states", ...).

        Returns
        -------
        Quantity
        """
        if key not in FIELDS:
            msg = f"expected a catalogue key among {', '.join(FIELDS)}, got {key!r}"
            raise ValueError(msg)
        value = getattr(self, key)
        if value is None:
            msg = (
                f"expected {self.name} to have {key} for {computation}, got none (not in the "
                f"catalogue entry; give it in a body file, andoyer bodies {self.key} --format json "
                "shows the keys)"
            )
            raise ValueError(msg)
        return value

    def moments(self, set: str | None = None) -> tuple[float, float]:
        """``(A/C, B/C)``: of the named moment set, or the default (module docstring).

        Parameters
        ----------
        set : str, optional
            A key of :attr:`moment_sets` (``"lara2013"``); default: the entry's own moments.

        Returns
        -------
        tuple of float

        Examples
        --------
        >>> from andoyer import catalogue
        >>> earth = catalogue.get("earth")
        >>> earth.moments("lara2013")
        (0.99672, 0.9967222)
        >>> a, b = earth.moments()              # IAU (MHB2000) H, Lara's B - A
        >>> round(1 - (a + b) / 2, 11)
        0.00327379492
        """
        if set is not None:
            chosen = self.moment_sets.get(set)
            if chosen is None or "a_over_c" not in chosen or "b_over_c" not in chosen:
                have = ", ".join(self.moment_sets) or "none"
                msg = f"expected a moment set of {self.name} among {have}, got {set!r}"
                raise ValueError(msg)
            return chosen["a_over_c"].value, chosen["b_over_c"].value
        if self.a_over_c is not None and self.b_over_c is not None:
            return self.a_over_c.value, self.b_over_c.value
        if self.dynamical_ellipticity is not None:
            H = self.dynamical_ellipticity.value
            if self.c22 is not None and self.moment_of_inertia is not None:
                spread = 4 * self.c22.value / self.moment_of_inertia.value
            else:
                spread = next(
                    (s["b_over_c"].value - s["a_over_c"].value for s in self.moment_sets.values()),
                    0.0,
                )
            return 1 - H - spread / 2, 1 - H + spread / 2
        if self.j2 is not None and self.c22 is not None and self.moment_of_inertia is not None:
            k = self.moment_of_inertia.value
            return 1 - (self.j2.value + 2 * self.c22.value) / k, 1 - (self.j2.value - 2 * self.c22.value) / k
        msg = (
            f"expected {self.name} to have a_over_c and b_over_c, dynamical_ellipticity, or j2, c22 "
            "and moment_of_inertia for its principal moments, got none"
        )
        raise ValueError(msg)

    def rigid_body(self, set: str | None = None) -> RigidBody:
        """The :class:`~andoyer.RigidBody` with moments ``(A/C, B/C, 1)`` (:meth:`moments`).

        Examples
        --------
        >>> from andoyer import catalogue
        >>> catalogue.get("mars").rigid_body()
        RigidBody(I1=0.9942917, I2=0.9949813, I3=1.0, name='Mars')
        """
        from andoyer.body import RigidBody

        a, b = self.moments(set)
        return RigidBody.from_ratios(a, b, name=self.name)

    def to_dict(self) -> dict[str, Any]:
        """The entry as JSON-ready data: text keys, every value present, the moment sets."""
        out: dict[str, Any] = {"name": self.name, "kind": self.kind}
        for key in ("primary", "orbit_frame", "orbit_epoch", "note"):
            if getattr(self, key):
                out[key] = getattr(self, key)
        out.update({k: q.to_dict() for k, q in self.values().items()})
        if self.moment_sets:
            out["moment_sets"] = {
                name: {k: q.to_dict() for k, q in values.items()} for name, values in self.moment_sets.items()
            }
        return out
