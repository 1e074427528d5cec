"""Tilting a spinning wheel (the notes' §5.2): how far the spin axis turns under a torque.

The wheel spins with L = I omega along x; a torque tau along y (perpendicular to the initial
spin) acts for a time dt. Vector route: dL/dt = tau integrates to L = (I omega, tau dt), so
the axis turns by atan(tau dt / (I omega)). Rate route: the axis turns at the perpendicular
torque over |L|, dphi/dt = tau cos(phi)^2 / (I omega), integrated. The notes'
Delta phi = tau dt / (I omega) is the small-angle limit of both. Both are the turn of L: the axle
itself nods about L (a free disk wheel simulated at tau dt/(I omega) = 1/60 turns its axle 3 % more
at the end of the torque), which the notes' picture, the axis along L, leaves out.
The rate route separates the variables: the integral of dphi / cos^2 equals tau dt / (I omega).

>>> tau, dt, I, w = sp.symbols("tau dt I omega", positive=True)
>>> axis_turn(tau, dt, I, w, "vector")
atan(dt*tau/(I*omega))
>>> small_angle(tau, dt, I, w)
dt*tau/(I*omega)
"""
from __future__ import annotations

import sympy as sp

from derive.mechanics.derivation import tidy


def axis_turn(tau, dt, inertia, spin, route: str) -> sp.Expr:
    """The exact angle the spin axis turns through, by one route."""
    if route == "vector":
        momentum = sp.Matrix([inertia * spin, 0]) + sp.Matrix([0, tau]) * dt  # L0 + integral of tau dt
        return tidy(sp.atan(momentum[1] / momentum[0]))
    # Separate the variables: integral of dphi / cos(phi)^2 from 0 to Phi = tau dt / (I omega).
    phi, turned, t = sp.symbols("phi Phi t", positive=True)
    left = sp.integrate(1 / sp.cos(phi) ** 2, (phi, 0, turned))
    right = sp.integrate(tau / (inertia * spin), (t, 0, dt))
    (angle,) = [a for a in sp.solve(sp.Eq(left, right), turned) if a.is_positive is not False]
    return tidy(angle)


def small_angle(tau, dt, inertia, spin) -> sp.Expr:
    """The leading term of the turn for a small impulse tau dt: the notes' formula."""
    exact = axis_turn(tau, dt, inertia, spin, "vector")
    return tidy(sp.series(exact, tau, 0, 2).removeO())
