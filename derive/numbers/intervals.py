"""Signs proven over boxes of parameter values: an expression evaluated in balls (derive.numbers.balls)
whose arguments are whole intervals, the box bisected along its widest side until every piece's
ball excludes zero, or a budget of pieces runs out (then nothing is proven).

A problem file's sizes must be positive for every value its parameters may take: sympy's
assumptions prove d*sin(theta) positive only for every positive theta, not for theta in [0.05,
0.15]; the ranges are what the file declares.

>>> import sympy as sp
>>> d, theta = sp.symbols("d theta", positive=True)
>>> positive_over(d * sp.sin(theta), {d: (1, 2), theta: (sp.Rational(1, 20), sp.Rational(3, 20))})
True
>>> positive_over(d * sp.sin(theta), {d: (1, 2), theta: (sp.Rational(1, 20), 4)})
False
>>> positive_over(d * sp.sin(theta) + d, {d: (10, 100), theta: (sp.Rational(1, 5), sp.Rational(7, 5))})
True
"""
from __future__ import annotations

import sympy as sp
from flint import arb, ctx

from derive.numbers import balls

PIECES = 256  # boxes tried at most: a sign that needs more is not proven
BITS = 64


def _strict_sign(factor: sp.Expr, box: dict[sp.Symbol, tuple]) -> int | None:
    """+1 or -1 where the factor is proven to keep that sign (never zero) over the box, else None."""
    if factor.is_number:
        return 1 if factor > 0 else -1 if factor < 0 else None
    return 1 if _by_balls(factor, box, True) else -1 if _by_balls(-factor, box, True) else None


def _relative_width(low: sp.Expr, high: sp.Expr) -> float:
    """A side's width against its size: midpoint-radius balls lose a product's sign by the relative
    width of its factors ([10, 100] times [0.7, 1.2] straddles zero), so that side is split first."""
    low, high = float(low), float(high)
    return (high - low) / max(abs(low), abs(high), 1e-300)


def _ball(low: sp.Expr, high: sp.Expr) -> arb:
    """A ball holding the whole interval [low, high] (exact ends: pi/18 for 10 deg)."""
    saved, ctx.prec = ctx.prec, BITS
    try:
        return balls.constant(low).union(balls.constant(high))
    finally:
        ctx.prec = saved


def positive_over(expression: sp.Expr, box: dict[sp.Symbol, tuple], strict: bool = True) -> bool:
    """Whether `expression` is positive (or, not `strict`, not negative) at every point of `box`
    (each symbol's closed interval of exact values), proven in balls; False where it is not, or
    where it could not be proven."""
    if not expression.free_symbols <= set(box) or not balls.mapped(expression):
        return False
    factors = sp.Mul.make_args(sp.factor_terms(expression))
    if len(factors) > 1:  # a product: each factor's sign on its own (F L sin(phi) with F in [10, 100])
        signs = [_strict_sign(f, box) for f in factors]
        if None not in signs:
            return sp.prod(signs) > 0
    return _by_balls(expression, box, strict)


def _by_balls(expression: sp.Expr, box: dict[sp.Symbol, tuple], strict: bool) -> bool:
    """`positive_over` of the expression as a whole: its ball over the box, bisected."""
    if not balls.mapped(expression):
        return False
    program = balls.Program([expression])
    pending = [{s: (sp.sympify(low, strict=True), sp.sympify(high, strict=True))  # safe: parsed ends, never text
                for s, (low, high) in box.items()}]
    tried = 0
    while pending:
        piece = pending.pop()
        tried += 1
        if tried > PIECES:
            return False
        (result,) = program.run([[_ball(*piece[s]) for s in program.symbols]], BITS)
        if isinstance(result, Exception):
            return False
        (value,) = result
        if value.lower() > 0 or not strict and value.lower() >= 0:
            continue
        if value.upper() < 0 or strict and value.upper() <= 0:
            return False
        widest = max(program.symbols, key=lambda s: _relative_width(*piece[s]), default=None)
        low, high = piece[widest] if widest is not None else (0, 0)
        if widest is None or high == low:
            return False
        middle = (low + high) / 2
        pending += [{**piece, widest: (low, middle)}, {**piece, widest: (middle, high)}]
    return True
