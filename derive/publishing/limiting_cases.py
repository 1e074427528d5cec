"""Limiting cases of an answer, chosen as lecture notes choose them: the ones that say something
and stay inside the problem's domain, each with a sentence that reads it.

Which limits: a mass to zero (a massless disk) and to infinity (a heavy block); any other
parameter, a size, an angle, a coefficient, to zero (a point-like body, a vanishing angle, a
smooth surface). A limit is kept only where it is finite and definite, where it comes quickly
(SECONDS), and where the problem still makes sense on the way there: `allowed(symbol, point)`
says whether the problem's conditions hold close to it (r -> 0 is no case where r > R must hold,
and R -> 0 breaks b <= R). At most MOST cases are shown, masses first, then angles, then the rest.

A massless disk lets the block fall freely; a very heavy one holds it:

>>> import sympy as sp
>>> m, M, g = sp.symbols("m M g", positive=True)
>>> [(c.symbol, c.point, c.value) for c in limiting_cases(-2*m*g/(M + 2*m), {M: "kg"})]
[(M, 0, -g), (M, oo, 0)]
>>> reading(Case(M, sp.oo, sp.Integer(0)), "mass of the disk")
'as the mass of the disk grows without bound'
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import sympy as sp

from derive.core import limits, units

SECONDS = 2.0  # per limit: a case that takes longer is left out, not waited for
MOST = 5  # cases shown per problem


@dataclass(frozen=True)
class Case:
    symbol: sp.Symbol
    point: sp.Expr  # 0 or oo
    value: sp.Expr


def _quick_in(expression: sp.Expr, symbol: sp.Symbol, point: sp.Expr) -> bool:
    """Sums, products and powers of the symbol, and at zero its sines, cosines and tangents
    (sympy's limits are quick and sure there); other functions of it are left out."""
    trigonometric = (sp.sin, sp.cos, sp.tan) if point == 0 else ()
    return all(not f.has(symbol) or isinstance(f, trigonometric) and f.args[0] == symbol
               for f in expression.atoms(sp.Function))


def _kind(unit: str) -> str:
    """"mass", "angle" or "other": what decides a parameter's limits and their order."""
    dimension = units.dimension(units.parse_unit(unit))
    if dimension == {"mass": 1}:
        return "mass"
    return "angle" if unit.strip() in ("rad", "deg", "°", "degree", "degrees") else "other"


def _points(unit: str) -> tuple[sp.Expr, ...]:
    """Zero for every parameter; infinity for a mass too (a heavy body)."""
    return (sp.Integer(0), sp.oo) if _kind(unit) == "mass" else (sp.Integer(0),)


def limiting_cases(expression: sp.Expr, varying: dict[sp.Symbol, str],
                   allowed: Callable[[sp.Symbol, sp.Expr], bool] = lambda symbol, point: True) -> list[Case]:
    """The finite limits of `expression` as each symbol of `varying` (symbol -> unit) goes to its
    points where `allowed`; cases with no definite finite limit, or taking longer than SECONDS,
    are left out."""
    result = []
    for symbol, unit in varying.items():
        for point in _points(unit):
            if not expression.has(symbol) or not _quick_in(expression, symbol, point) or not allowed(symbol, point):
                continue
            try:
                with limits.time_limit(f"the limit {symbol} -> {point}", seconds=SECONDS):
                    value = sp.limit(expression, symbol, point, "+" if point == 0 else "-")
            except (limits.TimeLimitError, NotImplementedError, ValueError):
                continue
            if value.has(sp.Limit, sp.nan, sp.zoo, sp.AccumBounds, sp.oo, -sp.oo):
                continue  # no definite value, or the answer leaves every scale: the model's edge
            result.append(Case(symbol, point, sp.factor(value)))
    return result


def chosen(cases: list[tuple[str, Case]], varying: dict[sp.Symbol, str]) -> list[tuple[str, Case]]:
    """At most MOST of (answer, case), the answers in turn, each taking its first case of a limit
    not shown yet (else its next one): masses first, then angles, then the rest. So every answer
    gets its say and each physical situation (a massless disk, a heavy block) comes once before
    any comes twice."""
    order = {"mass": 0, "angle": 1, "other": 2}
    pending: dict[str, list[Case]] = {}
    for answer, case in sorted(cases, key=lambda item: order[_kind(varying[item[1].symbol])]):
        pending.setdefault(answer, []).append(case)
    picked, seen = [], set()
    while len(picked) < MOST and any(pending.values()):
        for answer, queue in pending.items():
            if queue and len(picked) < MOST:
                case = next((c for c in queue if (c.symbol, c.point) not in seen), queue[0])
                queue.remove(case)
                seen.add((case.symbol, case.point))
                picked.append((answer, case))
    return picked


def reading(case: Case, parameter: str) -> str:
    """What a case supposes, in words from the parameter's meaning (plain text, beside the limit
    that gives its value)."""
    return f"as the {parameter} {'goes to zero' if case.point == 0 else 'grows without bound'}"
