r"""Andoyer's method (Gurfil et al., Appendix A.5) as a symbolic computation.

For an attitude written as a chain of rotations with angles ``α``, Andoyer's
function ``J_α`` is the polar form of the kinetic energy with respect to the
virtual rotation ``ω_α`` (Gurfil eq. 228):

.. math::

    J_α = m · ω_α, \\qquad \\widehat{ω_α} = \\mathrm{rot}^{\\mathsf T}\\,
    \\frac{\\partial\\,\\mathrm{rot}}{\\partial α}
    \\quad(\\text{body components}).

Where ``J_α`` depends only on momenta and vanishes for the non-canonical angles, the
remaining angles are canonical coordinates with momenta ``J_α`` (Gurfil eqs. 220–223).
In Lie–Poisson terms, ``J_α`` is the Hamiltonian whose flow is the rotation ``α``.
"""

from __future__ import annotations

from typing import Any

import sympy as sp

__all__ = ["andoyer_momenta", "euler_momenta"]


_AXES = {"x": 0, "z": 2}


def _rotation(axis: str, a: Any) -> Any:
    c, s = sp.cos(a), sp.sin(a)
    if axis == "z":
        return sp.Matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]])
    return sp.Matrix([[1, 0, 0], [0, c, -s], [0, s, c]])


def _momenta(chain: list[tuple[str, Any]], m_ref: Any) -> dict[str, Any]:
    """``J_k = (R_1 ... R_k)ᵀ m_ref · e_k`` for ``rot = R_1 ... R_n`` (``R_k`` about axis ``e_k``).

    Same as ``m_body · ω_k`` with ``hat(ω_k) = rotᵀ ∂rot/∂α_k``, because
    ``ω_k = (R_{k+1} ... R_n)ᵀ e_k``; peeling the factors one by one keeps every
    expression small.
    """
    out = {}
    v = m_ref
    for axis, angle in chain:
        v = (_rotation(axis, angle).T * v).applyfunc(lambda e: sp.trigsimp(sp.expand(e)))
        out[str(angle)] = v[_AXES[axis]]
    return out


def andoyer_momenta() -> dict[str, Any]:
    """``J_α`` for the chain ``rot = Rz(h) Rx(I) Rz(g) Rx(J) Rz(l)``, ``m_ref = G·Rz(h)Rx(I)e3``.

    Gurfil et al. A.5 finds ``J_h = G cos I``, ``J_I = 0``, ``J_g = G``, ``J_J = 0``,
    ``J_l = G cos J``: hence the canonical pairs ``(l, L = G cos J)``, ``(g, G)``,
    ``(h, H = G cos I)``.

    Returns
    -------
    dict of str to sympy expression
        Keys ``"h", "I", "g", "J", "l"``; symbols ``G`` (positive) and angles (real).

    Examples
    --------
    >>> andoyer_momenta()
    {'h': G*cos(I), 'I': 0, 'g': G, 'J': 0, 'l': G*cos(J)}
    """
    h, inc, g, J, ell = sp.symbols("h I g J l", real=True)
    G = sp.Symbol("G", positive=True)
    chain = [("z", h), ("x", inc), ("z", g), ("x", J), ("z", ell)]
    m_ref = G * _rotation("z", h) * _rotation("x", inc) * sp.Matrix([0, 0, 1])
    return _momenta(chain, m_ref)


def euler_momenta() -> dict[str, Any]:
    """``J_α`` for Euler angles 3-1-3, ``rot = Rz(φ) Rx(θ) Rz(ψ)``, body momentum ``m``.

    These are the Euler momenta ``(Φ, Θ, Ψ)`` of Gurfil et al. eqs. 40–42:
    ``Φ = m·γ``, ``Θ = m1 cos ψ − m2 sin ψ``, ``Ψ = m3``; the inverse of eqs. 25–27.

    Returns
    -------
    dict of str to sympy expression
        Keys ``"phi", "theta", "psi"``; symbols ``m1, m2, m3`` and the angles (real).

    Examples
    --------
    >>> euler_momenta()
    {'phi': m1*sin(psi)*sin(theta) + m2*sin(theta)*cos(psi) + m3*cos(theta), \
'theta': m1*cos(psi) - m2*sin(psi), 'psi': m3}
    """
    phi, theta, psi = sp.symbols("phi theta psi", real=True)
    m = sp.Matrix(sp.symbols("m1 m2 m3", real=True))
    chain = [("z", phi), ("x", theta), ("z", psi)]
    rot = _rotation("z", phi) * _rotation("x", theta) * _rotation("z", psi)
    return _momenta(chain, rot * m)
