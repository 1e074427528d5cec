"""Events: a point mass sticking to or bouncing off a body, and a body turning on a shared axle.

An impact is solved twice. By conservation: the total momentum in the directions no pin acts,
and the angular momentum about the pin (or the origin), with the bodies moving rigidly
together afterwards (sticking), or with the normal relative velocity reversed and scaled by
the coefficient of restitution and the tangential velocity of the point unchanged (a smooth
bounce). By impulse and momentum per body (Newton–Euler): the contact
impulse and the pin impulses are unknowns, m dv = J and I d(omega) = r x J for each body.
An internal turn (Elroy's beanie) is solved by conservation of angular momentum about the
axle, and by torque balance with an unknown internal torque, integrated from rest.

>>> import sympy as sp
>>> from derive.parts.pin import Pin
>>> from derive.scene import Body, Motion, Scene, Stick
>>> m, M, R, I, v = sp.symbols("m M R I v", positive=True)
>>> scene = Scene({"disk": Body("disk", "custom", M, {}, I), "bug": Body("bug", "point", m, {})},
...               (Pin("axle", "disk", (0, 0)),), motions={"bug": Motion((R, 0), (0, v))},
...               events=(Stick("stop", "bug", "disk"),))
>>> by_conservation(scene).after["disk"][2]
R*m*v/(I + R**2*m)
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.mechanics.derivation import Step, solve_linear, tidy
from derive.parts.pin import Pin
from derive.scene import Bounce, InternalTurn, Motion, Scene, Stick


class EventError(ValueError):
    """The event is not one this module can solve."""


@dataclass(frozen=True)
class EventResult:
    """Velocities (vx, vy, omega) of each body after the event, by one route."""

    route: str
    after: dict[str, tuple[sp.Expr, sp.Expr, sp.Expr]]
    turn: sp.Expr | None
    steps: tuple[Step, ...]


def _cross(r, v) -> sp.Expr:
    return r[0] * v[1] - r[1] * v[0]


class _Event:
    """The bodies' states before, unknown velocities after, and the kinematics of sticking."""

    def __init__(self, scene: Scene):
        impacts = [e for e in scene.events if isinstance(e, (Stick, Bounce))]
        if len(impacts) != 1 or len(scene.events) != 1:
            raise EventError("one impact at a time")
        self.scene, self.impact = scene, impacts[0]
        if scene.bodies[self.impact.body].rotates:
            raise EventError("the striking body is a point mass")
        self.before = {name: scene.motions.get(name, Motion()) for name in scene.bodies}
        self.pins = [c for c in scene.constraints if isinstance(c, Pin)]
        if len({tuple(self._pin_point(p)) for p in self.pins}) > 1:
            raise EventError("pins at different points")
        self.unknown = {}
        for name, body in scene.bodies.items():
            # "prime": sympy typesets these as v'_x ... and omega'; the names stay readable as text.
            vx, vy = sp.symbols(f"vxprime_{name} vyprime_{name}", real=True)
            omega = sp.Symbol(f"omegaprime_{name}", real=True) if body.rotates else sp.Integer(0)
            self.unknown[name] = (vx, vy, omega)

    def position(self, name: str) -> sp.Matrix:
        return sp.Matrix(self.before[name].position)

    def _pin_point(self, pin: Pin) -> sp.Matrix:
        return self.position(pin.body) + sp.Matrix(pin.offset)

    @property
    def pivot(self) -> sp.Matrix:
        return self._pin_point(self.pins[0]) if self.pins else sp.zeros(2, 1)

    def velocity_after(self, name: str, point: sp.Matrix) -> sp.Matrix:
        vx, vy, omega = self.unknown[name]
        r = point - self.position(name)
        return sp.Matrix([vx - omega * r[1], vy + omega * r[0]])

    @property
    def target(self) -> str:
        return self.impact.to if isinstance(self.impact, Stick) else self.impact.off

    def normal(self) -> sp.Matrix:
        """Unit normal of a smooth contact: radial on a round body, across a rod (along y)."""
        body = self.scene.bodies[self.target]
        if "radius" in body.sizes:
            out = self.position(self.impact.body) - self.position(self.target)
            return out / sp.sqrt(out.dot(out))
        if body.shape == "rod":
            return sp.Matrix([0, 1])
        raise EventError(f"a bounce off a {body.shape}: the contact normal is defined for round bodies and rods")

    def relative_velocity(self, velocities, point: sp.Matrix) -> sp.Matrix:
        """Velocity of the point mass relative to the target's material point where they touch."""
        vx, vy, omega = velocities[self.target]
        r = point - self.position(self.target)
        target = sp.Matrix([vx - omega * r[1], vy + omega * r[0]])
        return sp.Matrix(velocities[self.impact.body][:2]) - target

    def after_conditions(self) -> list[sp.Eq]:
        """Sticking: the point moves with the body's material point there. Bouncing: the normal
        relative velocity reverses, scaled by e. Pins stay still."""
        point = self.position(self.impact.body)
        if isinstance(self.impact, Stick):
            conditions = list(self.velocity_after(self.impact.to, point) - sp.Matrix(self.unknown[self.impact.body][:2]))
        else:
            n = self.normal()
            before = self.relative_velocity(self.states_before(), point).dot(n)
            conditions = [self.relative_velocity(self.unknown, point).dot(n) + self.impact.restitution * before]
        pinned = [v for p in self.pins for v in self.velocity_after(p.body, self._pin_point(p))]
        return [sp.Eq(e, 0) for e in [*conditions, *pinned]]

    def momentum(self, velocities) -> sp.Matrix:
        return sum((self.scene.bodies[n].mass * sp.Matrix(v[:2]) for n, v in velocities.items()), sp.zeros(2, 1))

    def angular_momentum(self, velocities, about: sp.Matrix) -> sp.Expr:
        total = sp.Integer(0)
        for name, (vx, vy, omega) in velocities.items():
            body = self.scene.bodies[name]
            total += body.mass * _cross(self.position(name) - about, (vx, vy))
            if body.rotates:
                total += body.inertia * omega
        return total

    def states_before(self):
        return {n: (*m.velocity, m.spin) for n, m in self.before.items()}

    def result(self, route: str, equations: list[sp.Eq], extra: list[sp.Symbol], text: str) -> EventResult:
        unknowns = [u for v in self.unknown.values() for u in v if isinstance(u, sp.Symbol)] + extra
        solution = solve_linear(equations, unknowns)
        after = {n: tuple(tidy(sp.sympify(u).xreplace(solution)) for u in v)  # safe: our symbols or 0
                 for n, v in self.unknown.items()}
        steps = (Step(text, tuple(equations)), Step("Solving", tuple(sp.Eq(u, solution[u]) for u in unknowns)))
        return EventResult(route, after, None, steps)


def _not_an_impact(scene: Scene, by_conservation: bool) -> EventResult | None:
    """Internal turns have routes of their own; None for an impact."""
    if any(isinstance(e, InternalTurn) for e in scene.events):
        return _turn(scene, "conservation" if by_conservation else "torques")
    return None


def by_conservation(scene: Scene) -> EventResult:
    """Momentum (where no pin acts) and angular momentum about the pivot, before = after."""
    other = _not_an_impact(scene, by_conservation=True)
    if other is not None:
        return other
    event = _Event(scene)
    before, after = event.states_before(), event.unknown
    equations = event.after_conditions()
    if isinstance(event.impact, Bounce):  # a smooth contact: the point keeps its tangential velocity
        n = event.normal()
        tangent = sp.Matrix([-n[1], n[0]])
        point = event.impact.body
        equations.append(sp.Eq(sp.Matrix(after[point][:2]).dot(tangent), sp.Matrix(before[point][:2]).dot(tangent)))
    if not event.pins:
        equations += [sp.Eq(a, b) for a, b in zip(event.momentum(before), event.momentum(after))]
    equations.append(sp.Eq(event.angular_momentum(before, event.pivot), event.angular_momentum(after, event.pivot)))
    return event.result("conservation", equations, [], "Conservation laws and the motion after the event")


def by_impulses(scene: Scene) -> EventResult:
    """Impulse and momentum for each body, with the contact and pin impulses unknown."""
    other = _not_an_impact(scene, by_conservation=False)
    if other is not None:
        return other
    event = _Event(scene)
    if isinstance(event.impact, Stick):
        J = sp.Matrix(sp.symbols("J_x J_y", real=True))
        extra = list(J)
    else:  # a smooth contact: the impulse is along the normal
        size = sp.Symbol("J", real=True)
        J = size * event.normal()
        extra = [size]
    impulses = {n: [] for n in scene.bodies}  # (point of application, impulse)
    point = event.position(event.impact.body)
    impulses[event.impact.body].append((point, J))
    impulses[event.target].append((point, -J))
    for pin in event.pins:
        P = sp.Matrix(sp.symbols(f"P_x^{pin.name} P_y^{pin.name}", real=True))
        impulses[pin.body].append((event._pin_point(pin), P))
        extra += list(P)
    equations = event.after_conditions()
    for name, body in scene.bodies.items():
        (vx, vy, omega), (ux, uy, spin) = event.unknown[name], event.states_before()[name]
        total = sum((imp for _, imp in impulses[name]), sp.zeros(2, 1))
        equations += [sp.Eq(body.mass * (vx - ux), total[0]), sp.Eq(body.mass * (vy - uy), total[1])]
        if body.rotates:
            moment = sum((_cross(p - event.position(name), imp) for p, imp in impulses[name]), sp.Integer(0))
            equations.append(sp.Eq(body.inertia * (omega - spin), moment))
    return event.result("impulses", equations, extra, "Impulse and momentum for each body")


def energy_change(scene: Scene, result: EventResult) -> sp.Expr:
    """Kinetic energy after minus before, in a factored form (no cancelling difference)."""
    def kinetic(states):
        return sum((scene.bodies[n].mass * (vx**2 + vy**2) / 2
                    + (scene.bodies[n].inertia * w**2 / 2 if scene.bodies[n].rotates else 0))
                   for n, (vx, vy, w) in states.items())
    before = {n: (*m.velocity, m.spin) for n, m in ((n, scene.motions.get(n, Motion())) for n in scene.bodies)}
    return tidy(kinetic(result.after) - kinetic(before))


def velocity_of_center(scene: Scene, result: EventResult) -> tuple[sp.Expr, sp.Expr]:
    total = sum((b.mass for b in scene.bodies.values()), sp.Integer(0))
    return tuple(tidy(sum((scene.bodies[n].mass * v[i] for n, v in result.after.items()), sp.Integer(0)) / total)
                 for i in (0, 1))


def _turn(scene: Scene, route: str) -> EventResult:
    """How far `relative_to` turns while `body` turns `angle` relative to it, from rest."""
    (turn,) = [e for e in scene.events if isinstance(e, InternalTurn)]
    inner, outer = scene.bodies[turn.body], scene.bodies[turn.relative_to]
    if any(scene.motions.get(n, Motion()).spin != 0 for n in (turn.body, turn.relative_to)):
        raise EventError("an internal turn starts from rest (zero angular momentum)")
    theta, psi = sp.symbols("theta psi", real=True)  # the outer body's angle, the relative angle
    if route == "conservation":
        # L = I_out theta' + I_in (theta' + psi') = 0 at every instant: d theta / d psi is constant.
        rate = sp.solve(outer.inertia * sp.Symbol("dtheta") + inner.inertia * (sp.Symbol("dtheta") + 1),
                        sp.Symbol("dtheta"))[0]
        text = "Angular momentum about the axle stays zero"
        equations = (sp.Eq(outer.inertia * sp.Symbol("dtheta") + inner.inertia * (sp.Symbol("dtheta") + 1), 0),)
    else:
        # I_out theta'' = -tau and I_in (theta'' + psi'') = tau: eliminate the internal torque.
        tau, accel, relative = sp.symbols("tau thetaddot psiddot", real=True)
        solved = sp.solve([sp.Eq(outer.inertia * accel, -tau), sp.Eq(inner.inertia * (accel + relative), tau)],
                          [accel, tau])
        rate = sp.simplify(solved[accel] / relative)  # integrated twice from rest: theta = rate * psi
        text = "Torques between the bodies are equal and opposite"
        equations = (sp.Eq(outer.inertia * accel, -tau), sp.Eq(inner.inertia * (accel + relative), tau))
    total = tidy(rate * turn.angle)
    steps = (Step(text, equations), Step("Over the whole internal turn", (sp.Eq(sp.Symbol("Delta_theta"), total),)))
    zero = (sp.Integer(0),) * 3
    return EventResult(route, {turn.body: zero, turn.relative_to: zero}, total, steps)
