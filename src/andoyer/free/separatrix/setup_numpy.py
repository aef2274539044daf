"""The constants of the separatrix motion on arrays (derived in :mod:`andoyer.free.separatrix`).

Both backends of :class:`andoyer.free.FreeMotion` use this numpy driver; the working frame and
the attitude anchor are those of the triaxial states
(:mod:`andoyer.free.common.polhode_numpy`).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from andoyer.free.common.cycles_numpy import Frequency, frequency
from andoyer.free.common.polhode_numpy import PolhodeFrame, attitude_anchor, working_axes
from andoyer.special.compensated import PI_DD, dd_div, dd_mul

__all__ = ["Separatrix", "separatrix"]


class Separatrix(NamedTuple):
    """Per-state constants on the separatrix (vectors ``(3, N)``, quaternions ``(4, N)``).

    Attributes
    ----------
    omega, tau0 : ndarray
        Rate and initial value of ``τ``.
    u_sech, u_tanh : ndarray, shape (3, N)
        Body vectors with ``m = u_sech sech τ + u_tanh tanh τ``.
    spin : Frequency
        ``G w₂ / 2π`` in cycles per unit time.
    r, coef, art0 : ndarray
        ``r``, the coefficient of the arctan term in ``Δψ/2`` and its initial value.
    quat_u, quat_v, v_tanh, v_sech : ndarray
        Attitude constants as in :class:`andoyer.free.triaxial.setup_numpy.Triaxial`.
    G, a3 : ndarray
    """

    omega: np.ndarray
    tau0: np.ndarray
    u_sech: np.ndarray
    u_tanh: np.ndarray
    spin: Frequency
    r: np.ndarray
    coef: np.ndarray
    art0: np.ndarray
    quat_u: np.ndarray
    quat_v: np.ndarray
    v_tanh: np.ndarray
    v_sech: np.ndarray
    G: np.ndarray
    a3: np.ndarray


def separatrix(frame: PolhodeFrame, q0=None):
    """Constants of separatrix motion (states with ``m₁ ≠ 0`` in the SAM working frame).

    Parameters
    ----------
    frame : PolhodeFrame
        SAM working frame of states with ``P₂ = 0`` and ``m₁ ≠ 0``.
    q0 : ndarray, shape (N, 4), optional
        Initial attitudes.

    Returns
    -------
    Separatrix

    Examples
    --------
    >>> from andoyer.free.common.polhode_numpy import polhode_frame
    >>> fr = polhode_frame(np.array([[3.0, 4.0, 6.0]]), np.array([[1.0, 0.0, 1.0]]),
    ...                    np.array([False]))
    >>> float(fr.P2[0][0]), float(separatrix(fr).tau0[0])
    (0.0, 0.0)
    """
    hi = lambda p: p[0]  # noqa: E731
    e13, e23, P1, P3, G = (hi(x) for x in (frame.e13, frame.e23, frame.P1, frame.P3, frame.G))
    a1 = np.sqrt(P1 / e13)
    a2 = np.sqrt(P1 / e23)
    a3 = np.sqrt(P3 / e13)
    omega = np.sqrt(e23 * P3)
    mw = frame.mw
    sigma = np.where(mw[:, 0] < 0, -1.0, 1.0)
    tau0 = np.arcsinh(a3 * mw[:, 1] / (sigma * a2 * mw[:, 2]))
    c = a3 / G
    r = np.sqrt((1.0 - c) / (1.0 + c))
    coef = -c * P1 / (omega * a1)  # = −c P₁/(G ω √(1−c²)), √(1−c²) = a₁/G
    # G w₂ = D/G on the separatrix; D/G = G w₃ + P₁/G
    w2 = dd_div(1.0, 0.0, frame.Iw[:, 1], 0.0)
    spin = dd_div(*dd_mul(*frame.G, *w2), 2.0 * PI_DD[0], 2.0 * PI_DD[1])
    cols = working_axes(frame)
    n = G.size
    quat_u = quat_v = np.zeros((4, n))
    if q0 is not None:
        quat_u, quat_v = attitude_anchor(frame, q0)
    return Separatrix(
        omega=omega,
        tau0=tau0,
        u_sech=sigma * (a1 * cols[0]) + a3 * cols[2],
        u_tanh=sigma * a2 * cols[1],
        spin=frequency(*spin),
        r=r,
        coef=coef,
        art0=np.arctan(r * np.tanh(0.5 * tau0)),
        quat_u=quat_u,
        quat_v=quat_v,
        v_tanh=sigma * a2 * cols[0],
        v_sech=-sigma * a1 * cols[1],
        G=G,
        a3=a3,
    )


