r"""Cassini states: the equilibria of Colombo's top (Peale 1969; Ward 1975; Henrard & Murigande 1987).

A body with second-degree gravity coefficients ``(J2, C22)`` and polar moment ``C/MR²``
circles its primary on an orbit of inclination ``i`` to a Laplace plane; the orbit's node
regresses uniformly, ``Ω̇ = g < 0``. Averaged over the orbit and the rotation, the spin axis
``s`` (a unit vector; principal-axis rotation about the axis of ``C``) obeys, in the frame
that turns with the node (Laplace pole ``K``, orbit normal ``k`` fixed in it),

.. math::
   \frac{d\mathbf s}{dt} = \nabla\mathcal H \times \mathbf s, \qquad
   \mathcal H(\mathbf s) = -\frac{\alpha}{2}(\mathbf s\cdot\mathbf k)^2
   - \beta\,(\mathbf s\cdot\mathbf k) - g\,(\mathbf s\cdot\mathbf K),

the Hamiltonian of Colombo's top per unit spin angular momentum ``G = Cω`` (rad/yr). It is the
Andoyer pair ``(h, H/G)`` of a frame with ``k`` as the reference axis: ``s·k = cos θ = H/G``,
and the last term is the precessing frame's ``ΔH = −μ·M`` (Gurfil et al. eq. 126) with
``μ = g K`` (:class:`~andoyer.perturbations.PrecessingFrame`). The sign convention is the
project's: ``dM/dt = ∇H × M`` for reference-frame momenta
(:class:`~andoyer.perturbations.secular.SecularGravityGradient`).

The package, one concept per module:

* :mod:`~andoyer.planetary.cassini.top` -- :class:`ColomboTop`: the Cassini equation, its
  roots numbered as Peale, their stability, the separatrix.
* :mod:`~andoyer.planetary.cassini.body` -- :class:`CassiniBody`: the precession and resonance
  constants ``α, β`` from ``J2, C22, C/MR²``, the orbit and the spin–orbit resonance.
* :mod:`~andoyer.planetary.cassini.laplace` -- :class:`SatelliteSystem`: a satellite's Laplace
  plane from its planet's ``J2``, the Sun and the other satellites, and the secular modes of
  the node about it.
* :mod:`~andoyer.planetary.cassini.forced` -- :class:`ForcedObliquity`: the obliquity forced by
  an orbit whose inclination is a sum of node modes.
* :mod:`~andoyer.planetary.cassini.named` -- the above from :mod:`andoyer.catalogue` (or a body
  file): :func:`get`, :func:`forced_obliquity`.
* :mod:`~andoyer.planetary.cassini.inverse` -- :func:`moment_of_inertia_from_obliquity`: an
  observed obliquity to ``C/MR²``, with the uncertainties carried through.

Left out: the forced physical librations (the Moon's, Mercury's 88-day 38.5″ libration), the
non-uniform motion of the orbit beyond its node modes (the Moon's solar perturbations,
Mercury's pericentre precession), tides and core–mantle friction (the Moon's pole lags its
Cassini state by about 0.26″, Williams et al. 2001), an ocean that decouples a shell, and the
non-rigid response: see ``docs/cassini.md``.

Examples
--------
>>> from andoyer.planetary import cassini
>>> [(s.number, round(s.obliquity_deg, 2), s.stable) for s in cassini.states("moon")]
[(2, 6.69, True), (3, 175.68, True)]
>>> import math
>>> round(math.degrees(float(cassini.forced_obliquity("titan").obliquity())), 3)  # a rigid Titan
0.11
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from functools import cache

from andoyer import catalogue
from andoyer.catalogue.units import ARCSEC
from andoyer.planetary.cassini.body import CassiniBody, eccentricity_function
from andoyer.planetary.cassini.forced import ForcedObliquity, ModeResponse, NodeMode
from andoyer.planetary.cassini.inverse import MomentEstimate, moment_of_inertia_from_obliquity
from andoyer.planetary.cassini.laplace import LaplaceModes, Satellite, SatelliteSystem
from andoyer.planetary.cassini.named import NODE_SOURCES, forced_obliquity, satellite_system
from andoyer.planetary.cassini.top import CassiniState, ColomboTop

__all__ = [
    "ARCSEC",
    "BODIES",
    "NODE_SOURCES",
    "CassiniBody",
    "CassiniState",
    "ColomboTop",
    "ForcedObliquity",
    "LaplaceModes",
    "ModeResponse",
    "MomentEstimate",
    "NodeMode",
    "Satellite",
    "SatelliteSystem",
    "eccentricity_function",
    "forced_obliquity",
    "get",
    "moment_of_inertia_from_obliquity",
    "satellite_system",
    "states",
]


def get(name: str | catalogue.Body, node: str = "auto") -> CassiniBody:
    """The :class:`CassiniBody` of a catalogued body (case-insensitive name) or of a body file's entry.

    Parameters
    ----------
    name : str or andoyer.catalogue.Body
    node : {"auto", "model", "catalogue"}
        Where the node rate and inclination come from (:mod:`andoyer.planetary.cassini.named`);
        a body whose orbit has several node modes gets its largest.

    Returns
    -------
    CassiniBody

    Examples
    --------
    >>> get("Mercury").resonance
    1.5
    >>> get("pluto")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: expected Pluto to have resonance for the Cassini states, got none ...
    """
    return forced_obliquity(name, node).body


def states(body: CassiniBody | str | catalogue.Body) -> list[CassiniState]:
    """The Cassini states of a body (or a named body), numbered as Peale (1969).

    Parameters
    ----------
    body : CassiniBody, str or andoyer.catalogue.Body

    Returns
    -------
    list of CassiniState
        Those that exist, in order of number.

    Examples
    --------
    >>> state1 = next(s for s in states("mercury") if s.number == 1)
    >>> round(state1.obliquity_deg * 60, 2)  # arcmin; Margot et al. (2012) measure 2.04 ± 0.08
    2.06
    """
    system = (
        body
        if isinstance(body, CassiniBody)
        else get(body)
        if isinstance(body, str | catalogue.Body)
        else None
    )
    if not isinstance(system, CassiniBody):
        msg = f"expected a CassiniBody or a body name, got {type(body).__name__}"
        raise ValueError(msg)
    return system.top().states()


class _Bodies(Mapping[str, CassiniBody]):
    """The catalogued bodies whose Cassini states the catalogue's values give, built when first read."""

    @staticmethod
    @cache
    def _built() -> dict[str, CassiniBody]:
        out = {}
        for name in catalogue.names():
            if catalogue.get(name).resonance is None:
                continue
            try:
                out[name] = get(name)
            except ValueError:
                continue  # a value is missing (Triton) or the orbit is not inclined (Enceladus)
        return out

    def __getitem__(self, key: str) -> CassiniBody:
        return self._built()[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self._built())

    def __len__(self) -> int:
        return len(self._built())

    def __repr__(self) -> str:
        return f"BODIES({sorted(self)})"


#: Every catalogued spin–orbit resonant body with what the Cassini states need, by lower-case
#: name: the Moon, Mercury, the Galilean satellites, Titan (built on first use).
BODIES: Mapping[str, CassiniBody] = _Bodies()
