r"""The Earth–Moon tides of ``andoyer obliquity``: ``--tides MODEL`` and the default ``--tidal-dissipation``.

Two ways for the tides to act on the precession of the Earth's axis (planetary.tides,
planetary.spin_axis):

* ``--tidal-dissipation T_d`` (Zeebe & Lourens 2022, the snvecR option): the modern tidal rates
  of the Moon's mean motion and the Earth's spin times ``T_d``, to first order in time. Its
  default is the body's present-day dissipation, :data:`DEFAULT_TIDAL_DISSIPATION`: 1 for the
  Earth (over 5 Myr on the N-body orbit, the obliquity is 0.21° from La2004 with it, 1.73° with
  0), 0 for a body without a measured tidal dissipation (Mars). 0 stays an option.
* ``--tides MODEL`` (``ocean``, the reference after Farhat et al. 2022, or ``constant-lag``):
  the Earth–Moon system integrated back in time (:func:`andoyer.planetary.tides.tidal_history`)
  sets the precession constant's change, ``α(t) ∝ ω(t)[(1 − e²)^{−3/2} + β (a₀/a(t))³]``
  (:func:`andoyer.planetary.tides.tidal_spin_axis_history`). It replaces ``T_d`` and the
  ellipticity ``H`` (the tidal model sets both: ``H ∝ ω²``), so ``--tidal-dissipation`` and
  ``--dynamical-ellipticity`` are refused with it; ``--precession-rate`` still sets ``α`` at
  J2000. Earth only. Each row then carries the tidal history's ``day_length`` (hours),
  ``lunar_distance`` (km) and ``precession_constant`` (″/yr, ``α cos ε`` in the convention of
  Laskar et al. 2004), as ``andoyer tides earth --model MODEL`` prints them at the same times.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from andoyer.cli.output import CliError

__all__ = [
    "DEFAULT_TIDAL_DISSIPATION",
    "REFERENCE_MODEL",
    "TIDAL_COLUMNS",
    "TIDES_MODELS",
    "TIDES_ROW_BYTES",
    "TIDES_ROW_SECONDS",
    "ObliquityTides",
    "add_tides_argument",
    "obliquity_tides",
]

#: The tidal models of ``--tides`` (:func:`andoyer.planetary.tides.tidal_model`).
TIDES_MODELS = ("ocean", "constant-lag")
#: The documented reference among them (docs/tides.md): the resonant ocean after Farhat et al. (2022).
REFERENCE_MODEL = "ocean"
#: ``--tidal-dissipation`` when it is not given, by body: the Earth's present-day rates (``T_d = 1``,
#: Zeebe & Lourens 2022: lunar laser ranging's recession); every other body 0 (no measured
#: dissipation, and no moon in the spin-axis model).
DEFAULT_TIDAL_DISSIPATION = {"earth": 1.0}
#: The JSON keys (and the table's columns) a ``--tides`` run adds to every row.
TIDAL_COLUMNS = {
    "day_length": "day_length_h",
    "lunar_distance": "lunar_distance_km",
    "precession_constant": "precession_constant_arcsec_yr",
}
#: Bytes per output time of the tidal columns while they are computed: the tidal history's
#: states and its described quantities, and the three columns kept (a bound: measured 88 at the
#: peak of a history of 10⁶ output times, 64 kept).
TIDES_ROW_BYTES = 112
#: Seconds per output time of the tidal history (every output time ends a step of its
#: Dormand–Prince integration: measured 13 µs per time for 10⁶ times over 100 Myr on the
#: project's shared 2-core machine, under load).
TIDES_ROW_SECONDS = 2.0e-5


def add_tides_argument(parser: argparse.ArgumentParser) -> None:
    """Add ``--tides MODEL`` to the ``obliquity`` parser."""
    parser.add_argument(
        "--tides",
        choices=TIDES_MODELS,
        metavar="MODEL",
        help=f"couple the Earth's axis to the Earth-Moon tidal evolution ({'|'.join(TIDES_MODELS)}; "
        f"{REFERENCE_MODEL} is the reference, after Farhat et al. 2022): adds day_length, "
        "lunar_distance and precession_constant to every row; not with --tidal-dissipation or "
        "--dynamical-ellipticity, which the tidal model sets",
    )


@dataclass(frozen=True)
class ObliquityTides:
    """What the tides make of one ``obliquity`` run.

    Attributes
    ----------
    tidal_dissipation : float
        ``T_d`` of the spin-axis model (0 with ``--tides``).
    model : str or None
        The ``--tides`` model, or ``None``.
    """

    tidal_dissipation: float
    model: str | None = None

    @property
    def coupling(self) -> Callable[[Any, tuple[float, float]], Any] | None:
        """The spin-axis model's coupling to the tidal history (``coupling=`` of ``spin_axis_history``)."""
        if self.model is None:
            return None
        from andoyer.planetary.tides import tidal_spin_axis_model

        model = self.model

        def coupled(base: Any, span: tuple[float, float]) -> Any:
            return tidal_spin_axis_model(base, span, model)

        return coupled

    @property
    def header(self) -> list[str]:
        """The table's extra columns."""
        return [] if self.model is None else list(TIDAL_COLUMNS.values())

    @property
    def row_bytes(self) -> float:
        """Memory per output time the extra columns need."""
        return 0.0 if self.model is None else float(TIDES_ROW_BYTES)

    @property
    def row_seconds(self) -> float:
        """Time per output time the extra columns need."""
        return 0.0 if self.model is None else TIDES_ROW_SECONDS

    def fields(self, t: np.ndarray) -> dict[str, np.ndarray]:
        """The extra JSON keys at the output times ``t`` (increasing), from the tidal history."""
        if self.model is None:
            return {}
        from andoyer.planetary.tides import tidal_history

        h = tidal_history(t, self.model)
        return {key: np.asarray(getattr(h, key)) for key in TIDAL_COLUMNS}

    def columns(self, t: np.ndarray) -> list[np.ndarray]:
        """The table's extra columns at the output times ``t``."""
        return list(self.fields(t).values())


def obliquity_tides(args: argparse.Namespace) -> ObliquityTides:
    """The tides of an ``obliquity`` command line, checked before any work.

    Parameters
    ----------
    args : argparse.Namespace
        With ``body``, ``tides``, ``tidal_dissipation`` (``None`` when not given) and
        ``dynamical_ellipticity``.

    Returns
    -------
    ObliquityTides

    Raises
    ------
    CliError
        ``--tides`` for another body than the Earth, or with ``--tidal-dissipation``,
        ``--dynamical-ellipticity`` or ``--ensemble``.

    Examples
    --------
    >>> plain = argparse.Namespace(body="earth", tides=None, tidal_dissipation=None,
    ...                            dynamical_ellipticity=None)
    >>> obliquity_tides(plain).tidal_dissipation  # the Earth's present-day dissipation
    1.0
    >>> obliquity_tides(argparse.Namespace(**{**vars(plain), "body": "mars"})).tidal_dissipation
    0.0
    >>> obliquity_tides(argparse.Namespace(**{**vars(plain), "tides": "ocean"}))
    ObliquityTides(tidal_dissipation=0.0, model='ocean')
    """
    body = str(args.body)
    given = args.tidal_dissipation
    if args.tides is not None and getattr(args, "ensemble", None) is not None:
        msg = f"expected no --tides with --ensemble (its members have no tides), got --tides {args.tides}"
        raise CliError(msg)
    if args.tides is None:
        default = DEFAULT_TIDAL_DISSIPATION.get(body, 0.0)
        return ObliquityTides(float(default if given is None else given))
    if body != "earth":
        msg = f"expected the body earth with --tides (the Earth-Moon tides), got {body}"
        raise CliError(msg)
    if given is not None:
        msg = (
            "expected no --tidal-dissipation with --tides (the tidal model sets the dissipation), "
            f"got --tidal-dissipation {given:g}"
        )
        raise CliError(msg)
    if args.dynamical_ellipticity is not None:
        msg = (
            "expected no --dynamical-ellipticity with --tides (the tidal model sets H from the "
            f"Earth's spin), got --dynamical-ellipticity {args.dynamical_ellipticity:g}"
        )
        raise CliError(msg)
    return ObliquityTides(0.0, args.tides)
