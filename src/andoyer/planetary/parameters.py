r"""The physical parameters of the planetary layer: each one's range, unit, reason and source.

One table, :data:`PARAMETERS`, says which values each named physical parameter may take. The
API (:mod:`~andoyer.planetary.spin_axis`, :mod:`~andoyer.planetary.precession`,
:mod:`~andoyer.planetary.cassini`, the orbit tables of :mod:`~andoyer.planetary.orbits`) and the
command line (``andoyer obliquity``, ``precession``, ``nutation``, ``cassini``, ``portrait
cassini``) check a value with :func:`check`, so that a value out of range gets the same answer
everywhere: ``expected a <name> <range> (<reason>), got <value>``. Angles are radians in the API and
degrees on the command line (the same bounds, converted).

======================  ==========  ===========================  ==========================================
parameter               unit        range                        why (source)
======================  ==========  ===========================  ==========================================
dynamical_ellipticity               0 < H < 0.5                  ``A + B ≥ C`` bounds ``H = (C − (A+B)/2)/C``
                                                                 by 1/2; ``H ≤ 0`` is a prolate or round
                                                                 body, which does not precess this way
precession_rate         arcsec/yr   P > 0                        a prograde spin precesses westward; at
                                                                 most the rate of ``H = 1/2`` for the body
                                                                 (:meth:`SpinAxisModel.from_precession_rate
                                                                 <andoyer.planetary.spin_axis.SpinAxisModel.from_precession_rate>`)
tidal_dissipation                   0 ≤ T_d ≤ 1.2                tides dissipate energy (``T_d < 0`` would
                                                                 feed it back); 1 is the modern rate, the
                                                                 geological record's means lie in [0, 1]
                                                                 (Zeebe & Lourens 2022; snvecR warns
                                                                 outside [0, 1.2])
ellipticity_drift       1/yr        finite                       ``H (1 + Ḣ_r t)`` must stay in (0, 1/2)
                                                                 over the span (checked with the span)
obliquity               rad         0 ≤ ε₀ < π/2                 ``ψ̇ = α cos ε₀`` sets ``α``: it needs
                                                                 ``cos ε₀ > 0``
eccentricity                        0 ≤ e < 1                    a bound orbit
semi_major_axis         au          a > 0                        a bound orbit's size (solution files)
inclination             rad         0 ≤ i ≤ π                    the angle between two unit normals
laplace_inclination     rad         0 < i < π/2                  Colombo's top: the orbit's inclination to
                                                                 its Laplace plane (Peale 1969)
moment_of_inertia                   0 < C/MR² ≤ 1                ``C = ∫(x² + y²) dm ≤ M R²`` for a body
                                                                 within the radius ``R`` (1: a ring)
j2                                  J2 > 0                       ``C > (A+B)/2``: an oblate body
c22                                 C22 ≥ 0                      ``B ≥ A`` (and ``C22 ≤ J2/2``, ``C`` the
                                                                 largest moment, checked with ``J2``)
node_period             yr          T_node > 0                   the period of a regressing node
migration_age           yr          0 < T_0 ≤ 1.3787e10          the satellites formed after the universe
                                                                 did: 13.787 Gyr (Planck Collaboration
                                                                 2020, A&A 641, A6)
======================  ==========  ===========================  ==========================================

The spans of validity (an orbit source's ``span``, the lunar theory's, the output step against
the fastest motion printed) depend on the request, not on one number: they are checked where
the request is known and named in the same ``expected …, got …`` form.

Examples
--------
>>> check("tidal_dissipation", 1.0)
1.0
>>> check("tidal_dissipation", 1e6)  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
ValueError: expected a tidal dissipation 0 <= T_d <= 1.2 (tides dissipate energy...), got 1000000.0
>>> check("inclination", 500.0, degrees=True)  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
ValueError: expected an inclination 0 <= i <= 180 deg (the angle between two unit normals), got 500.0
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

__all__ = ["PARAMETERS", "Parameter", "check"]


@dataclass(frozen=True)
class Parameter:
    """A named physical parameter: its symbol, unit and range, and why the range is what it is.

    Attributes
    ----------
    name : str
        In words, as the messages say it (``"dynamical ellipticity"``).
    symbol : str
        ASCII symbol of the messages (``"H"``).
    low, high : float
        The bounds (``-inf`` / ``inf``: none), in the API's unit.
    low_closed, high_closed : bool
        Whether a bound itself is allowed.
    unit : str
        The API's unit (``"rad"`` for angles, ``""`` for a pure number).
    reason : str
        Why the bounds are there (and where the numbers come from).

    Examples
    --------
    >>> PARAMETERS["eccentricity"].describe()
    '0 <= e < 1'
    """

    name: str
    symbol: str
    low: float
    high: float
    low_closed: bool
    high_closed: bool
    unit: str
    reason: str

    def describe(self, degrees: bool = False) -> str:
        """The range as the messages write it, e.g. ``0 < H < 0.5`` (angles in degrees if asked)."""
        scale = 180.0 / math.pi if degrees and self.unit == "rad" else 1.0
        unit = "deg" if scale != 1.0 else self.unit
        low, high = math.isfinite(self.low), math.isfinite(self.high)
        if low and not high:  # one bound: "J2 > 0" reads better than "0 < J2"
            parts = [self.symbol, ">=" if self.low_closed else ">", _number(self.low * scale)]
        elif high and not low:
            parts = [self.symbol, "<=" if self.high_closed else "<", _number(self.high * scale)]
        elif not low:
            parts = [self.symbol, "finite"]
        else:
            parts = [
                _number(self.low * scale),
                "<=" if self.low_closed else "<",
                self.symbol,
                "<=" if self.high_closed else "<",
                _number(self.high * scale),
            ]
        return " ".join(parts) + (f" {unit}" if unit else "")

    def contains(self, value: float, degrees: bool = False) -> bool:
        """Whether the real ``value`` (degrees for an angle when asked) lies in the range."""
        x = math.radians(value) if degrees and self.unit == "rad" else value
        if not math.isfinite(x):
            return False
        above = x >= self.low if self.low_closed else x > self.low
        below = x <= self.high if self.high_closed else x < self.high
        return above and below

    def check(self, value: object, degrees: bool = False) -> float:
        """``value`` as a float, or :class:`ValueError` ``expected a <name> <range> (<reason>), got …``.

        Parameters
        ----------
        value : float
            A real number (a 0-d array or a numpy scalar too; not a bool).
        degrees : bool
            For an angle: ``value`` and the message are in degrees; the answer stays in degrees.

        Returns
        -------
        float
        """
        real = isinstance(value, numbers.Real) and not isinstance(value, bool)
        if not real and getattr(value, "shape", None) == () and getattr(value, "dtype", None) is not None:
            real = value.dtype.kind in "iuf"  # type: ignore[attr-defined]
        x = float(value) if real else math.nan  # type: ignore[arg-type]
        if not self.contains(x, degrees):
            article = "an" if self.name[0] in "aeiou" else "a"
            msg = f"expected {article} {self.name} {self.describe(degrees)} ({self.reason}), got {value!r}"
            raise ValueError(msg)
        return x


def _number(x: float) -> str:
    return f"{x:.10g}"


#: Every named physical parameter of the planetary layer (see the module's table).
PARAMETERS: dict[str, Parameter] = {
    "dynamical_ellipticity": Parameter(
        "dynamical ellipticity", "H", 0.0, 0.5, False, False, "",
        "A + B >= C bounds H = (C - (A+B)/2)/C by 1/2; H <= 0 is a prolate or round body, "
        "which does not precess this way",
    ),
    "precession_rate": Parameter(
        "precession rate", "P", 0.0, math.inf, False, False, "arcsec/yr",
        "psi_A at J2000, westward for a prograde spin; at most the rate of H = 1/2 for the body",
    ),
    "tidal_dissipation": Parameter(
        "tidal dissipation", "T_d", 0.0, 1.2, True, True, "",
        "tides dissipate energy: T_d < 0 would feed it back; 1 is the modern rate and the geological "
        "record's means lie in [0, 1], Zeebe & Lourens 2022, whose snvecR warns outside [0, 1.2]",
    ),
    "ellipticity_drift": Parameter(
        "ellipticity drift", "dH/H", -math.inf, math.inf, False, False, "1/yr",
        "H (1 + drift t) must also stay within (0, 1/2) over the span",
    ),
    "obliquity": Parameter(
        "obliquity at J2000", "eps0", 0.0, math.pi / 2, True, False, "rad",
        "the precession rate alpha cos(eps0) sets alpha: it needs cos(eps0) > 0",
    ),
    "eccentricity": Parameter("eccentricity", "e", 0.0, 1.0, True, False, "", "a bound orbit"),
    "semi_major_axis": Parameter(
        "semi-major axis", "a", 0.0, math.inf, False, False, "au", "a bound orbit's size"
    ),
    "inclination": Parameter(
        "inclination", "i", 0.0, math.pi, True, True, "rad", "the angle between two unit normals"
    ),
    "laplace_inclination": Parameter(
        "inclination", "i", 0.0, math.pi / 2, False, False, "rad",
        "Colombo's top: the orbit's inclination to its Laplace plane, Peale 1969",
    ),
    "moment_of_inertia": Parameter(
        "polar moment of inertia", "C/MR^2", 0.0, 1.0, False, True, "",
        "C = integral of (x^2 + y^2) dm <= M R^2 for a body within the radius R (1: a ring)",
    ),
    "j2": Parameter(
        "second-degree zonal coefficient", "J2", 0.0, math.inf, False, False, "",
        "C > (A+B)/2: an oblate body",
    ),
    "c22": Parameter(
        "second-degree sectoral coefficient", "C22", 0.0, math.inf, True, False, "",
        "B >= A; C22 <= J2/2 is checked with J2",
    ),
    "node_period": Parameter(
        "node period", "T_node", 0.0, math.inf, False, False, "yr", "the period of a regressing node"
    ),
    "migration_age": Parameter(
        "migration age", "T0", 0.0, 1.3787e10, False, True, "yr",
        "the time since the satellites formed: at most the age of the universe, 13.787 Gyr, Planck 2020",
    ),
}  # fmt: skip


def check(name: str, value: object, degrees: bool = False) -> float:
    """Check ``value`` against the range of the parameter ``name`` of :data:`PARAMETERS`.

    Parameters
    ----------
    name : str
        A key of :data:`PARAMETERS`.
    value : float
    degrees : bool
        For an angle, ``value`` in degrees (the command line's unit).

    Returns
    -------
    float
        ``value`` (in its own unit).

    Examples
    --------
    >>> check("dynamical_ellipticity", 0.0032737949)
    0.0032737949
    >>> check("dynamical_ellipticity", 0.9)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: expected a dynamical ellipticity 0 < H < 0.5 (A + B >= C bounds H ...), got 0.9
    """
    if name not in PARAMETERS:
        msg = f"expected a parameter among {', '.join(PARAMETERS)}, got {name!r}"
        raise ValueError(msg)
    return PARAMETERS[name].check(value, degrees)
