"""Issue 26 item 1, the cause: the spin axis's step grid is never held whole.

The axis is integrated (and ``p_A`` unwrapped) a block of steps at a time: the memory of a run
does not grow with its span, only with its outputs. Measured with :mod:`tracemalloc` (numpy
reports its arrays to it) on two spans ten times apart; before the fix the longer run took
ten times the memory (10 Gyr of secular obliquity, 1.5·10⁸ stages: 24 GB).
"""

from __future__ import annotations

import importlib
import tracemalloc

import numpy as np
from spin_cases import PrecessingOrbit

from andoyer.planetary.spin_axis import SpinAxisModel, default_axis, output_times
from andoyer.planetary.spin_axis.history import evolve_axes, integrate_axis, step_count

# the module (the package's own name ``history`` is its function)
history_module = importlib.import_module("andoyer.planetary.spin_axis.history")

ORBIT = PrecessingOrbit()
MODEL = SpinAxisModel.from_precession_rate("mars", 7.597, np.radians(25.19), eccentricity=0.05)


def _peak(call) -> tuple[int, object]:
    tracemalloc.start()
    try:
        result = call()
        return tracemalloc.get_traced_memory()[1], result
    finally:
        tracemalloc.stop()


def test_spin_axis_memory_does_not_grow_with_the_steps(monkeypatch):
    monkeypatch.setattr(history_module, "BLOCK_STEPS", 256)
    s0 = default_axis("mars")
    short, _ = _peak(lambda: evolve_axes(ORBIT, MODEL, np.array([-2e6, 0.0, 1e6]), s0, 1000.0))
    times = np.array([-2e7, 0.0, 1e7])
    long, (axes_long, p_long) = _peak(lambda: evolve_axes(ORBIT, MODEL, times, s0, 1000.0))
    assert step_count(times, 1000.0) == 30000
    # 30 000 steps of 15 stages held whole: 450 000 orbit samples, about 100 MB
    assert long < 1.2 * short + 2**20, (short, long)
    assert axes_long.shape == (1, 3, 3)
    assert np.all(np.isfinite(p_long))


def test_spin_axis_blocks_give_the_unblocked_integration(monkeypatch):
    # Blocks of 7 steps against one block: the same axes to the last bit (the kernel continues
    # from the state it stopped at), and p_A to round-off (it is unwrapped by counting turns).
    times = output_times(-5e5, 2e5, 3e4)
    s0 = default_axis("mars")
    whole_axes, whole_p = evolve_axes(ORBIT, MODEL, times, s0)
    monkeypatch.setattr(history_module, "BLOCK_STEPS", 7)
    axes, p = evolve_axes(ORBIT, MODEL, times, s0)
    np.testing.assert_array_equal(axes, whole_axes)
    np.testing.assert_allclose(p, whole_p, rtol=0, atol=1e-12)
    grid, dense, index = integrate_axis(ORBIT, MODEL, times, s0[None, :])
    np.testing.assert_array_equal(dense[:, index], whole_axes)
    assert grid.size == step_count(times) + 1


def test_spin_axis_precession_counts_turns_beyond_two_pi():
    # The node regresses at 2π per 70 000 years: p_A of J2000's axis turns with it, many times
    # over 10 Myr, and is unwrapped between steps of 1000 years (a seventieth of a turn).
    times = np.array([-1e7, 0.0, 1e7])
    _, p = evolve_axes(ORBIT, MODEL, times, default_axis("mars"))
    assert abs(p[0, 0]) > 100 * np.pi
    assert p[0, 1] == 0.0
