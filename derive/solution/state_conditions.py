"""The conditions a variant must meet for the motion to reach each named state: a Solution's mixin.

For each state asks are read in, and each it comes from: the motion gets there (the state lies on
the scene's geometry at these values), the parts keep their signs there (a cord taut, a contact
pressed, no joint pulling in an impact), a grip holds on the way, a slipping clutch or a sliding
contact slips the way it did at the middle of the ranges, a body has not dropped past an
incline's bottom; and the regime each rough bounce takes per variant (grips, slides). They join
the answers' conditions (derive.solution.answer_conditions), which a set's draws must meet.

>>> from derive.solution.answers import Solution
>>> from derive.language.problem import load
>>> solution = Solution(load("rod_swings_down"))
>>> solution._state_conditions()[0][2]
"the motion never gets to the state lowest at these values (it lies off the scene's geometry there)"
"""
from __future__ import annotations

import sympy as sp

from derive.mechanics import friction, impacts, states as state_motion
from derive.core.tidying import tidy
from derive.parts.clutch import Clutch
from derive.parts.contact import Contact
from derive.parts.slipping_clutch import SlippingClutch
from derive.parts.surfaces import Plane


class StateConditions:
    """The conditions of a Solution's states (a mixin: it reads the Solution's states and routes)."""

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
            result += self._start_regime_conditions(name)  # first: the other conditions are of its regime
            result += self._regime_followed_conditions(name)
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
        stops = self.scene.states[name].until == ("stops", None)  # where it stops the slip is zero
        for part in scene.constraints:
            if isinstance(part, Contact) and part.regime == "kinetic" and not stops:
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
