"""Damaged stores are repaired on resume: each chunk is checked against its ledger checksum.

Issue 18, item 4: deleting, garbling or truncating one chunk of a finished store and rerunning
the same command used to exit at once with NaNs, values up to 1e308 or an unreadable store.
Here every damage is followed by a rerun that must recompute exactly the damaged chunk, say so
in a warning, and leave files identical byte for byte to an undamaged run's.
"""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import google_crc32c
import numpy as np
import pytest
import zarr
from hypothesis import given
from hypothesis import strategies as st

from andoyer import bodies
from andoyer.ensemble import AndoyerSampler, DamagedChunkWarning, completed_chunks, run_ensemble
from andoyer.ensemble.ledger import digests_from_hex, digests_to_hex

EROS = bodies.get("eros")
TIMES = np.array([0.0, 1.5, 40.0])
N, CHUNK, N_CHUNKS = 27, 6, 5  # the last chunk short
DAMAGED = 2
VARIABLES = ("m_body", "m_body0", "quaternion", "quaternion0")


def run(out, scheduler="synchronous", on_chunk=None):
    return run_ensemble(
        AndoyerSampler(),
        N,
        TIMES,
        body=EROS,
        chunk=CHUNK,
        seed=9,
        out=out,
        scheduler=scheduler,
        progress=False,
        on_chunk=on_chunk,
    )


def file_bytes(path: Path) -> dict[str, bytes]:
    """Every file of a store (or the one file) by relative path, with its bytes."""
    if path.is_file():
        return {".": path.read_bytes()}
    return {str(p.relative_to(path)): p.read_bytes() for p in sorted(path.rglob("*")) if p.is_file()}


@pytest.fixture(scope="module")
def clean(tmp_path_factory):
    """An undamaged Zarr store and NetCDF file of the ensemble, and the in-memory result."""
    where = tmp_path_factory.mktemp("clean")
    run(where / "e.zarr")
    run(where / "e.nc")
    return {"zarr": where / "e.zarr", "nc": where / "e.nc", "memory": run(None)}


@pytest.fixture
def zarr_copy(clean, tmp_path):
    shutil.copytree(clean["zarr"], tmp_path / "e.zarr")
    return tmp_path / "e.zarr"


@pytest.fixture
def nc_copy(clean, tmp_path):
    shutil.copy(clean["nc"], tmp_path / "e.nc")
    return tmp_path / "e.nc"


def garble(path: Path, start: int = 0, stop: int | None = None) -> None:
    """Overwrite bytes [start, stop) of a file with seeded random bytes (their length kept)."""
    data = bytearray(path.read_bytes())
    stop = len(data) if stop is None else stop
    data[start:stop] = np.random.default_rng(7).integers(0, 256, stop - start, dtype=np.uint8).tobytes()
    path.write_bytes(bytes(data))


def damage_zarr(store: Path, how: str) -> None:
    """Damage chunk DAMAGED of a Zarr store (zarr v3 keys: <variable>/c/<sample chunk>/...)."""
    data = store / "quaternion" / "c" / str(DAMAGED) / "0" / "0"
    entry = store / "chunk_digest" / "c" / str(DAMAGED) / "0"
    assert data.is_file()
    assert entry.is_file()
    if how == "delete":  # every file of the chunk: its data read back as the NaN fill value
        for name in VARIABLES:
            shutil.rmtree(store / name / "c" / str(DAMAGED))
    elif how == "garble":
        garble(data)
    elif how == "garble-one-value":
        garble(data, 8 * 17, 8 * 18)
    elif how == "truncate":
        os.truncate(data, data.stat().st_size // 2)
    elif how == "ledger-garble":
        garble(entry)
    elif how == "ledger-truncate":
        os.truncate(entry, 5)
    elif how == "ledger-delete":
        entry.unlink()
    elif how == "ledger-and-data-delete":
        entry.unlink()
        shutil.rmtree(store / "quaternion" / "c" / str(DAMAGED))
    else:  # pragma: no cover - a typo in the parametrisation
        raise AssertionError(how)


def assert_repaired(result, damaged, clean_path, out, record, again, memory):
    """Exactly the damaged chunks recomputed and named once, files and values as undamaged."""
    assert sorted(again) == damaged
    assert len(record) == 1
    message = str(record[0].message)
    assert message.startswith(f"{len(damaged)} chunk(s) of the ensemble in")
    assert message.endswith(f"(chunk(s) {', '.join(map(str, damaged))})")
    assert record[0].filename == __file__  # stacklevel: the caller's line
    assert file_bytes(out) == file_bytes(clean_path)
    for name in (*VARIABLES, "time"):
        np.testing.assert_array_equal(result[name].values, memory[name].values)


@pytest.mark.parametrize(
    "how",
    [
        "delete",
        "garble",
        "garble-one-value",
        "truncate",
        "ledger-garble",
        "ledger-truncate",
        "ledger-delete",
        "ledger-and-data-delete",
    ],
)
def test_ensemble_zarr_damaged_chunk_is_recomputed_bit_for_bit(how, zarr_copy, clean):
    damage_zarr(zarr_copy, how)
    assert completed_chunks(zarr_copy).tolist() == [k != DAMAGED for k in range(N_CHUNKS)]
    again = []
    with pytest.warns(DamagedChunkWarning) as record:
        ds = run(zarr_copy, on_chunk=again.append)
    assert_repaired(ds, [DAMAGED], clean["zarr"], zarr_copy, record, again, clean["memory"])
    third = []
    run(zarr_copy, on_chunk=third.append)  # repaired: nothing to do, no warning (warnings are errors)
    assert third == []


@given(st.lists(st.binary(min_size=8, max_size=8), min_size=1, max_size=12))
def test_ensemble_ledger_hex_round_trip(entries):
    array = np.frombuffer(b"".join(entries), dtype=np.uint8).reshape(-1, 8)
    text = digests_to_hex(array)
    assert text.split() == [e.hex() for e in entries]
    np.testing.assert_array_equal(digests_from_hex(text, len(entries)), array)


def test_ensemble_zarr_damage_repaired_on_a_cluster(zarr_copy, clean, loopback_cluster):
    damage_zarr(zarr_copy, "garble")
    shutil.rmtree(zarr_copy / "m_body" / "c" / "4")  # and the short last chunk
    again = []
    with pytest.warns(DamagedChunkWarning) as record:
        ds = run(zarr_copy, loopback_cluster.scheduler_address, again.append)
    assert_repaired(ds, [DAMAGED, 4], clean["zarr"], zarr_copy, record, again, clean["memory"])


def documented_entry(memory, k):
    """The ledger entry as documented: CRC-32C of the variables in name order, each as its name, its
    shape and its values as little-endian float64, then the chunk's sample count (big-endian)."""
    region = slice(k * CHUNK, min((k + 1) * CHUNK, N))
    values = {name: memory[name].values[region].astype("<f8") for name in VARIABLES}
    message = b"".join(f"{name}{v.shape}".encode() + v.tobytes() for name, v in values.items())
    return google_crc32c.value(message).to_bytes(4, "big") + (region.stop - region.start).to_bytes(4, "big")


def test_ensemble_ledger_crc_matches_the_catalogue():
    # The check value of CRC-32C (CRC-32/ISCSI in Greg Cook's catalogue of parametrised CRCs).
    assert google_crc32c.value(b"123456789") == 0xE3069283


def test_ensemble_zarr_ledger_entry_is_the_documented_checksum(clean):
    group = zarr.open_group(clean["zarr"], mode="r")
    for k in range(N_CHUNKS):
        assert bytes(group["chunk_digest"][k]) == documented_entry(clean["memory"], k)


def test_ensemble_zarr_unfinished_store_resumes_without_warning(zarr_copy, clean):
    # A run killed before its end: chunks without a ledger entry are work to do, not damage.
    group = zarr.open_group(zarr_copy, mode="r+")
    del group.attrs["andoyer_finished"]
    (zarr_copy / "chunk_digest" / "c" / "3" / "0").unlink()
    again = []
    run(zarr_copy, on_chunk=again.append)
    assert again == [3]
    assert file_bytes(zarr_copy) == file_bytes(clean["zarr"])


def nc_offset(path: Path, memory, name: str, k: int) -> tuple[int, int]:
    """Where chunk k of variable ``name`` lies in a NetCDF3 file (big-endian float64)."""
    region = slice(k * CHUNK, min((k + 1) * CHUNK, N))
    needle = memory[name].values[region].astype(">f8").tobytes()
    data = path.read_bytes()
    start = data.find(needle)
    assert start > 0
    assert data.count(needle) == 1
    return start, start + len(needle)


@pytest.mark.parametrize("how", ["garble", "nan", "ledger-garble"])
def test_ensemble_netcdf_damaged_chunk_is_recomputed_bit_for_bit(how, nc_copy, clean):
    memory = clean["memory"]
    start, stop = nc_offset(nc_copy, memory, "m_body", DAMAGED)
    if how == "garble":
        garble(nc_copy, start, stop)
    elif how == "nan":
        data = bytearray(nc_copy.read_bytes())
        data[start:stop] = np.full((stop - start) // 8, np.nan).astype(">f8").tobytes()
        nc_copy.write_bytes(bytes(data))
    else:  # one hexadecimal digit of chunk DAMAGED's digest in the header's attribute
        data = nc_copy.read_bytes()
        at = data.index(documented_entry(memory, DAMAGED).hex().encode())
        flipped = b"0" if data[at : at + 1] != b"0" else b"1"
        nc_copy.write_bytes(data[:at] + flipped + data[at + 1 :])
    again = []
    with pytest.warns(DamagedChunkWarning) as record:
        ds = run(nc_copy, on_chunk=again.append)
    assert_repaired(ds, [DAMAGED], clean["nc"], nc_copy, record, again, memory)
    assert sorted(p.name for p in nc_copy.parent.iterdir()) == ["e.nc"]  # no parts or temporary left
    third = []
    run(nc_copy, on_chunk=third.append)
    assert third == []


class StopError(Exception):
    """Raised from the chunk callback: the run is interrupted."""


def test_ensemble_netcdf_interrupted_run_with_damaged_parts_is_repaired(tmp_path, clean):
    out = tmp_path / "e.nc"
    seen = []

    def stop_after_three(k):
        seen.append(k)
        if len(seen) == 3:
            raise StopError

    with pytest.raises(StopError):
        run(out, on_chunk=stop_after_three)
    parts = tmp_path / "e.nc.parts.zarr"
    garble(parts / "quaternion" / "c" / "1" / "0" / "0")
    again = []
    with pytest.warns(DamagedChunkWarning) as record:
        ds = run(out, on_chunk=again.append)
    np.testing.assert_array_equal(ds.quaternion.values, clean["memory"].quaternion.values)
    assert sorted(again) == [1, 3, 4]  # the damaged chunk and the two never written
    assert str(record[0].message).endswith("(chunk(s) 1)")
    assert file_bytes(out) == file_bytes(clean["nc"])
    assert not parts.exists()


def test_ensemble_netcdf_truncated_file_is_recomputed(nc_copy, clean):
    os.truncate(nc_copy, nc_copy.stat().st_size * 3 // 4)  # unreadable, its header still ours
    again = []
    with pytest.warns(DamagedChunkWarning) as record:
        ds = run(nc_copy, on_chunk=again.append)
    assert_repaired(ds, list(range(N_CHUNKS)), clean["nc"], nc_copy, record, again, clean["memory"])


@pytest.mark.parametrize(
    ("damage", "match"),
    [
        ("zarr.json", "expected an andoyer ensemble Zarr store at .* got an unreadable one"),
        ("quaternion/zarr.json", "expected an andoyer ensemble Zarr store at .* got an unreadable one"),
        ("chunk_digest/zarr.json", "expected an andoyer ensemble Zarr store at .* got an unreadable one"),
        ("rm quaternion", r"expected the arrays of this ensemble.*got \{'quaternion': 'missing'\}"),
        ("extra array", r"expected the arrays of this ensemble.*'notes': 'none'.*got \{'notes'"),
        ("other ensemble", r"expected the settings of the ensemble already in .*'seed': 8"),
    ],
)
def test_ensemble_zarr_damaged_metadata_is_a_clear_error(damage, match, zarr_copy):
    before = file_bytes(zarr_copy)
    if damage == "rm quaternion":
        shutil.rmtree(zarr_copy / "quaternion")
    elif damage == "extra array":
        zarr.open_group(zarr_copy, mode="r+").create_array("notes", shape=(N,), dtype=np.float64)
    elif damage == "other ensemble":
        group = zarr.open_group(zarr_copy, mode="r+")
        group.attrs["andoyer_ensemble"] = group.attrs["andoyer_ensemble"].replace('"seed": 9', '"seed": 8')
    else:
        garble(zarr_copy / damage, 10, 40)
    changed = file_bytes(zarr_copy)
    assert changed != before
    with pytest.raises(ValueError, match=match):
        run(zarr_copy)
    assert file_bytes(zarr_copy) == changed  # refused: nothing written


@pytest.mark.parametrize("damage", ["magic", "other ensemble"])
def test_ensemble_netcdf_foreign_or_unreadable_file_is_a_clear_error(damage, nc_copy):
    data = nc_copy.read_bytes()
    if damage == "magic":
        data = b"XYZ" + data[3:]
        match = "expected an andoyer ensemble NetCDF file at .* got an unreadable file"
    else:
        data = data.replace(b'"seed": 9', b'"seed": 8')
        match = "expected the settings of the ensemble already in"
    nc_copy.write_bytes(data)
    with pytest.raises(ValueError, match=match):
        run(nc_copy)
    assert nc_copy.read_bytes() == data


@pytest.mark.parametrize("kind", ["symlink", "fifo"])
def test_ensemble_zarr_refuses_links_and_special_files_inside(kind, zarr_copy, tmp_path):
    chunk_file = zarr_copy / "quaternion" / "c" / str(DAMAGED) / "0" / "0"
    outside = tmp_path / "precious.txt"
    outside.write_text("keep me")
    chunk_file.unlink()
    if kind == "symlink":
        chunk_file.symlink_to(outside)
    else:
        os.mkfifo(chunk_file)  # reading it would block forever
    with pytest.raises(ValueError, match=f"got a {'symbolic link' if kind == 'symlink' else 'special file'}"):
        run(zarr_copy)
    assert outside.read_text() == "keep me"


@pytest.mark.parametrize("suffix", ["zarr", "nc"])
def test_ensemble_output_symlink_is_written_through(suffix, tmp_path, clean):
    link, target = tmp_path / f"link.{suffix}", tmp_path / "data" / f"e.{suffix}"
    target.parent.mkdir()
    link.symlink_to(target)  # dangling until the run
    run(link)
    assert link.is_symlink()
    assert os.readlink(link) == str(target)
    assert file_bytes(target) == file_bytes(clean[suffix])
    again = []
    run(link, on_chunk=again.append)
    assert again == []


@pytest.mark.parametrize(
    ("suffix", "make", "got"),
    [("zarr", "file", "regular file"), ("nc", "dir", "directory"), ("nc", "fifo", "special file")],
)
def test_ensemble_output_of_the_wrong_kind_is_refused(suffix, make, got, tmp_path):
    out = tmp_path / f"e.{suffix}"
    if make == "file":
        out.write_text("mine")
    elif make == "dir":
        out.mkdir()
    else:
        os.mkfifo(out)
    with pytest.raises(ValueError, match=f"expected a .* at the ensemble output .* got a {got}"):
        run(out)
    assert sorted(p.name for p in tmp_path.iterdir()) == [out.name]
