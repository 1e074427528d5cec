"""Steady precession of a symmetric top on a fixed tip (the notes' §7).

Lagrange: L = I1 (theta'^2 + phi'^2 sin^2 theta)/2 + I3 (psi' + phi' cos theta)^2 / 2
- m g R cos theta in Euler angles; steady precession (theta' = theta'' = 0, phi' = Omega, spin
omega3 = psi' + phi' cos theta) makes the theta equation a quadratic in Omega. Newton–Euler:
the same condition from dH/dt = r_cm x (-m g z) with sympy.physics.mechanics (a rigid body in
Euler-angle frames). The slow root is written rationalized, 2 m g R / (I3 w + sqrt(disc)),
which does not cancel when the top is fast; its leading term as the spin grows is the notes'
Omega = m g R / (I3 w).

>>> m, g, R, I1, I3, w, th = sp.symbols("m g R I_1 I_3 omega theta", positive=True)
>>> fast_top_limit(m, g, R, I1, I3, w, th)
R*g*m/(I_3*omega)
"""
from __future__ import annotations

from functools import lru_cache

import sympy as sp

from derive.mechanics.derivation import tidy

OMEGA = sp.Symbol("Omega", real=True)


class PrecessionError(ValueError):
    """No steady precession at these parameters."""


@lru_cache(maxsize=None)
def precession_condition(m, g, R, I1, I3, spin, tilt, route: str) -> sp.Expr:
    """The condition on the precession rate, Omega^2 + p Omega + q = 0, by one route."""
    t = sp.Symbol("t")
    theta, phi, psi = (sp.Function(n)(t) for n in ("theta", "phi", "psi"))
    steady = {theta.diff(t, 2): 0, phi.diff(t, 2): 0, psi.diff(t, 2): 0}
    rates = {phi.diff(t): OMEGA, psi.diff(t): spin - OMEGA * sp.cos(tilt), theta.diff(t): 0}
    if route == "lagrange":
        lagrangian = (I1 * (theta.diff(t) ** 2 + phi.diff(t) ** 2 * sp.sin(theta) ** 2) / 2
                      + I3 * (psi.diff(t) + phi.diff(t) * sp.cos(theta)) ** 2 / 2 - m * g * R * sp.cos(theta))
        equation = sp.diff(lagrangian, theta.diff(t)).diff(t) - sp.diff(lagrangian, theta)
    else:
        from sympy.physics.mechanics import Point, ReferenceFrame, RigidBody, inertia

        ground = ReferenceFrame("N")
        top = ground.orientnew("B", "Body", [phi, theta, psi], "313")
        tip = Point("O")
        tip.set_vel(ground, 0)
        center = tip.locatenew("C", R * top.z)
        body = RigidBody("top", center, top, m, (inertia(top, I1 - m * R**2, I1 - m * R**2, I3), center))
        change = body.angular_momentum(tip, ground).dt(ground)
        torque = center.pos_from(tip).cross(-m * g * ground.z)
        nodes = ground.orientnew("K", "Axis", [phi, ground.z]).x  # the line of nodes
        equation = -(change - torque).dot(nodes)  # the theta component, in Lagrange's sign
    condition = sp.expand(sp.simplify(equation.subs(steady).subs(rates).subs(theta, tilt) / sp.sin(tilt)))
    return sp.expand(condition / condition.coeff(OMEGA, 2))  # monic: Omega^2 + p Omega + q


def roots(m, g, R, I1, I3, spin, tilt, route: str = "lagrange") -> tuple[sp.Expr, sp.Expr]:
    """(slow, fast) steady precession rates; the slow one rationalized (no cancellation)."""
    # cos(theta) > 0 for a top tilted less than 90 degrees: a positive stand-in lets roots simplify.
    cosine = sp.Symbol("cos_tilt", positive=True)
    condition = precession_condition(m, g, R, I1, I3, spin, tilt, route).subs(sp.cos(tilt), cosine)
    p, q = condition.coeff(OMEGA, 1), condition.coeff(OMEGA, 0)  # p = -I3 w / (I1 cos), q = m g R / (I1 cos)
    root = sp.sqrt(tidy(p**2 - 4 * q))
    slow = tidy(2 * q / (-p + root))  # = (-p - root)/2, without the cancellation
    fast = tidy((-p + root) / 2)
    return slow.subs(cosine, sp.cos(tilt)), fast.subs(cosine, sp.cos(tilt))


def fast_top_limit(m, g, R, I1, I3, spin, tilt) -> sp.Expr:
    """The leading term of the slow rate as the spin grows: the notes' m g R / (I3 omega)."""
    slow, _ = roots(m, g, R, I1, I3, spin, tilt)
    leading = sp.refine(sp.limit(slow * spin, spin, sp.oo), sp.Q.positive(sp.cos(tilt)))  # tilted less than 90°
    return tidy(leading / spin)
