"""Bodies on their own (an inertia question): side by side, with their sizes and the asked axes."""
from __future__ import annotations

import math

import sympy as sp

from derive.model import inertia
from derive.publishing.figure.canvas import ASPECT, WIDTH, _add, _clamp, _f, _Figure, _label_mass, _pt, _unit
from derive.text.latex import tex_escape
from derive.model.scene import Body


def _specimens(fig: _Figure) -> None:
    """Bodies on their own (an inertia question): side by side, with their sizes and the asked axes."""
    bodies = list(fig.scene.bodies.values())
    slot = WIDTH / len(bodies)
    for k, body in enumerate(bodies):
        center = (slot * (k + 0.5), 0.0)
        if body.shape in ("cylinder", "cylindrical_shell") and fig.tex(body.sizes.get("height")):
            _cylinder_side(fig, body, center)
        else:
            _specimen(fig, body, center, slot)
        if len(bodies) > 1:
            fig.label((center[0], -1.45), (0, -1), f"\\scriptsize {tex_escape(body.name)}")


def _asked_axes(fig: _Figure, body: Body):
    """(point, direction, shift) of each inertia ask about this body, in the shape's frame (metres)."""
    for ask in fig.problem.asks.values():
        q = ask.quantity
        if q.kind == "inertia" and q.target == body.name and body.shape in inertia.SHAPES:
            shape = inertia.SHAPES[body.shape]
            if isinstance(q.detail, tuple):  # a direction through the center of mass, drawn in the page's plane
                dx, dy = (fig.num(c, 0) for c in q.detail[:2])
                if body.shape in ("plate", "box"):  # as drawn: a diagonal through the drawn corners
                    dx, dy = dx / fig.size(body, "side_a", 1), dy * ASPECT / fig.size(body, "side_b", 1)
                size = math.hypot(dx, dy)
                yield (0.0, 0.0), ((dx / size, dy / size, 0) if size else (0, 0, 1)), ask.shift
                continue
            axis = q.detail or inertia.PLANAR_AXIS[body.shape]
            point, direction = shape.axes[axis]
            generic = {shape.sizes[n]: body.sizes[n] for n in shape.sizes if n in body.sizes}
            coordinates = [sp.sympify(c, strict=True) for c in point]  # safe: the shape table's, never text
            yield (tuple(fig.num(c.subs(generic), 0) for c in coordinates), direction, ask.shift)


def _specimen(fig: _Figure, body: Body, center, slot: float) -> None:
    if body.shape == "rod":
        half = min(2.6, slot / 2 - 0.3)
        fig.body(body, center, half)
        fig.dimension(_add(center, (-half, 0)), _add(center, (half, 0)), fig.tex(body.sizes.get("length")), side=-1,
                      gap=0.35)
        scale = half / (fig.size(body, "length", 1) / 2 or 1)
    else:
        half = min(1.0, slot / 2 - 0.25)
        fig.body(body, center, half)
        scale = half / (fig.size(body, "radius", fig.size(body, "outer_radius", 1)) or 1)
        size = body.sizes.get("radius", body.sizes.get("outer_radius"))
        if fig.tex(size):
            fig.line(center, _add(center, _unit(35), half), "thin")
            fig.label(_add(center, _unit(35), half * 0.5), (-0.5, 1), fig.m(size))
    if body.shape == "rod":
        _label_mass(fig, body, _add(center, (-half / 2, 0.12)), (0, 1))
    else:
        _label_mass(fig, body, _add(center, (0, -0.12)), (0, -1))
    for point, direction, shift in _asked_axes(fig, body):
        where = _add(center, (point[0] * scale, point[1] * scale))
        if shift is not None:  # moved as derive.quantities.moment_of_inertia.shift_vector does, to scale up to a clamp
            vector = shift if isinstance(shift, tuple) else tuple(shift * e for e in inertia.across(direction))
            dx, dy = fig.num(vector[0], 0), fig.num(vector[1], 0)
            reach = _clamp(math.hypot(dx, dy) * scale, 0.4, half + 0.6) / (math.hypot(dx, dy) or 1)
            moved = _add(where, (dx * reach, dy * reach))
            distance = shift if not isinstance(shift, tuple) else sp.sqrt(vector[0] ** 2 + vector[1] ** 2)
            fig.dimension(where, moved, fig.tex(distance), side=1, gap=0.45)
            where = moved
        if tuple(direction) == (0, 0, 1):
            fig.out_of_page(where)
        else:
            d = (direction[0], direction[1])
            fig.add(f"\\draw[axis] {_pt(_add(where, d, -half - 0.4))} -- {_pt(_add(where, d, half + 0.4))};")


def _cylinder_side(fig: _Figure, body: Body, center) -> None:
    """A cylinder in perspective, its axis vertical: radius, height and the asked axes."""
    radius = 1.0
    height = _clamp(fig.size(body, "height", 1) / (fig.size(body, "radius", 1) or 1) * radius, 0.8, 2.6)
    top, bottom = _add(center, (0, height / 2)), _add(center, (0, -height / 2))
    fill = "fill=gray!15" if body.shape == "cylinder" else "fill=white"
    fig.add(f"\\draw[{fill}] {_pt(_add(bottom, (-radius, 0)))} -- {_pt(_add(top, (-radius, 0)))} "
            f"arc[start angle=180, end angle=360, x radius={_f(radius)}, y radius=0.3] -- "
            f"{_pt(_add(bottom, (radius, 0)))} arc[start angle=0, end angle=-180, x radius={_f(radius)}, y radius=0.3];")
    fig.add(f"\\draw[{fill}] {_pt(top)} ellipse ({_f(radius)} and 0.3);")
    fig.add(f"\\draw[dashed, gray] {_pt(_add(bottom, (radius, 0)))} arc[start angle=0, end angle=180, "
            f"x radius={_f(radius)}, y radius=0.3];")
    fig.line(top, _add(top, (radius, 0)), "thin")
    fig.label(_add(top, (radius / 2, -0.02)), (0, -1), fig.m(body.sizes['radius'])
              if fig.tex(body.sizes.get("radius")) else None)
    fig.dimension(_add(bottom, (radius, 0)), _add(top, (radius, 0)), fig.tex(body.sizes["height"]), side=-1, gap=0.3)
    for point, direction, shift in _asked_axes(fig, body):
        if tuple(direction) == (0, 0, 1):
            fig.add(f"\\draw[axis] {_pt(_add(bottom, (0, -0.6)))} -- {_pt(_add(top, (0, 0.6)))};")
        else:
            fig.add(f"\\draw[axis] {_pt(_add(center, (-radius - 0.5, 0)))} -- {_pt(_add(center, (radius + 0.5, 0)))};")
    text = fig.tex(body.density) if body.density is not None else fig.tex(body.mass)
    fig.label(_add(center, (-radius, 0)), (-1, 0), f"${text}$" if text else None)
