"""Derived expressions in their simplest readable form: `tidy` (rational functions cancelled,
sin^2 + cos^2 folded, roots and absolute values of what the file's placement makes positive
taken out), `simplest` (the shortest polynomial form, for the steps), `root` (a square root kept
as one, as the notes write it) and `radicals` (roots of perfect squares and absolute values of
signed factors resolved). Every route's solutions, the steps and the answers go through them.

>>> m, g, x = sp.symbols("m g x")
>>> tidy(m*g*sp.sin(x)**2 + m*g*sp.cos(x)**2)
g*m
"""
from __future__ import annotations

from functools import lru_cache

import sympy as sp
from sympy.core import random

from derive.core import limits, trig_memo

trig_memo.install()  # every trigsimp of the process (tidy's, and sympy's simplify and solve's) remembers its nodes


def simplest(expr: sp.Expr) -> sp.Expr:
    """Expanded, with sin^2 + cos^2 folded where the directions of surfaces put it: the shortest
    of the expanded form and the forms with every cos^2 (or every sin^2) of one angle rewritten
    through the other. A polynomial reduction, where sympy's trigsimp searched every identity
    and took minutes on a drum's steps at some term orders (it showed these steps no shorter).

    >>> m, g, x = sp.symbols("m g x")
    >>> simplest(m*g*sp.sin(x)**2 + m*g*sp.cos(x)**2 + m*sp.cos(x)**2)
    g*m + m*cos(x)**2
    """
    expr = sp.expand(expr)
    angles = {f.args[0] for f in expr.atoms(sp.sin, sp.cos)}
    for angle in sorted(angles, key=sp.default_sort_key):
        forms = [expr] + [sp.expand(expr.replace(
            lambda e, f=f: e.is_Pow and e.base == f(angle) and e.exp.is_Integer and e.exp >= 2,
            lambda e, f=f, other=other: e.base ** (e.exp % 2) * (1 - other(angle) ** 2) ** (e.exp // 2)))
            for f, other in ((sp.cos, sp.sin), (sp.sin, sp.cos))]
        expr = min(forms, key=sp.count_ops)  # the first of the shortest: the expanded form on a tie
    return expr


#: Operations past which tidy first reduces a ratio of polynomials in symbols, sines and cosines
#: by cos^2 = 1 - sin^2 (every power), and with roots or absolute values in it by _folded_squares:
#: Newton–Euler's acceleration of a block pulled over a pulley up an incline came as a ratio of
#: polynomials of degree 19 in sin(theta) that trigsimp took 225 s over (0.2 s reduced). Shorter
#: expressions (trigsimp finds the perfect squares of their roots: a spring's length) go to
#: trigsimp as they are, which keeps the textbook's forms
#: (M g (3 sin^2 + 1)/4, not -M g (3 cos^2 - 4)/4) and the equations sympy's solve finds roots of.
LONG = 200
#: sympy's multivariate factoring (Wang's algorithm, which trigsimp and factor run) draws random
#: evaluation points from sympy's own generator, seeded afresh in each process: the same tidy took
#: 0.3 s or 32 s by the draw (a bearing's force, in a box tilted and rolled; a test ran 20 minutes).
#: tidy seeds it before each expression, so that its time, like its result, is the expression's
#: alone: a slow one is slow every time, and shows in the tests.
SEED = 0


def tidy(expr: sp.Expr, placed: tuple[sp.Expr, ...] = ()) -> sp.Expr:
    """A compact form of a solved expression: rational functions cancelled (a long one reduced by
    sin^2 + cos^2 = 1), trigonometric identities applied where every angle is a plain one, then
    factored; a Piecewise (friction's regimes) case by case. `placed`: expressions positive as the
    file places the scene (Scene.placed), whose absolute values are themselves.

    >>> m, g, x = sp.symbols("m g x")
    >>> tidy(m*g*sp.sin(x)**2 + m*g*sp.cos(x)**2)
    g*m
    """
    if isinstance(expr, sp.MatrixBase):  # mutable, so not remembered
        return _tidy.__wrapped__(expr, placed)
    return _tidy(expr, tuple(placed))


@lru_cache(maxsize=4096)  # answers, checks and steps tidy the same expression from each route
def _tidy(expr: sp.Expr, placed: tuple[sp.Expr, ...]) -> sp.Expr:
    if expr.has(sp.Piecewise):  # regimes: each case in its own simplest form
        folded = sp.piecewise_fold(expr)
        if isinstance(folded, sp.Piecewise):
            return sp.Piecewise(*((tidy(value, placed), where) for value, where in folded.args))
    random.seed(SEED)  # its time a function of `expr` alone (module docstring of SEED)
    with limits.time_limit("simplifying"):
        expr = sp.cancel(sp.together(radicals(expr, placed)))
        if expr.has(sp.sin, sp.cos) and _plain_angles(expr) and not _rational_trigonometric(expr) \
                and sp.count_ops(expr) > LONG:
            folded = _folded_squares(expr)  # not trigsimp: 90 s a cord's run over a pulley
            if folded is not None:
                return sp.factor_terms(sp.factor(folded))
        if expr.has(sp.sin, sp.cos) and _rational_trigonometric(expr) and sp.count_ops(expr) > LONG:
            numerator, denominator = sp.fraction(expr)
            expr = sp.cancel(simplest(numerator) / simplest(denominator))
        if expr.has(sp.sin, sp.cos):
            expr = sp.trigsimp(expr) if _plain_angles(expr) else sp.cancel(simplest(expr))
        return _numeric_roots(sp.factor_terms(sp.factor(expr)))


def _numeric_roots(expr: sp.Expr) -> sp.Expr:
    """Square roots of numbers in one product multiplied out: sqrt(3 - sqrt(5)) sqrt(3 + sqrt(5)) is 2
    (a particle leaving a dome at 2R/3), which sympy keeps as two roots.

    >>> _numeric_roots(sp.Symbol("R") * sp.sqrt(3 - sp.sqrt(5)) * sp.sqrt(3 + sp.sqrt(5)) / 3)
    2*R/3
    """
    def roots(term):
        return [f for f in term.args if f.is_Pow and f.exp == sp.S.Half and f.base.is_number and not f.base.is_Rational]

    def combined(term):
        found = roots(term)
        rest = sp.Mul(*(f for f in term.args if f not in found))
        return rest * sp.sqrt(sp.expand(sp.Mul(*(f.base for f in found))))

    return expr.replace(lambda e: e.is_Mul and len(roots(e)) >= 2, combined)


def _plain_angles(expr: sp.Expr) -> bool:
    """Whether every sine and cosine is of an angle free of other functions (theta, 2*phi + pi/3):
    sympy's trigsimp searches its identities there in a second; of an angle such as
    101*acos(...)/100 it searched for minutes (a slip angle put 1% off) and found nothing to fold,
    so those get the polynomial folding of sin^2 + cos^2 only.

    >>> x = sp.Symbol("x")
    >>> _plain_angles(sp.sin(2*x + 1)), _plain_angles(sp.cos(sp.acos(x/3)/2))
    (True, False)
    """
    return all(not f.args[0].atoms(sp.Function) for f in expr.atoms(sp.sin, sp.cos))


def root(expr: sp.Expr) -> sp.Expr:
    """sqrt(expr) kept as one root, as the notes write it (sympy would split sqrt(M*g) into
    sqrt(M)*sqrt(g) for positive symbols), unless it is a perfect square: sqrt(v0**2) is v0."""
    radicand = tidy(expr)
    evaluated = sp.sqrt(radicand)
    if all(p.exp.is_Integer for p in evaluated.atoms(sp.Pow)) and not evaluated.has(sp.Abs):
        return evaluated
    return sp.Pow(radicand, sp.S.Half, evaluate=False)


def _rational_trigonometric(expr: sp.Expr) -> bool:
    """Whether expr is a rational function of symbols and of sines and cosines of plain angles."""
    return all(isinstance(f, (sp.sin, sp.cos)) for f in expr.atoms(sp.Function)) and _plain_angles(expr) \
        and all(p.exp.is_Integer for p in expr.atoms(sp.Pow))


def _folded_squares(expr: sp.Expr) -> sp.Expr | None:
    """A ratio in which roots and absolute values meet sines and cosines, with
    sin^2 = 1 - cos^2, sqrt(b)^2 = b and |x|^2 = x^2 applied to its numerator and denominator as
    polynomials in them, then cancelled: each an identity, so nothing is assumed of a sign. A cord
    from a block on an incline over a pulley to a hanging block gave its acceleration as a ratio of
    7000 operations with sqrt(b), 1/sqrt(b) and |d - r cos(theta)|, over which trigsimp took 90 s
    (this takes 1 s). sympy's ratsimpmodprime does the same over a Groebner basis, but needs a
    prime ideal, which |x|^2 = x^2 is not. Where the denominator would keep a root or an absolute
    value, or a root is not a square root of a polynomial, None: rationalizing a denominator could
    make one that vanishes.

    >>> b, th = sp.symbols("b theta", positive=True)
    >>> _folded_squares((sp.sqrt(b)**3*sp.sin(th)**2 + sp.sqrt(b)**3*sp.cos(th)**2) / b)
    sqrt(b)
    """
    squares = {}
    for atom in sorted(expr.atoms(sp.Pow, sp.Abs), key=sp.default_sort_key):
        inner = atom.args[0]
        if isinstance(atom, sp.Abs):
            squares[atom] = inner ** 2
        elif atom.exp.is_Rational and atom.exp.q == 2 and sp.fraction(sp.together(inner))[1] == 1:
            squares.setdefault(sp.sqrt(inner), inner)
        elif not atom.exp.is_Integer:
            return None  # a cube root, or a root of a ratio: no square of a polynomial folds it
        if not _rational_trigonometric(inner):
            return None  # nested
    squares.update({f: 1 - sp.cos(f.args[0]) ** 2 for f in expr.atoms(sp.sin)})  # last: the others bring sines
    symbols = {atom: sp.Dummy() for atom in squares}
    generic = expr.xreplace({a: symbols[sp.sqrt(a.base)] ** (2 * a.exp) for a in expr.atoms(sp.Pow)
                             if a.exp.is_Rational and a.exp.q == 2})
    numerator, denominator = sp.fraction(sp.together(generic.xreplace(symbols)))  # expr comes cancelled
    for atom, square in squares.items():
        relation = symbols[atom] ** 2 - square.xreplace(symbols)
        numerator = sp.rem(numerator, relation, symbols[atom])
        denominator = sp.rem(denominator, relation, symbols[atom])
    if denominator == 0 or denominator.free_symbols & set(symbols.values()):
        return None
    back = {symbol: atom for atom, symbol in symbols.items()}
    return sp.cancel(numerator / denominator).xreplace(back)


def _positive(factor: sp.Expr, placed: tuple[sp.Expr, ...] = ()) -> bool:
    """Whether a factor is positive for every value of its symbols (positive ones) and angles: each
    sine and cosine put in [-1, 1] by sympy's interval arithmetic (AccumBounds); or is one of the
    `placed` factors (positive where the file places the bodies, a condition of every variant).

    >>> R, th = sp.symbols("R theta", positive=True)
    >>> _positive(sp.cos(th)**2 + 20*sp.cos(th) + 101), _positive(R + sp.cos(th))
    (True, False)
    """
    if factor.is_positive or any(sp.expand(factor - p) == 0 for p in placed):
        return True
    bounded = factor.xreplace({f: sp.AccumBounds(-1, 1) for f in factor.atoms(sp.sin, sp.cos)})
    if bounded.free_symbols:
        return _positive_square(factor)
    return bool(bounded.min.is_positive) if isinstance(bounded, sp.AccumBounds) else bool(bounded.is_positive)


def _positive_square(factor: sp.Expr) -> bool:
    """Whether a factor is a*x**2 + b*x + c with a and c - b**2/(4 a) positive for all values, for
    one of its symbols x: then it is positive for every real x (the square completed). A cord's
    squared length from a block to a pulley, d**2 - 2*d*r*cos(theta) + r**2*cos(theta)**2 + r**2,
    is (d - r cos(theta))**2 + r**2.

    >>> d, r, th = sp.symbols("d r theta", positive=True)
    >>> _positive_square(d**2 - 2*d*r*sp.cos(th) + r**2*sp.cos(th)**2 + r**2), _positive_square(d**2 - r**2)
    (True, False)
    """
    if sp.fraction(sp.together(factor))[1] != 1:
        return False  # a polynomial factor only (the remainder below is one too)
    inside = set().union(*(f.free_symbols for f in factor.atoms(sp.Function)))
    for x in sorted(factor.free_symbols - inside, key=sp.default_sort_key):
        polynomial = sp.Poly(factor, x)
        if polynomial.degree() == 2:
            a, b, c = polynomial.all_coeffs()
            if _positive(a) and _positive(sp.expand(4 * a * c - b ** 2)):  # = 4 a (c - b^2/(4 a))
                return True
    return False


def _factors(expr: sp.Expr) -> list[tuple[sp.Expr, sp.Integer]]:
    """expr (a rational function of symbols, sines and cosines) as (factor, power) pairs, its
    numerical coefficient first, with sin^2 + cos^2 folded first."""
    numerator, denominator = sp.fraction(sp.together(simplest(sp.together(expr))))
    pairs = []
    for part, sign in ((numerator, 1), (denominator, -1)):
        coefficient, factors = sp.factor_list(part)
        pairs += [(coefficient, sign), *((f, sign * k) for f, k in factors)]
    return pairs


def _unsigned(value: sp.Expr, placed: tuple[sp.Expr, ...] = ()) -> sp.Expr:
    """|value|, with the sign of each factor taken out where it is the same for all values of its
    symbols (sympy writes a tangent length sqrt((R*cos(theta) + 10*R)**2) as Abs(R*cos(theta) + 10*R)).

    >>> R, th = sp.symbols("R theta", positive=True)
    >>> _unsigned(-R*sp.cos(th) - 10*R), _unsigned(R*sp.cos(th))
    (R*(cos(theta) + 10), R*Abs(cos(theta)))
    """
    if not _rational_trigonometric(value):
        return sp.Abs(value)
    signed, unknown = sp.Integer(1), sp.Integer(1)
    for factor, power in _factors(value):
        if _positive(factor, placed):
            signed *= factor ** power
        elif _positive(-factor, placed):
            signed *= (-factor) ** power
        else:
            unknown *= factor ** power
    return signed * sp.Abs(unknown)


def _root_factors(base: sp.Expr, exp: sp.Rational, placed: tuple[sp.Expr, ...] = ()) -> sp.Expr:
    """base**exp with sin^2 + cos^2 folded in the base, and each factor of it that is positive for
    all values (_positive) raised on its own: the tangent length of a cord from a pulley at
    (R sin(theta), R cos(theta)) to a block 10 R below it, sqrt(R**2*(cos(theta) + 10)**2), is then
    R*(cos(theta) + 10), and the run's sqrt(1 - R**2/|D|**2) shares its root with |D|**3 (as
    separate roots of unfolded bases, an incline's pulley made a system sympy did not solve in 15
    minutes). The rest of the base keeps one root: sqrt(x*y) is not sqrt(x)*sqrt(y) for negative x, y.

    >>> R, th = sp.symbols("R theta", positive=True)
    >>> _root_factors(R**2*sp.sin(th)**2 + R**2*sp.cos(th)**2, sp.Rational(-3, 2))
    R**(-3)
    """
    whole, kept = sp.Integer(1), sp.Integer(1)
    for factor, power in _factors(base):
        if _positive(factor, placed):
            whole *= factor ** (power * exp)
        elif power % 2 == 0 and _positive(-factor, placed):  # (h - R)**2 where R - h is placed positive
            whole *= (-factor) ** (power * exp)
        else:
            kept *= factor ** power
    return whole * kept ** exp


def radicals(expr, placed: tuple[sp.Expr, ...] = ()):
    """expr (or a matrix) with each root of a base of symbols, sines and cosines written by
    _root_factors, and each Abs by _unsigned: what a cord's tangent geometry needs before it
    cancels. `placed`: factors positive as the file places the scene (a hanging block's run |h - R|
    is h - R where it hangs below its pulley).

    >>> R, th = sp.symbols("R theta", positive=True)
    >>> radicals(sp.sqrt(R**2*sp.sin(th)**2 + R**2*sp.cos(th)**2 + 3*R**2) + sp.Abs(sp.cos(th) - 2))
    2*R - cos(theta) + 2
    """
    expr = expr.xreplace(_unnested(expr))
    roots = {a: _root_factors(a.base, a.exp, placed) for a in expr.atoms(sp.Pow)
             if a.exp.is_Rational and not a.exp.is_Integer and _rational_trigonometric(a.base)}
    expr = expr.xreplace(roots)
    return expr.xreplace({a: _unsigned(a.args[0], placed) for a in expr.atoms(sp.Abs)})


def _unnested(expr) -> dict[sp.Expr, sp.Expr]:
    """Each root whose base holds roots that square away once the base is expanded, with its base
    expanded: a ball's distance from a loop's center, on the loop as a chain of states reaches it
    from a chute (its coordinates from the placement on the chute, its height a root), came as
    sqrt((x - a)**2 + (b - sqrt((R - r)**2 - (x - a)**2) - b)**2), which is sqrt((R - r)**2); as an
    opaque root it made the states' linear solves run past 300 s.

    >>> x, R, b, c = sp.symbols("x R b c", positive=True)
    >>> list(_unnested(sp.sqrt(x**2 + (b*(c + 1) - sp.sqrt(R**2 - x**2) - b*c - b)**2)).values())
    [R]
    """
    result = {}
    for a in expr.atoms(sp.Pow):
        if a.exp.is_Rational and not a.exp.is_Integer \
                and any(p.exp.is_Rational and not p.exp.is_Integer for p in a.base.atoms(sp.Pow)):
            base = sp.expand(a.base)
            if _rational_trigonometric(base):
                result[a] = base ** a.exp
    return result


def leading_plus(expr: sp.Expr) -> sp.Expr:
    """`expr` written without a leading minus where one of its factors is a sum whose terms can
    take it: g (m2 - m1 sin(theta))/(m1 + m2), not -g (m1 sin(theta) - m2)/(m1 + m2). The form a
    teacher writes a positive quantity in (tidy leaves the minus outside: sympy's canonical order).

    >>> a, b, c = sp.symbols("a b c", positive=True)
    >>> leading_plus(-c * (a - b)), leading_plus(-a * b)
    (c*(-a + b), -a*b)
    """
    if not expr.could_extract_minus_sign():
        return expr
    numerator, denominator = sp.fraction(sp.together(expr))
    coefficient, factors = numerator.as_coeff_mul()
    for i, factor in enumerate(factors):
        if factor.is_Add:
            turned = sp.Add(*(-term for term in factor.args), evaluate=False)
            return sp.Mul(-coefficient, *factors[:i], turned, *factors[i + 1:]) / denominator
    return expr
