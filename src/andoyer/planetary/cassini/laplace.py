r"""Laplace planes and secular node modes of a satellite system: the planet's J2, the Sun, the satellites.

A satellite's orbit normal ``h`` (a unit vector) is torqued by the planet's equatorial bulge
(pole ``p``), by the Sun (whose apparent orbit about the planet has the normal ``q``, at the
planet's obliquity ``ε`` from ``p``) and by the other satellites. Averaged over the orbits
(circular satellites), each of these torques has the form ``w (h·u)(h × u)`` about an axis ``u``:

.. math::
   \frac{d\mathbf h_j}{dt} = \nu_{J,j}(\mathbf h_j\cdot\mathbf p)(\mathbf h_j\times\mathbf p)
   + \nu_{\odot,j}(\mathbf h_j\cdot\mathbf q)(\mathbf h_j\times\mathbf q)
   + \sum_{k\ne j} B_{jk}(\mathbf h_j\cdot\mathbf h_k)(\mathbf h_j\times\mathbf h_k),

with, for a satellite of mean motion ``n_j``, semi-major axis ``a_j`` and eccentricity ``e_j``,

.. math::
   \nu_{J,j} = \tfrac32 n_j J_2 (R/a_j)^2 (1-e_j^2)^{-2}, \qquad
   \nu_{\odot,j} = \tfrac34 \frac{n_\odot^2}{n_j}, \quad
   n_\odot^2 = \frac{GM_\odot}{a_p^3(1-e_p^2)^{3/2}}, \qquad
   B_{jk} = \tfrac14 n_j \frac{m_k}{M}\,\alpha_{jk}\bar\alpha_{jk}\, b^{(1)}_{3/2}(\alpha_{jk}).

``ν_J`` follows from the orbit average of the ``J2`` potential, ``⟨Φ⟩ = GM J2 R²(1 −
3(h·p)²)/(4a³)``, and the torque ``L dh/dt = −h × ∂E/∂h`` on the orbit's angular momentum
``L = m n a²``; ``ν_⊙`` from the doubly averaged solar tide ``⟨Φ⟩ = −(n_⊙² a²/8)(3(h·q)² − 1)``
(the Sun's orbit of semi-major axis ``a_p`` and eccentricity ``e_p`` about the planet); ``B_jk``
is the Laplace–Lagrange coefficient of the mutual secular interaction (Murray & Dermott 1999,
§7.2: ``α_jk = a_<`` ``/a_>``, ``ᾱ_jk = α_jk`` for an outer perturber and ``1`` for an inner one,
``b^{(1)}_{3/2}`` the Laplace coefficient), written in vector form so that it conserves the
total angular momentum (``Λ_j B_jk = Λ_k B_kj``). An inner satellite far inside acts as an
added ``J2``: ``B_jk → (3/4) n_j (m_k/M)(a_k/a_j)²``, i.e. ``ΔJ2 = (m_k/2M)(a_k/R)²``.

**The Laplace planes.** The equilibria ``dh_j/dt = 0`` lie in the plane of ``p`` and ``q``; with
``φ_j`` the angle from ``p`` towards ``q``,

.. math:: \nu_{J,j}\sin 2\varphi_j = \nu_{\odot,j}\sin 2(\varepsilon - \varphi_j)
   + \sum_k B_{jk}\sin 2(\varphi_k - \varphi_j),

which for one satellite is the classical Laplace plane (Laplace 1805; Tremaine, Touma &
Namouni 2009, eq. 21), ``tan 2φ = sin 2ε/(cos 2ε + ν_J/ν_⊙)`` = ``sin 2ε/(cos 2ε + (r_L/a)^5)``
with the Laplace radius ``r_L^5 = 2 J2 R² a_p³(1 − e_p²)^{3/2} M/M_⊙``. It is solved by Newton's
method from the one-satellite planes.

**The modes.** About the equilibria, a small tilt ``w_j = δh_j·e_{1,j} + i δh_j·e_2`` (``e_1`` in
the plane of ``p``, ``q``, ``e_2 = p × q/|p × q|``) obeys, to first order,
``ẇ = i A w + i Q w̄``, with for each axis ``u`` at angle ``χ`` from ``h_j`` the diagonal
``A_jj = −Σ w_u (3cos²χ − 1)/2`` and for each satellite ``k`` the coupling
``A_jk = B_jk(cos χ_jk + cos 2χ_jk)/2``; the part ``Q`` (``−w_u sin²χ/2``) makes the tilt's
circle an ellipse and is left out (for Titan it is 0.3 % of ``A``). The eigenvalues of ``A``
are the node rates ``g_k < 0`` of the modes; a satellite's inclination to its Laplace plane is
``w_j(t) = Σ_k c_k v_jk e^{i g_k t}``, the amplitudes ``c_k`` fixed by the observed orbits.
With one satellite and no mutual terms, ``g = −√(𝓗_θθ 𝓗_ψψ)``'s circular mean
``−(ν_J(3cos²φ − 1) + ν_⊙(3cos²(ε − φ) − 1))/2``.

Left out: the planet's ``J4`` and rings, satellites the catalogue does not hold, the planet's
own precession and its orbit's (the Laplace plane is fixed), eccentricities' coupling to the
inclinations, and the second-order terms in the masses (the Moon's node: see docs/cassini.md).

Examples
--------
>>> n = 5.0**-1.5                                       # a = 5 R, GM = 1
>>> system = SatelliteSystem(planet_gm=1.0, planet_radius=1.0, planet_j2=1e-3, obliquity=0.4,
...                          sun_rate2=6e-7, satellites=(Satellite("a", 0.0, 5.0, n),))
>>> ratio = (1.5 * n * 1e-3 / 25) / (0.75 * 6e-7 / n)    # ν_J/ν_⊙ = (r_L/a)^5
>>> phi = 0.5 * math.atan2(math.sin(0.8), math.cos(0.8) + ratio)
>>> round(float(system.laplace_angles()[0]), 12) == round(phi, 12), round(phi, 6)
(True, 0.193181)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["LaplaceModes", "Satellite", "SatelliteSystem", "laplace_coefficient"]

Array = NDArray[np.float64]


def laplace_coefficient(alpha: ArrayLike, s: float = 1.5, j: int = 1) -> Array:
    r"""The Laplace coefficient ``b_s^{(j)}(α) = (1/π)∫₀^{2π} cos jψ dψ/(1 − 2α cos ψ + α²)^s``.

    The trapezoidal rule on the periodic integrand (2048 points) is exact to round-off for
    ``α ≤ 0.95``.

    Parameters
    ----------
    alpha : array_like, shape (...)
        ``0 ≤ α < 1``.
    s : float
    j : int

    Returns
    -------
    numpy.ndarray, shape (...)

    Examples
    --------
    >>> a = 0.01
    >>> round(float(laplace_coefficient(a)) / (3 * a), 6)  # 3α(1 + 15α²/8 + ...)
    1.000188
    """
    a = np.asarray(alpha, dtype=float)
    if np.any(~np.isfinite(a)) or np.any((a < 0) | (a >= 1)):
        msg = f"expected 0 <= alpha < 1, got {a.tolist()!r}"
        raise ValueError(msg)
    psi = np.linspace(0.0, 2 * np.pi, 2049)[:-1]
    x = a[..., None]
    integrand = np.cos(j * psi) / (1 - 2 * x * np.cos(psi) + x * x) ** s
    return 2.0 * integrand.mean(axis=-1)


@dataclass(frozen=True)
class Satellite:
    """One satellite of a :class:`SatelliteSystem` (units of the system: ``GM`` and lengths alike).

    Attributes
    ----------
    name : str
    gm : float
        ``GM`` (0 for a test particle, which feels the others but moves none).
    semi_major_axis : float
    mean_motion : float
        ``n`` (rad per time unit of the rates).
    eccentricity : float
        Enters ``ν_J`` only (``(1 − e²)^{-2}``); the mutual terms take circular orbits.
    """

    name: str
    gm: float
    semi_major_axis: float
    mean_motion: float
    eccentricity: float = 0.0

    def __post_init__(self) -> None:
        for key in ("gm", "semi_major_axis", "mean_motion", "eccentricity"):
            value = getattr(self, key)
            if not isinstance(value, int | float) or not math.isfinite(value):
                msg = f"expected a finite {key} of satellite {self.name!r}, got {value!r}"
                raise ValueError(msg)
        if self.gm < 0 or self.semi_major_axis <= 0 or self.mean_motion <= 0:
            msg = (
                f"expected gm >= 0, semi_major_axis > 0 and mean_motion > 0 of satellite {self.name!r}, "
                f"got {self.gm!r}, {self.semi_major_axis!r}, {self.mean_motion!r}"
            )
            raise ValueError(msg)
        if not 0 <= self.eccentricity < 1:
            msg = f"expected 0 <= eccentricity < 1 of satellite {self.name!r}, got {self.eccentricity!r}"
            raise ValueError(msg)


@dataclass(frozen=True)
class LaplaceModes:
    """The secular inclination modes of a :class:`SatelliteSystem` about its Laplace planes.

    Attributes
    ----------
    node_rates : numpy.ndarray, shape (m,)
        ``g_k`` (rad per time unit), the eigenvalues of ``A``; mode ``k`` is the one whose
        eigenvector weighs most on satellite ``k`` (``m`` = number of satellites).
    vectors : numpy.ndarray, shape (m, m)
        Column ``k`` is the eigenvector ``v_k``, normalised to ``v_kk = 1``.
    matrix : numpy.ndarray, shape (m, m)
        ``A`` (``ẇ = i A w``).
    """

    node_rates: Array
    vectors: Array
    matrix: Array

    def amplitudes(self, tilts: ArrayLike) -> NDArray[np.complex128]:
        """The complex amplitude of each mode in each satellite's tilt, ``c_k v_jk``, shape (m, m).

        Parameters
        ----------
        tilts : array_like of complex, shape (m,)
            ``w_j`` at the epoch: inclination to the Laplace plane times ``e^{iΩ}``.

        Returns
        -------
        numpy.ndarray of complex, shape (m, m)
            Row ``j``, column ``k``: mode ``k`` in satellite ``j``; the rows sum to ``tilts``.
        """
        w = np.asarray(tilts, dtype=complex)
        c = np.linalg.solve(self.vectors.astype(complex), w)
        return self.vectors * c[None, :]


@dataclass(frozen=True)
class SatelliteSystem:
    """A planet (``GM``, radius, ``J2``, obliquity) with the Sun and its satellites (module docstring).

    Parameters
    ----------
    planet_gm, planet_radius, planet_j2 : float
        ``GM`` of the planet (same unit as the satellites'), the reference radius of ``J2``
        (same unit as the semi-major axes) and ``J2``.
    obliquity : float
        ``ε``, the planet's equator to its orbit (rad).
    sun_rate2 : float
        ``n_⊙² = GM_⊙/(a_p³(1 − e_p²)^{3/2})`` in the rate unit squared (0: no Sun).
    satellites : tuple of Satellite
    """

    planet_gm: float
    planet_radius: float
    planet_j2: float
    obliquity: float
    sun_rate2: float
    satellites: tuple[Satellite, ...] = field(default_factory=tuple)

    def __post_init__(self) -> None:
        values = (self.planet_gm, self.planet_radius, self.planet_j2, self.obliquity, self.sun_rate2)
        if not all(isinstance(v, int | float) and math.isfinite(v) for v in values):
            msg = f"expected finite planet_gm, planet_radius, planet_j2, obliquity, sun_rate2, got {values!r}"
            raise ValueError(msg)
        if not (
            self.planet_gm > 0 and self.planet_radius > 0 and self.planet_j2 >= 0 and self.sun_rate2 >= 0
        ):
            msg = f"expected planet_gm > 0, planet_radius > 0, planet_j2 >= 0, sun_rate2 >= 0, got {values!r}"
            raise ValueError(msg)
        if not 0 <= self.obliquity < math.pi / 2:
            msg = f"expected a planetary obliquity in [0, pi/2) (radians), got {self.obliquity!r}"
            raise ValueError(msg)
        if not self.satellites or not all(isinstance(s, Satellite) for s in self.satellites):
            msg = f"expected a non-empty tuple of Satellite, got {self.satellites!r}"
            raise ValueError(msg)
        if self.planet_j2 == 0 and self.sun_rate2 == 0:
            msg = "expected a planet J2 > 0 or a Sun (sun_rate2 > 0): without them no plane is fixed"
            raise ValueError(msg)

    def index(self, name: str) -> int:
        """The position of the satellite ``name`` (case-insensitive)."""
        names = [s.name.lower() for s in self.satellites]
        if name.lower() not in names:
            msg = f"expected a satellite among {names}, got {name!r}"
            raise ValueError(msg)
        return names.index(name.lower())

    def rates(self) -> tuple[Array, Array, Array]:
        """``(ν_J, ν_⊙, B)``: shapes (m,), (m,), (m, m) with a zero diagonal (copies)."""
        return tuple(x.copy() for x in self._rates)  # type: ignore[return-value]

    @cached_property
    def _rates(self) -> tuple[Array, Array, Array]:
        sats = self.satellites
        n = np.array([s.mean_motion for s in sats])
        a = np.array([s.semi_major_axis for s in sats])
        e = np.array([s.eccentricity for s in sats])
        nu_j = 1.5 * n * self.planet_j2 * (self.planet_radius / a) ** 2 / (1 - e * e) ** 2
        nu_s = 0.75 * self.sun_rate2 / n
        m = len(sats)
        mutual = np.zeros((m, m))
        for j in range(m):
            for k in range(m):
                if j == k or sats[k].gm == 0:
                    continue
                inner = a[k] < a[j]
                alpha = a[k] / a[j] if inner else a[j] / a[k]
                alpha_bar = 1.0 if inner else alpha
                ratio = sats[k].gm / self.planet_gm
                mutual[j, k] = 0.25 * n[j] * ratio * alpha * alpha_bar * float(laplace_coefficient(alpha))
        return nu_j, nu_s, mutual

    def _axes(self, phi: Array) -> tuple[Array, Array]:
        """Each satellite's weights and axis angles: (m, m + 2) arrays (J2, Sun, the satellites)."""
        nu_j, nu_s, mutual = self.rates()
        weights = np.concatenate([nu_j[:, None], nu_s[:, None], mutual], axis=1)
        angles = np.concatenate([np.zeros(len(phi)), np.full(len(phi), self.obliquity), phi])
        return weights, np.broadcast_to(angles[None, :], weights.shape).copy()

    def laplace_angles(self) -> Array:
        """``φ_j`` (rad): each Laplace pole's angle from the planet's pole towards its orbit normal.

        Returns
        -------
        numpy.ndarray, shape (m,)
        """
        nu_j, nu_s, mutual = self.rates()
        eps = self.obliquity
        phi = 0.5 * np.arctan2(nu_s * math.sin(2 * eps), nu_j + nu_s * math.cos(2 * eps))
        for _ in range(100):
            diff = phi[None, :] - phi[:, None]  # φ_k − φ_j
            residual = (
                -nu_j * np.sin(2 * phi)
                + nu_s * np.sin(2 * (eps - phi))
                + np.sum(mutual * np.sin(2 * diff), 1)
            )
            jacobian = 2 * mutual * np.cos(2 * diff)
            np.fill_diagonal(
                jacobian,
                -2 * nu_j * np.cos(2 * phi) - 2 * nu_s * np.cos(2 * (eps - phi)) - np.sum(jacobian, 1),
            )
            step = np.linalg.solve(jacobian, -residual)
            phi = phi + step
            if np.max(np.abs(step)) < 1e-15:
                break
        return phi

    def poles(self) -> Array:
        """The Laplace poles in the system's frame (``p = z``, ``q = (sin ε, 0, cos ε)``), shape (m, 3)."""
        phi = self.laplace_angles()
        return np.stack([np.sin(phi), np.zeros_like(phi), np.cos(phi)], axis=-1)

    def modes(self) -> LaplaceModes:
        """The secular modes about the Laplace planes (module docstring).

        Returns
        -------
        LaplaceModes
        """
        phi = self.laplace_angles()
        nu_j, nu_s, mutual = self.rates()
        m = len(phi)
        matrix = np.zeros((m, m))
        for j in range(m):
            chi_p, chi_q = phi[j], phi[j] - self.obliquity
            chi = phi[j] - phi  # to each satellite
            matrix[j, j] = (
                -(
                    nu_j[j] * (3 * math.cos(chi_p) ** 2 - 1)
                    + nu_s[j] * (3 * math.cos(chi_q) ** 2 - 1)
                    + np.sum(mutual[j] * (3 * np.cos(chi) ** 2 - 1))
                )
                / 2
            )
            for k in range(m):
                if k != j:
                    matrix[j, k] = mutual[j, k] * (math.cos(chi[k]) + math.cos(2 * chi[k])) / 2
        values, vectors = np.linalg.eig(matrix)
        values, vectors = values.real, vectors.real
        # Mode k is the one that weighs most on satellite k (weights: the angular momenta).
        order = _assign(np.abs(vectors))
        values, vectors = values[order], vectors[:, order]
        vectors = vectors / np.diag(vectors)[None, :]
        return LaplaceModes(values, vectors, matrix)

    def vector_field(self, normals: ArrayLike) -> Array:
        """``dh_j/dt`` of the averaged equations for orbit normals (m, 3), in the system's frame.

        Examples
        --------
        >>> system = SatelliteSystem(1.0, 1.0, 1e-3, 0.4, 1e-6, (Satellite("a", 0.0, 20.0, 20.0**-1.5),))
        >>> bool(np.allclose(system.vector_field(system.poles()), 0.0, rtol=0, atol=1e-20))
        True
        """
        h = np.asarray(normals, dtype=float)
        nu_j, nu_s, mutual = self._rates
        p = np.array([0.0, 0.0, 1.0])
        q = np.array([math.sin(self.obliquity), 0.0, math.cos(self.obliquity)])
        axis = (nu_j * (h @ p))[:, None] * p + (nu_s * (h @ q))[:, None] * q + (mutual * (h @ h.T)) @ h
        return np.cross(h, axis)


def _assign(weights: Array) -> Array:
    """A permutation ``order`` with ``weights[k, order[k]]`` large: mode ``k`` for satellite ``k``."""
    m = weights.shape[0]
    scaled = weights / np.max(weights, axis=0, keepdims=True)
    order = np.full(m, -1)
    free = set(range(m))
    for k in np.argsort(-np.max(scaled, axis=1)):
        column = max(free, key=lambda c: scaled[k, c])
        order[k] = column
        free.remove(column)
    return order
