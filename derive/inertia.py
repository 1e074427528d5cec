"""Moments of inertia by integration, and the parallel-axis theorem.

Every moment of inertia in the project comes from here: a shape is described by
its natural coordinates, their limits, the volume (or length, or area) element
and the Cartesian position of a mass element; the moment about an axis is the
integral of rho * (distance to the axis)^2 over the shape, with the uniform
density rho = M / measure fixed by the same integral of 1.

>>> result = moment_of_inertia("rod", "end")
>>> result.I
L**2*M/3
>>> moment_of_inertia("disk", "symmetry").ratio
1/2
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import sympy as sp

# The generic symbols a shape is integrated with; a body substitutes its own.
M, L, R = sp.symbols("M L R", positive=True)
x = sp.Symbol("x", real=True)
r = sp.Symbol("r", nonnegative=True)
phi = sp.Symbol("phi", real=True)


@dataclass(frozen=True)
class Shape:
    """A body shape: coordinates with limits, the measure element, element positions.

    `position` is the Cartesian position (x, y, z) of the mass element at the given
    coordinates, with the center of mass at the origin; `sizes` maps the size names
    a problem uses (length, radius) to the generic symbols above; `axes` maps axis
    names to (point on the axis, unit direction).
    """

    name: str
    coordinates: tuple[tuple[sp.Symbol, sp.Expr, sp.Expr], ...]
    element: sp.Expr
    position: tuple[sp.Expr, sp.Expr, sp.Expr]
    sizes: dict[str, sp.Symbol]
    scale: sp.Symbol
    axes: dict[str, tuple[tuple[sp.Expr, sp.Expr, sp.Expr], tuple[int, int, int]]]
    element_name: str


Z_THROUGH_CENTER = ((0, 0, 0), (0, 0, 1))

SHAPES: dict[str, Shape] = {
    "rod": Shape(
        name="rod",
        coordinates=((x, -L / 2, L / 2),),
        element=sp.Integer(1),
        position=(x, 0, 0),
        sizes={"length": L},
        scale=L,
        axes={"center": Z_THROUGH_CENTER, "end": ((-L / 2, 0, 0), (0, 0, 1))},
        element_name=r"\lambda\,dx",
    ),
    "ring": Shape(
        name="ring",
        coordinates=((phi, 0, 2 * sp.pi),),
        element=R,
        position=(R * sp.cos(phi), R * sp.sin(phi), 0),
        sizes={"radius": R},
        scale=R,
        axes={"symmetry": Z_THROUGH_CENTER, "diameter": ((0, 0, 0), (1, 0, 0))},
        element_name=r"\lambda\,R\,d\phi",
    ),
    "disk": Shape(
        name="disk",
        coordinates=((r, 0, R), (phi, 0, 2 * sp.pi)),
        element=r,
        position=(r * sp.cos(phi), r * sp.sin(phi), 0),
        sizes={"radius": R},
        scale=R,
        axes={"symmetry": Z_THROUGH_CENTER, "diameter": ((0, 0, 0), (1, 0, 0))},
        element_name=r"\sigma\,r\,dr\,d\phi",
    ),
}

#: The axis about which a body of each shape turns in a planar scene (normal to the plane).
PLANAR_AXIS = {"rod": "center", "ring": "symmetry", "disk": "symmetry"}


@dataclass(frozen=True)
class InertiaResult:
    """The integral set up for a moment of inertia, the mass from the same density, and I."""

    shape: str
    axis: str
    integral: sp.Integral
    mass_integral: sp.Integral
    I: sp.Expr
    ratio: sp.Expr
    distance_from_center: sp.Expr

    def substitute(self, mass: sp.Expr, sizes: dict[str, sp.Expr]) -> sp.Expr:
        """I for a body of the given mass and sizes (by the size names of the shape)."""
        shape = SHAPES[self.shape]
        mapping = {M: mass, **{shape.sizes[name]: value for name, value in sizes.items()}}
        return self.I.xreplace(mapping)


def _squared_distance(position, axis) -> sp.Expr:
    """Squared distance of a point from the line through `axis[0]` along the unit `axis[1]`."""
    point, direction = (sp.Matrix(v) for v in axis)
    offset = sp.Matrix(position) - point
    along = offset.dot(direction)
    return sp.expand(offset.dot(offset) - along**2)


@lru_cache(maxsize=None)
def moment_of_inertia(shape_name: str, axis: str) -> InertiaResult:
    """Integrate rho * d^2 over the shape; rho is uniform, fixed by the total mass M.

    Cached by (shape, axis): a set of 300 variants integrates each body once.

    >>> moment_of_inertia("rod", "center").I
    L**2*M/12
    """
    shape = SHAPES[shape_name]
    if axis not in shape.axes:
        raise KeyError(axis)
    limits = [(c, lo, hi) for c, lo, hi in reversed(shape.coordinates)]
    measure = sp.integrate(shape.element, *limits)
    density = M / measure
    d2 = _squared_distance(shape.position, shape.axes[axis])
    integrand = density * d2 * shape.element
    inertia = sp.simplify(sp.integrate(integrand, *limits))
    center_point = sp.Matrix(shape.axes[axis][0])
    return InertiaResult(
        shape=shape_name,
        axis=axis,
        integral=sp.Integral(integrand, *limits),
        mass_integral=sp.Integral(density * shape.element, *limits),
        I=inertia,
        ratio=sp.simplify(inertia / (M * shape.scale**2)),
        distance_from_center=sp.sqrt(center_point.dot(center_point)),
    )


def parallel_axis(I_cm: sp.Expr, mass: sp.Expr, distance: sp.Expr) -> sp.Expr:
    """The parallel-axis theorem, I = I_cm + M d^2.

    >>> parallel_axis(M*L**2/12, M, L/2)
    L**2*M/3
    """
    return sp.expand(I_cm + mass * distance**2)


def central_moment(shape_name: str, mass: sp.Expr, sizes: dict[str, sp.Expr]) -> sp.Expr:
    """The moment of inertia of a body about the axis normal to the plane through its center."""
    if shape_name == "point":
        return sp.Integer(0)
    return moment_of_inertia(shape_name, PLANAR_AXIS[shape_name]).substitute(mass, sizes)
