"""Issue 14's acceptance with the ``nbody`` orbit: Mars against La2004, the Earth against VCW 2011.

Slow: one REBOUND integration of the Solar System over the last Myr and 20 kyr forward, in a
cache folder of its own shared by every test of this module, at an 8-day step: 48 CPU s per Myr
instead of the default 4-day step's 84, and measured 1.1×10⁻⁴° (Mars) and 3×10⁻⁵° (the Earth)
from it in obliquity over 1 Myr, far inside every tolerance below.
Reference numbers (typed in, with their sources; the measured distances are in docs/spin-axis.md):

* Mars, La2004 (Laskar et al. 2004, Icarus 170, 343; the IMCCE file INSOLN.LA2004.MARS.ASC):
  obliquity 25.1894° at J2000 (the 25.19° of the literature), 15.02° at its minimum 809 kyr ago
  and 35.23° at its maximum 987 kyr ago: the 15–35° band of the last Myr (Laskar et al. 2004;
  Ward 1992; Touma & Wisdom 1993); and its values at the epochs of :data:`LA2004_MARS`.
* The Earth, La2004 (Laskar et al. 2004, A&A 428, 261; INSOLN.LA2004.BTL.100.ASC): obliquity and
  climatic precession ``e sin ϖ`` at the epochs of :data:`LA2004_EARTH`.
* The Earth's equator and ecliptic of Vondrák, Capitaine & Wallace (2011, A&A 534, A22) through
  ``erfa.ltpequ`` and ``erfa.ltpecl``: an obliquity independent of andoyer's integrator and orbits.
"""

from __future__ import annotations

import erfa
import numpy as np
import pytest
from spin_cases import angle

from andoyer.planetary.orbits import NBodyOrbit, VondrakEcliptic
from andoyer.planetary.spin_axis import output_times, spin_axis_history

pytestmark = pytest.mark.slow

#: La2004's Mars obliquity (degrees) at J2000, and its minimum (−809 kyr) and maximum (−987 kyr) over
#: the last Myr.
LA2004_MARS_TODAY = 25.1894
LA2004_MARS_MIN = (-809000.0, 15.024)
LA2004_MARS_MAX = (-987000.0, 35.225)
#: La2004's Mars obliquity (degrees) at epochs of the last Myr (kyr from J2000).
LA2004_MARS = {
    -50: 22.60709264,
    -100: 26.50801829,
    -150: 24.61766905,
    -200: 22.11066798,
    -250: 26.20510132,
    -500: 32.70376376,
    -750: 34.33387117,
    -1000: 33.50802947,
}
#: La2004's Earth obliquity (degrees) and ``e sin ϖ`` at epochs of the last Myr (kyr from J2000).
LA2004_EARTH = {
    -100: (23.66470392, -0.00065012),
    -200: (23.13173858, -0.03833589),
    -500: (23.70887897, 0.00902333),
    -1000: (23.62814922, -0.0337606),
}
#: The WHFast step of these tests (days): see the module's notes.
STEP_DAYS = 8.0


@pytest.fixture(scope="module")
def nbody_cache(tmp_path_factory):
    """A fresh N-body cache folder for this module (never the user's)."""
    folder = tmp_path_factory.mktemp("andoyer-nbody-cache")
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("ANDOYER_CACHE_DIR", str(folder))
        yield folder


@pytest.fixture(scope="module")
def mars_history(nbody_cache):
    """Mars' axis over the last Myr at 1-kyr output, ``--precession-rate 7.597`` (the issue's setting)."""
    times = output_times(-1.0e6, 0.0, 1000.0)
    orbit = NBodyOrbit("mars", step_days=STEP_DAYS, progress=False)
    return spin_axis_history(orbit, "mars", times, precession_rate=7.597)


def test_mars_obliquity_today_nbody(mars_history):
    # The IAU pole of Mars (Archinal et al. 2011) on the N-body orbit of J2000: measured 25.1916°,
    # 0.0022° from La2004's 25.1894° (their pole differs from the IAU's by that much).
    assert mars_history.t[-1] == 0.0
    assert np.degrees(mars_history.obliquity[-1]) == pytest.approx(LA2004_MARS_TODAY, abs=0.005)


def test_mars_obliquity_range_last_myr_nbody(mars_history):
    # Measured (DE421 start): 14.992° 809 kyr ago and 35.493° 988 kyr ago against La2004's 15.024°
    # and 35.225° at -809 and -987 kyr.
    obliquity = np.degrees(mars_history.obliquity)
    assert 14.9 <= obliquity.min() <= 15.3
    assert 35.0 <= obliquity.max() <= 35.6
    for epoch, value in (LA2004_MARS_MIN, LA2004_MARS_MAX):
        near = np.abs(mars_history.t - epoch) <= 3000.0
        k = np.argmin(obliquity[near]) if value < 25 else np.argmax(obliquity[near])
        assert 0 < k < np.count_nonzero(near) - 1  # a local extremum inside the window
        assert obliquity[near][k] == pytest.approx(value, abs=0.3)


def test_mars_obliquity_last_20kyr_nbody(mars_history):
    # La2004's Mars obliquity 10 and 20 kyr ago (INSOLN.LA2004.MARS.ASC): 24.1838°, 23.5331°;
    # measured 0.0021° and 0.0016° away.
    for epoch, value in ((-10000.0, 24.1838), (-20000.0, 23.5331)):
        j = int(np.searchsorted(mars_history.t, epoch))
        assert np.degrees(mars_history.obliquity[j]) == pytest.approx(value, abs=0.005)


@pytest.mark.parametrize(("kyr", "tolerance"), [(-50, 0.03), (-100, 0.03), (-150, 0.03), (-200, 0.03),
                                                (-250, 0.03), (-500, 0.5), (-750, 0.5), (-1000, 0.5)])
def test_mars_obliquity_la2004_nbody(mars_history, kyr, tolerance):
    # Issue 14: a few hundredths of a degree over 250 kyr, about a degree over 1 Myr. Measured
    # 0.0045-0.0063° to -250 kyr, then 0.050°, 0.11°, 0.37° at -500, -750, -1000 kyr.
    j = int(np.searchsorted(mars_history.t, kyr * 1000.0))
    assert np.degrees(mars_history.obliquity[j]) == pytest.approx(LA2004_MARS[kyr], abs=tolerance)


def test_earth_obliquity_and_climatic_precession_la2004_nbody(nbody_cache):
    # Issue 14: the Earth with nbody within ~0.1° in obliquity and ~0.02 in e sin ϖ over 1 Myr.
    # Measured: obliquity 0.0006°, 0.0008°, 0.0032°, 0.022°; e sin ϖ 3.5e-4, 7.5e-4, 0.0016, 0.0020.
    t = output_times(-1.0e6, 0.0, 1000.0)
    h = spin_axis_history(NBodyOrbit("earth", step_days=STEP_DAYS, progress=False), "earth", t)
    for kyr, (obliquity, climatic) in LA2004_EARTH.items():
        j = int(np.searchsorted(t, kyr * 1000.0))
        assert np.degrees(h.obliquity[j]) == pytest.approx(obliquity, abs=0.05)
        assert h.climatic_precession[j] == pytest.approx(climatic, abs=0.005)


def test_earth_obliquity_nbody_near_vcw2011_20kyr(nbody_cache):
    # Measured over ±20 kyr: 0.00095° from the same integration on VCW's ecliptic (``vondrak``), and
    # 0.040° from VCW's own obliquity, where the ``vondrak`` history is 0.041° away too: VCW's
    # precession is a fit of a few hundredths of a degree at ±20 kyr, not the orbit.
    t = output_times(-20000.0, 20000.0, 500.0)
    h = spin_axis_history(NBodyOrbit("earth", step_days=STEP_DAYS, progress=False), "earth", t)
    on_vcw_ecliptic = spin_axis_history(VondrakEcliptic(), "earth", t)
    assert np.degrees(np.abs(h.obliquity - on_vcw_ecliptic.obliquity)).max() <= 0.002
    vcw = angle(erfa.ltpequ(2000.0 + t), erfa.ltpecl(2000.0 + t))
    assert np.degrees(np.abs(h.obliquity - vcw)).max() <= 0.045
