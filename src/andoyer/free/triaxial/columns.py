r"""The columns of the compiled triaxial table: one row of floats per body, each column named here.

:func:`andoyer.free.triaxial.setup_compiled.triaxial_table` writes one row per triaxial state
and :mod:`andoyer.free.triaxial.evaluate_compiled` (and
:mod:`andoyer.free.triaxial.periodic_numpy`) read it; the constants of a state lie together in
memory, as the compiled evaluation reads them.  Every index into the
table is one of the integer constants below: numba treats a module-level ``int`` as a
compile-time constant, so ``c[r, Q]`` or ``c[r, WA + n]`` inside a kernel costs what
``c[r, 6]`` did.  A field of several columns is named by its first column and has a width
(``NU`` and ``NU + 1`` are the high and low words of ``ν``).

The fields (notation of :mod:`andoyer.free.triaxial`: working frame of
:mod:`andoyer.free.common.polhode_numpy` with axis 3 the polhode axis, ``s = +1`` SAM, ``−1`` LAM; time
and momentum in the scaled units of :func:`andoyer.free.common.scaling_numpy.normalise`):

==================  =====  ======================================================================
name                width  meaning
==================  =====  ======================================================================
``CIRCULAR``        1      ``1.0`` where ``k² ≤ 1/2`` (circular theta series), ``0.0`` if not
``NU``              4      polhode frequency ``ν = ω/(4K)``, cycles per unit time: ``hi, lo``
                           (double-double) and ``hi`` split in halves ``hh, hl`` (Veltkamp)
``FRAC0``           1      initial polhode phase ``τ₀/(4K)``, cycles
``Q``               1      nome ``q = e^{−πK'/K}`` (circular) or ``q' = e^{−πK/K'}`` (hyperbolic)
``C_SN``            1      theta-quotient constant of ``sn`` (``ϑ₃/ϑ₂`` circular, ``ϑ₃/ϑ₄``
                           hyperbolic, of the nome ``q``; :class:`andoyer.special.theta.ThetaLattice`)
``C_CN``            1      that of ``cn``
``C_DN``            1      that of ``dn``
``KK``              1      ``2πK/K'``: the hyperbolic variable per polhode cycle
``MU_CN``           3      body-frame vector ``a₁ c_cn e₁`` (working axis 1 in body axes)
``MU_SN``           3      body-frame vector ``s a₂ c_sn e₂``
``MU_DN``           3      body-frame vector ``a₃ c_dn e₃``: ``m = (μ_cn ϑ_cn + μ_sn ϑ_sn +
                           μ_dn ϑ_dn)/ϑ₄``
``S``               1      ``s``: ``+1`` SAM, ``−1`` LAM
``NU_PSI``          4      secular rate of ``ψ``, ``Ω_ψ/(2π)`` cycles per unit time, as ``NU``
``WA``              6      coefficients of the ``ϑ₁`` series of ``Φ`` (``sin`` terms)
``WB``              6      the same for the ``cos`` terms, times ``s``
``SLOPE``           1      part of ``sΦ/2`` linear in the polhode phase: ``s`` (circular) or
                           ``s v₁/(2K')`` (hyperbolic), cycles per polhode cycle
``PSI0``            1      offset of the ``ψ`` phase (cycles) that makes ``Δψ(0) = 0``
``QUAT_U``          4      ``U = Q₀ ⊗ P`` (scalar last; zero without an attitude)
``QUAT_V``          4      ``V = Q₀ ⊗ e_z ⊗ P``
``V_SN``            3      body-frame vector part of the shortest arc: ``v_sn sn τ + v_cn cn τ``
``V_CN``            3      its ``cn`` part
``G``               1      ``G = |m|``
``A3``              1      amplitude ``a₃ = √(P₃/e₁₃)`` of ``m₃``
``PERIOD``          1      polhode period ``4K/ω``
``PRECESSION_RATE`` 1      mean rate of Andoyer's ``g`` about the polhode axis, rad per unit time
                           (``nan`` when the set-up skipped ``Π``)
``FLAT``            1      ``1.0`` for a steady spin (``P₁ = 0``; its row is dropped), else ``0.0``
==================  =====  ======================================================================

:data:`FIELDS` lists them as ``(name, first column, width)`` in column order; they tile
``range(NCOLUMNS)`` (``tests/free/triaxial/test_free_triaxial_columns.py``).
"""

from __future__ import annotations

__all__ = [
    "A3",
    "CIRCULAR",
    "C_CN",
    "C_DN",
    "C_SN",
    "FIELDS",
    "FLAT",
    "FRAC0",
    "HH",
    "HI",
    "HL",
    "KK",
    "LO",
    "MU_CN",
    "MU_DN",
    "MU_SN",
    "NCOLUMNS",
    "NU",
    "NU_PSI",
    "NWA",
    "PERIOD",
    "PRECESSION_RATE",
    "PSI0",
    "QUAT_U",
    "QUAT_V",
    "SLOPE",
    "V_CN",
    "V_SN",
    "WA",
    "WB",
    "G",
    "Q",
    "S",
]

#: Offsets of the words of a frequency field (``NU``, ``NU_PSI``) from its first column: the
#: double-double ``hi, lo`` and ``hi`` split in halves ``hh, hl``.
HI, LO, HH, HL = 0, 1, 2, 3
#: Number of ``ϑ₁`` series coefficients kept (width of ``WA`` and ``WB``).
NWA = 6

CIRCULAR = 0
NU = 1
FRAC0 = 5
Q = 6
C_SN = 7
C_CN = 8
C_DN = 9
KK = 10
MU_CN = 11
MU_SN = 14
MU_DN = 17
S = 20
NU_PSI = 21
WA = 25
WB = 31
SLOPE = 37
PSI0 = 38
QUAT_U = 39
QUAT_V = 43
V_SN = 47
V_CN = 50
G = 53
A3 = 54
PERIOD = 55
PRECESSION_RATE = 56
FLAT = 57
#: Number of columns of the table.
NCOLUMNS = 58

#: ``(name, first column, width)`` of every field, in column order.
FIELDS = (
    ("circular", CIRCULAR, 1),
    ("nu", NU, 4),
    ("frac0", FRAC0, 1),
    ("q", Q, 1),
    ("c_sn", C_SN, 1),
    ("c_cn", C_CN, 1),
    ("c_dn", C_DN, 1),
    ("kk", KK, 1),
    ("mu_cn", MU_CN, 3),
    ("mu_sn", MU_SN, 3),
    ("mu_dn", MU_DN, 3),
    ("s", S, 1),
    ("nu_psi", NU_PSI, 4),
    ("wa", WA, NWA),
    ("wb", WB, NWA),
    ("slope", SLOPE, 1),
    ("psi0", PSI0, 1),
    ("quat_u", QUAT_U, 4),
    ("quat_v", QUAT_V, 4),
    ("v_sn", V_SN, 3),
    ("v_cn", V_CN, 3),
    ("G", G, 1),
    ("a3", A3, 1),
    ("period", PERIOD, 1),
    ("precession_rate", PRECESSION_RATE, 1),
    ("flat", FLAT, 1),
)
