"""Issue 26 item 1, the cause: the nutation's quarter-day grid is never held whole.

The torque is integrated, the axis described, the fits accumulated and the outputs
interpolated a block of steps at a time: the memory of a run does not grow with its span.
Measured by the resident memory of a process; before the fix 1000 years
of nutation took 4.7 GB.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from andoyer import _limits as limits
from andoyer.planetary import nutation as nutation_package
from andoyer.planetary.nutation import numeric

RSS = """
import resource, sys
import andoyer.planetary.nutation.numeric as numeric
numeric.BLOCK_STEPS = 1024
from andoyer.planetary.nutation import nutation
nutation([0.0, float(sys.argv[1])], axis=sys.argv[2])
print(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss)
"""


def _peak_rss(span: float, axis: str) -> int:
    """The largest resident memory (KiB) of a process that computes one nutation over ``span`` years."""
    env = {**os.environ, "PYTHONPATH": str(Path(numeric.__file__).resolve().parents[3])}
    done = subprocess.run([sys.executable, "-c", RSS, str(span), axis], env=env, capture_output=True,
                          text=True, check=True, timeout=900)
    return int(done.stdout.split()[-1])


@pytest.mark.slow
@pytest.mark.parametrize("axis", ["figure", "momentum"])
def test_nutation_memory_does_not_grow_with_the_span(axis):
    # Measured in processes of their own (tracemalloc would trace RK4's every float): 100 years
    # held whole were 146 000 quarter-day points, about 400 MB more than 18.7 years.
    short, long = _peak_rss(18.7, axis), _peak_rss(100.0, axis)
    assert long < short + 16 * 2**10, (short, long)


@pytest.mark.slow
def test_nutation_blocks_give_the_unblocked_integration(monkeypatch):
    # Blocks of 1000 steps (the m̈ of the figure axis across their joints, the fits' rows, the
    # spline windows) against a single block; the times in any order.
    t = np.linspace(0.0, 18.0, 181)
    whole = np.array(nutation_package.nutation(t))
    monkeypatch.setattr(numeric, "BLOCK_STEPS", 1000)
    blocked = np.array(nutation_package.nutation(t[::-1]))[:, ::-1]
    np.testing.assert_allclose(blocked, whole, rtol=0, atol=1e-9)


def test_nutation_cost_known_before_the_work(monkeypatch):
    # 200 000 years: 292 million quarter-day steps of 60 µs, past the 3.6 hours a run may take.
    seconds, nbytes = nutation_package.nutation_cost([0.0, 2e5])
    assert seconds == pytest.approx(2e5 * 365.25 * 4 * 6e-5, rel=1e-6)
    assert nbytes == numeric.BLOCK_BYTES + 2 * numeric.OUTPUT_BYTES
    # The lunar theory's span (-100 000 to 39 747 years) keeps every accepted request under
    # 3.6 hours, so the refusal is shown under a budget of 0.36 hours: 20 000 years need 0.49.
    monkeypatch.setattr(limits, "MAX_STEPS", 10**9)
    with pytest.raises(ValueError, match=r"expected a nutation run at 2 times of at most about 0.36 hours"):
        nutation_package.nutation([0.0, 2e4])
