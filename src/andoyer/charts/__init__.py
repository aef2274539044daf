"""Canonical charts of the rotation state, one module per chart.

Each chart module holds array-level converters to and from the hub
representation (attitude quaternion plus body angular momentum) used by
:class:`andoyer.State`, the chart's rotation matrix in Gurfil's convention,
and direct formulas to neighbouring charts where those are simpler.
"""

from andoyer.charts.andoyer import (
    Andoyer,
    andoyer_from_euler,
    andoyer_matrix,
    euler_from_andoyer,
    inclinations,
)
from andoyer.charts.euler import Euler, euler_matrix
from andoyer.charts.serret import Serret, andoyer_to_serret, serret_to_andoyer
from andoyer.charts.singular import SingularChartWarning

__all__ = [
    "Andoyer",
    "Euler",
    "Serret",
    "SingularChartWarning",
    "andoyer_from_euler",
    "andoyer_matrix",
    "andoyer_to_serret",
    "euler_from_andoyer",
    "euler_matrix",
    "inclinations",
    "serret_to_andoyer",
]
