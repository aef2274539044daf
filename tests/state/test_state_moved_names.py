"""The names of the modules that became the state package keep working for one release.

``andoyer.charts``, ``andoyer.equations``, ``andoyer.hamiltonians``, ``andoyer.state_charts`` and
``andoyer.free.rotation`` are old module paths (``andoyer._moved.MOVED``); ``andoyer.free.FreeRotation``
is an old attribute of a package that stays. Each old public name (the ``__all__`` lists of the
old modules, as they were) gives the object at its new place, with a DeprecationWarning; the
new places give it without one. Run in fresh interpreters, with warnings as errors for the new
names, so that no earlier import hides a warning.
"""

from __future__ import annotations

import json
import subprocess
import sys
import textwrap

#: old module -> (new module, its old ``__all__``)
OLD_MODULES = {
    "andoyer.charts": (
        "andoyer.state",
        ["Andoyer", "Euler", "Serret", "SingularChartWarning", "andoyer_from_euler", "andoyer_matrix",
         "andoyer_to_serret", "euler_from_andoyer", "euler_matrix", "inclinations", "serret_to_andoyer"],
    ),
    "andoyer.charts.registry": (
        "andoyer.state.registry",
        ["CHARTS", "Chart", "Hub", "charts", "charts_markdown", "install", "register"],
    ),
    "andoyer.charts.euler": (
        "andoyer.state.euler",
        ["Euler", "euler_matrix", "euler_to_hub", "hub_to_euler", "transverse_momentum"],
    ),
    "andoyer.charts.andoyer": (
        "andoyer.state.andoyer",
        ["Andoyer", "andoyer_from_euler", "andoyer_matrix", "andoyer_to_hub", "euler_from_andoyer",
         "hub_to_andoyer", "inclinations"],
    ),
    "andoyer.charts.sadov": (
        "andoyer.state.sadov",
        ["Sadov", "SadovFrequencies", "andoyer_to_sadov", "sadov_frequencies", "sadov_hamiltonian",
         "sadov_to_andoyer", "separatrix_action"],
    ),
    "andoyer.charts.sam": (
        "andoyer.state.sam",
        ["SAM", "SAMAxes", "andoyer_from_sam", "andoyer_parameters", "hub_to_sam", "sam_axes", "sam_energy",
         "sam_from_andoyer", "sam_to_hub"],
    ),
    "andoyer.charts.serret": ("andoyer.state.serret", ["Serret", "andoyer_to_serret", "serret_to_andoyer"]),
    "andoyer.equations": (
        "andoyer.state",
        ["AndoyerRates", "EulerRates", "andoyer_equations", "attitude_rate", "euler_equations",
         "euler_poinsot", "euler_poinsot_omega", "lie_poisson"],
    ),
    "andoyer.hamiltonians": (
        "andoyer.state",
        ["andoyer_hamiltonian", "euler_hamiltonian", "state_hamiltonian"],
    ),
    "andoyer.state_charts": ("andoyer.state.hub", ["check_body", "free_flow"]),
    "andoyer.free.rotation": ("andoyer.free_rotation", ["FreeRotation"]),
}

#: where each moved function is written now: a name leads to its chart's file
HOMES = {
    "euler_equations": "andoyer.state.euler",
    "euler_hamiltonian": "andoyer.state.euler",
    "andoyer_equations": "andoyer.state.andoyer",
    "andoyer_hamiltonian": "andoyer.state.andoyer",
    "euler_poinsot": "andoyer.state.hub",
    "state_hamiltonian": "andoyer.state.hub",
    "attitude_rate": "andoyer.state.hub",
    "check_body": "andoyer.state.hub",
    "free_flow": "andoyer.state.hub",
}


def _run(code: str) -> list:
    command = [sys.executable, "-c", textwrap.dedent(code)]
    proc = subprocess.run(command, capture_output=True, text=True, check=True)
    return json.loads(proc.stdout)


def test_state_moved_old_names_are_the_new_objects():
    out = _run(
        f"""
        import importlib, json, warnings
        out = {{}}
        for old, (new, names) in {OLD_MODULES!r}.items():
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                module = importlib.import_module(old)
            with warnings.catch_warnings():
                warnings.simplefilter("error")
                target = importlib.import_module(new)
                same = [getattr(module, n) is getattr(target, n) for n in names]
            out[old] = [same, [str(w.message) for w in caught if w.category is DeprecationWarning]]
        print(json.dumps(out))
        """
    )
    for old, (new, names) in OLD_MODULES.items():
        same, warned = out[old]
        assert same == [True] * len(names), old
        assert warned == [f"{old} moved to {new}; the old name works until the next release"]


def test_state_moved_functions_written_in_their_chart_module():
    modules = _run(
        f"""
        import importlib, json, warnings
        warnings.simplefilter("error")
        import andoyer.state
        print(json.dumps([getattr(andoyer.state.hub if n in ("check_body", "free_flow") else andoyer.state, n)
                          .__module__ for n in {sorted(HOMES)!r}]))
        """
    )
    assert modules == [HOMES[name] for name in sorted(HOMES)]


def test_state_moved_free_rotation_attribute_warns():
    out = _run(
        """
        import json, warnings
        import andoyer, andoyer.free, andoyer.free_rotation
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            old = andoyer.free.FreeRotation
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            new = andoyer.FreeRotation
        print(json.dumps([old is new is andoyer.free_rotation.FreeRotation,
                          [str(w.message) for w in caught], [w.category.__name__ for w in caught],
                          "FreeRotation" in andoyer.free.__all__]))
        """
    )
    assert out == [
        True,
        [
            (
                "andoyer.free.FreeRotation moved to andoyer.free_rotation (andoyer.FreeRotation); "
                "the old name works until the next release"
            )
        ],
        ["DeprecationWarning"],
        False,
    ]


def test_state_moved_charts_attribute_of_andoyer_warns():
    out = _run(
        """
        import json, warnings
        import andoyer
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            old = andoyer.charts
        import andoyer.state
        print(json.dumps([old is andoyer.state, [w.category.__name__ for w in caught]]))
        """
    )
    assert out == [True, ["DeprecationWarning"]]
