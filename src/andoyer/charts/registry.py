"""The registry of charts: each chart's signature written once.

As astropy registers its frame transforms on a graph, each chart module registers one
:class:`Chart` here, a star around the hub (the attitude quaternion ``q`` and the body
angular momentum ``m`` of :class:`andoyer.State`): the chart's coordinate names, which of
them are angles, whether it needs the body's moments, its keyword options and the two
converters between its coordinates and a state.  The command line's chart table
(:mod:`andoyer.cli.chart_table`), the documentation's table (:func:`charts_markdown`, in
``docs/charts.md``) and the test that the ``State.from_<name>``/``as_<name>`` methods keep
the registry's parameters are generated from, or checked against, :data:`CHARTS`.

The converters receive the state class (or a state) rather than importing it, so this
layer stays below :mod:`andoyer.state`:

``to_state(cls, values, body, **options) -> cls`` and
``from_state(state, body, **options) -> coordinates``.

Examples
--------
>>> from andoyer import State
>>> from andoyer.charts.registry import charts
>>> chart = charts()["andoyer"]
>>> chart.columns, chart.angles
(('l', 'g', 'h', 'L', 'G', 'H'), ('l', 'g', 'h'))
>>> s = chart.to_state(State, (0.3, 0.4, 0.5, 0.9, 1.0, 0.2), None)
>>> [round(float(x), 12) for x in chart.from_state(s, None)]
[0.3, 0.4, 0.5, 0.9, 1.0, 0.2]
"""

from __future__ import annotations

import importlib
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, NamedTuple

import numpy as np

__all__ = ["CHARTS", "Chart", "Hub", "charts", "charts_markdown", "register"]

# The chart modules that register their charts on import.
_MODULES = ("euler", "andoyer", "sadov", "serret", "sam")
# The order of the tables (import order varies with what the caller imported first).
_ORDER = ("state", "euler", "andoyer", "initial_andoyer", "sadov", "serret", "sam")


class Hub(NamedTuple):
    """The hub chart's columns: the scalar-last attitude quaternion and the body momentum."""

    qx: Any
    qy: Any
    qz: Any
    qw: Any
    m1: Any
    m2: Any
    m3: Any


@dataclass(frozen=True)
class Chart:
    """One chart of the rotation state, registered once.

    Attributes
    ----------
    name : str
        The chart's name: ``State.from_<name>`` and ``State.as_<name>`` where ``method`` is set.
    columns : tuple of str
        The coordinate names, in order (a NamedTuple's ``_fields``).
    angles : tuple of str
        The columns that are angles (radians).
    summary : str
        One line for the tables.
    to_state : callable
        ``to_state(cls, values, body, **options)``: the state of class ``cls`` at the coordinates.
    from_state : callable
        ``from_state(state, body, **options)``: the coordinates of ``state``.
    needs_body : bool
        Whether the converters need the body's :class:`~andoyer.RigidBody`.
    options : tuple of str
        Keyword options of the ``State`` methods (``t``, ``epoch``, ``mode``).
    method : bool
        Whether ``State`` has ``from_<name>``/``as_<name>`` methods with these columns.
    source : str
        Where the chart's formulas and conventions are stated.
    """

    name: str
    columns: tuple[str, ...]
    angles: tuple[str, ...]
    summary: str
    to_state: Callable[..., Any]
    from_state: Callable[..., Any]
    needs_body: bool = False
    options: tuple[str, ...] = ()
    method: bool = True
    source: str = ""

    def __post_init__(self) -> None:
        if not set(self.angles) <= set(self.columns):
            msg = f"expected angles among the columns {self.columns}, got {self.angles}"
            raise ValueError(msg)


CHARTS: dict[str, Chart] = {}


def register(chart: Chart) -> Chart:
    """Add ``chart`` to :data:`CHARTS` (a second chart of the same name is refused).

    Parameters
    ----------
    chart : Chart
        The chart to register.

    Returns
    -------
    Chart
        ``chart`` itself.

    Examples
    --------
    >>> from andoyer.charts.registry import CHARTS, register
    >>> register(CHARTS["state"])
    Traceback (most recent call last):
    ...
    ValueError: expected a new chart name, got 'state' (already registered)
    """
    if chart.name in CHARTS:
        msg = f"expected a new chart name, got {chart.name!r} (already registered)"
        raise ValueError(msg)
    CHARTS[chart.name] = chart
    return chart


def charts() -> Mapping[str, Chart]:
    """Every registered chart, the chart modules imported first (they register on import).

    Returns
    -------
    Mapping of str to Chart
        The hub chart ``state`` first, then the charts in the order of ``docs/charts.md``.

    Examples
    --------
    >>> from andoyer.charts.registry import charts
    >>> list(charts())
    ['state', 'euler', 'andoyer', 'initial_andoyer', 'sadov', 'serret', 'sam']
    """
    for module in _MODULES:
        importlib.import_module(f"andoyer.charts.{module}")
    rank = {name: i for i, name in enumerate(_ORDER)}
    return dict(sorted(CHARTS.items(), key=lambda item: rank.get(item[0], len(rank))))


def charts_markdown() -> str:
    """The Markdown table of the registered charts (the table of ``docs/charts.md``).

    Returns
    -------
    str
        One header, one rule and one row per chart, each line ending in a newline.

    Examples
    --------
    >>> from andoyer.charts.registry import charts_markdown
    >>> print(charts_markdown().splitlines()[0])
    | chart | columns | angles | body | options | summary |
    """
    lines = ["| chart | columns | angles | body | options | summary |", "|" + " --- |" * 6]
    for chart in charts().values():
        cells = (
            f"`{chart.name}`",
            ", ".join(f"`{c}`" for c in chart.columns),
            ", ".join(f"`{c}`" for c in chart.angles) or "none",
            "yes" if chart.needs_body else "no",
            ", ".join(f"`{o}`" for o in chart.options) or "none",
            chart.summary,
        )
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def _hub_to_state(cls: Any, v: Sequence[Any], _: Any) -> Any:
    return cls.from_quaternion(np.stack(v[:4], -1), np.stack(v[4:], -1))


def _state_to_hub(s: Any, _: Any) -> Hub:
    return Hub(*np.moveaxis(s.quaternion, -1, 0), *np.moveaxis(s.m_body, -1, 0))


register(
    Chart(
        "state",
        Hub._fields,
        (),
        "the hub: attitude quaternion (scalar last) and body angular momentum",
        _hub_to_state,
        _state_to_hub,
        method=False,
        source="andoyer.state",
    )
)
