"""What a route of derivation produces: equations, their solution, and readable steps.

>>> import sympy as sp
>>> a, T = sp.symbols("a T")
>>> dict(solve_linear([sp.Eq(2*a, T - 2), sp.Eq(a, 1)], [a, T]))
{a: 1, T: 4}
"""
from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

import sympy as sp
from flint import arb, arb_mat, ctx
from sympy.polys.matrices import DomainMatrix
from sympy.polys.polyerrors import CoercionFailed

from derive.numbers import balls
from derive.core import limits
from derive.mechanics import jets
from derive.core.tidying import radicals, simplest, tidy
from derive.text.steps import Step


#: The symbols the steps name energies by: K for the kinetic energy (T is a tension in most
#: problems) and a script L for the Lagrangian (L is often a length). latex.symbol_latex prints
#: a name that starts with a backslash as it is (a problem file's names are identifiers).
KINETIC = sp.Symbol("K")
LAGRANGIAN = sp.Symbol(r"\mathcal{L}")
POTENTIAL = sp.Symbol("V")
#: The period of small oscillations, the period at an amplitude and the growth rate the steps solve
#: for (derive.publishing.notation prints each by the name of the ask of it, and renames one a problem file's
#: name takes with another meaning).
PERIOD = sp.Symbol("T")
EXACT_PERIOD = sp.Symbol("T_exact")
GROWTH_RATE = sp.Symbol("a")


class Solved(Mapping):
    """A solution whose values are put in compact form when first read: a question that asks
    for one quantity does not pay for simplifying all of them. `raw` holds them unsimplified."""

    def __init__(self, raw: dict[sp.Symbol, sp.Expr], placed: tuple[sp.Expr, ...] = ()):
        self.raw = raw
        self.placed = placed
        self._tidy: dict[sp.Symbol, sp.Expr] = {}

    def __getitem__(self, unknown: sp.Symbol) -> sp.Expr:
        if unknown not in self._tidy:
            self._tidy[unknown] = tidy(self.raw[unknown], self.placed)
        return self._tidy[unknown]

    def __iter__(self):
        return iter(self.raw)

    def __len__(self) -> int:
        return len(self.raw)


class Indeterminate(ValueError):
    """The equations do not determine every acceleration and force: the constraints are
    redundant (statically indeterminate: two contacts that both grip, a rod on two pins) or
    contradict each other."""

    def __init__(self, counts: str):
        super().__init__(f"the constraints do not determine every force ({counts}): they are redundant "
                         "(statically indeterminate, as two contacts that both grip) or contradict each other")


@dataclass
class Derivation:
    """The equations of motion of one route, solved for accelerations and constraint forces.

    `balances` are the route's own equations (Euler–Lagrange, or force and torque balances);
    `rates` the constraints on velocities, v(q, u) = 0 and linear in u, that close the system at
    acceleration level, dv/dt = 0. `equations` holds them all in general (every coordinate and
    velocity a symbol: a simulation needs them); with every velocity zero, dv/dt is only
    sum(dv/du_i a_i) (the terms in u vanish), which `at_rest_equations` builds without deriving
    the general terms: the second time derivative of a cord's exact geometry was most of a
    cascade's time (benchmarks: derive bench). `solution` solves them in general, on first use;
    `at(state)` solves them with some coordinates and velocities given (the reference
    configuration at rest, a state of the motion): with the state put in first, the linear system
    is far smaller than the general one. `steps` hold the derivation up to the equations, written
    by `written` on first use (the equations in the reference configuration, the parts' sentences:
    a derivation whose worked solution nobody reads does not pay for them); `solving_step` adds
    the solution for the unknowns a question needs.
    """

    route: str
    balances: list[sp.Eq]
    unknowns: list[sp.Symbol]
    written: Callable[[Derivation], list[Step]] = lambda derivation: []
    rates: list[sp.Expr] = field(default_factory=list)
    coords: object = None  # derive.model.kinematics.Coordinates, for the rates' derivatives
    gaps: list[sp.Expr] = field(default_factory=list)  # when each rate is dg/dt of a gap g(q)
    _states: dict = field(default_factory=dict, repr=False)
    _cache: dict = field(default_factory=dict, repr=False)

    @property
    def steps(self) -> list[Step]:
        """The steps up to the equations (written on first use)."""
        if "steps" not in self._cache:
            self._cache["steps"] = self.written(self)
        return self._cache["steps"]

    @property
    def placed(self) -> tuple[sp.Expr, ...]:
        """Expressions positive where the file places the scene (Scene.placed): the solutions take
        them as they are where an absolute value or a root of a square meets them."""
        return getattr(getattr(self.coords, "scene", None), "placed", ())

    @property
    def equations(self) -> list[sp.Eq]:
        """Every equation, in general: the balances and dv/dt = 0 for each rate."""
        if "general" not in self._cache:
            self._cache["general"] = self.balances + [sp.Eq(self.coords.ddt(v), 0) for v in self.rates]
        return self._cache["general"]

    @property
    def at_rest_equations(self) -> list[sp.Eq]:
        """The equations with every velocity zero (coordinates still free)."""
        if "rest" not in self._cache:
            still = {c.u: 0 for c in self.coords.all} if self.coords is not None else {}
            rows = [sp.Eq(self._slope_term(i, {}), 0, evaluate=False) if self._linear(i)
                    else sp.Eq(self.coords.ddt(v).xreplace(still), 0)  # not linear in u: in full
                    for i, v in enumerate(self.rates)]
            self._cache["rest"] = [e.xreplace(still) for e in self.balances] + rows
        return self._cache["rest"]

    @property
    def solution(self) -> Solved:
        return self.at({})

    def at(self, state: dict[sp.Symbol, sp.Expr], frozen=None) -> Solved:
        """The solution with `state` (coordinates and velocities, some or all) put in; `frozen`
        (equations, unknowns -> equations) rewrites the equations before they are solved (a
        motion along a line puts each coefficient that does not change along it at its start,
        derive.mechanics.states)."""
        key = (tuple(sorted(state.items(), key=lambda item: str(item[0]))), frozen)
        if key not in self._states:
            equations = self._equations_at(state)
            if frozen is not None:
                equations = frozen(equations, self.unknowns)
            with limits.time_limit(f"solving the equations of {self.route.replace('_', '-')}"):
                self._states[key] = solve_linear(equations, self.unknowns, self.placed)
        return self._states[key]

    def balls_at(self, state: dict[sp.Symbol, sp.Expr], bits: int = 256) -> dict[sp.Symbol, arb]:
        """Every unknown's ball (derive.numbers.balls) in a state that gives every symbol a number: the
        linear system's entries as balls, solved by python-flint (arb_mat.solve, which rounds
        outward), so each exact value lies in its ball. A check needs no exact solution: over the
        algebraic numbers of a cord's geometry (sin(9/20), its roots) the exact one took 3 s a state.

        Raises ValueError where the balls cannot decide: an entry with no ball, or a matrix not
        proven invertible at this precision."""
        key = ("balls", tuple(sorted(state.items(), key=lambda item: str(item[0]))), bits)
        if key not in self._cache:
            # The balances' coefficients taken in general, once, and the state put into them: the
            # Jacobian of the balances with the numbers in (a cord's geometry at sample angles) took
            # most of a double wedge's check.
            if "balances" not in self._cache:
                self._cache["balances"] = _linear_form(self.balances, self.unknowns)
            coefficients, free = self._cache["balances"]
            rates, rates_free = _linear_form(self._rates_at(state), self.unknowns)
            matrix = coefficients.xreplace(state).col_join(rates)
            rhs = free.xreplace(state).col_join(rates_free)
            if (matrix.free_symbols | rhs.free_symbols) or not all(balls.mapped(e) for e in [*matrix, *rhs]):
                raise ValueError("the equations at this state are not all numbers with balls")
            saved, ctx.prec = ctx.prec, bits
            try:
                entries = arb_mat([[balls.constant(e) for e in matrix.row(i)] for i in range(matrix.rows)])
                solved = entries.solve(arb_mat([[balls.constant(e)] for e in rhs]))
            except ZeroDivisionError:
                raise ValueError(f"the equations are not proven solvable at {bits} bits") from None
            finally:
                ctx.prec = saved
            self._cache[key] = {u: solved[i, 0] for i, u in enumerate(self.unknowns)}
        return self._cache[key]

    def _equations_at(self, state: dict[sp.Symbol, sp.Expr]) -> list[sp.Eq]:
        """The equations with `state` put in, in the cheapest form the state allows."""
        balances = self.at_rest_equations[:len(self.balances)] if self._at_rest(state) else self.balances
        return [e.xreplace(state) for e in balances] + self._rates_at(state)

    def _at_rest(self, state: dict[sp.Symbol, sp.Expr]) -> bool:
        coords = self.coords.all if self.coords is not None else []
        return bool(coords) and all(state.get(c.u, None) == 0 for c in coords)

    def _rates_at(self, state: dict[sp.Symbol, sp.Expr]) -> list[sp.Eq]:
        """The rows dv/dt = 0 with `state` put in, in the cheapest form the state allows: at rest
        (at_rest_equations), in a full state (one derivative along the motion), else in general."""
        coords = self.coords.all if self.coords is not None else []
        if self._at_rest(state):
            return [e.xreplace(state) for e in self.at_rest_equations[len(self.balances):]]
        if coords and all(c.q in state and c.u in state for c in coords) \
                and all(self._linear(i) for i in range(len(self.rates))):
            return self._rates_along(state)
        return [e.xreplace(state) for e in self.equations[len(self.balances):]]

    def _slopes(self, i: int) -> list[tuple[sp.Expr, sp.Symbol]]:
        """(dv/du_j, a_j) for the i-th rate v."""
        key = ("slopes", i)
        if key not in self._cache:
            self._cache[key] = [(sp.diff(self.rates[i], c.u), c.a) for c in self.coords.all
                                if c.u in self.rates[i].free_symbols]
        return self._cache[key]

    def _linear(self, i: int) -> bool:
        """Whether the i-th rate is linear and homogeneous in the velocities (as rigid-body
        kinematics and the rates of gaps are): then dv/dt = sum(dv/du_j a_j) + the terms in u."""
        velocities = {c.u for c in self.coords.all}
        still = {u: 0 for u in velocities}
        return self.rates[i].xreplace(still) == 0 and not any(slope.free_symbols & velocities
                                                              for slope, _ in self._slopes(i))

    def _slope_term(self, i: int, state: dict) -> sp.Expr:
        return sum((slope.xreplace(state) * a for slope, a in self._slopes(i)), sp.Integer(0))

    def _rates_along(self, state: dict[sp.Symbol, sp.Expr]) -> list[sp.Eq]:
        """dv/dt = 0 in a state that gives every coordinate and velocity u0: sum(dv/du_j a_j) plus
        the derivative along the motion, d/ds v(q0 + s u0, u0) at s = 0, or for the rate of a gap
        g, d^2/ds^2 g(q0 + s u0): one derivative in one symbol where the general dv/dt needs one
        per coordinate and velocity (the chain rule, exactly)."""
        line = {c.q: (state[c.q], state[c.u]) for c in self.coords.all}
        velocities = {c.u: state[c.u] for c in self.coords.all}
        # The state's other values (parameters at a sample point) first: the derivative is then
        # taken of a number-valued geometry, and the row holds no parameter the state gives.
        given = {k: v for k, v in state.items() if k not in line and k not in velocities}
        rows = []
        for i, v in enumerate(self.rates):
            gap = self.gaps[i] if self.gaps else None
            along = jets.along(gap.xreplace(given), line)[2] if gap is not None else \
                jets.along(v.xreplace(given).xreplace(velocities), line)[1]
            rows.append(sp.Eq(self._slope_term(i, state) + along, 0, evaluate=False))
        return rows

    def numeric(self, values: dict[sp.Symbol, sp.Expr]):
        """A function of the state array (every coordinate, then every velocity) giving every
        unknown (accelerations, then forces) at these parameter `values`: the general equations,
        linear in the unknowns, solved numerically at each call (numpy): with cords the general
        symbolic solution is large. For simulations."""
        import numpy as np  # only simulations need it

        state = [c.q for c in self.coords.all] + [c.u for c in self.coords.all]
        matrix, rhs = sp.linear_eq_to_matrix([(e.lhs - e.rhs).xreplace(values) for e in self.equations], self.unknowns)
        system = sp.lambdify(state, [matrix, rhs], "numpy")

        def unknowns(y):
            a, b = system(*y)
            return np.linalg.solve(np.asarray(a, dtype=float), np.asarray(b, dtype=float).ravel())
        return unknowns

    def solving_step(self, unknowns, state: dict[sp.Symbol, sp.Expr], where: str) -> Step:
        solved = self.at(state)
        return Step(f"Solving {where}", tuple(sp.Eq(u, solved[u]) for u in unknowns), role="solve")


def _linear_form(equations: list[sp.Eq], unknowns: list[sp.Symbol]) -> tuple[sp.Matrix, sp.Matrix]:
    """(A, b) of equations linear in the unknowns, A u = b: the Jacobian and what is left at zero
    (no rows for no equations: a body no constraint holds).

    >>> a, T = sp.symbols("a T")
    >>> _linear_form([sp.Eq(2*a, T - 2)], [a, T]), _linear_form([], [a, T])[0].shape
    ((Matrix([[2, -1]]), Matrix([[-2]])), (0, 2))
    """
    if not equations:
        return sp.zeros(0, len(unknowns)), sp.zeros(0, 1)
    residuals = sp.Matrix([e.lhs - e.rhs for e in equations])
    return residuals.jacobian(unknowns), -residuals.xreplace({u: 0 for u in unknowns})


def worth_showing(equations) -> tuple[sp.Eq, ...]:
    """The constraint equations a worked solution writes out: one that only says a coordinate's
    rate or acceleration is zero (an axle holding a center in place) is said in the step's words
    (FIXED_LEFT_OUT) instead.

    >>> x, y = sp.symbols("xdot_disk ydot_block")
    >>> worth_showing([sp.Eq(x, 0), sp.Eq(-x + y, 0)])
    (Eq(-xdot_disk + ydot_block, 0),)
    """
    return tuple(e for e in equations if not (e.rhs == 0 and (-e.lhs if e.lhs.could_extract_minus_sign() else e.lhs).is_Symbol))


#: What a constraints step says of the equations `worth_showing` leaves out.
FIXED_LEFT_OUT = "; a coordinate a constraint simply holds fixed, such as a center on an axle, stays at its place"


def at_state(equation: sp.Eq, state: dict) -> sp.Eq:
    """An equation with a state put in, each side in its simplest form (for the steps)."""
    return sp.Eq(simplest(equation.lhs.xreplace(state)), simplest(equation.rhs.xreplace(state)))


def part_sentences(scene, coords, route: str) -> list:
    """What each part of the scene contributes to `route`, in its words (derive.parts)."""
    return [s for part in scene.parts for s in part.sentences(route, coords)]


def rest_positions(coords) -> dict[sp.Symbol, sp.Expr]:
    """The reference configuration: every coordinate zero, the velocities left free."""
    return {c.q: 0 for c in coords.all}


def solve_linear(equations: list[sp.Eq], unknowns: list[sp.Symbol], placed: tuple[sp.Expr, ...] = ()) -> Solved:
    """Solve equations linear in the unknowns (accelerations and constraint forces).

    The system is reduced over the field of rational functions of its coefficients' symbols
    (sympy's sparse DomainMatrix, with sin/cos of the coordinates as generators), which keeps
    every intermediate result cancelled: a cascade of three disks on cords took 30 s by a
    symbolic LU decomposition and takes 0.04 s this way (benchmarks: derive bench).

    Raises ValueError when the system has no unique solution (an impossible or redundant
    set of constraints). `placed`: as for `tidy`.
    """
    # Linear in the unknowns: the matrix is the Jacobian and the rest is what is left at zero (no
    # expansion of the general equations, which a cord's exact geometry makes long).
    matrix, rhs = _linear_form(equations, unknowns)
    if matrix.free_symbols & set(unknowns):
        raise ValueError("the equations are not linear in the accelerations and forces")
    if matrix.shape[0] != matrix.shape[1]:
        raise Indeterminate(f"{len(unknowns)} accelerations and forces in {len(equations)} equations")
    reduced, pivots = row_reduced(matrix.row_join(rhs), placed)
    if pivots != tuple(range(len(unknowns))):
        raise Indeterminate(f"{len(unknowns)} accelerations and forces in {len(pivots)} independent equations")
    return Solved({unknown: reduced(row, len(unknowns)) for row, unknown in enumerate(unknowns)}, placed)


def row_reduced(matrix: sp.Matrix, placed: tuple[sp.Expr, ...] = ()) -> tuple[Callable[[int, int], sp.Expr], tuple[int, ...]]:
    """The reduced row echelon form of a matrix over the field of rational functions of its
    entries' symbols and generators (_as_rational): a function giving its (row, column) entry as
    an expression, and the pivot columns. sympy's Matrix.rref took 1 s for the five rates of an
    incline's cord at sample parameters (sin(9/20) and its roots); this takes 0.06 s.

    >>> x = sp.Symbol("x")
    >>> entry, pivots = row_reduced(sp.Matrix([[x, 2 * x], [1, 2]]))
    >>> pivots, entry(0, 1)
    ((0,), 2)
    """
    generated, back = _as_rational(matrix, placed)
    circles, roots = _circles(back), _roots(back)
    # Through the dense form: DomainMatrix.from_Matrix keeps an entry that is zero only in the
    # field (a vertical cord's x-component, once its roots are simplified) as a stored sparse
    # entry, which rref then takes for a pivot; to_dense().to_sparse() drops it.
    domain_matrix = DomainMatrix.from_Matrix(cancelled(generated, circles, roots)).to_dense().to_sparse()
    if not domain_matrix.domain.is_Field:
        domain_matrix = domain_matrix.to_field()
    # Over rational functions, fraction-free elimination of the matrix with its denominators cleared
    # ('CD'): sympy's default there, Gauss-Jordan over the field, takes a multivariate gcd at every
    # step; over the tangent geometry of a cord on a double wedge (13 equations, two angles) it took
    # 46 s, this 2 s. The reduced form is the same (it is unique), so is every answer.
    method = "CD" if domain_matrix.domain.is_FractionField else "auto"
    reduced, pivots = domain_matrix.rref(method=method)

    def entry(row: int, column: int) -> sp.Expr:
        # the relations again: the elimination's products square the generators they hold
        value = cancelled(sp.Matrix([[reduced.domain.to_sympy(reduced.rep.getitem(row, column))]]), circles, roots)
        return value[0, 0].xreplace(back)
    return entry, pivots


def nullspace(matrix: sp.Matrix) -> list[sp.Matrix]:
    """A basis of the null space of a matrix, as sympy's Matrix.nullspace gives it (one vector per
    column without a pivot, that column's entry 1), from row_reduced: sympy's own, by a symbolic rref,
    ran for minutes over the unfolded tangent geometry of a cord over a pulley on a double wedge.

    >>> x = sp.Symbol("x")
    >>> nullspace(sp.Matrix([[x, 2 * x]]))
    [Matrix([
    [-2],
    [ 1]])]
    """
    reduced, pivots = row_reduced(matrix)
    basis = []
    for free in (column for column in range(matrix.cols) if column not in pivots):
        vector = sp.zeros(matrix.cols, 1)
        vector[free] = 1
        for row, pivot in enumerate(pivots):
            vector[pivot] = -reduced(row, free)
        basis.append(vector)
    return basis


def cancelled(matrix: sp.Matrix, circles: tuple[tuple[sp.Symbol, sp.Symbol], ...] = (),
              roots: tuple[tuple[sp.Symbol, sp.Expr], ...] = ()) -> sp.Matrix:
    """Each entry of a matrix of rational functions as one cancelled ratio of expanded polynomials,
    built node by node in the field of rational functions of its symbols (sympy's FracField.from_expr:
    each sum and product cancelled as it is formed). sympy's construct_domain, which
    DomainMatrix.from_Matrix calls, expands each entry's numerator and denominator whole instead: at
    the top of a loop a rolling ball's row held sums that are (R - r)^2 in disguise, squared and over
    each other, and its expansion took 150 s for an entry that is 0 (this takes 0.05 s for the
    matrix). An entry with a float, or an atom that is no symbol (pi), is left as it is.
    `circles`: pairs of symbols (s, c) that stand for the sine and cosine of one angle, whose
    s^2 + c^2 = 1 the field does not know: each entry is folded by it (_folded). `roots`: pairs
    (g, b) of a symbol that stands for the square root of b, a rational function of the others, whose
    g^2 = b the field does not know either: each entry is written A + B g, A and B free of g (_rooted).

    >>> x, y = sp.symbols("x y")
    >>> cancelled(sp.Matrix([[((x + y)**2 - (x - y)**2) / (x*y), x/3 + sp.pi]]))
    Matrix([[4, x/3 + pi]])
    >>> s, c = sp.symbols("s c")
    >>> cancelled(sp.Matrix([[(x*s**2 + x*c**2) / (s**2 + c**2 + x**2)]]), ((s, c),))
    Matrix([[x/(x**2 + 1)]])
    >>> g = sp.Symbol("g")
    >>> cancelled(sp.Matrix([[x / (g**2 + x**2), 1 / (1 + g)]]), roots=((g, 1 - x**2),))
    Matrix([[x, (1 - g)/x**2]])
    """
    symbols = sorted(matrix.free_symbols, key=sp.default_sort_key)
    if not symbols or matrix.has(sp.Float):  # floats: construct_domain's RR, not QQ's exact ratios
        return matrix
    roots = tuple((g, b) for g, b in roots if g in matrix.free_symbols and g not in b.free_symbols)
    symbols = sorted(set(symbols).union(*(b.free_symbols for _, b in roots)), key=sp.default_sort_key)
    field = sp.QQ.frac_field(*symbols)
    indices = [(symbols.index(s), symbols.index(c)) for s, c in circles if s in symbols and c in symbols]
    squares = []
    for g, b in roots:
        try:
            squares.append((symbols.index(g), field.from_sympy(b)))
        except (ValueError, CoercionFailed):  # a root of a root: left as it is
            pass

    def entry(expr: sp.Expr) -> sp.Expr:
        try:
            value = field.from_sympy(expr)
        except (ValueError, CoercionFailed):  # not a rational function of the symbols alone
            return expr
        for sine, cosine in indices:
            value = _folded(value, sine, cosine)
        if squares:  # the roots' relations, then the circles' again (a root's square holds sines)
            for root, square in squares:
                value = _rooted(value, root, square)
            for sine, cosine in indices:
                value = _folded(value, sine, cosine)
        return field.to_sympy(value)
    return matrix.applyfunc(entry)


def _circles(back: dict[sp.Symbol, sp.Expr]) -> tuple[tuple[sp.Symbol, sp.Symbol], ...]:
    """The generators (_as_rational's map back) that are the sine and the cosine of one angle."""
    cosines = {value.args[0]: g for g, value in back.items() if isinstance(value, sp.cos)}
    return tuple((g, cosines[value.args[0]]) for g, value in back.items()
                 if isinstance(value, sp.sin) and value.args[0] in cosines)


def _roots(back: dict[sp.Symbol, sp.Expr]) -> tuple[tuple[sp.Symbol, sp.Expr], ...]:
    """The generators (_as_rational's map back) that are square roots, each with its square written
    in the generators (a loop's height over a ball's x, sqrt((R - r)^2 - (x - (H - r) sin(phi0))^2),
    has the generator of sin(phi0) in its square)."""
    functions = {value: g for g, value in back.items() if not isinstance(value, sp.Pow)}
    return tuple((g, value.base.xreplace(functions)) for g, value in back.items()
                 if isinstance(value, sp.Pow) and value.exp == sp.S.Half)


def _rooted(value, root: int, square):
    """A rational function (an element of sympy's FracField) with g^2 = b applied, g its generator at
    the index `root` and b (`square`) an element free of g: A + B g, A and B free of g, its
    denominator D0 + D1 g made rational by (D0 - D1 g), whose product with it is D0^2 - D1^2 b. As an
    independent generator, the root of a loop's height over a ball rolled in from a chute (its release
    angle a parameter) left 1/(X^2 + g^2), which is 1/(R - r)^2, in the linear system of the loop,
    and its reduction ran past 400 s (rooted, 1 s).

    >>> x, g = sp.symbols("x g")
    >>> field = sp.QQ.frac_field(x, g)
    >>> _rooted(field.from_sympy((g**3 + x) / (g + x)), 1, field.from_sympy(x + 1))
    (x**2*g - 2*x - 1)/(x**2 - x - 1)
    """
    numerator, denominator = value.numer, value.denom
    if numerator.degree(root) < 2 and denominator.degree(root) < 1:
        return value
    field = value.field
    a0, a1 = _halves(numerator, root, square)
    d0, d1 = _halves(denominator, root, square)
    if not d1:
        return (a0 + a1 * field.gens[root]) / d0
    rational = d0 ** 2 - d1 ** 2 * square
    return (a0 * d0 - a1 * d1 * square) / rational + (a1 * d0 - a0 * d1) / rational * field.gens[root]


def _halves(polynomial, root: int, square):
    """A polynomial (sympy's PolyElement) in a generator g (at the index `root`) as (A, B), elements of
    the field of `square` free of g, with polynomial = A + B g where g^2 = square."""
    field, ring = square.field, polynomial.ring
    by_power: dict[int, dict] = {}  # g's power -> the terms free of g: one field sum per power, not per term
    for monomial, coefficient in polynomial.terms():
        by_power.setdefault(monomial[root], {})[monomial[:root] + (0,) + monomial[root + 1:]] = coefficient
    parts = [field.zero, field.zero]
    for k, terms in by_power.items():  # each sum in the field cancels by a gcd: a loop's row took 1 s term by term
        parts[k % 2] += field(ring(terms)) * square ** (k // 2)
    return parts


def _folded(value, sine: int, cosine: int):
    """A rational function (an element of sympy's FracField) with s^2 + c^2 = 1 applied, s and c its
    generators at the indices `sine` and `cosine`: the one with the fewest terms of the value, the value
    with every s^2 written 1 - c^2 and the value with every c^2 written 1 - s^2 (the value itself on a
    tie). As independent generators, a cord's tangent geometry on a double wedge gave entries such as
    (c^4 R d^2 + 2 c^2 s^2 R d^2 + s^4 R d^2 + R^3)/((c^2 + s^2)(R^2 + d^2)), which is R, and the
    rref's gcds of their products ran past 400 s (folded, the system solves in 0.05 s)."""
    numerator, denominator = value.numer, value.denom
    if max(numerator.degree(sine), numerator.degree(cosine), denominator.degree(sine), denominator.degree(cosine)) < 2:
        return value
    field = value.field
    forms = [value] + [field(_squares_written(numerator, a, b)) / field(_squares_written(denominator, a, b))
                       for a, b in ((sine, cosine), (cosine, sine))]
    return min(forms, key=lambda form: len(form.numer) + len(form.denom))


def _squares_written(polynomial, square: int, other: int):
    """A polynomial (sympy's PolyElement) with every x^k of its generator at index `square` written
    x^(k mod 2) (1 - y^2)^(k div 2), y its generator at index `other`."""
    ring = polynomial.ring
    rest = ring.one - ring.gens[other] ** 2
    result = ring.zero
    for monomial, coefficient in polynomial.terms():
        k = monomial[square]
        kept = monomial[:square] + (k % 2,) + monomial[square + 1:]
        result += ring({kept: coefficient}) * rest ** (k // 2)
    return result


def _as_rational(matrix: sp.Matrix, placed: tuple[sp.Expr, ...] = ()) -> tuple[sp.Matrix, dict]:
    """The matrix as rational functions of new symbols (generators), and the map back.

    Roots and functions of the coordinates (a curved track's sqrt, an atan2) become generators,
    so that the field is one of rational functions and not sympy's slow expression domain. A
    root's base is put over one denominator and factored first, and b**(p/q) is written
    b**k * g**r with g = b**(1/q), 0 <= r < q: one generator per base, so that a cord's
    (R**2 + h**2)**(3/2) and sqrt(1 - R**2/(R**2 + h**2)) = h/sqrt(R**2 + h**2) cancel where
    they meet (as independent generators they made a stepped pulley's system too slow to solve).
    """
    matrix = radicals(matrix, placed)
    roots = {a: sp.factor(sp.together(a.base)) ** a.exp for a in matrix.atoms(sp.Pow)
             if a.exp.is_Rational and not a.exp.is_Integer and not a.base.has(sp.Function)}
    matrix = matrix.xreplace(roots)
    generators, replace = {}, {}
    for atom in matrix.atoms(sp.Pow):
        if atom.exp.is_Integer:
            continue
        if atom.exp.is_Rational and not atom.base.has(sp.Function):
            q = atom.exp.q
            g = generators.setdefault((atom.base, q), sp.Dummy(positive=True))
            whole, rest = divmod(atom.exp.p, q)
            replace[atom] = atom.base ** whole * g ** rest
        else:
            replace[atom] = generators.setdefault(atom, sp.Dummy(real=True))
    for atom in matrix.atoms(sp.Function):
        replace[atom] = generators.setdefault(atom, sp.Dummy(real=True))
    back = {g: (key[0] ** sp.Rational(1, key[1]) if isinstance(key, tuple) else key) for key, g in generators.items()}
    return matrix.xreplace(replace), back
