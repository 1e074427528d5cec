"""The impulses of an impact (derive.mechanics.impacts), as asked: the impulse a body takes
(`BODY.impulse.x|y`) and the impulse a joint gives the body it holds (`JOINT.impulse.x|y`: a
hinge's impulsive reaction), each by two routes:

- momentum: a body's impulse is its change of linear momentum, m (v+ - v-); a joint's is the
  change of linear momentum of the bodies on its side (all of them for a joint to the ground,
  else its own body) less the impulses of the other joints across that side's boundary;
- impulses: the impact's impulse equations solved for the joints' impulses, each joint's
  forces on the body with those values (Newton–Euler's `impacts.impact`).

A rod struck by a ball while it hangs on a pin takes the pin's impulse J (3 d/(2 L) - 1) for a
blow J at d below the pin: none at the center of percussion, d = 2 L/3.

>>> import sympy as sp
>>> from derive.model.kinematics import Coordinates
>>> from derive.model.scene import Body, Scene
>>> m, v, e = sp.symbols("m v e", positive=True)
>>> scene = Scene({"ball": Body("ball", "point", m, {})})
>>> coords = Coordinates(scene)
>>> before = {**{s: 0 for s in coords.state}, coords.of("ball", "y").u: -v}
>>> after = {**before, coords.of("ball", "y").u: e * v}
>>> by_momentum(scene, coords, before, after, "ball")[1]
m*v*(e + 1)
"""
from __future__ import annotations

import sympy as sp

from derive.core.tidying import tidy
from derive.model.kinematics import Coordinates
from derive.parts import AppliedForce, Part
from derive.model.scene import Scene


def by_momentum(scene: Scene, coords: Coordinates, before: dict, after: dict, body: str) -> sp.Matrix:
    """The impulse `body` takes: m (v+ - v-) of its center of mass."""
    mass = scene.bodies[body].mass
    return sp.Matrix([tidy(mass * (after[coords.of(body, k).u] - before[coords.of(body, k).u])) for k in ("x", "y")])


def on_body(parts, coords: Coordinates, at: dict, impulses: dict, body: str) -> sp.Matrix:
    """The impulse `parts` give `body`: their forces on it, each force's symbol its impulse in the
    impact (`impulses`), where the bodies are (`at`)."""
    total = sp.zeros(2, 1)
    for part in parts:
        for load in part.loads(coords):
            if isinstance(load, AppliedForce) and load.body == body:
                total += load.force
    return total.xreplace(at).xreplace(impulses).applyfunc(tidy)


def joint_by_momentum(scene: Scene, coords: Coordinates, before: dict, after: dict, impulses: dict,
                      joint: Part) -> sp.Matrix:
    """The impulse `joint` gives its body, from the change of linear momentum of the bodies on its
    side (every body for a joint to the ground, else its body alone) less the impulses of the other
    joints across that side's boundary (`impulses`: their values; none where the joint is alone)."""
    side = set(scene.bodies) if len(joint.bodies()) == 1 else {joint.body}
    across = [p for p in scene.constraints if p is not joint and set(p.bodies()) & side
              and not (len(p.bodies()) > 1 and set(p.bodies()) <= side)]
    at = {c.q: before[c.q] for c in coords.all}
    change = sum((by_momentum(scene, coords, before, after, b) for b in sorted(side)), sp.zeros(2, 1))
    others = sum((on_body(across, coords, at, impulses, b) for b in sorted(side)), sp.zeros(2, 1))
    return (change - others).applyfunc(tidy)
