"""Exact torque-free motion of rigid bodies on arrays: the public entry point.

:class:`FreeMotion` prepares the per-state constants once (regime, working frame,
frequencies in double-double, theta-series coefficients) and then evaluates the body
angular momentum and the attitude at any times, vectorised and in cache-sized chunks.
Each state is routed to its regime:

* :mod:`andoyer.free.triaxial` — SAM and LAM of a triaxial body (circular theta series
  for ``k² ≤ 1/2``, hyperbolic for ``k² > 1/2``);
* :mod:`andoyer.free.separatrix` — the separatrix ``2T = G²/B``;
* :mod:`andoyer.free.uniform` — axisymmetric bodies, spheres, steady spins about a
  principal axis and bodies at rest.

The backend (:mod:`andoyer.free.backends`, the keyword ``backend``) decides how: with
``"compiled"``, the default when numba is installed (:data:`andoyer._jit.NUMBA`), states are
classified, and the triaxial ones prepared and evaluated, in compiled loops
(:mod:`~andoyer.free.common.scaling_compiled`, :mod:`~andoyer.free.triaxial.setup_compiled`,
:mod:`~andoyer.free.triaxial.evaluate_compiled`: the same formulas and accuracy, ~1.5 µs a body
to set up and evaluate once, against ~10 µs), and so are the uniform motions
(:mod:`~andoyer.free.uniform.setup_compiled`, :mod:`~andoyer.free.uniform.evaluate_compiled`);
with ``"numpy"``, by the vectorised drivers of the same kernels (``*_numpy``).

With many epochs per state (:attr:`FreeMotion.periodic_epochs`), the triaxial states are
evaluated through a piecewise-polynomial representation of one period built once per state
(:mod:`~andoyer.free.triaxial.periodic_numpy`: same accuracy, several times cheaper per epoch).

Times are measured from the initial state.  Conventions (as the rest of ``andoyer``):
moments ``I`` along body axes b1, b2, b3 in any order; body angular momentum ``m``;
attitude quaternions scalar last, rotating body vectors into the reference frame.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from andoyer._jit import NUMBA
from andoyer._limits import PHASE_WARN_LIMIT, check_spin_phase, spin_bound
from andoyer.free.backends import resolve
from andoyer.free.common import constants as _const
from andoyer.free.common.blocks import Group, evaluate_blocks
from andoyer.free.common.polhode import steady_spin_limit
from andoyer.free.common.polhode_compiled import polhode_limit
from andoyer.free.common.polhode_numpy import polhode_frame
from andoyer.free.common.scaling_compiled import classify_and_scale
from andoyer.free.common.scaling_numpy import normalise
from andoyer.free.separatrix import evaluate_numpy as _sep_eval
from andoyer.free.separatrix.setup_numpy import separatrix
from andoyer.free.triaxial import evaluate_compiled as _ceval
from andoyer.free.triaxial import evaluate_numpy as series
from andoyer.free.triaxial import periodic_numpy as _periodic
from andoyer.free.triaxial.columns import PRECESSION_RATE
from andoyer.free.triaxial.setup_compiled import as_triaxial, triaxial_table
from andoyer.free.triaxial.setup_numpy import triaxial
from andoyer.free.uniform import evaluate_compiled as _cuni_eval
from andoyer.free.uniform import evaluate_numpy as _uni_eval
from andoyer.free.uniform.setup_compiled import uniform_table
from andoyer.free.uniform.setup_numpy import uniform, uniform_axes
from andoyer.regime import Regime, check_inputs, regime_codes

__all__ = ["FreeMotion", "FreePeriods", "attitude", "momentum", "periods", "propagate"]

_SETUP_BLOCK = 4096  # states per block of the vectorised triaxial set-up (temporaries stay in cache)


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
        Principal moments along body axes b1, b2, b3 (any order, positive; the triangle
        inequality of a mass distribution is not needed).
    m0 : array_like, shape (..., 3)
        Initial body-frame angular momentum.
    q0 : array_like, shape (..., 4), optional
        Initial attitude quaternions (scalar last, body → reference); normalised here.
        Required for :meth:`attitude`.
    backend : {"compiled", "numpy"}, optional
        The implementation that classifies the states and prepares and evaluates the
        triaxial ones (:mod:`andoyer.free.backends`): compiled loops or vectorised numpy, the
        same formulas and accuracy.  Default: the fastest available, ``"compiled"`` when
        numba is installed (:func:`andoyer.free.backends.default`).  ``ValueError`` for another
        name, or ``"compiled"`` without numba.

    Attributes
    ----------
    backend : str
        The backend used.
    shape : tuple
        Broadcast shape of the states.
    regime : ndarray of int8
        :class:`Regime` codes.
    periods : FreePeriods
        Period of ``m(t)`` and precession of the attitude per period.
    periodic_epochs : float
        Epochs per state from which triaxial states are evaluated through a
        piecewise-polynomial representation of one period, built once
        (:mod:`andoyer.free.triaxial.periodic_numpy`: same accuracy, several times faster per
        epoch); below it, directly.  A class default (4096 with numba, ``inf`` without, where the
        vectorised direct path is faster; ``inf`` too for the numpy backend with numba),
        settable per instance (``0``: always, ``inf``: never).

    Examples
    --------
    >>> fm = FreeMotion([1.0, 2.0, 3.0], [0.3, 0.2, 1.0], [0.0, 0.0, 0.0, 1.0])
    >>> T = float(fm.periods.period)
    >>> fm.momentum(T).round(12).tolist()
    [0.3, 0.2, 1.0]
    >>> fm.attitude([0.0, T]).shape
    (2, 4)
    >>> vectorised = FreeMotion([1.0, 2.0, 3.0], [0.3, 0.2, 1.0], [0.0, 0.0, 0.0, 1.0], backend="numpy")
    >>> vectorised.backend, bool(abs(vectorised.attitude(T) - fm.attitude(T)).max() < 1e-14)
    ('numpy', True)
    """

    # measured break-even (50 random triaxial bodies at 2^11 … 2^13 epochs, build included):
    # ~1300 epochs a state for the momentum, ~4096 with the attitude (at 4096: 0.44× and 1.0×
    # the direct path's time); without numba the vectorised direct kernels beat the
    # per-epoch gathers of the pieces
    periodic_epochs = 4096.0 if NUMBA else np.inf

    def __init__(self, moments, m0, q0=None, *, backend=None):
        self.backend = resolve(backend)
        compiled = self.backend == "compiled"
        if not compiled and NUMBA:  # the numpy backend's own break-even (the class default is numba's)
            self.periodic_epochs = np.inf
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
            q0 = _flat(q0, shape)
        self.shape = shape
        moments, m0 = _flat(moments, shape), _flat(m0, shape)
        n = moments.shape[0]
        self._spin = (moments, m0)  # their spin rate bounds every phase rate (andoyer._limits)
        self._spin_bound = None
        # solve the scaled problem (powers of two, exact): internal time 2^(b−a) t
        if compiled:
            regime, moments, m0, a, b = classify_and_scale(moments, m0)
        else:
            moments, m0, a, b = normalise(moments, m0)
            regime = regime_codes(moments, m0)
        tshift = b - a
        self.regime = regime.reshape(shape)
        self._has_attitude = q0 is not None
        period = np.empty(n)
        rate = np.empty(n)
        groups = []
        self._pending = None

        zeros = np.sum(m0 == 0, axis=-1)
        triax = regime <= Regime.SEPARATRIX
        spin = triax & (zeros >= 2)
        sep = (regime == Regime.SEPARATRIX) & ~spin
        tri = triax & ~sep & ~spin
        if tri.any():
            idx = np.nonzero(tri)[0]
            qi = None if q0 is None else q0[idx]
            idx, flat, tri_groups, const, self._pending = _triaxial_groups(
                moments[idx], m0[idx], regime[idx] == Regime.LAM, qi, idx, compiled
            )
            spin[flat] = True  # a wobble whose square underflows (|m⊥| < 1e-154 |m|)
            tri[flat] = False  # is a steady spin
            period[idx] = const.period
            rate[idx] = const.precession_rate
            groups += tri_groups
        uni = ~triax | spin

        if sep.any():
            idx = np.nonzero(sep)[0]
            frame = polhode_frame(moments[idx], m0[idx], np.zeros(idx.size, dtype=bool))
            const = separatrix(frame, None if q0 is None else q0[idx])
            period[idx] = np.inf
            rate[idx] = 2.0 * np.pi * const.spin.hi
            groups.append((_sep_eval.evaluate, idx, const))
        if uni.any():
            idx = np.nonzero(uni)[0]
            qi = None if q0 is None else q0[idx]
            if compiled:  # the set-up and evaluation of one body take µs instead of ~0.5 ms
                const, kernel = uniform_table(moments[idx], m0[idx], regime[idx], qi), _cuni_eval.evaluate
            else:
                axis, I_s, I_t = uniform_axes(moments[idx], m0[idx], regime[idx])
                const, kernel = uniform(m0[idx], axis, I_s, I_t, qi), _uni_eval.evaluate
            period[idx] = const.period
            rate[idx] = const.precession_rate
            lim = spin[idx] & (regime[idx] != Regime.SEPARATRIX)
            if lim.any():  # steady spin about the polhode axis: the limit of nearby polhodes
                j = idx[lim]
                if compiled:
                    period[j], rate[j] = polhode_limit(moments[j], m0[j], regime[j] == Regime.LAM)
                else:
                    frame = polhode_frame(moments[j], m0[j], regime[j] == Regime.LAM)
                    period[j], rate[j] = steady_spin_limit(
                        frame.s, frame.e13[0], frame.e23[0], frame.G[0], frame.w3[0]
                    )
            groups.append((kernel, idx, const))
        self._groups = [Group(k, idx, c, tshift[idx], b[idx]) for k, idx, c in groups]
        self._scaled_periods = (period, rate, tshift)
        self._periods = None
        self._periodic = {}

    @property
    def periods(self):
        """Period of ``m(t)`` and precession of the attitude per period (:class:`FreePeriods`).

        Computed on first use where the set-up skipped the precession rate (compiled
        set-up, no attitude asked).
        """
        if self._periods is None:
            period, rate, tshift = self._scaled_periods
            if self._pending is not None:
                idx, args = self._pending
                rate[idx] = triaxial_table(*args, rate=True)[0][:, PRECESSION_RATE]
                self._pending = None
            period = np.ldexp(period, -tshift)
            rate = np.ldexp(rate, tshift)
            with np.errstate(invalid="ignore"):
                prec = np.where(rate == 0, 0.0, rate * period)
            shape = self.shape
            self._periods = FreePeriods(period.reshape(shape), prec.reshape(shape), rate.reshape(shape))
        return self._periods

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
        # the least and greatest time: two passes without a temporary of t's size (a NaN or an
        # infinity makes one of them non-finite), which also bound |t| for the phase check
        lo, hi = (float(t.min()), float(t.max())) if t.size else (0.0, 0.0)
        if not (math.isfinite(lo) and math.isfinite(hi)):
            raise ValueError(f"expected finite times t, got {t[~np.isfinite(t)].ravel()[:3]}")
        try:
            np.broadcast_shapes(self.shape, t.shape)
        except ValueError:
            msg = f"expected times broadcastable with the states' shape {self.shape}, got shape {t.shape}"
            raise ValueError(msg) from None
        if self._spin_bound is None:
            self._spin_bound = spin_bound(*self._spin)
        if self._spin_bound * max(hi, -lo) > PHASE_WARN_LIMIT:  # else check_spin_phase returns at once
            check_spin_phase(*self._spin, t, "the free motion", self._spin_bound)
        n = max(1, math.prod(self.shape))
        per_state = math.prod(np.broadcast_shapes(self.shape, t.shape)) / n
        groups = self._groups
        if per_state >= self.periodic_epochs:
            groups = self._periodic_groups(attitude)
        return evaluate_blocks(groups, self.shape, t, attitude)

    def _periodic_groups(self, attitude):
        """The groups with the triaxial ones replaced by their periodic representation (cached)."""
        if True in self._periodic:  # the attitude representation serves the momentum too
            return self._periodic[True]
        if attitude not in self._periodic:
            groups = []
            for group in self._groups:
                if group.kernel is _ceval.evaluate or group.kernel is series.evaluate:
                    built = [g for g in _periodic.build(group, attitude) if g is not None]
                    if self.backend == "numpy":  # the vectorised fill, numba or not
                        built = [g._replace(kernel=_NumpyPieces) if g.kernel is _periodic.evaluate else g
                                 for g in built]
                    groups += built
                else:
                    groups.append(group)
            self._periodic[attitude] = groups
        return self._periodic[attitude]


def _flat(a, shape):
    """``a`` (..., k) broadcast to ``shape + (k,)`` and flattened to (N, k) (no broadcast if not needed)."""
    k = a.shape[-1]
    return a.reshape(-1, k) if a.shape[:-1] == shape else np.broadcast_to(a, (*shape, k)).reshape(-1, k)


class _NumpyPieces:
    """The numpy backend's kernel of periodic groups: the vectorised fill (``periodic_numpy.fill_numpy``).

    :func:`andoyer.free.triaxial.periodic_numpy.evaluate` fills through the compiled per-epoch
    loop whenever numba is installed; :func:`andoyer.free.common.blocks.evaluate_blocks` calls
    only this ``fill``.
    """

    fill = staticmethod(_periodic.fill_numpy)


def _triaxial_groups(moments, m0, lam, q0, idx, compiled):
    """Constants and evaluation groups of triaxial states (SAM, LAM) with flat indices ``idx``.

    ``compiled`` (the compiled backend): one compiled loop builds the constants and a
    compiled kernel evaluates them (:mod:`andoyer.free.triaxial.setup_compiled`,
    :mod:`andoyer.free.triaxial.evaluate_compiled`); else (numpy) the vectorised
    :mod:`andoyer.free.triaxial.setup_numpy` and :mod:`andoyer.free.triaxial.evaluate_numpy`.  Returns
    the indices kept, those found to be steady spins (a wobble ``P₁`` that underflows),
    the ``(kernel, indices, constants)`` groups, the :class:`Triaxial` constants and, where
    the compiled set-up skipped the precession rate (no attitude), what it needs to
    compute it later: ``(positions, (moments, m0, lam))``.
    """
    if compiled:
        table, flat = triaxial_table(moments, m0, lam, q0, rate=False)
        keep = idx[~flat]
        pending = None
        if q0 is None:
            pending = (keep, (moments[~flat], m0[~flat], lam[~flat]))
        return keep, idx[flat], [(_ceval.evaluate, keep, table)], as_triaxial(table), pending
    # in blocks: the double-double arithmetic makes many temporaries per state, and
    # beyond the cache their memory traffic, not the arithmetic, set the cost per state
    flat, consts = [], []
    for s in range(0, moments.shape[0], _SETUP_BLOCK):
        b = slice(s, s + _SETUP_BLOCK)
        frame = polhode_frame(moments[b], m0[b], lam[b])
        fl = frame.P1[0] == 0
        qb = None if q0 is None else q0[b]
        if np.any(fl):
            sel = s + np.nonzero(~fl)[0]
            frame = polhode_frame(moments[sel], m0[sel], lam[sel])
            qb = None if q0 is None else q0[sel]
        flat.append(fl)
        consts.append(triaxial(frame, qb))
    flat = np.concatenate(flat)
    const = consts[0] if len(consts) == 1 else _const.concatenate(consts)
    keep = idx[~flat]
    groups = []
    for kind in (True, False):
        sel = np.nonzero(const.circular == kind)[0]
        if sel.size:
            groups.append((series.evaluate, keep[sel], _const.subset(const, sel)))
    return keep, idx[flat], groups, const, None


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
