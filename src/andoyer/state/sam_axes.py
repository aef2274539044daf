r"""The relabelled body axes of Lara's SAM and LAM charts and Andoyer's parameters α, β.

For body axes ``(b1, b2, b3)`` with any positive moments ``(I1, I2, I3)`` the free-body
Hamiltonian in Andoyer variables (Gurfil eq. 89) is, exactly,

.. math:: \mathcal{H} = \frac{G^2}{2 I_3}\Big[1 + \alpha\Big(1 - \frac{L^2}{G^2}\Big)
          (1 - \beta\cos 2l)\Big], \qquad \alpha(1+\beta) = \frac{I_3}{I_1} - 1,\quad
          \alpha(1-\beta) = \frac{I_3}{I_2} - 1.

The SAM chart is taken about the axis of maximum inertia, the LAM chart about the axis of
minimum inertia: the body axes are relabelled cyclically (a proper rotation of the body frame)
so that this axis becomes the third (Lara eqs. 37–39 for LAM).  See :mod:`andoyer.state.sam`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.spatial.transform import Rotation

from andoyer._validation import as_finite, broadcast
from andoyer.body import RigidBody

__all__ = ["MODES", "SAMAxes", "andoyer_parameters", "sam_axes"]

Array = NDArray[np.float64]
MODES = ("SAM", "LAM")


def andoyer_parameters(I1: ArrayLike, I2: ArrayLike, I3: ArrayLike) -> tuple[Array, Array]:
    r"""Andoyer's ``(α, β)`` of the Hamiltonian written about ``b3``, for any positive moments.

    ``α = ½(I3/I1 + I3/I2) − 1`` and ``αβ = ½ I3 (I2 − I1)/(I1 I2)``, formed from differences
    of moments (no cancellation).  ``β = 0`` when ``I1 = I2``.

    Parameters
    ----------
    I1, I2, I3 : array_like, shape (...)
        Positive moments along ``b1, b2, b3``; they broadcast.

    Returns
    -------
    alpha, beta : numpy.ndarray, shape (...)

    Raises
    ------
    ValueError
        If ``α = 0`` with ``I1 ≠ I2`` (``I3`` the harmonic mean of ``I1, I2``): ``β`` is infinite.

    Examples
    --------
    >>> a, b = andoyer_parameters(0.5, 0.75, 1.0)      # Lara's A, B, C: eq. 2
    >>> round(float(a), 15), round(float(b), 15)
    (0.666666666666667, 0.5)
    >>> a, b = andoyer_parameters(0.75, 1.0, 0.5)      # LAM axes: alpha* < 0, beta = -beta*
    >>> float(a), round(float(b), 15), (1 - 0.5) / (1 + 3 * 0.5)
    (-0.41666666666666663, -0.2, 0.2)
    """
    I1, I2, I3 = broadcast(*((n, as_finite(v, n)) for n, v in (("I1", I1), ("I2", I2), ("I3", I3))))
    if np.any((I1 <= 0) | (I2 <= 0) | (I3 <= 0)):
        msg = f"expected positive moments, got I1, I2, I3 = {I1.min()!r}, {I2.min()!r}, {I3.min()!r}"
        raise ValueError(msg)
    alpha = 0.5 * ((I3 - I1) / I1 + (I3 - I2) / I2)
    alpha_beta = 0.5 * I3 * (I2 - I1) / (I1 * I2)
    bad = (alpha == 0) & (alpha_beta != 0)
    if np.any(bad):
        msg = "expected I3 different from the harmonic mean of I1 and I2, got alpha = 0 (beta infinite)"
        raise ValueError(msg)
    return alpha, np.where(alpha_beta == 0, 0.0, alpha_beta / np.where(alpha == 0, 1.0, alpha))


@dataclass(frozen=True)
class SAMAxes:
    """The relabelled body frame of a SAM or LAM chart.

    Attributes
    ----------
    mode : str
        ``"SAM"`` (about the axis of maximum inertia) or ``"LAM"`` (minimum).
    permutation : tuple of int
        New axis ``j`` is old body axis ``permutation[j]``; a cyclic permutation, so the
        relabelling is a proper rotation.  ``permutation[2]`` is the chart's axis.
    moments : tuple of float
        ``(I1', I2', I3')`` of the relabelled axes.
    alpha, beta : float
        :func:`andoyer_parameters` of ``moments``; ``|beta| < 1``.
    quaternion : numpy.ndarray, shape (4,)
        The rotation taking relabelled components to body components:
        ``q_body→ref ⊗ quaternion = q_relabelled→ref``.
    """

    mode: str
    permutation: tuple[int, int, int]
    moments: tuple[float, float, float]
    alpha: float
    beta: float
    quaternion: Array


def sam_axes(body: RigidBody, mode: str = "SAM") -> SAMAxes:
    """The relabelled axes and Andoyer parameters of the SAM or LAM chart of ``body``.

    Parameters
    ----------
    body : RigidBody
    mode : {"SAM", "LAM"}

    Returns
    -------
    SAMAxes

    Raises
    ------
    ValueError
        If the chart's axis is not unique (``β = ±1``: a SAM chart of a prolate body, a LAM chart
        of an oblate body, any chart of a sphere).

    Examples
    --------
    >>> axes = sam_axes(RigidBody(0.5, 0.75, 1.0), "LAM")
    >>> axes.permutation, axes.moments
    ((1, 2, 0), (0.75, 1.0, 0.5))
    """
    if not isinstance(body, RigidBody):
        msg = f"expected an andoyer.RigidBody, got {type(body).__name__}"
        raise ValueError(msg)
    if mode not in MODES:
        msg = f"expected mode 'SAM' or 'LAM', got {mode!r}"
        raise ValueError(msg)
    k = body.axis_order[2] if mode == "SAM" else body.axis_order[0]
    perm = ((k + 1) % 3, (k + 2) % 3, k)
    moments = tuple(float(body.moments[i]) for i in perm)
    if moments[2] in moments[:2]:
        kind = "maximum" if mode == "SAM" else "minimum"
        msg = f"expected a unique axis of {kind} inertia for mode {mode!r}, got {body.moments.tolist()}"
        raise ValueError(msg)
    alpha, beta = (float(x) for x in andoyer_parameters(*moments))
    P = np.zeros((3, 3))
    P[list(perm), [0, 1, 2]] = 1.0
    return SAMAxes(mode, perm, moments, alpha, beta, Rotation.from_matrix(P).as_quat())
