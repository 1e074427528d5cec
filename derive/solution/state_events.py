"""The events of a scene's chain of states, each solved by both routes: a Solution's mixin.

An impact (a stick, a lock, a bounce) by derive.mechanics.impacts from the joint it makes; the
impulse each part gives, by Lagrange's generalized momenta against Newton–Euler's per-body
impulses; a transfer of a body's contact onto another surface where the two meet tangentially
(derive.mechanics.transfers: no impulse, the speed and spin kept); a move of a point mass on
the body that holds it (derive.mechanics.moves). Each gives the state just after it, from which
the chain's next motion starts (derive.solution.state_answers).

>>> from derive.solution.answers import Solution
>>> from derive.language.problem import load
>>> solution = Solution(load("rod_ballistic_pendulum"))
>>> sorted(solution._chain.impacts)
['struck']
"""
from __future__ import annotations


import sympy as sp

from derive.core.memo import kept
from derive.mechanics import impacts, impulses, moves, transfers, reaching, states as state_motion
from derive.text.steps import Step
from derive.core.tidying import tidy
from derive.parts.contact import Contact
from derive.parts.pin import Pin
from derive.text.prose import Sentence
from derive.model.scene import Quantity


def in_place(joints: tuple, made) -> tuple:
    """The joints events made, with `made` in place of the one of its name (a moved pin, a
    gripping clutch in place of the slipping one), else added."""
    return tuple(j for j in joints if j.name != made.name) + (made,)


class StateEvents:
    """The events of a Solution's chain (a mixin: it reads the Solution's scene and states)."""

    def _impact(self, name: str, before: dict, joints: tuple, made, route: str) -> impacts.Impact:
        """The impact of the state `name` by `route`, in the scene with the joints before it and the
        one it makes (`made`)."""
        event = self.scene.states[name].event
        bounce = impacts.Bounce(made, event.restitution, event.friction) if event.kind == "bounce" else None
        try:
            return impacts.impact(self._scene_with(in_place(joints, made)), self.coordinates, before, route, bounce)
        except impacts.ImpactError as error:
            if event.kind == "transfer":  # the impact is how derive proves that none acts
                raise state_motion.StateLimit(f"carry the {event.body} onto {event.to}, which needs it to {error}") \
                    from None
            raise state_motion.StateLimit(str(error)) from None

    @kept
    def _impact_by(self, name: str, route: str) -> impacts.Impact:
        """The impact of the state `name` by `route` (Lagrange's is the chain's own)."""
        if route == "lagrange":
            return self._chain.impacts[name]
        start = self.scene.states[name].start
        return self._impact(name, self.states[start].values, self._struck_with(name), self._chain.made[name], route)

    def _struck_with(self, name: str) -> tuple:
        """The joints the impact of the state `name` is solved in: those of the state before, with a
        contact held by friction sliding for the instant where it would need a friction impulse
        (state_answers._slides_through)."""
        return self._chain.struck.get(name, self._chain.joints[self.scene.states[name].start])

    def impulse_in(self, q: Quantity, name: str, route: str) -> sp.Expr:
        """The impulse a body takes in the impact of the state `name`, or a joint gives the body it
        holds (derive.mechanics.impulses): by Lagrange's route from the changes of momentum, by
        Newton–Euler's from the impact's impulse equations."""
        start = self.scene.states[name].start
        before, coords = self.states[start].values, self.coordinates
        scene = self._scene_with(in_place(self._struck_with(name), self._chain.made[name]))
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

    def _after_impact(self, name: str, before: dict, impact: impacts.Impact, scene) -> reaching.Reached:
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
        return reaching.Reached(values, (), steps)

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
                        old: str) -> reaching.Reached:
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
        return reaching.Reached(dict(before), (), steps)

    def _move(self, name: str, before: dict, joints: tuple, route: str) -> moves.Moved:
        """The move, turn or pull of the state `name` by `route`, in the scene with the joints before it."""
        event = self.scene.states[name].event
        made = {"turn": moves.turn, "pull": moves.pull}.get(event.kind, moves.move)
        return made(self._scene_with(joints), self.coordinates, before, event, route, self._sample)

    def _after_move(self, name: str, before: dict, moved: moves.Moved, pin: Pin | None = None) -> reaching.Reached:
        """The state after a move, a turn or a pull, with the kinetic energy the forces that make it add; a
        move's `pin` holds the mover at its new place."""
        event = self.scene.states[name].event
        added = tidy(-impacts.energy_lost(self.dynamics_scene, self.coordinates, before, moved.values))
        if event.kind == "pull":
            what = f"The pull: the cord {event.joint} is drawn slowly to the length {sp.sstr(event.length)}"
            said = Sentence((f"The cord {event.joint} is drawn through the point it is tied at until its length is ",
                             event.length, f": its force on the {event.body} points at that point whatever its size, "
                             "and the pull is slow, so at the end the cord is taut at its new length and the "
                             f"{event.body} moves across it.",))
        elif event.kind == "turn":
            what = f"The turn: the {event.body} turns relative to the {event.to}"
            said = Sentence((f"The {event.body} turns through ", event.angle, f" relative to the {event.to}, by a couple "
                             "between the two: equal and opposite, it pushes neither's center, and at the end the "
                             f"{event.body} is at rest relative to the {event.to} again.",))
        else:
            what = f"The move: the {event.body} is carried to a new place on the {event.to}"
            said = Sentence((f"The {event.body} is carried to ", sp.Tuple(*event.place), f" on the {event.to}, in its "
                             f"frame, by forces inside the scene: {pin.title} holds it to the {event.to} wherever it is, "
                             f"and what carries it pushes back on the {event.to} as much.",))
        inside = event.kind != "pull"  # a pull's force comes from outside, through the point the cord is tied at
        makers = "the forces inside the scene that make it do" if inside else "the pull on the cord does"
        steps = (Step(f"{what} by forces inside the scene (they come in equal and opposite pairs)" if inside else what,
                      (), sentences=(said,)),
                 *moved.steps,
                 Step(f"Kinetic energy the {event.kind} adds (the work of the forces that make it)",
                      (sp.Eq(sp.Symbol("Delta_K"), added),), sentences=(Sentence((
                          f"Kinetic energy is not conserved in a {event.kind}: {makers} work, which is the change "
                          "below." if added != 0 else
                          f"The forces inside the scene that make the {event.kind} do work on the way, but none in all: "
                          "the kinetic energy after it is the one before.",)),)))
        return reaching.Reached(moved.values, (), steps)
