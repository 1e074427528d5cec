"""The kinds moved onto the protocol of derive.quantities (issue 38): each module claims its own paths,
with the reader's one-line refusals, and says where its answers come from and how they are checked."""
import pytest
import sympy as sp

from derive import quantities
from derive.language.problem import load
from derive.mechanics.derivation import Solved
from derive.model.scene import DYNAMIC_KINDS, RATE_KINDS, STATE_KINDS, STATIC_KINDS, Quantity
from derive.quantities.by_routes import ByRoutes
from derive.solution.answers import Solution


@pytest.mark.parametrize("problem, path, expected", [
    ("kepler_orbit", "orbit.period", Quantity("orbit", None, "period")),
    ("diatomic_molecule", "system.reduced_mass", Quantity("system", None, "reduced_mass")),
    ("diatomic_molecule", "atom1.mass", Quantity("mass", "atom1", None)),
    ("disk_tilted_on_shaft", "disk.mass", Quantity("mass", "disk", None)),
    ("disk_tilted_on_shaft", "disk.bearings.force", Quantity("bearings", "disk", "bearings.force")),
    ("tilting_wheel", "wheel.turn.axle", Quantity("angular_impulse", "wheel", "turn.axle")),
    ("top_precession_exact", "top.nutation.frequency", Quantity("pivot_point", "top", "nutation.frequency")),
    ("tennis_racket", "book.rotation.greatest.wobble", Quantity("free_rotation", "book", "rotation.greatest.wobble")),
    ("rolling_kinetic_energy", "wheel.rolling.kinetic_energy", Quantity("rolling", "wheel", "kinetic_energy")),
    ("angular_momentum_quantization", "standing_wave.momentum", Quantity("standing_wave", None, "momentum")),
    ("circular_motion_L", "particle.acceleration.radial", Quantity("path", "particle", "acceleration.radial")),
    ("circular_motion_L", "particle.torque.z", Quantity("particle_torque", "particle", "torque.z")),
])
def test_a_module_claims_its_paths(problem, path, expected):
    assert quantities.parse(load(problem).scene, path) == expected


@pytest.mark.parametrize("problem, path, words", [
    ("kepler_orbit", "orbit.speed", "an orbit has circular_radius"),
    ("rod_endpoint", "orbit.period", "the scene has no orbit"),
    ("rod_endpoint", "system.reduced_mass", "a reduced mass is for a system of two bodies"),
    ("tennis_racket", "book.rotation.intermediate.wobble", "unstable (the tennis-racket theorem)"),
    ("disk_tilted_on_shaft", "disk.bearings.torqe.x", "did you mean"),
    ("rolling_kinetic_energy", "wheel.rolling.speed", "a rolling body has rolling.angular_velocity"),
    ("circular_motion_L", "particle.inertia", "a body on a path has"),
    ("circular_motion_L", "particle.torque", "the torque on a body on a path is a vector: ask particle.torque.x"),
    ("circular_motion_L", "particle.weight.torque.z", "the particle bears no force 'weight' (no gravity)"),
])
def test_a_module_refuses_a_path_of_its_kind_that_names_nothing(problem, path, words):
    with pytest.raises(ValueError, match=words.replace("(", r"\(").replace(")", r"\)")):
        quantities.parse(load(problem).scene, path)


def test_a_kind_whose_unit_depends_on_the_ask_leaves_the_dimension_to_the_answer():
    """An orbit's period and energy have different units: the kind has none; a torque has one."""
    assert quantities.KINDS["orbit"].unit is None and quantities.KINDS["internal_forces"].unit == "N*m"
    assert quantities.directional(Quantity("rolling", "wheel", "angular_velocity"))
    assert not quantities.directional(Quantity("rolling", "wheel", "kinetic_energy"))


def test_every_kind_of_the_equations_of_motion_is_a_module_read_from_both_routes():
    """Every kind a problem can ask is a module's (issue 38: no kind answered outside the protocol), and
    those of the equations of motion are exactly the ones the routes check compares."""
    assert STATIC_KINDS | DYNAMIC_KINDS | STATE_KINDS | RATE_KINDS <= set(quantities.KINDS)
    assert {kind for kind, module in quantities.KINDS.items() if isinstance(module, ByRoutes)} == DYNAMIC_KINDS
    assert not hasattr(Solution, "_route_expression")


def test_a_route_based_kind_reads_each_routes_own_solve(monkeypatch):
    """Route 1 is Newton–Euler's solve, not Lagrange's again: a Newton–Euler solve made wrong changes route
    1's tension and not route 0's (the key's)."""
    solution = Solution(load("string_wrapped_disk"))
    ask = solution.problem.asks["T"]
    right = [quantities.KINDS["force"].value(solution, ask, route) for route in (0, 1)]
    in_state = Solution.in_state

    def wrong(self, route, name):
        solved = in_state(self, route, name)
        return Solved({u: 2 * v for u, v in solved.raw.items()}) if route == "newton_euler" else solved
    monkeypatch.setattr(Solution, "in_state", wrong)
    assert quantities.KINDS["force"].value(solution, ask, 0) == right[0]
    assert sp.simplify(quantities.KINDS["force"].value(solution, ask, 1) - 2 * right[1]) == 0


def test_the_worked_solution_solves_for_what_the_asks_are_made_of():
    """`unknowns`: a body rolling down an incline is asked its acceleration along it, its friction and the
    least coefficient that holds it, so the solve is for its accelerations, normal force and friction."""
    solution = Solution(load("rolling_incline"))
    forces = solution.dynamics_scene.contact_of("ball").unknowns()
    accelerations = {solution.coordinates.of("ball", k).a for k in ("x", "y")}
    assert solution._needed_unknowns() == accelerations | {forces["normal"], forces["friction"]}
    assert quantities.KINDS["contact"].student_route(Quantity("contact", "ball", "speed_at_bottom"))
    assert not quantities.KINDS["contact"].student_route(Quantity("contact", "ball", "min_release_height"))
    assert quantities.KINDS["force"].student_route(Quantity("force", "rope", "tension"))


def test_a_small_oscillation_adds_its_linearization_to_each_routes_steps_once():
    solution = Solution(load("compound_pendulum"))
    kind = quantities.KINDS["small_oscillation"]
    asks = [a for a in solution.problem.asks.values() if a.quantity.kind == "small_oscillation"]
    assert len(asks) >= 1
    for route in ("lagrange", "newton_euler"):
        added = kind.route_steps(solution, asks, route)
        assert added and added == list(solution.linearized[route].steps)
        assert solution.steps()[route][-len(added):] == added
