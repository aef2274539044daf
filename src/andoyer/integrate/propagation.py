r"""One entry point for perturbed propagation: ``andoyer.propagate(model, state, t, method=...)``.

Three integrators, one call:

* ``"reference"`` (options ``t0``, ``rtol``, ``atol``, ``integrator``): the
  full equations ``q̇ = ½ q ⊗ (∂K/∂m, 0)``, ``ṁ = m × ∂K/∂m + τ`` with adaptive
  DOP853 (:func:`~andoyer.integrate.reference.integrate_reference`); every model,
  dissipative torques included. ``integrator="heyoka"`` uses heyoka's Taylor
  integrator instead (optional dependency) for gravity gradients on Kepler
  orbits, constant-rate precessing frames, heavy tops and linear damping.
* ``"splitting"`` (options ``step`` or ``rtol``, ``order``, ``t0``): the
  symplectic splitting ``K = T + V + F`` of exact free flow, momentum kicks
  and frame rotations (:func:`~andoyer.integrate.splitting.integrate_splitting`);
  Hamiltonian attitude-only models and precessing frames. Without a step, the order
  and step come from ``rtol`` (default ``1e-3``) through a documented error model
  (:mod:`andoyer.integrate.splitting.probe`).
* ``"secular"`` (options ``t0``, ``rtol``): the averaged model of a fast
  rotator, the mean angular momentum ``M̄`` (Andoyer ``h``, ``H``) under
  ``⟨ΔH⟩`` (:func:`~andoyer.integrate.secular.integrate_secular`); gravity
  gradients on Kepler orbits and precessing frames. First-order averaging:
  its relative error is of the order of the precession rate over the
  slowest orbital frequency averaged over.

For ``"secular"`` the input and output states are *mean* states: the fast
angles ``l``, ``g`` follow the torque-free motion and ``h``, ``H`` follow
``⟨ΔH⟩`` (see :mod:`andoyer.integrate.secular`); they differ from the states
of the other two methods by the short-period nutations, whose amplitude is
the precession rate divided by the perturbers' orbital frequencies.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from andoyer.integrate.reference import integrate_reference
from andoyer.integrate.secular import integrate_secular
from andoyer.integrate.splitting import integrate_splitting
from andoyer.perturbations.model import Model
from andoyer.state import State

__all__ = ["METHODS", "propagate"]

#: The options each method accepts.
METHODS: dict[str, tuple[str, ...]] = {
    "reference": ("t0", "rtol", "atol", "integrator"),
    "splitting": ("step", "order", "t0", "rtol"),
    "secular": ("t0", "rtol"),
}


def propagate(model: Model, state: State, t: ArrayLike, method: str = "reference", **options: Any) -> State:
    r"""Propagate ``state`` under ``model`` to the times ``t`` with the chosen integrator.

    Parameters
    ----------
    model : Model
        The body and its perturbations.
    state : State, shape (S...)
        The state(s) at time ``t0`` (a mean state for ``method="secular"``).
    t : array_like, shape (T...)
        Output times (absolute; forwards and backwards from ``t0``), broadcast
        with the state's shape.
    method : {"reference", "splitting", "secular"}
        See :mod:`andoyer.integrate.propagation`.
    **options
        ``t0`` (float, default 0) for every method; ``rtol``, ``atol`` for
        ``"reference"`` (DOP853, defaults 1e-12, 1e-14) and ``integrator``
        (``"dop853"``, default, or ``"heyoka"``: ``rtol`` is then heyoka's
        tolerance, default machine epsilon, and ``atol`` is not taken); ``step`` (> 0),
        ``order`` (2, 4 or 6) and ``rtol`` for ``"splitting"`` (a step, order 4 by default;
        or an ``rtol``, default 1e-3, from which the order and step are chosen: the result
        is then a :class:`~andoyer.integrate.splitting.SplittingState` with its
        ``error_estimate``, a bound of the relative error of ``M``);
        ``rtol`` (default 1e-12) for ``"secular"``.

    Returns
    -------
    State, shape broadcast(S..., T...)

    Raises
    ------
    ValueError
        For an unknown method, an option the method does not take, or a model the
        method cannot integrate (non-Hamiltonian or momentum-dependent terms other than precessing frames for
        ``"splitting"``; anything but gravity gradients on Kepler orbits and
        precessing frames for ``"secular"``); for no output time; for times
        whose spin phase ``|ω (t − t0)|`` (``ω = |m|/min(I)``) reaches ``2⁵²`` rad
        (no digit of it left); and for a run that cannot fit in memory or time
        (:func:`andoyer._limits.check_size`), before it starts.

    Warns
    -----
    PhasePrecisionWarning
        For times whose spin phase keeps fewer than six digits (``|ω (t − t0)| > 4.5·10⁹`` rad).

    Examples
    --------
    A heavy top (``ΔH = m g0 r_c·γ``): the splitting and DOP853 agree.

    >>> import numpy as np
    >>> from andoyer import RigidBody, State
    >>> from andoyer.perturbations import HeavyTop
    >>> model = Model(RigidBody(1.0, 1.2, 1.5), HeavyTop(0.5, [0.0, 0.1, 0.3]))
    >>> start = State.from_andoyer(0.1, 0.2, 0.3, 1.8, 2.0, 1.5)
    >>> ref = propagate(model, start, [0.0, 1.0, 2.0])
    >>> split = propagate(model, start, [0.0, 1.0, 2.0], method="splitting", step=0.1)
    >>> ref.shape, bool(np.abs(split.m_body - ref.m_body).max() < 1e-5)
    ((3,), True)
    >>> chosen = propagate(model, start, [0.0, 1.0, 2.0], method="splitting", rtol=1e-6)
    >>> bool(np.abs(chosen.m_body - ref.m_body).max() < 1e-6 * np.linalg.norm(start.m_body))
    True
    """
    if method not in METHODS:
        msg = f"expected method 'reference', 'splitting' or 'secular', got {method!r}"
        raise ValueError(msg)
    allowed = METHODS[method]
    extra = sorted(set(options) - set(allowed))
    if extra:
        msg = f"expected options of method={method!r} among {', '.join(allowed)}, got {', '.join(extra)}"
        raise ValueError(msg)
    if not isinstance(model, Model):
        msg = f"expected an andoyer Model, got {type(model).__name__}"
        raise ValueError(msg)
    if not isinstance(state, State):
        msg = f"expected an andoyer State, got {type(state).__name__}"
        raise ValueError(msg)
    if method == "reference":
        integrator = options.pop("integrator", "dop853")
        return integrate_reference(model, state, t, **options, method=integrator)
    if method == "splitting":
        times = np.append(np.asarray(t, dtype=float).ravel(), float(options.get("t0", 0.0)))
        span = float(np.max(times) - np.min(times)) if np.all(np.isfinite(times)) else 0.0
        step = options.get("step")
        if span > 0 and isinstance(step, int | float) and abs(step) > span:
            # The steps would be cut at the output times: the run would not be the one asked for.
            msg = f"expected a step no longer than the span of the times ({span:.6g}), got step={step!r}"
            raise ValueError(msg)
        return integrate_splitting(model, state, t, **options)
    return integrate_secular(model, state, t, **options)  # it checks the model's terms first
