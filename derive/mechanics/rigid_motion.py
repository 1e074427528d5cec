"""The full nonlinear motion of one rigid body in 3D, in numbers: the route by which `derive check`
simulates the 3D answers (derive.checks.simulate_solid), written apart from derive.mechanics (no Euler
angles, no sympy): vectors, matrices and a unit quaternion.

The state starts with the orientation, a quaternion q = (w, x, y, z) that turns the body's axes
into the ground's (z up), q' = q (0, omega)/2 with omega in the body frame; then omega in the
body frame. Three bodies:

- `about_point`: turning about a fixed point under its weight (about its center of mass and
  with no weight: free rotation) and a couple fixed in the ground: Euler's equations in the body
  frame, I omega' = tau - omega x I omega, I the tensor about the point (any tensor), tau = r_cm x
  m g plus the couple;
- `rolling_on_rim`: an axially symmetric body (its axis the body's z) rolling without slipping on
  its rim on a level floor, the center's position three more entries of the state: m a_G = F - m g z
  and dH_G/dt = r_GP x F in the ground frame, with a_G from the rolling condition (the rim's point
  at the contact P is at rest, v_G = omega x r_PG; P the rim's lowest point), which makes
  omega' the solution of a 3 x 3 linear system; `contact_force` gives F along the motion;
- `turned`: a body turned at a constant rate about the ground's z (a shaft in bearings): the
  orientation alone.

Integrated by scipy's DOP853 at rtol 1e-12 (`integrate`). A free body turning about its z:

>>> rates = about_point(np.diag([1.0, 2.0, 3.0]))
>>> run = integrate(rates, start(np.eye(3), [0.0, 0.0, 1.0]), 1.0)
>>> bool(np.allclose(axes(run.y[:, -1])[:, 0], [np.cos(1), np.sin(1), 0]))
True
"""
from __future__ import annotations

import math

import numpy as np

#: The integrator (non-stiff, high order) and its relative tolerance.
METHOD, RTOL = "DOP853", 1e-12
UP = np.array([0.0, 0.0, 1.0])


def axes(state) -> np.ndarray:
    """The body's axes in the ground frame (the columns), from the state's quaternion (normalized)."""
    w, x, y, z = state[:4] / np.sqrt(state[:4] @ state[:4])
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def start(orientation, omega, *rest) -> np.ndarray:
    """A state: the body's axes in the ground frame (columns of `orientation`), omega in the ground
    frame, then any other entries (a rolling body's center)."""
    from scipy.spatial.transform import Rotation  # here, as solve_ivp in `integrate`

    x, y, z, w = Rotation.from_matrix(np.asarray(orientation, dtype=float)).as_quat()
    return np.array([w, x, y, z, *np.asarray(orientation, dtype=float).T @ np.asarray(omega, dtype=float), *rest])


def _turning(q, omega) -> np.ndarray:
    """q' = q (0, omega)/2, omega in the body frame."""
    w, v = q[0], q[1:]
    return 0.5 * np.array([-v @ omega, *(w * omega + np.cross(v, omega))])


def about_point(tensor, mass: float = 0.0, g: float = 0.0, center=(0.0, 0.0, 0.0), couple=(0.0, 0.0, 0.0)):
    """The rates of (q, omega) of a body turning about a fixed point, `tensor` about that point in
    the body frame, its center of mass at `center` (body frame) and its weight m g down; `couple`, a
    constant torque fixed in the ground (ground frame)."""
    inertia = np.asarray(tensor, dtype=float)
    inverse, arm, applied = np.linalg.inv(inertia), np.asarray(center, dtype=float), np.asarray(couple, dtype=float)

    def rates(t, y):
        omega = y[4:7]
        turn = axes(y)
        weight = -mass * g * turn.T @ UP  # in the body frame
        torque = np.cross(arm, weight) + turn.T @ applied - np.cross(omega, inertia @ omega)
        return np.concatenate([_turning(y[:4], omega), inverse @ torque])
    return rates


def _contact(normal, omega, radius):
    """r = P - G (the rim's lowest point from the center) and its rate, for the axis `normal`
    turning at omega (ground frame)."""
    across = UP - (UP @ normal) * normal  # up, within the body's plane
    size = np.linalg.norm(across)
    unit = across / size
    normal_rate = np.cross(omega, normal)
    across_rate = -(UP @ normal_rate) * normal - (UP @ normal) * normal_rate
    return -radius * unit, -radius * (across_rate - unit * (unit @ across_rate)) / size


def _rolling_acceleration(y, I1, I3, mass, g, radius):
    """(omega' in the ground frame, r_GP, the rate of r_GP, omega) of a body rolling on its rim."""
    turn = axes(y)
    omega = turn @ y[4:7]
    normal = turn[:, 2]
    tensor = I1 * np.eye(3) + (I3 - I1) * np.outer(normal, normal)
    r, r_rate = _contact(normal, omega, radius)
    # a_G = -omega' x r - omega x r' (v_G = -omega x r); F = m a_G + m g z; I omega' + omega x I omega = r x F
    system = tensor + mass * ((r @ r) * np.eye(3) - np.outer(r, r))
    right = -np.cross(omega, tensor @ omega) - mass * np.cross(r, np.cross(omega, r_rate)) + mass * g * np.cross(r, UP)
    return np.linalg.solve(system, right), r, r_rate, omega


def contact_point(state, radius: float) -> np.ndarray:
    """Where a body rolling on its rim (the state of `rolling_on_rim`) touches the floor."""
    return state[7:10] + _contact(axes(state)[:, 2], np.zeros(3), radius)[0]


def rolling_on_rim(I1: float, I3: float, mass: float, g: float, radius: float):
    """The rates of (q, omega, G) of an axially symmetric body (moments I1 across its axis, I3
    along it, about its center) rolling without slipping on its rim of `radius` on a level floor."""
    def rates(t, y):
        acceleration, r, _, omega = _rolling_acceleration(y, I1, I3, mass, g, radius)
        turn = axes(y)
        return np.concatenate([_turning(y[:4], y[4:7]), turn.T @ acceleration, -np.cross(omega, r)])
    return rates


def contact_force(y, I1: float, I3: float, mass: float, g: float, radius: float) -> np.ndarray:
    """The floor's force on a body rolling on its rim (ground frame), F = m a_G + m g z."""
    acceleration, r, r_rate, omega = _rolling_acceleration(y, I1, I3, mass, g, radius)
    return mass * (-np.cross(acceleration, r) - np.cross(omega, r_rate)) + mass * g * UP


def turned(rate: float, turn: float = 0.0):
    """The rates of the orientation of a body turned at `rate` about a shaft along the ground's z at
    the start, the shaft itself turned at `turn` about the ground's y (`shaft`)."""
    def rates(t, y):
        omega = rate * shaft(turn, t) + turn * np.array([0.0, 1.0, 0.0])  # in the ground frame
        return _turning(y[:4], axes(y).T @ omega)
    return rates


def shaft(turn: float, t: float) -> np.ndarray:
    """The ground's z turned about its y by turn t: a shaft turned at `turn` from along z."""
    return np.array([math.sin(turn * t), 0.0, math.cos(turn * t)])


def about_y(angle: float) -> np.ndarray:
    """The rotation by `angle` about the ground's y (its columns: the turned axes)."""
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


def integrate(rates, state, duration: float, events=None, rtol: float = RTOL):
    """solve_ivp from `state` over `duration`, dense output; a failed run raises RuntimeError. The
    absolute tolerance of each part of the state (quaternion, omega, the rest) is `rtol`/10 of its size."""
    from scipy.integrate import solve_ivp  # here: half a second to import, and most derivations never integrate

    sizes = [1.0, float(np.linalg.norm(state[4:7])), float(np.linalg.norm(state[7:]))]
    scale = np.concatenate([[sizes[0]] * 4, [sizes[1] or 1.0] * len(state[4:7]), [sizes[2] or 1.0] * len(state[7:])])
    run = solve_ivp(rates, (0.0, duration), state, method=METHOD, rtol=rtol, atol=rtol / 10 * scale,
                    dense_output=True, events=events)
    if not run.success:
        raise RuntimeError(f"the integration failed: {run.message}")
    return run
