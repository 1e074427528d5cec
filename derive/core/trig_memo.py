"""sympy's trigsimp with each subexpression's simplification remembered across calls, and the
factoring that sympy's simplification runs remembered too.

sympy's trigsimp (method 'matching', its default, which tidy and sympy's own simplify and solve
run) is futrig: `bottom_up(expr, _futrig)`, one greedy search of Fu's identities at every node
of the tree. The same nodes come again and again: within one expression (a root that appears
in a velocity's both components), and across the expressions a derivation tidies (each state's
values hold the path's roots). A ball rolled from a chute into a loop ran _futrig 4151 times on
570 distinct nodes; remembered, its derivation took 24 s instead of 28 s, with every expression
the same (a node's result is a function of the node alone: _futrig is deterministic, and the
factoring it runs gives the same factors whatever its random evaluation points).

Within one node's search the same polynomials are factored again and again too: the greedy
search's branches (an expression expanded or not, then factored) meet the same forms, and
sympy's simplify and solve factor what trigsimp factored. The chute's derivation factored about 1300
times (those modules and derive's own), about 360 distinct expressions, half its factoring time on repeats. `install`
remembers `factor` as those modules call it (not as derive calls it: sp.factor is sympy's own).

sympy has no switch for this (its `cacheit` is on neither), so `install` wraps the functions
the modules look up at each call. A node or expression with a Float is not remembered: sympy
1.12 took Float(2.0) == 2, so a key could match a node of another kind.

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
#: The most factorings remembered: a derivation does a few thousand, of a few hundred expressions.
FACTORED = 20_000

_trigsimp = importlib.import_module("sympy.simplify.trigsimp")  # the module, not sympy's function of that name
#: The modules of sympy's simplification whose calls of `factor` are remembered (trigsimp's greedy
#: search, Fu's rules, simplify, and solve's simplification of its roots).
FACTORING = tuple(importlib.import_module(f"sympy.{name}") for name in
                  ("simplify.trigsimp", "simplify.fu", "simplify.simplify", "solvers.solvers"))


def install() -> None:
    """Remember _futrig's and the simplification modules' factor's results in this process (idempotent)."""
    original = getattr(_trigsimp, "_futrig", None)
    if original is not None and not getattr(original, "remembered", False):
        _trigsimp._futrig = _remembered(original, NODES)
    # a sympy without _futrig (a later version may rename it): trigsimp as it is, only slower
    for module in FACTORING:
        factor = getattr(module, "factor", None)
        if factor is not None and not getattr(factor, "remembered", False):
            module.factor = _remembered_factor(factor)


def _remembered(original, size: int):
    """`original`, a function of one expression, remembering up to `size` results (none with a Float)."""
    cached = functools.lru_cache(maxsize=size)(original)

    @functools.wraps(original)
    def remembered(e):
        return original(e) if e.has(sp.Float) else cached(e)

    remembered.remembered = True
    return remembered


def _remembered_factor(original):
    """sympy's factor remembering its results by expression, generators and options: the factors
    are unique (sympy orders them and fixes their signs), whatever the random points its
    multivariate factoring draws; an expression with a Float, or an option that is no key (a
    list), is factored afresh."""
    cached = functools.lru_cache(maxsize=FACTORED)(lambda f, gens, options: original(f, *gens, **dict(options)))

    @functools.wraps(original)
    def remembered(f, *gens, **options):
        if not isinstance(f, sp.Basic) or f.has(sp.Float):
            return original(f, *gens, **options)
        try:
            return cached(f, gens, tuple(sorted(options.items())))
        except TypeError:  # unhashable: an option's list
            return original(f, *gens, **options)

    remembered.remembered = True
    return remembered
