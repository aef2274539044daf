r"""Frequency analysis of orbit histories: the fundamental secular frequencies ``g_j``, ``s_j``.

A quasi-periodic signal ``z(t) = Σ_k A_k e^{i(ν_k t + φ_k)}`` (the eccentricity variable
``e e^{iϖ}`` or the inclination variable ``sin(i/2) e^{iΩ}`` of a planet) is analysed by the
frequency-modified Fourier transform of Šidlichovský & Nesvorný (1996, *Celest. Mech.* 65,
137), Laskar's (1988, 1990) refinement of the Fourier transform with a Hanning window and
iterative subtraction of each line found, through REBOUND's implementation
(``rebound.frequency_analysis``, ``type="fmft"``: a well-kept library, already a dependency).
The tests check it on a synthetic quasi-periodic signal.

The fundamental frequencies are identified as Laskar does: ``g_j`` (``s_j``) is the line of
planet ``j``'s eccentricity (inclination) variable nearest to a reference value (La2004's,
:data:`~andoyer.planetary.orbits.laplace_lagrange.LA2004_G`) among its strongest lines;
``s_5 = 0`` (the invariable plane) is not measured.

Examples
--------
>>> t = np.arange(4096) * 250.0
>>> nu = np.radians(np.array([4.2575, -26.35]) / 3600.0)      # rad/yr
>>> z = 0.04 * np.exp(1j * nu[0] * t) + 0.01 * np.exp(1j * (nu[1] * t + 1.0))
>>> f, a, _ = spectral_lines(z, 250.0, count=2)
>>> np.round(f, 4).tolist(), np.round(a, 5).tolist()
([4.2575, -26.35], [0.04, 0.01])
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer.catalogue.units import ARCSEC

__all__ = ["fundamental_frequencies", "spectral_lines"]

Array = NDArray[np.float64]
ARCSEC_PER_RAD = 1.0 / ARCSEC


def spectral_lines(
    signal: ArrayLike, dt: float, count: int = 10, band: float = 60.0
) -> tuple[Array, Array, Array]:
    """The ``count`` strongest lines of a complex signal sampled every ``dt`` years.

    Parameters
    ----------
    signal : array_like of complex, shape (N,)
        Samples; the first ``2^⌊log₂ N⌋`` are used (the FMFT works on a power of two).
    dt : float
        Sampling interval, years.
    count : int
        Number of lines.
    band : float
        Search ``|ν| ≤ band`` (″/yr).

    Returns
    -------
    frequency, amplitude, phase : numpy.ndarray, shape (count,)
        ″/yr, the signal's units, radians (at the first sample).
    """
    import rebound

    z = np.asarray(signal, dtype=complex)
    if z.ndim != 1 or z.size < 64 or not np.all(np.isfinite(z)):
        msg = f"expected a finite 1-d signal of at least 64 samples, got shape {z.shape}"
        raise ValueError(msg)
    n = 1 << int(np.floor(np.log2(z.size)))
    data = np.empty(2 * n)
    data[0::2], data[1::2] = z[:n].real, z[:n].imag
    limit = band / ARCSEC_PER_RAD * dt
    nu, amplitude, phase = rebound.frequency_analysis(
        data, type="fmft", nfreq=count, minfreq=-limit, maxfreq=limit
    )
    return np.asarray(nu) / dt * ARCSEC_PER_RAD, np.asarray(amplitude), np.asarray(phase)


def fundamental_frequencies(
    z: ArrayLike, zeta: ArrayLike, dt: float, reference_g: ArrayLike, reference_s: ArrayLike, count: int = 12
) -> tuple[Array, Array]:
    """``g_1…g_P`` and ``s_1…s_P`` (″/yr) from each planet's ``z`` and ``ζ`` histories.

    Parameters
    ----------
    z, zeta : array_like of complex, shape (P, N)
        Eccentricity and inclination variables of the planets (any normalisation), sampled
        every ``dt`` years.
    dt : float
    reference_g, reference_s : array_like, shape (P,)
        Approximate values (″/yr) that name the lines; ``s_j = 0`` references are not measured
        (returned as 0).
    count : int
        Lines searched per signal.

    Returns
    -------
    g, s : numpy.ndarray, shape (P,)
        For each planet, the line nearest to the reference among those with at least 5 % of
        the strongest line's amplitude.
    """
    out = []
    for signals, reference in ((z, reference_g), (zeta, reference_s)):
        values = np.zeros(len(reference))
        for j, target in enumerate(np.asarray(reference, dtype=float)):
            if target == 0.0:
                continue
            f, a, _ = spectral_lines(np.asarray(signals)[j], dt, count)
            strong = a >= 0.05 * a.max()
            values[j] = f[strong][np.argmin(np.abs(f[strong] - target))]
        out.append(values)
    return out[0], out[1]
