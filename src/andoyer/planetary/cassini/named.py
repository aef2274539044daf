r"""Cassini bodies from the catalogue (or a body file): the figure, the orbit and its node modes.

Every number comes from :mod:`andoyer.catalogue` (a body missing one says which, as
``Body.require`` words it). For a body ``B`` with primary ``P``:

* figure and orbit: ``J2``, ``C22``, ``C/MR²``, the resonance ``p``, ``n = 2π/P_orb`` (its
  ``orbital_period``), ``e``, and ``m/M = GM_B/GM_P``;
* the node, two ways (``node=``):

  - ``"catalogue"``: one mode, ``g = −2π/T_node`` (``node_period``) at the inclination to the
    plane the orbit precesses about (``laplace_inclination``; or ``inclination`` when the
    orbit is referred to its local Laplace plane, or for a satellite referred to the ecliptic
    when its planet orbits in it: the Moon, whose Laplace plane is the ecliptic to 0.002°);
  - ``"model"``: the secular theory of :mod:`andoyer.planetary.cassini.laplace` for the
    primary's satellite system (the planet's ``J2``, the Sun, every catalogued satellite of
    the planet with a ``GM``): the Laplace planes, the modes' node rates, and each mode's
    amplitude and phase in the body's inclination, from the catalogued inclinations and nodes
    on the local Laplace planes (JPL's mean elements) of all the system's satellites;
  - ``"auto"`` (the default): ``"model"`` for a satellite whose catalogued orbit is referred
    to its local Laplace plane (Jupiter's and Saturn's), ``"catalogue"`` otherwise (Mercury,
    whose node is set by the planets; the Moon, whose node the first-order solar theory misses
    by 4 %: 17.8 yr against the measured 18.6 yr).

The planet's obliquity ``ε`` is the angle between its IAU pole and its orbit normal (Standish's
J2000 mean elements on the ecliptic, turned to the ICRF by the IAU 2006 obliquity ``ε₀``).

Examples
--------
>>> from andoyer import catalogue
>>> round(math.degrees(planet_obliquity(catalogue.get("saturn"))), 2)
26.73
>>> cassini_body(catalogue.get("moon")).resonance
1.0
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from andoyer import catalogue
from andoyer.catalogue import Body
from andoyer.catalogue.units import JULIAN_YEAR
from andoyer.planetary.cassini.body import CassiniBody
from andoyer.planetary.cassini.forced import ForcedObliquity, NodeMode
from andoyer.planetary.cassini.laplace import LaplaceModes, Satellite, SatelliteSystem

__all__ = [
    "NODE_SOURCES",
    "SystemFrame",
    "cassini_body",
    "forced_obliquity",
    "node_source",
    "planet_obliquity",
    "satellite_system",
]

#: The ways to get the node (module docstring).
NODE_SOURCES = ("auto", "model", "catalogue")

_WHAT = "the Cassini states"
#: Satellites closer than this ratio of semi-major axes are co-orbital: no Laplace–Lagrange term.
COORBITAL = 1.05
Array = NDArray[np.float64]


def _unit(ra: float, dec: float) -> Array:
    return np.array([math.cos(dec) * math.cos(ra), math.cos(dec) * math.sin(ra), math.sin(dec)])


def _ecliptic_to_icrf(v: Array) -> Array:
    """A J2000 ecliptic vector in the ICRF (J2000 equator): a turn by ``ε₀`` about x."""
    eps = catalogue.get("earth").require("obliquity", "the ecliptic's orientation").to("rad")
    c, s = math.cos(eps), math.sin(eps)
    return np.array([v[0], c * v[1] - s * v[2], s * v[1] + c * v[2]])


def _pole(body: Body, what: str) -> Array:
    return _unit(body.require("pole_ra", what).to("rad"), body.require("pole_dec", what).to("rad"))


def _orbit_normal(body: Body, what: str) -> Array:
    """The normal of a planet's heliocentric orbit in the ICRF."""
    i = body.require("inclination", what).to("rad")
    node = body.require("node", what).to("rad")
    ecliptic = np.array([math.sin(i) * math.sin(node), -math.sin(i) * math.cos(node), math.cos(i)])
    return _ecliptic_to_icrf(ecliptic)


def planet_obliquity(planet: Body) -> float:
    """``ε`` (rad): the angle between a planet's IAU pole and its orbit normal.

    Examples
    --------
    >>> round(math.degrees(planet_obliquity(catalogue.get("jupiter"))), 2)
    3.12
    """
    what = f"the obliquity of {planet.name}"
    return math.acos(float(np.clip(_pole(planet, what) @ _orbit_normal(planet, what), -1.0, 1.0)))


def _primary(body: Body) -> Body:
    if not body.primary:
        msg = f"expected {body.name} to have a primary (a catalogued body it orbits) for {_WHAT}, got none"
        raise ValueError(msg)
    return catalogue.get(body.primary)


def _is_laplace_frame(body: Body) -> bool:
    return "laplace" in body.orbit_frame.lower()


def _laplace_inclination(body: Body) -> float:
    """The inclination (rad) to the plane the orbit precesses about (module docstring)."""
    if body.laplace_inclination is not None:
        return body.laplace_inclination.to("rad")
    if body.inclination is not None and _is_laplace_frame(body):
        return body.inclination.to("rad")
    if body.inclination is not None and "ecliptic" in body.orbit_frame.lower() and body.kind == "satellite":
        planet = _primary(body)
        if planet.inclination is not None and planet.inclination.to("deg") < 1e-3:
            return body.inclination.to("rad")
    msg = (
        f"expected {body.name} to have laplace_inclination for {_WHAT} (or an inclination with an "
        f"orbit_frame naming the local Laplace plane), got none"
    )
    raise ValueError(msg)


def node_source(body: Body, node: str = "auto") -> str:
    """``"model"`` or ``"catalogue"``: what ``node="auto"`` means for ``body`` (module docstring)."""
    if node not in NODE_SOURCES:
        msg = f"expected node in {NODE_SOURCES}, got {node!r}"
        raise ValueError(msg)
    if node != "auto":
        return node
    return "model" if body.kind == "satellite" and _is_laplace_frame(body) else "catalogue"


def _figure(body: Body, unknown_moment: bool = False) -> dict[str, float | str | None]:
    """The keys of :class:`CassiniBody` but the node's, from the catalogue.

    With ``unknown_moment`` (the inverse problem) a body without ``C/MR²`` gets one it accepts,
    above ``2J2`` and ``J2 + 2C22``, which the inverse problem replaces.
    """
    primary = _primary(body)
    gm = body.require("gm", _WHAT).to("km3/s2")
    gm_primary = primary.require("gm", f"the mass ratio of {body.name} to {primary.name}").to("km3/s2")
    resonance = body.require("resonance", _WHAT).value
    j2, c22 = body.require("j2", _WHAT).value, body.require("c22", _WHAT).value
    if unknown_moment and body.moment_of_inertia is None:
        moment = min(1.0, max(0.3, 2 * j2 + 4 * c22))
    else:
        moment = body.require("moment_of_inertia", _WHAT).value
    sources = [body.require(k, _WHAT).source for k in ("j2", "orbital_period")]
    return {
        "name": body.key,
        "j2": j2,
        "c22": c22,
        "moment_of_inertia": moment,
        "mean_motion": 2 * math.pi / body.require("orbital_period", _WHAT).to("yr"),
        "eccentricity": body.require("eccentricity", _WHAT).value,
        "resonance": resonance,
        "mass_ratio": gm / gm_primary,
        "source": "; ".join(dict.fromkeys(s.split(" (")[0] for s in sources)),
    }


@dataclass(frozen=True)
class SystemFrame:
    """A planet's satellite system from the catalogue, with its frame.

    Attributes
    ----------
    system : SatelliteSystem
        Rates in rad per Julian year, ``GM`` in km³/s², lengths in km.
    members : tuple of Body
        The catalogue entries of :attr:`system`'s satellites, in order.
    pole, orbit_normal : numpy.ndarray, shape (3,)
        The planet's ``p`` and ``q`` in the ICRF; the system's frame has ``z = p`` and ``q`` in
        its x–z plane.
    """

    system: SatelliteSystem
    members: tuple[Body, ...]
    pole: Array
    orbit_normal: Array

    def basis(self) -> Array:
        """The system's axes in the ICRF, rows ``x, y, z``."""
        z = self.pole
        x = self.orbit_normal - (self.orbit_normal @ z) * z
        x = x / np.linalg.norm(x)
        return np.stack([x, np.cross(z, x), z])

    def tilts(self) -> NDArray[np.complex128]:
        """Each satellite's observed tilt from its Laplace plane, ``w_j = i_j e^{iΩ_j}`` (rad).

        In the system's frame (``e_1`` towards ``q``, ``e_2 = p × q``): the orbit normal from the
        catalogued inclination and node on the catalogued local Laplace plane, less that plane's
        pole. A satellite without a Laplace pole and node gets the phase 0, which only the one
        inclined satellite of a system may do (the modes' relative phases need the others').
        """
        x, y, z = self.basis()
        phi = self.system.laplace_angles()
        inclined = [m for m in self.members if _laplace_inclination(m) > 0]
        out = []
        for j, member in enumerate(self.members):
            i = _laplace_inclination(member)
            if i == 0:
                out.append(0j)
                continue
            keys = ("laplace_pole_ra", "laplace_pole_dec", "node")
            if any(getattr(member, k) is None for k in keys):
                if len(inclined) > 1:
                    for k in keys:
                        member.require(k, f"the phases of the node modes of {self.system_name}")
                out.append(complex(i))
                continue
            K = _unit(member.laplace_pole_ra.to("rad"), member.laplace_pole_dec.to("rad"))
            x_l = np.cross([0.0, 0.0, 1.0], K)
            x_l /= np.linalg.norm(x_l)
            y_l = np.cross(K, x_l)
            node = member.node.to("rad")
            h = math.sin(i) * math.sin(node) * x_l - math.sin(i) * math.cos(node) * y_l + math.cos(i) * K
            delta = h - K
            e1 = math.cos(phi[j]) * x - math.sin(phi[j]) * z
            out.append(complex(delta @ e1, delta @ y))
        return np.array(out)

    @property
    def system_name(self) -> str:
        """``"the satellites of <planet>"``, for messages."""
        return f"the satellites of {catalogue.get(self.members[0].primary).name}"

    def modes(self) -> LaplaceModes:
        """The system's secular modes."""
        return self.system.modes()


def satellite_system(primary: str | Body, member: Body | None = None) -> SystemFrame:
    """The satellite system of a catalogued planet (module docstring), ``member`` in it.

    Parameters
    ----------
    primary : str or Body
        The planet.
    member : Body, optional
        A satellite of that planet replacing the catalogued one of the same name (a body file)
        or joining the system.

    Returns
    -------
    SystemFrame

    Examples
    --------
    >>> frame = satellite_system("jupiter")
    >>> [m.name for m in frame.members]
    ['Io', 'Europa', 'Ganymede', 'Callisto']
    """
    planet = catalogue.get(primary)
    what = f"the Laplace planes of the satellites of {planet.name}"
    sun = catalogue.get("sun")
    gm = planet.require("gm", what).to("km3/s2")
    a_p = planet.require("semi_major_axis", what).to("km")
    e_p = planet.require("eccentricity", what).value
    sun_rate2 = sun.require("gm", what).to("km3/s2") / (a_p**3 * (1 - e_p**2) ** 1.5) * JULIAN_YEAR**2
    members = [
        b
        for b in (catalogue.get(name) for name in catalogue.names())
        if b.primary == planet.key and b.gm is not None and b.semi_major_axis is not None
    ]
    if member is not None:
        member.require("gm", what)
        a = member.require("semi_major_axis", what).to("km")
        members = [b for b in members if b.key != member.key]
        for b in members:
            ratio = b.semi_major_axis.to("km") / a
            if 1 / COORBITAL < ratio < COORBITAL:
                msg = (
                    f"expected {member.name} to be {b.name} (name it so to replace it) or to orbit apart "
                    f"from it (the secular theory has no co-orbitals), got semi-major axes {a!r} and "
                    f"{b.semi_major_axis.to('km')!r} km"
                )
                raise ValueError(msg)
        members = sorted([*members, member], key=lambda b: b.semi_major_axis.to("km"))
    if not members:
        msg = f"expected satellites of {planet.name} with gm and semi_major_axis for {what}, got none"
        raise ValueError(msg)
    satellites = []
    for b in members:
        a = b.semi_major_axis.to("km")
        if b.orbital_period is not None:
            n = 2 * math.pi / b.orbital_period.to("yr")
        else:
            n = math.sqrt((gm + b.gm.to("km3/s2")) / a**3) * JULIAN_YEAR
        e = b.eccentricity.value if b.eccentricity is not None else 0.0
        satellites.append(Satellite(b.name, b.gm.to("km3/s2"), a, n, e))
    system = SatelliteSystem(
        planet_gm=gm,
        planet_radius=planet.require("radius", what).to("km"),
        planet_j2=planet.require("j2", what).value,
        obliquity=planet_obliquity(planet),
        sun_rate2=sun_rate2,
        satellites=tuple(satellites),
    )
    return SystemFrame(system, tuple(members), _pole(planet, what), _orbit_normal(planet, what))


def _model_modes(body: Body) -> tuple[NodeMode, ...]:
    frame = satellite_system(_primary(body), member=body)
    j = frame.system.index(body.name)
    modes = frame.modes()
    amplitudes = modes.amplitudes(frame.tilts())[j]
    return tuple(
        NodeMode(float(g), float(abs(a)), float(np.angle(a)))
        for g, a in zip(modes.node_rates, amplitudes, strict=True)
    )


def _catalogue_modes(body: Body) -> tuple[NodeMode, ...]:
    period = body.require("node_period", _WHAT).to("yr")
    return (NodeMode(-2 * math.pi / period, _laplace_inclination(body), 0.0),)


def forced_obliquity(
    body: str | Body, node: str = "auto", *, unknown_moment: bool = False
) -> ForcedObliquity:
    """The figure and the node modes of a catalogued body (or a body file's).

    Parameters
    ----------
    body : str or Body
    node : {"auto", "model", "catalogue"}
    unknown_moment : bool
        ``C/MR²`` is what is sought (the inverse problem): a body without one is accepted.

    Returns
    -------
    ForcedObliquity

    Examples
    --------
    >>> forced = forced_obliquity("europa")
    >>> forced.source, len(forced.modes)
    ('model', 4)
    >>> round(math.degrees(float(forced.obliquity())), 4)
    0.0595
    """
    entry = catalogue.get(body)
    source = node_source(entry, node)
    fields = _figure(entry, unknown_moment)
    if source == "model":
        if _primary(entry).key == "sun":
            msg = f"expected a satellite of a planet for node='model', got {entry.name} (primary sun)"
            raise ValueError(msg)
        modes = _model_modes(entry)
    else:
        modes = _catalogue_modes(entry)
    main = max(modes, key=lambda m: m.inclination)
    if main.inclination <= 0:
        msg = f"expected {entry.name} on an inclined orbit for {_WHAT}, got an inclination of 0"
        raise ValueError(msg)
    cassini = CassiniBody(**fields, node_rate=main.node_rate, inclination=main.inclination)
    return ForcedObliquity(cassini, modes, source)


def cassini_body(body: str | Body, node: str = "auto") -> CassiniBody:
    """The :class:`CassiniBody` of a catalogued body: its orbit's largest node mode.

    Examples
    --------
    >>> titan = cassini_body("titan")
    >>> round(2 * math.pi / abs(titan.node_rate))  # years, the model's (about 700 published)
    718
    """
    return forced_obliquity(body, node).body
