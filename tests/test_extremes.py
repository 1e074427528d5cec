"""Every answer correct to 15 significant digits at the edges (issue: speed against accuracy).

The reference is the exact answer evaluated at 50 digits by sympy, independently of the
evaluation backends `derive solve` uses; the float64 backend is shown to lose digits where the
policy does not.
"""
import mpmath
import pytest
import sympy as sp

from conftest import close
from derive.numbers import numeric
from derive.language import problem
from derive.publishing import report
from derive.bench.runs import EXTREME_CASES
from derive.solution.answers import Solution
from derive.core.errors import ProblemError

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
        exact = solution.signed(name).xreplace(values)
        reference = mpmath.mpf(str(sp.N(exact, 50))) if exact != 0 else mpmath.mpf(0)
        sense = solution.senses[name]
        if sense is not None and not p.asks[name].magnitude:  # a magnitude, its direction in words
            assert answer["direction"] == (sense.of(1 if reference > 0 else -1) if reference else None), name
            reference = abs(reference)
        if reference == 0:
            assert answer["value"] == "0"
        else:
            assert close(mpmath.mpf(answer["value"]), reference), (name, answer["value"], reference)


def test_float64_alone_loses_digits_where_the_policy_does_not():
    """The beetle whose momentum nearly cancels the lazy Susan's: float64 keeps only a few digits."""
    p = problem.load("beetle_lazy_susan")
    overrides = {"m": "0.004", "R": "0.25", "I": "0.001", "omega0": "0.6", "v": "0.6000000000006"}
    values = p.values(overrides)
    omega = Solution(p).signed("omega")
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


def test_approximations_report_their_relative_error():
    """Small-angle period: T0/T - 1 ~ -theta0^2/16; small-angle turn: x/atan(x) - 1 ~ x^2/3."""
    pendulum = report.solve(problem.load("compound_pendulum_large"),
                            {"M": "2", "Rcm": "0.3", "I_cm": "0.05", "theta0": "0.1"}, 15)
    error = float(pendulum["answers"]["T_small"]["approximation"]["relative_error"])
    assert abs(error - (-0.1**2 / 16)) < 1e-5
    wheel = report.solve(problem.load("tilting_wheel"), {"tau": "1", "dt": "0.2", "I": "0.1", "omega": "30"}, 15)
    x = 1 * 0.2 / (0.1 * 30)
    assert abs(float(wheel["answers"]["dphi"]["approximation"]["relative_error"]) - x**2 / 3) < 1e-4
    assert wheel["answers"]["dphi"]["approximation"]["exact"] == "dphi_exact"


def test_bad_regions_are_clear_errors(derive):
    open_orbit = derive("solve", "kepler_orbit", "--set", "a=1e11", "--set", "e=1")
    assert open_orbit.returncode == 2 and "parabola or a hyperbola" in open_orbit.stderr
    slow_top = derive("solve", "top_precession_exact", "--set", "m=0.2", "--set", "Rcm=0.05", "--set", "I3=5e-5",
                      "--set", "I1=5e-4", "--set", "theta=0.5", "--set", "omega=30")
    assert slow_top.returncode == 2 and "no steady precession" in slow_top.stderr


def test_a_nearly_vertical_incline_without_enough_friction_is_refused():
    """At pi/2 - 1e-9 rolling needs mu_s >= 2/7 tan(theta) ~ 2.9e8: no mu_s of the range holds it."""
    steep = {"M": "1", "R": "0.1", "H": "1", "theta": mpmath.nstr(mpmath.pi / 2 - mpmath.mpf("1e-9"), 45)}
    with pytest.raises(ProblemError, match="mu_s >= mu_min does not hold"):
        report.solve(problem.load("rolling_incline"), steep, 15)
