r"""Sadov's action–angle variables ``(φ_ℓ, φ_g, φ_h, I_ℓ, I_g, I_h)`` (Gurfil et al. §5).

For the free body with the Andoyer Hamiltonian
``K = ½ (sin²l/I1 + cos²l/I2)(G² − L²) + L²/(2 I3)`` the actions are

.. math:: I_\ell = \frac{1}{2\pi}\oint L\,dl, \qquad I_g = G, \qquad I_h = H,

and the angles come from the generating function ``W = I_g g + I_h h + V(l; I_ℓ, I_g)``,
``V = ∫ L dl`` along the orbit: ``φ_ℓ = ∂V/∂I_ℓ``, ``φ_g = g + ∂V/∂I_g
= g + (V − I_ℓ φ_ℓ)/G`` (``V`` is homogeneous of degree 1 in ``(I_ℓ, G)``),
``φ_h = h``. The body must have ``b3`` along an axis of extreme inertia (either one);
``b_i`` is the intermediate in-plane axis and ``b_e`` the other one (see
:mod:`andoyer.state.sadov_frame`; ``b_i = b2`` when ``I1 = I2``).

Conventions (``u = |I_ℓ|/G``, ``u_s = (2/π) arctan κ`` the separatrix value):

* **Circulation** of ``l`` (``u > u_s``): ``I_ℓ = (1/2π)∫₀^{2π} L dl`` has the sign of
  ``L``; ``φ_ℓ`` increases with ``l`` and ``φ_ℓ = 0`` where the momentum crosses the
  half-plane spanned by ``b3`` and ``+b_i`` (``l = 0`` when ``b_i = b2``, ``l = π/2`` when
  ``b_i = b1``).
* **Libration** about ``σ b_e`` (``u < u_s``, ``L`` changes sign): ``|I_ℓ|`` is the area
  enclosed in the ``(l, L)`` plane over ``2π``, ``I_ℓ = σ |I_ℓ|`` with ``σ = sign(m·b_e)``
  (the lobe), and ``φ_ℓ = 0`` where the orbit crosses the meridian of ``σ b_e`` with
  ``L > 0`` (the maximum of ``L``). With these signs ``H(I_ℓ, I_g)`` is even in ``I_ℓ``,
  continuous across the separatrix, and every map below is canonical.
* **Axisymmetric about b3** (``I1 = I2``) and the sphere: the Andoyer variables are already
  action–angle and the map is the identity, ``(φ_ℓ, φ_g, I_ℓ) = (l, g, L)``; this is also
  the limit ``I1 → I2`` when ``b2`` is the intermediate axis.
* **Separatrix** (``2T/G² = 1/I_i``, ``u = u_s``): the period is infinite and the angles
  undefined. ``andoyer_to_sadov`` returns the exact ``I_ℓ = ±G u_s`` (sign of ``L``, ``+``
  at ``L = 0``) with ``φ_ℓ = 0``, ``φ_g = g``; ``sadov_to_andoyer`` returns the unstable
  equilibrium ``+b_i`` (or, when ``I_i = I3``, the pole ``L = sign(I_ℓ) G`` of the circle of
  equilibria); ``sadov_frequencies`` returns the limits ``ω_ℓ = 0``, ``ω_g = G/I_i``; each
  issues a :class:`~andoyer.state.SingularChartWarning`.
* **Libration centres** ``m ∥ ±b_e`` (``I_ℓ = 0``): ``φ_ℓ`` is undefined; the forward map
  sets ``φ_ℓ = 0``, ``φ_g = g`` with a warning, and the inverse map picks the lobe from the
  sign bit of ``I_ℓ`` (``+0.0`` or ``−0.0``).

Angles are returned in ``[0, 2π)``. The formulas and the corrections to the printed ones are
derived in ``docs/errata-sadov.md``.

The chart's dynamics, registered with it: the Hamiltonian ``H(I_ℓ, I_g)``
(:func:`sadov_hamiltonian`) and Hamilton's equations, ``dφ/dt = (ω_ℓ, ω_g, 0)`` with the
frequencies of :func:`sadov_frequencies` and constant actions.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._fastmath import wrap_2pi
from andoyer._validation import broadcast_finite, check_momenta
from andoyer.body import RigidBody
from andoyer.state.andoyer import Andoyer
from andoyer.state.hub import State, check_body
from andoyer.state.registry import Chart, register
from andoyer.state.sadov_frame import SadovFrame
from andoyer.state.sadov_orbit import angles, orbit, point
from andoyer.state.sadov_solve import solve
from andoyer.state.singular import warn_if_singular

__all__ = [
    "Sadov",
    "SadovFrequencies",
    "andoyer_to_sadov",
    "sadov_frequencies",
    "sadov_hamiltonian",
    "sadov_to_andoyer",
    "separatrix_action",
]

Array = NDArray[np.float64]
EPS = np.finfo(float).eps
SEPARATRIX = "Sadov chart on the separatrix (infinite period)"


class Sadov(NamedTuple):
    """Sadov's angles and actions; each field has the state's shape."""

    phi_l: Array
    phi_g: Array
    phi_h: Array
    I_l: Array
    I_g: Array
    I_h: Array


class SadovFrequencies(NamedTuple):
    """``(∂H/∂I_ℓ, ∂H/∂I_g)``; ``∂H/∂I_h = 0``."""

    omega_l: Array
    omega_g: Array


def _actions(I_l: ArrayLike, I_g: ArrayLike, I_h: ArrayLike | None = None) -> list[Array]:
    """Validated, broadcast actions with ``I_g > 0``, ``|I_ℓ| <= I_g`` (and ``|I_h| <= I_g``)."""
    names, values = ["I_l", "I_g"], [I_l, I_g]
    if I_h is not None:
        names.append("I_h")
        values.append(I_h)
    arrays = broadcast_finite(names, values)
    G = arrays[1]
    if np.any(G <= 0):
        msg = f"expected I_g > 0, got I_g = {float(np.min(G))!r}"
        raise ValueError(msg)
    for name, value in zip(names[::2], arrays[::2], strict=True):
        excess = np.abs(value) - G
        if np.any(excess > 4 * EPS * G):
            i = np.unravel_index(np.argmax(excess), excess.shape) if excess.ndim else ()
            msg = f"expected |{name}| <= I_g, got |{name}| = {float(abs(value[i]))!r} > I_g = {float(G[i])!r}"
            raise ValueError(msg)
    arrays[0] = np.clip(arrays[0], -G, G)
    return arrays


def _finite(values: tuple[Array, ...], where: str) -> tuple[Array, ...]:
    """Guard against a silent NaN: every output of a valid input must be finite."""
    if not all(np.all(np.isfinite(v)) for v in values):
        msg = f"expected finite {where} for finite input, got a non-finite value (please report this state)"
        raise FloatingPointError(msg)
    return values


def separatrix_action(body: RigidBody, I_g: ArrayLike) -> Array:
    r"""``|I_ℓ|`` on the separatrix: ``I_g (2/π) arctan κ = I_g (2/π) arcsin √ρ``.

    Orbits with ``|I_ℓ|`` above it circulate, below it librate.

    Parameters
    ----------
    body : RigidBody
        A body whose ``b3`` has the smallest or the largest moment.
    I_g : array_like, shape (...)
        ``G > 0``.

    Returns
    -------
    numpy.ndarray, shape (...)

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> body = RigidBody(2.0, 3.0, 4.0)  # κ² = 4·(3 − 2)/(2·(4 − 3)) = 2
    >>> bool(abs(separatrix_action(body, 1.0) - 2 / np.pi * np.arctan(np.sqrt(2))) < 1e-15)
    True
    """
    _, G = _actions(0.0, I_g)
    return G * SadovFrame.from_body(body).separatrix_fraction


def andoyer_to_sadov(
    body: RigidBody,
    l: ArrayLike,
    g: ArrayLike,
    h: ArrayLike,
    L: ArrayLike,
    G: ArrayLike,
    H: ArrayLike,
) -> Sadov:
    r"""Sadov's action–angle variables of Andoyer states (eqs. 139–147, corrected).

    ``I_g = G``, ``I_h = H``, ``φ_h = h``; ``I_ℓ = σ G u`` and ``φ_ℓ``, ``φ_g`` from
    :func:`andoyer.state.sadov_orbit.angles`, with the conventions of this module's
    docstring.

    Parameters
    ----------
    body : RigidBody
        A body whose ``b3`` has the smallest or the largest moment (else ``ValueError``).
    l, g, h, L, G, H : array_like, shape (...)
        Andoyer angles (radians) and momenta, ``G > 0``, ``|L|, |H| <= G``; they broadcast.

    Returns
    -------
    Sadov
        Angles in ``[0, 2π)``.

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> body = RigidBody(1.0, 2.0, 2.5)
    >>> s = andoyer_to_sadov(body, 0.3, 0.2, 0.1, 0.9, 1.0, 0.5)  # circulation, L > 0
    >>> [round(float(v), 10) for v in s]
    [0.6815758166, 6.1026219874, 0.1, 0.9418041198, 1.0, 0.5]
    >>> a = sadov_to_andoyer(body, *s)
    >>> [round(float(v), 12) for v in a]
    [0.3, 0.2, 0.1, 0.9, 1.0, 0.5]
    """
    names = ("l", "g", "h", "L", "G", "H")
    l, g, h, L, G, H = broadcast_finite(names, (l, g, h, L, G, H))
    check_momenta(L, G, H)
    L, H = np.clip(L, -G, G), np.clip(H, -G, G)
    frame = SadovFrame.from_body(body)
    if frame.identity:
        return Sadov(wrap_2pi(l), wrap_2pi(g), wrap_2pi(h), L, np.array(G), H)
    shape = l.shape
    l, g, L, G = (np.ravel(v) for v in (l, g, L, G))
    s, c = frame.to_standard(np.sin(l), np.cos(l))
    x = L / G
    omx2 = (G - L) * (G + L) / (G * G)
    s2 = s * s
    rho, rho_c = frame.rho, frame.rho_c
    tau = omx2 * (rho_c + rho * s2)
    omt = x * x + rho * (c * c) * omx2
    delta = rho * s2 * omx2 - rho_c * x * x
    circ = delta < 0
    sep = delta == 0
    centre = ~circ & (omt == 0)
    with np.errstate(all="ignore"):
        v = np.where(circ, tau / rho_c, omt / rho)
        vc = np.where(circ, -delta / rho_c, delta / rho)
    ok = ~sep
    sign = np.where(circ | sep, np.where(L < 0, -1.0, 1.0), np.sign(s))
    u = np.full_like(l, frame.separatrix_fraction)
    phi_l, dg = np.zeros_like(l), np.zeros_like(l)
    if ok.any():
        o = orbit(frame, circ[ok], v[ok], vc[ok])
        u[ok] = o.u
        phi_l[ok], dg[ok] = angles(frame, o, sign[ok], s[ok], c[ok], x[ok])
    phi_l[centre], dg[centre], u[centre] = 0.0, 0.0, 0.0
    warn_if_singular(sep, f"{SEPARATRIX}: set phi_l = 0, phi_g = g", 2)
    warn_if_singular(centre, "Sadov chart at a libration centre (I_l = 0): set phi_l = 0, phi_g = g", 2)
    out = _finite((wrap_2pi(phi_l), wrap_2pi(g + dg), wrap_2pi(h), sign * G * u, G, H), "Sadov variables")
    return Sadov(*(np.reshape(a, shape) for a in out))


def sadov_to_andoyer(
    body: RigidBody,
    phi_l: ArrayLike,
    phi_g: ArrayLike,
    phi_h: ArrayLike,
    I_l: ArrayLike,
    I_g: ArrayLike,
    I_h: ArrayLike,
) -> Andoyer:
    r"""Andoyer variables of Sadov states: the inverse of :func:`andoyer_to_sadov`.

    The orbit of ``u = |I_ℓ|/I_g`` is found by a bracketed Newton iteration
    (:mod:`andoyer.state.sadov_solve`), then ``z = am(2K(φ_ℓ − φ_0)/π | m)`` (circulation)
    or ``ζ = am(2Kφ_ℓ/π | m)`` (libration) gives ``l``, ``L`` and ``g − φ_g``.

    Parameters
    ----------
    body : RigidBody
        A body whose ``b3`` has the smallest or the largest moment (else ``ValueError``).
    phi_l, phi_g, phi_h, I_l, I_g, I_h : array_like, shape (...)
        Angles (radians) and actions, ``I_g > 0``, ``|I_ℓ|, |I_h| <= I_g``; they broadcast.

    Returns
    -------
    Andoyer
        Angles in ``[0, 2π)``.

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> body = RigidBody(1.0, 2.0, 2.5)
    >>> a = sadov_to_andoyer(body, 1.0, 0.0, 0.0, 0.2, 1.0, 0.0)  # libration about +b1
    >>> float(np.sin(a.l)) > 0, round(float(andoyer_to_sadov(body, *a).I_l), 12)
    (True, 0.2)
    """
    names = ("phi_l", "phi_g", "phi_h")
    phi_l, phi_g, phi_h = broadcast_finite(names, (phi_l, phi_g, phi_h))
    I_l, G, H = _actions(I_l, I_g, I_h)
    phi_l, phi_g, phi_h, I_l, G, H = np.broadcast_arrays(phi_l, phi_g, phi_h, I_l, G, H)
    frame = SadovFrame.from_body(body)
    if frame.identity:
        return Andoyer(wrap_2pi(phi_l), wrap_2pi(phi_g), wrap_2pi(phi_h), 1.0 * I_l, 1.0 * G, 1.0 * H)
    shape = phi_l.shape
    phi_l, phi_g, I_l, G = (np.ravel(v) for v in (phi_l, phi_g, I_l, G))
    u = np.clip(np.abs(I_l) / G, 0.0, 1.0)
    sign = np.where(np.signbit(I_l), -1.0, 1.0)
    sep = u == frame.separatrix_fraction
    ok = ~sep
    s = np.zeros_like(u)
    c = np.full_like(u, -np.sign(frame.circulation_origin))  # +b_i on the separatrix
    x = np.where(frame.rho_c == 0.0, sign, 0.0) * sep
    dg = np.zeros_like(u)
    if ok.any():
        o = solve(frame, u[ok])
        s[ok], c[ok], x[ok], dg[ok] = point(frame, o, sign[ok], phi_l[ok])
    warn_if_singular(sep, f"{SEPARATRIX}: returned the equilibrium +b_i", 2)
    l = frame.angle_from_standard(s, c)
    out = (wrap_2pi(l), wrap_2pi(phi_g + dg), wrap_2pi(np.ravel(phi_h)), G * x, G, np.ravel(H))
    return Andoyer(*(np.reshape(a, shape) for a in _finite(out, "Andoyer variables")))


def _orbits(body: RigidBody, I_l: ArrayLike, I_g: ArrayLike) -> tuple:
    """Frame, flat actions, separatrix mask and the solved orbits (``None`` for ρ = 0)."""
    I_l, G = _actions(I_l, I_g)
    frame = SadovFrame.from_body(body)
    shape = I_l.shape
    I_l, G = np.ravel(I_l), np.ravel(G)
    if frame.identity:
        return frame, shape, I_l, G, None, None
    u = np.clip(np.abs(I_l) / G, 0.0, 1.0)
    sep = u == frame.separatrix_fraction
    o = solve(frame, np.where(sep, 0.5 * frame.separatrix_fraction, u))
    return frame, shape, I_l, G, sep, o


def sadov_hamiltonian(body: RigidBody, I_l: ArrayLike, I_g: ArrayLike) -> Array:
    r"""The free Hamiltonian in Sadov's actions, ``H(I_ℓ, I_g) = (G²/2)((1 − τ)/I3 + τ/I_e)``.

    ``τ`` (the normalised energy, ``λ² = ρτ/((1 − ρ)(1 − τ))`` of eq. 144) comes from the
    inversion of eq. 143; the form is eq. 144 written as a convex combination, which
    does not cancel. On the separatrix ``H = G²/(2 I_i)``.

    Parameters
    ----------
    body : RigidBody
    I_l, I_g : array_like, shape (...)
        Actions, ``I_g > 0``, ``|I_ℓ| <= I_g``; they broadcast.

    Returns
    -------
    numpy.ndarray, shape (...)

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> from andoyer.state.andoyer import andoyer_hamiltonian
    >>> body = RigidBody(1.0, 2.0, 2.5)
    >>> s = andoyer_to_sadov(body, 0.3, 0.2, 0.1, 0.9, 1.0, 0.5)
    >>> bool(abs(sadov_hamiltonian(body, s.I_l, s.I_g) - andoyer_hamiltonian(body, 0.3, 0.9, 1.0)) < 1e-15)
    True
    """
    frame, shape, I_l, G, sep, o = _orbits(body, I_l, I_g)
    a_e = frame.a3 + frame.d_e3
    if o is None:
        return np.reshape(0.5 * (frame.a3 * I_l * I_l + a_e * (G - I_l) * (G + I_l)), shape)
    tau = np.where(sep, frame.rho_c, o.tau)
    omt = np.where(sep, frame.rho, o.omt)
    (H,) = _finite((0.5 * G * G * (frame.a3 * omt + a_e * tau),), "energies")
    return np.reshape(H, shape)


def sadov_frequencies(body: RigidBody, I_l: ArrayLike, I_g: ArrayLike) -> SadovFrequencies:
    r"""``(ω_ℓ, ω_g) = ∂H/∂(I_ℓ, I_g)`` in closed form.

    With ``u = |I_ℓ|/G``, ``σ = sign I_ℓ``, ``du/dτ`` from eq. 145 and
    ``d_e3 = 1/I_e − 1/I3``:

    .. math::
       \omega_\ell = \frac{\sigma G\, d_{e3}}{2\, du/d\tau}, \qquad
       \omega_g = G\Big[\frac{1}{I_3} + d_{e3}\Big(\tau - \frac{u}{2\, du/d\tau}\Big)\Big],

    i.e. ``ω_ℓ = −σπG d_e3 √((1 − ρ)(1 − τ))/(2K(λ²))`` in circulation and
    ``−σπG d_e3 √(ρτ)/(2K(1/λ²))`` in libration. The identity case gives
    ``ω_ℓ = (1/I3 − 1/I1) I_ℓ``, ``ω_g = G/I1``.

    Parameters
    ----------
    body : RigidBody
    I_l, I_g : array_like, shape (...)
        Actions, ``I_g > 0``, ``|I_ℓ| <= I_g``; they broadcast.

    Returns
    -------
    SadovFrequencies

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> body = RigidBody(1.0, 2.0, 2.5)
    >>> w = sadov_frequencies(body, 0.0, 1.0)  # small oscillations about +b1
    >>> bool(abs(w.omega_l + np.sqrt((1 - 1 / 2) * (1 - 1 / 2.5))) < 1e-15), float(w.omega_g)
    (True, 1.0)
    """
    frame, shape, I_l, G, sep, o = _orbits(body, I_l, I_g)
    if o is None:
        omega_l, omega_g = -frame.d_e3 * I_l, (frame.a3 + frame.d_e3) * G
    else:
        sign = np.where(np.signbit(I_l), -1.0, 1.0)
        u = np.abs(I_l) / G
        omega_l = np.where(sep, 0.0, sign * G * frame.d_e3 / (2.0 * o.dudtau))
        shift = np.where(sep, frame.rho_c, o.tau - u / (2.0 * o.dudtau))
        omega_g = G * (frame.a3 + frame.d_e3 * shift)
        warn_if_singular(sep, f"{SEPARATRIX}: returned the limits omega_l = 0, omega_g = G/I_i", 2)
    omega_l, omega_g = _finite((omega_l, omega_g), "frequencies")
    return SadovFrequencies(np.reshape(omega_l, shape), np.reshape(omega_g, shape))


# The chart's methods of State (installed when the chart registers, below): their signatures
# are the chart's, written once here. ``cls`` and ``self`` are the State class and a state.


def _from_sadov(
    cls: type[State],
    body: RigidBody,
    phi_l: ArrayLike,
    phi_g: ArrayLike,
    phi_h: ArrayLike,
    I_l: ArrayLike,
    I_g: ArrayLike,
    I_h: ArrayLike,
) -> State:
    """State from Sadov's action–angle variables (Gurfil §5); see :mod:`andoyer.state.sadov`.

    Parameters
    ----------
    body : RigidBody
        The body.
    phi_l, phi_g, phi_h : array_like, shape (...)
        Sadov's angles in radians.
    I_l, I_g, I_h : array_like, shape (...)
        Sadov's actions. All six broadcast.

    Returns
    -------
    State, shape (...)
        The states (the broadcast shape of the six).

    Examples
    --------
    >>> from andoyer import RigidBody, State
    >>> body = RigidBody(1.0, 2.0, 3.0)
    >>> s = State.from_andoyer(0.3, 0.4, 0.5, 0.9, 1.0, 0.2)
    >>> back = State.from_sadov(body, *s.as_sadov(body))
    >>> bool(abs(back.m_body - s.m_body).max() < 1e-13)
    True
    """
    return cls.from_andoyer(*sadov_to_andoyer(check_body(body), phi_l, phi_g, phi_h, I_l, I_g, I_h))


def _as_sadov(self, body: RigidBody):
    """Sadov's action–angle variables ``(phi_l, phi_g, phi_h, I_l, I_g, I_h)`` of the free body.

    Parameters
    ----------
    body : RigidBody
        The body.

    Returns
    -------
    Sadov of arrays, each of shape (...)
        The six coordinates, of the state's shape.

    Examples
    --------
    >>> from andoyer import RigidBody, State
    >>> s = State.from_andoyer(0.3, 0.4, 0.5, 0.9, 1.0, 0.2)
    >>> round(float(s.as_sadov(RigidBody(1.0, 2.0, 3.0)).I_g), 12)
    1.0
    """
    return andoyer_to_sadov(check_body(body), *self.as_andoyer())


def _hamiltonian(
    body: RigidBody,
    phi_l: ArrayLike,
    phi_g: ArrayLike,
    phi_h: ArrayLike,
    I_l: ArrayLike,
    I_g: ArrayLike,
    I_h: ArrayLike,
) -> Array:
    """The registry's form of :func:`sadov_hamiltonian`: the six columns in, the angles cyclic."""
    columns = broadcast_finite(Sadov._fields, (phi_l, phi_g, phi_h, I_l, I_g, I_h))
    return sadov_hamiltonian(check_body(body), columns[3], columns[4])


def _equations(
    body: RigidBody,
    phi_l: ArrayLike,
    phi_g: ArrayLike,
    phi_h: ArrayLike,
    I_l: ArrayLike,
    I_g: ArrayLike,
    I_h: ArrayLike,
) -> Sadov:
    """Hamilton's equations in Sadov's chart: the angles turn at ``(ω_ℓ, ω_g, 0)``, the actions stay."""
    columns = broadcast_finite(Sadov._fields, (phi_l, phi_g, phi_h, I_l, I_g, I_h))
    _actions(columns[3], columns[4], columns[5])
    omega = sadov_frequencies(check_body(body), columns[3], columns[4])
    zero = np.zeros_like(columns[3])
    return Sadov(omega.omega_l, omega.omega_g, zero, zero.copy(), zero.copy(), zero.copy())


register(
    Chart(
        "sadov",
        Sadov._fields,
        ("phi_l", "phi_g", "phi_h"),
        "Sadov's action–angle variables of the free body (Gurfil §5)",
        _from_sadov,
        _as_sadov,
        source="andoyer.state.sadov",
        hamiltonian=_hamiltonian,
        equations=_equations,
    ),
    State,
)
