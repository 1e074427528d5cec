"""A couple that acts for a time on a body turning about a fixed point at its center of mass, where
the weight has no torque (the notes' §5.2: a spinning wheel tilted by a torque for a time dt).

The body spins at omega about its own symmetry axis n (no turning across it at the start), so
its angular momentum about the point is L0 = I3 omega n. A couple tau about a direction a fixed in
space acts from t = 0 to t = dt. Two routes to L at the end:

- impulse: the angular impulse about the fixed point, dL/dt = tau integrated: L1 = L0 + tau dt a;
- euler: Euler's equations in the body frame, I omega' + omega x (I omega) = R^T tau a, with the
  orientation (a quaternion), integrated numerically by derive.mechanics.rigid_motion (scipy DOP853, rtol
  1e-12), the route derive check's 3D simulations take; L1 = R I omega.

L turns through the angle between L0 and L1, atan2(|L0 x L1|, L0 . L1): atan(tau dt/(I3 omega))
for a couple across the spin; its leading term in the impulse is the notes' tau dt/(I3 omega).
The axle itself nods about L: omega = L/I1 + (1/I3 - 1/I1)(L . n) n, so n' = omega x n =
L(t) x n / I1 with L(t) = L0 + tau t a. That linear equation has no closed form (its axis sweeps
while it turns); `AxleTurn` integrates it by mpmath's Taylor method at the working precision, and
the Euler route's R(dt) n checks it.

>>> tau, dt, I, w = sp.symbols("tau dt I omega", positive=True)
>>> turn = momentum_turn(I, w, (1, 0, 0), (0, 0, 1), tau, dt)
>>> turn
atan(dt*tau/(I*omega))
>>> small_angle(I, w, (1, 0, 0), (0, 0, 1), tau, dt)
dt*tau/(I*omega)
"""
from __future__ import annotations

import mpmath
import numpy as np
import sympy as sp

from derive.mechanics import rigid_motion
from derive.core.tidying import tidy
from derive.mechanics.free_rotation import angle_between


def momentum_turn(axial, spin, axis, couple, torque, duration) -> sp.Expr:
    """The angle L turns through from the angular impulse about the fixed point: L0 = I3 omega n
    along the body's axis `axis`, L1 = L0 + tau dt a (`couple`: the unit direction a); both over
    I3 omega, so that the angle's arguments are numbers."""
    before = sp.Matrix(axis)
    return angle_between(before, before + torque * duration / (axial * spin) * sp.Matrix(couple))


def small_angle(axial, spin, axis, couple, torque, duration) -> sp.Expr:
    """The leading term of L's turn in the angular impulse: the torque scaled by a small factor."""
    small = sp.Dummy("epsilon", positive=True)
    turn = momentum_turn(axial, spin, axis, couple, small * torque, duration)
    return tidy(sp.series(turn, small, 0, 2).removeO().subs(small, 1))


def euler(moments, spin, axis, couple, torque, duration) -> tuple[float, float]:
    """(the angle L turns through, the angle the axle turns through) by Euler's equations integrated
    with the orientation (derive.mechanics.rigid_motion: a quaternion, scipy DOP853 at rtol 1e-12), for
    numbers: `moments` (I1, I3) about the point, the body's own z its axis."""
    transverse, axial = (float(m) for m in moments)
    inertia = np.diag([transverse, transverse, axial])
    n = np.array([float(c) for c in axis])
    across = np.cross([0.0, 1.0, 0.0], n) if abs(n[1]) < 0.9 else np.cross([1.0, 0.0, 0.0], n)
    across /= np.linalg.norm(across)
    start = np.column_stack([across, np.cross(n, across), n])  # the body's own axes in the ground frame
    applied = float(torque) * np.array([float(c) for c in couple])
    run = rigid_motion.integrate(rigid_motion.about_point(inertia, couple=applied),
                                 rigid_motion.start(start, float(spin) * n), float(duration))
    end = run.y[:, -1]
    turned = rigid_motion.axes(end)
    return _between(n, turned @ inertia @ end[4:7]), _between(n, turned[:, 2])


def _between(u, v) -> float:
    return float(np.arctan2(np.linalg.norm(np.cross(u, v)), np.dot(u, v)))


class AxleTurn(sp.Function):
    """The angle the axle turns through while the couple acts, of three numbers: P = I3 omega dt/I1
    (L0 dt/I1), A and C = tau dt^2/I1 along and across the axis. The axle n obeys n' = L(t) x n/I1;
    in the time s = t/dt and a frame with n(0) = e1 and the couple in the e1 e2 plane,
    dn/ds = ((P + A s) e1 + C s e2) x n, integrated by mpmath's Taylor method (odefun) at the
    working precision; the angle is atan2(|n(1) x e1|, n(1) . e1).

    >>> AxleTurn(0, 0, 1).evalf(10)  # not spinning: the axle turns about e2 through the integral of s
    0.5000000000
    """

    nargs = 3

    @staticmethod
    def _imp_(phase, along, across):  # lambdify's (floats or mpf)
        phase, along, across = (mpmath.mpf(x) for x in (phase, along, across))

        def rates(s, n):
            lx, ly = phase + along * s, across * s
            return [ly * n[2], -lx * n[2], lx * n[1] - ly * n[0]]

        n = mpmath.odefun(rates, 0, [mpmath.mpf(1), mpmath.mpf(0), mpmath.mpf(0)])(1)
        return mpmath.atan2(mpmath.sqrt(n[1] ** 2 + n[2] ** 2), n[0])

    def _eval_evalf(self, prec):
        if not all(a.is_number for a in self.args):
            return None
        digits = mpmath.libmp.prec_to_dps(prec) + 5
        with mpmath.workdps(digits):
            value = self._imp_(*(mpmath.mpf(sp.Float(sp.N(a, digits), digits)._mpf_) for a in self.args))
        return sp.Float(value, precision=prec)


def axle_turn(moments, spin, axis, couple, torque, duration) -> sp.Expr:
    """The angle the axle turns through while the couple acts (AxleTurn of its three numbers)."""
    transverse, axial = moments
    n, a = sp.Matrix(axis), sp.Matrix(couple)
    scale = torque * duration**2 / transverse
    return AxleTurn(tidy(axial * spin * duration / transverse), tidy(scale * n.dot(a)),
                    tidy(scale * sp.sqrt(tidy(n.cross(a).dot(n.cross(a))))))
