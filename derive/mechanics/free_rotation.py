"""A rigid body turning with no torque about its center of mass: in free flight, or on a
frictionless point at its center (Taylor, Classical Mechanics, §10.8; Kleppner & Kolenkow ch. 8;
Morin ch. 9).

The body's principal moments about its center are (Ix, Iy, Iz) along its own axes. Two routes,
both by sympy.physics.mechanics:

- newton_euler: Euler's equations, dH/dt = 0 in the ground frame N written in the body frame B
  (H = I·omega, d/dt taken in N: the body-frame rates plus omega x H), solved for omega';
- lagrange: LagrangesMethod on the free RigidBody in Euler angles (no potential).

A symmetric body (I1 about every axis across its symmetry axis, I3 along it), spinning at
omega3 along the axis with omega_t across it:

- in the body, omega turns about the axis at Omega_b = (I3 - I1) omega3 / I1: by Euler's
  equations, (omega1 omega2' - omega2 omega1')/(omega1^2 + omega2^2); by Lagrange, minus the
  spin rate psi' of the steady solution of the ZXZ Euler-angle equations (theta' = 0);
- in space the axis turns about L at |L|/I1: by Euler's route, the axis's speed omega x e3 over
  the radius sin(angle(L, e3)) of its circle about L; by Lagrange, phi' of the steady solution;
- the angles between L and the axis and between omega and the axis, atan2(|u x e3|, u·e3)
  from L = I·omega by the first route, from the Euler-angle frames by the second.

Steady rotation about a principal axis at a rate W (three distinct moments): small changes
grow or oscillate as e^(s t) with s^2 = -(Ik - Ii)(Ik - Ij) W^2 / (Ii Ij), Ik the axis's moment:
by Euler's equations linearized (their Jacobian's characteristic polynomial, s (s^2 - s_k^2));
by Lagrange's equations in ZXY angles (phi about N.z, then small beta, gamma) linearized about
phi' = W, whose determinant is I s (s^2 + W^2)(...) (s^2 + W^2: the axis of rotation tilted, the
body still turning rigidly about it), divided exactly. Stable (a wobble at sqrt(-s^2)) about
the axes of least and greatest moment, unstable (growing at sqrt(s^2)) about the intermediate
one: the tennis-racket theorem.

>>> I1, I3, w3 = sp.symbols("I_1 I_3 omega_3", positive=True)
>>> precession((I1, I3), w3, sp.Symbol("omega_t", positive=True), "free_precession.body", "newton_euler")
-omega_3*(I_1 - I_3)/I_1
>>> exponent_squared((1, 2, 3), 1, sp.Symbol("W"), "lagrange")  # about the intermediate axis: unstable
W**2/3
"""
from __future__ import annotations

from functools import lru_cache

import sympy as sp
from sympy.physics import mechanics as me

from derive.mechanics.derivation import KINETIC
from derive.text.steps import Step
from derive.core.tidying import tidy
from derive.model.solid_scene import FREE_ROTATION_QUANTITIES

ROUTES = ("newton_euler", "lagrange")
#: The asks of a symmetric body's free precession (the others: a steady rotation about an axis of a rank).
SYMMETRIC = tuple(q for q in FREE_ROTATION_QUANTITIES if not q.startswith("rotation."))
RANKS = ("least", "intermediate", "greatest")
S = sp.Symbol("s")  # the exponent of a small motion, e^(s t)


class NotModelled(ValueError):
    """The body's moments do not fit the ask (no symmetry axis, two equal moments, a zero moment)."""


class NotPrincipal(ValueError):
    """The body's own axes are not principal: finding its principal axes is not modelled."""


def principal_moments(tensor: sp.Matrix) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """(Ix, Iy, Iz) of a tensor about the center of mass whose own axes are principal.

    >>> principal_moments(sp.diag(1, 2, 2))
    (1, 2, 2)
    """
    if any(tidy(tensor[i, j]) != 0 for i, j in ((0, 1), (0, 2), (1, 2))):
        raise NotPrincipal(f"its own axes are not principal (its tensor about the center of mass is "
                           f"{sp.sstr(sp.Matrix(tensor).tolist())})")
    moments = tuple(tidy(tensor[i, i]) for i in range(3))
    if any(m == 0 for m in moments):
        raise NotModelled("a principal moment is zero (a thin rod about its length): its spin about that axis "
                          "carries no angular momentum; give the body a thickness (a cylinder)")
    return moments


def symmetric(moments) -> tuple[sp.Expr, sp.Expr, str]:
    """(I1, I3, axis): the repeated moment, the distinct one and its own axis (x, y or z).

    >>> symmetric(principal_moments(sp.diag(2, 1, 2)))
    (2, 1, 'y')
    """
    for k in range(3):
        others = [moments[i] for i in range(3) if i != k]
        if tidy(others[0] - others[1]) == 0 and tidy(moments[k] - others[0]) != 0:
            return others[0], moments[k], "xyz"[k]
    raise NotModelled(f"the principal moments {', '.join(map(sp.sstr, moments))} have no symmetry axis (two "
                      "equal, the third different)")


def _free_body(moments, order: str):
    """(ground, body frame, Euler angles, Lagrangian) of a free body of principal moments
    `moments` along its frame's x, y, z, turned by 'Body' angles in `order` (ZXZ: phi, theta,
    psi; ZXY: phi, then the small beta and gamma: not a and b, a box's sides)."""
    ground = me.ReferenceFrame("N")
    angles = me.dynamicsymbols("phi theta psi" if order == "ZXZ" else "phi beta gamma")
    frame = ground.orientnew("B", "Body", angles, order)
    center = me.Point("O")
    center.set_vel(ground, 0)
    body = me.RigidBody("body", center, frame, 1, (me.inertia(frame, *moments), center))
    return ground, frame, angles, me.Lagrangian(ground, body)


def _plain(expr, functions) -> sp.Expr:
    """An expression in dynamic symbols written in plain ones for a worked solution (q' as qdot)."""
    t = me.dynamicsymbols._t
    names = {f: f.func.__name__ for f in functions}
    rates = {f.diff(t): sp.Symbol(f"{n}dot") for f, n in names.items()}
    return me.msubs(expr, rates, {f: sp.Symbol(n) for f, n in names.items()})


def steps(moments, route: str, orders: tuple[str, ...]) -> list[Step]:
    """The equations a route starts from, for a worked solution: Euler's equations with no torque,
    or the kinetic energy in each order of Euler angles the asks need (ZXZ for a symmetric body's
    precession, ZXY for a steady rotation's small motions).

    >>> steps((1, 1, 2), "newton_euler", ())[1].equations[0]
    Eq(omegadot_1, -omega_2*omega_3)
    """
    named = [(sp.Symbol(f"I_{k}"), m) for k, m in zip((1, 2, 3), moments)]
    result = [Step("The principal moments about the center of mass, along the body's own axes",
                   tuple(sp.Eq(s, m, evaluate=False) for s, m in named  # not I_1 = I_1 for a parameter I1
                         if not (isinstance(m, sp.Symbol) and m.name.replace("_", "") == s.name.replace("_", ""))))]
    if route == "newton_euler":
        rates, w = euler_rates(moments)
        return [*result, Step("Euler's equations with no torque, in the body's principal axes",
                              tuple(sp.Eq(sp.Symbol(f"omegadot_{k}"), _plain(r, w)) for k, r in zip((1, 2, 3), rates)),
                              role="equations")]
    for order in orders:
        turned = {"ZXZ": "phi about L, theta from it, psi about the symmetry axis",
                  "ZXY": "phi about the steady axis, then small turns beta and gamma across it"}[order]
        _, _, angles, lagrangian = _free_body(moments, order)
        result.append(Step(f"The kinetic energy in Euler angles ({turned}), the Lagrangian of the free body",
                           (sp.Eq(KINETIC, tidy(_plain(lagrangian, angles))),), role="equations"))
    return result


def euler_rates(moments, torque=(0, 0, 0)) -> tuple[sp.Matrix, tuple]:
    """omega' in the body frame from Euler's equations, dH/dt = `torque` (its components along the
    body's axes; none by default): (rates, (w1, w2, w3)).

    >>> euler_rates((1, 1, 2), (0, 1, 0))[0][1]
    omega_1(t)*omega_3(t) + 1
    """
    ground, frame = me.ReferenceFrame("N"), me.ReferenceFrame("B")
    w = me.dynamicsymbols("omega_1:4")
    frame.set_ang_vel(ground, sum((c * e for c, e in zip(w, frame)), me.Vector(0)))
    momentum = me.inertia(frame, *moments).dot(frame.ang_vel_in(ground))
    balance = [momentum.dt(ground).dot(e) - c for e, c in zip(frame, torque)]  # dH/dt in N = torque
    rates = [c.diff(me.dynamicsymbols._t) for c in w]
    return sp.Matrix([sp.solve(balance, rates, dict=True)[0][r] for r in rates]), tuple(w)


def angle_between(u: sp.Matrix, v: sp.Matrix) -> sp.Expr:
    """The angle between two vectors, atan2(|u x v|, u·v)."""
    across = u.cross(v)
    return tidy(sp.atan2(tidy(sp.sqrt(across.dot(across))), tidy(u.dot(v))))


@lru_cache(maxsize=None)
def _steady_precession(I1, I3, spin, across) -> dict:
    """The steady solution of Lagrange's equations in ZXZ Euler angles (phi, theta, psi) with
    theta' = 0, fitted to omega's components (spin along the axis, across it): phi', theta, psi',
    and omega in the body frame from the Euler-angle frames."""
    ground, frame, angles, lagrangian = _free_body((I1, I1, I3), "ZXZ")
    phi, theta, psi = angles
    theta_equation = me.LagrangesMethod(lagrangian, list(angles)).form_lagranges_equations()[1]
    t = me.dynamicsymbols._t
    # the axis's rate about N.z (phi') and tilt from it: P cos(theta) = c, P sin(theta) = across
    c = sp.Symbol("c", positive=True)
    rate, tilt = sp.sqrt(c**2 + across**2), sp.atan2(across, c)
    omega = frame.ang_vel_in(ground)
    steady = {**{q.diff(t, 2): 0 for q in angles}, theta.diff(t): 0, phi.diff(t): rate, theta: tilt}
    psi_rate = tidy(spin - me.msubs(omega.dot(frame.z), {**steady, psi.diff(t): 0}))  # omega3 = psi' + phi' cos
    steady[psi.diff(t)] = psi_rate
    found = sp.solve(tidy(me.msubs(theta_equation, steady)), c)
    if len(found) != 1:
        raise NotModelled(f"no single steady precession: {found}")
    fitted = {c: found[0]}
    omega_body = sp.Matrix([me.msubs(omega.dot(e), {**steady, psi: 0}) for e in frame]).xreplace(fitted)
    return {"phi_rate": tidy(rate.xreplace(fitted)), "theta": tidy(tilt.xreplace(fitted)),
            "psi_rate": tidy(psi_rate.xreplace(fitted)), "omega": omega_body.applyfunc(tidy)}


def precession(moments, spin, across, detail: str, route: str) -> sp.Expr:
    """One of SYMMETRIC for a symmetric body, moments (I1, I3), by one route."""
    I1, I3 = moments
    if route == "lagrange":
        steady = _steady_precession(I1, I3, spin, across)
        return {"free_precession.body": tidy(-steady["psi_rate"]), "free_precession.space": steady["phi_rate"],
                "angle_L_axis": steady["theta"],
                "angle_omega_axis": angle_between(steady["omega"], sp.Matrix([0, 0, 1]))}[detail]
    rates, w = euler_rates((I1, I1, I3))
    now = {w[0]: across, w[1]: 0, w[2]: spin}
    axis, omega = sp.Matrix([0, 0, 1]), sp.Matrix([across, 0, spin])
    momentum = sp.diag(I1, I1, I3) * omega
    if detail == "free_precession.body":  # the turning rate of omega's part across the axis
        return tidy(((w[0] * rates[1] - w[1] * rates[0]) / (w[0] ** 2 + w[1] ** 2)).xreplace(now))
    if detail == "free_precession.space":  # the axis moves at |omega x e3| on a circle about L
        speed, radius = omega.cross(axis), momentum.cross(axis)
        return tidy(sp.sqrt(speed.dot(speed)) * sp.sqrt(momentum.dot(momentum)) / sp.sqrt(radius.dot(radius)))
    return angle_between(momentum if detail == "angle_L_axis" else omega, axis)


def ranked(moments, values) -> tuple[int, int, int]:
    """The own axes' indices (0, 1, 2 for x, y, z) by increasing moment, ordered by their
    `values` (the moments at sample parameters); two moments equal as expressions are refused.

    >>> a, b = sp.symbols("a b", positive=True)
    >>> ranked((3 * a, a, 2 * b), (3, 1, 2))
    (1, 2, 0)
    """
    order = tuple(sorted(range(3), key=lambda k: values[k]))
    if any(tidy(moments[order[i]] - moments[order[i + 1]]) == 0 for i in range(2)):
        raise NotModelled("two principal moments are equal: a steady rotation is asked of a body with three "
                          "different moments (a symmetric body: ask free_precession)")
    return order


@lru_cache(maxsize=None)
def exponent_squared(moments: tuple, axis: int, rate, route: str) -> sp.Expr:
    """s^2 of small motions about a steady rotation at `rate` about the own axis `axis`, by one
    route: negative where the rotation is stable (a wobble at sqrt(-s^2)), positive where not."""
    others = [k for k in range(3) if k != axis]
    if route == "newton_euler":
        rates, w = euler_rates(moments)
        steady = {w[k]: (rate if k == axis else 0) for k in range(3)}
        jacobian = rates.jacobian(w).xreplace(steady)
        characteristic = sp.Poly(jacobian.charpoly(S).as_expr(), S)
        quotient, remainder = sp.div(characteristic, sp.Poly(S, S))  # the spin's own rate: s = 0
    else:
        turned = (moments[others[0]], moments[others[1]], moments[axis])  # the spin axis as B.z
        _, _, angles, lagrangian = _free_body(turned, "ZXY")
        phi, a, b = angles
        equations = me.LagrangesMethod(lagrangian, list(angles)).form_lagranges_equations()
        t = me.dynamicsymbols._t
        steady = {**{q.diff(t, 2): 0 for q in angles}, a.diff(t): 0, b.diff(t): 0, phi.diff(t): rate, a: 0, b: 0}
        terms = [[(a, 1), (a.diff(t), S), (a.diff(t, 2), S**2)], [(b, 1), (b.diff(t), S), (b.diff(t, 2), S**2)],
                 [(phi.diff(t), 1), (phi.diff(t, 2), S)]]
        linear = sp.Matrix([[sum(me.msubs(e.diff(x), steady) * p for x, p in group) for group in terms]
                            for e in equations])
        # phi's drift (s = 0) and the rotation axis tilted (s^2 = -W^2) leave a quadratic in s^2
        quotient, remainder = sp.div(sp.Poly(sp.expand(linear.det()), S), sp.Poly(S * (S**2 + rate**2), S))
    if not remainder.is_zero or quotient.degree() != 2 or quotient.coeff_monomial(S) != 0:
        raise NotModelled(f"unexpected characteristic polynomial {quotient.as_expr()} (remainder {remainder})")
    return tidy(-quotient.coeff_monomial(1) / quotient.coeff_monomial(S**2))
