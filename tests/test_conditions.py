"""Conditions declared in problem files: parsed safely, checked in SI units, enforced by the
sampler (redraws), by `derive solve` and by `derive check --seeds`."""
import os
import random
import re
import subprocess
import sys
from decimal import Decimal

import pytest
import sympy as sp

from conftest import copy_library, run_derive
from derive.core import expr, units
from derive.publishing import variants
from derive.solution.answers import Solution
from derive.core.errors import ProblemError
from derive.language.problem import load, parse

r, R, e = sp.symbols("r R e")


def test_inequalities_parse_into_signed_differences():
    assert expr.parse_condition("r < R", {"r": r, "R": R}) == [(R - r, True)]
    assert expr.parse_condition("r >= 2*R", {"r": r, "R": R}) == [(r - 2 * R, False)]
    assert expr.parse_condition("0 <= e < 1", {"e": e}) == [(e, False), (1 - e, True)]


@pytest.mark.parametrize("text, reason", [
    ("r == R", "'==' is not allowed"),
    ("r", "expected an inequality"),
    ("r < R and R < r", "expected an inequality"),
    ("(r < R) + 1 > 0", "comparisons are not allowed"),
    ("r < __import__('os')", "function '__import__' is not allowed"),
    ("r < x", "unknown symbol 'x'"),
])
def test_bad_inequalities_are_refused(text, reason):
    with pytest.raises(expr.ExprError, match=reason):
        expr.parse_condition(text, {"r": r, "R": R})


@pytest.mark.parametrize("condition, field, reason", [
    ("{holds: b <= m, because: x}", "conditions[0].holds", "different dimensions"),
    ("{holds: b <= 0.3, because: x}", "conditions[0].holds", "different dimensions"),
    ("{holds: b <= Q, because: x}", "conditions[0].holds", "unknown symbol 'Q'"),
    ("{holds: b <= R}", "conditions[0].because", "missing"),
    ("{holds: b <= R, because: x, why: y}", "conditions[0].why", "unknown key"),
    ("b <= R", "conditions[0]", "expected a mapping"),
])
def test_bad_conditions_name_the_field(condition, field, reason, tmp_path):
    text = load("sticky_impact_pivoted").path.read_text().replace(
        "conditions:\n  - {holds: b <= R, because: the mass must hit the sphere (an impact parameter beyond R misses it)}",
        f"conditions:\n  - {condition}")
    with pytest.raises(ProblemError, match=rf"problem\.yaml: {re.escape(field)}: .*{reason}"):
        parse(text, tmp_path / "problem.yaml")


def _si(problem, draw):
    return {p.symbol: draw[n] * units.si_factor(units.parse_unit(p.unit)) for n, p in problem.parameters.items()}


def test_the_sampler_redraws_until_an_answer_condition_holds():
    """rolling_incline declares mu_s >= mu_min, an asked quantity: steep inclines need more
    friction than some draws offer, and those draws are redrawn."""
    problem = load("rolling_incline")
    solution = Solution(problem)
    mu_min = solution.expression("mu_min")
    rejected = 0
    for seed in range(40):
        plain = variants.draw(problem, random.Random(f"{seed}/rolling_incline/1"))
        rejected += bool(plain["mu_s"] < mu_min.xreplace(_si(problem, plain)))
        valid = variants.valid_draw(problem, solution, random.Random(f"{seed}/rolling_incline/1"))
        assert valid["mu_s"] >= mu_min.xreplace(_si(problem, valid))
    assert rejected > 0  # the condition did reject some plain draws


def test_a_parameter_condition_widens_nothing_it_should_not():
    problem = load("sticky_impact_pivoted")
    solution = Solution(problem)
    draws = [variants.valid_draw(problem, solution, random.Random(n)) for n in range(30)]
    assert all(d["b"] <= d["R"] for d in draws)
    assert any(variants.draw(problem, random.Random(n))["b"] > variants.draw(problem, random.Random(n))["R"]
               for n in range(30))


def test_solve_refuses_parameters_that_break_a_declared_condition(derive):
    done = derive("solve", "sticky_impact_pivoted", "--set", "b=0.3", "--set", "R=0.2", "--set", "m=0.1",
                  "--set", "M=1", "--set", "v=3")
    assert done.returncode == 2
    assert done.stderr.count("\n") == 1
    assert "sticky_impact_pivoted.yaml: parameters: b <= R does not hold: the mass must hit the sphere" in done.stderr


def test_unsatisfiable_conditions_are_an_error_naming_the_problem(tmp_path):
    library = copy_library(tmp_path)
    spool = library / "torque" / "tugged_spool.yaml"
    spool.write_text(spool.read_text().replace("holds: r < R", "holds: r > R"))
    done = run_derive("check", "--seeds", "2", "tugged_spool", library=library)
    assert done.returncode == 1
    assert "tugged_spool.yaml: parameters: no draw in 200 meets the problem's conditions" in done.stdout
    assert "200 of 200 draws broke this one: r > R does not hold" in done.stdout  # the one that breaks, alone


def test_a_magnitude_whose_sign_was_read_at_samples_is_checked_at_each_variant(monkeypatch):
    """rolling_incline's f (magnitude: true) is 2 M g sin(theta)/7, its sign read at samples of the
    ranges: every variant checks that it is not negative there, so a formula whose sign changed
    between the samples is refused, never printed as a magnitude."""
    solution = Solution(load("rolling_incline"))
    (condition,) = [c for c, _, meaning in solution.conditions if meaning.startswith("f, a magnitude")]
    assert sp.simplify(condition - solution.expression("f")) == 0
    values = variants.ProblemVariants(solution.problem, solution, []).si_values(
        {n: p.value if p.range is None else p.at(Decimal("0.5")) for n, p in solution.problem.parameters.items()})
    assert solution.violated(values) is None
    theta = solution.problem.parameters["theta"].symbol
    assert solution.violated_at(condition, False, {**values, theta: -values[theta]})  # f < 0 there: refused


def test_sample_points_are_the_same_whatever_the_hash_seed():
    """The points a sign is read at (a magnitude, a root in range) do not depend on the order of a
    set of symbols, which changes with PYTHONHASHSEED: a key built twice is the same."""
    script = ("from derive.solution.crosschecks import sample_points; from derive.language.problem import load; import sympy as sp; "
              "p = load('tugged_spool'); e = sum(q.symbol for q in p.parameters.values()); "
              "print(sorted((str(k), str(v)) for point in sample_points(p, e) for k, v in point.items()))")
    runs = {subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                           env={**os.environ, "PYTHONHASHSEED": str(seed)}).stdout for seed in (0, 3, 7)}
    assert len(runs) == 1 and runs != {""}
