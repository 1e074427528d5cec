"""A student's worked solution takes the route a textbook takes (issue 37, item 1): Newton's second
law along the motion and torques about the center or a fixed pivot, the ties between the motions,
energy for a speed between two states, and the two engine routes only as the proof.

Each case names the textbook route it follows and checks the principle of each step, the number of
equations, and the result against the closed form the text prints (written here, not read back).
"""
import pytest
import sympy as sp

from conftest import run_derive, textbook
from derive.language.problem import load
from derive.solution.answers import Solution



def _load(problem_id: str):
    """A library problem (the textbook setups among them)."""
    return load(problem_id)


def _symbols(*names):
    return [sp.Symbol(n, positive=True) for n in names]


def _principles(steps) -> list[str]:
    """Each step's principle, by the words it opens with."""
    kinds = {"Newton's second law": "newton", "Torque about": "torque", "Across its motion": "across",
             "Solving": "solve", "Energy is conserved": "energy", "Energy conservation": "energy",
             "From rest at the constant acceleration": "kinematics", "It rolls without slipping while": "friction",
             "With the question's sign convention": "convention"}
    result = []
    for step in steps:
        kind = next((k for opening, k in kinds.items() if step.text.startswith(opening)), None)
        if kind is None and ("rolls without slipping" in step.text or "neither stretches" in step.text
                             or "turns about its pin" in step.text):
            kind = "ties"
        result.append(kind or step.text)
    return result


def _solved(steps, name: str) -> sp.Expr:
    """The value a solving step gives `name` (the last, where the question's sign convention turns it round)."""
    return [e.rhs for s in steps if s.role == "solve" for e in s.equations if str(e.lhs) == name][-1]


def _same(a, b) -> bool:
    return sp.simplify(a - b) == 0


def test_the_rolling_sphere_reads_as_the_textbook_solves_it():
    """Halliday, Resnick & Walker, Fundamentals of Physics 10th ed., ch. 11, Module 11-2 (forces of
    rolling, eq. 11-10: a = g sin(theta)/(1 + I/(M R^2)); the ball rolling down a ramp by energy,
    v = sqrt(10 g h / 7)): Newton along the slope with friction up it, the torque about the center,
    a = R alpha; energy for the speed at the bottom."""
    solution = Solution(load("rolling_incline"))
    steps = solution.student_steps
    assert list(steps) == ["Forces and torques along the motion", "The speed at the bottom, by energy",
                           "The time to the bottom"]
    along = steps["Forces and torques along the motion"]
    assert _principles(along) == ["newton", "ties", "across", "solve", "friction"]
    M, g, theta, R, H = _symbols("M", "g", "theta", "R", "H")
    a, f = sp.Symbol("a", real=True), sp.Symbol("f", real=True)
    newton, torque = along[0].equations
    assert _same(newton.lhs - newton.rhs, M * a - (M * g * sp.sin(theta) - f))  # friction up the slope: a magnitude
    assert _same(_solved(along, "a"), sp.Rational(5, 7) * g * sp.sin(theta))
    assert _same(_solved(along, "f"), sp.Rational(2, 7) * M * g * sp.sin(theta))
    energy = steps["The speed at the bottom, by energy"]
    assert _principles(energy) == ["energy", "energy"]
    assert _same(energy[-1].equations[-1].rhs, sp.sqrt(sp.Rational(10, 7) * g * H))
    assert sum(len(s.equations) for s in along[:4]) <= 8  # a and f in at most eight equations


def test_the_atwood_machine_with_a_massive_pulley():
    """Serway & Jewett, Physics for Scientists and Engineers 9th ed., ch. 10 (an Atwood machine with
    a massive pulley): Newton for each block, the torque about the axle, a = R alpha;
    a = (m1 - m2) g/(m1 + m2 + M/2)."""
    steps = Solution(_load("atwood_massive_pulley")).student_steps["Forces and torques along the motion"]
    assert _principles(steps) == ["torque", "newton", "newton", "ties", "solve", "convention"]
    m1, m2, M, g = _symbols("m1", "m2", "M", "g")
    assert _same(_solved(steps, "a_1"), (m1 - m2) * g / (m1 + m2 + M / 2))  # down, along its motion
    assert _same(_solved(steps, "a"), -(m1 - m2) * g / (m1 + m2 + M / 2))  # "taking up as positive"
    assert {"T_1", "T_2"} <= {str(e.lhs) for s in steps for e in s.equations}  # a tension on each side


def test_the_yo_yo_falls_by_newton_and_the_torque_about_its_center():
    """Halliday, Resnick & Walker 10th ed., ch. 11, Module 11-3 (the yo-yo, eq. 11-13:
    a = g/(1 + I/(M R0^2)), R0 the axle's radius)."""
    steps = Solution(_load("yoyo_axle")).student_steps["Forces and torques along the motion"]
    assert _principles(steps) == ["newton", "ties", "solve", "convention"]
    M, g, R, r = _symbols("M", "g", "R", "r")
    assert _same(_solved(steps, "a_1"), g / (1 + (M * R**2 / 2) / (M * r**2)))  # down, along its motion
    assert _same(_solved(steps, "a"), -g / (1 + (M * R**2 / 2) / (M * r**2)))  # "up positive"


def test_the_rod_released_from_horizontal_turns_about_its_pivot():
    """Serway & Jewett 9th ed., ch. 10 (a rod pinned at one end released from rest horizontal):
    the torque about the pivot, which the pivot's force has no moment about, I_P alpha = M g L/2 with
    I_P = M L^2/3: alpha = 3 g/(2 L); the hinge's force from Newton's law for the center, M g/4."""
    steps = Solution(_load("rod_released_horizontal")).student_steps["Forces and torques along the motion"]
    assert _principles(steps)[:2] == ["torque", "ties"] and steps[0].text.startswith("Torque about the rod's pivot")
    M, g, L = _symbols("M", "g", "L")
    (torque,) = steps[0].equations
    assert _same(torque.lhs / sp.Symbol("alpha", real=True), M * L**2 / 3)
    assert _same(_solved(steps, "a"), sp.Rational(3, 4) * g)  # the center's, (L/2) alpha
    assert _same(_solved(steps, "R_y"), M * g / 4)


def test_a_disk_on_its_axle_with_a_hanging_block():
    """The lecture notes' §4.1 and Halliday ch. 10 (a block hanging from a cord wound on a disk):
    m g - T = m a, T R = (M R^2/2) alpha, a = R alpha; a = 2 m g/(M + 2 m)."""
    steps = Solution(load("string_wrapped_disk")).student_steps["Forces and torques along the motion"]
    assert _principles(steps)[:4] == ["torque", "newton", "ties", "solve"]
    assert set(_principles(steps)[4:]) <= {"convention"}
    m, M, g = _symbols("m", "M", "g")
    # the ask `a` is the block's y component (y up), negative: the route's acceleration is renamed
    assert _same(_solved(steps, "a_2"), 2 * m * g / (M + 2 * m))
    assert _same(_solved(steps, "a"), -2 * m * g / (M + 2 * m))


def test_the_route_agrees_with_both_routes_in_derive_check():
    done = run_derive("check", "rolling_incline", "string_wrapped_disk")
    assert done.returncode == 0, done.stderr
    assert done.stdout.count("textbook_route") == 2


def test_the_compound_pendulum_swings_by_the_torque_about_its_pivot():
    """Serway & Jewett 9th ed., ch. 15 (the physical pendulum): tau = -m g d sin(theta) ~ -m g d theta
    about the pivot, I theta'' = tau, omega = sqrt(m g d / I) with I = I_cm + m d^2 (parallel axes)."""
    solution = Solution(load("compound_pendulum"))
    (steps,) = solution.student_steps.values()
    assert [s.text.split(" ")[0] for s in steps] == ["The", "Turned", "Newton's"]
    assert "parallel-axis theorem" in steps[0].text and "torque" in steps[1].text
    M, g, d, inertia = _symbols("M", "g", "Rcm", "I_cm")
    (moment,) = steps[0].equations
    assert _same(moment.rhs, inertia + M * d**2)
    assert _same(steps[1].equations[0].rhs, -M * g * d * sp.sin(sp.Symbol("theta", real=True)))
    assert _same(steps[2].equations[2].rhs, sp.sqrt(M * g * d / (inertia + M * d**2)))
    assert sum(len(s.equations) for s in steps) <= 8


def test_keplers_orbit_by_the_conservation_of_angular_momentum_and_of_energy_at_its_turning_points():
    """Taylor, Classical Mechanics, ch. 8, and Kleppner & Kolenkow 2nd ed., ch. 10 (the Kepler problem):
    r_p = a (1 - e), r_a = a (1 + e); r_p v_p = r_a v_a (no torque about the Sun); v^2/2 - GM/r the same at
    both (gravity conservative): l = sqrt(GM a (1 - e^2)), E = -GM/(2 a); Kepler's second law, the area
    pi a b swept at l/2: P = 2 pi sqrt(a^3/GM)."""
    (steps,) = Solution(load("kepler_orbit")).student_steps.values()
    openings = ["The Sun is at a focus", "Conservation of angular momentum", "Conservation of energy", "Solving the two",
                "The energy per unit mass", "Kepler's second law"]
    assert [next((o for o in openings if s.text.startswith(o)), s.text) for s in steps] == openings
    GM, a = _symbols("GM", "a")
    e = sp.Symbol("e", real=True)
    rp, ra, vp, va = _symbols("r_p", "r_a", "v_p", "v_a")
    assert _same(_found(steps, "r_p"), a * (1 - e)) and _same(_found(steps, "r_a"), a * (1 + e))
    (momentum,) = steps[1].equations
    assert _same(momentum.lhs - momentum.rhs, rp * vp - ra * va)
    (energy,) = steps[2].equations
    assert _same(energy.lhs - energy.rhs, vp**2 / 2 - GM / rp - va**2 / 2 + GM / ra)
    assert _same(_found(steps, "l") ** 2, GM * a * (1 - e**2))
    assert _same(_found(steps, "E"), -GM / (2 * a))
    assert _same(_found(steps, "P"), 2 * sp.pi * sp.sqrt(a**3 / GM))
    assert sum(len(s.equations) for s in steps) == 9


@pytest.mark.parametrize("stem, inertia, kappa", [
    # Morin, Introduction to Classical Mechanics, ch. 8: a solid hemisphere rocking without slipping, its center
    # of mass d = 3R/8 below its center: I_P = I_cm + m (R - d)^2 = 13 m R^2/20, kappa = m g d, omega^2 = 15 g/(26 R)
    ("hemisphere_rocking", lambda m, R: sp.Rational(13, 20) * m * R**2, lambda m, g, R: 3 * m * g * R / 8),
    # Morin ch. 8: a half-cylinder, d = 4R/(3 pi), I_cm = m R^2/2 - m d^2: I_P = m R^2 (3/2 - 8/(3 pi))
    ("half_cylinder_rocking", lambda m, R: m * R**2 * (sp.Rational(3, 2) - 8 / (3 * sp.pi)),
     lambda m, g, R: 4 * m * g * R / (3 * sp.pi)),
])
def test_a_body_rocking_on_its_round_face_turns_about_its_point_of_contact(stem, inertia, kappa):
    """Morin, ch. 8 (and Kleppner & Kolenkow 2nd ed., ch. 7, the instantaneous axis): rocking without
    slipping, the body turns about its point of contact, at rest for the moment; the weight's torque
    about it is -m g d sin(theta) ~ -kappa theta; I_P theta'' = -kappa theta. Before, the worked
    solution printed each route's equations "at rest", which tell a student nothing."""
    solution = Solution(load(textbook(stem)))
    (title, steps), = solution.student_steps.items()
    omega = next((a.name for a in solution.problem.asks.values() if a.quantity.detail == "omega"), "omega")  # as asked
    assert title == "Small oscillations about the point of contact"
    assert "rocks without slipping" in steps[0].text and "parallel-axis theorem" in steps[0].text and "torque of the loads about the point of contact" in steps[1].text
    assert steps[2].text.startswith("Newton's second law for the rotation about the point of contact")
    m, g, R = _symbols("m", "g", "R")
    assert _same(_found(steps, "I_P"), inertia(m, R)) and _same(_found(steps, "kappa"), kappa(m, g, R))
    assert _same(_found(steps, omega) ** 2, kappa(m, g, R) / inertia(m, R))
    assert sum(len(s.equations) for s in steps) == 9


def test_the_puck_pulled_through_the_hole_keeps_its_angular_momentum_about_the_hole():
    """Serway & Jewett 9th ed., ch. 11 (a puck on a frictionless table pulled in through a hole: the cord's
    force points at the hole, so m r1 v1 = m r2 v; the pull's work is the change of kinetic energy,
    W = m v1^2 ((r1/r2)^2 - 1)/2; on the smaller circle T = m v^2/r2 = m v1^2 r1^2/r2^3)."""
    (title, steps), = Solution(load(textbook("puck_pulled_through_hole"))).student_steps.items()
    assert title == "The pull, by the angular momentum about the hole"
    openings = ["Conservation of angular momentum about the hole", "The work-energy theorem",
                "Newton's second law toward the hole"]
    assert [next((o for o in openings if s.text.startswith(o)), s.text) for s in steps] == openings
    m, r1, r2, v1, v = _symbols("m", "r1", "r2", "v1", "v")
    law = steps[0].equations[0]
    assert _same(law.lhs - law.rhs, m * r1 * v1 - m * r2 * v)
    assert _same(_found(steps, "v"), r1 * v1 / r2)
    assert _same(_found(steps, "W"), m * v1**2 * ((r1 / r2)**2 - 1) / 2)
    assert _same(_found(steps, "T"), m * v1**2 * r1**2 / r2**3)
    assert sum(len(s.equations) for s in steps) == 6


def test_the_rocking_and_the_pull_agree_with_both_engine_routes_in_derive_check():
    files = [str(textbook(stem)) for stem in ("hemisphere_rocking", "half_cylinder_rocking", "puck_pulled_through_hole")]
    done = run_derive("check", *files)
    assert done.returncode == 0, done.stderr
    assert done.stdout.count("textbook_route") == len(files)


def test_the_least_height_for_the_loop_is_newton_at_its_top_and_energy_from_the_release():
    """Serway & Jewett 9th ed., ch. 8, and Halliday 10th ed., ch. 8 (the loop-the-loop: at the top
    m g + N = m v^2/R, N >= 0 gives v^2 >= g R, energy m g (h - 2R) = m v^2/2: h = 5R/2); Halliday ch. 11
    (a small solid sphere that rolls: + I omega^2/2 with omega = v/r, h = 27R/10). Before, `derive solve`
    printed each route's equations "at rest" and the worked solution the engine's coordinates."""
    sections = Solution(load("loop_the_loop")).student_steps
    assert len(sections) == 2
    openings = ["Newton's second law toward the center of the loop", "It stays on the track while",
                "Energy is conserved from the release", "With the least speed at the top"]
    R, g, m, r = _symbols("R", "g", "m", "r")
    N, v, omega = sp.Symbol("N", real=True), *_symbols("v", "omega")
    for steps, height in zip(sections.values(), (5 * R / 2, 27 * R / 10)):
        assert [next((o for o in openings if s.text.startswith(o)), s.text) for s in steps] == openings
        top = steps[0].equations[0]
        assert _same(top.lhs - top.rhs, N + m * g - m * v**2 / R)
        assert _same(_found(steps, "v"), sp.sqrt(g * R)) and _same(_found(steps, "h"), height)
    rolling = list(sections.values())[1][2].equations
    assert _same(rolling[0].rhs, v / r) and _same(rolling[1].rhs, m * v**2 / 2 + m * r**2 * omega**2 / 5)
    assert sum(len(s.equations) for steps in sections.values() for s in steps) == 9


def test_the_loops_approximate_ask_is_one_line_after_the_exact_one():
    """loop_the_loop_ball (the notes' 27(R - r)/10, and 27R/10 with the ball's radius dropped): the second
    answer is not derived again."""
    exact, small = Solution(load("loop_the_loop_ball")).student_steps.values()
    R, r = _symbols("R", "r")
    assert _same(_found(exact, "h"), 27 * (R - r) / 10)
    (step,) = small
    assert _same(_found(small, "h"), 27 * R / 10) and "radius dropped" in step.text


def test_the_solutions_pdf_shows_the_route_and_the_proof_in_an_appendix(tmp_path):
    out = tmp_path / "out"
    done = run_derive("sheet", "rolling_incline", "--out", str(out), "--to", "")
    assert done.returncode == 0, done.stderr
    tex = (out / "solutions.tex").read_text()
    route, appendix = tex.split(r"\appendix")
    assert "Forces and torques along the motion" in route and r"\subsection*{Lagrange" not in route
    assert r"\subsubsection*{Lagrange's method}" in appendix and r"\subsubsection*{Newton–Euler}" in appendix


def test_the_ladder_against_a_smooth_wall_by_balances_and_the_torque_about_its_foot():
    """Serway & Jewett 9th ed., ch. 12 (Example 12.4, the leaning ladder): the forces balance
    across (f = P) and up (N = M g), and the torques about the foot, where the floor's two forces
    have no moment: P L sin(theta) = M g (L/2) cos(theta); mu_min = 1/(2 tan(theta))."""
    solution = Solution(_load("ladder_statics"))
    (steps,) = solution.student_steps.values()
    assert "torques about the point where it touches the floor" in steps[0].text
    assert len(steps[0].equations) == 3 and steps[1].text == "Solving"
    M, g, theta, L = _symbols("M", "g", "theta", "L")
    torque = steps[0].equations[2].rhs
    assert not torque.has(sp.Symbol("f", real=True))  # the foot's forces drop out
    assert _same(_solved(steps, "N_wall"), M * g / (2 * sp.tan(theta)))
    assert _same(steps[-1].equations[-1].rhs, 1 / (2 * sp.tan(theta)))


def test_a_sticky_impact_on_an_axle_is_one_line_of_angular_momentum():
    """Halliday, Resnick & Walker 10th ed., ch. 11, Module 11-7 (conservation of angular momentum;
    a mass sticking to a body on an axle): L about the axle before, m v b, equals L after,
    (I + m R^2) omega, as the axle's impulse has no moment about it."""
    solution = Solution(load("sticky_impact_pivoted"))
    (steps,) = solution.student_steps.values()
    assert len(steps) == 3 and "no moment about it" in steps[0].text
    M, m, v, b, R = _symbols("M", "m", "v", "b", "R")
    assert _same(steps[0].equations[0].rhs, m * v * b)
    assert _same(steps[1].equations[0].rhs, sp.Rational(2, 5) * M * R**2 + m * R**2)
    assert _same(steps[2].equations[0].rhs, m * v * b / (sp.Rational(2, 5) * M * R**2 + m * R**2))


def test_the_beetle_stops_and_the_lazy_susan_keeps_the_angular_momentum():
    """Halliday, Resnick & Walker 10th ed., ch. 11 (a beetle and a lazy Susan, angular momentum
    about the axle): I omega0 - m R v clockwise before, (I + m R^2) omega after; the kinetic energy
    the impact takes is the difference of the two, I m (R omega0 + v)^2 / (2 (I + m R^2))."""
    solution = Solution(load("beetle_lazy_susan"))
    (steps,) = solution.student_steps.values()
    I, omega0, m, R, v = _symbols("I", "omega0", "m", "R", "v")
    assert "clockwise" in steps[0].text and _same(steps[0].equations[0].rhs, I * omega0 - m * R * v)
    assert _same(steps[3].equations[-1].rhs, I * m * (R * omega0 + v) ** 2 / (2 * (I + m * R**2)))


def _sym(name):
    return sp.Symbol(name, positive=True)


#: (setup, the route's principles in order, {a symbol the route solves for: the text's closed form}),
#: each the textbook's route for its setup (the source each file cites).
ROUTES = [
    # Halliday 10th ed., ch. 11, Module 11-2, eq. 11-10: a = g sin(theta)/(1 + I/(M R^2)), I = M R^2
    ("hoop_rolls_incline", ["newton", "ties", "across", "solve"],
     {"a": lambda: _sym("g") * sp.sin(_sym("theta")) / 2}),
    # Kleppner & Kolenkow 2nd ed., ch. 7: a force F at a rolling disk's axle, a = 2F/(3M), friction F/3
    ("disk_pulled_at_axle", ["newton", "ties", "across", "solve"],
     {"a": lambda: 2 * _sym("F") / (3 * _sym("M"))}),
    # Kleppner & Kolenkow 2nd ed., ch. 7: a rolling cylinder pulled by a cord to a hanging mass m,
    # a = 2 m g/(3 M + 2 m)
    ("cylinder_table_hanging_block", ["newton", "newton", "ties", "solve"],
     {"a": lambda: 2 * _sym("m") * _sym("g") / (3 * _sym("M") + 2 * _sym("m"))}),
    # Serway & Jewett 9th ed., Example 5.10: a = (m2 - m1 sin(theta)) g/(m1 + m2), T = m1 m2 g (1 + sin(theta))/(m1 + m2)
    ("incline_hanging_block", ["newton", "newton", "across", "solve"],
     {"a": lambda: (_sym("m2") - _sym("m1") * sp.sin(_sym("theta"))) * _sym("g") / (_sym("m1") + _sym("m2"))}),
    # Halliday ch. 11: a yo-yo pulled along the floor by its string from below the axle rolls toward the pull,
    # a = 2 F (R - r)/(3 M R)
    ("yoyo_pulled_horizontal", ["newton", "ties", "solve"],
     {"a": lambda: 2 * _sym("F") * (_sym("R") - _sym("r")) / (3 * _sym("M") * _sym("R"))}),
    # Halliday 10th ed., Sample Problem 12.02: the wall's force g a (M/2 + m/3)/h, a = sqrt(L^2 - h^2)
    ("ladder_firefighter", ["The forces on the ladder balance, and so do their torques about the point where it "
                            "touches the floor", "solve"],
     {"N_wall": lambda: _sym("g") * sp.sqrt(_sym("L")**2 - _sym("h")**2) * (_sym("M") / 2 + _sym("m") / 3) / _sym("h")}),
]


@pytest.mark.parametrize("problem_id, principles, closed", ROUTES, ids=[r[0] for r in ROUTES])
def test_more_textbook_setups_take_the_textbooks_route(problem_id, principles, closed):
    solution = Solution(_load(problem_id))
    (steps,) = [s for title, s in solution.student_steps.items() if title.startswith("Forces and torques")]
    assert _principles(steps)[:len(principles)] == principles
    for name, form in closed.items():
        assert _same(_solved(steps, name), form()), name
    assert sum(len(s.equations) for s in steps) <= 10  # with the least coefficient of friction where asked


@pytest.mark.parametrize("problem_id, period", [
    # Halliday 10th ed., ch. 15, Module 15-4: a torsion pendulum T = 2 pi sqrt(I/kappa), I = M R^2/2
    ("torsion_pendulum", lambda: 2 * sp.pi * sp.sqrt(_sym("M") * _sym("R")**2 / (2 * _sym("kappa")))),
    # Halliday 10th ed., ch. 15, Module 15-4: a rod pivoted at its end, T = 2 pi sqrt(2L/(3g))
    ("rod_end_pendulum", lambda: 2 * sp.pi * sp.sqrt(2 * _sym("L") / (3 * _sym("g")))),
])
def test_pendulums_swing_by_the_torque_about_their_pivot(problem_id, period):
    solution = Solution(_load(problem_id))
    (steps,) = solution.student_steps.values()
    omega = next(e.rhs for e in steps[-1].equations if str(e.lhs) == "omega" and not e.rhs.has(sp.Symbol("I_P")))
    assert _same(2 * sp.pi / omega, period())
    assert len(steps) == 3


def test_the_answer_counted_as_the_question_says_keeps_its_name_in_the_document():
    """The Atwood machine's "taking up as positive" step printed its answer as lambda: the ask's name
    was taken for the engine's growth rate a and renamed (derive.publishing.notation)."""
    from conftest import student_solution
    tex, _ = student_solution("atwood_massive_pulley")
    step = tex[tex.index("With the question's sign convention"):]
    assert step[step.index("\\begin{align*}") + len("\\begin{align*}"):].lstrip().startswith("a &=")
    assert "\\lambda" not in tex


def _opening(steps) -> list[str]:
    """Each step's principle by its opening words (the routes of states and of a top)."""
    kinds = {"Torque about": "torque", "Newton's second law": "newton", "In steady precession": "momentum",
             "Dividing by the sine of the tilt, the top's condition": "condition", "Solving": "solve",
             "The question treats the top as fast": "fast top", "At these constant accelerations": "kinematics",
             "It rolls without slipping once": "rolling", "Then": "kinematics", "The kinetic energy": "energy",
             "No impulse from outside": "momentum", "Nor has any outside impulse a moment": "angular momentum",
             "The only impulse from outside the bodies acts at the axle": "angular momentum",
             "Just after": "after", "Setting the two equal": "solve", "From the rate": "kinematics",
             "Nutation of the fast top": "nutation"}
    return [next((k for opening, k in kinds.items() if s.text.startswith(opening)), s.text) for s in steps]


def _found(steps, name: str) -> sp.Expr:
    """The last value the steps give `name`."""
    return [e.rhs for s in steps for e in s.equations if str(e.lhs) == name][-1]


def test_the_top_precesses_by_the_torque_about_its_tip_and_the_tops_condition():
    """Taylor, Classical Mechanics, ch. 10 (the steady precession of a symmetric top: the condition
    I1 Omega^2 cos(theta) - I3 omega3 Omega + m g R = 0, its two roots); Kleppner & Kolenkow 2nd ed.,
    ch. 7 (the gyroscope: tau = Omega x L, the fast top's Omega = m g R/(I3 omega))."""
    solution = Solution(load("top_precession_exact"))
    (steps,) = solution.student_steps.values()
    assert _opening(steps) == ["torque", "momentum", "newton", "condition", "solve", "fast top"]
    m, g, R, I1, I3, w, theta = _symbols("m", "g", "Rcm", "I1", "I3", "omega", "theta")
    Omega = sp.Symbol("Omega", positive=True)
    assert _same(steps[0].equations[0].rhs, m * g * R * sp.sin(theta))
    (condition,) = steps[3].equations
    assert _same(condition.lhs - condition.rhs, I1 * Omega**2 * sp.cos(theta) - I3 * w * Omega + m * g * R)
    disc = sp.sqrt(I3**2 * w**2 - 4 * I1 * m * g * R * sp.cos(theta))
    assert _same(_found(steps, "Omega_slow"), (I3 * w - disc) / (2 * I1 * sp.cos(theta)))
    assert _same(_found(steps, "Omega_fast"), (I3 * w + disc) / (2 * I1 * sp.cos(theta)))
    assert _same(_found(steps, "Omega"), m * g * R / (I3 * w))
    assert sum(len(s.equations) for s in steps) == 8


def test_the_tops_two_precessions_are_the_roots_of_its_condition_and_the_fast_top_nutates_at_I3_omega_over_I1():
    """Taylor, Classical Mechanics, ch. 10 (the heavy symmetric top: I1 Omega^2 cos(theta) - I3 omega3 Omega
    + M g R = 0, a quadratic with a slow and a fast root); Kleppner & Kolenkow 1st ed., ch. 8 (2nd ed.
    ch. 7: the gyroscope's nutation: I1 u'' = -I3 omega3 w', I1 w'' = I3 omega3 u', omega_n = I3 omega3/I1)."""
    (steps,) = Solution(load("top_two_precessions")).student_steps.values()
    assert _opening(steps) == ["torque", "momentum", "newton", "condition", "solve", "nutation"]
    M, g, R, I1, I3, w, theta = _symbols("M", "g", "R", "I1", "I3", "omega3", "theta")
    Omega = sp.Symbol("Omega", positive=True)
    (condition,) = steps[3].equations
    assert _same(condition.lhs - condition.rhs, I1 * Omega**2 * sp.cos(theta) - I3 * w * Omega + M * g * R)
    for root in ("Omega_slow", "Omega_fast"):  # each a root of the condition
        assert _same(sp.expand(condition.lhs.subs(Omega, _found(steps, root))), 0)
    assert _same(_found(steps, "Omega_fast") - _found(steps, "Omega_slow"),
                 sp.sqrt(I3**2 * w**2 - 4 * I1 * M * g * R * sp.cos(theta)) / (I1 * sp.cos(theta)))
    uddot, wdot = (sp.Symbol(n, real=True) for n in ("uddot", "wdot"))
    wobble = steps[-1].equations
    assert _same(wobble[0].lhs - wobble[0].rhs, I1 * uddot + I3 * w * wdot)
    assert _same(_found(steps, "omega_n"), I3 * w / I1)
    assert sum(len(s.equations) for s in steps) == 9


def test_a_fast_top_drops_the_precessions_own_angular_momentum_only_as_the_question_says():
    """Kleppner & Kolenkow 2nd ed., ch. 7 (the fast top: Omega = m g R/(I omega)); the question says
    "treating it as a fast top". Its tilt and transverse moment, which it leaves out, are written as a
    textbook writes them (theta, I_1), never as the engine's own names."""
    (steps,) = Solution(load("top_precession")).student_steps.values()
    assert _opening(steps) == ["torque", "momentum", "newton", "condition", "fast top"]
    m, g, R, inertia, w = _symbols("m", "g", "Rcm", "I", "omega")
    assert _same(_found(steps, "Omega"), m * g * R / (inertia * w))
    shown = {x.name for s in steps for e in s.equations for x in e.free_symbols}
    assert {"theta", "I_1"} <= shown and not any(n.endswith("_top") for n in shown)


def test_the_bowling_ball_skids_by_newton_along_the_lane_and_the_torque_about_its_center():
    """Serway & Jewett, Physics for Scientists and Engineers 9th ed., ch. 10 (a bowling ball launched
    without spin: kinetic friction slows the center and spins the ball up until v = R omega); Kleppner &
    Kolenkow 2nd ed., ch. 7: t = 2 v0/(7 mu g), v = 5 v0/7, d = 12 v0^2/(49 mu g), and the kinetic energy
    lost to friction, M v0^2/7, positive. As the solution manual writes it, each law once and each
    answer once: M a = -mu M g, I alpha = mu M g R, v0 - mu g t = R alpha t, then V, d and the energy
    (10 equations; 17 before, each answer restated)."""
    (steps,) = Solution(load("skid_to_roll")).student_steps.values()
    assert _opening(steps) == ["newton", "torque", "rolling", "kinematics", "energy"]
    M, R, v0, mu, g = _symbols("M", "R", "v0", "mu", "g")
    assert _same(_found(steps, "a"), -mu * g) and _same(_found(steps, "alpha"), 5 * mu * g / (2 * R))
    assert _same(_found(steps, "t"), 2 * v0 / (7 * mu * g))
    assert _same(_found(steps, "V"), sp.Rational(5, 7) * v0)
    assert _same(_found(steps, "d"), 12 * v0**2 / (49 * mu * g))
    lost = steps[-1].equations[-1]
    assert str(lost.lhs) == "K_0 - K_1" and _same(lost.rhs, M * v0**2 / 7)
    assert sum(len(s.equations) for s in steps) == 10
    shown = [str(e.lhs) for s in steps for e in s.equations]
    assert all(shown.count(name) == 1 for name in ("a", "alpha", "t", "V", "d"))  # each answer stated once


def test_the_bowling_balls_kinetic_energy_once_it_rolls_is_its_centers_and_its_rotations():
    """Serway & Jewett 9th ed., ch. 10 (the bowling ball once it rolls: K = M V^2/2 + I omega^2/2 with
    omega = V/R, 5 M v0^2/14 for V = 5 v0/7); its acceleration while it skids, asked, is a = -mu g."""
    (steps,) = Solution(load("bowling_ball_skids")).student_steps.values()
    assert _opening(steps) == ["newton", "torque", "rolling", "kinematics", "energy"]
    M, v0, mu, g = _symbols("M", "v0", "mu", "g")
    assert _same(_found(steps, "a"), -mu * g)
    assert _same(_found(steps, "K_1"), 5 * M * v0**2 / 14) and "K_0 - K_1" not in {str(e.lhs) for e in steps[-1].equations}
    assert sum(len(s.equations) for s in steps) == 10


def test_the_cue_ball_with_backspin_skids_by_the_same_route_friction_backward():
    """Kleppner & Kolenkow 2nd ed., ch. 7, and Serway & Jewett ch. 10 (a cue ball struck low, at v0 with
    backspin w0: its bottom slides forward at v0 + R w0, so kinetic friction acts backward, a = -mu g,
    alpha = 5 mu g/(2 R) the way it rolls forward; it rolls once v0 - mu g t = -R w0 + 5 mu g t/2:
    t = 2 (v0 + R w0)/(7 mu g), V = (5 v0 - 2 R w0)/7, as the angular momentum about the contact point
    gives it)."""
    (steps,) = Solution(load("cue_ball_backspin")).student_steps.values()
    assert _opening(steps) == ["newton", "torque", "rolling", "kinematics"]
    assert "backspin" in steps[0].text and "backward" in steps[0].text
    R, v0, w0, mu, g = _symbols("R", "v0", "w0", "mu", "g")
    assert _same(_found(steps, "a"), -mu * g) and _same(_found(steps, "alpha"), 5 * mu * g / (2 * R))
    assert _same(_found(steps, "t"), 2 * (v0 + R * w0) / (7 * mu * g))
    assert _same(_found(steps, "V"), (5 * v0 - 2 * R * w0) / 7)
    assert sum(len(s.equations) for s in steps) == 7


def test_a_clutch_keeps_the_angular_momentum_about_the_axle_and_a_brake_stops_the_pair():
    """Halliday, Resnick & Walker 10th ed., ch. 11 (two disks on one axle that couple:
    I1 w1 + I2 w2 = (I1 + I2) w; the kinetic energy lost, positive); ch. 10 (a constant torque
    stops the pair: (I1 + I2) alpha = tau, t = w/alpha, an angle w^2/(2 alpha))."""
    steps = Solution(load("clutch_disks_brake")).student_steps
    clutch, brake = steps.values()
    assert _opening(clutch) == ["angular momentum", "after", "solve", "energy"]
    assert _opening(brake) == ["newton", "kinematics"]
    M1, R1, M2, R2, w1, tau = _symbols("M1", "R1", "M2", "R2", "w1", "tau")
    w2 = sp.Symbol("w2", real=True)  # the upper disk may turn either way
    I1, I2 = M1 * R1**2 / 2, M2 * R2**2 / 2
    w = (I1 * w1 + I2 * w2) / (I1 + I2)
    assert _same(_found(clutch, "omega"), w)
    lost = clutch[-1].equations[-1]
    assert str(lost.lhs) == "K0 - K1" and _same(lost.rhs, I1 * I2 * (w1 - w2)**2 / (2 * (I1 + I2)))
    assert _same(_found(brake, "t"), (I1 + I2) * w / tau)
    assert _same(_found(brake, "theta"), (I1 + I2) * w**2 / (2 * tau))
    assert sum(len(s.equations) for s in (*clutch, *brake)) == 11


def test_a_sticky_impact_on_a_free_sphere_keeps_momentum_and_the_angular_momentum_about_the_center_of_mass():
    """Kleppner & Kolenkow 2nd ed., ch. 7 (a bullet that sticks to a free body: the momentum, then
    the angular momentum about the center of mass, where no outside impulse has a moment):
    V = m v/(M + m), omega = m v (R - y_cm)/I_cm = 5 m v/(R (2 M + 7 m)); the kinetic energy lost,
    M m v^2/(2 M + 7 m), positive."""
    (steps,) = Solution(load("sticky_impact_free")).student_steps.values()
    assert _opening(steps) == ["momentum", "angular momentum", "after", "solve", "energy"]
    m, M, R, v = _symbols("m", "M", "R", "v")
    assert _same(_found(steps, "V_x"), m * v / (M + m))
    y = m * R / (M + m)
    assert _same(_found(steps, "y_cm"), y) and _same(steps[1].equations[-1].rhs, m * v * (R - y))
    assert _same(_found(steps, "I_cm"), sp.Rational(2, 5) * M * R**2 + M * y**2 + m * (R - y)**2)
    assert _same(_found(steps, "omega"), 5 * m * v / (R * (2 * M + 7 * m)))
    assert "clockwise" in steps[1].text
    assert _same(steps[-1].equations[-1].rhs, M * m * v**2 / (2 * M + 7 * m))


def test_the_new_routes_agree_with_both_engine_routes_in_derive_check():
    problems = ("top_precession_exact", "top_two_precessions", "kepler_orbit", "loop_the_loop", "loop_the_loop_ball",
                "skid_to_roll", "bowling_ball_skids", "cue_ball_backspin", "clutch_disks_brake",
                "sticky_impact_free")
    done = run_derive("check", *problems)
    assert done.returncode == 0, done.stderr
    assert done.stdout.count("textbook_route") == len(problems)


def test_the_handout_follows_the_students_route_then_the_proof(tmp_path):
    """`derive handout` shows the student's route first, then the engine's two routes as the proof."""
    done = run_derive("handout", "skid_to_roll", "--out", str(tmp_path / "h"), "--progress", "none")
    assert done.returncode == 0, done.stderr
    tex = (tmp_path / "h" / "skid_to_roll.tex").read_text()
    route = tex.index(r"\section*{The skid, by Newton along the motion and the torque about the center}")
    assert route < tex.index(r"\section*{The proof by two routes}")
    assert "lost" in tex[route:tex.index(r"\section*{Result}")]


def test_the_tops_proof_is_its_condition_by_lagrange_and_by_eulers_equations():
    """Taylor ch. 10 (Lagrange's equation for the tilt in the Euler angles at a steady precession):
    the proof the handout ends with, the top's condition by both of the engine's routes, in the
    letters the student's route uses (theta, I_1 for what a fast top's question leaves out)."""
    proof = Solution(load("top_precession")).steps()
    assert set(proof) == {"lagrange", "newton_euler"}
    m, g, R, inertia, w, I1, theta = _symbols("m", "g", "Rcm", "I", "omega", "I_1", "theta")
    Omega = sp.Symbol("Omega", real=True)
    for steps in proof.values():
        (step,) = steps
        (condition,) = step.equations
        assert _same(condition.lhs, I1 * Omega**2 * sp.cos(theta) - inertia * w * Omega + m * g * R)


def test_a_pendulum_of_parts_takes_each_parts_moment_about_the_pivot_and_the_periods_own_name():
    """Halliday, Resnick & Walker 10th ed., ch. 15 (a physical pendulum of a rod and a disk: I about the
    pivot by the parallel-axis theorem, part by part: m L^2/12 + m (L/2)^2 + M r^2/2 + M (L + r)^2). A newcomer's
    clock pendulum printed I_P as two fractions no one could read, and its route ended T = 2 pi/omega beside
    the answer P."""
    from conftest import textbook

    (steps,) = Solution(load(textbook("rod_disk_clock_pendulum"))).student_steps.values()
    m, L, M, r = _symbols("m", "L", "M", "r")
    parts = steps[0].equations[0].rhs
    assert isinstance(parts, sp.Add) and len(parts.args) == 4
    assert _same(parts.doit(), m * L**2 / 12 + m * (L / 2) ** 2 + M * r**2 / 2 + M * (L + r) ** 2)
    assert str(steps[-1].equations[-1].lhs) == "P"


def test_a_body_of_parts_on_a_pivot_swings_by_energy_and_torque_part_by_part():
    """Serway & Jewett 9th ed., ch. 10 (a rod with a ball at its end, pivoted at the rod's other end, released
    horizontal): I about the pivot part by part, M L^2/3 + m L^2; the energy with each part's drop, M g L/2 + m g L;
    the torque at release the same sum. A newcomer's rod and ball had no student's route (composites were the
    engine's alone)."""
    from conftest import derived, textbook

    solution = derived(textbook("rod_with_ball_swings_down"))
    energy, torque = solution.student_steps.values()
    M, m, L, g = _symbols("M", "m", "L", "g")
    moment = energy[0].equations[0].rhs
    assert isinstance(moment, sp.Add) and len(moment.args) == 3 and _same(moment.doit(), M * L**2 / 3 + m * L**2)
    drops = energy[1].equations[0].rhs
    assert isinstance(drops, sp.Add) and len(drops.args) == 2 and _same(drops.doit(), M * g * L / 2 + m * g * L)
    turning = torque[0].equations[0].rhs
    assert len(turning.args) == 2 and _same(turning.doit(), M * g * L / 2 + m * g * L)
    assert sum(len(s.equations) for section in (energy, torque) for s in section) <= 7
    assert "textbook_route" in {c.name for c in solution.checks() if c.passed}


def test_a_simple_pendulum_swings_by_the_torque_about_the_cords_end_and_hangs_in_balance():
    """Halliday, Resnick & Walker 10th ed., ch. 15, Module 15-5 (the simple pendulum: I = m L^2 about the cord's
    fixed end, tau = -L (m g sin theta) ~ -m g L theta, omega = sqrt(g/L)), and the cord's pull at rest by the
    balance of forces. Both had been the engine's two routes: a period beside a force, and a bob on a cord."""
    from conftest import derived

    solution = derived("simple_pendulum_cord")
    swing, balance = solution.student_steps.values()
    m, L, g = _symbols("m", "L", "g")
    assert _same(swing[0].equations[0].rhs, m * L**2)
    kappa = swing[1].equations[-1].rhs
    assert _same(kappa, m * g * L) and "no moment" in swing[1].text
    assert _same(swing[2].equations[2].rhs, sp.sqrt(g / L)) and str(swing[2].equations[-1].lhs) == "T"
    assert balance[0].text == "The forces on the bob balance"  # a point mass: no torques to balance
    assert [str(e.lhs) for e in balance[-1].equations] == ["F"]  # the ask's own name: T is the period
    assert sum(len(s.equations) for section in (swing, balance) for s in section) <= 10
    assert "textbook_route" in {c.name for c in solution.checks() if c.passed}


def test_a_period_beside_a_force_at_rest_takes_the_swing_and_then_the_balance():
    """Serway & Jewett 9th ed., ch. 15 (a hoop on a nail: I = 2 M R^2 about the nail, T = 2 pi sqrt(2R/g)), and the
    nail's force at rest, M g up, by the balance; each finding beside the engine's (the check textbook_route)."""
    from conftest import derived

    solution = derived("hoop_on_nail")
    assert list(solution.student_steps) == ["Small oscillations about the pivot", "The forces at rest, in balance"]
    M, g = _symbols("M", "g")
    (solved,) = solution.student_steps["The forces at rest, in balance"][-1].equations
    assert _same(solved.rhs, M * g)
    compared = {what for what, _, _ in solution.textbook_route.compared}
    assert {"omega^2", "R_x^nail", "R_y^nail"} <= compared  # the frequency, and the nail's force at rest


def test_a_ball_rolling_in_a_bowl_swings_by_newton_along_its_path_and_the_torque_about_its_center():
    """Taylor, Classical Mechanics (2005), ch. 7 and Serway & Jewett 9th ed., ch. 15 (a ball rolling near the bottom of
    a bowl: M a = f - M g sin(phi), I alpha = f r, alpha = -a/r, so omega^2 = g/((1 + I/(M r^2))(R - r)) = 5g/(7(R - r))).
    It had been the engine's two routes."""
    from conftest import derived

    solution = derived("ball_in_bowl")
    (steps,) = solution.student_steps.values()
    M, g, R, r = _symbols("M", "g", "R", "r")
    newton, torque, motion = steps
    assert newton.text.startswith("The ball's center moves on a circle") and "Newton's second law" in newton.text
    assert torque.text.startswith("The torque about the center") and _same(torque.equations[-1].rhs, 2 * M * r**2 / 5)
    omega_squared = next(e.rhs for e in motion.equations if str(e.lhs) == "omega**2")
    assert _same(omega_squared.subs(sp.Symbol("I"), 2 * M * r**2 / 5), 5 * g / (7 * (R - r)))
    assert "textbook_route" in {c.name for c in solution.checks() if c.passed}


def test_an_impact_about_an_axle_gives_the_axles_impulse_by_the_change_of_momentum():
    """A bullet into a door (Young & Freedman ch. 10, "crime bust"), asked the hinge's impulse too: the
    route about the axle had given way to the impulse equations in components; now one more step, the
    only outside impulse is the change of the bodies' momentum (Serway & Jewett ch. 9)."""
    from conftest import derived, textbook

    solution = derived(textbook("bullet_into_door"))
    (section,) = solution.student_steps.values()
    last = section[-1]
    assert last.text.startswith("The axle's impulse is the only one from outside") and len(last.equations) == 1
    M, m, v = (solution.problem.parameters[n].symbol for n in ("M", "m", "v"))
    assert sp.simplify(last.equations[0].rhs + M * m * v / (4 * M + 3 * m)) == 0
    assert sum(len(s.equations) for s in section) <= 8


def test_an_impacts_kinetic_energies_take_the_asks_names_and_never_one_that_means_another_thing():
    """A flywheel and a clutch plate (Young & Freedman ch. 10) asked K1, the kinetic energy before: the route
    printed K_1 for the energy just after, beside the ask K1; now the energy before is K1 and the one after K_f."""
    from conftest import derived, textbook

    (section,) = derived(textbook("flywheel_clutch_plate")).student_steps.values()
    energies = next(step for step in section if step.text.startswith("The kinetic energy just before"))
    assert [str(e.lhs) for e in energies.equations] == ["K1", "K_f", "K1 - K_f"]
