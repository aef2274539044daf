r"""The body-dependent frame in which Sadov's formulas hold (Gurfil et al. §5, eqs. 137–147).

Sadov's construction needs the body axis ``b3`` of the Andoyer chart to be an axis of
*extreme* inertia and ``b2`` to be the *intermediate* axis (his ``κ² ≥ 0``, eq. 139). Any
body whose ``b3`` has the smallest or the largest moment is brought to that form without
changing ``(L, G)``: when ``b1`` is the intermediate axis, the angle is shifted,
``l' = l + π/2`` (a translation, hence canonical), which exchanges ``sin² l`` and
``cos² l`` in the Hamiltonian. In that *standard frame* ``b_e`` (moment ``I_e``) is the
in-plane axis of extreme inertia and ``b_i`` (moment ``I_i``) the intermediate one.

Everything then depends on the inverse moments ``a = 1/I`` only through the ratio

.. math:: \rho = \frac{a_e - a_i}{a_e - a_3} = \frac{I_3 (I_i - I_e)}{I_i (I_3 - I_e)}
          = \frac{\kappa^2}{1 + \kappa^2} \in [0, 1],

which is invariant under ``a ↦ αa + β`` for either sign of ``α``: the same formulas hold
when ``b3`` is the axis of largest inertia (``a3`` smallest) and when it is the axis of
smallest inertia (``a3`` largest). ``ρ = 0`` for ``I_e = I_i`` (``b3`` an axis of
symmetry, or a sphere), ``ρ = 1`` for ``I_i = I3`` (``b_e`` an axis of symmetry).

A body whose ``b3`` is the intermediate axis is not supported: its ``(l, L)`` cylinder has
no circulating orbits (every orbit librates about ``±b1`` or ``±b2``) and Sadov's
substitution (eq. 142) does not apply.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from andoyer.body import RigidBody

__all__ = ["SadovFrame"]

Array = NDArray[np.float64]


@dataclass(frozen=True)
class SadovFrame:
    r"""Constants of a body in Sadov's standard frame.

    Attributes
    ----------
    rho : float
        ``ρ = κ²/(1 + κ²) = I3 (I_i − I_e) / (I_i (I3 − I_e))``.
    rho_c : float
        ``1 − ρ = I_e (I3 − I_i) / (I_i (I3 − I_e))``, formed without cancellation.
    a3 : float
        ``1/I3``.
    d_e3 : float
        ``a_e − a3 = (I3 − I_e)/(I_e I3)`` (positive when ``b3`` has the largest moment).
    swapped : bool
        True when ``b1`` is the intermediate axis and ``l' = l + π/2``.

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> frame = SadovFrame.from_body(RigidBody(1.0, 2.0, 2.5))
    >>> round(frame.rho, 12), frame.swapped
    (0.833333333333, False)
    >>> SadovFrame.from_body(RigidBody(2.0, 1.0, 2.5)).swapped
    True
    """

    rho: float
    rho_c: float
    a3: float
    d_e3: float
    swapped: bool

    @classmethod
    def from_body(cls, body: RigidBody) -> SadovFrame:
        """Standard-frame constants of ``body``; ``ValueError`` if ``b3`` is the intermediate axis."""
        I1, I2, I3 = body.I1, body.I2, body.I3
        if min(I1, I2) < I3 < max(I1, I2):
            msg = (
                "expected a body whose axis b3 has the smallest or the largest moment "
                "(Sadov's variables are built on the Andoyer chart about b3), got "
                f"I3 = {I3!r} between I1 = {I1!r} and I2 = {I2!r}; relabel the axes"
            )
            raise ValueError(msg)
        # The in-plane axis whose moment lies nearer to I3 is the intermediate one.
        swapped = abs(I1 - I3) < abs(I2 - I3)
        Ie, Ii = (I2, I1) if swapped else (I1, I2)
        if Ie == Ii:
            return cls(0.0, 1.0, 1.0 / I3, (I3 - Ie) / (Ie * I3), False)
        return cls(
            I3 * (Ii - Ie) / (Ii * (I3 - Ie)),
            Ie * (I3 - Ii) / (Ii * (I3 - Ie)),
            1.0 / I3,
            (I3 - Ie) / (Ie * I3),
            swapped,
        )

    @property
    def identity(self) -> bool:
        """True when the Andoyer variables are already action–angle (``ρ = 0``)."""
        return self.rho == 0.0

    @property
    def separatrix_fraction(self) -> float:
        r"""``|I_ℓ|/G`` on the separatrix: ``(2/π) arctan κ = (2/π) arcsin √ρ``."""
        return float(2.0 / np.pi * np.arctan2(np.sqrt(self.rho), np.sqrt(self.rho_c)))

    @property
    def circulation_origin(self) -> float:
        """Sadov's ``z`` (eq. 142) of the circulation origin ``φ_ℓ = 0`` (the meridian of ``+b_i``)."""
        return 0.5 * np.pi if self.swapped else -0.5 * np.pi

    def to_standard(self, sin_l: Array, cos_l: Array) -> tuple[Array, Array]:
        """``(sin l', cos l')`` of the standard frame from ``(sin l, cos l)`` (exact)."""
        return (cos_l, -sin_l) if self.swapped else (sin_l, cos_l)

    def angle_from_standard(self, sin_lp: Array, cos_lp: Array) -> Array:
        """The body-frame angle ``l`` (unreduced ``atan2``) from components of ``l'``."""
        return np.arctan2(-cos_lp, sin_lp) if self.swapped else np.arctan2(sin_lp, cos_lp)
