"""Which regime a contact whose friction coefficients decide it starts a segment of motion in,
where it does not slip at the segment's start: a block released from rest on a rough table, a
crate where it stops on its ramp. A Solution's mixin (derive.solution.state_answers).

Held by static friction there (the scene with the contact stuck, solved by Lagrange's route at
the start), it would need the friction f, with the normal force N. Where mu_s N >= |f| it
holds: a round body rolls on, any other stays put and never gets to the state. Elsewhere it
slips the way f points, against kinetic friction mu_k N (derive.mechanics.friction). The
regime is taken at the middle of the parameter ranges; a variant that starts in another is
refused, as its motion is another one.

>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> solution = Solution(load("rough_table_hanging_ball"))
>>> solution.starts["fallen"].taken.name
'slips'
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import sympy as sp

from derive.mechanics import friction, reaching, states as state_motion
from derive.text.steps import Step
from derive.core.tidying import tidy
from derive.parts.contact import Contact
from derive.text.prose import Sentence


@dataclass(frozen=True)
class Start:
    """A segment's start where the contact does not slip: where each regime holds (`where`, in
    the order of `regimes`, each where those before do not), the one taken at the middle of the
    ranges (`chosen`), the joints the motion has in it, the step that says why, and the body on
    the contact."""

    regimes: tuple[friction.Regime, ...]
    where: tuple
    chosen: int
    joints: tuple
    step: Step
    body: str

    @property
    def taken(self) -> friction.Regime:
        return self.regimes[self.chosen]


class StartRegimes:
    """The regimes segments start in (a mixin: it reads the Solution's scene, states and routes)."""

    @property
    def starts(self) -> dict[str, Start]:
        """Per state whose motion starts with the contact not slipping, how it starts."""
        return self._chain.starts

    def _start(self, name: str, values: dict, joints: tuple) -> Start | None:
        """How the motion to the state `name` starts from `values` (every coordinate and velocity)
        in the scene with `joints`, where the contact of `_sliding` does not slip there and either
        slid with kinetic friction until then (it stopped) or the chain starts there (None elsewhere).

        Raises StateError where, at the middle of the ranges, static friction holds a body that
        cannot roll: it stays put and never gets to the state."""
        contact, before = self._sliding, self.scene.states[name].start
        part = next((j for j in joints if j.name == contact.name), contact) if contact else None
        if part is None or not (part.regime == "kinetic" or before is None) or \
                tidy(part.slip(self.coordinates).xreplace(values)) != 0:
            return None
        held = self._gripped(contact.name, values)
        stuck = tuple(j for j in joints if j.name != contact.name) + ((held,) if held != contact else ())
        solved = self._solved(self._derivations_with(stuck)["lagrange"], values).raw
        forces = held.unknowns()
        normal, needed = tidy(solved[forces["normal"]]), tidy(solved[forces["friction"]])
        self._presses(contact, normal, needed)
        ratio = tidy(needed / normal)
        regimes = tuple(self.regimes)
        where = friction.where_each(contact, self.regimes, ratio)
        chosen = round(self._sample(sp.Piecewise(*((sp.Integer(k), w) for k, w in enumerate(where)))))
        taken = regimes[chosen]
        at = f"in the state {before}" if before else "at the start"
        if taken.name == "stays":
            raise state_motion.StateError(
                f"static friction holds the {contact.body} at rest on {contact.surface} {at}, at the middle of the "
                "parameter ranges (mu_s N >= |f|, the friction it needs to stay put): it never gets to the state; "
                "narrow the ranges to where it slips")
        others = tuple(j for j in joints if j.name != contact.name)
        motion = stuck if taken.direction == 0 else others + (friction.slipping(contact, taken.direction),)
        step = self._start_step(contact, held, taken, normal, needed, at)
        return Start(regimes, where, chosen, motion, step, contact.body)

    def _start_step(self, contact: Contact, held: Contact, taken: friction.Regime, normal: sp.Expr,
                    needed: sp.Expr, at: str) -> Step:
        """Why the contact starts in the regime it does: the friction holding it would need, against
        what static friction can give."""
        f, n = sp.Symbol(f"f^{contact.body}", real=True), held.unknowns()["normal"]
        if taken.direction == 0:
            said = (f"so the {contact.body} rolls without slipping, and static friction supplies ", f, ".")
        else:
            said = (f"so the {contact.body} slips, and kinetic friction, ", contact.kinetic * n,
                    ", acts against the slip, the way ", f, " points, as long as it slides.")
        still = "rolling without slipping" if self.regimes[0].name == "rolls" else "at rest"
        compared = "at least" if taken.direction == 0 else "less than"
        return Step(f"Whether the {contact.body} grips or slips {at}", (sp.Eq(n, normal), sp.Eq(f, needed)),
                    sentences=(Sentence((f"Held by static friction {at}, {still}, the {contact.body} would need the "
                                         "friction ", f, " below, with the normal force ", n, "; static friction gives "
                                         "at most ", friction.static_coefficient(contact) * n, f", {compared} ",
                                         sp.Abs(f), " here (a variant where it is not is refused): ", *said)),))

    def _start_regime_conditions(self, name: str) -> list[tuple[sp.Expr, bool, str]]:
        """A segment on the way to the state `name` that starts with the contact not slipping is
        derived in the regime taken at the middle of the ranges: a variant that starts in another is
        refused (held by static friction a block never moves; slipping the other way, or rolling,
        its motion is another one)."""
        result, link = [], name
        while link:
            start = self._chain.starts.get(link)
            if start is not None:
                result += self._other_regimes(start, name, link)
            link = self.scene.states[link].start
        return result

    def _other_regimes(self, start: Start, name: str, link: str) -> list[tuple[sp.Expr, bool, str]]:
        body, taken = self._sliding.body, start.taken
        before = self.scene.states[link].start
        at = f"in the state {before}" if before else "from the start"
        does = {"stays": f"static friction holds the {body} at rest {at}, so it never gets to the state {name}",
                "rolls": f"the {body} rolls without slipping {at}",
                "slips": f"the {body} slips {at}"}
        result = []
        for k, regime in enumerate(start.regimes):
            if k == start.chosen:
                continue
            said = does[regime.name] + (" the other way" if regime.direction and taken.direction else "")
            result.append((sp.Piecewise(*((sp.Integer(1), w) for w in start.where[:k]), (sp.Integer(-1), start.where[k]),
                                        (sp.Integer(1), True)), True,
                           f"at these values {said} (derive found the motion to {link} where it {taken.name}, as at "
                           "the middle of the ranges): narrow the ranges"))
        return result


def with_start_step(reached: reaching.Reached, start: Start | None) -> reaching.Reached:
    """The state with the step that says how its motion starts first."""
    return reached if start is None else dataclasses.replace(reached, steps=(start.step, *reached.steps))
