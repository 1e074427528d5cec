"""A step of a worked derivation: a sentence and its equations, what every route and every
quantity writes and the documents typeset (derive.publishing.worksheets).

>>> import sympy as sp
>>> x = sp.Symbol("x")
>>> Step("Solve for x", (sp.Eq(x, 2),)).equations
(Eq(x, 2),)
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp


@dataclass(frozen=True)
class Step:
    """One step of a derivation as the lecture notes would write it: a sentence and equations.
    `role`: "equations" for the equations a route solves (its equations of motion and its
    constraints), "solve" for the solving of them, which a worked solution refers back to by
    their numbers ("from (4) to (11)"); "" for any other step. `body`: the body whose balance a
    Newton–Euler step states (its free-body diagram goes beside it), "" for any other step.
    `sentences`: what the scene's parts contribute to it, in words with their symbols
    (derive.text.prose), said before it."""

    text: str
    equations: tuple[sp.Eq, ...] = ()
    role: str = ""
    body: str = ""
    sentences: tuple = ()
