"""A step of a worked derivation: a sentence and its equations, what every route and every
quantity writes and the documents typeset (derive.publishing.worksheets).

>>> import sympy as sp
>>> x = sp.Symbol("x")
>>> Step("Solve for x", (sp.Eq(x, 2),)).equations
(Eq(x, 2),)
"""
from __future__ import annotations

import dataclasses
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


def renamed(step: Step, change: dict) -> Step:
    """The step with symbols renamed (`change`) in its equations and in the math of its sentences: the
    engine's f^block as the student's route prints it.

    >>> f, g = sp.symbols("f g")
    >>> renamed(Step("Solve", (sp.Eq(f, 2),)), {f: g}).equations
    (Eq(g, 2),)
    """
    if not change:
        return step
    return dataclasses.replace(step, equations=tuple(e.xreplace(change) for e in step.equations),
                               sentences=tuple(s.with_math(lambda m: m.xreplace(change)) for s in step.sentences))
