"""The one atomic write: modes, replacement, and nothing left behind on failure."""

import os

import numpy as np
import pytest

from andoyer._files import atomic_replace, atomic_write_bytes


@pytest.fixture
def umask_027():
    old = os.umask(0o027)
    yield
    os.umask(old)


def test_atomic_replace_new_file_gets_umask_mode(tmp_path, umask_027):
    atomic_write_bytes(tmp_path / "new.bin", b"abc")
    assert (tmp_path / "new.bin").stat().st_mode & 0o777 == 0o640
    assert [p.name for p in tmp_path.iterdir()] == ["new.bin"]


def test_atomic_replace_keeps_mode_of_replaced_file(tmp_path, umask_027):
    target = tmp_path / "old.txt"
    target.write_text("old")
    target.chmod(0o604)
    atomic_write_bytes(target, b"new")
    assert target.read_bytes() == b"new"
    assert target.stat().st_mode & 0o777 == 0o604


def test_atomic_replace_failure_leaves_previous_file_and_no_debris(tmp_path):
    target = tmp_path / "keep.txt"
    target.write_text("previous")

    def write_half_and_fail():
        with atomic_replace(target) as part:
            part.write_text("half")
            raise RuntimeError("boom")

    with pytest.raises(RuntimeError, match="boom"):
        write_half_and_fail()
    assert target.read_text() == "previous"
    assert [p.name for p in tmp_path.iterdir()] == ["keep.txt"]


def test_orbit_table_written_with_umask_mode(tmp_path, umask_027):
    """Orbit tables were written 0600 (mkstemp's mode) before the one atomic write."""
    from andoyer.planetary.orbits.table import write_orbit_csv
    from andoyer.planetary.orbits.vondrak import VondrakEcliptic

    path = tmp_path / "orbit.csv"
    write_orbit_csv(path, VondrakEcliptic(), np.array([0.0, 1000.0]))
    assert path.stat().st_mode & 0o777 == 0o640
