"""The rigid body: principal moments of inertia and the parameters built on them.

The regime of a state (SAM, LAM, separatrix, ...) is :meth:`RigidBody.regime`, the one
classification of :mod:`andoyer.regime`; :class:`RotationMode` and
:meth:`RigidBody.rotation_mode`, an older view of it, are deprecated.
"""

from __future__ import annotations

import dataclasses
import os
import sys
import warnings
from dataclasses import dataclass, field
from enum import Enum
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._validation import as_finite, as_vectors, describe

__all__ = ["NonPhysicalInertiaWarning", "RigidBody", "Symmetry"]

_PACKAGE = os.path.dirname(os.path.abspath(__file__)) + os.sep


class NonPhysicalInertiaWarning(UserWarning):
    """Principal moments with ``A + B < C``: no rigid mass distribution has them.

    The moments of a mass distribution satisfy the triangle inequality
    ``A + B = ∫(x² + y² + 2z²) dm ≥ ∫(x² + y²) dm = C``.  Euler's equations, the exact
    torque-free solution and every chart hold for any positive moments, so such bodies
    (e.g. ``(3, 3, 9)``, common in other solvers' test suites) are accepted with this warning.
    """


def _caller_stacklevel() -> int:
    """``stacklevel`` for a warning raised by the caller of this function: the first frame outside andoyer.

    Frames of the package, of :mod:`dataclasses` and of the ``__init__`` it generates are
    skipped, so a body made by ``RigidBody(...)``, ``RigidBody.from_moments``, a named body or
    ``dataclasses.replace`` is reported at the user's line.
    """
    skip = (_PACKAGE, dataclasses.__file__, "<string>")
    frame, level = sys._getframe(1), 1
    while frame.f_back is not None and frame.f_code.co_filename.startswith(skip):
        frame, level = frame.f_back, level + 1
    return level


class Symmetry(str, Enum):
    """Shape class of the inertia ellipsoid, from the sorted moments ``A <= B <= C``."""

    TRIAXIAL = "triaxial"  # A < B < C
    OBLATE = "oblate"  # A = B < C (symmetry axis of maximum inertia)
    PROLATE = "prolate"  # A < B = C (symmetry axis of minimum inertia)
    SPHERICAL = "spherical"  # A = B = C


class RotationMode(str, Enum):
    """Rotation mode of a torque-free state (Lara §1; Gurfil Fig. 4); deprecated for :class:`andoyer.Regime`.

    SAM: circulation about the axis of maximum inertia (``2T/G² < 1/B``);
    LAM: about the axis of minimum inertia (``2T/G² > 1/B``);
    SEPARATRIX: ``2T/G² = 1/B`` (the hyperbolic limit); STEADY: a body whose
    motion is a uniform rotation for every state (sphere) or a regular
    precession (axisymmetric), where the distinction does not arise, and rest.
    These are the :class:`~andoyer.Regime` codes with AXISYMMETRIC, SPHERE and REST merged
    into STEADY; accessing ``RotationMode`` warns (:class:`DeprecationWarning`).
    """

    SAM = "SAM"
    LAM = "LAM"
    SEPARATRIX = "separatrix"
    STEADY = "steady"


# Served with a DeprecationWarning by the module's __getattr__.
_RotationMode = RotationMode
del RotationMode

#: The RotationMode value of each Regime code (SAM, LAM, SEPARATRIX, AXISYMMETRIC, SPHERE, REST).
_MODE_OF_REGIME = np.array(["SAM", "LAM", "separatrix", "steady", "steady", "steady"])


def __getattr__(name: str) -> Any:
    if name == "RotationMode":
        msg = (
            "andoyer.RotationMode is deprecated: RigidBody.regime gives andoyer.Regime codes "
            "(AXISYMMETRIC, SPHERE and REST where RotationMode said STEADY)"
        )
        warnings.warn(msg, DeprecationWarning, stacklevel=_caller_stacklevel())
        return _RotationMode
    msg = f"module 'andoyer.body' has no attribute {name!r}"
    raise AttributeError(msg)


@dataclass(frozen=True, eq=True)
class RigidBody:
    r"""A rigid body given by its principal moments of inertia.

    Parameters
    ----------
    I1, I2, I3 : float
        Principal moments along the body axes ``b1, b2, b3`` (any order, any
        consistent units), positive and finite.  Those of a mass distribution
        satisfy the triangle inequality ``A + B >= C``; moments that break it
        are accepted (Euler's equations hold for any positive moments) with a
        :class:`NonPhysicalInertiaWarning`.
    name : str, optional
        A label used in ``repr`` and reports.

    Notes
    -----
    The sorted moments are Lara's ``A <= B <= C``. Andoyer's parameters
    (Lara eq. 2) are defined by

    .. math:: \alpha (1 + \beta) = C/A - 1, \qquad \alpha (1 - \beta) = C/B - 1,

    so ``alpha = (C/A + C/B)/2 - 1 >= 0`` and ``0 <= beta <= 1`` (``beta = 0``
    for the sphere by convention, where it is undefined and nothing depends
    on it). Sadov's parameter (Gurfil eq. 139) is
    ``kappa² = C (B - A) / (A (C - B))``, infinite when ``B = C``.

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> body = RigidBody(0.9, 1.0, 1.2)
    >>> body.A, body.B, body.C
    (0.9, 1.0, 1.2)
    >>> round(body.alpha, 12), round(body.beta, 12)
    (0.266666666667, 0.25)
    >>> body.symmetry.value
    'triaxial'

    Moments that no rigid body has still give Euler's equations and their exact solution:

    >>> import warnings
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     disk = RigidBody(3.0, 3.0, 9.0)
    >>> caught[0].category.__name__, disk.symmetry.value
    ('NonPhysicalInertiaWarning', 'oblate')
    """

    I1: float
    I2: float
    I3: float
    name: str = field(default="", compare=False)

    def __post_init__(self) -> None:
        moments = []
        for label in ("I1", "I2", "I3"):
            value = getattr(self, label)
            arr = np.asarray(value)
            if arr.ndim != 0:
                msg = f"expected {label} to be a scalar moment of inertia, got {describe(value)}"
                raise ValueError(msg)
            x = float(as_finite(value, label))
            if x <= 0:
                msg = f"expected {label} > 0, got {label} = {x!r}"
                raise ValueError(msg)
            object.__setattr__(self, label, x)
            moments.append(x)
        if not self.is_physical:
            a, b, c = sorted(moments)
            msg = (
                f"moments with A + B = {a + b!r} < C = {c!r} break the triangle inequality: no rigid "
                "mass distribution has them (Euler's equations and their solution still hold)"
            )
            warnings.warn(msg, NonPhysicalInertiaWarning, stacklevel=_caller_stacklevel())

    @classmethod
    def from_moments(cls, moments: ArrayLike, name: str = "") -> RigidBody:
        """Build a body from a length-3 sequence ``(I1, I2, I3)``.

        Examples
        --------
        >>> RigidBody.from_moments([1.0, 2.0, 2.5]).moments
        array([1. , 2. , 2.5])
        """
        arr = as_vectors(moments, "moments")
        if arr.shape != (3,):
            msg = f"expected moments with shape (3,), got shape {arr.shape}"
            raise ValueError(msg)
        return cls(*arr.tolist(), name=name)

    @classmethod
    def from_ratios(cls, A_over_C: float, B_over_C: float, C: float = 1.0, name: str = "") -> RigidBody:
        """Build a body from Lara's Table 1 ratios ``A/C`` and ``B/C`` (axes b1, b2, b3 = A, B, C).

        Examples
        --------
        >>> RigidBody.from_ratios(0.5, 0.75).moments
        array([0.5 , 0.75, 1.  ])
        """
        return cls(A_over_C * C, B_over_C * C, C, name=name)

    @classmethod
    def from_alpha_beta(cls, alpha: float, beta: float, C: float = 1.0, name: str = "") -> RigidBody:
        """Build a body from Andoyer's ``alpha``, ``beta`` (Lara eq. 2) and ``C``.

        Examples
        --------
        >>> body = RigidBody.from_alpha_beta(0.2, 0.5)
        >>> round(body.alpha, 14), round(body.beta, 14)
        (0.2, 0.5)
        """
        a = as_finite(alpha, "alpha")
        b = as_finite(beta, "beta")
        if a < 0 or not 0 <= b <= 1:
            msg = f"expected alpha >= 0 and 0 <= beta <= 1, got alpha = {alpha!r}, beta = {beta!r}"
            raise ValueError(msg)
        return cls(C / (1 + a * (1 + b)), C / (1 + a * (1 - b)), C, name=name)

    # ------------------------------------------------------------------ moments
    @property
    def moments(self) -> NDArray[np.float64]:
        """Moments along the body axes, ``(I1, I2, I3)``, shape (3,)."""
        return np.array([self.I1, self.I2, self.I3])

    @property
    def inverse_moments(self) -> NDArray[np.float64]:
        """``(1/I1, 1/I2, 1/I3)``, shape (3,)."""
        return 1.0 / self.moments

    @property
    def sorted_moments(self) -> tuple[float, float, float]:
        """Lara's ``(A, B, C)``: the moments in increasing order."""
        a, b, c = sorted((self.I1, self.I2, self.I3))
        return a, b, c

    @property
    def axis_order(self) -> tuple[int, int, int]:
        """Body-axis indices of ``(A, B, C)``: ``moments[axis_order]`` is sorted.

        Examples
        --------
        >>> RigidBody(3.0, 1.0, 2.5).axis_order
        (1, 2, 0)
        """
        order = np.argsort(self.moments, kind="stable")
        return int(order[0]), int(order[1]), int(order[2])

    @property
    def A(self) -> float:
        """Smallest principal moment."""
        return self.sorted_moments[0]

    @property
    def B(self) -> float:
        """Intermediate principal moment."""
        return self.sorted_moments[1]

    @property
    def C(self) -> float:
        """Largest principal moment."""
        return self.sorted_moments[2]

    @property
    def euler_coefficients(self) -> NDArray[np.float64]:
        """``c_i = (I_j - I_k) / (I_j I_k)`` for cyclic ``(i, j, k)``, shape (3,).

        The free Euler–Poinsot equations read ``dm_i/dt = c_i m_j m_k``; the
        differences of moments are formed once, exactly, rather than as the
        difference ``1/I_k - 1/I_j`` which cancels on near-axisymmetric bodies.
        """
        I1, I2, I3 = self.I1, self.I2, self.I3
        return np.array([(I2 - I3) / (I2 * I3), (I3 - I1) / (I3 * I1), (I1 - I2) / (I1 * I2)])

    # ------------------------------------------------------- Andoyer parameters
    @property
    def alpha(self) -> float:
        """Andoyer's ``alpha = (C/A + C/B)/2 - 1`` (Lara eq. 2)."""
        a, b, c = self.sorted_moments
        return 0.5 * ((c - a) / a + (c - b) / b)

    @property
    def beta(self) -> float:
        """Andoyer's triaxiality ``beta = (C/A - C/B) / (C/A + C/B - 2)`` (Lara eq. 2); 0 for a sphere."""
        a, b, c = self.sorted_moments
        num = c * (b - a) / (a * b)
        den = (c - a) / a + (c - b) / b
        return 0.0 if den == 0 else num / den

    @property
    def kappa(self) -> float:
        """Sadov's ``kappa = sqrt(C (B - A) / (A (C - B)))`` (Gurfil eq. 139).

        ``inf`` for a prolate body (``B = C > A``); 0 for an oblate body and,
        by convention, for the sphere, where the ratio is 0/0.
        """
        a, b, c = self.sorted_moments
        if b == a:
            return 0.0
        if c == b:
            return float("inf")
        return float(np.sqrt(c * (b - a) / (a * (c - b))))

    @property
    def symmetry(self) -> Symmetry:
        """The shape class: triaxial, oblate (``A = B``), prolate (``B = C``) or spherical."""
        a, b, c = self.sorted_moments
        if a == c:
            return Symmetry.SPHERICAL
        if a == b:
            return Symmetry.OBLATE
        if b == c:
            return Symmetry.PROLATE
        return Symmetry.TRIAXIAL

    @property
    def is_physical(self) -> bool:
        """True when the moments satisfy the triangle inequality ``A + B >= C``, as a mass distribution's do.

        A relative slack of a few ulp accepts the planar (lamina) limit ``A + B = C`` computed
        in floating point.

        Examples
        --------
        >>> RigidBody(1.0, 2.0, 3.0).is_physical                  # a lamina
        True
        """
        a, b, c = self.sorted_moments
        return bool(a + b >= c * (1 - 4 * np.finfo(float).eps))

    @property
    def is_axisymmetric(self) -> bool:
        """True for oblate, prolate and spherical bodies."""
        return self.symmetry is not Symmetry.TRIAXIAL

    # --------------------------------------------------------- state functions
    def energy(self, m_body: ArrayLike) -> NDArray[np.float64]:
        """Kinetic energy ``T = ½ m·I⁻¹m`` of body angular momenta ``m_body`` (..., 3).

        Examples
        --------
        >>> float(RigidBody(1.0, 2.0, 2.5).energy([1.0, 2.0, 5.0]))
        6.5
        """
        m = as_vectors(m_body, "m_body")
        return 0.5 * np.sum(m * m / self.moments, axis=-1)

    def regime(self, m_body: ArrayLike) -> NDArray[np.int8]:
        r"""The :class:`~andoyer.Regime` of torque-free rotation of body angular momenta (..., 3).

        The package's one classification (:func:`andoyer.regime.regime_code`): REST for
        ``m = 0``, SPHERE for ``A = C``, AXISYMMETRIC for ``B = A`` or ``B = C``, else the sign
        of ``P₂ = G²/B − 2T`` evaluated exactly for the floating-point inputs (double-double
        arithmetic): SAM where ``2T < G²/B``, LAM where ``2T > G²/B``, SEPARATRIX where they
        are equal.  :class:`~andoyer.FreeRotation` and :class:`~andoyer.free.FreeMotion` decide
        with the same kernel, so a state near the separatrix is classified identically
        everywhere.

        Parameters
        ----------
        m_body : array_like, shape (..., 3)
            Body-frame angular momenta, finite.

        Returns
        -------
        numpy.ndarray of int8, shape (...)
            :class:`~andoyer.Regime` codes (``Regime(int(code)).name`` names one;
            :func:`andoyer.regime.regime_names` names an array).

        Examples
        --------
        >>> from andoyer import Regime, RigidBody
        >>> body = RigidBody(1.0, 2.0, 3.0)
        >>> [Regime(int(r)).name for r in body.regime([[0.1, 0.0, 1.0], [1.0, 0.0, 0.1], [0.0, 1.0, 0.0]])]
        ['SAM', 'LAM', 'SEPARATRIX']
        >>> Regime(int(RigidBody(1.0, 1.0, 1.5).regime([0.3, 0.0, 1.0]))).name
        'AXISYMMETRIC'
        """
        from andoyer.regime import regime_codes  # loads the compensated arithmetic on first use

        m = as_vectors(m_body, "m_body")
        return regime_codes(np.broadcast_to(self.moments, m.shape), m)

    def rotation_mode(self, m_body: ArrayLike) -> NDArray[np.str_]:
        """Classify body angular momenta (..., 3) as SAM, LAM, separatrix or steady.  Deprecated.

        Use :meth:`regime`, of which this is a view: :class:`~andoyer.Regime` SAM, LAM and
        SEPARATRIX give ``"SAM"``, ``"LAM"`` and ``"separatrix"``; AXISYMMETRIC, SPHERE and
        REST (a zero momentum: the body does not move) give ``"steady"``.  The separatrix test
        is :meth:`regime`'s, exact for the floating-point inputs.  Calling it warns
        (:class:`DeprecationWarning`).

        Returns
        -------
        numpy.ndarray of str, shape (...)
            The ``RotationMode`` values.

        Examples
        --------
        >>> import warnings
        >>> body = RigidBody(1.0, 2.0, 3.0)
        >>> with warnings.catch_warnings():
        ...     warnings.simplefilter("ignore", DeprecationWarning)
        ...     body.rotation_mode([[0.1, 0.0, 1.0], [1.0, 0.0, 0.1], [0.0, 0.0, 0.0]]).tolist()
        ['SAM', 'LAM', 'steady']
        """
        msg = (
            "RigidBody.rotation_mode is deprecated: use RigidBody.regime (andoyer.Regime codes; "
            "AXISYMMETRIC, SPHERE and REST where rotation_mode says 'steady')"
        )
        warnings.warn(msg, DeprecationWarning, stacklevel=2)
        codes = self.regime(m_body)
        return _MODE_OF_REGIME[codes.ravel()].reshape(codes.shape)  # an array also for one state

    def __repr__(self) -> str:
        label = f", name={self.name!r}" if self.name else ""
        return f"RigidBody(I1={self.I1!r}, I2={self.I2!r}, I3={self.I3!r}{label})"
