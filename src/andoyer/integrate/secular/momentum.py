r"""The mean angular momentum under the averaged gravity gradient of a fast rotator.

The model itself, ``⟨ΔH⟩`` and ``dM/dt``, lives with the other models:
:class:`andoyer.perturbations.averaged_gravity.SecularGravityGradient`. Here is its
propagation, :func:`propagate_momentum`: exact rotations about the orbit normals
composed to high order (:mod:`andoyer.integrate.secular.rotations`) or scipy's DOP853.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.integrate import solve_ivp

from andoyer._validation import as_finite, as_vectors
from andoyer.compositions import COMPOSITIONS
from andoyer.integrate.secular.rotations import propagate_controlled
from andoyer.perturbations.averaged_gravity import SecularGravityGradient as SecularModel

__all__ = ["propagate_checked", "propagate_momentum"]

Array = NDArray[np.float64]


def propagate_momentum(
    model: SecularModel,
    M0: ArrayLike,
    L: ArrayLike,
    t: ArrayLike,
    rtol: float = 1e-12,
    method: str = "rotations",
    order: int = 8,
    max_step: float | None = None,
    t0: float = 0.0,
) -> Array:
    """Integrate ``dM/dt`` from ``t0`` to the times ``t`` (1-D, increasing), shape (len(t), ..., 3).

    Parameters
    ----------
    model : SecularGravityGradient
        The averaged model (:meth:`andoyer.perturbations.GravityGradient.secular_average`).
    M0 : array_like, shape (..., 3)
        Reference-frame angular momenta at ``t0``.
    L : array_like, shape (...)
        ``L = M·b3`` (constant in the averaged model).
    t : array_like, shape (K,)
        Output times, ``≥ t0`` and increasing (absolute: the orbit normals are functions of ``t``).
    rtol : float
        Relative tolerance: DOP853's (per step), or for ``"rotations"`` the target
        relative global error of ``M``, met by Richardson's estimate
        (:func:`~andoyer.integrate.secular.rotations.propagate_controlled`).
    method : {"rotations", "dop853"}
        ``"rotations"`` (default): palindromic composition of the exact rotations
        about each ``k_p`` (:mod:`andoyer.integrate.secular.rotations`), fixed steps of
        up to two radians of the fastest rate (years for the planets), ``|M|``
        conserved to round-off. ``"dop853"``: scipy's adaptive DOP853.
    order : {2, 4, 6, 8}
        Order of the composition (``"rotations"`` only).
    max_step : float, optional
        Upper bound on the step (``"rotations"`` only; same units as ``t``).

    t0 : float
        The time of ``M0`` (default 0).

    Returns
    -------
    numpy.ndarray, shape (K, ..., 3)

    Examples
    --------
    >>> from andoyer import bodies
    >>> from andoyer.catalogue.units import ARCSEC
    >>> from andoyer.perturbations.averaged_gravity import SecularGravityGradient
    >>> from andoyer.perturbations.solar_system import JULIAN_YEAR, OBLIQUITY, mean_perturbers
    >>> earth = bodies.get("earth")
    >>> model = SecularGravityGradient(earth, mean_perturbers("earth"))
    >>> G = earth.C * 2 * np.pi / 86164.0905
    >>> M0 = G * np.array([0.0, -np.sin(OBLIQUITY["earth"]), np.cos(OBLIQUITY["earth"])])
    >>> M = propagate_momentum(model, M0, G, [100 * JULIAN_YEAR])
    >>> round(float(np.arctan2(M[0, 0], -M[0, 1]) / ARCSEC / 100), 2)  # arcsec per year
    -50.35
    """
    M0 = as_vectors(M0, "M0")
    L = np.broadcast_to(as_finite(L, "L"), M0.shape[:-1])
    times = as_finite(t, "t")
    t0 = float(as_finite(t0, "t0"))
    if times.ndim != 1 or np.any(np.diff(times) < 0) or times[0] < t0:
        msg = "expected increasing output times (1-D), none before t0, got another array"
        raise ValueError(msg)
    if method == "dop853":
        return _propagate_dop853(model, M0, L, times, rtol, t0)
    if method != "rotations":
        msg = f"expected method 'rotations' or 'dop853', got {method!r}"
        raise ValueError(msg)
    return propagate_checked(model, M0, L, times, rtol, order, max_step, t0)


def propagate_checked(
    model: SecularModel,
    M0: Array,
    L: Array,
    times: Array,
    rtol: float = 1e-12,
    order: int = 8,
    max_step: float | None = None,
    t0: float = 0.0,
) -> Array:
    """:func:`propagate_momentum` by rotations, for arrays validated by the caller.

    The checks of :func:`propagate_momentum` on ``M0``, ``L`` and ``times`` are left to the
    caller (:func:`andoyer.integrate.secular.integrate_secular` has made them on its state
    and times already: each costs microseconds, against a kernel of a few hundred for 1000
    years); ``order``, ``rtol`` and ``max_step`` are still checked here.

    Parameters
    ----------
    model : SecularGravityGradient
        The averaged model.
    M0 : numpy.ndarray, shape (..., 3)
        Finite reference-frame angular momenta at ``t0``.
    L : numpy.ndarray, shape (...)
        Finite ``L = M·b3``, the shape of ``M0``'s states.
    times : numpy.ndarray, shape (K,)
        Finite output times, increasing, none before ``t0``.
    rtol, order, max_step, t0
        As in :func:`propagate_momentum`.

    Returns
    -------
    numpy.ndarray, shape (K, ..., 3)

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> from andoyer.perturbations import CircularOrbit, PointMass
    >>> model = SecularModel(RigidBody(1.0, 1.0, 1.2), PointMass(1.0, CircularOrbit(1.0, 1.0)))
    >>> M0 = np.array([0.0, 0.6, 0.8])
    >>> bool(np.array_equal(propagate_checked(model, M0, np.array(0.8), np.array([2.0])),
    ...                     propagate_momentum(model, M0, 0.8, [2.0])))
    True
    """
    if order not in COMPOSITIONS:
        msg = f"expected order in {sorted(COMPOSITIONS)}, got {order!r}"
        raise ValueError(msg)
    if not rtol > 0 or (max_step is not None and not max_step > 0):
        msg = f"expected positive rtol and max_step, got {rtol!r} and {max_step!r}"
        raise ValueError(msg)
    shape = M0.shape
    M = M0.reshape(-1, 3)
    G = np.sqrt(np.sum(M * M, axis=-1))  # |M| (np.linalg.norm's arithmetic, without its dispatch)
    L = L.reshape(-1)
    coef = np.array([2 * model.strength(p, L, G) / G**2 for p in model.perturbers])
    outer, inner = model.split_normals()
    k0 = model.normal(model.perturbers[outer[0]], 0.0) if outer else np.array([0.0, 0.0, 1.0])
    c0 = coef[outer].sum(axis=0) if outer else np.zeros(len(M))
    orbits = [model.perturbers[i].orbit for i in inner]
    normals = (
        np.array([np.sin(o.inclination) for o in orbits]),
        np.array([np.cos(o.inclination) for o in orbits]),
        np.array([o.node + o.node_rate * (t0 - o.epoch) for o in orbits]),  # the nodes at t0
        np.array([o.node_rate for o in orbits]),
    )
    fastest = max(float((np.abs(coef) * G).max(initial=0.0)), float(np.abs(normals[3]).max(initial=0.0)))
    drifting = coef[inner].reshape(len(inner), len(M))
    bound = np.inf if max_step is None else float(max_step)
    out, _ = propagate_controlled(M, c0, k0, drifting, normals, times - t0, fastest, rtol, order, bound, g=G)
    return out.reshape((len(times), *shape))


def _propagate_dop853(
    model: SecularModel, M0: Array, L: Array, times: Array, rtol: float, t0: float = 0.0
) -> Array:
    """DOP853 steps over years: the model has no fast angle left."""
    shape = M0.shape

    def rhs(time: float, y: Array) -> Array:
        return model.momentum_rate(time, y.reshape(shape), L).ravel()

    scale = float(np.max(np.linalg.norm(M0, axis=-1)))
    sol = solve_ivp(
        rhs,
        (t0, float(times[-1])),
        M0.ravel(),
        method="DOP853",
        t_eval=times,
        rtol=rtol,
        atol=1e-15 * scale,
    )
    return sol.y.T.reshape((len(times), *shape))

