r"""Rigid-Earth luni-solar nutation of the figure, angular-momentum and rotation axes.

Modules: :mod:`~andoyer.planetary.nutation.model` (constants, equations),
:mod:`~andoyer.planetary.nutation.analytic` (the averaged series),
:mod:`~andoyer.planetary.nutation.numeric` (the integration), :mod:`~andoyer.planetary.nutation.fit`
(least squares over a span), :mod:`~andoyer.planetary.nutation.tables` (published values).

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

Constants, all the catalogue's (:func:`andoyer.catalogue.get`): the Earth's ``spin_rate``
``ω = 7.292115·10⁻⁵ rad/s`` (GRS80; IERS Conventions 2010, Table 1.2), its ``obliquity``
``ε₀ = 84381.406″`` (IAU 2006) and its default ``H = 0.00327379492`` (Mathews, Herring &
Buffett 2002, MHB2000; IERS Conventions 2010 rounds it to 0.0032737949); ``GM_Sun``,
``GM_Moon`` of :mod:`andoyer.perturbations.solar_system`.
"""

from andoyer.planetary.nutation.analytic import NutationSeries, luni_solar_precession, nutation_series
from andoyer.planetary.nutation.fit import fit_terms, minimum_span
from andoyer.planetary.nutation.model import (
    ARCSEC,
    AXES,
    EARTH_ROTATION,
    H_MHB2000,
    MEAN_OBLIQUITY,
    PRINCIPAL_TERMS,
)
from andoyer.planetary.nutation.numeric import nutation, nutation_cost
from andoyer.planetary.nutation.tables import (
    IAU2000A,
    REN2000,
    REN2000_NODE,
    WOOLARD1953,
    numeric_terms,
    terms_table,
)

__all__ = [
    "ARCSEC",
    "AXES",
    "EARTH_ROTATION",
    "H_MHB2000",
    "IAU2000A",
    "MEAN_OBLIQUITY",
    "PRINCIPAL_TERMS",
    "REN2000",
    "REN2000_NODE",
    "WOOLARD1953",
    "NutationSeries",
    "fit_terms",
    "luni_solar_precession",
    "minimum_span",
    "numeric_terms",
    "nutation",
    "nutation_cost",
    "nutation_series",
    "terms_table",
]
