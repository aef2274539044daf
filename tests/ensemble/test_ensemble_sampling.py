"""Seeded sampling: documented distributions, per-chunk reproducibility, input checks."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import stats

from andoyer.ensemble import AndoyerSampler, Draw, InertiaSampler, MomentumSampler, chunk_rng
from conftest import documented_andoyer_samples


@pytest.mark.parametrize(("seed", "index"), [(0, 0), (1, 7), (2**40, 3)])
def test_chunk_rng_is_the_spawned_seed_sequence(seed, index):
    expected = np.random.default_rng(np.random.SeedSequence(seed).spawn(index + 1)[index]).random(5)
    np.testing.assert_array_equal(chunk_rng(seed, index).random(5), expected)


def test_chunk_rng_streams_differ_between_chunks_and_seeds():
    draws = {(s, k): chunk_rng(s, k).random() for s in range(3) for k in range(3)}
    assert len(set(draws.values())) == 9


@pytest.mark.parametrize(
    "ranges", [{}, {"G": (0.5, 2.0), "cos_J": (0.9, 1.0)}, {"cos_I": (-0.2, 0.1), "G": 3.0}]
)
def test_andoyer_sampler_follows_the_documented_rule(ranges):
    got = AndoyerSampler(**ranges).sample(chunk_rng(4, 2), 50)
    G = ranges.get("G", (1.0, 1.0))
    G = (G, G) if np.isscalar(G) else G
    ref = documented_andoyer_samples(4, 2, 50, **{**ranges, "G": G})
    np.testing.assert_array_equal(got.quaternion, ref.quaternion)
    np.testing.assert_array_equal(got.m_body, ref.m_body)


def test_andoyer_sampler_default_directions_are_isotropic():
    s = AndoyerSampler().sample(chunk_rng(0, 0), 20000)
    u_body = s.m_body / np.linalg.norm(s.m_body, axis=-1, keepdims=True)
    u_ref = s.m_reference / np.linalg.norm(s.m_reference, axis=-1, keepdims=True)
    for u in (u_body, u_ref):
        for axis in range(3):  # each component of a uniform unit vector is uniform on [-1, 1]
            assert stats.kstest(u[:, axis], stats.uniform(-1, 2).cdf).pvalue > 1e-3


def test_momentum_sampler_box_and_haar_attitudes():
    s = MomentumSampler(low=(-1.0, 0.0, 2.0), high=(1.0, 0.5, 3.0)).sample(chunk_rng(5, 0), 20000)
    m = s.m_body
    assert np.all((m >= [-1.0, 0.0, 2.0]) & (m <= [1.0, 0.5, 3.0]))
    # Haar measure: the image of a fixed body axis is uniform on the sphere
    z = s.rotation.apply([0.0, 0.0, 1.0])
    assert stats.kstest(z[:, 2], stats.uniform(-1, 2).cdf).pvalue > 1e-3
    # and the rotation angle has density (1 - cos a)/π on [0, π]
    angle = s.rotation.magnitude()
    assert stats.kstest(angle, lambda a: (a - np.sin(a)) / np.pi).pvalue > 1e-3


def test_inertia_sampler_respects_triangle_inequality_and_box():
    d = InertiaSampler(MomentumSampler(), low=(0.1, 0.1, 0.1), high=(1.0, 1.0, 1.0)).sample(
        chunk_rng(3, 1), 5000
    )
    assert isinstance(d, Draw)
    I = np.sort(d.parameters["moments"], axis=-1)
    assert np.all(I[:, 0] + I[:, 1] >= I[:, 2])
    assert np.all((I >= 0.1) & (I <= 1.0))
    assert d.state.shape == (5000,)


def test_samplers_reproducible_from_the_same_generator_state():
    for sampler in (
        AndoyerSampler(),
        MomentumSampler(),
        InertiaSampler(AndoyerSampler(), (1, 1, 1), (2, 2, 2)),
    ):
        a, b = sampler.sample(chunk_rng(8, 1), 7), sampler.sample(chunk_rng(8, 1), 7)
        sa, sb = (a.state, b.state) if isinstance(a, Draw) else (a, b)
        np.testing.assert_array_equal(sa.quaternion, sb.quaternion)


@pytest.mark.parametrize(
    ("make", "match"),
    [
        (lambda: AndoyerSampler(G=(0.0, 1.0)), "expected G > 0"),
        (lambda: AndoyerSampler(G=(2.0, 1.0)), "low <= high"),
        (lambda: AndoyerSampler(cos_J=(-1.5, 1.0)), "cos_J"),
        (lambda: AndoyerSampler(l=(0.0, np.inf)), "finite"),
        (lambda: MomentumSampler(low=(0, 0)), "three finite numbers"),
        (lambda: MomentumSampler(low=(1, 0, 0), high=(0, 1, 1)), "low <= high"),
        (lambda: InertiaSampler(AndoyerSampler(), (0, 1, 1), (1, 1, 1)), "0 < low <= high"),
        (lambda: InertiaSampler(AndoyerSampler(), (1, 1, 5), (1, 1, 5)), "triangle inequality"),
        (lambda: InertiaSampler(object(), (1, 1, 1), (1, 1, 1)), "sample"),
        (lambda: chunk_rng(-1, 0), "non-negative integer seed"),
        (lambda: chunk_rng(0, 1.5), "non-negative integer chunk index"),
        (lambda: AndoyerSampler().sample(chunk_rng(0, 0), -1), "non-negative integer number of samples"),
    ],
)
def test_sampling_bad_input_raises(make, match):
    with pytest.raises(ValueError, match=match):
        make()


def test_inertia_sampler_reports_nearly_infeasible_box():
    sampler = InertiaSampler(AndoyerSampler(), (1.0, 1.0, 2.0 - 1e-9), (1.0, 1.0, 3.0))  # accepts ~1e-9
    with pytest.raises(ValueError, match="still rejected"):
        sampler.sample(chunk_rng(0, 0), 1000)
