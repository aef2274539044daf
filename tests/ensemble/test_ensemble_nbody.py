"""N-body ensembles: the perturbed initial conditions, members against a direct REBOUND run,
one member per task on Dask, resumed from the N-body cache, and bad input."""

from __future__ import annotations

import numpy as np
import pytest

import andoyer.planetary.orbits.nbody as nbody_module
from andoyer.ensemble import local_client, nbody_member, perturbed_state, run_nbody_ensemble
from andoyer.planetary.orbits import NBodyOrbit
from andoyer.planetary.orbits.planets import PLANETS, planet_data

SPAN = (-200.0, 0.0)
FAST = {"gr": False, "sample_years": 10.0}


@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv("ANDOYER_CACHE_DIR", str(tmp_path))
    return tmp_path


def heliocentric(rows):
    return rows[1:] - rows[:1]


@pytest.mark.parametrize(
    ("member", "seed", "perturb"), [(1, 0, "mercury"), (5, 3, "earth"), (2, 9, "neptune")]
)
def test_nbody_perturbed_state_moves_one_planet_by_delta(member, seed, perturb):
    data = planet_data()
    rows = perturbed_state(member, seed, 1e-10, perturb)
    helio = heliocentric(rows)
    j = PLANETS.index(perturb)
    moved = helio[:, :3] - data.position
    assert np.linalg.norm(moved[j]) == pytest.approx(1e-10, rel=1e-5)  # round-off of ~1 au positions
    others = np.delete(moved, j, axis=0)
    assert np.abs(others).max() < 1e-15
    np.testing.assert_allclose(helio[:, 3:], data.velocity, rtol=0, atol=1e-15)
    masses = np.array([data.sun_gm, *data.gm])
    np.testing.assert_allclose(masses @ rows, 0.0, atol=1e-14)  # barycentre at rest at the origin


def test_nbody_perturbed_state_seeded():
    a, b = perturbed_state(4, 1), perturbed_state(4, 1)
    np.testing.assert_array_equal(a, b)
    directions = [heliocentric(perturbed_state(k, 1))[0, :3] - planet_data().position[0] for k in (1, 2, 3)]
    assert min(np.linalg.norm(directions[i] - directions[j]) for i, j in ((0, 1), (0, 2), (1, 2))) > 1e-12
    assert perturbed_state(0, 1) is None


def test_nbody_member_zero_is_the_nominal_orbit():
    assert (
        nbody_member(0, "mars", seed=5, cache=False, gr=False).key
        == NBodyOrbit("mars", cache=False, gr=False).key
    )


def test_nbody_member_against_direct_rebound(cache):
    # A member displaced by 1e-5 au (1500 km: its orbit differs from the nominal one by ~1e-5)
    # integrated here with REBOUND's IAS15 from the same state, no andoyer code in the loop.
    import rebound

    delta = 1e-5
    member = nbody_member(1, "mercury", seed=2, delta=delta, **FAST)
    nominal = NBodyOrbit("mercury", **FAST)
    data = planet_data()
    sim = rebound.Simulation()
    sim.G = 1.0
    for m, row in zip([data.sun_gm, *data.gm], perturbed_state(1, 2, delta), strict=True):
        sim.add(m=m, x=row[0], y=row[1], z=row[2], vx=row[3], vy=row[4], vz=row[5])
    sim.integrator = "ias15"
    sim.dt = -1e-3
    sim.integrate(-100.0)
    r = np.array(sim.particles[1].xyz) - np.array(sim.particles[0].xyz)
    v = np.array(sim.particles[1].vxyz) - np.array(sim.particles[0].vxyz)
    h = np.cross(r, v)
    n = h / np.linalg.norm(h)
    e = np.cross(v, h) / (data.sun_gm + data.gm[0]) - r / np.linalg.norm(r)
    assert np.abs(member.normal(-100.0) - n).max() < 1e-9
    assert np.abs(member.eccentricity_vector(-100.0) - e).max() < 1e-8
    assert np.abs(nominal.eccentricity_vector(-100.0) - e).max() > 1e-7  # the displacement shows


def test_nbody_ensemble_resumes_from_the_cache(cache, monkeypatch):
    calls = []
    real = nbody_module.make_simulation

    def counting(*args, **kwargs):
        calls.append(1)
        return real(*args, **kwargs)

    monkeypatch.setattr(nbody_module, "make_simulation", counting)

    def stop_after_first(k):
        if k == 0:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        run_nbody_ensemble(3, SPAN, seed=1, scheduler="synchronous", on_member=stop_after_first, **FAST)
    first = len(calls)
    assert first > 0
    keys = run_nbody_ensemble(3, SPAN, seed=1, scheduler="synchronous", **FAST)
    second = len(calls) - first
    assert second == 2 * first  # members 1 and 2 integrated, member 0 read from its cache
    assert len(set(keys)) == 3
    run_nbody_ensemble(3, SPAN, seed=1, scheduler="synchronous", **FAST)
    assert len(calls) == first + second  # all three read from the cache

    # The members' orbits, read back, differ by the tiny displacement only.
    orbits = [nbody_member(k, "mercury", seed=1, **FAST) for k in range(3)]
    e = [o.eccentricity_vector(np.array(SPAN)) for o in orbits]
    assert 1e-12 < np.abs(e[1] - e[0]).max() < 1e-7
    assert len(calls) == first + second


def test_nbody_ensemble_on_dask_matches_synchronous(cache):
    with local_client(1, processes=False) as client:
        on_dask = run_nbody_ensemble(2, (-100.0, 0.0), seed=4, scheduler=client, **FAST)
    assert on_dask == run_nbody_ensemble(
        2, (-100.0, 0.0), seed=4, scheduler="synchronous", cache=False, **FAST
    )


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda: perturbed_state(-1), "expected a non-negative integer member"),
        (lambda: perturbed_state(1, seed=1.5), "expected a non-negative integer seed"),
        (lambda: perturbed_state(1, delta=0.0), "expected a displacement 0 < delta"),
        (lambda: perturbed_state(1, delta=float("nan")), "expected a displacement 0 < delta"),
        (lambda: perturbed_state(1, perturb="pluto"), "expected"),
        (lambda: nbody_member(1, initial_state=np.zeros((9, 6))), "expected the member's initial state"),
        (lambda: run_nbody_ensemble(0, SPAN, scheduler="synchronous"), "expected a positive integer number"),
        (lambda: run_nbody_ensemble(2, (0.0, -1.0), scheduler="synchronous"), "expected a finite span"),
        (lambda: run_nbody_ensemble(2, SPAN, delta=2.0, scheduler="synchronous"), "expected a displacement"),
        (
            lambda: run_nbody_ensemble(2, (-1e12, 0.0), scheduler="synchronous", cache=False, gr=False),
            "expected",
        ),
        (
            lambda: NBodyOrbit("mars", initial_state=np.zeros((8, 6)), cache=False, gr=False),
            "shape \\(9, 6\\)",
        ),
    ],
)
def test_nbody_ensemble_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()
