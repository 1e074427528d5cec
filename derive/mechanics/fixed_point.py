"""A rigid body turning about a fixed point under gravity: a top on its tip, a gyroscope on its
pivot, a ball joint (the notes' §7; Taylor ch. 10, Kleppner & Kolenkow ch. 8).

The top frame B has its z axis from the fixed point O through the center of mass, a distance l
away (`standing` turns a body's own frame so). B is turned from the ground N by the Euler
angles phi (precession, about N.z), theta (tilt, about the line of nodes) and psi (spin, about
B.z): 'Body' ZXZ. Three routes give the equations of motion, each in Lagrange's form
d/dt dL/dq' - dL/dq, all by sympy.physics.mechanics:

- lagrange: LagrangesMethod on the RigidBody, potential m g l cos(theta);
- newton_euler: Euler's equations about the fixed point, dH_O/dt = r_cm x (-m g z), each
  projected on a partial angular velocity d omega/d q';
- kane: KanesMethod with u = q', -(Fr + Fr*).

The steady motions of a symmetric top (I1 about every transverse axis through O, I3 along B.z;
spin omega3 = psi' + phi' cos(theta), the component of omega along the axis):

- steady precession: theta' = 0 and phi' = Omega make theta's equation a quadratic,
  I1 Omega^2 cos(theta) - I3 omega3 Omega + m g l = 0; its slow root written rationalized,
  2 m g l / (I3 w + sqrt(disc)), leads to the fast-top rate m g l / (I3 omega3);
- a sleeping top (upright, spinning) is stable for I3^2 omega3^2 > 4 I1 m g l: by Lagrange, the
  effective potential of theta with phi's and psi's momenta held; by Newton–Euler, Euler's
  equations linearized about the vertical in two small tilts (no Euler-angle singularity there);
- steady conical motion (`conical_squared`): the body turning as one about the vertical, a rod
  hanging from its end and swinging round in a cone;
- nutation about the slow steady precession: by Lagrange, the effective potential's curvature;
  by Newton–Euler, the three equations linearized about the steady motion; its leading term for
  a fast top is I3 omega3 / I1.

>>> m, g, l, I1, I3, w = sp.symbols("m g l I_1 I_3 omega", positive=True)
>>> tensor = sp.diag(I1 - m * l**2, I1 - m * l**2, I3)  # about the center of mass, in B
>>> min_spin(tensor, m, g, l, "newton_euler")
2*sqrt(I_1)*sqrt(g)*sqrt(l)*sqrt(m)/I_3
"""
from __future__ import annotations

from functools import lru_cache

import sympy as sp
from sympy.physics import mechanics as me

from derive.core.tidying import tidy

ROUTES = ("lagrange", "newton_euler", "kane")
OMEGA = sp.Symbol("Omega", real=True)  # the precession rate
S = sp.Symbol("s")  # the exponent of a small motion, e^(s t)


class NotSymmetric(ValueError):
    """The body is not a symmetric top about its fixed point: no steady precession is modelled."""


def standing(tensor: sp.Matrix, offset) -> tuple[sp.ImmutableMatrix, sp.Expr]:
    """The tensor about the center of mass in the top frame (z from the fixed point through the
    center) and the distance l, from the tensor in the body's own frame and the fixed point's
    `offset` (x, y, z) from the center there. The top frame's x is the own z where the axis lies
    across it (a rod, a composite), else the own x.

    >>> standing(sp.diag(1, 2, 3), (0, 0, 2))  # standing on +z: turned over about x
    (Matrix([
    [1, 0, 0],
    [0, 2, 0],
    [0, 0, 3]]), 2)
    """
    offset = sp.Matrix(offset)
    distance = tidy(sp.sqrt(offset.dot(offset)))
    axis = -offset / distance  # from the fixed point to the center of mass
    across = sp.Matrix([0, 0, 1]) if axis[2] == 0 else sp.Matrix([1, 0, 0])
    turn = sp.Matrix.vstack(across.T, axis.cross(across).T, axis.T)  # rows: B's axes in the own frame
    return sp.ImmutableMatrix((turn * sp.Matrix(tensor) * turn.T).applyfunc(tidy)), distance


def about_pivot(tensor: sp.Matrix, mass, distance) -> sp.ImmutableMatrix:
    """The tensor about the fixed point in the top frame (parallel axes along B.z)."""
    return sp.ImmutableMatrix((sp.Matrix(tensor) + mass * distance**2 * sp.diag(1, 1, 0)).applyfunc(tidy))


def moments(tensor: sp.Matrix, mass, distance) -> tuple[sp.Expr, sp.Expr]:
    """(I1, I3) of a symmetric top about its fixed point; NotSymmetric for any other body."""
    pivot = about_pivot(tensor, mass, distance)
    if any(tidy(pivot[i, j]) != 0 for i, j in ((0, 1), (0, 2), (1, 2))) or tidy(pivot[0, 0] - pivot[1, 1]) != 0:
        raise NotSymmetric(f"the moments about the fixed point are {sp.sstr(pivot)}: not a symmetric top "
                           "(equal transverse moments, the center on the symmetry axis)")
    return pivot[0, 0], pivot[2, 2]


def _angles():
    return me.dynamicsymbols("phi theta psi")


def _top(tensor, mass, g, distance, orientation, angles):
    """The ground, the top frame, the fixed point, the center and the RigidBody with its weight."""
    ground = me.ReferenceFrame("N")
    frame = ground.orientnew("B", "Body", angles, orientation)
    pivot = me.Point("O")
    pivot.set_vel(ground, 0)
    center = pivot.locatenew("C", distance * frame.z)
    center.v2pt_theory(pivot, ground, frame)
    t = tensor
    dyadic = me.inertia(frame, t[0, 0], t[1, 1], t[2, 2], t[0, 1], t[1, 2], t[0, 2])
    body = me.RigidBody("top", center, frame, mass, (dyadic, center))
    return ground, frame, pivot, center, body, -mass * g * ground.z


def _newton_euler(tensor, mass, g, distance, orientation, angles) -> sp.Matrix:
    """dH_O/dt - r_cm x W about the fixed point, projected on d omega / d q'_i."""
    ground, frame, pivot, center, body, weight = _top(tensor, mass, g, distance, orientation, angles)
    balance = body.angular_momentum(pivot, ground).dt(ground) - center.pos_from(pivot).cross(weight)
    omega = frame.ang_vel_in(ground)
    return sp.Matrix([balance.dot(omega.diff(q.diff(), ground)) for q in angles])


@lru_cache(maxsize=None)
def equations(tensor: sp.ImmutableMatrix, mass, g, distance, route: str) -> sp.Matrix:
    """The equations of motion in (phi, theta, psi), d/dt dL/dq' - dL/dq = 0, by one route."""
    angles = _angles()
    if route == "newton_euler":
        return _newton_euler(tensor, mass, g, distance, "ZXZ", angles).applyfunc(sp.expand)
    ground, frame, pivot, center, body, weight = _top(tensor, mass, g, distance, "ZXZ", angles)
    if route == "lagrange":
        body.potential_energy = -weight.dot(center.pos_from(pivot))
        method = me.LagrangesMethod(me.Lagrangian(ground, body), angles)
        return method.form_lagranges_equations().applyfunc(sp.expand)
    rates = me.dynamicsymbols("u1:4")
    method = me.KanesMethod(ground, q_ind=angles, u_ind=rates, kd_eqs=[q.diff() - u for q, u in zip(angles, rates)])
    active, inertial = method.kanes_equations([body], [(center, weight)])
    back = {**{u.diff(): q.diff(me.dynamicsymbols._t, 2) for q, u in zip(angles, rates)},
            **{u: q.diff() for q, u in zip(angles, rates)}}
    return (-(active + inertial)).xreplace(back).applyfunc(sp.expand)


def _steady(angles, spin, tilt, rate):
    """Steady precession at `rate`: theta = tilt fixed, phi' = rate, omega3 = spin."""
    phi, theta, psi = angles
    t = me.dynamicsymbols._t
    return {**{q.diff(t, 2): 0 for q in angles}, theta.diff(t): 0, phi.diff(t): rate,
            psi.diff(t): spin - rate * sp.cos(tilt), theta: tilt}


def steady_vectors(tensor, mass, distance, spin, tilt, rate) -> dict:
    """In steady precession at `rate` (spin omega3, the axis at `tilt`), at the instant the axis
    leans toward N.x (phi = pi/2, psi = 0): omega, L about the fixed point (the RigidBody's) and the
    top frame's axes (columns), all in N.

    >>> I1, I3, w, W = sp.symbols("I_1 I_3 omega Omega", positive=True)
    >>> found = steady_vectors(sp.diag(I1, I1, I3), 0, 1, w, sp.pi / 2, W)  # a level axle
    >>> found["omega"].T, found["momentum"].T
    (Matrix([[omega, 0, Omega]]), Matrix([[I_3*omega, 0, I_1*Omega]]))
    """
    angles = _angles()
    ground, frame, pivot, _, body, _ = _top(tensor, mass, 0, distance, "ZXZ", angles)
    now = {**_steady(angles, spin, tilt, rate), angles[0]: sp.pi / 2, angles[2]: 0}

    def column(vector):
        return sp.Matrix([tidy(me.msubs(vector.dot(e), now)) for e in ground])

    return {"omega": column(frame.ang_vel_in(ground)), "momentum": column(body.angular_momentum(pivot, ground)),
            "axes": sp.Matrix.hstack(*(column(e) for e in frame))}


@lru_cache(maxsize=None)
def precession_condition(tensor, mass, g, distance, spin, tilt, route: str) -> sp.Expr:
    """The condition on a steady precession rate, Omega^2 + p Omega + q = 0, from theta's equation
    (at a tilt with cos(tilt) != 0; `roots` takes a horizontal axis as the limit)."""
    moments(tensor, mass, distance)
    theta_equation = equations(tensor, mass, g, distance, route)[1]
    condition = sp.expand(sp.simplify(me.msubs(theta_equation, _steady(_angles(), spin, tilt, OMEGA)) / sp.sin(tilt)))
    return sp.expand(condition / condition.coeff(OMEGA, 2))


def conical_squared(tensor, mass, g, distance, tilt, route: str) -> sp.Expr:
    """Omega^2 of steady conical motion, by one route: the body turns as one about the vertical at
    Omega (no spin of its own, psi' = 0), so omega3 = Omega cos(tilt) and the steady condition
    becomes (I1 - I3) Omega^2 cos(tilt) + m g l = 0; a rod hanging at theta from the downward
    vertical (tilt pi - theta) turns at Omega^2 = 3 g/(2 L cos(theta)).

    >>> m, g, L, theta = sp.symbols("m g L theta", positive=True)
    >>> rod = sp.ImmutableMatrix(sp.diag(m * L**2 / 12, m * L**2 / 12, 0))  # about its center, z along it
    >>> conical_squared(rod, m, g, L / 2, sp.pi - theta, "lagrange")
    3*g/(2*L*cos(theta))
    """
    spin = sp.Dummy("omega_3")
    turning = sp.expand(precession_condition(tensor, mass, g, distance, spin, tilt, route)
                        .subs(spin, OMEGA * sp.cos(tilt)))
    return tidy(-turning.coeff(OMEGA, 0) / turning.coeff(OMEGA, 2))


def roots(tensor, mass, g, distance, spin, tilt, route: str = "lagrange") -> tuple[sp.Expr, sp.Expr]:
    """(slow, fast) steady precession rates; the slow one rationalized (no cancellation), which
    stays finite for a horizontal axis (m g l / (I3 omega3) there, where the fast one is None)."""
    # cos(theta) > 0 for a top tilted less than 90 degrees: a positive stand-in lets roots simplify.
    cosine, leaning = sp.Symbol("cos_tilt", positive=True), sp.Symbol("theta_tilt", positive=True)
    condition = precession_condition(tensor, mass, g, distance, spin, leaning, route).subs(sp.cos(leaning), cosine)
    p, q = condition.coeff(OMEGA, 1), condition.coeff(OMEGA, 0)  # p = -I3 w / (I1 cos), q = m g l / (I1 cos)
    level = tidy(-q / p) if sp.cos(tilt) == 0 else None  # a level axis: the condition is linear, Omega = -q/p
    if level is not None and not level.has(cosine, leaning):  # the cosines cancelled: slow's limit, in its own form
        return level, None
    root = sp.sqrt(tidy(p**2 - 4 * q))
    slow = tidy(2 * q / (-p + root))  # = (-p - root)/2, without the cancellation
    fast = tidy((-p + root) / 2)
    slow, fast = (r.subs(cosine, sp.cos(leaning)).subs(leaning, tilt) for r in (slow, fast))
    return slow, (None if sp.cos(tilt) == 0 else fast)


def fast_top(exact: sp.Expr, spin, tilt) -> sp.Expr:
    """The leading term of `exact` as the spin grows (the slow rate: the notes' m g l/(I3 omega))."""
    power = 1 if sp.limit(exact, spin, sp.oo) == sp.oo else -1
    leading = sp.refine(sp.limit(exact * spin**-power, spin, sp.oo), sp.Q.positive(sp.cos(tilt)))
    return tidy(leading * spin**power)


def min_spin(tensor, mass, g, distance, route: str) -> sp.Expr:
    """The least spin at which a sleeping top (upright, spinning) is stable, by one route."""
    moments(tensor, mass, distance)
    spin = sp.Symbol("omega_3", positive=True)
    if route == "lagrange":
        tilt = sp.Symbol("theta", positive=True)
        potential = _effective_potential(tensor, mass, g, distance, spin, spin, tilt)
        curvature = sp.series(potential, tilt, 0, 3).removeO().coeff(tilt, 2)  # stable where positive
    else:
        # Newton–Euler about the vertical: small tilts a (about N.x) and b (about A.y), spin psi.
        a, b, psi = me.dynamicsymbols("a b psi")
        balance = _newton_euler(tensor, mass, g, distance, "XYZ", (a, b, psi))[:2, 0]
        t = me.dynamicsymbols._t
        small = [a, b, a.diff(t), b.diff(t), a.diff(t, 2), b.diff(t, 2)]
        turning = {psi.diff(t, 2): 0, psi.diff(t): spin, **{x: 0 for x in reversed(small)}}
        linear = sp.Matrix([[me.msubs(e.diff(x), turning) for x in small] for e in balance])
        # a, b ~ e^(s t): det(K + C s + M s^2) = A s^4 + B s^2 + C; stable where both s^2 are
        # real and negative: B^2 - 4 A C > 0 (B, C > 0 then hold too)
        characteristic = sp.Poly(sp.expand((linear[:, :2] + S * linear[:, 2:4] + S**2 * linear[:, 4:]).det()), S)
        A, B, C = (characteristic.coeff_monomial(S**k) for k in (4, 2, 0))
        curvature = sp.factor(B**2 - 4 * A * C)
    positive = [r for r in sp.solve(curvature, spin) if r.is_positive]
    return tidy(positive[0])


def _effective_potential(tensor, mass, g, distance, momentum_phi, momentum_psi, tilt) -> sp.Expr:
    """Routh's potential of theta for phi's and psi's momenta over I3 (p/I3, rates), theta' = 0:
    minus the Routhian L - p_phi phi' - p_psi psi' with the rates eliminated."""
    phi, theta, psi = angles = _angles()
    ground, frame, pivot, center, body, weight = _top(tensor, mass, g, distance, "ZXZ", angles)
    body.potential_energy = -weight.dot(center.pos_from(pivot))
    lagrangian = me.Lagrangian(ground, body)
    I3 = moments(tensor, mass, distance)[1]
    t = me.dynamicsymbols._t
    rates = sp.symbols("phi_dot psi_dot")
    still = {theta.diff(t): 0, phi.diff(t): rates[0], psi.diff(t): rates[1], theta: tilt}
    reduced = me.msubs(lagrangian, still)
    given = (I3 * momentum_phi, I3 * momentum_psi)
    solved = sp.solve([reduced.diff(r) - p for r, p in zip(rates, given)], rates, dict=True)[0]
    return tidy(-(reduced - given[0] * rates[0] - given[1] * rates[1]).subs(solved))


def nutation_frequency(tensor, mass, g, distance, spin, tilt, route: str) -> sp.Expr:
    """The angular frequency of small nutations about the slow steady precession, by one route:
    its square found at a precession rate Omega, the weight eliminated by the steady condition
    (m g l = I3 omega3 Omega - I1 Omega^2 cos(theta)), then the slow rate put in."""
    I1, I3 = moments(tensor, mass, distance)
    weight = sp.Dummy("g", positive=True)
    if route == "lagrange":
        theta = sp.Symbol("theta_n", positive=True)
        momentum_phi = (I1 * OMEGA * sp.sin(tilt) ** 2 + I3 * spin * sp.cos(tilt)) / I3
        potential = _effective_potential(tensor, mass, weight, distance, momentum_phi, spin, theta)
        squared = potential.diff(theta, 2).subs(theta, tilt) / I1
    else:
        # the three equations linearized about the steady motion; phi and psi are cyclic, so the
        # unknowns are theta's change and the changes of phi' and psi', each ~ e^(s t)
        phi, theta, psi = angles = _angles()
        t = me.dynamicsymbols._t
        steady = _steady(angles, spin, tilt, OMEGA)
        terms = [[(theta, 1), (theta.diff(t), S), (theta.diff(t, 2), S**2)],
                 [(phi.diff(t), 1), (phi.diff(t, 2), S)], [(psi.diff(t), 1), (psi.diff(t, 2), S)]]
        linear = sp.Matrix([[sum(me.msubs(e.diff(x), steady) * power for x, power in group) for group in terms]
                            for e in equations(tensor, mass, weight, distance, "newton_euler")])
        # s = 0 twice (the cyclic angles' drifts), then A s^2 + B: s^2 = -omega_n^2
        characteristic = sp.Poly(sp.cancel(sp.expand(linear.det()) / S**2), S)
        squared = characteristic.coeff_monomial(1) / characteristic.coeff_monomial(S**2)
    steady_weight = sp.solve(precession_condition(tensor, mass, weight, distance, spin, tilt, route), weight)[0]
    squared = sp.factor(sp.simplify(squared.subs(weight, steady_weight)))
    return sp.sqrt(squared).subs(OMEGA, roots(tensor, mass, g, distance, spin, tilt)[0])
