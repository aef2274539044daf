"""Bad input to every public function: ``ValueError``/``TypeError`` saying "expected …", no RuntimeWarning.

One table, ``CASES``: ``(public object, callable, args, exception, match)`` over the classes of
bad input of issue 18 (NaN, ±inf, ±1e300, empty arrays, wrong shapes, shapes that do not
broadcast, ``|L| > G``, ``G ≤ 0``, non-physical inertia, impossible sizes and phases). The
project runs pytest with ``filterwarnings = error``, so a RuntimeWarning (an overflow on the
way to the error) fails the case. ``test_every_public_name_is_in_the_table_or_exempt`` walks
``andoyer.__all__`` and the ``__all__`` of the subpackages it lists, and of theirs (``andoyer.planetary``'s):
a new public function must add its bad inputs here, or say in ``EXEMPT`` why it has none.
The command line's half is ``tests/cli/test_cli_bad_input.py``.
"""

from __future__ import annotations

import functools
import inspect
import types

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

import andoyer
import andoyer.planetary.cassini
import andoyer.planetary.cassini as cassini_api
import andoyer.planetary.nutation
import andoyer.planetary.precession
import andoyer.planetary.spin_axis
from andoyer import (
    FreeRotation,
    RigidBody,
    State,
    bodies,
    catalogue,
    free,
    integrate,
    propagate,
    special,
    state,
)
from andoyer.perturbations import (
    CircularOrbit,
    GravityGradient,
    HeavyTop,
    KeplerOrbit,
    LinearDamping,
    Model,
    PointMass,
    PrecessingFrame,
    SecularGravityGradient,
    perturbed_rates,
    solve_kepler,
)
from andoyer.planetary.cassini import CassiniBody, ColomboTop, eccentricity_function
from andoyer.planetary.migration import MigratingSpinAxisModel, SatelliteMigration, satellite_migration
from andoyer.planetary.nutation import (
    fit_terms,
    luni_solar_precession,
    minimum_span,
    numeric_terms,
    nutation,
    nutation_cost,
    nutation_series,
    terms_table,
)
from andoyer.planetary.orbits import (
    LaplaceLagrangeOrbit,
    NBodyOrbit,
    SecularOrbit,
    TableOrbit,
    VondrakEcliptic,
    check_times,
    fundamental_frequencies,
    lyapunov_exponent,
    orbit_history,
    planet_orbits,
    read_alkhqp,
    read_orbit_csv,
    read_solution,
    solution_format,
    source_span,
    spectral_lines,
    write_orbit_csv,
)
from andoyer.planetary.parameters import PARAMETERS, Parameter, check
from andoyer.planetary.precession import (
    check_dynamical_ellipticity,
    default_step,
    fit_trend,
    mean_node_rate,
    planet_body,
    precession_problem,
    precession_rates,
)
from andoyer.planetary.precession_constant import (
    obliquity as body_obliquity,
)
from andoyer.planetary.precession_constant import (
    precession_constant,
    satellites_of,
    spin_axis_ecliptic,
)
from andoyer.planetary.spin_axis import (
    SpinAxisModel,
    build_model,
    daily_insolation,
    default_axis,
    equinox,
    evolve_axes,
    general_precession,
    member_cost,
    member_obliquities,
    member_times,
    obliquity_statistics,
    output_times,
    perturbed_states,
    resonance_distances,
    run_cost,
    spin_axis_blocks,
    spin_axis_history,
)
from andoyer.planetary.tides import (
    ConstantPhaseLag,
    ConstantTimeLag,
    EarthMoonSystem,
    OceanTides,
    TidalResponse,
    TidalSpinAxisModel,
    calibrate,
    present_rates,
    tidal_history,
    tidal_model,
    tidal_spin_axis_history,
    tidal_spin_axis_model,
)
from andoyer.theories import SAMRotation, beta_polynomial_value, sam_tables, sam_theory

P = functools.partial
AXIS = np.array([0.0, 0.4, 0.9])
NAN, INF, HUGE = float("nan"), float("inf"), 1e300
BODY = RigidBody(1.0, 2.0, 3.0)
EROS = bodies.get("eros")
STATE = State.from_andoyer(0.1, 0.2, 0.3, 0.9, 1.0, 0.5)
STATES3 = State.from_andoyer(np.array([0.1, 0.2, 0.3]), 0.2, 0.3, 0.9, 1.0, 0.5)
TOP = HeavyTop(0.5, [0.0, 0.1, 0.3])
MODEL = Model(RigidBody(1.0, 1.2, 1.5), TOP)
IDENT = Rotation.identity()
FREE = FreeRotation(BODY)
MODEL_EARTH = SpinAxisModel.from_precession_rate("earth", 50.3848, 0.4091)
MODEL_TIDES = SpinAxisModel.from_precession_rate("earth", 50.3848, 0.4091, tidal_dissipation=1.0)
Q0 = [0.0, 0.0, 0.0, 1.0]
M0 = [0.3, 0.2, 1.0]

# (public object exercised, callable, args, exception, regular expression the message matches)
CASES = [
    # -- bodies: non-physical inertia, NaN, inf, 1e300
    (RigidBody, RigidBody, (-1.0, 1.0, 1.0), ValueError, "expected"),
    (RigidBody, RigidBody, (NAN, 1.0, 1.0), ValueError, "expected"),
    (RigidBody, RigidBody, (INF, 1.0, 1.0), ValueError, "expected"),
    (RigidBody, RigidBody, (1.0, 1.0, -HUGE), ValueError, "expected"),  # (1, 1, 1e300) only warns: A + B < C
    (RigidBody, RigidBody, (0.0, 1.0, 1.0), ValueError, "expected"),
    (RigidBody, RigidBody.from_moments, ([],), ValueError, "expected"),
    (RigidBody, RigidBody.from_moments, ([1.0, 2.0],), ValueError, "expected"),
    (RigidBody, RigidBody.from_ratios, (NAN, 0.5), ValueError, "expected"),
    (RigidBody, RigidBody.from_alpha_beta, (0.1, 1.5), ValueError, "expected"),
    (bodies.get, bodies.get, ("vulcan",), ValueError, "expected"),
    (bodies.info, bodies.info, ("vulcan",), ValueError, "expected"),
    # -- the catalogue: unknown names, bad user bodies (each check: tests/catalogue), bad units
    (catalogue.get, catalogue.get, ("vulcan",), ValueError, "expected a body among"),
    (catalogue.get, catalogue.get, (None,), ValueError, "expected a body among"),
    (
        catalogue.body_from_dict,
        catalogue.body_from_dict,
        ({"name": "x", "gm": NAN},),
        ValueError,
        "expected a finite",
    ),
    (
        catalogue.body_from_dict,
        catalogue.body_from_dict,
        ({"name": "x", "gm": -1.0},),
        ValueError,
        "expected gm > 0",
    ),
    (
        catalogue.body_from_dict,
        catalogue.body_from_dict,
        ({"name": "x", "radius": -HUGE},),
        ValueError,
        "expected radius > 0",
    ),
    (catalogue.body_from_dict, catalogue.body_from_dict, ([],), ValueError, "expected a table"),
    (
        catalogue.read_body,
        catalogue.read_body,
        ("/nonexistent/body.json",),
        ValueError,
        "expected a readable",
    ),
    (catalogue.units.convert, catalogue.units.convert, (1.0, "km", "deg"), ValueError, "expected a unit"),
    (catalogue.units.dimension, catalogue.units.dimension, ("furlong",), ValueError, "expected a unit"),
    # -- states: every constructor with NaN, inf, ±1e300, |L| > G, G <= 0, shapes
    (State, State.from_andoyer, (NAN, 0, 0, 0.5, 1.0, 0.5), ValueError, "expected finite l"),
    (State, State.from_andoyer, (0, 0, 0, 0.5, INF, 0.5), ValueError, "expected finite G"),
    (State, State.from_andoyer, (0, 0, 0, 0.5, HUGE, 0.5), ValueError, "expected G .*got"),
    (State, State.from_andoyer, (0, 0, 0, -HUGE, HUGE, 0.0), ValueError, "expected G .*got"),
    (State, State.from_andoyer, (0, 0, 0, 2.0, 1.0, 0.5), ValueError, r"expected \|L\| <= G"),
    (State, State.from_andoyer, (0, 0, 0, 0.0, 1.0, -1.5), ValueError, r"expected \|H\| <= G"),
    (State, State.from_andoyer, (0, 0, 0, 0.0, 0.0, 0.0), ValueError, "expected G > 0"),
    (State, State.from_andoyer, (0, 0, 0, 0.0, -1.0, 0.0), ValueError, "expected G > 0"),
    (State, State.from_andoyer, (np.zeros(3), np.zeros(4), 0, 0.5, 1, 0), ValueError, "expected shapes"),
    (State, State.from_euler, (0, 1, 0, NAN, 0, 0), ValueError, "expected finite"),
    (State, State.from_euler, (0, 1, 0, HUGE, HUGE, HUGE), ValueError, "expected"),
    (State, State.from_euler, (0, -0.1, 0, 1, 0, 1), ValueError, "expected"),
    (State, State.from_quaternion, ([0, 0, 1], [1, 0, 0]), ValueError, "expected quaternion"),
    (State, State.from_quaternion, (Q0, [HUGE, 0, 0]), ValueError, "expected m_body"),
    (State, State.from_quaternion, (Q0, [-HUGE, HUGE, 0]), ValueError, "expected m_body"),
    (State, State.from_quaternion, (Q0, [INF, 0, 0]), ValueError, "expected finite m_body"),
    (State, State.from_quaternion, ([0, 0, 0, 2.0], [1, 0, 0]), ValueError, "expected unit"),
    (State, State.from_quaternion, (np.tile(Q0, (3, 1)), np.ones((4, 3))), ValueError, "expected"),
    (State, State.from_quaternion, (np.empty((0, 4)), np.ones((2, 3))), ValueError, "expected"),
    (State, State.from_attitude, (np.eye(3), [1, 0, 0]), ValueError, "expected"),
    (State, State.from_angular_velocity, (IDENT, [1.0], BODY), ValueError, "expected"),
    (State, State.from_angular_velocity, (IDENT, [HUGE, 0, 0], BODY), ValueError, "expected"),
    (State, State.from_sadov, (BODY, 0, 0, 0, NAN, 1.0, 0.5), ValueError, "expected"),
    (State, State.from_serret, (BODY, 0, 0, 0, 1.0, 0.5, NAN), ValueError, "expected"),
    (State, State.from_initial_andoyer, (BODY, 0, 0, 0, 0.9, 1.0, 0.5, NAN), ValueError, "expected"),
    (State, P(State.from_sam, body=BODY), (0, 0, 0, NAN, 1.0, 0.5), ValueError, "expected"),
    (State, State.from_quaternion(Q0, [0, 0, 0]).as_andoyer, (), ValueError, "expected"),
    (State, STATE.energy, ((1, 2, 3),), ValueError, "expected"),
    (State, STATE.as_sadov, ("earth",), ValueError, "expected"),
    (State, STATE.as_serret, (BODY, NAN), ValueError, "expected"),
    (State, STATE.as_initial_andoyer, (BODY, INF), ValueError, "expected"),
    (State, STATE.as_sam, (BODY, "XAM"), ValueError, "expected"),
    (State, STATE.reshape, (5,), ValueError, "expected"),
    # -- charts
    (state.inclinations, state.inclinations, (1.5, 1.0, 0.0), ValueError, r"expected \|L\| <= G"),
    (state.inclinations, state.inclinations, (0.5, HUGE, 0.0), ValueError, "expected G .*got"),
    (state.euler_matrix, state.euler_matrix, (INF, 0, 0), ValueError, "expected finite"),
    (state.andoyer_matrix, state.andoyer_matrix, (np.zeros(2), 0, np.zeros(3), 0, 0), ValueError, "shapes"),
    (state.andoyer_from_euler, state.andoyer_from_euler, (0, 0, 0, 1, 0, 1), ValueError, "expected"),
    (state.andoyer_from_euler, state.andoyer_from_euler, (0, 1, 0, HUGE, 0, HUGE), ValueError, "expected"),
    (state.euler_from_andoyer, state.euler_from_andoyer, (0, 0, 0, 0.5, -1.0, 0), ValueError, "expected"),
    (state.euler_from_andoyer, state.euler_from_andoyer, (0, 0, 0, 0.5, HUGE, 0), ValueError, "expected"),
    (state.andoyer_to_serret, state.andoyer_to_serret, (BODY, 0, 0, 0, 2.0, 1.0, 0.5), ValueError, "L"),
    (state.serret_to_andoyer, state.serret_to_andoyer, (BODY, 0, 0, 0, 1.0, 0.5, -1.0), ValueError, "T"),
    # -- each chart's dynamics (andoyer.state: the hub's, the Euler and the Andoyer chart's)
    (state.andoyer_equations, state.andoyer_equations, (BODY, 0, 0, 0, 1.5, 1.0, 0.0), ValueError, "<= G"),
    (state.andoyer_equations, state.andoyer_equations, (BODY, NAN, 0, 0, 0.5, 1, 0), ValueError, "finite"),
    (state.andoyer_hamiltonian, state.andoyer_hamiltonian, (BODY, 0, 1.5, 1.0), ValueError, r"\|L\| <= G"),
    (state.andoyer_hamiltonian, state.andoyer_hamiltonian, (BODY, INF, 0.5, 1.0), ValueError, "finite l"),
    (state.euler_equations, state.euler_equations, (BODY, 0, 0, 0, 1, 0, 1), ValueError, "sin.theta. != 0"),
    (state.euler_equations, state.euler_equations, (BODY, 0, 1, 0, NAN, 0, 1), ValueError, "finite Phi"),
    (state.euler_hamiltonian, state.euler_hamiltonian, (BODY, 0, 0, 0, 1, 0, 0.5), ValueError, "sin.theta"),
    (state.euler_hamiltonian, state.euler_hamiltonian, (BODY, 0, 1, 0, INF, 0, 1), ValueError, "finite Phi"),
    (state.euler_poinsot, state.euler_poinsot, (BODY, [NAN, 0, 1]), ValueError, "finite m_body"),
    (state.euler_poinsot, state.euler_poinsot, (BODY, [0, 0, 1], [INF, 0, 0]), ValueError, "finite torque"),
    (state.euler_poinsot_omega, state.euler_poinsot_omega, (BODY, [0, 1]), ValueError, "shape"),
    (state.lie_poisson, state.lie_poisson, ([0, 0, 1], [0, 1]), ValueError, "shape"),
    (state.lie_poisson, state.lie_poisson, ([NAN, 0, 1], [0, 1, 0]), ValueError, "finite m_body"),
    (state.attitude_rate, state.attitude_rate, ([0, 0, 1], [0, 0, 1]), ValueError, "shape"),
    (state.attitude_rate, state.attitude_rate, ([0, 0, 0, 1], [INF, 0, 1]), ValueError, "finite omega_body"),
    (state.state_hamiltonian, state.state_hamiltonian, (BODY, [NAN, 0, 1]), ValueError, "finite m_body"),
    (state.state_hamiltonian, state.state_hamiltonian, (BODY, [0, 1]), ValueError, "shape"),
    # -- the exact free motion
    (FreeRotation, FreeRotation, ((1, 2, 3),), ValueError, "expected"),
    (FreeRotation, FREE.propagate, (STATES3, [0.0, 1.0]), ValueError, "expected times broadcast"),
    (FreeRotation, FREE.propagate, (STATE, NAN), ValueError, "expected finite times"),
    (FreeRotation, FREE.propagate, (STATE, HUGE), ValueError, r"expected times with \|ω t\|"),
    (FreeRotation, FREE.propagate, (STATE, -HUGE), ValueError, r"expected times with \|ω t\|"),
    (FreeRotation, FREE.propagate, ("state", 1.0), ValueError, "expected"),
    (FreeRotation, FREE.momentum, (STATES3, [0.0, 1.0]), ValueError, "expected times broadcast"),
    (free.FreeMotion, free.FreeMotion, ([1, 2, 3], M0, [0, 0, 1]), ValueError, "expected q0"),
    (free.FreeMotion, free.FreeMotion, ([1, 2, -3], M0), ValueError, "expected"),  # A + B < C is fine
    (free.propagate, free.propagate, ([1, 2, 3], M0, Q0, 1e17), ValueError, r"expected times with \|ω t\|"),
    (free.momentum, free.momentum, ([1, 2, 3], [NAN, 0, 1], 0.0), ValueError, "expected"),
    (free.momentum, free.momentum, ([1, 2, 3], M0, INF), ValueError, "expected finite times"),
    (free.attitude, free.attitude, ([1, 2, 3], M0, np.tile(Q0, (2, 1)), np.zeros(3)), ValueError, "expected"),
    (free.attitude, free.attitude, ([1, 2, 3], np.ones((3, 3)), Q0, np.zeros(2)), ValueError, "expected"),
    (free.periods, free.periods, ([1, 2, 3], [1.0, 2.0]), ValueError, "expected"),
    (free.periods, free.periods, ([-1, 2, 3], M0), ValueError, "expected"),
    (free.classify, free.classify, ([1, 2, 3], [1.0, 2.0]), ValueError, "expected"),
    (free.classify, free.classify, ([1, 2, INF], M0), ValueError, "expected"),
    # -- propagation under a model
    (propagate, propagate, (MODEL, STATE, []), ValueError, "expected at least one output time"),
    (propagate, propagate, (MODEL, STATE, NAN), ValueError, "expected finite t"),
    (propagate, propagate, (MODEL, STATES3, [0.0, 1.0]), ValueError, "expected times broadcastable"),
    (propagate, propagate, (MODEL, STATE, 1e300), ValueError, r"expected times with \|ω t\|"),
    (propagate, propagate, (MODEL, STATE, -1e300), ValueError, r"expected times with \|ω t\|"),
    (propagate, P(propagate, method="splitting", step=1e-9), (MODEL, STATE, [0.0, 1e6]), ValueError, "steps"),
    (propagate, propagate, (MODEL, STATE, 1e9), ValueError, "expected a DOP853 run of at most"),
    (propagate, P(propagate, method="splitting", step=NAN), (MODEL, STATE, 1.0), ValueError, "expected"),
    (propagate, P(propagate, method="rk4"), (MODEL, STATE, 1.0), ValueError, "expected method"),
    (propagate, P(propagate, method="splitting", rtol=0.0), (MODEL, STATE, 1.0), ValueError, "finite rtol"),
    (propagate, P(propagate, method="splitting", rtol=1e-20), (MODEL, STATE, 1.0), ValueError, "round-off"),
    (propagate, P(propagate, t0=INF), (MODEL, STATE, 1.0), ValueError, "expected finite t0"),
    (propagate, propagate, (BODY, STATE, 1.0), ValueError, "expected an andoyer Model"),
    (integrate.integrate_reference, integrate.integrate_reference, (MODEL, STATE, []), ValueError, "time"),
    (
        integrate.integrate_euler_poisson,
        integrate.integrate_euler_poisson,
        (MODEL.body, TOP, M0, [0, 0, 1.0], NAN),
        ValueError,
        "expected",
    ),
    (
        integrate.integrate_euler_poisson,
        integrate.integrate_euler_poisson,
        (MODEL.body, TOP, M0, [0, 0, 1.0], 1e300),
        ValueError,
        r"expected times with \|ω t\|",
    ),
    (
        integrate.integrate_euler_poisson,
        integrate.integrate_euler_poisson,
        (MODEL.body, TOP, M0, [0, 0, 1.0], []),
        ValueError,
        "expected at least one output time",
    ),
    (
        integrate.integrate_euler_poisson,
        integrate.integrate_euler_poisson,
        (MODEL.body, TOP, M0, [0, 0, 1.0], 1e9),
        ValueError,
        "expected a DOP853 run of at most",
    ),
    (
        integrate.euler_poisson_rates,
        integrate.euler_poisson_rates,
        (MODEL.body, TOP, [1.0, 2.0], [0, 0, 1.0]),
        ValueError,
        "expected",
    ),
    (
        integrate.euler_poisson_integrals,
        integrate.euler_poisson_integrals,
        (MODEL.body, TOP, M0, [NAN, 0, 1.0]),
        ValueError,
        "expected",
    ),
    (Model, Model, ("earth",), ValueError, "expected"),
    (HeavyTop, HeavyTop, (0.0, [0, 0, 1]), ValueError, "expected"),
    (HeavyTop, HeavyTop, (1.0, [NAN, 0, 1]), ValueError, "expected"),
    (PrecessingFrame, PrecessingFrame, ([INF, 0, 0],), ValueError, "expected"),
    (LinearDamping, LinearDamping, (BODY, [-1.0, 0, 0]), ValueError, "expected"),
    (CircularOrbit, CircularOrbit, (-1.0, 1.0), ValueError, "expected"),
    (KeplerOrbit, KeplerOrbit, (1.0, 1.5, 0, 0, 0, 0, 1.0), ValueError, "expected"),
    (PointMass, PointMass, (NAN, CircularOrbit(1.0, 1.0)), ValueError, "expected"),
    (GravityGradient, GravityGradient, ([],), ValueError, "expected"),
    (SecularGravityGradient, SecularGravityGradient, (BODY, []), ValueError, "expected"),
    (SecularGravityGradient, SecularGravityGradient, ("earth", []), ValueError, "expected"),
    (solve_kepler, solve_kepler, (0.5, 1.5), ValueError, "expected"),
    (solve_kepler, solve_kepler, (INF, 0.5), ValueError, "expected"),
    (perturbed_rates, perturbed_rates, (BODY, TOP, 0.0, Q0, [1.0, 2.0]), ValueError, "expected"),
    # -- precession of the planets
    (precession_rates, precession_rates, ("venus",), ValueError, "expected one of"),
    (precession_constant, precession_constant, ("vulcan",), ValueError, "expected a body among"),
    (precession_constant, precession_constant, ("pluto",), ValueError, "expected Pluto to have"),
    (precession_constant, P(precession_constant, dynamical_ellipticity=NAN), ("mars",), ValueError, "expec"),
    (precession_constant, P(precession_constant, dynamical_ellipticity=0.01), ("saturn",), ValueError, "Tit"),
    (body_obliquity, body_obliquity, ("vulcan",), ValueError, "expected a body among"),
    (satellites_of, satellites_of, (None,), ValueError, "expected a body among"),
    (spin_axis_ecliptic, spin_axis_ecliptic, ("miranda",), ValueError, "expected Miranda to have pole_ra"),
    (resonance_distances, resonance_distances, (NAN,), ValueError, "expected a finite precession rate"),
    (default_axis, default_axis, ("miranda",), ValueError, "expected Miranda to have pole_ra"),
    (precession_rates, P(precession_rates, integrate=1.0, step=1e8), ("earth",), ValueError, "half the span"),
    (precession_rates, P(precession_rates, integrate=1e9), ("earth",), ValueError, "would need"),
    (precession_rates, P(precession_rates, integrate=NAN), ("earth",), ValueError, "expected"),
    (precession_rates, P(precession_rates, secular_years=-HUGE), ("earth",), ValueError, "expected"),
    (default_step, default_step, ("pluto",), ValueError, "expected"),
    (precession_rates, P(precession_rates, moments="iers"), ("earth",), ValueError, "expected a moment set"),
    (planet_body, planet_body, ("venus",), ValueError, "expected one of"),
    (planet_body, P(planet_body, moments="lara"), ("earth",), ValueError, "expected a moment set among"),
    (precession_problem, precession_problem, ("pluto",), ValueError, "expected"),
    (mean_node_rate, mean_node_rate, ([0.0, 1.0], [0.0, 1.0]), ValueError, "expected"),
    (mean_node_rate, mean_node_rate, (np.arange(4.0), np.zeros(5)), ValueError, "expected"),
    (fit_trend, fit_trend, ([0.0, 1.0, 2.0], [NAN, 1.0, 2.0]), ValueError, "expected finite"),
    (fit_trend, fit_trend, ([0.0, 1.0, 2.0], [0.0, 1.0]), ValueError, "expected"),
    (check_dynamical_ellipticity, check_dynamical_ellipticity, (NAN,), ValueError, "expected"),
    (check_dynamical_ellipticity, check_dynamical_ellipticity, (HUGE,), ValueError, "expected"),
    # -- orbit histories
    (VondrakEcliptic, VondrakEcliptic().normal, (3e5,), ValueError, "expected times within"),
    (VondrakEcliptic, VondrakEcliptic().normal, (NAN,), ValueError, "expected finite"),
    (NBodyOrbit, NBodyOrbit, ("pluto",), ValueError, "expected a planet"),
    (NBodyOrbit, P(NBodyOrbit, step_days=NAN), ("earth",), ValueError, "expected"),
    (SecularOrbit, SecularOrbit, ("pluto",), ValueError, "expected a planet"),
    (SecularOrbit, P(SecularOrbit, step=NAN), ("earth",), ValueError, "expected an integration step"),
    (SecularOrbit, SecularOrbit("mars").normal, (-HUGE,), ValueError, "expected times within"),
    (LaplaceLagrangeOrbit, LaplaceLagrangeOrbit, ("pluto",), ValueError, "expected a planet"),
    (LaplaceLagrangeOrbit, P(LaplaceLagrangeOrbit, frequencies="bvw"), ("earth",), ValueError, "expected"),
    (spectral_lines, spectral_lines, ([0j] * 10, 1.0), ValueError, "expected a finite 1-d signal"),
    (spectral_lines, spectral_lines, ([NAN] * 100, 1.0), ValueError, "expected a finite 1-d signal"),
    (
        fundamental_frequencies,
        fundamental_frequencies,
        ([[0j] * 10], [[0j] * 10], 1.0, [1.0], [-1.0]),
        ValueError,
        "expected",
    ),
    (lyapunov_exponent, P(lyapunov_exponent, span=NAN), (), ValueError, "expected a nonzero span"),
    (lyapunov_exponent, P(lyapunov_exponent, separation=1.0), (), ValueError, "expected 0 < separation"),
    (TableOrbit, TableOrbit, ([0.0, 1.0], [[0, 0, 1], [0, 0, 1]]), ValueError, "expected at least 4 rows"),
    (TableOrbit, TableOrbit, ([0.0, 1.0, 2.0, NAN], [[0, 0, 1]] * 4), ValueError, "expected"),
    (check_times, check_times, (NAN, (-1.0, 1.0), "x"), ValueError, "expected finite"),
    (check_times, check_times, (HUGE, (-1.0, 1.0), "x"), ValueError, "expected times within"),
    (orbit_history, orbit_history, ("nowhere",), ValueError, "expected an orbit source"),
    (orbit_history, P(orbit_history, body="mars"), ("vondrak",), ValueError, "expected"),
    (read_orbit_csv, read_orbit_csv, (andoyer.__file__,), ValueError, "expected a time column"),
    (read_alkhqp, read_alkhqp, (andoyer.__file__, np.eye(3)), ValueError, "expected 7 columns"),
    (read_alkhqp, read_alkhqp, (andoyer.__file__, 2 * np.eye(3)), ValueError, "expected a proper orthogonal"),
    (orbit_history, P(orbit_history, orbit_format="la2010"), ("secular",), ValueError, "expected orbit_"),
    (read_solution, read_solution, ("nowhere.dat",), ValueError, "expected an existing orbit or solution"),
    (read_solution, read_solution, (andoyer.__file__, "la2004"), ValueError, "expected 4 columns"),
    (read_solution, read_solution, (andoyer.__file__, "csv"), ValueError, "expected a solution format"),
    (read_solution, read_solution, (andoyer.__file__, "nope"), ValueError, "expected a solution format"),
    (solution_format, solution_format, (andoyer.__file__,), ValueError, "expected an orbit or solution file"),
    (planet_orbits, planet_orbits, ("nowhere",), ValueError, "expected an existing orbit or solution file"),
    (planet_orbits, planet_orbits, ("vondrak", ["mars"]), ValueError, "expected planets earth"),
    (planet_orbits, planet_orbits, ("secular", ["pluto"]), ValueError, "expected"),
    (planet_orbits, P(planet_orbits, frequencies="nope"), ("laplace-lagrange",), ValueError, "expected"),
    (write_orbit_csv, write_orbit_csv, ("unused.csv", VondrakEcliptic(), [NAN]), ValueError, "expected"),
    # -- spin-axis histories
    (spin_axis_history, spin_axis_history, (VondrakEcliptic(), "earth", [HUGE]), ValueError, "expected"),
    (spin_axis_history, spin_axis_history, (VondrakEcliptic(), "pluto", [0.0]), ValueError, "expected"),
    (
        spin_axis_history,
        P(spin_axis_history, precession_rate=NAN),
        (VondrakEcliptic(), "earth", [0.0]),
        ValueError,
        "expected",
    ),
    (
        build_model,
        P(build_model, precession_rate=-HUGE),
        (VondrakEcliptic(), "earth", [0, 0.4, 0.9]),
        ValueError,
        "expected",
    ),
    (SpinAxisModel, SpinAxisModel, ("earth", NAN, 1.0, 0.01), ValueError, "expected a finite real"),
    (
        spin_axis_history,
        P(spin_axis_history, tolerance=0.0),
        (VondrakEcliptic(), "earth", [0.0, 100.0]),
        ValueError,
        "expected a positive finite tolerance",
    ),
    (
        spin_axis_history,
        P(spin_axis_history, tolerance=1e-20),
        (VondrakEcliptic(), "earth", [0.0, 100.0]),
        ValueError,
        "round-off",
    ),
    # -- physical parameters out of range (issue 26 item 4; the table andoyer.planetary.parameters)
    (check, check, ("tidal_dissipation", -5.0), ValueError, "expected a tidal dissipation 0 <= T_d <= 1.2"),
    (check, check, ("colour", 1.0), ValueError, "expected a parameter among"),
    (Parameter, PARAMETERS["eccentricity"].check, (1.0,), ValueError, "expected an eccentricity 0 <= e < 1"),
    (
        SpinAxisModel,
        P(SpinAxisModel.from_precession_rate, tidal_dissipation=1e6),
        ("earth", 50.3848, 0.4091),
        ValueError,
        "expected a tidal dissipation",
    ),
    (SpinAxisModel, SpinAxisModel.from_precession_rate, ("earth", 1e10, 0.4091), ValueError, "P < "),
    (SpinAxisModel, SpinAxisModel.from_precession_rate, ("mars", 7.6, 0.44, 1.5), ValueError, "eccentricity"),
    (SpinAxisModel, SpinAxisModel.from_dynamical_ellipticity, ("earth", 0.9), ValueError, "0 < H < 0.5"),
    (SpinAxisModel, MODEL_TIDES.check_span, (0.0, 1e10), ValueError, "within the linear tidal"),
    (
        spin_axis_history,
        P(spin_axis_history, tidal_dissipation=-5.0),
        (VondrakEcliptic(), "earth", [0.0]),
        ValueError,
        "expected a tidal dissipation",
    ),
    (
        spin_axis_history,
        P(spin_axis_history, ellipticity_drift=-1.0),
        (VondrakEcliptic(), "earth", [0.0, 100.0]),
        ValueError,
        "expected an ellipticity drift",
    ),
    (source_span, source_span, ("nowhere",), ValueError, "expected a named orbit source"),
    (source_span, source_span, ("vondrak", "mars"), ValueError, "expected body 'earth'"),
    (SpinAxisModel, SpinAxisModel, ("earth", 1e-4, 1.0, 1.5), ValueError, "expected"),
    (daily_insolation, daily_insolation, (NAN, 0.0, 0.4, 0.01, 1.0), ValueError, "expected finite"),
    (daily_insolation, daily_insolation, (1.0, 0.0, 0.4, 1.5, 1.0), ValueError, "expected"),
    (default_axis, default_axis, ("vulcan",), ValueError, "expected a body among"),
    (equinox, equinox, ([0.0, 0.0, 1.0], [0.0, 0.0, 1.0]), ValueError, "expected a spin axis off"),
    (equinox, equinox, ([NAN, 0.0, 1.0], [0.0, 0.0, 1.0]), ValueError, "expected finite"),
    (
        general_precession,
        general_precession,
        ([NAN, 0, 1], [0, 0, 1], [0, 1, 1], [0, 0, 1]),
        ValueError,
        "expected",
    ),
    (output_times, output_times, (0.0, 1.0, -1.0), ValueError, "expected a positive"),
    # -- their cost, known before the work (issue 26)
    (run_cost, run_cost, (VondrakEcliptic(), [NAN]), ValueError, "expected finite"),
    (run_cost, P(run_cost, step=INF), (VondrakEcliptic(), [0.0]), ValueError, "expected a positive finite"),
    (run_cost, run_cost, (VondrakEcliptic(), [1.0, 0.0]), ValueError, "expected increasing"),
    (
        andoyer.planetary.spin_axis.check_run,
        andoyer.planetary.spin_axis.check_run,
        (LaplaceLagrangeOrbit("earth"), [0.0, 1e15], "a test"),
        ValueError,
        "expected a test of at most about 3.6 hours",
    ),
    (spin_axis_blocks, spin_axis_blocks, (VondrakEcliptic(), "pluto", [0.0]), ValueError, "expected"),
    (spin_axis_blocks, P(spin_axis_blocks, rows=0), (VondrakEcliptic(), "earth", [0]), ValueError, "whole"),
    (nutation_cost, nutation_cost, ([NAN],), ValueError, "expected finite"),
    (nutation_cost, P(nutation_cost, method="x"), ([0.0],), ValueError, "expected method"),
    (output_times, output_times, (0.0, HUGE, 1e-300), ValueError, "expected"),
    # -- the Earth–Moon tides
    (ConstantTimeLag, ConstantTimeLag, (-1.0,), ValueError, "expected k2"),
    (ConstantTimeLag, ConstantTimeLag, (INF,), ValueError, "expected k2"),
    (ConstantPhaseLag, ConstantPhaseLag, (NAN,), ValueError, "expected"),
    (OceanTides, P(OceanTides, depth=NAN), (), ValueError, "expected a positive finite ocean depth"),
    (OceanTides, P(OceanTides, drag=HUGE), (), ValueError, "expected a depth up to"),
    (TidalResponse, OceanTides().lag, (3, 1e-4), ValueError, "expected a tidal order"),
    (TidalResponse, OceanTides().lag, (2, [NAN]), ValueError, "expected finite tidal frequencies"),
    (EarthMoonSystem, P(EarthMoonSystem, spin_rate=NAN), (), ValueError, "expected a finite real"),
    (EarthMoonSystem, P(EarthMoonSystem, j2=-HUGE), (), ValueError, "expected a second-degree zonal"),
    (tidal_history, tidal_history, ([NAN],), ValueError, "expected finite"),
    (tidal_history, tidal_history, ([-HUGE, 0.0],), ValueError, "expected times within"),
    (tidal_history, P(tidal_history, obliquity=HUGE), ([0.0],), ValueError, "expected an obliquity"),
    (tidal_history, tidal_history, ([-2e9, 0.0], "constant-lag"), ValueError, "Laplace-plane transition"),
    (tidal_model, tidal_model, ("darwin",), ValueError, "expected a tidal model"),
    (calibrate, P(calibrate, recession=NAN), (), ValueError, "expected a lunar recession"),
    (present_rates, present_rates, ("darwin",), ValueError, "expected a tidal model"),
    (TidalSpinAxisModel, TidalSpinAxisModel, ("earth", 1e-4, 2.0, 0.01), ValueError, "expected the tidal"),
    (tidal_spin_axis_model, tidal_spin_axis_model, (MODEL_EARTH, (NAN, 0.0)), ValueError, "expected finite"),
    (satellite_migration, satellite_migration, ("saturn", "titan", NAN), ValueError, "expected a finite"),
    (satellite_migration, satellite_migration, ("saturn", "titan", 0.4, INF), ValueError, "expected"),
    (satellite_migration, satellite_migration, ("saturn", "rhea"), ValueError, "expected a satellite of"),
    (SatelliteMigration, P(satellite_migration("saturn", "titan")), (MODEL_EARTH, (0.0, 1.0)), ValueError,
     "expected the model of Saturn from its figure"),
    (MigratingSpinAxisModel, MigratingSpinAxisModel, ("saturn", 1e-4, 0.0, 0.05), ValueError,
     "expected a SatelliteMigration"),
    (
        tidal_spin_axis_history,
        tidal_spin_axis_history,
        (VondrakEcliptic(), "earth", [HUGE]),
        ValueError,
        "expected",
    ),
    # -- Cassini states
    (CassiniBody, CassiniBody, ("x", NAN, 1e-5, 0.3, 1.0, 0.0, 0.1, -0.01), ValueError, "expected"),
    (CassiniBody, CassiniBody, ("x", 1e-4, 1e-5, 1.5, 1.0, 0.0, 0.1, -0.01), ValueError, "expected"),
    (CassiniBody, CassiniBody, ("x", 1e-4, 1e-5, 0.3, 1.0, 0.0, 1.6, -0.01), ValueError, "0 < i < 1.57"),
    (CassiniBody, CassiniBody, ("x", 1e-4, -1e-5, 0.3, 1.0, 0.0, 0.1, -0.01), ValueError, "C22 >= 0"),
    (ColomboTop, ColomboTop, (NAN, 0.0, -0.01, 0.1), ValueError, "expected finite"),
    (eccentricity_function, eccentricity_function, (1.5, 1.0), ValueError, "expected"),
    (
        andoyer.planetary.cassini.get,
        andoyer.planetary.cassini.get,
        ("vulcan",),
        ValueError,
        "expected a body",
    ),
    (andoyer.planetary.cassini.get, andoyer.planetary.cassini.get, ("triton",), ValueError, "to have j2"),
    (
        andoyer.planetary.cassini.states,
        andoyer.planetary.cassini.states,
        ("vulcan",),
        ValueError,
        "expected a body",
    ),
    (
        cassini_api.forced_obliquity,
        cassini_api.forced_obliquity,
        ("moon", "jpl"),
        ValueError,
        "expected node",
    ),
    (cassini_api.forced_obliquity, cassini_api.forced_obliquity, ("enceladus",), ValueError, "to have"),
    (
        cassini_api.satellite_system,
        cassini_api.satellite_system,
        ("mars",),
        ValueError,
        "expected satellites",
    ),
    (cassini_api.NodeMode, cassini_api.NodeMode, (0.1, 0.01), ValueError, "expected node_rate < 0"),
    (cassini_api.NodeMode, cassini_api.NodeMode, (-0.1, NAN), ValueError, "expected finite"),
    (
        cassini_api.ForcedObliquity,
        cassini_api.ForcedObliquity,
        ("moon", ()),
        ValueError,
        "expected a CassiniBody",
    ),
    (cassini_api.Satellite, cassini_api.Satellite, ("s", 1.0, -1.0, 1.0), ValueError, "expected gm >= 0"),
    (cassini_api.Satellite, cassini_api.Satellite, ("s", 1.0, INF, 1.0), ValueError, "expected a finite"),
    (
        cassini_api.SatelliteSystem,
        cassini_api.SatelliteSystem,
        (1.0, 1.0, NAN, 0.1, 1e-6, (cassini_api.Satellite("s", 0.0, 3.0, 0.2),)),
        ValueError,
        "expected finite",
    ),
    (
        cassini_api.moment_of_inertia_from_obliquity,
        cassini_api.moment_of_inertia_from_obliquity,
        ("titan", NAN),
        ValueError,
        "expected an observed obliquity",
    ),
    (
        cassini_api.moment_of_inertia_from_obliquity,
        cassini_api.moment_of_inertia_from_obliquity,
        ("titan", 0.005, HUGE),
        ValueError,
        "expected an obliquity error",
    ),
    # -- nutation
    (nutation, nutation, ([NAN],), ValueError, "expected finite"),
    (nutation, P(nutation, axis="x"), ([0.0],), ValueError, "expected axis"),
    (nutation_series, nutation_series, (-1.0,), ValueError, "expected a dynamical ellipticity"),
    (luni_solar_precession, luni_solar_precession, (NAN,), ValueError, "expected"),
    (minimum_span, minimum_span, ([[0, 0, 0, 0, NAN]],), ValueError, "expected finite"),
    (minimum_span, minimum_span, ([[0, 0, 0, 0, 0]],), ValueError, "expected terms with nonzero"),
    (numeric_terms, numeric_terms, ((0.0, 1.0),), ValueError, "expected a span of at least"),
    (terms_table, terms_table, ((0.0, HUGE),), ValueError, "expected times within"),
    (evolve_axes, evolve_axes, (VondrakEcliptic(), MODEL_EARTH, [NAN], [0, 0.4, 0.9]), ValueError, "finite"),
    (fit_terms, fit_terms, ([0.0, 1.0], [NAN, 1.0], [0.0, 1.0], [[0, 0, 0, 0, 1]]), ValueError, "expected"),
    # -- special functions
    (special.ellipk, special.ellipk, (NAN,), ValueError, "expected"),
    (special.ellipe, special.ellipe, (INF,), ValueError, "expected"),
    (special.ellipf, special.ellipf, (0.5, 2.0), ValueError, "expected"),
    (special.ellipeinc, special.ellipeinc, (NAN, 0.5), ValueError, "expected"),
    (special.ellippi, special.ellippi, (0.5, NAN), ValueError, "expected"),
    (special.ellippiinc, special.ellippiinc, (0.5, INF, 0.5), ValueError, "expected"),
    (special.ellipj, special.ellipj, (0.5, 1.5), ValueError, "expected"),
    (special.am, special.am, (NAN, 0.5), ValueError, "expected"),
    # -- series and theories
    (sam_theory, sam_theory, (0,), ValueError, "expected an integer order"),
    (sam_theory, sam_theory, (200,), ValueError, "would take about"),
    (sam_tables, sam_tables, (200,), ValueError, "would take about"),
    (sam_tables, sam_tables, (1.5,), ValueError, "expected an integer order"),
    (SAMRotation, SAMRotation, (BODY, 0), ValueError, "expected"),
    (SAMRotation, SAMRotation, (BODY, 4, "XAM"), ValueError, "expected"),
    (beta_polynomial_value, beta_polynomial_value, ((1, 2), NAN), ValueError, "expected"),
    # -- chaotic-obliquity members and statistics (issue 22 item 3)
    (perturbed_states, perturbed_states, (-1, 1e-6, np.random.default_rng(0)), ValueError, "expected a non"),
    (perturbed_states, perturbed_states, (2, NAN, np.random.default_rng(0)), ValueError, "perturbation size"),
    (perturbed_states, perturbed_states, (2, 0.5, np.random.default_rng(0)), ValueError, "perturbation size"),
    (member_times, member_times, (0.0, 1e3), ValueError, "expected a nonzero end"),
    (member_times, member_times, (-2e9, 1e3), ValueError, "expected a nonzero end"),
    (member_times, member_times, (-1e5, NAN), ValueError, "expected an output step"),
    (member_times, member_times, (-1e5, 2e5), ValueError, "expected an output step"),
    (member_times, member_times, (-1e9, 1e-3), ValueError, "at most 10 million"),
    (member_cost, member_cost, (10, -1e5, 1e4, -5.0), ValueError, "spin-axis step"),
    (
        member_obliquities,
        member_obliquities,
        ("pluto", -1e5, 1e4, np.zeros((1, 16)), AXIS),
        ValueError,
        "body",
    ),
    (
        member_obliquities,
        member_obliquities,
        ("mars", -1e5, 1e4, np.zeros((1, 15)), AXIS),
        ValueError,
        "shape",
    ),
    (
        member_obliquities,
        member_obliquities,
        ("mars", -1e5, 1e4, np.full((1, 16), NAN), AXIS),
        ValueError,
        "finite",
    ),
    (
        member_obliquities,
        P(member_obliquities, precession_rate=NAN),
        ("mars", -1e5, 1e4, np.zeros((1, 16)), AXIS),
        ValueError,
        "expected",
    ),
    (
        member_obliquities,
        P(member_obliquities, precession_rate=7.6, dynamical_ellipticity=0.005),
        ("mars", -1e5, 1e4, np.zeros((1, 16)), AXIS),
        ValueError,
        "got both",
    ),
    (
        member_obliquities,
        member_obliquities,
        ("mars", -1e5, 1e4, np.zeros((1, 16)), [0.0, 0.0, 0.0]),
        ValueError,
        "non-zero axis",
    ),
    (obliquity_statistics, obliquity_statistics, ([0.0, 1.0], np.zeros((2, 3))), ValueError, "shape"),
    (obliquity_statistics, obliquity_statistics, ([0.0, NAN], np.zeros((2, 2))), ValueError, "finite times"),
    (obliquity_statistics, obliquity_statistics, ([0.0], np.full((1, 1), INF)), ValueError, "finite obliq"),
    (
        obliquity_statistics,
        P(obliquity_statistics, bins=[1.0, 0.0]),
        ([0.0], np.zeros((1, 1))),
        ValueError,
        "bin",
    ),
    (
        obliquity_statistics,
        P(obliquity_statistics, thresholds=[NAN]),
        ([0.0], np.zeros((1, 1))),
        ValueError,
        "thresholds",
    ),
]

# Public names without bad numeric input of their own, and why.
EXEMPT = {
    # types, enums, named tuples and warnings: data holders built by the functions above
    "Symmetry": "an enum",
    "SingularChartWarning": "a warning class",
    "PhasePrecisionWarning": "a warning class",
    "NonPhysicalInertiaWarning": "a warning class",
    "OrbitHistory": "a protocol",
    "SpinAxisHistory": "a record of results",
    "MemberRun": "a record of results",
    "ObliquityStatistics": "a record of results (its to_dataset has no numeric input)",
    "TidalHistory": "a record of results",
    "NutationSeries": "a record of results",
    "CassiniState": "a record of results",
    "LaplaceModes": "a record of results (SatelliteSystem.modes, in the table)",
    "ModeResponse": "a record of results (ForcedObliquity.responses)",
    "MomentEstimate": "a record of results (moment_of_inertia_from_obliquity, in the table)",
    "NODE_SOURCES": "a constant",
    "mean_pole_j2000": "takes no argument",
    # constants of the applications
    "AXES": "a constant",
    "BODIES": "a constant",
    "DEFAULT_PRECESSION_RATE": "a constant",
    "EARTH_DYNAMICAL_ELLIPTICITY": "a constant",
    "MOMENT_SETS": "a constant",
    "EARTH_ROTATION": "a constant",
    "EPSILON_0": "a constant",
    "H_MHB2000": "a constant",
    "LUNAR_AGE": "a constant",
    "MEASURED_RECESSION": "a constant",
    "IAU2000A": "a constant table",
    "MEAN_OBLIQUITY": "a constant",
    "PRINCIPAL_TERMS": "a constant table",
    "REN2000": "a constant table",
    "REN2000_NODE": "a constant table",
    "SOURCES": "a constant",
    "SOLUTION_FORMATS": "a constant",
    "PARAMETERS": "a constant table (its entries' check is in the table)",
    "WOOLARD1953": "a constant table",
    "Regime": "an enum",
    "FreePeriods": "a named tuple of results",
    "Andoyer": "a named tuple of results",
    "Euler": "a named tuple of results",
    "AndoyerRates": "a named tuple of results",
    "EulerRates": "a named tuple of results",
    "Serret": "a named tuple of results",
    "BodyInfo": "a record of the named bodies",
    "Body": "a record of the catalogue; built and checked by body_from_dict and read_body (in the table)",
    "Quantity": "a record of the catalogue (value, unit, uncertainty, source)",
    "FIELDS": "a constant table",
    "UNITS": "a constant table",
    "ARCMIN": "a constant",
    "AU": "a constant",
    "AU_KM": "a constant",
    "DAY": "a constant",
    "DEGREE": "a constant",
    "GAUSSIAN_GRAVITATIONAL_CONSTANT": "a constant",
    "HOUR": "a constant",
    "J2000_JD": "a constant",
    "JULIAN_CENTURY": "a constant",
    "JULIAN_YEAR": "a constant",
    "MAS": "a constant",
    "SPEED_OF_LIGHT": "a constant",
    "PrecessionRates": "a record of results",
    "PrecessionConstant": "a record of results (precession_constant, in the table)",
    "SatelliteShare": "a record of results (precession_constant, in the table)",
    "SAMFrequencies": "a named tuple of results",
    "SAMTheory": "built by sam_theory (in the table)",
    "Orbit": "an abstract base class",
    "Perturbation": "an abstract base class",
    # constants
    "ARCSEC": "a constant",
    "NODE_PHASES": "a constant",
    "PLANETS": "a constant",
    "SAM_RING": "a constant ring of exact series",
    # no arguments, or names only
    "names": "takes no argument",
    "sam_hamiltonian": "takes no argument",
    # exact-rational series (the symbolic layer: input is series, not numbers)
    "CompiledSeries": "exact series, validated by tests/series",
    "LieTransform": "exact series, validated by tests/series",
    "PoissonRing": "exact series, validated by tests/series",
    "PoissonSeries": "exact series, validated by tests/series",
    "Term": "exact series, validated by tests/series",
    "average": "exact series, validated by tests/series",
    "deprit": "exact series, validated by tests/series",
    "derivative": "exact series, validated by tests/series",
    "frequencies": "exact series, validated by tests/series",
    "lie_sum": "exact series, validated by tests/series",
    "poisson_bracket": "exact series, validated by tests/series",
    "solve_homological": "exact series, validated by tests/series",
    "tables_from_json": "text of exact tables, validated by tests/theories/test_sam_tables.py",
    "tables_to_json": "text of exact tables, validated by tests/theories/test_sam_tables.py",
    # user-supplied callables: their input is the user's function
    "SumOfPerturbations": "a sum of perturbation objects",
    "TabulatedOrbit": "wraps a user function",
    "UserPotential": "wraps a user function",
    "UserTorque": "wraps a user function",
    # analytic tops built from a few scalars, checked by tests/integrate/reference/test_heavy_tops.py
    "kovalevskaya_top": "tests/integrate/reference/test_heavy_tops.py",
    "lagrange_top": "tests/integrate/reference/test_heavy_tops.py",
    "kovalevskaya_integral": "tests/integrate/reference/test_heavy_tops.py",
    "kovalevskaya_integral_e3": "tests/integrate/reference/test_heavy_tops.py",
    "andoyer_perturbed_equations": "tests/perturbations/test_perturbations.py",
    # the Lie–Poisson layer: symbolic brackets and tables, checked by tests/liepoisson
    "liepoisson": "the whole subpackage: symbolic algebra, validated by tests/liepoisson",
}


def _public_modules() -> list[types.ModuleType]:
    """``andoyer`` and the subpackages named in the ``__all__`` lists reached from it."""
    modules = [andoyer]
    index = 0
    while index < len(modules):  # the list grows as subpackages (andoyer.planetary's) are met
        module = modules[index]
        index += 1
        for name in module.__all__:
            obj = getattr(module, name)
            if isinstance(obj, types.ModuleType) and obj not in modules:
                if module is andoyer and name in EXEMPT:
                    continue
                modules.append(obj)
    return modules


def _public() -> dict[int, tuple[str, object]]:
    """Every public object: ``andoyer.__all__`` and its subpackages', ``andoyer.planetary``'s included."""
    found: dict[int, tuple[str, object]] = {}
    for module in _public_modules():
        for name in module.__all__:
            obj = getattr(module, name)
            if not isinstance(obj, types.ModuleType):
                found.setdefault(id(obj), (name, obj))
    return found


def _case_id(case) -> str:
    target, call, args = case[0], case[1], case[2]
    name = getattr(target, "__name__", type(target).__name__)
    inner = getattr(call, "func", call)
    return f"{name}.{getattr(inner, '__name__', '?')}({', '.join(map(_short, args))})"


def _short(value) -> str:
    if isinstance(value, np.ndarray):
        return f"array{value.shape}"
    text = repr(value)
    return text if len(text) < 20 else type(value).__name__


@pytest.mark.parametrize("case", CASES, ids=[_case_id(c) for c in CASES])
def test_api_bad_input_raises_expected(case):
    _, call, args, error, match = case
    with pytest.raises(error, match=match) as info:
        call(*args)
    assert "expected" in str(info.value)


def test_every_public_name_is_in_the_table_or_exempt():
    covered = {id(case[0]) for case in CASES}
    missing = sorted(
        name for key, (name, _) in _public().items() if key not in covered and name not in EXEMPT
    )
    assert missing == [], f"add bad-input cases (or an exemption with its reason) for {missing}"


def test_every_exemption_is_a_public_name():
    # By name, not by object: two public constants may be one float object (the catalogue's
    # value re-exported under two names), which _public() keeps once.
    public = set(andoyer.__all__)
    for module in _public_modules():
        public |= set(module.__all__)
    assert sorted(set(EXEMPT) - public) == []


def test_every_table_entry_targets_a_public_object():
    public = set(_public())
    strays = [_case_id(c) for c in CASES if id(c[0]) not in public]
    assert strays == []
    assert all(inspect.isclass(c[3]) and issubclass(c[3], (ValueError, TypeError)) for c in CASES)


@pytest.mark.parametrize(
    ("q", "m", "message"),
    [
        ([0.0, 0.0, 0.0, 2.0], [0.0, 0.0, 1.0], "expected unit quaternions"),
        ([0.0, 0.0, 0.0, np.nan], [0.0, 0.0, 1.0], "expected unit quaternions"),
        ([0.0, 0.0, 1.0], [0.0, 0.0, 1.0], "of one leading shape"),
        ([[0.0, 0.0, 0.0, 1.0]] * 2, [0.0, 0.0, 1.0], "of one leading shape"),
    ],
)
def test_state_from_unit_quaternion_bad_input_raises(q, m, message):
    """The no-copy constructor is public: non-unit, NaN or mismatched inputs get an error, not a state."""
    with pytest.raises(ValueError, match=message):
        State.from_unit_quaternion(np.array(q), np.array(m))
