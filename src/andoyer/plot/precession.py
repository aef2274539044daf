r"""Precession, nutation and obliquity time series of a propagated rotation.

For an axis with unit vector ``a(t)`` in the reference frame — the figure axis
``a = 𝓡 b3`` or the angular-momentum axis ``a = m_ref/|m|`` — the series are

.. math::

   \varepsilon(t) = \operatorname{atan2}\big(\sqrt{a_1^2 + a_2^2},\, a_3\big), \qquad
   \Omega(t) = \operatorname{atan2}(a_1, -a_2) \ \text{(unwrapped in time)},

the obliquity (angle from the reference pole ``s3``) and the precession (longitude of the node
of the plane normal to ``a`` on the reference plane ``s1 s2``).  They are the Euler angles
``(θ, φ)`` for the figure axis (``b3 = (sin θ sin φ, −sin θ cos φ, cos θ)``) and Andoyer's
``(I, h)`` for the momentum axis (``m_ref = G (sin I sin h, −sin I cos h, cos I)``).  The trends
``Ω₀ + Ω̇ t`` and ``ε₀ + ε̇ t`` are fitted by least squares (:func:`andoyer.planetary.precession.fit_trend`)
together with sinusoids of the known nutation frequencies, if given: a straight line alone over
a span that is not a whole number of nutation periods is biased by them (one state of the Earth
over one 18.6-year lunar nutation: 52.2″/yr instead of 50.48″/yr).  The nutations are what is
left,

.. math:: \Delta\Omega(t) = \Omega(t) - \Omega_0 - \dot\Omega t, \qquad
          \Delta\varepsilon(t) = \varepsilon(t) - \varepsilon_0 - \dot\varepsilon t.

``Ω̇`` is the mean rate of the node; a regressing node (``Ω̇ < 0``, the luni-solar precession of
the planets) has the astronomical *precession rate* ``p = −Ω̇ > 0`` (``p = −⟨ḣ⟩`` for the
momentum axis, as in :mod:`andoyer.planetary.precession`).  ``Ω`` is undefined where the axis is at the pole
(``ε = 0`` or ``π``), and the unwrapping needs samples closer than half a turn of ``Ω``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from numpy.typing import ArrayLike, NDArray

from andoyer._validation import as_finite
from andoyer.catalogue.units import ARCSEC, DEGREE
from andoyer.planetary.precession import fit_trend
from andoyer.state import State

__all__ = ["PrecessionSeries", "precession", "precession_data"]

Array = NDArray[np.float64]
AXES = ("figure", "momentum")


@dataclass(frozen=True)
class PrecessionSeries:
    """What :func:`precession` draws.

    Attributes
    ----------
    t : numpy.ndarray, shape (n,)
    axis : str
        ``"figure"`` or ``"momentum"``.
    direction : numpy.ndarray, shape (n, 3)
        The unit axis ``a(t)`` in reference components.
    precession : numpy.ndarray, shape (n,)
        ``Ω(t)``, unwrapped (radians).
    obliquity : numpy.ndarray, shape (n,)
        ``ε(t)`` (radians).
    precession_rate, precession_at_zero : float
        ``Ω̇`` and ``Ω₀`` of the trend (fitted with the nutation frequencies).
    obliquity_rate, obliquity_at_zero : float
        ``ε̇`` and ``ε₀``.
    nutation_longitude, nutation_obliquity : numpy.ndarray, shape (n,)
        ``ΔΩ(t)`` and ``Δε(t)``.
    frequencies : numpy.ndarray, shape (F,)
        The nutation frequencies fitted with the trends (those whose period fits in the span).
    """

    t: Array
    axis: str
    direction: Array
    precession: Array
    obliquity: Array
    precession_rate: float
    precession_at_zero: float
    obliquity_rate: float
    obliquity_at_zero: float
    nutation_longitude: Array
    nutation_obliquity: Array
    frequencies: Array


def precession_data(
    times: ArrayLike, states: State, axis: str = "figure", frequencies: ArrayLike = ()
) -> PrecessionSeries:
    """Precession, obliquity, their trends and the nutations of ``states`` at ``times``.

    Parameters
    ----------
    times : array_like, shape (n,)
        At least two distinct times.
    states : State, shape (n,)
        The propagated states, e.g. ``FreeRotation(body).propagate(state, times)`` or
        :func:`andoyer.integrate.integrate_reference`.
    axis : {"figure", "momentum"}
        The figure axis ``b3`` or the angular momentum.
    frequencies : array_like, shape (F,)
        Angular frequencies (radians per unit of ``times``) of the nutation terms to fit together
        with the trends; those whose period is longer than the span are left out (see
        :func:`andoyer.planetary.precession.fit_trend`).  Default none: straight lines.

    Returns
    -------
    PrecessionSeries

    Examples
    --------
    Regular precession of an axisymmetric body about a momentum along ``s3``: ``φ̇ = G/A``.

    >>> import numpy as np
    >>> from andoyer import FreeRotation, RigidBody, State
    >>> body = RigidBody(1.0, 1.0, 1.5)
    >>> s = State.from_andoyer(l=0.0, g=0.0, h=0.0, L=0.9, G=2.0, H=2.0)
    >>> t = np.linspace(0.0, 10.0, 201)
    >>> series = precession_data(t, FreeRotation(body).propagate(s, t))
    >>> round(series.precession_rate, 12), round(float(np.cos(series.obliquity[0])), 12)
    (2.0, 0.45)

    A slow nutation biases a straight line over a span that is not a whole number of its periods:

    >>> wobble = State.from_andoyer(0.0, 0.0, 0.5 * t + 0.1 * np.sin(2.0 * t), 0.9, 2.0, 1.8)
    >>> round(precession_data(t, wobble, "momentum").precession_rate, 4)
    0.4962
    >>> round(precession_data(t, wobble, "momentum", frequencies=[2.0]).precession_rate, 12)
    0.5
    """
    t = as_finite(times, "times")
    if t.ndim != 1 or t.size < 2 or np.ptp(t) == 0:
        msg = f"expected at least two distinct times in a 1-D array, got shape {t.shape}"
        raise ValueError(msg)
    if not isinstance(states, State) or states.shape != t.shape:
        got = getattr(states, "shape", type(states).__name__)
        msg = f"expected an andoyer State of shape {t.shape} (one per time), got {got}"
        raise ValueError(msg)
    if axis not in AXES:
        msg = f"expected axis 'figure' or 'momentum', got {axis!r}"
        raise ValueError(msg)
    if axis == "figure":
        a = states.rotation.apply(np.array([0.0, 0.0, 1.0]))
    else:
        m = states.m_reference
        size = np.linalg.norm(m, axis=-1)
        if np.any(size == 0):
            msg = "expected nonzero angular momentum for axis='momentum', got m = 0"
            raise ValueError(msg)
        a = m / size[:, None]
    obliquity = np.arctan2(np.hypot(a[:, 0], a[:, 1]), a[:, 2])
    node = np.unwrap(np.arctan2(a[:, 0], -a[:, 1]))
    nu = as_finite(frequencies, "frequencies")
    at_p, rate_p, _, nu = fit_trend(t, node, nu)
    at_o, rate_o, _, _ = fit_trend(t, obliquity, nu)
    return PrecessionSeries(
        t,
        axis,
        a,
        node,
        obliquity,
        rate_p,
        at_p,
        rate_o,
        at_o,
        node - at_p - rate_p * t,
        obliquity - at_o - rate_o * t,
        nu,
    )


def precession(
    times: ArrayLike,
    states: State,
    axis: str = "figure",
    *,
    frequencies: ArrayLike = (),
    regression: bool = False,
    degrees: bool = False,
    time_unit: str | None = None,
    axes: tuple[Axes, Axes, Axes] | None = None,
) -> Figure:
    r"""Draw the precession ``Ω``, the obliquity ``ε`` (with their trends) and the nutations.

    Parameters
    ----------
    times, states, axis, frequencies
        As in :func:`precession_data`.
    regression : bool
        Label the trend with the precession rate ``p = −Ω̇`` of a regressing node (positive for
        the luni-solar precession; in arcseconds with ``degrees=True``) instead of ``Ω̇``.
    degrees : bool
        Show angles in degrees (default radians).
    time_unit : str, optional
        Name of the unit of ``times`` for the labels (e.g. ``"yr"``); default "unit time".
    axes : three matplotlib Axes, optional
        Where to draw the three panels; default a new figure with three rows.

    Returns
    -------
    matplotlib.figure.Figure
        With the :class:`PrecessionSeries` as ``figure.andoyer_data``.

    Examples
    --------
    >>> import numpy as np
    >>> from andoyer import FreeRotation, RigidBody, State
    >>> body, t = RigidBody(1.0, 1.0, 1.5), np.linspace(0.0, 10.0, 201)
    >>> s = State.from_andoyer(0.0, 0.0, 0.0, 0.9, 2.0, 2.0)
    >>> fig = precession(t, FreeRotation(body).propagate(s, t))
    >>> len(fig.axes)
    3
    >>> print(fig.axes[0].get_lines()[1].get_label())
    trend:
    $\dot\Omega = 2$ rad per unit time
    """
    data = precession_data(times, states, axis, frequencies)
    if axes is None:
        fig = Figure(layout="constrained", figsize=(7.5, 7.0))
        axes = tuple(fig.subplots(3, 1, sharex=True))
    else:
        if len(axes) != 3 or not all(isinstance(a, Axes) for a in axes):
            msg = f"expected three matplotlib Axes, got {axes!r}"
            raise ValueError(msg)
        fig = axes[0].figure
    k, unit = (1 / DEGREE, "deg") if degrees else (1.0, "rad")
    names = ("\\varphi", "\\theta") if axis == "figure" else ("h", "I")
    what = "figure axis $b_3$" if axis == "figure" else "angular momentum"
    t = data.t
    top, mid, low = axes
    top.plot(t, k * data.precession, color="tab:blue", label=f"$\\Omega = {names[0]}$")
    per = f"per {time_unit or 'unit time'}"
    if not regression:
        rate = f"$\\dot\\Omega = {k * data.precession_rate:.6g}$ {unit} {per}"
    elif degrees:  # precession rates are quoted in arcseconds
        rate = f"$p = -\\dot\\Omega$ = {-data.precession_rate / ARCSEC:.4g}″ {per}"
    else:
        rate = f"$p = -\\dot\\Omega$ = {-data.precession_rate:.6g} rad {per}"
    fitted = f", fitted with {data.frequencies.size} nutation terms" if data.frequencies.size else ""
    top.plot(
        t,
        k * (data.precession_at_zero + data.precession_rate * t),
        color="k",
        ls="--",
        lw=0.8,
        label=f"trend{fitted}:\n{rate}",
    )
    top.set_ylabel(f"precession $\\Omega$ ({unit})")
    top.set_title(f"Precession, obliquity and nutation of the {what}")
    mid.plot(t, k * data.obliquity, color="tab:green", label=f"$\\varepsilon = {names[1]}$")
    mid.plot(
        t, k * (data.obliquity_at_zero + data.obliquity_rate * t), color="k", ls="--", lw=0.8, label="trend"
    )
    mid.set_ylabel(f"obliquity $\\varepsilon$ ({unit})")
    low.plot(t, k * data.nutation_longitude, color="tab:blue", lw=0.9, label="$\\Delta\\Omega$ (longitude)")
    low.plot(
        t, k * data.nutation_obliquity, color="tab:green", lw=0.9, label="$\\Delta\\varepsilon$ (obliquity)"
    )
    low.set_ylabel(f"nutation ({unit})")
    low.set_xlabel(f"time $t$ ({time_unit or 'units of the input'})")
    for a in axes:
        a.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize="small", frameon=False)
    fig.andoyer_data = data  # type: ignore[attr-defined]
    return fig
