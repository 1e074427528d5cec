"""The torque on a point mass on a prescribed path, about a fixed point, as a vector in space:
`BODY.torque.x|y|z|magnitude` (the net force's), `BODY.weight.torque.x|...` (its weight's, with
`- gravity: g` along -y) and `BODY.FORCE.torque.x|...` (a given `force:` named FORCE acting on it),
with `about: [x, y, z]` (or `[x, y]`, z = 0), for a body with `path:` (in space with `z`, or in the
plane). A component is along the axis it names; the magnitude is positive.

    tau = (r - r_P) x F                 the net force's: F = m a = m r'',  so  tau = dL/dt

The net force is what the prescribed path needs, m a, whichever forces give it: the forces the file
names need not be all of them (a particle held at rest bears no net torque, whatever a given force's).
Route 0 (the key's): the cross product by components. Route 1, its check: for the net torque, the
time derivative of the angular momentum about the point, by sympy.physics.mechanics
(particle_angular_momentum.by_mechanics: tau = dL/dt about a fixed point); for one force, the work it
does in a small turn of its point about each axis through P, tau . n = d/de [F . R_n(e) (r - r_P)] at 0.
A spring, cord or other part acting on a body on a path is not modelled there, and is refused.

>>> from derive.language.problem import load
>>> scene = load("circular_motion_L").scene
>>> PARTICLE_TORQUE.claims(scene, "particle", "torque.z")
Quantity(kind='particle_torque', target='particle', detail='torque.z')
>>> _split("weight.torque.magnitude")
('weight', 'magnitude')
"""
from __future__ import annotations

import sympy as sp

from derive.core.expr import TIME
from derive.core.spelling import did_you_mean
from derive.model.scene import Quantity
from derive.parts.force import Force
from derive.parts.gravity import Gravity
from derive.quantities.base import QuantityKind, named
from derive.quantities.particle_angular_momentum import COMPONENTS, by_mechanics
from derive.text.prose import Sentence
from derive.text.steps import Step

#: A component of (r - r_P) x F, from the arm's and the force's: the book's y F_z - z F_y, ...
_COMPONENT = {"x": (1, 2), "y": (2, 0), "z": (0, 1)}


def _split(detail: str) -> tuple[str | None, str]:
    """(the load, None for the net force; the component) of an ask's `LOAD.torque.COMPONENT`."""
    load, _, component = detail.rpartition(".")
    return (load[: -len(".torque")] if load != "torque" else None), component


class ParticleTorque(QuantityKind):
    """The torque on a point mass on a path, about a fixed point, in space (see the module)."""

    kind = "particle_torque"
    symbol = "tau"
    unit = "N*m"
    routes = ("the cross product (r - r_P) x F by components (the net force m a)",
              "dL/dt of sympy.physics.mechanics' angular momentum about the point for the net torque, and for a "
              "force the work it does in a small turn about each axis")
    options = ("about",)
    about_in_space = True

    def claims(self, scene, head: str, rest: str) -> Quantity | None:
        body = scene.bodies.get(head)
        words = rest.split(".")
        if body is None or body.path is None or "torque" not in words:
            return None
        at = words.index("torque")
        load, component = ".".join(words[:at]) or None, ".".join(words[at + 1:])
        asked = f"{head}.{load + '.' if load else ''}torque"
        if component not in COMPONENTS:
            raise ValueError(f"the torque on a body on a path is a vector: ask {asked}.{'|'.join(COMPONENTS)}"
                             + (did_you_mean(component, COMPONENTS) if component else ""))
        if load is not None:
            forces = [p.name for p in scene.parts if isinstance(p, Force) and p.body == head]
            has_weight = any(isinstance(p, Gravity) for p in scene.parts)
            known = [*(["weight"] if has_weight else []), *forces]
            if load not in known:
                acting = [p.name for p in scene.parts if head in p.bodies() and p.name not in forces]
                raise ValueError(
                    (f"the torque of the {load} on a body on a path is not modelled; " if load in acting else
                     f"the {head} bears no force {load!r}{'' if has_weight or load != 'weight' else ' (no gravity)'}; ")
                    + f"ask {head}.torque.{component} (the net force's, m r x a)"
                    + "".join(f" or {head}.{n}.torque.{component}" for n in known) + did_you_mean(load, known))
        return Quantity(self.kind, head, ".".join(words))

    def _force(self, solution, ask) -> sp.Matrix:
        """The force the ask names, in space: the net force m r'' (None), the weight or a given force."""
        body = solution.scene.bodies[ask.quantity.target]
        load, _ = _split(ask.quantity.detail)
        if load is None:
            return body.mass * body.path.position3.diff(TIME, 2)
        if load == "weight":
            gravity = next(p for p in solution.scene.parts if isinstance(p, Gravity))
            return sp.Matrix([0, -body.mass * gravity.g, 0])
        force = next(p for p in solution.scene.parts if isinstance(p, Force) and p.name == load and p.body == body.name)
        return sp.Matrix([*force.vector, 0])

    def _arm(self, solution, ask) -> sp.Matrix:
        """The body's position from the point the torque is taken about."""
        return solution.scene.bodies[ask.quantity.target].path.position3 - sp.Matrix(ask.about.offset)

    def value(self, solution, ask, route: int) -> sp.Expr:
        load, component = _split(ask.quantity.detail)
        arm, force = self._arm(solution, ask), self._force(solution, ask)
        if route == 0:
            vector = arm.cross(force)
        elif load is None:  # tau = dL/dt about the fixed point
            vector = by_mechanics(solution.scene.bodies[ask.quantity.target], ask.about.offset).diff(TIME)
        else:  # the work of the force in a small turn e of its point about each axis through the point
            e = sp.Dummy("e")
            turns = (sp.rot_ccw_axis1(e), sp.rot_ccw_axis2(e), sp.rot_ccw_axis3(e))
            vector = sp.Matrix([sp.diff(force.dot(turn * arm), e).subs(e, 0) for turn in turns])
        vector = vector.applyfunc(sp.simplify)
        if component == "magnitude":
            return sp.simplify(sp.sqrt(sum((c**2 for c in vector), sp.Integer(0))))
        return vector["xyz".index(component)]

    def axis_of(self, quantity: Quantity) -> str | None:
        component = _split(quantity.detail)[1]
        return None if component == "magnitude" else component

    def symbol_for(self, ask) -> str:
        component = _split(ask.quantity.detail)[1]
        return "tau" if component == "magnitude" else f"tau_{component}"

    def steps(self, solution, ask) -> list[Step]:
        """The position from the point and the force, in components, and their cross product."""
        load, component = _split(ask.quantity.detail)
        body = ask.quantity.target
        arm = self._arm(solution, ask).applyfunc(sp.simplify)
        force = self._force(solution, ask).applyfunc(sp.simplify)
        x, y, z, fx, fy, fz = sp.symbols("x y z F_x F_y F_z")
        what = "net force, its mass times its acceleration," if load is None else \
            "weight" if load == "weight" else f"force {load}"
        said = Sentence((f"The {body} is at ", sp.Eq(x, arm[0]), ", ", sp.Eq(y, arm[1]), ", ", sp.Eq(z, arm[2]),
                         f" from {ask.about.words}; the {what} on it is ", sp.Eq(fx, force[0]), ", ", sp.Eq(fy, force[1]),
                         ", ", sp.Eq(fz, force[2]), "."))
        name = named(self, ask)
        if component == "magnitude":
            return [Step("The torque is the cross product of the position and the force; its size is the square root "
                         "of the sum of its components' squares", (sp.Eq(name, self.value(solution, ask, 0)),),
                         sentences=(said,))]
        i, j = _COMPONENT[component]
        (a, b), (fa, fb) = ((x, y, z)[i], (x, y, z)[j]), ((fx, fy, fz)[i], (fx, fy, fz)[j])
        return [Step(f"The torque's {component} component is that of the cross product of the position and the force",
                     (sp.Eq(name, a * fb - b * fa, evaluate=False), sp.Eq(name, self.value(solution, ask, 0))),
                     sentences=(said,))]

    def describe(self, ask) -> str:
        load, component = _split(ask.quantity.detail)
        body = ask.quantity.target
        part = "the size" if component == "magnitude" else f"the {component} component"
        what = f"the net torque on the {body}" if load is None else \
            f"the torque of the {body}'s weight" if load == "weight" else f"the torque of the force {load} on the {body}"
        return f"{part} of {what} about {ask.about.words}"


PARTICLE_TORQUE = ParticleTorque()
