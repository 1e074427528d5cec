r"""Bodies in 3D on the page: an oblique (cabinet) projection, and the solids, axes and vectors drawn in it.

The world's x runs to the right, z up the page and y into the page, drawn up and to the right at
45 degrees at half its length (the cabinet projection). The frontal plane, x and z, keeps its true
shape: a vector in it is drawn at its true direction and length, so the angle between two vectors
in it is the true angle. Each 3D figure (`derive.publishing.figure.solids`) turns its derivation's frame into
the world by a rotation (`Oblique.turn`, rows: the world's axes in the frame) chosen so that the
vectors it compares, omega and L, lie in the frontal plane where the physics allows.

>>> page((1, 0, 0)), page((0, 0, 1)), page((0, 2, 0))
((1.0, 0.0), (0.0, 1.0), (0.707107, 0.707107))
>>> view = Oblique(None, ((0, 0, 1), (1, 0, 0), (0, 1, 0)))  # the frame's z to the right
>>> view.world((0, 0, 2))
(2.0, 0.0, 0.0)
"""
from __future__ import annotations

import math

from derive.publishing.figure.canvas import _f, _pt

DEPTH = 0.5 * math.sqrt(0.5)  # y's run on the page along each of x and z, per unit


def page(point) -> tuple[float, float]:
    """A world point (cm) on the page: x + y/(2 sqrt 2) across, z + y/(2 sqrt 2) up."""
    x, y, z = point
    return (round(x + DEPTH * y, 6), round(z + DEPTH * y, 6))


def _unit(v):
    length = math.sqrt(sum(c * c for c in v))
    return tuple(c / length for c in v)


def _cross(u, v):
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def along(at, direction, length: float):
    """The world point `length` along `direction` from `at`."""
    return tuple(a + length * d for a, d in zip(at, direction))


class Oblique:
    """Draws on a `_Figure` in 3D: positions in world cm, directions in the derivation's frame turned
    by `turn` (three rows, the world's x, y, z in that frame's components)."""

    def __init__(self, fig, turn=((1, 0, 0), (0, 1, 0), (0, 0, 1))):
        self.fig = fig
        self.turn = turn

    def world(self, vector) -> tuple[float, float, float]:
        """A vector of the derivation's frame in world components."""
        return tuple(float(sum(r * c for r, c in zip(row, vector))) for row in self.turn)

    def line(self, a, b, style: str = "") -> None:
        self.fig.line(page(a), page(b), style)

    def dot(self, point, radius: float = 0.05) -> None:
        self.fig.dot(page(point), radius)

    def label(self, point, direction, text: str | None) -> None:
        """A label beside a world point, away from it along a world direction."""
        self.fig.label(page(point), _screen(direction), text)

    def arrow(self, at, direction, length: float, style: str, text: str | None = None,
              toward=None) -> tuple[float, float]:
        """An arrow from a world point along a world direction (any length: it is made `length` cm in
        3D, then projected), labelled at its tip (on the page side `toward`, if given); the arrow's
        run on the page."""
        start, end = page(at), page(along(at, _unit(direction), length))
        run = (end[0] - start[0], end[1] - start[1])
        self.fig.arrow(start, run, style, text, toward)
        return run

    def circle(self, center, normal, radius: float, style: str = "body", start=None, sweep: float = 360.0) -> None:
        """A circle of a world radius about a world normal (an arc of `sweep` degrees from `start`, a
        direction across the normal), as a smooth curve through its projected points."""
        normal = _unit(normal)
        if sweep == 360 and abs(abs(normal[1]) - 1) < 1e-12:  # in the page's true-shape plane
            self.fig.add(f"\\draw[{style}] {_pt(page(center))} circle ({_f(radius)});")
            return
        if start is None:
            start = _cross(normal, (0, 1, 0)) if abs(normal[1]) < 0.9 else _cross(normal, (1, 0, 0))
        u = _unit(start)
        v = _cross(normal, u)
        steps = max(4, round(sweep / 10))
        points = []
        for k in range(steps + (0 if sweep == 360 else 1)):
            angle = math.radians(sweep * k / steps)
            points.append(page(tuple(c + radius * (math.cos(angle) * a + math.sin(angle) * b)
                                     for c, a, b in zip(center, u, v))))
        kind = "smooth cycle" if sweep == 360 else "smooth"
        self.fig.add(f"\\draw[{style}] plot[{kind}] coordinates {{{' '.join(_pt(p) for p in points)}}};")

    def turning(self, center, axis, radius: float, text: str | None) -> None:
        """A curved arrow about a world axis (right-handed: the sense of a positive rate), labelled."""
        across = _cross(_unit(axis), (0, 1, 0)) if abs(_unit(axis)[1]) < 0.9 else (1, 0, 0)
        self.circle(center, axis, radius, "->, thick", start=across, sweep=300)
        self.label(along(center, _unit(across), radius + 0.1), _unit(across), text)

    def axes(self, center, axes, length: float = 0.9, names=("x'", "y'", "z'")) -> None:
        """A body's own axes (world unit vectors) from its center, thin, labelled."""
        for direction, name in zip(axes, names):
            self.arrow(center, direction, length, "->, thin, gray", f"$\\scriptstyle {name}$")

    def solid(self, body, center, axes, scale: float) -> None:
        """A body by its shape at a world point, its own x, y, z along `axes` (world unit vectors),
        `scale` cm per unit of its sizes: a rod a bar along x, round bodies their rims about z (a
        cylinder two and its sides), a cone from its base to its apex up z, a plate or box its edges,
        a sphere a shaded ball, a point a dot, a composite each part where it sits, joined by a light
        bar, any other body a disk about z."""
        _solid(self, body.shape, {k: self.fig.num(v, 1.0) * scale for k, v in body.sizes.items()}, center, axes,
               body.composite, scale)


def _screen(direction) -> tuple[float, float]:
    x, y = page(direction)
    return (x, y) if abs(x) + abs(y) > 1e-9 else (0.0, 1.0)


def _solid(view: Oblique, shape: str, sizes: dict, center, axes, composite, scale: float) -> None:
    x, y, z = axes
    fig = view.fig
    if shape == "composite":
        _composite(view, composite, center, axes, scale)
    elif shape == "point":
        view.dot(center, 0.09)
    elif shape == "rod":
        half = sizes.get("length", 2.0) / 2
        fig.bar(page(along(center, x, -half)), page(along(center, x, half)))
    elif shape in ("sphere", "spherical_shell", "thick_spherical_shell"):
        radius = sizes.get("radius", sizes.get("outer_radius", 1.0))
        fig.add(f"\\shade[ball color=gray!35] {_pt(page(center))} circle ({_f(radius)}); "
                f"\\draw {_pt(page(center))} circle ({_f(radius)});")
        view.circle(center, z, radius, "thin, gray")
    elif shape == "cone":
        radius, height = sizes.get("radius", 1.0), sizes.get("height", 2.0)
        base, apex = along(center, z, -height / 4), along(center, z, 3 * height / 4)
        view.circle(base, z, radius)
        for side in silhouette(base, z, radius, apex):
            view.line(side, apex)
    elif shape in ("plate", "box"):
        half = [sizes.get(k, 1.0) / 2 for k in ("side_a", "side_b", "side_c")]
        if shape == "plate":
            half[2] = 0.0
        corners = {(i, j, k): tuple(c + i * half[0] * a + j * half[1] * b + k * half[2] * d
                                    for c, a, b, d in zip(center, x, y, z))
                   for i in (-1, 1) for j in (-1, 1) for k in (-1, 1)}
        for corner in corners:  # each edge once, from its lower corner along one axis
            for n in range(3):
                if corner[n] == -1 and (shape == "box" or n < 2):
                    other = tuple(1 if m == n else corner[m] for m in range(3))
                    view.line(corners[corner], corners[other], "thick")
    else:  # round about z: a disk, ring, annulus, cylinder, shell or custom body
        radius = sizes.get("radius", sizes.get("outer_radius", 1.0))
        height = sizes.get("height", 0.0) if shape in ("cylinder", "cylindrical_shell") else 0.0
        style = "line width=1.8pt" if shape == "ring" else "body"
        rims = [along(center, z, -height / 2), along(center, z, height / 2)] if height else [center]
        for rim in rims:
            view.circle(rim, z, radius, style)
        if height:
            for low in silhouette(rims[0], z, radius, rims[1]):
                view.line(low, along(low, z, height))
        if "inner_radius" in sizes:
            view.circle(center, z, sizes["inner_radius"], "fill=white")


def silhouette(center, normal, radius: float, toward):
    """The two points of a circle's rim whose page directions to `toward` (a point off the circle's
    center along its normal) bound its outline: the rim points farthest either side of that line."""
    u = _cross(normal, (0, 1, 0)) if abs(_unit(normal)[1]) < 0.9 else _cross(normal, (1, 0, 0))
    u = _unit(u)
    v = _cross(_unit(normal), u)
    c, t = page(center), page(toward)
    line = (t[0] - c[0], t[1] - c[1])
    rim = [tuple(a + radius * (math.cos(math.radians(k)) * p + math.sin(math.radians(k)) * q)
                 for a, p, q in zip(center, u, v)) for k in range(0, 360, 2)]

    def side(point):
        at = page(point)
        return line[0] * (at[1] - c[1]) - line[1] * (at[0] - c[0])

    return max(rim, key=side), min(rim, key=side)


def _composite(view: Oblique, composite, center, axes, scale: float) -> None:
    """A composite's parts at their places about its center of mass (each part's own axes turned by
    its angle about z), the point masses joined by a light bar along x with arms across to them."""
    x, y, z = axes
    cx, cy = (view.fig.num(c, 0.0) for c in composite.center)
    points = []
    for shape, _, sizes, (px, py), angle in composite.parts.values():
        at = (view.fig.num(px, 0.0) - cx, view.fig.num(py, 0.0) - cy)
        where = tuple(c + scale * (at[0] * a + at[1] * b) for c, a, b in zip(center, x, y))
        turn = view.fig.num(angle, 0.0)
        own = (tuple(math.cos(turn) * a + math.sin(turn) * b for a, b in zip(x, y)),
               tuple(-math.sin(turn) * a + math.cos(turn) * b for a, b in zip(x, y)), z)
        if shape == "point":
            points.append((at, where))
        _solid(view, shape, {k: view.fig.num(v, 1.0) * scale for k, v in sizes.items()}, where, own, None, scale)
    if len(points) >= 2:
        along = [at[0] for at, _ in points]
        ends = [tuple(c + scale * s * a for c, a in zip(center, x)) for s in (min(along), max(along))]
        view.line(ends[0], ends[1], "line width=1.2pt, gray!60!black")
        for at, where in points:
            view.line(tuple(c + scale * at[0] * a for c, a in zip(center, x)), where, "line width=1.2pt, gray!60!black")

