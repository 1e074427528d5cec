"""What a route of derivation produces: equations, their solution, and readable steps.

>>> import sympy as sp
>>> a, T = sp.symbols("a T")
>>> dict(solve_linear([sp.Eq(2*a, T - 2), sp.Eq(a, 1)], [a, T]))
{a: 1, T: 4}
"""
from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import sympy as sp
from sympy.polys.matrices import DomainMatrix

from derive import limits


@dataclass(frozen=True)
class Step:
    """One step of a derivation as the lecture notes would write it: a sentence and equations."""

    text: str
    equations: tuple[sp.Eq, ...] = ()


class Solved(Mapping):
    """A solution whose values are put in compact form when first read: a question that asks
    for one quantity does not pay for simplifying all of them. `raw` holds them unsimplified."""

    def __init__(self, raw: dict[sp.Symbol, sp.Expr]):
        self.raw = raw
        self._tidy: dict[sp.Symbol, sp.Expr] = {}

    def __getitem__(self, unknown: sp.Symbol) -> sp.Expr:
        if unknown not in self._tidy:
            self._tidy[unknown] = tidy(self.raw[unknown])
        return self._tidy[unknown]

    def __iter__(self):
        return iter(self.raw)

    def __len__(self) -> int:
        return len(self.raw)


@dataclass
class Derivation:
    """The equations of motion of one route, solved for accelerations and constraint forces.

    `solution` solves them in general (every coordinate and velocity a symbol), on first use;
    `at(state)` solves them with some coordinates and velocities given (the reference
    configuration at rest, a state of the motion): with the state put in first, the linear system
    is far smaller than the general one. `steps` hold the derivation up to the equations;
    `solving_step` adds the solution for the unknowns a question needs.
    """

    route: str
    equations: list[sp.Eq]
    unknowns: list[sp.Symbol]
    steps: list[Step] = field(default_factory=list)
    _states: dict = field(default_factory=dict, repr=False)

    @property
    def solution(self) -> Solved:
        return self.at({})

    def at(self, state: dict[sp.Symbol, sp.Expr]) -> Solved:
        """The solution with `state` (coordinates and velocities, some or all) put in."""
        key = tuple(sorted(state.items(), key=lambda item: str(item[0])))
        if key not in self._states:
            with limits.time_limit(f"solving the equations of {self.route.replace('_', '-')}"):
                self._states[key] = solve_linear([e.xreplace(state) for e in self.equations], self.unknowns)
        return self._states[key]

    def solving_step(self, unknowns, state: dict[sp.Symbol, sp.Expr], where: str) -> Step:
        solved = self.at(state)
        return Step(f"Solving {where}", tuple(sp.Eq(u, solved[u]) for u in unknowns))


def simplest(expr: sp.Expr) -> sp.Expr:
    """Expanded, with sin^2 + cos^2 folded where the directions of surfaces put it."""
    expr = sp.expand(expr)
    return sp.expand(sp.trigsimp(expr)) if expr.has(sp.sin, sp.cos) else expr


def at_state(equation: sp.Eq, state: dict) -> sp.Eq:
    """An equation with a state put in, each side in its simplest form (for the steps)."""
    return sp.Eq(simplest(equation.lhs.xreplace(state)), simplest(equation.rhs.xreplace(state)))


def rest_positions(coords) -> dict[sp.Symbol, sp.Expr]:
    """The reference configuration: every coordinate zero, the velocities left free."""
    return {c.q: 0 for c in coords.all}


def tidy(expr: sp.Expr) -> sp.Expr:
    """A compact form of a solved expression: rational functions cancelled, then factored."""
    with limits.time_limit("simplifying"):
        expr = sp.cancel(sp.together(expr))
        if expr.has(sp.sin, sp.cos):
            expr = sp.trigsimp(expr)
        return sp.factor_terms(sp.factor(expr))


def root(expr: sp.Expr) -> sp.Expr:
    """sqrt(expr) kept as one root, as the notes write it (sympy would split sqrt(M*g) into
    sqrt(M)*sqrt(g) for positive symbols)."""
    return sp.Pow(tidy(expr), sp.S.Half, evaluate=False)


def solve_linear(equations: list[sp.Eq], unknowns: list[sp.Symbol]) -> Solved:
    """Solve equations linear in the unknowns (accelerations and constraint forces).

    The system is reduced over the field of rational functions of its coefficients' symbols
    (sympy's sparse DomainMatrix, with sin/cos of the coordinates as generators), which keeps
    every intermediate result cancelled: a cascade of three disks on cords took 30 s by a
    symbolic LU decomposition and takes 0.04 s this way (benchmarks: derive bench).

    Raises ValueError when the system has no unique solution (an impossible or redundant
    set of constraints).
    """
    # Linear in the unknowns: the matrix is the Jacobian and the rest is what is left at zero (no
    # expansion of the general equations, which a cord's exact geometry makes long).
    residuals = sp.Matrix([e.lhs - e.rhs for e in equations])
    matrix = residuals.jacobian(unknowns)
    rhs = -residuals.xreplace({u: 0 for u in unknowns})
    if matrix.free_symbols & set(unknowns):
        raise ValueError("the equations are not linear in the accelerations and forces")
    if matrix.shape[0] != matrix.shape[1]:
        raise ValueError(f"the constraints leave {len(unknowns)} unknowns in {len(equations)} equations: "
                         "they are redundant or impossible")
    augmented = matrix.row_join(rhs)
    # Roots and functions of the coordinates (a curved track's sqrt, an atan2) as generators of
    # the field, so that it is one of rational functions and not sympy's slow expression domain.
    atoms = {a for a in augmented.atoms(sp.Pow) if not a.exp.is_Integer} | augmented.atoms(sp.Function)
    generators = {atom: sp.Dummy(real=True) for atom in atoms}
    back = {d: atom for atom, d in generators.items()}
    domain_matrix = DomainMatrix.from_Matrix(augmented.xreplace(generators)).to_sparse()
    if not domain_matrix.domain.is_Field:
        domain_matrix = domain_matrix.to_field()
    reduced, pivots = domain_matrix.rref()
    if pivots != tuple(range(len(unknowns))):
        raise ValueError(
            f"the constraints leave {len(unknowns)} unknowns in {len(equations)} independent "
            "equations: they are redundant or impossible"
        )
    column = len(unknowns)
    values = {unknown: reduced.domain.to_sympy(reduced.rep.getitem(row, column)).xreplace(back)
              for row, unknown in enumerate(unknowns)}
    return Solved(values)
