"""The anchor of `derive bench`: each benchmark scene written again by hand with
sympy.physics.mechanics' KanesMethod, and the scenes derive reads (library ids, or problem files
written here: an Atwood machine, a double pendulum, a yo-yo, a cart with a pendulum, a block on a
table pulled over a pulley; and chains of n pendulum links or n disks on cords).

What an anchor computes (all of it timed): the frames, points, bodies and loads; Kane's equations
in minimal coordinates, fr + fr* = 0, with one auxiliary speed for each constraint force that
derive computes in the scene (every pin reaction, cord tension, normal force and friction);
solved in the reference configuration at rest for the accelerations (LU) and then those forces
(the auxiliary equations), each cancelled. Where a problem asks for more than that, the anchor
does it too: small oscillations about a rest position (omega^2 from the equation linearized
there), and the least release height on a loop (the normal force at the top at speed s, then
energy).

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
from sympy.physics.mechanics import KanesMethod, Particle, Point, ReferenceFrame, RigidBody, dynamicsymbols, inertia

TIME = dynamicsymbols._t


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
    """The least release height of `body`'s center: the normal force at the top of the loop at
    speed s vanishes at s_c; energy from the release to the top gives the drop."""
    s = sp.Symbol("s", positive=True)
    path = loop_radius - radius
    top = {model.q[index]: sp.pi, model.u[index]: s / path}
    normal = model.solve(top)[model.forces[f"N^{body}"]]
    (critical,) = [r for r in sp.solve(normal, s) if r.is_positive is not False]
    moving = next(b for b in model.bodies if b.name == body)
    kinetic = moving.kinetic_energy(model.N).xreplace({model.u[index]: critical / path}).xreplace(model.rest())
    height = sp.cancel(kinetic / (moving.mass * model.g)) + loop_radius + path
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


# --- scenes written here ----------------------------------------------------------------------

ATWOOD = """\
id: atwood
title: An Atwood machine with a massive pulley
topic: torque
parameters:
  m1: {meaning: mass of the left block, unit: kg, range: [0.5, 2], sig_figs: 3}
  m2: {meaning: mass of the right block, unit: kg, range: [2.5, 5], sig_figs: 3}
  M: {meaning: mass of the pulley, unit: kg, range: [0.5, 2], sig_figs: 3}
  R: {meaning: radius of the pulley, unit: m, range: [0.05, 0.2], sig_figs: 2}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  bodies:
    pulley: {shape: disk, mass: M, radius: R, joint: fixed_axle}
    left: {shape: point, mass: m1, at: [-R, -4*R]}
    right: {shape: point, mass: m2, at: [R, -4*R]}
  cords:
    rope: [left, {over: pulley}, right]
  loads:
    - gravity: g
ask:
  a: {meaning: acceleration of the right block, of: right.acceleration.y, unit: m/s^2}
  T1: {meaning: tension on the left, of: rope.tension_1, unit: N}
  T2: {meaning: tension on the right, of: rope.tension_2, unit: N}
question: |
  Two blocks hang from a cord over a uniform disk on a fixed axle.
"""


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


CART_PENDULUM = """\
id: cart_pendulum
title: A rod hinged to a cart on a rail
topic: torque
parameters:
  m1: {meaning: mass of the cart, unit: kg, range: [1, 5], sig_figs: 3}
  m2: {meaning: mass of the rod, unit: kg, range: [0.2, 1], sig_figs: 3}
  L: {meaning: length of the rod, unit: m, range: [0.2, 1], sig_figs: 2}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  bodies:
    cart: {shape: point, mass: m1}
    rod: {shape: rod, mass: m2, length: L, at: [L/2, 0]}
  joints:
    rail: {slider: cart, angle: 0}
    hinge: {pin: rod.start, to: cart}
  loads:
    - gravity: g
ask:
  a: {meaning: acceleration of the cart, of: cart.acceleration.x, unit: m/s^2}
  alpha: {meaning: angular acceleration of the rod, of: rod.angular_acceleration, unit: rad/s^2}
  N: {meaning: force of the rail on the cart, of: rail.normal, unit: N}
question: |
  A rod hinged to a cart on a level rail is released from rest, horizontal.
"""


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


TABLE_PULLEY = """\
id: table_pulley
title: A block on a table pulled by a hanging block over a pulley
topic: torque
parameters:
  m1: {meaning: mass of the block on the table, unit: kg, range: [0.5, 3], sig_figs: 3}
  m2: {meaning: mass of the hanging block, unit: kg, range: [0.2, 2], sig_figs: 3}
  M: {meaning: mass of the pulley, unit: kg, range: [0.2, 1], sig_figs: 3}
  R: {meaning: radius of the pulley, unit: m, range: [0.03, 0.1], sig_figs: 2}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  surfaces:
    table: {plane: {angle: 0}}
  bodies:
    box: {shape: point, mass: m1, on: table, contact: sliding}
    pulley: {shape: disk, mass: M, radius: R, at: [4*R, -R], joint: fixed_axle}
    weight: {shape: point, mass: m2, at: [5*R, -5*R]}
  cords:
    rope: [box, {over: pulley}, weight]
  loads:
    - gravity: g
ask:
  a: {meaning: acceleration of the box, of: box.acceleration.x, unit: m/s^2}
  T1: {meaning: tension of the level run, of: rope.tension_1, unit: N}
  T2: {meaning: tension of the hanging run, of: rope.tension_2, unit: N}
question: |
  A box on a smooth table is tied by a cord over a pulley at the table's edge to a hanging weight.
"""


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


# --- chains: n pendulum links, n disks on cords -------------------------------------------------

def _parameters(lines: list[str], specs) -> None:
    for name, meaning, unit, low, high in specs:
        lines.append(f"  {name}: {{meaning: {meaning}, unit: {unit}, range: [{low}, {high}], sig_figs: 3}}")


def _names(prefix: str, n: int, distinct: bool) -> list[str]:
    return [f"{prefix}{k}" if distinct else prefix for k in range(1, n + 1)]


def pendulum_chain_file(n: int, distinct: bool = False, angles=None) -> str:
    """n rods pinned end to end, the first to the ground at its start; link k at angle `angles`[k]
    (default: all level), released from rest."""
    masses, lengths = _names("m", n, distinct), _names("L", n, distinct)
    angles = angles or [0] * n
    lines = [f"id: pendulum_chain_{n}", f"title: A chain of {n} pendulum links", "topic: torque", "parameters:"]
    _parameters(lines, dict.fromkeys([(m, "mass of a link", "kg", 0.5, 2) for m in masses]
                                     + [(L, "length of a link", "m", 0.2, 1) for L in lengths]))
    lines += ["  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}", "scene:", "  bodies:"]
    start = sp.Matrix([0, 0])
    for k in range(n):
        L, angle = sp.Symbol(lengths[k]), sp.sympify(angles[k])
        along = sp.Matrix([sp.cos(angle), sp.sin(angle)])
        center = start + L / 2 * along
        lines.append(f"    link{k + 1}: {{shape: rod, mass: {masses[k]}, length: {L}, "
                     f"at: [{sp.sstr(center[0])}, {sp.sstr(center[1])}], angle: {sp.sstr(angle)}}}")
        start = start + L * along
    lines += ["  joints:", "    pin1: {pin: link1.start}"]
    lines += [f"    pin{k}: {{pin: link{k}.start, to: link{k - 1}.end}}" for k in range(2, n + 1)]
    lines += ["  loads:", "    - gravity: g", "ask:",
              f"  alpha: {{meaning: angular acceleration of the last link, of: link{n}.angular_acceleration, "
              "unit: rad/s^2}",
              "  F: {meaning: vertical reaction of the top pin, of: pin1.reaction.y, unit: N}",
              "question: |", f"  A chain of {n} rods is released from rest."]
    return "\n".join(lines) + "\n"


def pendulum_chain(n: int, distinct: bool = False, angles=None) -> Model:
    """The same chain: the links' turns q_k; each pin's reaction by auxiliary speeds of the
    link's start."""
    masses = [sp.Symbol(s, positive=True) for s in _names("m", n, distinct)]
    lengths = [sp.Symbol(s, positive=True) for s in _names("L", n, distinct)]
    g = sp.Symbol("g", positive=True)
    angles = angles or [0] * n
    model = Model(n, [f"R_{c}^pin{k}" for k in range(1, n + 1) for c in "xy"], g)
    N, a, f = model.N, model.aux, model.forces
    end = model.origin
    for k in range(1, n + 1):
        link = model.frame(f"link{k}", model.q[k - 1], model.u[k - 1], sp.sympify(angles[k - 1]))
        start = end.locatenew(f"P{k}", 0)
        start.set_vel(N, end.vel(N) + a[f"R_x^pin{k}"] * N.x + a[f"R_y^pin{k}"] * N.y)
        L, m = lengths[k - 1], masses[k - 1]
        model.rigid(f"link{k}", model.on(start, f"C{k}", L / 2 * link.x, link), link, m, m * L**2 / 12)
        reaction = f[f"R_x^pin{k}"] * N.x + f[f"R_y^pin{k}"] * N.y
        model.load(start, reaction)
        if k > 1:
            model.load(end, -reaction)
        end = model.on(start, f"E{k}", L * link.x, link)
    return model.equations()


def cascade_file(n: int, distinct: bool = False) -> str:
    """n disks: the first on a fixed axle, each next one hanging from a cord wound on the right of
    the one above and on its own left (a stack of yo-yos), released from rest."""
    masses, radii = _names("M", n, distinct), _names("R", n, distinct)
    lines = [f"id: disk_cascade_{n}", f"title: A cascade of {n} disks on cords", "topic: torque", "parameters:"]
    _parameters(lines, dict.fromkeys([(m, "mass of a disk", "kg", 0.5, 2) for m in masses]
                                     + [(r, "radius of a disk", "m", 0.05, 0.2) for r in radii]))
    lines += ["  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}", "scene:", "  bodies:"]
    x = y = sp.Integer(0)
    for k in range(n):
        if k:
            x, y = x + sp.Symbol(radii[k - 1]) + sp.Symbol(radii[k]), y - 4 * sp.Symbol(radii[0])
        axle = ", joint: fixed_axle" if k == 0 else ""
        lines.append(f"    disk{k + 1}: {{shape: disk, mass: {masses[k]}, radius: {radii[k]}, "
                     f"at: [{sp.sstr(x)}, {sp.sstr(y)}]{axle}}}")
    if n > 1:
        lines.append("  cords:")
        lines += [f"    cord{k}: [{{wound: disk{k - 1}, side: right}}, {{wound: disk{k}, side: left}}]"
                  for k in range(2, n + 1)]
    lines += ["  loads:", "    - gravity: g", "ask:",
              f"  a: {{meaning: acceleration of the lowest disk, of: disk{n}.acceleration.y, unit: m/s^2}}",
              "  F: {meaning: force of the axle on the top disk, of: axle.reaction.y, unit: N}",
              "question: |", f"  A cascade of {n} disks is released from rest."]
    return "\n".join(lines) + "\n"


def cascade(n: int, distinct: bool = False) -> Model:
    """The same cascade: the disks' turns q_k; disk k's center moves along y with the rim of the
    disk above plus R_k u_k; the axle's reaction and each cord's tension by auxiliary speeds."""
    masses = [sp.Symbol(s, positive=True) for s in _names("M", n, distinct)]
    radii = [sp.Symbol(s, positive=True) for s in _names("R", n, distinct)]
    g = sp.Symbol("g", positive=True)
    model = Model(n, ["R_x^axle", "R_y^axle", *(f"T_cord{k}" for k in range(2, n + 1))], g)
    N, a, f, q, u = model.N, model.aux, model.forces, model.q, model.u
    center = model.point("C1", a["R_x^axle"] * N.x + a["R_y^axle"] * N.y)
    model.load(center, f["R_x^axle"] * N.x + f["R_y^axle"] * N.y)
    frame = None
    for k in range(1, n + 1):
        M, R = masses[k - 1], radii[k - 1]
        if k > 1:
            above = model.on(center, f"right{k - 1}", radii[k - 2] * N.x, frame)
            center = model.point(f"C{k}", (above.vel(N).dot(N.y) + R * u[k - 1] + a[f"T_cord{k}"]) * N.y)
        frame = model.frame(f"disk{k}", q[k - 1], u[k - 1])
        model.rigid(f"disk{k}", center, frame, M, M * R**2 / 2)
        if k > 1:
            left = model.on(center, f"left{k}", -R * N.x, frame)
            model.load(left, f[f"T_cord{k}"] * N.y)
            model.load(above, -f[f"T_cord{k}"] * N.y)
    return model.equations()


# --- the table --------------------------------------------------------------------------------

@dataclass(frozen=True)
class Anchor:
    """A benchmark scene: derive's problem (a library id, or a problem file's text) and the same
    scene by KanesMethod (`build` forms the equations; `extra` computes what else the problem
    asks from the built model)."""

    id: str
    source: str | Callable[[], str]
    build: Callable[[], Model]
    extra: Callable[[Model], dict] | None = None

    def text(self) -> str | None:
        """The problem file's text for a scene written here; None for a library id."""
        source = self.source() if callable(self.source) else self.source
        return source if "\n" in source else None

    def reference(self, folder) -> str:
        """What `derive.problem.load` reads: the library id, or the scene's file written to `folder`."""
        text = self.text()
        if text is None:
            return self.source
        path = Path(folder) / f"{self.id}.yaml"
        path.write_text(text)
        return str(path)

    def run(self) -> dict:
        """What is timed: the model, Kane's equations, their solution at the reference
        configuration at rest, and the extra answers."""
        model = self.build()
        result = model.solve()
        if self.extra is not None:
            result.update(self.extra(model))
        return result


def _omega(model: Model) -> dict:
    return {"omega^2": model.omega_squared()}


def _loop_heights(model: Model) -> dict:
    R, r = _symbols("R radius_ball")
    return {"h_slide": release_height(model, 0, "cart", R, 0),
            "h_roll": release_height(model, 1, "ball", R, r, small=True)}


def _ball_height(model: Model) -> dict:
    R, r = _symbols("R r")
    return {"h_roll": release_height(model, 0, "ball", R, r)}


_DOUBLE = dict(n=2, distinct=True, angles=[0, -sp.pi / 2])

SCENES = {a.id: a for a in (
    Anchor("string_wrapped_disk", "string_wrapped_disk", string_wrapped_disk),
    Anchor("tugged_spool", "tugged_spool", tugged_spool),
    Anchor("compound_pendulum", "compound_pendulum", compound_pendulum, _omega),
    Anchor("tightrope_walker", "tightrope_walker", tightrope_walker, _omega),
    Anchor("rolling_incline", "rolling_incline", rolling_incline),
    Anchor("incline_race", "incline_race", incline_race),
    Anchor("loop_the_loop", "loop_the_loop", loop_the_loop, _loop_heights),
    Anchor("loop_the_loop_ball", "loop_the_loop_ball", loop_the_loop_ball, _ball_height),
    Anchor("atwood", ATWOOD, atwood),
    Anchor("double_pendulum", lambda: pendulum_chain_file(**_DOUBLE).replace("pendulum_chain_2", "double_pendulum"),
           lambda: pendulum_chain(**_DOUBLE)),
    Anchor("yo_yo", lambda: cascade_file(2, distinct=True).replace("disk_cascade_2", "yo_yo"),
           lambda: cascade(2, distinct=True)),
    Anchor("cart_pendulum", CART_PENDULUM, cart_pendulum),
    Anchor("table_pulley", TABLE_PULLEY, table_pulley),
)}

#: A shorter run (`derive bench --quick`): a scene of each kind of part.
QUICK = ("string_wrapped_disk", "compound_pendulum", "rolling_incline", "atwood", "cart_pendulum")

#: Chains for the growth with n: (file, anchor model) by kind.
CHAINS = {
    "pendulum links": (pendulum_chain_file, pendulum_chain),
    "disks on cords": (cascade_file, cascade),
}
