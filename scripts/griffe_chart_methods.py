"""Griffe extension for the API pages: the chart methods that the registry installs on ``State``.

``State.from_<chart>`` and ``State.as_<chart>`` are written in the chart modules
(``andoyer/state/<chart>.py``) and installed on the class when each chart registers
(:func:`andoyer.state.registry.register`, as :mod:`andoyer.state` imports them), so griffe's
static reading of ``andoyer/state/hub.py`` does not see them. This extension adds them to the
statically loaded class from griffe's inspection of the imported class: their signatures and
docstrings as ``help(State.from_euler)`` shows them. ``mkdocs.yml`` loads it
(``extensions: [scripts/griffe_chart_methods.py:ChartMethods]``).
"""

from __future__ import annotations

from typing import Any

import griffe


class ChartMethods(griffe.Extension):
    """Add the installed chart methods to the class ``andoyer.state.hub.State``."""

    def on_class_members(
        self,
        *,
        cls: griffe.Class,
        agent: griffe.Visitor | griffe.Inspector,
        **kwargs: Any,  # noqa: ARG002 (griffe passes more)
    ) -> None:
        """Copy each ``from_*``/``as_*`` member that the static reading missed from the inspected class."""
        if cls.path != "andoyer.state.hub.State":
            return
        from andoyer.state.registry import charts

        # The docstrings parsed as the static ones are (numpy style, from mkdocs.yml).
        parser, options = agent.docstring_parser, agent.docstring_options
        module = griffe.inspect("andoyer.state.hub", docstring_parser=parser, docstring_options=options)
        inspected = module["State"]
        # Listed where hub.py's own constructors end, chart by chart in the registry's order: by
        # line number (``members_order: source``) and by place (the page shows ``andoyer.State``, an
        # alias whose members keep the class's order).
        anchor = cls.members["from_angular_velocity"].endlineno
        added = []
        for chart in charts().values():
            for name in (f"from_{chart.name}", f"as_{chart.name}"):
                if chart.method and name not in cls.members:
                    member = inspected.members[name]
                    member.lineno = member.endlineno = anchor
                    cls.set_member(name, member)
                    added.append(name)
        order = [name for name in cls.members if name not in added]
        at = order.index("from_angular_velocity") + 1
        members = {name: cls.members[name] for name in (*order[:at], *added, *order[at:])}
        cls.members.clear()
        cls.members.update(members)
