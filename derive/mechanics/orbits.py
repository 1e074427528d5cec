"""Kepler orbits: a point mass in the field of a mass M at the origin (per unit mass).

Two routes to the radial equation: Lagrange in polar coordinates (phi is cyclic, so
l = r^2 phi' is conserved), and Newton with the Cartesian force -GM r_vec / r^3 projected on
r-hat (its torque vanishes, so l is conserved). From the radial equation: the effective
potential (minus the integral of the radial force per unit mass), its minimum (the circular
orbit), and, with u = 1/r, the orbit equation u'' + u = GM / l^2 solved by sympy's dsolve:
r(f) = p / (1 + e cos f). The turning points, l, E and the period follow.

>>> GM, l = sp.symbols("GM l", positive=True)
>>> circular_orbit(GM, l)
(l**2/GM, -GM**2/(2*l**2))
"""
from __future__ import annotations

from functools import lru_cache

import sympy as sp

from derive.mechanics.paths import quantity
from derive.core.expr import TIME
from derive.model.scene import Path

r = sp.Symbol("r", positive=True)
f = sp.Symbol("f", real=True)


@lru_cache(maxsize=None)
def radial_acceleration(GM: sp.Expr, l: sp.Expr, route: str) -> sp.Expr:
    """r'' as a function of r for angular momentum per unit mass l, by one route."""
    rt, phi = sp.Function("r")(TIME), sp.Function("phi")(TIME)
    rate = sp.Symbol("phidot")
    if route == "lagrange":
        lagrangian = (rt.diff(TIME) ** 2 + rt**2 * phi.diff(TIME) ** 2) / 2 + GM / rt
        equation = sp.diff(lagrangian, rt.diff(TIME)).diff(TIME) - sp.diff(lagrangian, rt)
        accel = sp.solve(equation, rt.diff(TIME, 2))[0]
    else:
        radial = quantity(Path("polar", (rt, phi)), 1, "acceleration.radial")  # r'' - r phi'^2
        position = Path("polar", (rt, phi)).position
        force = -GM * position / rt**3
        along = sp.simplify(force.dot(sp.Matrix([sp.cos(phi), sp.sin(phi)])))
        accel = sp.solve(sp.Eq(radial, along), rt.diff(TIME, 2))[0]
    # l = r^2 phi' is conserved (phi cyclic; a central force has no torque).
    accel = accel.subs(phi.diff(TIME), rate).subs(rate, l / rt**2)
    return sp.simplify(accel.subs(rt, r))


def effective_potential(GM: sp.Expr, l: sp.Expr) -> sp.Expr:
    """U_eff(r) per unit mass, zero at infinity: minus the integral of the radial acceleration."""
    accel = radial_acceleration(GM, l, "lagrange")
    return sp.simplify(-sp.integrate(accel, (r, sp.oo, r)))


def circular_orbit(GM: sp.Expr, l: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """Radius of the circular orbit (the minimum of U_eff) and U_eff there."""
    potential = effective_potential(GM, l)
    (radius,) = [x for x in sp.solve(sp.diff(potential, r), r) if x.is_positive]
    assert sp.diff(potential, r, 2).subs(r, radius).is_positive
    return radius, sp.simplify(potential.subs(r, radius))


@lru_cache(maxsize=None)
def conic(GM: sp.Expr, l: sp.Expr) -> tuple[sp.Expr, sp.Symbol]:
    """The orbit r(f) = p/(1 + e cos f) from u'' + u = GM/l^2, periapsis at f = 0."""
    u = sp.Function("u")
    # r = 1/u(phi): r' = -l u_phi, r'' = -l^2 u^2 u_phiphi; the radial equation becomes:
    accel = radial_acceleration(GM, l, "lagrange")
    equation = sp.Eq(-(l**2) * u(f).diff(f, 2) / r**2, accel).subs(r, 1 / u(f))
    linear = sp.expand(sp.simplify((equation.lhs - equation.rhs) / (-(l**2) * u(f) ** 2)))  # u'' + u - GM/l^2
    solution = sp.dsolve(linear, u(f))
    e = sp.Symbol("e", nonnegative=True)
    constants = solution.rhs.free_symbols - {f, GM, l}
    # Periapsis at f = 0: the cosine's constant is e GM / l^2, the sine's is zero.
    oriented = solution.rhs.subs({c: e * GM / l**2 if solution.rhs.diff(c) == sp.cos(f) else 0 for c in constants})
    return sp.simplify(1 / oriented), e


def kepler(GM: sp.Expr, a: sp.Expr, e: sp.Expr) -> dict[str, sp.Expr]:
    """E (per unit mass), l (per unit mass), period, periapsis and apoapsis of the ellipse (a, e), and the
    speeds there (l / r: the velocity is perpendicular to r at both)."""
    l = sp.Symbol("l", positive=True)
    orbit, e_symbol = conic(GM, l)
    orbit = orbit.subs(e_symbol, e)
    periapsis, apoapsis = orbit.subs(f, 0), orbit.subs(f, sp.pi)
    (l_value,) = [x for x in sp.solve(sp.Eq((periapsis + apoapsis) / 2, a), l) if x.is_positive is not False]
    periapsis, apoapsis = sp.simplify(periapsis.subs(l, l_value)), sp.simplify(apoapsis.subs(l, l_value))
    speed = l_value / periapsis  # at periapsis the velocity is perpendicular to r
    energy = sp.simplify(speed**2 / 2 - GM / periapsis)
    semi_minor = sp.sqrt(periapsis * apoapsis)
    period = sp.simplify(sp.pi * a * semi_minor / (l_value / 2))  # area / areal velocity (Kepler's 2nd law)
    return {"energy": energy, "angular_momentum": l_value, "period": period,
            "periapsis": periapsis, "apoapsis": apoapsis,
            "speed_at_periapsis": speed, "speed_at_apoapsis": sp.simplify(l_value / apoapsis)}
