r"""A term's equations as components: Python floats (one body), arrays (N,) or heyoka expressions.

The reference integrators write the hub equations of each model term on the
components of ``q`` and ``m``: on Python floats for one body (a numpy call costs
twenty times a float operation), on arrays ``(N,)`` for many, or as heyoka
expressions. The helpers here are generic over the three, so a term writes its
formula once (:meth:`~andoyer.perturbations.base.Perturbation.hub_rates`,
:meth:`~andoyer.perturbations.base.Perturbation.heyoka_rates`).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from andoyer._quaternion import apply
from andoyer.perturbations.orbits import CircularOrbit, KeplerOrbit, Orbit

__all__ = ["HeyokaContext", "Parameters", "float_position", "kepler_position", "to_body"]

# Components: Python floats for one body, else arrays (N,) or heyoka expressions.
Vector = tuple[Any, Any, Any]
Quaternion = tuple[Any, Any, Any, Any]
#: A term's contribution to the hub equations: ``(δω, δṁ)`` (either ``None`` when zero) from
#: ``(t, q, m)`` components; ``δω`` is added to ``ω = I⁻¹m`` in ``q̇``, ``δṁ`` to ``ṁ``.
HubRates = Callable[[float, Quaternion, Vector], tuple[Vector | None, Vector | None]]


def to_body(q: Sequence[Any], v: Sequence[Any]) -> Vector:
    """``Rᵀ v`` (as ``quat.rotate(quat.conjugate(q), v)``), by components (:func:`andoyer._quaternion.apply`).

    Examples
    --------
    A quarter turn about ``s3``: the reference axis ``s1`` is ``−b2`` in the body.

    >>> q = (0.0, 0.0, math.sin(0.25 * math.pi), math.cos(0.25 * math.pi))
    >>> [round(c, 12) + 0.0 for c in to_body(q, (1.0, 0.0, 0.0))]
    [0.0, -1.0, 0.0]
    """
    return apply(-q[0], -q[1], -q[2], q[3], v[0], v[1], v[2])


class Parameters:
    """Runtime parameters of a heyoka system: each number becomes ``par[k]`` with its value recorded."""

    def __init__(self, hy: Any) -> None:
        self.hy = hy
        self.values: list[float] = []

    def __call__(self, value: float) -> Any:
        """``par[k]`` for a new parameter ``k`` holding ``value``."""
        self.values.append(float(value))
        return self.hy.par[len(self.values) - 1]


def _cos_sin(hy: Any, par: Parameters, angle: float, rate: float, dt: Any) -> tuple[Any, Any]:
    """``cos``, ``sin`` of ``angle + rate dt``: parameters when the angle does not drift."""
    if rate == 0.0:
        return par(math.cos(angle)), par(math.sin(angle))
    value = par(angle) + par(rate) * dt
    return hy.cos(value), hy.sin(value)


def kepler_position(hy: Any, par: Parameters | None, orbit: Orbit, time: Any = None) -> list[Any]:
    r"""Reference-frame position of a Kepler orbit as heyoka expressions of ``heyoka.time``.

    .. math:: \mathbf r = R_z(\Omega)R_x(i)R_z(\omega)\,a(\cos E - e, \sqrt{1-e^2}\sin E, 0),
       \quad E = \mathrm{kepE}(e, M_0 + n(t - t_0)),

    ``E = M`` for circular orbits; ``Ω``, ``ω`` drift linearly when their rates are nonzero.

    Parameters
    ----------
    hy : module
        heyoka.
    par : callable or None
        Maps each number to a runtime parameter; ``None`` embeds the numbers as constants.
    orbit : KeplerOrbit or CircularOrbit
    time : heyoka expression, optional
        The time ``t`` of the orbit's elements; default ``heyoka.time``.

    Returns
    -------
    list of 3 heyoka expressions

    Raises
    ------
    ValueError
        For other orbits (tabulated ones: no closed form).

    Examples
    --------
    >>> from andoyer.perturbations import TabulatedOrbit
    >>> kepler_position(None, None, TabulatedOrbit(lambda t: np.stack([t, t, t], -1)))  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: expected a KeplerOrbit or CircularOrbit for heyoka, got <...TabulatedOrbit object at ...>
    """
    if type(orbit) not in (KeplerOrbit, CircularOrbit):
        msg = f"expected a KeplerOrbit or CircularOrbit for heyoka, got {orbit!r}"
        raise ValueError(msg)
    if par is None:
        par = float  # type: ignore[assignment]
    dt = (hy.time if time is None else time) - par(orbit.epoch)
    mean = par(orbit.mean_anomaly) + par(orbit.mean_motion) * dt
    a, e = orbit.semi_major_axis, orbit.eccentricity
    if e == 0.0:
        x, y = par(a) * hy.cos(mean), par(a) * hy.sin(mean)
    else:
        anomaly = hy.kepE(par(e), mean)
        x = par(a) * (hy.cos(anomaly) - par(e))
        y = par(a * math.sqrt((1 - e) * (1 + e))) * hy.sin(anomaly)
    cO, sO = _cos_sin(hy, par, orbit.node, orbit.node_rate, dt)
    cw, sw = _cos_sin(hy, par, orbit.periapsis, orbit.periapsis_rate, dt)
    ci, si = par(math.cos(orbit.inclination)), par(math.sin(orbit.inclination))
    return [
        (cO * cw - sO * ci * sw) * x + (-cO * sw - sO * ci * cw) * y,
        (sO * cw + cO * ci * sw) * x + (-sO * sw + cO * ci * cw) * y,
        si * sw * x + si * cw * y,
    ]


def eccentric_anomaly(M: float, e: float) -> float:
    """:func:`~andoyer.perturbations.solve_kepler` on one float (same start and stopping rule)."""
    turns = math.floor((M + math.pi) / (2 * math.pi))
    Mr = M - 2 * math.pi * turns
    E = Mr + 0.85 * e * (math.copysign(1.0, math.sin(Mr)) if math.sin(Mr) != 0 else 0.0)
    for _ in range(60):
        step = (E - e * math.sin(E) - Mr) / (1 - e * math.cos(E))
        E -= step
        if abs(step) <= 4 * np.finfo(float).eps * max(1.0, abs(E)):
            break
    return E + 2 * math.pi * turns


def float_position(orbit: Orbit) -> Callable[[float], Vector]:
    """``orbit.position`` at one time, on Python floats for Kepler and circular orbits."""
    if type(orbit) not in (KeplerOrbit, CircularOrbit):
        return lambda t: tuple(np.asarray(orbit.position(t), dtype=float).reshape(3).tolist())
    a, e, epoch = orbit.semi_major_axis, orbit.eccentricity, orbit.epoch
    b = a * math.sqrt((1 - e) * (1 + e))
    ci, si = math.cos(orbit.inclination), math.sin(orbit.inclination)

    def position(t: float) -> Vector:
        dt = t - epoch
        mean = orbit.mean_anomaly + orbit.mean_motion * dt
        if e == 0.0:
            x, y = a * math.cos(mean), a * math.sin(mean)
        else:
            E = eccentric_anomaly(mean, e)
            x, y = a * (math.cos(E) - e), b * math.sin(E)
        node = orbit.node + orbit.node_rate * dt
        periapsis = orbit.periapsis + orbit.periapsis_rate * dt
        cO, sO, cw, sw = math.cos(node), math.sin(node), math.cos(periapsis), math.sin(periapsis)
        return (
            (cO * cw - sO * ci * sw) * x + (-cO * sw - sO * ci * cw) * y,
            (sO * cw + cO * ci * sw) * x + (-sO * sw + cO * ci * cw) * y,
            si * sw * x + si * cw * y,
        )

    return position


@dataclass(frozen=True)
class HeyokaContext:
    """What a term needs to write its heyoka expressions.

    Attributes
    ----------
    hy : module
        heyoka.
    par : Parameters
        Turns each number into a runtime parameter.
    q, m : tuple of heyoka variables
        The attitude quaternion (scalar last) and ``m / scale``.
    time : heyoka expression
        The physical time ``t = T τ``.
    time_unit, scale : float
        ``T`` and ``scale`` (the rates are multiplied by ``T``; momenta are ``m/scale``).
    """

    hy: Any
    par: Parameters
    q: Sequence[Any]
    m: Sequence[Any]
    time: Any
    time_unit: float
    scale: float
