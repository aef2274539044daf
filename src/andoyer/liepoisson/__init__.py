"""Lie–Poisson layer (work in progress)."""
