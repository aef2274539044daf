"""The separatrix motion at many epochs on arrays (derived in :mod:`andoyer.free.separatrix`).

From the constants of :mod:`andoyer.free.separatrix.setup_numpy`: ``m`` from ``sech τ`` and
``tanh τ``, the attitude by :func:`andoyer.free.common.polhode_numpy.anchored_attitude`, the
secular phase by :func:`andoyer.free.common.cycles_numpy.cycles`.
"""

from __future__ import annotations

import numpy as np

from andoyer.free.common.cycles_numpy import cycles
from andoyer.free.common.polhode_numpy import anchored_attitude
from andoyer.free.separatrix.setup_numpy import Separatrix

__all__ = ["evaluate"]


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
    >>> from andoyer.free.common.polhode_numpy import polhode_frame
    >>> from andoyer.free.separatrix.setup_numpy import separatrix
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
