"""Numeric values of exact answers, correct to the significant digits they show.

Parameter values are exact rationals; an answer is evaluated by sympy's arbitrary-
precision evalf with strict accuracy (it raises rather than return digits it cannot
vouch for), with guard digits, then rounded half-to-even on that decimal value, never
on a float's repr.

>>> import sympy as sp
>>> m, M, g = sp.symbols("m M g", positive=True)
>>> a = -2*m*g/(M + 2*m)
>>> evaluate(a, {m: sp.Rational(1, 10**12), M: 1, g: sp.Rational(981, 100)}, 15)
'-1.96199999999608e-11'
>>> significant(sp.Rational(1, 3), 3)
'0.333'
"""
from __future__ import annotations

from decimal import ROUND_HALF_EVEN, Decimal

import sympy as sp

GUARD_DIGITS = 10


def significant(value: sp.Expr, digits: int) -> str:
    """An exact (or exactly evaluable) number as a decimal string with `digits` significant digits."""
    approx = sp.N(value, digits + GUARD_DIGITS, strict=True) if value != 0 else sp.Integer(0)
    if not approx.is_real:
        raise ValueError(f"{value} is not a real number")
    exact = Decimal(str(approx)) if approx != 0 else Decimal(0)
    if exact == 0:
        return "0"
    quantum = Decimal(1).scaleb(exact.adjusted() - digits + 1)
    rounded = exact.quantize(quantum, rounding=ROUND_HALF_EVEN)
    if rounded.adjusted() != exact.adjusted():  # 9.995 -> 10.0: one digit fewer after the point
        rounded = rounded.quantize(quantum.scaleb(1), rounding=ROUND_HALF_EVEN)
    exponent = rounded.adjusted()
    if -5 <= exponent < digits:
        return f"{rounded:f}"
    mantissa = rounded.scaleb(-exponent)
    return f"{mantissa:f}e{exponent:+03d}"


def evaluate(expression: sp.Expr, values: dict[sp.Symbol, sp.Expr], digits: int) -> str | None:
    """The value of an answer to `digits` significant digits, or None if a symbol has no value."""
    if expression.free_symbols - set(values):
        return None
    return significant(expression.xreplace(values), digits)
