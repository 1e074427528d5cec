"""Limiting cases of an answer, the way lecture notes check a result: each parameter that
varies taken to zero and, when it has a dimension and is not an angle, to infinity.

A massless disk lets the block fall freely; a very heavy one holds it:

>>> import sympy as sp
>>> m, M, g = sp.symbols("m M g", positive=True)
>>> [(c.symbol, c.point, c.value) for c in limiting_cases(-2*m*g/(M + 2*m), {M: "kg"})]
[(M, 0, -g), (M, oo, 0)]
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive import limits, units

SECONDS = 2.0  # per limit: a case that takes longer is left out, not waited for


@dataclass(frozen=True)
class Case:
    symbol: sp.Symbol
    point: sp.Expr  # 0 or oo
    value: sp.Expr


def _algebraic_in(expression: sp.Expr, symbol: sp.Symbol) -> bool:
    """Sums, products and powers of the symbol only (sympy's limits are quick and sure there);
    trigonometric and other functions of it are left out."""
    return all(not f.has(symbol) for f in expression.atoms(sp.Function))


def _points(unit: str) -> tuple[sp.Expr, ...]:
    """Zero for every parameter; infinity only for one with a dimension that is not an angle."""
    dimensional = units.dimension(units.parse_unit(unit)) and not units.same_dimension(
        units.dimension(units.parse_unit(unit)), units.dimension(units.parse_unit("rad")))
    return (sp.Integer(0), sp.oo) if dimensional else (sp.Integer(0),)


def limiting_cases(expression: sp.Expr, varying: dict[sp.Symbol, str]) -> list[Case]:
    """The finite or infinite limits of `expression` as each symbol of `varying` (symbol -> unit)
    goes to its points; cases with no definite limit, or taking longer than SECONDS, are left out."""
    result = []
    for symbol, unit in varying.items():
        if not expression.has(symbol) or not _algebraic_in(expression, symbol):
            continue
        for point in _points(unit):
            try:
                with limits.time_limit(f"the limit {symbol} -> {point}", seconds=SECONDS):
                    value = sp.limit(expression, symbol, point, "+" if point == 0 else "-")
            except (limits.TimeLimitError, NotImplementedError, ValueError):
                continue
            if value.has(sp.Limit, sp.nan, sp.zoo, sp.AccumBounds):
                continue
            result.append(Case(symbol, point, sp.factor(value) if value.is_finite else value))
    return result
