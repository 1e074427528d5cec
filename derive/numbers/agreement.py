"""Whether two routes' expressions agree: symbolically where that is cheap, else certified by balls.

`agree(a, b)` tries, in order:
1. exact tests that cost little: a == b, a - b cancelled to 0 (sympy.cancel), and sympy.simplify
   of a - b where it is short (SIMPLIFY_OPS); a Piecewise with the same conditions on both sides
   (friction's regimes) is compared case by case, each case on its own;
2. balls (derive.numbers.balls, python-flint's arb): a and b evaluated with outward rounding at each
   point, inside the problem's ranges where the caller gives them. A ball of a - b that excludes
   0 proves a disagreement; balls of radius below 1e-30 (relative) that contain 0 at every point,
   and at least MIN_POINTS of them, are an agreement to 30 digits;
3. what balls cannot evaluate (an integral, an unknown function) or decide (a condition on the
   edge) is compared by sympy's evalf at 30 digits, as before balls.

It returns how agreement was established ("symbolic", "balls", "numeric"), or None when the two
differ. Simplifying a long difference cost more than the question: on an incline with friction,
minutes for expressions the balls settle in a second.

>>> import sympy as sp
>>> x = sp.Symbol("x", positive=True)
>>> agree(sp.sin(x)**2 + sp.cos(x)**2, sp.Integer(1))
'symbolic'
>>> agree(sp.sqrt(x**2 + 2*x + 1) * sp.atan(x) ** 9, (x + 1) * sp.atan(x) ** 9), agree(x, x + sp.Rational(1, 10**20))
('balls', None)
"""
from __future__ import annotations

import random

import sympy as sp
from flint import arb, ctx

from derive.numbers import balls

#: sympy.simplify only differences of at most this many operations (count_ops): longer ones go
#: to the balls, where simplify took most of a problem's time (an incline with friction: 60 s).
SIMPLIFY_OPS = 60
#: The digits two values must share at every point, and how many points at least.
DIGITS = 30
MIN_POINTS = 5
#: Working precisions tried in turn, until a ball is narrow enough or a condition is decided.
BITS = (128, 256, 512)

#: How agreement was established, weakest last (a Piecewise is only as strong as its weakest case).
METHODS = ("symbolic", "balls", "numeric")


def agree(a: sp.Expr, b: sp.Expr, trials: int = MIN_POINTS, symbolic: bool = True, points=None) -> str | None:
    """'symbolic', 'balls' or 'numeric' (the module's docstring) when a and b agree, None when
    they differ. `points` (parameter values inside a problem's ranges, where two routes may agree
    only there: sqrt(-g/(r - R)) is sqrt(g |R - r|)/|R - r| where R > r) replace `trials` random
    ones; `symbolic=False` skips the exact tests (values already numbers)."""
    if symbolic and _exactly(a, b):
        return "symbolic"
    cases = _cases(a, b)
    if cases is not None:
        methods = [agree(x, y, trials, symbolic, points) for x, y in cases]
        return None if None in methods else max(methods, key=METHODS.index)
    symbols = sorted(sp.Tuple(a, b).free_symbols, key=str)
    if not points:  # numbers need one look; expressions a few random points
        rng = random.Random(0)
        points = [{s: sp.Rational(rng.randint(11, 99), 37) for s in symbols} for _ in range(trials if symbols else 1)]
    verdict = by_balls(a, b, points)
    if verdict is not None:
        return "balls" if verdict else None
    return _by_evalf(a, b, points)


def _exactly(a: sp.Expr, b: sp.Expr) -> bool:
    """Whether a = b is proven by a cheap exact test."""
    if a == b:
        return True
    difference = a - b
    if difference == 0 or sp.cancel(difference) == 0:
        return True
    return sp.count_ops(difference) <= SIMPLIFY_OPS and sp.simplify(difference) == 0


def _cases(a: sp.Expr, b: sp.Expr) -> list[tuple[sp.Expr, sp.Expr]] | None:
    """The pairs of values of two Piecewise with the same conditions, in order (else None): each
    regime compared on its own, at every point, not only in the regime the points reach."""
    a, b = sp.piecewise_fold(a), sp.piecewise_fold(b)
    if not (isinstance(a, sp.Piecewise) and isinstance(b, sp.Piecewise) and len(a.args) == len(b.args)):
        return None
    if any(x.cond != y.cond for x, y in zip(a.args, b.args)):
        return None
    return [(x.expr, y.expr) for x, y in zip(a.args, b.args)]


def by_balls(a: sp.Expr, b: sp.Expr, points: list[dict]) -> bool | None:
    """False when a ball of a - b excludes 0 at some point (a proven disagreement); True when
    every point's ball contains 0 with a radius below 10^-DIGITS of the values' size, at
    min(MIN_POINTS, len(points)) points at least; None when balls cannot tell (an expression
    they do not map, too few points decided)."""
    if not (balls.mapped(a) and balls.mapped(b)):
        return None
    program = balls.Program([a, b])
    agreed = 0
    for point in points:
        if not all(s in point for s in program.symbols):
            continue
        row = [point[s] for s in program.symbols]
        for bits in BITS:
            result = program.run([row], bits)[0]
            if isinstance(result, Exception):  # a condition on the edge at this precision
                continue
            verdict = same_ball(*result, bits=bits)
            if verdict is False:
                return False
            if verdict:
                agreed += 1
                break
    return True if agreed >= min(MIN_POINTS, len(points)) else None


def same_ball(first: arb, second: arb, bits: int) -> bool | None:
    """False when two balls are disjoint (the exact values differ), True when they overlap and
    their difference (taken at `bits`) is narrower than 10^-DIGITS of their size, None when too
    wide to tell.

    >>> same_ball(arb(1) / 4, arb(2) / 8, 128), same_ball(arb(1), arb("1 +/- 0.1"), 128), same_ball(arb(1), arb(2), 128)
    (True, None, False)
    """
    saved, ctx.prec = ctx.prec, bits
    try:
        difference = first - second
    finally:
        ctx.prec = saved
    if not difference.is_finite():
        return None
    if not difference.contains(0):
        return False
    size = 1 + abs(float(first.mid())) + abs(float(second.mid()))
    return True if float(difference.rad()) <= size * 10.0**-DIGITS else None


def _by_evalf(a: sp.Expr, b: sp.Expr, points: list[dict]) -> str | None:
    """'numeric' when sympy's evalf gives a and b within 1e-25 (relative) at every point."""
    for point in points:
        first, second = (sp.N(e.xreplace(point), DIGITS) for e in (a, b))  # each tree walked once
        if abs(first - second) > (abs(first) + 1) * sp.Float("1e-25"):
            return None
    return "numeric"
