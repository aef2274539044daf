r"""Spin axes on perturbed secular orbits: the members of a chaotic-obliquity ensemble.

A member is one solar system of the long secular model
(:mod:`andoyer.planetary.orbits.secular`) started from the J2000 state ``w₀`` displaced by a
seeded perturbation, and one spin axis carried along by its planet's orbit. Over 10⁸–10⁹ years
both are chaotic (the inner planets' Lyapunov time is about 5 Myr, the obliquity of Mars
wanders through secular spin–orbit resonances: Laskar & Robutel 1993, Touma & Wisdom 1993),
so a single history is one possible past, and an ensemble of members gives the statistics.

**Perturbation.** In the dimensionless ``u = x/√Λ``, ``v = y/√Λ`` (≈ ``e e^{iϖ}``,
``i e^{iΩ}``, the variables of :mod:`andoyer.planetary.orbits.lyapunov`) every component of
every planet gets ``size · (a + i b)/√2`` with ``a, b`` standard normal:
``w₀ → w₀ + √Λ · size · (a + i b)/√2``. The default ``size`` (:data:`PERTURBATION`, 10⁻⁶)
is well below what the mean elements are known to (the secular model's own J2000 state is a
fit to the N-body solution's mean elements, good to about 10⁻⁴ in ``e``), so each member is
as plausible as the nominal one, and well above round-off, so that the chaos separates the
members within about ``5 Myr · ln(10⁶) ≈ 70 Myr``.

**Integration.** Each member's planets are integrated by the secular model's own kernel
(:func:`andoyer.planetary.orbits.secular_flow.integrate`, Lawson–DOP853, a step ``h`` of at
most the model's default, a whole number of them per output step), which returns the planet's
Poincaré ``x, y`` and their derivatives at every step; the spin axis is turned, in the same
pass and compiled, by the order-8 composition of exact rotations of
:mod:`andoyer.planetary.spin_axis.stepping` (``ṡ = α (s·n)(s×n)``, ``α = α_⊙ [(1−e²)^{−3/2}
+ β]``), ``k`` substeps of at most ``spin_step`` years per orbit step, the normal and ``e`` at
each stage from the cubic Hermite interpolant of ``x, y`` between the two steps — the
interpolation :class:`~andoyer.planetary.orbits.SecularOrbit` uses, so that an unperturbed
member is :func:`~andoyer.planetary.spin_axis.spin_axis_history` on
``SecularOrbit(body, step=h)`` (the tests compare the two to 1e-12 rad).

A member whose planets leave the model's domain (an eccentricity beyond
:data:`~andoyer.planetary.orbits.secular.E_MAX` or an inclination beyond
:data:`~andoyer.planetary.orbits.secular.I_MAX`: Mercury, in rare histories of several hundred
Myr) is stopped there: its obliquity is ``NaN`` from the next output on, and ``left_domain``
says when.

Examples
--------
>>> from andoyer.planetary.spin_axis import default_axis
>>> run = member_obliquities("mars", -2e5, 1e5, np.zeros((1, 16), complex), default_axis("mars"))
>>> run.t.tolist(), np.round(np.degrees(run.obliquity), 2).tolist()
([0.0, -100000.0, -200000.0], [[25.19, 26.55, 22.13]])
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._jit import jit
from andoyer.catalogue.units import ARCSEC
from andoyer.compositions import COMPOSITIONS, turn_about
from andoyer.planetary.orbits.secular import poincare_normal
from andoyer.planetary.orbits.secular_flow import hermite_basis
from andoyer.planetary.spin_axis.model import EARTH_DYNAMICAL_ELLIPTICITY, SpinAxisModel

__all__ = [
    "MEMBER_BODIES",
    "PERTURBATION",
    "MemberRun",
    "member_cost",
    "member_models",
    "member_obliquities",
    "member_times",
    "perturbed_states",
]

Array = NDArray[np.float64]
CArray = NDArray[np.complex128]

#: Default size of the perturbation of the J2000 secular state (dimensionless, ≈ ``Δe``, ``Δi``).
PERTURBATION = 1e-6
#: The bodies a member may be: Mars, the Earth, and the Earth without the Moon (the lunar torque
#: off, today's spin rate and dynamical ellipticity: Laskar, Joutel & Robutel 1993; Lissauer,
#: Barnes & Chambers 2012).
MEMBER_BODIES = ("mars", "earth", "moonless-earth")
#: Orbit steps integrated at once for one member (the unit of work between two looks at the
#: domain; 4096 steps of about 10 kyr are 40 Myr).
BLOCK_STEPS = 4096
#: Seconds per orbit step of the secular kernel (12 evaluations of the flow), measured (one core of
#: the shared 2-core machine, 2026-11-28, after the kernel's four-lane sums: 54-86 µs per step alone,
#: 77-80 µs over whole 1-Gyr members with the spin axis); a bound with about twice that, used only
#: to refuse or announce a run before it starts.
STEP_SECONDS = 1.5e-4
#: Seconds per spin substep and member (the order-8 composition's 15 rotations and the orbit's
#: interpolation; measured 1.15 µs for one member alone, less for each of several on one orbit); a
#: bound used only to refuse or announce a run.
SUBSTEP_SECONDS = 1.0e-6
#: Bytes per output time and member (the obliquity, and the arrays the ensemble keeps of it).
ROW_BYTES = 32


def perturbed_states(n: int, size: float, rng: np.random.Generator) -> CArray:
    """``n`` J2000 states of the secular model, each displaced by a seeded perturbation of ``size``.

    Parameters
    ----------
    n : int
    size : float
        ``0 ≤ size ≤ 10⁻²`` in the dimensionless ``u = x/√Λ``, ``v = y/√Λ`` (``0``: the nominal
        state for every member).
    rng : numpy.random.Generator

    Returns
    -------
    numpy.ndarray of complex, shape (n, 16)
        The displacements ``Δw`` (added to the model's ``w₀`` by :func:`member_obliquities`).

    Examples
    --------
    >>> d = perturbed_states(3, 1e-6, np.random.default_rng(0))
    >>> d.shape, bool(np.abs(d).max() < 1e-4)
    ((3, 16), True)
    """
    from andoyer.planetary.orbits.secular import secular_model

    if isinstance(n, bool) or not isinstance(n, int | np.integer) or n < 0:
        msg = f"expected a non-negative whole number of members, got {n!r}"
        raise ValueError(msg)
    if not (isinstance(size, int | float | np.floating) and np.isfinite(size) and 0 <= size <= 1e-2):
        msg = f"expected a perturbation size 0 <= size <= 0.01 (dimensionless, like e), got {size!r}"
        raise ValueError(msg)
    model = secular_model()
    scale = np.sqrt(np.concatenate([model.Lambda, model.Lambda]))
    z = rng.standard_normal((int(n), scale.size)) + 1j * rng.standard_normal((int(n), scale.size))
    return scale * float(size) * z / np.sqrt(2.0)


def _body(body: str) -> str:
    key = str(body).strip().lower()
    if key not in MEMBER_BODIES:
        msg = f"expected a body in {', '.join(MEMBER_BODIES)}, got {body!r}"
        raise ValueError(msg)
    return key


def member_models(
    body: str,
    normal0: Array,
    e0: Array,
    axis: Array,
    precession_rate: ArrayLike | None = None,
    dynamical_ellipticity: ArrayLike | None = None,
) -> list[SpinAxisModel]:
    """One spin-axis model per member, matched to its own orbit at J2000.

    Parameters
    ----------
    body : {"mars", "earth", "moonless-earth"}
    normal0 : numpy.ndarray, shape (M, 3)
        Each member's orbit normal at J2000.
    e0 : numpy.ndarray, shape (M,)
        Each member's eccentricity at J2000.
    axis : numpy.ndarray, shape (3,) or (M, 3)
        The spin axis at J2000 (unit, J2000 ecliptic), shared or one per member.
    precession_rate, dynamical_ellipticity : array_like, shape (M,) or scalar, optional
        At most one; ``ψ̇`` at J2000 (″/yr) or ``H``. Default: the body's precession rate
        (Mars, the Earth), today's ``H`` with no Moon (``"moonless-earth"``).

    Returns
    -------
    list of SpinAxisModel
    """
    from andoyer.planetary.spin_axis.model import DEFAULT_PRECESSION_RATE

    key = _body(body)
    if precession_rate is not None and dynamical_ellipticity is not None:
        msg = "expected a precession rate or a dynamical ellipticity, got both"
        raise ValueError(msg)
    runs = len(e0)
    axes = np.broadcast_to(axis, (runs, 3))
    planet = "earth" if key == "moonless-earth" else key
    if key == "moonless-earth" and precession_rate is None and dynamical_ellipticity is None:
        dynamical_ellipticity = EARTH_DYNAMICAL_ELLIPTICITY
    models = []
    for i in range(runs):
        if dynamical_ellipticity is not None:
            h = float(np.broadcast_to(dynamical_ellipticity, (runs,))[i])
            model = replace(SpinAxisModel.from_dynamical_ellipticity(planet, h), eccentricity=float(e0[i]))
            if key == "moonless-earth":
                model = replace(model, beta=0.0)
        else:
            rate = DEFAULT_PRECESSION_RATE[planet] if precession_rate is None else precession_rate
            rate = float(np.broadcast_to(rate, (runs,))[i])
            eps0 = float(np.arctan2(np.linalg.norm(np.cross(axes[i], normal0[i])), axes[i] @ normal0[i]))
            if key == "moonless-earth":
                # ψ̇ = α_⊙ cos ε₀ (1−e²)^{−3/2} with the Sun alone.
                model = SpinAxisModel.from_precession_rate(planet, rate, eps0, float(e0[i]))
                alpha = rate * ARCSEC / (np.cos(eps0) * (1.0 - e0[i] ** 2) ** -1.5)
                model = replace(model, alpha_sun=float(alpha), beta=0.0)
            else:
                model = SpinAxisModel.from_precession_rate(planet, rate, eps0, float(e0[i]))
        models.append(model)
    return models


@dataclass(frozen=True)
class MemberRun:
    """The obliquities of ``M`` members at ``N`` output times.

    Attributes
    ----------
    t : numpy.ndarray, shape (N,)
        Julian years from J2000, ``0, Δt, 2Δt, …`` (signed).
    obliquity : numpy.ndarray, shape (M, N)
        Radians; ``NaN`` after a member left the secular model's domain.
    left_domain : numpy.ndarray, shape (M,)
        The time (years) at which each member left the domain, ``NaN`` if it never did.
    orbit_step, spin_step : float
        The steps taken (years, positive).
    """

    t: Array
    obliquity: Array
    left_domain: Array
    orbit_step: float
    spin_step: float


def _steps(end: float, interval: float, spin_step: float) -> tuple[Array, float, int, int, int]:
    """Output times, the orbit step, orbit steps per output, samples per step, spin substeps per sample.

    The orbit takes :class:`~andoyer.planetary.orbits.SecularOrbit`'s steps (at most
    :data:`~andoyer.planetary.orbits.secular.LONG_STEP_FRACTION` of the shortest linear period, a
    whole number per output step) and keeps its samples (at most
    :data:`~andoyer.planetary.orbits.secular.STEP_FRACTION` of that period apart).
    """
    from andoyer.planetary.orbits.secular import LONG_STEP_FRACTION, MAX_SPAN, STEP_FRACTION, secular_model
    from andoyer.planetary.orbits.secular_flow import default_step

    if not (np.isfinite(end) and end != 0 and abs(end) <= MAX_SPAN):
        msg = f"expected a nonzero end time within +-{MAX_SPAN:g} years of J2000, got {end!r}"
        raise ValueError(msg)
    if not (np.isfinite(interval) and 0 < interval <= abs(end)):
        msg = f"expected an output step 0 < DT <= |end| = {abs(end):g} years, got {interval!r}"
        raise ValueError(msg)
    if not (np.isfinite(spin_step) and spin_step > 0):
        msg = f"expected a positive finite spin-axis step in years, got {spin_step!r}"
        raise ValueError(msg)
    count = int(np.floor(abs(end) / interval + 1e-9))
    if count > 10**7:
        msg = f"expected at most 10 million output times, got {count}"
        raise ValueError(msg)
    sign = 1.0 if end > 0 else -1.0
    t = sign * interval * np.arange(count + 1)
    t[0] = 0.0  # not -0.0
    linear = secular_model().terms.linear
    per = max(1, int(np.ceil(interval / default_step(linear, LONG_STEP_FRACTION) - 1e-9)))
    h = interval / per
    samples = max(1, int(np.ceil(h / default_step(linear, STEP_FRACTION) - 1e-9)))
    substeps = max(1, int(np.ceil(h / samples / spin_step - 1e-9)))
    return t, h, per, samples, substeps


def member_times(end: float, interval: float) -> Array:
    """The output times of :func:`member_obliquities`: ``0, ±Δt, ±2Δt, …`` up to ``end``.

    Parameters
    ----------
    end, interval : float
        Years; ``0 < |end| ≤ 10⁹``, ``0 < interval ≤ |end|``.

    Returns
    -------
    numpy.ndarray, shape (N,)

    Examples
    --------
    >>> member_times(-2.5e5, 1e5).tolist()
    [0.0, -100000.0, -200000.0]
    """
    return _steps(float(end), float(interval), 1000.0)[0]


def member_cost(
    members: int, end: float, interval: float, spin_step: float = 1000.0, orbits: int | None = None
) -> tuple[float, float]:
    """Seconds and bytes of :func:`member_obliquities`, before the work.

    Parameters
    ----------
    members : int
    end, interval, spin_step : float
        As :func:`member_obliquities`.
    orbits : int, optional
        How many of the members have orbits of their own (default: all); the others share them.

    Returns
    -------
    seconds, nbytes : float

    Examples
    --------
    >>> seconds, nbytes = member_cost(1000, -1e8, 1e5)
    >>> round(seconds), nbytes  # 10^3 members of 100 Myr, each its own orbit (10^4 steps each)
    (1600, 32032000.0)
    >>> round(member_cost(1000, -1e8, 1e5, orbits=100)[0])  # ten spin axes per orbit
    250
    """
    t, _, per, samples, substeps = _steps(end, interval, spin_step)
    steps = (t.size - 1) * per
    orbits = members if orbits is None else orbits
    seconds = (
        float(orbits) * steps * STEP_SECONDS + float(members) * steps * samples * substeps * SUBSTEP_SECONDS
    )
    return seconds, float(members) * t.size * ROW_BYTES


@jit
def _spin_block(w, dw, spacing, rows, lam, rotation, s, alpha_sun, beta, gamma, substeps, per, first, out):
    """Turn the axes ``s`` of ``M`` members over ``rows`` sample intervals of one orbit.

    ``w, dw`` (rows + 1, 2): the planet's ``x, y`` and their derivatives at the samples, ``spacing``
    (signed) apart; ``s`` (M, 3) turned in place, each member at its own ``α_⊙, β`` (M,); the
    orbit's normal and ``√(1−e²)`` at each stage are computed once for all members.
    ``out[:, first + j]`` is the obliquity after ``(j+1)·per`` intervals. Returns the number of
    obliquities stored per member.
    """
    S = gamma.size
    M = s.shape[0]
    stored = 0
    for i in range(rows):
        xa, ya, dxa, dya = w[i, 0], w[i, 1], dw[i, 0] * spacing, dw[i, 1] * spacing
        xb, yb, dxb, dyb = w[i + 1, 0], w[i + 1, 1], dw[i + 1, 0] * spacing, dw[i + 1, 1] * spacing
        for q in range(substeps):
            before = 0.0
            for g in range(S):
                tau = (q + before + 0.5 * gamma[g]) / substeps
                before += gamma[g]
                h00, h10, h01, h11 = hermite_basis(tau)
                x = h00 * xa + h10 * dxa + h01 * xb + h11 * dxb
                y = h00 * ya + h10 * dya + h01 * yb + h11 * dyb
                nx, ny, nz, root = poincare_normal(x, y, lam, rotation)
                factor = 1.0 / (root * root * root)
                duration = -gamma[g] * spacing / substeps
                for m in range(M):
                    alpha = alpha_sun[m] * (factor + beta[m])
                    s[m, 0], s[m, 1], s[m, 2] = turn_about(
                        s[m, 0], s[m, 1], s[m, 2], nx, ny, nz, alpha * duration
                    )
            for m in range(M):
                scale = 1.0 / np.sqrt(s[m, 0] * s[m, 0] + s[m, 1] * s[m, 1] + s[m, 2] * s[m, 2])
                s[m, 0], s[m, 1], s[m, 2] = s[m, 0] * scale, s[m, 1] * scale, s[m, 2] * scale
        if (i + 1) % per == 0:
            nx, ny, nz, _ = poincare_normal(xb, yb, lam, rotation)
            for m in range(M):
                sx, sy, sz = s[m, 0], s[m, 1], s[m, 2]
                cx, cy, cz = sy * nz - sz * ny, sz * nx - sx * nz, sx * ny - sy * nx
                cross = np.sqrt(cx * cx + cy * cy + cz * cz)
                out[m, first + stored] = np.arctan2(cross, sx * nx + sy * ny + sz * nz)
            stored += 1
    return stored


def member_obliquities(
    body: str,
    end: float,
    interval: float,
    perturbation: ArrayLike,
    axis: ArrayLike,
    *,
    precession_rate: ArrayLike | None = None,
    dynamical_ellipticity: ArrayLike | None = None,
    spin_step: float = 1000.0,
    on_block: object = None,
) -> MemberRun:
    """The obliquity of ``M`` members from J2000 to ``end``, every ``interval`` years.

    Members whose perturbations are equal share one orbit: it is integrated once, and their spin
    axes (which then differ by their spin parameters or their J2000 axes) are turned together in
    the same compiled pass.

    Parameters
    ----------
    body : {"mars", "earth", "moonless-earth"}
        The planet (the Earth–Moon barycentre's orbit for the Earth); ``"moonless-earth"``: the
        Earth with the lunar torque off (``β = 0``), today's spin and ``H``.
    end : float
        Julian years from J2000 (negative: the past), ``0 < |end| ≤ 10⁹``.
    interval : float
        Output step, years, ``0 < interval ≤ |end|``.
    perturbation : array_like of complex, shape (M, 16)
        Each member's displacement of the J2000 secular state (:func:`perturbed_states`).
    axis : array_like, shape (3,) or (M, 3)
        Spin axis at J2000, J2000 ecliptic (e.g. :func:`~andoyer.planetary.spin_axis.default_axis`
        of the planet), shared or one per member.
    precession_rate, dynamical_ellipticity : array_like, shape (M,) or scalar, optional
        See :func:`member_models`.
    spin_step : float
        Largest spin-axis step, years (default 1000, the library's).
    on_block : callable, optional
        Called with the years done (of one orbit) after each block (progress).

    Returns
    -------
    MemberRun

    Raises
    ------
    ValueError
        For a body, time, step or parameter out of range.
    """
    from andoyer.planetary.orbits.planets import PLANETS
    from andoyer.planetary.orbits.secular import (
        E_MAX,
        I_MAX,
        secular_model,
        secular_tableau,
        vectors_from_poincare,
    )
    from andoyer.planetary.orbits.secular_flow import integrate

    key = _body(body)
    planet = "earth" if key == "moonless-earth" else key
    t, h, per, samples, substeps = _steps(float(end), float(interval), float(spin_step))
    delta = np.asarray(perturbation)
    if delta.ndim != 2 or delta.shape[1] != 16 or not np.all(np.isfinite(delta)):
        msg = f"expected finite perturbations of shape (M, 16), got shape {delta.shape}"
        raise ValueError(msg)
    runs = delta.shape[0]
    s0 = np.asarray(axis, dtype=float)
    if s0.shape not in ((3,), (runs, 3)) or not np.all(np.isfinite(s0)):
        msg = f"expected a finite axis of shape (3,) or ({runs}, 3), got shape {s0.shape}"
        raise ValueError(msg)
    s0 = np.array(np.broadcast_to(s0, (runs, 3)))
    size = np.linalg.norm(s0, axis=-1, keepdims=True)
    if not np.all(size > 0):
        msg = f"expected a non-zero axis for every member, got {s0[np.ravel(size == 0)].tolist()}"
        raise ValueError(msg)
    s0 /= size
    model = secular_model()
    terms = model.terms
    P = terms.count
    j = PLANETS.index(planet)
    lam = float(model.Lambda[j])
    orbits, member_orbit = np.unique(delta.astype(complex), axis=0, return_inverse=True)
    member_orbit = member_orbit.ravel()
    w0 = model.w0[None, :] + orbits
    # one orbit at a time: a matrix product's last bits would depend on how many orbits it holds
    vectors = [vectors_from_poincare(w[j], w[P + j], lam, model.rotation) for w in w0]
    normal0, ecc0 = np.array([v[0] for v in vectors]), np.array([v[1] for v in vectors])
    models = member_models(
        key, normal0[member_orbit], np.linalg.norm(ecc0, axis=-1)[member_orbit], s0,
        precession_rate, dynamical_ellipticity,
    )  # fmt: skip
    sign = 1.0 if end > 0 else -1.0
    tableau = secular_tableau(sign * h, samples)
    gamma = np.ascontiguousarray(COMPOSITIONS[8])
    keep = np.array([j, P + j], dtype=np.int64)
    total = (t.size - 1) * per
    block = max(per, (BLOCK_STEPS // per) * per)
    out = np.full((runs, t.size), np.nan)
    left = np.full(runs, np.nan)
    arrays = terms.arrays()
    alpha_sun = np.array([m.alpha_sun for m in models])
    beta = np.array([m.beta for m in models])
    for k in range(len(orbits)):
        members = np.flatnonzero(member_orbit == k)
        state = np.ascontiguousarray(w0[k])
        s = np.ascontiguousarray(s0[members])
        rows = np.full((members.size, t.size), np.nan)
        rows[:, 0] = np.arctan2(
            np.linalg.norm(np.cross(s, normal0[k]), axis=-1), np.sum(s * normal0[k], axis=-1)
        )
        done = 0
        while done < total:
            n = min(block, total - done)
            w = np.empty((n * samples + 1, 2), dtype=complex)
            dw = np.empty_like(w)
            extreme = np.zeros(2 * P)
            integrate(state, n, sign * h, *tableau, *arrays, terms.linear, keep, w, dw, extreme)
            root = 1.0 - extreme[:P] / (2.0 * model.Lambda)
            e = np.sqrt(np.clip(1.0 - root * root, 0.0, 1.0))
            cos_i = 1.0 - extreme[P:] / (2.0 * model.Lambda * np.clip(root, 1e-3, None))
            if np.any(e > E_MAX) or np.any(np.arccos(np.clip(cos_i, -1.0, 1.0)) > I_MAX):
                left[members] = t[done // per]
                break
            _spin_block(
                w, dw, sign * h / samples, n * samples, lam, model.rotation, s, alpha_sun[members],
                beta[members], gamma, substeps, per * samples, done // per + 1, rows,
            )  # fmt: skip
            done += n
            if on_block is not None:
                on_block(n * h)
        out[members] = rows
    return MemberRun(t, out, left, float(h), float(h / samples / substeps))
