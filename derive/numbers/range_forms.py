"""An expression in the form a teacher writes it for the values a problem draws: what holds over the
parameter ranges, proven there, for printing only (the value is the same at every point of them).

`tidy` (derive.core.tidying) keeps what holds for every value of the symbols: a root of tan^2 + 1 stays
a root, |cos(beta)| stays absolute, acos(sin(alpha)) stays as it is, since none of them is simpler for
every angle. Over the ranges the file gives they are: `within` rewrites

- a root of a product that expands shorter, expanded (a product of conjugates);
- tan(x)^2 + 1 as 1/cos(x)^2 (an identity; sympy's own trigsimp does it, but searches every
  identity of the whole expression, for minutes on long ones: this rewrites the sum alone);
- |x| as x or -x where the sign of x is proven over the ranges (derive.numbers.intervals), so that
  sqrt(tan^2(beta) + 1) is 1/cos(beta) for an incline's angle;
- asin(sin(a)), acos(cos(a)), acos(sin(a)) and asin(cos(a)) as a, a, pi/2 - a, pi/2 - a where a lies
  in the interval of the inverse function's values over the ranges (sympy rewrites them only for
  numbers; no sympy function takes the ranges of a symbol that is not a number).

The documents print each expression (the steps', the answers') through it, with the box of the
problem's parameter ranges (`box`); the keys and `derive solve` keep the derived expression.

>>> import sympy as sp
>>> alpha, beta, v, g = sp.symbols("alpha beta v g", positive=True)
>>> box = {alpha: (0, sp.pi / 3), beta: (sp.pi / 18, sp.pi / 6), v: (1, 2), g: (9, 10)}
>>> within(sp.acos(sp.sin(alpha)), box), within(v * sp.sqrt(sp.tan(beta)**2 + 1) / g, box)
(-alpha + pi/2, v/(g*cos(beta)))
"""
from __future__ import annotations

import dataclasses

import sympy as sp

from derive.numbers import intervals

#: (inverse, function) -> (the interval of the inverse's values, what inverse(function(a)) is there).
_INVERSES = {
    (sp.asin, sp.sin): ((-sp.pi / 2, sp.pi / 2), lambda a: a),
    (sp.acos, sp.cos): ((0, sp.pi), lambda a: a),
    (sp.acos, sp.sin): ((-sp.pi / 2, sp.pi / 2), lambda a: sp.pi / 2 - a),
    (sp.asin, sp.cos): ((0, sp.pi), lambda a: sp.pi / 2 - a),
}


def box(problem) -> dict[sp.Symbol, tuple[sp.Expr, sp.Expr]]:
    """Each parameter's symbol and its least and greatest value in SI units (a fixed value twice)."""
    return {p.symbol: p.si_ends for p in problem.parameters.values() if p.range is not None or p.value is not None}


def within(expr, ranges: dict[sp.Symbol, tuple[sp.Expr, sp.Expr]]):
    """`expr` (an expression or an equation) as it reads over `ranges` (the module's rewrites); an
    object that is not sympy's, or that the ranges settle nothing of, as it is."""
    if isinstance(expr, sp.Eq):
        return sp.Eq(within(expr.lhs, ranges), within(expr.rhs, ranges), evaluate=False)
    if not isinstance(expr, sp.Expr) or not expr.has(sp.tan, sp.Abs, sp.asin, sp.acos, sp.Pow):
        return expr
    expr = expr.replace(_pythagorean, lambda e: _pythagorean(e))
    expr = expr.replace(_shorter_root, lambda e: _shorter_root(e))
    expr = expr.replace(lambda e: _inverse(e, ranges) is not None, lambda e: _inverse(e, ranges))
    return expr.replace(lambda e: isinstance(e, sp.Abs) and _signed(e.args[0], ranges) is not None,
                        lambda e: _signed(e.args[0], ranges))


def steps_within(steps: dict[str, list], ranges: dict[sp.Symbol, tuple[sp.Expr, sp.Expr]]) -> dict[str, list]:
    """A worked solution's steps (by route) with their equations and their sentences' math `within`
    the ranges; a step it changes nothing of is the same object (a free-body diagram is found by its
    step's id)."""
    def one(step):
        equations = tuple(within(e, ranges) for e in step.equations)
        sentences = tuple(s.with_math(lambda m: within(m, ranges)) for s in step.sentences)
        if equations == step.equations and sentences == step.sentences:
            return step
        return dataclasses.replace(step, equations=equations, sentences=sentences)
    return {route: [one(s) for s in route_steps] for route, route_steps in steps.items()}


def _pythagorean(e):
    """tan(x)^2 + 1 + rest as 1/cos(x)^2 + rest (the first such x), else None (falsy for `replace`)."""
    if not isinstance(e, sp.Add) or sp.S.One not in e.args:
        return None
    for term in e.args:
        if isinstance(term, sp.Pow) and term.exp == 2 and isinstance(term.base, sp.tan):
            return e - term - 1 + 1 / sp.cos(term.base.args[0]) ** 2
    return None


def _shorter_root(e):
    """A square root whose radicand is shorter expanded, with it expanded: the root of a product of
    conjugates, sqrt((sqrt(F^2 + m^2 g^2) - F)(sqrt(F^2 + m^2 g^2) + F)), is m g (an identity, but
    tidy factors, and factoring keeps the product). None otherwise (falsy for `replace`)."""
    if not isinstance(e, sp.Pow) or e.exp != sp.S.Half or not isinstance(e.base, sp.Mul):
        return None
    expanded = sp.expand(e.base)
    return sp.sqrt(expanded) if sp.count_ops(expanded) < sp.count_ops(e.base) else None


def _inverse(e, ranges):
    """An inverse sine or cosine of a sine or cosine as the angle it is over the ranges, else None."""
    if not isinstance(e, (sp.asin, sp.acos)) or not isinstance(e.args[0], (sp.sin, sp.cos)):
        return None
    (low, high), value = _INVERSES[type(e), type(e.args[0])]
    angle = e.args[0].args[0]
    if intervals.positive_over(angle - low, ranges, strict=False) and \
            intervals.positive_over(high - angle, ranges, strict=False):
        return value(angle)
    return None


def _signed(x, ranges):
    """x or -x, whichever is not negative over the ranges (None: neither proven)."""
    if not x.free_symbols or not x.free_symbols <= set(ranges):
        return None
    if intervals.positive_over(x, ranges, strict=False):
        return x
    if intervals.positive_over(-x, ranges, strict=False):
        return -x
    return None
