r"""The long secular orbit model of the eight planets: a billion years of averaged orbits.

**Model.** The averaged (secular) Hamiltonian of the Sun and the eight planets in Poincaré's
canonical heliocentric variables (:mod:`andoyer.planetary.orbits.disturbing`): every pair's
mutual interaction averaged over the mean longitudes and expanded to degree 4 in the
eccentricities and inclinations (the nonlinear secular terms, which give the inner planets'
secular resonances and their chaos); the second-order terms in the masses of every pair, all
harmonics ``|k| ≤ 16`` of their mutual perturbation, the Jupiter–Saturn 5:2 near-resonance
(the great inequality) among them, to degree 6; the Sun's relativistic perihelion precession
(0.43″/yr for Mercury) in closed form. The Earth–Moon barycentre is one body; the Moon, the
Sun's oblateness, asteroids and tides are left out, as in
:class:`~andoyer.planetary.orbits.nbody.NBodyOrbit`, which the model is measured against.

**Initial conditions** (the mean elements at J2000, in the invariable plane): measured from the
N-body solution over ±5 kyr (:mod:`andoyer.planetary.orbits.mean_elements`). The Hamiltonian
and these elements ship in ``data/secular_model.json`` (``scripts/make_secular_model.py``).

**Integration.** Lawson's method with the 8th-order Dormand–Prince tableau, the quadratic
(Laplace–Lagrange) part exact (:mod:`andoyer.planetary.orbits.secular_flow`), a fixed step of
1/5 of the shortest period of the linear flow (10.1 kyr), compiled; terms too small to matter
(:data:`PRUNE`) are left out of the flow. A run at an eighth of that step moves the orbits over
±2 Myr by 1.6″ at most. The orbit is integrated from J2000 as far as it is asked for, forwards
and backwards, and kept every half step (the chosen planet's ``x, y`` and their rates: 64 bytes
per sample, 13 MB per Gyr; the samples within a step from its stages, the linear flow exact);
between samples a cubic Hermite interpolant (up to 1″ for the Earth's normal, 5″ for Mars').

**Validity** (``docs/orbits.md`` has the measurements): the fundamental frequencies ``g_1…g_8``,
``s_1…s_8`` are within 0.03″/yr of the N-body solution's over 9.8 Myr but ``g_6`` (−0.16″/yr),
``s_6`` (+0.06″/yr), ``s_2`` (+0.05″/yr); the Lyapunov time of the inner planets is 4–9 Myr. Beyond
a few tens of Myr a single solution is one possible history, not a prediction; over 10⁸–10⁹ years
the model serves statistics. ``span`` is ±1 Gyr. A planet beyond ``e = 0.35`` or ``i = 20°``
(Mercury, in some histories of a few hundred Myr) gives a :class:`RuntimeWarning`: the expansion
loses accuracy there; beyond ``e = 0.6`` or ``i = 40°`` the run stops with a :class:`ValueError`.
"""

from __future__ import annotations

import json
import sys
from collections.abc import Sequence
from dataclasses import dataclass
from functools import cache
from importlib import resources
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._jit import jit, jitable
from andoyer.planetary.orbits.elements import eccentricity_from_elements
from andoyer.planetary.orbits.planets import PLANETS, check_planet, planet_data
from andoyer.planetary.orbits.protocol import check_times
from andoyer.planetary.orbits.secular_flow import hermite_basis

__all__ = [
    "MAX_SPAN",
    "SecularModel",
    "SecularOrbit",
    "poincare_normal",
    "sample_normal",
    "secular_model",
    "secular_tableau",
    "vectors_from_poincare",
]

Array = NDArray[np.float64]
CArray = NDArray[np.complex128]

#: The largest ``|t|`` (years) the model answers for.
MAX_SPAN = 1.0e9
#: Where the degree-4 expansion starts to lose accuracy (a warning): eccentricity, inclination (rad).
#: At e = 0.35 the remainder of Mercury's interaction with Venus is about 2 % of its quadratic part
#: (``scripts/secular_truncation.py``: 0.3 % at J2000's 0.21, growing like e⁴).
E_WARN, I_WARN = 0.35, np.radians(20.0)
#: Where the model stops (a ValueError): the remainder would be of the order of the terms kept.
E_MAX, I_MAX = 0.6, np.radians(40.0)
#: Steps per extension of a run (the unit of progress and of interruption).
CHUNK_STEPS = 1 << 15
#: The samples kept are at most this fraction of the shortest period of the linear flow apart
#: (5.0 kyr), and so is the step of a caller who keeps the state at every step only.
STEP_FRACTION = 1.0 / 10.0
#: :class:`SecularOrbit`'s default step, as a fraction of that period (10.1 kyr), with samples
#: within each step from the interaction variable (:func:`~andoyer.planetary.orbits.secular_flow.integrate`).
LONG_STEP_FRACTION = 1.0 / 5.0
#: Derivative monomials smaller than this fraction of their component's linear rate are left out
#: of the flow (at 1.5 times the largest amplitude the linear theory allows each variable).
PRUNE = 1e-5


@dataclass(frozen=True)
class SecularModel:
    """The shipped secular model: its Hamiltonian arranged for the flow, and the J2000 state.

    Attributes
    ----------
    terms : FlowTerms
        :class:`~andoyer.planetary.orbits.secular_flow.FlowTerms` (relativity included).
    sun : float
        The Sun's GM (au³/yr²).
    gm, Lambda, a, n : numpy.ndarray, shape (8,)
        The planets' GM, ``Λ_j``, mean semi-major axes (au), mean motions (rad/yr).
    w0 : numpy.ndarray of complex, shape (16,)
        ``(x_1…x_8, y_1…y_8)`` at J2000, invariable frame.
    rotation : numpy.ndarray, shape (3, 3)
        J2000 ecliptic → invariable frame.
    settings : dict
        How the model was made (degree, second-order pairs, …).
    """

    terms: object
    sun: float
    gm: Array
    Lambda: Array
    a: Array
    n: Array
    w0: CArray
    rotation: Array
    settings: dict


@cache
def secular_model(path: str | None = None) -> SecularModel:
    """Read ``data/secular_model.json`` (or a variant made by the script) once and arrange it for the flow.

    Parameters
    ----------
    path : str, optional
        A model file written by ``scripts/make_secular_model.py --out``; default: the shipped one.

    Returns
    -------
    SecularModel

    Examples
    --------
    >>> model = secular_model()
    >>> model.w0.shape, model.settings["degree"]
    ((16,), 4)
    """
    from andoyer.planetary.orbits.disturbing import relativity_constant
    from andoyer.planetary.orbits.nbody import C_AU_PER_YEAR
    from andoyer.planetary.orbits.secular_flow import FlowTerms

    if path is None:
        text = (
            resources.files("andoyer.planetary.orbits").joinpath("data/secular_model.json").read_text("utf-8")
        )
    else:
        with open(path, encoding="utf-8") as f:
            text = f.read()
    raw = json.loads(text)
    if raw["planets_j2000_sha256"] != planet_data().digest:
        msg = (
            "expected data/secular_model.json made from the shipped planets_j2000.json "
            "(run scripts/make_secular_model.py), got one made from other data"
        )
        raise ValueError(msg)
    count = len(raw["planets"])
    exponents = np.zeros((len(raw["terms"]), 4 * count), dtype=np.int64)
    coefficients = np.empty(len(raw["terms"]), dtype=complex)
    for row, (factors, re, im) in enumerate(raw["terms"]):
        for var, power in factors:
            exponents[row, var] = power
        coefficients[row] = complex(re, im)
    Lambda, a = np.array(raw["Lambda"]), np.array(raw["a"])
    gr = relativity_constant(raw["sun_gm"], np.array(raw["gm"]), a, C_AU_PER_YEAR)
    w0 = np.array([complex(*z) for z in raw["x0"] + raw["y0"]])
    # The linear flow alone (an infinite threshold keeps only the quadratic terms), and the largest
    # |w_b| it reaches from w0: Σ_m |V_bm| |(V⁻¹ w0)_m|.
    linear = FlowTerms.from_polynomial(exponents, coefficients, count, gr, Lambda, np.ones(2 * count), np.inf)
    _, vectors = np.linalg.eig(linear.linear)
    amplitude = 1.5 * np.abs(vectors) @ np.abs(np.linalg.solve(vectors, w0))
    terms = FlowTerms.from_polynomial(exponents, coefficients, count, gr, Lambda, amplitude, PRUNE)
    return SecularModel(
        terms, float(raw["sun_gm"]), np.array(raw["gm"]), Lambda, a, np.array(raw["n"]), w0,
        np.array(raw["rotation"]), raw["settings"],
    )  # fmt: skip


@cache
def secular_tableau(h: float, samples: int = 1, path: str | None = None) -> tuple[NDArray, ...]:
    """The shipped model's :func:`~andoyer.planetary.orbits.secular_flow.lawson_matrices`, once per step.

    The stage exponentials cost about as much as integrating a few Myr (about 25 matrix exponentials of
    16×16); every run at the same signed step and samples shares them (read-only).

    Parameters
    ----------
    h : float
        Signed step, years.
    samples : int
        Samples per step.
    path : str, optional
        As :func:`secular_model`.

    Returns
    -------
    tuple of numpy.ndarray

    Examples
    --------
    >>> secular_tableau(-1e4, 2) is secular_tableau(-1e4, 2)
    True
    """
    from andoyer.planetary.orbits.secular_flow import lawson_matrices

    tableau = lawson_matrices(secular_model(path).terms.linear, float(h), int(samples))
    for array in tableau:
        array.flags.writeable = False
    return tableau


def vectors_from_poincare(
    x: CArray, y: CArray, Lambda: float | Array, rotation: Array
) -> tuple[Array, Array]:
    r"""The unit normal and eccentricity vector (J2000 ecliptic) from Poincaré ``x, y`` (invariable frame).

    ``√(1−e²) = 1 − |x|²/(2Λ)``, ``ϖ = arg x``; ``1 − cos i = |y|²/(2Λ√(1−e²))``, ``Ω = arg y``.

    Parameters
    ----------
    x, y : numpy.ndarray of complex, shape (...)
    Lambda : float or numpy.ndarray, shape (...)
    rotation : numpy.ndarray, shape (3, 3)
        J2000 ecliptic → invariable frame.

    Returns
    -------
    normal, eccentricity_vector : numpy.ndarray, shape (..., 3)

    Examples
    --------
    >>> n, e = vectors_from_poincare(np.array(0.1 + 0j), np.array(0j), 1.0, np.eye(3))
    >>> n.tolist(), e.round(6).tolist()
    ([0.0, 0.0, 1.0], [0.099875, 0.0, 0.0])
    """
    root = 1.0 - (x.real**2 + x.imag**2) / (2.0 * Lambda)
    e = np.sqrt(np.clip(1.0 - root * root, 0.0, None))
    cos_i = 1.0 - (y.real**2 + y.imag**2) / (2.0 * Lambda * root)
    sin_i = np.sqrt(np.clip(1.0 - cos_i * cos_i, 0.0, None))
    node, varpi = np.angle(y), np.angle(x)
    normal = np.stack([sin_i * np.sin(node), -sin_i * np.cos(node), cos_i], axis=-1)
    ecc = eccentricity_from_elements(e, np.arctan2(sin_i, cos_i), node, varpi)
    return normal @ rotation, ecc @ rotation


@jit
def poincare_normal(x, y, Lambda, rotation):
    r"""The unit orbit normal (J2000 ecliptic) and ``√(1−e²)`` from one planet's Poincaré ``x, y``.

    :func:`vectors_from_poincare`'s normal for one planet at one time, for compiled loops (no
    angles: ``(sin i sin Ω, −sin i cos Ω) = sin i (Im y, −Re y)/|y|``).

    Parameters
    ----------
    x, y : complex
    Lambda : float
    rotation : numpy.ndarray, shape (3, 3)
        J2000 ecliptic → invariable frame.

    Returns
    -------
    nx, ny, nz, root : float
        The normal and ``√(1−e²) = 1 − |x|²/(2Λ)``.

    Examples
    --------
    >>> n, _ = vectors_from_poincare(np.array(0.1 + 0.02j), np.array(0.03 - 0.01j), 1.0, np.eye(3))
    >>> nx, ny, nz, root = poincare_normal(0.1 + 0.02j, 0.03 - 0.01j, 1.0, np.eye(3))
    >>> bool(np.allclose([nx, ny, nz], n, rtol=0, atol=1e-15)), round(root, 6)
    (True, 0.9948)
    """
    root = 1.0 - (x.real * x.real + x.imag * x.imag) / (2.0 * Lambda)
    size2 = y.real * y.real + y.imag * y.imag
    cos_i = 1.0 - size2 / (2.0 * Lambda * root)
    sin_i = np.sqrt(max(1.0 - cos_i * cos_i, 0.0))
    size = np.sqrt(size2)
    if size > 0.0:
        a, b = sin_i * y.imag / size, -sin_i * y.real / size
    else:
        a, b = 0.0, 0.0
    nx = a * rotation[0, 0] + b * rotation[1, 0] + cos_i * rotation[2, 0]
    ny = a * rotation[0, 1] + b * rotation[1, 1] + cos_i * rotation[2, 1]
    nz = a * rotation[0, 2] + b * rotation[1, 2] + cos_i * rotation[2, 2]
    return nx, ny, nz, root


@jitable
def sample_normal(w, dw, spacing, cx, cy, Lambda, rotation, t):
    """The normal and ``√(1−e²)`` at one time ``t`` from samples ``w, dw`` every ``spacing`` from J2000.

    :func:`~andoyer.planetary.orbits.secular_flow.hermite` of the columns ``cx, cy`` (``x, y``)
    between the two samples around ``t``, then :func:`poincare_normal`: the one interpolation of
    :class:`SecularOrbit` for compiled loops (its own sampling and the spin axis' rotations).

    Examples
    --------
    >>> w = np.array([[0.1 + 0j, 0.02 + 0j], [0.1 + 0j, 0.02 + 0j]])
    >>> nx, ny, nz, root = sample_normal(w, 0 * w, 10.0, 0, 1, 1.0, np.eye(3), 5.0)
    >>> round(root, 6), round(nz, 6)
    (0.995, 0.999799)
    """
    position = t / spacing
    i = min(max(int(np.floor(position)), 0), w.shape[0] - 2)
    h00, h10, h01, h11 = hermite_basis(position - i)
    x = h00 * w[i, cx] + h10 * spacing * dw[i, cx] + h01 * w[i + 1, cx] + h11 * spacing * dw[i + 1, cx]
    y = h00 * w[i, cy] + h10 * spacing * dw[i, cy] + h01 * w[i + 1, cy] + h11 * spacing * dw[i + 1, cy]
    return poincare_normal(x, y, Lambda, rotation)


@jit
def _sample(t, spacing, w, dw, cx, cy, Lambda, rotation, normal, root):
    """:func:`sample_normal` at every time of ``t``, into ``normal`` (N, 3) and ``root`` (N,)."""
    for k in range(t.size):
        normal[k, 0], normal[k, 1], normal[k, 2], root[k] = sample_normal(
            w, dw, spacing, cx, cy, Lambda, rotation, t[k]
        )


class _Run:
    """The integration in one direction from J2000 (``sign = ±1``): every step's ``w`` and ``ẇ`` kept."""

    def __init__(
        self, model: SecularModel, keep: NDArray[np.int64], sign: int, step: float, samples: int
    ) -> None:
        self.model, self.keep, self.sign, self.step, self.samples = model, keep, sign, step, samples
        #: The spacing of the samples kept (years).
        self.spacing = step / samples
        self.tableau = secular_tableau(sign * step, samples)  # the shipped model's (SecularOrbit's only)
        self.state = model.w0.copy()
        self.w = np.zeros((0, keep.size), dtype=complex)
        self.dw = np.zeros((0, keep.size), dtype=complex)
        self.extreme = np.zeros(2 * model.terms.count)
        self.warned = np.zeros(model.terms.count, dtype=bool)

    @property
    def reach(self) -> float:
        """How far from J2000 (years, ≥ 0) the samples go."""
        return (len(self.w) - 1) * self.spacing if len(self.w) else -1.0

    def extend(self, reach: float, progress: bool | None) -> None:
        """Integrate until the samples cover ``reach`` years (and one step beyond)."""
        from tqdm import tqdm

        from andoyer.planetary.orbits.secular_flow import integrate

        total = int(np.ceil(reach / self.step)) + 1
        if len(self.w) > total * self.samples:
            return
        done = max(len(self.w) - 1, 0) // self.samples
        terms = self.model.terms
        show = (sys.stderr.isatty() if progress is None else progress) and (total - done) * self.step > 2e8
        with tqdm(total=total - done, disable=not show, unit="step", desc="secular", file=sys.stderr) as bar:
            while done < total:
                n = min(CHUNK_STEPS, total - done)
                state = self.state.copy()
                out_w = np.empty((n * self.samples + 1, self.keep.size), dtype=complex)
                out_dw = np.empty_like(out_w)
                extreme = np.zeros_like(self.extreme)
                integrate(
                    state, n, self.sign * self.step, *self.tableau, *terms.arrays(), terms.linear, self.keep,
                    out_w, out_dw, extreme,
                )  # fmt: skip
                self._check_domain(extreme, done + n)
                w = np.concatenate([self.w[:-1], out_w]) if len(self.w) else out_w
                dw = np.concatenate([self.dw[:-1], out_dw]) if len(self.dw) else out_dw
                # One assignment per chunk: an interruption (Ctrl-C) between chunks leaves the run
                # consistent, and a later request goes on from there.
                self.w, self.dw, self.state, self.extreme = w, dw, state, np.maximum(self.extreme, extreme)
                done += n
                bar.update(n)

    def _check_domain(self, extreme: Array, steps: int) -> None:
        P = self.model.terms.count
        L = self.model.Lambda
        # √(1−e²) = 1 − |x|²/(2Λ); 1 − cos i = |y|²/(2Λ√(1−e²)) (bounded with the smallest √(1−e²)).
        root = 1.0 - extreme[:P] / (2.0 * L)
        e = np.sqrt(np.clip(1.0 - root * root, 0.0, 1.0))
        i = np.arccos(np.clip(1.0 - extreme[P:] / (2.0 * L * np.clip(root, 1e-3, None)), -1.0, 1.0))
        when = f"within {steps * self.step:.3g} years of J2000"
        bad = np.nonzero((e > E_MAX) | (i > I_MAX))[0]
        if bad.size:
            j = int(bad[0])
            msg = (
                f"expected the planets' eccentricities below {E_MAX} and inclinations below "
                f"{np.degrees(I_MAX):g} degrees, where the secular model's expansion holds, got "
                f"{PLANETS[j]} at e = {e[j]:.3f}, i = {np.degrees(i[j]):.1f} degrees {when}"
            )
            raise ValueError(msg)
        far = np.nonzero(((e > E_WARN) | (i > I_WARN)) & ~self.warned)[0]
        if far.size:
            import warnings

            j = int(far[0])
            self.warned[far] = True
            msg = (
                f"{PLANETS[j]} reached e = {e[j]:.3f}, i = {np.degrees(i[j]):.1f} degrees {when}: beyond "
                f"e = {E_WARN}, i = {np.degrees(I_WARN):g} degrees the secular model's degree-4 expansion "
                "loses accuracy (its remainder grows like e⁴; docs/orbits.md)"
            )
            warnings.warn(msg, RuntimeWarning, stacklevel=5)


class SecularOrbit:
    """A planet's orbit from the long secular model of the eight planets (mean elements).

    Parameters
    ----------
    body : str
        One of :data:`~andoyer.planetary.orbits.planets.PLANETS` (``"earth"`` = Earth–Moon
        barycentre).
    step : float, optional
        Integration step, years (default: :data:`LONG_STEP_FRACTION` of the shortest linear
        period, 10.1 kyr); the samples kept are at most :data:`STEP_FRACTION` of it apart.
    max_span : float
        The largest ``|t|`` that may be asked for (at most :data:`MAX_SPAN`).
    progress : bool or None
        Progress bar on runs longer than 200 Myr; ``None``: when standard error is a terminal.

    Examples
    --------
    >>> orbit = SecularOrbit("earth")
    >>> orbit.span
    (-1000000000.0, 1000000000.0)
    >>> round(float(np.linalg.norm(orbit.eccentricity_vector(0.0))), 4)
    0.0167
    """

    name = "secular"
    has_eccentricity = True
    span = (-MAX_SPAN, MAX_SPAN)

    def __init__(
        self,
        body: str = "earth",
        step: float | None = None,
        max_span: float = MAX_SPAN,
        progress: bool | None = None,
    ) -> None:
        from andoyer.planetary.orbits.secular_flow import default_step

        self.body = PLANETS[check_planet(body)]
        self._index = PLANETS.index(self.body)
        if not (np.isfinite(max_span) and 0 < max_span <= MAX_SPAN):
            msg = f"expected 0 < max_span <= {MAX_SPAN:g} years, got {max_span!r}"
            raise ValueError(msg)
        self.model = secular_model()
        if step is None:
            step = default_step(self.model.terms.linear, LONG_STEP_FRACTION)
        if not (np.isfinite(step) and 1.0 <= step <= 20000.0):
            msg = f"expected an integration step between 1 and 20000 years, got {step!r}"
            raise ValueError(msg)
        self.step = float(step)
        shortest = default_step(self.model.terms.linear, STEP_FRACTION)
        #: Samples kept per step, and their spacing (years).
        self.samples = max(1, int(np.ceil(self.step / shortest - 1e-9)))
        self.spacing = self.step / self.samples
        self.span = (-float(max_span), float(max_span))
        self.progress = progress
        P = self.model.terms.count
        keep = np.array([self._index, P + self._index], dtype=np.int64)
        self._runs = {sign: _Run(self.model, keep, sign, self.step, self.samples) for sign in (1, -1)}
        self._columns = np.array([0, 1])  # of x_j, y_j among the runs' kept variables

    @classmethod
    def system(cls, bodies: Sequence[str], **options: Any) -> dict[str, SecularOrbit]:
        """The orbits of several planets from one integration (each alone integrates all eight).

        Parameters
        ----------
        bodies : sequence of str
            Planets of :data:`~andoyer.planetary.orbits.planets.PLANETS`.
        **options
            As :class:`SecularOrbit` (``step``, ``max_span``, ``progress``).

        Returns
        -------
        dict of str to SecularOrbit
            Sharing their integration: asking one for a longer span extends them all.

        Examples
        --------
        >>> orbits = SecularOrbit.system(["mars", "earth"])
        >>> bool((orbits["mars"].normal(-1e5) == SecularOrbit("mars").normal(-1e5)).all())
        True
        """
        orbits = {PLANETS[check_planet(b)]: cls(b, **options) for b in bodies}
        if not orbits:
            msg = "expected at least one planet, got none"
            raise ValueError(msg)
        first = next(iter(orbits.values()))
        P = first.model.terms.count
        indices = [orbit._index for orbit in orbits.values()]
        keep = np.array(indices + [P + j for j in indices], dtype=np.int64)
        runs = {sign: _Run(first.model, keep, sign, first.step, first.samples) for sign in (1, -1)}
        for k, orbit in enumerate(orbits.values()):
            orbit._runs = runs
            orbit._columns = np.array([k, len(indices) + k])
        return orbits

    def _poincare(self, t: ArrayLike) -> tuple[CArray, CArray]:
        from andoyer.planetary.orbits.secular_flow import hermite

        times = check_times(t, self.span, self.name)
        flat = times.ravel()
        out = np.empty((flat.size, 2), dtype=complex)
        for sign, run in self._runs.items():
            side = flat >= 0 if sign > 0 else flat < 0
            if not np.any(side):
                continue
            run.extend(float(np.abs(flat[side]).max()), self.progress)
            out[side] = hermite(flat[side], 0.0, sign * self.spacing, run.w, run.dw)[:, self._columns]
        return out[:, 0].reshape(times.shape), out[:, 1].reshape(times.shape)

    def poincare(self, t: ArrayLike) -> tuple[CArray, CArray]:
        """The planet's mean Poincaré variables ``x, y`` (invariable frame) at ``t``.

        Parameters
        ----------
        t : array_like, shape (...)
            Julian years TT from J2000.

        Returns
        -------
        x, y : numpy.ndarray of complex, shape (...)
        """
        return self._poincare(t)

    def _normal_root(self, t: ArrayLike) -> tuple[Array, Array]:
        """The normal (..., 3) and ``√(1−e²)`` (...) at ``t``, compiled (:func:`_sample`)."""
        times = check_times(t, self.span, self.name)
        flat = np.ascontiguousarray(times.ravel())
        normal = np.empty((flat.size, 3))
        root = np.empty(flat.size)
        cx, cy = (int(c) for c in self._columns)
        lam = float(self.model.Lambda[self._index])
        for sign, run in self._runs.items():
            on_side = flat >= 0 if sign > 0 else flat < 0
            whole = bool(on_side.all())
            if not (whole or on_side.any()):
                continue
            part = flat if whole else np.ascontiguousarray(flat[on_side])
            run.extend(float(np.abs(part).max()), self.progress)
            if whole:  # one side only (a spin-axis history's blocks): no copies
                _sample(
                    part, sign * self.spacing, run.w, run.dw, cx, cy, lam, self.model.rotation, normal, root
                )
                break
            part_normal, part_root = np.empty((part.size, 3)), np.empty(part.size)
            _sample(
                part,
                sign * self.spacing,
                run.w,
                run.dw,
                cx,
                cy,
                lam,
                self.model.rotation,
                part_normal,
                part_root,
            )
            normal[on_side], root[on_side] = part_normal, part_root
        return normal.reshape(*times.shape, 3), root.reshape(times.shape)

    def hermite_samples(self, reach: float) -> tuple[CArray, CArray, float, int, int, float, Array]:
        """The samples the interpolation uses on one side of J2000, integrated as far as ``reach``.

        For compiled callers that interpolate themselves (the spin axis'
        :func:`~andoyer.planetary.spin_axis.stepping.rotate_on_samples`), as :meth:`normal` does.

        Parameters
        ----------
        reach : float
            Years from J2000, nonzero; its sign chooses the side.

        Returns
        -------
        w, dw : numpy.ndarray of complex, shape (N, K)
            The kept ``x, y`` and their rates at ``0, s, 2s, …``.
        spacing : float
            ``s``, signed like ``reach``.
        cx, cy : int
            The planet's ``x`` and ``y`` columns.
        Lambda : float
        rotation : numpy.ndarray, shape (3, 3)

        Examples
        --------
        >>> orbit = SecularOrbit("mars")
        >>> w, dw, spacing, cx, cy, lam, rotation = orbit.hermite_samples(-2e4)
        >>> spacing == -orbit.spacing, bool(len(w) * orbit.spacing > 2e4)
        (True, True)
        """
        check_times(reach, self.span, self.name)
        sign = 1 if reach > 0 else -1
        run = self._runs[sign]
        run.extend(abs(float(reach)), self.progress)
        cx, cy = (int(c) for c in self._columns)
        lam = float(self.model.Lambda[self._index])
        return run.w, run.dw, sign * self.spacing, cx, cy, lam, self.model.rotation

    def normal(self, t: ArrayLike) -> Array:
        """Unit normal of the mean orbit, J2000 ecliptic frame.

        Parameters
        ----------
        t : array_like, shape (...)
            Julian years TT from J2000.

        Returns
        -------
        numpy.ndarray, shape (..., 3)
        """
        return self._normal_root(t)[0]

    def normal_and_eccentricity(self, t: ArrayLike) -> tuple[Array, Array]:
        """:meth:`normal` and :meth:`eccentricity` from one interpolation.

        Parameters
        ----------
        t : array_like, shape (...)
            Julian years TT from J2000.

        Returns
        -------
        normal : numpy.ndarray, shape (..., 3)
        e : numpy.ndarray, shape (...)

        Examples
        --------
        >>> orbit = SecularOrbit("mars")
        >>> n, e = orbit.normal_and_eccentricity([-1e5, 0.0])
        >>> bool((n == orbit.normal([-1e5, 0.0])).all() and (e == orbit.eccentricity([-1e5, 0.0])).all())
        True
        """
        normal, root = self._normal_root(t)
        return normal, np.sqrt(np.clip(1.0 - root * root, 0.0, None))

    def eccentricity(self, t: ArrayLike) -> Array:
        """Mean eccentricity, ``e = √(1 − (1 − |x|²/(2Λ))²)``.

        The norm of :meth:`eccentricity_vector` without its angles (the spin axis' torque needs
        ``e`` alone).

        Parameters
        ----------
        t : array_like, shape (...)
            Julian years TT from J2000.

        Returns
        -------
        numpy.ndarray, shape (...)

        Examples
        --------
        >>> orbit = SecularOrbit("mars")
        >>> t = np.array([-3e5, 0.0, 2e5])
        >>> bool(np.allclose(orbit.eccentricity(t), np.linalg.norm(orbit.eccentricity_vector(t), axis=-1)))
        True
        """
        return self.normal_and_eccentricity(t)[1]

    def eccentricity_vector(self, t: ArrayLike) -> Array:
        """Mean eccentricity vector (``e`` times the unit vector to perihelion), J2000 ecliptic.

        Parameters
        ----------
        t : array_like, shape (...)
            Julian years TT from J2000.

        Returns
        -------
        numpy.ndarray, shape (..., 3)
        """
        x, y = self._poincare(t)
        return vectors_from_poincare(x, y, self.model.Lambda[self._index], self.model.rotation)[1]

    def __repr__(self) -> str:
        return f"SecularOrbit({self.body!r}, step={self.step:g})"
