r"""The Earth's tidal response ``k₂(σ)``: constant time lag, constant phase lag, resonant ocean.

Each model gives ``Q(m, σ) = −Im k₂(σ)`` at the tidal frequency ``σ`` (rad/s) of a wave of
order ``m`` (:func:`andoyer.planetary.tides.equations.lag`, one compiled kernel for all) and
its kernel parameters.

* :class:`ConstantTimeLag` (Mignard 1979, 1980; Hut 1981; Néron de Surgy & Laskar 1997):
  ``k₂(σ) = k₂ e^{−iσΔt}`` in the small-lag limit, ``Q = k₂Δt σ``.
* :class:`ConstantPhaseLag`: ``Q = (k₂/Q_f) sign σ`` (a constant quality factor). Its
  equations integrate in closed form (the ``a^{13/2}`` law); the tests use it.
* :class:`OceanTides` (after Farhat et al. 2022, A&A 665, L1, and Auclair-Desrotour et al.
  2018, 2023): a solid Earth of constant ``Q`` plus a global ocean of uniform depth ``H``
  with a Rayleigh drag ``σ_R``, without the Coriolis force, coupled to the solid Earth by
  the tidal and load Love numbers. Linearising the shallow-water equations
  ``∂u/∂t + σ_R u = −g∇(ζ − ζ_eq)``, ``∂ζ/∂t = −H∇·u`` for a degree-2 wave
  ``e^{iσt}`` (``ζ_eq = [(1 + k₂ − h₂) U + (1 + k'₂ − h'₂) κ g ζ]/g`` with the ocean's
  self-attraction ``κ = 3ρ_w/(5ρ̄)``) gives the ocean's share of the Love number

  .. math:: k_2^{oc}(\sigma) = \frac{(1+k'_2)(1+k_2-h_2)\,\kappa\,\sigma_2^2}
            {\sigma_2^2\,[1 - (1 + k'_2 - h'_2)\kappa] - \sigma^2 + i\sigma\sigma_R},
            \qquad \sigma_2^2 = \frac{6 g H}{R^2},

  a damped resonance at ``σ ≈ σ₂√(1 − (1+k'−h')κ)``. It acts on the semidiurnal band
  (``m = 2``) only: on a rotating Earth a uniform global ocean has no diurnal (``m = 1``)
  tide of degree 2 (Laplace's result; Lamb 1932, ch. VIII), and the long-period tide (``m = 0``)
  is in equilibrium. What Farhat et al.'s model has and this one does not: the continents
  (their hemispherical ocean and its drift over the last Gyr, which give the resonances of
  the Phanerozoic); see the docs page for what that costs.

Examples
--------
>>> round(float(ConstantTimeLag(100.0).lag(2, 1.0e-4)), 6)  # k2 Δt σ
0.01
>>> OceanTides(depth=-1.0)
Traceback (most recent call last):
...
ValueError: expected a positive finite ocean depth in metres, got -1.0
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer.planetary.tides import equations
from andoyer.planetary.tides.system import EarthMoonSystem

__all__ = ["ConstantPhaseLag", "ConstantTimeLag", "OceanTides", "TidalResponse"]

Array = NDArray[np.float64]


def _positive(value: object, what: str) -> float:
    if not (isinstance(value, int | float | np.floating) and math.isfinite(value) and value > 0):
        msg = f"expected a positive finite {what}, got {value!r}"
        raise ValueError(msg)
    return float(value)


class TidalResponse:
    """Base of the response models: ``Q(m, σ)`` through the one compiled kernel."""

    name = ""
    kind = -1

    def kernel_parameters(self, system: EarthMoonSystem) -> tuple[float, float, float, float]:
        """``(p1, p2, p3, p4)`` of :func:`andoyer.planetary.tides.equations.lag` for ``system``."""
        raise NotImplementedError

    def lag(self, order: int, frequency: ArrayLike, system: EarthMoonSystem | None = None) -> Array:
        """``−Im k₂`` at the tidal frequencies ``frequency`` (rad/s) of order ``order``.

        Parameters
        ----------
        order : {0, 1, 2}
        frequency : array_like, shape (...)
            rad/s, signed.
        system : EarthMoonSystem, optional
            Default: :class:`EarthMoonSystem()`.

        Returns
        -------
        numpy.ndarray, shape (...)
        """
        if order not in (0, 1, 2):
            msg = f"expected a tidal order 0, 1 or 2, got {order!r}"
            raise ValueError(msg)
        sigma = np.asarray(frequency, dtype=np.float64)
        if not np.all(np.isfinite(sigma)):
            msg = "expected finite tidal frequencies in rad/s, got NaN or infinity"
            raise ValueError(msg)
        p = self.kernel_parameters(EarthMoonSystem() if system is None else system)
        flat = [equations.lag(self.kind, order, float(s), *p) for s in sigma.ravel()]
        return np.array(flat, dtype=np.float64).reshape(sigma.shape)


@dataclass(frozen=True)
class ConstantTimeLag(TidalResponse):
    """Constant time lag: ``−Im k₂(σ) = k₂Δt σ``.

    Parameters
    ----------
    k2_time_lag : float
        ``k₂ Δt`` in seconds (≥ 0). :meth:`andoyer.planetary.tides.calibrate` fits it to
        the lunar recession measured by lunar laser ranging.

    Examples
    --------
    >>> ConstantTimeLag(-1.0)
    Traceback (most recent call last):
    ...
    ValueError: expected k2 Δt >= 0 seconds (finite), got -1.0
    """

    k2_time_lag: float
    name = "constant-lag"
    kind = equations.CONSTANT_LAG

    def __post_init__(self) -> None:
        value = self.k2_time_lag
        if not (isinstance(value, int | float | np.floating) and math.isfinite(value) and value >= 0):
            msg = f"expected k2 Δt >= 0 seconds (finite), got {value!r}"
            raise ValueError(msg)

    def kernel_parameters(self, system: EarthMoonSystem) -> tuple[float, float, float, float]:  # noqa: ARG002
        """``(k₂Δt, 0, 0, 0)``."""
        return float(self.k2_time_lag), 0.0, 0.0, 0.0


@dataclass(frozen=True)
class ConstantPhaseLag(TidalResponse):
    """Constant phase lag (constant ``Q``): ``−Im k₂(σ) = (k₂/Q) sign σ``.

    Parameters
    ----------
    k2_over_q : float
        ``k₂/Q`` (≥ 0).

    Examples
    --------
    >>> float(ConstantPhaseLag(0.01).lag(2, -1.0))
    -0.01
    """

    k2_over_q: float
    name = "constant-q"
    kind = equations.CONSTANT_Q

    def __post_init__(self) -> None:
        value = self.k2_over_q
        if not (isinstance(value, int | float | np.floating) and math.isfinite(value) and 0 <= value < 1):
            msg = f"expected 0 <= k2/Q < 1 (finite), got {value!r}"
            raise ValueError(msg)

    def kernel_parameters(self, system: EarthMoonSystem) -> tuple[float, float, float, float]:  # noqa: ARG002
        """``(k₂/Q, 0, 0, 0)``."""
        return float(self.k2_over_q), 0.0, 0.0, 0.0


#: Defaults of :class:`OceanTides`: ``(H, σ_R)`` fitted by ``python3 scripts/fit_ocean_tides.py``
#: to the two constraints of Farhat et al. (2022): the lunar recession of 3.830 cm/yr today
#: (Williams & Boggs 2016) and the Moon at the Laplace-plane transition 4.425 Gyr ago (the
#: lunar age, Maurice et al. 2020).
FITTED_DEPTH = 7935.09
FITTED_DRAG = 9.44858e-5


@dataclass(frozen=True)
class OceanTides(TidalResponse):
    r"""A solid Earth of constant ``Q`` and a resonant global ocean (after Farhat et al. 2022).

    ``−Im k₂ = (k₂ sin δ_s) sign σ − [m = 2] Im k₂^{oc}(σ)`` (module docstring).

    Parameters
    ----------
    depth : float
        The ocean's uniform depth ``H``, metres (default :data:`FITTED_DEPTH`: an effective
        depth, fitted, not the real ocean's 3.7 km; see the docs).
    drag : float
        The Rayleigh drag frequency ``σ_R``, s⁻¹ (default :data:`FITTED_DRAG`).
    water_density : float
        ``ρ_w`` = 1025 kg m⁻³ (sea water at the surface).
    body_love : tuple of float
        The solid Earth's tidal Love numbers ``(k₂, h₂)`` = (0.30, 0.6078) (IERS Conventions
        2010, §6.2 and §7.1.1).
    load_love : tuple of float
        Degree-2 load Love numbers ``(k'₂, h'₂)`` = (−0.3025, −0.9902) (PREM, Han & Wahr 1995).
    solid_lag : float
        The body tide's phase lag ``δ_s`` = 0.204° in radians (Ray, Eanes & Lemoine 2001:
        0.20° ± 0.05° at M2, ``Q`` ≈ 280).

    Examples
    --------
    >>> tides = OceanTides()
    >>> round(tides.resonance_frequency() * 1e5, 2)  # rad/s, ×1e-5: below today's 2(ω − n) = 14.05
    9.67
    """

    depth: float = FITTED_DEPTH
    drag: float = FITTED_DRAG
    water_density: float = 1025.0
    body_love: tuple[float, float] = (0.30, 0.6078)
    load_love: tuple[float, float] = (-0.3025, -0.9902)
    solid_lag: float = math.radians(0.204)
    name = "ocean"
    kind = equations.OCEAN

    def __post_init__(self) -> None:
        _positive(self.depth, "ocean depth in metres")
        _positive(self.drag, "drag frequency in 1/s")
        _positive(self.water_density, "water density in kg/m^3")
        if not 0 <= self.solid_lag < math.pi / 2:
            msg = f"expected a solid-Earth phase lag in [0, π/2) radians, got {self.solid_lag!r}"
            raise ValueError(msg)
        pairs = {"body_love": self.body_love, "load_love": self.load_love}
        for name, pair in pairs.items():
            numbers = all(isinstance(v, int | float) and math.isfinite(v) for v in pair)
            if len(pair) != 2 or not numbers:
                msg = f"expected {name} as two finite numbers (k, h), got {pair!r}"
                raise ValueError(msg)
        if self.depth > 2.0e4 or self.drag > 1.0:
            msg = f"expected a depth up to 20 km and a drag up to 1/s, got {self.depth!r}, {self.drag!r}"
            raise ValueError(msg)

    def _terms(self, system: EarthMoonSystem) -> tuple[float, float, float]:
        """``(κ, σ₂², 1 − (1 + k' − h')κ)`` on ``system``'s sphere."""
        radius = system.mean_radius
        gravity = system.gm_earth / radius**2
        density = system.mass_earth / (4.0 / 3.0 * math.pi * radius**3)
        kappa = 3.0 * self.water_density / (5.0 * density)
        sigma2 = 6.0 * gravity * self.depth / radius**2
        k_load, h_load = self.load_love
        return kappa, sigma2, 1.0 - (1.0 + k_load - h_load) * kappa

    def kernel_parameters(self, system: EarthMoonSystem) -> tuple[float, float, float, float]:
        """``(k₂ sin δ_s, (1+k')(1+k−h)κσ₂², σ₂²[1 − (1+k'−h')κ], σ_R)``."""
        kappa, sigma2, shift = self._terms(system)
        k_body, h_body = self.body_love
        k_load, _ = self.load_love
        amplitude = (1.0 + k_load) * (1.0 + k_body - h_body) * kappa * sigma2
        return k_body * math.sin(self.solid_lag), amplitude, sigma2 * shift, float(self.drag)

    def love_number(
        self, frequency: ArrayLike, system: EarthMoonSystem | None = None
    ) -> NDArray[np.complex128]:
        """The ocean's ``k₂^{oc}(σ)`` (complex), for ``e^{iσt}`` forcing (``Im < 0``: a lag).

        Parameters
        ----------
        frequency : array_like, shape (...)
            rad/s.
        system : EarthMoonSystem, optional

        Returns
        -------
        numpy.ndarray of complex, shape (...)
        """
        s = EarthMoonSystem() if system is None else system
        _, amplitude, stiffness, drag = self.kernel_parameters(s)
        sigma = np.asarray(frequency, dtype=np.float64)
        return amplitude / (stiffness - sigma**2 + 1j * sigma * drag)

    def resonance_frequency(self, system: EarthMoonSystem | None = None) -> float:
        """``σ₂√(1 − (1+k'−h')κ)``, rad/s: where the undamped ocean would resonate."""
        _, sigma2, shift = self._terms(EarthMoonSystem() if system is None else system)
        return math.sqrt(sigma2 * shift)
