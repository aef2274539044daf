from __future__ import annotations

import numpy as np
import pytest

from andoyer._fastmath import atan2_2pi, chunked


def test_atan2_2pi_matches_numpy_within_2ulp(rng):
    y, x = rng.normal(size=(2, 100_000)) * 10.0 ** rng.uniform(-200, 200, (2, 100_000))
    expected = np.mod(np.arctan2(y, x), 2 * np.pi)
    got = atan2_2pi(y, x)
    # Near 0 and 2π the two branches of the cut meet: compare on the circle.
    err = np.abs(np.angle(np.exp(1j * (got - expected))))
    assert err.max() <= 2 * np.spacing(2 * np.pi)
    assert np.all((got >= 0) & (got < 2 * np.pi))


@pytest.mark.parametrize(
    ("y", "x", "angle"),
    [
        (0.0, 1.0, 0.0),
        (1.0, 0.0, np.pi / 2),
        (0.0, -1.0, np.pi),
        (-1.0, 0.0, 1.5 * np.pi),
        (0.0, 0.0, 0.0),
        (1.0, 1.0, np.pi / 4),
        (-1.0, -1.0, 1.25 * np.pi),
    ],
)
def test_atan2_2pi_axes_and_diagonals(y, x, angle):
    assert atan2_2pi(np.array(y), np.array(x)) == pytest.approx(angle, abs=1e-15)


def test_chunked_equals_unchunked():
    a = np.arange(20_001, dtype=float)
    out = chunked(lambda v: (v * 2, v + 1), [a], 2, chunk=1000)
    assert np.array_equal(out[0], 2 * a)
    assert np.array_equal(out[1], a + 1)
