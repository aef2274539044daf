r"""Spin-axis histories as ensemble members: a sampler of (precession rate or H, T_d) and a propagator.

:class:`SpinParameterSampler` draws, per sample, the precession rate ``ψ̇`` at J2000 (″/yr) or the
dynamical ellipticity ``H``, and the tidal dissipation ``T_d`` (Zeebe & Lourens 2022), uniformly
in ranges or on a regular grid, as snvecR's users do by hand; its states carry the spin axis at
J2000 (J2000 ecliptic frame, ``G = 1``, ``J = 0``). :class:`SpinAxisPropagator` integrates each
sample's axis along one orbit history (:func:`andoyer.planetary.spin_axis.evolve_axes`) and returns states
in the **orbit frame of date** turned back by the general precession, the figure axis along
the spin axis (``J = 0``): the Euler angle ``θ`` is the obliquity ``ε(t)`` and ``φ = π − p_A(t)``
(so ``output="euler"`` stores obliquity and precession directly; ``φ(0) = π``: the equator's
ascending node on the orbit is the autumnal equinox). The Andoyer chart is singular at
``J = 0`` and warns; use ``"euler"`` or ``"state"``.

Examples
--------
>>> from andoyer.ensemble import run_ensemble
>>> from andoyer.planetary.orbits import VondrakEcliptic
>>> ds = run_ensemble(SpinParameterSampler("earth", precession_rate=(50.0, 51.0), grid=(3,)), 3,
...                   [-1000.0, 0.0], propagator=SpinAxisPropagator(VondrakEcliptic(), "earth"), chunk=3,
...                   output="euler", scheduler="synchronous", progress=False)
>>> ds.precession_rate.values.tolist()
[50.0, 50.5, 51.0]
>>> np.round(np.degrees(ds.theta.values[:, 0]), 3).tolist()  # obliquity 1 kyr ago
[23.568, 23.569, 23.569]
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer.ensemble.sampling import Draw, _interval
from andoyer.planetary.orbits.protocol import OrbitHistory
from andoyer.planetary.spin_axis import DEFAULT_PRECESSION_RATE, build_model, default_axis, evolve_axes
from andoyer.planetary.spin_axis.history import DEFAULT_STEP
from andoyer.state import State

__all__ = ["SpinAxisPropagator", "SpinParameterSampler"]

Array = NDArray[np.float64]


@dataclass(frozen=True)
class SpinParameterSampler:
    """Per-sample precession rate (or dynamical ellipticity) and tidal dissipation.

    Parameters
    ----------
    body : {"earth", "mars"}
    precession_rate : float or (low, high), optional
        ``ψ̇`` at J2000, ″/yr (default: the body's, fixed). Not with ``dynamical_ellipticity``.
    dynamical_ellipticity : float or (low, high), optional
        ``H``.
    tidal_dissipation : float or (low, high)
        ``T_d``.
    grid : tuple of int, optional
        Points per varying parameter (in the order rate-or-H, then ``T_d``): a regular grid,
        ends included (C order, ``T_d`` fastest), instead of uniform draws. Sample ``j`` of a
        chunk is grid point ``j mod size``: with ``chunk`` equal to the grid's size every chunk
        is the whole grid (``n_samples = chunk`` for one pass).
    axis : array_like, shape (3,), optional
        Spin axis at J2000 (default :func:`andoyer.planetary.spin_axis.default_axis`).

    Examples
    --------
    >>> from andoyer.ensemble import chunk_rng
    >>> draw = SpinParameterSampler("earth", tidal_dissipation=(0.0, 1.2)).sample(chunk_rng(0, 0), 4)
    >>> sorted(draw.parameters), draw.state.shape
    (['precession_rate', 'tidal_dissipation'], (4,))
    """

    body: str = "earth"
    precession_rate: float | tuple[float, float] | None = None
    dynamical_ellipticity: float | tuple[float, float] | None = None
    tidal_dissipation: float | tuple[float, float] = 0.0
    grid: tuple[int, ...] | None = None
    axis: tuple[float, float, float] | None = None

    def _ranges(self) -> dict[str, tuple[float, float]]:
        if self.precession_rate is not None and self.dynamical_ellipticity is not None:
            msg = "expected a precession rate or a dynamical ellipticity range, got both"
            raise ValueError(msg)
        key = str(self.body).strip().lower()
        if key not in DEFAULT_PRECESSION_RATE:
            msg = f"expected a body in {', '.join(DEFAULT_PRECESSION_RATE)}, got {self.body!r}"
            raise ValueError(msg)
        if self.dynamical_ellipticity is not None:
            h_range = _interval(self.dynamical_ellipticity, "dynamical_ellipticity", 0.0)
            first = ("dynamical_ellipticity", h_range)
        else:
            rate = DEFAULT_PRECESSION_RATE[key] if self.precession_rate is None else self.precession_rate
            first = ("precession_rate", _interval(rate, "precession_rate", 0.0))
        return dict([first, ("tidal_dissipation", _interval(self.tidal_dissipation, "tidal_dissipation"))])

    def sample(self, rng: np.random.Generator, n: int) -> Draw:
        """``n`` samples: the J2000 axis as states (n,), and the parameters (n,) each.

        Parameters
        ----------
        rng : numpy.random.Generator
        n : int

        Returns
        -------
        Draw
        """
        ranges = self._ranges()
        varying = [name for name, (lo, hi) in ranges.items() if hi > lo]
        values: dict[str, Array] = {}
        if self.grid is not None:
            shape = tuple(int(k) for k in self.grid)
            if len(shape) != len(varying) or min(shape, default=1) < 1:
                msg = (
                    f"expected a grid with one positive size per varying parameter "
                    f"({', '.join(varying) or 'none'}), got {self.grid!r}"
                )
                raise ValueError(msg)
            axes = [np.linspace(*ranges[name], k) for name, k in zip(varying, shape, strict=True)]
            mesh = np.meshgrid(*axes, indexing="ij")
            pick = np.arange(n) % int(np.prod(shape))
            values = {name: m.ravel()[pick] for name, m in zip(varying, mesh, strict=True)}
        for name, (lo, hi) in ranges.items():
            if name not in values:
                values[name] = rng.uniform(lo, hi, n) if hi > lo else np.full(n, lo)
        s0 = default_axis(self.body) if self.axis is None else np.asarray(self.axis, dtype=float)
        s0 = s0 / np.linalg.norm(s0)
        h0 = np.arctan2(s0[0], -s0[1])
        state = State.from_andoyer(0.0, 0.0, np.full(n, h0), 1.0, 1.0, np.full(n, s0[2]))
        return Draw(state, values)


@dataclass(frozen=True)
class SpinAxisPropagator:
    """The secular spin-axis flow along ``orbit``, as an ensemble kernel.

    Each sample starts from its state's angular-momentum direction at J2000 (J2000 ecliptic
    frame) with its own ``precession_rate`` or ``dynamical_ellipticity`` and
    ``tidal_dissipation``; times are Julian years from J2000 within ``orbit.span``.

    Parameters
    ----------
    orbit : OrbitHistory
    body : {"earth", "mars"}
    step : float
        Largest integration step (years).
    """

    orbit: OrbitHistory
    body: str = "earth"
    step: float = DEFAULT_STEP

    def __call__(
        self,
        state: State,
        times: ArrayLike,
        precession_rate: ArrayLike | None = None,
        dynamical_ellipticity: ArrayLike | None = None,
        tidal_dissipation: ArrayLike | None = None,
    ) -> State:
        """States (n, T) in the orbit frame of date: obliquity ``θ``, ``φ = π − p_A`` (Euler angles)."""
        from andoyer.planetary.orbits.protocol import check_times

        times = check_times(times, self.orbit.span, self.orbit.name)
        n = state.size
        m = state.reshape(-1).m_reference
        G = np.linalg.norm(m, axis=-1)
        s0 = m / G[:, None]

        def column(values: ArrayLike | None) -> list[float | None]:
            return [None] * n if values is None else [float(v) for v in np.asarray(values).reshape(n)]

        rates, ells, tides = column(precession_rate), column(dynamical_ellipticity), column(tidal_dissipation)
        models = [
            build_model(self.orbit, self.body, s0[i], rates[i], ells[i], tides[i] or 0.0) for i in range(n)
        ]
        axes, p = evolve_axes(self.orbit, models, np.asarray(times, dtype=float), s0, self.step)
        normal = self.orbit.normal(times)
        cos_eps = np.clip(np.sum(axes * normal, axis=-1), -1.0, 1.0)
        G = G[:, None] * np.ones_like(cos_eps)
        return State.from_andoyer(0.0, 0.0, np.pi - p, G, G, G * cos_eps)
