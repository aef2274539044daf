r"""The long-term ecliptic of Vondrák, Capitaine & Wallace (2011), through pyerfa.

``erfa.ltpecl`` gives the ecliptic pole as a unit vector in the J2000 mean
equator and equinox frame; the J2000 ecliptic frame is that frame turned by
``ε₀ = 84381.406″`` about ``x``:

.. math:: n_{ecl} = R_x(\varepsilon_0)\, n_{eq}, \qquad
   R_x(\varepsilon) = \begin{pmatrix}1&0&0\\0&\cos\varepsilon&\sin\varepsilon\\
   0&-\sin\varepsilon&\cos\varepsilon\end{pmatrix}.

Valid for ±200 000 years (a few tenths of a degree at the ends, ERFA's notes);
the source knows the plane only, not the ellipse.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer import catalogue
from andoyer.planetary.orbits.protocol import check_times

__all__ = ["EPSILON_0", "VondrakEcliptic"]

#: IAU 2006 obliquity of the ecliptic at J2000 (radians): 84381.406″, the catalogue's Earth
#: ``obliquity`` (Capitaine et al. 2003).
EPSILON_0 = catalogue.get("earth").obliquity.si()


class VondrakEcliptic:
    """The Earth's orbit plane of Vondrák, Capitaine & Wallace (2011), ±200 kyr.

    Examples
    --------
    >>> orbit = VondrakEcliptic()
    >>> orbit.normal([-1e5, 0.0, 1e5]).shape
    (3, 3)
    >>> orbit.has_eccentricity
    False
    """

    name = "vondrak"
    span = (-200000.0, 200000.0)
    has_eccentricity = False

    def normal(self, t: ArrayLike) -> NDArray[np.float64]:
        """Unit normal of the ecliptic of date, J2000 ecliptic frame.

        Parameters
        ----------
        t : array_like, shape (...)
            Julian years TT from J2000, within ``span``.

        Returns
        -------
        numpy.ndarray, shape (..., 3)
        """
        import erfa

        times = check_times(t, self.span, self.name)
        pole = erfa.ltpecl(2000.0 + times)
        c, s = np.cos(EPSILON_0), np.sin(EPSILON_0)
        y = c * pole[..., 1] + s * pole[..., 2]
        z = -s * pole[..., 1] + c * pole[..., 2]
        return np.stack([pole[..., 0], y, z], axis=-1)

    def eccentricity_vector(self, t: ArrayLike) -> NDArray[np.float64]:
        """Not known to this source: raises :class:`NotImplementedError`.

        Parameters
        ----------
        t : array_like, shape (...)
        """
        msg = "expected an orbit source with the eccentricity (nbody, secular or a table), got vondrak"
        raise NotImplementedError(msg)

    def __repr__(self) -> str:
        return "VondrakEcliptic()"
