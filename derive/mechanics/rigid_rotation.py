"""Angular momentum of a rigid body turning about an axis that is not a principal axis (§3.5).

A body turns at rate omega about the fixed z axis through its center of mass, its own symmetry
(long) axis tilted by alpha from z in the xz plane. Tensor route: L = R I R^T omega with the
body's inertia tensor from `derive.inertia`. Integral route: L = integral of r x (omega x r) dm
over the body's elements directly. L is not along omega unless the axis is principal.

>>> m, l, w, a = sp.symbols("m L omega alpha", positive=True)
>>> angular_momentum("rod", m, {"length": l}, w, a, "integral")[2]
L**2*m*omega*sin(alpha)**2/12
"""
from __future__ import annotations

import sympy as sp

from derive import inertia
from derive.mechanics.derivation import tidy


def _rotation(shape: str, tilt: sp.Expr) -> sp.Matrix:
    """Turn the body's long (rod: x) or symmetry (z) axis to make the angle `tilt` with z."""
    if shape == "rod":  # x axis to (sin a, 0, cos a): a turn about y by pi/2 - a
        angle = sp.pi / 2 - tilt
    else:  # z axis to (sin a, 0, cos a): a turn about y by a
        angle = tilt
    return sp.Matrix([[sp.cos(angle), 0, sp.sin(angle)], [0, 1, 0], [-sp.sin(angle), 0, sp.cos(angle)]])


def angular_momentum(shape: str, mass, sizes: dict, spin, tilt, route: str) -> sp.Matrix:
    omega = sp.Matrix([0, 0, spin])
    turn = _rotation(shape, tilt)
    if route == "tensor":
        generic = inertia.SHAPES[shape]
        mapping = {inertia.M: mass, **{generic.sizes[k]: v for k, v in sizes.items()}}
        body_tensor = inertia.tensor(shape).xreplace(mapping)
        return (turn * body_tensor * turn.T * omega).applyfunc(tidy)
    shape_data = inertia.SHAPES[shape]
    mapping = {generic: sizes[name] for name, generic in shape_data.sizes.items()}
    element = sp.Matrix(shape_data.position).xreplace(mapping)
    position = turn * element
    density = mass / _measure(shape_data, mapping)
    integrand = density * position.cross(omega.cross(position)) * shape_data.element.xreplace(mapping)
    limits = [(c, lo.xreplace(mapping), hi.xreplace(mapping)) for c, lo, hi in reversed(shape_data.coordinates)]
    return integrand.applyfunc(lambda e: tidy(sp.integrate(e, *limits)))


def _measure(shape_data, mapping) -> sp.Expr:
    limits = [(c, lo.xreplace(mapping), hi.xreplace(mapping)) for c, lo, hi in reversed(shape_data.coordinates)]
    return sp.integrate(shape_data.element.xreplace(mapping), *limits)


def angle_to_spin(shape: str, mass, sizes: dict, spin, tilt) -> sp.Expr:
    """The angle between L and omega."""
    momentum = angular_momentum(shape, mass, sizes, spin, tilt, "tensor")
    cosine = sp.refine(tidy(momentum[2] / sp.sqrt(momentum.dot(momentum))), sp.Q.positive(sp.sin(tilt)))
    return sp.acos(cosine)  # a tilt between 0 and pi/2
