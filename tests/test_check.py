"""`derive check` and the simulation check: they pass on the library and catch what is wrong."""
import difflib
import re

import pytest
import sympy as sp

from conftest import ROOT, copy_library, derived, run_derive, student_solution
from derive.core import library
from derive.checks import simulate
from derive.solution.answers import Solution
from derive.solution.crosschecks import CheckFailure
from derive.language.problem import load
from derive.publishing import worksheets
from derive.text import prose


def test_simulation_agrees_with_the_closed_forms():
    report = simulate.check(Solution(load("compound_pendulum")))
    assert report.passed and report.compared == ["omega", "T"]


def test_the_simulated_acceleration_at_release_agrees_where_it_changes_as_the_body_turns(monkeypatch):
    """A trapdoor pulled up at its edge from rest (Young & Freedman ch. 10): its angular acceleration
    changes with the angle, which grows as t^2. The mean over the first millisecond extrapolated once
    (which leaves that t^2 term) was 1.1e-6 off the closed form, and `derive check` failed a right file;
    extrapolated twice, it agrees to 1e-8."""
    seen = {}
    compare = simulate.compare
    monkeypatch.setattr(simulate, "compare", lambda report, name, simulated, exact, values:
                        seen.setdefault(name, (simulated, float(sp.N(exact.xreplace(values), 20))))
                        and compare(report, name, simulated, exact, values))
    report = simulate.check(derived(ROOT / "tests" / "textbook" / "trapdoor_pulled_at_its_edge.yaml"))
    simulated, exact = seen["alpha"]
    assert report.passed and abs(simulated - exact) <= 1e-8 * abs(exact), (simulated, exact)


def test_a_block_let_go_near_its_pulley_is_simulated_over_a_shorter_run(recwarn):
    """atwood_pulley_speed's blocks reach their pulleys within the second: LSODA's steps went past the
    event that stops a run there, to where the cord's geometry takes the root of a negative number, and
    `derive check` stopped with an internal error (LinAlgError: Singular matrix) after a page of numpy's
    warnings. The release is now simulated over a shorter run, and nothing is printed."""
    report = simulate.check(derived("atwood_pulley_speed"))
    assert report.passed, report.notes
    assert not [w for w in recwarn if issubclass(w.category, RuntimeWarning)], [str(w.message) for w in recwarn]


def test_simulation_catches_a_wrong_closed_form():
    solution = Solution(load("string_wrapped_disk"))
    solution.expressions["a"] = solution.expressions["a"] * sp.Rational(101, 100)  # 1% off
    report = simulate.check(solution)
    assert not report.passed and "a: simulation" in report.notes[0]


def test_check_command_prints_a_table_and_passes(derive):
    done = derive("check", "string_wrapped_disk", "rod_endpoint", "beetle_lazy_susan", "circular_motion_L")
    assert done.returncode == 0, done.stdout + done.stderr
    lines = done.stdout.splitlines()
    assert lines[0].split()[:2] == ["problem", "independent"]
    assert "lagrange_vs_newton_euler" in done.stdout and "ok: a, alpha" in done.stdout
    assert "states" in done.stdout and "path_vs_mechanics" in done.stdout  # the beetle: an impact in states
    assert "4 passed, 0 failed" in done.stdout


def test_check_command_fails_with_exit_1(tmp_path):
    library = copy_library(tmp_path)
    disk = library / "torque" / "string_wrapped_disk.yaml"
    disk.write_text(disk.read_text().replace("block.acceleration.y, unit: m/s^2,", "block.acceleration.y, unit: m/s,"))
    done = run_derive("check", "string_wrapped_disk", library=library)
    assert done.returncode == 1
    assert "0 passed, 1 failed" in done.stdout and "FAILED string_wrapped_disk" in done.stdout


def test_the_work_energy_theorem_is_checked(monkeypatch):
    solution = Solution(load("tugged_spool"))
    assert any(c.name == "work_energy" for c in solution.checks())
    ledger = solution.energy_ledger()
    assert ledger["power_nonconservative"] != 0
    wrong = {**ledger, "power_nonconservative": ledger["power_nonconservative"] * 2}
    monkeypatch.setattr(Solution, "energy_ledger", lambda self, scene=None: wrong)
    try:
        Solution(load("tugged_spool"))._work_energy_check()
    except CheckFailure as failure:
        assert "work-energy" in str(failure)
    else:
        raise AssertionError("a wrong power passed the work-energy check")


def test_simulation_checks_the_work_of_the_pull(monkeypatch):
    monkeypatch.setattr(simulate, "nonconservative_power", lambda scene, coords: sp.Integer(0))  # pretend the pull does no work
    report = simulate.check(Solution(load("tugged_spool")))
    assert not report.passed and "work-energy" in report.notes[0]


READINGS = [p.stem for p in library.problem_files()]


def _reads_as_a_sentence(text: str) -> bool:
    """Prose a student can read: a capitalised sentence, no engine words or ASCII pseudo-math."""
    return (text[:1].isupper() and text.endswith(".") and "(symbolic)" not in text and "(numeric)" not in text
            and not any(w in text for w in ("lagrange_vs", "_vs_", "T + V", "d/dt(", "dL/dq", "I_cm")))


#: ASCII pseudo-math that must not stand in a step's prose (the equations carry the math).
PSEUDO_MATH = ("d/d", "''", "^", ">=", "<=", "**", "sqrt(", "exp(", "sum_", "mu_", "_cm", "[m/s")


@pytest.mark.parametrize("problem_id", READINGS)
def test_every_check_and_step_of_the_library_reads_as_prose(problem_id):
    """Worked solutions and handouts print each check's reading (issue 15): "Energy is conserved:
    the constraint forces do no work.", never "work_energy: T + V conserved (numeric)"; and each
    step's sentence says in words what its equations say in math (no d/dt(dL/dq'), no mu_s N >= |f|),
    and so does each part's sentence, its math kept apart from its words (derive.text.prose)."""
    solution = derived(problem_id)
    checks = solution.checks()
    assert checks and all(_reads_as_a_sentence(c.reading) for c in checks), [c.reading for c in checks]
    meanings = {a.meaning for a in solution.problem.asks.values()}  # the file's words, which a step may quote
    texts = [step.text for steps in solution.steps().values() for step in steps if step.text not in meanings]
    assert not [t for t in texts if any(p in t for p in PSEUDO_MATH)], texts  # some systems have no steps yet
    said = [s.words for steps in solution.steps().values() for step in steps for s in step.sentences]  # the parts'
    assert not [t for t in said if any(p in t for p in PSEUDO_MATH) or not _reads_as_a_sentence(t)], said


#: Words a fragment opens with: a heading or a step's lead that continues the one before.
FRAGMENT = re.compile(r"(and|or|but|of|their|its)\b", re.I)
GREEK_WORDS = {"alpha", "beta", "gamma", "delta", "theta", "phi", "psi", "omega", "mu", "tau", "lambda", "rho", "sigma"}


def _prose(tex: str) -> list[str]:
    """The prose of a worked solution, paragraph by paragraph (a heading, a step's lead before its
    equations, the sentences of a step): its equations, figures and numbers left out."""
    body = tex[tex.index("\\maketitle") + len("\\maketitle"):]
    body = re.sub(r"\\begin\{(align\*|center)\}.*?\\end\{\1\}", "\n\n", body, flags=re.S)
    body = re.sub(r"\\\[.*?\\\]", " ", body, flags=re.S)  # a long piece of a sentence's math, displayed
    body = body.split("\\subsection*{Numbers for")[0]
    return [p.strip() for p in re.split(r"\n", body) if p.strip() and not p.startswith("\\section{")]


def _lone_symbols(paragraph: str, names: set[str]) -> list[str]:
    """The problem's symbols (and Greek letters' names) in a paragraph's running text, not set as math."""
    text = re.sub(r"\\[a-zA-Z]+\*?", " ", re.sub(r"\$[^$]*\$", " ", paragraph)).replace("\\_", "_")
    return [w for w in re.findall(r"(?<![\w\\'’])([A-Za-z]\w*)(?!\w)", text) if w in names or w in GREEK_WORDS]


def _unreadable(tex: str, names: set[str]) -> tuple[list, list, list]:
    """(the fragments, the repeated paragraphs, the lone symbols) of a worked solution's prose."""
    paragraphs = _prose(tex)
    fragments, repeated, lone = [], [], []
    for paragraph, after in zip(paragraphs, paragraphs[1:] + [""]):
        heading = re.fullmatch(r"\\subsection\*\{(.*)\}", paragraph)
        lead = heading.group(1) if heading else paragraph
        if not paragraph.startswith(r"\textbf") and (not lead[:1].isupper() and not lead.startswith("$")
                                                     or FRAGMENT.match(lead)):
            fragments.append(lead)
        if paragraph.endswith(".") and after.endswith(":") and prose.repeats(re.split(r"(?<=\.) ", paragraph)[-1], after):
            repeated.append((paragraph, after))
        if paragraph.endswith(".") and after.endswith(".") and \
                difflib.SequenceMatcher(None, paragraph.split(), after.split()).ratio() > 0.8:
            repeated.append((paragraph, after))
        lone += _lone_symbols(paragraph, names)
    return fragments, repeated, lone


def test_the_prose_checks_find_what_the_issue_found():
    """Issue 37's own examples, each found."""
    tex = "\\maketitle\n" + "\n".join([
        r"\subsection*{and, their rates, on the accelerations}",
        "The constraints leave one coordinate of the scene: the kinetic energy is a function of it times the square "
        "of its rate.", "The constraints leave one coordinate; the kinetic energy in its rate:",
        "Energy conservation from rest as the center drops h, at $v$.", "With omega found in Lagrange's equations."])
    fragments, repeated, lone = _unreadable(tex, {"h", "v"})
    assert fragments == ["and, their rates, on the accelerations"]
    assert [after for _, after in repeated] == ["The constraints leave one coordinate; the kinetic energy in its rate:"]
    assert lone == ["h", "omega"]


@pytest.mark.parametrize("problem_id", READINGS)
def test_every_worked_solution_reads_as_prose(problem_id):
    """Issue 37, item 7, over the LaTeX a student is given of each library problem: every heading and
    every step's lead opens with a capital and is no fragment ("Step 3: and, their rates, on the
    accelerations"); no lead before a step's equations says again what the sentence before it just
    said (derive.text.prose.repeats), and no paragraph is followed by a near-copy of itself; a symbol
    of the problem in running text is set as math ("as the center drops $H$"), and so is a Greek
    letter (no "omega" in words)."""
    tex, _ = student_solution(problem_id)
    solution = derived(problem_id)
    steps = {**solution.steps(), **(solution.student_steps or {})}
    names = {n for n in worksheets.symbol_names(solution.problem, steps) if not prose.stays_a_word(n)}
    fragments, repeated, lone = _unreadable(tex, names)
    assert not fragments, fragments
    assert not repeated, repeated
    assert not lone, lone


INCLINE_AND_PULLEY = """
id: incline_pulley_short
title: A block on a smooth incline tied over a massive pulley to a hanging block
parameters:
  m1: {meaning: mass of the block on the incline, unit: kg, value: 3}
  m2: {meaning: mass of the hanging block, unit: kg, value: 5}
  M: {meaning: mass of the pulley, unit: kg, value: 2}
  R: {meaning: radius of the pulley, unit: m, value: 0.1}
  theta: {meaning: angle of the incline, unit: deg, value: 30}
  D: {meaning: distance of each block from the pulley, unit: m, value: 0.5}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  surfaces:
    ramp: {plane: {angle: theta, through: [0, 0], descends: left}}
  bodies:
    pulley: {shape: disk, mass: M, radius: R, at: [R*sin(theta), -R*cos(theta)], joint: fixed_axle}
    block: {shape: point, mass: m1, at: [-D*cos(theta), -D*sin(theta)], on: ramp, contact: sliding}
    hanger: {shape: point, mass: m2, at: [R + R*sin(theta), -R*cos(theta) - D]}
  cords:
    rope: [block, {over: pulley}, hanger]
  loads:
    - gravity: g
ask:
  a: {meaning: acceleration of the hanging block, of: hanger.acceleration.y, unit: m/s^2}
question: A block on an incline is tied over a pulley to a hanging block. Find the acceleration.
"""


def test_a_simulation_stops_where_a_cords_run_shrinks_to_nothing(tmp_path):
    """A trial's block pulled up an incline to a pulley (Serway ch. 10): in the simulated second
    the block reached the pulley, the cord's equations took the root of a negative number, and
    `derive check` reported FAILED (LSODA's 'Unexpected istate') with numpy's warnings, though
    every answer was right. Both runs now stop where a run of the cord is down to a hundredth of
    its length, say so, and the acceleration is compared over the time they lasted."""
    (tmp_path / "incline.yaml").write_text(INCLINE_AND_PULLEY)
    solution = Solution(load(tmp_path / "incline.yaml"))
    report = simulate.check(solution)
    assert report.passed, report.notes
    assert report.compared == ["a"]
    assert any("shrink to nothing" in why for _, why in report.unchecked), report.unchecked


@pytest.mark.parametrize("old, new, ask", [
    # the rod's angle "from the horizontal" came out -1.22 rad (below it), its center's "height" -0.30 m
    ("angle of the rod below the horizontal at its highest, of: rod.angle, in: highest, unit: rad, magnitude: true",
     "angle of the rod from the horizontal at its highest, of: rod.angle, in: highest, unit: rad", "angle"),
    ("depth of its center below the pin then, of: rod.position.y, in: highest, unit: m, magnitude: true",
     "height of its center then, of: rod.position.y, in: highest, unit: m", "h"),
])
def test_check_refuses_a_negative_answer_whose_sign_the_question_does_not_state(tmp_path, old, new, ask):
    text = load("rod_swing_stops").path.read_text()
    assert old in text
    path = tmp_path / "rod.yaml"
    path.write_text(text.replace(old, new))
    done = run_derive("check", str(path))
    assert done.returncode == 1, done.stdout + done.stderr
    assert f"FAILED rod_swing_stops: ask.{ask}: -" in done.stdout
    assert "where the question states no sign convention: ask its magnitude (magnitude: true)" in done.stdout
    stated = text.replace(old, new.replace("unit: rad", "unit: rad, sign: \"negative: below\"").replace(
        "unit: m", "unit: m, sign: \"negative: below\"")).replace("find its angle", "find (negative: below) its angle")
    path.write_text(stated)
    done = run_derive("check", str(path))
    assert done.returncode == 0, done.stdout + done.stderr


@pytest.mark.parametrize("problem_id, reading", [
    ("sticky_impact_pivoted", "Energy is conserved while the bodies move between the events: the constraint forces do "
                              "no work; the impact, in an instant, is not part of this check."),
    ("bowling_ball_skids", "The energy changes only by the work of the applied forces and of kinetic friction where "
                           "it slides: the other constraint forces do no work."),
    ("rolling_incline", "Energy is conserved: the constraint forces do no work."),
])
def test_the_work_energy_reading_is_true_of_the_scene(problem_id, reading):
    """Issue 37: "Energy is conserved: the constraint forces do no work." stood beside a sticky
    impact's loss of energy, and "the constraint forces do no work" beside kinetic friction's."""
    (check,) = [c for c in derived(problem_id).checks() if c.name == "work_energy"]
    assert check.reading == reading
