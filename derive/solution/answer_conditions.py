"""The conditions a problem's answers need, and which variants break them: a Solution's mixin.

An answer holds only where its derivation's assumptions do: a cord taut, a body pressing on its
surface, a grip that holds, an equilibrium that is stable, a magnitude whose sign was read at
the middle of the ranges, the file's own `conditions:`. Each is an expression that must be
positive (strict) or not negative, with its meaning; a set's variants are drawn until none breaks
(derive.publishing.variants.valid_draws), their signs certified together (derive.numbers.numeric).

>>> from derive.solution.answers import Solution
>>> from derive.language.problem import load
>>> solution = Solution(load("string_wrapped_disk"))
>>> expression, strict, meaning = solution.conditions[0]
>>> expression, meaning
(M*g*m/(M + 2*m), 'the cord string goes slack (its tension would be negative)')
"""
from __future__ import annotations

from functools import cached_property

import sympy as sp

from derive import quantities
from derive.core import limits
from derive.numbers import numeric
from derive.solution.crosschecks import sample_points
from derive.core.errors import InputError
from derive.mechanics import friction
from derive.core.tidying import tidy
from derive.parts.contact import Contact
from derive.parts.surfaces import Plane
from derive.model.scene import DYNAMIC_KINDS


class AnswerConditions:
    """The conditions of a Solution's answers (a mixin: it reads the Solution's derivations)."""

    @cached_property
    def conditions(self) -> list[tuple[sp.Expr, bool, str]]:
        """(expression, strict, meaning): each expression must be positive (strict) or not
        negative for the answers to exist."""
        with limits.time_limit(f"{self.problem.path}: the conditions of its answers"):
            return self._conditions()

    def _conditions(self) -> list[tuple[sp.Expr, bool, str]]:
        # the file's own conditions on parameters alone first: where one breaks, its words say why
        # (an impact parameter beyond the sphere's radius, before the engine finds the hit off it)
        result = self._declared(answers=False)
        orbit = self.scene.orbit
        if orbit is not None and orbit.eccentricity is not None:
            result.append((1 - orbit.eccentricity, True, "e >= 1 is not an ellipse but a parabola or a hyperbola"))
            result.append((orbit.eccentricity, False, "an eccentricity cannot be negative"))
        result += [(placed, True, f"the bodies are not placed as at the middle of the ranges, where "
                                  f"{sp.sstr(placed)} > 0 (a cord's run would turn over): the derivation is for that "
                                  "placement") for placed in self.scene.placed]
        for surface in self.scene.surfaces.values():  # a file's angle in symbols: checked per variant
            if isinstance(surface, Plane) and surface.angle.free_symbols:
                result += [(surface.angle, False, f"the plane {surface.name}'s angle {sp.sstr(surface.angle)} is "
                                                  "negative: a plane's angle lies in [0, pi/2) (`descends: left` for one that goes down to the left)"),
                           (sp.pi / 2 - surface.angle, True, f"the plane {surface.name}'s angle {sp.sstr(surface.angle)} "
                                                             "is pi/2 or more: a plane's angle lies in [0, pi/2)")]
        if {a.quantity.kind for a in self.problem.asks.values()} & DYNAMIC_KINDS:
            result += self._sign_conditions()
        for ask in self.problem.asks.values():
            result += quantities.KINDS[ask.quantity.kind].conditions(self, ask)
        return result + self._magnitudes() + self._found_in_range() + self._declared(answers=True)

    def small_oscillation_conditions(self, ask: str) -> list[tuple[sp.Expr, bool, str]]:
        """What a small oscillation's answers need (derive.quantities.small_oscillation): each normal
        mode's; of one degree of freedom, the forces that carry the swing positive at the equilibrium,
        a stability read at the middle of the ranges kept, and no overdamping (`ask`: the first ask of
        one, named where a force at the equilibrium is zero)."""
        if self.freedoms > 1:
            return list(self.normal_modes["lagrange"].conditions)
        result = self._loaded_at_equilibrium(ask)
        oscillation = self.oscillations["lagrange"]
        if not oscillation.proven:  # its sign was read at the middle of the ranges
            result.append((oscillation.stiffness if oscillation.stable else -oscillation.stiffness, True,
                           f"the equilibrium is {'un' if oscillation.stable else ''}stable at these parameters "
                           f"(q'' = {sp.sstr(-oscillation.stiffness)} q)"))
        if oscillation.damping != 0 and oscillation.stable:
            result.append((tidy(oscillation.stiffness - oscillation.damping**2 / 4), True,
                           "the damping is too strong at these parameters: it does not oscillate "
                           "(overdamped, c^2/4 >= k)"))
        return result

    def _found_in_range(self) -> list[tuple[sp.Expr, bool, str]]:
        """A parameter an inverse ask finds (`find:`) lies in the range the file declares for it, in
        every variant: a ramp's angle found negative, or past its range, is no answer to give."""
        result = []
        for name, ask in self.problem.asks.items():
            parameter = self.problem.parameters.get(ask.zero_for) if ask.finds == "find" else None
            if parameter is None or parameter.range is None:
                continue
            found, (low, high) = self.expression(name), parameter.si_ends
            words = f"the {parameter.name} that {ask.path} needs lies outside its range [{parameter.range[0]}, " \
                    f"{parameter.range[1]}] {parameter.unit} at these parameters"
            result += [(found - low, False, words), (high - found, False, words)]
        return result

    def _magnitudes(self) -> list[tuple[sp.Expr, bool, str]]:
        """A magnitude whose sign `_magnitude` read off samples of the ranges (its formula without
        Abs) must not be negative at a variant's parameters: where it is, the sign changed between
        the samples and the formula does not hold there."""
        result = []
        for name, ask in self.problem.asks.items():
            if not ask.magnitude:  # a direction in words: its magnitude's sign proven, or |...| (answer_signs)
                continue
            try:
                magnitude = self.expression(name)
            except (InputError, KeyError, ValueError):  # no answer here (a mistaken set-up's friction with
                continue  # none to give it, derive.publishing.distractors): asking it says why; nothing to check
            if not magnitude.has(sp.Abs, sp.Piecewise):
                result.append((magnitude, False, f"{name}, a magnitude, comes out negative here: its formula holds "
                                                 "only where the sign it had at the samples of the ranges holds"))
        return result

    def _declared(self, answers: bool) -> list[tuple[sp.Expr, bool, str]]:
        """The problem file's own conditions that read answers (substituted), or those that do not."""
        result = []
        for declared in self.problem.conditions:
            if bool(declared.answers) == answers:
                values = {d: self.expression(name) for d, name in declared.answers.items()}
                result += [(difference.xreplace(values), strict, f"{declared.text} does not hold: {declared.because}")
                           for difference, strict in declared.parts]
        return result

    def _loaded_at_equilibrium(self, ask: str) -> list[tuple[sp.Expr, bool, str]]:
        """A small oscillation swings both ways about its equilibrium (the reference configuration,
        derive.mechanics.oscillation): a cord's tension or a contact's normal force zero there and
        changing to first order along the swing would change sign for half of every swing, so each
        must be positive there, strictly. One zero for every parameter is refused here; one that
        depends on them, per variant. A force that stays zero along the swing to first order (a
        floor under a block with no gravity) carries nothing and is left to the parts' own signs."""
        solved = self.at_reference("lagrange").raw
        scene = self.dynamics_scene
        first_order = self.oscillations["lagrange"].first_order
        result = []
        for sign in (sign for part in (*scene.constraints, *scene.loads) for sign in part.signs()):
            if _zero(sign.expression.xreplace(first_order)):
                continue
            force = tidy(sign.expression.xreplace(solved))
            if _zero(force):
                raise self.problem.error(f"ask.{ask}.of", f"{sign.unloaded} at the equilibrium: {sign.force} is 0 "
                                         "there, so a small oscillation about it would need it negative for half "
                                         "of every swing (every cord taut and every contact pressed there)")
            result.append((force, True, f"{sign.unloaded} at the equilibrium at these parameters: {sign.force} "
                                        "there is not positive, and a small oscillation needs it positive"))
        return result

    def _sign_conditions(self) -> list[tuple[sp.Expr, bool, str]]:
        """The signs the parts' forces must keep in the reference configuration at rest (a taut
        cord, a body pressing on its surface), and a grip that must hold where the file gives no
        mu_k to derive the slipping."""
        solved = self.at_reference("lagrange").raw
        scene = self.dynamics_scene
        result = [(sign.expression.xreplace(solved), False, sign.meaning)
                  for part in (*scene.constraints, *scene.loads) for sign in part.signs()]
        result += self._state_conditions()
        for part in scene.constraints:  # a grip with no coefficient: it still needs something to press on
            if isinstance(part, Contact) and part.rolling and not part.has_friction:
                forces = part.unknowns()
                self._presses(part, solved[forces["normal"]], solved[forces["friction"]])
        contact = friction.frictional(self.scene)
        if contact is not None:
            normal, grip = self._grip("lagrange")
            if contact.kinetic is None:
                result.append((friction.grip_margin(contact, normal, grip), False,
                               f"the {contact.body} slips: it needs mu_s >= {sp.sstr(friction.least_coefficient(normal, grip))}"
                               f" (give friction.kinetic: mu_k to derive the slipping)"))
            elif contact.static is not None:
                result.append((contact.static - contact.kinetic, False,
                               "mu_k > mu_s: kinetic friction cannot exceed static friction"))
        return result

    def violated(self, values: dict[sp.Symbol, sp.Expr]) -> str | None:
        """The meaning of the first condition these values break, or None (every sign certified:
        derive.numbers.numeric, the conditions evaluated together)."""
        return self.violations([values])[0]

    def violations(self, rows: list[dict[sp.Symbol, sp.Expr]]) -> list[str | None]:
        """violated() of each row of values, the rows evaluated together (a set's variants: one
        compiled program over them all)."""
        try:
            signs = numeric.evaluator(tuple(c for c, _, _ in self.conditions)).signs(rows)
        except ValueError:  # a later condition is not real where an earlier one breaks (an acos past 1
            # once a swing goes over the top): row by row, and in that row in order, one at a time
            if len(rows) > 1:
                return [self.violated(values) for values in rows]
            return [next((meaning for condition, strict, meaning in self.conditions
                          if self.violated_at(condition, strict, rows[0])), None)]
        return [next((meaning for (_, strict, meaning), sign in zip(self.conditions, row)
                      if sign is not None and (sign < 0 or strict and sign == 0)), None) for row in signs]

    def never_holds(self, values: dict[sp.Symbol, sp.Expr]) -> str | None:
        """The meaning of the first condition that the given values leave open and that every
        sample of the rest of the parameter ranges breaks (a wall facing the wrong way would have
        to pull in every variant), or None."""
        for condition, strict, meaning in self.conditions:
            if condition.free_symbols <= set(values):
                continue  # decided by the values (violated)
            points = [{**point, **values} for point in sample_points(self.problem, condition, count=20)]
            if all(self.violated_at(condition, strict, point) for point in points):
                return meaning
        return None

    @staticmethod
    def violated_at(condition: sp.Expr, strict: bool, values: dict) -> bool:
        """Whether these values break one condition (False where a symbol has no value; True where
        it is not a real number: a quantity that does not exist where an earlier condition breaks,
        the speed of a block static friction holds)."""
        try:
            value = numeric.evaluate(condition, values, 15)
        except ValueError:
            return True
        return value is not None and (float(value) < 0 or strict and float(value) == 0)


def _zero(expr: sp.Expr) -> bool:
    """Whether an expression is zero for every value of its symbols (as far as sympy can tell)."""
    return bool(expr.is_zero) or sp.simplify(expr) == 0
