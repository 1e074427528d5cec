"""Where a function of a path's one coordinate s first reaches zero ahead of the start: the state a
motion gets to (derive.mechanics.states), as sympy's roots of the equation, with the signs the
middle of the parameter ranges decides written out first (`signs_settled`), a polynomial in the
cosine of one angle solved through it (`cosine_roots`), the nearest root ahead kept where it is a
root at the sample parameters and no change of sign comes before it (`first`), and what keeps it
a root in every variant (`a_root`).
"""
from __future__ import annotations

import numpy as np
import sympy as sp

from derive.core.tidying import radicals, tidy
from derive.model.kinematics import roots
from derive.mechanics.reaching import Gets, Path
from derive.mechanics.state_errors import StateError, StateLimit


def toward(positions: dict, condition: Gets, s: sp.Symbol, s0: sp.Expr, decide) -> int:
    """+1 or -1: the way s must go for the state's coordinate to get to its value (the nearest
    such point on the path), 0 where it never does."""
    if condition.coordinate.q == s and condition.measured is None:
        return 1 if decide(condition.value - s0) > 0 else -1
    found = [r for r in roots(condition.at(positions) - condition.value, s) if real(r, decide)]
    ahead = [decide(r) - decide(s0) for r in found if abs(decide(r) - decide(s0)) > 1e-12]
    return 0 if not ahead else 1 if min(ahead, key=abs) > 0 else -1


def a_root(function: sp.Expr, s: sp.Symbol, s0: sp.Expr, s1: sp.Expr) -> list:
    """What keeps s1, a root of `function` at the middle of the ranges, a root in every variant:
    sympy's solution of an equation with roots in it holds where the roots' signs are those of the
    middle (squaring both sides of sqrt(L^2 - x^2) = L - h gives an x also where L < h, on the
    other branch of the circle). Positive where function(s1) is zero to 1e-9 of function(s0), as
    `first` asks of a root at the middle."""
    residual = function.xreplace({s: s1})
    scale = function.xreplace({s: s0})
    if residual == 0 or tidy(scale) == 0:
        return []
    return [(sp.Rational(1, 10**18) * scale**2 - residual**2, "the formula derive found for the state does not hold "
                                                                 "at these values (they put the motion on another "
                                                                 "branch of the scene's geometry than the middle of "
                                                                 "the parameter ranges)")]


def first(equation: sp.Eq, function: sp.Expr, path: Path, decide, fails: str) -> sp.Expr:
    """The first s ahead of the start (in the path's direction) where `function` of s is zero:
    sympy's roots of `equation` (with their turns by 2 pi where s is in a trigonometric
    function) that are roots at the sample parameters, the nearest one ahead, and no change of
    sign before it (sampled), which would be a root sympy missed."""
    s, s0, direction = path.s, path.start[path.s], path.direction
    if equation in (sp.true, sp.false):  # K(s) = 0 with K constant: it never holds (or always)
        raise StateError(f"{fails} (it moves {'up' if direction > 0 else 'down'} in {s} from {sp.sstr(s0)})")
    if equation.lhs == s:
        found = [equation.rhs]
    else:
        equation = signs_settled(equation, s, s0 + direction * sp.Rational(1, 10**6), decide)
        found = cosine_roots(equation.lhs - equation.rhs, s)
        found = found if found is not None else shifted_roots(equation.lhs - equation.rhs, s)
        try:
            found = found if found is not None else [r for r in sp.solve(equation, s) if not r.has(sp.I)]
        except NotImplementedError:
            raise StateLimit(f"solve {sp.sstr(equation)} for {s}") from None
        if any(f.has(s) for f in function.atoms(sp.sin, sp.cos, sp.tan)):  # periodic in s
            found = [r + 2 * sp.pi * k for r in found for k in (-1, 0, 1)]
    start, scale = decide(s0), 1 + abs(decide(function.xreplace({s: s0})))
    on_path = [r for r in found if real(r, decide) and all(real(p.xreplace({s: r}), decide) for p in path.positions.values())]
    ahead = sorted({r for r in on_path if direction * (decide(r) - start) > 1e-12
                    and abs(decide(function.xreplace({s: r}))) <= 1e-9 * scale},
                   key=lambda r: abs(decide(r) - start))
    if not ahead:
        # Where the coordinate followed turns back (a bob's x at the level of its pivot), the path
        # in it ends: the state may lie beyond, on the motion's way back in it.
        ends = [r for r in roots(sp.fraction(sp.together(path.inertia))[1], s)
                if real(r, decide) and direction * (decide(r) - start) > 1e-12]
        if ends:
            end = min(ends, key=lambda r: abs(decide(r) - start))
            raise StateLimit(f"follow the motion past {s} = {sp.sstr(end)}, where that coordinate turns back: "
                             "give a state there (when:) and reach this one from it (from:)")
        raise StateError(f"{fails} (it moves {'up' if direction > 0 else 'down'} in {s} from {sp.sstr(s0)})")
    first = ahead[0]
    end = decide(first)
    signs = [decide(function.xreplace({s: s0 + sp.Rational(k, 64) * (first - s0)})) for k in range(1, 64)]
    if any(a * b < 0 for a, b in zip(signs, signs[1:])):
        raise StateLimit(f"find where {sp.sstr(function)} = 0 in closed form: it changes sign before {s} = {end:.6g}")
    return first


def signs_settled(equation: sp.Eq, s: sp.Symbol, ahead: sp.Expr, decide) -> sp.Eq:
    """The equation with the signs the middle of the ranges decides written out, so that sympy
    (or `cosine_roots`) solves a polynomial: atan2(0, x) of a positive x as 0, |x| free of s and
    the roots of squares by x's sign there (tidying.radicals), and |a(s)| as a or -a by its sign
    just ahead of the start (a ball's cos on a dome). A ball rolling inside a loop gave its normal
    force with atan2(0, R - r), |R - r| and sqrt(1 - sin^2) in it, which sympy's solve took more
    than the time limit over. Each an identity where those signs hold: a root past a change of
    one fails `a_root`'s check in the variants where it does.

    >>> x, R, r = sp.symbols("x R r", positive=True)
    >>> signs_settled(sp.Eq(sp.sqrt((R - r)**2) * sp.cos(x + sp.atan2(0, R - r)), 0), x, sp.Rational(1, 10), lambda e: 1)
    Eq((R - r)*cos(x), 0)
    """
    equation = equation.xreplace({a: sp.Integer(0) for a in equation.atoms(sp.atan2)
                                  if a.args[0] == 0 and not a.has(s) and decide(a.args[1]) > 0})
    placed = tuple({a.args[0] if decide(a.args[0]) > 0 else -a.args[0] for a in equation.atoms(sp.Abs)
                    if not a.has(s)})
    equation = radicals(equation, placed)
    equation = equation.xreplace({p: sp.Abs(p.base.base) for p in equation.atoms(sp.Pow)
                                  if p.exp == sp.S.Half and isinstance(p.base, sp.Pow) and p.base.exp == 2})
    return equation.xreplace({a: a.args[0] if decide(a.args[0].xreplace({s: ahead})) >= 0 else -a.args[0]
                              for a in equation.atoms(sp.Abs) if a.has(s)})


def cosine_roots(expr: sp.Expr, s: sp.Symbol) -> list[sp.Expr] | None:
    """The roots in s of a polynomial in cos(a s + b) and sin(a s + b)^2 (a ball's grip on a dome,
    mu^2 N^2 - f^2), through the polynomial in c = cos(a s + b): s = (+-acos(c) - b)/a (and their
    turns by 2 pi/a). sympy's solve took minutes on the trigonometric form. None where `expr` is
    not of that form."""
    arguments = {f.args[0] for f in expr.atoms(sp.sin, sp.cos) if f.has(s)}
    if len(arguments) != 1:
        return None
    (argument,) = arguments
    slope = sp.diff(argument, s)
    if slope == 0 or slope.has(s):
        return None
    c = sp.Dummy("c", real=True)
    sine = sp.sin(argument)
    polynomial = sp.expand(expr).replace(lambda e: e.is_Pow and e.base == sine and e.exp.is_even,  # sin^4: (1 - c^2)^2
                                         lambda e: (1 - c**2) ** (e.exp / 2)).xreplace({sp.cos(argument): c})
    if polynomial.has(s):
        return None
    offset = argument.xreplace({s: 0})
    cosines = [r for r in sp.solve(polynomial, c) if not r.has(sp.I)]
    return [(sign * sp.acos(r) - offset + 2 * sp.pi * k) / slope for r in cosines for sign in (1, -1) for k in (-1, 0, 1)]


def shifted_roots(expr: sp.Expr, s: sp.Symbol) -> list[sp.Expr] | None:
    """The roots in s of a sum of sines and cosines of integer multiples of s plus constants, found
    in s - c for c one of the constants that zero an argument: with the arguments a - phi,
    2 phi, a + phi the sum factors once expanded (a ladder leaves its wall where
    -2 sin(s) + 3 sin(2 a - 2 s) - 2 sin(2 a - s), which is 2 cos(phi) (3 sin(phi) - 2 sin(a)) at
    s = a - phi; sympy's solve of the first form ran past the time limit, of the second took
    0.4 s). The shift taken is the one whose expanded sum factors into the fewest operations; None
    where it does not factor, or none is needed.

    >>> s, a = sp.symbols("s a", real=True)
    >>> sorted(shifted_roots(-2 * sp.sin(s) + 3 * sp.sin(2 * a - 2 * s) - 2 * sp.sin(2 * a - s), s), key=str)
    [a + 3*pi/2, a + asin(2*sin(a)/3) + pi, a + pi/2, a - asin(2*sin(a)/3)]
    """
    arguments = {sp.expand(f.args[0]) for f in expr.atoms(sp.sin, sp.cos) if f.has(s)}
    slopes = {argument: argument.coeff(s) for argument in arguments}
    if not arguments or any(not k.is_Integer or (argument - k * s).has(s) for argument, k in slopes.items()):
        return None
    phi = sp.Dummy("phi", real=True)
    shifts = {c: sp.factor(sp.expand_trig(sp.expand(expr.xreplace({s: c + phi}))))
              for c in dict.fromkeys(sp.expand(-(argument - k * s) / k) for argument, k in slopes.items())}
    c = min(shifts, key=lambda c: (sp.count_ops(shifts[c]), str(c)))  # the sum that factors furthest
    if c == 0 or len(sp.Mul.make_args(shifts[c])) < 2:
        return None
    try:
        return [c + r for r in sp.solve(shifts[c], phi) if not r.has(sp.I)]
    except NotImplementedError:
        return None


def real(expr: sp.Expr, decide) -> bool:
    try:
        return bool(np.isfinite(decide(expr)))
    except (TypeError, ValueError):
        return False
