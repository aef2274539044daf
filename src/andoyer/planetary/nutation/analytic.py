"""The analytic nutation: second-order averaging of Kinoshita's Hamiltonian on the Delaunay torus.

The right-hand sides ``f = (ψ̇, ε̇)`` of :mod:`andoyer.planetary.nutation.model` are
Fourier-analysed by FFT on a grid of ``θ = (l, l′, F, D, Ω)``; a term
``c e^{in·θ}`` integrates to ``c e^{in·θ}/(i n·θ̇)``. The second order repeats
this for ``g = (∂f/∂ε) Δε₁ + (∂f/∂ψ) Δψ₁`` (``∂/∂ψ = ∂/∂Ω`` at fixed
``l, l′, F, D``), and the Oppolzer terms map the momentum axis to the others.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer.perturbations.lunar_theory import delaunay_arguments, delaunay_rates
from andoyer.planetary.nutation.model import (
    ARCSEC,
    H_MHB2000,
    MEAN_OBLIQUITY,
    _axis,
    _axis_coefficients,
    _forcing,
)
from andoyer.planetary.precession import check_dynamical_ellipticity

__all__ = ["NutationSeries", "luni_solar_precession", "nutation_series"]

Array = NDArray[np.float64]

# Torus grid of the Fourier analysis: harmonics of (l, l′, F, D, Ω) up to half these sizes
# (the forcing has Ω-harmonics |k| <= 2 and l′-harmonics of order e☉^k; the rest decay fast).
_GRID = (12, 6, 12, 16, 6)
# Terms kept in the analytic series: |amplitude| above this, arcsec.
_THRESHOLD = 2e-5
#: Times summed at once by a :class:`NutationSeries` (each holds a phase per term: 8 MB a block
#: of a thousand terms).
BLOCK_TIMES = 1024


def _spectrum(t: float, H: float, eps: float) -> tuple[float, Array, Array, Array]:
    """Fourier analysis of the forcing to second order: ``⟨ψ̇⟩`` and ``c_n`` of ``ψ̇`` and ``ε̇``.

    Per multiplier ``n`` the complex coefficients; their first-order parts are
    proportional to ``H``, the second-order parts to ``H²``.
    """
    first, second = _unit_spectrum(float(t), float(eps))
    constant, index, cpsi, ceps = (H * v for v in first[:1]), first[1], H * first[2], H * first[3]
    (constant,) = constant
    constant = constant + H * H * second[0]
    return constant, index, cpsi + H * H * second[1], ceps + H * H * second[2]


@functools.lru_cache(maxsize=8)
def _unit_spectrum(t: float, eps: float) -> tuple[tuple, tuple]:
    """For H = 1: ``(⟨ψ̇⟩, index, c_ψ, c_ε)`` of the first-order forcing, ``(⟨g_ψ⟩, g_ψ, g_ε)`` of the second.

    The second-order forcing is ``g = (∂f/∂ε) Δε₁ + (∂f/∂ψ) Δψ₁`` with ``Δ₁`` the
    first-order solution on the torus; ``∂/∂ψ`` shifts every longitude, i.e.
    ``∂/∂Ω`` at fixed ``l, l′, F, D``. It holds the coupling of the precession
    rate to the obliquity (``(∂p/∂ε) Δε``, 3 mas on the 18.6-year term) and the
    crossed nutations (1 mas on 2Ω).
    """
    axes = [2 * np.pi * np.arange(n) / n for n in _GRID]
    grid = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1)
    index = np.stack(np.meshgrid(*[np.fft.fftfreq(n, 1 / n).astype(int) for n in _GRID], indexing="ij"), -1)
    rate = index @ delaunay_rates(t)
    integrate = np.zeros(rate.shape, dtype=complex)
    integrate[rate != 0] = 1 / (1j * rate[rate != 0])  # the constant term is not integrated
    size = grid[..., 0].size
    # np.fft uses exp(-i k x): the coefficient of exp(+i n·θ) sits at index n (mod N).
    fpsi, feps = _forcing(t, grid, 1.0, eps)
    cpsi, ceps = np.fft.fftn(fpsi) / size, np.fft.fftn(feps) / size
    dpsi1 = np.fft.ifftn(cpsi * integrate).real * size
    deps1 = np.fft.ifftn(ceps * integrate).real * size
    step = 1e-6
    plus, minus = _forcing(t, grid, 1.0, eps + step), _forcing(t, grid, 1.0, eps - step)
    n_node = index[..., 4]
    gpsi = (plus[0] - minus[0]) / (2 * step) * deps1 + np.fft.ifftn(1j * n_node * cpsi).real * size * dpsi1
    geps = (plus[1] - minus[1]) / (2 * step) * deps1 + np.fft.ifftn(1j * n_node * ceps).real * size * dpsi1
    gpsi_c, geps_c = np.fft.fftn(gpsi) / size, np.fft.fftn(geps) / size
    first = (float(cpsi.flat[0].real), index.reshape(-1, 5), cpsi.reshape(-1), ceps.reshape(-1))
    second = (float(gpsi_c.flat[0].real), gpsi_c.reshape(-1), geps_c.reshape(-1))
    return first, second


@dataclass(frozen=True)
class NutationSeries:
    """A nutation series ``Δψ = Σ ψs sin θ + ψc cos θ``, ``Δε = Σ εc cos θ + εs sin θ`` (arcsec).

    Attributes
    ----------
    multipliers : numpy.ndarray, shape (K, 5)
        Of ``(l, l′, F, D, Ω)``.
    psi_sin, psi_cos, eps_cos, eps_sin : numpy.ndarray, shape (K,)
    precession : float
        Luni-solar precession in longitude (to second order), arcsec per Julian year.
    dynamical_ellipticity, obliquity : float
    axis : str
    """

    multipliers: Array
    psi_sin: Array
    psi_cos: Array
    eps_cos: Array
    eps_sin: Array
    precession: float
    dynamical_ellipticity: float
    obliquity: float
    axis: str

    def __call__(self, t: ArrayLike) -> tuple[Array, Array]:
        """``Δψ, Δε`` (arcsec) at ``t`` (Julian years TT from J2000), each of shape ``t.shape``.

        Summed :data:`BLOCK_TIMES` times at a time: each time takes every term's phase.
        """
        times = np.asarray(t, dtype=float)
        flat = times.reshape(-1)
        dpsi, deps = np.empty(flat.size), np.empty(flat.size)
        for first in range(0, flat.size, BLOCK_TIMES):
            part = slice(first, first + BLOCK_TIMES)
            theta = delaunay_arguments(flat[part]) @ self.multipliers.T
            s, c = np.sin(theta), np.cos(theta)
            dpsi[part] = s @ self.psi_sin + c @ self.psi_cos
            deps[part] = c @ self.eps_cos + s @ self.eps_sin
        return dpsi.reshape(times.shape)[()], deps.reshape(times.shape)[()]

    def term(self, multipliers: tuple[int, ...]) -> tuple[float, float, float, float]:
        """``(ψs, ψc, εc, εs)`` of one argument (zeros when absent)."""
        hit = np.flatnonzero(np.all(self.multipliers == np.asarray(multipliers), axis=1))
        if hit.size == 0:
            return 0.0, 0.0, 0.0, 0.0
        k = hit[0]
        parts = (self.psi_sin, self.psi_cos, self.eps_cos, self.eps_sin)
        return tuple(float(part[k]) for part in parts)  # type: ignore[return-value]


def _oppolzer(psi_s, psi_c, eps_c, eps_s, rate, axis, H, eps):  # type: ignore[no-untyped-def]
    """Map momentum-axis amplitudes to ``axis`` (``rate`` = ``θ̇`` in rad/yr).

    In the tangent plane ``(x, y) = (Δψ sin ε, Δε)``, ``m × ṁ = (−ẏ, ẋ)`` and
    ``m̈⊥ = (ẍ, ÿ) = −θ̇² (x, y)`` for one term.
    """
    c, d = _axis_coefficients(axis, H)
    se = np.sin(eps)
    grow = 1 - d * rate**2
    x_s, x_c = grow * se * psi_s + c * rate * eps_c, grow * se * psi_c - c * rate * eps_s
    y_c, y_s = grow * eps_c + c * se * rate * psi_s, grow * eps_s - c * se * rate * psi_c
    return x_s / se, x_c / se, y_c, y_s


def nutation_series(
    dynamical_ellipticity: float = H_MHB2000,
    axis: str = "figure",
    epoch: float = 0.0,
    obliquity: float = MEAN_OBLIQUITY,
) -> NutationSeries:
    """The analytic nutation series to second order (see the module docstring), terms above 0.02 mas.

    Parameters
    ----------
    dynamical_ellipticity : float
        ``H = (C − (A+B)/2)/C``.
    axis : {"figure", "momentum", "rotation"}
    epoch : float
        Julian years from J2000 at which the slow factors (eccentricities,
        rates) of the lunar and solar theories are taken.
    obliquity : float
        Mean obliquity, radians.

    Returns
    -------
    NutationSeries

    Examples
    --------
    >>> series = nutation_series()
    >>> [round(v, 4) for v in series.term((0, 0, 0, 0, 1))[::2]]  # 18.6 yr: Δψ sin, Δε cos (arcsec)
    [-17.2805, 9.228]
    """
    H = check_dynamical_ellipticity(dynamical_ellipticity)
    key = _axis(axis)
    eps = float(obliquity)
    rates = delaunay_rates(epoch)
    constant, index, cpsi, ceps = _spectrum(float(epoch), H, eps)
    # Keep one of each ±n pair: the first non-zero multiplier positive.
    first = index[np.arange(index.shape[0]), np.argmax(index != 0, axis=1)]
    keep = first > 0
    n, cpsi, ceps = index[keep], cpsi[keep], ceps[keep]
    rate = n @ rates
    # f = 2 Re c cos θ − 2 Im c sin θ, integrated term by term.
    psi_s, psi_c = 2 * cpsi.real / rate, 2 * cpsi.imag / rate
    eps_s, eps_c = 2 * ceps.real / rate, 2 * ceps.imag / rate
    psi_s, psi_c, eps_c, eps_s = _oppolzer(psi_s, psi_c, eps_c, eps_s, rate, key, H, eps)
    amplitudes = np.stack([psi_s, psi_c, eps_c, eps_s]) / ARCSEC
    big = np.max(np.abs(amplitudes), axis=0) > _THRESHOLD
    order = np.argsort(-np.abs(amplitudes[0] * big))[: int(np.sum(big))]
    return NutationSeries(
        n[order].astype(float),
        *amplitudes[:, order],
        precession=constant / ARCSEC,
        dynamical_ellipticity=H,
        obliquity=eps,
        axis=key,
    )


def luni_solar_precession(
    dynamical_ellipticity: float = H_MHB2000, obliquity: float = MEAN_OBLIQUITY
) -> float:
    """First-order luni-solar precession in longitude, ``⟨ψ̇⟩``, arcsec per Julian year.

    Examples
    --------
    >>> round(luni_solar_precession(), 3)
    50.404
    """
    H = check_dynamical_ellipticity(dynamical_ellipticity)
    return _unit_spectrum(0.0, float(obliquity))[0][0] * H / ARCSEC
