"""Moments of inertia and inertia tensors by integration, and the parallel-axis theorem.

Every moment of inertia in the project comes from here: a shape is described by
its natural coordinates, their limits, the volume (or length, or area) element
and the Cartesian position of a mass element; the moment about an axis is the
integral of rho * (distance to the axis)^2 over the shape. Without a density,
rho = M / measure is uniform, fixed by the same integral of 1; a density may also
be given, as an expression in the shape's coordinates (`COORDINATE_SYMBOLS`).

>>> result = moment_of_inertia("rod", "end")
>>> result.I
L**2*M/3
>>> moment_of_inertia("disk", "symmetry").ratio
1/2
>>> moment_of_inertia("disk", "symmetry", density=(r / R)**2).ratio
2/3
>>> tensor("box")
Matrix([
[M*(b**2 + c**2)/12,                  0,                  0],
[                 0, M*(a**2 + c**2)/12,                  0],
[                 0,                  0, M*(a**2 + b**2)/12]])
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import mpmath
import sympy as sp

from derive.core import limits
from derive.core.errors import InputError

# The generic symbols a shape is integrated with; a body substitutes its own.
M, L, R, R1, R2, h, a, b, c = sp.symbols("M L R R1 R2 h a b c", positive=True)
x, y, z = sp.symbols("x y z", real=True)
r = sp.Symbol("r", nonnegative=True)
phi, theta = sp.symbols("phi theta", real=True)

#: The coordinates a density may be written in (each shape accepts its own and x, y, z).
COORDINATE_SYMBOLS = {"x": x, "y": y, "z": z, "r": r, "phi": phi, "theta": theta}

Vector = tuple[sp.Expr, sp.Expr, sp.Expr]


@dataclass(frozen=True)
class Shape:
    """A body shape: coordinates with limits, the measure element, element positions.

    `coordinates` run from the outermost integral to the innermost (inner limits may
    depend on outer coordinates); `position` is the Cartesian position (x, y, z) of the
    mass element, with the center of mass at the origin; `sizes` maps the size names a
    problem uses (length, radius) to the generic symbols above; `scale` is the size the
    ratio I/(M scale^2) refers to; `axes` maps axis names to (point on the axis, unit
    direction).
    """

    name: str
    coordinates: tuple[tuple[sp.Symbol, sp.Expr, sp.Expr], ...]
    element: sp.Expr
    position: Vector
    sizes: dict[str, sp.Symbol]
    scale: sp.Expr
    axes: dict[str, tuple[Vector, Vector]]

    @property
    def density_symbols(self) -> dict[str, sp.Symbol]:
        """The coordinates a density on this shape may use: its own, and Cartesian x, y, z.

        >>> list(SHAPES["disk"].density_symbols)
        ['r', 'phi', 'x', 'y', 'z']
        """
        names = [str(coordinate) for coordinate, _, _ in self.coordinates] + ["x", "y", "z"]
        return {name: COORDINATE_SYMBOLS[name] for name in names}


ORIGIN = (0, 0, 0)
X_AXIS, Y_AXIS, Z_AXIS = (1, 0, 0), (0, 1, 0), (0, 0, 1)
AROUND = (phi, 0, 2 * sp.pi)
ROUND = {"symmetry": (ORIGIN, Z_AXIS), "diameter": (ORIGIN, X_AXIS)}
SPHERICAL = (sp.sin(theta) * sp.cos(phi), sp.sin(theta) * sp.sin(phi), sp.cos(theta))


def _limits(coordinates) -> list[tuple]:
    """Limits in the order sympy integrates them: the innermost first."""
    return list(reversed(coordinates))


def _cone() -> Shape:
    """A solid cone along z, base radius R, height h, moved so its center of mass is the origin."""
    base_at_zero = ((z, 0, h), (r, 0, R * (1 - z / h)), AROUND)
    z_cm = sp.integrate(z * r, *_limits(base_at_zero)) / sp.integrate(r, *_limits(base_at_zero))  # h/4

    def moved(limit):  # the old z is the new z + z_cm
        return sp.simplify(sp.sympify(limit).subs(z, z + z_cm))  # safe: the module's own limits, not text

    coordinates = tuple((v, lo - z_cm, hi - z_cm) if v == z else (v, moved(lo), moved(hi))
                        for v, lo, hi in base_at_zero)
    return Shape("cone", coordinates, r, (r * sp.cos(phi), r * sp.sin(phi), z), {"radius": R, "height": h}, R, ROUND)


SHAPES: dict[str, Shape] = {shape.name: shape for shape in (
    Shape("point", (), sp.Integer(1), ORIGIN, {}, sp.Integer(1), {"center": (ORIGIN, Z_AXIS)}),
    Shape("rod", ((x, -L / 2, L / 2),), sp.Integer(1), (x, 0, 0), {"length": L}, L,
          {"center": (ORIGIN, Z_AXIS), "end": ((-L / 2, 0, 0), Z_AXIS)}),
    Shape("ring", (AROUND,), R, (R * sp.cos(phi), R * sp.sin(phi), 0), {"radius": R}, R, ROUND),
    Shape("disk", ((r, 0, R), AROUND), r, (r * sp.cos(phi), r * sp.sin(phi), 0), {"radius": R}, R, ROUND),
    Shape("annulus", ((r, R1, R2), AROUND), r, (r * sp.cos(phi), r * sp.sin(phi), 0),
          {"inner_radius": R1, "outer_radius": R2}, R2, ROUND),
    Shape("cylinder", ((z, -h / 2, h / 2), (r, 0, R), AROUND), r, (r * sp.cos(phi), r * sp.sin(phi), z),
          {"radius": R, "height": h}, R, ROUND),
    Shape("cylindrical_shell", ((z, -h / 2, h / 2), AROUND), R, (R * sp.cos(phi), R * sp.sin(phi), z),
          {"radius": R, "height": h}, R, ROUND),
    Shape("sphere", ((r, 0, R), (theta, 0, sp.pi), AROUND), r**2 * sp.sin(theta), tuple(r * u for u in SPHERICAL),
          {"radius": R}, R, {"symmetry": (ORIGIN, Z_AXIS)}),
    Shape("spherical_shell", ((theta, 0, sp.pi), AROUND), R**2 * sp.sin(theta), tuple(R * u for u in SPHERICAL),
          {"radius": R}, R, {"symmetry": (ORIGIN, Z_AXIS)}),
    Shape("thick_spherical_shell", ((r, R1, R2), (theta, 0, sp.pi), AROUND), r**2 * sp.sin(theta),
          tuple(r * u for u in SPHERICAL), {"inner_radius": R1, "outer_radius": R2}, R2,
          {"symmetry": (ORIGIN, Z_AXIS)}),
    Shape("plate", ((x, -a / 2, a / 2), (y, -b / 2, b / 2)), sp.Integer(1), (x, y, 0),
          {"side_a": a, "side_b": b}, a, {"symmetry": (ORIGIN, Z_AXIS), "a": (ORIGIN, X_AXIS), "b": (ORIGIN, Y_AXIS)}),
    Shape("box", ((x, -a / 2, a / 2), (y, -b / 2, b / 2), (z, -c / 2, c / 2)), sp.Integer(1), (x, y, z),
          {"side_a": a, "side_b": b, "side_c": c}, a,
          {"symmetry": (ORIGIN, Z_AXIS), "a": (ORIGIN, X_AXIS), "b": (ORIGIN, Y_AXIS), "c": (ORIGIN, Z_AXIS)}),
    _cone(),
)}

#: The axis about which a body of each shape turns in a planar scene (normal to the plane).
PLANAR_AXIS = {"point": "center", "rod": "center", "ring": "symmetry", "disk": "symmetry", "annulus": "symmetry",
               "cylinder": "symmetry", "cylindrical_shell": "symmetry", "sphere": "symmetry",
               "spherical_shell": "symmetry", "thick_spherical_shell": "symmetry", "plate": "symmetry",
               "box": "symmetry", "cone": "symmetry"}


@dataclass(frozen=True)
class InertiaResult:
    """The integral set up for a moment of inertia, the mass from the same density, and I.

    `axis` is the axis name, or (point, unit direction) for an axis given by direction;
    `distance_from_center` is the distance of the axis from the center of mass.
    """

    shape: str
    axis: str | tuple[Vector, Vector]
    integral: sp.Expr
    mass_integral: sp.Expr
    mass: sp.Expr
    I: sp.Expr
    ratio: sp.Expr
    distance_from_center: sp.Expr

    def substitute(self, mass: sp.Expr, sizes: dict[str, sp.Expr]) -> sp.Expr:
        """I for a body of the given mass and sizes (by the size names of the shape).

        >>> moment_of_inertia("rod", "end").substitute(2, {"length": 3})
        6
        """
        shape = SHAPES[self.shape]
        mapping = {M: mass, **{shape.sizes[name]: value for name, value in sizes.items()}}
        return self.I.xreplace(mapping)


def _shape(name: str) -> Shape:
    if name not in SHAPES:
        raise InputError(f"unknown shape {name!r} (shapes: {', '.join(SHAPES)})")
    return SHAPES[name]


def _exact(value, what: str) -> sp.Expr:
    """A sympy object from a number or an expression; text is refused, never parsed."""
    try:
        return sp.sympify(value, strict=True)  # safe: strict=True refuses text (tested: it is never parsed)
    except sp.SympifyError:
        raise InputError(f"{what}: expected a number or a sympy expression, got {value!r}") from None


def _vector(values, what: str) -> Vector:
    values = tuple(values)
    if len(values) != 3:
        raise InputError(f"{what}: a vector has 3 components, got {len(values)}")
    return tuple(_exact(v, what) for v in values)


def _axis(shape: Shape, axis) -> str | tuple[Vector, Vector]:
    """An axis name of the shape, or (point, direction) with the direction made a unit vector."""
    if isinstance(axis, str):
        if axis not in shape.axes:
            raise InputError(f"axis: a {shape.name} has axes {', '.join(shape.axes)} (or give (point, direction))")
        return axis
    point, direction = axis
    point, direction = _vector(point, "axis point"), sp.Matrix(_vector(direction, "axis direction"))
    length = sp.sqrt(sp.simplify(direction.dot(direction)))
    if length.is_zero:
        raise InputError("axis direction: the zero vector has no direction")
    return point, tuple(sp.simplify(direction / length))


def _squared_distance(position, axis) -> sp.Expr:
    """Squared distance of a point from the line through `axis[0]` along the unit `axis[1]`."""
    point, direction = (sp.Matrix(v) for v in axis)
    offset = sp.Matrix(position) - point
    along = offset.dot(direction)
    return sp.factor(sp.trigsimp(sp.expand(offset.dot(offset) - along**2)))


def _integral(integrand: sp.Expr, shape: Shape) -> sp.Expr:
    """The integral over the shape, unevaluated; a point mass has nothing to integrate over."""
    return sp.Integral(integrand, *_limits(shape.coordinates)) if shape.coordinates else integrand


def _integrate(integrand: sp.Expr, shape: Shape) -> sp.Expr:
    """The integral over the shape, simplified; refused when sympy finds no closed form."""
    # (r/R)**k as R**-k * r**k where valid: sympy integrates a power of one symbol much faster
    with limits.time_limit(f"integrating over the {shape.name}",
                           faster="a density that is a polynomial in the shape's coordinates (sympy integrates one at once)"):
        value = _integral(sp.powsimp(sp.expand_power_base(integrand)), shape).doit()
    if value.has(sp.Integral):
        raise InputError(f"sympy finds no closed form for the integral of {integrand} over the {shape.name}")
    with limits.time_limit(f"simplifying the integral over the {shape.name}"):
        return sp.simplify(value)


def _check_density(shape: Shape, rho: sp.Expr) -> None:
    """Refuse a density that is negative somewhere on the shape (sizes and parameters positive).

    Sympy tries to prove rho >= 0; failing that, rho is evaluated on a grid of the
    coordinates for a few values of the parameters.
    """
    coordinates = [coordinate for coordinate, _, _ in shape.coordinates]
    others = rho.free_symbols - set(coordinates)
    if rho.xreplace({s: sp.Dummy(s.name, positive=True) for s in others}).is_nonnegative:
        return
    sizes = {s: i + 1 for i, s in enumerate(shape.sizes.values())}  # 1, 2: an inner radius below the outer
    parameters = others - set(sizes)
    fractions = [sp.Rational(k, 4) for k in range(5)]
    for value in (sp.Rational(1, 3), 1, 3):
        points = [{**sizes, **{p: value for p in parameters}}]
        for coordinate, lo, hi in shape.coordinates:
            points = [{**p, coordinate: sp.sympify(lo + t * (hi - lo)).xreplace(p)}  # safe: numbers, not text
                      for p in points for t in fractions]
        for point in points:
            if rho.xreplace(point).evalf().is_extended_negative:
                where = ", ".join(f"{s}={v}" for s, v in point.items())
                raise InputError(f"density {rho} is negative on the {shape.name} (at {where})")


@lru_cache(maxsize=None)
def _distribution(shape_name: str, density: sp.Expr | None, check: bool = True) -> tuple[sp.Expr, sp.Expr]:
    """(rho in the shape's own coordinates, total mass): uniform of mass M, or from `density`; its sign
    checked here (`check`) for `derive inertia`, or over a problem's ranges by its reader (body_file)."""
    shape = SHAPES[shape_name]
    if density is None:
        return M / _integrate(shape.element, shape), M
    allowed = shape.density_symbols
    stray = sorted(s.name for s in density.free_symbols if s.name in COORDINATE_SYMBOLS and allowed.get(s.name) != s)
    if stray:
        raise InputError(f"density: {', '.join(stray)} is not one of the {shape_name}'s coordinates "
                         f"{', '.join(allowed)} (derive.model.inertia.COORDINATE_SYMBOLS)")
    rho = density.xreplace(dict(zip((x, y, z), shape.position)))
    if check:
        _check_density(shape, rho)
    mass = _integrate(rho * shape.element, shape)
    if mass.is_zero:
        raise InputError(f"density {density} gives the {shape_name} no mass")
    return rho, mass


def _density(density) -> sp.Expr | None:
    return None if density is None else _exact(density, "density")


def moment_of_inertia(shape_name: str, axis, density=None) -> InertiaResult:
    """Integrate rho * d^2 over the shape: rho uniform with total mass M, or `density`.

    `axis` is an axis name of the shape or (point, direction). `density` is an
    expression in the shape's coordinates (`Shape.density_symbols`) and any parameters;
    the mass is then its integral. Cached by (shape, axis, density): a set of 300
    variants integrates each body once.

    >>> moment_of_inertia("rod", "center").I
    L**2*M/12
    >>> moment_of_inertia("cylinder", ((0, 0, h / 2), (1, 0, 0))).I
    M*(3*R**2 + 4*h**2)/12
    """
    shape = _shape(shape_name)
    return _moment(shape_name, _axis(shape, axis), _density(density))


@lru_cache(maxsize=None)
def _moment(shape_name: str, axis, density: sp.Expr | None, check: bool = True) -> InertiaResult:
    shape = SHAPES[shape_name]
    line = shape.axes[axis] if isinstance(axis, str) else axis
    rho, mass = _distribution(shape_name, density, check)
    integrand = rho * _squared_distance(shape.position, line) * shape.element
    inertia = _integrate(integrand, shape)
    return InertiaResult(
        shape=shape_name,
        axis=axis,
        integral=_integral(integrand, shape),
        mass_integral=_integral(rho * shape.element, shape),
        mass=mass,
        I=inertia,
        ratio=sp.simplify(inertia / (mass * shape.scale**2)),
        distance_from_center=sp.sqrt(_squared_distance(_center_of_mass(shape_name, density, check), line)),
    )


def center_of_mass(shape_name: str, density=None) -> Vector:
    """The center of mass: the origin for a uniform shape, elsewhere for some densities.

    >>> center_of_mass("disk", density=1 + x / R)
    (R/4, 0, 0)
    """
    _shape(shape_name)
    return _center_of_mass(shape_name, _density(density))


@lru_cache(maxsize=None)
def _center_of_mass(shape_name: str, density: sp.Expr | None, check: bool = True) -> Vector:
    shape = SHAPES[shape_name]
    rho, mass = _distribution(shape_name, density, check)
    return tuple(_integrate(rho * u * shape.element, shape) / mass for u in shape.position)


def tensor(shape_name: str, about=ORIGIN, density=None) -> sp.ImmutableMatrix:
    """The inertia tensor about a point: the integral of rho (|s|^2 1 - s s^T), s = position - about.

    The moment about an axis through that point along the unit n is n^T I n.

    >>> tensor("rod", about=(-L / 2, 0, 0))
    Matrix([
    [0,        0,        0],
    [0, L**2*M/3,        0],
    [0,        0, L**2*M/3]])
    """
    _shape(shape_name)
    return _tensor(shape_name, _vector(about, "about"), _density(density))


@lru_cache(maxsize=None)
def _tensor(shape_name: str, about: Vector, density: sp.Expr | None, check: bool = True) -> sp.ImmutableMatrix:
    shape = SHAPES[shape_name]
    rho, _ = _distribution(shape_name, density, check)
    s = sp.Matrix(shape.position) - sp.Matrix(about)
    integrand = rho * shape.element * (s.dot(s) * sp.eye(3) - s * s.T)
    upper = {(i, j): _integrate(sp.expand(integrand[i, j]), shape) for i in range(3) for j in range(i, 3)}
    return sp.ImmutableMatrix(3, 3, lambda i, j: upper[min(i, j), max(i, j)])


def parallel_axis(I_cm: sp.Expr, mass: sp.Expr, distance: sp.Expr) -> sp.Expr:
    """The parallel-axis theorem, I = I_cm + M d^2.

    >>> parallel_axis(M*L**2/12, M, L/2)
    L**2*M/3
    """
    return sp.expand(I_cm + mass * distance**2)


def parallel_axis_tensor(I_cm: sp.Matrix, mass: sp.Expr, d_vector) -> sp.ImmutableMatrix:
    """The tensor form: I_P = I_cm + M (d.d 1 - d d^T), d from the center of mass to P.

    >>> parallel_axis_tensor(sp.zeros(3), M, (0, 0, h))[0, 0]
    M*h**2
    """
    d = sp.Matrix(_vector(d_vector, "d_vector"))
    return sp.ImmutableMatrix(sp.Matrix(I_cm) + mass * (d.dot(d) * sp.eye(3) - d * d.T))


def principal(inertia_tensor: sp.Matrix) -> tuple[tuple[sp.Expr, ...], tuple[sp.Matrix, ...]]:
    """Principal moments and orthonormal principal axes (columns) of a symmetric tensor.

    Symbolic when the characteristic polynomial factors; otherwise, for a tensor without
    symbols, numeric (mpmath, 30 digits).

    >>> principal(sp.diag(M, 2*M, 2*M))[0]
    (M, 2*M, 2*M)
    """
    matrix = sp.Matrix(inertia_tensor)
    roots = sp.roots(matrix.charpoly(), cubics=False)
    if sum(roots.values()) == 3:
        moments, axes = [], []
        for value, multiplicity in roots.items():
            space = (matrix - value * sp.eye(3)).nullspace(simplify=True)
            moments += [sp.simplify(value)] * multiplicity
            axes += [sp.simplify(v) for v in sp.GramSchmidt(space, orthonormal=True)]
        return tuple(moments), tuple(axes)
    if matrix.free_symbols:
        raise InputError("principal: the characteristic polynomial does not factor; give the symbols values")
    with mpmath.workdps(30):
        values, vectors = mpmath.eigsy(mpmath.matrix(matrix.evalf(40).tolist()))
        return (tuple(sp.Float(v, 30) for v in values),
                tuple(sp.Matrix([sp.Float(vectors[i, k], 30) for i in range(3)]) for k in range(3)))


@dataclass(frozen=True)
class Part:
    """A uniform part of a composite body: its shape, mass and sizes (by the shape's size
    names), the position of its center of mass, and its orientation (a rotation matrix
    taking the part's own frame to the body's; None for unturned)."""

    shape: str
    mass: sp.Expr
    sizes: dict[str, sp.Expr]
    offset: Vector
    rotation: sp.Matrix | None = None


@dataclass(frozen=True)
class Composite:
    """Total mass, center of mass and inertia tensor (about the point asked) of a composite."""

    mass: sp.Expr
    center: sp.Matrix
    tensor: sp.ImmutableMatrix


def _part_tensor(part: Part) -> sp.Matrix:
    """A part's tensor about its own center of mass, in the body's frame: R I R^T."""
    shape = _shape(part.shape)
    mass = _exact(part.mass, f"{part.shape} mass")
    if mass.is_negative:
        raise InputError(f"{part.shape} mass: a mass cannot be negative ({mass})")
    if set(part.sizes) != set(shape.sizes):
        raise InputError(f"{part.shape} sizes: a {part.shape} needs {', '.join(shape.sizes) or 'no sizes'}")
    mapping = {M: mass}
    for name, value in part.sizes.items():
        mapping[shape.sizes[name]] = _exact(value, f"{part.shape} {name}")
        if mapping[shape.sizes[name]].is_positive is False:
            raise InputError(f"{part.shape} {name}: must be positive, got {value}")
    turn = sp.eye(3) if part.rotation is None else sp.Matrix(part.rotation)
    if turn.shape != (3, 3) or sp.simplify(turn * turn.T - sp.eye(3)) != sp.zeros(3):
        raise InputError(f"{part.shape} rotation: not a rotation matrix")
    return turn * tensor(part.shape).xreplace(mapping) * turn.T


def composite_tensor(parts: list[Part], about=None) -> Composite:
    """Mass, center of mass and inertia tensor of parts, about a point (None: the center of mass).

    Each part's tensor about its own center, turned into the body's frame, is moved to
    the point by the tensor parallel-axis theorem.

    >>> m, l = sp.symbols("m l", positive=True)
    >>> ends = [Part("point", m, {}, (s * l / 2, 0, 0)) for s in (-1, 1)]
    >>> composite_tensor(ends).tensor[2, 2]
    l**2*m/2
    """
    if not parts:
        raise InputError("composite: no parts")
    masses = [_exact(p.mass, f"{p.shape} mass") for p in parts]
    offsets = [sp.Matrix(_vector(p.offset, f"{p.shape} offset")) for p in parts]
    mass = sp.Add(*masses)
    if mass.is_zero:
        raise InputError("composite: the parts have no mass")
    center = sp.simplify(sum((m * o for m, o in zip(masses, offsets)), sp.zeros(3, 1)) / mass)
    point = center if about is None else sp.Matrix(_vector(about, "about"))
    total = sum((parallel_axis_tensor(_part_tensor(p), m, o - point) for p, m, o in zip(parts, masses, offsets)),
                sp.zeros(3))
    return Composite(mass, center, sp.ImmutableMatrix(sp.simplify(total)))


def central_moment(shape_name: str, mass: sp.Expr, sizes: dict[str, sp.Expr]) -> sp.Expr:
    """The moment of inertia of a body about the axis normal to the plane through its center.

    >>> central_moment("point", M, {})
    0
    """
    return moment_of_inertia(shape_name, PLANAR_AXIS[shape_name]).substitute(mass, sizes)


def _shielded(shape: Shape, sizes: dict[str, sp.Expr], *exprs) -> dict[sp.Symbol, sp.Dummy]:
    """Dummies for the symbols of a body's own expressions (its density, an offset) that happen to be
    this module's generic ones (R, M, ...) without standing for the same size: kept apart from them
    during the integration. A body's size that is the generic symbol itself (a rod's length L, and L
    in its density) is that size, and not kept apart: (x + L/2)/L is the rod's own L."""
    same = {shape.sizes[name] for name, value in sizes.items() if value == shape.sizes[name]}
    generic = {M, *shape.sizes.values()} - same
    found = set().union(*(sp.sympify(e, strict=True).free_symbols  # safe: parsed sympy or the table's ints; no text
                          for e in exprs if e is not None))
    return {s: sp.Dummy(s.name, **s.assumptions0) for s in found if s in generic}


def body_moment(shape_name: str, axis, mass: sp.Expr | None, sizes: dict[str, sp.Expr],
                density: sp.Expr | None = None, route: str = "integral", offset: Vector | None = None,
                direction: Vector | None = None) -> tuple[sp.Expr, sp.Expr]:
    """(mass, moment of inertia) of a body of this shape and sizes about a named axis, or about
    (point, direction) in the shape's frame, or along `direction` through its center of mass (in the
    body's own symbols: a plate's diagonal [a, b, 0]), moved by `offset` (a vector in the body's own symbols).

    Uniform with the given mass; or with a `density` in the shape's coordinates: a profile
    scaled to the given mass, or, with mass None, an absolute density whose integral is the
    mass (`_shielded` says which of its symbols are the body's sizes). `route="tensor"` takes
    n^T I n from the inertia tensor about a point of the axis instead of integrating d^2: a
    second route. The density's sign is not checked here: a problem's reader proves it over the
    ranges the file declares (derive.language.body_file), which `_check_density` cannot know.

    >>> body_moment("disk", "symmetry", None, {"radius": 2}, sp.Symbol("sigma", positive=True))
    (4*pi*sigma, 8*pi*sigma)
    >>> body_moment("rod", "center", M, {"length": L}, (x + L / 2) / L, offset=(L / 2, 0, 0))[1]
    L**2*M/6
    >>> w, h = sp.symbols("w h", positive=True)
    >>> body_moment("plate", None, M, {"side_a": w, "side_b": h}, direction=(w, h, 0))[1]
    M*h**2*w**2/(6*(h**2 + w**2))
    """
    shape = _shape(shape_name)
    if direction is not None:  # along `direction` (the body's own symbols) through its center of mass
        center = body_center(shape_name, sizes, density)
        axis, offset = (ORIGIN, direction), tuple(c + o for c, o in zip(center, offset or ORIGIN))
    shield = _shielded(shape, sizes, density, *(offset or ()), *(direction or ()))
    if direction is not None:
        axis = (ORIGIN, tuple(sp.sympify(d, strict=True).xreplace(shield) for d in direction))  # safe: parsed sympy
    shielded = None if density is None else density.xreplace(shield)
    if offset is not None:
        point, direction = shape.axes[axis] if isinstance(axis, str) else axis
        axis = (tuple(sp.sympify(p, strict=True) + sp.sympify(o, strict=True).xreplace(shield)  # safe: no text
                      for p, o in zip(point, offset)), direction)  # the shape table's coordinates, a parsed offset
    result = _moment(shape_name, _axis(shape, axis), shielded, False)  # its sign proven by the reader, over the ranges
    moment = result.I
    if route == "tensor":
        point, direction = shape.axes[axis] if isinstance(axis, str) else axis
        n = sp.Matrix(direction) / sp.Matrix(direction).norm()
        moment = sp.simplify((n.T * _tensor(shape_name, _vector(point, "about"), shielded, False) * n)[0, 0])
    mapping = {shape.sizes[name]: value for name, value in sizes.items()}
    restore = {d: s for s, d in shield.items()}
    integrated_mass = result.mass.xreplace(mapping).xreplace(restore)
    moment = moment.xreplace(mapping).xreplace(restore)
    if density is None:
        return mass, moment.xreplace({M: mass})
    if mass is None:
        return integrated_mass, moment
    return mass, sp.simplify(mass * moment / integrated_mass)


def body_center(shape_name: str, sizes: dict[str, sp.Expr], density: sp.Expr | None = None) -> Vector:
    """A body's center of mass in its shape's frame, in the body's own symbols.

    >>> body_center("rod", {"length": L}, (x + L / 2) / L)
    (L/6, 0, 0)
    """
    shape = _shape(shape_name)
    shield = _shielded(shape, sizes, density)
    mapping = {shape.sizes[name]: value for name, value in sizes.items()}
    restore = {d: s for s, d in shield.items()}
    center = _center_of_mass(shape_name, None if density is None else density.xreplace(shield), False)
    return tuple(sp.simplify(c.xreplace(mapping).xreplace(restore)) for c in center)


def central_body_moment(shape_name: str, axis: str, mass: sp.Expr | None, sizes: dict[str, sp.Expr],
                        density: sp.Expr | None = None) -> tuple[sp.Expr, sp.Expr]:
    """(mass, moment) about the axis parallel to the named one through the body's center of mass,
    integrated there: the I_cm of the parallel-axis theorem (the named axis itself where the center
    of mass lies on it; a rod denser at one end has its center of mass off its middle).

    >>> central_body_moment("rod", "center", M, {"length": L}, (x + L / 2) / L)[1]
    L**2*M/18
    """
    center = body_center(shape_name, sizes, density)
    if all(c == 0 for c in center):
        return body_moment(shape_name, axis, mass, sizes, density)
    direction = _shape(shape_name).axes[axis][1]
    return body_moment(shape_name, (ORIGIN, direction), mass, sizes, density, offset=center)


def off_axis(shape_name: str, axis: str, sizes: dict[str, sp.Expr], density: sp.Expr | None,
             offset: Vector = (0, 0, 0)) -> sp.Expr:
    """The squared distance from a body's center of mass to its named axis moved by `offset` (a
    vector in the body's own symbols): zero where the axis passes through it.

    >>> off_axis("rod", "center", {"length": L}, (x + L / 2) / L), off_axis("rod", "end", {"length": L}, None)
    (L**2/36, L**2/4)
    """
    shape = _shape(shape_name)
    point, direction = shape.axes[axis]
    generic = {shape.sizes[name]: value for name, value in sizes.items()}
    apart = sp.Matrix([sp.sympify(c, strict=True).xreplace(generic) + o  # safe: the shape table's, never text
                       for c, o in zip(point, offset)]) - \
        sp.Matrix(body_center(shape_name, sizes, density))
    n = sp.Matrix(direction) / sp.Matrix(direction).norm()
    return sp.simplify(apart.dot(apart) - apart.dot(n) ** 2)


def across(direction: Vector) -> Vector:
    """The direction a distance from an axis is measured along where none is given: the first of x,
    y, z square to the axis (along a rod for an axis normal to the page).

    >>> across((0, 0, 1)), across((1, 0, 0))
    ((1, 0, 0), (0, 1, 0))
    """
    return next(e for e in ((1, 0, 0), (0, 1, 0), (0, 0, 1)) if sp.Matrix(e).dot(sp.Matrix(direction)) == 0)
