"""A rotation model: the body and the disturbing terms acting on it."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

from andoyer.body import RigidBody
from andoyer.perturbations.base import Perturbation, SumOfPerturbations

__all__ = ["Model"]


@dataclass(frozen=True)
class Model:
    """A rigid body and the perturbations acting on it (none: the free body).

    Parameters
    ----------
    body : RigidBody
        Given once, here: each term reads it from the model (:meth:`Perturbation.bind`).
    perturbations : Perturbation or sequence of Perturbation, optional
        Stored bound to ``body``; a term built for another body is refused.

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> from andoyer.perturbations import HeavyTop
    >>> model = Model(RigidBody(1, 1, 1.5), HeavyTop(1.0, [0, 0, 0.2]))
    >>> model.is_free, model.perturbation.hamiltonian
    (False, True)
    >>> len(Model(RigidBody(1, 1, 1.5), [HeavyTop(1.0, [0, 0, 1]) + HeavyTop(2.0, [0, 0, 1])]).parts)
    2
    """

    body: RigidBody
    perturbations: Perturbation | Sequence[Perturbation] = field(default_factory=tuple)
    #: The elementary perturbations, sums flattened (what integrators dispatch on).
    parts: tuple[Perturbation, ...] = field(init=False, repr=False, compare=False)
    _sum: Perturbation | None = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        if not isinstance(self.body, RigidBody):
            msg = f"expected an andoyer.RigidBody, got {type(self.body).__name__}"
            raise ValueError(msg)
        items = (
            (self.perturbations,)
            if isinstance(self.perturbations, Perturbation)
            else tuple(self.perturbations)
        )
        for item in items:
            if not isinstance(item, Perturbation):
                msg = f"expected Perturbation models, got {type(item).__name__}"
                raise ValueError(msg)
        items = tuple(item.bind(self.body) for item in items)
        object.__setattr__(self, "perturbations", items)
        total = None if not items else items[0] if len(items) == 1 else SumOfPerturbations(items)
        object.__setattr__(self, "_sum", total)
        object.__setattr__(self, "parts", () if total is None else SumOfPerturbations([total]).models)

    @property
    def is_free(self) -> bool:
        """``True`` when no perturbation acts."""
        return not self.perturbations

    @property
    def perturbation(self) -> Perturbation | None:
        """The sum of the perturbations, or ``None`` for the free body."""
        return self._sum
