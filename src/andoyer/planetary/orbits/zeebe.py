r"""Zeebe's published solutions: ZB18a's full HNBody output, the ZB17/ZB18a/ZB20 eccentricity files, ZB23.

As distributed at ``soest.hawaii.edu/oceanography/faculty/zeebe_files/Astro.html`` and read by
the R package snvecR (Kocken & Zeebe; its ``get_solution``, ``prepare_solution`` and ``snvec``
functions, which this module follows for the layouts, the time units and the frame):

* **ZB18a, full** (``ems-plan3.dat``, "full-ZB18a" in snvecR; Zeebe & Lourens 2019, Science
  365, 926): HNBody's output for the Earth–Moon system over 100 Myr, a few header lines
  (snvecR skips three) and eight columns: ``t`` (days from J2000, negative into the past),
  ``a`` (au), ``e``, ``i``, ``ϖ`` (longitude of perihelion), ``Ω`` (node), ``ω`` (argument of
  perihelion), ``M`` (mean anomaly), angles in degrees. The elements are in the
  heliocentric inertial frame (HCI), whose ``x-y`` plane is the Sun's equator and whose ``x``
  axis is the ascending node of the Sun's equator on the J2000 ecliptic; snvecR turns
  vectors from it into the J2000 ecliptic with the Sun's equator at ``Ω☉ = 75.5940°``,
  ``i☉ = 7.155°`` (its constants ``OMT``, ``INCT``, "as in Zeebe 2017", AJ 154, 193):

  .. math:: v_{\mathrm{ecl}} = A^T v_{\mathrm{HCI}}, \qquad A = R_1(i_\odot)\,R_3(\Omega_\odot),

  with ``R₁``, ``R₃`` the frame rotations (``A`` takes J2000-ecliptic components into HCI
  ones, as snvecR's ``euler``). So the Earth's J2000 orbit, in the ecliptic, lies in HCI at
  ``i = 7.155°`` with its ascending node at ``Ω = 180°``. ``frame="ecliptic"`` reads a file
  already in the J2000 ecliptic (snvecR's ``os_ref_frame = "J2000"``).
* **ZB17x, ZB18a-100, ZB18a-300, ZB20x** (``ZB18a.dat``, ``300Myr/ZB20a.dat``; Zeebe 2017,
  AJ 154, 193; Zeebe & Lourens 2019, 2022): three columns, the age (kyr, positive into the
  past: snvecR negates it), ``e``, ``i`` (degrees; to a plane the files do not name, so not
  read as an element). Comment lines start with ``%``.
* **ZB23.Rxx** (``ZB23.R01.eiop.dat``, 3.6 Gyr; Zeebe & Lourens 2022, 2023): five columns,
  ``t`` (kyr, negative into the past), ``e``, ``i`` (radians), the obliquity (radians) and the
  climatic precession ``e sin ϖ``.

The last two are eccentricity and climate solutions: ``e`` (and the obliquity and ``e sin ϖ``)
without the orbit plane.
"""

from __future__ import annotations

import os
import re
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from andoyer.catalogue.units import DAY, DEGREE, JULIAN_YEAR
from andoyer.planetary.orbits.elements import eccentricity_from_elements, normal_from_elements
from andoyer.planetary.orbits.numeric_text import read_table
from andoyer.planetary.orbits.solutions import SolutionFile, check_column, increasing

__all__ = ["HCI_INCLINATION", "HCI_NODE", "hci_to_ecliptic", "read_zb18a", "read_zb23", "read_zb_ecc"]

Array = NDArray[np.float64]

#: The node (rad) of the Sun's equator on the J2000 ecliptic, snvecR's ``OMT`` = 75.5940°.
HCI_NODE = 75.5940 * DEGREE
#: The inclination (rad) of the Sun's equator on the J2000 ecliptic, snvecR's ``INCT`` = 7.155°.
HCI_INCLINATION = 7.155 * DEGREE
FULL_COLUMNS = ("t", "a", "e", "i", "varpi", "node", "omega", "M")
#: HNBody's header: at most this many leading lines that are not numbers (snvecR skips three).
FULL_HEADER_LINES = 3
KYR = 1000.0
#: Planets of HNBody file names (``ems-plan3.dat``: the Earth–Moon system).
_PREFIXES = {"mer": "mercury", "ven": "venus", "ems": "earth", "ear": "earth", "mar": "mars",
             "jup": "jupiter", "sat": "saturn", "ura": "uranus", "nep": "neptune"}  # fmt: skip


def hci_to_ecliptic(node: float = HCI_NODE, inclination: float = HCI_INCLINATION) -> Array:
    r"""The rotation ``A^T`` taking HCI components to J2000-ecliptic ones (see the module's notes).

    Parameters
    ----------
    node, inclination : float
        The Sun's equator on the J2000 ecliptic (radians).

    Returns
    -------
    numpy.ndarray, shape (3, 3)

    Examples
    --------
    >>> R = hci_to_ecliptic()
    >>> [round(float(np.degrees(x)), 4) for x in (np.arccos(R[2, 2]), np.arctan2(R[0, 2], -R[1, 2]))]
    [7.155, 75.594]
    """
    cO, sO, ci, si = np.cos(node), np.sin(node), np.cos(inclination), np.sin(inclination)
    A = np.array([[cO, sO, 0.0], [-ci * sO, ci * cO, si], [si * sO, -si * cO, ci]])
    return A.T


def planet_from_name(name: str) -> str | None:
    """The planet of an HNBody file name (``ems-plan3.dat`` → ``earth``), or ``None``.

    Examples
    --------
    >>> planet_from_name("ems-plan3.dat"), planet_from_name("orbit.dat")
    ('earth', None)
    """
    match = re.match(r"^([a-z]{3})-plan", name.lower())
    return _PREFIXES.get(match.group(1)) if match else None


def read_zb18a(path: str | os.PathLike[str], frame: str = "hci", planet: str | None = None) -> SolutionFile:
    r"""Read ZB18a's full solution (HNBody output: ``t`` days, ``a e i ϖ Ω ω M``, degrees).

    Parameters
    ----------
    path : str or path-like
    frame : {"hci", "ecliptic"}
        The file's frame: the Sun's equator (HCI, Zeebe's files) or the J2000 ecliptic.
    planet : str, optional
        Default: from an HNBody name (``ems-plan3.dat``: the Earth), else the Earth.

    Returns
    -------
    SolutionFile
        With ``a``, ``e``, ``normal`` and ``eccentricity_vector`` in the J2000 ecliptic.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "ems-plan3.dat"
    >>> rows = [f"{-146100 * k} 1.0 0.0167 7.155 282.9 180.0 102.9 0.0" for k in range(4)]
    >>> _ = path.write_text("# HNBody\n" + "\n".join(rows) + "\n")
    >>> sol = read_zb18a(path)
    >>> sol.span, sol.planet, round(float(np.degrees(np.arccos(sol.normal[-1, 2]))), 6)
    ((-1200.0, 0.0), 'earth', 0.0)
    """
    if frame not in ("hci", "ecliptic"):
        msg = f"expected the frame 'hci' (the Sun's equator) or 'ecliptic' (J2000), got {frame!r}"
        raise ValueError(msg)
    table = read_table(path, FULL_COLUMNS, header_lines=FULL_HEADER_LINES)
    values = table.values
    t, a, e, inc, varpi, node, omega = (values[:, k] for k in range(7))
    check_column(table, a, "semi_major_axis", "a")
    check_column(table, e, "eccentricity", "e")
    check_column(table, inc, "inclination", "i", degrees=True)
    # ϖ = Ω + ω by definition: a file whose columns are in another order fails here.
    mismatch = np.abs((varpi - node - omega + 180.0) % 360.0 - 180.0)
    bad = np.flatnonzero(mismatch > 0.01)
    if bad.size:
        k = int(bad[0])
        msg = (
            f"expected the longitude of perihelion = node + argument of perihelion (columns 5 = 6 + 7, "
            f"degrees), got {varpi[k]:g} against {node[k]:g} + {omega[k]:g} on line {table.line(k)} of "
            f"{str(path)!r}"
        )
        raise ValueError(msg)
    i, O, w = inc * DEGREE, node * DEGREE, varpi * DEGREE
    normal = normal_from_elements(i, O)
    ecc = eccentricity_from_elements(e, i, O, w)
    R = hci_to_ecliptic() if frame == "hci" else np.eye(3)
    order = increasing(t)
    if planet is None:
        planet = planet_from_name(Path(path).name) or "earth"
    text = (
        "HCI (the Sun's equator at node 75.5940 deg, inclination 7.155 deg on the J2000 ecliptic, snvecR's) "
        "turned into the J2000 ecliptic"
        if frame == "hci"
        else "the J2000 ecliptic"
    )
    return SolutionFile(
        path=str(path),
        format="zb18a",
        planet=planet,
        t=t[order] * DAY / JULIAN_YEAR,
        e=e[order],
        a=a[order],
        normal=(normal @ R.T)[order],
        eccentricity_vector=(ecc @ R.T)[order],
        frame=text,
    )


def read_zb_ecc(path: str | os.PathLike[str]) -> SolutionFile:
    r"""Read a ZB17/ZB18a/ZB20 eccentricity file: the age (kyr, positive into the past), ``e``, ``i`` (deg).

    Parameters
    ----------
    path : str or path-like

    Returns
    -------
    SolutionFile
        ``e`` only (the inclination's reference plane is not given).

    Examples
    --------
    >>> import tempfile, pathlib
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "ZB20a.dat"
    >>> _ = path.write_text("% age e inc\n" + "".join(f"{k}.0 0.0{k + 1} 1.5\n" for k in range(4)))
    >>> sol = read_zb_ecc(path)
    >>> sol.t.tolist(), sol.e.tolist()
    ([-3000.0, -2000.0, -1000.0, 0.0], [0.04, 0.03, 0.02, 0.01])
    """
    table = read_table(path, ("age", "e", "i"))
    values = table.values
    check_column(table, values[:, 1], "eccentricity", "e")
    if np.any(values[:, 0] < 0):
        k = int(np.flatnonzero(values[:, 0] < 0)[0])
        msg = (
            f"expected ages (kyr, positive into the past), got {values[k, 0]:g} on line {table.line(k)} "
            f"of {str(path)!r}"
        )
        raise ValueError(msg)
    order = increasing(-values[:, 0])
    return SolutionFile(
        str(path), "zb-ecc", "earth", -values[order, 0] * KYR, values[order, 1], frame="frame-free (e only)"
    )


def read_zb23(path: str | os.PathLike[str]) -> SolutionFile:
    r"""Read a ZB23.Rxx file: ``t`` (kyr, negative into the past), ``e``, ``i``, obliquity (rad), ``e sin ϖ``.

    Parameters
    ----------
    path : str or path-like

    Returns
    -------
    SolutionFile
        ``e``, ``obliquity``, ``climatic_precession``; no orbit plane.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "ZB23.R01.eiop.dat"
    >>> _ = path.write_text("".join(f"{-k}.0 0.0167 0.02 0.409 0.01\n" for k in range(4)))
    >>> read_zb23(path).span
    (-3000.0, 0.0)
    """
    table = read_table(path, ("t", "e", "i", "obliquity", "cp"))
    values = table.values
    check_column(table, values[:, 1], "eccentricity", "e")
    check_column(table, values[:, 3], "inclination", "obliquity")
    order = increasing(values[:, 0])
    t, e, _, obliquity, cp = values[order].T
    return SolutionFile(
        str(path),
        "zb23",
        "earth",
        t * KYR,
        e,
        obliquity=obliquity,
        climatic_precession=cp,
        frame="frame-free (e, obliquity, e sin(perihelion of date))",
    )


_ZB_ECC_NAME = re.compile(r"^ZB(1[78]|20)[a-z]", re.IGNORECASE)


def format_from_name(name: str) -> str | None:
    """The Zeebe format a file's name says (``zb18a``, ``zb-ecc``, ``zb23``), or ``None``.

    Examples
    --------
    >>> [format_from_name(n) for n in ("ems-plan3.dat", "ZB20a.dat", "ZB23.R01.eiop.dat")]
    ['zb18a', 'zb-ecc', 'zb23']
    """
    lower = name.lower()
    if lower.startswith("zb23") or lower.endswith(".eiop.dat"):
        return "zb23"
    if planet_from_name(name) is not None or "plan3" in lower:
        return "zb18a"
    if _ZB_ECC_NAME.match(name):
        return "zb-ecc"
    return None
