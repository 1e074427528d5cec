"""A ball that skids, then rolls (beyond the notes): kinetic friction until V + omega R = 0.

The ball moves along +x on a level floor; the contact point, R below the center, slips at
s = V + omega R. Newton–Euler: kinetic friction mu M g opposes the slip, so V falls and omega
turns clockwise at constant rates until s = 0. Conservation: the angular momentum about the
contact point, -M R V + I omega, is conserved (friction and the normal force act there, and
gravity and the normal force balance), which gives the final speed; the time follows from
the linear impulse. Energy: the loss equals the friction's dissipation mu M g s0 t / 2 (the
slip falls linearly from s0 to 0).

>>> M, R, v0, mu, g = sp.symbols("M R v_0 mu g", positive=True)
>>> skid(M, 2 * M * R**2 / 5, R, v0, 0, mu, g, "newton_euler")["speed"]
5*v_0/7
"""
from __future__ import annotations

import sympy as sp

from derive.mechanics.derivation import tidy


def skid(mass, inertia, radius, v0, spin0, mu, g, route: str) -> dict[str, sp.Expr]:
    """Final speed (and spin), time and distance to rolling, and the kinetic energy change."""
    t = sp.Symbol("t", nonnegative=True)
    slip0 = v0 + spin0 * radius
    friction = mu * mass * g  # kinetic, opposing the slip (slip0 > 0)
    if route == "newton_euler":
        speed_t = v0 - friction / mass * t
        spin_t = spin0 - friction * radius / inertia * t  # torque of -f x-hat at (0, -R): -f R
        (duration,) = sp.solve(sp.Eq(speed_t + spin_t * radius, 0), t)
        speed = speed_t.subs(t, duration)
        distance = sp.integrate(speed_t, (t, 0, duration))
    else:
        about_contact = -mass * radius * v0 + inertia * spin0
        final = sp.Symbol("V")
        (speed,) = sp.solve(sp.Eq(-mass * radius * final + inertia * (-final / radius), about_contact), final)
        duration = (v0 - speed) * mass / friction  # linear impulse of the friction
        distance = (v0 + speed) / 2 * duration  # uniform deceleration
    kinetic = lambda v, w: mass * v**2 / 2 + inertia * w**2 / 2  # noqa: E731
    change = kinetic(speed, -speed / radius) - kinetic(v0, spin0)
    if route != "newton_euler":
        change = -friction * slip0 * duration / 2  # dissipated by the slipping contact
    return {"speed": tidy(speed), "spin": tidy(-speed / radius), "duration": tidy(duration),
            "distance": tidy(distance), "energy_change": tidy(change)}
