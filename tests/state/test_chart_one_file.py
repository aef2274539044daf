"""Adding a chart is adding one file: a throw-away chart module registers itself and is complete.

The module below is written to a temporary folder and imported in a fresh interpreter (so the
registry of this test session keeps its seven charts). It knows only the hub and the registry;
importing it gives ``State`` its two methods and the registry its Hamiltonian and equations.
The expected numbers are worked by hand: the body ``(1, 2, 2.5)`` spinning at ``ω = (1, 1, 1)``
has ``T = ½ Σ I_i ω_i² = 2.75`` and, by Euler's equations ``I1 dω1/dt = (I2 − I3) ω2 ω3`` and
cyclic, ``dω/dt = (−0.5, 0.75, −0.4)``; about ``q = (0, 0, 0, 1)``, ``dq/dt = ½ (ω, 0)``.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap
from pathlib import Path

CHART = textwrap.dedent(
    '''
    """A throw-away chart: the attitude quaternion and the body angular velocity."""

    from typing import NamedTuple

    import numpy as np

    from andoyer.state.hub import State, check_body
    from andoyer.state.registry import Chart, register


    class Omega(NamedTuple):
        qx: object
        qy: object
        qz: object
        qw: object
        w1: object
        w2: object
        w3: object


    def _from_omega(cls, body, qx, qy, qz, qw, w1, w2, w3):
        """State from the attitude and the body angular velocity."""
        moments = check_body(body).moments
        return cls.from_quaternion(np.stack([qx, qy, qz, qw], -1), np.stack([w1, w2, w3], -1) * moments)


    def _as_omega(self, body):
        """The attitude and the body angular velocity."""
        return Omega(*np.moveaxis(self.quaternion, -1, 0), *np.moveaxis(self.omega(body), -1, 0))


    def hamiltonian(body, qx, qy, qz, qw, w1, w2, w3):
        I1, I2, I3 = body.moments
        return 0.5 * (I1 * w1 * w1 + I2 * w2 * w2 + I3 * w3 * w3)


    def equations(body, qx, qy, qz, qw, w1, w2, w3):
        I1, I2, I3 = body.moments
        dq = (  # dq/dt = 1/2 q (x) (w, 0), scalar last
            0.5 * (qw * w1 + qy * w3 - qz * w2),
            0.5 * (qw * w2 + qz * w1 - qx * w3),
            0.5 * (qw * w3 + qx * w2 - qy * w1),
            -0.5 * (qx * w1 + qy * w2 + qz * w3),
        )
        dw = ((I2 - I3) * w2 * w3 / I1, (I3 - I1) * w3 * w1 / I2, (I1 - I2) * w1 * w2 / I3)
        return Omega(*dq, *dw)


    register(
        Chart(
            "omega",
            Omega._fields,
            (),
            "attitude and body angular velocity",
            _from_omega,
            _as_omega,
            source="omega_chart",
            hamiltonian=hamiltonian,
            equations=equations,
        ),
        State,
    )
    '''
)

RUN = textwrap.dedent(
    """
    import json
    import numpy as np
    from andoyer import RigidBody, State
    from andoyer.state.registry import charts, charts_markdown
    before = list(charts())
    import omega_chart
    body = RigidBody(1.0, 2.0, 2.5)
    s = State.from_omega(body, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0)
    chart = charts()["omega"]
    values = [float(x) for x in s.as_omega(body)]
    print(json.dumps({
        "before": before,
        "after": list(charts()),
        "m_body": s.m_body.tolist(),
        "as_omega": values,
        "hamiltonian": float(chart.hamiltonian(body, *values)),
        "energy": float(s.energy(body)),
        "equations": [float(x) for x in chart.equations(body, *values)],
        "needs_body": chart.needs_body,
        "methods": [State.from_omega.__qualname__, State.as_omega.__qualname__],
        "table": charts_markdown().splitlines()[-1],
    }))
    """
)


def test_chart_one_file_registers_methods_and_dynamics(tmp_path: Path):
    (tmp_path / "omega_chart.py").write_text(CHART, encoding="utf-8")
    src = Path(__file__).resolve().parents[2] / "src"
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(tmp_path), str(src)])}
    proc = subprocess.run(
        [sys.executable, "-W", "error", "-c", RUN], capture_output=True, text=True, check=True, env=env
    )
    out = json.loads(proc.stdout)
    builtin = ["state", "euler", "andoyer", "initial_andoyer", "sadov", "serret", "sam"]
    assert out["before"] == builtin
    assert out["after"] == [*builtin, "omega"]
    assert out["methods"] == ["State.from_omega", "State.as_omega"]
    assert out["needs_body"] is True
    assert out["m_body"] == [1.0, 2.0, 2.5]
    assert out["as_omega"] == [0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0]
    assert out["hamiltonian"] == out["energy"] == 2.75
    assert out["equations"] == [0.5, 0.5, 0.5, 0.0, -0.5, 0.75, -0.4]
    assert out["table"].startswith("| `omega` | `qx`, `qy`, `qz`, `qw`, `w1`, `w2`, `w3` | none | yes |")
