"""The uniform motions at many epochs on arrays (the numpy driver of ``evaluate``).

The kernels of :mod:`andoyer.free.uniform.evaluate` applied to whole arrays (states as rows,
epochs as columns), from the constants of :mod:`andoyer.free.uniform.setup_numpy`; the phases
are :func:`andoyer.free.common.cycles_numpy.cycles` (the compiled driver,
:mod:`andoyer.free.uniform.evaluate_compiled`, forms the same values per state).
"""

from __future__ import annotations

from andoyer.free.common.cycles_numpy import cycles
from andoyer.free.uniform import evaluate as _k
from andoyer.free.uniform.setup_numpy import Uniform
from andoyer.special.compensated import split

__all__ = ["evaluate"]


def evaluate(c: Uniform, t, attitude=True):
    """Body angular momentum and attitude of uniform motions at times ``t``.

    Parameters
    ----------
    c : Uniform
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
    >>> import numpy as np
    >>> from andoyer.free.uniform.setup_numpy import uniform
    >>> u = uniform(np.array([[0.5, 0.0, 1.0]]), np.array([2]), np.array([3.0]), np.array([2.0]))
    >>> m, _ = evaluate(u, np.array([u.period[0] / 4]), attitude=False)
    >>> [round(float(v[0]), 12) for v in m]
    [0.0, 0.5, 1.0]
    """
    tt = split(t)
    cb, sb = _k.turn(cycles(c.body, t, tt))
    m = _k.momentum(cb, sb, c.m_par, c.m_perp, c.m_cross)
    if not attitude:
        return m, None
    ca, sa = _k.turn(cycles(c.spin, t, tt))
    return m, _k.attitude(cb, sb, ca, sa, c.q1, c.q2, c.q3, c.q4)
