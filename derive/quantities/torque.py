"""The torque of loads on a body about a point: of one load, or of every load (the net torque).

Asked as `BODY.torque` (every load on the body), `BODY.weight.torque`, `BODY.friction.torque` and
`BODY.normal_force.torque` (of its contact with a surface), or `BODY.PART.torque` (what a joint,
cord, force, spring, damper or couple named PART exerts on the body), with `about: POINT`: a
joint's name (the point it holds), `BODY` (its center of mass), `BODY.POINT`, `{BODY: [x, y]}`
or `[x, y]` (a fixed point); at the placement at rest, or `in: STATE`. Counter-clockwise positive,
the component along the normal to the page:

            F
            ^            tau = (r_A - r_P) x F      (counter-clockwise positive)
            |
    P o-----+ A          a force up at A, to the right of P: counter-clockwise

Route 0 (the key's), Newton–Euler: the sum of (r_A - r_P) x F over the loads, with the
constraint forces of the Newton–Euler solve. Route 1, its check: the net torque by Euler's law,
I_cm alpha + (r_cm - r_P) x M a_cm, from Lagrange's accelerations; one load's by the work it does
in a small turn of its point about P, F . d(R(e)(r_A - r_P))/de at e = 0, with the forces of
Lagrange's multipliers.

>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> problem = load("rod_endpoint")
>>> scene = problem.scene
>>> TORQUE.claims(scene, "rod", "weight.torque")
Quantity(kind='torque', target='rod', detail='weight')
"""
from __future__ import annotations

from collections import Counter

import sympy as sp

from derive.core.spelling import did_you_mean
from derive.core.tidying import tidy
from derive.text.steps import Step
from derive.model.scene import Quantity
from derive.parts import AppliedForce, AppliedTorque
from derive.quantities.base import QuantityKind, named
from derive.text.prose import Sentence

#: The subscripts of a load's torque in the worked solution, by its label.
_SHORT = {"weight": "W", "normal force": "N", "static friction": "f", "kinetic friction": "f", "tension": "T",
          "reaction": "R"}
#: Loads named by what they are rather than by a part's name.
NAMED = {"weight": ("weight",), "friction": ("static friction", "kinetic friction"), "normal_force": ("normal force",)}


def _symbols(loads) -> list[sp.Symbol]:
    """Each load's torque as the worked solution names it: by what the load is (tau_W, tau_N, tau_f;
    a cord's tension tau_T, a joint's reaction tau_R, a given force tau_F), never by a part's key in
    the file; loads of one kind numbered in order (the two sides of a pulley's cord: tau_1, tau_2).

    >>> from collections import namedtuple
    >>> Load = namedtuple("Load", "label")
    >>> _symbols([Load("tension of rope"), Load("tension of rope"), Load("weight")])
    [tau_1, tau_2, tau_W]
    """
    kinds = [_SHORT.get(load.label) or _SHORT.get(load.label.partition(" of ")[0], "F") for load in loads]
    counts, seen, result = Counter(kinds), Counter(), []
    alone = sum(1 for n in counts.values() if n > 1) == 1  # one kind repeats: its loads numbered, 1, 2, ...
    for kind in kinds:
        seen[kind] += 1
        result.append(sp.Symbol(f"tau_{kind if counts[kind] == 1 else seen[kind] if alone else f'{kind}{seen[kind]}'}"))
    return result


def _cross(arm: sp.Matrix, force: sp.Matrix) -> sp.Expr:
    return arm[0] * force[1] - arm[1] * force[0]


class Torque(QuantityKind):
    """A torque about a point (see the module)."""

    kind = "torque"
    symbol = "tau"
    unit = "N*m"
    state = "optional"
    sense = ("counter-clockwise", "clockwise")
    routes = ("r x F of each load, with the Newton–Euler forces",
              "Euler's law (I alpha + r x M a) or the load's work in a small turn, by Lagrange")
    options = ("about",)

    def claims(self, scene, head: str, rest: str) -> Quantity | None:
        if not (rest == "torque" or rest.endswith(".torque")) or head not in scene.bodies:
            return None
        load = rest[: -len(".torque")] if rest != "torque" else None
        if load is None:
            return Quantity(self.kind, head, None)
        names = [*NAMED, *(p.name for p in scene.parts if head in p.bodies())]
        if load not in names:
            raise ValueError(f"the {head} bears no load {load!r}: ask {head}.torque (every load), or one of "
                             + ", ".join(f"{head}.{n}.torque" for n in names) + did_you_mean(load, names))
        return Quantity(self.kind, head, load)

    def reads_motion(self, ask) -> bool:
        return True  # the forces of the derivation, a friction's regime among them

    def _loads(self, solution, ask) -> list[AppliedForce | AppliedTorque]:
        body, wanted = ask.quantity.target, ask.quantity.detail
        scene = solution.scene_in(ask.state) if ask.state else solution.dynamics_scene
        coords = solution.coordinates
        result = []
        for part in scene.parts:
            for load in part.loads(coords):
                if load.body != body:
                    continue
                if wanted is None or wanted == part.name or load.label in NAMED.get(wanted, ()):
                    result.append(load)
        if not result:
            raise solution.problem.error(f"ask.{ask.name}.of", f"no {wanted} acts on the {body}")
        return result

    def _where(self, solution, ask) -> dict:
        """The coordinates and velocities where the torque is read: the state's, or the placement at rest."""
        if ask.state:
            return solution.states[ask.state].values
        return solution.coordinates.at_rest_in_reference()

    def _point(self, solution, ask) -> sp.Matrix:
        return solution.coordinates.position(ask.about.body, ask.about.offset)

    def _moments(self, solution, ask) -> list[tuple]:
        """Each load's (load, position from the point, force, torque), read where the ask is, with the forces
        of the Newton–Euler solve (a couple: no position or force): route 0 and its steps."""
        coords, where, point = solution.coordinates, self._where(solution, ask), self._point(solution, ask)
        solved = solution.in_state("newton_euler", ask.state)
        known = {u: solved[u] for u in self.unknowns(solution, ask)}
        result = []
        for load in self._loads(solution, ask):
            if isinstance(load, AppliedTorque):
                result.append((load, None, None, tidy(load.torque.xreplace(known).xreplace(where))))
                continue
            arm = (coords.position(load.body) + load.offset - point).xreplace(where).applyfunc(tidy)
            force = load.force.xreplace(known).xreplace(where).applyfunc(tidy)
            result.append((load, arm, force, tidy(_cross(arm, force))))
        return result

    def value(self, solution, ask, route: int) -> sp.Expr:
        if route == 0:
            return tidy(sum((torque for *_, torque in self._moments(solution, ask)), sp.Integer(0)))
        coords = solution.coordinates
        where = self._where(solution, ask)
        point = self._point(solution, ask)
        solved = solution.in_state("lagrange", ask.state)
        known = {u: solved[u] for u in self.unknowns(solution, ask) | self._accelerations(solution, ask)}
        if ask.quantity.detail is None:  # Euler's law for the body: I alpha + (r_cm - r_P) x M a_cm
            body = solution.scene.bodies[ask.quantity.target]
            name = body.name
            spin = body.inertia * coords.of(name, "theta").a if body.rotates else sp.Integer(0)
            acceleration = sp.Matrix([coords.of(name, "x").a, coords.of(name, "y").a])
            total = spin + _cross(coords.position(name) - point, body.mass * acceleration)
        else:  # the work of each load in a small turn e of its point about P
            e = sp.Dummy("e")
            turn = sp.Matrix([[sp.cos(e), -sp.sin(e)], [sp.sin(e), sp.cos(e)]])
            total = sum((load.torque if isinstance(load, AppliedTorque) else
                         sp.diff(load.force.dot(turn * (coords.position(load.body) + load.offset - point)), e).subs(e, 0)
                         for load in self._loads(solution, ask)), sp.Integer(0))
        return tidy(total.xreplace(known).xreplace(where))

    def _accelerations(self, solution, ask) -> set[sp.Symbol]:
        if ask.quantity.detail is not None:
            return set()
        body = solution.scene.bodies[ask.quantity.target]
        coords = solution.coordinates
        return {coords.of(body.name, k).a for k in (("x", "y", "theta") if body.rotates else ("x", "y"))}

    def unknowns(self, solution, ask) -> set[sp.Symbol]:
        """The constraint forces among the loads (a weight or a given force needs none)."""
        found = set()
        for load in self._loads(solution, ask):
            parts = (load.force, load.offset) if isinstance(load, AppliedForce) else (load.torque,)
            found |= {s for p in parts for s in sp.sympify(p).free_symbols}  # safe: the engine's own expressions
        return found & set(solution.derivations["newton_euler"].unknowns)

    def steps(self, solution, ask) -> list[Step]:
        """Each load's torque, r x F with its point's position r from the point the torque is taken
        about (the forces as the Newton–Euler solve above finds them), and their sum."""
        about, result = ask.about.words, []
        moments = self._moments(solution, ask)
        for (load, arm, force, torque), name in zip(moments, _symbols([load for load, *_ in moments])):
            if arm is None:
                result.append(Step(f"The {load.label} is a couple: its torque is the same about every point", (
                    sp.Eq(name, torque),)))
                continue
            x, y, fx, fy = sp.symbols("x y F_x F_y")
            said = Sentence((f"The {load.label or 'pull of the cord'} on the {load.body} acts at ",
                             sp.Eq(x, arm[0]), ", ", sp.Eq(y, arm[1]), f" from {about}, with ", sp.Eq(fx, force[0]),
                             ", ", sp.Eq(fy, force[1]), "."))
            result.append(Step("The torque about that point, counter-clockwise positive, is the cross product of "
                               "the position and the force",
                               (sp.Eq(name, x * fy - y * fx, evaluate=False), sp.Eq(name, torque)), sentences=(said,)))
        if len(moments) > 1:
            result.append(Step(f"The net torque about {about} is their sum, counter-clockwise positive",
                               (sp.Eq(named(self, ask), self.value(solution, ask, 0)),)))
        return result

    def describe(self, ask) -> str:
        body, load = ask.quantity.target, ask.quantity.detail
        about = ask.about.words
        if load is None:
            return f"the net torque on the {body} about {about}"
        what = {"weight": f"the {body}'s weight", "friction": f"the friction on the {body}",
                "normal_force": f"the normal force on the {body}"}.get(load, f"the {load} on the {body}")
        return f"the torque of {what} about {about}"


TORQUE = Torque()
