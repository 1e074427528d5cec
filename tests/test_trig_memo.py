"""sympy's trigsimp remembering its nodes (derive.core.trig_memo): the same result as sympy's own, node
by node and across calls, and a node with a Float never answered from a node without one."""
import importlib

import sympy as sp

from derive.core import tidying, trig_memo

_trigsimp = importlib.import_module("sympy.simplify.trigsimp")
x, y, R, r = sp.symbols("x y R r", positive=True)
EXPRESSIONS = [2 * sp.cos(x) ** 2 - 1, sp.sin(x) ** 2 + sp.cos(x) ** 2 + R,
               sp.sqrt(R ** 2 * sp.sin(x) ** 2 + R ** 2 * sp.cos(x) ** 2) * (r * sp.sin(x) * sp.cos(x) + sp.sin(y)),
               (R - r * sp.cos(x)) ** 2 / (R ** 2 - 2 * R * r * sp.cos(x) + r ** 2 * sp.cos(x) ** 2),
               sp.tan(x) * sp.cos(x) / sp.sin(x) + sp.cos(x + y)]


def _with(futrig_node, expr):
    """sympy's trigsimp of expr with `futrig_node` simplifying each node (sympy's own: the memo's wrapped one)."""
    saved = _trigsimp._futrig
    _trigsimp._futrig = futrig_node
    try:
        return sp.trigsimp(expr)
    finally:
        _trigsimp._futrig = saved


def test_the_memo_is_installed_once():
    assert tidying.trig_memo is trig_memo  # tidying installs it on import
    trig_memo.install()
    assert _trigsimp._futrig.remembered
    assert not getattr(_trigsimp._futrig.__wrapped__, "remembered", False)


def test_remembered_trigsimp_is_sympys_and_stays_so_when_asked_again():
    for expr in EXPRESSIONS:
        fresh = _with(_trigsimp._futrig.__wrapped__, expr)
        assert sp.trigsimp(expr) == fresh
        assert sp.trigsimp(expr) == fresh  # the second time from the memo


def test_a_float_node_is_not_answered_from_an_exact_one():
    exact = sp.trigsimp(2 * sp.cos(x) ** 2 - 1)
    floating = sp.trigsimp(2.0 * sp.cos(x) ** 2 - 1)
    assert exact == sp.cos(2 * x)
    assert floating.has(sp.Float)


def test_sympys_simplification_factors_through_the_memo():
    for module in trig_memo.FACTORING:
        assert module.factor.remembered
        assert not getattr(module.factor.__wrapped__, "remembered", False)
    assert not getattr(sp.factor, "remembered", False)  # derive's own calls are sympy's


def test_a_remembered_factoring_is_sympys_and_stays_so_when_asked_again():
    remembered = trig_memo.FACTORING[0].factor
    for expr in [R ** 2 - 2 * R * r + r ** 2, (x ** 2 - y ** 2) * sp.cos(x) ** 2 - (x ** 2 - y ** 2) * sp.sin(x) ** 2,
                 sp.sqrt(R ** 2 - r ** 2) * (R ** 3 - r ** 3) / (R - r)]:
        assert remembered(expr) == sp.factor(expr)
        assert remembered(expr) == sp.factor(expr)  # the second time from the memo
    assert remembered(x ** 2 - 2, extension=sp.sqrt(2)) == sp.factor(x ** 2 - 2, extension=sp.sqrt(2))
    assert remembered(x ** 2 - 2) == x ** 2 - 2  # the options are part of the key


def test_a_float_expression_is_not_factored_from_an_exact_one():
    remembered = trig_memo.FACTORING[0].factor
    assert remembered(2 * x ** 2 - 2) == sp.factor(2 * x ** 2 - 2)
    assert remembered(2.0 * x ** 2 - 2).has(sp.Float)
