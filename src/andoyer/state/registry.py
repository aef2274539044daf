"""The registry of charts: each chart's signature and dynamics written once.

As astropy registers its frame transforms on a graph, each chart module registers one
:class:`Chart` here, a star around the hub (the attitude quaternion ``q`` and the body
angular momentum ``m`` of :class:`andoyer.State`): the chart's coordinate names, which of
them are angles, the two functions that :func:`install` makes the chart's methods
``State.from_<name>`` (a class method) and ``State.as_<name>``, and the chart's free-body
Hamiltonian and equations of motion. Those functions' signatures are the chart's signature:
whether it needs the body's moments and its keyword options are read from them, and the
columns are checked against them when the chart registers. The ``State`` methods, the command
line's chart table (:mod:`andoyer.cli.chart_table`) and the documentation's table
(:func:`charts_markdown`, in ``docs/charts.md``) are generated from :data:`CHARTS`.

This module knows neither the state class nor any chart: the hub (:mod:`andoyer.state.hub`)
and each chart module import it, and a chart module registers with
``register(chart, State)``, which installs the methods; the package's ``__init__`` imports the
chart modules, in the order of the tables. The functions receive the state class (or a state);
:meth:`Chart.to_state` and :meth:`Chart.from_state` call them with the columns as a sequence:

``to_state(cls, values, body, **options) -> cls`` and
``from_state(state, body, **options) -> coordinates``.

Adding a chart is adding one module that registers a :class:`Chart` (``docs/charts.md``).

Examples
--------
>>> from andoyer import State
>>> from andoyer.state.registry import charts
>>> chart = charts()["andoyer"]
>>> chart.columns, chart.angles
(('l', 'g', 'h', 'L', 'G', 'H'), ('l', 'g', 'h'))
>>> s = chart.to_state(State, (0.3, 0.4, 0.5, 0.9, 1.0, 0.2), None)
>>> [round(float(x), 12) for x in chart.from_state(s, None)]
[0.3, 0.4, 0.5, 0.9, 1.0, 0.2]
>>> State.from_andoyer.__doc__ == chart.from_method.__doc__
True
"""

from __future__ import annotations

import inspect
import types
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any, NamedTuple

__all__ = ["CHARTS", "Chart", "Hub", "charts", "charts_markdown", "install", "register"]


class Hub(NamedTuple):
    """The hub chart's columns: the scalar-last attitude quaternion and the body momentum."""

    qx: Any
    qy: Any
    qz: Any
    qw: Any
    m1: Any
    m2: Any
    m3: Any


def _parameters(function: Callable[..., Any], first: str, where: str) -> list[inspect.Parameter]:
    """The parameters of ``function`` after its first, which must be called ``first``."""
    params = list(inspect.signature(function).parameters.values())
    if not params or params[0].name != first:
        msg = f"expected {where} to take {first!r} first, got {[p.name for p in params]}"
        raise ValueError(msg)
    return params[1:]


@dataclass(frozen=True)
class Chart:
    """One chart of the rotation state, registered once.

    Attributes
    ----------
    name : str
        The chart's name: ``State.from_<name>`` and ``State.as_<name>`` where ``method`` is set.
    columns : tuple of str
        The coordinate names, in order (a NamedTuple's ``_fields``); ``from_method`` takes them
        in this order, before its options.
    angles : tuple of str
        The columns that are angles (radians).
    summary : str
        One line for the tables.
    from_method : callable
        The function of the class method ``State.from_<name>``:
        ``from_method(cls, [body,] *columns, **options) -> cls`` (the body, where the chart needs
        it, may come first or as a keyword). Its signature, docstring and code are the method's.
    as_method : callable
        The function of the method ``State.as_<name>``: ``as_method(self, [body,] **options)``,
        the coordinates of the state ``self``.
    method : bool
        Whether :func:`install` gives ``State`` the two methods (the hub chart has none).
    source : str
        Where the chart's formulas and conventions are stated.
    needs_body : bool
        Whether the methods take the body's :class:`~andoyer.RigidBody` (a parameter ``body``);
        read from their signatures.
    hamiltonian : callable or None
        The free-body Hamiltonian in the chart's variables,
        ``hamiltonian(body, *columns, **options) -> array`` of the columns' broadcast shape
        (``None``: the chart gives none).
    equations : callable or None
        Hamilton's equations of the free body in the chart,
        ``equations(body, *columns, **options) -> rates``, a NamedTuple with one rate a column
        (``None``: the chart gives none).
    options : tuple of str
        The keyword options of the methods (``t``, ``epoch``, ``mode``): their parameters other
        than the columns and ``body``, in order of appearance; read from their signatures.
    """

    name: str
    columns: tuple[str, ...]
    angles: tuple[str, ...]
    summary: str
    from_method: Callable[..., Any]
    as_method: Callable[..., Any]
    method: bool = True
    source: str = ""
    hamiltonian: Callable[..., Any] | None = None
    equations: Callable[..., Any] | None = None
    needs_body: bool = field(init=False)
    options: tuple[str, ...] = field(init=False)

    def __post_init__(self) -> None:
        if not set(self.angles) <= set(self.columns):
            msg = f"expected angles among the columns {self.columns}, got {self.angles}"
            raise ValueError(msg)
        build = _parameters(self.from_method, "cls", f"from_{self.name}")
        read = _parameters(self.as_method, "self", f"as_{self.name}")
        names = [p.name for p in build if p.name in self.columns]
        positional = [p.name for p in build if p.kind is p.POSITIONAL_OR_KEYWORD and p.name != "body"]
        if names != list(self.columns) or positional[: len(names)] != names:
            msg = (
                f"expected from_{self.name} to take the columns {self.columns} positionally and in "
                f"order, got {[p.name for p in build]}"
            )
            raise ValueError(msg)
        in_build = any(p.name == "body" for p in build)
        if in_build != any(p.name == "body" for p in read):
            msg = f"expected from_{self.name} and as_{self.name} both to take the body or neither"
            raise ValueError(msg)
        for kind in ("hamiltonian", "equations"):
            function = getattr(self, kind)
            if function is None:
                continue
            given = [p.name for p in _parameters(function, "body", f"the {kind} of {self.name}")]
            if given[: len(self.columns)] != list(self.columns):
                msg = f"expected the {kind} of {self.name} to take body, then the columns {self.columns}"
                msg += f", got {given}"
                raise ValueError(msg)
        options = dict.fromkeys(p.name for p in (*build, *read) if p.name not in {*self.columns, "body"})
        object.__setattr__(self, "needs_body", in_build)
        object.__setattr__(self, "options", tuple(options))

    def to_state(self, cls: type, values: Sequence[Any], body: Any, **options: Any) -> Any:
        """The states of class ``cls`` at the coordinates ``values`` (one array a column).

        Parameters
        ----------
        cls : type
            The state class (:class:`andoyer.State`).
        values : sequence of array_like, each of shape (...)
            The columns, in the order of :attr:`columns`.
        body : RigidBody or None
            The body, where :attr:`needs_body`; ignored otherwise.
        **options
            The chart's :attr:`options`.

        Returns
        -------
        cls
            ``cls.from_<name>`` of the columns, the body and the options.

        Examples
        --------
        >>> from andoyer import State
        >>> from andoyer.state.registry import charts
        >>> charts()["euler"].to_state(State, (0.1, 0.5, 0.2, 1.0, 0.3, 0.8), None).shape
        ()
        """
        columns = list(values)
        if len(columns) != len(self.columns):
            msg = f"expected {len(self.columns)} columns {self.columns}, got {len(columns)}"
            raise ValueError(msg)
        arguments = dict(zip(self.columns, columns, strict=True))
        if self.needs_body:
            arguments["body"] = body
        return self.from_method(cls, **arguments, **options)

    def from_state(self, state: Any, body: Any, **options: Any) -> Any:
        """The coordinates of ``state`` (``state.as_<name>`` with the body and the options).

        Parameters
        ----------
        state : State, shape (...)
            The states.
        body : RigidBody or None
            The body, where :attr:`needs_body`; ignored otherwise.
        **options
            The chart's :attr:`options`.

        Returns
        -------
        NamedTuple of arrays, each of shape (...)
            The columns, in the order of :attr:`columns`.

        Examples
        --------
        >>> from andoyer import State
        >>> from andoyer.state.registry import charts
        >>> s = State.from_euler(0.1, 0.5, 0.2, 1.0, 0.3, 0.8)
        >>> round(float(charts()["euler"].from_state(s, None).Theta), 12)
        0.3
        """
        if self.needs_body:
            return self.as_method(state, body=body, **options)
        return self.as_method(state, **options)


CHARTS: dict[str, Chart] = {}


def register(chart: Chart, state: type | None = None) -> Chart:
    """Add ``chart`` to :data:`CHARTS` and give the state class its methods.

    A chart module calls ``register(chart, State)`` once, when it is imported: the chart joins
    the tables and :func:`install` gives ``State`` its ``from_<name>``/``as_<name>`` methods. A
    second chart of the same name is refused, before anything is installed.

    Parameters
    ----------
    chart : Chart
        The chart to register.
    state : type, optional
        The state class (:class:`andoyer.State`) that gets the chart's methods (none: only the
        tables get the chart).

    Returns
    -------
    Chart
        ``chart`` itself.

    Examples
    --------
    >>> from andoyer.state.registry import CHARTS, register
    >>> register(CHARTS["state"])
    Traceback (most recent call last):
    ...
    ValueError: expected a new chart name, got 'state' (already registered)
    """
    if chart.name in CHARTS:
        msg = f"expected a new chart name, got {chart.name!r} (already registered)"
        raise ValueError(msg)
    if state is not None:
        install(state, {chart.name: chart})
    CHARTS[chart.name] = chart
    return chart


def charts() -> Mapping[str, Chart]:
    """Every registered chart, in the order they registered.

    The package :mod:`andoyer.state` imports its chart modules in the order of the tables
    (``docs/charts.md``), so the built-in charts are all here whenever this module is.

    Returns
    -------
    Mapping of str to Chart
        The hub chart ``state`` first, then the charts in the order of ``docs/charts.md``, then
        any registered later.

    Examples
    --------
    >>> from andoyer.state.registry import charts
    >>> list(charts())
    ['state', 'euler', 'andoyer', 'initial_andoyer', 'sadov', 'serret', 'sam']
    """
    return dict(CHARTS)


def _method(owner: type, name: str, function: Callable[..., Any]) -> types.FunctionType:
    """``function`` as the method ``owner.<name>``: the same code, defaults and docstring, owner's names.

    A copy, not a wrapper, so a call costs what the function costs (the single-state fast
    paths) and a warning's ``stacklevel`` counts the same frames; the chart module keeps its
    function under its own name.
    """
    if not isinstance(function, types.FunctionType):
        msg = f"expected a Python function for {owner.__qualname__}.{name}, got {type(function).__name__}"
        raise TypeError(msg)
    method = types.FunctionType(
        function.__code__, function.__globals__, name, function.__defaults__, function.__closure__
    )
    method.__kwdefaults__ = dict(function.__kwdefaults__) if function.__kwdefaults__ else None
    method.__annotations__ = dict(function.__annotations__)
    method.__doc__ = function.__doc__
    method.__module__ = owner.__module__
    method.__qualname__ = f"{owner.__qualname__}.{name}"
    return method


def install(cls: type, registered: Mapping[str, Chart]) -> None:
    """Give ``cls`` the class method ``from_<name>`` and the method ``as_<name>`` of each chart.

    Each method is a copy of the chart's ``from_method``/``as_method`` (its code, signature and
    docstring) named as ``cls``'s own, so ``help``, :func:`inspect.signature` and the API pages
    show it as written in the chart's module. A chart whose ``method`` is false is skipped; a
    name ``cls`` defines already is refused.

    Parameters
    ----------
    cls : type
        The state class (:class:`andoyer.State`, on which :func:`register` installs each chart's
        methods).
    registered : Mapping of str to Chart
        The charts (:func:`charts`).

    Examples
    --------
    >>> from andoyer import State
    >>> from andoyer.state.registry import charts, install
    >>> class Sub(State):
    ...     __slots__ = ()
    >>> install(Sub, {"euler": charts()["euler"]})
    >>> Sub.from_euler.__qualname__, type(Sub.from_euler(0.1, 0.5, 0.2, 1.0, 0.3, 0.8)).__name__
    ('Sub.from_euler', 'Sub')
    >>> install(Sub, {"euler": charts()["euler"]})
    Traceback (most recent call last):
    ...
    ValueError: expected no attribute from_euler on Sub before install, got one
    """
    for chart in registered.values():
        if not chart.method:
            continue
        names = (f"from_{chart.name}", f"as_{chart.name}")
        for name in names:
            if name in vars(cls):
                msg = f"expected no attribute {name} on {cls.__qualname__} before install, got one"
                raise ValueError(msg)
        setattr(cls, names[0], classmethod(_method(cls, names[0], chart.from_method)))
        setattr(cls, names[1], _method(cls, names[1], chart.as_method))


def charts_markdown() -> str:
    """The Markdown table of the registered charts (the table of ``docs/charts.md``).

    Returns
    -------
    str
        One header, one rule and one row per chart, each line ending in a newline.

    Examples
    --------
    >>> from andoyer.state.registry import charts_markdown
    >>> print(charts_markdown().splitlines()[0])
    | chart | columns | angles | body | options | dynamics | summary |
    """
    lines = ["| chart | columns | angles | body | options | dynamics | summary |", "|" + " --- |" * 7]
    for chart in charts().values():
        dynamics = [kind for kind in ("hamiltonian", "equations") if getattr(chart, kind) is not None]
        cells = (
            f"`{chart.name}`",
            ", ".join(f"`{c}`" for c in chart.columns),
            ", ".join(f"`{c}`" for c in chart.angles) or "none",
            "yes" if chart.needs_body else "no",
            ", ".join(f"`{o}`" for o in chart.options) or "none",
            ", ".join(dynamics) or "none",
            chart.summary,
        )
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"
