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

FORCES, UNIFORM = "Forces and torques along the motion", "The motion at constant acceleration"
BY_ENERGY, TIMED = "The speed by energy", "The speed by energy, the time at constant acceleration"


def _s(name):
    return sp.Symbol(name, positive=True)


def _found(steps, name: str, solution) -> sp.Expr:
    """The last value the route's steps give `name` in the problem's parameters alone."""
    given = {str(p.symbol) for p in solution.problem.parameters.values()}
    return [e.rhs for step in steps for e in step.equations
            if str(e.lhs) == name and {str(s) for s in e.rhs.free_symbols} <= given][-1]


def _same(a, b) -> bool:
    return sp.simplify(a.xreplace({s: _s(s.name) for s in a.free_symbols}) - b) == 0


def _opening(steps) -> list[str]:
    """Each step's principle, by the words it opens with."""
    kinds = {"the time it takes": "time", "Newton's second law": "newton", "Torque about": "torque", "Solving": "solve",
             "grips or slips": "regime", "is sent sliding": "sent", "Across its motion": "across",
             "work–energy theorem": "energy", "starts from rest": "kinematics", "starts moving": "kinematics",
             "starts turning": "kinematics", "It stops where": "stops", "Where the state is reached": "reached",
             "rate of turning follows": "rolling", "number of turns": "turns", "rolls without slipping": "ties",
             "neither stretches": "ties", "Kinetic friction on": "friction", "kinetic energy there follows": "kinetic",
             "there follows from the way": "component", "moves in proportion": "proportion"}
    return [next((k for words, k in kinds.items() if words in step.text), step.text) for step in steps]


def _g_sin_mu_cos(s, sign=-1):
    """g (sin(theta) - mu cos(theta)) down a rough incline, g (sin(theta) + mu cos(theta)) sliding up it (Serway &
    Jewett 9th ed., ch. 5)."""
    return s("g") * (sp.sin(s("theta")) + sign * s("mu") * sp.cos(s("theta")))


#: (file, {section: the principles of its steps}, {a symbol the route finds: the text's closed form}, the equations)
CASES = [
    # Halliday, Resnick & Walker 10th ed., ch. 11 (a solid cylinder rolling up a ramp at v0 stops after
    # d = 3 v0^2/(4 g sin(theta))): the slope's Newton and torque, then it slows at a = 2 g sin(theta)/3.
    ("disk_rolls_up_incline", {FORCES: ["newton", "ties", "solve"], UNIFORM: ["kinematics", "stops"]},
     {"a": lambda: 2 * _s("g") * sp.sin(_s("theta")) / 3, "d": lambda: 3 * _s("v0")**2 / (4 * _s("g") * sp.sin(_s("theta")))},
     7),
    # Serway & Jewett 9th ed., ch. 10 (a solid sphere rolling from rest down a slope of height h: by energy,
    # M v^2/2 + I omega^2/2 = M g h with omega = v/R gives v = sqrt(10 g h/7); a = 5 g sin(theta)/7 for the time).
    ("sphere_rolls_down", {FORCES: ["newton", "ties", "solve"], TIMED: ["energy", "reached", "time", "rolling"]},
     {"a": lambda: 5 * _s("g") * sp.sin(_s("theta")) / 7, "v": lambda: sp.sqrt(10 * _s("g") * _s("h") / 7),
      "omega": lambda: sp.sqrt(10 * _s("g") * _s("h") / 7) / _s("R")}, 12),
    # Halliday, Resnick & Walker 10th ed., ch. 11 (a yo-yo falling on its string): a = 2g/3, T = Mg/3; by energy
    # from rest v = sqrt(4 g h/3).
    ("yoyo_falls", {FORCES: ["newton", "ties", "solve"], TIMED: ["energy", "reached", "time"]},
     {"a": lambda: 2 * _s("g") / 3, "T": lambda: _s("M") * _s("g") / 3, "v": lambda: sp.sqrt(4 * _s("g") * _s("h") / 3)},
     11),
    # Serway & Jewett 9th ed., ch. 10 (an Atwood machine with a massive pulley, I = M R^2/2, released from
    # rest: v = sqrt(2 (m1 - m2) g h/(m1 + m2 + I/R^2)) after a fall h). Two blocks and a pulley: no one body's
    # work-energy step, the kinematics of constant acceleration.
    ("atwood_pulley_speed", {FORCES: ["torque", "newton", "newton", "ties", "solve"],
                             UNIFORM: ["kinematics", "reached", "rolling"]},
     {"v": lambda: sp.sqrt(2 * (_s("m1") - _s("m2")) * _s("g") * _s("h") / (_s("m1") + _s("m2") + _s("M") / 2))}, 13),
    # Serway & Jewett 9th ed., ch. 10 (a rigid body under constant angular acceleration): a grindstone slowed by a
    # constant friction torque turns through I w0^2/(2 tau) before it stops, after t = I w0/tau.
    ("grindstone_slowed_by_friction", {FORCES: ["torque", "solve"], UNIFORM: ["kinematics", "stops", "turns"]},
     {"alpha": lambda: 2 * _s("tau") / (_s("M") * _s("R")**2),
      "t": lambda: _s("M") * _s("R")**2 * _s("w0") / (2 * _s("tau")),
      "n": lambda: _s("M") * _s("R")**2 * _s("w0")**2 / (8 * sp.pi * _s("tau"))}, 8),
    # Halliday, Resnick & Walker 10th ed., ch. 6 and Serway & Jewett 9th ed., ch. 5 (a block sliding down a rough
    # incline): N = m g cos(theta), a = g (sin(theta) - mu_k cos(theta)); the ranges prove it slips at every value.
    ("block_incline_kinetic", {FORCES: ["regime", "newton", "across", "solve"]},
     {"a": lambda: _s("g") * (sp.sin(_s("theta")) - _s("mu_k") * sp.cos(_s("theta"))),
      "N": lambda: _s("m") * _s("g") * sp.cos(_s("theta"))}, 6),
    # Serway & Jewett 9th ed., ch. 5 (a block given v0 up a smooth incline: a = -g sin(theta), it stops after
    # d = v0^2/(2 g sin(theta)), h = v0^2/(2 g), t = v0/(g sin(theta))); back down from rest by energy, v = v0.
    ("block_up_incline", {FORCES: ["newton", "solve"], "Height it rises": ["kinematics", "stops", "component"],
                          "Time it takes to slide back": ["energy", "reached", "time"]},
     {"a": lambda: _s("g") * sp.sin(_s("theta")), "d": lambda: _s("v0")**2 / (2 * _s("g") * sp.sin(_s("theta"))),
      "h": lambda: _s("v0")**2 / (2 * _s("g")), "t": lambda: _s("v0") / (_s("g") * sp.sin(_s("theta"))),
      "v": lambda: _s("v0")}, 11),
    # Halliday, Resnick & Walker 10th ed., ch. 6 (a puck sliding on a rough floor: a = -mu_k g, it stops after
    # d = v0^2/(2 mu_k g), t = v0/(mu_k g); its speed halves after 3 v0^2/(8 mu_k g)).
    ("puck_slides_to_stop", {FORCES: ["sent", "newton", "across", "solve"], "Distance it slides": ["kinematics", "stops"],
                             "Where it is when its speed has halved": ["kinematics", "reached"]},
     {"a": lambda: _s("mu") * _s("g"), "d": lambda: _s("v0")**2 / (2 * _s("mu") * _s("g")),
      "t": lambda: _s("v0") / (_s("mu") * _s("g")), "s": lambda: 3 * _s("v0")**2 / (8 * _s("mu") * _s("g"))}, 10),
    # Serway & Jewett 9th ed., ch. 8 (a crate sliding down a rough ramp from rest: the friction's work
    # -mu_k m g cos(theta) d, v = sqrt(2 g d (sin(theta) - mu_k cos(theta)))) and ch. 5 (a, N, f_k = mu_k N).
    ("block_down_rough_incline", {FORCES: ["regime", "newton", "across", "solve"],
                                  TIMED: ["energy", "reached", "time", "kinetic", "friction"]},
     {"a": lambda: _g_sin_mu_cos(_s), "N": lambda: _s("m") * _s("g") * sp.cos(_s("theta")),
      "v": lambda: sp.sqrt(2 * _s("d") * _g_sin_mu_cos(_s)), "K": lambda: _s("m") * _s("d") * _g_sin_mu_cos(_s),
      "f": lambda: _s("mu") * _s("m") * _s("g") * sp.cos(_s("theta"))}, 14),
    # Serway & Jewett 9th ed., ch. 10 (energy in rolling motion: from rest down a height h, v = sqrt(2 g h/(1 + I/(M R^2)));
    # a solid cylinder, I = M R^2/2: v = sqrt(4 g h/3)).
    ("cylinder_rolls_down_by_energy", {FORCES: ["newton", "ties", "solve"], BY_ENERGY: ["energy", "reached"]},
     {"a": lambda: 2 * _s("g") * sp.sin(_s("theta")) / 3, "v": lambda: sp.sqrt(4 * _s("g") * _s("h") / 3)}, 9),
    # Serway & Jewett 9th ed., ch. 8 (m v^2/2 - m v0^2/2 = m g d sin(theta) - mu_k m g cos(theta) d) and ch. 5
    # (a = g (sin(theta) - mu_k cos(theta)), t = (v - v0)/a): a block sent down a rough incline.
    ("block_sent_down_rough_incline", {FORCES: ["sent", "newton", "across", "solve"], TIMED: ["energy", "reached", "time"]},
     {"a": lambda: _g_sin_mu_cos(_s), "v": lambda: sp.sqrt(_s("v0")**2 + 2 * _s("d") * _g_sin_mu_cos(_s)),
      "t": lambda: (sp.sqrt(_s("v0")**2 + 2 * _s("d") * _g_sin_mu_cos(_s)) - _s("v0")) / _g_sin_mu_cos(_s)}, 8),
    # Serway & Jewett 9th ed., ch. 5 (a block sliding up a rough incline: a = -g (sin(theta) + mu_k cos(theta)); from v0
    # it stops after d = v0^2/(2 g (sin(theta) + mu_k cos(theta))), in t = v0/(g (sin(theta) + mu_k cos(theta)))).
    ("crate_stops_on_rough_ramp", {FORCES: ["sent", "newton", "across", "solve"], UNIFORM: ["kinematics", "stops"]},
     {"a": lambda: _g_sin_mu_cos(_s, 1), "d": lambda: _s("v0")**2 / (2 * _g_sin_mu_cos(_s, 1)),
      "t": lambda: _s("v0") / _g_sin_mu_cos(_s, 1)}, 8),
]
CASES.append(
    # Serway & Jewett 9th ed., ch. 5 (connected objects, kinetic friction on the table's block): a = g (m2 - mu_k m1)/
    # (m1 + m2), T = m1 m2 g (1 + mu_k)/(m1 + m2); from rest v = sqrt(2 a h) after the ball falls h.
    ("rough_table_hanging_ball", {FORCES: ["regime", "newton", "newton", "across", "solve"],
                                  UNIFORM: ["kinematics", "reached", "proportion"]},
     {"a": lambda: _s("g") * (_s("m2") - _s("mu") * _s("m1")) / (_s("m1") + _s("m2")),
      "T": lambda: _s("g") * _s("m1") * _s("m2") * (1 + _s("mu")) / (_s("m1") + _s("m2")),
      "v": lambda: sp.sqrt(2 * _s("g") * _s("h") * (_s("m2") - _s("mu") * _s("m1")) / (_s("m1") + _s("m2")))}, 13))
CASES.append(
    # Serway & Jewett 9th ed., ch. 10 (a block on a rough table tied over a massive pulley, I = M R^2/2, to a hanging
    # block): a = (m2 - mu_k m1) g/(m1 + m2 + M/2), T_1 = m1 (a + mu_k g), T_2 = m2 (g - a).
    ("table_block_massive_pulley_friction", {FORCES: ["regime", "newton", "torque", "newton", "ties", "across", "solve"]},
     {"a": lambda: (_s("m2") - _s("mu_k") * _s("m1")) * _s("g") / (_s("m1") + _s("m2") + _s("M") / 2),
      "T_1": lambda: _s("m1") * _s("g") * (_s("mu_k") + (_s("m2") - _s("mu_k") * _s("m1")) / (_s("m1") + _s("m2") + _s("M") / 2)),
      "T_2": lambda: _s("m2") * _s("g") * (1 - (_s("m2") - _s("mu_k") * _s("m1")) / (_s("m1") + _s("m2") + _s("M") / 2))}, 10))
#: The library problems the route now takes, which had the engine's long route (its equations then).
MOVED = {"block_incline_kinetic": 39, "block_up_incline": 11, "puck_slides_to_stop": 11, "block_down_rough_incline": 20}


#: Where each case's file is: a library problem by its id, else a file of the tests.
FILES = {"disk_rolls_up_incline": ROOT / "tests" / "asks" / "disk_rolls_up_incline.yaml",
         **{name: ROOT / "tests" / "textbook" / f"{name}.yaml" for name in (
             "grindstone_slowed_by_friction", "cylinder_rolls_down_by_energy", "block_sent_down_rough_incline",
             "crate_stops_on_rough_ramp")}}


@pytest.mark.parametrize("name, principles, closed, equations", CASES, ids=[c[0] for c in CASES])
def test_a_motion_between_two_states_at_constant_acceleration_takes_the_textbooks_route(name, principles, closed,
                                                                                         equations):
    solution = derived(FILES.get(name, name))
    route = solution.textbook_route
    assert isinstance(route, TextbookRoute) and route.along is not None
    sections = solution.student_steps
    assert {title: _opening(steps) for title, steps in sections.items()} == principles
    steps = [step for title in sections for step in sections[title]]
    for symbol, form in closed.items():
        assert _same(_found(steps, symbol, solution), form()), symbol
    assert sum(len(step.equations) for step in steps) == equations
    assert name not in MOVED or equations <= MOVED[name]  # no more than the engine's long route wrote
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


def _taken(solution) -> bool:
    route = solution.textbook_route
    return isinstance(route, TextbookRoute) and route.along is not None


def test_a_slide_that_stops_and_turns_back_is_refused(tmp_path):
    """A crate shoved up a rough ramp stops, then slides back down where tan(theta) > mu_s: kinetic friction turns
    with it, a change of regime (Halliday, Resnick & Walker 10th ed., ch. 8: up at g (sin + mu_k cos), back at
    g (sin - mu_k cos)). Asked where it is back, the route refuses; asked only up to where it stops, it is taken
    (crate_stops_on_rough_ramp)."""
    library = (ROOT / "problems" / "energy" / "crate_up_rough_ramp.yaml").read_text()
    assert not _taken(Solution(load("crate_up_rough_ramp")))
    back = tmp_path / "crate_back.yaml"  # the kinetic energy's change left out: only the turn refuses it
    back.write_text("\n".join(line for line in library.splitlines() if not line.lstrip().startswith("W:")))
    solution = Solution(load(str(back)))
    assert solution._chain.joints["back"] != solution._chain.joints["highest"]  # the engine: another regime
    assert not _taken(solution)
    assert _taken(derived(FILES["crate_stops_on_rough_ramp"]))


def test_a_block_that_may_stay_put_at_some_values_is_refused(tmp_path):
    """Released on a rough incline, a block slips only where tan(theta) > mu_s: where the ranges reach a slope it
    grips on, the route along a slide is not proven for every variant, and the engine's routes answer."""
    library = (ROOT / "problems" / "dynamics" / "block_incline_kinetic.yaml").read_text()
    assert "range: [0.8, 1.2]" in library
    gentle = tmp_path / "gentle.yaml"
    gentle.write_text(library.replace("range: [0.8, 1.2]", "range: [0.1, 1.2]"))
    assert Solution(load(str(gentle))).textbook_route is None
    assert _taken(Solution(load("block_incline_kinetic")))


def test_a_disk_that_slips_as_it_turns_is_refused():
    """A disk slipping down a rough incline slides and turns at rates no constraint ties (a = g (sin - mu_k cos),
    alpha = 2 mu_k g cos(theta)/R): Newton along one line of motion does not describe it."""
    assert Solution(load("disk_incline_slips")).textbook_route is None
