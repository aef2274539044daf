r"""Torque-free motion on the separatrix ``2T = G²/B`` (the ``k → 1`` limit).

In the SAM working frame (axis 3 = ``C``, ``m₃ > 0``), with ``σ = sign m₁`` and the
amplitudes of :mod:`andoyer.free.triaxial` (now ``a₁² + a₃² = G²``, ``k = 1``),

.. math::
   m_1 = \sigma a_1 \operatorname{sech}\tau,\quad m_2 = \sigma a_2 \tanh\tau,\quad
   m_3 = a_3 \operatorname{sech}\tau,\qquad \tau = \omega t + \tau_0,\quad
   \sinh\tau_0 = \frac{a_3 m_2}{\sigma a_2 m_3}.

The momentum leaves the unstable axis ``±B`` at ``t → −∞`` and reaches the other one at
``t → +∞``.  With ``c = a₃/G`` and ``∫dτ/(1 + c sech τ) = τ − (2c/√(1−c²))
arctan(√((1−c)/(1+c)) tanh(τ/2))``,

.. math::
   \Delta\psi = G w_2\,\Delta t - \frac{2 c P_1}{G \omega \sqrt{1 - c^2}}
      \Big[\arctan\big(r\tanh\tfrac{\tau}{2}\big)\Big]_{\tau_0}^{\tau},
   \qquad r = \sqrt{\frac{1-c}{1+c}} .

The attitude is assembled as in the triaxial case (:func:`andoyer.free.regime.attitude_anchor`).
The steady spin about ``±B`` (``m₁ = m₃ = 0``) is handled by :mod:`andoyer.free.uniform`.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from andoyer.free.phase import Frequency, cycles, frequency
from andoyer.free.quaternion import anchored_attitude
from andoyer.free.regime import PolhodeFrame, attitude_anchor, working_axes
from andoyer.special.compensated import PI_DD, dd_div, dd_mul

__all__ = ["Separatrix", "evaluate", "separatrix"]


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
        Attitude constants as in :class:`andoyer.free.triaxial.Triaxial`.
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
    >>> from andoyer.free.regime import polhode_frame
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


def evaluate(c: Separatrix, t, attitude=True):
    """Body angular momentum and attitude on the separatrix at times ``t``.

    Parameters
    ----------
    c : Separatrix
        Constants shaped to broadcast against ``t``.
    t : ndarray
        Times since the initial state.
    attitude : bool, optional
        Also return the attitude quaternion components.

    Returns
    -------
    m : tuple of 3 ndarray
    q : tuple of 4 ndarray or None

    Examples
    --------
    >>> from andoyer.free.regime import polhode_frame
    >>> fr = polhode_frame(np.array([[3.0, 4.0, 6.0]]), np.array([[1.0, 0.0, 1.0]]),
    ...                    np.array([False]))
    >>> m, _ = evaluate(separatrix(fr), np.array([1e3]), attitude=False)
    >>> [round(float(v[0]), 12) for v in m]
    [0.0, 1.414213562373, 0.0]
    """
    tau = c.tau0 + c.omega * t
    th = np.tanh(tau)
    se = 1.0 / np.cosh(tau)
    m = tuple(c.u_sech[k] * se + c.u_tanh[k] * th for k in range(3))
    if not attitude:
        return m, None
    half = np.pi * cycles(c.spin, t) + c.coef * (np.arctan(c.r * np.tanh(0.5 * tau)) - c.art0)
    arc = ((c.v_tanh, th), (c.v_sech, se))
    return m, anchored_attitude(c, (np.cos(half), np.sin(half)), arc, c.a3 * se)
