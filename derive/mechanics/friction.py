"""Which friction regime a contact is in, decided by the engine from mu_s and mu_k.

A contact whose file gives friction coefficients (`friction: {static: mu_s, kinetic: mu_k}`) is
first derived *stuck*: without slip at the point of contact (a round body rolls, a block stays
put on its surface). That gives the friction f the grip needs and the normal force N. The grip
holds where mu_s N >= |f| (with mu_k alone, mu_s is taken equal to mu_k, as texts that give one
coefficient do). Where it does not, the body slips, and kinetic friction mu_k N acts the way the
needed friction pointed: against the slip that would start. Each answer is then a Piecewise
over the parameters, regime by regime, and the regime's boundary is stated as the least mu_s
that keeps the grip. Without mu_k, slipping cannot be derived: the grip is a condition of the
problem (a variant that breaks it is redrawn, `derive solve` refuses it).

>>> import sympy as sp
>>> from derive.parts.contact import Contact
>>> mu = sp.Symbol("mu_s", positive=True)
>>> contact = Contact("ball_contact", "ball", "ramp", True, mu)
>>> stuck(contact).rolling, slipping(contact, -1).direction
(True, -1)
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import sympy as sp

from derive.core.tidying import tidy
from derive.parts.contact import Contact
from derive.model.scene import Scene


@dataclass(frozen=True)
class Regime:
    """One regime of the frictional contact: `name` (rolls, stays, slips), the scene in that
    regime, `direction` of kinetic friction along the surface's tangent (0 when stuck)."""

    name: str
    scene: Scene
    direction: int = 0


def frictional(scene: Scene) -> Contact | None:
    """The contact whose regime is to be decided: the one that gives friction coefficients.

    Raises ValueError (an engine limit) when two contacts give them."""
    found = [c for c in scene.constraints if isinstance(c, Contact) and c.has_friction]
    if len(found) > 1:
        raise ValueError(f"decide the friction regimes of two contacts at once ({found[0].name}, {found[1].name})")
    return found[0] if found else None


def stuck(contact: Contact) -> Contact:
    """The contact without slip: rolling for a round body, held in place for any other."""
    return dataclasses.replace(contact, rolling=True, direction=0)


def slipping(contact: Contact, direction: int) -> Contact:
    """The contact slipping, with kinetic friction mu_k N along `direction` times the tangent."""
    return dataclasses.replace(contact, rolling=False, direction=direction)


def with_contact(scene: Scene, contact: Contact) -> Scene:
    """The scene with the contact of that name replaced."""
    constraints = tuple(contact if c.name == contact.name else c for c in scene.constraints)
    return dataclasses.replace(scene, constraints=constraints)


def regimes(scene: Scene, contact: Contact) -> list[Regime]:
    """The regimes to derive: stuck, and, with mu_k, slipping either way."""
    held = "rolls" if contact.point is None and "radius" in scene.bodies[contact.body].sizes else "stays"
    result = [Regime(held, with_contact(scene, stuck(contact)))]
    if contact.kinetic is not None:
        result += [Regime("slips", with_contact(scene, slipping(contact, d)), d) for d in (1, -1)]
    return result


def where_each(contact: Contact, regimes: list[Regime], ratio: sp.Expr) -> tuple:
    """Where each of `regimes` holds, in their order (each where those before do not), from f/N,
    the friction the stuck contact needs over its normal force: stuck while mu_s >= |f/N|, then
    slipping the way f points."""
    return (sp.Ge(static_coefficient(contact), sp.Abs(ratio)),
            *(ratio > 0 if regime.direction > 0 else sp.true for regime in regimes[1:]))


def static_coefficient(contact: Contact) -> sp.Expr:
    """mu_s, or mu_k where the file gives only that."""
    return contact.static if contact.static is not None else contact.kinetic


def grip_margin(contact: Contact, normal: sp.Expr, friction: sp.Expr) -> sp.Expr:
    """mu_s - |f/N|: the grip holds where it is not negative (N > 0 is a condition of its own;
    the ratio cancels what scales both, such as the mass, so fewer parameters decide it)."""
    return static_coefficient(contact) - least_coefficient(normal, friction)


def least_coefficient(normal: sp.Expr, friction: sp.Expr) -> sp.Expr:
    """|f| / N: the least mu_s that keeps the grip (the regimes' boundary)."""
    return tidy(sp.Abs(friction / normal))
