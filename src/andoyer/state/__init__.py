"""The rotation state and its charts: the hub, the registry, one module per chart.

The package is wired the way astropy wires its frames and transforms. The hub,
:class:`State` in :mod:`andoyer.state.hub`, holds the attitude quaternion and the body
angular momentum and knows none of its charts. Each chart module (:mod:`~andoyer.state.euler`,
:mod:`~andoyer.state.andoyer`, :mod:`~andoyer.state.initial_andoyer`,
:mod:`~andoyer.state.sadov`, :mod:`~andoyer.state.serret`, :mod:`~andoyer.state.sam`) imports
the hub and the registry (:mod:`andoyer.state.registry`) and, when imported, registers its
chart and installs its methods: ``State.from_sadov`` is written in :mod:`andoyer.state.sadov`.
A chart module holds the chart's converters to and from the hub, its rotation matrix and
direct formulas where those are simpler, and its dynamics (the free-body Hamiltonian and
Hamilton's equations in its variables). This ``__init__`` does the registration: it imports
the hub, then each chart module, in the order of the tables (``docs/charts.md``). Adding a
chart is adding one module that registers itself.

Examples
--------
>>> from pathlib import Path
>>> from andoyer.state import State
>>> Path(State.from_sadov.__code__.co_filename).name    # written in the Sadov chart's module
'sadov.py'
>>> from andoyer.state.registry import charts
>>> list(charts())
['state', 'euler', 'andoyer', 'initial_andoyer', 'sadov', 'serret', 'sam']
"""

# isort: off
# The registration, in the order of the tables: the hub (which registers the hub chart
# ``state``), then each chart module, which registers its chart and installs State's methods.
from andoyer.state.hub import (
    State,
    attitude_rate,
    euler_poinsot,
    euler_poinsot_omega,
    lie_poisson,
    state_hamiltonian,
)
from andoyer.state.euler import Euler, EulerRates, euler_equations, euler_hamiltonian, euler_matrix
from andoyer.state.andoyer import (
    Andoyer,
    AndoyerRates,
    andoyer_equations,
    andoyer_from_euler,
    andoyer_hamiltonian,
    andoyer_matrix,
    euler_from_andoyer,
    inclinations,
)
from andoyer.state import initial_andoyer  # noqa: F401 (it registers on import)
from andoyer.state import sadov  # noqa: F401 (it registers on import)
from andoyer.state.serret import Serret, andoyer_to_serret, serret_to_andoyer
from andoyer.state import sam  # noqa: F401 (it registers on import)

# isort: on
from andoyer.state.singular import SingularChartWarning

__all__ = [
    "Andoyer",
    "AndoyerRates",
    "Euler",
    "EulerRates",
    "Serret",
    "SingularChartWarning",
    "State",
    "andoyer_equations",
    "andoyer_from_euler",
    "andoyer_hamiltonian",
    "andoyer_matrix",
    "andoyer_to_serret",
    "attitude_rate",
    "euler_equations",
    "euler_from_andoyer",
    "euler_hamiltonian",
    "euler_matrix",
    "euler_poinsot",
    "euler_poinsot_omega",
    "inclinations",
    "lie_poisson",
    "serret_to_andoyer",
    "state_hamiltonian",
]
