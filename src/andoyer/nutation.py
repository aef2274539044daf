r"""Rigid-Earth luni-solar nutation of the figure, angular-momentum and rotation axes.

**Model.** The Moon and the Sun (:mod:`andoyer.perturbations.lunar_theory`,
mean ecliptic and equinox of date) act on the Earth's oblateness through the
MacCullagh torque of :class:`~andoyer.perturbations.GravityGradient`,
``τ = Σ 3μ/r⁵ (r·k)(r × I r)``, averaged over the daily rotation (exact for
the axisymmetric part; the ``(B − A)`` part only drives diurnal terms, which
rigid-Earth tables list apart). For a fast rotator, ``L = Cω m`` to the order
kept, and with ``H = (C − (A+B)/2)/C`` the dynamical ellipticity the unit
angular momentum ``m`` obeys

.. math::
   \dot{\mathbf m} = \frac{3H}{\omega}\,(\mathsf S\,\mathbf m)\times\mathbf m
   + p\,\hat{\mathbf z}\times\mathbf m, \qquad
   \mathsf S = \sum_{\rm Sun, Moon} \frac{\mu\,\mathbf r\mathbf r^{\mathsf T}}{r^5},

in the frame of the mean ecliptic and mean equinox of date, which turns at
the model's own mean precession rate ``p`` about the ecliptic pole ``ẑ``.
With ``m = (sin ε sin h, −sin ε cos h, cos ε)`` (Andoyer's node ``h``, the
equinox at ``h + π``), the nutation in longitude is ``Δψ = −δh`` and in
obliquity ``Δε = δε`` (IERS sign conventions: ``Δψ`` adds to longitudes).

**Analytic solution (second-order averaging of Kinoshita's 1977 Hamiltonian).**
With ``V = (3/2)(C − Ā)Σ μ/r³ (u·m)²`` and the canonical pair ``(h, G cos ε)``,

.. math::
   \dot\psi = \frac{1}{G\sin\varepsilon}\frac{\partial V}{\partial\varepsilon}
   = \frac{3H}{2\omega\sin\varepsilon}\big[(P - R)\sin 2\varepsilon + Q\cos 2\varepsilon\big],\qquad
   \dot\varepsilon = -\frac{1}{G\sin\varepsilon}\frac{\partial V}{\partial\psi}
   = -\frac{3H}{2\omega\sin\varepsilon}\big[P_\lambda\sin^2\varepsilon
     + Q_\lambda\sin\varepsilon\cos\varepsilon\big],

with ``P = Σ μ/r³ cos²β sin²λ``, ``Q = 2Σ μ/r³ sinβ cosβ sinλ``,
``R = Σ μ/r³ sin²β`` and their longitude derivatives ``P_λ, Q_λ`` (``λ, β``
ecliptic coordinates of date; a shift of the equinox moves every longitude,
i.e. shifts ``Ω`` at fixed ``l, l′, F, D``). These right-hand sides are
functions on the torus of the Delaunay arguments ``θ = (l, l′, F, D, Ω)``;
:func:`nutation_series` takes their Fourier coefficients by a five-dimensional
FFT of the lunar theory on a grid, and each term ``c e^{in·θ}`` integrates to
``c e^{in·θ}/(i n·θ̇)``. The second order repeats this for
``g = (∂f/∂ε) Δε₁ + (∂f/∂ψ) Δψ₁`` with ``Δ₁`` the first-order solution: the
dependence of the precession rate on the obliquity (2.9 mas on the 18.6-year
``Δψ``) and the crossed nutations (1.2 mas on ``2Ω``). The constant term of
``ψ̇`` is the luni-solar precession (:func:`luni_solar_precession`: first order).

**Numeric solution.** :func:`nutation` with ``method="numeric"`` integrates
the vector equation above (RK4 on a quarter-day grid of precomputed ``S``) over
at least 18.63 years, from the forced state at the start (the series only sets
the free constants: where the mean pole lies), then removes the mean pole (a
constant and a linear drift fitted together with the periodic terms). Terms
slower than the span cannot be told from the mean pole.

**Axes (Oppolzer terms).** With ``ω⊥ = k × k̇`` the rotation vector's
equatorial part, ``L = Cω₃ k + Ā ω⊥`` and ``ω = ω₃ k + ω⊥``; with
``a = (1−H)/ω`` and iterating once,

.. math::
   \mathbf k = \mathbf m - a\,\mathbf m\times\dot{\mathbf m} - a^2\,\ddot{\mathbf m}_\perp, \qquad
   \hat{\boldsymbol\omega} = \mathbf m + \frac{H}{\omega}\,\mathbf m\times\dot{\mathbf m}

(inertial ``ṁ``; the ``a²`` term is ``(σ/ω)²`` of a term of frequency ``σ``,
0.5 mas at 13.66 days; the rotation axis's is ``H`` times smaller and left
out). A term ``Δψ = A sin θ``, ``Δε = B cos θ`` of the momentum axis becomes
``A(1 + a²θ̇²) − aB θ̇/sin ε`` and ``B(1 + a²θ̇²) − aA sin ε θ̇`` for the figure
axis (about 7 mas at 13.66 days); the rotation axis differs from the momentum
axis by ``H`` times less. The
constant part of ``m × ṁ`` (the precession, 8.7 mas in obliquity) belongs to
the mean pole, not to the nutation.

Constants: ``ω = 7.292115·10⁻⁵ rad/s`` (IERS Conventions 2010, Table 1.2);
``ε₀ = 84381.406″`` (IAU 2006); default ``H = 0.0032737949`` (Mathews,
Herring & Buffett 2002, MHB2000, the IERS Conventions 2010 value);
``GM_Sun``, ``GM_Moon`` of :mod:`andoyer.perturbations.solar_system`.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer.perturbations.lunar_theory import (
    delaunay_arguments,
    delaunay_rates,
    ecliptic_vector,
    moon_ecliptic,
    sun_ecliptic,
)
from andoyer.perturbations.solar_system import DAY, GM_MOON, GM_SUN, JULIAN_YEAR
from andoyer.precession import check_dynamical_ellipticity

__all__ = [
    "AXES",
    "EARTH_ROTATION",
    "H_MHB2000",
    "IAU2000A",
    "MEAN_OBLIQUITY",
    "PRINCIPAL_TERMS",
    "REN2000_NODE",
    "WOOLARD1953",
    "NutationSeries",
    "fit_terms",
    "luni_solar_precession",
    "minimum_span",
    "numeric_terms",
    "nutation",
    "nutation_series",
    "terms_table",
]

Array = NDArray[np.float64]

ARCSEC = np.pi / 648000.0
#: Earth's nominal mean angular velocity, rad/s (IERS Conventions 2010, Table 1.2).
EARTH_ROTATION = 7.292115e-5
#: Dynamical ellipticity ``(C − (A+B)/2)/C`` of MHB2000 (Mathews et al. 2002; IERS Conventions 2010,
#: Table 1.1).
H_MHB2000 = 0.0032737949
#: Mean obliquity of the ecliptic at J2000.0, IAU 2006: 84381.406″.
MEAN_OBLIQUITY = 84381.406 * ARCSEC
#: The axes whose nutation is offered.
AXES = ("figure", "momentum", "rotation")
#: The principal terms: name -> multipliers of ``(l, l′, F, D, Ω)``.
PRINCIPAL_TERMS = {
    "Ω": (0, 0, 0, 0, 1),
    "2Ω": (0, 0, 0, 0, 2),
    "2(F−D+Ω)": (0, 0, 2, -2, 2),
    "2(F+Ω)": (0, 0, 2, 0, 2),
    "l′": (0, 1, 0, 0, 0),
    "l": (1, 0, 0, 0, 0),
}

# Torus grid of the Fourier analysis: harmonics of (l, l′, F, D, Ω) up to half these sizes
# (the forcing has Ω-harmonics |k| <= 2 and l′-harmonics of order e☉^k; the rest decay fast).
_GRID = (12, 6, 12, 16, 6)
# Terms kept in the analytic series and the fits: |amplitude| above this, arcsec.
_THRESHOLD = 2e-5
_STEP_DAYS = 0.25
# Regressors of the fits: the series' terms above this, arcsec (smaller ones barely leak into the rest).
_FIT_THRESHOLD = 1e-4


def _axis(axis: str) -> str:
    key = str(axis).strip().lower()
    if key not in AXES:
        msg = f"expected axis one of {', '.join(AXES)}, got {axis!r}"
        raise ValueError(msg)
    return key


def _forcing(t: float, args: Array, H: float, eps: float) -> tuple[Array, Array]:
    """``ψ̇, ε̇`` (rad per Julian year) of the first-order equations at Delaunay arguments ``args``."""
    P = Q = R = Pl = Ql = 0.0
    bodies = ((GM_MOON, moon_ecliptic(t, args, planetary=False)), (GM_SUN, sun_ecliptic(t, args)))
    for gm, (lon, lat, r) in bodies:
        w = gm / r**3
        cb, sb = np.cos(lat), np.sin(lat)
        sl, cl = np.sin(lon), np.cos(lon)
        P = P + w * cb * cb * sl * sl
        Q = Q + 2 * w * sb * cb * sl
        R = R + w * sb * sb
        Pl = Pl + w * cb * cb * 2 * sl * cl
        Ql = Ql + 2 * w * sb * cb * cl
    scale = 3 * H / (2 * EARTH_ROTATION * np.sin(eps)) * JULIAN_YEAR
    dpsi = scale * ((P - R) * np.sin(2 * eps) + Q * np.cos(2 * eps))
    deps = -scale * (Pl * np.sin(eps) ** 2 + Ql * np.sin(eps) * np.cos(eps))
    return dpsi, deps


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
        """``Δψ, Δε`` (arcsec) at ``t`` (Julian years TT from J2000), each of shape ``t.shape``."""
        theta = delaunay_arguments(t) @ self.multipliers.T
        s, c = np.sin(theta), np.cos(theta)
        return s @ self.psi_sin + c @ self.psi_cos, c @ self.eps_cos + s @ self.eps_sin

    def term(self, multipliers: tuple[int, ...]) -> tuple[float, float, float, float]:
        """``(ψs, ψc, εc, εs)`` of one argument (zeros when absent)."""
        hit = np.flatnonzero(np.all(self.multipliers == np.asarray(multipliers), axis=1))
        if hit.size == 0:
            return 0.0, 0.0, 0.0, 0.0
        k = hit[0]
        parts = (self.psi_sin, self.psi_cos, self.eps_cos, self.eps_sin)
        return tuple(float(part[k]) for part in parts)  # type: ignore[return-value]


def _axis_coefficients(axis: str, H: float) -> tuple[float, float]:
    """``(c, d)`` of ``axis = m + c m × ṁ + d m̈⊥`` (time in Julian years; see the module docstring)."""
    a = (1 - H) / (EARTH_ROTATION * JULIAN_YEAR)
    return {"momentum": (0.0, 0.0), "figure": (-a, -a * a), "rotation": (H / (1 - H) * a, 0.0)}[axis]


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


def minimum_span(multipliers: ArrayLike | None = None, epoch: float = 0.0) -> float:
    """The shortest span (Julian years) over which the terms ``multipliers`` (K, 5) can be fitted.

    The rule: the span must cover one period of the slowest term (18.613 years
    with ``Ω`` among the terms), which also separates every pair of the
    principal terms.

    Examples
    --------
    >>> round(minimum_span(), 3)
    18.613
    """
    if multipliers is None:
        multipliers = list(PRINCIPAL_TERMS.values())
    rates = np.abs(np.asarray(multipliers, dtype=float) @ delaunay_rates(epoch))
    return float(2 * np.pi / np.min(rates))


def fit_terms(t: ArrayLike, dpsi: ArrayLike, deps: ArrayLike, multipliers: ArrayLike) -> Array:
    """Least-squares amplitudes ``(ψs, ψc, εc, εs)`` (K, 4) of the terms ``multipliers`` (K, 5).

    Fits ``Δψ = a + b t + Σ ψs sin θ + ψc cos θ`` and likewise ``Δε`` (with
    ``θ = n·(l, l′, F, D, Ω)(t)``), the constant and the trend absorbing the
    mean pole.

    Parameters
    ----------
    t : array_like, shape (T,)
        Julian years from J2000, spanning at least :func:`minimum_span`.
    dpsi, deps : array_like, shape (T,)
    multipliers : array_like, shape (K, 5)

    Returns
    -------
    numpy.ndarray, shape (K, 4)

    Examples
    --------
    >>> t = np.linspace(0.0, 20.0, 2001)
    >>> theta = delaunay_arguments(t)[:, 4]
    >>> fit_terms(t, 1 + 2 * np.sin(theta), 3 * np.cos(theta), [(0, 0, 0, 0, 1)]).round(12).tolist()
    [[2.0, 0.0, 3.0, 0.0]]
    """
    t = np.asarray(t, dtype=float)
    n = np.atleast_2d(np.asarray(multipliers, dtype=float))
    values = np.stack([np.asarray(dpsi, dtype=float), np.asarray(deps, dtype=float)], axis=-1)
    if t.ndim != 1 or values.shape != (t.size, 2) or n.shape[-1] != 5:
        msg = (
            "expected t (T,), dpsi and deps (T,) and multipliers (K, 5), "
            f"got {t.shape}, {values.shape}, {n.shape}"
        )
        raise ValueError(msg)
    span = float(t.max() - t.min()) if t.size else 0.0
    need = minimum_span(n, float(np.mean(t)) if t.size else 0.0)
    if span < need * (1 - 1e-9):
        msg = f"expected a span of at least {need:.3f} years to fit these terms, got {span:.3f}"
        raise ValueError(msg)
    theta = delaunay_arguments(t) @ n.T
    design = np.concatenate([np.ones((t.size, 1)), (t - t.mean())[:, None], np.sin(theta), np.cos(theta)], 1)
    coefficients = np.linalg.lstsq(design, values, rcond=None)[0]
    K = n.shape[0]
    sin_part, cos_part = coefficients[2 : 2 + K], coefficients[2 + K :]
    return np.stack([sin_part[:, 0], cos_part[:, 0], cos_part[:, 1], sin_part[:, 1]], axis=-1)


def _pole(psi: float, eps: float) -> Array:
    h = -np.pi - psi
    return np.array([np.sin(eps) * np.sin(h), -np.sin(eps) * np.cos(h), np.cos(eps)])


def _angles(vectors: Array) -> tuple[Array, Array]:
    """``(ψ, ε)`` of unit vectors (..., 3), ``ψ = −(h + π)`` wrapped to ``(−π, π]``."""
    h = np.arctan2(vectors[..., 0], -vectors[..., 1])
    psi = -np.angle(np.exp(1j * (h + np.pi)))
    eps = np.arctan2(np.hypot(vectors[..., 0], vectors[..., 1]), vectors[..., 2])
    return psi, eps


def _gradient_matrices(t: Array, H: float) -> Array:
    """``(3H/ω) S`` (rad per Julian year), shape (T, 3, 3), in the frame of date."""
    out = np.empty((t.size, 3, 3))
    block = 20000  # the lunar series makes (block, 60) arrays: keep them small
    for start in range(0, t.size, block):
        times = t[start : start + block]
        total = 0.0
        places = ((GM_MOON, moon_ecliptic(times, planetary=False)), (GM_SUN, sun_ecliptic(times)))
        for gm, (lon, lat, r) in places:
            u = ecliptic_vector(lon, lat, np.ones_like(r))
            total = total + (gm / r**3)[:, None, None] * u[:, :, None] * u[:, None, :]
        out[start : start + block] = total
    return 3 * H / EARTH_ROTATION * JULIAN_YEAR * out


def _rk4(S: Array, m0: Array, h: float, p: float) -> Array:
    """RK4 for ``ṁ = (S m) × m + p ẑ × m`` with ``S`` given at half steps (2N+1, 3, 3); returns (N+1, 3)."""
    steps = (S.shape[0] - 1) // 2
    out = np.empty((steps + 1, 3))
    s = S.reshape(S.shape[0], 9).tolist()
    x, y, z = (float(v) for v in m0)
    out[0] = x, y, z

    def rate(k: list[float], x: float, y: float, z: float) -> tuple[float, float, float]:
        a = k[0] * x + k[1] * y + k[2] * z
        b = k[3] * x + k[4] * y + k[5] * z
        c = k[6] * x + k[7] * y + k[8] * z
        return b * z - c * y - p * y, c * x - a * z + p * x, a * y - b * x

    for i in range(steps):
        k0, k1, k2 = s[2 * i], s[2 * i + 1], s[2 * i + 2]
        a1 = rate(k0, x, y, z)
        a2 = rate(k1, x + 0.5 * h * a1[0], y + 0.5 * h * a1[1], z + 0.5 * h * a1[2])
        a3 = rate(k1, x + 0.5 * h * a2[0], y + 0.5 * h * a2[1], z + 0.5 * h * a2[2])
        a4 = rate(k2, x + h * a3[0], y + h * a3[1], z + h * a3[2])
        x += h / 6 * (a1[0] + 2 * a2[0] + 2 * a3[0] + a4[0])
        y += h / 6 * (a1[1] + 2 * a2[1] + 2 * a3[1] + a4[1])
        z += h / 6 * (a1[2] + 2 * a2[2] + 2 * a3[2] + a4[2])
        out[i + 1] = x, y, z
    return out


@dataclass(frozen=True)
class _Integration:
    t: Array  # grid, Julian years
    m: Array  # unit angular momentum (T, 3), frame of date
    mdot: Array  # inertial dm/dt (T, 3), rad per year
    precession: float  # frame rate p, rad per year


def _integrate(t0: float, t1: float, H: float, p: float, start: tuple[float, float]) -> _Integration:
    h = _STEP_DAYS * DAY / JULIAN_YEAR
    steps = max(int(np.ceil((t1 - t0) / h)), 1)
    half = t0 + 0.5 * h * np.arange(2 * steps + 1)
    S = _gradient_matrices(half, H)
    m = _rk4(S, _pole(*start), h, p)
    Sg = S[::2]
    mdot = np.cross(np.einsum("tij,tj->ti", Sg, m), m)
    return _Integration(half[::2], m, mdot, p)


def _axis_vectors(run: _Integration, axis: str, H: float) -> Array:
    c, d = _axis_coefficients(axis, H)
    vectors = run.m + c * np.cross(run.m, run.mdot)
    if d:
        # m̈ by central differences of the torque's ṁ on the quarter-day grid (its own error is
        # (hσ)²/6 ≈ 1 % of a term that is itself 0.5 mas at 13.66 days).
        mdd = np.gradient(run.mdot, run.t, axis=0)
        vectors += d * (mdd - run.m * np.sum(run.m * mdd, axis=-1, keepdims=True))
    return vectors / np.linalg.norm(vectors, axis=-1, keepdims=True)


def nutation(
    t: ArrayLike,
    dynamical_ellipticity: float = H_MHB2000,
    axis: str = "figure",
    method: str = "numeric",
    obliquity: float = MEAN_OBLIQUITY,
) -> tuple[Array, Array]:
    """The rigid-Earth luni-solar nutation ``Δψ, Δε`` (arcsec) at times ``t``.

    Parameters
    ----------
    t : array_like, shape (T,)
        Julian years TT from J2000 (any order; one value is fine).
    dynamical_ellipticity : float
        ``H = (C − (A+B)/2)/C``, ``0 < H < 1/2``.
    axis : {"figure", "momentum", "rotation"}
    method : {"numeric", "analytic"}
        ``"numeric"`` integrates the torque over ``[min t, max t]`` (at least
        :func:`minimum_span` of the principal terms, so that the mean pole can
        be separated); ``"analytic"`` sums :func:`nutation_series`.
    obliquity : float
        Mean obliquity ``ε₀``, radians.

    Returns
    -------
    dpsi, deps : numpy.ndarray, shape (T,)

    Examples
    --------
    >>> dpsi, deps = nutation([0.0, 0.5], method="analytic")
    >>> dpsi.round(3).tolist(), deps.round(3).tolist()  # IAU 2000A at J2000: -13.932, -5.769
    ([-13.98, -15.193], [-5.794, -4.517])
    """
    H = check_dynamical_ellipticity(dynamical_ellipticity)
    key = _axis(axis)
    times = np.atleast_1d(np.asarray(t, dtype=float))
    if times.ndim != 1 or times.size == 0 or not np.all(np.isfinite(times)):
        msg = f"expected finite times (T,), got shape {np.shape(t)}"
        raise ValueError(msg)
    if method == "analytic":
        series = nutation_series(H, key, float(np.mean(times)), obliquity)
        return series(times)
    if method != "numeric":
        msg = f"expected method 'numeric' or 'analytic', got {method!r}"
        raise ValueError(msg)
    t0, t1 = float(times.min()), float(times.max())
    grid, dpsi, deps = _window_residuals(t0, max(t1, t0 + minimum_span() * 1.001), H, float(obliquity), key)
    from scipy.interpolate import CubicSpline

    return CubicSpline(grid, dpsi)(times), CubicSpline(grid, deps)(times)


@functools.lru_cache(maxsize=4)
def _window_residuals(t0: float, end: float, H: float, eps: float, axis: str) -> tuple[Array, Array, Array]:
    """The grid and ``Δψ, Δε`` of ``axis`` on it for one integration window (cached with the run)."""
    run, series = _window_run(t0, end, H, eps)
    return (run.t, *_residuals(run, axis, H, series))


def _numeric_run(t0: float, t1: float, H: float, eps: float) -> tuple[_Integration, NutationSeries]:
    """Integrate over ``[t0, max(t1, t0 + span)]`` from the forced state at ``t0`` (mean pole ``ε₀``).

    The start sets only the free constants (where the mean pole lies); the
    analytic series supplies them, which spares a second pass. Runs are cached
    per window, so the series and the terms of one span share one integration.
    """
    return _window_run(t0, max(t1, t0 + minimum_span() * 1.001), H, eps)


@functools.lru_cache(maxsize=2)
def _window_run(t0: float, end: float, H: float, eps: float) -> tuple[_Integration, NutationSeries]:
    series = nutation_series(H, "momentum", 0.5 * (t0 + end), eps)
    dpsi0, deps0 = series(t0)
    start = (float(dpsi0) * ARCSEC, eps + float(deps0) * ARCSEC)
    return _integrate(t0, end, H, series.precession * ARCSEC, start), series


def _large(series: NutationSeries) -> Array:
    """The series' multipliers with an amplitude above ``_FIT_THRESHOLD``."""
    size = np.max(np.abs([series.psi_sin, series.psi_cos, series.eps_cos, series.eps_sin]), axis=0)
    return series.multipliers[size > _FIT_THRESHOLD]


def _resolved(multipliers: Array, span: float, epoch: float, first: Array | None = None) -> Array:
    """Regressors for a fit over ``span``: ``first``, then the rows of ``multipliers`` in order.

    A row is kept when its period fits in ``span`` (slower terms fold into the
    mean pole's trend) and its frequency differs from every kept row's by at
    least one cycle over the span (else the two cannot be told apart).
    """
    return _split(multipliers, span, epoch, first)[0]


def _split(multipliers: Array, span: float, epoch: float, first: Array | None = None) -> tuple[Array, Array]:
    """:func:`_resolved`'s regressors, and the rows left out as too close to one of them (not too slow)."""
    rates = delaunay_rates(epoch)
    kept = [] if first is None else [np.asarray(row, dtype=float) for row in first]
    kept_rates = [abs(float(row @ rates)) for row in kept]
    close = []
    resolution = 2 * np.pi / span
    for row in multipliers:
        if any(np.array_equal(row, other) for other in kept):
            continue
        rate = abs(float(row @ rates))
        if rate < resolution:
            continue
        if all(abs(rate - other) >= resolution for other in kept_rates):
            kept.append(np.asarray(row, dtype=float))
            kept_rates.append(rate)
        else:
            close.append(np.asarray(row, dtype=float))
    return np.asarray(kept).reshape(-1, 5), np.asarray(close).reshape(-1, 5)


def _residuals(run: _Integration, axis: str, H: float, series: NutationSeries) -> tuple[Array, Array]:
    """``Δψ, Δε`` (arcsec) of ``axis`` on the grid: the angles minus their mean pole (constant + trend)."""
    psi, eps = _angles(_axis_vectors(run, axis, H))
    n = _resolved(_large(series), run.t[-1] - run.t[0], float(run.t.mean()))
    theta = delaunay_arguments(run.t) @ n.T
    dt = run.t - run.t[0]
    design = np.concatenate([np.ones((dt.size, 1)), dt[:, None], np.sin(theta), np.cos(theta)], 1)
    values = np.stack([psi, eps], -1)
    coefficients = np.linalg.lstsq(design[::8], values[::8], rcond=None)[0]
    trend = design[:, :2] @ coefficients[:2]
    return (psi - trend[:, 0]) / ARCSEC, (eps - trend[:, 1]) / ARCSEC


def numeric_terms(
    span: tuple[float, float],
    dynamical_ellipticity: float = H_MHB2000,
    axis: str = "figure",
    multipliers: ArrayLike | None = None,
    obliquity: float = MEAN_OBLIQUITY,
) -> tuple[Array, float]:
    """Fitted amplitudes (K, 4) of the integrated nutation over ``span``, and the precession rate (″/yr).

    The fit (:func:`fit_terms`) uses every term of the analytic series above
    0.02 mas as a regressor, so the principal terms do not absorb their
    neighbours; the span must reach :func:`minimum_span`. The precession rate
    is the frame's rate plus the fitted drift of ``ψ``.

    Parameters
    ----------
    span : (float, float)
        Julian years from J2000.
    dynamical_ellipticity : float
    axis : {"figure", "momentum", "rotation"}
    multipliers : array_like, shape (K, 5), optional
        Default: the :data:`PRINCIPAL_TERMS`.
    obliquity : float

    Returns
    -------
    amplitudes : numpy.ndarray, shape (K, 4)
        ``(ψs, ψc, εc, εs)``, arcsec.
    precession : float

    Examples
    --------
    >>> numeric_terms((0.0, 10.0))
    Traceback (most recent call last):
    ...
    ValueError: expected a span of at least 18.613 years to fit these terms, got 10.000
    """
    H = check_dynamical_ellipticity(dynamical_ellipticity)
    key = _axis(axis)
    eps0 = float(obliquity)
    t0, t1 = (float(v) for v in span)
    chosen = list(PRINCIPAL_TERMS.values()) if multipliers is None else multipliers
    wanted = np.atleast_2d(np.asarray(chosen, dtype=float))
    need = minimum_span(wanted, 0.5 * (t0 + t1))
    if not (t1 - t0 >= need * (1 - 1e-9)):
        msg = f"expected a span of at least {need:.3f} years to fit these terms, got {t1 - t0:.3f}"
        raise ValueError(msg)
    run, series = _numeric_run(t0, t1, H, float(obliquity))
    psi, eps = _angles(_axis_vectors(run, key, H))
    inside = run.t <= t1 + 1e-12
    every, close = _split(_large(series), t1 - t0, 0.5 * (t0 + t1), first=wanted)
    # Terms closer in frequency to a regressor than one cycle over the span cannot be told apart
    # from it (l′ and 2F − 2D + 2Ω − l′ differ by the Sun's perigee, 21 000 years): take them
    # out with the analytic series of this axis first.
    own = nutation_series(H, key, float(run.t.mean()), float(obliquity))
    amplitudes = np.array([own.term(tuple(row)) for row in close]).T.reshape(4, -1)
    prior = NutationSeries(close, *amplitudes, 0.0, H, eps0, key)
    known_psi, known_eps = prior(run.t)
    psi = psi - known_psi * ARCSEC
    eps = eps - known_eps * ARCSEC
    fitted = fit_terms(run.t[inside][::8], psi[inside][::8], eps[inside][::8], every)
    design = np.stack([np.ones(inside.sum()), run.t[inside] - run.t[inside].mean()], -1)
    theta = delaunay_arguments(run.t[inside]) @ every.T
    periodic = np.sin(theta) @ fitted[:, 0] + np.cos(theta) @ fitted[:, 1]
    drift = np.linalg.lstsq(design, psi[inside] - periodic, rcond=None)[0][1]
    return fitted[: wanted.shape[0]] / ARCSEC, (run.precession + drift) / ARCSEC


#: IAU 2000A (MHB2000, non-rigid) in-phase amplitudes ``(Δψ sin, Δε cos)`` of the principal terms,
#: arcsec (IERS Conventions 2010, Table 5.3a/5.3b; ``erfa.nut00a`` sums the same series).
IAU2000A = {
    "Ω": (-17.2064161, 9.2052331),
    "2Ω": (0.2074554, -0.0897492),
    "2(F−D+Ω)": (-1.3170906, 0.5730336),
    "2(F+Ω)": (-0.2276413, 0.0978459),
    "l′": (0.1475877, 0.0073871),
    "l": (0.0711159, -0.0006750),
}
#: Rigid-Earth 18.6-year amplitudes of the figure axis, REN-2000 (Souchay, Loysel, Kinoshita &
#: Folgueira 1999, A&AS 135, 111, Table 5.2; H = 0.0032737548, which MHB2000 rescaled by
#: 1.0000122 to H = 0.0032737949: 0.2 mas here), arcsec. The digits are those quoted in issue 15;
#: the paper's tables are images online and were not re-read when this was written.
REN2000_NODE = (-17.2806, 9.2282)
#: Woolard's (1953) rigid-Earth series (rotation axis; Astron. Pap. Amer. Eph. 15, part 1, as in
#: the Explanatory Supplement 1961), in-phase ``(Δψ sin, Δε cos)``, arcsec. His ``H`` and lunar
#: mass (1/81.45) are older: compare ratios to the 18.6-year term.
WOOLARD1953 = {
    "Ω": (-17.2327, 9.2100),
    "2Ω": (0.2088, -0.0904),
    "2(F−D+Ω)": (-1.2729, 0.5522),
    "2(F+Ω)": (-0.2037, 0.0884),
    "l′": (0.1261, 0.0),
    "l": (0.0675, 0.0),
}


def terms_table(
    span: tuple[float, float], dynamical_ellipticity: float = H_MHB2000, axis: str = "figure"
) -> dict:
    """The principal terms fitted over ``span`` beside the analytic series, REN-2000 and IAU 2000A.

    Parameters
    ----------
    span : (float, float)
        Julian years from J2000, at least :func:`minimum_span` long.
    dynamical_ellipticity : float
    axis : {"figure", "momentum", "rotation"}

    Returns
    -------
    dict
        ``terms``: one dict per principal term (``argument``, ``multipliers``,
        ``period_days``, fitted ``dpsi_sin``, ``dpsi_cos``, ``deps_cos``,
        ``deps_sin``, ``analytic_dpsi``, ``analytic_deps``, ``ren2000_dpsi``,
        ``ren2000_deps`` (the 18.6-year term only, else ``None``),
        ``iau2000a_dpsi``, ``iau2000a_deps``), arcsec; ``precession``: ″/yr.

    Examples
    --------
    >>> terms_table((0.0, 5.0), axis="momentum")
    Traceback (most recent call last):
    ...
    ValueError: expected a span of at least 18.613 years to fit these terms, got 5.000
    """
    H = check_dynamical_ellipticity(dynamical_ellipticity)
    key = _axis(axis)
    t0, t1 = (float(v) for v in span)
    fitted, precession = numeric_terms((t0, t1), H, key)
    series = nutation_series(H, key, 0.5 * (t0 + t1))
    rates = delaunay_rates(0.5 * (t0 + t1))
    rows = []
    for (name, n), amp in zip(PRINCIPAL_TERMS.items(), fitted, strict=True):
        analytic = series.term(n)
        ren = REN2000_NODE if name == "Ω" and key == "figure" else (None, None)
        rows.append(
            {
                "argument": name,
                "multipliers": list(n),
                "period_days": float(2 * np.pi / abs(np.dot(n, rates)) * JULIAN_YEAR / DAY),
                "dpsi_sin": float(amp[0]),
                "dpsi_cos": float(amp[1]),
                "deps_cos": float(amp[2]),
                "deps_sin": float(amp[3]),
                "analytic_dpsi": analytic[0],
                "analytic_deps": analytic[2],
                "ren2000_dpsi": ren[0],
                "ren2000_deps": ren[1],
                "iau2000a_dpsi": IAU2000A[name][0],
                "iau2000a_deps": IAU2000A[name][1],
            }
        )
    return {"terms": rows, "precession": float(precession)}
