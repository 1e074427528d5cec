"""A rigid body turning at a constant rate about a fixed axis through its center of mass, held
by bearings (notes §3.5: L = I·ω need not lie along ω, and the bearings must turn it).

The shaft is the z axis of the ground frame N. The body's own axis (a rod's length, a
composite's x, the symmetry axis z of every other shape) is tilted by `tilt` from the shaft
toward +x, the body first turned by `roll` about that axis; vectors are given in N at the
instant the own axis lies in N's xz plane. Three routes, by sympy.physics.mechanics:

- Newton–Euler: the body frame turned about N.z by the spin angle phi(t), L = I·ω about the
  center (the inertia dyadic from derive.inertia's tensor), the bearings' torque tau = dL/dt
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
"""
from __future__ import annotations

from functools import lru_cache

import sympy as sp
from sympy.physics import mechanics as me

from derive import inertia
from derive.mechanics.derivation import tidy

ROUTES = ("newton_euler", "lagrange")


def own_axis(shape: str) -> str:
    """The body axis the tilt is measured from: x for a rod (its length) or a composite (its
    parts' frame), z (the symmetry axis) for every other shape."""
    return "x" if shape in ("rod", "composite") else "z"


def body_tensor(shape: str, mass, sizes: dict, parts: dict | None = None) -> sp.ImmutableMatrix:
    """The inertia tensor about the center of mass in the body's own frame; a composite's
    `parts` (derive.composite: name -> (shape, mass, sizes, (x, y), angle)) composed in 3D."""
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


def _dyadic(frame: me.ReferenceFrame, tensor: sp.Matrix) -> me.Dyadic:
    return me.inertia(frame, tensor[0, 0], tensor[1, 1], tensor[2, 2], tensor[0, 1], tensor[1, 2], tensor[0, 2])


@lru_cache(maxsize=None)
def motion(tensor: sp.ImmutableMatrix, rate, tilt, roll, axis: str, route: str) -> dict:
    """{"angular_momentum": L, "torque": tau (columns in N), "kinetic_energy": T} by one route."""
    t = me.dynamicsymbols._t
    ground = me.ReferenceFrame("N")
    center = me.Point("O")
    center.set_vel(ground, 0)
    if route == "newton_euler":
        phi = me.dynamicsymbols("phi")
        body_frame = _mounted(ground.orientnew("S", "Axis", [phi, ground.z]), tilt, roll, axis)
        body = me.RigidBody("body", center, body_frame, 1, (_dyadic(body_frame, tensor), center))
        now = {phi.diff(t, 2): 0, phi.diff(t): rate, phi: 0}
        momentum = body.angular_momentum(center, ground)
        vectors = [momentum, momentum.dt(ground)]
        columns = [sp.Matrix([v.dot(e) for e in ground]).subs(now) for v in vectors]
        energy = body.kinetic_energy(ground).subs(now)
    else:
        q = me.dynamicsymbols("q1:4")
        free = ground.orientnew("A", "Body", [q[2], q[1], q[0]], "ZYX")
        body_frame = _mounted(free, tilt, roll, axis)
        body = me.RigidBody("body", center, body_frame, 1, (_dyadic(body_frame, tensor), center))
        lagrangian = me.Lagrangian(ground, body)
        method = me.LagrangesMethod(lagrangian, q, hol_coneqs=[q[0], q[1], q[2] - rate * t], frame=ground)
        method.form_lagranges_equations()
        now = {**{c.diff(t): 0 for c in q[:2]}, q[2].diff(t): rate, **{c: 0 for c in q}}
        multipliers = method.solve_multipliers(now)
        # sympy's equations carry the constraints' generalized forces as -lambda
        generalized = sp.Matrix([-multipliers[lam] for lam in method.lam_vec])
        momenta = sp.Matrix([lagrangian.diff(c.diff(t)) for c in q]).subs(now)
        omega = body_frame.ang_vel_in(ground)
        partials = sp.Matrix([[omega.diff(c.diff(t), ground).dot(e) for e in ground] for c in q]).subs(now)
        columns = [partials.solve(momenta), partials.solve(generalized)]
        energy = lagrangian.subs(now)
    momentum, torque = (c.applyfunc(tidy) for c in columns)
    return {"angular_momentum": momentum, "torque": torque, "kinetic_energy": tidy(energy)}


@lru_cache(maxsize=None)
def angular_momentum_by_integral(shape: str, mass, sizes: tuple, rate, tilt, roll) -> sp.Matrix:
    """L = integral of r x (omega x r) dm over a uniform shape's elements, turned as mounted."""
    shape_data = inertia.SHAPES[shape]
    mapping = {generic: dict(sizes)[name] for name, generic in shape_data.sizes.items()}
    ground = me.ReferenceFrame("N")
    body_frame = _mounted(ground, tilt, roll, own_axis(shape))
    element = sum((c * e for c, e in zip(sp.Matrix(shape_data.position).xreplace(mapping), body_frame)), me.Vector(0))
    position = element.to_matrix(ground)
    omega = sp.Matrix([0, 0, rate])
    limits = [(c, sp.sympify(lo).xreplace(mapping), sp.sympify(hi).xreplace(mapping))  # safe: the module's own limits
              for c, lo, hi in reversed(shape_data.coordinates)]
    measure = shape_data.element.xreplace(mapping)
    total = sp.integrate(measure, *limits) if limits else sp.Integer(1)
    integrand = (mass / total) * measure * position.cross(omega.cross(position))
    return integrand.applyfunc(lambda e: tidy(sp.integrate(sp.expand(e), *limits) if limits else e))


def quantity(found: dict, detail: str, tilt, apart=None) -> sp.Expr:
    """One quantity a file may ask (derive.scene.BEARING_QUANTITIES) from a route's `motion`: a
    component, a magnitude, the angle between L and omega (along +z), the kinetic energy, or the
    force of each bearing of a pair `apart` that supplies the torque across the shaft.

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
    if detail == "angle_L_omega":
        return sp.acos(tidy(momentum[2] / length(momentum)))
    if detail == "bearings.force":
        return tidy(length(torque[:2, 0]) / apart)
    head, _, component = detail.rpartition(".")
    vector = torque if head == "bearings.torque" else momentum
    return length(vector) if component == "magnitude" else vector["xyz".index(component)]
