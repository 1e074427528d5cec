"""The anchor of `derive bench`: each benchmark scene written again with sympy.physics.mechanics'
KanesMethod, and the problem file derive reads for it (a library id, or a file of
derive/bench/scenes/: an Atwood machine, a double pendulum, a yo-yo, a cart with a pendulum, a
block on a table pulled over a pulley, a rod held by a spring; and the n-link pendulum chain).

What an anchor computes (all of it timed): the frames, points, bodies and loads; Kane's equations
in minimal coordinates, fr + fr* = 0, with one auxiliary speed for each constraint force that
derive computes in the scene (every pin reaction, cord tension, normal force and friction);
solved in the reference configuration at rest for the accelerations (LU) and then those forces
(the auxiliary equations), each cancelled. Where a problem asks for more than that, the anchor
does it too: small oscillations about a rest position (omega^2 from the equation linearized
there), and the least release height on a loop (the normal force at the top at speed s, then
energy).

The n-link pendulum (and the double pendulum) is built with sympy's joints (PinJoint, System),
accelerations only; the other scenes by hand, since rolling, cords and the constraint forces need
auxiliary speeds, which the joints do not give.

The models are the textbook ones, in minimal coordinates: a straight run of cord keeps its
direction (a block hanging from a cord moves along the cord and does not swing). derive's cords
have exact geometry, so it keeps the swing as a degree of freedom and its equations hold in any
configuration; at the reference configuration at rest the accelerations and forces are the same,
and tests/test_bench.py checks every one of them numerically against derive's.

>>> anchor = SCENES["string_wrapped_disk"]
>>> values = anchor.build().in_derive_terms()
>>> sp.factor(values["yddot_block"])
-2*g*m/(M + 2*m)
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import sympy as sp
from sympy.physics.mechanics import (KanesMethod, Particle, PinJoint, Point, ReferenceFrame, RigidBody, System,
                                     dynamicsymbols, inertia)

TIME = dynamicsymbols._t
#: The problem files of the scenes that are not in the library.
SCENE_FILES = Path(__file__).resolve().parent / "scenes"


def _symbols(names: str):
    return sp.symbols(names, positive=True)


class Model:
    """A scene in minimal coordinates q (turns and distances from the reference configuration,
    speeds u = q'), with an auxiliary speed for each constraint force named as derive names it."""

    def __init__(self, coordinates: int, forces: list[str], g: sp.Symbol):
        self.N = ReferenceFrame("N")
        self.origin = Point("O")
        self.origin.set_vel(self.N, 0)
        self.q = [dynamicsymbols(f"q{k}") for k in range(1, coordinates + 1)]
        self.u = [dynamicsymbols(f"u{k}") for k in range(1, coordinates + 1)]
        self.forces = {name: sp.Symbol(name, real=True) for name in forces}
        self.aux = {name: dynamicsymbols(f"ua{k}") for k, name in enumerate(forces, start=1)}
        self.g = g
        self.bodies: list = []
        self.loads: list = []
        self.centers: dict[str, tuple[Point, ReferenceFrame | None]] = {}
        self.kane: KanesMethod | None = None

    def frame(self, name: str, turn: sp.Expr, rate: sp.Expr, angle: sp.Expr = 0) -> ReferenceFrame:
        """A body frame at `angle` + `turn` from N, turning at `rate`."""
        frame = self.N.orientnew(name, "Axis", (angle + turn, self.N.z))
        frame.set_ang_vel(self.N, rate * self.N.z)
        return frame

    def point(self, name: str, velocity) -> Point:
        point = Point(name)
        point.set_vel(self.N, velocity)
        return point

    def on(self, base: Point, name: str, offset, frame: ReferenceFrame) -> Point:
        """The material point of the body turning with `frame` at `offset` from `base`."""
        point = base.locatenew(name, offset)
        point.v2pt_theory(base, self.N, frame)
        return point

    def rigid(self, name: str, center: Point, frame: ReferenceFrame, mass: sp.Expr, moment: sp.Expr) -> None:
        self.bodies.append(RigidBody(name, center, frame, mass, (inertia(frame, 0, 0, moment), center)))
        self.loads.append((center, -mass * self.g * self.N.y))
        self.centers[name] = (center, frame)

    def particle(self, name: str, point: Point, mass: sp.Expr) -> None:
        self.bodies.append(Particle(name, point, mass))
        self.loads.append((point, -mass * self.g * self.N.y))
        self.centers[name] = (point, None)

    def load(self, point: Point, force) -> None:
        self.loads.append((point, force))

    def equations(self) -> "Model":
        """Kane's equations (fr + fr* = 0 and the auxiliary ones)."""
        kinematic = [q.diff(TIME) - u for q, u in zip(self.q, self.u)]
        self.kane = KanesMethod(self.N, self.q, self.u, kd_eqs=kinematic, u_auxiliary=list(self.aux.values()))
        self.kane.kanes_equations(self.bodies, self.loads)
        return self

    def rest(self) -> dict:
        return {s: sp.S.Zero for s in (*self.q, *self.u, *self.aux.values())}

    def solve(self, state: dict | None = None) -> dict:
        """The accelerations u' and the constraint forces at `state` (default: the reference
        configuration at rest)."""
        state = {**self.rest(), **(state or {})}
        mass_matrix = self.kane.mass_matrix.xreplace(state)
        forcing = self.kane.forcing.xreplace(state)
        rates = {u.diff(TIME): sp.cancel(v) for u, v in zip(self.u, mass_matrix.LUsolve(forcing))}
        rates.update({a.diff(TIME): sp.S.Zero for a in self.aux.values()})
        if not self.forces:
            return rates
        auxiliary = self.kane.auxiliary_eqs.xreplace(rates).xreplace(state)
        unknowns = list(self.forces.values())
        matrix, rhs = sp.linear_eq_to_matrix(list(auxiliary), unknowns)
        forces = {f: sp.cancel(v) for f, v in zip(unknowns, matrix.LUsolve(rhs))}
        return {**rates, **forces}

    def omega_squared(self) -> sp.Expr:
        """One degree of freedom at rest in equilibrium: omega^2 = -d(q'')/dq, linearized there."""
        rest = self.rest()
        stiffness = self.kane.forcing[0].diff(self.q[0]).xreplace(rest)
        return sp.cancel(-stiffness / self.kane.mass_matrix[0, 0].xreplace(rest))

    def in_derive_terms(self, state: dict | None = None) -> dict[str, sp.Expr]:
        """derive's unknowns from the solution at `state` (untimed; for the tests): every body's
        xddot, yddot (and thetaddot), and the constraint forces, by derive's names."""
        state = {**self.rest(), **(state or {})}
        solved = self.solve(state)
        speeds = {q.diff(TIME): u for q, u in zip(self.q, self.u)}
        rates = {k: v for k, v in solved.items() if isinstance(k, sp.Derivative)}

        def at(expr):
            return sp.cancel(expr.xreplace(rates).xreplace(speeds).xreplace(state))

        result = {}
        for name, (point, frame) in self.centers.items():
            acceleration = point.acc(self.N)
            result[f"xddot_{name}"] = at(acceleration.dot(self.N.x))
            result[f"yddot_{name}"] = at(acceleration.dot(self.N.y))
            if frame is not None:
                result[f"thetaddot_{name}"] = at(frame.ang_acc_in(self.N).dot(self.N.z))
        result.update({name: solved[symbol] for name, symbol in self.forces.items()})
        return result


# --- the library's scenes ---------------------------------------------------------------------

def string_wrapped_disk() -> Model:
    M, R, m, g = _symbols("M R m g")
    model = Model(1, ["R_x^axle", "R_y^axle", "T_string"], g)
    N, (q,), (u,), a = model.N, model.q, model.u, model.aux
    disk = model.frame("disk", q, u)
    center = model.point("C", a["R_x^axle"] * N.x + a["R_y^axle"] * N.y)
    model.rigid("disk", center, disk, M, M * R**2 / 2)
    rim = model.on(center, "rim", R * N.x, disk)
    block = model.point("block", (center.vel(N).dot(N.y) + R * u + a["T_string"]) * N.y)
    model.particle("block", block, m)
    f = model.forces
    model.load(center, f["R_x^axle"] * N.x + f["R_y^axle"] * N.y)
    model.load(block, f["T_string"] * N.y)
    model.load(rim, -f["T_string"] * N.y)
    return model.equations()


def _roller(model: Model, name: str, start, mass, moment, radius, normal, tangent, turn=None, rate=None,
            along=None, speed=None) -> tuple[Point, Point]:
    """A round body of `radius` on a surface (unit `normal` toward its center, `tangent`
    t = (n_y, -n_x)), rolling: its center at `start` + `along`(q) moving at `speed`(u) along
    the surface, turning by `turn`; the contact's slip and lift-off are auxiliary speeds."""
    N, a, f = model.N, model.aux, model.forces
    frame = model.frame(name, turn, rate)
    center = model.origin.locatenew(f"{name}_center", start + along)
    slip = a.get(f"f^{name}", 0) * tangent + a[f"N^{name}"] * normal
    center.set_vel(N, speed + slip)
    model.rigid(name, center, frame, mass, moment)
    contact = model.on(center, f"{name}_contact", -radius * normal, frame)
    model.load(contact, f[f"N^{name}"] * normal + f[f"f^{name}"] * tangent)
    return center, contact


def tugged_spool() -> Model:
    F, M, R, r, I_cm, theta, g = _symbols("F M R r I_cm theta g")
    model = Model(1, ["N^spool", "f^spool"], g)
    N, (q,), (u,) = model.N, model.q, model.u
    center, _ = _roller(model, "spool", R * N.y, M, I_cm, R, N.y, N.x, q, u, -R * q * N.x, -R * u * N.x)
    hub = model.on(center, "hub", r * (sp.sin(theta) * N.x - sp.cos(theta) * N.y), model.centers["spool"][1])
    model.load(hub, F * (sp.cos(theta) * N.x + sp.sin(theta) * N.y))
    return model.equations()


def _pivoted(mass: sp.Expr, moment: sp.Expr, below: sp.Expr, g: sp.Symbol, body: str) -> Model:
    """A body turning about a pin `below` above its center of mass (negative: below it)."""
    model = Model(1, ["R_x^pivot", "R_y^pivot"], g)
    N, (q,), (u,), a, f = model.N, model.q, model.u, model.aux, model.forces
    frame = model.frame(body, q, u)
    pivot = model.point("P", a["R_x^pivot"] * N.x + a["R_y^pivot"] * N.y)
    center = model.on(pivot, "C", -below * frame.y, frame)
    model.rigid(body, center, frame, mass, moment)
    model.load(pivot, f["R_x^pivot"] * N.x + f["R_y^pivot"] * N.y)
    return model.equations()


def compound_pendulum() -> Model:
    M, Rcm, I_cm, g = _symbols("M Rcm I_cm g")
    return _pivoted(M, I_cm, Rcm, g, "pendulum")


def tightrope_walker() -> Model:
    m, h, I, g = _symbols("m h I g")
    return _pivoted(m, I - m * h**2, -h, g, "walker")


def _incline(model: Model, angle, bodies) -> None:
    """Bodies (name, mass, moment or None for a sliding point, radius) touching a plane through
    the origin that descends to the right at `angle`; coordinate k is body k's turn (rolling) or
    distance down the plane (sliding)."""
    N = model.N
    down = sp.cos(angle) * N.x - sp.sin(angle) * N.y
    normal = sp.sin(angle) * N.x + sp.cos(angle) * N.y
    for (name, mass, moment, radius), q, u in zip(bodies, model.q, model.u):
        if moment is None:
            point = model.origin.locatenew(name, q * down)
            point.set_vel(N, u * down + model.aux[f"N^{name}"] * normal)
            model.particle(name, point, mass)
            model.load(point, model.forces[f"N^{name}"] * normal)
        else:
            _roller(model, name, radius * normal, mass, moment, radius, normal, down, q, u,
                    -radius * q * down, -radius * u * down)


def rolling_incline() -> Model:
    M, R, H, theta, mu_s, g = _symbols("M R H theta mu_s g")
    model = Model(1, ["N^ball", "f^ball"], g)
    _incline(model, theta, [("ball", M, 2 * M * R**2 / 5, R)])
    return model.equations()


def incline_race() -> Model:
    H, g, angle = _symbols("H g angle_ramp")
    names = ("block", "ball", "can", "hoop")
    masses = dict(zip(names, _symbols("m_block m_ball m_can m_hoop")))
    radii = dict(zip(names[1:], _symbols("radius_ball radius_can radius_hoop")))
    shares = {"ball": sp.Rational(2, 5), "can": sp.Rational(1, 2), "hoop": sp.Integer(1)}
    model = Model(4, ["N^block", "N^ball", "f^ball", "N^can", "f^can", "N^hoop", "f^hoop"], g)
    _incline(model, angle, [("block", masses["block"], None, 0)]
             + [(n, masses[n], shares[n] * masses[n] * radii[n] ** 2, radii[n]) for n in names[1:]])
    return model.equations()


def _loop(model: Model, loop_radius, bodies) -> None:
    """Bodies (name, mass, moment or None for a sliding point, radius) inside a loop whose lowest
    point is the origin; coordinate k is body k's angle about the loop's center."""
    N = model.N
    middle = loop_radius * N.y
    for (name, mass, moment, radius), q, u in zip(bodies, model.q, model.u):
        path = loop_radius - radius
        outward = sp.sin(q) * N.x - sp.cos(q) * N.y
        normal = -outward  # toward the loop's center
        tangent = sp.cos(q) * N.x + sp.sin(q) * N.y
        if moment is None:
            point = model.origin.locatenew(name, middle + path * outward)
            point.set_vel(N, path * u * tangent + model.aux[f"N^{name}"] * normal)
            model.particle(name, point, mass)
            model.load(point, model.forces[f"N^{name}"] * normal)
        else:
            _roller(model, name, middle, mass, moment, radius, normal, tangent, -path / radius * q,
                    -path / radius * u, path * outward, path * u * tangent)


def release_height(model: Model, index: int, body: str, loop_radius, radius, small: bool = False) -> sp.Expr:
    """The least release height of `body`'s center above its lowest position (as derive's
    min_release_height): the normal force at the top of the loop at speed s vanishes at s_c;
    energy from the release to the top, 2 (R - r) above the lowest position, gives the drop."""
    s = sp.Symbol("s", positive=True)
    path = loop_radius - radius
    top = {model.q[index]: sp.pi, model.u[index]: s / path}
    normal = model.solve(top)[model.forces[f"N^{body}"]]
    (critical,) = [r for r in sp.solve(normal, s) if r.is_positive is not False]
    moving = next(b for b in model.bodies if b.name == body)
    kinetic = moving.kinetic_energy(model.N).xreplace({model.u[index]: critical / path}).xreplace(model.rest())
    height = sp.cancel(kinetic / (moving.mass * model.g)) + 2 * path
    return sp.limit(height, radius, 0, "+") if small else height


def loop_the_loop_ball() -> Model:
    R, r, g, m = _symbols("R r g m_ball")
    model = Model(1, ["N^ball", "f^ball"], g)
    _loop(model, R, [("ball", m, 2 * m * r**2 / 5, r)])
    return model.equations()


def loop_the_loop() -> Model:
    R, g, m_cart, m_ball, r = _symbols("R g m_cart m_ball radius_ball")
    model = Model(2, ["N^cart", "N^ball", "f^ball"], g)
    _loop(model, R, [("cart", m_cart, None, 0), ("ball", m_ball, 2 * m_ball * r**2 / 5, r)])
    return model.equations()




# --- scenes of derive/bench/scenes --------------------------------------------------------------

def atwood() -> Model:
    m1, m2, M, R, g = _symbols("m1 m2 M R g")
    model = Model(1, ["R_x^axle", "R_y^axle", "T_rope_1", "T_rope_2"], g)
    N, (q,), (u,), a, f = model.N, model.q, model.u, model.aux, model.forces
    pulley = model.frame("pulley", q, u)
    center = model.point("C", a["R_x^axle"] * N.x + a["R_y^axle"] * N.y)
    model.rigid("pulley", center, pulley, M, M * R**2 / 2)
    rise = center.vel(N).dot(N.y)
    for name, mass, side, tension in (("left", m1, -1, "T_rope_1"), ("right", m2, 1, "T_rope_2")):
        rim = model.on(center, f"rim_{name}", side * R * N.x, pulley)
        block = model.point(name, (rise + side * R * u + a[tension]) * N.y)
        model.particle(name, block, mass)
        model.load(block, f[tension] * N.y)
        model.load(rim, -f[tension] * N.y)
    model.load(center, f["R_x^axle"] * N.x + f["R_y^axle"] * N.y)
    return model.equations()


def cart_pendulum() -> Model:
    m1, m2, L, g = _symbols("m1 m2 L g")
    model = Model(2, ["N^rail", "R_x^hinge", "R_y^hinge"], g)
    N, (x, q), (v, u), a, f = model.N, model.q, model.u, model.aux, model.forces
    cart = model.origin.locatenew("cart", x * N.x)
    cart.set_vel(N, v * N.x + a["N^rail"] * N.y)
    model.particle("cart", cart, m1)
    rod = model.frame("rod", q, u)
    hinge = cart.locatenew("hinge", 0)
    hinge.set_vel(N, cart.vel(N) + a["R_x^hinge"] * N.x + a["R_y^hinge"] * N.y)
    model.rigid("rod", model.on(hinge, "rod_center", L / 2 * rod.x, rod), rod, m2, m2 * L**2 / 12)
    reaction = f["R_x^hinge"] * N.x + f["R_y^hinge"] * N.y
    model.load(hinge, reaction)
    model.load(cart, f["N^rail"] * N.y - reaction)
    return model.equations()


def table_pulley() -> Model:
    m1, m2, M, R, g = _symbols("m1 m2 M R g")
    model = Model(1, ["N^box", "R_x^axle", "R_y^axle", "T_rope_1", "T_rope_2"], g)
    N, (q,), (u,), a, f = model.N, model.q, model.u, model.aux, model.forces
    pulley = model.frame("pulley", q, u)
    center = model.origin.locatenew("C", 4 * R * N.x - R * N.y)
    center.set_vel(N, a["R_x^axle"] * N.x + a["R_y^axle"] * N.y)
    model.rigid("pulley", center, pulley, M, M * R**2 / 2)
    top, right = model.on(center, "top", R * N.y, pulley), model.on(center, "right", R * N.x, pulley)
    box = model.point("box", (top.vel(N).dot(N.x) + a["T_rope_1"]) * N.x + a["N^box"] * N.y)
    model.particle("box", box, m1)
    weight = model.point("weight", (right.vel(N).dot(N.y) + a["T_rope_2"]) * N.y)
    model.particle("weight", weight, m2)
    model.load(box, f["T_rope_1"] * N.x + f["N^box"] * N.y)
    model.load(top, -f["T_rope_1"] * N.x)
    model.load(weight, f["T_rope_2"] * N.y)
    model.load(right, -f["T_rope_2"] * N.y)
    model.load(center, f["R_x^axle"] * N.x + f["R_y^axle"] * N.y)
    return model.equations()


def yo_yo() -> Model:
    m, R, r, g = _symbols("m R r g")
    model = Model(1, ["T_string"], g)
    N, (q,), (u,), a, f = model.N, model.q, model.u, model.aux, model.forces
    yoyo = model.frame("yoyo", q, u)
    center = model.point("C", (-r * u + a["T_string"]) * N.y)  # the cord's tangent point stays put
    model.rigid("yoyo", center, yoyo, m, m * R**2 / 2)
    model.load(model.on(center, "axle", r * N.x, yoyo), f["T_string"] * N.y)
    return model.equations()


def spring_pendulum() -> Model:
    m, L, k, H, L0, g = _symbols("m L k H L0 g")
    model = Model(1, ["R_x^hinge", "R_y^hinge"], g)
    N, (q,), (u,), a, f = model.N, model.q, model.u, model.aux, model.forces
    rod = model.frame("rod", q, u)
    hinge = model.point("P", a["R_x^hinge"] * N.x + a["R_y^hinge"] * N.y)
    model.rigid("rod", model.on(hinge, "C", L / 2 * rod.x, rod), rod, m, m * L**2 / 12)
    end = model.on(hinge, "E", L * rod.x, rod)
    stretch = (L * N.x + H * N.y) - end.pos_from(hinge)  # from the rod's end to the spring's top
    model.load(end, k * (stretch.magnitude() - L0) * stretch.normalize())
    model.load(hinge, f["R_x^hinge"] * N.x + f["R_y^hinge"] * N.y)
    return model.equations()


# --- the n-link pendulum: sympy's joints ---------------------------------------------------------

def _names(prefix: str, n: int, distinct: bool) -> list[str]:
    return [f"{prefix}{k}" if distinct else prefix for k in range(1, n + 1)]


def pendulum_chain_file(n: int) -> str:
    """derive's problem file of n equal rods pinned end to end, the first to the ground at its
    start, all level, released from rest."""
    lines = [f"id: pendulum_chain_{n}", f"title: A chain of {n} pendulum links", "topic: torque", "parameters:",
             "  m: {meaning: mass of a link, unit: kg, range: [0.5, 2], sig_figs: 3}",
             "  L: {meaning: length of a link, unit: m, range: [0.2, 1], sig_figs: 3}",
             "  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}", "scene:", "  bodies:"]
    lines += [f"    link{k}: {{shape: rod, mass: m, length: L, at: [{2 * k - 1}*L/2, 0], angle: 0}}"
              for k in range(1, n + 1)]
    lines += ["  joints:", "    pin1: {pin: link1.start}"]
    lines += [f"    pin{k}: {{pin: link{k}.start, to: link{k - 1}.end}}" for k in range(2, n + 1)]
    lines += ["  loads:", "    - gravity: g", "ask:",
              f"  alpha: {{meaning: angular acceleration of the last link, of: link{n}.angular_acceleration, "
              "unit: rad/s^2}",
              "  F: {meaning: vertical reaction of the top pin, of: pin1.reaction.y, unit: N}",
              "question: |", f"  A chain of {n} rods is released from rest."]
    return "\n".join(lines) + "\n"


def pendulum_chain(n: int, distinct: bool = False, angles=None) -> Model:
    """The KanesMethod n-link pendulum of rods (sympy's PinJoint and System): link k at the
    absolute angle `angles`[k] (default: all level), its turn from there the joint's coordinate.
    Accelerations only: the joints give no pin reactions."""
    masses = [sp.Symbol(s, positive=True) for s in _names("m", n, distinct)]
    lengths = [sp.Symbol(s, positive=True) for s in _names("L", n, distinct)]
    angles = [sp.sympify(a, strict=True) for a in (angles or [0] * n)]  # safe: numbers from the bench's own code; strict refuses text
    ground = RigidBody("ground")
    system = System.from_newtonian(ground)
    model = Model(0, [], sp.Symbol("g", positive=True))
    model.N, model.origin = ground.frame, ground.masscenter
    parent, joint_at, previous = ground, ground.masscenter, 0
    for k, (m, L, angle) in enumerate(zip(masses, lengths, angles), start=1):
        link = RigidBody(f"link{k}", mass=m)
        link.inertia = (inertia(link.frame, 0, 0, m * L**2 / 12), link.masscenter)
        turned = parent.frame.orientnew(f"at{k}", "Axis", (angle - previous, parent.frame.z))
        system.add_joints(PinJoint(f"pin{k}", parent, link, dynamicsymbols(f"q{k}"), dynamicsymbols(f"u{k}"),
                                   parent_point=joint_at, child_point=-L / 2 * link.frame.x,
                                   parent_interframe=turned, joint_axis=turned.z))
        model.centers[link.name] = (link.masscenter, link.frame)
        parent, joint_at, previous = link, L / 2 * link.frame.x, angle
    system.apply_uniform_gravity(-model.g * model.N.y)
    system.form_eoms()
    model.q, model.u, model.kane = list(system.q), list(system.u), system.eom_method
    return model


# --- the table --------------------------------------------------------------------------------

@dataclass(frozen=True)
class Anchor:
    """A benchmark scene: the same physics as derive's problem of the same id (a file of
    derive/bench/scenes, or a library id) by KanesMethod. `build` forms the model and its
    equations; `answers` computes what else the problem asks, by the problem's ask names."""

    id: str
    build: Callable[[], Model]
    answers: Callable[[Model], dict[str, sp.Expr]] | None = None

    def reference(self) -> str:
        """What `derive.language.problem.load` reads for this scene."""
        path = SCENE_FILES / f"{self.id}.yaml"
        return str(path) if path.exists() else self.id

    def run(self) -> tuple[Model, dict[str, sp.Expr]]:
        """What is timed: the model, Kane's equations, their solution at the reference
        configuration at rest, and the answers asked beyond it."""
        model = self.build()
        model.solve()
        return model, self.answers(model) if self.answers else {}


def _frequency(model: Model) -> dict:
    return {"omega": sp.sqrt(model.omega_squared())}


def _growth_rate(model: Model) -> dict:
    return {"a": sp.sqrt(-model.omega_squared())}


def _loop_heights(model: Model) -> dict:
    R, r = _symbols("R radius_ball")
    return {"h_slide": release_height(model, 0, "cart", R, 0),
            "h_roll": release_height(model, 1, "ball", R, r, small=True)}


def _ball_height(model: Model) -> dict:
    R, r = _symbols("R r")
    return {"h_roll": release_height(model, 0, "ball", R, r)}


SCENES = {a.id: a for a in (
    Anchor("string_wrapped_disk", string_wrapped_disk),
    Anchor("tugged_spool", tugged_spool),
    Anchor("compound_pendulum", compound_pendulum, _frequency),
    Anchor("tightrope_walker", tightrope_walker, _growth_rate),
    Anchor("rolling_incline", rolling_incline),
    Anchor("incline_race", incline_race),
    Anchor("loop_the_loop", loop_the_loop, _loop_heights),
    Anchor("loop_the_loop_ball", loop_the_loop_ball, _ball_height),
    Anchor("atwood", atwood),
    Anchor("table_pulley", table_pulley),
    Anchor("yo_yo", yo_yo),
    Anchor("spring_pendulum", spring_pendulum),
    Anchor("cart_pendulum", cart_pendulum),
    Anchor("double_pendulum", lambda: pendulum_chain(2, distinct=True, angles=[0, -sp.pi / 2])),
)}

#: A shorter run (`derive bench --quick`): a pendulum, a cord over a pulley, rolling, a pin linkage.
QUICK = ("compound_pendulum", "atwood", "rolling_incline", "cart_pendulum")


# --- the same numbers on both sides ---------------------------------------------------------------

def sample_point(p) -> dict[str, sp.Expr]:
    """The values, by name, at which both engines' expressions are compared: a problem's
    parameters at their value or the middle of their range."""
    return {n: q.value if q.value is not None else (q.range[0] + q.range[1]) / 2 for n, q in p.parameters.items()}


def numbers(expressions: dict[str, sp.Expr], point: dict[str, sp.Expr]) -> dict[str, list[float]]:
    """Each expression at `point` as [real, imaginary]; a symbol `point` lacks (a size the problem
    leaves open) at a value fixed by its name, the same on both sides."""
    def value(name: str) -> sp.Expr:
        return point[name] if name in point else sp.Rational(3 + sum(map(ord, name)) % 7, 10)

    result = {}
    for key, expression in expressions.items():
        try:
            number = complex(sp.N(expression.xreplace({s: value(str(s)) for s in expression.free_symbols}), 20))
        except TypeError:  # not a number there (an answer that is not a scalar): not compared
            continue
        result[key] = [number.real, number.imag]
    return result


def disagreements(derived: dict[str, list[float]], anchored: dict[str, list[float]],
                  tolerance: float = 1e-9) -> list[str]:
    """What the anchor computes that derive lacks or gives differently (relative `tolerance`)."""
    wrong = []
    for key, theirs in anchored.items():
        ours = derived.get(key)
        if ours is None:
            wrong.append(f"{key}: not in derive's solution")
        elif abs(complex(*ours) - complex(*theirs)) > tolerance * (1 + abs(complex(*theirs))):
            wrong.append(f"{key}: derive {ours[0]:.10g}, anchor {theirs[0]:.10g}")
    return wrong


def anchor_numbers(model: Model, answers: dict[str, sp.Expr], point: dict[str, sp.Expr]) -> dict[str, list[float]]:
    """The anchor's accelerations, constraint forces and answers, in derive's names, at `point`."""
    return numbers({**model.in_derive_terms(), **answers}, point)


def derive_numbers(solution, point: dict[str, sp.Expr]) -> dict[str, list[float]]:
    """derive's accelerations and constraint forces (Lagrange's route, at the reference
    configuration at rest) and every answer, at `point`."""
    rest = solution.coordinates.at_rest_in_reference()
    raw = solution.derivations["lagrange"].at(rest).raw
    return numbers({**{str(k): v for k, v in raw.items()}, **solution.expressions}, point)
