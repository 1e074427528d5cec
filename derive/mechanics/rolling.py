"""A round body rolling without slipping at a given speed (lecture notes §2, §2.1): its rotation
rate, the distance it covers per turn, and its kinetic energy split between translation and
rotation, each by two routes that share only the scene:

- "center of mass": the material point touching the surface is at rest, v_cm + omega x r = 0
  (rigid-body kinematics); K = M v^2 / 2 + I_cm omega^2 / 2 (the notes' eq. 11);
- "contact point": the rolling constraint's gap (distance rolled + R theta) has zero rate;
  K = I_P omega^2 / 2, the body turning about the contact point with I_P = I_cm + M R^2.

>>> import sympy as sp
>>> from derive.language.problem import load
>>> problem = load("rolling_kinetic_energy")
>>> rolling(problem.scene, "wheel", "center of mass")[0]["rotational_fraction"]
1/3
"""
from __future__ import annotations

import sympy as sp

from derive.mechanics.derivation import KINETIC
from derive.text.steps import Step
from derive.core.tidying import tidy
from derive.model.kinematics import Coordinates
from derive.model.scene import Scene

ROUTES = ("center of mass", "contact point")
QUANTITIES = ("angular_velocity", "distance_per_turn", "kinetic_energy", "translational_energy",
              "rotational_energy", "rotational_fraction")


def rolling(scene: Scene, body: str, route: str) -> tuple[dict[str, sp.Expr], tuple[Step, ...]]:
    """Every rolling quantity of `body` (moving at its given velocity) by one route, with the steps."""
    coords = Coordinates(scene)
    contact = scene.contact_of(body)
    rigid = scene.bodies[body]
    radius = rigid.sizes["radius"]
    velocity = scene.motions[body].velocity
    # In the reference configuration, moving at the given velocity (the unknown: the spin rate).
    state = {c.q: 0 for c in coords.all}
    state.update({coords.of(body, "x").u: velocity[0], coords.of(body, "y").u: velocity[1]})
    spin = coords.of(body, "theta").u
    if route == "center of mass":
        condition = contact.conditions(coords)[-1]
        reason = ("The point touching the surface is at rest: the center's velocity plus the turn's velocity "
                  "there adds to nothing along the surface")
    else:
        condition = coords.ddt(contact.gaps(coords)[-1])
        reason = "The rolling constraint's rate vanishes: the distance rolled plus the radius times the turn stays fixed"
    (omega,) = sp.solve(condition.xreplace(state), spin)
    omega = tidy(omega)
    speed = tidy(sp.sqrt(velocity[0] ** 2 + velocity[1] ** 2))
    w = sp.Symbol("omega")
    rotational = tidy(rigid.inertia * omega**2 / 2)
    if route == "center of mass":
        translational = tidy(rigid.mass * speed**2 / 2)
        total = tidy(translational + rotational)
        energy = Step("Kinetic energy: translation of the center plus rotation about it",
                      (sp.Eq(KINETIC, sp.Symbol("M") * sp.Symbol("v") ** 2 / 2 + sp.Symbol("I_cm") * w**2 / 2),
                       sp.Eq(KINETIC, total)))
    else:
        about_contact = tidy(rigid.inertia + rigid.mass * radius**2)
        total = tidy(about_contact * omega**2 / 2)
        translational = tidy(total - rotational)
        energy = Step("Kinetic energy as a rotation about the contact point, its moment of inertia by the "
                      "parallel-axis theorem",
                      (sp.Eq(sp.Symbol("I_P"), about_contact), sp.Eq(KINETIC, total)))
    values = {
        "angular_velocity": omega,
        "distance_per_turn": tidy(2 * sp.pi * speed / sp.Abs(omega)),
        "kinetic_energy": total,
        "translational_energy": translational,
        "rotational_energy": rotational,
        "rotational_fraction": tidy(rotational / total),
    }
    steps = (
        Step(reason, (sp.Eq(condition.xreplace(state), 0), sp.Eq(w, omega))),
        Step("In one turn the center covers", (
            sp.Eq(sp.Symbol("d"), values["distance_per_turn"]),)),
        energy,
        Step("The share of the kinetic energy in rotation", (
            sp.Eq(sp.Symbol("K_rot") / KINETIC, values["rotational_fraction"]),)),
    )
    return values, steps
