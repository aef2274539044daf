r"""Secular spin-axis dynamics under a moving orbit: obliquity, precession, insolation.

The averaged torque of the Sun (and, for the Earth, the Moon) on an oblate planet turns its
unit spin axis ``s`` about the orbit normal of date ``n(t)`` of any
:class:`~andoyer.planetary.orbits.OrbitHistory` (:mod:`andoyer.planetary.spin_axis.model` derives it from
:class:`~andoyer.perturbations.averaged_gravity.SecularGravityGradient`):

.. math:: \dot{\mathbf s} = \alpha(t)\,(\mathbf s\cdot\mathbf n)\,(\mathbf s\times\mathbf n),
   \qquad \alpha(t) = \alpha_\odot\big[(1 - e(t)^2)^{-3/2} + \beta\big],

integrated by compositions of exact rotations (:mod:`andoyer.planetary.spin_axis.stepping`; order 8,
``|s| = 1`` to round-off) and described by :mod:`andoyer.planetary.spin_axis.history` (obliquity,
general precession ``p_A``, climatic precession ``e sin ϖ``) and
:mod:`andoyer.planetary.spin_axis.insolation` (Berger 1978). Times are Julian years TT from J2000, the
frame the J2000 ecliptic and equinox.

Examples
--------
>>> from andoyer.planetary.orbits import VondrakEcliptic
>>> h = spin_axis_history(VondrakEcliptic(), "earth", [-1000.0, 0.0, 1000.0])
>>> np.round(np.degrees(h.obliquity), 4).tolist()  # IAU 2006 (erfa.obl06): 23.5688, 23.4393, 23.3097
[23.5687, 23.4393, 23.3098]
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

import numpy as np
from numpy.typing import ArrayLike

from andoyer._validation import as_finite
from andoyer.planetary.orbits.protocol import OrbitHistory, check_times
from andoyer.planetary.spin_axis.history import (
    BLOCK_ROWS,
    EPSILON_0,
    HISTORY_ROW_BYTES,
    SpinAxisHistory,
    build_model,
    check_run,
    equinox,
    evolve_axes,
    general_precession,
    history_blocks,
    mean_pole_j2000,
    output_times,
    resolve_stepping,
    run_cost,
)
from andoyer.planetary.spin_axis.insolation import daily_insolation
from andoyer.planetary.spin_axis.members import (
    MemberRun,
    member_cost,
    member_obliquities,
    member_times,
    perturbed_states,
)
from andoyer.planetary.spin_axis.model import (
    ARCSEC,  # noqa: F401 - the doctests use it
    DEFAULT_PRECESSION_RATE,
    EARTH_DYNAMICAL_ELLIPTICITY,
    SpinAxisModel,
)
from andoyer.planetary.spin_axis.resonances import resonance_distances
from andoyer.planetary.spin_axis.statistics import ObliquityStatistics, obliquity_statistics

__all__ = [
    "DEFAULT_PRECESSION_RATE",
    "EARTH_DYNAMICAL_ELLIPTICITY",
    "EPSILON_0",
    "MemberRun",
    "ObliquityStatistics",
    "SpinAxisHistory",
    "SpinAxisModel",
    "build_model",
    "check_run",
    "daily_insolation",
    "default_axis",
    "equinox",
    "evolve_axes",
    "general_precession",
    "mean_pole_j2000",
    "member_cost",
    "member_obliquities",
    "member_times",
    "obliquity_statistics",
    "output_times",
    "perturbed_states",
    "resonance_distances",
    "run_cost",
    "spin_axis_blocks",
    "spin_axis_history",
]

def default_axis(body: str) -> np.ndarray:
    """The spin axis at J2000 in the J2000 ecliptic frame, shape (3,).

    Earth: the IAU 2006 mean pole (:func:`mean_pole_j2000`). Any other catalogued body (Mars: the
    IAU WGCCRE 2015 pole with its periodic terms, α = 317.680854°, δ = 52.886439° at J2000,
    Archinal et al. 2018) or a body of the user's own: its IAU pole turned from the equator to the
    ecliptic of J2000 by ``ε₀``, reversed for a retrograde rotator
    (:func:`andoyer.planetary.precession_constant.spin_axis_ecliptic`).

    Parameters
    ----------
    body : str or Body

    Returns
    -------
    numpy.ndarray, shape (3,)

    Examples
    --------
    >>> np.round(default_axis("mars"), 6).tolist()
    [0.446155, -0.055517, 0.893232]
    >>> i, node = np.radians(1.85061), np.radians(49.57854)  # Mars' J2000 orbit (JPL mean elements)
    >>> n = [np.sin(i) * np.sin(node), -np.sin(i) * np.cos(node), np.cos(i)]
    >>> round(float(np.degrees(np.arccos(default_axis("mars") @ n))), 2)  # obliquity
    25.19
    """
    from andoyer.catalogue import Body

    key = body.key if isinstance(body, Body) else str(body).strip().lower()
    if key == "earth" and not isinstance(body, Body):
        return mean_pole_j2000()
    from andoyer.planetary.precession_constant import spin_axis_ecliptic

    return np.array(spin_axis_ecliptic(body))


def spin_axis_history(
    orbit: OrbitHistory,
    body: str,
    times: ArrayLike,
    *,
    precession_rate: float | None = None,
    dynamical_ellipticity: float | None = None,
    tidal_dissipation: float = 0.0,
    ellipticity_drift: float = 0.0,
    axis: ArrayLike | None = None,
    step: float | None = None,
    order: int | None = None,
    tolerance: float | None = None,
    coupling: Callable[[SpinAxisModel, tuple[float, float]], SpinAxisModel] | None = None,
) -> SpinAxisHistory:
    r"""The spin axis of ``body`` along ``orbit`` at ``times`` (Julian years from J2000).

    The axis starts at J2000 from ``axis`` (default :func:`default_axis`) and is integrated
    forward and backward. The torque's strength is set by one of ``precession_rate`` (``ψ̇`` at
    J2000 in ″/yr, the rate of IAU 2006's ``ψ_A``; default :data:`DEFAULT_PRECESSION_RATE`) or
    ``dynamical_ellipticity`` (``H``).

    Parameters
    ----------
    orbit : OrbitHistory
        The planet's orbit (any source: :mod:`andoyer.planetary.orbits`).
    body : {"earth", "mars"}
    times : array_like, shape (N,)
        Increasing output times within ``orbit.span``.
    precession_rate : float, optional
        ″/yr, positive, at most the rate of ``H = 1/2``.
    dynamical_ellipticity : float, optional
        ``H = (C − (A+B)/2)/C``, ``0 < H < 1/2``.
    tidal_dissipation : float
        ``T_d`` (Zeebe & Lourens 2022; 0: none, 1: modern rates), in ``[0, 1.2]``. Earth only.
    ellipticity_drift : float
        ``Ḣ/H`` per Julian year; ``H`` must stay within ``(0, 1/2)`` over the span.
    axis : array_like, shape (3,), optional
        Spin axis at J2000, J2000 ecliptic frame.
    step : float, optional
        Largest integration step (years), shortened where the axis would turn by more than
        1/16 of a turn in one (:data:`~andoyer.planetary.spin_axis.history.MAX_TURN_PER_STEP`).
        Given without a ``tolerance``: the run takes it (no error estimate). Otherwise
        the first step tried (default 1000 years).
    order : {2, 4, 6, 8}, optional
        Order of the composition (default 8).
    tolerance : float, optional
        The largest error of the axis wanted over the output times, radians (at least
        1e-12): the step is halved until two runs agree to it
        (:func:`~andoyer.planetary.spin_axis.history.controlled_outputs`). Default, when no
        ``step`` is given: 0.01″
        (:data:`~andoyer.planetary.spin_axis.history.DEFAULT_TOLERANCE`, far below the
        model's own error, the forced nutation it averages out).
    coupling : callable, optional
        ``coupling(model, (T0, T1))`` returns the model to integrate in place of the one built
        here (e.g. with ``α(t)`` following a tidal history:
        ``andoyer.planetary.tides.tidal_spin_axis_history``).

    Returns
    -------
    SpinAxisHistory
        Its ``largest_turn`` says whether the output times sample the precession; its
        ``error_estimate`` (radians), ``integration_step`` and ``order`` what the run took.

    Raises
    ------
    ValueError
        For a parameter out of its range (:mod:`andoyer.planetary.parameters`), times
        outside the orbit's span, and a run that cannot fit in memory or time
        (:func:`run_cost`, :func:`andoyer._limits.check_size`: the memory is that of the
        output, 88 bytes per time, and of one block of the integration, whatever the span).

    Examples
    --------
    >>> from andoyer.planetary.orbits import VondrakEcliptic
    >>> h = spin_axis_history(VondrakEcliptic(), "earth", [0.0, 100.0])
    >>> round(float(h.precession[1] / ARCSEC), 2)  # p_A after a century; IAU 2006: 5029.90
    5029.9
    """
    blocks = spin_axis_blocks(
        orbit,
        body,
        times,
        precession_rate=precession_rate,
        dynamical_ellipticity=dynamical_ellipticity,
        tidal_dissipation=tidal_dissipation,
        ellipticity_drift=ellipticity_drift,
        axis=axis,
        step=step,
        order=order,
        tolerance=tolerance,
        coupling=coupling,
        row_bytes=HISTORY_ROW_BYTES,
        what="a spin-axis history",
    )
    return SpinAxisHistory.concatenate(list(blocks))


def _prepare(
    orbit: OrbitHistory,
    body: str,
    times: ArrayLike,
    precession_rate: float | None,
    dynamical_ellipticity: float | None,
    tidal_dissipation: float,
    ellipticity_drift: float,
    axis: ArrayLike | None,
    coupling: Callable[[SpinAxisModel, tuple[float, float]], SpinAxisModel] | None = None,
) -> tuple[OrbitHistory, SpinAxisModel, np.ndarray, np.ndarray]:
    """The checked orbit, model, times and J2000 axis of :func:`spin_axis_history`."""
    if not isinstance(orbit, OrbitHistory):
        msg = f"expected an orbit history (andoyer.planetary.orbits), got {type(orbit).__name__}"
        raise ValueError(msg)
    t = as_finite(times, "times")
    if t.ndim != 1 or t.size == 0 or np.any(np.diff(t) <= 0):
        msg = f"expected increasing output times (1-D, non-empty), got shape {t.shape}"
        raise ValueError(msg)
    lo, hi = orbit.span
    if not lo <= 0.0 <= hi:
        msg = f"expected an orbit span containing J2000 (the axis starts there), got {lo:g} to {hi:g}"
        raise ValueError(msg)
    check_times(t, orbit.span, orbit.name)
    s0 = default_axis(body) if axis is None else as_finite(axis, "axis")
    if s0.shape != (3,) or not np.linalg.norm(s0) > 0:
        msg = f"expected a non-zero axis of shape (3,), got shape {s0.shape}"
        raise ValueError(msg)
    s0 = s0 / np.linalg.norm(s0)
    model = build_model(
        orbit, body, s0, precession_rate, dynamical_ellipticity, tidal_dissipation, ellipticity_drift
    )
    model.check_span(min(t[0], 0.0), max(t[-1], 0.0))
    if coupling is not None:
        model = coupling(model, (float(t[0]), float(t[-1])))
    return orbit, model, t, s0


def spin_axis_blocks(
    orbit: OrbitHistory,
    body: str,
    times: ArrayLike,
    *,
    precession_rate: float | None = None,
    dynamical_ellipticity: float | None = None,
    tidal_dissipation: float = 0.0,
    ellipticity_drift: float = 0.0,
    axis: ArrayLike | None = None,
    step: float | None = None,
    order: int | None = None,
    tolerance: float | None = None,
    coupling: Callable[[SpinAxisModel, tuple[float, float]], SpinAxisModel] | None = None,
    rows: int = BLOCK_ROWS,
    row_bytes: float = 0.0,
    row_seconds: float = 0.0,
    fixed_bytes: float = 0.0,
    what: str = "a spin-axis run",
) -> Iterator[SpinAxisHistory]:
    """:func:`spin_axis_history` a block of ``rows`` output times at a time, for streamed output.

    The arguments and the cost are checked when it is called (:func:`check_run`: the
    integration's memory, 96 bytes per output time and a block's, and ``row_bytes`` per
    output time and ``fixed_bytes`` that the caller keeps; its time, with ``row_seconds``
    per output time of the caller's); the integration runs when the first block is asked for.
    Every block carries the ``largest_turn`` of the whole history.

    Parameters
    ----------
    orbit, body, times, precession_rate, dynamical_ellipticity : see :func:`spin_axis_history`
    tidal_dissipation, ellipticity_drift, axis : see :func:`spin_axis_history`
    step, order, tolerance, coupling : see :func:`spin_axis_history`
    rows : int
        Output times per block.
    row_bytes, row_seconds, fixed_bytes : float
        What the caller adds to the cost.
    what : str
        The run, for the messages.

    Returns
    -------
    iterator of SpinAxisHistory

    Examples
    --------
    >>> from andoyer.planetary.orbits import VondrakEcliptic
    >>> blocks = spin_axis_blocks(VondrakEcliptic(), "earth", [-1000.0, 0.0, 1000.0], rows=2)
    >>> [b.t.tolist() for b in blocks]
    [[-1000.0, 0.0], [1000.0]]
    """
    if not (isinstance(rows, int | np.integer) and rows >= 1):
        msg = f"expected a positive whole number of rows per block, got {rows!r}"
        raise ValueError(msg)
    orbit, model, t, s0 = _prepare(
        orbit,
        body,
        times,
        precession_rate,
        dynamical_ellipticity,
        tidal_dissipation,
        ellipticity_drift,
        axis,
        coupling,
    )
    step, order, tolerance = resolve_stepping(step, order, tolerance)
    _, step = check_run(orbit, t, what, 1, step, order, row_bytes, row_seconds, fixed_bytes, model)
    return history_blocks(orbit, model, t, s0, step, order, int(rows), tolerance)
