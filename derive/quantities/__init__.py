"""The quantities a problem asks of its scene, one module each (the protocol: `QuantityKind`).

A quantity says, through `QuantityKind`, everything the rest of derive needs of it:
- the ask paths it answers (`claims`), whether it is read in a state (`state`), the ask keys it
  takes besides the common ones (`options`);
- its dimension (`unit`, SI) and, if it points one way or the other, the words for its two
  signs (`sense`);
- its value by two independent routes (`value`, with `routes` naming them): the first gives
  the key, the second checks it (derive.solution.crosschecks compares them at points of the
  ranges, symbolically where that is cheap);
- the sentence that states it to a student (`describe`).

The quantities of the equations of motion (an acceleration, a force, a state's rates, an equilibrium,
an oscillation: `by_routes.ByRoutes`) read their values from the whole derivation's solve, through
the Solution; derive.model.scene parses their paths.

The answer layer (derive.solution.answers) and the checks ask this protocol for the values; they
never branch on the kind to find one. Adding a quantity is one module here and one line in `KINDS` (docs/design.md, "Adding a
quantity", walks through `turns`).

>>> from derive.language.problem import load
>>> scene = load("rod_endpoint").scene
>>> parse(scene, "rod.weight.torque")
Quantity(kind='torque', target='rod', detail='weight')
>>> KINDS["torque"].unit, KINDS["turns"].unit
('N*m', 'rev')
"""
from __future__ import annotations

from derive.model.directions import Sense
from derive.model.scene import Quantity
from derive.quantities import (acceleration, angular_impulse, bearings, center_of_mass, conical, contact, distance,
                               equilibrium, force, free_rotation, impulse, internal_forces, mass, moment_of_inertia, orbit,
                               oscillation, particle_angular_momentum, particle_torque, path, pivot_point, position_cm,
                               rates, rolling, rolls_on_edge, small_oscillation, standing_wave, system, torque, turns)
from derive.quantities.base import QuantityKind, StateChange, describe_capitalized

__all__ = ["KINDS", "QuantityKind", "StateChange", "describe_capitalized", "directional", "parse", "sense"]


#: Every quantity of this package, by kind, in the order they claim an ask's path (`parse`: a particle's torque
#: before a body's) and add their steps to a route's section of the worked solution (`QuantityKind.route_steps`).
KINDS: dict[str, QuantityKind] = {k.kind: k for k in (particle_torque.PARTICLE_TORQUE, torque.TORQUE, turns.TURNS,
                                                      distance.DISTANCE, center_of_mass.CENTER_OF_MASS,
                                                      position_cm.POSITION_CM, conical.CONICAL,
                                                      particle_angular_momentum.ANGULAR_MOMENTUM,
                                                      standing_wave.STANDING_WAVE, internal_forces.INTERNAL_FORCES,
                                                      bearings.BEARINGS, angular_impulse.ANGULAR_IMPULSE,
                                                      pivot_point.PIVOT_POINT, rolls_on_edge.ROLLS_ON_EDGE,
                                                      free_rotation.FREE_ROTATION,
                                                      system.SYSTEM, mass.MASS, orbit.ORBIT, path.PATH,
                                                      moment_of_inertia.MOMENT_OF_INERTIA, rolling.ROLLING,
                                                      acceleration.ACCELERATION, acceleration.ANGULAR_ACCELERATION,
                                                      force.FORCE, contact.CONTACT, *rates.RATES, impulse.IMPULSE,
                                                      small_oscillation.SMALL_OSCILLATION, equilibrium.EQUILIBRIUM,
                                                      oscillation.OSCILLATION)}


def sense(scene, quantity: Quantity, coords, sample) -> Sense | None:
    """The words for the two ways an asked quantity can point (`QuantityKind.sense_in`)."""
    return KINDS[quantity.kind].sense_in(scene, quantity, coords, sample)


def directional(quantity: Quantity) -> bool:
    """Whether the quantity points one way or the other, whatever the scene (`QuantityKind.directional`)."""
    return KINDS[quantity.kind].directional(quantity)


def parse(scene, path: str) -> Quantity | None:
    """The quantity a path names, if one of this package's kinds claims it (ValueError where the
    path is one of theirs but names nothing in the scene)."""
    head, _, rest = path.partition(".")
    for kind in KINDS.values():
        quantity = kind.claims(scene, head, rest)
        if quantity is not None:
            return quantity
    return None
