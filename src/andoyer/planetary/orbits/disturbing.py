r"""The secular Hamiltonian of the planets: the disturbing function averaged, expanded and summed.

**Variables.** Poincaré's canonical heliocentric variables (Laskar & Robutel 1995, *Celest.
Mech.* 62, 193): heliocentric positions ``r_j`` and barycentric momenta ``p_j``, with
``β_j = m_0 m_j/(m_0 + m_j)``, ``μ_j = G(m_0 + m_j)``, ``Λ_j = β_j √(μ_j a_j)`` and

.. math:: x_j = \sqrt{2\Lambda_j(1-\sqrt{1-e_j^2})}\; e^{i\varpi_j}, \qquad
          y_j = \sqrt{2\Lambda_j\sqrt{1-e_j^2}\,(1-\cos i_j)}\; e^{i\Omega_j},

canonical as ``(x_j, −i x̄_j)``, ``(y_j, −i ȳ_j)``: ``ẋ_j = −2i ∂H/∂x̄_j``, ``ẏ_j = −2i ∂H/∂ȳ_j``,
the Poisson bracket ``{f, g}_x = −2i Σ_j (∂_{x_j} f ∂_{x̄_j} g − ∂_{x̄_j} f ∂_{x_j} g)``.
The Hamiltonian (units ``G = 1``, masses as ``GM`` in au³/yr², years) is

.. math:: H = \sum_j \Big(\frac{|p_j|^2}{2\beta_j} - \frac{\mu_j\beta_j}{r_j}\Big)
        + \sum_{j<k} \Big(\frac{p_j\cdot p_k}{m_0} - \frac{m_j m_k}{|r_j-r_k|}\Big)
        = H_0(\Lambda) + H_1(\lambda, \Lambda, x, y).

**First order in the masses.** The secular Hamiltonian is the average of ``H_1`` over the
mean longitudes, ``K_1 = ⟨H_1⟩`` (the indirect part ``p_j·p_k/m_0`` averages to zero), a sum
over pairs. Each pair's average is expanded in ``u = x/√Λ``, ``v = y/√Λ`` (≈ ``e e^{iϖ}``,
``i e^{iΩ}``) to degree ``D`` (4 by default) by jet arithmetic
(:mod:`andoyer.planetary.orbits.jets`): the positions of the two Kepler orbits as truncated
series in ``(u, ū, v, v̄)`` (Kepler's equation solved by iteration on series), the mutual
distance ``Δ² = D_0 + δ`` with ``D_0`` the circular coplanar value, ``Δ^{-1} = Σ_n
\binom{-1/2}{n} D_0^{-1/2-n} δ^n``, and the double average over the two mean longitudes by
the trapezoidal rule on an ``N × N`` grid. The expansion is the classical literal one
(Laplace coefficients appear as the averages of ``D_0^{-s}``), carried out numerically: the
Taylor coefficients are exact to round-off once ``N`` resolves the harmonics of
``D_0^{-1/2-D}`` (``α^N N^{2D} ≲ 10^{-17}``).

**Second order in the masses** (Lie transform, for chosen pairs): with ``H_1 − K_1 =
Σ_{k≠0} A_k e^{ik·λ}`` and the generating function ``χ = Σ A_k e^{ik·λ}/(i k·n)``, the
second-order secular Hamiltonian is ``K_2 = ½⟨\{H_1 − K_1, χ\}⟩``:

.. math:: K_2 = \sum_{k \in \text{half plane}} \Big[
   \frac{\sum_j k_j^2\, n'_j}{(k\cdot n)^2}\, A_k A_{-k}
   - \sum_j \frac{k_j}{k\cdot n}\, \frac{\partial (A_k A_{-k})}{\partial \Lambda_j}
   + \frac{i}{k\cdot n}\, \{A_k, A_{-k}\}_{x,y} \Big],
   \qquad n'_j = \frac{dn_j}{d\Lambda_j} = -\frac{3 n_j}{\Lambda_j},

``∂/∂Λ_j`` at fixed ``x, y``. The first term carries the square of the small divisor of a
near-resonance: for Jupiter and Saturn near 5:2, ``5n_6 − 2n_5`` (period ~900 yr, the great
inequality). ``A_k`` is of degree ≥ ``|k_j + k_k|`` (d'Alembert); each harmonic's products
are kept to the degree they are complete at (``|k_j + k_k| + D`` for the ``A A`` terms,
``|k_j + k_k| + D − 2`` for the bracket) and at most ``degree2`` (6 by default), so the 5:2
terms (degree 3 each) give their degree-6 part. ``k·n`` uses the planets' actual mean
motions (the second-order theory's small divisors are those of the motion, not of
Kepler's law at ``a``).

**General relativity** (per planet, not a polynomial): the averaged first post-Newtonian
correction of the Sun, ``H_{GR} = −3 μ_j² β_j /(c² a_j² \sqrt{1-e_j^2})``, which gives the
perihelion precession ``3 μ^{3/2}/(c² a^{5/2}(1−e²))`` (43″/cy for Mercury); with
``√(1−e²) = 1 − |x|²/(2Λ)`` it is a function of ``|x_j|²`` alone.

This is build-time code: :func:`pair_expansion` and :func:`secular_hamiltonian` run once
(``scripts/make_secular_model.py``) and their result ships with the package.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import numpy as np
from numpy.typing import NDArray

from andoyer.planetary.orbits.jets import JetSpace

__all__ = [
    "PairExpansion",
    "kepler_jets",
    "pair_expansion",
    "pair_grid_size",
]

Array = NDArray[np.float64]
CArray = NDArray[np.complex128]

#: The variables of one planet in its own jet space: u, ū, v, v̄.
PLANET_PAIRS = [(0, 1), (2, 3)]
#: The variables of a pair (inner j, outer k): u_j, ū_j, v_j, v̄_j, u_k, ū_k, v_k, v̄_k.
PAIR_PAIRS = [(0, 1), (2, 3), (4, 5), (6, 7)]


@cache
def _space(count: int, degree: int) -> JetSpace:
    return JetSpace(count, degree)


def kepler_jets(lam: Array, degree: int) -> tuple[CArray, CArray]:
    r"""Position and ``∂/∂λ`` of a unit Kepler orbit as jets in ``(u, ū, v, v̄)``, on a grid of λ.

    With ``z = e e^{iϖ} = u √(1 − |u|²/4)``, ``β = √(1−e²) = 1 − |u|²/2`` and
    ``ζ = sin(i/2) e^{iΩ} = v/(2√β)``: the eccentric anomaly ``E = M + Φ``,
    ``Φ = e sin(M + Φ)`` with ``e e^{iM} = z̄ e^{iλ}`` (iterated on series), the position in
    the orbit plane ``X + iY = ½(1+β) e^{iλ} e^{iΦ} + z² e^{−iλ} e^{−iΦ}/(2(1+β)) − z``
    (longitudes counted as ``ϖ + f``), turned into space by
    ``R = R_z(Ω) R_x(i) R_z(−Ω)``:

    .. math:: R = \begin{pmatrix} 1-2p^2 & 2pq & 2p\chi \\ 2pq & 1-2q^2 & -2q\chi \\
              -2p\chi & 2q\chi & 1-2p^2-2q^2 \end{pmatrix},\quad q + ip = ζ,\ χ = \cos(i/2).

    Parameters
    ----------
    lam : numpy.ndarray, shape (N,)
        Mean longitudes (radians), ``N`` equally spaced over a full turn (the ``λ``
        derivative is spectral).
    degree : int
        Truncation degree.

    Returns
    -------
    position, derivative : numpy.ndarray, shape (3, N, M)
        ``r/a`` and ``∂(r/a)/∂λ`` (so that the velocity is ``n a ∂(r/a)/∂λ``).

    Examples
    --------
    >>> r, dr = kepler_jets(np.array([0.0, np.pi / 2, np.pi, 3 * np.pi / 2]) , 1)
    >>> r[:, 1, 0].real.round(12).tolist()        # circular orbit at λ = 90°
    [0.0, 1.0, 0.0]
    """
    s = _space(4, degree)
    u, ub, v, _ = (s.variable(i) for i in range(4))
    uu = s.multiply(u, ub)
    beta = s.add_constant(-0.5 * uu, 1.0)
    root = s.power(s.add_constant(-0.25 * uu, 1.0), 0.5)
    z, zb = s.multiply(u, root), s.multiply(ub, root)
    phase = np.exp(1j * lam)[:, None]
    w, wb = zb[None, :] * phase, z[None, :] * np.conj(phase)
    phi = s.zeros(lam.shape)
    for _ in range(degree + 1):
        ep, em = s.exp(1j * phi), s.exp(-1j * phi)
        phi = (s.multiply(w, ep) - s.multiply(wb, em)) / 2j
    ep, em = s.exp(1j * phi), s.exp(-1j * phi)
    one_plus = s.add_constant(beta, 1.0)
    plane = (
        0.5 * s.multiply(one_plus, phase * ep)
        + 0.5 * s.multiply(s.multiply(s.multiply(z, z), s.power(one_plus, -1.0)), np.conj(phase) * em)
        - z[None, :]
    )
    plane_bar = s.conjugate(plane, PLANET_PAIRS)
    X, Y = 0.5 * (plane + plane_bar), (plane - plane_bar) / 2j
    zeta = 0.5 * s.multiply(v, s.power(beta, -0.5))
    zeta_bar = s.conjugate(zeta, PLANET_PAIRS)
    q, p = 0.5 * (zeta + zeta_bar), (zeta - zeta_bar) / 2j
    chi = s.power(s.add_constant(-s.multiply(zeta, zeta_bar), 1.0), 0.5)
    pp, qq, pq = s.multiply(p, p), s.multiply(q, q), s.multiply(p, q)
    pchi, qchi = s.multiply(p, chi), s.multiply(q, chi)
    position = np.stack(
        [
            s.multiply(s.add_constant(-2.0 * pp, 1.0), X) + s.multiply(2.0 * pq, Y),
            s.multiply(2.0 * pq, X) + s.multiply(s.add_constant(-2.0 * qq, 1.0), Y),
            s.multiply(-2.0 * pchi, X) + s.multiply(2.0 * qchi, Y),
        ]
    )
    harmonics = np.fft.fftfreq(lam.size, 1.0 / lam.size)
    derivative = np.fft.ifft(1j * harmonics[None, :, None] * np.fft.fft(position, axis=1), axis=1)
    return position, derivative


def pair_grid_size(alpha: float, degree: int, max_harmonic: int = 0) -> int:
    """Trapezoid nodes per longitude for a pair with semi-major-axis ratio ``alpha``.

    The trapezoidal rule's error on a harmonic is the integrand's harmonic ``N`` away from it;
    those of ``D_0^{-1/2-D}`` in ``λ_j − λ_k`` decay like
    ``m^D α^m (1 − α²)^{-D-1/2}``. The grid makes that ``< 10^{-17}`` beyond the
    ``D + 2`` harmonics the jets add in each longitude and the ``max_harmonic`` kept, rounded up
    to a multiple of 16.

    Examples
    --------
    >>> pair_grid_size(0.5, 4)      # the tail is below 1e-17 from m = 84; + 2(D + 2) = 96
    96
    """
    m = np.arange(1, 20000, dtype=float)
    tail = m**degree * alpha**m * (1.0 - alpha * alpha) ** (-degree - 0.5)
    need = int(m[np.argmax((tail < 1e-17) & (m > degree))])
    return int(16 * np.ceil((need + 2 * (degree + 2) + 2 * max_harmonic) / 16))


@dataclass(frozen=True)
class PairExpansion:
    """The averaged interaction of two planets, and its harmonics, in ``(u, v)`` jets.

    Attributes
    ----------
    degree : int
        Jet degree ``D``.
    mean : numpy.ndarray, shape (M,)
        ``K_1 = ⟨H_1⟩`` as a jet in ``u_j, ū_j, v_j, v̄_j, u_k, ū_k, v_k, v̄_k``.
    harmonics : numpy.ndarray, shape (K, 2) or (0, 2)
        The wave vectors ``k = (k_j, k_k)`` kept (when asked for).
    amplitudes, d_inner, d_outer : numpy.ndarray, shape (K, M)
        ``A_k`` and ``∂A_k/∂a_j``, ``∂A_k/∂a_k`` at fixed ``u, v``.
    """

    degree: int
    mean: CArray
    harmonics: NDArray[np.int64]
    amplitudes: CArray
    d_inner: CArray
    d_outer: CArray


def pair_expansion(
    sun: float,
    masses: tuple[float, float],
    axes: tuple[float, float],
    degree: int = 4,
    nodes: int | None = None,
    max_harmonic: int = 0,
    chunk: int = 8,
) -> PairExpansion:
    """Expand the interaction of planets ``j`` (inner) and ``k`` (outer) in ``u, v`` and average it.

    Parameters
    ----------
    sun : float
        ``m_0`` (GM, au³/yr²).
    masses : tuple of float
        ``(m_j, m_k)`` (GM).
    axes : tuple of float
        ``(a_j, a_k)``, au, ``a_j < a_k``.
    degree : int
        Jet degree ``D``.
    nodes : int, optional
        Trapezoid nodes per longitude (default :func:`pair_grid_size`).
    max_harmonic : int
        Keep the harmonics ``|k_j|, |k_k| ≤ max_harmonic`` of ``H_1`` and their ``a``
        derivatives (for the second order); 0: only the average.
    chunk : int
        Rows of the grid per vectorised block (memory ``chunk · N · M`` complex numbers).

    Returns
    -------
    PairExpansion

    Examples
    --------
    The circular coplanar average is ``−m_j m_k ⟨1/Δ⟩ = −m_j m_k b_{1/2}^{(0)}(α)/(2 a_k)``, with
    the Laplace coefficient ``b_{1/2}^{(0)}(1/2) = 2.1463640143`` (mpmath quadrature of
    ``(1/π)∫₀^{2π} (1 − 2α cos ψ + α²)^{−1/2} dψ``):

    >>> e = pair_expansion(1.0, (1e-3, 1e-3), (1.0, 2.0), degree=2, nodes=64)
    >>> round(float(-e.mean[0].real / 1e-6 * 2.0 * 2.0), 10)      # b_{1/2}^{(0)}(1/2)
    2.1463640143
    """
    (mj, mk), (aj, ak) = masses, axes
    if not (0 < aj < ak):
        msg = f"expected 0 < a_inner < a_outer, got {aj!r} and {ak!r}"
        raise ValueError(msg)
    N = nodes or pair_grid_size(aj / ak, degree, max_harmonic)
    pair = _space(8, degree)
    planet = _space(4, degree)
    lam = 2.0 * np.pi * np.arange(N) / N
    rho, drho = kepler_jets(lam, degree)
    rj = pair.embed(rho, planet, [0, 1, 2, 3])
    rk = pair.embed(rho, planet, [4, 5, 6, 7])
    vj = pair.embed(drho, planet, [0, 1, 2, 3])
    vk = pair.embed(drho, planet, [4, 5, 6, 7])
    norm_j = pair.multiply(rj[0], rj[0]) + pair.multiply(rj[1], rj[1]) + pair.multiply(rj[2], rj[2])
    norm_k = pair.multiply(rk[0], rk[0]) + pair.multiply(rk[1], rk[1]) + pair.multiply(rk[2], rk[2])
    betaj, betak = sun * mj / (sun + mj), sun * mk / (sun + mk)
    nj, nk = np.sqrt((sun + mj) / aj**3), np.sqrt((sun + mk) / ak**3)
    indirect = betaj * betak / sun * nj * aj * nk * ak
    c_half = [_binomial(-0.5, n) for n in range(degree + 1)]
    c_three = [_binomial(-1.5, n) for n in range(degree + 1)]
    K = max_harmonic
    kk = np.r_[0 : K + 1, N - K : N] if K else np.array([0])
    kj_values = np.r_[0 : K + 1, -K:0] if K else np.array([0])
    total = pair.zeros((3, kj_values.size, kk.size))
    for start in range(0, N, chunk):
        rows = slice(start, min(start + chunk, N))
        dot = sum(pair.multiply(rj[c, rows, None, :], rk[c, None, :, :]) for c in range(3))
        vdot = sum(pair.multiply(vj[c, rows, None, :], vk[c, None, :, :]) for c in range(3))
        D = aj * aj * norm_j[rows, None, :] + ak * ak * norm_k[None, :, :] - 2.0 * aj * ak * dot
        D0 = D[..., 0].real
        delta = D.copy()
        delta[..., 0] = 0.0
        inv1 = pair.constant(D0**-0.5)
        inv3 = pair.constant(D0**-1.5)
        power = None
        for n in range(1, degree + 1):
            power = delta if power is None else pair.multiply(power, delta)
            inv1 = inv1 + (c_half[n] * D0 ** (-0.5 - n))[..., None] * power
            inv3 = inv3 + (c_three[n] * D0 ** (-1.5 - n))[..., None] * power
        h_ind = indirect * vdot
        h = -mj * mk * inv1 + h_ind
        # ∂/∂a at fixed u, v: Δ^{-1} through D, the indirect part as n a ∝ a^{-1/2}.
        dD_j = 2.0 * aj * norm_j[rows, None, :] - 2.0 * ak * dot
        dD_k = 2.0 * ak * norm_k[None, :, :] - 2.0 * aj * dot
        dh_j = 0.5 * mj * mk * pair.multiply(inv3, dD_j) - h_ind / (2.0 * aj)
        dh_k = 0.5 * mj * mk * pair.multiply(inv3, dD_k) - h_ind / (2.0 * ak)
        block = np.stack([h, dh_j, dh_k])  # (3, rows, N, M)
        spectrum = np.fft.fft(block, axis=2)[:, :, kk, :] / N  # harmonics in λ_k
        weights = np.exp(-1j * np.outer(kj_values, lam[rows])) / N  # harmonics in λ_j
        total += np.einsum("ja,xakm->xjkm", weights, spectrum)
    mean = total[0, 0, 0]
    if not K:
        empty = np.zeros((0, pair.size), dtype=complex)
        return PairExpansion(degree, mean, np.zeros((0, 2), dtype=np.int64), empty, empty, empty)
    kj_grid = np.repeat(kj_values, kk.size)
    kk_signed = np.where(kk > N // 2, kk - N, kk)
    kk_grid = np.tile(kk_signed, kj_values.size)
    harmonics = np.stack([kj_grid, kk_grid], axis=1)
    flat = total.reshape(3, -1, pair.size)
    keep = np.any(harmonics != 0, axis=1)
    return PairExpansion(degree, mean, harmonics[keep], flat[0][keep], flat[1][keep], flat[2][keep])


def _binomial(x: float, n: int) -> float:
    out = 1.0
    for i in range(n):
        out *= (x - i) / (i + 1)
    return out


def _planet_degrees(space: JetSpace) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """Degree of each monomial in the inner planet's variables and in the outer planet's."""
    e = space.exponents
    return e[:, :4].sum(axis=1), e[:, 4:].sum(axis=1)


def second_order(
    expansion: PairExpansion,
    Lambda: tuple[float, float],
    axes: tuple[float, float],
    motions: tuple[float, float],
    degree2: int = 6,
    batch: int = 32,
) -> CArray:
    r"""The second-order secular Hamiltonian ``K_2`` of a pair, as a jet in its ``(u, v)``.

    See the module's notes for the formula. ``u = x/√Λ`` at the given ``Λ``: ``∂/∂Λ`` at
    fixed ``x`` of a coefficient ``c(a) u^m`` is ``(2a/Λ) ∂c/∂a − |m|/(2Λ) c`` per planet.

    Parameters
    ----------
    expansion : PairExpansion
        With its harmonics (``pair_expansion(..., max_harmonic > 0)``).
    Lambda, axes : tuple of float
        ``(Λ_j, Λ_k)`` and ``(a_j, a_k)`` of the expansion.
    motions : tuple of float
        Mean motions ``(n_j, n_k)``, rad/yr: the small divisors ``k·n``.
    degree2 : int
        Highest degree kept.
    batch : int
        Harmonics per vectorised block.

    Returns
    -------
    numpy.ndarray of complex, shape (M₂,)
        ``K_2`` in the jet space of 8 variables and degree ``degree2``.
    """
    D = expansion.degree
    small, big = _space(8, D), _space(8, degree2)
    deg_j, deg_k = _planet_degrees(small)
    Lj, Lk = Lambda
    aj, ak = axes
    nj, nk = motions
    slope_j, slope_k = -3.0 * nj / Lj, -3.0 * nk / Lk
    k = expansion.harmonics
    index = {tuple(row): i for i, row in enumerate(k.tolist())}
    half = [i for i, (kj, kk) in enumerate(k.tolist()) if kj > 0 or (kj == 0 and kk > 0)]
    partner = np.array([index[(-k[i, 0], -k[i, 1])] for i in half])
    half = np.array(half)

    def d_lambda(amp: CArray, d_inner: CArray, d_outer: CArray) -> tuple[CArray, CArray]:
        dj = (2.0 * aj / Lj) * d_inner - deg_j / (2.0 * Lj) * amp
        dk = (2.0 * ak / Lk) * d_outer - deg_k / (2.0 * Lk) * amp
        return dj, dk

    def lift(jet: CArray) -> CArray:
        return big.embed(jet, small, list(range(8)))

    scale = np.array([Lj, Lj, Lj, Lj, Lk, Lk, Lk, Lk])
    out = big.zeros()
    for start in range(0, half.size, batch):
        sel, par = half[start : start + batch], partner[start : start + batch]
        kj, kk = k[sel, 0].astype(float), k[sel, 1].astype(float)
        omega = kj * nj + kk * nk
        order = np.abs(k[sel, 0] + k[sel, 1])
        A, B = expansion.amplitudes[sel], expansion.amplitudes[par]
        dAj, dAk = d_lambda(A, expansion.d_inner[sel], expansion.d_outer[sel])
        dBj, dBk = d_lambda(B, expansion.d_inner[par], expansion.d_outer[par])
        product = big.multiply(lift(A), lift(B))
        d_product_j = big.multiply(lift(dAj), lift(B)) + big.multiply(lift(A), lift(dBj))
        d_product_k = big.multiply(lift(dAk), lift(B)) + big.multiply(lift(A), lift(dBk))
        bracket = big.zeros((sel.size,))
        for var, bar in PAIR_PAIRS:
            factor = -2j / scale[var]
            bracket += factor * (
                big.multiply(lift(small.derivative(A, var)), lift(small.derivative(B, bar)))
                - big.multiply(lift(small.derivative(A, bar)), lift(small.derivative(B, var)))
            )
        first = ((kj**2 * slope_j + kk**2 * slope_k) / omega**2)[:, None] * product
        first -= (kj / omega)[:, None] * d_product_j + (kk / omega)[:, None] * d_product_k
        third = (1j / omega)[:, None] * bracket
        keep_first = big.degrees[None, :] <= np.minimum(degree2, order + D)[:, None]
        keep_third = big.degrees[None, :] <= np.minimum(degree2, order + D - 2)[:, None]
        out += np.sum(np.where(keep_first, first, 0.0) + np.where(keep_third, third, 0.0), axis=0)
    return out


def to_poincare(
    jet: CArray, space: JetSpace, planets: tuple[int, int], Lambda: tuple[float, float], count: int = 8
) -> dict[tuple[int, ...], complex]:
    """A pair's jet in ``(u, v)`` as terms of the global Poincaré polynomial.

    The global variables are ``x_1…x_P, x̄_1…x̄_P, y_1…y_P, ȳ_1…ȳ_P`` (``P = count``);
    ``u = x/√Λ`` turns a coefficient ``c`` of ``u^m`` into ``c Λ_j^{−|m_j|/2} Λ_k^{−|m_k|/2}``.
    Terms of degree 0 (constants), and those that d'Alembert's rules make zero (a nonzero
    total phase, an odd degree in the inclinations: round-off), are dropped.

    Returns
    -------
    dict
        Exponents (length ``4P``) → coefficient.
    """
    j, k = planets
    Lj, Lk = Lambda
    where = [j, count + j, 2 * count + j, 3 * count + j, k, count + k, 2 * count + k, 3 * count + k]
    e = space.exponents
    charge = e[:, 0] - e[:, 1] + e[:, 2] - e[:, 3] + e[:, 4] - e[:, 5] + e[:, 6] - e[:, 7]
    odd_y = (e[:, 2] + e[:, 3] + e[:, 6] + e[:, 7]) % 2 == 1
    keep = (space.degrees > 0) & (charge == 0) & ~odd_y & (jet != 0)
    deg_j, deg_k = _planet_degrees(space)
    scale = Lj ** (-0.5 * deg_j) * Lk ** (-0.5 * deg_k)
    out: dict[tuple[int, ...], complex] = {}
    for i in np.nonzero(keep)[0]:
        full = [0] * (4 * count)
        for position, power in zip(where, e[i], strict=True):
            full[position] += int(power)
        out[tuple(full)] = complex(jet[i] * scale[i])
    return out


def secular_hamiltonian(
    sun: float,
    gm: Array,
    a: Array,
    Lambda: Array,
    n: Array,
    degree: int = 4,
    second_order_pairs: tuple[tuple[int, int], ...] = ((4, 5),),
    degree2: int = 6,
    max_harmonic: int = 16,
    high_degree_pairs: tuple[tuple[int, int], ...] = (),
    high_degree: int = 6,
    progress=None,
) -> tuple[NDArray[np.int64], CArray]:
    """The polynomial secular Hamiltonian of the planets in Poincaré variables.

    Parameters
    ----------
    sun : float
        ``m_0`` (GM).
    gm, a, Lambda, n : numpy.ndarray, shape (P,)
        Masses (GM), mean semi-major axes, ``Λ`` and mean motions (rad/yr), Sun outwards.
    degree : int
        Degree of the first-order expansion.
    second_order_pairs : tuple of (int, int)
        Pairs (inner, outer) whose second-order terms are added.
    degree2 : int
        Highest degree of the second-order terms.
    max_harmonic : int
        Harmonics kept for the second order.
    high_degree_pairs : tuple of (int, int)
        Pairs expanded to ``high_degree`` instead of ``degree``.
    high_degree : int
    progress : callable, optional
        Called with a message per pair.

    Returns
    -------
    exponents : numpy.ndarray of int, shape (T, 4P)
        Over ``x, x̄, y, ȳ`` (see :func:`to_poincare`).
    coefficients : numpy.ndarray of complex, shape (T,)
    """
    count = len(gm)
    terms: dict[tuple[int, ...], complex] = {}
    for j in range(count):
        for k in range(j + 1, count):
            with_second = (j, k) in second_order_pairs
            D = high_degree if (j, k) in high_degree_pairs else degree
            expansion = pair_expansion(
                sun, (gm[j], gm[k]), (a[j], a[k]), D, max_harmonic=max_harmonic if with_second else 0,
                chunk=1 if D > 4 else 8,
            )  # fmt: skip
            parts = [(expansion.mean, _space(8, D))]
            if with_second:
                k2 = second_order(expansion, (Lambda[j], Lambda[k]), (a[j], a[k]), (n[j], n[k]), degree2)
                parts.append((k2, _space(8, degree2)))
            for jet, space in parts:
                for key, value in to_poincare(jet, space, (j, k), (Lambda[j], Lambda[k]), count).items():
                    terms[key] = terms.get(key, 0.0) + value
            if progress is not None:
                progress(f"pair {j}-{k}{' (second order)' if with_second else ''}")
    keys = sorted(terms, key=lambda m: (sum(m), m))
    return np.array(keys, dtype=np.int64), np.array([terms[m] for m in keys])


def relativity_constant(sun: float, gm: Array, a: Array, c: float) -> Array:
    """``K_j = 3 μ_j² β_j/(c² a_j²)`` of the averaged relativistic term ``−K_j/√(1−e_j²)``.

    Parameters
    ----------
    sun : float
        ``m_0`` (GM, au³/yr²).
    gm, a : numpy.ndarray, shape (P,)
        Masses (GM) and semi-major axes (au).
    c : float
        Speed of light (au/yr).

    Returns
    -------
    numpy.ndarray, shape (P,)

    Examples
    --------
    >>> K = relativity_constant(39.47692642, np.array([6.5536e-6]), np.array([0.3871]), 63241.077)
    >>> beta = 39.47692642 * 6.5536e-6 / (39.47692642 + 6.5536e-6)
    >>> L = beta * np.sqrt(39.47692642 * 0.3871)
    >>> round(float(K[0] / L / 4.8481368e-6 * 100 / (1 - 0.2056**2)), 1)  # ″/cy, Mercury
    43.0
    """
    mu = sun + np.asarray(gm, dtype=float)
    beta = sun * np.asarray(gm, dtype=float) / mu
    return 3.0 * mu * mu * beta / (c * c * np.asarray(a, dtype=float) ** 2)
