r"""Inversion of Sadov's action: the orbit of a given ``u = |I_ℓ|/G`` (``λ = φ(I_ℓ/I_g)``, §5).

``u`` is monotonic in each region (Sadov 1970): in circulation it rises from the
separatrix value ``u_s = (2/π) arcsin √ρ`` at ``y_c = 0`` to 1 at ``y_c = 1`` (the pole);
in libration from 0 at ``w = 0`` (the centre ``±b_e``) to ``u_s`` at ``w = 1``. Near the
separatrix ``u − u_s ∼ y_c log(1/y_c)``, whose derivative is infinite, while the other
end is smooth; so each region is split at its midpoint ``v = 1/2`` and the unknown is the
member of the pair ``(v, 1 − v)`` that is at most 1/2:

* regular half (the pole or the centre is near): plain Newton on ``y`` or ``w``, which keeps
  ``w`` to full relative precision where ``u ∝ w``;
* singular half (the separatrix is near): Newton on ``y_c`` or ``w_c``, safeguarded by a
  bracket and a bisection that is geometric, so that roots down to ``1e-300`` are found in
  a few dozen steps.

The derivative is eq. 145 written for ``τ``: ``du/dτ = −K(m)/(π√((1 − ρ)(1 − τ)))``
(circulation) or ``−K(m)/(π√(ρτ))`` (libration), and ``dτ/dy_c = −(1 − ρ)``,
``dτ/dw = −ρ``.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from andoyer.state.sadov_frame import SadovFrame
from andoyer.state.sadov_orbit import Orbit, orbit

__all__ = ["solve"]

Array = NDArray[np.float64]
EPS = np.finfo(float).eps
TINY = 1e-300
MAX_ITER = 200


def _pair(complement: NDArray[np.bool_], t: Array) -> tuple[Array, Array]:
    """``(v, v_c)`` of the region from the unknown ``t`` (``t = v_c`` where ``complement``)."""
    v = np.where(complement, 1.0 - t, t)
    vc = np.where(complement, t, 1.0 - t)
    return v, vc


def _slope(frame: SadovFrame, o: Orbit, complement: NDArray[np.bool_]) -> Array:
    """``du/dt`` for the unknown ``t`` (``v`` or ``v_c``)."""
    dtau_dv = np.where(o.circ, frame.rho_c, frame.rho)  # τ = (1−ρ) y ; 1 − τ = ρ w
    dtau_dv = np.where(o.circ, dtau_dv, -dtau_dv)
    return o.dudtau * np.where(complement, -dtau_dv, dtau_dv)


def _separatrix_guess(frame: SadovFrame, circ: NDArray[np.bool_], gap: Array) -> Array:
    r"""Start for ``t = y_c`` or ``w_c`` from ``|u − u_s| ≈ A t (log(B/t) + 1)``.

    The logarithmic asymptote of ``K`` (``K ≈ ½ log(16/m_c)``) in ``du/dτ`` gives
    ``A = √(1 − ρ)/(2π√ρ)``, ``B = 16ρ`` (circulation) and ``A = √ρ/(2π√(1 − ρ))``,
    ``B = 16(1 − ρ)`` (libration); the equation is solved by a few fixed-point steps. When
    ``ρ = 1`` the libration has ``u = 1 − √w_c`` exactly.
    """
    rho, rho_c = frame.rho, frame.rho_c
    if rho_c == 0.0:
        return np.clip(gap * gap, TINY, 0.5)
    A = np.where(circ, np.sqrt(rho_c / rho), np.sqrt(rho / rho_c)) / (2.0 * np.pi)
    B = 16.0 * np.where(circ, rho, rho_c)
    t = np.clip(gap / A, TINY, 0.5)
    for _ in range(4):
        t = np.clip(gap / (A * (np.log(B / t) + 1.0)), TINY, 0.5)
    return t


def solve(frame: SadovFrame, u: Array) -> Orbit:
    """Orbits with action fraction ``u`` (1-D, ``0 <= u <= 1``, none on the separatrix).

    Parameters
    ----------
    frame : SadovFrame
    u : numpy.ndarray, shape (n,)
        ``|I_ℓ|/G``, different from ``frame.separatrix_fraction``.

    Returns
    -------
    Orbit
        Circulating where ``u`` exceeds the separatrix value; ``orbit.u`` reproduces ``u`` to
        a few ulp (``ε log(1/m_c)`` near the separatrix).

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> frame = SadovFrame.from_body(RigidBody(1.0, 2.0, 2.5))
    >>> o = solve(frame, np.array([0.3, 0.9]))
    >>> o.circ.tolist(), bool(np.allclose(o.u, [0.3, 0.9], rtol=1e-15, atol=0))
    ([False, True], True)
    """
    u_s = frame.separatrix_fraction
    circ = u > u_s
    half = orbit(frame, np.array([True, False]), np.full(2, 0.5), np.full(2, 0.5)).u
    u_half = np.where(circ, half[0], half[1])
    # Singular half: the root lies nearer the separatrix than the region's midpoint.
    singular = np.where(circ, u < u_half, u > u_half)
    complement = singular  # the unknown is y_c or w_c on the singular half, y or w on the other
    u_end = np.where(circ, 1.0, 0.0)  # u at t = 0 on the regular half
    t0_regular = 0.5 * (u - u_end) / (u_half - u_end)
    t = np.where(singular, _separatrix_guess(frame, circ, np.abs(u - u_s)), t0_regular)
    lo = np.where(singular, TINY, 0.0)
    hi = np.full_like(u, 0.5)
    t = np.clip(t, lo, hi)
    exact = u == u_end  # the pole (u = 1) or the centre (u = 0)
    active = ~exact
    for _ in range(MAX_ITER):
        if not active.any():
            break
        idx = np.flatnonzero(active)
        ti = t[idx]
        o = orbit(frame, circ[idx], *_pair(complement[idx], ti))
        slope = _slope(frame, o, complement[idx])
        resid = o.u - u[idx]
        # Orient so that the residual increases with t.
        up = slope > 0
        f = np.where(up, resid, -resid)
        lo_i = np.where(f < 0, ti, lo[idx])
        hi_i = np.where(f > 0, ti, hi[idx])
        lo[idx], hi[idx] = lo_i, hi_i
        with np.errstate(divide="ignore", invalid="ignore"):
            newton = ti - resid / slope
        inside = (newton > lo_i) & (newton < hi_i) & np.isfinite(newton)
        geometric = singular[idx] & (hi_i > 4.0 * lo_i)
        bisect = np.where(
            geometric, np.sqrt(np.maximum(lo_i, 1e-12 * hi_i)) * np.sqrt(hi_i), 0.5 * (lo_i + hi_i)
        )
        # Converged: the residual or the Newton step is at round-off level (the step may then
        # fall on the bracket's end, which is the root itself), or the bracket has collapsed,
        # possibly onto the floor TINY when u is within the rounding of u(t) from u_s.
        small = (np.abs(newton - ti) <= 2.0 * EPS * np.abs(ti)) | (np.abs(resid) <= 2.0 * EPS * u[idx])
        done = (f == 0) | small | (hi_i - lo_i <= 2.0 * EPS * hi_i) | (hi_i <= 4.0 * TINY)
        new = np.where(inside, newton, np.where(done, ti, bisect))
        t[idx] = new
        active[idx] = ~done
    t = np.where(exact, 0.0, t)
    return orbit(frame, circ, *_pair(complement, t))
