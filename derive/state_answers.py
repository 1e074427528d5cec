"""Answers in the named states of a scene (`scene.states`, `in: STATE`): where each state is
(derive.mechanics.states), each route's accelerations and forces there, the rates, positions and
times asked in it, the conditions a variant must meet for the motion to get there, and the steps
a worked solution shows. A mixin of derive.answers.Solution, which gives it the scene, the
coordinates, the routes' derivations and the parameter ranges.

>>> from derive.problem import load
>>> from derive.answers import Solution
>>> solution = Solution(load("tests/textbook/states/rod_swings_down.yaml"))
>>> solution.expression("omega")
sqrt(3)*sqrt(g)/sqrt(L)
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass
import functools
from functools import cached_property

import sympy as sp

from derive import limits
from derive.mechanics import durations, friction, grips, impacts, impulses, lagrange, moves, newton_euler, transfers
from derive.mechanics import states as state_motion
from derive.mechanics.derivation import Solved, Step, root, tidy
from derive.parts.clutch import Clutch
from derive.parts.contact import Contact
from derive.parts.pin import Pin
from derive.parts.slipping_clutch import SlippingClutch
from derive.parts.weld import Weld
from derive.parts.places import extent
from derive.parts.surfaces import Plane
from derive.prose import Sentence, capital
from derive.scene import Quantity


#: How a heading names each route (the routes in a state that an event changed the scene of).
ROUTES = {"lagrange": "Lagrange's method", "newton_euler": "Newton–Euler"}


@dataclass(frozen=True)
class Chain:
    """The named states of a scene, in the order the file names them (`reached`); the joints
    events made on the way to each (`joints`: the scene in a state has them, a moved pin in place
    of the pin it was); and per event, its solution by Lagrange (`impacts`: an impact's or a
    move's) and the joint it made (`made`: a bounce's touch lasts its instant only, in no state's
    scene); per state whose motion starts just after a bounce that grips or slides by the variant,
    the bounce's regime it was derived in (`followed`: the one at the middle of the ranges)."""

    reached: dict[str, state_motion.Reached]
    joints: dict[str, tuple]
    impacts: dict[str, impacts.Impact | moves.Moved]
    made: dict[str, object]
    followed: dict[str, impacts.Regime] = dataclasses.field(default_factory=dict)


def _in_place(joints: tuple, made) -> tuple:
    """The joints events made, with `made` in place of the one of its name (a moved pin, a
    gripping clutch in place of the slipping one), else added."""
    return tuple(j for j in joints if j.name != made.name) + (made,)


class StateAnswers:
    """What Solution answers in a named state."""

    @property
    def states(self) -> dict[str, state_motion.Reached]:
        """Every coordinate and velocity in each named state of the scene (derive.mechanics.states):
        the placement moving at given rates, where a coordinate gets to from another state, or
        just after an impact (derive.mechanics.impacts)."""
        return self._chain.reached

    @cached_property
    def _chain(self) -> Chain:
        """Each named state in turn, from the state it starts from (see Chain)."""
        if self.scene.states and len(self.regimes) > 1 and self._sliding is None:
            raise self.problem.limit("read a state of a scene whose friction regime it decides (mu_s given): "
                                     "give contact: rolling or sliding")
        result, joints, solved, made, followed = {}, {}, {}, {}, {}

        def resolve(expr: sp.Expr) -> sp.Expr:  # |L0 - d|, |sin(theta0)|: as the parameter ranges have them
            return self._within_ranges(expr, absolute=True) if expr.has(sp.Abs, sp.Piecewise) else expr
        for name, state in self.scene.states.items():
            joints[name] = joints[state.start] if state.start else self._slides_from(result)
            try:
                found = result
                if isinstance(solved.get(state.start), impacts.Impact) and solved[state.start].regimes:
                    if state.event is not None or state.until and state.until[0] == "grips":
                        raise state_motion.StateLimit(f"derive an event or a grip just after the bounce {state.start}, "
                                                      "which grips or slides by the variant: only a state the motion "
                                                      "gets to (when:) may follow it, or give grips: true")
                    followed[name] = self._middle_regime(solved[state.start])
                    found = {**result, state.start: dataclasses.replace(result[state.start], values={
                        **result[state.start].values, **followed[name].impact.velocities})}
                if isinstance(solved.get(state.start), moves.Moved) and solved[state.start].loose:
                    raise state_motion.StateError(f"where the bodies are after the turn {state.start} depends on how "
                                                  "long it takes (it keeps a momentum that is not zero): no state may "
                                                  "follow it")
                with limits.time_limit(f"finding the state {name}"):
                    if state.until and state.until[0] == "grips":
                        start = result[state.start].values if state.start else state_motion.rest(self.coordinates)
                        reached = grips.grip(self.coordinates, start, self._slipping(state.until[1]),
                                             self._derivations_with(joints[name])["lagrange"], self._sample)
                        made[name] = self._gripped(state.until[1], reached.values)
                        joints[name] = _in_place(joints[name], made[name])
                    elif state.event is None:
                        reached = self._state(state, found, joints[name])
                        if name in followed:
                            reached = dataclasses.replace(reached, steps=(Step(
                                f"The motion after the bounce {state.start} where it {followed[name].name}, as at the "
                                "middle of the ranges (a variant where it does otherwise is refused)"), *reached.steps))
                    elif state.event.kind == "move":
                        made[name] = moves.moved_pin(self._scene_with(joints[name]), state.event, state.event.place)
                        joints[name] = _in_place(joints[name], made[name])
                        solved[name] = self._move(name, result[state.start].values, joints[state.start], "lagrange")
                        reached = self._after_move(name, result[state.start].values, solved[name], made[name])
                    elif state.event.kind == "turn":
                        solved[name] = self._move(name, result[state.start].values, joints[name], "lagrange")
                        reached = self._after_move(name, result[state.start].values, solved[name])
                    elif state.event.kind == "transfer":
                        old = self._scene_with(joints[name]).constraint(state.event.joint)
                        made[name] = self._transferred(state, result[state.start].values, old)
                        solved[name] = self._impact(name, result[state.start].values, joints[name], made[name],
                                                    "lagrange")
                        joints[name] = _in_place(joints[name], made[name])
                        reached = self._after_transfer(name, result[state.start].values, solved[name], made[name],
                                                       old.surface)
                    else:
                        made[name] = self._joint(state, result)
                        solved[name] = self._impact(name, result[state.start].values, joints[name], made[name],
                                                    "lagrange")
                        if state.event.kind != "bounce":  # a bounce's touch lasts the instant only
                            joints[name] = _in_place(joints[name], made[name])
                        reached = self._after_impact(name, result[state.start].values, solved[name],
                                                     self._scene_with(_in_place(joints[name], made[name])))
                # (what must stay positive is evaluated per variant, Abs and all: left as it is; so is
                # the regime a rough bounce takes)
                if not (isinstance(solved.get(name), impacts.Impact) and solved[name].regimes):
                    reached = dataclasses.replace(reached, values={k: resolve(v) for k, v in reached.values.items()})
                result[name] = reached
                if state.start is None and self._sliding is not None:  # its friction against the slip found
                    joints[name] = self._slides_from(result)
            except (state_motion.StateLimit, moves.MoveLimit) as error:
                raise self.problem.limit(f"{error} (scene.states.{name})") from None
            except (state_motion.StateError, ValueError) as error:
                raise self.problem.error(f"scene.states.{name}", str(error)) from None
        return Chain(result, joints, solved, made, followed)

    def _middle_regime(self, impact: impacts.Impact) -> impacts.Regime:
        """The regime a rough bounce takes at the middle of the parameter ranges."""
        which = sp.Piecewise(*((sp.Integer(k), r.where) for k, r in enumerate(impact.regimes)))
        return impact.regimes[round(self._sample(which))]

    def _regime_followed_conditions(self, name: str) -> list[tuple[sp.Expr, bool, str]]:
        """A state whose motion starts after a bounce that grips or slides by the variant was
        derived in the bounce's regime at the middle of the ranges: a variant where the bounce does
        otherwise is refused (its motion after is another one)."""
        regime = self._chain.followed.get(name)
        if regime is None:
            return []
        start = self.scene.states[name].start
        regimes = self._chain.impacts[start].regimes
        return [(sp.Piecewise(*((sp.Integer(1), r.where) for r in regimes[:k]), (sp.Integer(-1), other.where),
                              (sp.Integer(1), True)), True,
                 f"the bounce {start} {other.name} at these values, and the motion after it to the state {name} is "
                 f"derived where it {regime.name}, as at the middle of the ranges: narrow the ranges")
                for k, other in enumerate(regimes) if other is not regime]

    def _state(self, state, found: dict, joints: tuple) -> state_motion.Reached:
        coords = self.coordinates
        if state.rates:
            return state_motion.moving(self._scene_with(joints), coords, {coords.of(body, kind): value
                                                                          for body, kind, value in state.rates})
        start = found[state.start].values if state.start else state_motion.rest(coords)
        scene = self._scene_with(joints)
        return state_motion.reach(scene, coords, start, self._condition(state, scene),
                                  self._derivations_with(joints)["lagrange"], self._sample)

    @cached_property
    def _sliding(self) -> Contact | None:
        """The contact a state grips (`when: {grips: BODY}`): it slides with kinetic friction in
        the states before, whatever the regimes at the placement."""
        names = {s.until[1] for s in self.scene.states.values() if s.until and s.until[0] == "grips"}
        return next((c for c in self.dynamics_scene.constraints if isinstance(c, Contact) and c.name in names), None)

    def _slides_from(self, found: dict) -> tuple:
        """The joints of a state at the root of a chain: none, or the sliding contact with kinetic
        friction against the slip of the first state given by its rates (found with the contact
        smooth, which holds the same constraints)."""
        contact = self._sliding
        if contact is None:
            return ()
        if not found:  # the first state itself, before its slip is known
            return (friction.slipping(contact, 0),)
        first = next(iter(found.values())).values
        way = self._sample(contact.slip(self.coordinates).xreplace(first))
        if way == 0:
            raise state_motion.StateError(f"the {contact.body} does not slide on {contact.surface} in the first state: "
                                          "give it rates that slip")
        return (friction.slipping(contact, -1 if way > 0 else 1),)

    def _slipping(self, name: str) -> SlippingClutch | Contact | None:
        """The part of that name that slips until it grips: a slipping clutch, or a contact with
        kinetic friction (None: none)."""
        scene = self.dynamics_scene
        return next((p for p in (*scene.loads, *scene.constraints) if p.name == name
                     and (isinstance(p, SlippingClutch) or isinstance(p, Contact) and p.kinetic is not None)), None)

    def _gripped(self, name: str, values: dict) -> Clutch | Contact:
        """What takes a slipping part's place where it grips, as the bodies are then: a clutch at
        the turn between its plates, a contact that rolls (or holds) from where it slid to."""
        part, coords = self._slipping(name), self.coordinates
        if isinstance(part, Contact):
            rolled = part.rolled(coords)
            slid = tidy(rolled.xreplace(values) - rolled.xreplace(coords.at_rest_in_reference()))
            return dataclasses.replace(friction.stuck(part), slipped=slid)
        turn = coords.angle(part.body) - (coords.angle(part.to) if part.to else 0)
        return Clutch(name, part.body, part.to, tidy(turn.xreplace(values)))

    def _joint(self, state, found: dict):
        """The joint the impact of `state` makes, where the bodies are in the state it happens in
        (refused where, at the middle of the ranges, they do not touch there)."""
        try:
            joint = impacts.joint(self.scene, self.coordinates, found[state.start].values, state.event, state.name,
                                  self._sample)
        except impacts.ImpactError as error:
            raise state_motion.StateLimit(str(error)) from None
        for gap, meaning in self._apart(joint, state.start):
            if self._sample(gap) < -1e-12 * (1 + abs(self._sample(gap + 1))):
                raise state_motion.StateError(meaning)
        return joint

    def _apart(self, joint, start: str) -> list[tuple[sp.Expr, str]]:
        """(reach^2 - distance^2, meaning) for a joint an impact made: not negative where the point
        mass lies on the body it sticks to, or two bodies that stick are near enough to touch."""
        if not isinstance(joint, (Pin, Weld, impacts.Touch)) or joint.to is None:
            return []

        def reach(name: str) -> sp.Expr | None:
            body = self.scene.bodies[name]
            if not body.rotates:
                return sp.Integer(0)
            return extent(body.shape, body.sizes) if body.composite is None else body.composite.extent()

        offset = joint.offset if isinstance(joint, Weld) else joint.to_offset
        if isinstance(joint, impacts.Touch):  # the point struck, on the body struck
            struck = reach(joint.to)
            where = sum((e**2 for e in offset), sp.Integer(0))
            return [] if struck is None else [(tidy(struck**2 - where), (
                f"the {joint.body} would strike the {joint.to} {sp.sstr(tidy(sp.sqrt(where)))} from its center in the "
                f"state {start}, beyond its end: a bounce off a rod's end or corner is not modelled"))]
        reaches = [reach(joint.to), reach(joint.body)]
        if any(r is None for r in reaches):
            return []
        where = sum((e**2 for e in offset), sp.Integer(0))
        return [(tidy(sum(reaches) ** 2 - where), f"the {joint.body} is {sp.sstr(tidy(sp.sqrt(where)))} from the "
                                                  f"{joint.to}'s center in the state {start}, too far to touch it: it "
                                                  "cannot stick there")]

    def _impact(self, name: str, before: dict, joints: tuple, made, route: str) -> impacts.Impact:
        """The impact of the state `name` by `route`, in the scene with the joints before it and the
        one it makes (`made`)."""
        event = self.scene.states[name].event
        bounce = impacts.Bounce(made, event.restitution, event.friction) if event.kind == "bounce" else None
        try:
            return impacts.impact(self._scene_with(_in_place(joints, made)), self.coordinates, before, route, bounce)
        except impacts.ImpactError as error:
            if event.kind == "transfer":  # the impact is how derive proves that none acts
                raise state_motion.StateLimit(f"carry the {event.body} onto {event.to}, which needs it to {error}") \
                    from None
            raise state_motion.StateLimit(str(error)) from None

    @functools.lru_cache(maxsize=None)  # noqa: B019 - one Solution per problem, a few impacts
    def _impact_by(self, name: str, route: str) -> impacts.Impact:
        """The impact of the state `name` by `route` (Lagrange's is the chain's own)."""
        if route == "lagrange":
            return self._chain.impacts[name]
        start = self.scene.states[name].start
        return self._impact(name, self.states[start].values, self._chain.joints[start], self._chain.made[name], route)

    def _impulse(self, q: Quantity, name: str, route: str) -> sp.Expr:
        """The impulse a body takes in the impact of the state `name`, or a joint gives the body it
        holds (derive.mechanics.impulses): by Lagrange's route from the changes of momentum, by
        Newton–Euler's from the impact's impulse equations."""
        start = self.scene.states[name].start
        before, coords = self.states[start].values, self.coordinates
        scene = self._scene_with(_in_place(self._chain.joints[start], self._chain.made[name]))
        solved = self._impact_by(name, route)
        joint = next((p for p in scene.constraints if p.name == q.target), None)
        if route == "lagrange":
            after = self.states[name].values
            vector = (impulses.by_momentum(scene, coords, before, after, q.target) if joint is None else
                      impulses.joint_by_momentum(scene, coords, before, after, solved.impulses, joint))
        else:
            at = {c.q: before[c.q] for c in coords.all}
            vector = impulses.on_body(scene.constraints if joint is None else [joint], coords, at, solved.impulses,
                                      q.target if joint is None else joint.body)
        return vector[0 if q.detail == "x" else 1]

    def _after_impact(self, name: str, before: dict, impact: impacts.Impact, scene) -> state_motion.Reached:
        """The state just after an impact: where the bodies were, at the velocities the impact leaves."""
        values = {**{c.q: before[c.q] for c in self.coordinates.all}, **impact.velocities}
        lost = impacts.energy_lost(self.dynamics_scene, self.coordinates, before, values)
        event = self.scene.states[name].event
        body, to = event.body, event.to
        what = {"stick": f"the {body} sticks to the {to}", "lock": f"the {body} and the {to} lock together",
                "bounce": f"the {body} bounces off the {to} (coefficient of restitution {event.restitution}"
                          + (", gripping at the contact" if event.grips else
                             f", friction coefficient {sp.sstr(event.friction[0])} at the contact" if event.friction
                             else "") + ")"}
        what = what[event.kind]
        kept = impacts.conserved(scene, self.coordinates, before, values)
        said = scene.constraint(name).sentences("lagrange", self.coordinates)  # the joint it makes, in words
        said += impacts.said(event, scene.constraint(name), scene, kept is not None)
        steps = (Step(f"The impact: {what}", (), sentences=tuple(said)), *impact.steps, *((kept,) if kept else ()),
                 Step("Kinetic energy taken by the impact (before minus after)", (sp.Eq(sp.Symbol("Delta_K"), lost),),
                      sentences=(impacts.lost_said(event),)))
        return state_motion.Reached(values, (), steps)

    def _transferred(self, state, before: dict, old: Contact) -> Contact:
        """The contact `old` on the surface the transfer of `state` carries it onto, where the body
        is in the state before (refused where the body does not touch that surface there)."""
        made = transfers.onto(old, state.event.to, self.coordinates, before)
        off = transfers.gap(made, self.coordinates, before)
        off = tidy(self._within_ranges(off, absolute=True)) if off.has(sp.Abs, sp.Piecewise) else off
        if off != 0:
            at_middle = self._sample(off)
            where = sum((abs(self._sample(before[c.q])) for c in self.coordinates.all), 1.0)  # the lengths at hand
            if abs(at_middle) > 1e-12 * where:
                raise state_motion.StateError(
                    f"the {old.body} does not touch {state.event.to} where it is in the state {state.start} (it stands "
                    f"{sp.sstr(off)} off it, {at_middle:.4g} m at the middle of the ranges): a transfer happens where "
                    f"the {old.body} touches both surfaces")
            raise state_motion.StateLimit(f"prove that the {old.body} touches {state.event.to} in the state "
                                          f"{state.start} (it stands {sp.sstr(off)} off it, zero at the middle of "
                                          "the ranges)")
        return made

    def _after_transfer(self, name: str, before: dict, impact: impacts.Impact, made: Contact,
                        old: str) -> state_motion.Reached:
        """The state just after a transfer: the bodies where they were, at the velocities they had,
        once the impact with the new contact is proved to need no impulse (else refused: a kink)."""
        def size(impulse: sp.Expr) -> float:
            proved = self._within_ranges(impulse, absolute=True) if impulse.has(sp.Abs, sp.Piecewise) else impulse
            return 0.0 if tidy(proved) == 0 else self._sample(proved)

        start = self.scene.states[name].start
        refused = transfers.needed(impact.impulses, made, size, name, start, old)
        if refused is not None:
            raise state_motion.StateError(refused)
        if any(tidy(v) != 0 for v in impact.impulses.values()):
            raise state_motion.StateLimit(f"prove that the transfer {name} needs no impulse (each is zero at the "
                                          "middle of the ranges)")
        event = self.scene.states[name].event
        steps = (Step(f"The transfer: the {event.body} passes from the {old} onto the {event.to}", (),
                      sentences=transfers.said(made, old)),
                 *impact.steps,
                 Step("Kinetic energy taken by the transfer (before minus after)", (sp.Eq(sp.Symbol("Delta_K"), 0),),
                      sentences=(Sentence(("Kinetic energy is conserved through the transfer: no impulse acts, so "
                                           "nothing does work in the instant.",)),)))
        return state_motion.Reached(dict(before), (), steps)

    def _move(self, name: str, before: dict, joints: tuple, route: str) -> moves.Moved:
        """The move or turn of the state `name` by `route`, in the scene with the joints before it."""
        event = self.scene.states[name].event
        return (moves.turn if event.kind == "turn" else moves.move)(self._scene_with(joints), self.coordinates, before,
                                                                   event, route, self._sample)

    def _after_move(self, name: str, before: dict, moved: moves.Moved, pin: Pin | None = None) -> state_motion.Reached:
        """The state after a move or a turn, with the kinetic energy the forces that make it add; a
        move's `pin` holds the mover at its new place."""
        event = self.scene.states[name].event
        added = tidy(-impacts.energy_lost(self.dynamics_scene, self.coordinates, before, moved.values))
        if event.kind == "turn":
            what = f"The turn: the {event.body} turns relative to the {event.to}"
            said = Sentence((f"The {event.body} turns through ", event.angle, f" relative to the {event.to}, by a couple "
                             "between the two: equal and opposite, it pushes neither's center, and at the end the "
                             f"{event.body} is at rest relative to the {event.to} again.",))
        else:
            what = f"The move: the {event.body} is carried to a new place on the {event.to}"
            said = Sentence((f"The {event.body} is carried to ", sp.Tuple(*event.place), f" on the {event.to}, in its "
                             f"frame, by forces inside the scene: {pin.title} holds it to the {event.to} wherever it is, "
                             f"and what carries it pushes back on the {event.to} as much.",))
        steps = (Step(f"{what} by forces inside the scene (they come in equal and opposite pairs)", (), sentences=(said,)),
                 *moved.steps,
                 Step(f"Kinetic energy the {event.kind} adds (the work of the forces that make it)",
                      (sp.Eq(sp.Symbol("Delta_K"), added),), sentences=(Sentence((
                          f"Kinetic energy is not conserved in a {event.kind}: the forces inside the scene that make it "
                          "do work, which is the change below." if added != 0 else
                          f"The forces inside the scene that make the {event.kind} do work on the way, but none in all: "
                          "the kinetic energy after it is the one before.",)),)))
        return state_motion.Reached(moved.values, (), steps)

    def scene_in(self, name: str | None):
        """The scene in a state (None: the placement): with the joints impacts on the way made."""
        return self._scene_with(self._chain.joints[name] if name else ())

    def _scene_with(self, joints: tuple):
        """The scene with the joints events made (a moved pin in place of the one of its name)."""
        scene = self.dynamics_scene
        if not joints:
            return scene
        replaced = {j.name for j in joints}
        return dataclasses.replace(scene, constraints=tuple(c for c in scene.constraints if c.name not in replaced)
                                   + joints, loads=tuple(p for p in scene.loads if p.name not in replaced))

    def derivations_in(self, name: str | None) -> dict:
        """Each route's derivation of the scene in a state (see scene_in)."""
        return self._derivations_with(self._chain.joints[name] if name else ())

    def grips_in(self, name: str) -> bool:
        """Whether the state `name` is where a slipping part grips (`when: {grips: ...}`)."""
        until = self.scene.states[name].until
        return until is not None and until[0] == "grips"

    def derivations_to(self, name: str) -> dict:
        """Each route's derivation of the motion that gets to the state `name`: the scene of the
        state it starts from where the state is a grip (the part slipping on the way), else its own."""
        return self.derivations_in(self.scene.states[name].start if self.grips_in(name) else name)

    @functools.lru_cache(maxsize=None)  # noqa: B019 - one Solution per problem, a few impacts
    def _derivations_with(self, joints: tuple) -> dict:
        if not joints:
            return self.derivations
        scene = self._scene_with(joints)
        with limits.time_limit("the derivation by Lagrange, after the impact"):
            by_lagrange = lagrange.derive(scene, self.coordinates)
        with limits.time_limit("the derivation by Newton-Euler, after the impact"):
            by_newton_euler = newton_euler.derive(scene, self.coordinates)
        return {"lagrange": by_lagrange, "newton_euler": by_newton_euler}

    def _condition(self, state, scene=None) -> state_motion.Gets | state_motion.GetsRate | state_motion.Stops | \
            state_motion.Vanishes:
        """Where a state reached by the motion is: a coordinate's value or its rate's, a stop, a force at zero
        (of a part of `scene`, the scene on the way: by default the scene in the state)."""
        if state.until is None:
            body, kind, value = state.when
            if state.rate:
                return state_motion.GetsRate(self.coordinates.of(body, kind), value)
            return state_motion.Gets(self.coordinates.of(body, kind), value - self.scene.bodies[body].placed(kind))
        kind, name = state.until
        if kind == "stops":
            return state_motion.Stops()
        if kind == "grips":  # the slip rate, positive at the middle of the ranges at the start
            slip = self._slipping(name).slip(self.coordinates)
            start = self.states[state.start].values if state.start else state_motion.rest(self.coordinates)
            return state_motion.Vanishes(sp.sign(self._sample(slip.xreplace(start))) * slip,
                                         f"the slip rate of {name}")
        part = (scene or self.scene_in(state.name)).constraint(name)
        if kind == "slips":
            forces = part.unknowns()
            return state_motion.Vanishes(self._grip_margin(part), f"the grip margin of the {part.body} at {name}", (
                Sentence((f"The {part.body} grips the {part.surface} while static friction can supply the friction ",
                          forces["friction"], " it needs, at most ", friction.static_coefficient(part) * forces["normal"],
                          " in size: while ", self._grip_margin(part), " is not negative.")),
                Sentence(("Along the way the equations of motion, with the rates energy gives, say how large that is "
                          f"at each point: the {part.body} starts to slip where it first falls to zero.",))))
        force = part.unknowns()["normal"] if kind == "leaves" else next(iter(part.unknowns().values()))
        what = f"the normal force on the {part.body} at {name}" if kind == "leaves" else f"the tension of {name}"
        holds = (f"The {part.body} stays on the {part.surface} while the normal force on it, ", force) \
            if kind == "leaves" else (f"{capital(part.title)} stays taut while its tension, ", force)
        ends = f"the {part.body} leaves the {part.surface}" if kind == "leaves" else "it goes slack"
        return state_motion.Vanishes(force, what, (
            Sentence((*holds, ", is positive.")),
            Sentence(("Along the way the equations of motion, with the rates energy gives, say how large it is at "
                      f"each point: {ends} where it first falls to zero.",))))

    @functools.lru_cache(maxsize=None)  # noqa: B019 - one Solution per problem, two routes, a few states
    def in_state(self, route: str, name: str | None) -> Solved:
        """One route's accelerations and forces in a named state (None: the placement at rest)."""
        if name is None:
            return self.at_reference(route)
        reached, derivation = self.states[name], self.derivations_in(name)[route]
        if reached.path is None:
            return self._solved(derivation, reached.values)
        # Along the path first (functions of its one coordinate s), then at the state: its values
        # hold roots of the whole scene's sizes (a ball leaving a dome), in which the linear solve
        # took 26 s against 1 s along the path.
        path = reached.path
        general, where, rate = path.general
        at = {where: reached.values[path.s], rate: reached.values[path.coordinate.u]}
        return Solved({u: v.xreplace(at) for u, v in self._solved(derivation, general, path.frozen).raw.items()})

    def _refuse_undetermined(self, ask) -> None:
        """A body's speed after a move is the same however the move is made where the bodies can
        only turn about the ground's pins (a turntable); where a set of them was free to shift (a
        bead on a free rod) it is not, and the ask is refused. After a turn that leaves coordinates
        loose (moves.turn), only what does not depend on where the bodies are is asked."""
        moved = self._chain.impacts.get(ask.state) if ask.state else None
        if not isinstance(moved, moves.Moved):
            return
        if ask.quantity.kind == "speed" and any(s.along for s in moved.kept):
            raise self.problem.error(f"ask.{ask.name}.in", f"after the move {ask.state} the bodies are free to shift, "
                                                           "so their speeds depend on how the move is made: ask an "
                                                           "angular velocity or the kinetic energy")
        if moved.loose and ask.quantity.kind not in ("angular_velocity", "kinetic_energy", "kinetic_energy_change",
                                                     "speed"):
            loose = ", ".join(sorted(str(q) for q in moved.loose))
            raise self.problem.error(f"ask.{ask.name}.of", f"after the turn {ask.state}, {loose} depend on how long it "
                                                           "takes (it keeps a momentum that is not zero, or whose "
                                                           "coefficients change): ask an angular velocity, a speed or "
                                                           "the kinetic energy there")

    def _rate(self, q: Quantity, name: str) -> sp.Expr:
        """A body's velocity, speed, angular velocity, position or angle in a named state, the
        kinetic energy of every body there (or its change from the state it comes from), the
        velocity of their center of mass, or the time the motion takes to get there."""
        if q.kind == "time":
            return self._duration(name)[0]
        start = self.scene.states[name].start
        return self.rate_at(q, self.states[name].values, self.states[start].values if start else None)

    def rate_at(self, q: Quantity, values: dict, before: dict | None = None) -> sp.Expr:
        """A quantity of `_rate` but the time, at the coordinates and velocities `values` (the
        change of kinetic energy from those `before`): of a state's closed form, or of a
        simulation's state (derive.chain_simulation)."""
        coords = self.coordinates
        kinetic = lagrange.energies(self.dynamics_scene, coords)[0]
        if q.kind == "kinetic_energy":
            return tidy(kinetic.xreplace(values))
        if q.kind == "kinetic_energy_change":
            return tidy(kinetic.xreplace(values) - kinetic.xreplace(before))
        if q.kind == "center_of_mass_velocity":
            bodies = self.scene.bodies.values()
            momentum = sum((b.mass * values[coords.of(b.name, q.detail).u] for b in bodies), sp.Integer(0))
            return tidy(momentum / sum((b.mass for b in bodies), sp.Integer(0)))
        if q.kind in ("angle", "position"):
            kind = "theta" if q.kind == "angle" else q.detail
            return tidy(self.scene.bodies[q.target].placed(kind) + values[coords.of(q.target, kind).q])
        if q.kind == "angular_velocity":
            return values[coords.of(q.target, "theta").u]
        if q.kind == "velocity":
            return values[coords.of(q.target, q.detail).u]
        return root(values[coords.of(q.target, "x").u] ** 2 + values[coords.of(q.target, "y").u] ** 2)

    @functools.lru_cache(maxsize=None)  # noqa: B019 - one Solution per problem, a few states
    def _duration(self, name: str) -> tuple[sp.Expr, Step]:
        reached = self.states[name]
        if reached.took is not None:
            return reached.took
        time, step = durations.duration(reached.path, reached.end)
        # |s1 - s0| by the ranges; an integral's integrand as it is (simplifying it cancels digits)
        return time.xreplace({a: self._within_ranges(a, absolute=True) for a in time.atoms(sp.Abs)}), step

    def _state_conditions(self) -> list[tuple[sp.Expr, bool, str]]:
        """In each state asked: the motion gets there, the state is on the scene's geometry, and
        the parts keep their signs there."""
        result = []
        for name in self._on_the_way():
            reached, scene = self.states[name], self.scene_in(name)
            if isinstance(self._chain.impacts.get(name), impacts.Impact):  # no joint pulls where it can only push
                made, start = self._chain.made[name], self.scene.states[name].start
                result += [(gap, False, meaning) for gap, meaning in self._apart(made, start)]
                impulses = self._chain.impacts[name].impulses
                result += [(sign.expression.xreplace(impulses), False, f"{sign.meaning} (in the impact {name})")
                           for part in (*self.scene_in(start).constraints, made) for sign in part.signs()]
                if isinstance(made, impacts.Touch) and made.rough:
                    result += self._rough_conditions(name)
            result += self._regime_followed_conditions(name)  # first: the other conditions are of its regime
            forces = self.in_state("lagrange", name).raw
            # the state is real, first: where a formula puts it off the scene's geometry (a ball
            # higher than its cord reaches, a swing that would stop above the top), the motion
            # never gets there at these values, and the other conditions are not numbers
            never = (f"the motion goes over the top and never stops at these values ({name})"
                     if self.scene.states[name].until == ("stops", None) else
                     f"the motion never gets to the state {name} at these values (it lies off the scene's geometry "
                     "there)")
            exprs = [*reached.values.values(), *(e for e, _ in reached.positive)]
            result += [(real, False, never) for real in dict.fromkeys(
                [p.base for v in exprs for p in v.atoms(sp.Pow) if p.exp.is_Rational and p.exp.q == 2]
                + [tidy(1 - f.args[0] ** 2) for v in exprs for f in v.atoms(sp.acos, sp.asin)])]
            result += [(expr, True, f"{meaning} ({name})") for expr, meaning in reached.positive]
            result += self._grip_conditions(name)
            result += self._slip_conditions(name, scene, forces)
            # (a force the state is defined by, zero there, has no sign to keep: it was positive on the way)
            result += [(sign.expression.xreplace(forces).xreplace(reached.values), False, f"{sign.meaning} ({name})")
                       for part in (*scene.constraints, *scene.loads) for sign in part.signs()
                       if not sign.expression.has(*reached.vanished)]
        return result + self._ramp_conditions()

    def impact_regimes(self) -> dict[str, tuple]:
        """The regimes (impacts.Regime: grips, slides either way) of each rough bounce whose
        regime is decided per variant, in the states asks are read in or come from."""
        return {name: self._chain.impacts[name].regimes for name in self._on_the_way()
                if isinstance(self._chain.impacts.get(name), impacts.Impact) and self._chain.impacts[name].regimes}

    def impact_regime_at(self, name: str, values: dict) -> str | None:
        """What the contact does in the bounce `name` at these parameter values (grips, slides);
        None when a parameter it depends on has no value."""
        for regime in self.impact_regimes()[name]:
            decided = regime.where.xreplace(values)
            if decided not in (sp.true, sp.false):
                return None
            if decided == sp.true:
                return regime.name
        raise AssertionError("the last regime holds wherever the others do not")

    def _rough_conditions(self, name: str) -> list[tuple[sp.Expr, bool, str]]:
        """A rough bounce slides the one way throughout where it slides (impacts.regime_conditions),
        and takes kinetic energy (with Newton's restitution and friction at a contact whose normal and
        tangential motions are coupled it could give some, which is not physical)."""
        start = self.scene.states[name].start
        before, after = self.states[start].values, self.states[name].values
        lost = impacts.energy_lost(self.dynamics_scene, self.coordinates, before, after)
        return [*impacts.regime_conditions(self._chain.impacts[name], self._chain.made[name], self.coordinates,
                                           before),
                (lost, False, f"the bounce {name} would give the bodies kinetic energy (Newton's restitution with "
                              "friction where the normal and tangential motions are coupled): not modelled")]

    def _slip_conditions(self, name: str, scene, forces: dict) -> list[tuple[sp.Expr, bool, str]]:
        """A slipping clutch slips in the state, the way it does at the middle of the ranges, and a
        sliding contact the way its kinetic friction opposes (where it stops slipping it grips: a
        state `when: {grips: ...}`); a clutch that has gripped needs a couple of at most its
        kinetic one (derive takes no larger static couple)."""
        values, result = self.states[name].values, []
        for part in scene.loads:
            if isinstance(part, SlippingClutch):
                slip = part.slip(self.coordinates).xreplace(values)
                result.append((sp.sign(self._sample(slip)) * slip, True,
                               f"the plates of {part.name} do not slip in the state {name} the way they do at the "
                               f"middle of the ranges (they turn together, or slip the other way): narrow the ranges, "
                               f"or give a state when: {{grips: {part.name}}} and go on from it"))
        for part in scene.constraints:
            if isinstance(part, Contact) and part.regime == "kinetic":
                result.append((-part.direction * part.slip(self.coordinates).xreplace(values), True,
                               f"the {part.body} does not slide on {part.surface} in the state {name} the way it does "
                               f"at the middle of the ranges, which its kinetic friction opposes (it slides the other "
                               f"way, or grips): narrow the ranges"))
        for part in scene.constraints:
            slipping = self._slipping(part.name) if isinstance(part, Clutch) else None
            if slipping is not None:
                couple = forces[part.unknowns()["torque"]].xreplace(values)
                result.append((slipping.couple**2 - couple**2, False,
                               f"the clutch {part.name} would slip again in the state {name}: it needs a couple "
                               f"larger than {sp.sstr(slipping.couple)}"))
        return result

    @staticmethod
    def _grip_margin(contact) -> sp.Expr:
        """mu_s^2 N^2 - f^2: not negative while the contact's grip holds (N >= 0 is a sign of its own)."""
        forces = contact.unknowns()
        return friction.static_coefficient(contact) ** 2 * forces["normal"] ** 2 - forces["friction"] ** 2

    def _grip_conditions(self, name: str) -> list[tuple[sp.Expr, bool, str]]:
        """A contact held by static friction (friction: {static: mu_s}) keeps its grip in the state
        and, on the motion's way there, at ON_THE_WAY - 1 points between: past the point where it
        would slip, the motion is not the one derived (a ball slips on a dome long before it leaves)."""
        state, reached, result = self.scene.states[name], self.states[name], []
        for contact in self.scene_in(name).constraints:
            if not isinstance(contact, Contact) or not contact.has_friction or not contact.rolling \
                    or state.until == ("slips", contact.name):
                continue
            margin = self._grip_margin(contact)
            meaning = (f"the {contact.body} slips at {contact.name} on the way to the state {name} (mu_s N < |f|): ask "
                       f"where it starts to slip (when: {{slips: {contact.name}}})")
            forces = self.in_state("lagrange", name).raw
            result.append((margin.xreplace(forces).xreplace(reached.values), False, meaning))
            if reached.path is not None:
                path, s1 = reached.path, reached.end
                s0 = path.start[path.s]
                on_path = state_motion.along(path, margin, self.derivations_in(name)["lagrange"])
                result += [(on_path.xreplace({path.s: s0 + sp.Rational(k, state_motion.ON_THE_WAY) * (s1 - s0)}), False,
                            meaning) for k in range(state_motion.ON_THE_WAY)]
        return result

    def _on_the_way(self) -> list[str]:
        """The states asks are read in, and those their motions start from, in the file's order: a
        chain's every link."""
        names = {a.state for a in self.problem.asks.values() if a.state is not None}
        for name in reversed(self.scene.states):
            if name in names and self.scene.states[name].start:
                names.add(self.scene.states[name].start)
        return [name for name in self.scene.states if name in names]

    def _ramp_conditions(self) -> list[tuple[sp.Expr, bool, str]]:
        """An incline's height is how far it drops below where a body starts
        (derive.parts.surfaces.Plane): in every state the motion gets to, the body has not dropped
        past its bottom (where a formula for an endless plane would put it beyond, the variant is
        refused). Up the slope the plane goes on: a block pulled up it is not limited."""
        result = []
        for name, reached in self.states.items():
            if reached.path is None:
                continue
            for contact in self.scene_in(name).constraints:  # on the surface the body is on there
                surface = self.scene.surfaces.get(getattr(contact, "surface", None))
                if not isinstance(contact, Contact) or not isinstance(surface, Plane) or surface.height is None:
                    continue
                drop = -reached.values[self.coordinates.of(contact.body, "y").q]
                result.append((surface.height - drop, False, f"the {contact.body} would be past the bottom of "
                                                             f"{contact.surface} in the state {name} (it drops "
                                                             f"{sp.sstr(surface.height)} below where the "
                                                             f"{contact.body} starts)"))
        return result

    def state_heading(self, name: str) -> str:
        """The heading of a state's steps in a worked solution, in words: the start, an event (the
        impact, move or turn that makes the state, just after the state it happens in), or the
        segment of motion from the state it starts from to where it ends.

        >>> from derive.problem import load
        >>> from derive.answers import Solution
        >>> solution = Solution(load("tests/textbook/states/clutch_disks_brake.yaml"))
        >>> [solution.state_heading(n) for n in ("spinning", "coupled", "stopped")]  # doctest: +NORMALIZE_WHITESPACE
        ['The start, spinning: the placement moving at the given rates', 'The impact coupled, just after spinning:
        the upper and the lower lock together', 'From coupled to stopped: the motion until it stops']
        """
        state = self.scene.states[name]
        if state.rates:
            return f"The start, {name}: the placement moving at the given rates"
        event = state.event
        if event is not None:
            what = {"stick": f"the {event.body} sticks to the {event.to}",
                    "lock": f"the {event.body} and the {event.to} lock together",
                    "bounce": f"the {event.body} bounces off the {event.to}",
                    "move": f"the {event.body} is carried to a new place on the {event.to}",
                    "turn": f"the {event.body} turns relative to the {event.to}",
                    "transfer": f"the {event.body} passes onto the {event.to}"}[event.kind]
            if event.kind == "transfer":
                what = what.replace("passes", f"passes from the {self.scene_in(state.start).constraint(event.joint).surface}")
            kind = "impact" if event.kind in ("stick", "lock", "bounce") else event.kind
            return f"The {kind} {name}, just after {state.start}: {what}"
        start = f"From {state.start} to {name}" if state.start else f"From rest at the placement to {name}"
        if state.until is None:
            body, kind, _ = state.when
            return f"{start}: the motion until the {body}'s {'angle' if kind == 'theta' else kind} gets to its value"
        kind, part = state.until
        if kind == "grips":
            slipping = self._slipping(part)
            if isinstance(slipping, SlippingClutch):
                return f"{start}: the motion while the plates of {slipping.title} slip, until they grip"
            return f"{start}: the motion while the {slipping.body} slides, until it grips"
        if kind == "stops":
            return f"{start}: the motion until it stops"
        part = self.scene_in(name).constraint(part)
        if kind == "slack":
            return f"{start}: the motion until {part.title} goes slack"
        return f"{start}: the motion until the {part.body} " + ("starts to slip" if kind == "slips" else
                                                                f"leaves the {part.surface}")

    def _state_steps(self, result: dict[str, list[Step]]) -> None:
        """Add to a worked solution's steps, by route, how each state asked is found and the
        routes' solution there."""
        for name in self._on_the_way():
            heading = self.state_heading(name)
            result[heading] = list(self.states[name].steps)
            timed = self._duration(name)[1] if any(a.state == name and a.quantity.kind == "time"
                                                   for a in self.problem.asks.values()) else None
            if timed is not None and timed not in result[heading]:  # a grip's time is one of its steps already
                result[heading].append(timed)
            in_state = self._needed_unknowns(name)
            joints = self._chain.joints[name]
            for route, d in self.derivations_in(name).items() if in_state else ():
                solved = self.in_state(route, name)  # the answers' own solution there (along a path: by it)
                if joints:  # the scene after an impact: its own equations
                    route = f"{ROUTES[route]}, with the joint{'s' if len(joints) > 1 else ''} " + \
                            ", ".join(j.name for j in joints)
                result[route] = [*(result.get(route) or d.steps),
                                 Step(f"Solving in the state {name}", tuple(sp.Eq(u, solved[u]) for u in d.unknowns
                                                                            if u in in_state))]
