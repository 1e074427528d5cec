"""What a route of derivation produces: equations, their solution, and readable steps.

>>> import sympy as sp
>>> a, T = sp.symbols("a T")
>>> solve_linear([sp.Eq(2*a, T - 2), sp.Eq(a, 1)], [a, T])
{a: 1, T: 4}
"""
from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp


@dataclass(frozen=True)
class Step:
    """One step of a derivation as the lecture notes would write it: a sentence and equations."""

    text: str
    equations: tuple[sp.Eq, ...] = ()


@dataclass
class Derivation:
    """The equations of motion of one route, solved for accelerations and constraint forces."""

    route: str
    equations: list[sp.Eq]
    unknowns: list[sp.Symbol]
    solution: dict[sp.Symbol, sp.Expr]
    steps: list[Step] = field(default_factory=list)


def tidy(expr: sp.Expr) -> sp.Expr:
    """A compact form of a solved expression: rational functions cancelled, then factored."""
    expr = sp.cancel(sp.together(expr))
    if expr.has(sp.sin, sp.cos):
        expr = sp.trigsimp(expr)
    return sp.factor_terms(sp.factor(expr))


def root(expr: sp.Expr) -> sp.Expr:
    """sqrt(expr) kept as one root, as the notes write it (sympy would split sqrt(M*g) into
    sqrt(M)*sqrt(g) for positive symbols)."""
    return sp.Pow(tidy(expr), sp.S.Half, evaluate=False)


def solve_linear(equations: list[sp.Eq], unknowns: list[sp.Symbol]) -> dict[sp.Symbol, sp.Expr]:
    """Solve equations linear in the unknowns (accelerations and constraint forces).

    Raises ValueError when the system has no unique solution (an impossible or redundant
    set of constraints).
    """
    matrix, rhs = sp.linear_eq_to_matrix([e.lhs - e.rhs for e in equations], unknowns)
    if matrix.shape[0] != matrix.shape[1] or matrix.det(method="berkowitz").equals(0):
        raise ValueError(
            f"the constraints leave {len(unknowns)} unknowns in {len(equations)} independent "
            "equations: they are redundant or impossible"
        )
    values = matrix.LUsolve(rhs)
    return {u: tidy(v) for u, v in zip(unknowns, values)}
