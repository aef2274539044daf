"""The perturbation models ``andoyer propagate --model NAME`` can build, with their parameters.

Solar-system models use SI seconds for time (``gm`` in m³ s⁻², distances in
metres); the body's moments and momenta may be in any consistent unit (the
named bodies are normalised to ``C = 1``, so ``G = ω`` in rad/s).
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
from dataclasses import dataclass

from andoyer.body import RigidBody
from andoyer.cli.output import CliError
from andoyer.perturbations import GravityGradient, HeavyTop, Model, PrecessingFrame
from andoyer.perturbations.solar_system import mean_perturbers

__all__ = ["MODELS", "NamedModel", "add_model_arguments", "model_from_args"]


@dataclass(frozen=True)
class NamedModel:
    """A model of the command line: what it is, the body it defaults to, the options it needs."""

    description: str
    build: Callable[[RigidBody, argparse.Namespace], Model]
    default_body: str | None = None
    needs: tuple[str, ...] = ()


MODELS: dict[str, NamedModel] = {
    "free": NamedModel("torque-free (the exact closed-form flow by default)", lambda body, _: Model(body)),
    "gravity-gradient-sun": NamedModel(
        "gravity gradient of the Sun on the Earth's mean orbit (1 au, SI seconds)",
        lambda body, _: Model(body, GravityGradient(mean_perturbers("earth")[0])),
    ),
    "earth-lunisolar": NamedModel(
        "gravity gradients of the Sun and the Moon on their mean orbits about the Earth (SI seconds)",
        lambda body, _: Model(body, GravityGradient(mean_perturbers("earth"))),
        default_body="earth",
    ),
    "mars-solar": NamedModel(
        "gravity gradient of the Sun on Mars' mean orbit (SI seconds)",
        lambda body, _: Model(body, GravityGradient(mean_perturbers("mars"))),
        default_body="mars",
    ),
    "heavy-top": NamedModel(
        "uniform gravity on a body with a fixed point: ΔH = weight r_c·γ",
        lambda body, args: Model(body, HeavyTop(args.weight, args.center_of_mass)),
        needs=("weight", "center_of_mass"),
    ),
    "precessing-frame": NamedModel(
        "a reference frame turning at the constant rate μ: ΔH = -μ·M",
        lambda body, args: Model(body, PrecessingFrame(args.frame_rate)),
        needs=("frame_rate",),
    ),
}

_OPTION_NAMES = {"weight": "--weight", "center_of_mass": "--center-of-mass", "frame_rate": "--frame-rate"}


def add_model_arguments(parser: argparse.ArgumentParser) -> None:
    """``--model NAME`` and the parameters of the models that take some."""
    parser.add_argument(
        "--model",
        choices=tuple(MODELS),
        default="free",
        help="; ".join(f"{name}: {m.description}" for name, m in MODELS.items()),
    )
    parser.add_argument("--weight", type=float, metavar="W", help="heavy-top: m g0")
    parser.add_argument(
        "--center-of-mass", nargs=3, type=float, metavar=("X", "Y", "Z"), help="heavy-top: body components"
    )
    parser.add_argument(
        "--frame-rate",
        nargs=3,
        type=float,
        metavar=("MU1", "MU2", "MU3"),
        help="precessing-frame: μ in the frame's components",
    )


def model_from_args(body: RigidBody, args: argparse.Namespace) -> Model:
    """Build the named model, checking that exactly its own parameters were given."""
    named = MODELS[args.model]
    missing = [_OPTION_NAMES[n] for n in named.needs if getattr(args, n) is None]
    if missing:
        msg = f"expected {' and '.join(missing)} for --model {args.model}, got none"
        raise CliError(msg)
    extra = [
        flag for n, flag in _OPTION_NAMES.items() if n not in named.needs and getattr(args, n) is not None
    ]
    if extra:
        msg = f"expected only the parameters of --model {args.model}, got {', '.join(extra)}"
        raise CliError(msg)
    return named.build(body, args)
