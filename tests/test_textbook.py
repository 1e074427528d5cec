"""Textbook setups the engine was not designed around, each answered against the closed form the
book prints: the library problems whose `source` is a book (problems/TOPIC/*.yaml; the lecture
notes' problems cite the notes), and any kept in tests/textbook/*.yaml.

Each problem file cites its source in `source:`; the closed forms live here, one dict per file,
written with the problem's own parameter symbols. Every file's
checks (what `derive solve` reports) must pass, Lagrange and Newton-Euler in agreement.
Setups the engine cannot state, refuses or answers wrongly are listed in
tests/textbook/PENDING.md (with their files quoted there), not here.
"""
from types import SimpleNamespace

import pytest
import sympy as sp

from conftest import derived, textbook, textbook_files
from derive.numbers import numeric
from derive.publishing import report



def _sin(x):
    return sp.sin(x)


def _cos(x):
    return sp.cos(x)


_PHI = sp.Symbol("phi", positive=True)


def _omega_squared(s, phi):
    """A rod falling on a smooth floor, released at theta0 from the vertical: phi'^2 at phi."""
    return 12 * s.g * (_cos(s.theta0) - _cos(phi)) / (s.L * (1 + 3 * _sin(phi) ** 2))


def _rims_rate(s):
    """Two disks on fixed axles pressed at their rims (K&K ch. 7): the first one's final rate."""
    i1, i2 = s.M1 * s.R1**2 / 2, s.M2 * s.R2**2 / 2
    return (i1 * s.R2**2 * s.w1 - i2 * s.R1 * s.R2 * s.w2) / (i1 * s.R2**2 + i2 * s.R1**2)


def _wedge_vy(s):
    """A ball dropped from h onto a smooth face at 45 degrees: its vertical velocity just after."""
    return -(1 - s.e) * sp.sqrt(2 * s.g * s.h) / 2


def _tangent_cosine(s):
    """The cosine of the angle a cord makes with a face tangent to a pulley of radius R below it, from a
    block d along the face from the point of contact to the pulley's far side: 2 atan(R/d)."""
    return (s.d**2 - s.R**2) / (s.d**2 + s.R**2)


#: file stem -> {ask: closed form as a function of the parameter symbols (a namespace)}.
EXPECTED = {
    # Rocking without slipping on a round face off the center of mass (a custom body's round_center, a
    # composite's round part off its center of mass). Morin ch. 8: omega^2 = m g d/(I_cm + m (R - d)^2):
    # a solid hemisphere (d = 3R/8, I_cm = 83 m R^2/320) 15 g/(26 R); a half-cylinder (d = 4R/(3 pi))
    # 8 g/((9 pi - 16) R); Kleppner & Kolenkow ch. 7: a hoop loaded at its rim, m g/(2 M R).
    "hemisphere_rocking": {"w": lambda s: sp.sqrt(15 * s.g / (26 * s.R)),
                           "T": lambda s: 2 * sp.pi * sp.sqrt(26 * s.R / (15 * s.g))},
    "half_cylinder_rocking": {"T": lambda s: 2 * sp.pi / sp.sqrt(8 * s.g / ((9 * sp.pi - 16) * s.R))},
    "loaded_hoop_rocking": {"w": lambda s: sp.sqrt(s.m * s.g / (2 * s.M * s.R))},
    # A body on a fixed point hanging below it, turning as one in a cone (rod.conical.rate). Kleppner &
    # Kolenkow ch. 7: a uniform rod pivoted at its upper end, at theta from the vertical: omega^2 = 3 g/(2 L cos(theta)).
    "rod_conical_pendulum": {"W": lambda s: sp.sqrt(3 * s.g / (2 * s.L * sp.cos(s.theta)))},
    # A rotor spinning in bearings whose shaft is itself turned (bearings: {turned: Omega}). Irodov sec. 1.6, a
    # ship's turbine as the ship turns: the bearings' gyroscopic torque I omega Omega, each bearing's force that over d.
    "ship_turbine_turning": {"tau": lambda s: s.I * s.omega * s.Omega, "F": lambda s: s.I * s.omega * s.Omega / s.d},
    # From a balance, with a vanishing push (nudged:). Serway & Jewett ch. 10: a rod standing on a smooth floor
    # lands flat at v_cm = sqrt(3 g L)/2, omega = sqrt(3 g/L) (clockwise here: it falls to the right).
    "rod_upright_nudged": {"v": lambda s: sp.sqrt(3 * s.g * s.L) / 2, "w": lambda s: -sp.sqrt(3 * s.g / s.L)},
    # Serway & Jewett ch. 8: a particle pushed off a smooth dome's top leaves it 2R/3 above the center at sqrt(2gR/3).
    "particle_off_dome_nudged": {"h": lambda s: 2 * s.R / 3, "v": lambda s: sp.sqrt(2 * s.g * s.R / 3)},
    # Serway & Jewett 9th ed., ch. 8: a pendulum released from rest at thetaA, v_B = sqrt(2 g L (1 - cos thetaA)) and
    # T_B = m g (3 - 2 cos thetaA) at the lowest point.
    "pendulum_tension_at_bottom": {"vB": lambda s: sp.sqrt(2 * s.g * s.L * (1 - _cos(s.thetaA))),
                                   "TB": lambda s: s.m * s.g * (3 - 2 * _cos(s.thetaA))},
    # Halliday, Resnick & Walker 10th ed., ch. 10: a rod pivoted at one end released from the horizontal,
    # alpha = 3 g/(2 L) at release, omega = sqrt(3 g/L) hanging, its center at (L/2) omega (counter-clockwise here).
    # Serway & Jewett 9th ed., ch. 10: a rod with a small ball at its end, pivoted at the rod's other end and
    # released horizontal: I = M L^2/3 + m L^2; (1/2) I omega^2 = M g L/2 + m g L; I alpha = M g L/2 + m g L.
    # The ball starts to the right of the pivot: it swings down clockwise (negative, counter-clockwise positive).
    "rod_with_ball_swings_down": {"alpha0": lambda s: -3 * s.g * (s.M + 2 * s.m) / (2 * s.L * (s.M + 3 * s.m)),
                                  "w": lambda s: -sp.sqrt(3 * s.g * (s.M + 2 * s.m) / (s.L * (s.M + 3 * s.m)))},
    "meter_stick_pivoted_at_end": {"alpha0": lambda s: 3 * s.g / (2 * s.L), "w": lambda s: sp.sqrt(3 * s.g / s.L),
                                   "vc": lambda s: sp.sqrt(3 * s.g * s.L) / 2},
    # Serway & Jewett 9th ed., ch. 6 and 8: a ball on a cord round a vertical circle, v_top^2 = v0^2 - 4 g R;
    # T = m (v0^2/R + g) at the bottom, m (v_top^2/R - g) at the top.
    "ball_whirled_vertical_circle": {"vt": lambda s: sp.sqrt(s.v0**2 - 4 * s.g * s.R),
                                     "Tb": lambda s: s.m * (s.v0**2 / s.R + s.g),
                                     "Tt": lambda s: s.m * (s.v0**2 - 5 * s.g * s.R) / s.R},
    # Serway & Jewett ch. 13: an ellipse from its periapsis r_p and the speed v_p there. The energy gives
    # a = GM r_p/(2 GM - r_p v_p^2); the farthest distance is 2a - r_p; Kepler's second law v_a r_a = v_p r_p;
    # the third, P = 2 pi sqrt(a^3/GM).
    # Serway & Jewett 9th ed., ch. 10 (a rigid body under constant angular acceleration): a grindstone, a
    # uniform disk I = M R^2/2 spinning at w0, slowed by a constant friction torque tau on its axle:
    # alpha = tau/I (clockwise, against its counter-clockwise spin); omega^2 = w0^2 - 2 alpha dtheta gives the
    # angle turned to rest I w0^2/(2 tau) (asked in turns, compared in rad), after t = I w0/tau.
    # Serway & Jewett 9th ed., ch. 10 (energy in rolling motion): a solid cylinder, I = M R^2/2, rolling from rest
    # down a height h has v = sqrt(2 g h/(1 + I/(M R^2))) = sqrt(4 g h/3).
    "cylinder_rolls_down_by_energy": {"v": lambda s: sp.sqrt(4 * s.g * s.h / 3)},
    # Serway & Jewett 9th ed., ch. 8 (work-energy with kinetic friction on an incline): m v^2/2 - m v0^2/2 =
    # m g d sin(theta) - mu_k m g cos(theta) d; ch. 5: a = g (sin(theta) - mu_k cos(theta)), t = (v - v0)/a.
    "block_sent_down_rough_incline": {
        "v": lambda s: sp.sqrt(s.v0**2 + 2 * s.g * s.d * (sp.sin(s.theta) - s.mu * sp.cos(s.theta))),
        "t": lambda s: (sp.sqrt(s.v0**2 + 2 * s.g * s.d * (sp.sin(s.theta) - s.mu * sp.cos(s.theta))) - s.v0)
        / (s.g * (sp.sin(s.theta) - s.mu * sp.cos(s.theta))),
    },
    # Serway & Jewett 9th ed., ch. 5 (a block sliding up a rough incline): a = -g (sin(theta) + mu_k cos(theta)), so it
    # stops after d = v0^2/(2 g (sin(theta) + mu_k cos(theta))), in t = v0/(g (sin(theta) + mu_k cos(theta))).
    "crate_stops_on_rough_ramp": {
        "d": lambda s: s.v0**2 / (2 * s.g * (sp.sin(s.theta) + s.mu * sp.cos(s.theta))),
        "t": lambda s: s.v0 / (s.g * (sp.sin(s.theta) + s.mu * sp.cos(s.theta))),
    },
    "grindstone_slowed_by_friction": {
        "alpha": lambda s: -2 * s.tau / (s.M * s.R**2),
        "n": lambda s: s.M * s.R**2 * s.w0**2 / (4 * s.tau),
        "t": lambda s: s.M * s.R**2 * s.w0 / (2 * s.tau),
    },
    # Halliday, Resnick & Walker 10th ed., ch. 15 (a physical pendulum, T = 2 pi sqrt(I/(m g h))): a rod of mass m
    # and length L pivoted at its top, a disk of mass M and radius r fixed by its rim to its lower end;
    # I = m L^2/3 + M r^2/2 + M (L + r)^2 by the parallel-axis theorem, h from the pivot to the center of mass.
    "rod_disk_clock_pendulum": {
        "P": lambda s: 2 * sp.pi * sp.sqrt((s.m * s.L**2 / 3 + s.M * s.r**2 / 2 + s.M * (s.L + s.r)**2)
                                           / (s.g * (s.m * s.L / 2 + s.M * (s.L + s.r)))),
    },
    # Serway & Jewett 9th ed., ch. 10 (a solid cylinder, I = M R^2/2, rolling without slipping up a slope at v0:
    # a = 2 g sin(theta)/3 down the slope, static friction M g sin(theta)/3 up it; it stops after
    # d = v0^2/(2a) = 3 v0^2/(4 g sin(theta)), at t = v0/a = 3 v0/(2 g sin(theta))). A newcomer's file.
    "cylinder_rolls_up_slope": {
        "a": lambda s: 2 * s.g * sp.sin(s.theta) / 3,
        "f": lambda s: s.M * s.g * sp.sin(s.theta) / 3,
        "d": lambda s: 3 * s.v0**2 / (4 * s.g * sp.sin(s.theta)),
        "t": lambda s: 3 * s.v0 / (2 * s.g * sp.sin(s.theta)),
    },
    # Serway & Jewett 9th ed., ch. 10 problems (a solid cylinder rolling on a level table, pulled at its axle by
    # a string over a light pulley to a hanging block: a = m g/(m + 3M/2), T = M a (3/2), f = M a/2 backward).
    # A newcomer's file (stop 41), answered on the student's route on first contact.
    "cylinder_pulled_by_hanging_block": {
        "a": lambda s: s.m * s.g / (s.m + 3 * s.M / 2),
        "T": lambda s: 3 * s.M / 2 * s.m * s.g / (s.m + 3 * s.M / 2),
        "f": lambda s: s.M / 2 * s.m * s.g / (s.m + 3 * s.M / 2),
    },
    # Young & Freedman, University Physics 14th ed., ch. 10, secs. 10.1-10.2 (tau = F r sin(phi); a hinged uniform
    # board, I = M L^2/3 about its edge: alpha = (F L sin(phi) - M g L/2)/I, counter-clockwise positive).
    # A newcomer's file (stop 41): the torque of each force about the hinge asked directly.
    "trapdoor_pulled_at_its_edge": {
        "tauF": lambda s: s.F * s.L * sp.sin(s.phi),
        "tauW": lambda s: -s.M * s.g * s.L / 2,
        "tau": lambda s: s.F * s.L * sp.sin(s.phi) - s.M * s.g * s.L / 2,
        "alpha": lambda s: (s.F * s.L * sp.sin(s.phi) - s.M * s.g * s.L / 2) / (s.M * s.L**2 / 3),
    },
    # Halliday, Resnick & Walker, Fundamentals of Physics 10th ed., ch. 11, sec. 11-12 (a gyroscope's precession,
    # Omega = M_tot g r/(I omega); a hoop of mass M on a uniform axle of mass m and length D pivoted at its far end,
    # so r = (M D + m D/2)/(M + m): Omega = (M + m/2) g D/(M R^2 omega)). A newcomer's file (stop 41), whose key had
    # printed the root of the quadratic unsimplified at the level axle.
    "bicycle_wheel_gyroscope": {
        "Omega": lambda s: (s.M + s.m / 2) * s.g * s.D / (s.M * s.R**2 * s.omega),
    },
    # Young & Freedman, University Physics 14th ed., ch. 10, sec. 10.6, "Angular momentum in a crime bust" (a bullet
    # m at v embeds at the center of a door of width L, mass M, hinged at one edge: m v L/2 = (M L^2/3 + m L^2/4)
    # omega); the hinge's impulse on the door, the change of the momentum (Serway & Jewett ch. 9):
    # J = (M + m) omega L/2 - m v, along the bullet's line. A newcomer's file (stop 41).
    "bullet_into_door": {
        "omega": lambda s: s.m * s.v * s.L / 2 / (s.M * s.L**2 / 3 + s.m * s.L**2 / 4),
        "K0": lambda s: s.m * s.v**2 / 2,
        "K": lambda s: (s.M * s.L**2 / 3 + s.m * s.L**2 / 4) / 2 * (s.m * s.v * s.L / 2 / (s.M * s.L**2 / 3 + s.m * s.L**2 / 4))**2,
        "J": lambda s: (s.M + s.m) * s.L / 2 * s.m * s.v * s.L / 2 / (s.M * s.L**2 / 3 + s.m * s.L**2 / 4) - s.m * s.v,
    },
    # Young & Freedman, University Physics 14th ed., ch. 10, sec. 10.6, "A rotational collision" (a flywheel and a
    # clutch plate on one axis pushed together: omega = (I_A omega_A + I_B omega_B)/(I_A + I_B); the energy lost,
    # I_A I_B (omega_A - omega_B)^2/(2 (I_A + I_B))). A newcomer's file (stop 41), whose K1 is the energy before.
    "flywheel_clutch_plate": {
        "w": lambda s: (s.IA * s.wA + s.IB * s.wB) / (s.IA + s.IB),
        "K1": lambda s: (s.IA * s.wA**2 + s.IB * s.wB**2) / 2,
        "dK": lambda s: -s.IA * s.IB * (s.wA - s.wB)**2 / (2 * (s.IA + s.IB)),  # the change: a loss
    },
    # Serway & Jewett 9th ed., ch. 12, Example 12.2, "Standing on a horizontal beam" (torques about the hinge:
    # T L sin(phi) = m_b g L/2 + m_p g d; R_x = T cos(phi), R_y = (m_b + m_p) g - T sin(phi)). A newcomer's file
    # (stop 41), whose worked solution the terminal printed with T tan(phi) |cos(phi)|.
    "beam_cable_person": {
        "T": lambda s: s.g * (s.mb * s.L / 2 + s.mp * s.d) / (s.L * sp.sin(s.phi)),
        "Rx": lambda s: s.g * (s.mb * s.L / 2 + s.mp * s.d) / (s.L * sp.sin(s.phi)) * sp.cos(s.phi),
        "Ry": lambda s: (s.mb + s.mp) * s.g - s.g * (s.mb * s.L / 2 + s.mp * s.d) / s.L,
    },
    # Serway & Jewett 9th ed., ch. 10 (a rod pivoted at its lower end falls from upright: M g L/2 = (1/2)(M L^2/3)
    # omega^2, omega = sqrt(3 g/L); at the level alpha = 3 g/(2 L), the hinge pushes 3 M g/2 toward itself and
    # M g/4 up). A newcomer's file (stop 41), on the swing route with the force along the tangent.
    "falling_chimney_rod": {
        "omega": lambda s: -sp.sqrt(3 * s.g / s.L),  # clockwise: it falls to the right
        "v": lambda s: sp.sqrt(3 * s.g * s.L) / 2,
        "Rx": lambda s: -3 * s.M * s.g / 2,
        "Ry": lambda s: s.M * s.g / 4,
    },
    "comet_from_periapsis": {
        "ra": lambda s: 2 * s.GM * s.rp / (2 * s.GM - s.rp * s.vp**2) - s.rp,
        "va": lambda s: s.vp * s.rp / (2 * s.GM * s.rp / (2 * s.GM - s.rp * s.vp**2) - s.rp),
        "P": lambda s: 2 * sp.pi * sp.sqrt((s.GM * s.rp / (2 * s.GM - s.rp * s.vp**2)) ** 3 / s.GM),
    },
    # Where a scene rests (derive.mechanics.equilibrium). Serway & Jewett ch. 5: a ball on a
    # string of length L pushed by a horizontal F rests at tan(theta) = F/(m g) from the vertical.
    "bob_pushed_aside": {
        "x": lambda s: s.L * s.F / sp.sqrt(s.F**2 + (s.m * s.g) ** 2),
        "y": lambda s: -s.L * s.m * s.g / sp.sqrt(s.F**2 + (s.m * s.g) ** 2),
    },
    # Halliday ch. 12 (torques about the hinge): a uniform rod pushed at its lower end by F rests
    # at tan(phi) = 2F/(M g) from the vertical; its angle from +x is phi - pi/2.
    "rod_pushed_aside": {
        "angle": lambda s: sp.atan(2 * s.F / (s.M * s.g)) - sp.pi / 2,
        "x": lambda s: s.L / 2 * 2 * s.F / sp.sqrt(4 * s.F**2 + (s.M * s.g) ** 2),
    },
    # Serway & Jewett ch. 7: on a smooth incline a spring of rest length L0 fixed up the slope
    # stretches by m g sin(theta)/k.
    "spring_incline_rest": {
        "x": lambda s: (s.L0 + s.m * s.g * _sin(s.theta) / s.k) * _cos(s.theta),
        "y": lambda s: -(s.L0 + s.m * s.g * _sin(s.theta) / s.k) * _sin(s.theta),
    },
    # Morin ch. 3 (a block on a frictionless wedge free to slide on a frictionless floor): the
    # wedge A = -m g sin(theta) cos(theta)/(M + m sin^2(theta)) (it moves back, -x); momentum
    # gives the block's m a_x = -M A; a_y = -(M + m) g sin^2(theta)/(M + m sin^2(theta));
    # N = M m g cos(theta)/(M + m sin^2(theta)).
    "wedge_block": {
        "A": lambda s: -s.m * s.g * _sin(s.theta) * _cos(s.theta) / (s.M + s.m * _sin(s.theta) ** 2),
        "ax": lambda s: s.M * s.g * _sin(s.theta) * _cos(s.theta) / (s.M + s.m * _sin(s.theta) ** 2),
        "ay": lambda s: -(s.M + s.m) * s.g * _sin(s.theta) ** 2 / (s.M + s.m * _sin(s.theta) ** 2),
        "N": lambda s: s.M * s.m * s.g * _cos(s.theta) / (s.M + s.m * _sin(s.theta) ** 2),
    },
    # Serway & Jewett ch. 5 (two blocks on the smooth faces of a double incline, joined over the
    # apex): the left face descends to the left (`descends: left`).
    "double_incline_peg": {
        "a": lambda s: s.g * (s.m1 * _sin(s.alpha) - s.m2 * _sin(s.beta)) / (s.m1 + s.m2),
        "T": lambda s: s.m1 * s.m2 * s.g * (_sin(s.alpha) + _sin(s.beta)) / (s.m1 + s.m2),
    },
    # Kleppner & Kolenkow ch. 7 (torques about a fixed pivot): a block on the smooth face of a
    # plank pivoted at its center and tilted phi below the horizontal, at release; the surface turns
    # with the plank (it was turned the wrong way, and the routes disagreed).
    # Serway & Jewett 9th ed., Example 5.10: a block on a smooth incline tied over a light smooth
    # pulley at its top to a hanging block; a is the incline block's acceleration down the slope.
    "incline_hanging_block": {
        "a": lambda s: s.g * (s.m1 * _sin(s.theta) - s.m2) / (s.m1 + s.m2),
        "ay": lambda s: s.g * (s.m1 * _sin(s.theta) - s.m2) / (s.m1 + s.m2),
        "T": lambda s: s.m1 * s.m2 * s.g * (1 + _sin(s.theta)) / (s.m1 + s.m2),
        "N": lambda s: s.m1 * s.g * _cos(s.theta),
    },
    "plank_block_tilted": {
        "alpha": lambda s: -s.m * s.g * s.d * _cos(s.phi) / (s.M * s.L**2 / 12 + s.m * s.d**2),
        "N": lambda s: s.m * s.g * _cos(s.phi) * s.M * s.L**2 / (s.M * s.L**2 + 12 * s.m * s.d**2),
    },
    # The same at release for a bead in a cart's circular track, where the track is inclined at
    # phi: the cart moves toward the bead's side (+x).
    "cart_track_bead": {
        "A": lambda s: s.m * s.g * _sin(s.phi) * _cos(s.phi) / (s.M + s.m * _sin(s.phi) ** 2),
        "N": lambda s: s.M * s.m * s.g * _cos(s.phi) / (s.M + s.m * _sin(s.phi) ** 2),
    },
    # Kleppner & Kolenkow ch. 7 (a plank pulled from under a uniform cylinder that rolls on it):
    # friction f = m a on the cylinder, f R = (m R^2/2) alpha, no slip a + alpha R = A (alpha
    # counter-clockwise), F - f = M A: A = 3F/(3M + m), a = A/3, f = m A/3.
    "plank_cylinder": {
        "A": lambda s: 3 * s.F / (3 * s.M + s.m),
        "a": lambda s: s.F / (3 * s.M + s.m),
        "alpha": lambda s: 2 * s.F / (s.R * (3 * s.M + s.m)),
        "f": lambda s: s.F * s.m / (3 * s.M + s.m),
    },
    # Halliday ch. 12 (a ladder against a frictionless wall): floor normal M g, floor friction and
    # wall push (M g/2) cot(theta), the friction toward the wall; Serway & Jewett Example 12.3: it
    # stands while mu_s >= cot(theta)/2.
    "ladder_statics": {
        "N": lambda s: s.M * s.g,
        "f": lambda s: -s.M * s.g / (2 * sp.tan(s.theta)),
        "P": lambda s: s.M * s.g / (2 * sp.tan(s.theta)),
        "mu_min": lambda s: 1 / (2 * sp.tan(s.theta)),
    },
    # Halliday Sample Problem 12.02: F_wall = g a (M/2 + m/3)/h with a = sqrt(L^2 - h^2); the
    # floor pushes (M + m) g up and F_wall toward the wall.
    "ladder_firefighter": {
        "Fw": lambda s: s.g * sp.sqrt(s.L**2 - s.h**2) * (s.M / 2 + s.m / 3) / s.h,
        "Fpx": lambda s: -s.g * sp.sqrt(s.L**2 - s.h**2) * (s.M / 2 + s.m / 3) / s.h,
        "Fpy": lambda s: (s.M + s.m) * s.g,
    },
    # Kleppner & Kolenkow ch. 7 (the sliding ladder, both surfaces smooth), at release: the angle
    # above the floor has theta'' = -(3 g/(2 L)) cos(theta) (the rod's own angle is pi - theta);
    # N_floor = M g (1 - 3 cos^2(theta)/4), N_wall = 3 M g sin(theta) cos(theta)/4.
    "ladder_sliding": {
        "alpha": lambda s: 3 * s.g * _cos(s.theta) / (2 * s.L),
        "N": lambda s: s.M * s.g * (1 - 3 * _cos(s.theta) ** 2 / 4),
        "P": lambda s: 3 * s.M * s.g * _sin(s.theta) * _cos(s.theta) / 4,
    },
    # Halliday ch. 11 (a yo-yo pulled by its string): pulled straight up from the axle's right,
    # I = M R^2 / 2: a = -F r R / (I + M R^2) = -2 F r / (3 M R), N = M g - F.
    "yoyo_pulled_up_rolls_left": {
        "a": lambda s: -2 * s.F * s.r / (3 * s.M * s.R),
        "N": lambda s: s.M * s.g - s.F,
    },
    # Taylor, Classical Mechanics, ch. 7: a solid ball rolling at the bottom of a bowl of radius R,
    # its center on a circle of radius R - r: omega^2 = 5 g / (7 (R - r)).
    "ball_in_bowl": {
        "omega": lambda s: sp.sqrt(5 * s.g / (7 * (s.R - s.r))),
    },
    # Halliday ch. 15, Module 15-6 (damped SHM), rotational: I = M R^2 / 2,
    # omega' = sqrt(kappa / I - c^2 / (4 I^2)).
    "torsion_pendulum_damped": {
        "omega": lambda s: sp.sqrt(2 * s.kappa / (s.M * s.R**2) - s.c**2 / (s.M**2 * s.R**4)),
    },
    # Serway & Jewett 9th ed. ch. 5 (the Atwood machine): a = (m1 - m2) g/(m1 + m2), T = 2 m1 m2 g/(m1 + m2).
    # The first block is the heavier; y is up, so its acceleration is negative.
    "atwood_peg": {
        "a": lambda s: -(s.m1 - s.m2) * s.g / (s.m1 + s.m2),
        "T": lambda s: 2 * s.m1 * s.m2 * s.g / (s.m1 + s.m2),
    },
    "atwood_smooth": {
        "a": lambda s: -(s.m1 - s.m2) * s.g / (s.m1 + s.m2),
        "T": lambda s: 2 * s.m1 * s.m2 * s.g / (s.m1 + s.m2),
    },
    # Atwood with a uniform-disk pulley (cf. Serway & Jewett ch. 10; Halliday ch. 10):
    # a = (m1 - m2) g/(m1 + m2 + M/2), T1 = m1 (g - a), T2 = m2 (g + a), alpha = a/R.
    "atwood_massive_pulley": {
        "a": lambda s: -(s.m1 - s.m2) * s.g / (s.m1 + s.m2 + s.M / 2),
        "T1": lambda s: s.m1 * (s.g - (s.m1 - s.m2) * s.g / (s.m1 + s.m2 + s.M / 2)),
        "T2": lambda s: s.m2 * (s.g + (s.m1 - s.m2) * s.g / (s.m1 + s.m2 + s.M / 2)),
        "alpha": lambda s: (s.m1 - s.m2) * s.g / (s.m1 + s.m2 + s.M / 2) / s.R,
    },
    # Kleppner & Kolenkow ch. 7: a cylinder pulled at its axle by a hanging mass m over the
    # table's edge: a = m g/(m + 3M/2), T = (3M/2) a, friction M a/2 backwards.
    "cylinder_table_hanging_block": {
        "a": lambda s: s.m * s.g / (s.m + 3 * s.M / 2),
        "T": lambda s: 3 * s.M / 2 * s.m * s.g / (s.m + 3 * s.M / 2),
        "f": lambda s: -s.M / 2 * s.m * s.g / (s.m + 3 * s.M / 2),
    },
    # Kleppner & Kolenkow ch. 7: a force F at the axle of a rolling solid cylinder:
    # a = 2F/(3M), alpha = -a/R, friction F/3 against the pull, mu_min = F/(3 M g).
    "disk_pulled_at_axle": {
        "a": lambda s: 2 * s.F / (3 * s.M),
        "alpha": lambda s: -2 * s.F / (3 * s.M * s.R),
        "f": lambda s: -s.F / 3,
        "mu_min": lambda s: s.F / (3 * s.M * s.g),
    },
    # Physical pendulum (Halliday ch. 15, Module 15-4): omega^2 = m g h / I; a disk about its rim:
    # I = 3/2 M R^2, h = R.
    "disk_rim_pendulum": {
        "omega": lambda s: sp.sqrt(2 * s.g / (3 * s.R)),
    },
    # Rolling down an incline (Halliday ch. 11, eq. 11-10): a = g sin(theta)/(1 + I/(M R^2));
    # friction f = I a/R^2; least mu_s = f/(M g cos(theta)).
    "hoop_rolls_incline": {
        "a": lambda s: s.g * _sin(s.theta) / 2,
        "f": lambda s: s.M * s.g * _sin(s.theta) / 2,
        "mu_min": lambda s: sp.tan(s.theta) / 2,
    },
    "disk_rolls_incline": {
        "a": lambda s: 2 * s.g * _sin(s.theta) / 3,
        "f": lambda s: s.M * s.g * _sin(s.theta) / 3,
        "mu_min": lambda s: sp.tan(s.theta) / 3,
    },
    "sphere_rolls_incline": {
        "a": lambda s: 5 * s.g * _sin(s.theta) / 7,
        "f": lambda s: 2 * s.M * s.g * _sin(s.theta) / 7,
        "mu_min": lambda s: 2 * sp.tan(s.theta) / 7,
    },
    "shell_rolls_incline": {
        "a": lambda s: 3 * s.g * _sin(s.theta) / 5,
        "f": lambda s: 2 * s.M * s.g * _sin(s.theta) / 5,
        "mu_min": lambda s: 2 * sp.tan(s.theta) / 5,
    },
    # Serway & Jewett ch. 15: a solid cylinder on a horizontal spring rolls: omega^2 = 2k/(3M).
    "disk_spring_rolling": {
        "omega": lambda s: sp.sqrt(2 * s.k / (3 * s.M)),
    },
    # A flywheel started from rest: I alpha = tau - c omega, omega = 0 at the start: alpha = tau/I.
    "flywheel_torque_damper": {
        "alpha": lambda s: s.tau / (s.M * s.R**2 / 2),
    },
    # Physical pendulum: a hoop on a nail, I = 2 M R^2 about the rim: T = 2 pi sqrt(2R/g); at rest
    # the nail holds the weight.
    "hoop_on_nail": {
        "T": lambda s: 2 * sp.pi * sp.sqrt(2 * s.R / s.g),
        "Fy": lambda s: s.M * s.g,
    },
    # Halliday ch. 15 (Sample Problem: meter stick pivoted at its end): T = 2 pi sqrt(2L/(3g)).
    "rod_end_pendulum": {
        "omega": lambda s: sp.sqrt(3 * s.g / (2 * s.L)),
        "T": lambda s: 2 * sp.pi * sp.sqrt(2 * s.L / (3 * s.g)),
    },
    # Physical pendulum pivoted d from the center: omega^2 = g d/(L^2/12 + d^2).
    "rod_pivot_off_center": {
        "omega": lambda s: sp.sqrt(s.g * s.d / (s.L**2 / 12 + s.d**2)),
    },
    # Serway & Jewett ch. 10 (rotating rod released horizontal): alpha = 3g/(2L) (clockwise),
    # the center falls at 3g/4, the pivot pushes up M g/4 and not sideways.
    "rod_released_horizontal": {
        "alpha": lambda s: -3 * s.g / (2 * s.L),
        "ay": lambda s: -3 * s.g / 4,
        "Ry": lambda s: s.M * s.g / 4,
        "Rx": lambda s: sp.Integer(0),
    },
    # The same rod at theta0 below the horizontal: alpha = 3 g cos(theta0)/(2L); the center's
    # acceleration is alpha x r, so R = M a_cm + M g j:
    # Rx = -(3/4) M g sin(theta0) cos(theta0), Ry = M g (1 - (3/4) cos^2(theta0)).
    "rod_released_at_angle": {
        "alpha": lambda s: -3 * s.g * _cos(s.theta0) / (2 * s.L),
        "Rx": lambda s: -3 * s.M * s.g * _sin(s.theta0) * _cos(s.theta0) / 4,
        "Ry": lambda s: s.M * s.g * (1 - 3 * _cos(s.theta0)**2 / 4),
    },
    # A seesaw (plank M, L on a central pivot, children m1, m2 at its ends) released level:
    # alpha = (m1 - m2) g (L/2)/(M L^2/12 + (m1 + m2) L^2/4); the left child's seat pushes
    # m1 (g - alpha L/2).
    "seesaw": {
        "alpha": lambda s: (s.m1 - s.m2) * s.g * s.L / 2 / (s.M * s.L**2 / 12 + (s.m1 + s.m2) * s.L**2 / 4),
        "F": lambda s: s.m1 * (s.g - (s.m1 - s.m2) * s.g * s.L / 2
                               / (s.M * s.L**2 / 12 + (s.m1 + s.m2) * s.L**2 / 4) * s.L / 2),
    },
    # Simple pendulum (Halliday ch. 15, Module 15-4): T = 2 pi sqrt(L/g); at rest the cord holds m g.
    "simple_pendulum_cord": {
        "T": lambda s: 2 * sp.pi * sp.sqrt(s.L / s.g),
        "F": lambda s: s.m * s.g,
    },
    # Serway & Jewett ch. 10 (spool pulled by a string from the top of its hub):
    # a = F (1 + r/R)/(M + I/R^2); friction = M a - F.
    "spool_pulled_from_top": {
        "a": lambda s: s.F * (1 + s.r / s.R) / (s.M + s.I / s.R**2),
        "f": lambda s: s.M * s.F * (1 + s.r / s.R) / (s.M + s.I / s.R**2) - s.F,
    },
    # Halliday ch. 15 (a block on a spring along an incline): T = 2 pi sqrt(m/k); N = m g cos(theta).
    "spring_block_incline": {
        "T": lambda s: 2 * sp.pi * sp.sqrt(s.m / s.k),
        "N": lambda s: s.m * s.g * _cos(s.theta),
    },
    # Normal modes (derive.mechanics.normal_modes). Morin, Introduction to Classical Mechanics, ch. 6,
    # and Taylor, Classical Mechanics, Problem 7.29 (a pendulum hanging from a cart free on a level
    # rail): omega^2 = g (M + m)/(M l), the cart's free translation a zero mode.
    "cart_pendulum": {
        "omega": lambda s: sp.sqrt(s.g * (s.M + s.m) / (s.M * s.l)),
        "r": lambda s: -s.M / s.m,  # the center of mass stays put: M x_cart + m x_bob = 0
    },
    # The same dynamics with the bead held at R from the center of a free cart's circular track
    # (once refused, tests/textbook/PENDING.md, Resolved): omega^2 = (g/R)(1 + m/M).
    "cart_track_bead_oscillation": {
        "omega": lambda s: sp.sqrt(s.g / s.R * (1 + s.m / s.M)),
    },
    # Taylor, Classical Mechanics, §11.4 (the double pendulum, equal masses and lengths):
    # omega^2 = (2 -+ sqrt 2) g/L.
    "double_pendulum": {
        "w1": lambda s: sp.sqrt((2 - sp.sqrt(2)) * s.g / s.L),
        "w2": lambda s: sp.sqrt((2 + sp.sqrt(2)) * s.g / s.L),
        "T1": lambda s: 2 * sp.pi / sp.sqrt((2 - sp.sqrt(2)) * s.g / s.L),
        # Taylor's mode shapes in the angles, phi2 = +-sqrt(2) phi1; the bobs' displacements
        # x1 = L phi1, x2 = L (phi1 + phi2): x2/x1 = 1 +- sqrt(2).
        "r1": lambda s: 1 + sp.sqrt(2),
        "r2": lambda s: 1 - sp.sqrt(2),
    },
    # Taylor, Classical Mechanics, §11.2 (two equal carts, three identical springs between two
    # walls): omega^2 = k/m (in phase) and 3k/m (out of phase).
    "two_blocks_three_springs": {
        "w1": lambda s: sp.sqrt(s.k / s.m),
        "w2": lambda s: sp.sqrt(3 * s.k / s.m),
        "r1": lambda s: sp.Integer(1),  # in phase
        "r2": lambda s: sp.Integer(-1),  # out of phase
    },
    # French, Vibrations and Waves, ch. 5 (two identical pendulums coupled by a spring between
    # the bobs): omega^2 = g/l (in phase) and g/l + 2k/m (out of phase).
    "coupled_pendulums": {
        "w1": lambda s: sp.sqrt(s.g / s.l),
        "w2": lambda s: sp.sqrt(s.g / s.l + 2 * s.k / s.m),
    },
    # Halliday ch. 15, Module 15-1 (linear oscillator): omega = sqrt(k/m).
    "spring_horizontal": {
        "omega": lambda s: sp.sqrt(s.k / s.m),
        "N": lambda s: s.m * s.g,
    },
    # Serway & Jewett ch. 15 (block hanging over a pulley held by a spring): omega^2 = k/(m + I/R^2),
    # I = M R^2/2; at equilibrium the cord holds m g.
    "spring_pulley_block": {
        "omega": lambda s: sp.sqrt(s.k / (s.m + s.M / 2)),
        "T": lambda s: s.m * s.g,
    },
    # Serway & Jewett ch. 15 (a block on a smooth table held by a spring and by a cord over a
    # pulley of moment of inertia I to a hanging block m2): omega^2 = k/(m + m2 + I/R^2),
    # I = M R^2/2; at equilibrium both runs hold m2 g (the spring is stretched by m2 g/k).
    "spring_block_pulley_hanging": {
        "omega": lambda s: sp.sqrt(s.k / (s.m + s.m2 + s.M / 2)),
        "T1": lambda s: s.m2 * s.g,
        "T2": lambda s: s.m2 * s.g,
    },
    # Halliday ch. 15, Module 15-4 (torsion pendulum, eq. 15-23): T = 2 pi sqrt(I/kappa), I = M R^2/2.
    "torsion_pendulum": {
        "omega": lambda s: sp.sqrt(s.kappa / (s.M * s.R**2 / 2)),
        "T": lambda s: 2 * sp.pi * sp.sqrt(s.M * s.R**2 / 2 / s.kappa),
    },
    # Kleppner & Kolenkow ch. 7 (a wheel driven by a torque tau rolls): a = tau R/(I + M R^2) =
    # 2 tau/(3 M R); the road's friction M a drives it forward; N = M g.
    "wheel_torque_floor": {
        "a": lambda s: 2 * s.tau / (3 * s.M * s.R),
        "f": lambda s: 2 * s.tau / (3 * s.R),
        "N": lambda s: s.M * s.g,
    },
    # Halliday ch. 11 (the yo-yo, a = g/(1 + I/(M R0^2)) with the axle radius R0): here I = M R^2/2,
    # R0 = r: a = 2 g r^2/(R^2 + 2 r^2) downward, T = M (g - |a|).
    "yoyo_axle": {
        "a": lambda s: -s.g / (1 + s.R**2 / (2 * s.r**2)),
        "T": lambda s: s.M * (s.g - s.g / (1 + s.R**2 / (2 * s.r**2))),
    },
    # The falling cylinder unwinding from its rim (cord tied to the ceiling): a = 2g/3, T = M g/3,
    # alpha = a/R (it turns clockwise with the cord on its left).
    "yoyo_rim": {
        "a": lambda s: -2 * s.g / 3,
        "alpha": lambda s: -2 * s.g / (3 * s.R),
        "T": lambda s: s.M * s.g / 3,
    },
    # A yo-yo on a floor pulled by a string leaving the bottom of its axle at theta above the
    # horizontal: a = F (cos(theta) - r/R)/(M + I/R^2), I = M R^2/2; it rolls toward the pull
    # below cos(theta_c) = r/R and away above; N = M g - F sin(theta).
    "yoyo_pulled_at_angle": {
        "a": lambda s: s.F * (_cos(s.theta) - s.r / s.R) / (3 * s.M / 2),
        "N": lambda s: s.M * s.g - s.F * _sin(s.theta),
        "theta_c": lambda s: sp.acos(s.r / s.R),
    },
    # The same pulled horizontally: a = F (1 - r/R)/(3M/2); friction M a - F.
    "yoyo_pulled_horizontal": {
        "a": lambda s: s.F * (1 - s.r / s.R) / (3 * s.M / 2),
        "f": lambda s: s.M * s.F * (1 - s.r / s.R) / (3 * s.M / 2) - s.F,
    },
    # Kleppner & Kolenkow ch. 7: too little friction for rolling (mu_s < tan(theta)/3 over the
    # file's ranges): it slips, a = g (sin(theta) - mu_k cos(theta)), |alpha| = 2 mu_k g cos(theta)/R.
    "disk_incline_slips": {
        "a": lambda s: s.g * (_sin(s.theta) - s.mu_k * _cos(s.theta)),
        "alpha": lambda s: 2 * s.mu_k * s.g * _cos(s.theta) / s.R,
    },
    # Halliday ch. 11 (a ball rolls down a ramp of height h): v = sqrt(10 g h/7); with
    # a = (5/7) g sin(theta) along h/sin(theta): t = sqrt(2 (h/sin(theta))/a).
    "sphere_speed_at_bottom": {
        "v": lambda s: sp.sqrt(10 * s.g * s.h / 7),
        "t": lambda s: sp.sqrt(2 * s.h / _sin(s.theta) / (5 * s.g * _sin(s.theta) / 7)),
    },
    # Serway & Jewett ch. 10 (a block on a rough incline pulled up over a disk pulley by a hanging
    # block): up the incline a = g (m2 - m1 (sin(theta) + mu_k cos(theta)))/(m1 + m2 + M/2), so down
    # it -a; the incline's run holds T1 = m1 (a + g sin(theta) + mu_k g cos(theta)). The file's
    # ranges always slip up the incline.
    # Serway & Jewett ch. 10 (blocks over a massive disk pulley) on a double wedge: the faces at alpha
    # and beta, the pulley's center R below both, each block d from its tangent point (issue 38).
    "double_wedge_pulley": {
        "a": lambda s: s.g * (s.m1 * _sin(s.alpha) - s.m2 * _sin(s.beta)) / (s.m1 + s.m2 + s.M / 2),
        "T1": lambda s: s.m1 * (s.g * _sin(s.alpha) - s.g * (s.m1 * _sin(s.alpha) - s.m2 * _sin(s.beta)) / (s.m1 + s.m2 + s.M / 2)),
        "T2": lambda s: s.m2 * (s.g * _sin(s.beta) + s.g * (s.m1 * _sin(s.alpha) - s.m2 * _sin(s.beta)) / (s.m1 + s.m2 + s.M / 2)),
    },
    # Serway & Jewett ch. 10 and ch. 6: a solid ball from rest with its center at (2H + 3r)/5 rolls
    # down a circular chute into a loop it meets at the bottom: v^2 = (10/7) g (drop) = (4/7) g (H - r)
    # there; it leaves the loop where v^2 = g y', y' = 10 (h - R)/17 above the loop's center (issue 38).
    "ball_chute_into_loop": {
        "v": lambda s: sp.sqrt(4 * s.g * (s.H - s.r) / 7),
        "y": lambda s: s.R + 10 * ((2 * s.H + 3 * s.r) / 5 - s.R) / 17,
        "v_off": lambda s: sp.sqrt(s.g * 10 * ((2 * s.H + 3 * s.r) / 5 - s.R) / 17),
    },
    # The same, released where the chute's radius to the ball is at phi0 from the vertical: its center
    # starts at h = H - (H - r) cos(phi0), so v^2 = (10/7) g (H - r)(1 - cos(phi0)) at the bottom, and it
    # leaves the loop 10 (h - R)/17 above the loop's center (issue 38: past 400 s, a root's square unfolded).
    "ball_chute_into_loop_released": {
        "v": lambda s: sp.sqrt(10 * s.g * (s.H - s.r) * (1 - _cos(s.phi0)) / 7),
        "y": lambda s: s.R + 10 * (s.H - (s.H - s.r) * _cos(s.phi0) - s.R) / 17,
        "v_off": lambda s: sp.sqrt(s.g * 10 * (s.H - (s.H - s.r) * _cos(s.phi0) - s.R) / 17),
    },
    # Serway & Jewett ch. 10 and ch. 5 on issue 38's own double wedge, each face tangent to the pulley from
    # below: each cord climbs from its block to the pulley's top at 2 atan(R/d) to its face, cosine k.
    # From rest (no centripetal terms) the blocks' balances along their faces and the pulley's torque give
    # a = g (m1 sin(alpha) - m2 sin(beta))/(m1 + m2 + k^2 M/2) and T1 = m1 (g sin(alpha) - a)/k.
    "double_wedge_tangent_cords": {
        "a": lambda s: s.g * (s.m1 * _sin(s.alpha) - s.m2 * _sin(s.beta)) / (s.m1 + s.m2 + _tangent_cosine(s) ** 2 * s.M / 2),
        "T1": lambda s: s.m1 * (s.g * _sin(s.alpha) - s.g * (s.m1 * _sin(s.alpha) - s.m2 * _sin(s.beta))
                                / (s.m1 + s.m2 + _tangent_cosine(s) ** 2 * s.M / 2)) / _tangent_cosine(s),
    },
    "incline_friction_pulley": {
        "a": lambda s: -s.g * (s.m2 - s.m1 * (_sin(s.theta) + s.mu_k * _cos(s.theta))) / (s.m1 + s.m2 + s.M / 2),
        "T1": lambda s: s.m1 * s.g * ((s.m2 - s.m1 * (_sin(s.theta) + s.mu_k * _cos(s.theta))) / (s.m1 + s.m2 + s.M / 2)
                                      + _sin(s.theta) + s.mu_k * _cos(s.theta)),
    },
    # Halliday ch. 6 (kinetic friction on an incline; the file's ranges always slide):
    # a = g (sin(theta) - mu_k cos(theta)), N = m g cos(theta).
    "block_incline_kinetic": {
        "a": lambda s: s.g * (_sin(s.theta) - s.mu_k * _cos(s.theta)),
        "N": lambda s: s.m * s.g * _cos(s.theta),
    },
    # Halliday ch. 5 (block M on a frictionless table, m hanging): a = m g/(M + m), T = M m g/(M + m).
    "table_block_smooth_pulley": {
        "a": lambda s: s.m * s.g / (s.M + s.m),
        "ay": lambda s: -s.m * s.g / (s.M + s.m),
        "T": lambda s: s.M * s.m * s.g / (s.M + s.m),
        "N": lambda s: s.M * s.g,
    },
    # Serway & Jewett ch. 10 (rough table, disk pulley; the file's ranges always slide):
    # a = (m2 - mu_k m1) g/(m1 + m2 + M/2), T1 = m1 (a + mu_k g), T2 = m2 (g - a).
    "table_block_massive_pulley_friction": {
        "a": lambda s: (s.m2 - s.mu_k * s.m1) * s.g / (s.m1 + s.m2 + s.M / 2),
        "T1": lambda s: s.m1 * ((s.m2 - s.mu_k * s.m1) * s.g / (s.m1 + s.m2 + s.M / 2) + s.mu_k * s.g),
        "T2": lambda s: s.m2 * (s.g - (s.m2 - s.mu_k * s.m1) * s.g / (s.m1 + s.m2 + s.M / 2)),
    },
    # Serway & Jewett ch. 10 (double pulley): alpha = g (m1 R1 - m2 R2)/(I + m1 R1^2 + m2 R2^2)
    # (counter-clockwise: the left block on the small step descends), a1 = -R1 alpha, T1 = m1 (g + a1).
    "stepped_pulley": {
        "alpha": lambda s: s.g * (s.m1 * s.R1 - s.m2 * s.R2) / (s.I + s.m1 * s.R1**2 + s.m2 * s.R2**2),
        "a1": lambda s: -s.R1 * s.g * (s.m1 * s.R1 - s.m2 * s.R2) / (s.I + s.m1 * s.R1**2 + s.m2 * s.R2**2),
        "T1": lambda s: s.m1 * s.g * (1 - s.R1 * (s.m1 * s.R1 - s.m2 * s.R2)
                                      / (s.I + s.m1 * s.R1**2 + s.m2 * s.R2**2)),
    },
    # Kleppner & Kolenkow ch. 7 (angular impulse about a fixed axis): disks on fixed parallel axles
    # pressed together at their rims. Friction F on the rims for dt: I1 (w1f - w1) = -R1 F dt,
    # I2 (w2f - w2) = -R2 F dt, and once they roll, w1f R1 = -w2f R2 (they touch from outside):
    # w1f = (I1 R2^2 w1 - I2 R1 R2 w2)/(I1 R2^2 + I2 R1^2), I = M R^2/2; the kinetic energy lost is
    # the initial minus the final.
    # Serway & Jewett ch. 11 (a puck on a frictionless table held by a cord through a hole, pulled slowly
    # from below): the cord's force is central, so m v1 r1 = m v r; the pull's work is the change of kinetic
    # energy, (m v1^2/2)((r1/r2)^2 - 1).
    "puck_pulled_through_hole": {
        "v": lambda s: s.v1 * s.r1 / s.r2,
        "W": lambda s: s.m * s.v1**2 * ((s.r1 / s.r2) ** 2 - 1) / 2,
        "T": lambda s: s.m * (s.v1 * s.r1 / s.r2) ** 2 / s.r2,  # the cord holds it on its circle: m v^2/r
    },
    # Serway & Jewett ch. 5 (a block pulled across a board on a frictionless floor): a1 = F/m - mu g,
    # a2 = mu m g/M; the block gains L on the board after t = sqrt(2 L/(a1 - a2)), the board moving a2 t^2/2
    # (a state relative to another body: `relative_to: board`).
    "block_slides_off_plank": {
        "t": lambda s: sp.sqrt(2 * s.L / (s.F / s.m - s.mu * s.g - s.mu * s.m * s.g / s.M)),
        "d": lambda s: s.mu * s.m * s.g / s.M * s.L / (s.F / s.m - s.mu * s.g - s.mu * s.m * s.g / s.M),
    },
    "disks_pressed_at_rims": {
        "w1f": lambda s: _rims_rate(s),
        "w2f": lambda s: -s.R1 * _rims_rate(s) / s.R2,
        "dK": lambda s: (s.M1 * s.R1**2 * _rims_rate(s)**2 + s.M2 * s.R1**2 * _rims_rate(s)**2
                         - s.M1 * s.R1**2 * s.w1**2 - s.M2 * s.R2**2 * s.w2**2) / 4,
    },
}
# The same setup with a free length in the positions (how deep the blocks hang), which cancels
# from every answer: the cords' radicals must simplify.
EXPECTED["stepped_pulley_deep"] = EXPECTED["stepped_pulley"]

# States (issue 12): rates and forces where the motion gets to, from the work-energy theorem.
EXPECTED.update({
    # Serway & Jewett Ex. 10.11: omega = sqrt(3g/L) at the lowest position; the hinge then holds
    # M g + M omega^2 L/2 = 5 M g/2 (Newton's second law toward the pin); no torque: alpha = 0.
    # The same rod released at a symbolic angle theta0 below the horizontal (a new-user trial: the
    # placement's angle made the pin's gap slow to solve for an angle, 106 s; 2 s once the roots
    # are found lazily): alpha = -3 g cos(theta0)/(2 L), omega = -sqrt(3 g (1 - sin(theta0))/L).
    "rod_released_below_swings": {
        "alpha": lambda s: -3 * s.g * _cos(s.theta0) / (2 * s.L),
        "omega": lambda s: -sp.sqrt(3 * s.g * (1 - _sin(s.theta0)) / s.L),
    },
    # Serway & Jewett ch. 10 (a rod on a frictionless surface falls with its center straight down),
    # from theta0 to the vertical; derived here independently in the rod's angle phi from the
    # vertical alone: no horizontal force, so x_cm stays put, y_cm = (L/2) cos(phi), and energy
    # (M/2) y_cm'^2 + (M L^2/24) phi'^2 = M g (L/2)(cos(theta0) - cos(phi)) gives
    # phi'^2 = 12 g (cos(theta0) - cos(phi))/(L (1 + 3 sin^2(phi))); flat (phi = pi/2):
    # omega = sqrt(3 g cos(theta0)/L) clockwise, v_cm = (L/2) omega. Newton for the center,
    # N - M g = M y_cm'', with phi'' = (1/2) d(phi'^2)/dphi: N = M g (4 + 3 (cos(phi) - cos(theta0))^2
    # - 3 cos^2(theta0))/(1 + 3 sin^2(phi))^2, positive for every phi (the foot never leaves the
    # floor): M g/(1 + 3 sin^2(theta0)) at release, M g/4 as it lands; the time is the integral of
    # dphi/phi' (no closed form: an elliptic integral).
    "rod_falls_on_smooth_floor": {
        "N": lambda s: s.M * s.g / (1 + 3 * _sin(s.theta0) ** 2),
        "v1": lambda s: s.L / 2 * _sin(s.theta) * sp.sqrt(_omega_squared(s, s.theta)),
        "w1": lambda s: -sp.sqrt(_omega_squared(s, s.theta)),
        "N1": lambda s: s.M * s.g * (4 + 3 * (_cos(s.theta) - _cos(s.theta0)) ** 2 - 3 * _cos(s.theta0) ** 2)
        / (1 + 3 * _sin(s.theta) ** 2) ** 2,
        "x1": lambda s: s.L * _sin(s.theta0) / 2,
        "v": lambda s: sp.sqrt(3 * s.g * s.L * _cos(s.theta0)) / 2,
        "w": lambda s: -sp.sqrt(3 * s.g * _cos(s.theta0) / s.L),
        "N2": lambda s: s.M * s.g / 4,
        "t": lambda s: sp.Integral(1 / sp.sqrt(_omega_squared(s, _PHI)), (_PHI, s.theta0, sp.pi / 2)),
    },
    "rod_swings_down": {
        "omega": lambda s: sp.sqrt(3 * s.g / s.L),
        "v": lambda s: sp.sqrt(3 * s.g / s.L) * s.L / 2,
        "F": lambda s: 5 * s.M * s.g / 2,
        "alpha": lambda s: 0,
    },
    # Serway & Jewett ch. 8: v_B = sqrt(2 g L (1 - cos theta_A)), T_B = m g (3 - 2 cos theta_A).
    "pendulum_bob_released": {
        "v": lambda s: sp.sqrt(2 * s.g * s.L * (1 - _cos(s.theta0))),
        "T": lambda s: s.m * s.g * (3 - 2 * _cos(s.theta0)),
        "t": lambda s: sp.sqrt(s.L / s.g) * sp.elliptic_k(sp.sin(s.theta0 / 2) ** 2),
    },
    # Halliday ch. 8 and 6: v^2 = v0^2 - 2 g L where the cord is level, T = m v^2/L there; just
    # after the push T0 = m g + m v0^2/L.
    "bob_given_speed": {
        "v": lambda s: sp.sqrt(s.v0**2 - 2 * s.g * s.L),
        "T": lambda s: s.m * (s.v0**2 - 2 * s.g * s.L) / s.L,
        "T0": lambda s: s.m * s.g + s.m * s.v0**2 / s.L,
    },
    # Serway & Jewett ch. 8 problems: from the rim, v = sqrt(2 g R) and N = 3 m g at the bottom.
    "block_in_bowl": {
        "v": lambda s: sp.sqrt(2 * s.g * s.R),
        "N": lambda s: 3 * s.m * s.g,
    },
    # Serway & Jewett Ex. 10.13: v = sqrt(10 g h/7) rolling without slipping; omega = v/R.
    "sphere_rolls_down": {
        "v": lambda s: sp.sqrt(10 * s.g * s.h / 7),
        "omega": lambda s: sp.sqrt(10 * s.g * s.h / 7) / s.R,
        # d = h / sin(theta) at a = (5/7) g sin(theta) from rest: t = sqrt(2 d / a)
        "t": lambda s: sp.sqrt(14 * s.h / (5 * s.g * sp.sin(s.theta) ** 2)),
    },
    # Kleppner & Kolenkow ch. 5: from the top of a smooth hemisphere with v0, it leaves where
    # cos(phi) = 2/3 + v0^2/(3 g R), moving at sqrt(g R cos(phi)).
    "bead_off_dome": {
        "h": lambda s: 2 * s.R / 3 + s.v0**2 / (3 * s.g),
        "v": lambda s: sp.sqrt(s.g * (2 * s.R / 3 + s.v0**2 / (3 * s.g))),
    },
    # Morin ch. 8: a ball rolling off a fixed sphere, cos(phi) = (10 + 7 v0^2/(g (R + r)))/17;
    # rolling on the outside, omega = v/r = -sqrt(g (R + r) cos(phi))/r (clockwise, to the right).
    # Serway & Jewett ch. 10: inside a loop, (7/10) m v^2 = (7/10) m v0^2 - m g (y + R - r), and it
    # leaves where m v^2/(R - r) = m g y/(R - r), v^2 = g y; rolling clockwise, omega = -v/r.
    "ball_leaves_loop": {
        "y": lambda s: (7 * s.v0**2 - 10 * s.g * (s.R - s.r)) / (17 * s.g),
        "omega": lambda s: -sp.sqrt(s.g * (7 * s.v0**2 - 10 * s.g * (s.R - s.r)) / (17 * s.g)) / s.r,
    },
    "ball_rolls_off_dome": {
        "h": lambda s: (10 * s.g * (s.R + s.r) + 7 * s.v0**2) / (17 * s.g),
        "omega": lambda s: -sp.sqrt(s.g * (10 * s.g * (s.R + s.r) + 7 * s.v0**2) / (17 * s.g)) / s.r,
    },
    # Serway & Jewett ch. 8 and ch. 6: a block on a frictionless loop-the-loop track, released
    # H = (R + 3 d)/5 above the loop's bottom (d along a ramp rising at sin = 3/5 that meets the
    # loop tangentially, a transfer event): v^2 = 2 g H at the bottom, v^2 = 2 g (H - 2R) at the
    # top, where N + m g = m v^2/R.
    "block_ramp_into_loop": {
        "v": lambda s: sp.sqrt(2 * s.g * (s.R + 3 * s.d) / 5),
        "v_top": lambda s: sp.sqrt(2 * s.g * ((s.R + 3 * s.d) / 5 - 2 * s.R)),
        "N_top": lambda s: s.m * (2 * s.g * ((s.R + 3 * s.d) / 5 - 2 * s.R) / s.R - s.g),
        "d_min": lambda s: (5 * sp.Rational(5, 2) * s.R - s.R) / 3,  # the book's least release height, 5R/2
    },
    # Halliday ch. 8, Serway & Jewett ch. 6: the same track released lower; it leaves where N = 0,
    # v^2 = g y with y above the center, and v^2 = 2 g (H - R - y): y = 2 (H - R)/3.
    "block_leaves_loop": {
        "y": lambda s: s.R + 2 * ((s.R + 3 * s.d) / 5 - s.R) / 3,
        "v_off": lambda s: sp.sqrt(s.g * 2 * ((s.R + 3 * s.d) / 5 - s.R) / 3),
    },
    # Serway & Jewett ch. 8: down a smooth quarter circle of radius h onto the level, across it and
    # up a second smooth ramp: v = sqrt(2 g h) on the level, and it rises to its release height h.
    "block_ramp_floor_ramp": {
        "v": lambda s: sp.sqrt(2 * s.g * s.h),
        "y": lambda s: s.h,
    },
    # Serway & Jewett ch. 10: a solid ball rolling at v0 on the floor into a loop (a transfer that
    # keeps its spin): (7/10) v_top^2 = (7/10) v0^2 - g 2 (R - r), rolling clockwise, omega = -v/r;
    # ch. 6: at the top N + m g = m v_top^2/(R - r).
    "ball_floor_into_loop": {
        "v_top": lambda s: sp.sqrt(s.v0**2 - sp.Rational(20, 7) * s.g * (s.R - s.r)),
        "omega_top": lambda s: -sp.sqrt(s.v0**2 - sp.Rational(20, 7) * s.g * (s.R - s.r)) / s.r,
        "N_top": lambda s: s.m * ((s.v0**2 - sp.Rational(20, 7) * s.g * (s.R - s.r)) / (s.R - s.r) - s.g),
    },
    # Serway & Jewett ch. 10 and ch. 6, Halliday ch. 11: a solid ball released d along the ramp (its
    # center (R + 3 d - r)/5 above its center at the loop's bottom) rolls down and round the loop:
    # (7/10) v^2 = g times its center's drop, (R + 3 d - r)/5 at the bottom and 2 (R - r) less at
    # the top, where N + m g = m v_top^2/(R - r); it stays on for a drop to the bottom of at least
    # 2.7 (R - r) (the book's 2.7 R for r << R): (R + 3 d - r)/5 = 27 (R - r)/10.
    "ball_ramp_into_loop": {
        "v": lambda s: sp.sqrt(sp.Rational(10, 7) * s.g * (s.R + 3 * s.d - s.r) / 5),
        "v_top": lambda s: sp.sqrt(sp.Rational(10, 7) * s.g * ((s.R + 3 * s.d - s.r) / 5 - 2 * (s.R - s.r))),
        "N_top": lambda s: s.m * (sp.Rational(10, 7) * s.g * ((s.R + 3 * s.d - s.r) / 5 - 2 * (s.R - s.r))
                                  / (s.R - s.r) - s.g),
        "d_min": lambda s: (5 * sp.Rational(27, 10) * (s.R - s.r) - s.R + s.r) / 3,
    },
    # Serway & Jewett ch. 10 and ch. 6: a solid ball rolling at v0 across a bowl's bottom rises until
    # (7/10) v0^2 = g h, its centre from -(Rb - r) below the bowl's centre; at the bottom
    # N - m g = m v0^2/(Rb - r). (A trial's file: its answers were refused by the dimension check,
    # which took atan2 of two lengths for a function of a length.)
    "ball_rolls_up_bowl": {
        "y": lambda s: -(s.Rb - s.r) + sp.Rational(7, 10) * s.v0**2 / s.g,
        "N": lambda s: s.m * (s.g + s.v0**2 / (s.Rb - s.r)),
    },
    # Serway & Jewett ch. 10: (1/2)(M L^2/3) w0^2 = M g (L/2)(1 - cos(theta_max)); at the top it is
    # at rest, so the hinge's vertical pull is M g (1 - 3 sin^2(theta_max)/4) (alpha = -3 g sin/(2L));
    # the time there is a quarter period of the physical pendulum, sqrt(2L/(3g)) K(sin^2(theta_max/2)).
    "rod_swing_stops": {
        # asked as magnitudes: the angle below the horizontal, the depth of the center below the pin
        "angle": lambda s: sp.pi / 2 - sp.acos(1 - s.L * s.w0**2 / (3 * s.g)),
        "h": lambda s: s.L / 2 * (1 - s.L * s.w0**2 / (3 * s.g)),
        "F": lambda s: s.M * s.g * (1 - 3 * (1 - (1 - s.L * s.w0**2 / (3 * s.g)) ** 2) / 4),
        "t": lambda s: sp.sqrt(2 * s.L / (3 * s.g))
        * sp.elliptic_k(sp.sin(sp.acos(1 - s.L * s.w0**2 / (3 * s.g)) / 2) ** 2),
    },
    # Serway & Jewett ch. 5: up a smooth incline at v0, it rises v0^2/(2g) in t = v0/(g sin(theta)),
    # and slides back in as long, arriving at v0.
    "block_up_incline": {
        "h": lambda s: s.v0**2 / (2 * s.g),
        "t": lambda s: s.v0 / (s.g * sp.sin(s.theta)),
        "tb": lambda s: s.v0 / (s.g * sp.sin(s.theta)),
        "vb": lambda s: s.v0,
    },
    # Kleppner & Kolenkow ch. 4/5: given v0 at the bottom (2gL < v0^2 < 5gL), the string goes
    # slack at (v0^2 - 2 g L)/(3 g) above the center, the ball moving at sqrt(g times that).
    "ball_circle_slack": {
        "h": lambda s: (s.v0**2 - 2 * s.g * s.L) / (3 * s.g),
        "v": lambda s: sp.sqrt((s.v0**2 - 2 * s.g * s.L) / 3),
    },
    # Serway & Jewett Eq. 10.25: tau phi = I omega^2/2 from rest, I = M R^2/2.
    "flywheel_torque_work": {
        "omega": lambda s: sp.sqrt(2 * s.tau * s.phi / (s.M * s.R**2 / 2)),
    },
    # Serway & Jewett ch. 10 problems: a disk pivoted at its rim, released with its center level
    # with the pivot: (3/2) M R^2 omega^2/2 = M g R, omega = sqrt(4g/(3R)); the pivot then holds
    # M g + M omega^2 R = 7 M g/3. (Written from the README alone as a new user's trial: its
    # center is extremal at the state, which the first parametrization could not follow.)
    "disk_rim_swing": {
        "omega": lambda s: sp.sqrt(4 * s.g / (3 * s.R)),
        "v": lambda s: sp.sqrt(4 * s.g * s.R / 3),
        "F": lambda s: 7 * s.M * s.g / 3,
    },
    # Serway & Jewett ch. 7: v = d sqrt(k/m) where the spring is relaxed; the floor holds m g.
    "spring_launch": {
        "v": lambda s: s.d * sp.sqrt(s.k / s.m),
        "N": lambda s: s.m * s.g,
    },
    # Serway & Jewett Example 10.14 (an Atwood machine with a disk pulley, by energy): after m1
    # falls h, v = sqrt(2 (m1 - m2) g h/(m1 + m2 + I/R^2)), I = M R^2/2, omega = v/R; the
    # acceleration a = (m1 - m2) g/(m1 + m2 + M/2) is constant, so t = sqrt(2 h/a), and the rope
    # holds the heavier block with T1 = m1 (g - a).
    "atwood_pulley_speed": {
        "v": lambda s: sp.sqrt(2 * (s.m1 - s.m2) * s.g * s.h / (s.m1 + s.m2 + s.M / 2)),
        "omega": lambda s: sp.sqrt(2 * (s.m1 - s.m2) * s.g * s.h / (s.m1 + s.m2 + s.M / 2)) / s.R,
        "t": lambda s: sp.sqrt(2 * s.h * (s.m1 + s.m2 + s.M / 2) / ((s.m1 - s.m2) * s.g)),
        "T1": lambda s: s.m1 * (s.g - (s.m1 - s.m2) * s.g / (s.m1 + s.m2 + s.M / 2)),
    },
    # Serway & Jewett ch. 10 problems (a yo-yo, a uniform disk, unwinding from a string fixed
    # above it): M g h = (M v^2 + I v^2/R^2)/2 gives v = sqrt(4 g h/3); a = 2 g/3, so
    # t = sqrt(2 h/a) = sqrt(3 h/g), and T = M (g - a) = M g/3.
    "yoyo_falls": {
        "v": lambda s: sp.sqrt(4 * s.g * s.h / 3),
        "t": lambda s: sp.sqrt(3 * s.h / s.g),
        "T": lambda s: s.M * s.g / 3,
    },
    # Serway & Jewett ch. 10 (a block on a frictionless table pulled over a uniform disk pulley by
    # a hanging block): (m1 + m2 + M/2) v^2/2 = m2 g h; the block on the table has moved h toward
    # the pulley, and the table holds its weight.
    # Serway & Jewett ch. 10 (by energy, a block pulled up a smooth incline over a disk pulley):
    # (m1 + m2 + M/2) v^2/2 = m2 g h - m1 g h sin(theta); the hanging block moves down (y up).
    "incline_pulley_speed": {
        "v": lambda s: -sp.sqrt(2 * s.g * s.h * (s.m2 - s.m1 * _sin(s.theta)) / (s.m1 + s.m2 + s.M / 2)),
    },
    "table_block_pulley_speed": {
        "v": lambda s: sp.sqrt(2 * s.m2 * s.g * s.h / (s.m1 + s.m2 + s.M / 2)),
        "x": lambda s: -10 * s.R + s.h,
        "N": lambda s: s.m1 * s.g,
    },
    # Kinetic friction from rest, or until it stops: the friction's work is -mu_k N times the
    # distance slid, N constant on a plane. Serway & Jewett ch. 8: a block on a rough table tied
    # over a light pulley to a hanging ball, v^2 = 2 g h (m2 - mu_k m1)/(m1 + m2), a constant
    # acceleration (so t = 2 h/v), T = m2 (g - a).
    "rough_table_hanging_ball": {
        "v": lambda s: sp.sqrt(2 * s.g * s.h * (s.m2 - s.mu * s.m1) / (s.m1 + s.m2)),
        "t": lambda s: sp.sqrt(2 * s.h * (s.m1 + s.m2) / (s.g * (s.m2 - s.mu * s.m1))),
        "T": lambda s: s.m1 * s.m2 * s.g * (1 + s.mu) / (s.m1 + s.m2),
    },
    # Serway & Jewett ch. 8: a crate sliding down a rough ramp from rest, v^2 = 2 g d (sin - mu_k cos).
    "block_down_rough_incline": {
        "v": lambda s: sp.sqrt(2 * s.g * s.d * (_sin(s.theta) - s.mu * _cos(s.theta))),
        "t": lambda s: sp.sqrt(2 * s.d / (s.g * (_sin(s.theta) - s.mu * _cos(s.theta)))),
        "N": lambda s: s.m * s.g * _cos(s.theta),
        "K": lambda s: s.m * s.g * s.d * (_sin(s.theta) - s.mu * _cos(s.theta)),
        "f": lambda s: s.mu * s.m * s.g * _cos(s.theta),
    },
    # Halliday ch. 8: up a rough incline at v0, it stops after d = v0^2/(2 g (sin + mu_k cos)), at
    # the height d sin(theta), in v0/(g (sin + mu_k cos)); tan(theta) > mu_k, so it slides back,
    # v^2 = 2 g d (sin - mu_k cos).
    "crate_up_rough_ramp": {
        "h": lambda s: s.v0**2 * _sin(s.theta) / (2 * s.g * (_sin(s.theta) + s.mu * _cos(s.theta))),
        "t": lambda s: s.v0 / (s.g * (_sin(s.theta) + s.mu * _cos(s.theta))),
        "W": lambda s: -s.m * s.v0**2 / 2,
        "vb": lambda s: s.v0 * sp.sqrt((_sin(s.theta) - s.mu * _cos(s.theta)) / (_sin(s.theta) + s.mu * _cos(s.theta))),
    },
    # Halliday ch. 6: a puck slides d = v0^2/(2 mu_k g) in v0/(mu_k g); at half its speed it has
    # gone (v0^2 - v0^2/4)/(2 mu_k g).
    "puck_slides_to_stop": {
        "d": lambda s: s.v0**2 / (2 * s.mu * s.g),
        "t": lambda s: s.v0 / (s.mu * s.g),
        "x": lambda s: 3 * s.v0**2 / (8 * s.mu * s.g),
    },
    # Serway & Jewett Example 8.6: (1/2) m v^2 = (1/2) k d^2 - mu_k m g d at the relaxed length.
    # The time: Morin, Introduction to Classical Mechanics, ch. 4 (a spring with kinetic
    # friction moves harmonically about the shifted equilibrium L0 - mu_k m g/k): from rest at
    # amplitude A = d - mu_k m g/k, it reaches L0 where cos(omega t) = -mu_k m g/(k A).
    "spring_block_rough_floor": {
        "v": lambda s: sp.sqrt(s.k * s.d**2 / s.m - 2 * s.mu * s.g * s.d),
        "t": lambda s: sp.acos(-s.mu * s.m * s.g / (s.k * (s.d - s.mu * s.m * s.g / s.k))) / sp.sqrt(s.k / s.m),
    },
    # Serway & Jewett Example 10.13: a solid sphere rolls from rest, v^2 = 10 g d sin(theta)/7,
    # held by the friction f = (2/7) M g sin(theta) (I/(I + M R^2) of the weight's component).
    "ball_rolls_down_rough_incline": {
        "v": lambda s: sp.sqrt(10 * s.g * s.d * _sin(s.theta) / 7),
        "f": lambda s: 2 * s.M * s.g * _sin(s.theta) / 7,
    },
    # A rolling ball off a smooth cushion at the height of its center: v -> -e v0, the spin -v0/R
    # kept (the cloth's friction, at most mu N, gives no impulse where N gives none); then it
    # skids, the slip v + R omega = -(1 + e) v0 shrinking at (7/2) mu g (a = mu g, alpha = 5 mu g/(2 R)),
    # for t = 2 (1 + e) v0/(7 mu g), and rolls at -e v0 + mu g t = (2 - 5 e) v0/7, its center at
    # X - R - e v0 t + mu g t^2/2.
    "ball_rolls_into_cushion": {
        "vb": lambda s: -s.e * s.v0,
        "wb": lambda s: -s.v0 / s.R,
        "V": lambda s: (2 - 5 * s.e) * s.v0 / 7,
        "t": lambda s: 2 * (1 + s.e) * s.v0 / (7 * s.mu * s.g),
        "x": lambda s: (s.X - s.R - s.e * s.v0 * 2 * (1 + s.e) * s.v0 / (7 * s.mu * s.g)
                        + s.mu * s.g * (2 * (1 + s.e) * s.v0 / (7 * s.mu * s.g)) ** 2 / 2),
    },
    # Kleppner & Kolenkow ch. 7: the ladder's top leaves the smooth wall where sin(phi) = (2/3)
    # sin(th0), phi its angle above the floor; energy, phi'^2 = 3 g (sin(th0) - sin(phi))/L, so
    # omega^2 = g sin(th0)/L there; the center then falls at 3 g/4 (y'' = (L/2)(cos(phi) phi'' -
    # sin(phi) phi'^2) with phi'' = -(3 g/(2 L)) cos(phi)), so N = M g/4; the time is the integral
    # of dphi/|phi'| from there to th0, which no table gives in closed form (mpmath's quadrature).
    "ladder_leaves_wall": {
        "y": lambda s: s.L * _sin(s.th0) / 3,
        "w": lambda s: sp.sqrt(s.g * _sin(s.th0) / s.L),
        "N": lambda s: s.M * s.g / 4,
        "t": lambda s: sp.Integral(1 / sp.sqrt(3 * s.g * (_sin(s.th0) - _sin(_PHI)) / s.L),
                                   (_PHI, sp.asin(2 * _sin(s.th0) / 3), s.th0)),
    },
    # Serway & Jewett ch. 11: angular momentum about the pivot in the collision, m v L = I omega
    # with I = M L^2/3 + m L^2; just after, the rod is vertical and not accelerating, so the pin
    # holds the weight and the centripetal pull, (M + m) g + omega^2 L (M/2 + m); then energy:
    # (1/2) I omega^2 = (M/2 + m) g L (1 - cos(theta_max)), the angle from hanging straight down.
    "rod_ballistic_pendulum": {
        "omega": lambda s: 3 * s.m * s.v / (s.L * (s.M + 3 * s.m)),
        "F": lambda s: (s.M + s.m) * s.g + (3 * s.m * s.v / (s.L * (s.M + 3 * s.m))) ** 2 * s.L * (s.M / 2 + s.m),
        "angle": lambda s: -sp.pi / 2 + sp.acos(1 - (s.M + 3 * s.m) * s.L**2 / 3
                                                * (3 * s.m * s.v / (s.L * (s.M + 3 * s.m))) ** 2
                                                / ((s.M + 2 * s.m) * s.g * s.L)),
    },
    # Serway & Jewett Example 9.6 (the ballistic pendulum): v_B = m1 v/(m1 + m2), h = v_B^2/(2 g);
    # the cord then holds (m1 + m2)(g + v_B^2/L).
    "ballistic_pendulum_block": {
        "vB": lambda s: s.m1 * s.v / (s.m1 + s.m2),
        "h": lambda s: (s.m1 * s.v / (s.m1 + s.m2)) ** 2 / (2 * s.g),
        "T": lambda s: (s.m1 + s.m2) * (s.g + (s.m1 * s.v / (s.m1 + s.m2)) ** 2 / s.L),
    },
    # Serway & Jewett ch. 11 problems: m v R = (M R^2/2 + m R^2) omega; the kinetic energy m v^2/2
    # before, (M R^2/2 + m R^2) omega^2/2 after; the axle then supplies the centripetal force of the
    # system's center of mass, m R/(M + m) from the axle: -(M + m) omega^2 m R/(M + m) along x.
    "child_jumps_on_platform": {
        "omega": lambda s: s.m * s.v * s.R / (s.M * s.R**2 / 2 + s.m * s.R**2),
        "K0": lambda s: s.m * s.v**2 / 2,
        "K1": lambda s: (s.M * s.R**2 / 2 + s.m * s.R**2) * (s.m * s.v * s.R / (s.M * s.R**2 / 2 + s.m * s.R**2)) ** 2 / 2,
        "F": lambda s: -s.m * s.R * (s.m * s.v * s.R / (s.M * s.R**2 / 2 + s.m * s.R**2)) ** 2,
    },
    # Halliday, Resnick & Walker ch. 11: I1 w1 + I2 w2 = (I1 + I2) w (I = M R^2/2); a constant
    # braking torque tau then stops them after a turn (I1 + I2) w^2/(2 tau), in (I1 + I2) w/tau.
    "clutch_disks_brake": {
        "omega": lambda s: (s.M1 * s.R1**2 * s.w1 + s.M2 * s.R2**2 * s.w2) / (s.M1 * s.R1**2 + s.M2 * s.R2**2),
        "K0": lambda s: s.M1 * s.R1**2 * s.w1**2 / 4 + s.M2 * s.R2**2 * s.w2**2 / 4,
        "K1": lambda s: (s.M1 * s.R1**2 + s.M2 * s.R2**2) / 4
        * ((s.M1 * s.R1**2 * s.w1 + s.M2 * s.R2**2 * s.w2) / (s.M1 * s.R1**2 + s.M2 * s.R2**2)) ** 2,
        "turn": lambda s: (s.M1 * s.R1**2 + s.M2 * s.R2**2) / 2
        * ((s.M1 * s.R1**2 * s.w1 + s.M2 * s.R2**2 * s.w2) / (s.M1 * s.R1**2 + s.M2 * s.R2**2)) ** 2 / (2 * s.tau),
        "t": lambda s: (s.M1 * s.R1**2 + s.M2 * s.R2**2) / 2
        * ((s.M1 * s.R1**2 * s.w1 + s.M2 * s.R2**2 * s.w2) / (s.M1 * s.R1**2 + s.M2 * s.R2**2)) / s.tau,
    },
    # Kleppner & Kolenkow ch. 7 / Morin ch. 8: rolling on a fixed sphere (rho = R + r from its
    # center), N = M g (17 c - k)/7 with k = 10 + 7 v0^2/(g rho), c = cos(phi), and f = 2 M g sin(phi)/7;
    # |f| = mu N where mu^2 (17 c - k)^2 = 4 (1 - c^2), the larger root (reached first from the top):
    # c = (17 mu^2 k + 2 sqrt(4 + mu^2 (289 - k^2)))/(289 mu^2 + 4); the center is rho c above.
    "ball_slips_on_dome": {
        "h": lambda s: (s.R + s.r) * (17 * s.mu**2 * (10 + 7 * s.v0**2 / (s.g * (s.R + s.r)))
                                      + 2 * sp.sqrt(4 + s.mu**2 * (289 - (10 + 7 * s.v0**2 / (s.g * (s.R + s.r))) ** 2)))
        / (289 * s.mu**2 + 4),
    },
    # Serway & Jewett ch. 11 problems: about the pivot m v L = m u L + (M L^2/3) omega, and the
    # ends' relative speed reversed and scaled, L omega - u = e v.
    "ball_bounces_off_rod": {
        "omega": lambda s: 3 * (1 + s.e) * s.m * s.v / (s.L * (s.M + 3 * s.m)),
        "u": lambda s: s.v * (3 * s.m - s.M * s.e) / (s.M + 3 * s.m),
        "K0": lambda s: s.m * s.v**2 / 2,
        "K1": lambda s: s.m * (s.v * (3 * s.m - s.M * s.e) / (s.M + 3 * s.m)) ** 2 / 2
        + s.M * s.L**2 / 6 * (3 * (1 + s.e) * s.m * s.v / (s.L * (s.M + 3 * s.m))) ** 2,
    },
    # Kleppner & Kolenkow ch. 7: the blow J_b = (1 + e) m v I_p/(I_p + m d^2), I_p = M L^2/3, from
    # I_p omega = J_b d and the ends' relative speed reversed, d omega - v' = e v; the ball takes
    # -J_b, the rod M omega L/2 = 3 J_b d/(2 L), the pin the rest, J_b (3 d/(2 L) - 1): none at the
    # center of percussion, d = 2 L/3, and none upward (finite forces give no impulse).
    "rod_center_of_percussion": {
        "J": lambda s: -(1 + s.e) * s.m * s.v * s.M * s.L**2 / (s.M * s.L**2 + 3 * s.m * s.d**2),
        "Jrod": lambda s: 3 * s.d / (2 * s.L) * (1 + s.e) * s.m * s.v * s.M * s.L**2 / (s.M * s.L**2 + 3 * s.m * s.d**2),
        "P": lambda s: (3 * s.d / (2 * s.L) - 1) * (1 + s.e) * s.m * s.v * s.M * s.L**2
        / (s.M * s.L**2 + 3 * s.m * s.d**2),
        "Py": lambda s: sp.Integer(0),
        "dp": lambda s: 2 * s.L / 3,
    },
    # Kleppner & Kolenkow ch. 7 problems: the impulse J at the rod's end gives V = J/M and, about its
    # center, omega = -6 J/(M L) (the end above the center, pushed +x); the end's speed V + 3 J/M
    # less the puck's v - J/m is e v: J = (1 + e) m M v/(M + 4 m). A smooth puck does not spin; the
    # energy taken is (1 - e^2) M m v^2/(2 (M + 4 m)).
    "disk_strikes_free_rod": {
        "u": lambda s: s.v * (4 * s.m - s.e * s.M) / (s.M + 4 * s.m),
        "V": lambda s: (1 + s.e) * s.m * s.v / (s.M + 4 * s.m),
        "omega": lambda s: -6 * (1 + s.e) * s.m * s.v / (s.L * (s.M + 4 * s.m)),
        "spin": lambda s: sp.Integer(0),
        "J": lambda s: (1 + s.e) * s.m * s.M * s.v / (s.M + 4 * s.m),
        "dK": lambda s: -(1 - s.e**2) * s.M * s.m * s.v**2 / (2 * (s.M + 4 * s.m)),
    },
    # Serway & Jewett ch. 9 (two dimensions): along the line of centers n = (cos(phi), -sin(phi))
    # the target leaves at (1 + e) m1 v cos(phi)/(m1 + m2); the striker keeps its velocity across n
    # and loses the target's momentum along it; the energy taken is (1 - e^2) mu (v cos(phi))^2/2.
    "disks_glancing_collision": {
        "v1x": lambda s: s.v - (1 + s.e) * s.m2 * s.v * _cos(s.phi) ** 2 / (s.m1 + s.m2),
        "v1y": lambda s: (1 + s.e) * s.m2 * s.v * _cos(s.phi) * _sin(s.phi) / (s.m1 + s.m2),
        "v2x": lambda s: (1 + s.e) * s.m1 * s.v * _cos(s.phi) ** 2 / (s.m1 + s.m2),
        "v2y": lambda s: -(1 + s.e) * s.m1 * s.v * _cos(s.phi) * _sin(s.phi) / (s.m1 + s.m2),
        "Jy": lambda s: -(1 + s.e) * s.m1 * s.m2 * s.v * _cos(s.phi) * _sin(s.phi) / (s.m1 + s.m2),
        "dK": lambda s: -(1 - s.e**2) * s.m1 * s.m2 / (s.m1 + s.m2) * (s.v * _cos(s.phi)) ** 2 / 2,
    },
    # Serway & Jewett ch. 11: about the axle (M R^2/2 + m R^2) w0 = (M R^2/2) omega.
    # Kleppner & Kolenkow ch. 7 / Morin ch. 8: the floor's impulse acts at the point of contact,
    # so the angular momentum about it is kept, m v_x R = m v_x' R + (2/5) m R^2 (-omega'), and
    # gripping it leaves rolling, v_x' = -R omega': v_x' = 5 v_x/7; v_y' = e v_y (up); the energy
    # taken is m v_x^2/7 of the spin-up and m (1 - e^2) v_y^2/2 of the normal impulse.
    "sphere_bounces_gripping": {
        "vx": lambda s: 5 * s.v * _sin(s.theta) / 7,
        "vy": lambda s: s.e * s.v * _cos(s.theta),
        "omega": lambda s: -5 * s.v * _sin(s.theta) / (7 * s.R),
        "dK": lambda s: -s.m * (s.v * _sin(s.theta)) ** 2 / 7 - s.m * (1 - s.e**2) * (s.v * _cos(s.theta)) ** 2 / 2,
    },
    # Derived here from impulse and momentum (the file's source): the normal impulse is
    # J_n = m (1 + e) v_y; sliding throughout, the tangential one is mu J_n against the slip, so
    # m v_x' = m v_x - mu J_n and, about the center, (2/5) m R^2 omega' = -R mu J_n; it slides
    # while 2 v_x/7 > mu (1 + e) v_y (the ranges keep it there).
    "sphere_bounces_sliding": {
        "vx": lambda s: s.v * _sin(s.theta) - s.mu * (1 + s.e) * s.v * _cos(s.theta),
        "vy": lambda s: s.e * s.v * _cos(s.theta),
        "omega": lambda s: -5 * s.mu * (1 + s.e) * s.v * _cos(s.theta) / (2 * s.R),
        "dK": lambda s: s.m / 2 * ((s.v * _sin(s.theta) - s.mu * (1 + s.e) * s.v * _cos(s.theta)) ** 2
                                   + (s.e * s.v * _cos(s.theta)) ** 2)
        + s.m * s.R**2 / 5 * (5 * s.mu * (1 + s.e) * s.v * _cos(s.theta) / (2 * s.R)) ** 2 - s.m * s.v**2 / 2,
    },
    # The flight after a bounce (free flight: constant accelerations). Kleppner & Kolenkow ch. 7:
    # gripping, the ball leaves at v0x = 5 v sin(theta)/7, spinning -5 v sin(theta)/(7 R), and
    # v0y = e v cos(theta) up; then Halliday ch. 4's projectile: the top at v0y^2/(2 g) above the
    # bounce (its center R above the floor there), v0y/g later and v0x v0y/g along; back on the
    # floor after T = 2 v0y/g, 2 v0x v0y/g along, falling at v0y, its spin unchanged (no torque).
    "ball_bounces_then_flies": {
        "rise": lambda s: s.R + (s.e * s.v * _cos(s.theta)) ** 2 / (2 * s.g),
        "xtop": lambda s: 5 * s.v * _sin(s.theta) / 7 * s.e * s.v * _cos(s.theta) / s.g,
        "ttop": lambda s: s.e * s.v * _cos(s.theta) / s.g,
        "range": lambda s: 2 * (5 * s.v * _sin(s.theta) / 7) * s.e * s.v * _cos(s.theta) / s.g,
        "T": lambda s: 2 * s.e * s.v * _cos(s.theta) / s.g,
        "spin": lambda s: -5 * s.v * _sin(s.theta) / (7 * s.R),
        "vy": lambda s: -s.e * s.v * _cos(s.theta),
    },
    # Meriam & Kraige art. 3/12 (oblique impact on a smooth face): dropped from h, the ball strikes
    # a face at 45 degrees at v0 = sqrt(2 g h) straight down; along the face's normal
    # n = (1, 1)/sqrt(2) its velocity -v0 n/sqrt(2) becomes e v0 n/sqrt(2), along the face v0/sqrt(2)
    # stays: vx = (1 + e) v0/2, vy = -(1 - e) v0/2. Halliday ch. 4: it falls H in
    # t = (vy + sqrt(vy^2 + 2 g H))/g, landing vx t along, at sqrt(vx^2 + vy^2 + 2 g H).
    "ball_bounces_off_wedge": {
        "vx": lambda s: (1 + s.e) * sp.sqrt(2 * s.g * s.h) / 2,
        "vy": lambda s: _wedge_vy(s),
        "x": lambda s: (1 + s.e) * sp.sqrt(2 * s.g * s.h) / 2 * (_wedge_vy(s) + sp.sqrt(_wedge_vy(s) ** 2 + 2 * s.g * s.H)) / s.g,
        "t": lambda s: (_wedge_vy(s) + sp.sqrt(_wedge_vy(s) ** 2 + 2 * s.g * s.H)) / s.g,
        "u": lambda s: sp.sqrt(((1 + s.e) * sp.sqrt(2 * s.g * s.h) / 2) ** 2 + _wedge_vy(s) ** 2 + 2 * s.g * s.H),
    },
    "child_walks_to_center": {
        "omega": lambda s: s.w0 * (s.M + 2 * s.m) / s.M,
        "K0": lambda s: (s.M * s.R**2 / 2 + s.m * s.R**2) * s.w0**2 / 2,
        "K1": lambda s: s.M * s.R**2 / 4 * (s.w0 * (s.M + 2 * s.m) / s.M) ** 2,
    },
    # Serway & Jewett ch. 11: (I + 2 m r1^2) w0 = (I + 2 m r2^2) omega.
    "stool_pulls_in_weights": {
        "omega": lambda s: s.w0 * (s.I + 2 * s.m * s.r1**2) / (s.I + 2 * s.m * s.r2**2),
        "K0": lambda s: (s.I + 2 * s.m * s.r1**2) * s.w0**2 / 2,
        "K1": lambda s: (s.I + 2 * s.m * s.r2**2) * (s.w0 * (s.I + 2 * s.m * s.r1**2) / (s.I + 2 * s.m * s.r2**2)) ** 2 / 2,
    },
    # Serway & Jewett ch. 10-11: the couple C speeds the record (I2) and slows the turntable (I1)
    # until I1 w0 = (I1 + I2) omega, after t = I2 omega/C; the record turns C t^2/(2 I2) meanwhile.
    "turntable_record_slips": {
        "alpha": lambda s: s.C / (s.M2 * s.R2**2 / 2),
        "omega": lambda s: s.M1 * s.R1**2 * s.w0 / (s.M1 * s.R1**2 + s.M2 * s.R2**2),
        "t": lambda s: s.M2 * s.R2**2 / 2 * s.M1 * s.R1**2 * s.w0 / (s.M1 * s.R1**2 + s.M2 * s.R2**2) / s.C,
        "turn": lambda s: s.C / (s.M2 * s.R2**2) * (s.M2 * s.R2**2 / 2 * s.M1 * s.R1**2 * s.w0
                                                   / (s.M1 * s.R1**2 + s.M2 * s.R2**2) / s.C) ** 2,
        "K1": lambda s: (s.M1 * s.R1**2 + s.M2 * s.R2**2) / 4
        * (s.M1 * s.R1**2 * s.w0 / (s.M1 * s.R1**2 + s.M2 * s.R2**2)) ** 2,
    },
    # Halliday, Resnick & Walker ch. 10: alpha = -tau/I, t = I w0/tau, turn I w0^2/(2 tau), I = M R^2.
    "flywheel_brake_grips": {
        "alpha": lambda s: -s.C / (s.M * s.R**2),
        "t": lambda s: s.M * s.R**2 * s.w0 / s.C,
        "turn": lambda s: s.M * s.R**2 * s.w0**2 / (2 * s.C),
    },
    # Serway & Jewett ch. 10; Kleppner & Kolenkow ch. 7: kinetic friction mu M g slows the ball
    # and spins it up until v = -R omega: t = 2 v0/(7 mu g), V = 5 v0/7, d = 12 v0^2/(49 mu g).
    "bowling_ball_skids": {
        "a": lambda s: -s.mu * s.g,
        "t": lambda s: 2 * s.v0 / (7 * s.mu * s.g),
        "d": lambda s: 12 * s.v0**2 / (49 * s.mu * s.g),
        "V": lambda s: 5 * s.v0 / 7,
        "K": lambda s: 5 * s.M * s.v0**2 / 14,
    },
    # Kleppner & Kolenkow ch. 7: angular momentum about the contact point, M R v0 - I w0 =
    # (M R^2 + I) V / R; the slip v + R w falls at 7 mu g/2.
    "cue_ball_backspin": {
        "V": lambda s: (5 * s.v0 - 2 * s.R * s.w0) / 7,
        "t": lambda s: 2 * (s.v0 + s.R * s.w0) / (7 * s.mu * s.g),
    },
    # Halliday, Resnick & Walker ch. 11; Morin ch. 8: I w0 = (I + M R^2) V/R, V = 2 R w0/7.
    "spinning_ball_set_down": {
        "V": lambda s: 2 * s.R * s.w0 / 7,
        "t": lambda s: 2 * s.R * s.w0 / (7 * s.mu * s.g),
    },
    # Serway & Jewett ch. 11: m v R = (I + m R^2) w1 = (I + m r^2) w2, I = M R^2/2.
    "child_jumps_then_walks_in": {
        "w1": lambda s: s.m * s.v * s.R / (s.M * s.R**2 / 2 + s.m * s.R**2),
        "w2": lambda s: s.m * s.v * s.R / (s.M * s.R**2 / 2 + s.m * s.r**2),
        "K2": lambda s: (s.M * s.R**2 / 2 + s.m * s.r**2) * (s.m * s.v * s.R / (s.M * s.R**2 / 2 + s.m * s.r**2)) ** 2 / 2,
    },
    # Halliday, Resnick & Walker ch. 15: tau = -kappa theta at any angle, so T = 2 pi sqrt(I/kappa),
    # I = M R^2/2, whatever the amplitude (here by energy between the turning points, a quadrature).
    "torsion_pendulum_wide_swing": {
        "T": lambda s: 2 * sp.pi * sp.sqrt(s.M * s.R**2 / (2 * s.kappa)),
    },
    # Bearings (3D; derive.mechanics.bearings). Kleppner & Kolenkow ch. 7: a dumbbell (m at l either
    # side of the center) on a shaft at alpha: |L| = 2 m l^2 omega sin(alpha), the bearings' torque
    # omega |L| cos(alpha), a couple of forces tau/d from bearings d apart.
    "dumbbell_tilted_shaft": {
        "L": lambda s: 2 * s.m * s.l**2 * s.omega * _sin(s.alpha),
        "tau": lambda s: 2 * s.m * s.l**2 * s.omega**2 * _sin(s.alpha) * _cos(s.alpha),
        "F": lambda s: 2 * s.m * s.l**2 * s.omega**2 * _sin(s.alpha) * _cos(s.alpha) / s.d,
    },
    # Taylor ch. 10 / Goldstein ch. 5 (dynamic imbalance): tau = (I3 - I1) omega^2 sin(beta) cos(beta),
    # I3 = M R^2/2, I1 = M R^2/4.
    "disk_tilted_on_shaft": {
        "tau": lambda s: s.M * s.R**2 / 4 * s.omega**2 * _sin(s.beta) * _cos(s.beta),
        "F": lambda s: s.M * s.R**2 / 4 * s.omega**2 * _sin(s.beta) * _cos(s.beta) / s.d,
    },
    # Rotating unbalance (Meriam & Kraige ch. 7; Hibbeler ch. 21): a mass m at radius e on a rotor
    # needs F = m e omega^2 across the shaft, whatever the rotor's mass, shared by bearings either
    # side; on a level shaft each also carries half the weight (M + m) g, and with the mass level
    # with the shaft the drive holds the weight's moment m g e about it. The disk turns about its
    # principal axis through its center, so the torque about the center of mass is zero.
    "rotor_static_imbalance": {
        "F": lambda s: sp.sqrt((s.m * s.e * s.omega**2) ** 2 + ((s.M + s.m) * s.g) ** 2),
        "FAx": lambda s: s.m * s.e * s.omega**2 / 2,  # a magnitude, away from the mass (centripetal)
        "FAy": lambda s: (s.M + s.m) * s.g / 2,
        "tau": lambda s: 0,
        "Q": lambda s: s.m * s.g * s.e,
    },
    # Dynamic imbalance (Meriam & Kraige ch. 7): masses m at r on opposite sides, 2a apart along the
    # shaft: no net force, a couple m r omega^2 * 2a, each bearing d apart its share 2 m r a omega^2/d.
    "shaft_dynamic_imbalance": {
        "F": lambda s: 0,
        "tau": lambda s: 2 * s.m * s.r * s.a * s.omega**2,
        "FA": lambda s: 2 * s.m * s.r * s.a * s.omega**2 / s.d,
        "FB": lambda s: 2 * s.m * s.r * s.a * s.omega**2 / s.d,
    },
    # Kleppner & Kolenkow ch. 7 (the skew rod), a uniform rod: L = (M L^2/12) omega sin(alpha),
    # perpendicular to the rod, so pi/2 - alpha from omega; tau = (M L^2/12) omega^2 sin(alpha) cos(alpha);
    # T = omega L_z/2 = (M L^2/24) omega^2 sin^2(alpha).
    "rod_tilted_on_shaft": {
        "Lmag": lambda s: s.M * s.L**2 / 12 * s.omega * _sin(s.alpha),
        "angle": lambda s: sp.pi / 2 - s.alpha,
        "tau": lambda s: s.M * s.L**2 / 12 * s.omega**2 * _sin(s.alpha) * _cos(s.alpha),
        "K": lambda s: s.M * s.L**2 / 24 * s.omega**2 * _sin(s.alpha) ** 2,
    },
    # A body on a fixed point (derive.mechanics.fixed_point). Halliday ch. 11 / Serway & Jewett ch. 11:
    # a disk on a light horizontal axle of length d precesses at Omega = M g d/(I omega), I = M R^2/2.
    "gyroscope_wheel": {
        "Omega": lambda s: s.M * s.g * s.d / (s.M * s.R**2 / 2 * s.omega),
    },
    # Taylor ch. 10: steady precession where I1 Omega^2 cos(theta) - I3 omega3 Omega + M g R = 0;
    # Kleppner & Kolenkow ch. 8: a fast top nutates at I3 omega3/I1.
    "top_two_precessions": {
        "slow": lambda s: (s.I3 * s.omega3 - sp.sqrt(s.I3**2 * s.omega3**2 - 4 * s.I1 * s.M * s.g * s.R * _cos(s.theta)))
        / (2 * s.I1 * _cos(s.theta)),
        "fast": lambda s: (s.I3 * s.omega3 + sp.sqrt(s.I3**2 * s.omega3**2 - 4 * s.I1 * s.M * s.g * s.R * _cos(s.theta)))
        / (2 * s.I1 * _cos(s.theta)),
        "nutation": lambda s: s.I3 * s.omega3 / s.I1,
    },
    # Taylor ch. 10 (Example 10.3, the cone about its apex; the sleeping top): stable for
    # omega^2 > 4 lambda1 M g l/lambda3^2, lambda1 = 3/20 M (R^2 + 4 h^2), lambda3 = 3/10 M R^2, l = 3h/4.
    "sleeping_cone": {
        "omega_min": lambda s: 2 * sp.sqrt(sp.Rational(3, 20) * s.M * (s.R**2 + 4 * s.h**2) * s.M * s.g * 3 * s.h / 4)
        / (sp.Rational(3, 10) * s.M * s.R**2),
    },
    # A body rolling on its edge (derive.mechanics.rolling_coin). Kleppner & Kolenkow ch. 8 (the
    # rolling coin, small against its circle): tan(phi) = 3 V^2/(2 g R); N = M g and the friction is
    # the centripetal force M V^2/R.
    "coin_rolls_in_circle": {
        "V": lambda s: sp.sqrt(2 * s.g * s.R * sp.tan(s.phi) / 3),
        "N": lambda s: s.M * s.g,
        "f": lambda s: 2 * s.M * s.g * sp.tan(s.phi) / 3,
    },
    # Routh art. 244 (the rolling disk and hoop): upright rolling is stable for v^2 > g a/3 (a
    # uniform disk; the spin v/a) and v^2 > g a/4 (a hoop).
    "disk_rolls_upright": {
        "v_min": lambda s: sp.sqrt(s.g * s.a / 3),
        "omega_min": lambda s: sp.sqrt(s.g / (3 * s.a)),
    },
    "hoop_rolls_upright": {
        "v_min": lambda s: sp.sqrt(s.g * s.a / 4),
    },
    # Free rotation (derive.mechanics.free_rotation). Taylor §10.8 (Euler's equations with zero
    # torque): omega turns about the symmetry axis in the body at Omega_b = (lambda3 - lambda1)
    # omega3/lambda1; the Earth wobbles so (test_free_rotation checks Taylor's 300 days).
    "earth_free_precession": {
        "Omega": lambda s: (s.I3 - s.I1) * s.omega / s.I1,
    },
    # Taylor §10.8 for a thin disk, lambda1 = M R^2/4, lambda3 = M R^2/2: Omega_b = omega3; the axis
    # turns about L at |L|/lambda1 = sqrt(omega_t^2 + 4 omega3^2) (Feynman's plate: twice omega3 for a
    # small wobble); tan(angle of L) = lambda1 omega_t/(lambda3 omega3), tan(angle of omega) = omega_t/omega3.
    "thrown_plate_wobble": {
        "body": lambda s: s.omega3,
        "space": lambda s: sp.sqrt(s.omega_t**2 + 4 * s.omega3**2),
        "L_axis": lambda s: sp.atan(s.omega_t / (2 * s.omega3)),
        "omega_axis": lambda s: sp.atan(s.omega_t / s.omega3),
    },
    # Kleppner & Kolenkow ch. 8 (torque-free precession), a solid cylinder, I1 = M (3 R^2 + h^2)/12,
    # I3 = M R^2/2: Omega = (I3 - I1) omega3/I1 (retrograde: I3 < I1), the axis about L at |L|/I1,
    # tan(angle of L) = I1 omega_t/(I3 omega3).
    "football_free_precession": {
        "body": lambda s: (s.M * s.R**2 / 2 - s.M * (3 * s.R**2 + s.h**2) / 12) * s.omega3
        / (s.M * (3 * s.R**2 + s.h**2) / 12),
        "space": lambda s: sp.sqrt((s.M * (3 * s.R**2 + s.h**2) / 12 * s.omega_t) ** 2 + (s.M * s.R**2 / 2 * s.omega3) ** 2)
        / (s.M * (3 * s.R**2 + s.h**2) / 12),
        "L_axis": lambda s: sp.atan((3 * s.R**2 + s.h**2) / 12 * s.omega_t / (s.R**2 / 2 * s.omega3)),
    },
    # Taylor §10.8 (three different moments, Euler's equations linearized) and Morin ch. 9 (the
    # tennis-racket theorem): about axis k, small motions go as e^(s t), s^2 = -(Ik - Ii)(Ik - Ij) W^2/(Ii Ij);
    # a box's moments (b^2 + c^2), (a^2 + c^2), (a^2 + b^2) times M/12 about x, y, z; with a < b < c the
    # least is about z (along c), the greatest about x (along a), and about y small motions grow at
    # sqrt((I2 - I1)(I3 - I2)/(I1 I3)) W. The mass is left open: it cancels.
    "tennis_racket": {
        "least": lambda s: s.W * sp.sqrt((s.b**2 + s.c**2 - s.a**2 - s.b**2) * (s.a**2 + s.c**2 - s.a**2 - s.b**2)
                                         / ((s.b**2 + s.c**2) * (s.a**2 + s.c**2))),
        "middle": lambda s: s.W * sp.sqrt((s.a**2 + s.c**2 - s.a**2 - s.b**2) * (s.b**2 + s.c**2 - s.a**2 - s.c**2)
                                          / ((s.a**2 + s.b**2) * (s.b**2 + s.c**2))),
        "greatest": lambda s: s.W * sp.sqrt((s.b**2 + s.c**2 - s.a**2 - s.c**2) * (s.b**2 + s.c**2 - s.a**2 - s.b**2)
                                            / ((s.a**2 + s.c**2) * (s.a**2 + s.b**2))),
    },
})

FILES = textbook_files()


def _points_in_ranges(problem, fractions=(sp.Rational(1, 10), sp.Rational(1, 2), sp.Rational(9, 10))):
    """Three points inside the parameter ranges (every parameter of these files is in SI units)."""
    points = []
    for f in fractions:
        point = {}
        for p in problem.parameters.values():
            low, high = p.range if p.range is not None else (p.value, p.value)
            point[p.symbol] = low + f * (high - low)
        points.append(point)
    return points


def test_every_file_has_its_closed_forms():
    """Every library problem that cites a book is checked against the book here (and nothing else)."""
    assert {f.stem for f in FILES} == set(EXPECTED)
    assert len(FILES) == len(set(EXPECTED)) >= 120
    assert sum("states:" in f.read_text() for f in FILES) >= 50


@pytest.mark.parametrize("path", FILES, ids=[f.stem for f in FILES])
def test_textbook_closed_form(path):
    solution = derived(path)
    problem = solution.problem
    assert problem.source, "every textbook file cites its source"
    symbols = SimpleNamespace(**{name: p.symbol for name, p in problem.parameters.items()})
    expected = EXPECTED[path.stem]
    assert set(expected) == set(problem.asks), "every ask is compared with the book"
    for name, closed_form in expected.items():
        # the book's closed form is the component along the file's axes (y up, counter-clockwise positive),
        # or the magnitude where the ask says magnitude: true: what the routes give, before a direction in words
        answer = solution.signed(name)
        if answer.has(sp.Piecewise):  # friction regimes: the book's is the one the ranges reach
            for point in _points_in_ranges(problem):
                value = sp.N(answer.xreplace(point), 30)
                book = sp.N(closed_form(symbols).xreplace(point), 30)
                assert abs(value - book) <= 1e-20 * max(1, abs(book)), f"{name} at {point}: {value} vs {book}"
            continue
        if answer.has(sp.Integral) or sp.simplify(answer - closed_form(symbols)) != 0:
            # an integral (evaluated by quadrature), or a form sympy cannot prove equal (sqrt(tan^2 + 1)
            # is 1/cos only where cos > 0): the book's value at three points, to 14 digits
            for point in _points_in_ranges(problem):
                value = sp.Float(numeric.evaluate(answer, point, 15), 30)
                book = sp.N(closed_form(symbols).xreplace(point), 30)
                assert abs(value - book) <= 1e-14 * max(1, abs(book)), f"{name} at {point}: {value} vs {book}"
    # What `derive solve` reports, from the same derivation: the two routes agree, every check passes.
    checks = report.solve(problem, solution=solution)["checks"]
    assert checks["lagrange_vs_newton_euler"]["passed"], checks
    assert all(c["passed"] for c in checks.values()), checks
    # what a worked solution prints of them: sentences a student can read
    assert all(c["reading"][:1].isupper() and c["reading"].endswith(".") and "_vs_" not in c["reading"]
               for c in checks.values()), checks


def test_a_level_axles_precession_is_the_linear_conditions_root_with_no_square_root():
    """The bicycle wheel's key had printed 2 D g (M + m)(2M + m)/(2 M^2 R^2 omega + ... + sqrt(2 (M + m)(...)))
    where the level axle makes the top's condition linear: Omega = m g l/(I3 omega) (Halliday ch. 11)."""
    answer = derived(textbook("bicycle_wheel_gyroscope")).expression("Omega")
    assert not answer.atoms(sp.Pow) & {p for p in answer.atoms(sp.Pow) if p.exp == sp.Rational(1, 2)}, answer
    assert sp.count_ops(answer) <= 9, answer  # D g (2M + m)/(2 M R^2 omega)
