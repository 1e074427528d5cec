"""A thin axially symmetric body (a coin, a disk, a hoop) rolling without slipping on its rim on
a horizontal plane: nonholonomic, 3D (Routh's rolling disk; Kleppner & Kolenkow ch. 8, the
rolling coin; Morin ch. 9).

The coin frame follows sympy's rolling disc: the heading frame Y turned about the vertical N.z
by psi, the lean frame L turned about the heading Y.x by the lean theta (from the vertical), the
coin turned about its symmetry axis L.y by phi; the center of mass G is a above the contact
point P, along L.z. I1 is the moment about a diameter through G, I3 about the symmetry axis (the
inertia dyadic is the same in L as in the coin's frame, so no spin angle enters the equations).
Three routes give the equations of motion in (psi, theta, phi), in Lagrange's form (the generalized
speeds are the rates q'):

- lagrange: LagrangesMethod in (psi, theta, phi) and G's x, y, z, the height z = a cos(theta) a
  holonomic constraint and v_P = 0 along the ground two nonholonomic ones; the multipliers, found
  from the equations of x, y, z, are the contact force, and the constraints give G's rates;
- kane: KanesMethod with G's velocity as three dependent speeds and the rolling constraints
  v_P = 0 as velocity constraints, -(Fr + Fr*); the contact force by auxiliary speeds at P;
- newton_euler: dH_G/dt = r_GP x F about the center of mass with the contact force from Newton's
  law, F = m a_G + m g z, a_G the derivative of v_G = omega x r_PG, projected on d omega/d q'_i.

Their consequences, each read from one route's own equations and kinematics:

- steady motion on a circle: lean theta fixed, heading turning at Omega, the contact point on a
  circle of radius `circle` about a vertical axis on the side the coin leans to; the lean
  equation gives Omega^2, the rolling kinematics the spin and the speed, the contact force F;
- upright rolling in a straight line at the speed v = a omega: the lean and heading equations
  linearized about it, stable where the lean's characteristic roots are imaginary.

>>> m, g, a = sp.symbols("m g a", positive=True)
>>> min_speed(m * a**2 / 4, m * a**2 / 2, m, g, a, "kane")  # a uniform disk: v^2 > g a/3
sqrt(3)*sqrt(a)*sqrt(g)/3
"""
from __future__ import annotations

from functools import lru_cache

import sympy as sp
from sympy.physics import mechanics as me

from derive.text.steps import Step
from derive.core.tidying import tidy

ROUTES = ("lagrange", "kane", "newton_euler")
#: What a steady motion on a circle gives (each a magnitude; `friction` points to the circle's axis).
STEADY = ("precession", "speed", "spin", "normal_force", "friction")
OMEGA = sp.Symbol("Omega", positive=True)  # the heading's rate in the steady motion
S = sp.Symbol("s")  # the exponent of a small motion, e^(s t)
SPIN = sp.Symbol("omega", positive=True)  # the spin of upright rolling
_T = me.dynamicsymbols._t


def _frames(psi, theta, phi):
    """The ground N, the heading Y, the lean L and the coin frame B."""
    ground = me.ReferenceFrame("N")
    heading = ground.orientnew("Y", "Axis", [psi, ground.z])
    lean = heading.orientnew("L", "Axis", [theta, heading.x])
    return ground, heading, lean, lean.orientnew("B", "Axis", [phi, lean.y])


def _coordinates():
    """The heading, the lean and the spin angle (named apart from a file's parameters, theta or phi)."""
    return me.dynamicsymbols("psi_coin theta_coin phi_coin")


def _kane(I1, I3, mass, g, radius):
    """KanesMethod's equations with the rolling constraints, and the contact force's components
    in L by auxiliary speeds at P, both with u = q' and G's dependent speeds eliminated."""
    q = _coordinates()
    u, v, aux = me.dynamicsymbols("u1:4"), me.dynamicsymbols("v1:4"), me.dynamicsymbols("w1:4")
    force = sp.symbols("F_1:4")
    ground, heading, lean, coin = _frames(*q)
    coin.set_ang_vel(ground, coin.ang_vel_in(ground).xreplace({c.diff(_T): s for c, s in zip(q, u)}))
    center = me.Point("G")
    center.set_vel(ground, sum((s * e for s, e in zip(v, lean)), me.Vector(0)))
    contact = center.locatenew("P", -radius * lean.z)
    contact.v2pt_theory(center, ground, coin)
    rolling = [contact.vel(ground).dot(e) for e in lean]  # the coin's point at P does not move
    shift = sum((s * e for s, e in zip(aux, lean)), me.Vector(0))  # auxiliary: the contact force's work
    center.set_vel(ground, center.vel(ground) + shift)
    contact.set_vel(ground, contact.vel(ground) + shift)
    body = me.RigidBody("coin", center, coin, mass, (me.inertia(lean, I1, I3, I1), center))
    method = me.KanesMethod(ground, q_ind=q, u_ind=u, u_dependent=v, kd_eqs=[c.diff(_T) - s for c, s in zip(q, u)],
                            velocity_constraints=rolling, u_auxiliary=aux)
    loads = [(center, -mass * g * ground.z), (contact, sum((f * e for f, e in zip(force, lean)), me.Vector(0)))]
    active, inertial = method.kanes_equations([body], loads)
    back = {**{s.diff(_T): c.diff(_T, 2) for c, s in zip(q, u)}, **{s: c.diff(_T) for c, s in zip(q, u)}}
    dependent = {k: e.xreplace(back) for k, e in sp.solve(rolling, v, dict=True)[0].items()}
    dependent = {**{k.diff(_T): e.diff(_T) for k, e in dependent.items()}, **dependent}

    def eliminate(e):
        return e.xreplace(back).xreplace(dependent).xreplace(back)

    equations = (-(active + inertial))[:3, :].applyfunc(lambda e: sp.expand(eliminate(e)))  # then the auxiliary rows
    contact_force = [sp.solve(eliminate(e), f)[0] for e, f in zip(method.auxiliary_eqs, force)]
    velocity = sum((dependent[s] * e for s, e in zip(v, lean)), me.Vector(0))
    return (equations, coin.ang_vel_in(ground).xreplace(back), velocity,
            sum((f * e for f, e in zip(contact_force, lean)), me.Vector(0)), (ground, heading, lean))


def _lagrange(I1, I3, mass, g, radius):
    """LagrangesMethod with the rolling constraints as multipliers: the angles' equations with the
    multipliers and G's rates eliminated, and the contact force, the multipliers' generalized forces
    along G's x, y and z."""
    q = _coordinates()
    place = me.dynamicsymbols("x_coin y_coin z_coin")
    ground, heading, lean, coin = _frames(*q)
    origin = me.Point("O")
    origin.set_vel(ground, 0)
    center = origin.locatenew("G", sum((c * e for c, e in zip(place, ground)), me.Vector(0)))
    center.set_vel(ground, center.pos_from(origin).dt(ground))
    contact = center.locatenew("P", -radius * lean.z)
    contact.v2pt_theory(center, ground, coin)
    body = me.RigidBody("coin", center, coin, mass, (me.inertia(lean, I1, I3, I1), center))
    body.potential_energy = mass * g * place[2]
    height = place[2] - radius * sp.cos(q[1])
    rolling = [contact.vel(ground).dot(ground.x), contact.vel(ground).dot(ground.y)]
    method = me.LagrangesMethod(me.Lagrangian(ground, body), [*q, *place], hol_coneqs=[height],
                                nonhol_coneqs=rolling, frame=ground)
    rows = method.form_lagranges_equations()
    rates = sp.solve([*rolling, height.diff(_T)], [c.diff(_T) for c in place], dict=True)[0]
    rates = {**{k.diff(_T): e.diff(_T) for k, e in rates.items()}, **rates}  # in the angles alone
    multipliers = sp.solve(list(rows[3:, 0]), list(method.lam_vec), dict=True)[0]

    def eliminate(e):
        return sp.expand(e.xreplace(multipliers).xreplace(rates))

    equations = rows[:3, :].applyfunc(eliminate)
    generalized = method.lam_coeffs.T * method.lam_vec  # rows - (d/dt dL/dq' - dL/dq) = -these
    force = sum((eliminate(generalized[3 + i]) * e for i, e in enumerate(ground)), me.Vector(0))
    velocity = sum((rates[c.diff(_T)] * e for c, e in zip(place, ground)), me.Vector(0))
    return equations, coin.ang_vel_in(ground), velocity, force, (ground, heading, lean)


def _newton_euler(I1, I3, mass, g, radius):
    """Euler's equations about the center of mass with the contact force from Newton's law."""
    q = _coordinates()
    ground, heading, lean, coin = _frames(*q)
    omega = coin.ang_vel_in(ground)
    velocity = omega.cross(radius * lean.z)  # v_G = omega x r_PG: P at rest
    force = mass * velocity.dt(ground) + mass * g * heading.z  # on the coin at P (N.z is Y.z)
    momentum = me.inertia(lean, I1, I3, I1).dot(omega)
    balance = momentum.dt(ground) - (-radius * lean.z).cross(force)
    equations = sp.Matrix([balance.dot(omega.diff(c.diff(_T), ground)) for c in q]).applyfunc(sp.expand)
    return equations, omega, velocity, force, (ground, heading, lean)


@lru_cache(maxsize=None)
def motion(I1, I3, mass, g, radius, route: str) -> dict:
    """By one route: the equations of motion d/dt dL/dq' - dL/dq = 0 in Lagrange's form (comparable
    term by term), the coin's angular velocity, v_G, the contact force on the coin and the frames
    (N, Y, L)."""
    found = {"lagrange": _lagrange, "kane": _kane, "newton_euler": _newton_euler}[route](I1, I3, mass, g, radius)
    return dict(zip(("equations", "omega", "velocity", "force", "frames"), found))


@lru_cache(maxsize=None)
def steady(I1, I3, mass, g, radius, tilt, circle, route: str) -> dict:
    """The steady motion on a circle by one route, each a magnitude: {precession, speed, spin (omega
    along the axis), normal_force, friction (toward the axis)}; and `squared`, Omega^2, positive
    where the center lies inside the circle (the caller's condition), `spin_rate`, phi' in terms of
    Omega, and `tangential`, the contact force along the heading (zero)."""
    found = motion(I1, I3, mass, g, radius, route)
    ground, heading, lean = found["frames"]
    rate = sp.Symbol("phi_dot", real=True)
    now = {**{c.diff(_T, 2): 0 for c in _coordinates()}, **_steady_angles(tilt, OMEGA, rate)}

    def steady_value(vector, direction):  # a component in the steady motion, Omega and the spin open
        return me.msubs(vector.dot(direction), now)

    inward = circle - radius * sp.sin(tilt)  # G's distance from the axis, which is at P - circle Y.y
    wanted = -OMEGA * inward  # v_G along Y.x: Omega N.z x (G - axis)
    spin_rate = {rate: sp.solve(steady_value(found["velocity"], heading.x) - wanted, rate)[0]}
    lean_equation = me.msubs(found["equations"][1], now).subs(spin_rate)  # A Omega^2 + B
    weight_term = lean_equation.subs(OMEGA, 0)
    squared = sp.simplify(tidy(-weight_term / tidy((lean_equation - weight_term) / OMEGA**2)))
    at_rate = {OMEGA: sp.sqrt(squared)}

    def value(vector, direction):
        return steady_value(vector, direction).subs(spin_rate).subs(at_rate)

    found = {"precession": sp.sqrt(squared), "speed": OMEGA * inward, "normal_force": value(found["force"], ground.z),
             "spin": -value(found["omega"], lean.y),  # a omega3 Y.x = v_G = -Omega inward Y.x
             "friction": -value(found["force"], heading.y), "tangential": value(found["force"], heading.x)}
    return {"squared": squared, "spin_rate": tidy(spin_rate[rate]),
            **{k: sp.simplify(tidy(v.subs(at_rate))) for k, v in found.items()}}


def _in_ground(found: dict, now: dict) -> dict:
    """omega, L about G (I1, I3 in the lean frame), v_G and the lean frame's axes (columns) in N at
    the instant the heading is N.x (psi = 0), the coordinates and rates at `now`."""
    ground, _, lean = found["frames"]
    at = {**now, _coordinates()[0]: 0}

    def column(vector):
        return sp.Matrix([tidy(me.msubs(vector.dot(e), at)) for e in ground])

    return {"omega": column(found["omega"]), "velocity": column(found["velocity"]), "lean": lean,
            "momentum": column(me.inertia(lean, found["I1"], found["I3"], found["I1"]).dot(found["omega"])),
            "axes": sp.Matrix.hstack(*(column(e) for e in lean)), "column": column}


def steady_vectors(I1, I3, mass, g, radius, tilt, circle, route: str = "lagrange") -> dict:
    """The steady motion on a circle (`steady`) at the instant the heading is N.x, in N: omega, L
    about G, v_G, the lean frame's axes (columns: the heading, the symmetry axis, P to G), G from
    the contact point P and the circle's center from P.

    >>> m, g, a, R, th = sp.symbols("m g a R theta", positive=True)
    >>> found = steady_vectors(m * a**2 / 4, m * a**2 / 2, m, g, a, th, R)
    >>> found["center"].T, found["axis"].T
    (Matrix([[0, -a*sin(theta), a*cos(theta)]]), Matrix([[0, -R, 0]]))
    """
    found = {**motion(I1, I3, mass, g, radius, route), "I1": I1, "I3": I3}
    rates = steady(I1, I3, mass, g, radius, tilt, circle, route)
    spin_rate = rates["spin_rate"].subs(OMEGA, rates["precession"])
    now = {**{c.diff(_T, 2): 0 for c in _coordinates()}, **_steady_angles(tilt, rates["precession"], spin_rate)}
    vectors = _in_ground(found, now)
    lean, heading = vectors.pop("lean"), found["frames"][1]
    column = vectors.pop("column")
    return {**vectors, "center": column(radius * lean.z), "axis": column(-circle * heading.y)}


def upright_vectors(I1, I3, mass, g, radius, route: str = "lagrange") -> dict:
    """Upright rolling along N.x at a unit spin (directions only), in N: omega, L about G, v_G and
    the lean frame's axes (columns), as `steady_vectors`.

    >>> m, g, a = sp.symbols("m g a", positive=True)
    >>> found = upright_vectors(m * a**2 / 4, m * a**2 / 2, m, g, a)
    >>> found["omega"].T, found["velocity"].T
    (Matrix([[0, 1, 0]]), Matrix([[a, 0, 0]]))
    """
    found = {**motion(I1, I3, mass, g, radius, route), "I1": I1, "I3": I3}
    psi, theta, phi = _coordinates()
    now = {**{c.diff(_T, 2): 0 for c in _coordinates()}, theta.diff(_T): 0, psi.diff(_T): 0, theta: 0}
    forward = me.msubs(found["velocity"].dot(found["frames"][0].x), {**now, phi.diff(_T): 1, psi: 0})
    now[phi.diff(_T)] = sp.sign(tidy(forward))
    vectors = _in_ground(found, now)
    vectors.pop("lean"), vectors.pop("column")
    return vectors


def _steady_angles(tilt, heading_rate, spin_rate) -> dict:
    psi, theta, phi = _coordinates()
    return {theta.diff(_T): 0, psi.diff(_T): heading_rate, phi.diff(_T): spin_rate, theta: tilt}


@lru_cache(maxsize=None)
def upright(I1, I3, mass, g, radius, route: str) -> tuple[sp.Poly, sp.Expr]:
    """Upright rolling in a straight line at the spin omega, by one route: the lean and heading
    equations linearized about it (small theta, psi'; phi' = omega), det = s (A s^2 + C) as a Poly
    in s after the factor s (the heading's drift), and the least speed a omega, stable where
    C/A > 0 (the lean oscillates)."""
    equations = motion(I1, I3, mass, g, radius, route)["equations"]
    psi, theta, phi = _coordinates()
    small = {theta: 1, theta.diff(_T): S, theta.diff(_T, 2): S**2, psi.diff(_T): 1, psi.diff(_T, 2): S}
    upright_rolling = {**_steady_angles(0, 0, SPIN), phi.diff(_T, 2): 0, **{x: 0 for x in reversed(list(small))}}
    linear = sp.Matrix([[sum((me.msubs(e.diff(x), upright_rolling) * small[x] for x in group), sp.Integer(0))
                         for group in ((theta, theta.diff(_T), theta.diff(_T, 2)), (psi.diff(_T), psi.diff(_T, 2)))]
                        for e in (equations[0], equations[1])])
    characteristic = sp.Poly(sp.cancel(sp.expand(linear.det()) / S), S)
    A, C = characteristic.coeff_monomial(S**2), characteristic.coeff_monomial(1)
    if characteristic.coeff_monomial(S) != 0:
        raise ValueError(f"upright rolling's lean is not a pure oscillation: {characteristic}")
    least = [r for r in sp.solve(C / A, SPIN) if r.is_positive]
    return characteristic, tidy(radius * least[0])


def min_speed(I1, I3, mass, g, radius, route: str) -> sp.Expr:
    """The least speed a omega at which upright rolling in a straight line is stable, by one route."""
    return upright(I1, I3, mass, g, radius, route)[1]


def steps(I1, I3, mass, g, radius, tilt, circle, route: str, upright_asked: bool) -> list[Step]:
    """The worked solution by one route: its lean equation, and from it the steady motion (where a
    tilt is given) and upright rolling's least speed (where asked)."""
    phi = _coordinates()[2]
    lean_equation = motion(I1, I3, mass, g, radius, route)["equations"][1]
    how = ("Lagrange's method in the heading psi, the lean theta, the spin phi and the center's x, y, z: the "
           "height z = a cos(theta) and the rolling (the coin's point at the contact does not move along the "
           "floor) held by multipliers, which the equations of x, y, z give; with them and the center's rates "
           "eliminated, the lean's equation is" if route == "lagrange" else
           "Kane's method: the center's velocity three dependent speeds, held by the rolling constraints (the "
           "coin's point at the contact does not move); with the rates of the heading psi, the lean theta and "
           "the spin phi as the independent speeds, the lean's equation is" if route == "kane" else
           "Newton–Euler about the center of mass G: v_G = omega x r_PG (the contact point P at rest), the contact "
           "force F = m a_G + m g z from Newton's law, and dH_G/dt = r_GP x F; projected on the lean's partial "
           "angular velocity, that is")
    result = [Step(how, (sp.Eq(lean_equation, 0),), "equations")]
    if tilt is not None:
        found = steady(I1, I3, mass, g, radius, tilt, circle, route)
        result.append(Step("In the steady motion on the circle the lean stays at its tilt and the heading turns at "
                           "Omega; the center circling the axis needs the spin rate phi' below, and the lean's "
                           "equation then gives Omega", (sp.Eq(phi.diff(_T), found["spin_rate"]),
                                                         sp.Eq(OMEGA**2, found["squared"])), "solve"))
    if not upright_asked:
        return result
    characteristic, least = upright(I1, I3, mass, g, radius, route)
    result.append(Step("Upright, rolling straight at the spin omega, small leans and heading rates grow or "
                       "oscillate exponentially in time: the lean oscillates, and upright rolling is stable, where "
                       "the two coefficients of the characteristic equation below have one sign, that is above "
                       "the least speed",
                       (sp.Eq(characteristic.as_expr(), 0), sp.Eq(sp.Symbol("v_min"), least)), "solve"))
    return result
