"""Every answer correct to 15 significant digits at the edges (issue: speed against accuracy).

The reference is the exact answer evaluated at 50 digits by sympy, independently of the
evaluation backends `derive solve` uses; the float64 backend is shown to lose digits where the
policy does not.
"""
import mpmath
import pytest
import sympy as sp

from conftest import close
from derive import numeric, problem, report
from derive.bench import EXTREME_CASES
from derive.answers import Solution

EXTREMES = EXTREME_CASES


@pytest.mark.parametrize("problem_id, overrides", EXTREMES, ids=[f"{p}-{i}" for i, (p, _) in enumerate(EXTREMES)])
def test_fifteen_digits_at_the_edges(problem_id, overrides):
    p = problem.load(problem_id)
    result = report.solve(p, overrides, 15)
    solution = Solution(p)
    values = p.values(overrides)
    for name, answer in result["answers"].items():
        if answer["value"] is None:
            continue
        exact = solution.expressions[name].xreplace(values)
        reference = mpmath.mpf(str(sp.N(exact, 50))) if exact != 0 else mpmath.mpf(0)
        if reference == 0:
            assert answer["value"] == "0"
        else:
            assert close(mpmath.mpf(answer["value"]), reference), (name, answer["value"], reference)


def test_float64_alone_loses_digits_where_the_policy_does_not():
    """The beetle whose momentum nearly cancels the lazy Susan's: float64 keeps only a few digits."""
    p = problem.load("beetle_lazy_susan")
    overrides = {"m": "0.004", "R": "0.25", "I": "0.001", "omega0": "0.6", "v": "0.6000000000006"}
    values = p.values(overrides)
    omega = Solution(p).expressions["omega"]
    reference = mpmath.mpf(str(sp.N(omega.xreplace(values), 50)))
    fast = numeric.evaluate(omega, values, 15, backend="float")
    policy = numeric.evaluate(omega, values, 15, backend="auto")
    assert close(mpmath.mpf(policy), reference)
    assert not close(mpmath.mpf(fast), reference, 8)


def test_spool_at_exactly_the_critical_angle_does_not_accelerate():
    """theta given exactly as acos(r/R) (an expression, exact): the acceleration is exactly zero."""
    result = report.solve(problem.load("tugged_spool"), {"F": "5", "M": "1", "R": "0.06", "r": "0.02",
                                                         "I_cm": "0.001", "theta": "acos(1/3)"}, 15)
    assert result["answers"]["a"]["value"] == "0"
