"""A point on a prescribed path about O: a circle, a straight line or a general curve."""
from __future__ import annotations

import math

import sympy as sp

from derive.publishing.figure.canvas import _add, _f, _Figure, _label_mass, _pt, _unit
from derive.model.scene import Body


def _paths(fig: _Figure) -> None:
    """A point on a prescribed path about the origin O: a circle, a straight line (with its
    distance from O), or a general curve with r, theta and the polar unit vectors."""
    name, body = next((n, b) for n, b in fig.scene.bodies.items() if b.path is not None)
    path = body.path
    fig.dot((0, 0))
    fig.label((0, 0), (-1, -1), "$O$")
    t = sp.Symbol("t")
    if path.kind == "polar" and not path.functions[0].has(t) and path.functions[1].has(t):
        _circle_path(fig, path, body)
    elif path.kind == "cartesian" and all(sp.degree(f, t) <= 1 for f in path.functions if f.is_polynomial(t)) \
            and all(f.is_polynomial(t) for f in path.functions):
        _line_path(fig, path, body)
    else:
        _curve_path(fig, path, body)


def _circle_path(fig: _Figure, path, body: Body) -> None:
    radius, theta = path.functions
    size = 1.4
    fig.add(f"\\draw[dashed] (0,0) circle ({_f(size)});")
    at = 40.0
    point = _add((0, 0), _unit(at), size)
    fig.line((0, 0), point)
    fig.label(_add((0, 0), _unit(at), size / 2), _unit(at + 90), fig.m(radius))
    fig.arc((0, 0), 0.5, 0, at, fig.tex(theta), label_radius=0.55)
    fig.line((0, 0), (size + 0.3, 0), "thin, gray")
    fig.dot(point, 0.08)
    _label_mass(fig, body, _add(point, _unit(at), 0.12), _unit(at))
    sign = 1 if fig.num(sp.diff(theta, sp.Symbol("t")), 1) >= 0 else -1
    fig.arrow(point, _add((0, 0), _unit(at + 90 * sign), 0.8), "velocity", "$v$")
    fig.out_of_page((-0.75, 0.4), r"\vec L")


def _line_path(fig: _Figure, path, body: Body) -> None:
    t = sp.Symbol("t")
    start = [f.subs(t, 0) for f in path.functions]
    velocity = [sp.diff(f, t) for f in path.functions]
    v = (fig.num(velocity[0], 1), fig.num(velocity[1], 0))
    speed = math.hypot(*v) or 1.0
    along = (v[0] / speed, v[1] / speed)
    left = (-along[1], along[0])
    distance_expr = sp.simplify(start[0] * velocity[1] - start[1] * velocity[0]) / sp.sqrt(
        sp.simplify(velocity[0] ** 2 + velocity[1] ** 2))
    foot = _add((0, 0), left, -1.2 if fig.num(distance_expr, 1) >= 0 else 1.2)
    fig.line(_add(foot, along, -2.2), _add(foot, along, 1.6), "dashed")
    at = _add(foot, along, -1.4)
    fig.dot(at, 0.08)
    _label_mass(fig, body, _add(at, left, 0.12), left)
    fig.arrow(at, (0.9 * along[0], 0.9 * along[1]), "velocity",
              fig.m(sp.simplify(sp.sqrt(velocity[0] ** 2 + velocity[1] ** 2))), toward=left)
    fig.dimension((0, 0), foot, fig.tex(sp.simplify(abs(distance_expr))), side=1, gap=0.3)


def _curve_path(fig: _Figure, path, body: Body) -> None:
    """An arbitrary path r(t), theta(t): the point, r and theta, the polar unit vectors (and the
    area swept, when the areal velocity is asked)."""
    points = []
    for k in range(25):
        phi = math.radians(-10 + 100 * k / 24)
        rho = 2.6 / (1 + 0.45 * math.cos(phi - 0.3))
        points.append((rho * math.cos(phi), rho * math.sin(phi)))
    p, q = points[12], points[16]
    if any(a.quantity.detail == "areal_velocity" for a in fig.problem.asks.values()):
        fig.add(f"\\fill[gray!25] (0,0) -- plot[smooth] coordinates {{{' '.join(_pt(x) for x in points[12:17])}}} "
                f"-- cycle;")
        fig.label(_add((0, 0), _add(p, q), 0.33), (0, 0), "$dA$")
    fig.add(f"\\draw[thick] plot[smooth] coordinates {{{' '.join(_pt(x) for x in points)}}};")
    fig.line((0, 0), (2.3, 0), "thin, gray")
    fig.add(f"\\draw[->] (0,0) -- {_pt(p)};")
    angle = math.degrees(math.atan2(p[1], p[0]))
    fig.label(_add((0, 0), p, 0.5), _unit(angle - 90), "$r$")
    fig.arc((0, 0), 0.55, 0, angle, r"\theta", label_radius=0.6)
    fig.dot(p, 0.08)
    _label_mass(fig, body, _add(p, (0.1, -0.1)), (1, -1))
    radial = _unit(angle)
    fig.arrow(p, (0.6 * radial[0], 0.6 * radial[1]), "->, thick", r"$\hat r$")
    fig.arrow(p, (-0.6 * radial[1], 0.6 * radial[0]), "->, thick", r"$\hat\theta$")
