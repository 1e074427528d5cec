"""A rigid body turning at a constant rate about a fixed axis, through its center of mass or not, held
by bearings (notes §3.5: L = I·ω need not lie along ω, and the bearings must turn it).

The shaft is the z axis of the ground frame N. The body's own axis (a rod's length, a
composite's x, the symmetry axis z of every other shape) is tilted by `tilt` from the shaft
toward +x, the body first turned by `roll` about that axis; vectors are given in N at the
instant the own axis lies in N's xz plane. Three routes, by sympy.physics.mechanics:

- Newton–Euler: the body frame turned about N.z by the spin angle phi(t), L = I·ω about the
  center (the inertia dyadic from derive.model.inertia's tensor), the bearings' torque tau = dL/dt
  (the time derivative in N), the kinetic energy of the RigidBody;
- Lagrange: the body free to turn by body-fixed angles q3, q2, q1 (about z, y, x) ahead of its
  mounting; the bearings hold q1 = q2 = 0 and turn q3 = omega t (LagrangesMethod with
  hol_coneqs). Their multipliers are the torque's generalized components and the momenta
  dT/dq' those of L, both along the partial angular velocities;
- integral (L only): L = integral of r x (omega x r) dm over the body's elements.

>>> m, l, w, a = sp.symbols("m L omega alpha", positive=True)
>>> rod = body_tensor("rod", m, {"length": l})
>>> motion(rod, w, a, 0, "x", "newton_euler")["torque"][1]
-L**2*m*omega**2*sin(2*alpha)/24

A shaft through a point of the body off its center of mass (`through`, in the body's own frame)
must also give the center its centripetal acceleration, F = m a_cm, and under gravity hold the
weight; the bearings, `apart` either side of that point, share both by the statics of the shaft
(Newton–Euler: moments about each bearing; Lagrange: the shaft point's coordinates held too, their
multipliers the force). A disk on a level shaft through a point e from its center:

>>> e, g, d = sp.symbols("e g d", positive=True)
>>> found = motion(body_tensor("disk", m, {"radius": l}), w, 0, 0, "z", "lagrange", m, (e, 0, 0), (0, -g, 0), d)
>>> found["force"].T, found["bearing.A"].T, found["drive"]
(Matrix([[e*m*omega**2, g*m, 0]]), Matrix([[e*m*omega**2/2, g*m/2, 0]]), -e*g*m)
"""
from __future__ import annotations

from functools import lru_cache

import sympy as sp
from sympy.physics import mechanics as me

from derive.model import inertia
from derive.core.tidying import tidy
from derive.model.solid_scene import own_axis

ROUTES = ("newton_euler", "lagrange")


def body_tensor(shape: str, mass, sizes: dict, parts: dict | None = None) -> sp.ImmutableMatrix:
    """The inertia tensor about the center of mass in the body's own frame; a composite's
    `parts` (derive.model.composite: name -> (shape, mass, sizes, (x, y), angle)) composed in 3D."""
    if parts is not None:
        placed = [inertia.Part(s, m, z, (x, y, 0), sp.rot_axis3(-angle))
                  for s, m, z, (x, y), angle in parts.values()]
        return inertia.composite_tensor(placed).tensor
    generic = inertia.SHAPES[shape]
    return inertia.tensor(shape).xreplace({inertia.M: mass, **{generic.sizes[k]: v for k, v in sizes.items()}})


def _mounted(frame: me.ReferenceFrame, tilt, roll, axis: str) -> me.ReferenceFrame:
    """The body frame: the own axis turned by `roll` about itself, then tilted from frame.z
    toward frame.x by `tilt` (a turn about frame.y)."""
    tilted = frame.orientnew("C", "Axis", [tilt - sp.pi / 2 if axis == "x" else tilt, frame.y])
    return tilted.orientnew("B", "Axis", [roll, getattr(tilted, axis)])


def mounted_axes(tilt, roll, axis: str) -> sp.Matrix:
    """The body's own axes in N (the columns) at the instant its own axis lies in N's xz plane.

    >>> mounted_axes(sp.pi / 2, 0, "z").tolist()  # the symmetry axis z tilted a right angle, to N.x
    [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]
    """
    ground = me.ReferenceFrame("N")
    return ground.dcm(_mounted(ground, tilt, roll, axis))


def center_offset(tilt, roll, axis: str, through) -> sp.Matrix:
    """Where the center of mass is from the shaft's point `through` (in the body's own frame), in N
    at the instant the own axis lies in N's xz plane.

    >>> e = sp.Symbol("e", positive=True)
    >>> center_offset(sp.pi / 2, 0, "x", (e, 0, 0)).T
    Matrix([[-e, 0, 0]])
    """
    ground = me.ReferenceFrame("N")
    body_frame = _mounted(ground, tilt, roll, axis)
    return -_column(ground, _along(body_frame, through))


def own_axes(tilt, roll, axis: str) -> sp.Matrix:
    """The body's own x, y, z (columns) in N at the instant the own axis lies in N's xz plane.

    >>> own_axes(sp.pi / 2, 0, "z")[:, 2].T  # the symmetry axis tilted a right angle: along N.x
    Matrix([[1, 0, 0]])
    """
    ground = me.ReferenceFrame("N")
    return sp.Matrix.hstack(*(_column(ground, e) for e in _mounted(ground, tilt, roll, axis)))


def _dyadic(frame: me.ReferenceFrame, tensor: sp.Matrix) -> me.Dyadic:
    return me.inertia(frame, tensor[0, 0], tensor[1, 1], tensor[2, 2], tensor[0, 1], tensor[1, 2], tensor[0, 2])


def _column(frame: me.ReferenceFrame, vector: me.Vector) -> sp.Matrix:
    """A vector's components along a frame's axes."""
    return sp.Matrix([vector.dot(e) for e in frame])


def _along(frame: me.ReferenceFrame, components) -> me.Vector:
    """The vector of these components along a frame's axes."""
    return sum((c * e for c, e in zip(components, frame)), me.Vector(0))


def by_moments(torque: sp.Matrix, force: sp.Matrix, center: sp.Matrix, apart, thrust) -> dict:
    """Newton–Euler's statics of the shaft (the z axis, bearing A at z = apart/2 and B at -apart/2
    from the shaft's point at the origin): the supports' moment about each bearing is the torque
    about the center of mass plus (center - bearing) x force, and only the other bearing's force
    across the shaft has a moment about it, so F_A = (M_B / apart) x z, F_B = -(M_A / apart) x z;
    what is left about the shaft is the drive's couple. The thrust bearing takes the force along it."""
    z = sp.Matrix([0, 0, 1])
    found = {"drive": (torque + center.cross(force))[2]}  # the same about every point of the shaft
    if apart is not None:
        about = {end: torque + (center - sign * apart / 2 * z).cross(force) for end, sign in (("A", 1), ("B", -1))}
        across = {"A": about["B"].cross(z) / apart, "B": -about["A"].cross(z) / apart}
        for end in "AB":
            found[f"bearing.{end}"] = across[end] + (force[2] * z if thrust == end else sp.zeros(3, 1))
    return found


def _by_halves(moment: sp.Matrix, force: sp.Matrix, apart, thrust) -> dict:
    """Lagrange's split of the shaft's supports, from their total force and their moment about the
    shaft's point midway between the bearings: each bearing takes half the force across the shaft,
    and the pair a couple (M x z)/apart either way; the moment's z is the drive's couple."""
    z = sp.Matrix([0, 0, 1])
    found = {"drive": moment[2]}
    if apart is not None:
        half, couple = force.multiply_elementwise(sp.Matrix([1, 1, 0])) / 2, moment.cross(z) / apart
        for end, sign in (("A", 1), ("B", -1)):
            found[f"bearing.{end}"] = half + sign * couple + (force[2] * z if thrust == end else sp.zeros(3, 1))
    return found


@lru_cache(maxsize=None)
def motion(tensor: sp.ImmutableMatrix, rate, tilt, roll, axis: str, route: str, mass=0, through=(0, 0, 0),
           gravity=(0, 0, 0), apart=None, thrust=None, turned=0) -> dict:
    """{"angular_momentum": L about the center of mass, "torque": tau = dL/dt, what the supports
    supply about the center, "force": their total force, "drive": the couple about the shaft that
    keeps the rate (columns in N), "kinetic_energy": T}, and with `apart` each bearing's force,
    "bearing.A" (at z = apart/2 from the shaft's point) and "bearing.B", by one route. The shaft
    (N.z) passes through the body's point `through` (from the center of mass, in the body's own
    frame); `gravity` is g's vector in N; `thrust` names the bearing that takes the force along
    the shaft (None: there is none); `turned`, the rate at which the shaft itself turns about N.y
    (a ship's turbine as the ship turns), vectors then at the instant the shaft lies along N.z."""
    t = me.dynamicsymbols._t
    ground = me.ReferenceFrame("N")
    origin = me.Point("O")
    origin.set_vel(ground, 0)
    weight = mass * sp.Matrix(gravity)
    if route == "newton_euler":
        phi, psi = me.dynamicsymbols("phi psi")
        ship = ground.orientnew("T", "Axis", [psi, ground.y])  # the shaft's own turn
        body_frame = _mounted(ship.orientnew("S", "Axis", [phi, ship.z]), tilt, roll, axis)
        center = origin.locatenew("C", -_along(body_frame, through))
        center.v2pt_theory(origin, ground, body_frame)
        body = me.RigidBody("body", center, body_frame, mass, (_dyadic(body_frame, tensor), center))
        now = {phi.diff(t, 2): 0, phi.diff(t): rate, phi: 0, psi.diff(t, 2): 0, psi.diff(t): turned, psi: 0}
        momentum = body.angular_momentum(center, ground)
        acceleration = center.a2pt_theory(origin, ground, body_frame)
        momentum, torque, acceleration, position = (_column(ground, v).subs(now) for v in (
            momentum, momentum.dt(ground), acceleration, center.pos_from(origin)))
        energy = body.kinetic_energy(ground).subs(now)
        force = mass * acceleration - weight  # the supports' force and the weight give m a_cm
    else:
        q = me.dynamicsymbols("q1:4")
        s = me.dynamicsymbols("s1:4")  # where the shaft's point is
        ship = ground.orientnew("T", "Axis", [turned * t, ground.y])  # the shaft's own turn, prescribed
        free = ship.orientnew("A", "Body", [q[2], q[1], q[0]], "ZYX")
        body_frame = _mounted(free, tilt, roll, axis)
        point = origin.locatenew("P", _along(ground, s))
        center = point.locatenew("C", -_along(body_frame, through))
        center.set_vel(ground, center.pos_from(origin).dt(ground))
        body = me.RigidBody("body", center, body_frame, mass, (_dyadic(body_frame, tensor), center))
        body.potential_energy = -sp.Matrix(gravity).dot(_column(ground, center.pos_from(origin))) * mass
        lagrangian = me.Lagrangian(ground, body)
        coordinates = [*q, *s]
        method = me.LagrangesMethod(lagrangian, coordinates, hol_coneqs=[q[0], q[1], q[2] - rate * t, *s],
                                    frame=ground)
        method.form_lagranges_equations()
        now = {**{c.diff(t): 0 for c in [*q[:2], *s]}, q[2].diff(t): rate, **{c: 0 for c in coordinates}, t: 0}
        multipliers = method.solve_multipliers(now)
        # sympy's equations carry the constraints' generalized forces as -lambda
        generalized = sp.Matrix([-multipliers[lam] for lam in method.lam_vec])
        momenta = sp.Matrix([lagrangian.diff(c.diff(t)) for c in coordinates]).subs(now)
        omega = body_frame.ang_vel_in(ground)
        partials = sp.Matrix([[omega.diff(c.diff(t), ground).dot(e) for e in ground] for c in q]).subs(now)
        position = _column(ground, center.pos_from(point)).subs(now)
        momentum = partials.solve(momenta[:3, 0]) - position.cross(momenta[3:, 0])  # about P, less m r x v
        # T = (p . q' + omega_turn . L)/2: quadratic in the rates, the shaft's turn (its center on it) one of them
        energy = (sum(p * c.diff(t) for p, c in zip(momenta, coordinates)).subs(now) + turned * momentum[1]) / 2
        force = generalized[3:, 0]  # along the shaft point's partial velocities, N's axes
        moment = partials.solve(generalized[:3, 0])  # the supports' about the shaft's point
        torque = moment - position.cross(force)

    # tidied in this order, L and the torque first: sympy's caches make the later forms depend on it
    momentum, torque = (c.applyfunc(tidy) for c in (momentum, torque))
    energy, force, position = tidy(energy), force.applyfunc(tidy), position.applyfunc(tidy)
    split = (by_moments(torque, force, position, apart, thrust) if route == "newton_euler"
             else _by_halves(moment.applyfunc(tidy), force, apart, thrust))
    split = {k: v.applyfunc(tidy) if isinstance(v, sp.MatrixBase) else tidy(v) for k, v in split.items()}
    return {"angular_momentum": momentum, "torque": torque, "kinetic_energy": energy, "force": force, **split}


@lru_cache(maxsize=None)
def angular_momentum_by_integral(shape: str, mass, sizes: tuple, rate, tilt, roll, turned=0) -> sp.Matrix:
    """L = integral of r x (omega x r) dm over a uniform shape's elements, turned as mounted; omega is
    the rate about the shaft N.z plus the shaft's own turn about N.y."""
    shape_data = inertia.SHAPES[shape]
    mapping = {generic: dict(sizes)[name] for name, generic in shape_data.sizes.items()}
    ground = me.ReferenceFrame("N")
    body_frame = _mounted(ground, tilt, roll, own_axis(shape))
    element = _along(body_frame, sp.Matrix(shape_data.position).xreplace(mapping))
    position = element.to_matrix(ground)
    omega = sp.Matrix([0, turned, rate])
    limits = [(c, sp.sympify(lo).xreplace(mapping), sp.sympify(hi).xreplace(mapping))  # safe: the module's own limits
              for c, lo, hi in reversed(shape_data.coordinates)]
    measure = shape_data.element.xreplace(mapping)
    total = sp.integrate(measure, *limits) if limits else sp.Integer(1)
    integrand = (mass / total) * measure * position.cross(omega.cross(position))
    return integrand.applyfunc(lambda e: tidy(sp.integrate(sp.expand(e), *limits) if limits else e))


#: The vectors a file may ask of a body in bearings (derive.model.solid_scene.BEARING_QUANTITIES), by the key
#: `motion` gives each.
VECTORS = {"angular_momentum": "angular_momentum", "bearings.torque": "torque", "bearings.total_force": "force",
           "bearings.A.force": "bearing.A", "bearings.B.force": "bearing.B"}


def quantity(found: dict, detail: str, tilt, apart=None) -> sp.Expr:
    """One quantity a file may ask (derive.model.solid_scene.BEARING_QUANTITIES) from a route's `motion`: a
    component or magnitude of a vector (VECTORS), the angle between L and omega (along +z), the
    kinetic energy, the drive's couple about the shaft, or the force of each bearing of a pair
    `apart` that supplies the torque across the shaft where the supports exert no net force.

    >>> m, l, w, a = sp.symbols("m L omega alpha", positive=True)
    >>> found = motion(body_tensor("rod", m, {"length": l}), w, a, 0, "x", "lagrange")
    >>> quantity(found, "angle_L_omega", a)
    acos(sin(alpha))
    """
    momentum, torque = found["angular_momentum"], found["torque"]

    def length(vector: sp.Matrix) -> sp.Expr:  # the reader keeps the tilt in [0, pi]: sin(tilt) >= 0
        return sp.refine(tidy(sp.sqrt(vector.dot(vector))), sp.Q.nonnegative(sp.sin(tilt)))

    if detail == "kinetic_energy":
        return found["kinetic_energy"]
    if detail == "bearings.drive_torque":
        return found["drive"]
    if detail == "angle_L_omega":
        return sp.acos(tidy(momentum[2] / length(momentum)))
    if detail == "bearings.force":
        return tidy(length(torque[:2, 0]) / apart)
    head, _, component = detail.rpartition(".")
    vector = found[VECTORS[head]]
    return length(vector) if component == "magnitude" else vector["xyz".index(component)]
