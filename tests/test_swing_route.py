"""The student's route to a state on a circle (derive.solution.swing_route; issue 37): a pendulum, a rod or
disk on a pivot, a body in a bowl, on a dome or in a loop, by the conservation of energy from the start and
Newton's second law toward the center (F = 0 where it leaves the surface or the cord goes slack; no kinetic
energy where it stops), in at most eight equations, where the engine's two routes took 13 to 25. Each case cites the text whose route it follows and compares what the route
finds with the closed form the text prints (written here, not read back)."""
import pytest
import sympy as sp

from conftest import derived, run_derive, textbook, write_problem
from derive.core.errors import EngineLimit
from derive.language.problem import load
from derive.solution.answers import Solution
from derive.solution.textbook_routes import TextbookRoute

ENERGY, SPEED = "The speed, by the conservation of energy", "The rate of turning, by the conservation of energy"
NEWTON, TORQUE = "The forces, by Newton's second law toward the center", \
    "The angular acceleration, by the torque about the pivot"
LEAVES = "Where it leaves the surface, by Newton's second law toward the center and energy"
SLACK = "Where the cord goes slack, by Newton's second law toward the center and energy"
RISES = "How high it rises, by the conservation of energy"


def _s(name):
    return sp.Symbol(name, positive=True)


def _found(steps, name: str) -> sp.Expr:
    """The last value the route's steps give `name`."""
    return [e.rhs for step in steps for e in step.equations if str(e.lhs) == name][-1]


def _same(a, b) -> bool:
    return sp.simplify(a.xreplace({s: _s(s.name) for s in a.free_symbols}) - b) == 0


m, M, g, L, R, r, v0 = (_s(n) for n in ("m", "M", "g", "L", "R", "r", "v0"))

#: (problem, its sections, {a symbol the route finds: the text's closed form}, the equations in all)
CASES = [
    # Serway & Jewett 9th ed., Example 10.11 (a rod pivoted at one end released from the horizontal: omega =
    # sqrt(3 g/L) at the lowest position); the pivot's pull there F - M g = M omega^2 L/2, 5 M g/2.
    ("rod_swings_down", [SPEED, NEWTON, TORQUE],
     {"omega": sp.sqrt(3 * g / L), "v": sp.sqrt(3 * g * L) / 2, "F": 5 * M * g / 2, "alpha": 0}, 8),
    # Halliday, Resnick & Walker 10th ed., ch. 8 and 6 (energy from the lowest point, v^2 = v0^2 - 2 g L where the
    # cord is horizontal; the cord's pull the centripetal force there, T = m v^2/L).
    ("bob_given_speed", [ENERGY, NEWTON],
     {"v": sp.sqrt(v0**2 - 2 * g * L), "T": m * (v0**2 - 2 * g * L) / L, "T0": m * (v0**2 + g * L) / L}, 6),
    # Serway & Jewett 9th ed., ch. 10 (released theta0 below the horizontal: alpha = 3 g cos(theta0)/(2 L),
    # omega = sqrt(3 g (1 - sin(theta0))/L) hanging vertically).
    ("rod_released_below_swings", [SPEED, TORQUE],
     {"alpha": 3 * g * sp.cos(_s("theta0")) / (2 * L), "omega": sp.sqrt(3 * g * (1 - sp.sin(_s("theta0"))) / L)}, 5),
    # Serway & Jewett 9th ed., ch. 8 problems (released at the rim of a smooth bowl: v = sqrt(2 g R), N = 3 m g).
    ("block_in_bowl", [ENERGY, NEWTON], {"v": sp.sqrt(2 * g * R), "N": 3 * m * g}, 4),
    # Serway & Jewett 9th ed., ch. 10 problems (a disk pivoted at its rim, its center level with the pivot:
    # omega = sqrt(4 g/(3 R)) at the lowest position, I_P = 3 M R^2/2); the pivot's pull 7 M g/3.
    ("disk_rim_swing", [SPEED, NEWTON], {"omega": sp.sqrt(4 * g / (3 * R)), "F": 7 * M * g / 3}, 7),
    # Kleppner & Kolenkow 2nd ed., ch. 5 (a particle leaves a smooth hemisphere where cos(phi) = 2/3 + v0^2/(3 g R)).
    ("bead_off_dome", [LEAVES], {"h": (2 * g * R + v0**2) / (3 * g), "v": sp.sqrt((2 * g * R + v0**2) / 3)}, 5),
    # Serway & Jewett ch. 10 (a solid ball rolling in a loop leaves where v^2 = g y: y = (7 v0^2 - 10 g (R - r))/(17 g)).
    ("ball_leaves_loop", [LEAVES],
     {"y": (7 * v0**2 - 10 * g * (R - r)) / (17 * g), "omega": sp.sqrt((7 * v0**2 - 10 * g * (R - r)) / 17) / r}, 8),
    # Morin ch. 8; Kleppner & Kolenkow 2nd ed., ch. 7 (a solid ball rolling off a sphere: cos(phi) = (10 + 7 v0^2/(g (R
    # + r)))/17).
    ("ball_rolls_off_dome", [LEAVES],
     {"h": (10 * g * (R + r) + 7 * v0**2) / (17 * g), "omega": sp.sqrt((10 * g * (R + r) + 7 * v0**2) / 17) / r}, 8),
    # Kleppner & Kolenkow 2nd ed., ch. 4/5 (a mass on a string given v0 at the bottom goes slack where T = 0, at
    # (v0^2 - 2 g L)/(3 g) above the center, at sqrt((v0^2 - 2 g L)/3)).
    ("ball_circle_slack", [SLACK], {"h": (v0**2 - 2 * g * L) / (3 * g), "v": sp.sqrt((v0**2 - 2 * g * L) / 3)}, 5),
    # Serway & Jewett ch. 10 and 6 (a solid ball rolling in a bowl at v0 rises h with (7/10) m v0^2 = m g h; at the
    # bottom N - m g = m v0^2/(R - r)), its height from the bowl's center y = h - (Rb - r).
    ("ball_rolls_up_bowl", [RISES, NEWTON],
     {"y": 7 * v0**2 / (10 * g) - (_s("Rb") - r), "N": m * g + m * v0**2 / (_s("Rb") - r)}, 6),
    # Serway & Jewett 9th ed., ch. 8 (a particle nudged from the top of a smooth hemisphere leaves 2R/3 above its
    # center, at sqrt(2 g R/3)).
    ("particle_off_dome_nudged", [LEAVES], {"h": 2 * R / 3, "v": sp.sqrt(2 * g * R / 3)}, 5),
]

#: Textbook setups this route was not designed around (tests/textbook), each with the closed form its text prints.
NEW = [
    # Serway & Jewett 9th ed., ch. 8 (a pendulum released from rest at theta_A: v_B = sqrt(2 g L (1 - cos theta_A)),
    # T_B = m g (3 - 2 cos theta_A)).
    ("pendulum_tension_at_bottom", [ENERGY, NEWTON],
     {"vB": sp.sqrt(2 * g * L * (1 - sp.cos(_s("thetaA")))), "TB": m * g * (3 - 2 * sp.cos(_s("thetaA")))}, 4),
    # Halliday, Resnick & Walker 10th ed., ch. 10 (a rod pivoted at one end, released from the horizontal: omega =
    # sqrt(3 g/L) at the bottom; alpha = 3 g/(2 L) at release), here pivoted at its right end.
    ("meter_stick_pivoted_at_end", [SPEED, TORQUE],
     {"w": sp.sqrt(3 * g / L), "vc": sp.sqrt(3 * g * L) / 2, "alpha0": 3 * g / (2 * L)}, 7),
    # Serway & Jewett 9th ed., ch. 6 and 8 (a ball on a cord round a vertical circle: at the top T + m g = m v^2/R,
    # v^2 = v0^2 - 4 g R), through a state at the side on the way that energy does not need.
    ("ball_whirled_vertical_circle", [ENERGY, NEWTON],
     {"vt": sp.sqrt(v0**2 - 4 * g * R), "Tt": m * (v0**2 - 5 * g * R) / R, "Tb": m * (v0**2 + g * R) / R}, 6),
]


def _file(name: str):
    return textbook(name)


@pytest.mark.parametrize("name, sections, closed, equations", CASES + NEW, ids=[c[0] for c in CASES + NEW])
def test_a_state_on_a_circle_takes_energy_and_newton_toward_the_center(name, sections, closed, equations):
    solution = derived(_file(name))
    route = solution.textbook_route
    assert isinstance(route, TextbookRoute) and route.principle.startswith("the conservation of energy and Newton")
    steps = solution.student_steps
    assert list(steps) == sections
    shown = [step for title in sections for step in steps[title]]
    for symbol, form in closed.items():
        assert _same(_found(shown, symbol), form), symbol
    assert sum(len(step.equations) for step in shown) == equations <= 8
    assert {what for what, _, _ in route.compared} == set(solution.problem.asks)  # every finding beside the key's
    words = set(" ".join(step.text for step in shown).replace(",", " ").replace(":", " ").replace("'s", "").split())
    assert not set(solution.scene.bodies) & words  # no body's key in the student's words ("it", "its center")


def test_the_leaving_height_is_newton_with_no_push_and_energy():
    """Kleppner & Kolenkow ch. 5: m g cos(phi) - N = m v^2/R toward the center, N = 0 where it leaves: v^2 = g h
    with h = R cos(phi); the energy from the top then gives h."""
    (steps,) = derived(_file("bead_off_dome")).student_steps.values()
    newton, leaves = steps[0].equations[0], steps[1].equations[0]
    N, v, h = _s("N"), _s("v"), _s("h")
    assert _same(newton.lhs - newton.rhs, m * g * h / R - N - m * v**2 / R)  # the push, away from the center
    assert _same(leaves.lhs - leaves.rhs, v**2 - g * h)


def test_the_new_route_agrees_with_both_engine_routes_in_derive_check():
    """`derive check` (its simulations too) of one problem for each holder: a pivot, a cord, a surface. Every
    textbook file's checks, textbook_route among them, pass in tests/test_textbook.py, and its states are
    simulated in tests/test_chain_simulation.py."""
    files = [str(_file(name)) for name in ("rod_swings_down", "bob_given_speed", "block_in_bowl")]
    done = run_derive("check", *files)
    assert done.returncode == 0, done.stderr
    assert done.stdout.count("textbook_route") == len(files)


def test_derive_solve_prints_the_route_first():
    done = run_derive("solve", "block_in_bowl")
    assert done.returncode == 0, done.stderr
    assert "The solution, as a textbook writes it" in done.stdout and "Equations of motion" not in done.stdout
    assert "The speed, by the conservation of energy" in done.stdout and "[ok] textbook_route" in done.stdout


RELEASED = """
id: pendulum_tension_at_release
title: A pendulum's cord at its release and at the bottom
parameters:
  m: {meaning: mass, unit: kg, range: [0.1, 2]}
  L: {meaning: length, unit: m, range: [0.5, 2]}
  theta0: {meaning: angle of release from the vertical, unit: rad, range: [0.2, 1.2]}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  points:
    hook: [0, 0]
  bodies:
    bob: {shape: point, mass: m, at: [L*sin(theta0), -L*cos(theta0)]}
  cords:
    cord: [hook, bob]
  loads:
    - gravity: g
  states:
    bottom: {when: {bob.x: 0}}
ask:
  T0: {meaning: tension at release, of: cord.tension, unit: N}
  v: {meaning: speed at the bottom, of: bob.speed, in: bottom, unit: m/s}
question: A pendulum is released.
"""


def test_the_cords_pull_at_the_release_balances_the_weights_component(tmp_path):
    """Serway & Jewett 9th ed., ch. 8 (the pendulum at its release, at rest: T_A = m g cos(theta_A), no centripetal
    acceleration yet)."""
    solution = Solution(load(write_problem(tmp_path, RELEASED)))
    steps = solution.student_steps[NEWTON]
    theta0 = _s("theta0")
    assert "at the release" in steps[0].text and "balance, at rest" in steps[0].text
    assert _same(_found(steps, "T0"), m * g * sp.cos(theta0))
    assert _same(_found(solution.student_steps[ENERGY], "v"), sp.sqrt(2 * g * L * (1 - sp.cos(theta0))))


ACROSS = """
id: rod_hinge_across
title: A rod swings down; the pivot's force across the rod at the bottom
parameters:
  M: {meaning: mass, unit: kg, range: [0.5, 3]}
  L: {meaning: length, unit: m, range: [0.5, 2]}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  bodies:
    rod: {shape: rod, mass: M, length: L, at: [L/2, 0], angle: 0}
  joints:
    hinge: {pin: rod.start}
  loads:
    - gravity: g
  states:
    lowest: {when: {rod.angle: -pi/2}}
ask:
  omega: {meaning: angular velocity there, of: rod.angular_velocity, in: lowest, unit: rad/s}
  Fx: {meaning: horizontal force of the hinge there, of: hinge.reaction.x, in: lowest, unit: N}
question: A rod swings down.
"""

ROUGH_BOWL = """
id: rough_bowl
title: A block slides down a rough bowl
parameters:
  m: {meaning: mass, unit: kg, range: [0.1, 1]}
  R: {meaning: radius, unit: m, range: [0.1, 1]}
  mu: {meaning: coefficient of kinetic friction, unit: '1', range: [0.1, 0.2]}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  surfaces:
    bowl: {circle: {radius: R, center: [0, 0], side: inside}}
  bodies:
    bead: {shape: point, mass: m, at: [R, 0], on: bowl, contact: sliding, friction: {kinetic: mu}}
  loads:
    - gravity: g
  states:
    bottom: {when: {bead.x: 0}}
ask:
  v: {meaning: speed at the bottom, of: bead.speed, in: bottom, unit: m/s}
question: A block slides down a rough bowl.
"""


def test_what_the_route_does_not_prove_keeps_the_engines_routes(tmp_path):
    """A time along the swing (an elliptic integral) and friction that takes energy on the way: no swing
    route (a force across the radius is found with the angular acceleration: it is taken)."""
    assert not isinstance(Solution(load("pendulum_bob_released")).textbook_route, TextbookRoute)
    across = Solution(load(write_problem(tmp_path, ACROSS)))  # the force along the tangent: by the torque, below
    assert isinstance(across.textbook_route, TextbookRoute) and across.expression("Fx") == 0
    (tmp_path / "rough").mkdir()
    rough = Solution(load(write_problem(tmp_path / "rough", ROUGH_BOWL)))
    with pytest.raises(EngineLimit, match="cannot yet decide whether the bead slips"):
        rough.textbook_route  # friction on a curve: the engine's own refusal, never a route of energy conserved


def test_a_force_along_the_tangent_comes_from_the_torque_about_the_pivot():
    """A chimney (a rod on a hinge) falling from upright to the level (Serway & Jewett ch. 10): the hinge's
    vertical force is along the tangent there; the route finds the angular acceleration by the torque about the
    pivot and Newton's second law along the tangent, M g/4 up, as the book prints."""
    solution = derived(textbook("falling_chimney_rod"))
    steps = [step for section in solution.student_steps.values() for step in section]
    tangent = next(step for step in steps if step.text.startswith("Newton's second law along the tangent, up"))
    M, g = (solution.problem.parameters[n].symbol for n in ("M", "g"))
    assert sp.simplify(tangent.equations[-1].rhs - M * g / 4) == 0
    assert sum(len(step.equations) for step in steps) == 11  # the speed, then each force: five steps of the book's
