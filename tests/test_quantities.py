"""The quantities of derive.quantities, asked of setups from textbooks (tests/asks/*.yaml) and
checked against the closed forms the books print; and the inverse asks (`find:` with `equals:`).

Each file cites its source. The closed forms live here, one dict per file, in the file's parameter
symbols, as the magnitude the key gives (with its direction in words: `DIRECTIONS`).
"""
from pathlib import Path
from types import SimpleNamespace

import pytest
import sympy as sp

from conftest import run_derive
from derive import quantities
from derive.core.expr import TIME
from derive.language.problem import load
from derive.numbers import numeric
from derive.publishing import report
from derive.solution.answers import Solution

ASKS = Path(__file__).parent / "asks"
FILES = sorted(ASKS.glob("*.yaml"))


def _r_cross_f(r, f) -> tuple:
    """The books' torque in unit-vector notation, tau = r x F = (y Fz - z Fy) i + (z Fx - x Fz) j + (x Fy - y Fx) k
    (Halliday, Resnick & Walker 10th ed., module 11-6; Serway & Jewett 9th ed., eq. 11.1), written out."""
    (x, y, z), (fx, fy, fz) = r, f
    return (y * fz - z * fy, z * fx - x * fz, x * fy - y * fx)


def _size(v) -> sp.Expr:
    return sp.sqrt(sum(c**2 for c in v))


def _projectile(s) -> tuple:
    """Where a projectile launched from the origin at (vx, vy, vz) is at time t, y up."""
    return (s.vx * TIME, s.vy * TIME - s.g * TIME**2 / 2, s.vz * TIME)


def _from(r, point) -> tuple:
    return tuple(a - b for a, b in zip(r, point))


def _conical_rate(s) -> sp.Expr:
    """The conical pendulum's rate (Kleppner & Kolenkow ch. 7): omega^2 = g/(l cos(alpha))."""
    return sp.sqrt(s.g / (s.l * sp.cos(s.alpha)))


#: file stem -> {ask: closed form of the parameter symbols (a namespace)}, the magnitude the key gives.
EXPECTED = {
    # Serway & Jewett ch. 10: a rod pinned at one end, released horizontal: tau = M g L/2 about the hinge,
    # alpha = 3g/(2L), so I_cm alpha = M g L/8 about the center, where only the hinge's force has a moment.
    "rod_hinge_torques": {
        "tau": lambda s: s.M * s.g * s.L / 2, "net": lambda s: s.M * s.g * s.L / 2,
        "netc": lambda s: s.M * s.g * s.L / 8, "Rt": lambda s: s.M * s.g * s.L / 8,
    },
    # Serway & Jewett ch. 10: a solid ball rolls up an incline at v0 a distance 7 v0^2/(10 g sin(theta)),
    # turning once per 2 pi R of it.
    "ball_rolls_up_incline": {
        "d": lambda s: 7 * s.v0**2 / (10 * s.g * sp.sin(s.theta)),
        "n": lambda s: 7 * s.v0**2 / (10 * s.g * sp.sin(s.theta)) / s.R,  # in rad, SI; the key gives rev
    },
    # Serway & Jewett ch. 10: from rest under a constant torque, omega^2 = 2 (tau/I) phi, so the angle
    # that reaches w1 is I w1^2/(2 tau), with I = M R^2/2 for a disk.
    "flywheel_turns_to_speed": {"n": lambda s: s.M * s.R**2 * s.w1**2 / (4 * s.tau)},
    # Serway & Jewett 9th ed., ch. 11: L = r x p of a particle in space, by components, and its size.
    "particle_angular_momentum_3d": {
        "Lx": lambda s: s.m * (s.y0 * s.vz - s.z0 * s.vy), "Ly": lambda s: s.m * (s.z0 * s.vx - s.x0 * s.vz),
        "Lz": lambda s: s.m * (s.x0 * s.vy - s.y0 * s.vx),
        "L": lambda s: s.m * sp.sqrt((s.y0 * s.vz - s.z0 * s.vy) ** 2 + (s.z0 * s.vx - s.x0 * s.vz) ** 2
                                     + (s.x0 * s.vy - s.y0 * s.vx) ** 2),
    },
    # Serway & Jewett ch. 9, example 9.11: the center of mass of three particles.
    "three_masses_center": {
        "x": lambda s: s.m2 * s.a / (s.m1 + s.m2 + s.m3), "y": lambda s: s.m3 * s.b / (s.m1 + s.m2 + s.m3),
    },
    # Serway & Jewett 9th ed., Example 12.1: the torque of each child's weight about the pivot is m g times its arm.
    "seesaw_torques": {
        "t1": lambda s: s.m1 * s.g * s.L / 2, "t2": lambda s: s.m2 * s.g * s.L / 2, "tw": lambda s: 0,
        "net": lambda s: (s.m1 - s.m2) * s.g * s.L / 2,
    },
    # Serway & Jewett 9th ed., Example 12.3 (beam and cable): about the hinge the cable's torque balances the weight's M g L/2.
    "beam_cable_torques": {"tw": lambda s: s.M * s.g * s.L / 2, "tc": lambda s: s.M * s.g * s.L / 2, "net": lambda s: 0},
    # Halliday, Resnick & Walker 10th ed., ch. 12: torque = force times lever arm, about the hinge and about the far end.
    "beam_hinge_push": {
        "tp": lambda s: s.F * s.d, "twe": lambda s: s.M * s.g * s.L / 2, "tpe": lambda s: s.F * (s.L - s.d),
        "twc": lambda s: 0,
    },
    # Serway & Jewett 9th ed., Example 12.3 (ladder): about the foot, M g (L/2) cos(theta) = P L sin(theta).
    "ladder_torques": {
        "tw": lambda s: s.M * s.g * s.L * sp.cos(s.theta) / 2, "tp": lambda s: s.M * s.g * s.L * sp.cos(s.theta) / 2,
        "net": lambda s: 0, "tf": lambda s: s.M * s.g * s.L * sp.cos(s.theta) / 2,
    },
    # Halliday, Resnick & Walker 10th ed., sec. 11-3: a yo-yo's string pulls T = M g/3, torque T R about its center;
    # about the point where the string leaves, the net torque I_P alpha = M g R is the weight's.
    "yoyo_string_torque": {
        "ts": lambda s: s.M * s.g * s.R / 3, "tw": lambda s: s.M * s.g * s.R, "net": lambda s: s.M * s.g * s.R,
    },
    # Young & Freedman 14th ed., ch. 10: a hinged rod released at beta below the horizontal, alpha = 3 g cos(beta)/(2 L):
    # the weight's torque about the hinge, I_cm alpha about the center, and (I_cm - M L^2/4) alpha about the free end.
    "rod_released_at_angle_torques": {
        "tw": lambda s: s.M * s.g * s.L * sp.cos(s.beta) / 2, "th": lambda s: s.M * s.g * s.L * sp.cos(s.beta) / 8,
        "te": lambda s: s.M * s.g * s.L * sp.cos(s.beta) / 4,
    },
    # Young & Freedman 14th ed., ch. 10: kinetic friction mu M g at the contact of a skidding ball, alpha = 5 mu g/(2 R).
    "bowling_ball_friction_torque": {
        "tf": lambda s: s.mu * s.M * s.g * s.R, "alpha": lambda s: 5 * s.mu * s.g / (2 * s.R),
    },
    # Serway & Jewett 9th ed., sec. 10.9: a rolling cylinder's friction (1/3) M g sin(theta), its torque f R about the
    # center; about the contact point the net torque, the weight's, M g R sin(theta).
    "cylinder_friction_torque": {
        "tf": lambda s: s.M * s.g * s.R * sp.sin(s.theta) / 3, "tw": lambda s: s.M * s.g * s.R * sp.sin(s.theta),
        "net": lambda s: s.M * s.g * s.R * sp.sin(s.theta), "netc": lambda s: s.M * s.g * s.R * sp.sin(s.theta) / 3,
    },
    # Serway & Jewett 9th ed., sec. 10.6 (and Halliday, Resnick & Walker ch. 10): tau = r F sin(phi).
    "door_pushed_at_angle": {"tau": lambda s: s.F * s.L * sp.sin(s.phi), "net": lambda s: s.F * s.L * sp.sin(s.phi)},
    # Halliday, Resnick & Walker 10th ed., sec. 11-3: a yo-yo turns one radian per R its center falls (rad here, SI).
    "yoyo_turns_falling": {"n": lambda s: s.h / s.R, "d": lambda s: s.h},
    # Serway & Jewett 9th ed., sec. 10.9: s = R theta over the incline's length H/sin(beta); v = sqrt(4 g H/3).
    "cylinder_turns_to_bottom": {
        "n": lambda s: s.H / (s.R * sp.sin(s.beta)), "d": lambda s: s.H / sp.sin(s.beta),
        "v": lambda s: sp.sqrt(4 * s.g * s.H / 3),
    },
    # Halliday, Resnick & Walker 10th ed., ch. 10: a frictional torque C stops a wheel after I w0^2/(2 C), I = M R^2/2.
    "brake_turns_to_stop": {"n": lambda s: s.M * s.R**2 * s.w0**2 / (4 * s.C)},
    # Serway & Jewett 9th ed., ch. 10: omega^2 = 2 (tau/I) theta, omega = (tau/I) t, a hoop I = M R^2.
    "wheel_torque_turns_to_speed": {
        "n": lambda s: s.M * s.R**2 * s.w1**2 / (2 * s.tau), "t": lambda s: s.M * s.R**2 * s.w1 / s.tau,
    },
    # Serway & Jewett 9th ed., ch. 10 problems: a ball launched without spin skids
    # t = 2 v0/(7 mu g), d = 12 v0^2/(49 mu g), turning 5 v0^2/(49 mu g R) rad.
    "bowling_ball_skid": {
        "t": lambda s: 2 * s.v0 / (7 * s.mu * s.g), "d": lambda s: 12 * s.v0**2 / (49 * s.mu * s.g),
        "n": lambda s: 5 * s.v0**2 / (49 * s.mu * s.g * s.R),
    },
    # Halliday, Resnick & Walker 10th ed., ch. 8: (1/2) m v0^2 = mu_k m g d; t = v0/(mu_k g).
    "block_slides_to_stop_floor": {
        "d": lambda s: s.v0**2 / (2 * s.mu * s.g), "t": lambda s: s.v0 / (s.mu * s.g),
    },
    # Young & Freedman 14th ed., ch. 10: a hoop rolling up a slope at v0 goes v0^2/(g sin(beta)), turning d/R rad.
    "hoop_rolls_up_incline": {
        "d": lambda s: s.v0**2 / (s.g * sp.sin(s.beta)), "n": lambda s: s.v0**2 / (s.g * s.R * sp.sin(s.beta)),
    },
    # Halliday, Resnick & Walker 10th ed., ch. 11: a solid cylinder rolling up a ramp at v0 goes 3 v0^2/(4 g sin(theta)).
    "disk_rolls_up_incline": {"d": lambda s: 3 * s.v0**2 / (4 * s.g * sp.sin(s.theta))},
    # Serway & Jewett 9th ed., ch. 9: the Earth-Moon center of mass, and the Moon's distance from it.
    "earth_moon_center": {
        "x": lambda s: s.mM * s.d / (s.ME + s.mM), "xm": lambda s: s.ME * s.d / (s.ME + s.mM),
    },
    # Halliday, Resnick & Walker 10th ed., ch. 9: two rods in an L, each a particle at its own center.
    "l_shaped_rods_center": {
        "x": lambda s: s.m1 * s.L1 / (2 * (s.m1 + s.m2)), "y": lambda s: s.m2 * s.L2 / (2 * (s.m1 + s.m2)),
    },
    # Halliday, Resnick & Walker 10th ed., ch. 9 problems: the water molecule.
    "water_molecule_center": {
        "x": lambda s: 2 * s.mH * s.d * sp.cos(s.phi) / (s.mO + 2 * s.mH), "y": lambda s: 0,
    },
    # Halliday, Resnick & Walker 10th ed., ch. 9 problems: an Atwood machine's center of mass drops (m1 - m2) h/(m1 + m2).
    "atwood_center_moves": {
        "y0": lambda s: -s.D, "y": lambda s: -s.D - (s.m1 - s.m2) * s.h / (s.m1 + s.m2),
    },
    # Young & Freedman 14th ed., ch. 8: a rod from the origin and a disk beyond its end, each at its own center.
    "rod_and_disk_center": {
        "x": lambda s: (s.m * s.L / 2 + s.M * (s.L + s.R)) / (s.m + s.M),
        "xd": lambda s: s.L + s.R - (s.m * s.L / 2 + s.M * (s.L + s.R)) / (s.m + s.M),
    },
    # Kleppner & Kolenkow 2nd ed., ch. 4: no horizontal force, so a rod on a smooth floor falls with its center's x kept.
    "rod_falls_flat_center": {
        "x0": lambda s: s.L * sp.sin(s.theta0) / 2, "x": lambda s: s.L * sp.sin(s.theta0) / 2, "y": lambda s: 0,
    },
    # Serway & Jewett 9th ed., ch. 10: a = m g/(m + M/2) for a block on a cord wound on a disk, solved for m.
    "hanging_mass_for_acceleration": {"mb": lambda s: s.M * s.a1 / (2 * (s.g - s.a1))},
    # Kleppner & Kolenkow 2nd ed., ch. 7: a = (m1 - m2) g/(m1 + m2 + M/2), solved for m1.
    "atwood_mass_for_acceleration": {"mh": lambda s: (s.m2 * (s.g + s.a1) + s.M * s.a1 / 2) / (s.g - s.a1)},
    # Serway & Jewett 9th ed., ch. 10: a rolling solid sphere reaches v = sqrt(10 g h/7), so h = 7 v^2/(10 g).
    "sphere_release_height": {"h": lambda s: 7 * s.v1**2 / (10 * s.g)},
    # Serway & Jewett 9th ed., ch. 10: omega^2 = 2 alpha phi with alpha = m g/(R (m + M/2)) and v = R omega (rad, SI).
    "wheel_turns_for_block_speed": {"n": lambda s: s.v1**2 * (s.m + s.M / 2) / (2 * s.m * s.g * s.R)},
    # Kleppner & Kolenkow ch. 7: Atwood's machine with a disk pulley, a = (m1 - m2) g/(m1 + m2 + M/2); the cord's
    # net torque on the pulley (T1 - T2) R = (M R^2/2) a/R.
    "atwood_pulley_torques": {
        "tr": lambda s: s.M * s.R * s.g * (s.m1 - s.m2) / (s.M + 2 * s.m1 + 2 * s.m2),
        "net": lambda s: s.M * s.R * s.g * (s.m1 - s.m2) / (s.M + 2 * s.m1 + 2 * s.m2),
    },
    # Serway & Jewett ch. 8: up a rough incline at v0, d = v0^2/(2 g (sin(theta) + mu_k cos(theta))).
    "block_slides_up_rough_incline": {"d": lambda s: s.v0**2 / (2 * s.g * (sp.sin(s.theta) + s.mu * sp.cos(s.theta)))},
    # Serway & Jewett ch. 10 problems: a ball launched without spin skids 12 v0^2/(49 mu g), turning 5 v0^2/(49 mu g R) rad.
    "bowling_ball_skid_distance": {
        "d": lambda s: 12 * s.v0**2 / (49 * s.mu * s.g), "n": lambda s: 5 * s.v0**2 / (49 * s.mu * s.g * s.R),
    },
    # Serway & Jewett sec. 10.6: tau = r F sin(phi), so the torque tau0 needs sin(phi) = tau0/(r F).
    "door_angle_for_torque": {"ang": lambda s: sp.asin(s.tau0 / (s.F * s.L))},
    # Serway & Jewett Example 12.3: about the foot the weight's torque M g (L/2) cos(theta) balances the wall's push;
    # about the top, the floor's force has the same moment.
    "ladder_torques_rough": {
        "tw": lambda s: s.M * s.g * s.L * sp.cos(s.theta) / 2, "tp": lambda s: s.M * s.g * s.L * sp.cos(s.theta) / 2,
        "net": lambda s: sp.Integer(0), "tf": lambda s: s.M * s.g * s.L * sp.cos(s.theta) / 2,
    },
    # Halliday, Resnick & Walker sec. 11-6: tau_z = x F_y - y F_x.
    "particle_force_torque": {
        "tau": lambda s: s.F * (s.a * sp.sin(s.phi) - s.b * sp.cos(s.phi)), "tq": lambda s: s.F * s.b * sp.cos(s.phi),
    },
    # Serway & Jewett ch. 10: a solid ball rolling up an incline at v0 goes 7 v0^2/(10 g sin(theta)): D needs
    # v0 = sqrt(10 g D sin(theta)/7).
    "ramp_speed_for_distance": {"v": lambda s: sp.sqrt(10 * s.g * s.D * sp.sin(s.theta) / 7)},
    # Serway & Jewett Example 12.1: the daughter balances the father at l = m_f d/m_d.
    "seesaw_balance_point": {"x": lambda s: s.mf * s.d / s.md},
    # Serway & Jewett ch. 10: omega^2 = 2 (tau/I) theta from rest, I = M R^2/2: tau = M R^2 w1^2/(4 theta), theta in
    # rad (SI; the file's N turns).
    "torque_for_turns_to_speed": {"T": lambda s: s.M * s.R**2 * s.w1**2 / (4 * s.N)},
    # Kleppner & Kolenkow ch. 7: a rectangular plate w x h about its diagonal, I = M w^2 h^2/(6 (w^2 + h^2)).
    "plate_about_its_diagonal": {"I": lambda s: s.M * s.w**2 * s.h**2 / (6 * (s.w**2 + s.h**2))},
    # Halliday, Resnick & Walker sec. 11-3: a yo-yo turns one radian per R its center falls (rad here, SI).
    "yoyo_turns_from_rest": {"n": lambda s: s.h / s.R, "d": lambda s: s.h},
    # Halliday, Resnick & Walker 10th ed., ch. 11 (Torque revisited): a particle at (0, -4.0 m, 3.0 m), F1 = (2.0 N) i:
    # tau = r x F = (6.0 N m) j + (8.0 N m) k; about another point, r is measured from it. Held at rest: no net torque.
    "force_on_particle_torque_3d": {
        "tx": lambda s: _r_cross_f((0, s.y0, s.z0), (s.F, 0, 0))[0],
        "ty": lambda s: _r_cross_f((0, s.y0, s.z0), (s.F, 0, 0))[1],
        "tz": lambda s: _r_cross_f((0, s.y0, s.z0), (s.F, 0, 0))[2],
        "t": lambda s: _size(_r_cross_f((0, s.y0, s.z0), (s.F, 0, 0))),
        "tpy": lambda s: _r_cross_f((-s.a, s.y0, s.z0 - s.c), (s.F, 0, 0))[1],
        "tpz": lambda s: _r_cross_f((-s.a, s.y0, s.z0 - s.c), (s.F, 0, 0))[2],
        "net": lambda s: sp.Integer(0),
    },
    # Serway & Jewett 9th ed., ch. 11, sec. 11.1 problems: r = (4.00 i + 6.00 j) m, F = (3.00 i + 2.00 j) N, so
    # tau = (x Fy - y Fx) k = -10.0 k N m; about a point h up the z axis, r - r_P = (x, y, -h).
    "force_in_plane_torque_vector": {
        "tz": lambda s: _r_cross_f((s.x0, s.y0, 0), (s.Fx, s.Fy, 0))[2],
        "t": lambda s: sp.Abs(_r_cross_f((s.x0, s.y0, 0), (s.Fx, s.Fy, 0))[2]),
        "thx": lambda s: _r_cross_f((s.x0, s.y0, -s.h), (s.Fx, s.Fy, 0))[0],
        "thy": lambda s: _r_cross_f((s.x0, s.y0, -s.h), (s.Fx, s.Fy, 0))[1],
        "thz": lambda s: _r_cross_f((s.x0, s.y0, -s.h), (s.Fx, s.Fy, 0))[2],
    },
    # Serway & Jewett 9th ed., ch. 11, sec. 11.2 problems: a projectile from the origin, tau = r x m g (= -m g x k in
    # the plane) and L = m r x v (= -(1/2) m g vx t^2 k in the plane), here with a velocity vz out of the plane too.
    "projectile_torque_3d": {
        **{name: (lambda i: lambda s: _r_cross_f(_projectile(s), (0, -s.m * s.g, 0))[i])(i)
           for i, name in enumerate(("tx", "ty", "tz"))},
        "netz": lambda s: _r_cross_f(_projectile(s), (0, -s.m * s.g, 0))[2],
        "Lx": lambda s: s.m * _r_cross_f(_projectile(s), [c.diff(TIME) for c in _projectile(s)])[0],
        "Lz": lambda s: s.m * _r_cross_f(_projectile(s), [c.diff(TIME) for c in _projectile(s)])[2],
        "tpx": lambda s: _r_cross_f(_from(_projectile(s), (0, s.H, s.D)), (0, -s.m * s.g, 0))[0],
        "Lpx": lambda s: s.m * _r_cross_f(_from(_projectile(s), (0, s.H, s.D)), [c.diff(TIME) for c in _projectile(s)])[0],
    },
    # Kleppner & Kolenkow 2nd ed., ch. 7, the conical pendulum: about the pivot, tau = dL/dt is horizontal, of size
    # m g l sin(alpha) (the weight's; the string's passes through the pivot); L = m l^2 omega sin(alpha), its vertical
    # part m l^2 omega sin(alpha)^2. alpha lies in (0, pi/2): sin(alpha) = |sin(alpha)|, as derive writes it.
    "conical_pendulum_torque": {
        "tw": lambda s: s.m * s.g * s.l * sp.Abs(sp.sin(s.alpha)), "net": lambda s: s.m * s.g * s.l * sp.Abs(sp.sin(s.alpha)),
        "nety": lambda s: sp.Integer(0),
        "L": lambda s: s.m * s.l**2 * _conical_rate(s) * sp.Abs(sp.sin(s.alpha)),
        "Ly": lambda s: s.m * s.l**2 * _conical_rate(s) * sp.sin(s.alpha) ** 2,
    },
}
#: The direction in words each directed answer is given with, in every variant.
DIRECTIONS = {("rod_hinge_torques", "tau"): "clockwise", ("rod_hinge_torques", "netc"): "clockwise",
              ("ball_rolls_up_incline", "n"): "counter-clockwise",
              ("seesaw_torques", "t1"): "counter-clockwise",
              ("seesaw_torques", "t2"): "clockwise",
              ("seesaw_torques", "net"): "counter-clockwise",
              ("beam_cable_torques", "tw"): "clockwise",
              ("beam_cable_torques", "tc"): "counter-clockwise",
              ("beam_hinge_push", "tp"): "counter-clockwise",
              ("beam_hinge_push", "twe"): "counter-clockwise",
              ("beam_hinge_push", "tpe"): "clockwise",
              ("ladder_torques", "tw"): "counter-clockwise",
              ("ladder_torques", "tp"): "clockwise",
              ("ladder_torques", "tf"): "counter-clockwise",
              ("yoyo_string_torque", "ts"): "clockwise",
              ("yoyo_string_torque", "tw"): "clockwise",
              ("yoyo_string_torque", "net"): "clockwise",
              ("rod_released_at_angle_torques", "tw"): "clockwise",
              ("rod_released_at_angle_torques", "th"): "clockwise",
              ("rod_released_at_angle_torques", "te"): "counter-clockwise",
              ("bowling_ball_friction_torque", "tf"): "clockwise",
              ("cylinder_friction_torque", "tf"): "clockwise",
              ("cylinder_friction_torque", "tw"): "clockwise",
              ("cylinder_friction_torque", "net"): "clockwise",
              ("cylinder_friction_torque", "netc"): "clockwise",
              ("door_pushed_at_angle", "tau"): "counter-clockwise",
              ("door_pushed_at_angle", "net"): "counter-clockwise",
              ("yoyo_turns_falling", "n"): "clockwise",
              ("cylinder_turns_to_bottom", "n"): "clockwise",
              ("brake_turns_to_stop", "n"): "counter-clockwise",
              ("wheel_torque_turns_to_speed", "n"): "counter-clockwise",
              ("bowling_ball_skid", "n"): "clockwise",
              ("hoop_rolls_up_incline", "n"): "counter-clockwise",
              ("ladder_torques_rough", "tw"): "counter-clockwise", ("ladder_torques_rough", "tp"): "clockwise",
              ("particle_force_torque", "tau"): "counter-clockwise", ("particle_force_torque", "tq"): "clockwise",
              ("atwood_pulley_torques", "tr"): "counter-clockwise"}


def test_every_file_has_its_closed_forms():
    assert {f.stem for f in FILES} == set(EXPECTED)


@pytest.mark.parametrize("path", FILES, ids=[f.stem for f in FILES])
def test_a_textbook_ask_of_a_quantity_gives_the_books_closed_form(path):
    problem = load(str(path))
    assert problem.source
    solution = Solution(problem)
    symbols = SimpleNamespace(**{name: p.symbol for name, p in problem.parameters.items()})
    assert set(EXPECTED[path.stem]) == set(problem.asks)
    for name, closed_form in EXPECTED[path.stem].items():
        assert sp.simplify(solution.expression(name) - closed_form(symbols)) == 0, (name, solution.expression(name))
    result = report.solve(problem, solution=solution)
    assert result["checks"] and all(c["passed"] for c in result["checks"].values())
    # every quantity of derive.quantities is checked by a second route: its own, or the motion simulated,
    # or the checks its module names (an inertia's against the tensor)
    for name, ask in problem.asks.items():
        kind = quantities.KINDS.get(ask.quantity.kind)
        own = kind.checks(solution, [name]) if kind is not None else None
        if own is not None:
            assert all(c.name in result["checks"] for c in own), name  # a mass is given: none
        elif kind is not None:
            assert kind.kind in result["checks"] or "states" in result["checks"], name
    for (stem, name), words in DIRECTIONS.items():
        if stem == path.stem:
            assert result["answers"][name]["direction"] == words


def test_turns_are_given_in_rev_and_their_formula_too():
    problem = load(str(ASKS / "ball_rolls_up_incline.yaml"))
    result = report.solve(problem, {"M": "1", "R": "0.1", "theta": "0.5", "v0": "2"})
    # n = 7 v0^2/(10 g sin(theta)) / (2 pi R) turns
    expected = 7 * 4 / (10 * 9.81 * float(sp.sin(sp.Rational(1, 2)))) / (2 * float(sp.pi) * 0.1)
    assert abs(float(result["answers"]["n"]["value"]) - expected) < 1e-2 * expected
    text = run_derive("solve", str(ASKS / "ball_rolls_up_incline.yaml")).stdout
    assert "20⋅π⋅R⋅g⋅sin(θ)" in text  # the formula printed in turns, not radians


def test_the_torque_check_catches_a_wrong_lever_arm(monkeypatch):
    """Route 0 planted wrong (the weight's point moved): the check by Lagrange's route fails."""
    from derive.quantities import torque
    from derive.solution.crosschecks import CheckFailure

    problem = load(str(ASKS / "rod_hinge_torques.yaml"))
    real = torque.Torque.value

    def planted(self, solution, ask, route):
        value = real(self, solution, ask, route)
        return value * 2 if route == 0 and ask.quantity.detail is None else value

    monkeypatch.setattr(torque.Torque, "value", planted)
    with pytest.raises(CheckFailure, match="net"):
        Solution(problem).checks()


REFUSED = [
    ({"of": "rod.weight.torque", "unit": "N*m"}, "about", "a torque is taken about a point"),
    ({"of": "rod.angular_acceleration", "about": "hinge", "unit": "rad/s^2"}, "about", "only a torque"),
    ({"of": "rod.spring.torque", "about": "hinge", "unit": "N*m"}, "of", "bears no load 'spring'"),
    ({"of": "rod.weight.torque", "about": "rod.middle", "unit": "N*m"}, "about", "has no point 'middle'"),
    ({"of": "rod.weight.torque", "about": "hinge", "unit": "N"}, "unit", "a torque is in N*m"),
    ({"of": "rod.weight.torque", "about": "hinge", "unit": "N*m", "find": "M"}, "equals", "needs the value"),
    ({"of": "rod.weight.torque", "about": "hinge", "unit": "kg", "find": "M", "equals": "2 N*m"}, "equals",
     "points one way or the other"),
    ({"of": "rod.weight.torque", "about": "hinge", "unit": "kg", "zero_for": "M", "equals": "2 N*m"}, "equals",
     "give find:"),
    ({"of": "center_of_mass.position.z", "unit": "m"}, "of", "position.x and position.y"),
]


@pytest.mark.parametrize("ask, field, message", REFUSED, ids=[r[2] for r in REFUSED])
def test_an_ask_that_cannot_mean_anything_is_refused_naming_its_field(tmp_path, ask, field, message):
    text = (ASKS / "rod_hinge_torques.yaml").read_text()
    head = text.split("ask:")[0]
    path = tmp_path / "p.yaml"
    body = ", ".join(f"{k}: {v}" for k, v in ask.items())
    path.write_text(head + f"ask:\n  q: {{meaning: a quantity, {body}}}\nquestion: |\n  Find it.\n")
    result = run_derive("solve", str(path))
    assert result.returncode == 2, result.stdout + result.stderr
    assert f"ask.q.{field}" in result.stderr and message in result.stderr, result.stderr


def test_turns_of_a_point_mass_and_in_radians_are_refused(tmp_path):
    text = (ASKS / "ball_rolls_up_incline.yaml").read_text()
    for old, new, field, message in (("unit: rev}", "unit: rad}", "ask.n.unit", "asked in rev"),
                                     ("in: highest, unit: rev", "unit: rev", "ask.n.in", "give in: STATE")):
        path = tmp_path / "p.yaml"
        path.write_text(text.replace(old, new))
        result = run_derive("solve", str(path))
        assert result.returncode == 2 and field in result.stderr and message in result.stderr, result.stderr


def test_an_inverse_ask_solves_for_the_parameter_and_refuses_more_than_one_root(tmp_path):
    """The rod's weight about the hinge with the rod at theta from the horizontal: M g L cos(theta)/2,
    clockwise. Asked where it is M g L/4 (counted clockwise), theta = pi/3 in [0.1, 1.5]; over
    [0.1, 6] there is a second root, 5 pi/3, and the ask is refused."""
    text = (ASKS / "rod_hinge_torques.yaml").read_text().split("ask:")[0]
    text = text.replace("angle: 0}", "angle: -theta}").replace(
        "  g: {meaning", "  theta: {meaning: angle below the horizontal, unit: rad, range: [0.1, 1.5], sig_figs: 2}\n"
                         "  g: {meaning")
    ask = ("ask:\n  th: {meaning: angle where the torque is half its greatest, of: rod.weight.torque, about: hinge,"
           " find: theta, equals: M*g*L/4, sign: clockwise positive, unit: rad}\n"
           "question: |\n  At what angle is the torque of its weight (clockwise positive) half its greatest?\n")
    path = tmp_path / "p.yaml"
    path.write_text(text + ask)
    solution = Solution(load(str(path)))
    assert solution.expression("th") == sp.pi / 3
    path.write_text(text.replace("[0.1, 1.5]", "[0.1, 6]") + ask)
    result = run_derive("solve", str(path))
    assert result.returncode == 2 and "ask.th.find" in result.stderr and "not one" in result.stderr, result.stderr


def test_an_inverse_ask_checks_its_root_against_a_scan_of_the_range():
    """sympy solves tan(x) = 1 with one root, pi/4; over [0.1, 4] the scan of the sign finds 5 pi/4 too."""
    from derive.solution import inverse

    theta = sp.Symbol("theta", positive=True)
    parameter = SimpleNamespace(name="theta", symbol=theta, range=(0.1, 4), si_ends=(sp.Rational(1, 10), 4))
    problem = SimpleNamespace(parameters={"theta": parameter}, error=lambda field, text: ValueError(f"{field}: {text}"))
    with pytest.raises(ValueError, match="times in its range"):
        inverse._check(problem, "ask.x.find", sp.sin(theta) - sp.cos(theta), theta, sp.pi / 4, {}, parameter)
    inverse._check(problem, "ask.x.find", sp.sin(theta) - sp.cos(theta), theta, sp.pi / 4, {},
                   SimpleNamespace(name="theta", symbol=theta, range=(0.1, 3), si_ends=(sp.Rational(1, 10), 3)))
    assert numeric.evaluate(sp.pi / 4, {}, 5) == "0.78540"


def test_an_axis_is_a_direction_through_the_center_of_mass_or_is_refused(tmp_path):
    """A plate's diagonal as [w, h, 0]; no direction is [0, 0, 0]; a direction is three components."""
    text = (ASKS / "plate_about_its_diagonal.yaml").read_text()
    for axis, message in (("[0, 0, 0]", "no direction"), ("[w, h]", "expected a direction")):
        path = tmp_path / "p.yaml"
        path.write_text(text.replace("[w, h, 0]", axis))
        result = run_derive("solve", str(path))
        assert result.returncode == 2 and "ask.I.axis" in result.stderr and message in result.stderr, result.stderr


def test_a_path_in_space_answers_in_space_and_refuses_the_planes_quantities(tmp_path):
    """A particle on a path with z: its speed counts z; its radial acceleration and areal velocity, notions of
    the plane, are refused; z is a cartesian path's only, and the components are x, y, z and magnitude."""
    text = (ASKS / "particle_angular_momentum_3d.yaml").read_text()
    head = text.split("ask:")[0]
    path = tmp_path / "p.yaml"
    path.write_text(head + "ask:\n  v: {meaning: speed, of: particle.speed, unit: m/s}\nquestion: |\n  Find it.\n")
    solution = Solution(load(str(path)))
    s = {name: p.symbol for name, p in solution.problem.parameters.items()}
    assert sp.simplify(solution.expression("v") - sp.sqrt(s["vx"] ** 2 + s["vy"] ** 2 + s["vz"] ** 2)) == 0
    for ask, field, message in (("particle.areal_velocity", "ask.q.of", "of a path in the plane"),
                                ("particle.angular_momentum.w", "ask.q.of", "angular_momentum.x|y|z|magnitude")):
        path.write_text(head + f"ask:\n  q: {{meaning: a quantity, of: {ask}, unit: m^2/s}}\nquestion: |\n  Find it.\n")
        result = run_derive("solve", str(path))
        assert result.returncode == 2 and field in result.stderr and message in result.stderr, result.stderr
    polar = text.replace("{cartesian: {x: x0 + vx*t, y: y0 + vy*t, z: z0 + vz*t}}", "{polar: {r: x0, theta: vx*t/x0, z: z0}}")
    path.write_text(polar)
    result = run_derive("solve", str(path))
    assert result.returncode == 2 and "path.polar.z" in result.stderr and "unknown key" in result.stderr, result.stderr


def test_a_torques_worked_solution_names_no_cord_by_its_key():
    """Issue 37, item 5: the pulley's two sides are tau_1 and tau_2 (one symbol, one meaning), not both
    tau_rope, and the terminal's solution says "the cord", as the documents do, never the file's key."""
    solution = Solution(load(str(ASKS / "atwood_pulley_torques.yaml")))
    sections = [s for title, steps in solution.student_steps.items() if "torque" in title for s in steps]
    named = [str(e.lhs) for step in sections for e in step.equations if str(e.lhs).startswith("tau")]
    assert set(named) >= {"tau_1", "tau_2"} and not any("rope" in n for n in named)
    out = run_derive("solve", str(ASKS / "atwood_pulley_torques.yaml")).stdout
    assert "rope" not in out.split("Answers:")[0] and "the cord on the pulley" in out


def test_a_particles_torque_in_space_is_the_rate_of_its_angular_momentum():
    """Serway & Jewett ch. 11: about a fixed point tau = dL/dt, component by component, the torque module's key
    against the time derivative of the angular momentum module's; under gravity alone the net torque is the weight's."""
    solution = Solution(load(str(ASKS / "projectile_torque_3d.yaml")))
    assert sp.simplify(solution.expression("Lz").diff(TIME) - solution.expression("netz")) == 0
    assert sp.simplify(solution.expression("Lx").diff(TIME) - solution.expression("tx")) == 0
    assert solution.expression("netz") == solution.expression("tz") != 0
    # about a fixed point off the launch point too: the weight's torque is the rate of L about it
    assert sp.simplify(solution.expression("Lpx").diff(TIME) - solution.expression("tpx")) == 0


@pytest.mark.parametrize("ask, extra, field, message", [
    ("particle.push.torque", "about: [0, 0, 0]", "ask.q.of", "is a vector: ask particle.push.torque.x|y|z|magnitude"),
    ("particle.torque.magnitud", "about: [0, 0, 0]", "ask.q.of", "did you mean 'magnitude'"),
    ("particle.weight.torque.x", "about: [0, 0, 0]", "ask.q.of", "bears no force 'weight' (no gravity)"),
    ("particle.coil.torque.x", "about: [0, 0, 0]", "ask.q.of", "the torque of the coil on a body on a path is not modelled"),
    ("particle.push.torque.x", "about: particle", "ask.q.about", "taken about a fixed point: [x, y, z]"),
    ("particle.push.torque.x", "about: [0, 0, 0, 0]", "ask.q.about", "taken about a fixed point: [x, y, z]"),
    ("particle.push.torque.x", "", "ask.q.about", "give about: [x, y, z]"),
    ("particle.speed", "about: [0, 0, 0]", "ask.q.about", "only a torque or a particle's angular momentum"),
    ("particle.angular_momentum.x", "about: particle", "ask.q.about", "taken about a fixed point: [x, y, z]"),
])
def test_a_particles_torque_in_space_refuses_what_it_does_not_model(tmp_path, ask, extra, field, message):
    """One line naming the file and the field, exit 2: a torque is a vector (a component or its size), of the net
    force, the weight (with gravity) or a given force, about a fixed point; a spring on a body on a path is not modelled."""
    head = (ASKS / "force_on_particle_torque_3d.yaml").read_text().split("ask:")[0]
    head = head.replace("    - force: {on: particle, magnitude: F, name: push}\n", "    - force: {on: particle, magnitude: F, name: push}\n"
                        "    - spring: {between: [particle, [a, 0]], stiffness: F/a, name: coil}\n")
    path = tmp_path / "p.yaml"
    path.write_text(head + f"ask:\n  q: {{meaning: a torque, of: {ask}, unit: N*m{', ' + extra if extra else ''}}}\n"
                    "question: |\n  Find it.\n")
    result = run_derive("solve", str(path))
    assert result.returncode == 2 and f"{path}: {field}" in result.stderr and message in result.stderr, result.stderr
    assert len(result.stderr.strip().splitlines()) == 1


def test_a_component_in_space_has_its_axis_sign_where_the_question_names_the_axis(tmp_path):
    """The signs check of derive check: a negative z component passes where the z axis is named, and is refused,
    naming the ask, where neither the question nor the meaning names it."""
    from derive.checks import signs

    text = (ASKS / "force_in_plane_torque_vector.yaml").read_text()
    assert signs.unstated(Solution(load(str(ASKS / "force_in_plane_torque_vector.yaml")))) == []
    path = tmp_path / "p.yaml"
    path.write_text(text.replace("z component of the torque about the origin", "the torque about the origin along one line")
                    .replace("its z component and its size", "one part and its size")
                    .replace("height of the point above the plane", "height of the point").replace("z axis", "axis"))
    found = signs.unstated(Solution(load(str(path))))
    assert len(found) == 1 and found[0].startswith("ask.tz: ") and "names the z axis" in found[0], found
