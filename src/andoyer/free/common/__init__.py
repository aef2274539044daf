"""What every regime of the free solution runs on: the working frame, the scaling, the phases, the blocks.

The files follow the naming rule of :mod:`andoyer.free`: the kernels of a step, each formula
written once, in ``<step>.py``, and its drivers in ``<step>_<backend>.py``:

========================  ============================================================
``scaling``               the power-of-two scaling of a state (kernel)
``scaling_numpy``         scaling and regime on arrays
``scaling_compiled``      scaling and regime per state (numba)
``polhode``               the polhode-centred working frame, its double-double
                          invariants, the attitude anchor and the anchored attitude
                          (kernels)
``polhode_numpy``         the frame on arrays (``PolhodeFrame``), quaternions on
                          component arrays
``polhode_compiled``      the steady-spin limit of the polhode per state (numba)
``cycles``                a phase ``ν t`` reduced modulo one cycle, ``sin``/``cos`` of it
                          (kernels)
``cycles_numpy``          double-double frequencies and reduced phases on arrays
``elliptic``              Carlson's ``R_F``, ``R_J``, the amplitude, unwrapped ``Π``
                          (scalar kernels)
``blocks``                evaluation of any regime over states × epochs in blocks
``constants``             the per-state constant tables of the numpy drivers
========================  ============================================================
"""
