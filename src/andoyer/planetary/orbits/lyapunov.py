r"""The largest Lyapunov exponent of the secular model: how fast two nearby solar systems part.

Benettin's method with two trajectories (Benettin, Galgani & Strelcyn 1976): a reference
solution from the J2000 state and a neighbour displaced by ``d_0``; every ``interval`` years
their distance ``d`` is measured, ``log(d/d_0)`` summed, and the neighbour brought back to
distance ``d_0`` along the current separation. The exponent is the sum over the time, and the
Lyapunov time its inverse. The distance is measured in the dimensionless ``u = x/√Λ``,
``v = y/√Λ`` (≈ ``e e^{iϖ}``, ``i e^{iΩ}``), so that each planet's eccentricity and
inclination count alike (the exponent does not depend on the norm; its convergence does).

For the Solar System the inner planets' secular resonances (``(s_4 − s_3) − 2(g_4 − g_3)``,
``(g_1 − g_5) − (s_1 − s_2)``) make the motion chaotic: Laskar (1989, *Nature* 338, 237)
found a Lyapunov time of about 5 Myr in his secular equations, Sussman & Wisdom (1992,
*Science* 257, 56) 4–5 Myr in N-body integrations.

Examples
--------
>>> result = lyapunov_exponent(span=2e6, interval=1e6)
>>> result.times.tolist()
[1000000.0, 2000000.0]
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

__all__ = ["LyapunovResult", "lyapunov_exponent"]

Array = NDArray[np.float64]


@dataclass(frozen=True)
class LyapunovResult:
    """The running estimate of the largest Lyapunov exponent.

    Attributes
    ----------
    times : numpy.ndarray, shape (K,)
        Years from J2000 at each renormalisation.
    exponent : numpy.ndarray, shape (K,)
        ``Σ log(d/d_0) / t`` up to each time, 1/yr.
    lyapunov_time : float
        ``1/exponent`` at the end, years.
    """

    times: Array
    exponent: Array
    lyapunov_time: float


def lyapunov_exponent(
    span: float = 2.0e8,
    interval: float = 1.0e6,
    separation: float = 1e-9,
    step: float | None = None,
    seed: int = 0,
) -> LyapunovResult:
    """Estimate the largest Lyapunov exponent of the secular model from J2000 over ``span`` years.

    Parameters
    ----------
    span : float
        Years integrated (signed: negative goes into the past).
    interval : float
        Years between renormalisations (well below the time over which ``d`` would leave the
        linear regime: ``d_0 e^{interval/T_L} ≪ 1``).
    separation : float
        ``d_0`` in the dimensionless variables.
    step : float, optional
        Integration step (default: the model's).
    seed : int
        Seeds the direction of the first displacement.

    Returns
    -------
    LyapunovResult
    """
    from andoyer.planetary.orbits.secular import STEP_FRACTION, secular_model
    from andoyer.planetary.orbits.secular_flow import default_step, integrate, lawson_matrices

    if not (np.isfinite(span) and span != 0 and np.isfinite(interval) and 0 < interval <= abs(span)):
        msg = f"expected a nonzero span and 0 < interval <= |span| (years), got {span!r} and {interval!r}"
        raise ValueError(msg)
    if not (np.isfinite(separation) and 0 < separation < 1e-3):
        msg = f"expected 0 < separation < 1e-3, got {separation!r}"
        raise ValueError(msg)
    model = secular_model()
    terms = model.terms
    h = default_step(terms.linear, STEP_FRACTION) if step is None else float(step)
    sign = 1.0 if span > 0 else -1.0
    per = max(1, round(interval / h))
    h = interval / per
    count = round(abs(span) / interval)
    tableau = lawson_matrices(terms.linear, sign * h)
    P = terms.count
    scale = np.sqrt(np.concatenate([model.Lambda, model.Lambda]))  # w = scale (u, v)
    rng = np.random.default_rng(seed)
    direction = rng.normal(size=2 * P) + 1j * rng.normal(size=2 * P)
    reference = model.w0.copy()
    neighbour = reference + separation * scale * direction / np.linalg.norm(direction)
    keep = np.zeros(1, dtype=np.int64)
    out = np.empty((per + 1, 1), dtype=complex)
    out_d = np.empty_like(out)
    extreme = np.zeros(2 * P)
    total = 0.0
    times, exponents = [], []
    for k in range(1, count + 1):
        for state in (reference, neighbour):
            integrate(
                state, per, sign * h, *tableau, *terms.arrays(), terms.linear, keep, out, out_d, extreme
            )
        delta = (neighbour - reference) / scale
        d = float(np.linalg.norm(delta))
        total += np.log(d / separation)
        neighbour = reference + separation * scale * delta / d
        times.append(sign * k * interval)
        exponents.append(total / (k * interval))
    exponent = np.array(exponents)
    return LyapunovResult(np.array(times), exponent, float(1.0 / exponent[-1]))
