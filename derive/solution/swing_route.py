"""The student's route to a state on a circle: a pendulum, a rod or disk on a pivot, a body in a bowl or
on a dome (sliding without friction, or rolling), as a solution manual solves it in a few equations
(Serway & Jewett 9th ed., ch. 8 and 10; Halliday, Resnick & Walker 10th ed., ch. 8 and 11):

    energy from the start:   K + U the same, K = m v^2/2 (+ I omega^2/2, omega = v/r rolling)
                             or I_P omega^2/2 about a fixed pivot (I_P = I_cm + M d^2)
    Newton toward the center: F + M g z/rho = M v^2/rho (z the center's height above the circle's
                             center, rho its radius; F the cord's pull, the pivot's force or the
                             surface's push toward the center), where it leaves the surface or the
                             cord goes slack: F = 0, v^2 = g z; where it stops, no kinetic energy left
    the torque about a pivot: I_P alpha = M g times the weight's arm

Offered only for one body held on its circle by one part (a pin to the ground, a cord from a fixed
point to a point mass, a contact on a circle with no friction or rolling with none given), under
gravity alone, from the placement (at rest or at given rates) to one state it gets to, where every ask
is one of these findings; each finding is compared with the key's answer before the route is offered
and again by the check textbook_route (derive.solution.crosschecks).

>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> list(Solution(load("block_in_bowl")).textbook_route.sections)
['The speed, by the conservation of energy', "The forces, by Newton's second law toward the center"]
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.core.tidying import root, tidy
from derive.model.scene import Body
from derive.parts.contact import Contact
from derive.parts.cord import Cord
from derive.parts.pin import Pin
from derive.parts.surfaces import Circle
from derive.solution.crosschecks import same_at_samples
from derive.solution.textbook_routes import TextbookRoute
from derive.text.steps import Step

#: The asks the route answers in a state: (kind, detail).
ANSWERED = {("speed", None), ("angular_velocity", None), ("angular_acceleration", None), ("force", "tension"),
            ("contact", "normal_force"), ("force", "reaction.x"), ("force", "reaction.y"), ("position", "y")}
#: The forces toward the center the route finds: (kind, detail).
FORCES = (("force", "tension"), ("contact", "normal_force"), ("force", "reaction.x"), ("force", "reaction.y"))
#: How each holder is said, and why it does no work.
HOLDERS = {"pivot": ("the pivot", "the pivot's force", "the pivot's force acts at a point that does not move, so it "
                     "does no work"),
           "cord": ("the cord's fixed end", "the cord's pull", "the cord's pull is at right angles to the motion and "
                    "does no work"),
           "inside": ("the center of the curve", "the surface's push", "the surface's push is at right angles to the "
                      "motion and does no work, and there is no friction"),
           "outside": ("the center of the curve", "the surface's push", "the surface's push is at right angles to "
                       "the motion and does no work, and there is no friction")}
ROLLING = "the surface's push does no work, nor does static friction, acting at a point that does not slip"


@dataclass(frozen=True)
class _Circle:
    """The circle the body's center of mass runs on: its center, its radius rho, what holds it there
    ("pivot", "cord", "inside" or "outside" a curved surface) and, rolling, the body's own radius."""

    body: Body
    center: sp.Matrix
    radius: sp.Expr
    holder: str
    part: object
    rolls: sp.Expr | None = None


def _circle(solution) -> _Circle | None:
    """The one body and the one part that holds its center on a circle (None for any other scene)."""
    scene = solution.scene
    if len(scene.bodies) != 1 or len(scene.constraints) != 1 or scene.loads or scene.gravity is None:
        return None
    (body,), (part,) = scene.bodies.values(), scene.constraints
    at = sp.Matrix(body.at)
    if body.path is not None or body.density is not None:
        return None
    if isinstance(part, Pin) and part.to is None and body.rotates:
        rest = solution.coordinates.at_rest_in_reference()
        center = solution.coordinates.position(body.name, part.offset).xreplace(rest)
        distance = tidy(sp.sqrt((at - center).dot(at - center)))
        return _Circle(body, center, distance, "pivot", part) if distance != 0 else None
    if isinstance(part, Cord) and len(part.path) == 2 and part.drawn == 0 and body.shape == "point":
        fixed = [a for a in part.path if a.body is None]
        held = [a for a in part.path if a.body == body.name]
        if len(fixed) != 1 or len(held) != 1 or any(a.kind != "point" for a in part.path) or held[0].offset != (0, 0):
            return None
        center = sp.Matrix(fixed[0].offset)
        return _Circle(body, center, tidy(sp.sqrt((at - center).dot(at - center))), "cord", part)
    if body.composite is not None:  # a body of parts on anything but a pivot: the engine's routes
        return None
    if isinstance(part, Contact) and not part.has_friction and part.point is None and part.center is None \
            and part.carrier is None:
        surface = scene.surfaces[part.surface]
        if not isinstance(surface, Circle) or surface.carrier is not None or surface.turn != 0:
            return None
        radius = body.sizes.get("radius", sp.Integer(0))
        if part.rolling and (radius == 0 or body.face_center is not None) or not part.rolling and body.rotates:
            return None  # a body that slides and may spin has two freedoms
        return _Circle(body, surface.middle, tidy(surface.path_radius(radius)), surface.side, part,
                       radius if part.rolling else None)
    return None


def swing_route(solution) -> TextbookRoute | None:
    """The route of a body on a circle from its placement (at rest, or at given rates) to the one state
    asked (through states on the way, which energy needs no more of; see the module), or None."""
    circle = _circle(solution)
    if circle is None or len(solution.regimes) != 1:
        return None
    states = solution.scene.states
    starts = [s for s in states.values() if s.rates]
    ends = [s for s in states.values() if not s.rates]
    asked = {a.state for a in solution.problem.asks.values()}
    if len(starts) > 1 or any(s.start is not None or s.event is not None for s in starts):
        return None
    start = starts[0] if starts else None
    on_the_way = [start and start.name]
    for state in ends:  # each from the start or from a state on the way there (energy needs no more)
        if state.event is not None or state.rate or state.relative_to is not None or state.start not in on_the_way \
                or state.when is None and state.until is None:
            return None
        on_the_way.append(state.name)
    ends = [s for s in ends if s.name in asked]
    if len(ends) != 1:
        return None
    (end,) = ends
    found = _found_where(end, circle)
    if end.when is None and found is None or any(s.until is not None for s in states.values() if s is not end):
        return None
    asks = solution.problem.asks
    for ask in asks.values():
        if ask.finds or ask.small or (ask.quantity.kind, ask.quantity.detail) not in ANSWERED \
                or ask.state not in (None, end.name, start and start.name):
            return None
        if ask.quantity.detail == "y" and not (found and ask.state == end.name):
            return None  # a position only where the route finds it: where it leaves, or stops
    try:
        swing = _Swing(solution, circle, start, end, found)
        sections = swing.sections()
    except _Refused:
        return None
    if sections is None or any(not swing.same(value, solution.expression(name))
                               for name, value in swing.answers.items()):
        return None  # a finding the key reads otherwise (a signed component): the engine's routes
    compared = [(name, value, (lambda name=name: solution.expression(name))) for name, value in swing.answers.items()]
    return TextbookRoute(sections, tuple(compared), "the conservation of energy and Newton's second law toward the "
                                                    "center of the circle")


def _found_where(end, circle: _Circle) -> str | None:
    """How the route finds where the state `end` is: "leaves" (a surface's push falls to zero), "slack" (the
    cord's pull does), "stops"; None where the file gives where it is (or the route does not find it)."""
    if end.until == ("stops", None):
        return "stops"
    if end.until == ("leaves", circle.part.name) and circle.holder in ("inside", "outside"):
        return "leaves"
    if end.until == ("slack", circle.part.name) and circle.holder == "cord":
        return "slack"
    return None


#: How each way of finding the state says it: (where, the force falling to zero).
FOUND = {"leaves": ("where it leaves", "It leaves the surface where the push has fallen to zero",
                    "Where it leaves the surface, by Newton's second law toward the center and energy"),
         "slack": ("where the cord goes slack", "The cord goes slack where its pull has fallen to zero",
                   "Where the cord goes slack, by Newton's second law toward the center and energy"),
         "stops": ("where it stops", None, "How high it rises, by the conservation of energy")}


class _Refused(Exception):
    """An ask or a state the route does not read."""


class _Swing:
    """The body's motion on its circle: where each state is (the height z of its center above the
    circle's center), its speed there, and the steps that find the asks."""

    def __init__(self, solution, circle: _Circle, start, end, found: str | None):
        self.solution, self.circle, self.start, self.end, self.found = solution, circle, start, end, found
        body = circle.body
        self.mass, self.g = body.mass, solution.scene.gravity.g
        self.pivot = circle.holder == "pivot"
        self.answers: dict[str, sp.Expr] = {}
        problem = solution.problem
        self.taken = {*(p.symbol.name for p in problem.parameters.values()), *problem.parameters, *problem.asks}
        self.moment = sp.Symbol(self._free("I_P", "I_O") if self.pivot else
                                body.inertia.name if isinstance(body.inertia, sp.Symbol) else self._free("I", "I_cm"))
        self.moment_value = tidy(body.inertia + self.mass * circle.radius**2) if self.pivot else body.inertia

    def _free(self, *names: str) -> str:
        name = next((n for n in names if n not in self.taken), None)
        if name is None:
            raise _Refused(names)
        return name

    def _asked(self, kinds: tuple, state) -> list:
        return [(name, ask) for name, ask in self.solution.problem.asks.items()
                if ask.state == state and (ask.quantity.kind, ask.quantity.detail) in kinds]

    def _named(self, kinds: tuple, state, default: tuple[str, ...]) -> sp.Symbol:
        """The ask's own name for what it asks in `state`, else the first of `default` free."""
        asked = self._asked(kinds, state)
        return sp.Symbol(asked[0][0] if asked else self._free(*default), positive=True)

    def same(self, a: sp.Expr, b: sp.Expr) -> bool:
        return same_at_samples(self.solution.problem, a, b)

    # where each state is, and how fast it moves there
    def _values(self, state) -> dict:
        if state is None:
            return self.solution.coordinates.at_rest_in_reference()
        return self.solution.states[state.name].values

    def _place(self, state) -> sp.Matrix:
        body, coords, values = self.circle.body, self.solution.coordinates, self._values(state)
        return sp.Matrix([tidy(body.at[i] + values.get(coords.of(body.name, k).q, 0)) for i, k in enumerate("xy")])

    def _rate(self, state) -> sp.Expr:
        """The start's speed (its rate of turning about a pivot), from the rates the file gives."""
        if state is None:
            return sp.Integer(0)
        body, coords, values = self.circle.body, self.solution.coordinates, self._values(state)
        if self.pivot:
            return tidy(sp.Abs(values[coords.of(body.name, "theta").u]))
        vx, vy = (values[coords.of(body.name, k).u] for k in "xy")
        return root(vx**2 + vy**2)

    def _kinetic(self, speed: sp.Expr, omega: sp.Expr | None = None) -> sp.Expr:
        """K in the speed (the rate of turning about a pivot), with the rolling body's omega as given."""
        if self.pivot:
            return self.moment * speed**2 / 2
        if self.circle.rolls is None:
            return self.mass * speed**2 / 2
        turning = omega if omega is not None else speed / self.circle.rolls
        return self.mass * speed**2 / 2 + self.moment * turning**2 / 2

    def _put(self, energy: sp.Eq, v: sp.Symbol, omega: sp.Symbol | None) -> sp.Eq:
        """The energy equation with the moment of inertia's value and the rolling tie put in."""
        tie = {omega: v / self.circle.rolls} if omega is not None else {}
        return energy.subs({self.moment: self.moment_value, **tie})

    def _inertia_steps(self) -> list[Step]:
        body = self.circle.body
        if self.pivot and body.composite is not None:
            return [Step("The moment of inertia about the pivot, by the parallel-axis theorem part by part: each "
                         "part's own about its center plus its mass times the square of its center's distance from "
                         "the pivot", (sp.Eq(self.moment, body.composite.moment_about(self.circle.part.offset)),
                                       sp.Eq(self.moment, self.moment_value)))]
        if self.pivot:
            return [Step("The moment of inertia about the pivot, by the parallel-axis theorem: the moment about the "
                         "center of mass plus the mass times the square of the center's distance from the pivot",
                         (sp.Eq(self.moment, self.moment_value),))]
        if self.circle.rolls is None or self.moment == body.inertia:
            return []
        return [Step("The moment of inertia about the center", (sp.Eq(self.moment, body.inertia),))]

    def sections(self) -> dict[str, tuple[Step, ...]] | None:
        """The route's sections, each ask's finding kept in `answers` (None where an ask is left)."""
        circle, rolls = self.circle, self.circle.rolls is not None
        speed0 = self._rate(self.start)
        v = self._named((("angular_velocity", None),) if self.pivot else (("speed", None),), self.end.name,
                        ("omega", "omega_1") if self.pivot else ("v", "v_1"))
        omega = self._named((("angular_velocity", None),), self.end.name, ("omega", "omega_1")) if rolls else None
        start_words = "the release" if speed0 == 0 else self._spot(self.start) or "the start"
        end_words = FOUND[self.found][0] if self.found else self._spot(self.end) or "the state asked"
        why = ROLLING if rolls else HOLDERS[circle.holder][2]
        energy_text = (f"Energy is conserved from {start_words} to {end_words}: {why}; "
                       "only gravity does work. The kinetic energy is that of " + (
                           "the rotation about the pivot" if self.pivot else "the center's motion and of the rotation, "
                           "rolling at the speed over its radius" if rolls else "its motion"))
        first = [*self._inertia_steps(), *([Step("It rolls without slipping", (sp.Eq(omega, v / circle.rolls),))]
                                           if rolls else [])]
        way = self._reaching if self.found is None else self._stopping if self.found == "stops" else self._leaving
        title, steps, speed = way(v, omega, speed0, energy_text)
        sections = {title: (*first, *steps, *self._readings(v, speed, omega))}
        newton = self._newton(self.start, self._place(self.start), speed0, None)
        if self.found is None:
            newton += self._newton(self.end, self._place(self.end), speed, v)
        elif self._asked(FORCES, self.end.name):
            raise _Refused("a force where the route finds the state")
        if newton:
            sections["The forces, by Newton's second law toward the center"] = tuple(newton)
        torques = self._torques()
        if torques:
            sections["The angular acceleration, by the torque about the pivot"] = tuple(torques)
        return None if set(self.solution.problem.asks) - set(self.answers) else sections

    def _energy(self, v: sp.Symbol, omega: sp.Symbol | None, speed0: sp.Expr, height: sp.Expr) -> sp.Eq:
        """K + U the same at the start and where the center is `height` above the circle's center."""
        start_height = tidy(self._place(self.start)[1] - self.circle.center[1])
        return sp.Eq(self._kinetic(v, omega), self._kinetic(speed0) + self.mass * self.g * tidy(start_height - height))

    def _reaching(self, v: sp.Symbol, omega: sp.Symbol | None, speed0: sp.Expr, text: str) -> tuple:
        """(title, steps, speed) to a state given where it is: the energy, solved for the speed."""
        energy = self._energy(v, omega, speed0, self._place(self.end)[1] - self.circle.center[1])
        if self.circle.body.composite is not None:  # each part's weight's work, as a solution manual sums it
            energy = sp.Eq(energy.lhs, self._kinetic(speed0) + self._drops())
            text += "; the potential energy each part gives up is its weight times the drop of its center"
        square = sp.Symbol("s", positive=True)
        squared = tidy(sp.solve(self._put(energy, v, omega).subs(v, sp.sqrt(square)), square)[0])
        if self.solution._sample(squared) < 0:
            raise _Refused("it does not get there")
        speed = root(squared)
        word = "the rate of turning" if self.pivot else "the speed"
        return (f"{word[0].upper()}{word[1:]}, by the conservation of energy",
                [Step(text, (energy,)), Step(f"Solving for {word}", (sp.Eq(v, speed),), role="solve")], speed)

    def _leaving(self, v: sp.Symbol, omega: sp.Symbol | None, speed0: sp.Expr, text: str) -> tuple:
        """(title, steps, speed) to where the body leaves the surface: Newton toward the center with no push,
        v^2 = g z, and the energy, solved for the height z; each position asked is read from z."""
        circle = self.circle
        height = sp.Symbol(self._height_name(), real=True)
        push = sp.Symbol(self._free("T", "F") if circle.holder == "cord" else self._free("N", "n"), real=True)
        toward = -push if circle.holder == "outside" else push
        energy = self._energy(v, omega, speed0, height)
        (z,) = sp.solve(self._put(energy, v, omega).subs(v, sp.sqrt(self.g * height)), height)
        z = tidy(z)
        speed = root(self.g * z)
        holder, pushes = HOLDERS[circle.holder][:2]
        where, zero, title = FOUND[self.found]
        steps = [Step(f"Newton's second law toward {holder}, with the body at a height above it: {pushes} and the "
                      "weight's component along the radius give the centripetal acceleration",
                      (sp.Eq(toward + self.mass * self.g * height / circle.radius, self.mass * v**2 / circle.radius),)),
                 Step(zero, (sp.Eq(v**2, self.g * height),), role="solve"),
                 Step(text, (energy,)),
                 Step(where[0].upper() + where[1:], (sp.Eq(height, z),), role="solve")]
        if self._asked((("speed", None), ("angular_velocity", None)), self.end.name):
            steps.append(Step("The speed there, from the same condition", (sp.Eq(v, speed),), role="solve"))
        return title, steps + self._heights(height, z), speed

    def _parts_at(self, state) -> list[tuple[sp.Expr, sp.Matrix]]:
        """(mass, where its center is) of each part of a body of parts in `state`."""
        body, coords, values = self.circle.body, self.solution.coordinates, self._values(state)
        return [(mass, coords.position(body.name, body.composite.points()[name]).xreplace(values))
                for name, (_, mass, _, _, _) in body.composite.parts.items()]

    def _drops(self) -> sp.Expr:
        """The work of the weights of a body of parts from the start to the end state, part by part (each part's
        mass times g times the drop of its center), unevaluated: M g L/2 + m g L for a rod with a ball at its end."""
        drops = [(mass, tidy(start[1] - end[1])) for (mass, start), (_, end)
                 in zip(self._parts_at(self.start), self._parts_at(self.end))]
        return sp.Add(*(sp.Mul(mass, self.g, drop, evaluate=False) for mass, drop in drops if drop != 0), evaluate=False)

    def _part_torques(self, state) -> sp.Expr:
        """The torques of a body of parts' weights about the pivot in `state`, part by part, unevaluated, each
        taken the way the whole weight turns it (a part beyond the pivot subtracts)."""
        way = 1 if self.solution._sample(self._place(state)[0] - self.circle.center[0]) > 0 else -1
        arms = [(mass, tidy(way * (at[0] - self.circle.center[0]))) for mass, at in self._parts_at(state)]
        return sp.Add(*(sp.Mul(mass, self.g, arm, evaluate=False) for mass, arm in arms if arm != 0), evaluate=False)

    def _stopping(self, v: sp.Symbol, omega: sp.Symbol | None, speed0: sp.Expr, text: str) -> tuple:
        """(title, steps, speed) to where the motion stops: the energy with no kinetic energy left, solved for
        the height z; each position asked is read from z."""
        height = sp.Symbol(self._height_name(), real=True)
        start_height = tidy(self._place(self.start)[1] - self.circle.center[1])
        energy = sp.Eq(self._kinetic(speed0), self.mass * self.g * (height - start_height))
        (z,) = sp.solve(self._put(energy, v, omega), height)
        z = tidy(z)
        steps = [Step(f"{text}; where it stops it has none left", (energy,)),
                 Step("Where it stops", (sp.Eq(height, z),), role="solve")]
        return FOUND["stops"][2], steps + self._heights(height, z), sp.Integer(0)

    def _heights(self, height: sp.Symbol, z: sp.Expr) -> list[Step]:
        """Each position asked in the end state, read from the height `z` above the circle's center."""
        steps = []
        for name, _ in self._asked((("position", "y"),), self.end.name):
            self.answers[name] = tidy(self.circle.center[1] + z)
            if name != height.name:
                steps.append(Step("The height, from the circle's center", (sp.Eq(sp.Symbol(name), self.answers[name]),),
                                  role="solve"))
        return steps

    def _height_name(self) -> str:
        """The height of the center above the circle's center: the ask's own name where it asks it."""
        asked = self._asked((("position", "y"),), self.end.name)
        if asked and self.circle.center[1] == 0:
            return asked[0][0]
        return self._free("h", "z", "y_1")

    def _readings(self, v: sp.Symbol, speed: sp.Expr, omega: sp.Symbol | None) -> list[Step]:
        """The speed or rate of turning asked beside the one energy finds: v = omega d about a pivot,
        omega = v/r rolling."""
        steps, circle = [], self.circle
        for name, ask in self._asked((("speed", None), ("angular_velocity", None)), self.end.name):
            symbol = sp.Symbol(name, positive=True)
            if symbol == v:
                self.answers[name] = speed
                continue
            if symbol == omega:  # the rolling tie gives it
                self.answers[name] = tidy(speed / circle.rolls)
                steps.append(Step("The rate of turning there, rolling without slipping",
                                  (sp.Eq(symbol, self.answers[name]),), role="solve"))
                continue
            if ask.quantity.kind == "speed" and self.pivot:
                relation, text = circle.radius * v, ("The center moves on its circle about the pivot at the rate of "
                                                    "turning times its distance from the pivot")
            elif ask.quantity.kind == "angular_velocity" and circle.rolls is not None:
                relation, text = v / circle.rolls, "Rolling without slipping, it turns at its speed over its radius"
            elif ask.quantity.kind == "speed" and not self.pivot:
                relation, text = v, "The speed"
            else:
                raise _Refused(name)
            self.answers[name] = tidy(relation.subs(v, speed))
            equations = (sp.Eq(symbol, relation), sp.Eq(symbol, self.answers[name])) if relation != v else \
                (sp.Eq(symbol, self.answers[name]),)
            steps.append(Step(text, equations, role="solve"))
        return steps

    def _newton(self, state, place: sp.Matrix, speed: sp.Expr, v: sp.Symbol | None) -> list[Step]:
        """Newton's second law toward the center for each force asked in `state` (where the body is at `place`,
        moving at `speed`, named `v` where the energy found it)."""
        name = state.name if state else None
        circle, asked = self.circle, self._asked(FORCES, name)
        steps = []
        for ask_name, ask in asked:
            if ask.quantity.target not in (circle.part.name, circle.body.name):
                raise _Refused(ask_name)
            force = sp.Symbol(ask_name, real=True)
            inward = self._inward(place)
            if ask.quantity.kind == "force" and ask.quantity.detail.startswith("reaction"):
                along, across = (inward[1], inward[0]) if ask.quantity.detail.endswith("y") else (inward[0], inward[1])
                if along == 0 and across in (1, -1) and self.pivot:  # along the tangent: the torque gives it
                    steps += self._tangential(ask_name, ask, state, place)
                    continue
                if across != 0 or along not in (1, -1):
                    raise _Refused(ask_name)  # the force's component across the radius and along it: the engine's routes
                toward = along * force if ask.sign is not None else force  # asked as a size: the size toward the center
            else:
                toward = -force if circle.holder == "outside" else force
            height = tidy(place[1] - circle.center[1])
            rate = v if v is not None else speed if speed.is_Symbol or speed == 0 else \
                sp.Symbol(self._free("omega_0") if self.pivot else self._free("v_0", "u"), positive=True)
            given = () if rate is v or rate == speed else (sp.Eq(rate, speed),)
            centripetal = self.mass * rate**2 * circle.radius if self.pivot else self.mass * rate**2 / circle.radius
            law = sp.Eq(toward + tidy(self.mass * self.g * height / circle.radius), centripetal)
            value = tidy(sp.solve(law.subs(rate, speed), force)[0])
            self.answers[ask_name] = value
            where = self._at(state)
            gives = "balance, at rest" if speed == 0 else "give the centripetal acceleration"
            steps.append(Step(f"Newton's second law toward {HOLDERS[circle.holder][0]}, {where}: "
                              f"{HOLDERS[circle.holder][1]} and the weight's component along the radius {gives}",
                              (*given, law, sp.Eq(force, value))))
        return steps

    def _tangential(self, name: str, ask, state, place: sp.Matrix) -> list[Step]:
        """The pivot's force along the tangent (the x or y component asked where the radius lies along the
        other axis): the angular acceleration by the torque about the pivot, I_P alpha = -M g x (x the
        center's horizontal distance from the pivot, counter-clockwise positive), then Newton's second law
        along the tangent, F + W = M alpha r, the way the force points where it is asked as a size
        (Serway & Jewett ch. 10: a chimney falling to the level, M g/4 up on its base)."""
        arm = tidy(place - self.circle.center)
        alpha, force = sp.Symbol(self._free("alpha", "alpha_1"), real=True), sp.Symbol(name, real=True)
        torque = tidy(-self.mass * self.g * arm[0])
        alpha_value = tidy(torque / self.moment_value)

        def along(e: sp.Matrix) -> tuple:  # (k x r) . e, the tangential acceleration per unit alpha; W . e; F . e
            lever, weight = tidy(-arm[1] * e[0] + arm[0] * e[1]), tidy(-self.mass * self.g * e[1])
            return lever, weight, tidy(self.mass * alpha_value * lever - weight)
        e = sp.Matrix([1, 0]) if ask.quantity.detail.endswith("x") else sp.Matrix([0, 1])
        lever, weight, value = along(e)
        if ask.sign is None and self.solution._sample(value) < 0:  # asked as a size: along the way it points
            e = -e
            lever, weight, value = along(e)
        self.answers[name] = value
        words = {(1, 0): "to the right", (-1, 0): "to the left", (0, 1): "up", (0, -1): "down"}[tuple(e)] \
            if ask.sign is None else f"along {ask.quantity.detail[-1]}"
        where = self._at(state)
        return [Step(f"The torque about the pivot {where}, counter-clockwise positive: the pivot's force has no moment "
                     "about it, and the weight's is its size times the center's horizontal distance from the pivot",
                     (sp.Eq(self.moment * alpha, torque), sp.Eq(alpha, alpha_value))),
                Step(f"Newton's second law along the tangent, {words}, {where}: the pivot's force and the weight give "
                     "the center's acceleration along it, the angular acceleration times the center's distance from "
                     "the pivot", (sp.Eq(force + weight, self.mass * alpha * lever), sp.Eq(force, value)))]

    def _inward(self, place: sp.Matrix) -> sp.Matrix:
        """The unit vector from the body's center toward the circle's center."""
        return sp.Matrix([tidy(c) for c in (self.circle.center - place) / self.circle.radius])

    def _spot(self, state) -> str | None:
        """Where `state` is on the circle, in words ("the lowest point", "where it is level with the pivot"),
        or None where it is none of these."""
        inward = self._inward(self._place(state))
        if inward[0] == 0 and inward[1] in (1, -1):
            return "the lowest point" if inward[1] == 1 else "the top"
        if inward[1] == 0:
            what = "it is" if self.circle.body.shape == "point" else "its center is"
            return f"where {what} level with {HOLDERS[self.circle.holder][0]}"
        return None

    def _at(self, state) -> str:
        """`_spot` after "at" ("at the lowest point"), or "at the start", "there"."""
        spot = self._spot(state)
        if spot is None:
            return "at the release" if state is None else "at the start" if state is not self.end else "there"
        return spot if spot.startswith("where") else f"at {spot}"

    def _torques(self) -> list[Step]:
        """The angular acceleration asked in a state, by the torque about the pivot."""
        steps = []
        for name, ask in self._asked((("angular_acceleration", None),), None) + \
                self._asked((("angular_acceleration", None),), self.end.name) + \
                (self._asked((("angular_acceleration", None),), self.start.name) if self.start else []):
            if not self.pivot or self.found and ask.state == self.end.name:
                raise _Refused(name)
            state = self.end if ask.state == self.end.name else self.start if ask.state else None
            arm = tidy(sp.Abs(self._place(state)[0] - self.circle.center[0]))
            arm = self.solution._within_ranges(arm, absolute=True) if arm.has(sp.Abs) else arm
            alpha = sp.Symbol(name, real=True)
            self.answers[name] = tidy(self.mass * self.g * arm / self.moment_value)
            where = "at the release" if state is None else "there"
            if arm == 0:
                steps.append(Step(f"The torque about the pivot {where}: the weight acts along the line through the "
                                  "pivot and has no moment about it, nor has the pivot's force", (sp.Eq(alpha, 0),),
                                  role="solve"))
            elif self.circle.body.composite is not None:  # each part's weight's torque, as a solution manual sums it
                steps.append(Step(f"The torque about the pivot {where}: the pivot's force has no moment about it; each "
                                  "part's weight's arm is the horizontal distance from the pivot to the part's center",
                                  (sp.Eq(self.moment * alpha, self._part_torques(state)),
                                   sp.Eq(alpha, self.answers[name]))))
            else:
                steps.append(Step(f"The torque about the pivot {where}: the pivot's force has no moment about it; the "
                                  "weight's arm is the horizontal distance from the pivot to the center",
                                  (sp.Eq(self.moment * alpha, self.mass * self.g * arm),
                                   sp.Eq(alpha, self.answers[name]))))
        return steps
