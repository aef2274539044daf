"""The package loads its names lazily: ``import andoyer`` stays light, every public name resolves."""

from __future__ import annotations

import subprocess
import sys

import pytest

import andoyer


def test_lazy_names_match_all():
    assert set(andoyer._LAZY) == set(andoyer.__all__)


@pytest.mark.parametrize("name", andoyer.__all__)
def test_lazy_name_resolves(name):
    assert getattr(andoyer, name) is not None
    assert name in dir(andoyer)


def test_lazy_unknown_name_raises():
    with pytest.raises(AttributeError, match="no attribute 'nonexistent'"):
        _ = andoyer.nonexistent


def test_lazy_import_loads_no_heavy_dependency():
    heavy = ("numpy", "scipy", "numba", "matplotlib", "flint", "sympy")
    code = f"import sys, andoyer; print(sorted(m for m in {heavy!r} if m in sys.modules))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


def test_cli_help_loads_no_command_module():
    code = (
        "import sys\n"
        "from andoyer.cli import main\n"
        "try:\n"
        "    main(['--help'])\n"
        "except SystemExit:\n"
        "    pass\n"
        "print(sorted(m for m in sys.modules if m.startswith('andoyer.cli.') or m in ('numpy', 'scipy')))\n"
    )
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert proc.stdout.strip().splitlines()[-1] == "[]"
    from andoyer.cli import COMMANDS

    for name in COMMANDS:
        assert name in proc.stdout


def test_cli_command_loads_only_its_module():
    from andoyer.cli import COMMANDS

    code = (
        "import sys\n"
        "from andoyer.cli import main\n"
        "main(['bodies', '--format', 'csv'])\n"
        "print(sorted(m for m in sys.modules if m.endswith('_cmd')))\n"
    )
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert proc.stdout.strip().splitlines()[-1] == "['andoyer.cli.bodies_cmd']"
    assert COMMANDS["bodies"][0] == "andoyer.cli.bodies_cmd"
