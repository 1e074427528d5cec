"""sympy's trigsimp with each subexpression's simplification remembered across calls.

sympy's trigsimp (method 'matching', its default, which tidy and sympy's own simplify and solve
run) is futrig: `bottom_up(expr, _futrig)`, one greedy search of Fu's identities at every node
of the tree. The same nodes come again and again: within one expression (a root that appears
in a velocity's both components), and across the expressions a derivation tidies (each state's
values hold the path's roots). A ball rolled from a chute into a loop ran _futrig 4151 times on
570 distinct nodes; remembered, its derivation took 24 s instead of 28 s, with every expression
the same (a node's result is a function of the node alone: _futrig is deterministic, and the
factoring it runs gives the same factors whatever its random evaluation points).

sympy has no switch for this (its `cacheit` is not on _futrig), so `install` wraps the function
its futrig looks up at each call. A node with a Float is not remembered: sympy 1.12 takes
Float(2.0) == 2, so a key could match a node of another kind.

>>> install()
>>> x = sp.Symbol("x")
>>> sp.trigsimp(2 * sp.sin(x)**2 + 2 * sp.cos(x)**2)
2
"""
from __future__ import annotations

import functools
import importlib

import sympy as sp

#: The most nodes remembered (the least recently used go first): a derivation meets a few thousand.
NODES = 50_000

_trigsimp = importlib.import_module("sympy.simplify.trigsimp")  # the module, not sympy's function of that name


def install() -> None:
    """Remember _futrig's results in this process (idempotent)."""
    original = getattr(_trigsimp, "_futrig", None)
    if original is None or getattr(original, "remembered", False):
        return  # a sympy without it (a later version may rename it): trigsimp as it is, only slower
    cached = functools.lru_cache(maxsize=NODES)(original)

    @functools.wraps(original)
    def remembered(e):
        return original(e) if e.has(sp.Float) else cached(e)

    remembered.remembered = True
    _trigsimp._futrig = remembered
