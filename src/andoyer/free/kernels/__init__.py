"""Scalar, numba-compilable kernels of the exact free rotation, one definition per formula.

Used directly by the compiled paths and, through vectorisation, by the numpy path; see
``docs/architecture.md``.
"""
