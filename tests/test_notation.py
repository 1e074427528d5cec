"""Issue 15: no typeset symbol stands for two things in one document (derive.publishing.notation): the library's
worked solutions are free of clashes, a problem file's name that takes an engine symbol (V, T, K, a)
renames the engine's quantity in the document, and any other clash it makes is refused."""
from pathlib import Path

import pytest
import sympy as sp

from conftest import derived, notes_files, refused, run_derive, textbook, textbook_files, write_problem
from derive.core import library
from derive.publishing import notation, variants, worksheets
from derive.solution.answers import Solution
from derive.core.errors import ProblemError
from derive.mechanics.derivation import KINETIC, PERIOD, POTENTIAL
from derive.language.problem import load, parse

PENDULUM = (library.problems_dir() / "torque" / "compound_pendulum.yaml").read_text()
DISK = (library.problems_dir() / "torque" / "string_wrapped_disk.yaml").read_text()


def printed(problem) -> tuple[Solution, dict]:
    solution = Solution(problem)
    return solution, notation.named(problem, solution, solution.steps())


TEXTBOOK = textbook_files()


@pytest.mark.parametrize("path", notes_files() + TEXTBOOK, ids=lambda p: p.stem)
def test_worked_solutions_use_each_symbol_for_one_thing(path):
    """The library's problems and the textbook problems of the tests."""
    solution = derived(path)
    problem = solution.problem
    steps = notation.named(problem, solution, solution.steps())  # a clash nothing renames is refused
    assert notation.document_clashes(problem, solution, steps) == []
    if path not in TEXTBOOK:  # the library renames nothing but to its asks' own names
        assert symbols_of(steps) <= symbols_of(solution.steps()) | set(problem.asks)


def test_two_periods_in_one_document_are_two_symbols():
    """The large-amplitude pendulum asks T at its amplitude and T_small for small oscillations: each
    route's steps print both, each by its ask's name, and no longer T for both."""
    problem = load("compound_pendulum_large")
    solution, steps = printed(problem)
    for route in ("lagrange", "newton_euler"):
        equations = [e for s in steps[route] for e in s.equations]
        assert [e.lhs for e in equations if e.lhs in (sp.Symbol("T"), sp.Symbol("T_small"))] == [
            sp.Symbol("T_small"), sp.Symbol("T"), sp.Symbol("T")]
        assert sp.simplify(next(e.rhs for e in equations if e.lhs == sp.Symbol("T_small"))
                           - solution.signed("T_small")) == 0
    # the worked solution's and the handout's context (the handout adds its limiting cases to it)
    context = worksheets._solutions_context(variants.ProblemVariants(problem, solution, []), siunitx=True)
    typeset = "\n".join(e for route in context["routes"] for s in route["steps"] for e in s["equations"])
    assert typeset.count(r"T_{\mathrm{small}} &=") == 2 and r"\mathrm{exact}" not in typeset


def test_a_tension_asked_as_T_renames_the_period():
    """The spring-pulley problem asks T for the tension at equilibrium and the steps solve for the
    period of small oscillations, which no ask names: the worked solution calls it P."""
    problem = load(str(textbook("spring_pulley_block")))
    solution, steps = printed(problem)
    assert PERIOD in notation.step_symbols(solution.steps()["lagrange"])
    assert "T" not in symbols_of(steps) and "P" in symbols_of(steps)


def test_a_clash_is_found():
    tension, period = sp.Symbol("T_rope", real=True), sp.Symbol("T_rope")
    found = notation.clashes([("ask.P", "P", "the period")], {tension, period, sp.Symbol("P")},
                             {tension: "the tension of the rope"})
    assert [(c.latex, c.field) for c in found] == [(r"T_{\mathrm{rope}}", None)]  # the engine's own: no field
    found = notation.clashes([("parameters.T", "T", "the tension")], {PERIOD}, {})
    assert [(c.field, c.engine) for c in found] == [("parameters.T", PERIOD)]
    assert "the period" in found[0].message() and "the tension" in found[0].message()
    assert notation.clashes([("ask.T", "T", "the period")], {PERIOD}, {}, {"ask.T": PERIOD}) == []
    assert notation.clashes([("ask.K", "K", "the energy")], {KINETIC}, {}) != []


def symbols_of(steps) -> set[str]:
    return {s.name for s in notation.step_symbols(x for route in steps.values() for x in route)}


def test_an_ask_named_like_the_potential_energy_renames_it():
    problem = parse(PENDULUM.replace("  omega: {meaning: angular frequency", "  V: {meaning: angular frequency"), Path("v.yaml"))
    solution, steps = printed(problem)
    assert POTENTIAL in notation.step_symbols(solution.steps()["lagrange"])
    assert "V" not in symbols_of(steps) and "U" in symbols_of(steps)
    assert notation.document_clashes(problem, solution, steps) == []
    context = worksheets._solutions_context(variants.ProblemVariants(problem, solution, []), siunitx=True)
    proof = context["verification"] or context["routes"]  # the student's route first, Lagrange's in the proof
    lagrange = "\n".join(e for s in proof[0]["steps"] for e in s["equations"])
    assert "U &= M g y" in lagrange and "V &=" not in lagrange
    reference = Solution(load("compound_pendulum"))
    assert sp.simplify(solution.signed("V") - reference.signed("omega")) == 0  # the answer unchanged


def test_a_period_asked_as_P_and_a_frequency_named_T():
    text = PENDULUM.replace("  omega: {meaning: angular frequency", "  T_: {meaning: angular frequency")
    text = text.replace("  T: {meaning: period", "  P: {meaning: period").replace("  T_:", "  T:")
    problem = parse(text, Path("t.yaml"))
    solution, steps = printed(problem)
    assert "T" not in symbols_of(steps) and "P" in symbols_of(steps)  # the period by its ask's name
    assert notation.document_clashes(problem, solution, steps) == []


def test_an_ask_named_like_an_unknown_force_is_refused(tmp_path):
    text = DISK.replace("  alpha:", "  T_string:")
    message = refused(tmp_path, text, "ask.T_string")
    assert "the force T_string" in message and "rename it" in message
    result = run_derive("sheet", str(write_problem(tmp_path, text)), "--to", "", "--out", str(tmp_path / "out"))
    assert result.returncode == 2 and "ask.T_string" in result.stderr, result.stderr
    with pytest.raises(ProblemError, match="ask.T_string"):
        printed(parse(text, Path("disk.yaml")))
