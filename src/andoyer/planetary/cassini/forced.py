r"""The obliquity forced by an orbit whose inclination is a sum of node modes.

When a satellite's orbit normal ``n`` circles its Laplace pole ``K`` as a sum of modes, each with
its own node rate ``g_k``, amplitude ``i_k`` and phase ``φ_k`` (small tilts written as complex
numbers about ``K``),

.. math:: N(t) = \sum_k i_k\, e^{i(\varphi_k + g_k t)},

the spin axis answers each mode as it would answer that mode alone (Bills 2005; Baland, Yseboodt
& Van Hoolst 2012): for small angles the averaged spin equation ``ds/dt = (α s·n + β)(s × n)``
is linear in the tilts, ``Ṡ = −iκ(S − N)`` with ``κ = α + β``, and its forced solution is
``S = Σ_k κ N_k/(κ + g_k)``. Mode ``k`` alone is Colombo's top ``(α, β, g_k, i_k)``, whose Cassini
state of least obliquity (state 1 when ``|g_k| < κ``, state 2 beyond; the one that continues the
linear answer) has the signed obliquity ``θ_k``; its spin axis lies at ``(i_k − θ_k)`` from ``K``,
in the plane of ``K`` and the mode's orbit normal. The obliquity vector is the sum

.. math:: S(t) - N(t) = -\sum_k \theta_k\, e^{i(\varphi_k + g_k t)},
   \qquad \varepsilon(t) = \Big|\sum_k \theta_k e^{i(\varphi_k + g_k t)}\Big| ,

which lies between ``max(0, 2 max|θ_k| − Σ|θ_k|)`` and ``Σ|θ_k|``. With one mode it is exactly
the Cassini state of :mod:`andoyer.planetary.cassini.top`; with several the superposition is
first order in the tilts (the satellites' are below 0.5°).

Examples
--------
>>> from andoyer.planetary.cassini.body import CassiniBody
>>> body = CassiniBody("x", 3e-5, 1e-5, 0.34, 144.0, 0.03, 0.005, -0.009)
>>> forced = ForcedObliquity(body, (NodeMode(-0.009, 0.005, 0.0), NodeMode(-0.02, 0.001, 1.0)))
>>> [round(r.state.obliquity_deg, 4) for r in forced.responses()]
[0.1133, 0.0974]
>>> low, high = forced.obliquity_range()
>>> round(low, 6) <= round(float(forced.obliquity(0.0)), 6) <= round(high, 6)
True
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._validation import as_finite
from andoyer.planetary.cassini.body import CassiniBody
from andoyer.planetary.cassini.top import CassiniState

__all__ = ["ForcedObliquity", "ModeResponse", "NodeMode", "least_obliquity_state"]

Array = NDArray[np.float64]

#: Modes with a smaller amplitude (rad) force no obliquity worth a Cassini state (θ ∝ i).
NEGLIGIBLE_INCLINATION = 1e-12


@dataclass(frozen=True)
class NodeMode:
    """One mode of the orbit's node: ``i e^{i(φ + g t)}`` about the Laplace pole.

    Attributes
    ----------
    node_rate : float
        ``g < 0`` (rad/yr), a regressing node.
    inclination : float
        Amplitude ``i ≥ 0`` (rad).
    phase : float
        ``φ``, the mode's node at the epoch (rad), in the frame its system shares.
    """

    node_rate: float
    inclination: float
    phase: float = 0.0

    def __post_init__(self) -> None:
        values = (self.node_rate, self.inclination, self.phase)
        if not all(
            isinstance(v, int | float) and not isinstance(v, bool) and math.isfinite(v) for v in values
        ):
            msg = f"expected finite node_rate, inclination, phase, got {values!r}"
            raise ValueError(msg)
        if not (self.node_rate < 0 and 0 <= self.inclination < math.pi / 2):
            msg = f"expected node_rate < 0 and 0 <= inclination < pi/2, got {values[:2]!r}"
            raise ValueError(msg)

    @property
    def period(self) -> float:
        """The node's period ``2π/|g|`` (years)."""
        return 2 * math.pi / abs(self.node_rate)


@dataclass(frozen=True)
class ModeResponse:
    """The spin axis' answer to one :class:`NodeMode`.

    Attributes
    ----------
    mode : NodeMode
    state : CassiniState or None
        The Cassini state of least obliquity of the mode alone (``None`` for a mode of negligible
        amplitude, which forces none).
    """

    mode: NodeMode
    state: CassiniState | None

    @property
    def theta(self) -> float:
        """The signed obliquity ``θ_k`` (rad; 0 without a state)."""
        return 0.0 if self.state is None else self.state.theta


def least_obliquity_state(body: CassiniBody) -> CassiniState:
    """The Cassini state of least obliquity of a body: the one a damped spin settles in.

    State 1 while ``|g| < α + β`` roughly, state 2 past the bifurcation (the Moon).

    Examples
    --------
    >>> body = CassiniBody("x", 3e-5, 1e-5, 0.34, 144.0, 0.03, 0.005, -0.009)
    >>> least_obliquity_state(body).number
    1
    """
    return min(body.top().states(), key=lambda s: s.obliquity)


@dataclass(frozen=True)
class ForcedObliquity:
    """A body's figure and its orbit's node modes: the forced obliquity (module docstring).

    Parameters
    ----------
    body : CassiniBody
        The figure, mean motion, eccentricity, resonance and mass ratio (its own ``node_rate``
        and ``inclination`` are one mode's, usually the largest; they are not used here).
    modes : tuple of NodeMode
    source : str
        Where the modes come from (``"model"``, ``"catalogue"``, ``"command line"``).
    """

    body: CassiniBody
    modes: tuple[NodeMode, ...]
    source: str = ""

    def __post_init__(self) -> None:
        if not isinstance(self.body, CassiniBody):
            msg = f"expected a CassiniBody, got {type(self.body).__name__}"
            raise ValueError(msg)
        if not self.modes or not all(isinstance(m, NodeMode) for m in self.modes):
            msg = f"expected a non-empty tuple of NodeMode, got {self.modes!r}"
            raise ValueError(msg)
        if all(m.inclination <= NEGLIGIBLE_INCLINATION for m in self.modes):
            msg = f"expected an inclined orbit (a mode above {NEGLIGIBLE_INCLINATION} rad), got none"
            raise ValueError(msg)

    def responses(self) -> tuple[ModeResponse, ...]:
        """The answer to each mode, in the order of :attr:`modes`."""
        return self._responses

    @cached_property
    def _responses(self) -> tuple[ModeResponse, ...]:
        out = []
        for mode in self.modes:
            if mode.inclination <= NEGLIGIBLE_INCLINATION:
                out.append(ModeResponse(mode, None))
                continue
            alone = self.body.replace(node_rate=mode.node_rate, inclination=mode.inclination)
            out.append(ModeResponse(mode, least_obliquity_state(alone)))
        return tuple(out)

    def _sum(self, weights: Array, t: ArrayLike) -> NDArray[np.complex128]:
        time = as_finite(t, "t")
        rates = np.array([m.node_rate for m in self.modes])
        phases = np.array([m.phase for m in self.modes])
        return np.sum(weights * np.exp(1j * (phases + rates * time[..., None])), axis=-1)

    def obliquity_vector(self, t: ArrayLike = 0.0) -> NDArray[np.complex128]:
        """``S − N = −Σ θ_k e^{i(φ_k + g_k t)}`` (rad, complex), shape of ``t`` (years from the epoch)."""
        return self._sum(-np.array([r.theta for r in self.responses()]), t)

    def orbit_normal(self, t: ArrayLike = 0.0) -> NDArray[np.complex128]:
        """``N(t) = Σ i_k e^{i(φ_k + g_k t)}``, the orbit normal's tilt from the Laplace pole (rad)."""
        return self._sum(np.array([m.inclination for m in self.modes]), t)

    def spin_axis(self, t: ArrayLike = 0.0) -> NDArray[np.complex128]:
        """``S(t)``, the spin axis' tilt from the Laplace pole (rad, complex)."""
        return self.orbit_normal(t) + self.obliquity_vector(t)

    def obliquity(self, t: ArrayLike = 0.0) -> Array:
        """``ε(t) = |S − N|`` (rad), shape of ``t`` (Julian years from the epoch)."""
        return np.abs(self.obliquity_vector(t))

    def obliquity_range(self) -> tuple[float, float]:
        """The least and largest obliquity over time (rad): ``(max(0, 2 max|θ_k| − Σ|θ_k|), Σ|θ_k|)``.

        Reached when the modes' phases line up (exactly for two modes; the bounds hold for any).
        """
        sizes = [abs(r.theta) for r in self.responses()]
        total = float(sum(sizes))
        return max(0.0, 2 * max(sizes) - total), total

    def dominant(self) -> int:
        """The index of the mode with the largest amplitude."""
        return int(np.argmax([m.inclination for m in self.modes]))
