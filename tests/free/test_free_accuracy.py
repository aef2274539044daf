"""Acceptance: the closed form against a 57-digit Taylor integration of the equations of motion.

Body angular momentum relative error ≤ 1e-13 and attitude error ≤ 1e-12 rad at times up
to 100 periods, for 25 seeded bodies and states in every regime (SAM, LAM, 1 − k² down to
1e-10, near pure spin, the Earth, spheres, axisymmetric bodies, the separatrix, k² ≈ 1/2,
moments and momenta from 1e-6 to 1e12).  The default run checks five of them over a few
periods; ``-m slow`` checks all of them out to 100 periods.  Each on every backend
(``free_backends.py``: the scalar one near the separatrix over short steps, not on it).
"""

import mpmath as mp
import pytest
from free_backends import pairs
from free_cases import FAST, cases, complementary_parameter
from free_reference import TaylorReference, angle_between, relative_error

from andoyer.free import FreeMotion, Regime

CASES = cases()
BY_NAME = {c[0]: c for c in CASES}

M_TOL = 1e-13
Q_TOL = 1e-12


def _check(backend, name, multiples, reference):
    _, moments, m0, q0, t_unit = BY_NAME[name]
    times = backend.times(name, multiples)
    assert times, (name, backend)
    m, q = backend.propagate(moments, m0, q0, [k * t_unit for k in times])
    for j, k in enumerate(times):
        m_ref, q_ref = reference(name, k)
        assert relative_error(m_ref, m[j]) <= M_TOL, (name, backend, k)
        assert angle_between(q_ref, q[j]) <= Q_TOL, (name, backend, k)


def test_cases_cover_every_regime():
    regimes = {int(FreeMotion(c[1], c[2]).regime) for c in CASES}
    assert regimes >= {Regime.SAM, Regime.LAM, Regime.SEPARATRIX, Regime.AXISYMMETRIC, Regime.SPHERE}
    assert len(CASES) >= 20


@pytest.mark.slow
@pytest.mark.parametrize(("name", "free_backend"), pairs(FAST), indirect=["free_backend"])
def test_accuracy_over_a_few_periods(name, free_backend, reference):
    _check(free_backend, name, (0.37, 2.3), reference)


@pytest.mark.slow
@pytest.mark.parametrize(("name", "free_backend"), pairs(BY_NAME), indirect=["free_backend"])
def test_accuracy_to_100_periods(name, free_backend, reference):
    _check(free_backend, name, (0.37, 9.71, 100.0), reference)


def test_reference_conserves_the_invariants():
    # a self-check of the reference integrator: |m| and the energy to 30 digits
    _name, moments, m0, q0, t_unit = BY_NAME["sam-0"]
    ref = TaylorReference(moments, m0, q0)
    m, q = ref.advance_to(3.1 * t_unit)
    with mp.workdps(50):
        g0 = mp.fsum(mp.mpf(float(x)) ** 2 for x in m0)
        e0 = mp.fsum(mp.mpf(float(x)) ** 2 / mp.mpf(float(i)) for x, i in zip(m0, moments, strict=True))
        g1 = mp.fsum(x**2 for x in m)
        e1 = mp.fsum(x**2 / mp.mpf(float(i)) for x, i in zip(m, moments, strict=True))
        assert abs(g1 / g0 - 1) < mp.mpf(10) ** -30
        assert abs(e1 / e0 - 1) < mp.mpf(10) ** -30
        assert abs(mp.fsum(x**2 for x in q) - 1) < mp.mpf(10) ** -30


@pytest.mark.parametrize(
    ("name", "low", "high"),
    [
        ("near-separatrix-sam-1e-10", 0.5e-10, 2e-10),
        ("near-separatrix-lam-1e-10", 0.5e-10, 2e-10),
        ("k2-below-half", 0.5, 0.5 + 1e-9),
        ("k2-above-half", 0.5 - 1e-9, 0.5),
    ],
)
def test_cases_have_the_intended_modulus(name, low, high):
    _, moments, m0, _, _ = BY_NAME[name]
    assert low <= complementary_parameter(moments, m0) <= high
