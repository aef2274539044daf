"""Compilation of the scalar kernels with numba (a base dependency), with a pure-Python fallback.

``NUMBA`` tells whether numba is importable and not switched off (the fallback serves
``ANDOYER_NUMBA=0`` and an environment where numba could not be installed); :func:`jit` compiles a
function with ``numba.njit(cache=True)`` when it is, and returns it unchanged otherwise, so
every kernel also runs (slowly, but identically) as plain Python. ``ANDOYER_NUMBA=0`` in the
environment, read at import, forces the interpreted path, which the tests also run.
"""

from __future__ import annotations

import importlib.util
import os
from types import FunctionType

# numba is imported by the first jit/jitable call, not here: a module that only runs kernels as
# Python (a single state through andoyer.state._kernels) must not pay numba's ~0.6 s import.
_numba = None

#: Whether the kernels decorated with :func:`jit` are compiled.
NUMBA = os.environ.get("ANDOYER_NUMBA", "1") != "0" and importlib.util.find_spec("numba") is not None

__all__ = [
    "NUMBA",
    "every",
    "exponent",
    "fused_multiply_add",
    "jit",
    "jitable",
    "on_arrays",
    "on_floats",
    "select",
    "when_compiled",
]


def _load_numba():
    """numba, imported on first use, with :func:`select` and :func:`every` overloaded for kernels."""
    global _numba  # noqa: PLW0603 - the one lazily loaded module
    if _numba is None:
        import math

        import numba
        from numba.extending import overload

        # Not inline="always" (here and below): numba's IR inliner trips over the conditional's
        # phi node (NumbaIRAssumptionWarning); the chart loops measured as fast without it.
        @overload(select)
        def _select_compiled(condition, if_true, if_false):  # noqa: ARG001 - numba's overload signature
            def conditional(condition, if_true, if_false):
                return if_true if condition else if_false

            return conditional

        @overload(every)
        def _every_compiled(condition):  # noqa: ARG001 - numba's overload signature
            return lambda condition: condition

        @overload(exponent)
        def _exponent_compiled(x):  # noqa: ARG001 - numba's overload signature
            return lambda x: math.frexp(x)[1]

        from llvmlite import ir
        from numba.core import cgutils, types
        from numba.extending import intrinsic

        @intrinsic
        def _fma(typingctx, a, b, c):  # noqa: ARG001 - numba's intrinsic signature
            """``a b + c`` rounded once (LLVM's ``llvm.fma``: the instruction, or libm's ``fma``)."""
            sig = types.float64(types.float64, types.float64, types.float64)

            def codegen(context, builder, signature, args):  # noqa: ARG001 - numba's codegen signature
                d = ir.DoubleType()
                kind = ir.FunctionType(d, [d, d, d])
                fn = cgutils.get_or_insert_function(builder.module, kind, "llvm.fma.f64")
                return builder.call(fn, args)

            return sig, codegen

        @overload(fused_multiply_add)
        def _fused_multiply_add_compiled(a, b, c):  # noqa: ARG001 - numba's overload signature
            return lambda a, b, c: _fma(a, b, c)  # noqa: PLW0108 - numba wants a Python implementation

        _numba = numba
        from numba.extending import register_jitable

        for function in _PENDING:
            register_jitable(function)
        _PENDING.clear()
        for register in _WHEN_COMPILED:
            register(overload)
        _WHEN_COMPILED.clear()
    return _numba


#: Registrations of compiled forms waiting for numba (:func:`when_compiled`).
_WHEN_COMPILED: list = []


def when_compiled(register):
    """Run ``register(overload)`` once numba is loaded (at once if it is): a compiled form, registered lazily.

    A module that gives one of its Python functions another implementation inside compiled
    kernels (numba's ``overload``) registers it through this, so that importing the module
    does not import numba; :func:`jit` loads numba, and with it every waiting registration,
    before it compiles anything.

    Parameters
    ----------
    register : callable
        ``register(overload)``, with numba's :func:`numba.extending.overload`.

    Returns
    -------
    callable
        ``register`` itself (usable as a decorator).

    Examples
    --------
    >>> def twice(x):
    ...     return 2.0 * x
    >>> @when_compiled
    ... def _compiled_twice(overload):
    ...     @overload(twice)
    ...     def _twice(x):
    ...         return lambda x: x + x
    >>> twice(1.5)
    3.0
    """
    if _numba is not None:
        from numba.extending import overload

        register(overload)
    elif NUMBA:
        _WHEN_COMPILED.append(register)
    return register


def fused_multiply_add(a, b, c):  # noqa: ARG001 - the compiled overload uses them
    """``a b + c`` rounded once, inside kernels compiled by :func:`jit` only (LLVM's ``llvm.fma``).

    numpy has no fused multiply-add, so called from Python this refuses rather than round
    twice: array code forms the exact error of a product by Dekker's splitting instead
    (:func:`andoyer.special.compensated.product_error`).

    Parameters
    ----------
    a, b, c : float
        Float64 operands.

    Returns
    -------
    float
        ``fl(a b + c)``.

    Raises
    ------
    TypeError
        When called from Python.

    Examples
    --------
    >>> fused_multiply_add(0.1, 0.1, -0.01)
    Traceback (most recent call last):
    ...
    TypeError: expected a call from a compiled kernel, got one from Python (numpy has no fused multiply-add)
    """
    msg = "expected a call from a compiled kernel, got one from Python (numpy has no fused multiply-add)"
    raise TypeError(msg)


def jit(function=None, *, inline=False, contract=False):
    """``numba.njit(cache=True)`` when numba is installed, else the function itself.

    Parameters
    ----------
    function : callable, optional
        The kernel (``@jit``); omitted when options are given (``@jit(inline=True)``).
    inline : bool, optional
        Inline the kernel into its compiled callers (numba's ``inline="always"``): for
        small kernels in hot loops, where the call boundary keeps LLVM from interleaving
        the caller's work with the kernel's.
    contract : bool, optional
        Let LLVM fuse a product and the sum that uses it into one multiply-add (numba's
        ``fastmath={"contract"}``, nothing else of fast-math: one rounding instead of two,
        no reordering).  The compiled values then differ from the same text run on numpy
        arrays by rounding (a few ulps), which a kernel that asks for it must allow.

    Examples
    --------
    A kernel compiled (or not) this way is called like any function; Carlson's
    ``R_F(0, 1, 2)`` (DLMF 19.20.1: the lemniscate constant ``Γ(1/4)²/(4√(2π))``):

    >>> from andoyer.free.common.elliptic import carlson_rf
    >>> round(float(carlson_rf(0.0, 1.0, 2.0)), 13)
    1.3110287771461
    """
    if function is None:
        return lambda f: jit(f, inline=inline, contract=contract)
    if not NUMBA:  # pragma: no cover - depends on the environment
        return function
    options = {"inline": "always"} if inline else {}
    if contract:
        options["fastmath"] = {"contract"}
    return _load_numba().njit(cache=True, error_model="numpy", **options)(function)


def jitable(function):
    """Let compiled kernels call the plain Python ``function`` (``numba.extending.register_jitable``).

    The function itself is returned unchanged, so Python callers keep calling it as
    Python; kernels compiled with :func:`jit` that name it compile it inline. Until numba
    is loaded (by the first :func:`jit`, before anything compiles) the registration waits,
    so a module of kernels that Python also runs does not import numba.

    Examples
    --------
    >>> def twice(x):
    ...     return 2.0 * x
    >>> jitable(twice) is twice
    True
    """
    if not NUMBA:  # pragma: no cover - depends on the environment
        return function
    if _numba is None:
        _PENDING.append(function)
        return function
    from numba.extending import register_jitable

    return register_jitable(function)


#: Functions given to :func:`jitable` before numba was loaded; registered when it is.
_PENDING: list = []


def select(condition, if_true, if_false):
    """``if_true`` where ``condition`` holds, else ``if_false``: the one branch of a kernel written once.

    A scalar kernel that must also run on whole arrays (the numpy path) chooses with this
    function instead of ``if``: called from Python on a Python ``bool`` (a kernel run on
    floats) it is the conditional expression ``if_true if condition else if_false``, on
    anything else :func:`numpy.where` (element-wise on arrays, a 0-d array on numpy
    scalars); inside a kernel compiled by :func:`jit` numba replaces it by the conditional
    expression, and :func:`on_arrays` by :func:`numpy.where`. Both operands are evaluated,
    so each must be finite-safe on its own (guard a division by selecting a safe
    denominator first: on floats Python raises ``ZeroDivisionError``).

    Parameters
    ----------
    condition : bool or ndarray of bool, shape (...)
        Where to take ``if_true``.
    if_true, if_false : float or ndarray, shape (...)
        The two candidates, broadcast with ``condition``.

    Returns
    -------
    float or ndarray, shape (...)
        The chosen values.

    Examples
    --------
    >>> import numpy as np
    >>> select(np.array([True, False]), 1.0, np.array([2.0, 3.0])).tolist()
    [1.0, 3.0]
    >>> select(0.0 > 1.0, 1.0, 2.0)
    2.0
    """
    # A Python bool costs a comparison, not numpy's ~1 µs call: the single-state fast path.
    if condition is True:
        return if_true
    if condition is False:
        return if_false
    import numpy as np

    return np.where(condition, if_true, if_false)


def every(condition):
    """Whether ``condition`` holds everywhere: the stopping test of a kernel's loop written once.

    Called from Python it is :func:`numpy.all` (a loop over a whole array stops when every
    element has converged); inside a kernel compiled by :func:`jit` it is the condition
    itself.

    Parameters
    ----------
    condition : bool or ndarray of bool, shape (...)
        The per-element test.

    Returns
    -------
    bool
        True where every element holds.

    Examples
    --------
    >>> import numpy as np
    >>> every(np.array([True, False])), every(True)
    (False, True)
    """
    import numpy as np

    return bool(np.all(condition))


def exponent(x):
    """The binary exponent ``e`` of ``x = f·2^e``, ``1/2 ≤ |f| < 1`` (0 for ``x = 0``): frexp's second value.

    Called from Python it is :func:`numpy.frexp`'s exponent (element-wise on arrays); inside a
    kernel compiled by :func:`jit` it is :func:`math.frexp`'s (numba has no scalar
    ``numpy.frexp``).  With :func:`numpy.ldexp` (which numba has for scalars) it scales a
    kernel's inputs by exact powers of two.

    Parameters
    ----------
    x : float or ndarray, shape (...)
        Finite values.

    Returns
    -------
    int or ndarray of int, shape (...)
        The exponents.

    Examples
    --------
    >>> import numpy as np
    >>> exponent(np.array([0.75, 6.0, 0.0])).tolist(), int(exponent(1.0))
    ([0, 3, 0], 1)
    """
    import numpy as np

    return np.frexp(x)[1]


#: Copies made by :func:`on_arrays` and :func:`on_floats`, by the id of the kernel they copy
#: (the kernel is kept here too, so that its id stays its own).
_COPIES: dict[str, dict[int, tuple[FunctionType, FunctionType]]] = {"arrays": {}, "floats": {}}


def _copy_kernels(kernels, kind: str, swap: dict[int, object], extra: dict, make) -> list[FunctionType]:
    """Copies ``make(kernel, namespace)`` of ``kernels``, in their modules' globals rebound.

    Each module's globals are copied once, ``extra`` added, and every value listed in
    ``swap`` (by id) or copied before (by id) replaced by its counterpart.
    """
    copied = _COPIES[kind]
    swap = {**swap, **{key: copy for key, (_, copy) in copied.items()}}
    namespaces: dict[int, dict] = {}
    copies = []
    for kernel in kernels:
        namespace = namespaces.get(id(kernel.__globals__))
        if namespace is None:
            namespace = namespaces[id(kernel.__globals__)] = dict(kernel.__globals__, **extra)
        copy = make(kernel, namespace)
        copy.__doc__, copy.__wrapped__ = kernel.__doc__, kernel
        copied[id(kernel)] = (kernel, copy)
        swap[id(kernel)] = copy
        copies.append(copy)
    for namespace in namespaces.values():
        for name, value in namespace.items():
            namespace[name] = swap.get(id(value), value)
    return copies


def on_arrays(*kernels: FunctionType) -> list[FunctionType]:
    """The scalar ``kernels`` as functions of whole numpy arrays: the same code, numpy's functions.

    A kernel written once for floats names its elementary functions from :mod:`math`
    (``from math import sqrt``), ``min``/``max`` and :func:`select`; run as Python on floats
    it is the single-state path (:func:`on_floats` makes it faster), and :func:`jit` compiles
    it. Each copy returned here runs the kernel's own code object with those names bound to
    their numpy ufuncs (``math.atan`` to :func:`numpy.arctan`, ``min`` to
    :func:`numpy.minimum`, :func:`select` to :func:`numpy.where`, ...) and every kernel
    already copied (here or by an earlier call) to its copy, so a kernel calling another
    calls its array form. Arithmetic, comparisons, ``abs`` and ``&``/``|`` (not
    ``and``/``or``/``not``) work unchanged on arrays; branches go through :func:`select`.
    numpy's elementary functions may differ from the C library's by an ulp, so the copies
    agree with the scalar kernel to that, not bit for bit.

    Parameters
    ----------
    *kernels : function
        Scalar kernels (plain Python functions); their modules' globals are read now.

    Returns
    -------
    list of function
        The array forms, in the order given.

    Examples
    --------
    >>> import numpy as np
    >>> from math import sqrt
    >>> def norm(x, y):
    ...     return select(x < 0, -1.0, 1.0) * sqrt(x * x + y * y)
    >>> (norm_arrays,) = on_arrays(norm)
    >>> norm(3.0, 4.0), norm_arrays(np.array([3.0, -3.0]), np.array([4.0, 4.0])).tolist()
    (5.0, [5.0, -5.0])
    """
    import math

    import numpy as np

    pairs = (
        (math.sqrt, np.sqrt), (math.sin, np.sin), (math.cos, np.cos), (math.tan, np.tan),
        (math.atan, np.arctan), (math.atan2, np.arctan2), (math.asin, np.arcsin), (math.acos, np.arccos),
        (math.hypot, np.hypot), (math.exp, np.exp), (math.log, np.log), (math.copysign, np.copysign),
        (math.floor, np.floor), (math.fabs, np.abs), (math.isfinite, np.isfinite),
        (select, np.where),
    )  # fmt: skip

    def same_code(kernel, namespace):
        code, defaults, closure = kernel.__code__, kernel.__defaults__, kernel.__closure__
        return FunctionType(code, namespace, kernel.__name__, defaults, closure)

    swap = {id(scalar): array for scalar, array in pairs}
    return _copy_kernels(kernels, "arrays", swap, {"min": np.minimum, "max": np.maximum}, same_code)


def on_floats(*kernels: FunctionType) -> list[FunctionType]:
    """The scalar ``kernels`` with each ``select(c, a, b)`` written ``a if c else b``: fast on floats.

    A call of :func:`select` from Python costs ~50 ns, a kernel's conditional expression a
    few: the copies returned here are compiled from the kernel's own source with each call
    of :func:`select` replaced by the conditional expression that numba compiles it to (and
    every kernel already copied by an earlier call replaced by its copy), so the
    single-state path runs the written formula at the speed of hand-written branches and
    gives the compiled kernel's bits. Only the chosen operand is evaluated: a kernel whose
    operands are finite-safe on their own (as :func:`select` asks) computes the same.

    Parameters
    ----------
    *kernels : function
        Scalar kernels (plain Python functions, source available); their modules' globals are
        read now.

    Returns
    -------
    list of function
        The float forms, in the order given.

    Examples
    --------
    >>> def clip(x):
    ...     return select(x < 0.0, 0.0, select(x > 1.0, 1.0, x))
    >>> (clip_floats,) = on_floats(clip)
    >>> [clip_floats(x) for x in (-1.0, 0.5, 2.0)] == [clip(x) for x in (-1.0, 0.5, 2.0)]
    True
    """
    import __future__  # isort: skip
    import ast
    import linecache

    class Conditional(ast.NodeTransformer):
        def __init__(self, names: dict) -> None:
            self.names = names

        def visit_Call(self, node: ast.Call) -> ast.AST:
            self.generic_visit(node)
            function = node.func
            named = isinstance(function, ast.Name) and self.names.get(function.id) is select
            if named and len(node.args) == 3:
                test, body, orelse = node.args
                return ast.copy_location(ast.IfExp(test=test, body=body, orelse=orelse), node)
            return node

    trees: dict[str, dict[int, ast.FunctionDef]] = {}

    def recompiled(kernel, namespace):
        # The kernel's definition, found by its first line in its file's syntax tree (parsed once
        # per file: tokenising each function's source, as inspect.getsource does, costs ~2 ms).
        filename, first = kernel.__code__.co_filename, kernel.__code__.co_firstlineno
        if filename not in trees:
            source = "".join(linecache.getlines(filename))
            nodes = ast.walk(ast.parse(source, filename))
            functions = [node for node in nodes if isinstance(node, ast.FunctionDef)]
            # (a decorated function's code starts at its first decorator, not at ``def``)
            trees[filename] = {min([f.lineno] + [d.lineno for d in f.decorator_list]): f for f in functions}
        definition = Conditional(kernel.__globals__).visit(trees[filename][first])
        definition.decorator_list = []  # the copy is the plain function
        flags = __future__.annotations.compiler_flag  # annotations stay strings, as in the source
        module = ast.Module(body=[definition], type_ignores=[])
        local: dict = {}
        exec(compile(module, filename, "exec", flags=flags, dont_inherit=True), namespace, local)
        return local[definition.name]

    return _copy_kernels(kernels, "floats", {}, {}, recompiled)
