"""The cross-checks of the 3D answers, as a part of `derive.solution.answers.Solution` (as
`derive.solution.solid_answers` holds the answers): a couple's angular impulse against Euler's
equations integrated, and each 3D slice's routes against each other (bearings, a fixed point,
rolling on an edge, free rotation), each of the asks `names` of its kind. Each kind's module of
derive.quantities calls its own (`QuantityKind.checks`).
"""
from __future__ import annotations

from dataclasses import replace

import sympy as sp

from derive.numbers.agreement import METHODS, agree
from derive.solution.crosschecks import Check, CheckFailure, sample_points
from derive.mechanics import angular_impulse, bearings, fixed_point, free_rotation, rolling_coin
from derive.core.tidying import tidy


class SolidChecks:
    """The 3D checks of a Solution (a mixin: the Solution's scene, problem and answers)."""

    def angular_impulse_check(self, names: list[str]) -> Check:
        """A body on a fixed point at its center of mass under a couple for a time: Euler's equations
        integrated with the orientation (angular_impulse.euler) at the middle of the ranges and four
        random points give the angle L turns through as the angular impulse does, and the axle's turn
        as its integration (n' = L x n/I1); the small-angle limit is the slope of the turn at zero
        impulse (the turns at a couple s = 10^-3 and 2 s times as large, extrapolated), and its relative
        error to the exact turn is reported. Relative tolerances: 1e-8, and 1e-5 for the limit."""
        notes, worst, scale = [], 0.0, 1e-3
        for ask_name in names:
            ask = self.problem.asks[ask_name]
            moments, spin, axis, couple, torque, duration = self.impulse_turn(ask.quantity.target)
            inputs = sp.Tuple(sp.Tuple(*moments), spin, sp.Tuple(*axis), sp.Tuple(*couple), torque, duration)
            for point in sample_points(self.problem, sp.Tuple(inputs, self.expressions[ask_name]), count=5):
                numbers = [tuple(c.xreplace(point) for c in x) if isinstance(x, sp.Tuple) else x.xreplace(point)
                           for x in inputs]
                limit = ask.quantity.detail == "turn.small_angle"
                momentum, axle = angular_impulse.euler(*numbers)
                found = axle if ask.quantity.detail == "turn.axle" else momentum
                if limit:  # the slope at zero impulse, extrapolated from s and 2 s (Richardson: error ~ s^2)
                    slopes = [angular_impulse.euler(*numbers[:4], numbers[4] * k * scale, numbers[5])[0] / (k * scale)
                              for k in (1, 2)]
                    found = 2 * slopes[0] - slopes[1]
                derived = float(sp.N(self.expressions[ask_name].xreplace(point), 20))
                error = abs(found / derived - 1)
                if error > (1e-5 if limit else 1e-8):
                    raise CheckFailure(f"{self.problem.id}: {ask_name} is {derived} derived, {found} by Euler's "
                                       f"equations integrated")
                worst = max(worst, error)
            if ask.exact is not None and limit:
                error = tidy(self.expressions[ask_name] / self.expressions[ask.exact] - 1)
                notes.append(f"{ask_name} / {ask.exact} - 1 = {sp.sstr(error)}")
        return Check("impulse_vs_euler", True, "numeric",
                     "; ".join([f"Euler's equations integrated agree to {worst:.1e} at 5 points", *notes]),
                     "The turn from the couple's angular impulse about the fixed point agrees with Euler's equations "
                     "integrated over the time the couple acts.")

    def bearings_checks(self, names: list[str]) -> list[Check]:
        """For every body in bearings, Newton–Euler's and Lagrange's L, bearing torque, kinetic
        energy, the supports' force, the drive's couple and each bearing's force agree component by
        component, and each asked quantity by both; a uniform shape's L again by integrating
        r x (omega x r) dm."""
        integrated, methods = [], set()

        def differ(a, b) -> bool:
            methods.add(agree(a, b))
            return None in methods

        for name, held in self.scene.bearings.items():
            found = {route: self.bearing_motion(name, route) for route in bearings.ROUTES}
            for key in found["newton_euler"]:  # L, the torque, T, the supports' force, the drive, each bearing's
                pairs = zip(*(sp.Matrix([found[r][key]]) for r in bearings.ROUTES))
                if any(differ(a, b) for a, b in pairs):
                    raise CheckFailure(f"{self.problem.id}: the {name}'s {key.replace('_', ' ')} is "
                                       f"{found['newton_euler'][key]} by Newton–Euler, {found['lagrange'][key]} "
                                       "by Lagrange")
            body = self.scene.bodies[name]
            if body.composite is None and held.inertia is None:  # a uniform shape's elements
                by_integral = bearings.angular_momentum_by_integral(body.shape, body.mass, tuple(body.sizes.items()),
                                                                    held.rate, held.tilt, held.roll, held.turned)
                if any(differ(a, b) for a, b in zip(by_integral, found["newton_euler"]["angular_momentum"])):
                    raise CheckFailure(f"{self.problem.id}: the {name}'s L is {list(by_integral)} integrated, "
                                       f"{list(found['newton_euler']['angular_momentum'])} from the tensor")
                integrated.append(name)
        for ask_name in names:
            if differ(*(self._bearings(self.problem.asks[ask_name].quantity, r) for r in bearings.ROUTES)):
                raise CheckFailure(f"{self.problem.id}: Lagrange and Newton–Euler disagree on {ask_name}")
        method = " or ".join(m for m in METHODS if m in methods)
        result = [Check("lagrange_vs_newton_euler", True, method,
                        "angular momentum, bearing torque, kinetic energy and the bearings' forces agree, every "
                        "component",
                        "Lagrange's method, with the bearings' forces and torques as multipliers, and dL/dt = torque "
                        "with F = m a_cm give the same angular momentum, bearing torque, kinetic energy and forces.")]
        if integrated:
            result.append(Check("angular_momentum_by_integral", True, method,
                                f"L of {', '.join(integrated)} agrees, every component",
                                "Integrating r × (ω × r) over the body's mass gives the same angular momentum as "
                                "the inertia tensor."))
        return result

    def free_rotation_check(self, names: list[str]) -> Check:
        """Every asked free precession, wobble and growth rate by Euler's equations and by
        Lagrange's equations in Euler angles (derive.mechanics.free_rotation)."""
        methods = set()
        for ask_name in names:
            found = [self._free_rotation(self.problem.asks[ask_name].quantity, route) for route in free_rotation.ROUTES]
            methods.add(agree(*found))
            if None in methods:
                raise CheckFailure(f"{self.problem.id}: {ask_name} is {found[0]} by Euler's equations, "
                                   f"{found[1]} by Lagrange's")
        return Check("lagrange_vs_newton_euler", True, " or ".join(m for m in METHODS if m in methods),
                     "free precession, wobble and growth rates agree (Euler's equations, Lagrange in Euler angles)",
                     "Euler's equations with no torque and Lagrange's equations in Euler angles give the same "
                     "precession rates, angles and rates of the small motions about a steady rotation.")

    def pivot_point_check(self, names: list[str]) -> Check:
        """For every body on a fixed point asked (a top's motion, a steady cone's rate), the equations of
        motion by Lagrange, Newton–Euler (Euler's equations about the point) and Kane agree term by term,
        and each asked quantity by Lagrange and Newton–Euler; the fast-top rate's relative error against
        the slow root is reported."""
        methods, notes = {"symbolic"}, []
        for name in {self.problem.asks[n].quantity.target for n in names}:
            top = self.standing_top(name)
            found = {route: fixed_point.equations(*top, route) for route in fixed_point.ROUTES}
            for route in fixed_point.ROUTES[1:]:
                if any(tidy(a - b) != 0 for a, b in zip(found["lagrange"], found[route])):
                    raise CheckFailure(f"{self.problem.id}: the {name}'s equations of motion are "
                                       f"{list(found['lagrange'])} by Lagrange, {list(found[route])} by {route}")
        for ask_name in names:
            ask = self.problem.asks[ask_name]
            if ask.quantity.kind == "conical":  # a steady cone's rate, derive.quantities.conical
                methods.add(agree(*(self.conical_squared(ask.quantity.target, r) for r in ("lagrange", "newton_euler"))))
            else:
                methods.add(agree(*(self._pivot_point(ask.quantity, r) for r in ("lagrange", "newton_euler"))))
            if None in methods:
                raise CheckFailure(f"{self.problem.id}: Lagrange and Newton–Euler disagree on {ask_name}")
            if ask.quantity.detail == "precession.fast_top":
                slow = self._pivot_point(replace(ask.quantity, detail="precession.slow"))
                error = tidy(self.expressions[ask_name] / slow - 1)
                notes.append(f"fast-top rate / slow root - 1 = {sp.sstr(error)}")
        return Check("lagrange_vs_newton_euler", True, " or ".join(m for m in METHODS if m in methods),
                     "; ".join(["equations of motion agree (Lagrange, Newton–Euler, Kane)", *notes]),
                     "Lagrange's method, Euler's equations about the fixed point and Kane's method give the same "
                     "equations of motion, and the same steady motions.")

    def rolls_on_edge_check(self, names: list[str]) -> Check:
        """For every body rolling on its edge that is asked, Lagrange's method and Kane's with the
        rolling constraints and Newton–Euler about the center of mass agree term by term, each asked
        quantity by all three, and in a steady motion the contact force along the heading is zero."""
        methods = {"symbolic"}
        routes = rolling_coin.ROUTES
        for name in {self.problem.asks[n].quantity.target for n in names}:
            coin = self.scene.rolls_on_edge[name]
            found = {route: rolling_coin.motion(*self.rolling_coin(name), route)["equations"] for route in routes}
            for route in routes[1:]:
                if any(tidy(a - b) != 0 for a, b in zip(found["lagrange"], found[route])):
                    raise CheckFailure(f"{self.problem.id}: the {name}'s equations of motion are "
                                       f"{list(found['lagrange'])} by Lagrange, {list(found[route])} by {route}")
            if coin.tilt is not None:
                along = [rolling_coin.steady(*self.rolling_coin(name), coin.tilt, coin.circle, r)["tangential"]
                         for r in routes]
                if any(a != 0 for a in along):
                    raise CheckFailure(f"{self.problem.id}: the {name}'s steady motion needs a force along its "
                                       f"heading: {along}")
        for ask_name in names:
            first, *others = (self._rolls_on_edge(self.problem.asks[ask_name].quantity, r) for r in routes)
            methods.update(agree(first, other) for other in others)
            if None in methods:
                raise CheckFailure(f"{self.problem.id}: Lagrange, Kane and Newton–Euler disagree on {ask_name}")
        return Check("lagrange_vs_newton_euler", True, " or ".join(m for m in METHODS if m in methods),
                     "equations of motion agree (Lagrange and Kane with the rolling constraints, Newton–Euler about "
                     "the center of mass), and every asked quantity",
                     "Lagrange's method and Kane's with the rolling constraints, and Newton–Euler about the center of "
                     "mass with the contact force from Newton's law, give the same equations of motion, steady "
                     "motion and stability.")
