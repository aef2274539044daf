"""Moved module paths keep working for one release, with a DeprecationWarning."""

from __future__ import annotations

import importlib
import subprocess
import sys
import warnings

import pytest

from andoyer._moved import MOVED, new_name


@pytest.fixture(autouse=True)
def _forget_old_names():
    """Each test imports the old names afresh (an old name warns when it is first imported)."""
    for name in [name for name in sys.modules if new_name(name) is not None]:
        del sys.modules[name]


@pytest.mark.parametrize(("old", "new"), sorted(MOVED.items()))
def test_moved_old_name_is_new_module(old, new):
    parent = old.rpartition(".")[0]
    if new_name(parent) is not None:  # a moved package warns for itself (andoyer.free.kernels)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", DeprecationWarning)
            importlib.import_module(parent)
    with pytest.warns(DeprecationWarning, match=f"{old} moved to {new}"):
        module = importlib.import_module(old)
    assert module is importlib.import_module(new)


def test_moved_submodule_and_attribute_access():
    code = (
        "import warnings, andoyer\n"
        "warnings.simplefilter('error')\n"
        "try:\n"
        "    import andoyer.orbits.nbody\n"
        "except DeprecationWarning as exc:\n"
        "    print('warned', exc)\n"
        "warnings.simplefilter('ignore')\n"
        "import andoyer.orbits.nbody as old\n"
        "import andoyer.planetary.orbits.nbody as new\n"
        "print(old is new, andoyer.orbits is andoyer.planetary.orbits)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.splitlines() == [
        "warned andoyer.orbits moved to andoyer.planetary.orbits; the old name works until the next release",
        "True True",
    ]


def test_moved_renamed_leaf_keeps_the_new_child():
    # andoyer.orbits.secular (the Laplace-Lagrange theory) must not hide the package's own
    # andoyer.planetary.orbits.secular (the long model) once imported
    code = (
        "import warnings\n"
        "warnings.simplefilter('ignore')\n"
        "from andoyer.orbits.secular import LaplaceLagrangeOrbit\n"
        "import andoyer.planetary.orbits as package\n"
        "from andoyer.planetary.orbits import secular\n"
        "import sys\n"
        "print(package.secular.__name__, secular.__name__, LaplaceLagrangeOrbit.__module__)\n"
        "print(sys.modules['andoyer.orbits.secular'].__name__)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.splitlines() == [
        ("andoyer.planetary.orbits.secular andoyer.planetary.orbits.secular "
         "andoyer.planetary.orbits.laplace_lagrange"),
        "andoyer.planetary.orbits.laplace_lagrange",
    ]


def test_moved_new_name_cases():
    assert new_name("andoyer.cassini") == "andoyer.planetary.cassini"
    assert new_name("andoyer.spin_axis.model") == "andoyer.planetary.spin_axis.model"
    assert new_name("andoyer.cassinix") is None  # a prefix is a whole dotted part
    assert new_name("andoyer.plot.precession") is None


def test_moved_module_keeps_its_own_spec():
    with pytest.warns(DeprecationWarning, match="andoyer.orbits moved"):
        old = importlib.import_module("andoyer.orbits")
    assert old.__spec__.name == "andoyer.planetary.orbits"
    assert old.__spec__.submodule_search_locations  # still a package (importlib.resources needs it)
