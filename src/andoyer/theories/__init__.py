"""Concrete perturbation theories built on :mod:`andoyer.series`.

Lara's SAM theory (:func:`sam_theory`), its evaluation on states (:class:`SAMRotation`), its
tables (:mod:`andoyer.theories.sam_tables`) and its expansion in Kinoshita's ``j``
(:mod:`andoyer.theories.kinoshita`).

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
from andoyer.theories.sam_rotation import SAMFrequencies, SAMRotation
from andoyer.theories.sam_tables import sam_tables, tables_from_json, tables_to_json

__all__ = [
    "SAM_RING",
    "SAMFrequencies",
    "SAMRotation",
    "SAMTheory",
    "beta_polynomial_value",
    "sam_hamiltonian",
    "sam_tables",
    "sam_theory",
    "tables_from_json",
    "tables_to_json",
]
