"""The implementations (backends) of the exact torque-free solution: their names, which run here, the default.

The closed-form solution runs three ways, each a *backend* chosen by name. The compiled and the
numpy backends call the same kernels, each formula written once (``<step>.py`` in the folders
of :mod:`andoyer.free`; :mod:`andoyer.regime`, :mod:`andoyer.special.compensated`): compiled
per state in numba loops, or on whole arrays.  A backend's drivers carry its name,
``<step>_<backend>.py``.  The scalar backend is a different algorithm for a different use (one
short step from a state that has just changed, with Carlson's integrals instead of theta
series):

``"compiled"``
    numba loops, ``*_compiled.py``: the classification and exact scaling
    (:mod:`~andoyer.free.common.scaling_compiled`), the set-up of triaxial states
    (:mod:`~andoyer.free.triaxial.setup_compiled`), their evaluation
    (:mod:`~andoyer.free.triaxial.evaluate_compiled`) and the fill of their periodic
    representation (:mod:`~andoyer.free.triaxial.periodic_compiled`), and the uniform rotations
    (axisymmetric bodies, spheres, steady spins, rest: :mod:`~andoyer.free.uniform.setup_compiled`,
    :mod:`~andoyer.free.uniform.evaluate_compiled`).  Available when numba is
    (:data:`andoyer._jit.NUMBA`: installed, and not switched off by ``ANDOYER_NUMBA=0``).
``"numpy"``
    vectorised numpy on arrays of states, ``*_numpy.py``:
    :mod:`~andoyer.free.common.scaling_numpy`, :mod:`~andoyer.free.triaxial.setup_numpy`,
    :mod:`~andoyer.free.triaxial.evaluate_numpy`, :mod:`~andoyer.free.uniform.setup_numpy`,
    :mod:`~andoyer.free.uniform.evaluate_numpy` and
    :func:`andoyer.free.triaxial.periodic_numpy.fill_numpy` (whose piecewise kernels,
    :mod:`andoyer.free.triaxial.periodic`, numba compiles for arrays when it is installed).
    Always available.
``"scalar"``
    one state, one step, no set-up: :mod:`andoyer.free.step_scalar` (``_step_one``, compiled by
    numba when it is available, plain Python otherwise), behind
    :func:`andoyer.free.step_scalar.free_step` and the compiled splitting loop
    (:mod:`andoyer.integrate.splitting.kernel`).  Always available.

:class:`~andoyer.free.FreeMotion` offers the first two (:data:`MOTION_BACKENDS`, its keyword
``backend``; by default :func:`default`, the fastest available).  Both treat the separatrix
with the same numpy kernels (:mod:`~andoyer.free.separatrix`); they differ on triaxial states
(SAM, LAM), the uniform rotations and the classification.  The scalar backend advances a state by
a step ``h`` from wherever it is, and has no periods or regime to report; it leaves states
within ``10⁻¹²`` of the separatrix to ``FreeMotion`` and keeps the accuracy of the others
near the separatrix only over short steps (it works in float64 where they carry the phase in
double-double: over a third of a period its error grows to ~1e-12 at ``1 − k² = 10⁻⁶`` and
~1e-9 at ``10⁻¹⁰``, against 1e-15 over a hundredth of a period; ``tests/free/free_backends.py``).
"""

from __future__ import annotations

from andoyer import _jit

__all__ = ["BACKENDS", "MOTION_BACKENDS", "available", "default", "resolve"]

#: Every backend of the torque-free solution, by name.
BACKENDS = ("compiled", "numpy", "scalar")
#: The backends of :class:`~andoyer.free.FreeMotion` (the scalar one has no set-up).
MOTION_BACKENDS = ("compiled", "numpy")


def available() -> tuple[str, ...]:
    """The backends that run here: all of :data:`BACKENDS`, less ``"compiled"`` without numba.

    Returns
    -------
    tuple of str

    Examples
    --------
    >>> set(available()) <= set(BACKENDS) and {"numpy", "scalar"} <= set(available())
    True
    """
    return tuple(name for name in BACKENDS if name != "compiled" or _jit.NUMBA)


def default() -> str:
    """The default backend of :class:`~andoyer.free.FreeMotion`: the fastest available.

    Returns
    -------
    str
        ``"compiled"`` when numba is available, else ``"numpy"``.

    Examples
    --------
    >>> default() in available()
    True
    """
    return "compiled" if _jit.NUMBA else "numpy"


def resolve(backend: str | None = None) -> str:
    """The :class:`~andoyer.free.FreeMotion` backend named ``backend`` (``None``: :func:`default`), checked.

    Parameters
    ----------
    backend : str or None
        One of :data:`MOTION_BACKENDS`, or ``None``.

    Returns
    -------
    str

    Raises
    ------
    ValueError
        For a name that is not a ``FreeMotion`` backend (the scalar backend included), or
        ``"compiled"`` where numba is not available.

    Examples
    --------
    >>> resolve("numpy")
    'numpy'
    >>> resolve() == default()
    True
    >>> resolve("fortran")
    Traceback (most recent call last):
    ...
    ValueError: expected backend one of 'compiled', 'numpy' (or None for the default), got 'fortran'
    """
    if backend is None:
        return default()
    if backend == "scalar":
        msg = (
            "expected backend 'compiled' or 'numpy' for FreeMotion, got 'scalar': the scalar kernel "
            "has no set-up and advances states one step at a time (andoyer.free.step_scalar.free_step)"
        )
        raise ValueError(msg)
    if backend not in MOTION_BACKENDS:
        names = ", ".join(repr(name) for name in MOTION_BACKENDS)
        msg = f"expected backend one of {names} (or None for the default), got {backend!r}"
        raise ValueError(msg)
    if backend == "compiled" and not _jit.NUMBA:
        msg = (
            "expected backend 'numpy' (or None), got 'compiled': the compiled backend needs numba, "
            "which is not installed or is switched off by ANDOYER_NUMBA=0"
        )
        raise ValueError(msg)
    return backend
