"""Answers about bodies in 3D, as a part of `derive.solution.answers.Solution`: a body in bearings, on a
fixed point (under gravity, or at its center of mass under a couple for a time), rolling on its
edge, or turning freely. Each reads the body's tensor or moments from the scene and gives the
asked quantity by one route of its module in derive.mechanics (bearings, fixed_point,
angular_impulse, rolling_coin, free_rotation); the cross-checks compare the routes.

>>> from derive.solution.answers import Solution
>>> from derive.language.problem import load
>>> Solution(load("top_precession")).standing_top("top")[3]
Rcm
"""
from __future__ import annotations

import sympy as sp

from derive.mechanics import angular_impulse, bearings, fixed_point, free_rotation, rolling_coin, steady_top
from derive.text.steps import Step
from derive.core.tidying import tidy
from derive.parts.torque import Torque
from derive.model.scene import Quantity
from derive.model.solid_scene import own_axis


class SolidAnswers:
    """The 3D answers of a Solution (a mixin: `self.scene`, `self.problem`, `self._sample` are the
    Solution's)."""

    def bearing_motion(self, name: str, route: str) -> dict:
        """L, the bearings' torque and the kinetic energy of a body in bearings by one route
        (derive.mechanics.bearings.ROUTES)."""
        body, held = self.scene.bodies[name], self.scene.bearings[name]
        return bearings.motion(self.bearing_tensor(name), held.rate, held.tilt, held.roll, own_axis(body.shape), route,
                               body.mass, held.through, self.shaft_gravity(name), held.apart, held.thrust, held.turned)

    def bearing_tensor(self, name: str) -> sp.ImmutableMatrix:
        """The tensor about the center of mass, in its own frame, of a body in bearings (a custom
        body's from its moments, its own axis z)."""
        body, held = self.scene.bodies[name], self.scene.bearings[name]
        if held.inertia is not None:
            return sp.ImmutableMatrix(sp.diag(held.inertia[0], held.inertia[0], held.inertia[1]))
        parts = body.composite.parts if body.composite is not None else None
        return bearings.body_tensor(body.shape, body.mass, body.sizes, parts)

    def shaft_gravity(self, name: str) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
        """g's vector in the frame of the shaft of a body in bearings (the shaft is N.z, inclined by
        `incline` above the horizontal)."""
        held = self.scene.bearings[name]
        g = self.scene.gravity.g if self.scene.gravity is not None else sp.Integer(0)
        return (sp.Integer(0), -g * sp.cos(held.incline), -g * sp.sin(held.incline))

    def _bearings(self, q: Quantity, route: str) -> sp.Expr:
        held = self.scene.bearings[q.target]
        return bearings.quantity(self.bearing_motion(q.target, route), q.detail, held.tilt, held.apart)

    def standing_top(self, name: str) -> tuple:
        """(tensor about the center of mass in the top frame, mass, g, l) of a body on a fixed point
        (derive.mechanics.fixed_point)."""
        body, point = self.scene.bodies[name], self.scene.pivot_points[name]
        if point.inertia is not None:  # a custom body: its symmetry axis is its own z
            tensor = sp.diag(point.inertia[0], point.inertia[0], point.inertia[1])
        else:
            parts = body.composite.parts if body.composite is not None else None
            tensor = bearings.body_tensor(body.shape, body.mass, body.sizes, parts)
        standing, distance = fixed_point.standing(tensor, point.offset)
        return standing, body.mass, self.scene.gravity.g, distance

    def _pivot_point(self, q: Quantity, route: str = "lagrange") -> sp.Expr:
        """A steady motion of a body on a fixed point by one route; refused for a body that is not
        a symmetric top about the point."""
        point, top = self.scene.pivot_points[q.target], self.standing_top(q.target)
        try:
            if q.detail == "sleeping.min_spin":
                return fixed_point.min_spin(*top, route)
            if q.detail.startswith("nutation."):
                exact = fixed_point.nutation_frequency(*top, point.spin, point.tilt, route)
            else:
                slow, fast = fixed_point.roots(*top, point.spin, point.tilt, route)
                exact = fast if q.detail == "precession.fast" else slow
                if exact is None:
                    raise self.problem.error(f"scene.bodies.{q.target}.pivot_point.tilt", "a horizontal axis has one "
                                             "steady precession, the slow one: the fast one runs off to infinity")
        except fixed_point.NotSymmetric as error:
            raise self.problem.error(f"scene.bodies.{q.target}", f"{q.target}.{q.detail}: {error}") from None
        return fixed_point.fast_top(exact, point.spin, point.tilt) if q.detail.endswith("fast_top") else exact

    def conical_squared(self, name: str, route: str) -> sp.Expr:
        """Omega^2 of the steady conical motion of a body on a fixed point, by one route
        (derive.mechanics.fixed_point; refused for a body that is not symmetric about its axis)."""
        try:
            return fixed_point.conical_squared(*self.standing_top(name), self.scene.pivot_points[name].tilt, route)
        except fixed_point.NotSymmetric as error:
            raise self.problem.error(f"scene.bodies.{name}", f"{name}.conical.rate: {error}") from None

    def impulse_turn(self, name: str) -> tuple:
        """((I1, I3), spin, the axis n, the couple's direction a, tau, dt) of a body on a fixed point
        at its center of mass under a couple for a time (derive.mechanics.angular_impulse): the axis
        leans by the tilt from the ground's z toward its x; refused for a body whose moments about
        its own axis are not those of a symmetric body."""
        body, point = self.scene.bodies[name], self.scene.pivot_points[name]
        if point.inertia is not None:
            moments = point.inertia
        else:
            parts = body.composite.parts if body.composite is not None else None
            tensor = bearings.body_tensor(body.shape, body.mass, body.sizes, parts)
            k = "xyz".index(own_axis(body.shape))
            across = [i for i in range(3) if i != k]
            if any(tidy(tensor[i, j]) != 0 for i in range(3) for j in range(i)) \
                    or tidy(tensor[across[0], across[0]] - tensor[across[1], across[1]]) != 0:
                raise self.problem.error(f"scene.bodies.{name}", f"the moments about the center are {sp.sstr(tensor)}: "
                                         "a couple's turn is derived for a body symmetric about its own axis")
            moments = (tensor[across[0], across[0]], tensor[k, k])
            if tidy(moments[1]) == 0:
                raise self.problem.error(f"scene.bodies.{name}", "a thin rod has no moment about its length: its spin "
                                                                 "there carries no angular momentum")
        (couple,) = (p for p in self.scene.loads if isinstance(p, Torque) and p.body == name)
        axis = (sp.sin(point.tilt), sp.Integer(0), sp.cos(point.tilt))
        return moments, point.spin, axis, couple.axis, couple.torque, couple.duration

    def _angular_impulse(self, q: Quantity) -> sp.Expr:
        """The angle L turns through by the angular impulse, its small-angle limit, or the axle's turn."""
        moments, spin, axis, couple, torque, duration = self.impulse_turn(q.target)
        if q.detail == "turn.axle":
            return angular_impulse.axle_turn(moments, spin, axis, couple, torque, duration)
        route = angular_impulse.small_angle if q.detail == "turn.small_angle" else angular_impulse.momentum_turn
        return route(moments[1], spin, axis, couple, torque, duration)

    def _angular_impulse_steps(self) -> dict[str, list[Step]]:
        """The angular impulse route's steps (L before, the impulse, the angle), and the Euler route's
        equations (integrated numerically by the check)."""
        result = {}
        for name in {a.quantity.target for a in self.problem.asks.values()}:  # every ask is an angular impulse's
            (I1, I3), spin, _, _, torque, duration = self.impulse_turn(name)
            before, impulse = sp.Symbol("L_0"), sp.Symbol("J")
            asked = tuple(sp.Eq(sp.Symbol(n), self.expressions[n], evaluate=False) for n, a in self.problem.asks.items()
                          if a.quantity.target == name)
            axle = any(a.quantity.detail == "turn.axle" for a in self.problem.asks.values())
            result[f"the {name}, by the angular impulse"] = [
                Step(f"The {name} spins about its own axis with no turning across it, so its angular momentum about "
                     "the fixed point lies along the axis", (sp.Eq(before, I3 * spin),)),
                Step("About a fixed point the rate of change of the angular momentum is the torque: the couple, "
                     "about a direction fixed in the ground, adds its angular impulse along that direction over the "
                     "time it acts", (sp.Eq(impulse, torque * duration),), role="equations"),
                Step("The angular momentum turns through the angle between its values before and after the impulse "
                     "is added; the small-angle limit is the leading term of that angle in the impulse"
                     + ("; the axle nods about the angular momentum, at its size over the moment across the axis, "
                        "while the couple makes it grow, and is integrated numerically" if axle else ""),
                     asked, role="solve")]
            rates, turning = free_rotation.euler_rates((I1, I1, I3), sp.symbols("tau_1:4"))
            plain = dict(zip(turning, sp.symbols("omega_1:4")))
            result[f"the {name}, by Euler's equations"] = [Step(
                "Euler's equations in the body's axes, with the couple's components along them, integrated with "
                "the body's orientation over the time the couple acts (checked against the angular impulse)",
                tuple(sp.Eq(sp.Symbol(f"omegadot_{k}"), r.xreplace(plain))
                      for k, r in zip((1, 2, 3), rates)), role="equations")]
        return result

    def rolling_coin(self, name: str) -> tuple:
        """(I1, I3, mass, g, radius) of a body rolling on its edge (derive.mechanics.rolling_coin): a
        custom body's moments as given, a shape's from its tensor (the symmetry axis its own z)."""
        coin, body = self.scene.rolls_on_edge[name], self.scene.bodies[name]
        tensor = (sp.diag(coin.inertia[0], coin.inertia[0], coin.inertia[1]) if coin.inertia is not None
                  else bearings.body_tensor(body.shape, body.mass, body.sizes))
        return tensor[0, 0], tensor[2, 2], body.mass, self.scene.gravity.g, coin.radius

    def _rolls_on_edge(self, q: Quantity, route: str = "lagrange") -> sp.Expr:
        """A steady motion on a circle or upright rolling's least speed or spin, by one route."""
        coin, body = self.scene.rolls_on_edge[q.target], self.rolling_coin(q.target)
        group, _, what = q.detail.partition(".")
        if group == "upright":
            speed = rolling_coin.min_speed(*body, route)
            return speed if what == "min_speed" else tidy(speed / coin.radius)
        return rolling_coin.steady(*body, coin.tilt, coin.circle, route)[what]
    def free_moments(self, name: str) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
        """The principal moments about the center of mass along the own axes of a body in free
        rotation (derive.mechanics.free_rotation); refused naming the body where they do not fit."""
        body, free = self.scene.bodies[name], self.scene.free_rotations[name]
        if free.inertia is not None:  # a custom body's principal moments
            tensor = sp.diag(*free.inertia)
        else:
            parts = body.composite.parts if body.composite is not None else None
            tensor = bearings.body_tensor(body.shape, body.mass, body.sizes, parts)
        try:
            return free_rotation.principal_moments(tensor)
        except free_rotation.NotPrincipal as error:
            raise self.problem.limit(f"find the principal axes of the {name}: {error}; place its parts so that "
                                     "they are") from None
        except free_rotation.NotModelled as error:
            raise self.problem.error(f"scene.bodies.{name}", str(error)) from None

    def free_axis(self, name: str, rank: str) -> int:
        """The own axis (0, 1, 2) of least, intermediate or greatest moment, ordered at the middle
        of the ranges (`conditions` keeps the order in every variant)."""
        moments = self.free_moments(name)
        try:
            return free_rotation.ranked(moments, [self._sample(m) for m in moments])[free_rotation.RANKS.index(rank)]
        except free_rotation.NotModelled as error:
            raise self.problem.error(f"scene.bodies.{name}", str(error)) from None

    def _free_rotation(self, q: Quantity, route: str = "newton_euler") -> sp.Expr:
        """A free precession or a steady rotation's wobble or growth rate by one route."""
        free, moments = self.scene.free_rotations[q.target], self.free_moments(q.target)
        if q.detail in free_rotation.SYMMETRIC:
            try:
                I1, I3, _ = free_rotation.symmetric(moments)
            except free_rotation.NotModelled as error:
                raise self.problem.error(f"scene.bodies.{q.target}", f"{q.target}.{q.detail}: {error}") from None
            return free_rotation.precession((I1, I3), free.spin, free.across, q.detail, route)
        _, rank, kind = q.detail.split(".")
        squared = free_rotation.exponent_squared(moments, self.free_axis(q.target, rank), free.spin, route)
        return tidy(sp.sqrt(squared if kind == "growth_rate" else -squared))

    def _free_rotation_steps(self) -> dict[str, list[Step]]:
        """Each route's equations for the bodies in free rotation, then what it gives for each ask."""
        result = {}
        for route, title in zip(free_rotation.ROUTES, ("by Euler's equations", "by Lagrange's equations")):
            steps = []
            for name in self.scene.free_rotations:
                details = {a.quantity.detail for a in self.problem.asks.values() if a.quantity.target == name}
                orders = tuple(order for order, asked in (("ZXZ", details & set(free_rotation.SYMMETRIC)),
                                                          ("ZXY", details - set(free_rotation.SYMMETRIC))) if asked)
                steps += free_rotation.steps(self.free_moments(name), route, orders)
            asked = tuple(sp.Eq(sp.Symbol(n), self._free_rotation(a.quantity, route), evaluate=False)
                          for n, a in self.problem.asks.items())  # every ask is a free rotation's
            result[title] = [*steps, Step("Solved for what is asked", asked, role="solve")]
        return result

    def _steady_precession_steps(self) -> dict[str, list[Step]]:
        """The proof of a top's steady precessions (the student's route is tau = Omega x L,
        derive.mechanics.steady_top): each route's equation for the tilt (Lagrange's in the Euler angles,
        Euler's about the fixed point) with the tilt held and the axis turning at Omega, divided by
        sin(theta): the top's condition, the same by both. None for a level axle (no division by cos)."""
        result = {}
        for name in sorted({a.quantity.target for a in self.problem.asks.values()}):
            point, top = self.scene.pivot_points[name], self.standing_top(name)
            if sp.cos(point.tilt) == 0:
                continue
            I1 = fixed_point.moments(top[0], top[1], top[3])[0]
            names = steady_top.as_a_textbook_writes(I1, point.tilt, {p.symbol for p in self.problem.parameters.values()})
            for route in ("lagrange", "newton_euler"):
                condition = fixed_point.precession_condition(*top, point.spin, point.tilt, route)
                shown = tidy(sp.expand((condition * I1 * sp.cos(point.tilt)).xreplace(names)))
                result.setdefault(route, []).append(Step(
                    f"The {name}'s equation of motion for its tilt, in the Euler angles, with the tilt held, the axis "
                    "turning about the vertical at the rate Omega and the spin omega, divided by the sine of the tilt",
                    (sp.Eq(shown, 0),), role="equations"))
        return result

    def top_conditions(self, name: str) -> list[tuple[sp.Expr, bool, str]]:
        """A top asked a steady motion is spun fast enough to precess steadily, in every variant
        (derive.quantities.pivot_point)."""
        point, (tensor, mass, g, distance) = self.scene.pivot_points[name], self.standing_top(name)
        try:
            I1, I3 = fixed_point.moments(tensor, mass, distance)
        except fixed_point.NotSymmetric as error:
            raise self.problem.error(f"scene.bodies.{name}", f"a steady motion is asked: {error}") from None
        return [(tidy(I3**2 * point.spin**2 - 4 * I1 * mass * g * distance * sp.cos(point.tilt)), False,
                 f"no steady precession of the {name}: the spin is too slow (I3^2 w^2 < 4 I1 m g l cos(theta))")]

    def free_order_conditions(self, name: str) -> list[tuple[sp.Expr, bool, str]]:
        """A free body's principal moments keep the order of the middle of the ranges, in every variant
        (derive.quantities.free_rotation)."""
        moments = self.free_moments(name)
        order = [self.free_axis(name, rank) for rank in free_rotation.RANKS]
        return [(tidy(moments[high] - moments[low]), True, f"the {name}'s principal moments change order "
                 f"here ({'xyz'[low]} and {'xyz'[high]}): the axis of each rank is chosen at the middle of "
                 "the ranges") for low, high in zip(order, order[1:])]
