"""Answers in the named states of a scene (`scene.states`, `in: STATE`): where each state is
(derive.mechanics.states), each route's accelerations and forces there, the rates, positions and
times asked in it, the conditions a variant must meet for the motion to get there, and the steps
a worked solution shows. A mixin of derive.solution.answers.Solution, which gives it the scene, the
coordinates, the routes' derivations and the parameter ranges.

>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> solution = Solution(load("rod_swings_down"))
>>> solution.expression("omega")
sqrt(3)*sqrt(g)/sqrt(L)
"""
from __future__ import annotations

import dataclasses
import logging
from dataclasses import dataclass
from functools import cached_property

import sympy as sp

from derive.core.memo import kept
from derive.core import limits
from derive.mechanics import (durations, friction, grips, impacts, lagrange, moves, newton_euler, reaching, states as state_motion)
from derive.mechanics.derivation import Solved
from derive.text.steps import Step
from derive.core.tidying import tidy
from derive.parts.clutch import Clutch
from derive.parts.contact import Contact
from derive.parts.pin import Pin
from derive.parts.slipping_clutch import SlippingClutch
from derive.parts.weld import Weld
from derive.parts.places import extent
from derive.text.prose import Sentence, capital
from derive.model.scene import RATE_KINDS
from derive.solution.state_conditions import StateConditions

#: What the time limit suggests where finding a state of a chain is slow: each state is found from the
#: one before, over the whole motion between them (a ball released on a chute into a loop, until it
#: leaves the loop, took over 300 s; the same physics started at the loop's bottom, 5.6 s).
FASTER_CHAIN = ("start the chain at a later state given by its rates (states: {NAME: {rates: {...}}}), so that "
                "fewer states are found")
from derive.solution.state_events import StateEvents, in_place

PROGRESS = logging.getLogger(__name__)  # each state of a chain as it is found (derive.publishing.progress shows it)
from derive.solution.start_regimes import Start, StartRegimes, with_start_step


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

    reached: dict[str, reaching.Reached]
    joints: dict[str, tuple]
    impacts: dict[str, impacts.Impact | moves.Moved]
    made: dict[str, object]
    followed: dict[str, impacts.Regime] = dataclasses.field(default_factory=dict)
    starts: dict[str, Start | None] = dataclasses.field(default_factory=dict)
    struck: dict[str, tuple] = dataclasses.field(default_factory=dict)


class StateAnswers(StateEvents, StateConditions, StartRegimes):
    """What Solution answers in a named state (its events: derive.solution.state_events; the conditions of the
    states: derive.solution.state_conditions)."""

    @property
    def states(self) -> dict[str, reaching.Reached]:
        """Every coordinate and velocity in each named state of the scene (derive.mechanics.states):
        the placement moving at given rates, where a coordinate gets to from another state, or
        just after an impact (derive.mechanics.impacts)."""
        return self._chain.reached

    @cached_property
    def _chain(self) -> Chain:
        """Each named state in turn, from the state it starts from (see Chain)."""
        result, joints, solved, made, followed, starts, struck = {}, {}, {}, {}, {}, {}, {}

        def resolve(expr: sp.Expr) -> sp.Expr:  # |L0 - d|, |sin(theta0)|: as the parameter ranges have them
            return self._within_ranges(expr, absolute=True) if expr.has(sp.Abs, sp.Piecewise) else expr
        for number, (name, state) in enumerate(self.scene.states.items(), start=1):
            PROGRESS.info("%s: finding the state %s (%d of %d)", self.problem.id, name, number, len(self.scene.states))
            try:
                joints[name] = joints[state.start] if state.start else self._root_joints(state, result)
                if state.event is None and not state.rates and not self.grips_in(name):
                    starts[name] = self._start(name, result[state.start].values if state.start else
                                               state_motion.rest(self.coordinates), joints[name])
                    joints[name] = starts[name].joints if starts[name] else joints[name]
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
                with limits.time_limit(f"finding the state {name}", faster=FASTER_CHAIN):
                    if state.until and state.until[0] == "grips":
                        start = result[state.start].values if state.start else state_motion.rest(self.coordinates)
                        reached = grips.grip(self.coordinates, start, self._slipping(state.until[1]),
                                             self._derivations_with(joints[name])["lagrange"], self._sample)
                        made[name] = self._gripped(state.until[1], reached.values)
                        joints[name] = in_place(joints[name], made[name])
                    elif state.event is None:
                        reached = with_start_step(self._state(state, found, joints[name]), starts.get(name))
                        if name in followed:
                            reached = dataclasses.replace(reached, steps=(Step(
                                f"The motion after the bounce {state.start} where it {followed[name].name}, as at the "
                                "middle of the ranges (a variant where it does otherwise is refused)"), *reached.steps))
                    elif state.event.kind == "move":
                        made[name] = moves.moved_pin(self._scene_with(joints[name]), state.event, state.event.place)
                        joints[name] = in_place(joints[name], made[name])
                        solved[name] = self._move(name, result[state.start].values, joints[state.start], "lagrange")
                        reached = self._after_move(name, result[state.start].values, solved[name], made[name])
                    elif state.event.kind == "pull":
                        solved[name] = self._move(name, result[state.start].values, joints[name], "lagrange")
                        made[name] = moves.pulled_cord(self._scene_with(joints[name]), self.coordinates,
                                                       result[state.start].values, state.event)
                        joints[name] = in_place(joints[name], made[name])
                        reached = self._after_move(name, result[state.start].values, solved[name])
                    elif state.event.kind == "turn":
                        solved[name] = self._move(name, result[state.start].values, joints[name], "lagrange")
                        reached = self._after_move(name, result[state.start].values, solved[name])
                    elif state.event.kind == "transfer":
                        old = self._scene_with(joints[name]).constraint(state.event.joint)
                        made[name] = self._transferred(state, result[state.start].values, old)
                        solved[name] = self._impact(name, result[state.start].values, joints[name], made[name],
                                                    "lagrange")
                        joints[name] = in_place(joints[name], made[name])
                        reached = self._after_transfer(name, result[state.start].values, solved[name], made[name],
                                                       old.surface)
                    else:
                        made[name] = self._joint(state, result)
                        solved[name] = self._impact(name, result[state.start].values, joints[name], made[name],
                                                    "lagrange")
                        through = self._slides_through(solved[name], joints[name])
                        if through is not None:  # solved again with the contact sliding for the instant
                            joints[name] = struck[name] = through
                            solved[name] = self._impact(name, result[state.start].values, through, made[name],
                                                        "lagrange")
                        if state.event.kind != "bounce":  # a bounce's touch lasts the instant only
                            joints[name] = in_place(joints[name], made[name])
                        reached = self._after_impact(name, result[state.start].values, solved[name],
                                                     self._scene_with(in_place(joints[name], made[name])))
                # (what must stay positive is evaluated per variant, Abs and all: left as it is; so is
                # the regime a rough bounce takes)
                if not (isinstance(solved.get(name), impacts.Impact) and solved[name].regimes):
                    reached = dataclasses.replace(reached, values={k: resolve(v) for k, v in reached.values.items()})
                result[name] = reached
                if state.rates and self._sliding is not None:  # its friction against the slip found
                    joints[name] = self._root_joints(state, result)
                if name in struck:  # after it slid through the impact: against its slip from then on
                    joints[name] = self._slides_after(joints[name], reached.values)
            except (state_motion.StateLimit, moves.MoveLimit) as error:
                raise self.problem.limit(f"{error} (scene.states.{name})") from None
            except (state_motion.StateError, ValueError) as error:
                raise self.problem.error(f"scene.states.{name}", str(error)) from None
        return Chain(result, joints, solved, made, followed, starts, struck)

    def _slides_through(self, impact: impacts.Impact, joints: tuple) -> tuple | None:
        """The joints an impact is solved in again where a contact held by friction coefficients
        would need a friction impulse to hold (None where it needs none): its friction, at most
        mu N, gives none in an instant where N gives none, so the contact slides through the
        impact (a rolling ball rebounding from a smooth cushion keeps its spin). A contact
        `rolling` without coefficients holds by any impulse, as the file says.

        Raises StateLimit where the normal impulse is not zero: whether it grips through the
        impact is not decided."""
        contact = self._sliding
        held = next((j for j in self._scene_with(joints).constraints if j.name == contact.name), None) \
            if contact else None
        if held is None or not held.rolling:
            return None
        forces = held.unknowns()
        friction_impulse = tidy(impact.impulses.get(forces["friction"], sp.Integer(0)))
        normal_impulse = tidy(impact.impulses.get(forces["normal"], sp.Integer(0)))
        if friction_impulse == 0:
            return None
        if normal_impulse != 0:
            raise state_motion.StateLimit(
                f"decide whether friction holds the {held.body} on {held.surface} through the impact: it would take "
                f"the friction impulse {sp.sstr(friction_impulse)} with the normal impulse {sp.sstr(normal_impulse)}")
        return in_place(joints, friction.slipping(contact, 0))

    def _slides_after(self, joints: tuple, values: dict) -> tuple:
        """After the contact slid through an impact, kinetic friction against its slip then (held
        where it does not slip: the impact left it rolling)."""
        return in_place(joints, self._against_slip(values) or self._gripped(self._sliding.name, values))

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

    def _state(self, state, found: dict, joints: tuple) -> reaching.Reached:
        coords = self.coordinates
        if state.rates:
            return state_motion.moving(self._scene_with(joints), coords, {coords.of(body, kind): value
                                                                          for body, kind, value in state.rates})
        start = found[state.start].values if state.start else state_motion.rest(coords)
        scene = self._scene_with(joints)
        return state_motion.reach(scene, coords, start, self._condition(state, scene),
                                  self._derivations_with(joints)["lagrange"], self._sample, state.nudge)

    @cached_property
    def _sliding(self) -> Contact | None:
        """The contact with kinetic friction whose regime the states follow (None: none): a chain
        given by rates starts with it sliding against their slip (`_root_joints`); from rest, or
        where it stops sliding, the forces decide (derive.solution.start_regimes); it slides until a state
        where it grips (`when: {grips: BODY}`), and holds (rolls, or stays) after."""
        if len(self.regimes) == 1:
            return None
        return self.dynamics_scene.constraint(friction.frictional(self.scene).name)

    def _root_joints(self, state, found: dict) -> tuple:
        """The joints of a state at the root of a chain (no `from:`): none, or, where it is given by
        rates, the contact with kinetic friction (`_sliding`) sliding against their slip (found
        with the contact smooth, which holds the same constraints), held where they do not slip.
        From rest the regime is decided by the forces (derive.solution.start_regimes)."""
        contact = self._sliding
        if contact is None or not state.rates:
            return ()
        if state.name not in found:  # the state itself, before its slip is known
            return (friction.slipping(contact, 0),)
        against = self._against_slip(found[state.name].values)
        return () if against is None else (against,)

    def _against_slip(self, values: dict) -> Contact | None:
        """The contact of `_sliding` sliding with kinetic friction against its slip at `values`,
        the way it slips at the middle of the ranges; None where it does not slip."""
        contact = self._sliding
        way = self._sample(contact.slip(self.coordinates).xreplace(values))
        return None if way == 0 else friction.slipping(contact, -1 if way > 0 else 1)

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

    @kept
    def _derivations_with(self, joints: tuple) -> dict:
        if not joints:
            return self.derivations
        scene = self._scene_with(joints)
        with limits.time_limit("the derivation by Lagrange, after the impact"):
            by_lagrange = lagrange.derive(scene, self.coordinates)
        with limits.time_limit("the derivation by Newton-Euler, after the impact"):
            by_newton_euler = newton_euler.derive(scene, self.coordinates)
        return {"lagrange": by_lagrange, "newton_euler": by_newton_euler}

    def _condition(self, state, scene=None) -> reaching.Gets | reaching.GetsRate | reaching.Stops | \
            reaching.Vanishes:
        """Where a state reached by the motion is: a coordinate's value or its rate's, a stop, a force at zero
        (of a part of `scene`, the scene on the way: by default the scene in the state)."""
        if state.until is None:
            body, kind, value = state.when
            if state.rate:
                return reaching.GetsRate(self.coordinates.of(body, kind), value)
            if state.relative_to is not None:
                return reaching.Gets(self.coordinates.of(body, kind), value, reaching.measured_from(
                    self.coordinates, body, kind, *state.relative_to))
            return reaching.Gets(self.coordinates.of(body, kind), value - self.scene.bodies[body].placed(kind))
        kind, name = state.until
        if kind == "stops":
            return reaching.Stops()
        if kind == "grips":  # the slip rate, positive at the middle of the ranges at the start
            slip = self._slipping(name).slip(self.coordinates)
            start = self.states[state.start].values if state.start else state_motion.rest(self.coordinates)
            return reaching.Vanishes(sp.sign(self._sample(slip.xreplace(start))) * slip,
                                         f"the slip rate of {name}")
        part = (scene or self.scene_in(state.name)).constraint(name)
        if kind == "slips":
            forces = part.unknowns()
            return reaching.Vanishes(self._grip_margin(part), f"the grip margin of the {part.body} at {name}", (
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
        return reaching.Vanishes(force, what, (
            Sentence((*holds, ", is positive.")),
            Sentence(("Along the way the equations of motion, with the rates energy gives, say how large it is at "
                      f"each point: {ends} where it first falls to zero.",))))

    @kept
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

    def refuse_undetermined(self, ask) -> None:
        """A body's speed after a move is the same however the move is made where the bodies can
        only turn about the ground's pins (a turntable); where a set of them was free to shift (a
        bead on a free rod) it is not, and the ask is refused. After a turn that leaves coordinates
        loose (moves.turn), only what does not depend on where the bodies are is asked. Where a
        body sliding with kinetic friction stops, only its rates, positions and energies are asked:
        its friction jumps there."""
        if ask.state and self.scene.states[ask.state].until == ("stops", None) and \
                ask.quantity.kind not in RATE_KINDS:
            sliding = [c for c in self.scene_in(ask.state).constraints if isinstance(c, Contact) and c.regime == "kinetic"]
            if sliding:
                raise self.problem.error(f"ask.{ask.name}.in", f"where the {sliding[0].body} stops sliding, its "
                                         "friction jumps (static friction holds it, or it slides back): ask forces and "
                                         "accelerations in a state on the way (when:)")
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

    @cached_property
    def kinetic_energy(self) -> sp.Expr:
        """Every body's kinetic energy in the coordinates and velocities (derive.quantities.rates)."""
        return lagrange.energies(self.dynamics_scene, self.coordinates)[0]

    @kept
    def duration(self, name: str) -> tuple[sp.Expr, Step]:
        reached = self.states[name]
        if reached.took is not None:
            return reached.took
        time, step = durations.duration(reached.path, reached.end)
        # |s1 - s0| by the ranges; an integral's integrand as it is (simplifying it cancels digits)
        return time.xreplace({a: self._within_ranges(a, absolute=True) for a in time.atoms(sp.Abs)}), step

    def state_heading(self, name: str) -> str:
        """The heading of a state's steps in a worked solution, in words: the start, an event (the
        impact, move or turn that makes the state, just after the state it happens in), or the
        segment of motion from the state it starts from to where it ends.

        >>> from derive.language.problem import load
        >>> from derive.solution.answers import Solution
        >>> solution = Solution(load("clutch_disks_brake"))
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
                    "transfer": f"the {event.body} passes onto the {event.to}",
                    "pull": f"the cord {event.joint} is drawn to a new length"}[event.kind]
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
            timed = self.duration(name)[1] if any(a.state == name and a.quantity.kind == "time"
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
