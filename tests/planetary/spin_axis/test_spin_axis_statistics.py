"""Obliquity statistics against plain numpy and brute-force scans of the raw histories."""

from __future__ import annotations

import numpy as np
import pytest

from andoyer.planetary.spin_axis import obliquity_statistics


def _histories(seed: int = 3, members: int = 40, times: int = 120):
    rng = np.random.default_rng(seed)
    t = -1e5 * np.arange(times)[::-1]  # increasing, ending at J2000 (a past span)
    eps = np.radians(30.0 + 15.0 * np.cumsum(rng.standard_normal((members, times)), axis=1) / np.sqrt(times))
    eps[rng.integers(0, members, 5), :] = np.nan  # members with no value at all
    eps[2, :40] = np.nan  # a member that stopped, 40 outputs before the far end
    return t, eps


def test_statistics_moments_match_numpy_nan_functions():
    t, eps = _histories()
    s = obliquity_statistics(t, eps)
    with np.errstate(invalid="ignore"):
        assert np.allclose(s.mean, np.nanmean(eps, axis=0), rtol=1e-13, atol=0)
        assert np.allclose(s.std, np.nanstd(eps, axis=0), rtol=1e-12, atol=1e-15)
    assert np.array_equal(s.min, np.nanmin(eps, axis=0))
    assert np.array_equal(s.max, np.nanmax(eps, axis=0))
    assert np.array_equal(s.members, np.isfinite(eps).sum(axis=0))


def test_statistics_density_is_numpy_histogram_and_normalised():
    t, eps = _histories()
    edges = np.radians(np.linspace(-30.0, 120.0, 76))
    s = obliquity_statistics(t, eps, bins=edges)
    values = eps[np.isfinite(eps)]
    assert values.min() > edges[0]
    assert values.max() < edges[-1]
    expected, _ = np.histogram(values, bins=edges, density=True)
    assert np.allclose(s.pdf, expected, rtol=1e-13, atol=0)
    assert np.sum(s.pdf * np.diff(edges)) == pytest.approx(1.0, abs=1e-13)


def test_statistics_first_passage_matches_brute_scan():
    t, eps = _histories()
    thresholds = np.radians([20.0, 35.0, 45.0, 60.0])
    s = obliquity_statistics(t, eps, thresholds=thresholds)
    for k, level in enumerate(thresholds):
        for m in range(eps.shape[0]):
            expected = np.nan
            for j in range(t.size - 1, -1, -1):  # outward from J2000: the last time first
                if np.isfinite(eps[m, j]) and eps[m, j] >= level:
                    expected = t[j]
                    break
            assert s.first_passage[k, m] == expected or (
                np.isnan(expected) and np.isnan(s.first_passage[k, m])
            )
        reached = sum(np.nanmax(np.where(np.isfinite(row), row, -np.inf)) >= level for row in eps)
        assert s.exceedance[k] == reached / eps.shape[0]
        values = eps[np.isfinite(eps)]
        assert s.fraction_of_time[k] == np.count_nonzero(values >= level) / values.size


def test_statistics_exceedance_monotone_in_threshold():
    t, eps = _histories(seed=11)
    levels = np.radians(np.linspace(0.0, 90.0, 91))
    s = obliquity_statistics(t, eps, thresholds=levels)
    assert np.all(np.diff(s.exceedance) <= 0)
    assert np.all(np.diff(s.fraction_of_time) <= 0)
    assert s.exceedance[0] == np.mean(np.isfinite(eps).any(axis=1))


def test_statistics_dataset_in_degrees():
    t, eps = _histories()
    ds = obliquity_statistics(t, eps).to_dataset(eps)
    with np.errstate(invalid="ignore"):
        assert np.allclose(ds["mean"].values, np.degrees(np.nanmean(eps, axis=0)), rtol=1e-13)
    assert ds.threshold.values.tolist() == [40.0, 50.0, 60.0]
    widths = np.diff(ds.bin_edges.values)
    assert float(np.sum(ds.pdf.values * widths)) == pytest.approx(1.0, abs=1e-12)
    assert ds.obliquity.dims == ("sample", "time")
