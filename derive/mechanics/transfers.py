"""A body's contact passing onto another surface where the two meet (an event of kind transfer,
`{transfer: ball, to: loop}`): a ball rolling down a ramp into a loop, a block sliding off a curved
ramp onto the floor and up another.

The contact on the new surface (`onto`) is the same part: the same body, regime and friction, and
its forces the same unknowns (N, f), so that asks read them in the states after as before; rolling,
the arc along the new surface plus R theta counts from where it passes (`slipped`), so that its
rolling gap is zero there. The body must touch the new surface where it is (`gap`: zero).

derive.solution.state_answers solves the change as an impact whose joint is the new contact, by both routes
of derive.mechanics.impacts (the generalized momenta jump by the joints' generalized impulses, and
each body's impulse and momentum), compared by derive.solution.crosschecks. Where the two paths are tangent
at the junction and the body's contact point is at rest on the new surface as it was on the old
(rolling: the spin is continuous), the velocities already meet the new contact's constraints: every
impulse is zero, and the velocities, and so the kinetic energy, are what they were. Where they meet
at a kink the direction changes in an instant, which takes an impulse; how large depends on how
the body strikes the new surface (does it bounce; does friction make a rolling body grip at once),
which a transfer does not state, and a textbook's "the speed is kept" holds only for a rounded,
tangent junction. So a kink, or a grip that would need a friction impulse, is refused (`needed`
names the impulse) rather than taken as one impact model's answer.

>>> import sympy as sp
>>> from derive.model.kinematics import Coordinates
>>> from derive.parts.contact import Contact
>>> from derive.parts.surfaces import Circle, Plane
>>> from derive.model.scene import Body, Scene
>>> m, R = sp.symbols("m R", positive=True)
>>> scene = Scene({"block": Body("block", "point", m, {}, at=(-R, R))}, (Contact("block_contact", "block", "ramp",
...               False),), surfaces={"ramp": Circle("ramp", R, (0, R)), "floor": Plane("floor", 0)})
>>> coords = Coordinates(scene)
>>> x, y = coords.of("block", "x"), coords.of("block", "y")
>>> bottom = {x.q: R, y.q: -R, x.u: sp.Symbol("v"), y.u: 0}
>>> floor = onto(scene.constraints[0], "floor", coords, bottom)
>>> floor.surface, gap(floor, coords, bottom)
('floor', 0)
"""
from __future__ import annotations

import dataclasses

import sympy as sp

from derive.core.tidying import tidy
from derive.parts.contact import Contact
from derive.text.prose import Sentence


def onto(contact: Contact, surface: str, coords, values: dict) -> Contact:
    """The contact on `surface` as the bodies are in the state `values`: the same part, carried by
    that surface's carrier; rolling, its distance along the surface plus R theta counted from there."""
    moved = dataclasses.replace(contact, surface=surface, carrier=coords.scene.surfaces[surface].carrier,
                                slipped=sp.Integer(0))
    if not moved.rolling:
        return moved
    rolled = moved.rolled(coords)
    at = {c.q: values[c.q] for c in coords.all}
    return dataclasses.replace(moved, slipped=tidy(rolled.xreplace(at) - rolled.xreplace(coords.at_rest_in_reference())))


def gap(contact: Contact, coords, values: dict) -> sp.Expr:
    """How far the body stands off the contact's surface in the state `values` (zero: it touches)."""
    return tidy(contact.gaps(coords)[0].xreplace({c.q: values[c.q] for c in coords.all}))


def needed(impulses: dict[sp.Symbol, sp.Expr], contact: Contact, size, name: str, start: str, old: str) -> str | None:
    """Why the transfer `name` cannot happen as derived, or None: `impulses` (the impact's, by the
    forces' symbols) are all zero. `size`: an impulse's value at the middle of the ranges (zero
    where it is proved zero)."""
    sizes = {f: size(v) for f, v in impulses.items()}
    if all(v == 0 for v in sizes.values()):
        return None
    forces = contact.unknowns()
    normal = sizes.get(forces["normal"], 0)
    worst = max(sizes, key=lambda f: abs(sizes[f]))
    amount = f"{worst} = {sizes[worst]:.4g} N s at the middle of the ranges"
    if normal != 0 or worst != forces.get("friction"):
        return (f"the {old} and the {contact.surface} meet at a kink where the {contact.body} is in the state {start}: "
                f"its velocity there does not run along the {contact.surface}, and turning it in an instant takes an "
                f"impulse ({amount}), whose size depends on how the {contact.body} strikes the {contact.surface}, not "
                f"modelled by a transfer: make the two paths meet tangentially (a curved ramp, a circle touching the "
                f"{contact.surface})")
    return (f"the {contact.body}'s point of contact would slip on the {contact.surface} in the transfer {name}: a grip "
            f"there takes a friction impulse ({amount}), not modelled by a transfer")


def said(contact: Contact, old: str) -> tuple[Sentence, ...]:
    """The transfer of `contact` (on its new surface) from the surface `old`, in words."""
    body, surface = contact.body, contact.surface
    counted = (f" It keeps rolling: the distance along the {surface} plus its radius times its turn counts from here."
               if contact.rolling else "")
    return (Sentence((f"The {body} passes from the {old} onto the {surface} where it touches both: from then on "
                      f"{contact.title} holds it, with the same forces.{counted}",)),
            Sentence((f"The two paths are tangent there, and the {body}'s point of contact is at rest on the {surface} "
                      f"as it was on the {old}: the joints' forces give no impulse in the instant (each is zero "
                      "below), so the velocities, the spin and the kinetic energy are what they were.",)))
