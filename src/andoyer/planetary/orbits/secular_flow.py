r"""The flow of the secular Hamiltonian: compiled right-hand side and an 8th-order Lawson integrator.

**Equations.** The state is ``w = (x_1…x_P, y_1…y_P)`` (Poincaré variables, see
:mod:`andoyer.planetary.orbits.disturbing`), ``ẇ = −2i ∂H/∂w̄``. The Hamiltonian is a
polynomial ``Σ_t c_t Π_v w_v^{m_{tv}}`` over ``x, x̄, y, ȳ`` plus the relativistic term
``Σ_j −K_j/(1 − |x_j|²/(2Λ_j))``. Its quadratic part gives the linear flow ``ẇ = L w``
(the Laplace–Lagrange equations, with relativity's first term); the rest, ``N(w)``, is
evaluated term by term from the stored derivative monomials
``∂H/∂w̄_b = Σ c_t m_{tb} w^{m_t − e_b}`` (:class:`FlowTerms`).

**Integrator.** Lawson's integrating-factor method (Lawson 1967, *SIAM J. Numer. Anal.* 4,
372): in ``v = e^{−Lτ} w`` the equation ``v̇ = e^{−Lτ} N(e^{Lτ} v)`` has only the small
nonlinear part on its right-hand side, and is stepped by the 12-stage, 8th-order
Runge–Kutta method of Dormand & Prince (Hairer, Nørsett & Wanner 1993, the tableau of
scipy's ``DOP853``), with fixed steps; the linear flow ``e^{L c_i h}`` of each stage is a
precomputed matrix exponential, so the quadratic part of ``H`` is integrated exactly and the
step error is that of ``N`` alone (order 8, ``tests/planetary/orbits/test_orbits_secular.py``).
The step is set from the fastest linear frequency (:func:`default_step`).

**Output.** The kernel stores, every step, the chosen components of ``w`` and of ``ẇ``
(``ẇ = L w + N(w)``, the first stage's evaluation): cubic Hermite interpolation between
them gives ``w`` at any time (:func:`hermite`).

Examples
--------
>>> terms = FlowTerms.from_polynomial(np.array([[1, 0, 1, 0]]), np.array([-0.5 + 0j]), 1)
>>> terms.linear.round(12).tolist()      # H = −½ x x̄: ẋ = i x (a frequency of 1)
[[1j, 0j], [0j, 0j]]
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from andoyer._jit import jit

__all__ = ["FlowTerms", "default_step", "hermite", "integrate", "lawson_matrices"]

CArray = NDArray[np.complex128]
IArray = NDArray[np.int64]

@dataclass(frozen=True)
class FlowTerms:
    """The secular Hamiltonian arranged for the compiled flow.

    Attributes
    ----------
    count : int
        Planets ``P`` (the state has ``2P`` complex components).
    linear : numpy.ndarray of complex, shape (2P, 2P)
        ``L``: ``ẇ = L w`` from the quadratic terms and relativity's quadratic part.
    width : int
        One more than the highest power of a variable in a monomial.
    start : numpy.ndarray of int, shape (2P + 1,)
        The derivative monomials of ``∂H/∂w̄_b`` are rows ``start[b]`` to ``start[b+1]``.
    coefficient : numpy.ndarray of complex, shape (T,)
    factor_start : numpy.ndarray of int, shape (T + 1,)
    factor_index : numpy.ndarray of int, shape (F,)
        Row ``d`` is ``coefficient[d] Π_f powers[factor_index[f]]`` over ``f`` from
        ``factor_start[d]`` to ``factor_start[d+1]``, with ``powers[v·width + p] = w_v^p``
        (variables ``0…4P−1`` = ``x, x̄, y, ȳ``).
    energy_coefficient : numpy.ndarray of complex, shape (E,)
    energy_start, energy_index : numpy.ndarray of int
        The polynomial itself, in the same layout (for :func:`energy`).
    gr_constant, gr_lambda : numpy.ndarray, shape (P,)
        ``K_j`` and ``Λ_j`` of the relativistic term (zeros: no relativity).
    """

    count: int
    linear: CArray
    width: int
    start: IArray
    coefficient: CArray
    factor_start: IArray
    factor_index: IArray
    energy_coefficient: CArray
    energy_start: IArray
    energy_index: IArray
    gr_constant: NDArray[np.float64]
    gr_lambda: NDArray[np.float64]

    @classmethod
    def from_polynomial(
        cls,
        exponents: IArray,
        coefficients: CArray,
        count: int,
        gr_constant: NDArray[np.float64] | None = None,
        Lambda: NDArray[np.float64] | None = None,
    ) -> FlowTerms:
        """Arrange a polynomial Hamiltonian (exponents over ``x, x̄, y, ȳ``) for the flow.

        Parameters
        ----------
        exponents : numpy.ndarray of int, shape (T, 4P)
        coefficients : numpy.ndarray of complex, shape (T,)
        count : int
            ``P``.
        gr_constant, Lambda : numpy.ndarray, shape (P,), optional
            The relativistic term ``−K_j/(1 − |x_j|²/(2Λ_j))``.
        """
        exponents = np.asarray(exponents, dtype=np.int64)
        coefficients = np.asarray(coefficients, dtype=complex)
        P = count
        gr = np.zeros(P) if gr_constant is None else np.asarray(gr_constant, dtype=float)
        lam = np.ones(P) if Lambda is None else np.asarray(Lambda, dtype=float)
        linear = np.zeros((2 * P, 2 * P), dtype=complex)
        plain = np.r_[0:P, 2 * P : 3 * P]  # the columns of x, y among x, x̄, y, ȳ
        bars = np.r_[P : 2 * P, 3 * P : 4 * P]
        width = int(exponents.max()) + 1 if exponents.size else 2
        rows: list[list[tuple[complex, list[int]]]] = [[] for _ in range(2 * P)]
        for m, c in zip(exponents, coefficients, strict=True):
            if m.sum() == 2:
                # c w_a w̄_b: ∂H/∂w̄_b gets c w_a, ẇ_b = −2i c w_a.
                (b,) = np.nonzero(m[bars])[0]
                (a,) = np.nonzero(m[plain])[0]
                linear[b, a] += -2j * c
                continue
            for b, column in enumerate(bars):
                if m[column] == 0:
                    continue
                reduced = m.copy()
                reduced[column] -= 1
                nz = np.nonzero(reduced)[0]
                rows[b].append((c * m[column], (nz * width + reduced[nz]).tolist()))
        # Relativity's quadratic part −K(1 + |x|²/(2Λ) + …) is linear in the flow: ẋ = i (K/Λ) x.
        linear[np.arange(P), np.arange(P)] += 1j * gr / lam
        flat = [row for block in rows for row in block]
        start = np.cumsum([0] + [len(block) for block in rows])
        energy_rows = []
        for m, c in zip(exponents, coefficients, strict=True):
            nz = np.nonzero(m)[0]
            energy_rows.append((c, (nz * width + m[nz]).tolist()))
        return cls(
            count=P,
            linear=linear,
            width=width,
            start=np.asarray(start, dtype=np.int64),
            coefficient=np.array([c for c, _ in flat], dtype=complex),
            factor_start=np.cumsum([0] + [len(f) for _, f in flat]).astype(np.int64),
            factor_index=np.array([i for _, f in flat for i in f], dtype=np.int64),
            energy_coefficient=np.array([c for c, _ in energy_rows], dtype=complex),
            energy_start=np.cumsum([0] + [len(f) for _, f in energy_rows]).astype(np.int64),
            energy_index=np.array([i for _, f in energy_rows for i in f], dtype=np.int64),
            gr_constant=gr,
            gr_lambda=lam,
        )

    def arrays(self) -> tuple:
        """The arrays the compiled kernels take, in their order."""
        return (
            self.width, self.start, self.coefficient, self.factor_start, self.factor_index,
            self.gr_constant, self.gr_lambda,
        )  # fmt: skip


@jit
def _powers(w, P, width, out) -> None:
    """``out[v·width + p] = w_v^p`` for the ``4P`` variables ``x, x̄, y, ȳ`` and ``p < width``."""
    for v in range(4 * P):
        j = v % P
        block = v // P
        if block == 0:
            value = w[j]
        elif block == 1:
            value = np.conj(w[j])
        elif block == 2:
            value = w[P + j]
        else:
            value = np.conj(w[P + j])
        base = v * width
        out[base] = 1.0
        for p in range(1, width):
            out[base + p] = out[base + p - 1] * value


@jit
def _nonlinear(w, P, width, start, coefficient, factor_start, factor_index, gr_constant, gr_lambda, powers, out):
    """``N(w)``: the flow of the terms of degree ≥ 4 and of relativity beyond its quadratic part."""
    _powers(w, P, width, powers)
    for b in range(2 * P):
        acc = 0.0 + 0.0j
        for d in range(start[b], start[b + 1]):
            value = coefficient[d]
            for f in range(factor_start[d], factor_start[d + 1]):
                value = value * powers[factor_index[f]]
            acc += value
        out[b] = -2j * acc
    for j in range(P):
        if gr_constant[j] != 0.0:
            s = (w[j].real * w[j].real + w[j].imag * w[j].imag) / (2.0 * gr_lambda[j])
            out[j] += 1j * gr_constant[j] / gr_lambda[j] * w[j] * (1.0 / ((1.0 - s) * (1.0 - s)) - 1.0)


@jit
def _matvec(M, v, out) -> None:
    n = v.size
    for i in range(n):
        acc = 0.0 + 0.0j
        for k in range(n):
            acc += M[i, k] * v[k]
        out[i] = acc


@jit
def integrate(
    w0, steps, h, a_matrix, b_weights, forward, backward, width, start, coefficient, factor_start,
    factor_index, gr_constant, gr_lambda, linear, keep, out_w, out_dw, extreme,
) -> None:  # fmt: skip
    """Take ``steps`` Lawson–DOP853 steps of size ``h`` from ``w0``; store ``keep`` components every step.

    Parameters
    ----------
    w0 : numpy.ndarray of complex, shape (2P,)
        The state at the start; overwritten with the state at the end.
    steps : int
    h : float
        The step (years; negative integrates backwards).
    a_matrix : numpy.ndarray, shape (S, S)
    b_weights : numpy.ndarray, shape (S,)
        The Runge–Kutta tableau (``S`` stages, ``c_1 = 0``).
    forward, backward : numpy.ndarray of complex, shape (S, 2P, 2P)
        ``e^{L c_i h}`` and ``e^{−L c_i h}`` per stage; ``forward[S−1]`` must be ``e^{Lh}``
        (``c_S = 1``).
    width, start, coefficient, factor_start, factor_index, gr_constant, gr_lambda
        :meth:`FlowTerms.arrays`.
    linear : numpy.ndarray of complex, shape (2P, 2P)
        ``L``.
    keep : numpy.ndarray of int, shape (K,)
        Components stored.
    out_w, out_dw : numpy.ndarray of complex, shape (steps + 1, K)
        ``w`` and ``ẇ`` at the start and after every step.
    extreme : numpy.ndarray, shape (2P,)
        Raised to the largest ``|w_b|²`` met (at the steps).
    """
    n = w0.size
    P = n // 2
    S = b_weights.size
    powers = np.empty(2 * n * width, dtype=np.complex128)
    K = np.empty((S, n), dtype=np.complex128)
    v = np.empty(n, dtype=np.complex128)
    x = np.empty(n, dtype=np.complex128)
    tmp = np.empty(n, dtype=np.complex128)
    lin = np.empty(n, dtype=np.complex128)
    w = w0.copy()
    for step in range(steps + 1):
        for b in range(n):
            size = w[b].real * w[b].real + w[b].imag * w[b].imag
            if size > extreme[b]:
                extreme[b] = size
        # Stage 1 (c = 0): N(w), which with L w is also the derivative stored at this step.
        _nonlinear(w, P, width, start, coefficient, factor_start, factor_index, gr_constant, gr_lambda, powers, tmp)
        for b in range(n):
            K[0, b] = tmp[b]
        _matvec(linear, w, lin)
        for c in range(keep.size):
            out_w[step, c] = w[keep[c]]
            out_dw[step, c] = lin[keep[c]] + tmp[keep[c]]
        if step == steps:
            break
        for i in range(1, S):
            for b in range(n):
                acc = 0.0 + 0.0j
                for j in range(i):
                    if a_matrix[i, j] != 0.0:
                        acc += a_matrix[i, j] * K[j, b]
                v[b] = w[b] + h * acc
            _matvec(forward[i], v, x)
            _nonlinear(x, P, width, start, coefficient, factor_start, factor_index, gr_constant, gr_lambda, powers, tmp)
            _matvec(backward[i], tmp, x)
            for b in range(n):
                K[i, b] = x[b]
        for b in range(n):
            acc = 0.0 + 0.0j
            for i in range(S):
                acc += b_weights[i] * K[i, b]
            v[b] = w[b] + h * acc
        _matvec(forward[S - 1], v, w)
    for b in range(n):
        w0[b] = w[b]


def lawson_matrices(linear: CArray, h: float) -> tuple[NDArray, NDArray, CArray, CArray]:
    """The DOP853 tableau and the stage exponentials ``e^{±L c_i h}`` for a step ``h``.

    Returns
    -------
    a_matrix : numpy.ndarray, shape (12, 12)
    b_weights : numpy.ndarray, shape (12,)
    forward, backward : numpy.ndarray of complex, shape (12, 2P, 2P)
    """
    from scipy.integrate._ivp import dop853_coefficients as tableau
    from scipy.linalg import expm

    S = tableau.N_STAGES
    c = tableau.C[:S]
    forward = np.stack([expm(linear * (ci * h)) for ci in c])
    backward = np.stack([expm(-linear * (ci * h)) for ci in c])
    return np.ascontiguousarray(tableau.A[:S, :S]), np.ascontiguousarray(tableau.B), forward, backward


def default_step(linear: CArray, fraction: float = 1.0 / 64.0) -> float:
    """The step: ``fraction`` of the shortest period of the linear flow (years).

    Examples
    --------
    >>> default_step(np.diag([1j * 2 * np.pi / 64000.0, 0j]))
    1000.0
    """
    rates = np.abs(np.linalg.eigvals(linear))
    return float(fraction * 2.0 * np.pi / rates.max())


def hermite(t: NDArray, t0: float, h: float, w: CArray, dw: CArray) -> CArray:
    """Cubic Hermite interpolation of samples ``w`` (and derivatives ``dw``) every ``h`` from ``t0``.

    Parameters
    ----------
    t : numpy.ndarray, shape (N,)
        Times within the samples.
    t0, h : float
        Time of the first sample and the (signed) spacing.
    w, dw : numpy.ndarray of complex, shape (M, K)

    Returns
    -------
    numpy.ndarray of complex, shape (N, K)

    Examples
    --------
    >>> s = np.array([0.0, 1.0, 2.0])[:, None]
    >>> hermite(np.array([0.5, 1.5]), 0.0, 1.0, s ** 3 + 0j, 3 * s ** 2 + 0j).real.ravel().tolist()
    [0.125, 3.375]
    """
    position = (np.asarray(t, dtype=float) - t0) / h
    i = np.clip(np.floor(position).astype(np.int64), 0, len(w) - 2)
    s = (position - i)[:, None]
    h00 = (1.0 + 2.0 * s) * (1.0 - s) ** 2
    h10 = s * (1.0 - s) ** 2
    h01 = s * s * (3.0 - 2.0 * s)
    h11 = s * s * (s - 1.0)
    return h00 * w[i] + h10 * h * dw[i] + h01 * w[i + 1] + h11 * h * dw[i + 1]


@jit
def _energy_kernel(w, P, width, start, coefficient, factor_index, gr_constant, gr_lambda, powers) -> complex:
    _powers(w, P, width, powers)
    total = 0.0 + 0.0j
    for d in range(coefficient.size):
        value = coefficient[d]
        for f in range(start[d], start[d + 1]):
            value = value * powers[factor_index[f]]
        total += value
    for j in range(P):
        if gr_constant[j] != 0.0:
            s = (w[j].real * w[j].real + w[j].imag * w[j].imag) / (2.0 * gr_lambda[j])
            total += -gr_constant[j] / (1.0 - s)
    return total


def energy(terms: FlowTerms, w: CArray) -> float:
    """The secular Hamiltonian at the state ``w`` (its imaginary part is round-off).

    Parameters
    ----------
    terms : FlowTerms
    w : numpy.ndarray of complex, shape (2P,)

    Returns
    -------
    float

    Examples
    --------
    >>> terms = FlowTerms.from_polynomial(np.array([[1, 0, 1, 0]]), np.array([-0.5 + 0j]), 1)
    >>> energy(terms, np.array([2.0 + 0j, 0j]))
    -2.0
    """
    powers = np.empty(4 * terms.count * terms.width, dtype=complex)
    value = _energy_kernel(
        np.ascontiguousarray(w, dtype=complex), terms.count, terms.width, terms.energy_start,
        terms.energy_coefficient, terms.energy_index, terms.gr_constant, terms.gr_lambda, powers,
    )  # fmt: skip
    return float(np.real(value))
