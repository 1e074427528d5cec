"""Inverse asks: the value of a parameter at which an asked quantity takes a given value.

`find: N` with `equals: pi/6` asks the N that makes the quantity of `of:` equal pi/6 (how many
turns a reaction wheel makes to turn a satellite by 30 degrees); `zero_for: d` is `find: d` with
`equals: 0` (the least release distance, where the normal force at the loop's top vanishes).

sympy solves the equation exactly. Its roots are kept where they are real and of the parameter's
sign; a parameter with a range keeps those that land in it for some of the other parameters'
values. One root must remain, and it must be the only one at each point of the ranges the check
visits: there, the equation's sign changes over the parameter's range, counted on a fine grid,
must be as many as the roots inside it. sympy gives one turn of a periodic equation's roots, and
a scan that finds more refuses the ask rather than hand a key the wrong branch. The root, put
back into the equation, must make it hold to 30 digits at those points.

>>> import sympy as sp
>>> from types import SimpleNamespace
>>> from derive.language.problem import load
>>> problem = load("block_ramp_into_loop")
>>> ask = problem.asks["d_min"]
>>> R, d, m, g = (problem.parameters[n].symbol for n in ("R", "d", "m", "g"))
>>> solved(problem, m * g * (3 * d - 23 * R / 2) / (5 * R), ask)  # a normal force, linear in d
23*R/6
"""
from __future__ import annotations

import math

import mpmath
import sympy as sp

from derive.core import units
from derive.core.tidying import tidy
from derive.solution.crosschecks import sample_points

#: Points of the parameter's range where the scan reads the equation's sign, per point of the others.
SCAN = 400


def solved(problem, expr: sp.Expr, ask) -> sp.Expr:
    """The value of the parameter `ask.zero_for` at which `expr` equals `ask.equals` (see the module)."""
    parameter = problem.parameters[ask.zero_for]
    symbol, field = parameter.symbol, f"ask.{ask.name}.{ask.finds}"
    if ask.equals != 0 and expr != 0:
        found, given = (units.expression_dimension(e, problem.symbol_units) for e in (expr, ask.equals))
        if not units.same_dimension(found, given):
            raise problem.error(f"ask.{ask.name}.equals", f"{ask.path} has dimension {found or 'none'}, but "
                                f"{sp.sstr(ask.equals)} has {given or 'none'}")
    equation = sp.numer(sp.together(expr - ask.equals))
    try:
        roots = sp.solve(equation, symbol)
    except NotImplementedError:
        raise problem.error(field, f"sympy cannot solve {ask.path} = {sp.sstr(ask.equals)} for {ask.zero_for}") from None
    roots = [r for r in roots if not r.has(sp.I) and (r.is_nonnegative is not False or not symbol.is_positive)]
    points = sample_points(problem, sp.Tuple(equation, *roots), count=8)
    if parameter.range is not None:
        low, high = parameter.si_ends  # the roots are in SI, as the symbol is
        inside = [r for r in roots if any(_within(r, p, low, high) for p in points)]
        roots = inside or roots
    if len(roots) != 1:
        said = "vanishes" if ask.equals == 0 else f"is {sp.sstr(ask.equals)}"
        hint = (f" (a range for {ask.zero_for} that holds one of them, at the middle of the others', chooses it)"
                if len(roots) > 1 else "")
        raise problem.error(field, f"{ask.path} {said} at {len(roots)} values of {ask.zero_for}, not one: "
                            f"{', '.join(_said(r) for r in roots) or 'none'}{hint}")
    root = tidy(roots[0])
    real = [p for p in points if sp.N(root.xreplace({s: v for s, v in p.items() if s != symbol}), 30).is_real]
    if not real:
        raise problem.error(field, f"{ask.path} takes the value asked at no real {ask.zero_for} over the ranges "
                            f"({sp.sstr(root)}): narrow the ranges of the others to where it does")
    for point in real:  # where the root is not real, the variant is redrawn (answer_conditions: in its range)
        _check(problem, field, equation, symbol, root, point, parameter)
    if ask.finds == "find" and parameter.range is not None and \
            not any(_within(root, p, *parameter.si_ends) for p in sample_points(problem, root, count=20)):
        raise problem.error(field, f"{ask.zero_for} = {sp.sstr(root)} lies outside its range [{parameter.range[0]}, "
                            f"{parameter.range[1]}] {parameter.unit} at every point of the others' ranges: a variant's "
                            f"answer is a value of {ask.zero_for} in its range (widen it)")
    return root


def _within(root: sp.Expr, point: dict, low: sp.Expr, high: sp.Expr) -> bool:
    """Whether a root is real and in [low, high] at a point of the ranges."""
    value = sp.N(root.xreplace(point), 30)
    return bool(value.is_real and low <= value <= high)


def _said(root: sp.Expr) -> str:
    """A root as a message names it: a root by cases is long and says little."""
    return "a root by cases" if root.has(sp.Piecewise) else sp.sstr(root)


def _check(problem, field: str, equation: sp.Expr, symbol: sp.Symbol, root: sp.Expr, point: dict, parameter) -> None:
    """At one point of the other parameters: the root solves the equation, and it is the only one in
    the parameter's range (a scan of the equation's sign over the range)."""
    others = {s: v for s, v in point.items() if s != symbol}
    value = sp.N(root.xreplace(others), 30)
    if not value.is_real:
        raise problem.error(field, f"{parameter.name} is not real at {_where(others)}: {sp.sstr(root)}")
    residual = sp.N(equation.xreplace({**others, symbol: value}), 30)
    scale = max((abs(sp.N(t.xreplace({**others, symbol: value}), 30)) for t in sp.Add.make_args(sp.expand(equation))),
                default=0)
    if abs(residual) > 1e-20 * max(scale, 1e-300):
        raise problem.error(field, f"{parameter.name} = {sp.sstr(root)} does not solve the equation at {_where(others)}")
    if parameter.range is None:
        return
    low, high = (float(e) for e in parameter.si_ends)
    function = sp.lambdify(symbol, equation.xreplace(others), "mpmath")
    grid = [low + (high - low) * k / SCAN for k in range(SCAN + 1)]
    signs = [s for s in (_sign(function, x) for x in grid) if s]  # a grid point on a root, or not real, skipped
    changes = sum(1 for a, b in zip(signs, signs[1:]) if a != b)
    inside = low <= float(value) <= high
    if changes != int(inside):
        raise problem.error(field, f"{parameter.name} takes the asked value {changes} times in its range at "
                            f"{_where(others)}, where the solved root gives {int(inside)}: not one answer")


def _sign(function, x: float) -> int:
    try:
        value = complex(function(mpmath.mpf(x)))
    except (ZeroDivisionError, ValueError, TypeError):
        return 0
    if abs(value.imag) > 1e-12 * max(1.0, abs(value.real)) or not math.isfinite(value.real):
        return 0
    return (value.real > 0) - (value.real < 0)


def _where(point: dict) -> str:
    return ", ".join(f"{s} = {float(v):.4g}" for s, v in sorted(point.items(), key=lambda i: str(i[0])))
