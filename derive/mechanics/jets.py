"""Derivatives along a line of motion at one point: the value, slope and curvature of f(q0 + s u0)
at s = 0, by the chain rule node by node (a second-order jet).

The checks and the states solve the equations of motion in states that give every coordinate
and velocity, where a constraint's row needs d^2/ds^2 of its gap along the motion. sympy's `diff`
builds the whole derivative as a function of s first (for a cord's exact geometry, acos and atan2
of square roots: a third of a second per gap, most of an Atwood machine's derivation), then puts
s = 0. Here each node carries three numbers, or expressions where the point is symbolic, and only
the elementary functions' own derivatives are formed, in a plain symbol. sympy has no such
evaluation (`series` builds the expansion in s, and is slower still), so it is written here.

>>> import sympy as sp
>>> x, y = sp.symbols("x y")
>>> along(sp.sqrt(x**2 + y**2), {x: (3, 1), y: (4, 0)})
(5, 3/5, 16/125)
>>> s = sp.Symbol("s")
>>> sp.diff(sp.sqrt((3 + s)**2 + 16), s, 2).subs(s, 0)
16/125
"""
from __future__ import annotations

from functools import lru_cache

import sympy as sp

Jet = tuple[sp.Expr, sp.Expr, sp.Expr]  # f, df/ds, d^2f/ds^2 at s = 0

#: Functions whose derivatives are taken in plain symbols; any other (Abs, Piecewise, sign, ...)
#: is differentiated by sympy along the line itself.
ELEMENTARY = (sp.sin, sp.cos, sp.tan, sp.asin, sp.acos, sp.atan, sp.atan2, sp.exp, sp.log, sp.sinh, sp.cosh)


def along(expr: sp.Expr, line: dict[sp.Symbol, tuple[sp.Expr, sp.Expr]]) -> Jet:
    """(f, f', f'') of `expr` at s = 0 along `line`, which gives each moving symbol its value and
    rate (q0, u0); every other symbol stays as it is."""
    seen: dict[sp.Basic, Jet] = {}

    def jet(node: sp.Expr) -> Jet:
        if node in seen:
            return seen[node]
        if node in line:
            value, rate = line[node]
            result = (sp.sympify(value), sp.sympify(rate), sp.Integer(0))  # safe: a state's numbers or sympy expressions, never file text
        elif not node.free_symbols & line.keys():
            result = (node, sp.Integer(0), sp.Integer(0))
        elif node.is_Add:
            parts = [jet(a) for a in node.args]
            result = tuple(sp.Add(*(p[k] for p in parts)) for k in range(3))
        elif node.is_Mul:
            result = (sp.Integer(1), sp.Integer(0), sp.Integer(0))
            for factor in node.args:
                a, (b0, b1, b2) = result, jet(factor)
                result = (a[0] * b0, a[1] * b0 + a[0] * b1, a[2] * b0 + 2 * a[1] * b1 + a[0] * b2)
        elif node.is_Pow and not node.exp.free_symbols & line.keys():
            (b0, b1, b2), n = jet(node.base), node.exp
            slope = n * b0 ** (n - 1) if b1 != 0 or b2 != 0 else 0  # no 0 * zoo where the base stays at 0
            bend = n * (n - 1) * b0 ** (n - 2) * b1 ** 2 if b1 != 0 else 0
            result = (b0 ** n, slope * b1, bend + slope * b2)
        elif isinstance(node, ELEMENTARY):
            result = _function(node.func, [jet(a) for a in node.args])
        else:
            result = _by_sympy(node, line)
        seen[node] = result
        return result

    return jet(expr)


def _function(func, arguments: list[Jet]) -> Jet:
    """F(a(s)) for an elementary F of one or more arguments: its gradient and Hessian, formed
    once in plain symbols, at the arguments' values."""
    gradient, hessian, names = _derivatives(func, len(arguments))
    at = dict(zip(names, (a[0] for a in arguments)))
    slopes, curvatures = [a[1] for a in arguments], [a[2] for a in arguments]
    first = [g.xreplace(at) for g in gradient]
    value = func(*(a[0] for a in arguments))
    rate = sp.Add(*(f * s for f, s in zip(first, slopes)))
    curvature = sp.Add(*(f * c for f, c in zip(first, curvatures)),
                       *(hessian[i][j].xreplace(at) * slopes[i] * slopes[j]
                         for i in range(len(arguments)) for j in range(len(arguments)) if slopes[i] != 0 and slopes[j] != 0))
    return value, rate, curvature


@lru_cache(maxsize=None)
def _derivatives(func, count: int):
    names = sp.symbols(f"x0:{count}", cls=sp.Dummy)
    f = func(*names)
    gradient = [sp.diff(f, n) for n in names]
    return gradient, [[sp.diff(g, n) for n in names] for g in gradient], names


def _by_sympy(node: sp.Expr, line: dict) -> Jet:
    """A node with no rule here: sympy's derivatives along the line, s put to zero after."""
    s = sp.Dummy("s")
    moved = node.xreplace({q: sp.sympify(value) + s * rate for q, (value, rate) in line.items()})  # safe: as in along
    first = sp.diff(moved, s)
    return tuple(e.subs(s, 0) for e in (moved, first, sp.diff(first, s)))  # subs: a Derivative in s stays whole
