r"""Distances of a spin axis to the secular spin–orbit resonances with the nodal modes ``s_k``.

The orbit normal of a planet moves as a sum of modes ``sin(i/2) e^{iΩ} = Σ_k S_k e^{i(s_k t + γ_k)}``
(``s_k < 0``: the nodes regress; ``s_5 = 0``, the invariable plane, excluded). The spin axis
precesses about the orbit normal at ``ψ̇ = α cos ε`` the other way (westward, ``ψ̇ > 0``). A mode
``s_k`` forces the obliquity resonantly when ``ψ̇ + s_k = 0`` (Ward 1973; Laskar & Robutel 1993;
Ward & Hamilton 2004: Saturn and ``s_8``; Ward & Canup 2006, Saillenfest et al. 2020: Jupiter
and ``s_7``). The *distance* to the resonance with ``s_k`` is ``ψ̇ + s_k`` (″/yr): positive when
the axis precesses faster than the node regresses. The frequencies are La2004's
(:data:`andoyer.planetary.orbits.laplace_lagrange.LA2004_S`, Laskar et al. 2004, A&A 428, 261,
Table 3; a few digits unverified, see there); a drifting precession constant (satellite
migration) moves ``ψ̇`` across them: resonance capture or crossing.

Examples
--------
>>> nearest = resonance_distances(0.7297)[0]
>>> nearest["mode"], nearest["frequency"], round(nearest["distance"], 4)
('s8', -0.691736, 0.038)
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["resonance_distances"]


def resonance_distances(precession_rate: float) -> list[dict[str, Any]]:
    """The distances ``ψ̇ + s_k`` (″/yr) to the nodal modes ``s_k``, nearest first.

    Parameters
    ----------
    precession_rate : float
        ``ψ̇ = α cos ε`` in ″/yr (negative for a retrograde rotator: its axis precesses eastward
        and no nodal mode of the planets is resonant with it).

    Returns
    -------
    list of dict
        ``{"mode": "s8", "frequency": s_k, "distance": ψ̇ + s_k}``, ″/yr, sorted by ``|distance|``.

    Examples
    --------
    >>> [d["mode"] for d in resonance_distances(2.6)][:2]
    ['s7', 's8']
    >>> resonance_distances(float("nan"))
    Traceback (most recent call last):
    ...
    ValueError: expected a finite precession rate in arcsec/yr, got nan
    """
    from andoyer.planetary.orbits.laplace_lagrange import LA2004_S

    rate = float(precession_rate)
    if not np.isfinite(rate):
        msg = f"expected a finite precession rate in arcsec/yr, got {precession_rate!r}"
        raise ValueError(msg)
    modes = [
        {"mode": f"s{k + 1}", "frequency": float(s), "distance": rate + float(s)}
        for k, s in enumerate(LA2004_S)
        if s != 0
    ]
    return sorted(modes, key=lambda m: abs(m["distance"]))
