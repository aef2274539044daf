r"""Mean (secular) elements of the planets at J2000 from a short N-body run around J2000.

The secular model evolves *mean* elements: the osculating ones with their short-period terms
(the orbital periods, the 900-yr great inequality of Jupiter and Saturn) averaged out. They
are measured here from the N-body solution itself (:mod:`andoyer.planetary.orbits.nbody`'s
simulation: DE421's states at J2000, REBOUND's WHFast, GR where REBOUNDx is installed),
integrated over ``±window`` years and sampled every ``sample`` years:

* the frame: the *invariable plane* (normal to the total angular momentum ``Σ r_j × p_j``,
  Sun included, at J2000), with ``x`` along its ascending node on the J2000 ecliptic; the
  secular model works in it (the inclinations are smallest there and ``s_5 = 0`` has no
  amplitude) and :func:`invariable_rotation` turns it back into the J2000 ecliptic;
* each planet's osculating Poincaré variables (heliocentric positions, barycentric momenta
  ``p_j``, the Kepler orbit of ``(r_j, p_j/β_j)`` about ``μ_j``; see
  :mod:`andoyer.planetary.orbits.disturbing`): ``Λ_j``, ``x_j``, ``y_j`` and the mean
  longitude ``λ_j``;
* their values at ``t = 0`` by a local polynomial regression (degree 4, weights
  ``(1 − (t/W)²)²``): the secular motion (periods ≥ 46 kyr) is followed by the polynomial and
  the short-period terms (periods ≤ 0.9 kyr, more than ten of them in the window) are
  averaged out; the mean motions are the slopes of the unwrapped ``λ_j(t)``; ``Λ_j`` is the
  weighted mean (its secular part is constant).

Examples
--------
>>> M = invariable_rotation(np.array([0.0, 0.0, 1.0]))
>>> M.round(12).tolist()
[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from andoyer.catalogue.units import DAY, JULIAN_YEAR
from andoyer.planetary.orbits.planets import planet_data

__all__ = ["MeanElements", "invariable_rotation", "mean_elements", "poincare_elements"]

Array = NDArray[np.float64]


def invariable_rotation(momentum: Array) -> Array:
    """The rotation from the J2000 ecliptic frame to the frame of the plane normal to ``momentum``.

    Rows: the ascending node ``x' = ẑ × n/|ẑ × n|`` of the plane on the ecliptic, ``y' = n × x'``
    and ``n``; ``v_inv = M v_ecl``, ``v_ecl = Mᵀ v_inv``.

    Parameters
    ----------
    momentum : numpy.ndarray, shape (3,)
        The plane's normal (any length).

    Returns
    -------
    numpy.ndarray, shape (3, 3)
    """
    n = np.asarray(momentum, dtype=float) / np.linalg.norm(momentum)
    node = np.array([-n[1], n[0], 0.0])
    size = np.linalg.norm(node)
    node = np.array([1.0, 0.0, 0.0]) if size < 1e-300 else node / size
    return np.stack([node, np.cross(n, node), n])


def poincare_elements(
    sun: float, gm: Array, r: Array, p: Array
) -> tuple[Array, NDArray[np.complex128], NDArray[np.complex128], Array]:
    """``Λ, x, y, λ`` of each planet from heliocentric positions and barycentric momenta.

    Parameters
    ----------
    sun : float
        ``m_0`` (GM).
    gm : numpy.ndarray, shape (P,)
        ``m_j`` (GM).
    r, p : numpy.ndarray, shape (..., P, 3)
        Heliocentric positions (au) and barycentric momenta ``m_j v_j`` (GM·au/yr).

    Returns
    -------
    Lambda, lam : numpy.ndarray, shape (..., P)
    x, y : numpy.ndarray of complex, shape (..., P)

    Examples
    --------
    A circular orbit of radius 1 about ``m_0 = 1``, ``m_j = 10⁻³``: the relative speed is
    ``√(m_0 + m_j)``, the planet's barycentric speed ``m_0/(m_0 + m_j)`` of it, so
    ``p_j = m_j √(m_0 + m_j) m_0/(m_0 + m_j) = β_j √μ_j``:

    >>> L, x, y, lam = poincare_elements(1.0, np.array([1e-3]), np.array([[1.0, 0.0, 0.0]]),
    ...                                  np.array([[0.0, 1e-3 / np.sqrt(1.001), 0.0]]))
    >>> abs(complex(x[0])) < 1e-12, abs(complex(y[0])) < 1e-12
    (True, True)
    >>> round(float(L[0] / (1e-3 / 1.001 * np.sqrt(1.001))), 12)     # Λ = β √(μ a), a = 1
    1.0
    """
    beta = sun * gm / (sun + gm)
    mu = sun + gm
    v = p / beta[:, None]
    rn = np.linalg.norm(r, axis=-1)
    h = np.cross(r, v)
    hn = np.linalg.norm(h, axis=-1)
    ecc = np.cross(v, h) / mu[:, None] - r / rn[..., None]
    a = 1.0 / (2.0 / rn - np.sum(v * v, axis=-1) / mu)
    e = np.linalg.norm(ecc, axis=-1)
    cos_i = h[..., 2] / hn
    node = np.arctan2(h[..., 0], -h[..., 1])
    # ϖ = Ω + ω, with ω measured in the orbit plane from the node.
    n_hat = np.stack([np.cos(node), np.sin(node), np.zeros_like(node)], axis=-1)
    w_hat = h / hn[..., None]
    m_hat = np.cross(w_hat, n_hat)
    omega = np.arctan2(np.sum(ecc * m_hat, axis=-1), np.sum(ecc * n_hat, axis=-1))
    varpi = node + omega
    true_lon = node + np.arctan2(np.sum(r * m_hat, axis=-1), np.sum(r * n_hat, axis=-1))
    f = true_lon - varpi
    E = 2.0 * np.arctan2(np.sqrt(1.0 - e) * np.sin(f / 2.0), np.sqrt(1.0 + e) * np.cos(f / 2.0))
    lam = varpi + E - e * np.sin(E)
    Lambda = beta * np.sqrt(mu * a)
    root = np.sqrt(1.0 - e * e)
    x = np.sqrt(2.0 * Lambda * (1.0 - root)) * np.exp(1j * varpi)
    y = np.sqrt(2.0 * Lambda * root * (1.0 - cos_i)) * np.exp(1j * node)
    return Lambda, x, y, lam


@dataclass(frozen=True)
class MeanElements:
    """Mean Poincaré variables of the eight planets at J2000, in the invariable frame.

    Attributes
    ----------
    sun : float
        ``m_0`` (GM, au³/yr²).
    gm : numpy.ndarray, shape (8,)
    Lambda : numpy.ndarray, shape (8,)
        Mean ``Λ_j``.
    a : numpy.ndarray, shape (8,)
        ``(Λ_j/β_j)²/μ_j``, au.
    n : numpy.ndarray, shape (8,)
        Mean motions ``λ̇_j`` measured (rad/yr).
    x, y : numpy.ndarray of complex, shape (8,)
        Mean Poincaré variables at J2000.
    rotation : numpy.ndarray, shape (3, 3)
        J2000 ecliptic → invariable frame (:func:`invariable_rotation`).
    """

    sun: float
    gm: Array
    Lambda: Array
    a: Array
    n: Array
    x: NDArray[np.complex128]
    y: NDArray[np.complex128]
    rotation: Array


def _local_fit(t: Array, values: NDArray, window: float, degree: int = 4) -> tuple[NDArray, NDArray]:
    """Value and slope at ``t = 0`` of the weighted polynomial fit to ``values`` (axis 0 = time)."""
    s = t / window
    w = np.clip(1.0 - s * s, 0.0, None) ** 2
    V = np.vander(s, degree + 1, increasing=True) * np.sqrt(w)[:, None]
    rhs = values.reshape(len(t), -1) * np.sqrt(w)[:, None]
    coef, *_ = np.linalg.lstsq(V, rhs, rcond=None)
    shape = values.shape[1:]
    return coef[0].reshape(shape), (coef[1] / window).reshape(shape)


def mean_elements(window: float = 5000.0, sample: float = 0.0625, gr: bool | None = None) -> MeanElements:
    """Measure the mean elements at J2000 from an N-body run over ``±window`` years.

    Parameters
    ----------
    window : float
        Half-width of the fit, years.
    sample : float
        Sampling interval, years (well below Mercury's period: no short-period term aliases
        near zero frequency).
    gr : bool or None
        General relativity in the run (default: where REBOUNDx is installed).

    Returns
    -------
    MeanElements
    """
    from andoyer.planetary.orbits.nbody import _has_reboundx, make_simulation

    data = planet_data()
    if gr is None:
        gr = _has_reboundx()
    steps = max(1, round(sample * (JULIAN_YEAR / DAY) / 4.0))
    count = round(window / sample)
    states = []
    for sign in (1.0, -1.0):
        sim, extras = make_simulation(sign * sample / steps, gr)
        buf = np.empty((9, 6))
        chunk = np.empty((count + 1, 9, 6))
        for k in range(count + 1):
            if k:
                sim.integrate(sign * k * sample - 0.5 * sim.dt, exact_finish_time=0)
            sim.serialize_particle_data(xyzvxvyvz=buf)
            chunk[k] = buf
        del extras
        states.append(chunk if sign > 0 else chunk[:0:-1])
    state = np.concatenate([states[1], states[0]])
    t = sample * np.arange(-count, count + 1)
    masses = np.concatenate([[data.sun_gm], data.gm])
    r = state[:, 1:, :3] - state[:, :1, :3]
    p = data.gm[None, :, None] * state[:, 1:, 3:]
    momentum = np.sum(masses[None, :, None] * np.cross(state[:, :, :3], state[:, :, 3:]), axis=1)[count]
    M = invariable_rotation(momentum)
    r, p = r @ M.T, p @ M.T
    Lambda, x, y, lam = poincare_elements(data.sun_gm, data.gm, r, p)
    lam = np.unwrap(lam, axis=0)
    fit, slope = _local_fit(t, np.concatenate([Lambda, x.real, x.imag, y.real, y.imag, lam], axis=1), window)
    L0 = fit[:8]
    beta = data.sun_gm * data.gm / (data.sun_gm + data.gm)
    a = (L0 / beta) ** 2 / (data.sun_gm + data.gm)
    return MeanElements(
        sun=float(data.sun_gm),
        gm=data.gm.copy(),
        Lambda=L0,
        a=a,
        n=slope[40:48],
        x=fit[8:16] + 1j * fit[16:24],
        y=fit[24:32] + 1j * fit[32:40],
        rotation=M,
    )
