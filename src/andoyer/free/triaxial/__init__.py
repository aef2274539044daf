r"""Exact torque-free motion of a triaxial body in SAM or LAM (off the separatrix).

In the working frame of :mod:`andoyer.free.common.polhode_numpy` (axis 3 the polhode axis, ``m₃ > 0``)
the body angular momentum is (Jacobi; Gurfil et al. A.2 for SAM, with ``s`` for LAM)

.. math::
   m_1 = a_1 \operatorname{cn}\tau,\quad m_2 = s\,a_2 \operatorname{sn}\tau,\quad
   m_3 = a_3 \operatorname{dn}\tau,\qquad \tau = \omega t + \tau_0,\quad
   a_1^2 = \frac{P_1}{e_{13}},\ a_2^2 = \frac{P_1}{e_{23}},\ a_3^2 = \frac{P_3}{e_{13}},\
   k^2 = \frac{e_{12} P_1}{e_{23} P_3},\ \omega^2 = e_{23} P_3 .

Attitude.  With ``S(m)`` the shortest-arc rotation taking ``m`` to ``+z``
(:func:`andoyer.free.common.polhode_numpy.shortest_arc`), ``rot_w(t) = Q₀ R_z(Δψ(t)) S(m(t))``,
where ``Q₀`` is fixed by the initial attitude and ``ψ = g + l`` (Andoyer's node plus
proper-rotation angles, regular at ``J = 0``) obeys

.. math:: \dot\psi = G w_3 + \frac{D - G^2 w_3}{G + m_3}.

With ``c = a₃/G`` and ``f(τ) = 1/(1 + c dn τ)``, ``Δψ = G w₃ Δt + (sP₁/(Gω)) ∫f dτ``.
``f`` is elliptic with periods ``2K, 4iK'`` and simple poles at ``±i v₀``, ``v₀ = 2K' − v₁``,
``v₁ = F(arccot κ | m') = R_F(κ², κ² + m, 1 + κ²)``, ``κ² = e₁₂/e₂₃``, residues ``±iρ``,
``ρ = G a₃ / (a₁² √(1 + κ²))``.  The partial-fraction expansion in ``ϑ₁(·|q²)`` then gives
(``sP₁ρ/(Gω) = s`` exactly)

.. math::
   \Delta\psi = \Omega_\psi \Delta t + s\,[\Phi(\tau) - \Phi(\tau_0)],\qquad
   \Phi(\tau) = \frac{\pi\tau}{K}
      + 2\arg\vartheta_1\Big(\frac{\pi(\tau + i v_0)}{2K}\Big|q^2\Big),
   \qquad \Omega_\psi = G w_3 + \frac{s P_1}{G}\langle f\rangle .

``Φ`` is ``2K``-periodic modulo ``2π`` and only ``e^{iΦ/2}`` (up to sign) is needed, so
no branch of ``arg`` has to be tracked.  For ``m ≤ 1/2`` the series in ``q² ≤ e^{−2π}`` is
used directly ("circular"); for ``m > 1/2`` it is rewritten by Jacobi's imaginary
transformation (DLMF 20.7.30) as a series in ``q* = √q' ≤ e^{−π/2}`` of hyperbolic
functions plus a term linear in ``τ`` ("hyperbolic").  This replaces the incomplete
integral of the third kind of the classical solution,
``∫f dτ = [Π(−κ²; am τ | m) − c A(am τ)]/(1 − c²)`` with ``A(φ) = ∫dθ/(1 + κ² sin²θ)``
(the characteristic of Sadov's ``Π(κ², λ)``, Gurfil eq. 143, in the other sign
convention), by a few series terms per epoch, and avoids its cancellation near pure spin.
The secular rate needs the complete ``Π(−κ²|m)``: it is taken from the AGM in
double-double arithmetic (:func:`andoyer.free.triaxial.setup.secular_rate`), because
``Ω_ψ t`` reaches 10⁶ rad at 100 periods of a fast spinner.

Numbers are carried so that the phase stays exact over long times: the polhode frequency
``ω/4K`` and ``Ω_ψ/2π`` are double-doubles (``K`` from the AGM on ``1 − k²`` formed without
cancellation), multiplied by the time error-free (:mod:`andoyer.free.common.cycles_numpy`).

The files follow the naming rule of :mod:`andoyer.free`: the kernels of a step, each formula
written once, in ``<step>.py``, and its drivers in ``<step>_<backend>.py``:

========================  ============================================================
``setup``                 modulus, amplitudes, frequencies, secular rate of ``ψ``, ``ϑ₁``
                          coefficients (kernels)
``setup_numpy``           on arrays (:class:`~andoyer.free.triaxial.setup_numpy.Triaxial`)
``setup_compiled``        per state, one row of a table (numba)
``columns``               the named columns of that table
``evaluate``              ``sn, cn, dn`` by theta series, the ``ψ`` half angle (kernels)
``evaluate_numpy``        on arrays of states × epochs
``evaluate_compiled``     per state and epoch, from the table (numba)
``periodic``              piecewise polynomials of one period: locate, evaluate (kernels)
``periodic_numpy``        their fit, and their evaluation on arrays
``periodic_compiled``     their evaluation per state and epoch (numba)
========================  ============================================================
"""
