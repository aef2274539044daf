"""Module paths that moved: the old dotted name imports the new module, with a DeprecationWarning.

When a module or package of ``andoyer`` moves (``andoyer.orbits`` became
``andoyer.planetary.orbits``), its old name keeps working for one release: ``import
andoyer.orbits.nbody`` or ``from andoyer.orbits import nbody`` gives the module at its new
place, the same module object (so ``isinstance`` checks and module state are shared), and warns
once per old name. The table :data:`MOVED` is the one place that says what moved; the finder is
installed when ``andoyer`` is imported.

Examples
--------
>>> import warnings
>>> from andoyer._moved import MOVED, new_name
>>> new_name("andoyer.orbits.nbody")
'andoyer.planetary.orbits.nbody'
>>> new_name("andoyer.state") is None
True
"""

from __future__ import annotations

import importlib
import importlib.abc
import importlib.util
import sys
import warnings
from types import ModuleType

__all__ = ["MOVED", "install", "new_name"]

#: Old dotted prefix -> new dotted prefix. An old name ``old.x.y`` maps to ``new.x.y``.
MOVED: dict[str, str] = {
    "andoyer.orbits": "andoyer.planetary.orbits",
    "andoyer.orbits.secular": "andoyer.planetary.orbits.laplace_lagrange",
    "andoyer.precession": "andoyer.planetary.precession",
    "andoyer.cassini": "andoyer.planetary.cassini",
    "andoyer.spin_axis": "andoyer.planetary.spin_axis",
    "andoyer.nutation": "andoyer.planetary.nutation",
    "andoyer.propagation": "andoyer.integrate.propagation",
    "andoyer.integrate.averaged": "andoyer.integrate.secular",
    "andoyer.integrate.secular_steps": "andoyer.integrate.secular.rotations",
    "andoyer.integrate.split_kernel": "andoyer.integrate.splitting.kernel",
    "andoyer.integrate.reference_heyoka": "andoyer.integrate.reference.heyoka",
    "andoyer.integrate.euler_poisson": "andoyer.integrate.reference.euler_poisson",
    "andoyer.perturbations.secular": "andoyer.perturbations.averaged_gravity",
    "andoyer.charts": "andoyer.state",
    "andoyer.equations": "andoyer.state",
    "andoyer.hamiltonians": "andoyer.state",
    "andoyer.state_charts": "andoyer.state.hub",
    "andoyer.free.rotation": "andoyer.free_rotation",
    "andoyer.free.kernels.elliptic": "andoyer.free.common.elliptic",
    "andoyer.free.kernels.frame": "andoyer.free.common.polhode",
    "andoyer.free.kernels.piecewise": "andoyer.free.triaxial.periodic",
    "andoyer.free.kernels.series": "andoyer.free.triaxial.evaluate",
    "andoyer.free.kernels.triaxial": "andoyer.free.triaxial.setup",
    "andoyer.free.kernels.uniform": "andoyer.free.uniform.setup",
    "andoyer.free.kernels": "andoyer.free.common",  # after its modules: the first prefix that matches wins
    "andoyer.free.blocks": "andoyer.free.common.blocks",
    "andoyer.free.compiled_eval": "andoyer.free.triaxial.evaluate_compiled",
    "andoyer.free.compiled_regime": "andoyer.free.common.scaling_compiled",
    "andoyer.free.compiled_setup": "andoyer.free.triaxial.setup_compiled",
    "andoyer.free.compiled_uniform": "andoyer.free.uniform.evaluate_compiled",
    "andoyer.free.constants": "andoyer.free.common.constants",
    "andoyer.free.lean": "andoyer.free.step_scalar",
    "andoyer.free.periodic": "andoyer.free.triaxial.periodic_numpy",
    "andoyer.free.phase": "andoyer.free.common.cycles_numpy",
    "andoyer.free.quaternion": "andoyer.free.common.polhode_numpy",
    "andoyer.free.regime": "andoyer.free.common.polhode_numpy",
    "andoyer.free.series": "andoyer.free.triaxial.evaluate_numpy",
    "andoyer.free.table": "andoyer.free.triaxial.columns",
}


def new_name(fullname: str) -> str | None:
    """The new dotted name of the old module ``fullname``, or ``None`` if it did not move.

    Parameters
    ----------
    fullname : str
        A dotted module name.

    Returns
    -------
    str or None
    """
    # The longest old prefix wins: a module that moved on its own inside a moved package.
    for old, new in sorted(MOVED.items(), key=lambda item: -len(item[0])):
        if fullname == old or fullname.startswith(old + "."):
            return new + fullname[len(old) :]
    return None


class _Alias(importlib.abc.Loader):
    """Loads an old name as the module at its new place."""

    def __init__(self, old_name: str, target: str) -> None:
        self.old_name = old_name
        self.target = target

    def create_module(self, spec: importlib.machinery.ModuleSpec) -> ModuleType:
        warnings.warn(
            f"{spec.name} moved to {self.target}; the old name works until the next release",
            DeprecationWarning,
            stacklevel=2,
        )
        module = importlib.import_module(self.target)
        self.spec = module.__spec__
        return module

    def exec_module(self, module: ModuleType) -> None:
        """Nothing to run (the module ran at its new place): give it back its own spec.

        The import system sets ``__spec__`` of whatever ``create_module`` returns to the alias's
        spec; the module must keep its own (``importlib.resources`` reads it).
        """
        module.__spec__ = self.spec
        parent = sys.modules.get(self.old_name.rpartition(".")[0])
        old_leaf = self.old_name.rpartition(".")[2]
        if parent is not None and old_leaf != self.target.rpartition(".")[2] and type(parent) is ModuleType:
            parent.__class__ = _KeepsOwnChildren


class _KeepsOwnChildren(ModuleType):
    """A package whose children an old name's import cannot hide.

    After ``exec_module`` the import system binds the old leaf on the old parent, which is the
    new package itself. Where the leaf was renamed (``andoyer.orbits.secular`` is
    ``andoyer.planetary.orbits.laplace_lagrange``) that binding would replace the package's own
    child of that name (the long secular model, ``andoyer.planetary.orbits.secular``): a sibling
    module bound under another name than its own is not taken. The old name still imports its
    module (``from andoyer.orbits.secular import LaplaceLagrangeOrbit``, ``sys.modules``).
    """

    def __setattr__(self, name: str, value: object) -> None:
        if (
            isinstance(value, ModuleType)
            and value.__name__.rpartition(".")[0] == self.__name__
            and value.__name__ != f"{self.__name__}.{name}"
        ):
            return
        super().__setattr__(name, value)


class _Finder(importlib.abc.MetaPathFinder):
    """Finds old names of moved modules (ahead of the file system, where they no longer are)."""

    def find_spec(
        self, fullname: str, path: object = None, target: object = None  # noqa: ARG002
    ) -> importlib.machinery.ModuleSpec | None:
        new = new_name(fullname)
        if new is None:
            return None
        return importlib.util.spec_from_loader(fullname, _Alias(fullname, new))


def install() -> None:
    """Put the finder of moved modules first on ``sys.meta_path`` (once)."""
    if not any(isinstance(finder, _Finder) for finder in sys.meta_path):
        sys.meta_path.insert(0, _Finder())
