r"""Exact energy contours on the angular-momentum sphere (the polhodes of the free body).

A torque-free body keeps ``|m| = G`` and ``T = ½ m·I⁻¹m``, so its body angular momentum runs
along the intersection of the momentum sphere with the energy ellipsoid.  In the sorted axes
``(x, y, z)`` of the moments ``A ≤ B ≤ C``, with ``e = 2T/G²`` (``1/C ≤ e ≤ 1/A``), subtracting
the sphere times ``1/C`` (or ``1/A``) from the ellipsoid leaves an ellipse, which gives the
curves in closed form:

.. math::

   e < 1/B \;(\text{SAM}):\quad
   x = G\sqrt{\tfrac{e - 1/C}{1/A - 1/C}}\cos\tau,\;
   y = G\sqrt{\tfrac{e - 1/C}{1/B - 1/C}}\sin\tau,\;
   z = \pm G\sqrt{\tfrac{1/A - e}{1/A - 1/C}\cos^2\tau + \tfrac{1/B - e}{1/B - 1/C}\sin^2\tau},

   e > 1/B \;(\text{LAM}):\quad
   y = G\sqrt{\tfrac{1/A - e}{1/A - 1/B}}\cos\tau,\;
   z = G\sqrt{\tfrac{1/A - e}{1/A - 1/C}}\sin\tau,\;
   x = \pm G\sqrt{\tfrac{e - 1/B}{1/A - 1/B}\cos^2\tau + \tfrac{e - 1/C}{1/A - 1/C}\sin^2\tau},

and the separatrix ``e = 1/B`` is the pair of great circles through ``±G ŷ``,
``(x, y, z) = G (cos s cos χ, sin s, ±cos s sin χ)`` with ``tan χ = κ`` (Sadov's parameter,
``κ² = C(B − A)/(A(C − B))``).  Every difference of inverse moments is formed as a difference of
moments, so near-axisymmetric bodies (the Earth) lose nothing to cancellation.  The sorted axes
are then put back on the body axes ``b1, b2, b3`` (``RigidBody.axis_order``).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._validation import as_finite
from andoyer.body import RigidBody, Symmetry

__all__ = ["default_energies", "energy_contour", "separatrix_contour"]

Array = NDArray[np.float64]


def _check(body: RigidBody, G: float, n_points: int) -> tuple[float, int]:
    if not isinstance(body, RigidBody):
        msg = f"expected an andoyer.RigidBody, got {type(body).__name__}"
        raise ValueError(msg)
    if body.symmetry is Symmetry.SPHERICAL:
        msg = f"expected a body with unequal moments (a sphere has one energy), got {body.moments.tolist()}"
        raise ValueError(msg)
    g = float(as_finite(G, "G"))
    if g <= 0:
        msg = f"expected G > 0, got G = {g!r}"
        raise ValueError(msg)
    if int(n_points) != n_points or n_points < 8:
        msg = f"expected an integer n_points >= 8, got {n_points!r}"
        raise ValueError(msg)
    return g, int(n_points)


def _to_body(body: RigidBody, xyz: Array) -> Array:
    out = np.empty_like(xyz)
    out[..., list(body.axis_order)] = xyz
    return out


def energy_contour(body: RigidBody, G: float, energy: float, n_points: int = 361) -> tuple[Array, ...]:
    r"""The curves ``|m| = G``, ``½ m·I⁻¹m = energy`` in body components.

    Parameters
    ----------
    body : RigidBody
        A body with at least two different moments.
    G : float
        Magnitude of the angular momentum, ``G > 0``.
    energy : float
        Kinetic energy, ``G²/(2C) ≤ energy ≤ G²/(2A)``.
    n_points : int
        Points per curve (the first point is repeated at the end: the curves are closed).

    Returns
    -------
    tuple of numpy.ndarray, each of shape (n_points, 3)
        Two curves (the two branches ``±z`` of a SAM polhode, ``±x`` of a LAM polhode, or the
        two great circles of the separatrix), in body components ``(m1, m2, m3)``.

    Examples
    --------
    >>> import numpy as np
    >>> body = RigidBody(1.0, 2.0, 3.0)
    >>> curves = energy_contour(body, 1.0, 0.2)
    >>> [c.shape for c in curves]
    [(361, 3), (361, 3)]
    >>> m = np.concatenate(curves)
    >>> bool(np.allclose(np.linalg.norm(m, axis=-1), 1.0, rtol=1e-14))
    True
    >>> bool(np.allclose(body.energy(m), 0.2, rtol=1e-14))
    True
    """
    g, n = _check(body, G, n_points)
    energy = float(as_finite(energy, "energy"))
    A, B, C = body.sorted_moments
    e = 2.0 * energy / (g * g)
    # Energies outside [G²/2C, G²/2A] by a few ulp are clipped: they arise from rounding.
    slack = 8 * np.finfo(float).eps
    if not (1 - slack) / C <= e <= (1 + slack) / A:
        lo, hi = g * g / (2 * C), g * g / (2 * A)
        msg = f"expected G²/(2C) <= energy <= G²/(2A) = [{lo!r}, {hi!r}], got {energy!r}"
        raise ValueError(msg)
    e = min(max(e, 1 / C), 1 / A)
    if e * B == 1.0:
        return separatrix_contour(body, g, n)
    tau = np.linspace(0.0, 2 * np.pi, n)
    tau[-1] = 0.0  # closes the curve exactly
    c2, s2 = np.cos(tau) ** 2, np.sin(tau) ** 2
    cos2_chi = A * (C - B) / (B * (C - A))
    sin2_chi = C * (B - A) / (B * (C - A))
    # The level enters once, as a fraction in [0, 1]; every squared component is then a
    # combination of that fraction with weights summing to one, so |m| = G and the energy hold
    # to rounding even when A ≈ B or B ≈ C (where 1/A − e and e − 1/B nearly cancel).
    if e * B < 1.0:
        rho = min((e * C - 1) * B / (C - B), 1.0)  # (e − 1/C)/(1/B − 1/C)
        kx = rho * cos2_chi  # (e − 1/C)/(1/A − 1/C)
        x = g * np.sqrt(kx) * np.cos(tau)
        y = g * np.sqrt(rho) * np.sin(tau)
        z = g * np.sqrt((1 - kx) * c2 + (1 - rho) * s2)
        first, second = np.stack([x, y, z], -1), np.stack([x, y, -z], -1)
    else:
        lam = min((e * B - 1) * A / (B - A), 1.0)  # (e − 1/B)/(1/A − 1/B)
        mu = (1 - lam) * sin2_chi  # (1/A − e)/(1/A − 1/C)
        y = g * np.sqrt(1 - lam) * np.cos(tau)
        z = g * np.sqrt(mu) * np.sin(tau)
        x = g * np.sqrt(lam * c2 + (1 - mu) * s2)
        first, second = np.stack([x, y, z], -1), np.stack([-x, y, z], -1)
    return _to_body(body, first), _to_body(body, second)


def separatrix_contour(body: RigidBody, G: float, n_points: int = 361) -> tuple[Array, Array]:
    r"""The separatrix ``½ m·I⁻¹m = G²/(2B)`` on ``|m| = G``: two great circles through ``±G b_B``.

    Parameters
    ----------
    body : RigidBody
        A body with at least two different moments.
    G : float
        Magnitude of the angular momentum.
    n_points : int
        Points per circle (closed: the first point is repeated at the end).

    Returns
    -------
    tuple of two numpy.ndarray of shape (n_points, 3)
        Body components; the circles lie in the planes ``x sin χ = ±z cos χ``, ``tan χ = κ``.

    Examples
    --------
    >>> import numpy as np
    >>> body = RigidBody(1.0, 2.0, 3.0)
    >>> m = np.concatenate(separatrix_contour(body, 2.0))
    >>> bool(np.allclose(body.energy(m), 2.0**2 / (2 * 2.0), rtol=1e-14))
    True
    """
    g, n = _check(body, G, n_points)
    A, B, C = body.sorted_moments
    # cos²χ = A(C − B)/(B(C − A)), sin²χ = C(B − A)/(B(C − A)): tan χ = κ, no 0/0 when B = A or C.
    cos_chi = np.sqrt(A * (C - B) / (B * (C - A)))
    sin_chi = np.sqrt(C * (B - A) / (B * (C - A)))
    s = np.linspace(0.0, 2 * np.pi, n)
    s[-1] = 0.0
    x, y, z = g * np.cos(s) * cos_chi, g * np.sin(s), g * np.cos(s) * sin_chi
    return _to_body(body, np.stack([x, y, z], -1)), _to_body(body, np.stack([x, y, -z], -1))


def default_energies(body: RigidBody, G: float, per_side: int = 5) -> Array:
    """Evenly spread energies: ``per_side`` SAM levels, then ``per_side`` LAM levels.

    The levels divide ``[G²/2C, G²/2B]`` and ``[G²/2B, G²/2A]`` into ``per_side + 1`` equal parts
    (in ``2T/G²``), leaving out the poles and the separatrix.  An oblate body (``A = B``) has no
    LAM levels and a prolate one (``B = C``) no SAM levels.

    Parameters
    ----------
    body : RigidBody
    G : float
    per_side : int

    Returns
    -------
    numpy.ndarray, shape (k,)
        Increasing energies.

    Examples
    --------
    >>> default_energies(RigidBody(2.0, 3.0, 4.0), 1.0, per_side=1).round(12).tolist()
    [0.145833333333, 0.208333333333]
    """
    g, _ = _check(body, G, 8)
    if int(per_side) != per_side or per_side < 0:
        msg = f"expected a non-negative integer per_side, got {per_side!r}"
        raise ValueError(msg)
    A, B, C = body.sorted_moments
    frac = np.arange(1, int(per_side) + 1) / (int(per_side) + 1)
    sam = 1 / C + frac * (C - B) / (B * C) if C > B else np.empty(0)
    lam = 1 / B + frac * (B - A) / (A * B) if B > A else np.empty(0)
    return 0.5 * g * g * np.concatenate([sam, lam])


def check_energy(body: RigidBody, G: float, energies: ArrayLike) -> Array:
    """Validate a 1-D array of energies inside ``[G²/2C, G²/2A]``.

    Examples
    --------
    >>> check_energy(RigidBody(2.0, 3.0, 4.0), 1.0, [0.2]).tolist()
    [0.2]
    """
    values = np.atleast_1d(as_finite(energies, "energies"))
    if values.ndim != 1:
        msg = f"expected a 1-D sequence of energies, got shape {values.shape}"
        raise ValueError(msg)
    A, _, C = body.sorted_moments
    lo, hi = G * G / (2 * C), G * G / (2 * A)
    bad = (values < lo * (1 - 1e-15)) | (values > hi * (1 + 1e-15))
    if np.any(bad):
        msg = f"expected energies in [G²/(2C), G²/(2A)] = [{lo!r}, {hi!r}], got {float(values[bad][0])!r}"
        raise ValueError(msg)
    return values
