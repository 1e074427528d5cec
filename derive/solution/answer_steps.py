"""The steps a Solution's worked solution shows, by route: a Solution's mixin.

Which routes a problem shows follows from what it asks: integrals for moments of inertia, the
kinematics of a path, an orbit by Binet's equation, a rolling coin by both routes, and for the
dynamics each route's derivation (derive.mechanics.derivation: its equations, then the solve for
the unknowns the asks need), with the regimes a grip decides, equilibria, periods, energy
ledgers and the sense each cord goes round. The steps are written on first use (derive.text.prose
writes them into sentences; derive.publishing.worksheets into the worked solutions).

>>> from derive.solution.answers import Solution
>>> from derive.language.problem import load
>>> steps = Solution(load("rod_endpoint")).steps()
>>> list(steps), steps["integration"][0].text
(['integration'], 'Integrate over the rod (mass from the same uniform density)')
"""
from __future__ import annotations

import sympy as sp

from derive import quantities
from derive.core.memo import kept
from derive.model import inertia
from derive.core import limits, units
from derive.solution.crosschecks import sample_points
from derive.mechanics import friction, orbits, rolling, rolling_coin
from derive.text.steps import Step
from derive.parts.cord import Cord
from derive.language.problem import Ask
from derive.core.expr import TIME
from derive.mechanics.steady_top import TOP_RATES
from derive.model.scene import DYNAMIC_KINDS, STATIC_KINDS


class AnswerSteps:
    """The worked solution's steps of a Solution (a mixin: it reads the Solution's derivations)."""

    @kept
    def steps(self) -> dict[str, list[Step]]:
        """The derivation steps a worked solution shows, by route."""
        with limits.time_limit(f"{self.problem.path}: the worked solution"):
            return self._steps()

    def _steps(self) -> dict[str, list[Step]]:
        kinds = {a.quantity.kind for a in self.problem.asks.values()}
        if kinds <= STATIC_KINDS:
            return {"integration": [self._static_step(a) for a in self.problem.asks.values()]}
        windings = self.winding_steps() if kinds & DYNAMIC_KINDS else []
        return {"how the cords run": windings, **self._route_steps(kinds)} if windings else self._route_steps(kinds)

    def _needed_unknowns(self, state: str | None = None) -> set[sp.Symbol]:
        """The accelerations and forces the quantities asked in a state (None: the placement at
        rest) are made of."""
        return {u for ask in self.problem.asks.values() if ask.state == state
                for u in quantities.KINDS[ask.quantity.kind].unknowns(self, ask)}

    def winding_steps(self) -> list[Step]:
        """The sense each cord goes round each circle its file names a `side:` of, where it touches
        it, and the sides that would take the other tangent (derive.parts.cord.Cord.windings): what
        a figure of the file's placement shows, said in words, since the side decides the runs."""
        return [Step(text) for part in (*self.scene.constraints, *self.scene.loads) if isinstance(part, Cord)
                for text in part.windings(self.coordinates, self._sample)]

    def _route_steps(self, kinds: set) -> dict[str, list[Step]]:
        if kinds == {"path"}:
            return {"kinematics": self._path_steps()}
        if kinds == {"orbit"}:
            return {"orbit": self._orbit_steps()}
        if kinds <= {"rolls_on_edge", *STATIC_KINDS}:
            upright = {a.quantity.target for a in self.problem.asks.values() if a.quantity.kind == "rolls_on_edge"
                       and a.quantity.detail.startswith("upright.")}
            return {f"{name}, by {route.replace('_', '–')}": rolling_coin.steps(
                *self.rolling_coin(name), coin.tilt, coin.circle, route, name in upright)
                for name, coin in self.scene.rolls_on_edge.items() for route in ("lagrange", "newton_euler")}
        if kinds == {"free_rotation"}:
            return self._free_rotation_steps()
        if {(a.quantity.kind, a.quantity.detail) for a in self.problem.asks.values()} <= {("pivot_point", d) for d in TOP_RATES}:
            return self._steady_precession_steps()
        if kinds == {"angular_impulse"}:
            return self._angular_impulse_steps()
        if kinds == {"rolling"}:
            (body,) = {a.quantity.target for a in self.problem.asks.values()}
            return {f"by the {route}": list(rolling.rolling(self.scene, body, route)[1]) for route in rolling.ROUTES}
        needed = self._needed_unknowns()
        # The general equations only when an asked quantity is read from them (a release height
        # needs the normal force at one point of the loop, shown in its own steps).
        rest = self.coordinates.at_rest_in_reference()
        result = {route: [*d.steps, d.solving_step([u for u in d.unknowns if u in needed], rest,
                                                    "in the reference configuration, at rest")] if needed else []
                  for route, d in self.derivations.items()}
        if needed and len(self.regimes) > 1:
            result.update(self._regime_steps(needed, rest))
        self._state_steps(result)
        by_kind: dict[str, list[Ask]] = {}
        for ask in self.problem.asks.values():
            by_kind.setdefault(ask.quantity.kind, []).append(ask)
        for kind in quantities.KINDS.values():  # an equilibrium's balance, a period's integral, in KINDS' order
            if kind.kind in by_kind:
                for route in result:
                    result[route] += kind.route_steps(self, by_kind[kind.kind], route)
        for body, balance in self.energy_balances.items():
            result[f"energy of the {body}"] = list(balance.steps)
        result.update(self._quantity_sections())
        for ask in self.problem.asks.values():
            result.update(quantities.KINDS[ask.quantity.kind].sections(self, ask))
        return {route: steps for route, steps in result.items() if steps}

    def _quantity_sections(self) -> dict[str, list[Step]]:
        """Each ask of a quantity of derive.quantities, its own section (headed by what it is, or by the
        ask's meaning where two describe the same quantity); an inverse ask's ends solving for its parameter."""
        result = {}
        for ask in self.problem.asks.values():
            kind = quantities.KINDS[ask.quantity.kind]
            if not kind.own_section:
                continue
            title = quantities.describe_capitalized(kind.describe(ask))
            steps = kind.steps(self, ask)
            if ask.zero_for:
                title = quantities.describe_capitalized(ask.meaning)
                steps.append(self._solved_for(ask))
            result[title if title not in result else quantities.describe_capitalized(ask.meaning)] = steps
        return result

    def _solved_for(self, ask: Ask) -> Step:
        """An inverse ask's last step: the parameter at which the quantity takes the value asked."""
        parameter = self.problem.parameters[ask.zero_for]
        value = units.in_unit(self.expressions[ask.name], ask.unit)
        kind = quantities.KINDS[ask.quantity.kind]
        target = units.declared_symbols(units.in_unit(ask.equals, kind.unit), self.problem.symbol_units)
        quantity = sp.Symbol(kind.symbol_for(ask))
        return Step(f"Where it takes the value asked, solved for {parameter.name}",
                    (sp.Eq(quantity, target), sp.Eq(parameter.symbol, value)))

    def _regime_steps(self, needed: set, rest: dict) -> dict[str, list[Step]]:
        """The grip that decides the regime, and each slipping regime that some parameters of the
        ranges reach, derived by both routes."""
        contact = friction.frictional(self.scene)
        normal, grip = self._grip("lagrange")
        least = friction.least_coefficient(normal, grip)
        held = self.regimes[0].name
        result = {f"which regime: {held} or slips": [Step(
            f"Held without slip, the {contact.body} needs the friction f and the normal force N found above; it "
            f"{held} while static friction can supply f, that is while the coefficient of static friction is at least",
            (sp.Eq(sp.Symbol("mu_min"), least),)),
            Step("Otherwise it slips, and kinetic friction, N times the coefficient of kinetic friction, acts the way f "
                 "would: against the slip")]}
        ratio = grip / normal
        points = sample_points(self.problem, ratio + friction.static_coefficient(contact), count=20)
        for index, regime in enumerate(self.regimes[1:], start=1):
            if not any(self.regime_conditions()[0].xreplace(p) == sp.false
                       and bool(ratio.xreplace(p) > 0) == (regime.direction > 0) for p in points):
                continue  # not reached inside the ranges' samples; its answers remain in the Piecewise
            way = "+" if regime.direction > 0 else "-"
            for route, d in self._regime_derivations(index).items():
                result[f"{route.replace('_', '-')}, where the {contact.body} slips (friction along {way}t)"] = [
                    *d.steps, d.solving_step([u for u in d.unknowns if u in needed], rest,
                                             "in the reference configuration, at rest")]
        return result

    def _orbit_steps(self) -> list[Step]:
        orbit = self.scene.orbit
        l = orbit.angular_momentum if orbit.angular_momentum is not None else sp.Symbol("l", positive=True)
        f = orbits.f
        rr = sp.Symbol("rddot")
        conic, e = orbits.conic(orbit.GM, l)
        steps = [
            Step("Radial equation (Lagrange in polar coordinates; the angular momentum per unit mass, l, is conserved)",
                 (sp.Eq(rr, orbits.radial_acceleration(orbit.GM, l, "lagrange")),)),
            Step("Effective potential per unit mass", (sp.Eq(sp.Symbol("U_eff"), orbits.effective_potential(orbit.GM, l)),)),
            Step("The orbit, from the radial equation written in the reciprocal of the radius (Binet's equation)",
                 (sp.Eq(sp.Function("r")(f), conic),)),
        ]
        steps += [Step(a.meaning, (sp.Eq(sp.Symbol(n), self.expressions[n]),)) for n, a in self.problem.asks.items()]
        return steps

    def _path_steps(self) -> list[Step]:
        steps = []
        for name in sorted({a.quantity.target for a in self.problem.asks.values()}):
            body = self.scene.bodies[name]
            x, y = sp.symbols("x y")
            position = body.path.position
            steps.append(Step(f"Position of the {name} and its derivatives", (
                sp.Eq(x, position[0]), sp.Eq(y, position[1]),
                sp.Eq(sp.Derivative(x, TIME), position[0].diff(TIME)),
                sp.Eq(sp.Derivative(y, TIME), position[1].diff(TIME)))))
        for ask in self.problem.asks.values():
            steps.append(Step(ask.meaning, (sp.Eq(sp.Symbol(ask.name), self.expressions[ask.name]),)))
        return steps

    def _static_step(self, ask: Ask) -> Step:
        if ask.quantity.kind != "inertia" or ask.shift is not None or not isinstance(ask.quantity.detail, str):
            return Step(ask.meaning, (sp.Eq(sp.Symbol(ask.name), self.expressions[ask.name]),))
        body = self.scene.bodies[ask.quantity.target]
        if body.density is not None:
            return Step(f"Integrate the density over the {body.shape}",
                        (sp.Eq(sp.Symbol("rho"), body.density), sp.Eq(sp.Symbol(ask.name), self.expressions[ask.name])))
        derived = inertia.moment_of_inertia(body.shape, ask.quantity.detail)
        shape = inertia.SHAPES[body.shape]
        mapping = {inertia.M: body.mass, **{shape.sizes[k]: v for k, v in body.sizes.items()}}
        return Step(
            f"Integrate over the {body.shape} (mass from the same uniform density)",
            (
                sp.Eq(body.mass, derived.mass_integral.xreplace(mapping), evaluate=False),  # the body's own mass
                sp.Eq(sp.Symbol(ask.name), derived.integral.xreplace(mapping)),  # the ask's name, as the results
                sp.Eq(sp.Symbol(ask.name), derived.I.xreplace(mapping)),
            ),
        )

