r"""The IMCCE's published solutions: La2004's ``INSOL`` files and La2010's ``alkhqp`` and ``ecc`` files.

**La2004** (Laskar et al. 2004, A&A 428, 261; Mars: Laskar et al. 2004, Icarus 170, 343), as
distributed at ``vo.imcce.fr/insola/earth/online/earth/La2004`` (``INSOLN.LA2004.BTL.ASC``,
``INSOLP.LA2004.BTL.ASC``, ``INSOLN.LA2004.BTL.100.ASC``, ``.250.ASC``;
``INSOLN.LA2004.MARS.ASC``, ``INSOLP.LA2004.MARS.ASC``). Its README's byte-per-byte
description: four columns, ``t`` (1000 Julian years from J2000; ``INSOLN`` files run from 0
backwards, ``INSOLP`` forwards), ``e``, the obliquity ``ε`` (radians) and ``ϖ`` (radians), the
longitude of perihelion *from the moving equinox*, in Fortran ``D25.16`` (``D9.6`` in the
``.100``/``.250`` files). So it is a climate solution in the ecliptic and equinox *of date*:
``e`` is frame-free, and ``ϖ`` of date cannot be turned into the J2000 frame without La2004's
precession angle, which the file does not give. :func:`read_la2004` returns ``e``, ``ε``,
``ϖ`` of date and ``e sin ϖ``, no orbit plane. Its ``e`` and ``ϖ`` at J2000 (0.016702362,
1.796256991 rad = 102.9179°) are the osculating heliocentric elements of the Earth–Moon
barycentre of the JPL ephemeris (0.016702362 and 102.91793° from DE421's states,
:func:`~andoyer.planetary.orbits.planets.planet_data`), not Standish's mean ones (0.01671123,
102.93768°).

**La2010** (Laskar, Fienga, Gastineau & Manche 2011, A&A 532, A89), at
``vo.imcce.fr/insola/earth/online/earth/La2010``: ``La2010X_alkhqp3.dat`` (5-kyr steps) and
``La2010X_alkhqp3L.dat`` (1-kyr steps), ``X`` = a, b, c, d, from 0 to −250 Myr. Their README:
seven columns ``t`` (kyr from J2000), ``a``, ``l`` (mean longitude, radians),
``k = e cos ϖ``, ``h = e sin ϖ``, ``q = sin(i/2) cos Ω``, ``p = sin(i/2) sin Ω``, "taken in the
invariant reference frame". The README does not give that frame's orientation (the plane's
node on the ecliptic and where its ``x`` axis lies), so :func:`read_la2010` fixes it from the
file itself: the row at ``t = 0`` is the Earth's orbit at J2000, which in the J2000 ecliptic is
the osculating orbit of the Earth–Moon barycentre (DE421's states, to which La2010 was fitted
through INPOP08 — its ``e`` at J2000 matches DE421's to the digits La2004 prints). The rotation
``R`` (file frame → J2000 ecliptic) takes that row's normal onto DE421's and its perihelion
direction onto DE421's (the normal exactly, the perihelion in the plane):

.. math:: R = [\hat u_0, \hat v_0, \hat n_0]\,[\hat u_f, \hat v_f, \hat n_f]^T,
   \qquad \hat u = \frac{e - (e\cdot\hat n)\hat n}{|\cdot|},\quad \hat v = \hat n\times\hat u.

The reference plane of the file, ``R ẑ``, should then be the invariable plane: inclined
1°34′43.3″ (1.57869°) on the J2000 ecliptic with its ascending node at 107°34′56″ (107.5822°)
(Souami & Souchay 2012, A&A 543, A133); a warning says so when it is more than 0.05° away
(a file that is not the Earth's, or not in that frame). ``rotation=`` gives ``R`` instead.
``La2010X_ecc3.dat``/``ecc3L.dat`` (``t`` in kyr, ``e``) are read by :func:`read_la2010_ecc`.
"""

from __future__ import annotations

import os
import re
import warnings
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._limits import caller_stacklevel
from andoyer._validation import as_vectors
from andoyer.catalogue.units import DEGREE
from andoyer.planetary.orbits.elements import (
    eccentricity_from_elements,
    elements_from_vectors,
    normal_from_elements,
    state_to_vectors,
)
from andoyer.planetary.orbits.numeric_text import read_table
from andoyer.planetary.orbits.planets import PLANETS, planet_data
from andoyer.planetary.orbits.solutions import SolutionFile, check_column, increasing

if TYPE_CHECKING:
    from andoyer.planetary.orbits.table import TableOrbit

__all__ = [
    "INVARIABLE_PLANE",
    "read_alkhqp",
    "read_la2004",
    "read_la2010",
    "read_la2010_ecc",
    "rotation_from_j2000_row",
]

Array = NDArray[np.float64]

#: The invariable plane on the J2000 ecliptic (inclination, ascending node; radians):
#: 1°34′43.3″ and 107°34′56″, Souami & Souchay (2012), A&A 543, A133, from DE405.
INVARIABLE_PLANE = (
    (1.0 + 34.0 / 60.0 + 43.3 / 3600.0) * DEGREE,
    (107.0 + 34.0 / 60.0 + 56.0 / 3600.0) * DEGREE,
)
#: How far (radians) the plane found from a La2010 file may lie from :data:`INVARIABLE_PLANE` quietly.
PLANE_TOLERANCE = 0.05 * DEGREE
KYR = 1000.0
LA2004_COLUMNS = ("t", "e", "obliquity", "varpi")
ALKHQP_COLUMNS = ("t", "a", "l", "k", "h", "q", "p")


def read_la2004(path: str | os.PathLike[str], planet: str | None = None) -> SolutionFile:
    r"""Read a La2004 ``INSOL`` file: ``t`` (kyr), ``e``, obliquity and ``ϖ`` of date (module notes).

    Parameters
    ----------
    path : str or path-like
    planet : str, optional
        Default: ``"mars"`` for a name with ``MARS``, else ``"earth"``.

    Returns
    -------
    SolutionFile
        ``e``, ``obliquity``, ``perihelion_of_date``, ``climatic_precession``; no orbit plane.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "INSOLN.LA2004.BTL.ASC"
    >>> _ = path.write_text("".join(
    ...     f"{-k:13.3f}   0.1670236225492288D-01   0.4090928042223415D+00   0.1796256991128036D+01\n"
    ...     for k in range(4)))
    >>> sol = read_la2004(path)
    >>> sol.t.tolist(), sol.planet, sol.has_plane
    ([-3000.0, -2000.0, -1000.0, 0.0], 'earth', False)
    """
    table = read_table(path, LA2004_COLUMNS)
    values = table.values
    check_column(table, values[:, 1], "eccentricity", "e")
    check_column(table, values[:, 2], "inclination", "obliquity")  # the angle between two unit vectors
    order = increasing(values[:, 0])
    t, e, obliquity, varpi = values[order].T
    if planet is None:
        planet = "mars" if "MARS" in Path(path).name.upper() else "earth"
    return SolutionFile(
        path=str(path),
        format="la2004",
        planet=planet,
        t=t * KYR,
        e=e,
        obliquity=obliquity,
        perihelion_of_date=varpi,
        climatic_precession=e * np.sin(varpi),
        frame="the ecliptic and equinox of date (e, obliquity, perihelion from the moving equinox)",
    )


def read_la2010_ecc(path: str | os.PathLike[str]) -> SolutionFile:
    r"""Read a La2010 ``ecc3``/``ecc3L`` file: ``t`` (kyr from J2000) and the Earth's ``e``.

    Parameters
    ----------
    path : str or path-like

    Returns
    -------
    SolutionFile

    Examples
    --------
    >>> import tempfile, pathlib
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "La2010a_ecc3L.dat"
    >>> _ = path.write_text("".join(f"{-k}.000 0.0167{k}\n" for k in range(5)))
    >>> sol = read_la2010_ecc(path)
    >>> sol.span, round(float(sol.e[-1]), 5)
    ((-4000.0, 0.0), 0.0167)
    """
    table = read_table(path, ("t", "e"))
    check_column(table, table.values[:, 1], "eccentricity", "e")
    t, e = table.values[increasing(table.values[:, 0])].T
    return SolutionFile(str(path), "la2010-ecc", "earth", t * KYR, e, frame="frame-free (e only)")


def _earth_at_j2000() -> tuple[Array, Array]:
    """The Earth–Moon barycentre's osculating heliocentric normal and eccentricity vector at J2000 (DE421)."""
    data = planet_data()
    j = PLANETS.index("earth")
    n, e = state_to_vectors(data.sun_gm + data.gm[j], data.position[j], data.velocity[j])
    return n, e


def _triad(n: Array, e: Array) -> Array:
    """Columns ``û, v̂, n̂``: the perihelion direction in the plane, 90° ahead, the normal."""
    n = n / np.linalg.norm(n)
    u = e - np.dot(e, n) * n
    u = u / np.linalg.norm(u)
    return np.stack([u, np.cross(n, u), n], axis=-1)


def rotation_from_j2000_row(normal: ArrayLike, eccentricity_vector: ArrayLike) -> Array:
    r"""The rotation taking a file's frame to the J2000 ecliptic, from the Earth's orbit at J2000 in it.

    ``R`` takes ``normal`` onto the J2000 osculating normal of the Earth–Moon barycentre (DE421)
    and the perihelion direction onto its perihelion direction (see the module's notes).

    Parameters
    ----------
    normal, eccentricity_vector : array_like, shape (3,)
        The Earth's orbit at J2000, in the file's frame.

    Returns
    -------
    numpy.ndarray, shape (3, 3)
        Orthogonal, ``v_J2000 = R v_file``.

    Examples
    --------
    >>> n0, e0 = _earth_at_j2000()
    >>> bool(np.allclose(rotation_from_j2000_row(n0, e0), np.eye(3), atol=1e-14))
    True
    """
    n_f = as_vectors(normal, "normal")
    e_f = as_vectors(eccentricity_vector, "eccentricity vector")
    if n_f.shape != (3,) or e_f.shape != (3,):
        msg = f"expected a normal and an eccentricity vector of shape (3,), got {n_f.shape} and {e_f.shape}"
        raise ValueError(msg)
    n0, e0 = _earth_at_j2000()
    return _triad(n0, e0) @ _triad(n_f, e_f).T


def _plane_of(rotation: Array) -> tuple[float, float]:
    """Inclination and node on the J2000 ecliptic of the plane whose pole is ``R ẑ``."""
    _, i, node, _ = elements_from_vectors(rotation[:, 2], np.zeros(3))
    return float(i), float(node)


def read_la2010(
    path: str | os.PathLike[str], rotation: ArrayLike | None = None, planet: str = "earth"
) -> SolutionFile:
    r"""Read a La2010 ``t a l k h q p`` file, turning its frame into the J2000 ecliptic.

    Parameters
    ----------
    path : str or path-like
        Whitespace-separated, 7 columns, ``t`` in kyr from J2000 (see the module's notes).
    rotation : array_like, shape (3, 3), optional
        Orthogonal matrix taking vectors from the file's frame to the J2000 ecliptic (the
        identity for a file in the J2000 ecliptic already). Default: fixed by the file's row at
        ``t = 0``, the Earth's orbit at J2000 (:func:`rotation_from_j2000_row`).
    planet : str
        Whose orbit the file is (La2010's are the Earth's).

    Returns
    -------
    SolutionFile
        With ``a``, ``e``, ``normal`` and ``eccentricity_vector``; ``frame`` states the rotation.

    Warns
    -----
    UserWarning
        When the rotation found from the J2000 row does not put the file's reference plane
        within 0.05° of the invariable plane.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "orbit.dat"
    >>> _ = path.write_text("".join(f"{t} 1.0 0.0 0.0167 0.0 0.0 0.0\n" for t in (-3, -2, -1, 0)))
    >>> sol = read_la2010(path, rotation=np.eye(3))
    >>> sol.span, sol.orbit().eccentricity_vector(-1500.0).round(4).tolist()
    ((-3000.0, 0.0), [0.0167, 0.0, 0.0])
    """
    R = None
    if rotation is not None:
        R = as_vectors(rotation, "rotation")
        if R.shape != (3, 3) or not np.allclose(R @ R.T, np.eye(3), atol=1e-9) or np.linalg.det(R) < 0:
            msg = f"expected a proper orthogonal 3x3 rotation matrix, got {R.tolist()}"
            raise ValueError(msg)
    table = read_table(path, ALKHQP_COLUMNS)
    values = table.values
    k, h, q, p = values[:, 3], values[:, 4], values[:, 5], values[:, 6]
    check_column(table, values[:, 1], "semi_major_axis", "a")
    check_column(table, np.hypot(k, h), "eccentricity", "sqrt(k^2 + h^2)")
    sin_half = np.hypot(q, p)
    bad = np.flatnonzero(sin_half > 1.0)
    if bad.size:
        msg = (
            f"expected sin(i/2) = sqrt(q^2 + p^2) <= 1, got {sin_half[bad[0]]:.6g} on line "
            f"{table.line(bad[0])} of {str(path)!r}"
        )
        raise ValueError(msg)
    inc, node = 2.0 * np.arcsin(sin_half), np.arctan2(p, q)
    normal = normal_from_elements(inc, node)
    ecc = eccentricity_from_elements(np.hypot(k, h), inc, node, np.arctan2(h, k))
    if R is None:
        zero = np.flatnonzero(values[:, 0] == 0.0)
        if zero.size == 0:
            msg = (
                f"expected a row at t = 0 (J2000) in {str(path)!r} to fix its frame (the Earth's J2000 "
                "orbit), or rotation= (file frame to J2000 ecliptic)"
            )
            raise ValueError(msg)
        R = rotation_from_j2000_row(normal[zero[0]], ecc[zero[0]])
        inclination, ascending = _plane_of(R)
        frame = (
            f"the file's reference plane (fixed by its J2000 row, the Earth's orbit) lies at "
            f"i = {inclination / DEGREE:.5f} deg, node {ascending / DEGREE:.4f} deg on the J2000 ecliptic"
        )
        i0, node0 = INVARIABLE_PLANE
        pole0 = normal_from_elements(i0, node0)
        off = float(np.arccos(np.clip(np.dot(R[:, 2], pole0), -1.0, 1.0)))
        if off > PLANE_TOLERANCE:
            msg = (
                f"{Path(path).name}: the frame fixed by its J2000 row is {off / DEGREE:.3f} deg from the "
                f"invariable plane (i = 1.5787 deg, node 107.582 deg; Souami & Souchay 2012): is it the "
                f"Earth's orbit in La2010's invariant frame?"
            )
            warnings.warn(msg, UserWarning, stacklevel=caller_stacklevel())
    else:
        frame = "turned into the J2000 ecliptic by the rotation given"
    order = increasing(values[:, 0])
    return SolutionFile(
        path=str(path),
        format="la2010",
        planet=planet,
        t=values[order, 0] * KYR,
        e=np.hypot(k, h)[order],
        a=values[order, 1],
        normal=(normal @ R.T)[order],
        eccentricity_vector=(ecc @ R.T)[order],
        frame=frame,
    )


def read_alkhqp(path: str | os.PathLike[str], rotation: ArrayLike | None = None) -> TableOrbit:
    r"""Read a La2010-style ``t a λ k h q p`` file as an orbit history, in the J2000 ecliptic.

    The orbit of :func:`read_la2010` (the module's notes describe the format and its frame).

    Parameters
    ----------
    path : str or path-like
        Whitespace-separated, 7 columns, ``t`` in kyr from J2000.
    rotation : array_like, shape (3, 3), optional
        Orthogonal matrix taking vectors from the file's frame to the J2000 ecliptic
        (the identity if the file is referred to the J2000 ecliptic already); default: fixed by
        the file's row at ``t = 0`` (La2010's invariable frame onto the J2000 ecliptic).

    Returns
    -------
    TableOrbit

    Examples
    --------
    >>> import tempfile, pathlib
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "orbit.dat"
    >>> _ = path.write_text("".join(f"{t} 1.0 0.0 0.0167 0.0 0.0 0.0\n" for t in (-3, -2, -1, 0)))
    >>> orbit = read_alkhqp(path, rotation=np.eye(3))
    >>> orbit.span, orbit.eccentricity_vector(-1500.0).round(4).tolist()
    ((-3000.0, 0.0), [0.0167, 0.0, 0.0])
    """
    return read_la2010(path, rotation=rotation).orbit()


_LA2004_NAME = re.compile(r"^INSOL[NP]\..*\.ASC$", re.IGNORECASE)
_ALKHQP_NAME = re.compile(r"alkhqp", re.IGNORECASE)
_ECC_NAME = re.compile(r"^La20\d\d[a-z]?_ecc", re.IGNORECASE)


def format_from_name(name: str) -> str | None:
    """The IMCCE format a file's name says (``la2004``, ``la2010``, ``la2010-ecc``), or ``None``.

    Examples
    --------
    >>> format_from_name("INSOLN.LA2004.BTL.100.ASC"), format_from_name("La2010d_alkhqp3L.dat")
    ('la2004', 'la2010')
    """
    if _LA2004_NAME.match(name):
        return "la2004"
    if _ALKHQP_NAME.search(name):
        return "la2010"
    if _ECC_NAME.match(name):
        return "la2010-ecc"
    return None
