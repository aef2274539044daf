"""``andoyer ensemble``: outputs equal the library's, resumable, one-line errors with exit 2."""

from __future__ import annotations

import re

import numpy as np
import pytest
import xarray as xr

from andoyer import bodies
from andoyer.cli import main
from andoyer.ensemble import AndoyerSampler, MomentumSampler, run_ensemble


def test_cli_ensemble_zarr_equals_library(tmp_path, capsys, loopback_cluster):
    out = tmp_path / "e.zarr"
    argv = [
        "ensemble",
        "--body",
        "eros",
        "--samples",
        "13",
        "--range",
        "0",
        "100",
        "3",
        "--out",
        str(out),
        "--chunk",
        "5",
        "--seed",
        "4",
        "--G",
        "1",
        "2",
        "--cos-J",
        "0",
        "1",
        "--quiet",
        "--scheduler",
        loopback_cluster.scheduler_address,
    ]
    assert main(argv) == 0
    ref = run_ensemble(
        AndoyerSampler(G=(1.0, 2.0), cos_J=(0.0, 1.0)),
        13,
        np.linspace(0, 100, 3),
        body=bodies.get("eros"),
        chunk=5,
        seed=4,
        scheduler="synchronous",
        progress=False,
    )
    with xr.open_zarr(out, consolidated=False) as ds:
        np.testing.assert_array_equal(ds.quaternion.values, ref.quaternion.values)
        np.testing.assert_array_equal(ds.m_body.values, ref.m_body.values)
    assert main(argv) == 0  # rerun: complete store, nothing to do
    assert capsys.readouterr().err == ""


def test_cli_ensemble_netcdf_momentum_sampler(tmp_path, loopback_cluster):
    out = tmp_path / "e.nc"
    argv = [
        "ensemble",
        "--moments",
        "1",
        "2",
        "3",
        "--samples",
        "6",
        "--times",
        "0",
        "1",
        "--out",
        str(out),
        "--sampler",
        "momentum",
        "--m-low",
        "0",
        "0",
        "1",
        "--m-high",
        "1",
        "1",
        "1",
        "--output",
        "andoyer",
        "--quiet",
        "--scheduler",
        loopback_cluster.scheduler_address,
    ]
    assert main(argv) == 0
    from andoyer import RigidBody

    ref = run_ensemble(
        MomentumSampler((0, 0, 1), (1, 1, 1)),
        6,
        [0.0, 1.0],
        body=RigidBody(1, 2, 3),
        output="andoyer",
        scheduler="synchronous",
        progress=False,
    )
    with xr.open_dataset(out, engine="scipy") as ds:
        for name in "lghLGH":
            np.testing.assert_array_equal(ds[name].values, ref[name].values)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["e.nc"]


@pytest.mark.parametrize(
    ("extra", "match"),
    [
        (["--out", "{tmp}/e.csv"], "expected --out ending in .zarr or .nc"),
        (["--out", "{tmp}/missing/e.zarr"], "expected an existing directory"),
        (["--samples", "0"], "positive integer n_samples"),
        (["--chunk", "-2"], "positive integer chunk"),
        (["--seed", "-1"], "non-negative integer seed"),
        (["--G", "0", "1"], "expected G > 0"),
        (["--range", "0", "1", "2.5"], "positive integer COUNT"),
        (["--scheduler", "nonsense"], "reachable Dask scheduler"),
        (["--workers", "0"], "positive integer number of workers"),
    ],
)
def test_cli_ensemble_bad_arguments_one_line_exit_2(extra, match, tmp_path, capsys):
    argv = ["ensemble", "--body", "earth", "--samples", "4", "--out", str(tmp_path / "e.zarr"), "--quiet"]
    argv += [] if "--range" in extra else ["--times", "0", "1"]
    argv += [a.format(tmp=tmp_path) for a in extra]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert err.startswith("andoyer ensemble: error: expected")
    assert match in err


def test_cli_ensemble_needs_a_body(tmp_path, capsys):
    assert main(["ensemble", "--samples", "4", "--times", "0", "--out", str(tmp_path / "e.zarr")]) == 2
    assert "expected --body NAME or --moments" in capsys.readouterr().err


def test_cli_ensemble_refuses_other_settings_on_resume(tmp_path, capsys, loopback_cluster):
    base = [
        "ensemble",
        "--body",
        "mars",
        "--samples",
        "5",
        "--times",
        "0",
        "--out",
        str(tmp_path / "e.zarr"),
        "--quiet",
        "--scheduler",
        loopback_cluster.scheduler_address,
    ]
    assert main(base) == 0
    assert main([*base, "--seed", "1"]) == 2
    assert "expected the settings of the ensemble already in" in capsys.readouterr().err


@pytest.mark.parametrize("suffix", ["zarr", "nc"])
def test_cli_ensemble_rerun_repairs_a_damaged_output(suffix, tmp_path, capsys):
    out = tmp_path / f"e.{suffix}"
    argv = ["ensemble", "--body", "eros", "--samples", "9", "--times", "0", "7", "--chunk", "4"]
    argv += ["--seed", "3", "--out", str(out), "--quiet", "--scheduler", "synchronous"]
    assert main(argv) == 0
    eros = bodies.get("eros")
    ref = run_ensemble(AndoyerSampler(), 9, [0.0, 7.0], body=eros, chunk=4, seed=3, scheduler="synchronous",
                       progress=False)
    if suffix == "zarr":
        (out / "m_body" / "c" / "1" / "0" / "0").unlink()  # chunk 1 would read back as NaN
    else:  # chunk 1 of m_body, found by its big-endian bytes, set to NaN
        data = out.read_bytes()
        needle = ref.m_body.values[4:8].astype(">f8").tobytes()
        at = data.index(needle)
        nans = np.full(len(needle) // 8, np.nan).astype(">f8").tobytes()
        out.write_bytes(data[:at] + nans + data[at + len(needle) :])
    capsys.readouterr()
    assert main(argv) == 0
    # The command line prints the library's DamagedChunkWarning as one line.
    err = capsys.readouterr().err
    expected = r"andoyer ensemble: warning: 1 chunk\(s\) of the ensemble in .*\(chunk\(s\) 1\)\n"
    assert re.fullmatch(expected, err), err
    ds = xr.open_zarr(out, consolidated=False) if suffix == "zarr" else xr.load_dataset(out, engine="scipy")
    with ds:
        np.testing.assert_array_equal(ds.m_body.values, ref.m_body.values)
        np.testing.assert_array_equal(ds.quaternion.values, ref.quaternion.values)
