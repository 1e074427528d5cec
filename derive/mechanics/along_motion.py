"""Newton's second law along the motion and torques about the center of mass or a fixed pivot: the
route a solution manual takes for a scene of one degree of freedom released from rest.

For a sphere rolling down a slope a textbook writes three equations: M a = M g sin(theta) - f along
the slope, f R = (2/5) M R^2 alpha about the center, and a = R alpha; the Newton–Euler route writes
seven, in x and y components (derive.mechanics.newton_euler). This route writes the same balances,
each projected on the direction its body's center moves in (found from the constraints: the one
free direction of the coordinates at the placement), the torques about the center of mass, or about
a pin fixed to the ground, whose reaction then has no moment; and one relation per other body
between its acceleration and the first one's (the cord does not stretch, the ball does not slip).
The motion's sense is the one the scene takes from rest (at the middle of the parameter ranges), so
its accelerations come out positive; each constraint force points the way it acts there, so that
its symbol is a magnitude (friction up the slope, not a negative friction down it). A force the
equations along the motion leave open (a normal force) is found from the balance across it.

The route is a third one: what it gives for the accelerations and forces must be what the other
two give (derive.solution.textbook checks it).

>>> import sympy as sp
>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> solution = Solution(load("rolling_incline"))
>>> route = along_motion(solution.dynamics_scene, solution.coordinates, solution.derivations["newton_euler"],
...                      solution._sample)
>>> [str(e) for step in route.steps for e in step.equations][:3]
['Eq(M*a, M*g*sin(theta) - f^ball)', 'Eq(2*M*R**2*alpha/5, R*f^ball)', 'Eq(a, R*alpha)']
"""
from __future__ import annotations

from collections.abc import Callable
import dataclasses
from dataclasses import dataclass

import sympy as sp

from derive.core.tidying import leading_plus, tidy
from derive.mechanics.derivation import Derivation, Indeterminate, solve_linear
from derive.text.steps import Step
from derive.mechanics.newton_euler import all_forces
from derive.mechanics.oscillation import free_directions
from derive.model.directions import TURNS, along
from derive.model.kinematics import Coordinates
from derive.model.scene import Scene
from derive.parts import AppliedForce, AppliedTorque
from derive.parts.contact import Contact
from derive.parts.cord import Cord
from derive.parts.pin import Pin


class NotAlongALine(ValueError):
    """The scene is not one a solution manual solves along its motion (more than one degree of
    freedom, nothing moves, or the balances along the motion do not determine what is asked)."""


@dataclass(frozen=True)
class AlongMotion:
    """The route's steps, the values it gives the engine's unknowns (the coordinates'
    accelerations and the constraint forces, in the reference configuration at rest), and those of
    its own symbols (a, alpha, a_block: each body's acceleration along its motion, in its sense)."""

    steps: tuple[Step, ...]
    values: dict[sp.Symbol, sp.Expr]
    own: dict[sp.Symbol, sp.Expr]
    names: dict[tuple[str, str], sp.Symbol]  # (body, "a" or "alpha"): its symbol
    acting: dict[sp.Symbol, int]  # each constraint force's sense: -1 where it acts against its axis
    rates: dict = dataclasses.field(default_factory=dict)  # each coordinate's acceleration per the leading one


@dataclass(frozen=True)
class _Moving:
    """How one body moves along the scene's one free direction: its center along `heading` (a unit
    vector, None where the center stays) at `speed` times the rate along the motion; it turns at
    `turn` times that rate, in the sense `sense` (+1 counter-clockwise), the words `turning`."""

    name: str
    heading: sp.Matrix | None
    speed: sp.Expr
    turn: sp.Expr
    sense: int


def along_motion(scene: Scene, coords: Coordinates, newton: Derivation, sample: Callable[[sp.Expr], float],
                 needed: set[sp.Symbol] = frozenset()) -> AlongMotion:
    """The route along the motion of a scene of one degree of freedom at rest at its placement;
    `newton` (the Newton–Euler derivation) decides which way it starts (at the middle of the ranges:
    `sample`) and which way each constraint force acts; `needed`: the constraint forces asked."""
    rest = coords.at_rest_in_reference()
    reference = newton.at(rest)
    index = {c: i for i, c in enumerate(coords.all)}
    # From rest every coordinate starts along the accelerations: the line the motion starts on
    accelerations = [reference[c.a] for c in coords.all]
    first = next((i for i, a in enumerate(accelerations) if a != 0 and sample(a) != 0), None)
    if first is None:
        raise NotAlongALine("the scene stays at rest")
    direction = sp.Matrix([tidy(a / accelerations[first]) for a in accelerations])
    free = free_directions(scene, coords)
    coefficients = {s for c in scene.constraints if isinstance(c, Contact) and c.regime == "kinetic"
                    for s in c.kinetic.free_symbols}
    if len(free) > 1 and any(x.free_symbols & coefficients for x in direction):
        raise NotAlongALine("how the motions compare depends on kinetic friction (a disk that slides as it turns)")
    if len(free) > 1 and _dynamic(direction, scene):
        raise NotAlongALine("how the bodies' motions compare depends on their masses, not only on the constraints")
    if len(free) == 1 and _sliding(scene):
        # the same line, from the constraints alone: the ratios of accelerations mu_k enters tidy no further
        direction = sp.Matrix([tidy(x / free[0][first]) for x in free[0]])
    if sample(accelerations[first]) < 0:
        direction = -direction
    moving = [_moving(body, coords, direction, index, sample) for body in scene.bodies.values()]
    leading = next((m for m in moving if m.heading is not None), None) or next(m for m in moving if m.turn != 0)
    # Measured along the leading body's motion: its acceleration (or angular acceleration) is the rate's
    direction = direction / (leading.speed if leading.heading is not None else definite(sp.Abs(leading.turn), sample))
    moving = [_moving(body, coords, direction, index, sample) for body in scene.bodies.values()]
    leading = next(m for m in moving if m.name == leading.name)
    # each force's sign from its value as solved (a ball decides it): tidying every force of a cord's tangent
    # geometry on a double wedge (an axle's force, 500 operations in two angles) took minutes, for a sign
    flipped = {u: -1 if sample(reference.raw[u]) < 0 else 1 for c in scene.constraints for u in c.unknowns().values()}
    loads = all_forces(scene, coords)
    names = _names(moving, leading, scene)
    base = names[leading.name, "a" if leading.heading is not None else "alpha"]
    equations, steps = [], []
    for m in moving:
        body = scene.bodies[m.name]
        pin = next((c for c in scene.constraints if isinstance(c, Pin) and c.body == m.name and c.to is None), None)
        on_body = [oriented(f, flipped, rest) for f in loads if f.body == m.name]
        balances = []
        if pin is not None and body.rotates:
            point = coords.rotated(m.name, pin.offset).xreplace(rest)
            inertia = tidy(body.inertia + body.mass * point.dot(point))
            balances.append(sp.Eq(inertia * names[m.name, "alpha"], tidy(m.sense * moment(on_body, point, sample))))
            about = f"the {m.name}'s axle" if point == sp.zeros(2, 1) else f"the {m.name}'s pivot"
            text = f"Torque about {about} (the force of the {pin.name} there has no moment about it), {_turning(m)}"
        else:
            if m.heading is not None:
                balances.append(sp.Eq(_product(body.mass, names[m.name, "a"]), component(on_body, m.heading, sample)))
            if body.rotates and m.turn != 0:
                balances.append(sp.Eq(body.inertia * names[m.name, "alpha"],
                                      tidy(m.sense * moment(on_body, sp.zeros(2, 1), sample))))
            words = [f"Newton's second law for the {m.name} along its motion, {_words(m.heading, sample)}"] \
                if m.heading is not None else []
            words += [f"the torque about its center, {_turning(m)}"] if len(balances) > len(words) else []
            text = ", and ".join(words)
        if balances:
            equations += balances
            steps.append(Step(_capital(text), tuple(balances), role="equations", body=m.name))
    relations = _relations(moving, names, base, sample)
    if relations:
        equations += relations
        steps.append(Step(_ties(scene), tuple(relations), role="equations"))
    symbols = list(dict.fromkeys(names.values()))
    wanted = set(needed) & set(flipped)
    # The balances across the motion, body by body as they are looked for: where the equations along
    # it close (a cord over a pulley), none is written (a double wedge's took a tenth of its derivation).
    extra = _Offered(_across(moving, scene, loads, flipped, rest, sample, names))
    while True:  # the balances across the motion, where the equations along it leave a force open
        forces = sorted({u for e in equations for u in e.free_symbols if u in flipped}, key=str)
        short, pending = len(symbols) + len(forces) - len(equations), wanted - set(forces)
        if short <= 0 and not pending:
            break
        step = extra.take(lambda x: _forces(x, flipped) & pending) or \
            extra.take(lambda x: _forces(x, flipped) <= set(forces) and len(x.equations) <= short)
        if step is None:
            raise NotAlongALine("the balances along and across the motion leave a force open")
        equations += step.equations
        steps.append(step)
    unknowns = symbols + forces
    try:
        solved = solve_linear(equations, unknowns, newton.placed)
    except (Indeterminate, ValueError) as error:
        raise NotAlongALine(str(error)) from None
    shown = [sp.Eq(base, leading_plus(solved[base]))] + [sp.Eq(u, leading_plus(solved[u])) for u in forces
                                                         if u in wanted or not wanted]
    steps.append(Step("Solving", tuple(shown), role="solve"))
    values = {c.a: tidy(direction[index[c]] * solved[base]) for c in coords.all}
    values.update({u: tidy(flipped[u] * solved[u]) for u in forces})
    return AlongMotion(tuple(steps), values, {u: solved[u] for u in symbols}, names, flipped,
                       {c.a: tidy(direction[index[c]]) for c in coords.all})


def _dynamic(direction: sp.Matrix, scene: Scene) -> bool:
    """Whether the start's direction depends on the bodies' masses or moments of inertia (two blocks
    on a movable wedge), so that the ratios of their accelerations are no constraint's to state."""
    sizes = {s for b in scene.bodies.values() for size in b.sizes.values() for s in getattr(size, 'free_symbols', ())}
    inertial = {s for b in scene.bodies.values() for e in (b.mass, b.inertia) if e is not None
                for s in e.free_symbols} - sizes
    return any(x.free_symbols & inertial for x in direction)


def _moving(body, coords: Coordinates, direction: sp.Matrix, index: dict, sample) -> _Moving:
    x, y = (direction[index[coords.of(body.name, k)]] for k in ("x", "y"))
    turn = direction[index[coords.of(body.name, "theta")]] if body.rotates else sp.Integer(0)
    speed = definite(tidy(sp.sqrt(tidy(sp.trigsimp(x**2 + y**2)))), sample)
    heading = None if speed == 0 else sp.Matrix([definite(tidy(x / speed), sample), definite(tidy(y / speed), sample)])
    return _Moving(body.name, heading, speed, turn, 1 if turn == 0 or sample(turn) > 0 else -1)


def definite(expr: sp.Expr, sample) -> sp.Expr:
    """`expr` with each |e| written e or -e by its sign at the middle of the ranges (a heading's
    |cos(theta)| on an incline): the route's results are checked against both routes'."""
    return tidy(expr.replace(lambda e: isinstance(e, sp.Abs), lambda e: e.args[0] if sample(e.args[0]) >= 0 else -e.args[0]))


def _names(moving: list[_Moving], leading: _Moving, scene: Scene) -> dict[tuple[str, str], sp.Symbol]:
    """The symbols of each body's acceleration along its motion and angular acceleration: a and
    alpha where one body has each (or all move alike), else numbered by the body (`Scene.numbers`)."""
    taken = {str(s) for b in scene.bodies.values() for s in b.mass.free_symbols}
    result = {}
    alike = [m for m in moving if m.heading is not None and tidy(m.speed / leading.speed) == 1] \
        if leading.heading is not None else []
    translating = [m for m in moving if m.heading is not None]
    turning = [m for m in moving if m.turn != 0 and scene.bodies[m.name].rotates]
    number = scene.numbers()  # a_1, never a_block: the body's key is the file's
    for m in translating:
        result[m.name, "a"] = sp.Symbol("a" if m in alike or len(translating) == 1 else f"a_{number[m.name]}", real=True)
    for m in turning:
        result[m.name, "alpha"] = sp.Symbol("alpha" if len(turning) == 1 else f"alpha_{number[m.name]}", real=True)
    if any(str(s) in taken for s in result.values()):
        raise NotAlongALine("a parameter is named as an acceleration")
    return result


def _relations(moving: list[_Moving], names: dict, base: sp.Symbol, sample) -> list[sp.Eq]:
    """Each other acceleration in terms of the leading one (`base`, the rate along the motion):
    a = R alpha for a ball that rolls, a_2 = a_1 / 2 for a pulley block."""
    result = []
    for m in moving:
        for kind, factor in (("a", m.speed), ("alpha", definite(sp.Abs(m.turn), sample))):
            symbol = names.get((m.name, kind))
            if symbol is None or symbol == base or factor == 0:
                continue
            ratio = tidy(1 / factor)
            relation = sp.Eq(base, ratio * symbol) if ratio != 1 or kind == "alpha" else sp.Eq(symbol, base)
            if relation not in result and not (kind == "a" and symbol == base):
                result.append(relation)
    return [r for r in result if r.lhs != r.rhs]


def oriented(load, flipped: dict, rest: dict):
    """A load at rest at the placement, each constraint force turned the way it acts (`flipped`)."""
    turn = {u: -u for u, sign in flipped.items() if sign < 0}
    if isinstance(load, AppliedTorque):
        return AppliedTorque(load.body, tidy(load.torque.xreplace(rest).xreplace(turn)), load.label)
    return AppliedForce(load.body, load.offset.xreplace(rest), load.force.xreplace(rest).xreplace(turn), load.label)


def component(loads: list, heading: sp.Matrix, sample) -> sp.Expr:
    """The loads' forces along a direction, each |e| by its sign at the middle of the ranges (`definite`)."""
    total = sum((f.force.dot(heading) for f in loads if isinstance(f, AppliedForce)), sp.Integer(0))
    return tidy(sp.trigsimp(definite(sp.together(total), sample)))


def moment(loads: list, point: sp.Matrix, sample) -> sp.Expr:
    """The loads' moment about a point (world offset from the center of mass), counter-clockwise,
    each |e| by its sign at the middle of the ranges (`definite`)."""
    total = sp.Integer(0)
    for f in loads:
        if isinstance(f, AppliedTorque):
            total += f.torque
        else:
            r = f.offset - point
            total += r[0] * f.force[1] - r[1] * f.force[0]
    return tidy(sp.trigsimp(definite(sp.together(total), sample)))


def _product(mass: sp.Expr, acceleration: sp.Symbol) -> sp.Expr:
    """m a, in that order (sympy would print a m)."""
    return sp.Mul(mass, acceleration, evaluate=False)


def _forces(step: Step, forces) -> set[sp.Symbol]:
    """The constraint forces (`forces`) a step's equations hold: kinetic friction's mu_k N leaves N open
    along the motion, which the balance across it, 0 = N - m g cos(theta), gives."""
    return {s for e in step.equations for s in e.free_symbols if s in forces}


class _Offered:
    """Steps drawn from an iterator only as far as a search needs them, in its order; each taken once.

    >>> offered = _Offered(iter([1, 2, 3, 4]))
    >>> offered.take(lambda x: x % 2 == 0), offered.take(lambda x: x > 0), offered.take(lambda x: x == 2)
    (2, 1, None)
    """

    def __init__(self, steps):
        self._steps, self._drawn = steps, []

    def take(self, test):
        """The first step, in the iterator's order, that passes `test` (removed), or None."""
        found = next((x for x in self._drawn if test(x)), None)
        while found is None:
            x = next(self._steps, None)
            if x is None:
                return None
            self._drawn.append(x)
            found = x if test(x) else None
        self._drawn.remove(found)
        return found


def _across(moving, scene, loads, flipped, rest, sample, names: dict):
    """Newton's second law across the motion for each body a constraint force acts on: at rest its
    center has no acceleration across its path (nor any, where it stays put). A generator: each
    body's balances are written when a search gets to them."""
    for m in moving:
        on_body = [oriented(f, flipped, rest) for f in loads if f.body == m.name]
        if not any(isinstance(f, AppliedForce) and f.force.free_symbols & set(flipped) for f in on_body):
            continue
        if m.heading is not None:
            normal = sp.Matrix([-m.heading[1], m.heading[0]])
            balance = (sp.Eq(0, component(on_body, normal, sample)),)
            text = f"Across its motion the {m.name}'s center does not accelerate, " + \
                ("sliding along a straight line" if _sliding(scene) else "starting from rest")
            if any(isinstance(c, Pin) and c.body == m.name and c.to is None for c in scene.constraints):
                mass = scene.bodies[m.name].mass  # a pivoted body's balance along its motion is not written yet
                balance = (sp.Eq(_product(mass, names[m.name, "a"]), component(on_body, m.heading, sample)), *balance)
                text = (f"Newton's second law for the {m.name}'s center along its motion, "
                        f"{_words(m.heading, sample)}, and across it (no acceleration across, from rest)")
        else:
            balance = tuple(sp.Eq(0, component(on_body, axis, sample)) for axis in (sp.Matrix([1, 0]), sp.Matrix([0, 1])))
            text = f"The {m.name}'s center stays put: the forces on it balance"
        step = Step(text, tuple(b for b in balance if isinstance(b, sp.Eq)), role="equations", body=m.name)
        if step.equations:
            yield step


def _sliding(scene: Scene) -> bool:
    """Whether a contact slides with kinetic friction: the route then follows a slide along a line
    (derive.solution.sliding), at any speed, not only from rest."""
    return any(isinstance(c, Contact) and c.regime == "kinetic" for c in scene.constraints)


def _words(heading: sp.Matrix, sample) -> str:
    return along(*(sample(c) for c in heading)).positive


def _turning(m: _Moving) -> str:
    return TURNS[0] if m.sense > 0 else TURNS[1]


def _ties(scene: Scene) -> str:
    """What ties the bodies' motions together, in words."""
    said = []
    for part in scene.constraints:
        if isinstance(part, Contact) and part.rolling:
            said.append(f"the {part.body} rolls without slipping")
        elif isinstance(part, Cord):
            said.append("the cord neither stretches nor slips")
        elif isinstance(part, Pin):
            said.append(f"the {part.body} turns about its pin")
    return _capital("; ".join(dict.fromkeys(said)) or "How the motions are tied together")


def _capital(text: str) -> str:
    return text[:1].upper() + text[1:]
