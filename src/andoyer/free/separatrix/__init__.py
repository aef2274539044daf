r"""Torque-free motion on the separatrix ``2T = G²/B`` (the ``k → 1`` limit).

In the SAM working frame (axis 3 = ``C``, ``m₃ > 0``), with ``σ = sign m₁`` and the
amplitudes of :mod:`andoyer.free.triaxial` (now ``a₁² + a₃² = G²``, ``k = 1``),

.. math::
   m_1 = \sigma a_1 \operatorname{sech}\tau,\quad m_2 = \sigma a_2 \tanh\tau,\quad
   m_3 = a_3 \operatorname{sech}\tau,\qquad \tau = \omega t + \tau_0,\quad
   \sinh\tau_0 = \frac{a_3 m_2}{\sigma a_2 m_3}.

The momentum leaves the unstable axis ``±B`` at ``t → −∞`` and reaches the other one at
``t → +∞``.  With ``c = a₃/G`` and ``∫dτ/(1 + c sech τ) = τ − (2c/√(1−c²))
arctan(√((1−c)/(1+c)) tanh(τ/2))``,

.. math::
   \Delta\psi = G w_2\,\Delta t - \frac{2 c P_1}{G \omega \sqrt{1 - c^2}}
      \Big[\arctan\big(r\tanh\tfrac{\tau}{2}\big)\Big]_{\tau_0}^{\tau},
   \qquad r = \sqrt{\frac{1-c}{1+c}} .

The attitude is assembled as in the triaxial case
(:func:`andoyer.free.common.polhode_numpy.attitude_anchor`).  The steady spin about ``±B``
(``m₁ = m₃ = 0``) is handled by :mod:`andoyer.free.uniform`.

Both backends of :class:`andoyer.free.FreeMotion` use the numpy driver here (few states lie on
the separatrix), in the files named by the rule of :mod:`andoyer.free`:

========================  ============================================================
``setup_numpy``           the constants (:class:`~andoyer.free.separatrix.setup_numpy.Separatrix`)
``evaluate_numpy``        ``m(t)`` and ``q(t)`` on arrays of states × epochs
========================  ============================================================
"""
