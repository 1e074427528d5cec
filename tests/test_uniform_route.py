"""The student's route between two states at constant acceleration (derive.solution.uniform_route;
issue 37, item 1): Newton's second law along the motion and the torques give a (or alpha), then the
kinematics of constant acceleration take the motion to where it stops or to the state asked, in the
coordinate along the motion; no x and y components. Each case cites the text whose route it follows,
checks the principle of each step and the number of equations, and compares what the route finds with
the closed form the text prints (written here, not read back)."""
import re

import pytest
import sympy as sp

from conftest import ROOT, derived
from derive.solution.answers import Solution
from derive.language.problem import load
from derive.solution.textbook_routes import TextbookRoute

SECTIONS = ["Forces and torques along the motion", "The motion at constant acceleration"]


def _s(name):
    return sp.Symbol(name, positive=True)


def _found(steps, name: str) -> sp.Expr:
    """The last value the route's steps give `name`."""
    return [e.rhs for step in steps for e in step.equations if str(e.lhs) == name][-1]


def _same(a, b) -> bool:
    return sp.simplify(a.xreplace({s: _s(s.name) for s in a.free_symbols}) - b) == 0


def _opening(steps) -> list[str]:
    """Each step's principle, by the words it opens with."""
    kinds = {"Newton's second law": "newton", "Torque about": "torque", "Solving": "solve",
             "starts from rest": "kinematics", "starts moving": "kinematics", "starts turning": "kinematics",
             "It stops where": "stops", "Where the state is reached": "reached", "rate of turning follows": "rolling",
             "number of turns": "turns", "rolls without slipping": "ties", "neither stretches": "ties"}
    return [next((k for words, k in kinds.items() if words in step.text), step.text) for step in steps]


#: (file, the principles of its two sections, {a symbol the route finds: the text's closed form}, the equations)
CASES = [
    # Halliday, Resnick & Walker 10th ed., ch. 11 (a solid cylinder rolling up a ramp at v0 stops after
    # d = 3 v0^2/(4 g sin(theta))): the slope's Newton and torque, then it slows at a = 2 g sin(theta)/3.
    ("disk_rolls_up_incline", (["newton", "ties", "solve"], ["kinematics", "stops"]),
     {"a": lambda: 2 * _s("g") * sp.sin(_s("theta")) / 3, "d": lambda: 3 * _s("v0")**2 / (4 * _s("g") * sp.sin(_s("theta")))},
     7),
    # Serway & Jewett 9th ed., ch. 10 (a solid sphere rolling from rest down a slope of height h:
    # a = 5 g sin(theta)/7, v = sqrt(10 g h/7), omega = v/R).
    ("sphere_rolls_down", (["newton", "ties", "solve"], ["kinematics", "reached", "rolling"]),
     {"a": lambda: 5 * _s("g") * sp.sin(_s("theta")) / 7, "v": lambda: sp.sqrt(10 * _s("g") * _s("h") / 7),
      "omega": lambda: sp.sqrt(10 * _s("g") * _s("h") / 7) / _s("R")}, 12),
    # Halliday, Resnick & Walker 10th ed., ch. 11 (a yo-yo falling on its string): a = 2g/3, T = Mg/3; from rest
    # v = sqrt(2 a h).
    ("yoyo_falls", (["newton", "ties", "solve"], ["kinematics", "reached"]),
     {"a": lambda: 2 * _s("g") / 3, "T": lambda: _s("M") * _s("g") / 3, "v": lambda: sp.sqrt(4 * _s("g") * _s("h") / 3)},
     10),
    # Serway & Jewett 9th ed., ch. 10 (an Atwood machine with a massive pulley, I = M R^2/2, released from
    # rest: v = sqrt(2 (m1 - m2) g h/(m1 + m2 + I/R^2)) after a fall h).
    ("atwood_pulley_speed", (["torque", "newton", "newton", "ties", "solve"], ["kinematics", "reached", "rolling"]),
     {"v": lambda: sp.sqrt(2 * (_s("m1") - _s("m2")) * _s("g") * _s("h") / (_s("m1") + _s("m2") + _s("M") / 2))}, 13),
    # Serway & Jewett 9th ed., ch. 10 (a rigid body under constant angular acceleration): a grindstone slowed by a
    # constant friction torque turns through I w0^2/(2 tau) before it stops, after t = I w0/tau.
    ("grindstone_slowed_by_friction", (["torque", "solve"], ["kinematics", "stops", "turns"]),
     {"alpha": lambda: 2 * _s("tau") / (_s("M") * _s("R")**2),
      "t": lambda: _s("M") * _s("R")**2 * _s("w0") / (2 * _s("tau")),
      "n": lambda: _s("M") * _s("R")**2 * _s("w0")**2 / (8 * sp.pi * _s("tau"))}, 8),
]


#: Where each case's file is: a library problem by its id, else a file of the tests.
FILES = {"disk_rolls_up_incline": ROOT / "tests" / "asks" / "disk_rolls_up_incline.yaml",
         "grindstone_slowed_by_friction": ROOT / "tests" / "textbook" / "grindstone_slowed_by_friction.yaml"}


@pytest.mark.parametrize("name, principles, closed, equations", CASES, ids=[c[0] for c in CASES])
def test_a_motion_between_two_states_at_constant_acceleration_takes_the_textbooks_route(name, principles, closed,
                                                                                         equations):
    solution = derived(FILES.get(name, name))
    route = solution.textbook_route
    assert isinstance(route, TextbookRoute) and route.along is not None
    sections = solution.student_steps
    assert list(sections) == SECTIONS
    assert [_opening(sections[title]) for title in SECTIONS] == list(principles)
    steps = [step for title in SECTIONS for step in sections[title]]
    for symbol, form in closed.items():
        assert _same(_found(steps, symbol), form()), symbol
    assert sum(len(step.equations) for step in steps) == equations
    shown = {str(s) for step in steps for e in step.equations for s in e.free_symbols}
    assert not shown & {"x", "y"} and not any(s.startswith(("xdot", "ydot", "x_", "y_")) for s in shown)
    assert [c for c in solution.checks() if c.name == "textbook_route"][0].passed  # beside both engine routes


def test_a_result_read_from_the_kinematics_cites_no_equation_it_does_not_solve():
    """The sphere's rate of turning, omega = v/R, follows from the speed found and the rolling: the worked
    solution no longer says it comes "from (6)-(7)", the kinematics' two equations, while the solving of
    those still cites them."""
    from conftest import student_solution

    tex, student = student_solution("sphere_rolls_down")
    assert student and re.search(r"Where the state is reached, from \(\d+\)", tex), tex
    assert re.search(r"as the constraints tie them:", tex) and "tie them, from" not in tex


def test_a_motion_whose_acceleration_changes_keeps_the_engines_routes():
    """A pendulum released from the horizontal speeds up at a rate that changes with its angle: no
    kinematics of constant acceleration (v^2 - v_0^2 = 2 a d fails at points of the ranges)."""
    solution = Solution(load("rod_swings_down"))
    assert not isinstance(solution.textbook_route, TextbookRoute) or solution.textbook_route.along is None


def test_a_motion_with_kinetic_friction_or_an_inverse_ask_is_not_taken_by_the_kinematics():
    """Friction that may slip (three regimes), and an ask solved back for a parameter, stay with the engine."""
    for problem_id in ("puck_slides_to_stop", "rough_table_hanging_ball"):
        route = Solution(load(problem_id)).textbook_route
        assert not isinstance(route, TextbookRoute) or route.along is None, problem_id
