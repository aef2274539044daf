r"""Torque-free motion without elliptic functions: regular precession and steady spin.

For an axisymmetric body (symmetry axis ``ŝ`` with moment ``I_s``, transverse moment
``I_t``), the body angular velocity ``ω = w_t m + (w_s − w_t) m_s ŝ`` splits into a
uniform rotation about the fixed angular momentum and one about the body axis ``ŝ``:

.. math::
   \mathrm{rot}(t) = R_{\hat m_{ref}}(\Omega t)\;\mathrm{rot}_0\;R_{\hat s}(\lambda t),\qquad
   m(t) = R_{\hat s}(-\lambda t)\, m_0,\qquad \Omega = G w_t,\quad \lambda = m_s (w_s - w_t),

(check: ``rot⁻¹ d rot/dt = Ω m̂(t) + λ ŝ = ω``).  The same formula with ``λ = 0`` is the
motion of a sphere, of any steady spin about a principal axis (including the unstable
one) and, with ``Ω = 0``, of a body at rest.  Both angles are carried as double-double
phases (:mod:`andoyer.free.common.cycles`).

The files follow the naming rule of :mod:`andoyer.free`: the kernels of a step, each formula
written once, in ``<step>.py``, and its drivers in ``<step>_<backend>.py``:

========================  ============================================================
``setup``                 the axis, the frequencies ``Ω/2π``, ``λ/2π``, the momentum's
                          decomposition and the quaternions ``q₁ … q₄`` (kernels)
``setup_numpy``           on arrays (:class:`~andoyer.free.uniform.setup_numpy.Uniform`)
``setup_compiled``        per state, in one table (numba)
``evaluate``              ``m(t)`` and ``q(t)`` from the half angles (kernels)
``evaluate_numpy``        on arrays of states × epochs
``evaluate_compiled``     per state and epoch (numba)
========================  ============================================================
"""
