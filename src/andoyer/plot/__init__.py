"""Pictures of free and perturbed rotation (matplotlib).

Every drawing function returns a :class:`matplotlib.figure.Figure` (a new pyplot-free figure,
or the figure of the ``ax`` it was given) with what it drew attached as
``figure.andoyer_data``; the matching ``*_data`` function computes the same data without
drawing.  The contours are exact (closed form), not contoured on a grid (except the level curves
of Colombo's top, whose separatrix is exact).

* :func:`phase_portrait` — the ``(l, L)`` plane of the free body and its separatrix (Gurfil Fig. 4);
* :func:`momentum_sphere` — energy contours (polhodes) on ``|m| = G`` (Gurfil Fig. 1);
* :func:`lara_portrait` — free body vs. the main problem of SAM rotation (Lara Fig. 1);
* :func:`polhode`, :func:`herpolhode`, :func:`poinsot` — Poinsot's construction for a state;
* :func:`precession` — precession, obliquity and nutation series of a propagation;
* :func:`cassini_portrait`, :func:`cassini_geometry` — Colombo's top and its Cassini states.
* :func:`obliquity_history` — obliquity and climatic precession of spin-axis histories;
* :func:`obliquity_ensemble_figure` — a chaotic-obliquity ensemble: a few histories and the density;
* :func:`nutation_plot` — the nutation in longitude and obliquity;
* :func:`tidal_history_plot` — the Earth–Moon tidal history against the geological constraints.

Examples
--------
>>> from andoyer import RigidBody, plot
>>> fig = plot.phase_portrait(RigidBody(1.0, 2.0, 3.0))
>>> fig.andoyer_data.separatrix_energy
0.25
"""

from andoyer.plot.cassini import CassiniPortrait, cassini_geometry, cassini_portrait, cassini_portrait_data
from andoyer.plot.contours import default_energies, energy_contour, separatrix_contour
from andoyer.plot.lara import LARA_LEVELS, LaraPortrait, lara_portrait, lara_portrait_data
from andoyer.plot.nutation import nutation_plot
from andoyer.plot.obliquity_ensemble import obliquity_ensemble_figure
from andoyer.plot.phase import PhasePortrait, phase_portrait, phase_portrait_data
from andoyer.plot.poinsot import (
    Herpolhode,
    Polhode,
    herpolhode,
    herpolhode_data,
    poinsot,
    polhode,
    polhode_data,
)
from andoyer.plot.precession import PrecessionSeries, precession, precession_data
from andoyer.plot.sphere import MomentumSphere, momentum_sphere, momentum_sphere_data
from andoyer.plot.spin_axis import obliquity_history
from andoyer.plot.tides import tidal_history_plot

__all__ = [
    "LARA_LEVELS",
    "CassiniPortrait",
    "Herpolhode",
    "LaraPortrait",
    "MomentumSphere",
    "PhasePortrait",
    "Polhode",
    "PrecessionSeries",
    "cassini_geometry",
    "cassini_portrait",
    "cassini_portrait_data",
    "default_energies",
    "energy_contour",
    "herpolhode",
    "herpolhode_data",
    "lara_portrait",
    "lara_portrait_data",
    "momentum_sphere",
    "momentum_sphere_data",
    "nutation_plot",
    "obliquity_ensemble_figure",
    "obliquity_history",
    "phase_portrait",
    "phase_portrait_data",
    "poinsot",
    "polhode",
    "polhode_data",
    "precession",
    "precession_data",
    "separatrix_contour",
    "tidal_history_plot",
]
