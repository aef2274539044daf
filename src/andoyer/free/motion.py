"""Exact torque-free motion of rigid bodies on arrays: the public entry point.

:class:`FreeMotion` prepares the per-state constants once (regime, working frame,
frequencies in double-double, theta-series coefficients) and then evaluates the body
angular momentum and the attitude at any times, vectorised and in cache-sized chunks.
Each state is routed to one kernel:

* :mod:`andoyer.free.triaxial` — SAM and LAM of a triaxial body (circular theta series
  for ``k² ≤ 1/2``, hyperbolic for ``k² > 1/2``);
* :mod:`andoyer.free.separatrix` — the separatrix ``2T = G²/B``;
* :mod:`andoyer.free.uniform` — axisymmetric bodies, spheres, steady spins about a
  principal axis and bodies at rest.

Times are measured from the initial state.  Conventions (as the rest of ``andoyer``):
moments ``I`` along body axes b1, b2, b3 in any order; body angular momentum ``m``;
attitude quaternions scalar last, rotating body vectors into the reference frame.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from andoyer.free import constants as _const
from andoyer.free import separatrix as _sep
from andoyer.free import triaxial as _tri
from andoyer.free import uniform as _uni
from andoyer.free.regime import Regime, check_inputs, classify, normalise, polhode_frame

__all__ = ["FreeMotion", "FreePeriods", "attitude", "momentum", "periods", "propagate"]

_CHUNK = 16384  # elements per block: amortises numpy call overhead, temporaries stay in cache


class FreePeriods(NamedTuple):
    """Periods of torque-free motion (arrays of the body shape).

    Attributes
    ----------
    period : ndarray
        Period of the body angular momentum ``m(t)`` (``4K/ω`` for a triaxial body,
        ``2π/|λ|`` for regular precession).  ``inf`` where ``m`` never returns (the
        separatrix) or never moves without a polhode of finite period (sphere,
        axisymmetric body spinning about a transverse axis, rest); for a steady spin
        about the polhode axis of a triaxial body it is the limit ``2π/ω`` of nearby
        polhodes.
    precession : ndarray
        Angle by which the attitude turns about the fixed angular momentum over one
        period: ``rot(t + T) = R(m̂_ref, precession) rot(t)``.  Given unwrapped, as the
        advance of Andoyer's node angle ``g`` referred to the polhode axis (only its value
        modulo 2π is frame independent).  ``inf`` with an infinite period, ``0`` at rest.
    precession_rate : ndarray
        Mean rate of that angle, ``precession/period`` (its limit ``G/B`` on the
        separatrix, ``G/I`` for a sphere).
    """

    period: np.ndarray
    precession: np.ndarray
    precession_rate: np.ndarray


class FreeMotion:
    """Exact torque-free motion of many rigid bodies from their initial states.

    Parameters
    ----------
    moments : array_like, shape (..., 3)
        Principal moments along body axes b1, b2, b3 (any order, positive, triangle
        inequality).
    m0 : array_like, shape (..., 3)
        Initial body-frame angular momentum.
    q0 : array_like, shape (..., 4), optional
        Initial attitude quaternions (scalar last, body → reference); normalised here.
        Required for :meth:`attitude`.

    Attributes
    ----------
    shape : tuple
        Broadcast shape of the states.
    regime : ndarray of int8
        :class:`Regime` codes.
    periods : FreePeriods
        Period of ``m(t)`` and precession of the attitude per period.

    Examples
    --------
    >>> fm = FreeMotion([1.0, 2.0, 3.0], [0.3, 0.2, 1.0], [0.0, 0.0, 0.0, 1.0])
    >>> T = float(fm.periods.period)
    >>> fm.momentum(T).round(12).tolist()
    [0.3, 0.2, 1.0]
    >>> fm.attitude([0.0, T]).shape
    (2, 4)
    """

    def __init__(self, moments, m0, q0=None):
        moments, m0 = check_inputs(moments, m0)
        shape = moments.shape[:-1]
        if q0 is not None:
            q0 = np.asarray(q0, dtype=np.float64)
            if q0.ndim == 0 or q0.shape[-1] != 4:
                raise ValueError(f"expected q0 with shape (..., 4), got shape {q0.shape}")
            norm = np.sqrt(np.sum(q0 * q0, axis=-1, keepdims=True))
            if not np.all(np.isfinite(q0)) or np.any(norm == 0):
                raise ValueError("expected finite, non-zero quaternions q0, got zero or non-finite")
            q0 = q0 / norm
            shape = np.broadcast_shapes(shape, q0.shape[:-1])
            q0 = np.broadcast_to(q0, (*shape, 4)).reshape(-1, 4)
        self.shape = shape
        moments = np.broadcast_to(moments, (*shape, 3)).reshape(-1, 3)
        m0 = np.broadcast_to(m0, (*shape, 3)).reshape(-1, 3)
        n = moments.shape[0]
        regime = classify(moments, m0)
        # solve the scaled problem (powers of two, exact): internal time 2^(b−a) t
        moments, m0, a, b = normalise(moments, m0)
        self._tshift, self._mshift = b - a, b
        self.regime = regime.reshape(shape)
        self._has_attitude = q0 is not None
        self._n = n
        period = np.empty(n)
        rate = np.empty(n)
        self._groups = []

        zeros = np.sum(m0 == 0, axis=-1)
        triax = regime <= Regime.SEPARATRIX
        spin = triax & (zeros >= 2)
        sep = (regime == Regime.SEPARATRIX) & ~spin
        tri = triax & ~sep & ~spin
        if np.any(tri):
            # a wobble whose square underflows (|m⊥| < 1e-154 |m|) is a steady spin
            idx = np.nonzero(tri)[0]
            frame = polhode_frame(moments[idx], m0[idx], regime[idx] == Regime.LAM)
            flat = frame.P1[0] == 0
            spin[idx[flat]] = True
            tri[idx[flat]] = False
        uni = ~triax | spin

        if np.any(tri):
            idx = np.nonzero(tri)[0]
            frame = polhode_frame(moments[idx], m0[idx], regime[idx] == Regime.LAM)
            const = _tri.triaxial(frame, None if q0 is None else q0[idx])
            period[idx] = const.period
            rate[idx] = const.precession_rate
            for kind in (True, False):
                sel = np.nonzero(const.circular == kind)[0]
                if sel.size:
                    self._groups.append((_tri.evaluate, idx[sel], _const.subset(const, sel)))
        if np.any(sep):
            idx = np.nonzero(sep)[0]
            frame = polhode_frame(moments[idx], m0[idx], np.zeros(idx.size, dtype=bool))
            const = _sep.separatrix(frame, None if q0 is None else q0[idx])
            period[idx] = np.inf
            rate[idx] = 2.0 * np.pi * const.spin.hi
            self._groups.append((_sep.evaluate, idx, const))
        if np.any(uni):
            idx = np.nonzero(uni)[0]
            axis, I_s, I_t = _uniform_axes(moments[idx], m0[idx], regime[idx])
            const = _uni.uniform(m0[idx], axis, I_s, I_t, None if q0 is None else q0[idx])
            period[idx] = const.period
            rate[idx] = const.precession_rate
            lim = spin[idx] & (regime[idx] != Regime.SEPARATRIX)
            if np.any(lim):  # steady spin about the polhode axis: the limit of nearby polhodes
                j = idx[lim]
                frame = polhode_frame(moments[j], m0[j], regime[j] == Regime.LAM)
                e13, e23, G, w3 = frame.e13[0], frame.e23[0], frame.G[0], frame.w3[0]
                om = G * np.sqrt(e13 * e23)
                period[j] = 2.0 * np.pi / om
                rate[j] = G * w3 + frame.s * om
            self._groups.append((_uni.evaluate, idx, const))
        period = np.ldexp(period, -self._tshift)
        rate = np.ldexp(rate, self._tshift)
        with np.errstate(invalid="ignore"):
            prec = np.where(rate == 0, 0.0, rate * period)
        self.periods = FreePeriods(period.reshape(shape), prec.reshape(shape), rate.reshape(shape))

    def momentum(self, t):
        """Body angular momentum at times ``t`` after the initial state.

        Parameters
        ----------
        t : array_like
            Times, broadcast against the state shape.

        Returns
        -------
        ndarray, shape (*broadcast(shape, t.shape), 3)

        Examples
        --------
        >>> fm = FreeMotion([2.0, 2.0, 3.0], [0.5, 0.0, 1.0])
        >>> fm.momentum(fm.periods.period / 4).round(12).tolist()
        [0.0, 0.5, 1.0]
        """
        return self._evaluate(t, attitude=False)[0]

    def attitude(self, t):
        """Attitude quaternions (scalar last, body → reference) at times ``t``.

        Parameters
        ----------
        t : array_like
            Times, broadcast against the state shape.

        Returns
        -------
        ndarray, shape (*broadcast(shape, t.shape), 4)
            Unit quaternions (sign not normalised).

        Examples
        --------
        >>> fm = FreeMotion([1.0, 1.0, 1.0], [0.0, 0.0, 0.5], [0.0, 0.0, 0.0, 1.0])
        >>> fm.attitude(np.pi).round(12).tolist()  # half a turn about z at rate 0.5
        [0.0, 0.0, 0.707106781187, 0.707106781187]
        """
        if not self._has_attitude:
            raise ValueError("expected an initial attitude q0 to propagate the attitude, got None")
        return self._evaluate(t, attitude=True)[1]

    def propagate(self, t):
        """Body angular momentum and attitude at times ``t``.

        Parameters
        ----------
        t : array_like
            Times, broadcast against the state shape.

        Returns
        -------
        m : ndarray, shape (..., 3)
        q : ndarray, shape (..., 4)

        Examples
        --------
        >>> fm = FreeMotion([1.0, 2.0, 3.0], [0.3, 0.2, 1.0], [0.0, 0.0, 0.0, 1.0])
        >>> m, q = fm.propagate(np.zeros(5))
        >>> m.shape, q.shape
        ((5, 3), (5, 4))
        """
        if not self._has_attitude:
            raise ValueError("expected an initial attitude q0 to propagate the attitude, got None")
        return self._evaluate(t, attitude=True)

    def _evaluate(self, t, attitude):
        t = np.asarray(t, dtype=np.float64)
        if not np.all(np.isfinite(t)):
            raise ValueError(f"expected finite times t, got {t[~np.isfinite(t)].ravel()[:3]}")
        out_shape = np.broadcast_shapes(self.shape, t.shape)
        nd = len(out_shape)
        bs = (1,) * (nd - len(self.shape)) + self.shape
        ts = (1,) * (nd - t.ndim) + t.shape
        # states along rows, times along columns: the leading (state) axes of t are 1 or
        # those of the states, its trailing axes are the epochs
        def outer(k):
            lead = zip(ts[:k], bs[:k], strict=True)
            return set(bs[k:]) <= {1} and all(a in (1, b) for a, b in lead)

        split_at = next((k for k in range(nd + 1) if outer(k)), None)
        if split_at is not None:
            body_rows = None
            lead = ts[:split_at] if set(ts[:split_at]) <= {1} else bs[:split_at]
            t2 = np.broadcast_to(t.reshape(ts), (*lead, *ts[split_at:]))
            t2 = t2.reshape(int(np.prod(lead)), -1)
        else:  # general broadcast: one row per output element
            body_rows = np.broadcast_to(np.arange(self._n).reshape(bs), out_shape).ravel()
            t2 = np.broadcast_to(t, out_shape).reshape(-1, 1)
        nrows = self._n if body_rows is None else body_rows.size
        ncols = t2.shape[1]
        m_out = np.empty((nrows, ncols, 3))
        q_out = np.empty((nrows, ncols, 4)) if attitude else None
        for kernel, members, const in self._groups:
            if body_rows is None:
                rows, pos = members, np.arange(members.size)
            else:
                where = np.full(self._n, -1)
                where[members] = np.arange(members.size)
                rows = np.nonzero(where[body_rows] >= 0)[0]
                pos = where[body_rows[rows]]
            shifts = (self._tshift[members], self._mshift[members])
            _run((kernel, const, shifts), rows, pos, t2, (m_out, q_out))
        m_out = m_out.reshape(*out_shape, 3)
        return m_out, (None if q_out is None else q_out.reshape(*out_shape, 4))


def _run(group, rows, pos, t2, outs):
    """Evaluate one kernel on output rows ``rows`` (constants at ``pos``), block by block."""
    kernel, const, (tshift, mshift) = group
    m_out, q_out = outs
    ncols = t2.shape[1]
    cstep = min(ncols, _CHUNK)
    rstep = max(1, _CHUNK // cstep)
    per_row_t = t2.shape[0] > 1
    contiguous = rows.size > 0 and rows[-1] - rows[0] == rows.size - 1
    for r0 in range(0, rows.size, rstep):
        r_idx = rows[r0 : r0 + rstep]
        # a slice keeps the writes below in place; fancy indices would copy
        r_sel = slice(r_idx[0], r_idx[-1] + 1) if contiguous else r_idx
        p_rows = pos[r0 : r0 + rstep]
        c_rows = _const.rows(const, p_rows)
        tsh, msh = tshift[p_rows][:, None], mshift[p_rows][:, None]
        for c0 in range(0, ncols, cstep):
            cols = slice(c0, c0 + cstep)
            tc = np.ldexp(t2[r_sel, cols] if per_row_t else t2[:, cols], tsh)
            m, q = kernel(c_rows, tc, q_out is not None)
            m = [np.ldexp(comp, msh) for comp in m]
            for out, comps in ((m_out, m), (q_out, q)):
                if out is None:
                    continue
                if contiguous:  # a view: write the components in place, strided
                    block = out[r_sel, cols]
                    for k, comp in enumerate(comps):
                        block[..., k] = comp
                else:
                    out[r_sel, cols] = np.stack(comps, axis=-1)


def _uniform_axes(moments, m0, regime):
    """Axis, axial and transverse moments of the states that move without elliptic functions."""
    order = np.argsort(moments, axis=-1, kind="stable")
    rows = np.arange(moments.shape[0])
    s = moments[rows[:, None], order]
    # axisymmetric: the distinct moment; steady spin: the spin axis; sphere/rest: any axis
    distinct = np.where(s[:, 0] == s[:, 1], order[:, 2], order[:, 0])
    spin_axis = np.argmax(np.abs(m0), axis=-1)  # a steady spin (up to an underflowing wobble)
    axis = np.where(regime == Regime.AXISYMMETRIC, distinct, spin_axis)
    I_s = moments[rows, axis]
    transverse = np.where(s[:, 0] == s[:, 1], s[:, 0], s[:, 2])
    I_t = np.where(regime == Regime.AXISYMMETRIC, transverse, I_s)
    return axis, I_s, I_t


def periods(moments, m0):
    """Period of the body angular momentum and precession of the attitude per period.

    Parameters
    ----------
    moments : array_like, shape (..., 3)
        Principal moments.
    m0 : array_like, shape (..., 3)
        Body angular momentum.

    Returns
    -------
    FreePeriods

    Examples
    --------
    >>> p = periods([1.0, 2.0, 3.0], [0.3, 0.2, 1.0])
    >>> round(float(p.period), 10)
    20.2049347381
    """
    return FreeMotion(moments, m0).periods


def momentum(moments, m0, t):
    """Body angular momentum of torque-free motion at times ``t`` (see :class:`FreeMotion`).

    Parameters
    ----------
    moments, m0 : array_like, shape (..., 3)
        Principal moments and initial body angular momentum.
    t : array_like
        Times since the initial state, broadcast against the states.

    Returns
    -------
    ndarray, shape (..., 3)

    Examples
    --------
    >>> momentum([1.0, 2.0, 3.0], [0.3, 0.2, 1.0], 0.0).tolist()
    [0.3, 0.2, 1.0]
    """
    return FreeMotion(moments, m0).momentum(t)


def attitude(moments, m0, q0, t):
    """Attitude quaternions of torque-free motion at times ``t`` (see :class:`FreeMotion`).

    Parameters
    ----------
    moments, m0 : array_like, shape (..., 3)
        Principal moments and initial body angular momentum.
    q0 : array_like, shape (..., 4)
        Initial attitude (scalar last, body → reference).
    t : array_like
        Times since the initial state.

    Returns
    -------
    ndarray, shape (..., 4)

    Examples
    --------
    >>> attitude([1.0, 2.0, 3.0], [0.3, 0.2, 1.0], [0.0, 0.0, 0.0, 1.0], 0.0).round(15).tolist()
    [0.0, 0.0, 0.0, 1.0]
    """
    return FreeMotion(moments, m0, q0).attitude(t)


def propagate(moments, m0, q0, t):
    """Body angular momentum and attitude of torque-free motion at times ``t``.

    Parameters
    ----------
    moments, m0 : array_like, shape (..., 3)
        Principal moments and initial body angular momentum.
    q0 : array_like, shape (..., 4)
        Initial attitude (scalar last, body → reference).
    t : array_like
        Times since the initial state.

    Returns
    -------
    m : ndarray, shape (..., 3)
    q : ndarray, shape (..., 4)

    Examples
    --------
    >>> m, q = propagate([1.0, 2.0, 3.0], [0.3, 0.2, 1.0], [0.0, 0.0, 0.0, 1.0], [0.0, 1.0])
    >>> m.shape, q.shape
    ((2, 3), (2, 4))
    """
    return FreeMotion(moments, m0, q0).propagate(t)
