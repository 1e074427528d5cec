"""Which way an asked quantity points, in words: a vector component answered as a magnitude.

A student answers "the friction force" as 2.13 N and says which way it acts; the engine computes a
signed component along an axis the question may never mention (x to the right, y up, counter-
clockwise positive, along a surface's tangent). `sense` gives the words for the two signs of each
quantity that has a direction, from the scene's own geometry: "up"/"down", "to the right"/"to the
left", "down the slope"/"up the slope" (a surface's tangent where the body touches it),
"counter-clockwise"/"clockwise", and "gained"/"lost" for a change of energy. A quantity with no
direction (a speed, a tension, a moment of inertia, a coordinate measured from a stated origin)
has none. The Solution answers a quantity with a sense as its magnitude, and the documents give
its direction in these words (derive.solution.answers, derive.publishing).

>>> import sympy as sp
>>> from derive.model.scene import Quantity
>>> sense(None, Quantity("acceleration", "block", "y"), None, float)
Sense(positive='up', negative='down')
>>> sense(None, Quantity("angular_acceleration", "disk", None), None, float).of(-1)
'clockwise'
"""
from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass

import sympy as sp

from derive.model.scene import Quantity

AXES = {"x": ("to the right", "to the left"), "y": ("up", "down")}
TURNS = ("counter-clockwise", "clockwise")
SLOPE = ("down the slope", "up the slope")
ENERGY = ("gained", "lost")

#: Quantities whose detail is "x" or "y": a component of a vector along a stated axis.
COMPONENTS = {"acceleration", "velocity", "center_of_mass_velocity", "impulse"}
#: Rotations about the normal to the plane (counter-clockwise positive).
ROTATIONS = {("angular_acceleration", None), ("angular_velocity", None), ("rolling", "angular_velocity")}


@dataclass(frozen=True)
class Sense:
    """The words for the two ways a quantity can point: where its signed value is positive, negative."""

    positive: str
    negative: str

    def of(self, sign: int) -> str:
        """The words for a sign (+1 or -1)."""
        return self.positive if sign > 0 else self.negative


def directional(quantity: Quantity) -> bool:
    """Whether the quantity points one way or the other (so may be asked as a signed component with a
    stated sign convention, `sign:`), whatever the scene's geometry."""
    kind, detail = quantity.kind, quantity.detail
    return (kind in COMPONENTS and detail in AXES or (kind, detail) in ROTATIONS or kind == "kinetic_energy_change"
            or (kind, detail) == ("contact", "acceleration.down_incline")
            or kind in ("contact", "force") and detail in ("friction", "reaction.x", "reaction.y", "torque"))


def sense(scene, quantity: Quantity, coords, sample: Callable[[sp.Expr], float]) -> Sense | None:
    """The words for the signs of an asked quantity, or None where it has no direction. A friction's
    words follow the surface's tangent where the body touches it in the reference configuration,
    evaluated by `sample` (an expression's value at the middle of the parameter ranges)."""
    if not directional(quantity):
        return None
    kind, detail = quantity.kind, quantity.detail
    if kind in COMPONENTS:
        return Sense(*AXES[detail])
    if kind == "force" and detail.startswith("reaction."):
        return Sense(*AXES[detail[-1]])
    if (kind, detail) in ROTATIONS or detail == "torque":
        return Sense(*TURNS)
    if kind == "kinetic_energy_change":
        return Sense(*ENERGY)
    if detail == "acceleration.down_incline":
        return Sense(*SLOPE)
    contact = scene.contact_of(quantity.target)
    tangent = contact.friction_direction(coords).xreplace(coords.at_rest_in_reference())
    return along(*(sample(c) for c in tangent))


def along(x: float, y: float) -> Sense:
    """The words for a direction (x, y) and its opposite: along an axis, or down and up a slope.

    >>> along(0.8, -0.6), along(-1.0, 0.0).negative
    (Sense(positive='down the slope', negative='up the slope'), 'to the right')
    """
    size = (x * x + y * y) ** 0.5
    if abs(y) <= 1e-9 * size:
        return Sense(*AXES["x"]) if x > 0 else Sense(*reversed(AXES["x"]))
    if abs(x) <= 1e-9 * size:
        return Sense(*AXES["y"]) if y > 0 else Sense(*reversed(AXES["y"]))
    return Sense(*SLOPE) if y < 0 else Sense(*reversed(SLOPE))


#: Other words a question uses for the same way: a ramp's or an incline's slope, an anticlockwise turn.
_SAME_WAY = (("incline", "slope"), ("ramp", "slope"), ("anticlockwise", "counter-clockwise"),
             ("anti-clockwise", "counter-clockwise"), ("counterclockwise", "counter-clockwise"))


def stated(sense: Sense, convention: str) -> int | None:
    """The sign that makes a question's stated convention hold: +1 where it names the sense's positive
    words as the positive way ("up positive", "taking up as positive", "y up", "down negative"), -1
    where it names the negative words ("down the incline positive" for an acceleration whose routes
    count up the slope), None where it names neither or both (then the engine cannot tell which way
    the student is told is positive, and refuses).

    >>> stated(Sense("up", "down"), "taking up as positive"), stated(Sense("up", "down"), "down negative")
    (1, 1)
    >>> stated(Sense(*SLOPE), "positive up the incline"), stated(Sense(*TURNS), "clockwise positive")
    (-1, -1)
    >>> stated(Sense(*AXES["x"]), "x toward the pulley") is None
    True
    """
    text = " ".join(convention.lower().replace("$", " ").split())
    for word, same in _SAME_WAY:
        text = text.replace(word, same)
    named = [sign for sign, words in ((1, sense.positive), (-1, sense.negative))
             if re.search(rf"(?<![\w-]){re.escape(words)}(?![\w-])", text)]  # not "clockwise" in "counter-clockwise"
    if len(named) != 1:
        return None
    told_negative = re.search(r"\bnegative\b", text) and not re.search(r"\bpositive\b", text)
    return -named[0] if told_negative else named[0]
