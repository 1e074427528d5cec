"""Derivatives along a line at a point (derive.mechanics.jets) against sympy's own: the
function written out in s, differentiated twice, s put to zero."""
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from derive.mechanics.jets import along

x, y, s, R = sp.symbols("x y s R")


def by_sympy(expr, line):
    moved = expr.xreplace({q: v + s * u for q, (v, u) in line.items()})
    first = sp.diff(moved, s)
    return tuple(e.subs(s, 0) for e in (moved, first, sp.diff(first, s)))


def same(jet, expected):
    return all(sp.simplify(a - b) == 0 for a, b in zip(jet, expected))


CORD = (R * (sp.acos(-R / sp.sqrt((R - x) ** 2 + (4 * R - y) ** 2))
             - sp.atan2(-4 * R * (R - x) + R * (4 * R - y), R * (R - x) + 4 * R * (4 * R - y)))
        - sp.sqrt(-R ** 2 + (R - x) ** 2 + (4 * R - y) ** 2))


@pytest.mark.parametrize("expr, line", [
    (CORD.xreplace({R: sp.Rational(1, 8)}), {x: (0, sp.Rational(-76, 37)), y: (0, sp.Rational(69, 37))}),
    (CORD, {x: (0, 2), y: (0, -3)}),  # a symbolic point: the parameter stays
    (sp.sin(x) * sp.cos(y) ** 3 / (1 + x ** 2), {x: (sp.pi / 3, 2), y: (sp.Rational(1, 2), sp.Rational(-1, 3))}),
    (sp.exp(x * y) + sp.log(2 + x) + sp.tan(y) + sp.atan(x / 3) + sp.asin(y / 2), {x: (1, 1), y: (1, -1)}),
    (sp.Abs(x - 3) * sp.sign(y), {x: (1, 2), y: (1, 5)}),  # no rule of its own: sympy's derivative
    (x ** y, {x: (2, 1), y: (3, 1)}),  # an exponent that moves
    (sp.sqrt(x ** 2), {x: (0, 0)}),  # a root at zero that does not move: no 0 * zoo
])
def test_the_jet_is_sympys_derivative_at_the_point(expr, line):
    assert same(along(expr, line), by_sympy(expr, line))


ATOMS = st.sampled_from([x, y, sp.Integer(2), sp.Rational(1, 3), R])
UNARY = st.sampled_from([sp.sin, sp.cos, sp.atan, sp.exp, sp.sqrt, lambda e: 1 / (2 + e ** 2), lambda e: e ** 3])
expressions = st.recursive(ATOMS, lambda inner: st.one_of(
    st.tuples(UNARY, inner).map(lambda p: p[0](p[1])),
    st.tuples(inner, inner).map(lambda p: p[0] + p[1]),
    st.tuples(inner, inner).map(lambda p: p[0] * p[1]),
    st.tuples(inner, inner).map(lambda p: sp.atan2(p[0], 3 + p[1] ** 2))), max_leaves=6)


@settings(max_examples=40, deadline=None)
@given(expressions, st.integers(-3, 3), st.integers(-3, 3))
def test_any_composition_of_elementary_functions(expr, u, v):
    line = {x: (sp.Rational(1, 2), u), y: (sp.Rational(-1, 3), v)}
    jet, expected = along(expr, line), by_sympy(expr, line)
    assert all(abs(sp.N(a - b, 30).xreplace({R: sp.Rational(7, 5)})) < 1e-20 for a, b in zip(jet, expected))
