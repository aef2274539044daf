r"""A Laplace–Lagrange secular theory of the eight planets: instant for any span.

With ``z_j = e_j exp(iϖ_j)`` and ``ζ_j = sin i_j exp(iΩ_j)`` (J2000 ecliptic), the
first-order secular equations truncated at second degree (Murray & Dermott 1999,
§7.7–7.8, eqs. 7.28–7.31 and 7.128–7.131) are linear:

.. math:: \dot z = i A z, \qquad \dot\zeta = i B \zeta,

.. math::
   A_{jj} = \frac{n_j}{4}\sum_{k\ne j}\mu_{jk}\,\alpha_{jk}\bar\alpha_{jk}\,b_{3/2}^{(1)}(\alpha_{jk}),\quad
   A_{jk} = -\frac{n_j}{4}\mu_{jk}\,\alpha_{jk}\bar\alpha_{jk}\,b_{3/2}^{(2)}(\alpha_{jk}),

.. math::
   B_{jj} = -A'_{jj}, \quad
   B_{jk} = +\frac{n_j}{4}\mu_{jk}\,\alpha_{jk}\bar\alpha_{jk}\,b_{3/2}^{(1)}(\alpha_{jk}),

with ``μ_jk = m_k/(M_☉ + m_j)``, ``α_jk = min(a_j, a_k)/max(a_j, a_k)``, ``ᾱ_jk = α_jk`` for
an outer perturber (``a_k > a_j``) and ``1`` for an inner one, and ``A'_jj`` the diagonal
sum written with ``b_{3/2}^{(1)}``. Their eigenvalues are the fundamental frequencies
``g_1…g_8`` and ``s_1…s_8`` (``s_5 = 0``: the invariable plane), labelled by rank, which
matches Laskar's labels for the Solar System (``g_8 < g_7 < g_5 < g_1 < g_2 < g_3 < g_4 < g_6``,
``s_6 < s_3 < s_4 < s_2 < s_1 < s_7 < s_8 < s_5``). The solution
``z(t) = V diag(exp(i g t)) V⁻¹ z(0)`` is fitted to the J2000 elements of
:mod:`andoyer.planetary.orbits.planets` (Standish's JPL Table 1).

Frequencies (``frequencies=``):

* ``"linear"`` (default): the eigenvalues above (the classical theory; Brouwer & van Woerkom 1950
  without their Jupiter–Saturn great-inequality correction; the BvW values the tests use are
  unverified, see ``docs/orbits.md``). Computed here:
  ``g = 5.46, 7.35, 17.33, 18.01, 3.73, 22.51, 2.71, 0.634`` and
  ``s = −5.20, −6.57, −18.75, −17.64, 0, −25.99, −2.91, −0.679`` ″/yr; La2004's
  (Laskar et al. 2004, A&A 428, 261, Table 3; some digits unverified, see :data:`LA2004_G`) are
  ``g = 5.59, 7.452, 17.368, 17.916, 4.257452, 28.2450, 3.087951, 0.673021`` and
  ``s = −5.59, −7.05, −18.850, −17.755, 0, −26.347855, −2.9925259, −0.691736``: the
  linear theory misses ``g_5`` by 0.53″/yr and ``g_6`` by 5.7″/yr (the 5:2 near-resonance
  of Jupiter and Saturn), which turns the Earth's 405-kyr eccentricity cycle
  (``g_2 − g_5``) into 359 kyr; elsewhere it is within 0.48″/yr (``s_2``).
* ``"la2004"``: the same eigenvectors with La2004's frequencies in place of the
  eigenvalues (paired by rank), amplitudes refitted to J2000: an empirical patch that
  keeps the linear theory's mode shapes and gets the periods right (the 405-kyr cycle);
  it does not make the mode shapes right, and the Earth's normal moves *further* from
  VCW 2011 with it (0.84° against 0.61° at ±200 kyr), so ``"linear"`` is the default.

Distances (measured; more in ``docs/orbits.md``): the Earth's normal (``"linear"``) is
0.038° from :class:`~andoyer.planetary.orbits.vondrak.VondrakEcliptic` over ±20 kyr and 0.61° over
±200 kyr; from :class:`~andoyer.planetary.orbits.nbody.NBodyOrbit` 0.041°, 0.66° and 2.4° over ±20 kyr,
±200 kyr and ±1 Myr, its eccentricity vector 6×10⁻⁴, 0.012 and 0.046; Mars' normal 0.13°,
1.9° and 4.5°, its eccentricity vector 0.003, 0.038 and 0.13. The theory leaves out the
second-order (great-inequality) and higher-degree secular terms: a fast, qualitative source.
"""

from __future__ import annotations

from functools import cache

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer.catalogue.units import ARCSEC
from andoyer.planetary.orbits.elements import eccentricity_from_elements
from andoyer.planetary.orbits.laplace import laplace_coefficient
from andoyer.planetary.orbits.planets import PLANETS, check_planet, planet_data
from andoyer.planetary.orbits.protocol import check_times

__all__ = ["LA2004_G", "LA2004_S", "LaplaceLagrangeOrbit", "secular_matrices"]


#: La2004 fundamental frequencies g1…g8 (″/yr), Laskar et al. (2004), A&A 428, 261, Table 3.
#: Confirmed (review, 2026): the table number (A&A's table list for the paper), g2 and g5 (as
#: Laskar et al. 2011, A&A 532, A89, Table 6 reprints them) and g3, g4. Unverified (typed in
#: from memory, no reachable source prints them): g1, g6, g7, g8; an N-body frequency analysis
#: (scripts/check_outer_frequencies.py) corroborates g5, g7, g8 within 0.05″/yr and brackets g6
#: (26.05–29.35). See docs/orbits.md.
LA2004_G = np.array([5.59, 7.452, 17.368, 17.916, 4.257452, 28.2450, 3.087951, 0.673021])
#: La2004 fundamental frequencies s1…s8 (″/yr), same table (s5 = 0: the invariable plane).
#: Confirmed: s3, s4. Unverified: s1, s2, s6, s7, s8 (s7, s8 corroborated within 0.005″/yr,
#: s6 bracketed by −26.93 and −26.32, by the same N-body check).
LA2004_S = np.array([-5.59, -7.05, -18.850, -17.755, 0.0, -26.347855, -2.9925259, -0.691736])

# Rank of each label's frequency among the eight (the Solar System's order, see above).
_G_ORDER = np.argsort(LA2004_G)
_S_ORDER = np.argsort(LA2004_S)

Array = NDArray[np.float64]


def secular_matrices(
    a: ArrayLike | None = None, gm: ArrayLike | None = None, sun: float | None = None
) -> tuple[Array, Array]:
    """The Laplace–Lagrange matrices ``A`` and ``B`` (rad/yr) of the planets.

    Parameters
    ----------
    a, gm : array_like, shape (P,), optional
        Semi-major axes (au) and GM (au³/yr²), Sun outwards; default: the shipped
        J2000 data (Standish's ``a``, DE440 masses).
    sun : float, optional
        The Sun's GM; default: the shipped one.

    Returns
    -------
    A, B : numpy.ndarray, shape (P, P)

    Examples
    --------
    >>> A, B = secular_matrices()
    >>> A.shape, bool(abs(np.linalg.eigvals(B)).min() < 1e-15)
    ((8, 8), True)
    """
    data = planet_data()
    a = data.a if a is None else np.asarray(a, dtype=float)
    m = data.gm if gm is None else np.asarray(gm, dtype=float)
    sun = data.sun_gm if sun is None else float(sun)
    n = np.sqrt((sun + m) / a**3)
    N = len(a)
    A = np.zeros((N, N))
    B = np.zeros((N, N))
    for j in range(N):
        for k in range(N):
            if k == j:
                continue
            inner = a[j] < a[k]  # j inside: k is an external perturber
            alpha = a[j] / a[k] if inner else a[k] / a[j]
            factor = n[j] / 4.0 * m[k] / (sun + m[j]) * alpha * (alpha if inner else 1.0)
            b1 = float(laplace_coefficient(1.5, 1, alpha))
            b2 = float(laplace_coefficient(1.5, 2, alpha))
            A[j, j] += factor * b1
            A[j, k] = -factor * b2
            B[j, j] -= factor * b1
            B[j, k] = factor * b1
    return A, B


@cache
def _modes(frequencies: str) -> tuple[Array, Array, NDArray[np.complex128], NDArray[np.complex128]]:
    """Labelled frequencies ``g, s`` (rad/yr) and the modes' J2000 vectors ``V diag(c)``, ``W diag(c)``."""
    data = planet_data()
    A, B = secular_matrices()
    out = []
    for matrix, published, order, z0 in (
        (A, LA2004_G, _G_ORDER, data.e * np.exp(1j * data.varpi)),
        (B, LA2004_S, _S_ORDER, np.sin(data.inclination) * np.exp(1j * data.node)),
    ):
        values, vectors = np.linalg.eig(matrix)
        rank = np.argsort(values.real)
        labelled = np.empty(8, dtype=int)
        labelled[order] = rank  # label i gets the eigenpair of the same rank as published[i]
        freq = values.real[labelled]
        vec = vectors[:, labelled]
        if frequencies == "la2004":
            freq = published * ARCSEC
        out.append((freq, vec, np.linalg.solve(vec, z0)))
    (g, V, cg), (s, W, cs) = out
    return g, s, V @ np.diag(cg), W @ np.diag(cs)


class LaplaceLagrangeOrbit:
    """A planet's orbit from the Laplace–Lagrange secular theory of the eight planets.

    Parameters
    ----------
    body : str
        One of :data:`~andoyer.planetary.orbits.planets.PLANETS` (``"earth"`` = Earth–Moon barycentre).
    frequencies : {"linear", "la2004"}
        The eigenfrequencies of the linear theory, or La2004's in their place (see the
        module's notes).

    Attributes
    ----------
    g, s : numpy.ndarray, shape (8,)
        The fundamental frequencies used, ″/yr, labelled ``g1…g8``, ``s1…s8``.

    Examples
    --------
    >>> orbit = LaplaceLagrangeOrbit("earth", frequencies="linear")
    >>> [round(float(x), 2) for x in orbit.g[:4]]
    [5.46, 7.35, 17.33, 18.01]
    >>> float(np.linalg.norm(orbit.eccentricity_vector(0.0))).__round__(8)
    0.01671123
    """

    name = "laplace-lagrange"
    span = (-np.inf, np.inf)
    has_eccentricity = True

    def __init__(self, body: str = "earth", frequencies: str = "linear") -> None:
        self.body = PLANETS[check_planet(body)]
        self._index = PLANETS.index(self.body)
        if frequencies not in ("linear", "la2004"):
            msg = f"expected frequencies 'linear' or 'la2004', got {frequencies!r}"
            raise ValueError(msg)
        self.frequencies = frequencies
        g, s, self._ecc_modes, self._inc_modes = _modes(frequencies)
        self._g, self._s = g, s
        self.g = g / ARCSEC
        self.s = s / ARCSEC

    def _complex(self, t: ArrayLike) -> tuple[NDArray[np.complex128], NDArray[np.complex128]]:
        times = check_times(t, self.span, self.name)
        # z_j(t) = Σ_i V_ji c_i exp(i g_i t), and the same for ζ with W, s.
        z = np.exp(1j * times[..., None] * self._g) @ self._ecc_modes[self._index]
        zeta = np.exp(1j * times[..., None] * self._s) @ self._inc_modes[self._index]
        return z, zeta

    def normal(self, t: ArrayLike) -> Array:
        """Unit orbit normal ``(sin i sin Ω, −sin i cos Ω, cos i)``, J2000 ecliptic frame.

        Parameters
        ----------
        t : array_like, shape (...)
            Julian years TT from J2000.

        Returns
        -------
        numpy.ndarray, shape (..., 3)
        """
        _, zeta = self._complex(t)
        p, q = zeta.imag, zeta.real
        return np.stack([p, -q, np.sqrt(1.0 - p * p - q * q)], axis=-1)

    def eccentricity_vector(self, t: ArrayLike) -> Array:
        """``e`` times the unit vector to perihelion, J2000 ecliptic frame.

        Parameters
        ----------
        t : array_like, shape (...)
            Julian years TT from J2000.

        Returns
        -------
        numpy.ndarray, shape (..., 3)
        """
        z, zeta = self._complex(t)
        return eccentricity_from_elements(np.abs(z), np.arcsin(np.abs(zeta)), np.angle(zeta), np.angle(z))

    def __repr__(self) -> str:
        return f"LaplaceLagrangeOrbit({self.body!r}, frequencies={self.frequencies!r})"


def __getattr__(name: str):
    # PEP 562: before the long secular model took the name, this class was ``SecularOrbit`` in
    # ``andoyer.orbits.secular``; that old import keeps giving the linear theory for one release.
    if name == "SecularOrbit":
        import warnings

        warnings.warn(
            "the Laplace-Lagrange theory's SecularOrbit is now LaplaceLagrangeOrbit "
            "(andoyer.planetary.orbits.laplace_lagrange); andoyer.planetary.orbits.SecularOrbit is the "
            "long secular model; the old name works until the next release",
            DeprecationWarning,
            stacklevel=2,
        )
        return LaplaceLagrangeOrbit
    msg = f"module {__name__!r} has no attribute {name!r}"
    raise AttributeError(msg)
