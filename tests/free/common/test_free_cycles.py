"""Phases reduced modulo one cycle with double-double frequencies, and their sin/cos."""

from fractions import Fraction

import mpmath as mp
import numpy as np

from andoyer.free.common.cycles import sincos_cycles, sincos_half_cycles
from andoyer.free.common.cycles_numpy import cycles, frequency


def test_cycles_is_exact_for_huge_phases():
    # ν t with ν a double-double, t up to 1e12 cycles: compare with exact rationals
    rng = np.random.default_rng(1)
    hi = rng.uniform(0.1, 10.0, 500)
    lo = hi * rng.uniform(-1e-16, 1e-16, 500)
    t = 10 ** rng.uniform(0, 11, 500) * rng.choice([-1, 1], 500)
    offset = rng.uniform(-0.5, 0.5, 500)
    got = cycles(frequency(hi, lo), t, offset=offset)
    for g, h, low, tt, o in zip(got, hi, lo, t, offset, strict=True):
        nu = Fraction(float(h)) + Fraction(float(low))
        exact = nu * Fraction(float(tt)) + Fraction(float(o))
        frac = exact - round(exact)
        assert abs(float(frac) - g) < 4e-16 or abs(abs(float(frac) - g) - 1) < 4e-16
    assert np.all((got >= -0.5) & (got <= 0.5))


def test_plain_double_phase_would_not_do():
    # the same phase from fl(ν_hi t) alone is off by far more than an ulp of one cycle
    h, low, t = 0.7310585786300049, 3.4e-17, 1.0e11
    exact = (Fraction(h) + Fraction(low)) * Fraction(t)
    want = float(exact - round(exact))
    naive = (h * t) % 1.0
    assert abs(float(cycles(frequency(h, low), np.float64(t))) - want) < 4e-16
    assert abs(naive - want) > 1e-7


def test_sincos_cycles_matches_mpmath():
    f = np.concatenate([np.linspace(-0.5, 0.5, 2001), [0.25, -0.25, 0.125, 0.5, -0.5, 0.0]])
    s, c = sincos_cycles(f)
    with mp.workdps(30):
        es = max(abs(float(mp.sin(2 * mp.pi * mp.mpf(x))) - v) for x, v in zip(f, s, strict=True))
        ec = max(abs(float(mp.cos(2 * mp.pi * mp.mpf(x))) - v) for x, v in zip(f, c, strict=True))
    assert es <= 4 * np.finfo(float).eps
    assert ec <= 4 * np.finfo(float).eps


def test_sincos_half_cycles_matches_mpmath():
    # the half angle alone (the periodic attitude's sin, cos(πg)); no doubling, so two ulps
    f = np.concatenate([np.linspace(-0.5, 0.5, 2001), [0.25, -0.25, 0.125, 0.5, -0.5, 0.0]])
    s, c = sincos_half_cycles(f)
    with mp.workdps(30):
        es = max(abs(float(mp.sin(mp.pi * mp.mpf(x))) - v) for x, v in zip(f, s, strict=True))
        ec = max(abs(float(mp.cos(mp.pi * mp.mpf(x))) - v) for x, v in zip(f, c, strict=True))
    assert es <= 2 * np.finfo(float).eps
    assert ec <= 2 * np.finfo(float).eps
    assert np.array_equal(sincos_cycles(f)[0], 2.0 * s * c)  # the doubling of the same half angle
