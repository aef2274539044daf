"""Chaotic-obliquity ensembles through the ensemble runner: members, seeds, statistics, store."""

from __future__ import annotations

import numpy as np
import pytest

from andoyer.ensemble import MemberSampler, chunk_rng, obliquity_ensemble
from andoyer.planetary.spin_axis import default_axis, member_obliquities


def _small(**kwargs):
    return obliquity_ensemble(
        "mars", 3, -3e5, 1e5, scheduler="synchronous", progress=False, chunk=2, **kwargs
    )


def test_obliquity_ensemble_members_are_member_obliquities():
    """Each stored member is member_obliquities on its stored perturbation and precession rate."""
    ds = _small(seed=4)
    p = ds.orbit_perturbation.values
    for m in range(3):
        delta = (p[m, :16] + 1j * p[m, 16:])[None]
        run = member_obliquities(
            "mars", -3e5, 1e5, delta, default_axis("mars"), precession_rate=float(ds.precession_rate[m])
        )
        # the axis goes through the sampler's State: the same to round-off
        assert np.allclose(np.degrees(run.obliquity[0]), ds.obliquity.values[m], rtol=0, atol=1e-10)
    assert np.all((ds.precession_rate.values >= 7.59) & (ds.precession_rate.values <= 7.61))


def test_obliquity_ensemble_seeds_reproduce():
    a, b, c = _small(seed=1), _small(seed=1), _small(seed=2)
    assert np.array_equal(a.obliquity.values, b.obliquity.values)
    assert not np.array_equal(a.obliquity.values, c.obliquity.values)
    draw = MemberSampler("mars").sample(chunk_rng(1, 1), 1)  # sample 2 is chunk 1's first
    assert np.array_equal(draw.parameters["orbit_perturbation"][0], a.orbit_perturbation.values[2])


def test_obliquity_ensemble_statistics_against_numpy():
    ds = _small(seed=3, thresholds=np.radians([25.0, 26.0]))
    eps = ds.obliquity.values
    assert np.allclose(ds["mean"].values, eps.mean(axis=0), rtol=1e-13)
    assert np.allclose(ds["std"].values, eps.std(axis=0), rtol=1e-10, atol=1e-12)
    assert np.array_equal(ds["max"].values, eps.max(axis=0))
    reached = [(eps >= v).any(axis=1).mean() for v in (25.0, 26.0)]
    assert ds.exceedance.values.tolist() == pytest.approx(reached, abs=0)
    assert float(np.sum(ds.pdf.values * np.diff(ds.bin_edges.values))) == pytest.approx(1.0, abs=1e-12)


def test_obliquity_ensemble_store_resumes_identical(tmp_path):
    path = tmp_path / "mars.zarr"
    first = _small(seed=5, out=path)
    again = _small(seed=5, out=path)  # everything stored: nothing computed, the same numbers
    assert np.array_equal(first.obliquity.values, again.obliquity.values)


def test_obliquity_ensemble_moonless_earth_runs():
    ds = obliquity_ensemble("moonless-earth", 2, -2e5, 1e5, scheduler="synchronous", progress=False)
    assert ds.attrs["body"] == "moonless-earth"
    assert np.all(np.abs(ds.obliquity.values[:, 0] - 23.4393) < 0.01)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"body": "pluto"}, "expected a body"),
        ({"members": 0}, "positive whole number"),
        ({"precession_rate": (7.7, 7.6)}, "precession_rate"),
        ({"precession_rate": 7.6, "dynamical_ellipticity": 0.005}, "got both"),
        ({"perturbation": -1.0}, "perturbation size"),
        ({"end": 0.0}, "nonzero end"),
        ({"members": 4, "orbits": 3}, "dividing the 4 members"),
        ({"orbits": 0}, "number of orbits from 1"),
        ({"members": 4, "orbits": 2, "chunk": 3}, "chunk of whole orbits"),
        ({"body": "earth", "orbits": 1}, "spin-parameter range"),
        ({"orbits": 1, "precession_rate": 7.6}, "fixed spin parameter"),
    ],
)
def test_obliquity_ensemble_bad_input(kwargs, match):
    args = {"body": "mars", "members": 2, "end": -1e5, "interval": 1e5} | kwargs
    with pytest.raises(ValueError, match=match):
        obliquity_ensemble(**args, scheduler="synchronous", progress=False)


def test_obliquity_ensemble_shared_orbits_are_members_on_their_orbit():
    """Two orbits of three spin axes: each member is member_obliquities alone on its stored orbit and rate."""
    ds = obliquity_ensemble(
        "mars", 6, -3e5, 1e5, orbits=2, seed=7, scheduler="synchronous", progress=False, chunk=3
    )
    p = ds.orbit_perturbation.values
    assert ds.attrs["orbits"] == 2
    assert np.array_equal(p[0], p[2])
    assert np.array_equal(p[3], p[5])
    assert not np.array_equal(p[0], p[3])
    assert len(set(ds.precession_rate.values.tolist())) == 6
    for m in (0, 2, 4):
        delta = (p[m, :16] + 1j * p[m, 16:])[None]
        rate = float(ds.precession_rate[m])
        run = member_obliquities("mars", -3e5, 1e5, delta, default_axis("mars"), precession_rate=rate)
        assert np.allclose(np.degrees(run.obliquity[0]), ds.obliquity.values[m], rtol=0, atol=1e-10)


@pytest.mark.slow
def test_obliquity_ensemble_mars_100_myr_spreads():
    """Eight Mars members over 100 Myr: the secular model's chaos separates them (Laskar et al. 2004).

    After 100 Myr members started 1e-6 apart differ by degrees (the Lyapunov time is ~5 Myr),
    and the obliquity keeps within the range of Laskar et al. (2004)'s 100-Myr solutions, 0-70°.
    """
    ds = obliquity_ensemble("mars", 8, -1e8, 1e5, scheduler="synchronous", progress=False, seed=0, chunk=8)
    eps = ds.obliquity.values
    assert np.all(np.isfinite(eps))
    # 100 kyr on: together (the precession rates differ by up to 0.26 %: 0.2° apart after 1 Myr)
    assert ds["std"].values[1] < 0.01
    assert ds["std"].values[-100:].mean() > 1.0  # the last 10 Myr: apart
    assert eps.min() > 0.0
    assert eps.max() < 70.0


def test_obliquity_ensemble_cli_json_keys_match_the_api(tmp_path):
    import json

    from andoyer.cli import main

    out = tmp_path / "mars.json"
    argv = "obliquity mars --ensemble 3 --span -3e5 0 --step 1e5 --seed 2 --thresholds 25 60"
    code = main([*argv.split(), "--scheduler", "synchronous", "--format", "json", "--output", str(out)])
    assert code == 0
    got = json.loads(out.read_text())
    assert sorted(got) == [
        "density",
        "exceedance",
        "first_passage",
        "max",
        "mean",
        "members",
        "min",
        "std",
        "t",
    ]
    ds = obliquity_ensemble(
        "mars",
        3,
        -3e5,
        1e5,
        seed=2,
        thresholds=np.radians([25.0, 60.0]),
        scheduler="synchronous",
        progress=False,
    )
    assert got["members"] == 3
    assert got["t"] == ds.time.values.tolist()
    assert np.allclose(got["mean"], ds["mean"].values, rtol=1e-15)
    assert got["exceedance"] == {"25": float(ds.exceedance[0]), "60": float(ds.exceedance[1])}
    widths = np.diff(got["density"]["bins"])
    assert float(np.sum(np.array(got["density"]["pdf"]) * widths)) == pytest.approx(1.0, abs=1e-12)
