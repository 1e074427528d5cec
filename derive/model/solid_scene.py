"""The bodies of a scene that turn in 3D, data only: a body in bearings, on a fixed point, rolling on
its edge or in free rotation (read by derive.language.solid_file, derived by derive.mechanics.bearings,
fixed_point, angular_impulse, rolling_coin and free_rotation), and what each can be asked.

>>> import sympy as sp
>>> PivotPoint((0, 0, 0), sp.Symbol("theta"), sp.Symbol("omega")).centered
True
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp


def own_axis(shape: str) -> str:
    """The body axis the tilt is measured from: x for a rod (its length) or a composite (its
    parts' frame), z (the symmetry axis) for every other shape."""
    return "x" if shape in ("rod", "composite") else "z"


@dataclass(frozen=True)
class Bearings:
    """A body turning at the constant `rate` about a fixed shaft, its own axis
    (`own_axis`) tilted by `tilt` from the shaft, the body turned by `roll`
    about that axis; the shaft passes through the body's point `through` (x, y, z from the center of
    mass in the body's own frame); `apart` is the distance between the two bearings, either side of
    that point (None: not given); `incline`, the shaft's angle above the horizontal under gravity;
    `thrust`, the bearing ("A" or "B") that takes the weight's part along an inclined shaft;
    `turned`, the rate at which the shaft itself is turned about the ground's y, across it (a ship's
    turbine as the ship turns); `inertia`, a custom body's (transverse, axial) moments about its
    center of mass, its own axis z, else None."""

    rate: sp.Expr
    tilt: sp.Expr
    roll: sp.Expr = sp.Integer(0)
    apart: sp.Expr | None = None
    through: tuple[sp.Expr, sp.Expr, sp.Expr] = (sp.Integer(0),) * 3
    incline: sp.Expr = sp.Integer(0)
    thrust: str | None = None
    turned: sp.Expr = sp.Integer(0)
    inertia: tuple[sp.Expr, sp.Expr] | None = None


@dataclass(frozen=True)
class PivotPoint:
    """A body on a fixed point (a top's tip, a gyroscope's pivot): the point's `offset` (x, y, z)
    from the center of mass in the body's own frame; the axis from it through the center tilted by
    `tilt` from the vertical; `spin`, omega's component along that axis. At the center of mass
    (`offset` zero: no weight's torque about it) the axis is the body's own symmetry axis, leaning
    by `tilt` from the ground's z toward its x. `inertia`: a custom body's (transverse, axial)
    moments about its center of mass, else None. `hangs`: the tilt is beyond pi/2, the center of
    mass below the point (a rod swinging in a cone)."""

    offset: tuple[sp.Expr, sp.Expr, sp.Expr]
    tilt: sp.Expr
    spin: sp.Expr
    inertia: tuple[sp.Expr, sp.Expr] | None = None
    hangs: bool = False

    @property
    def centered(self) -> bool:
        """On its center of mass: the weight exerts no torque about the point."""
        return not any(self.offset)


@dataclass(frozen=True)
class RollsOnEdge:
    """A thin axially symmetric body rolling without slipping on its rim on a horizontal plane
    (derive.mechanics.rolling_coin): `radius`, the rim's; in the steady motion its plane leans by
    `tilt` from the vertical toward the axis of the circle of radius `circle` its contact point
    traces (None: not given, and no steady motion is asked); `inertia`: a custom body's (I1 about a
    diameter, I3 about the axis) through the center of mass, else None (the shape's)."""

    radius: sp.Expr
    tilt: sp.Expr | None = None
    circle: sp.Expr | None = None
    inertia: tuple[sp.Expr, sp.Expr] | None = None


#: What a body rolling on its edge can be asked: its steady motion on a circle, upright rolling's stability.
ROLLING_COIN_QUANTITIES = ("steady.precession", "steady.speed", "steady.spin", "steady.normal_force",
                           "steady.friction", "upright.min_speed", "upright.min_spin")


@dataclass(frozen=True)
class FreeRotation:
    """A body turning with no torque about its center of mass (free flight, or a frictionless point
    at its center): `spin`, omega's component along its symmetry axis (or the rate of a steady
    rotation about the principal axis asked); `across`, omega's component across that axis.
    `inertia`: a custom body's principal moments about its center of mass along its own x, y, z,
    else None."""

    spin: sp.Expr
    across: sp.Expr
    inertia: tuple[sp.Expr, sp.Expr, sp.Expr] | None = None


#: What a body in free rotation can be asked (derive.mechanics.free_rotation): of a symmetric body,
#: omega's precession about the axis in the body, the axis's about L in space and the angles of L
#: and omega from the axis; of a body with three different moments, a steady rotation about the
#: axis of least, intermediate or greatest moment (stable: its wobble; unstable: its growth rate).
FREE_ROTATION_QUANTITIES = ("free_precession.body", "free_precession.space", "angle_L_axis", "angle_omega_axis",
                            "rotation.least.wobble", "rotation.intermediate.growth_rate",
                            "rotation.greatest.wobble")
#: What a body on a fixed point can be asked (derive.mechanics.fixed_point).
PIVOT_POINT_QUANTITIES = ("precession.slow", "precession.fast", "precession.fast_top", "sleeping.min_spin",
                          "nutation.frequency", "nutation.fast_top")
#: What a body on a fixed point at its center of mass, under a couple for a time, can be asked
#: (derive.mechanics.angular_impulse): the angle L turns through, its small-angle limit (the leading
#: term in the angular impulse), the angle the axle turns through.
IMPULSE_TURN_QUANTITIES = ("turn.angular_momentum", "turn.small_angle", "turn.axle")


#: What a body in bearings can be asked (derive.mechanics.bearings); each bearing's force needs
#: `apart`, and `bearings.force` (the pair's couple) a shaft with no net force on it.
BEARING_QUANTITIES = ("angular_momentum.x", "angular_momentum.y", "angular_momentum.z", "angular_momentum.magnitude",
                      "angle_L_omega", "kinetic_energy", "bearings.torque.x", "bearings.torque.y",
                      "bearings.torque.z", "bearings.torque.magnitude", "bearings.force",
                      *(f"bearings.{v}.{c}" for v in ("total_force", "A.force", "B.force")
                        for c in ("x", "y", "z", "magnitude")), "bearings.drive_torque")
