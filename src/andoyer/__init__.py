"""andoyer: rigid-body rotation in canonical variables.

The Serret–Andoyer formalism as working software: a rigid body
(:class:`RigidBody`), one physical rotation state (:class:`State`) with
converters to every canonical chart (Euler angles and momenta, Andoyer
variables, ...), the free-body Hamiltonians and equations of motion.
"""

__version__ = "0.1.0.dev0"
