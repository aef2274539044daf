"""Concrete perturbation theories built on :mod:`andoyer.series`.

Examples
--------
>>> from andoyer.theories import sam_theory
>>> sam_theory(4).q[3]
(Fraction(3, 4), Fraction(0, 1), Fraction(9, 32))
"""

from andoyer.theories.sam import (
    SAM_RING,
    SAMTheory,
    beta_polynomial_value,
    sam_hamiltonian,
    sam_theory,
)

__all__ = ["SAM_RING", "SAMTheory", "beta_polynomial_value", "sam_hamiltonian", "sam_theory"]
