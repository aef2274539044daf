r"""The inverse problem: an observed obliquity ``ε ± σ`` to the polar moment ``C/MR²``, with its uncertainty.

``α`` and ``β`` are inversely proportional to ``C/MR²`` (:mod:`andoyer.planetary.cassini.body`):
``α = s(J2/X + C22 G_p)/C``, ``β = s C22 G_p/C`` with ``s = 3n'²/2ω``, ``X = (1 − e²)^{3/2}``. The
forced obliquity of each node mode solves the Cassini equation
``F_k = (α cos θ_k + β) sin θ_k + g_k sin(θ_k − i_k) = 0`` and the observed one is
``Θ = |Σ_k θ_k e^{i(φ_k + g_k t)}|`` (:mod:`andoyer.planetary.cassini.forced`). ``C`` solves
``Θ(C) = ε``: with one mode in closed form (Peale's relation),

.. math:: C = -\frac{(a_1\cos\theta + b_1)\sin\theta}{g\sin(\theta - i)}, \qquad
   a_1 = \alpha C,\ b_1 = \beta C,

and in general by bracketing the roots of ``Θ(C) − ε`` on ``(max(2J2, J2 + 2C22), 1]`` (``A > 0``,
``A + B ≥ C``). The derivatives are analytic, by implicit differentiation of each ``F_k``:
``∂θ_k/∂y = −(∂F_k/∂y)/(∂F_k/∂θ)`` with ``∂F/∂θ = α cos 2θ + β cos θ + g cos(θ − i)``,
``∂F/∂C = −(α cos θ + β) sin θ/C``, ``∂F/∂J2 = (s/XC) cos θ sin θ``,
``∂F/∂C22 = (sG_p/C)(1 + cos θ) sin θ``, ``∂F/∂g = sin(θ − i)``, ``∂F/∂i = −g cos(θ − i)``; then
``∂Θ/∂y = Re(Z̄ Σ_k ∂θ_k/∂y e^{i(φ_k+g_k t)})/Θ`` with ``Z = Σ θ_k e^{i(φ_k+g_k t)}``, and

.. math:: \frac{\partial C}{\partial\varepsilon} = \frac{1}{\partial\Theta/\partial C}, \qquad
   \frac{\partial C}{\partial y} = -\frac{\partial\Theta/\partial y}{\partial\Theta/\partial C},
   \qquad \sigma_C^2 = \Big(\frac{\partial C}{\partial\varepsilon}\sigma_\varepsilon\Big)^2
   + \sum_y \Big(\frac{\partial C}{\partial y}\sigma_y\Big)^2 ,

the inputs independent (first-order propagation; the tests check it against finite differences
and a seeded Monte Carlo).

Examples
--------
>>> import math
>>> from andoyer.planetary import cassini
>>> arcmin = math.radians(1 / 60)
>>> (estimate,) = moment_of_inertia_from_obliquity("mercury", 2.04 * arcmin, 0.08 * arcmin)
>>> round(estimate.moment_of_inertia, 3), round(estimate.error, 3)  # Margot et al. 2012: 0.346 ± 0.014
(0.343, 0.013)
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from andoyer import catalogue
from andoyer.planetary.cassini.body import CassiniBody
from andoyer.planetary.cassini.forced import ForcedObliquity, NodeMode
from andoyer.planetary.cassini.top import ColomboTop

__all__ = ["MomentEstimate", "moment_of_inertia_from_obliquity", "obliquity_and_derivatives"]

#: The inputs whose uncertainty can be carried (besides the obliquity): the figure, and the
#: largest node mode's rate (rad/yr) and inclination (rad).
UNCERTAIN = ("j2", "c22", "node_rate", "inclination")


@dataclass(frozen=True)
class MomentEstimate:
    """One solution of ``Θ(C/MR²) = ε``.

    Attributes
    ----------
    moment_of_inertia : float
        ``C/MR²``.
    error : float
        Its one-sigma uncertainty.
    contributions : dict of str to float
        The part of ``error`` from each input (``"obliquity"``, ``"j2"``, ...), ``|∂C/∂y| σ_y``.
    derivatives : dict of str to float
        ``∂C/∂y`` for each input, ``y`` in the API's units (rad, rad/yr).
    """

    moment_of_inertia: float
    error: float
    contributions: dict[str, float]
    derivatives: dict[str, float]


def _system(
    system: ForcedObliquity | CassiniBody | str | catalogue.Body, node: str
) -> tuple[ForcedObliquity, dict]:
    """The forced obliquity and the catalogue's uncertainties (empty for a built object)."""
    from andoyer.planetary.cassini.named import forced_obliquity

    if isinstance(system, ForcedObliquity):
        return system, {}
    if isinstance(system, CassiniBody):
        return ForcedObliquity(system, (NodeMode(system.node_rate, system.inclination, 0.0),)), {}
    if isinstance(system, str | catalogue.Body):
        entry = catalogue.get(system)
        forced = forced_obliquity(entry, node, unknown_moment=True)
        known = {k: getattr(entry, k).uncertainty for k in ("j2", "c22") if getattr(entry, k) is not None}
        if len(forced.modes) == 1 and forced.source == "catalogue":
            period = entry.node_period
            if period is not None and period.uncertainty:
                years = period.to("yr")
                known["node_rate"] = 2 * math.pi * period.uncertainty * units_factor(period, "yr") / years**2
            slope = entry.laplace_inclination
            if slope is not None and slope.uncertainty:
                known["inclination"] = slope.uncertainty * units_factor(slope, "rad")
        return forced, {k: v for k, v in known.items() if v}
    msg = f"expected a ForcedObliquity, a CassiniBody or a body name, got {type(system).__name__}"
    raise ValueError(msg)


def units_factor(quantity: catalogue.Quantity, unit: str) -> float:
    """The factor from the quantity's unit to ``unit`` (for its uncertainty)."""
    return catalogue.units.convert(1.0, quantity.unit, unit)


def obliquity_and_derivatives(forced: ForcedObliquity, t: float = 0.0) -> tuple[float, dict[str, float]]:
    """``Θ`` (rad) at ``t`` and its analytic derivatives by ``C/MR²``, ``J2``, ``C22``, ``g`` and ``i``.

    ``g`` (``"node_rate"``) and ``i`` (``"inclination"``) are the largest mode's.

    Examples
    --------
    >>> from andoyer.planetary.cassini import named
    >>> value, slopes = obliquity_and_derivatives(named.forced_obliquity("titan"))
    >>> sorted(slopes)
    ['c22', 'inclination', 'j2', 'moment_of_inertia', 'node_rate']
    """
    body = forced.body
    c = body.moment_of_inertia
    alpha, beta = body.precession_constant, body.resonance_constant
    scale = body._scale()
    x = (1 - body.eccentricity**2) ** 1.5
    gp = body.eccentricity_factor
    total = 0j
    keys = ("moment_of_inertia", "j2", "c22", "node_rate", "inclination")
    partials: dict[str, complex] = dict.fromkeys(keys, 0j)
    main = forced.dominant()
    for k, mode in enumerate(forced.modes):
        if mode.inclination <= 0:
            continue
        g, i = mode.node_rate, mode.inclination
        theta = ColomboTop(alpha, beta, g, i).least_obliquity_theta()
        u = complex(math.cos(mode.phase + g * t), math.sin(mode.phase + g * t))
        total += theta * u
        f_theta = alpha * math.cos(2 * theta) + beta * math.cos(theta) + g * math.cos(theta - i)
        s, co = math.sin(theta), math.cos(theta)
        f = {
            "moment_of_inertia": -(alpha * co + beta) * s / c,
            "j2": scale / x * co * s,
            "c22": scale * gp * (1 + co) * s,
            "node_rate": math.sin(theta - i),
            "inclination": -g * math.cos(theta - i),
        }
        for key in keys[:3] if k != main else keys:
            partials[key] += -f[key] / f_theta * u
    value = abs(total)
    direction = total.conjugate() / value
    return value, {k: float((direction * v).real) for k, v in partials.items()}


def _obliquity(forced: ForcedObliquity, c: float, t: float, numbered: bool = False) -> tuple[float, int]:
    """``Θ`` at ``C/MR² = c`` and (``numbered``) the number of the largest mode's state (``α, β ∝ 1/C``)."""
    body = forced.body
    a1 = body.precession_constant * body.moment_of_inertia
    b1 = body.resonance_constant * body.moment_of_inertia
    total = 0j
    number = 0
    main = forced.dominant()
    for k, mode in enumerate(forced.modes):
        if mode.inclination > 0:
            top = ColomboTop(a1 / c, b1 / c, mode.node_rate, mode.inclination)
            theta = top.least_obliquity_theta()
            total += theta * complex(
                math.cos(mode.phase + mode.node_rate * t), math.sin(mode.phase + mode.node_rate * t)
            )
            if numbered and k == main:
                number = _state_number(top, theta)
    return abs(total), number


def _state_number(top: ColomboTop, theta: float) -> int:
    """Peale's number of the root ``theta`` of ``top`` (2 if positive; 1 if negative with four roots)."""
    if theta > 0:
        return 2
    return 1 if top.roots().size == 4 else 3


def moment_of_inertia_from_obliquity(
    system: ForcedObliquity | CassiniBody | str | catalogue.Body,
    obliquity: float,
    obliquity_error: float = 0.0,
    *,
    errors: Mapping[str, float] | None = None,
    t: float = 0.0,
    state: int | None = None,
    node: str = "auto",
) -> tuple[MomentEstimate, ...]:
    """``C/MR²`` from an observed obliquity, with its uncertainty (module docstring).

    Parameters
    ----------
    system : ForcedObliquity, CassiniBody, str or andoyer.catalogue.Body
        The body and its node modes (its own ``moment_of_inertia`` is not used). A catalogued
        name or body brings the catalogue's uncertainties of ``J2``, ``C22`` (and, for a single
        catalogue mode, of its node period and inclination).
    obliquity : float
        The observed obliquity ``ε > 0`` (rad), spin axis to orbit normal, at time ``t``.
    obliquity_error : float
        Its one-sigma uncertainty (rad, ``≥ 0``).
    errors : mapping of str to float, optional
        One-sigma uncertainties replacing or adding to the catalogue's: keys ``"j2"``, ``"c22"``,
        ``"node_rate"`` (rad/yr) and ``"inclination"`` (rad) of the largest node mode.
    t : float
        Julian years from the epoch of the modes' phases (several modes only).
    state : int, optional
        Peale's number of the Cassini state the largest mode holds the body in (1 or 2); by
        default the one it holds at the system's own ``C/MR²`` (state 2 for the Moon, 1 for
        Mercury and the satellites). Solutions in another state are left out.
    node : {"auto", "model", "catalogue"}
        For a catalogued name or body: where its node modes come from
        (:func:`~andoyer.planetary.cassini.forced_obliquity`). It may lack ``C/MR²``.

    Returns
    -------
    tuple of MomentEstimate
        Every solution in ``(max(2J2, J2 + 2C22), 1]`` in that state, increasing (usually
        one; several where a mode's response is resonant). None: no rigid body in that state
        has this obliquity.

    Examples
    --------
    >>> (titan,) = moment_of_inertia_from_obliquity("titan", math.radians(0.32), math.radians(0.02))
    >>> round(titan.moment_of_inertia, 2)  # a rigid Titan; Bills & Nimmo found 0.55 for 0.3°
    0.66
    """
    forced, sigmas = _system(system, node)
    theta = float(obliquity)
    sigma = float(obliquity_error)
    if not (math.isfinite(theta) and 0 < theta < math.pi / 2):
        msg = f"expected an observed obliquity in (0, pi/2) rad, got {obliquity!r}"
        raise ValueError(msg)
    if not (math.isfinite(sigma) and 0 <= sigma < math.pi / 2):
        msg = f"expected an obliquity error in [0, pi/2) rad, got {obliquity_error!r}"
        raise ValueError(msg)
    if not (isinstance(t, int | float) and math.isfinite(t)):
        msg = f"expected a finite time t (years), got {t!r}"
        raise ValueError(msg)
    for key, value in dict(errors or {}).items():
        if key not in UNCERTAIN:
            msg = f"expected error keys among {UNCERTAIN}, got {key!r}"
            raise ValueError(msg)
        if not (isinstance(value, int | float) and math.isfinite(value) and value >= 0):
            msg = f"expected a finite error >= 0 for {key}, got {value!r}"
            raise ValueError(msg)
        sigmas[key] = float(value)
    if state not in (None, 1, 2):
        msg = f"expected state 1 or 2 (or None), got {state!r}"
        raise ValueError(msg)
    body = forced.body
    low = max(2 * body.j2, body.j2 + 2 * body.c22) * (1 + 1e-9)
    grid = np.geomspace(low, 1.0, 241)

    def residual(c: float) -> float:
        return _obliquity(forced, c, t)[0] - theta

    values = np.array([residual(c) for c in grid])
    changes = np.flatnonzero(np.sign(values[:-1]) != np.sign(values[1:]))
    roots = [brentq(residual, grid[j], grid[j + 1], xtol=1e-14, rtol=1e-13) for j in changes]
    wanted = _obliquity(forced, body.moment_of_inertia, t, True)[1] if state is None else state
    out = []
    for c in roots:
        if _obliquity(forced, c, t, True)[1] != wanted:
            continue
        at = ForcedObliquity(body.replace(moment_of_inertia=c), forced.modes, forced.source)
        _, slopes = obliquity_and_derivatives(at, t)
        d_c = slopes.pop("moment_of_inertia")
        derivatives = {"obliquity": 1 / d_c} | {k: -v / d_c for k, v in slopes.items()}
        parts = {"obliquity": abs(derivatives["obliquity"]) * sigma}
        parts |= {k: abs(derivatives[k]) * v for k, v in sigmas.items() if k in derivatives and v}
        error = math.sqrt(sum(p * p for p in parts.values()))
        out.append(MomentEstimate(float(c), error, parts, derivatives))
    return tuple(out)
