r"""The flow of the secular Hamiltonian: compiled right-hand side and an 8th-order Lawson integrator.

**Equations.** The state is ``w = (x_1…x_P, y_1…y_P)`` (Poincaré variables, see
:mod:`andoyer.planetary.orbits.disturbing`), ``ẇ = −2i ∂H/∂w̄``. The Hamiltonian is a
polynomial ``Σ_t c_t Π_v w_v^{m_{tv}}`` over ``x, x̄, y, ȳ`` plus the relativistic term
``Σ_j −K_j/(1 − |x_j|²/(2Λ_j))``. Its quadratic part gives the linear flow ``ẇ = L w``
(the Laplace–Lagrange equations, with relativity's first term); the rest, ``N(w)``, is
evaluated from the stored derivative monomials ``∂H/∂w̄_b = Σ c_t m_{tb} w^{m_t − e_b}``,
each monomial's largest factor taken out of the sums it shares with others (:class:`FlowTerms`).

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
>>> terms = FlowTerms.from_polynomial(np.array([[1, 1, 0, 0]]), np.array([-0.5 + 0j]), 1)
>>> terms.linear.round(12).tolist()      # H = −½ x x̄: ẋ = i x (a frequency of 1)
[[1j, 0j], [0j, 0j]]
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from andoyer._jit import jit, jitable

__all__ = [
    "FlowTerms", "default_step", "energy", "hermite", "hermite_basis", "integrate", "lawson_matrices",
    "product_tree",
]  # fmt: skip

CArray = NDArray[np.complex128]
IArray = NDArray[np.int64]

#: The DOP853 stages whose derivatives the samples within a step interpolate (nodes ``c`` = 0, 0.118,
#: 0.282, 1/3, 0.651, 0.6, 0.857, 1: degree 7, spread over the step). All twelve (degree 11) do
#: worse: the interpolant through the five nodes clustered below 0.12 swings in the sparse middle
#: (Mars' normal at mid-step off by 3″ against 0.7″ at the steps, at a 10-kyr step; this set: 0.7″).
CONTINUOUS_STAGES = (0, 3, 4, 5, 8, 9, 10, 11)

#: Groups of the right-hand side summed side by side (written out in :func:`_nonlinear`): one chain of
#: additions at a time left the processor waiting on each; four together took 10–15 % less time.
LANES = 4


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
    parent, factor : numpy.ndarray of uint32, shape (M,)
        The derivative monomials without their last factor (their *prefixes*) as a product
        tree (:func:`product_tree`): ``node[0] = 1`` and ``node[k] = node[parent[k]] · powers[factor[k]]``
        (``parent[k] < k``), with ``powers[v·width + p] = w_v^p`` (variables ``0…4P−1`` =
        ``x, x̄, y, ȳ``). A monomial's factors are sorted by variable, so monomials that share
        their leading factors share the nodes of those partial products: one complex
        multiplication per node. The index arrays are unsigned: numba then skips the
        negative-index test of every gather (a quarter of an evaluation's time).
    batch_start : numpy.ndarray of int64, shape (B + 1,)
    group_row : numpy.ndarray of int64, shape (B, LANES)
    group_power : numpy.ndarray of uint32, shape (B, LANES)
    term_node : numpy.ndarray of uint32, shape (T, LANES)
    term_coefficient : numpy.ndarray, shape (T, LANES)
        ``∂H/∂w̄_b = Σ_g powers[group_power[g]] Σ_d term_coefficient[d] node[term_node[d]]``
        over the groups ``g = (i, lane)`` of row ``b = group_row[g]`` and the rows ``d`` of
        batch ``i`` (``batch_start[i] ≤ d < batch_start[i+1]``) in that lane: the monomials of a
        row that end in the same factor are summed before it multiplies them (325 groups for
        the 1200 monomials of the shipped model: the leaves of the tree, one multiplication
        each, are gone), ``LANES`` groups of about equal length side by side, the shorter ones
        padded with zero coefficients (on node 0; an empty group has row 0 and factor
        ``w_0^0 = 1``). The coefficients are real
        (the secular Hamiltonian's are in these variables: it is even under
        ``(x, y) → (x̄, ȳ)``, the mirror image of the system with time reversed).
    energy_coefficient : numpy.ndarray, shape (E,)
    energy_factors : numpy.ndarray of int32, shape (E, F + 1)
        The polynomial itself, in the same layout (for :func:`energy`).
    gr_constant, gr_lambda : numpy.ndarray, shape (P,)
        ``K_j`` and ``Λ_j`` of the relativistic term (zeros: no relativity).
    """

    count: int
    linear: CArray
    width: int
    parent: NDArray[np.uint32]
    factor: NDArray[np.uint32]
    batch_start: IArray
    group_row: IArray
    group_power: NDArray[np.uint32]
    term_node: NDArray[np.uint32]
    term_coefficient: NDArray[np.float64]
    energy_coefficient: NDArray[np.float64]
    energy_factors: NDArray[np.int32]
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
        amplitude: NDArray[np.float64] | None = None,
        threshold: float = 0.0,
    ) -> FlowTerms:
        """Arrange a polynomial Hamiltonian (exponents over ``x, x̄, y, ȳ``) for the flow.

        Parameters
        ----------
        exponents : numpy.ndarray of int, shape (T, 4P)
        coefficients : numpy.ndarray, shape (T,)
            Real (a complex array must have imaginary parts below ``10⁻⁸`` of its moduli).
        count : int
            ``P``.
        gr_constant, Lambda : numpy.ndarray, shape (P,), optional
            The relativistic term ``−K_j/(1 − |x_j|²/(2Λ_j))``.
        amplitude : numpy.ndarray, shape (2P,), optional
            Bounds on ``|w_b|`` for the pruning.
        threshold : float
            Leave out the terms of degree ≥ 4 whose every derivative monomial, at ``amplitude``,
            is below ``threshold`` times ``Σ_a |L_ba| amplitude_a`` (the linear rate of its
            component); :func:`energy` is that of the terms kept.
        """
        exponents = np.asarray(exponents, dtype=np.int64)
        coefficients = np.asarray(coefficients)
        if np.iscomplexobj(coefficients):
            if np.any(np.abs(coefficients.imag) > 1e-8 * np.abs(coefficients)):
                msg = (
                    "expected real coefficients (imaginary parts below 1e-8 of the moduli), got complex ones"
                )
                raise ValueError(msg)
            coefficients = coefficients.real
        coefficients = coefficients.astype(float)
        P = count
        gr = np.zeros(P) if gr_constant is None else np.asarray(gr_constant, dtype=float)
        lam = np.ones(P) if Lambda is None else np.asarray(Lambda, dtype=float)
        linear = np.zeros((2 * P, 2 * P), dtype=complex)
        plain = np.r_[0:P, 2 * P : 3 * P]  # the columns of x, y among x, x̄, y, ȳ
        bars = np.r_[P : 2 * P, 3 * P : 4 * P]
        width = int(exponents.max()) + 1 if exponents.size else 2
        for m, c in zip(exponents, coefficients, strict=True):
            if m.sum() == 2:
                # c w_a w̄_b: ∂H/∂w̄_b gets c w_a, ẇ_b = −2i c w_a.
                if m[bars].sum() != 1 or m[plain].sum() != 1:
                    msg = (
                        "expected quadratic terms of the form w_a w̄_b (one plain and one barred "
                        f"variable over x, x̄, y, ȳ), got exponents {m.tolist()}"
                    )
                    raise ValueError(msg)
                (b,) = np.nonzero(m[bars])[0]
                (a,) = np.nonzero(m[plain])[0]
                linear[b, a] += -2j * c
        # Relativity's quadratic part −K(1 + |x|²/(2Λ) + …) is linear in the flow: ẋ = i (K/Λ) x.
        linear[np.arange(P), np.arange(P)] += 1j * gr / lam
        kept = np.ones(len(exponents), dtype=bool)
        if amplitude is not None and threshold > 0:
            # A term is left out when every component it drives gets less than ``threshold`` of
            # that component's linear rate (a whole term and its conjugate alike, so that the flow
            # stays the Hamiltonian flow of the terms kept).
            amp = np.asarray(amplitude, dtype=float)
            value = np.concatenate([amp[:P], amp[:P], amp[P:], amp[P:]])  # x, x̄, y, ȳ
            rate = np.abs(linear) @ amp
            component = np.concatenate([np.arange(P), np.arange(P), P + np.arange(P), P + np.arange(P)])
            # ∂(c w^m)/∂w_v at the amplitudes, over every variable of the term, barred or not (a term
            # and its conjugate agree), relative to the linear rate of the component v belongs to.
            whole = np.abs(coefficients) * np.prod(value[None, :] ** exponents, axis=1)
            with np.errstate(divide="ignore", invalid="ignore"):
                sizes = 2.0 * whole[:, None] * exponents / value[None, :] / rate[component][None, :]
            sizes = np.where(exponents > 0, sizes, 0.0)
            kept = (exponents.sum(axis=1) == 2) | (sizes.max(axis=1) >= threshold)
        rows: list[tuple[int, float, list[int]]] = []
        for m, c in zip(exponents[kept], coefficients[kept], strict=True):
            if m.sum() == 2:
                continue
            for b, column in enumerate(bars):
                if m[column] == 0:
                    continue
                reduced = m.copy()
                reduced[column] -= 1
                nz = np.nonzero(reduced)[0]
                rows.append((b, c * m[column], (nz * width + reduced[nz]).tolist()))
        # Each monomial as (its prefix) · (its last factor; w_0^0 = 1 for a constant): the monomials of
        # a row that end in the same factor share one multiplication by it.
        keys = [sorted(f) or [0] for _, _, f in rows]
        parent, factor, node_of = product_tree([key[:-1] for key in keys])
        members: dict[tuple[int, int], list[int]] = {}
        for d, ((b, _, _), key) in enumerate(zip(rows, keys, strict=True)):
            members.setdefault((b, key[-1]), []).append(d)
        # LANES groups side by side, the longest first so that those of a batch have about the same
        # length: a batch's sums are independent chains of additions, which the processor overlaps.
        groups = sorted(members, key=lambda g: (-len(members[g]), g))
        groups += [None] * (-len(groups) % LANES)  # empty groups: row 0, factor w_0^0 = 1, no terms
        batches = [groups[i : i + LANES] for i in range(0, len(groups), LANES)]
        lengths = [max(len(members[g]) if g else 0 for g in batch) for batch in batches]
        batch_start = np.concatenate([[0], np.cumsum(lengths)]).astype(np.int64)
        term_node = np.zeros((int(batch_start[-1]), LANES), dtype=np.uint32)  # padding: 0 · node 0
        term_coefficient = np.zeros((int(batch_start[-1]), LANES))
        group_row = np.zeros((len(batches), LANES), dtype=np.int64)
        group_power = np.zeros((len(batches), LANES), dtype=np.uint32)
        for i, batch in enumerate(batches):
            for lane, g in enumerate(batch):
                if g is None:
                    continue
                group_row[i, lane], group_power[i, lane] = g
                terms = sorted(members[g], key=lambda d: node_of[d])
                at = slice(batch_start[i], batch_start[i] + len(terms))
                term_node[at, lane] = [node_of[d] for d in terms]
                term_coefficient[at, lane] = [rows[d][1] for d in terms]
        energy = [
            (c, (np.nonzero(m)[0] * width + m[np.nonzero(m)[0]]).tolist())
            for m, c, k in zip(exponents, coefficients, kept, strict=True)
            if k
        ]
        wide = max([len(f) for _, f in energy], default=1)
        return cls(
            count=P,
            linear=linear,
            width=width,
            parent=parent,
            factor=factor,
            batch_start=batch_start,
            group_row=group_row,
            group_power=group_power,
            term_node=term_node,
            term_coefficient=term_coefficient,
            energy_coefficient=np.array([c for c, _ in energy], dtype=float),
            energy_factors=np.array([f + [0] * (wide - len(f)) for _, f in energy], dtype=np.int32).reshape(
                -1, wide
            ),
            gr_constant=gr,
            gr_lambda=lam,
        )

    def arrays(self) -> tuple:
        """The arrays the compiled kernels take, in their order."""
        return (
            self.width,
            self.parent,
            self.factor,
            self.batch_start,
            self.group_row,
            self.group_power,
            self.term_node,
            self.term_coefficient,
            self.gr_constant,
            self.gr_lambda,
        )


@jit
def _powers(w, P, width, out) -> None:
    """``out[v·width + p] = w_v^p`` for the ``4P`` variables ``x, x̄, y, ȳ`` and ``p < width``."""
    for v in range(4 * P):
        out[v * width] = 1.0
    # Power by power over all the plain variables at once (independent multiplications, which the
    # processor overlaps); a barred variable's powers are the conjugates, exactly: (x̄)^p = conj(x^p).
    for p in range(1, width):
        for half in range(2):
            for j in range(P):
                plain = (2 * half * P + j) * width + p
                value = out[plain - 1] * w[half * P + j]
                out[plain] = value
                out[plain + P * width] = np.conj(value)


@jit
def _nonlinear(
    w, P, width, parent, factor, batch_start, group_row, group_power, term_node, term_coefficient,
    gr_constant, gr_lambda, powers, node, out,
) -> None:  # fmt: skip
    """``N(w)``: the flow of the terms of degree ≥ 4 and of relativity beyond its quadratic part."""
    _powers(w, P, width, powers)
    node[0] = 1.0
    for k in range(1, parent.size):
        node[k] = node[parent[k]] * powers[factor[k]]
    for b in range(2 * P):
        out[b] = 0.0
    for i in range(group_row.shape[0]):
        # Real arithmetic: a real coefficient times a complex node is two multiplications, not four;
        # the four lanes (LANES) written out, so that their eight sums are eight registers.
        r0 = i0 = r1 = i1 = r2 = i2 = r3 = i3 = 0.0
        for d in range(batch_start[i], batch_start[i + 1]):
            v = node[term_node[d, 0]]
            c = term_coefficient[d, 0]
            r0 += c * v.real
            i0 += c * v.imag
            v = node[term_node[d, 1]]
            c = term_coefficient[d, 1]
            r1 += c * v.real
            i1 += c * v.imag
            v = node[term_node[d, 2]]
            c = term_coefficient[d, 2]
            r2 += c * v.real
            i2 += c * v.imag
            v = node[term_node[d, 3]]
            c = term_coefficient[d, 3]
            r3 += c * v.real
            i3 += c * v.imag
        out[group_row[i, 0]] += complex(r0, i0) * powers[group_power[i, 0]]
        out[group_row[i, 1]] += complex(r1, i1) * powers[group_power[i, 1]]
        out[group_row[i, 2]] += complex(r2, i2) * powers[group_power[i, 2]]
        out[group_row[i, 3]] += complex(r3, i3) * powers[group_power[i, 3]]
    for b in range(2 * P):
        out[b] = -2j * out[b]  # ẇ_b = −2i ∂H/∂w̄_b
    for j in range(P):
        if gr_constant[j] != 0.0:
            s = (w[j].real * w[j].real + w[j].imag * w[j].imag) / (2.0 * gr_lambda[j])
            out[j] += 1j * gr_constant[j] / gr_lambda[j] * w[j] * (1.0 / ((1.0 - s) * (1.0 - s)) - 1.0)


def product_tree(monomials: list[list[int]]) -> tuple[NDArray[np.int32], NDArray[np.int32], list[int]]:
    """Arrange monomials (lists of factor indices) as a product tree sharing their common prefixes.

    Parameters
    ----------
    monomials : list of list of int
        Each the indices (into the power table) of its factors, in any order.

    Returns
    -------
    parent, factor : numpy.ndarray of uint32, shape (M,)
        ``node[0] = 1``, ``node[k] = node[parent[k]] · powers[factor[k]]`` (``parent[k] < k``),
        the nodes in order of their number of factors.
    node_of : list of int
        The node whose value is each monomial.

    Examples
    --------
    >>> parent, factor, node_of = product_tree([[3, 1], [1, 3, 5], [1, 3]])
    >>> parent.tolist(), factor.tolist(), node_of
    ([0, 0, 1, 2], [0, 1, 3, 5], [2, 3, 2])
    >>> product_tree([[4], [1, 2]])[:2]     # one factor, then two: ``node[3] = w_1 · w_2``
    (array([0, 0, 0, 1], dtype=uint32), array([0, 1, 4, 2], dtype=uint32))
    """
    keys = [tuple(sorted(m)) for m in monomials]
    prefixes = {key[:n] for key in keys for n in range(len(key) + 1)}
    # Level by level (all products of one factor, then of two, …): consecutive nodes do not depend
    # on each other, so the processor overlaps their multiplications; a node right after its parent
    # waits for it (the tree of the shipped model took 1.5× as long in that order).
    ordered = sorted(prefixes, key=lambda p: (len(p), p))
    index = {p: k for k, p in enumerate(ordered)}
    parent = [0] + [index[p[:-1]] for p in ordered[1:]]
    factor = [0] + [p[-1] for p in ordered[1:]]
    return np.array(parent, dtype=np.uint32), np.array(factor, dtype=np.uint32), [index[k] for k in keys]


@jit
def _matvec(M, v, out, block) -> None:
    """``out = M v`` for a block-diagonal ``M`` (blocks of ``block`` rows and columns)."""
    n = v.size
    for start in range(0, n, block):
        for i in range(start, start + block):
            acc = 0.0 + 0.0j
            for k in range(start, start + block):
                acc += M[i, k] * v[k]
            out[i] = acc


@jit
def integrate(
    w0, steps, h, a_matrix, b_weights, forward, backward, inner, inner_rate, inner_weights, width, parent,
    factor, batch_start, group_row, group_power, term_node, term_coefficient, gr_constant, gr_lambda, linear,
    keep, out_w, out_dw, extreme,
) -> None:  # fmt: skip
    """Take ``steps`` Lawson–DOP853 steps of size ``h`` from ``w0``; store ``keep`` components.

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
    inner, inner_rate : numpy.ndarray of complex, shape (Q − 1, 2P, 2P)
        ``e^{L θ_q h}`` and ``L e^{L θ_q h}`` at ``θ_q = q/Q``, ``q = 1…Q−1``: the samples
        within each step (:func:`lawson_matrices`; ``Q = 1``: none).
    inner_weights : numpy.ndarray, shape (Q − 1, 2, S)
        ``v(θ_q h) = v(0) + h Σ_i inner_weights[q, 0, i] k_i`` and ``v̇(θ_q h) = Σ_i
        inner_weights[q, 1, i] k_i`` from the stages ``k_i``.
    width, parent, factor, batch_start, group_row, group_power, term_node, term_coefficient
        The first eight of :meth:`FlowTerms.arrays`.
    gr_constant, gr_lambda
        Its last two.
    linear : numpy.ndarray of complex, shape (2P, 2P)
        ``L``.
    keep : numpy.ndarray of int, shape (K,)
        Components stored.
    out_w, out_dw : numpy.ndarray of complex, shape (Q·steps + 1, K)
        ``w`` and ``ẇ`` at the start and every ``h/Q``.
    extreme : numpy.ndarray, shape (2P,)
        Raised to the largest ``|w_b|²`` met (at the steps).

    Notes
    -----
    The samples within a step come from the interaction variable ``v(τ) = e^{−Lτ} w(t_n + τ)``,
    whose derivative ``e^{−Lτ} N(e^{Lτ} v)`` the stages sample at the nodes ``c_i h``: the
    polynomial through those samples, integrated, gives ``v`` and ``v̇`` (a continuous
    extension of the step, no further evaluation), then ``w = e^{Lτ} v`` and
    ``ẇ = L w + e^{Lτ} v̇``: the linear flow stays exact within the step. A stage's value
    carries the error of its low-order state through the Jacobian of the small ``N`` only.
    """
    n = w0.size
    P = n // 2
    S = b_weights.size
    Q = inner.shape[0] + 1
    # The secular linear flow never couples x and y (a term x ȳ is odd in the inclinations):
    # the matrices are two blocks, unless a caller's are not.
    block = P
    for i in range(P):
        for k in range(P):
            if linear[i, P + k] != 0.0 or linear[P + i, k] != 0.0:
                block = n
    powers = np.empty(2 * n * width, dtype=np.complex128)
    node = np.empty(parent.size, dtype=np.complex128)
    K = np.empty((S, n), dtype=np.complex128)
    v = np.empty(n, dtype=np.complex128)
    x = np.empty(n, dtype=np.complex128)
    tmp = np.empty(n, dtype=np.complex128)
    lin = np.empty(n, dtype=np.complex128)
    vq = np.empty(n, dtype=np.complex128)
    dq = np.empty(n, dtype=np.complex128)
    w = w0.copy()
    for step in range(steps + 1):
        for b in range(n):
            size = w[b].real * w[b].real + w[b].imag * w[b].imag
            extreme[b] = max(extreme[b], size)
        # Stage 1 (c = 0): N(w), which with L w is also the derivative stored at this step.
        _nonlinear(
            w, P, width, parent, factor, batch_start, group_row, group_power, term_node, term_coefficient,
            gr_constant, gr_lambda, powers, node, tmp,
        )  # fmt: skip
        for b in range(n):
            K[0, b] = tmp[b]
        _matvec(linear, w, lin, block)
        for c in range(keep.size):
            out_w[step * Q, c] = w[keep[c]]
            out_dw[step * Q, c] = lin[keep[c]] + tmp[keep[c]]
        if step == steps:
            break
        for i in range(1, S):
            for b in range(n):
                acc = 0.0 + 0.0j
                for j in range(i):
                    if a_matrix[i, j] != 0.0:
                        acc += a_matrix[i, j] * K[j, b]
                v[b] = w[b] + h * acc
            _matvec(forward[i], v, x, block)
            _nonlinear(
                x, P, width, parent, factor, batch_start, group_row, group_power, term_node, term_coefficient,
                gr_constant, gr_lambda, powers, node, tmp,
            )  # fmt: skip
            _matvec(backward[i], tmp, x, block)
            for b in range(n):
                K[i, b] = x[b]
        for q in range(Q - 1):
            # v and v̇ within the step from the stages, then w = e^{Lτ} v, ẇ = L w + e^{Lτ} v̇.
            for b in range(n):
                acc = 0.0 + 0.0j
                rate = 0.0 + 0.0j
                for i in range(S):
                    acc += inner_weights[q, 0, i] * K[i, b]
                    rate += inner_weights[q, 1, i] * K[i, b]
                vq[b] = w[b] + h * acc
                dq[b] = rate
            row = step * Q + q + 1
            for c in range(keep.size):
                i = keep[c]
                value = 0.0 + 0.0j
                rate = 0.0 + 0.0j
                for k in range(n):
                    value += inner[q, i, k] * vq[k]
                    rate += inner_rate[q, i, k] * vq[k] + inner[q, i, k] * dq[k]
                out_w[row, c] = value
                out_dw[row, c] = rate
        for b in range(n):
            acc = 0.0 + 0.0j
            for i in range(S):
                acc += b_weights[i] * K[i, b]
            v[b] = w[b] + h * acc
        _matvec(forward[S - 1], v, w, block)
    for b in range(n):
        w0[b] = w[b]


def lawson_matrices(linear: CArray, h: float, samples: int = 1) -> tuple[NDArray, ...]:
    """The DOP853 tableau, the stage exponentials ``e^{±L c_i h}`` and those of the samples within a step.

    Parameters
    ----------
    linear : numpy.ndarray of complex, shape (2P, 2P)
    h : float
        The step.
    samples : int
        ``Q``: samples per step (every ``h/Q``).

    Returns
    -------
    a_matrix : numpy.ndarray, shape (12, 12)
    b_weights : numpy.ndarray, shape (12,)
    forward, backward : numpy.ndarray of complex, shape (12, 2P, 2P)
    inner, inner_rate : numpy.ndarray of complex, shape (Q − 1, 2P, 2P)
        ``e^{L q h/Q}`` and ``L e^{L q h/Q}``, ``q = 1…Q−1``.
    inner_weights : numpy.ndarray, shape (Q − 1, 2, 12)
        The samples' weights on the stages (:func:`integrate`).
    """
    from scipy.integrate._ivp import dop853_coefficients as tableau
    from scipy.linalg import expm

    S = tableau.N_STAGES
    c = tableau.C[:S]
    forward = np.stack([expm(linear * (ci * h)) for ci in c])
    backward = np.stack([expm(-linear * (ci * h)) for ci in c])
    n = linear.shape[0]
    theta = np.arange(1, samples) / samples
    inner = np.array([expm(linear * (t * h)) for t in theta], dtype=complex).reshape(samples - 1, n, n)
    inner_rate = np.ascontiguousarray(linear @ inner).reshape(samples - 1, n, n)
    # The Lagrange basis ℓ_i(θ), and ∫_0^θ ℓ_i, over the nodes of CONTINUOUS_STAGES.
    weights = np.zeros((samples - 1, 2, S))
    subset = list(CONTINUOUS_STAGES)
    for i in subset:
        others = c[[k for k in subset if k != i]]
        basis = np.poly1d(others, r=True) / np.prod(c[i] - others)
        weights[:, 0, i] = basis.integ()(theta)
        weights[:, 1, i] = basis(theta)
    return (
        np.ascontiguousarray(tableau.A[:S, :S]), np.ascontiguousarray(tableau.B), forward, backward, inner,
        inner_rate, weights,
    )  # fmt: skip


def default_step(linear: CArray, fraction: float = 1.0 / 64.0) -> float:
    """The step: ``fraction`` of the shortest period of the linear flow (years).

    Examples
    --------
    >>> default_step(np.diag([1j * 2 * np.pi / 64000.0, 0j]))
    1000.0
    """
    rates = np.abs(np.linalg.eigvals(linear))
    return float(fraction * 2.0 * np.pi / rates.max())


@jitable
def hermite_basis(s):
    """The cubic Hermite basis at ``s ∈ [0, 1]``: ``f(s) ≈ h00 f0 + h10 f0' + h01 f1 + h11 f1'``.

    ``h00 = (1 + 2s)(1 − s)²``, ``h10 = s(1 − s)²``, ``h01 = s²(3 − 2s)``, ``h11 = s²(s − 1)``
    (derivatives per unit ``s``). Floats in compiled kernels, or numpy arrays.

    Parameters
    ----------
    s : float or numpy.ndarray, shape (...)

    Returns
    -------
    h00, h10, h01, h11 : float or numpy.ndarray, shape (...)

    Examples
    --------
    >>> [float(v) for v in hermite_basis(0.5)]
    [0.5, 0.125, 0.5, -0.125]
    """
    return (1.0 + 2.0 * s) * (1.0 - s) ** 2, s * (1.0 - s) ** 2, s * s * (3.0 - 2.0 * s), s * s * (s - 1.0)


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
    h00, h10, h01, h11 = hermite_basis((position - i)[:, None])
    return h00 * w[i] + h10 * h * dw[i] + h01 * w[i + 1] + h11 * h * dw[i + 1]


@jit
def _energy_kernel(w, P, width, coefficient, factors, gr_constant, gr_lambda, powers) -> complex:
    _powers(w, P, width, powers)
    total = 0.0 + 0.0j
    for d in range(coefficient.size):
        value = coefficient[d] + 0.0j
        for f in range(factors.shape[1]):
            value = value * powers[factors[d, f]]
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
    >>> terms = FlowTerms.from_polynomial(np.array([[1, 1, 0, 0]]), np.array([-0.5 + 0j]), 1)
    >>> energy(terms, np.array([2.0 + 0j, 0j]))
    -2.0
    """
    powers = np.empty(4 * terms.count * terms.width, dtype=complex)
    value = _energy_kernel(
        np.ascontiguousarray(w, dtype=complex), terms.count, terms.width, terms.energy_coefficient,
        terms.energy_factors, terms.gr_constant, terms.gr_lambda, powers,
    )  # fmt: skip
    return float(np.real(value))
