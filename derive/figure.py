r"""A problem's scene drawn as a TikZ figure, from the scene's own geometry.

`tikz(problem)` returns a ``tikzpicture`` environment (about 6 cm wide) or None when the
scene has nothing to draw. Bodies are drawn by shape (a disk a circle with its center, a
ring a thick circle, a rod a thick bar, a sphere a shaded ball, a point a dot or a block),
joints as a hatched support (a pivot) or a circled dot (an axle), surfaces as an incline,
a floor or a loop, and forces (gravity, pulls, tension), velocities and spins as arrows,
each labelled with the problem's own symbols (``sp.latex``). Relative sizes come from the
middle of each parameter's range (or its value), clamped so that the figure stays legible.
The scene-level systems (orbit, top, spinning wheel, standing wave, internal forces,
a turning body, prescribed paths) have schematics of their own. Same problem, same bytes.

>>> from derive.problem import load
>>> figure = tikz(load("rolling_incline"))
>>> figure.startswith(r"\begin{tikzpicture}") and r"$\theta$" in figure
True
"""
from __future__ import annotations

import math

import sympy as sp

from derive import inertia, units
from derive.render import tex_escape
from derive.scene import (TIME, Body, Bounce, Contact, HubPull, InternalTurn, Loop, Pin, Skid, Stick,
                          WoundString)

#: Styles every figure declares (TikZ libraries: arrows.meta, patterns).
STYLES = (r"font=\small, >={Stealth[length=2mm]}, "
          r"force/.style={-{Stealth[length=2.2mm]}, thick, red!70!black}, "
          r"velocity/.style={-{Stealth[length=2.2mm]}, thick, blue!70!black}, "
          r"dim/.style={{Latex[length=1.4mm]}-{Latex[length=1.4mm]}, thin}, "
          r"axis/.style={dash dot, thin}, "
          r"body/.style={draw, fill=gray!15}")
#: TikZ libraries the figures use (the preamble loads them).
LIBRARIES = ("arrows.meta", "patterns")
WIDTH = 6.0  # cm, the figure's overall width
TAU = 2 * math.pi


def _f(x: float) -> str:
    """A coordinate in cm to two decimals, without trailing zeros (and never -0)."""
    text = f"{x:.2f}".rstrip("0").rstrip(".")
    return "0" if float(text) == 0 else text


def _pt(p) -> str:
    return f"({_f(p[0])},{_f(p[1])})"


def _add(p, q, k: float = 1.0):
    return (p[0] + k * q[0], p[1] + k * q[1])


def _unit(degrees: float):
    return (math.cos(math.radians(degrees)), math.sin(math.radians(degrees)))


def _anchor(dx: float, dy: float) -> str:
    """The anchor of a node placed beyond a point in the direction (dx, dy)."""
    if dx == 0 and dy == 0:
        return "center"
    names = ("west", "south west", "south", "south east", "east", "north east", "north", "north west")
    angle = math.degrees(math.atan2(dy, dx)) % 360
    return names[int(((angle + 22.5) % 360) // 45)]


def _clamp(x: float, low: float, high: float) -> float:
    return min(max(x, low), high)


class _Figure:
    """The lines of one picture, and the problem's numbers and symbols to draw it with."""

    def __init__(self, problem):
        self.problem = problem
        self.scene = problem.scene
        self.lines: list[str] = []
        self.parameters = {p.symbol for p in problem.parameters.values()} | {TIME}
        self.values = {}
        for p in problem.parameters.values():
            middle = p.value if p.range is None else (p.range[0] + p.range[1]) / 2
            self.values[p.symbol] = middle * units.si_factor(units.parse_unit(p.unit))

    # numbers and labels
    def num(self, expression, default: float) -> float:
        """The expression at the middle of the parameters' ranges; `default` when it has none."""
        if expression is None:
            return default
        try:
            value = sp.sympify(expression).subs(self.values)
            if value.free_symbols:
                return default
            number = complex(sp.N(value))
        except (TypeError, ValueError, ZeroDivisionError):
            return default
        if abs(number.imag) > 1e-12 or not math.isfinite(number.real):
            return default
        return number.real

    def tex(self, expression) -> str | None:
        """LaTeX of an expression in the problem's parameters; None for a size the problem leaves open."""
        if expression is None:
            return None
        expression = sp.sympify(expression)
        if not expression.free_symbols <= self.parameters:
            return None
        return sp.latex(expression)

    def m(self, expression) -> str | None:
        """The expression as inline math for a label, or None."""
        text = self.tex(expression)
        return f"${text}$" if text else None

    def product(self, *factors) -> str | None:
        """LaTeX of a product in the order given (m g, not g m); None if a factor is open."""
        parts = [self.tex(f) for f in factors]
        return None if None in parts else r"\,".join(parts)

    def ask_symbol(self, kind: str, target=None, detail=None) -> str | None:
        """The LaTeX name of the first ask of that kind (the asked quantity as the problem names it)."""
        for name, ask in self.problem.asks.items():
            q = ask.quantity
            if q.kind == kind and (target is None or q.target == target) and (detail is None or q.detail == detail):
                return sp.latex(sp.Symbol(name))
        return None

    # drawing
    def add(self, line: str) -> None:
        self.lines.append(line)

    def dot(self, point, radius: float = 0.05, style: str = "") -> None:
        self.add(f"\\fill{f'[{style}]' if style else ''} {_pt(point)} circle ({_f(radius)});")

    def label(self, point, direction, text: str | None, options: str = "") -> None:
        if text:
            extra = f", {options}" if options else ""
            self.add(f"\\node[anchor={_anchor(*direction)}, inner sep=1.5pt{extra}] at {_pt(point)} {{{text}}};")

    def arrow(self, start, vector, style: str, text: str | None = None, toward=None) -> None:
        """An arrow from `start` along `vector`, labelled at its tip (on the side `toward`, if given)."""
        end = _add(start, vector)
        node = f" node[anchor={_anchor(*(toward or vector))}, inner sep=1.5pt] {{{text}}}" if text else ""
        self.add(f"\\draw[{style}] {_pt(start)} -- {_pt(end)}{node};")

    def line(self, a, b, style: str = "") -> None:
        self.add(f"\\draw[{style}] {_pt(a)} -- {_pt(b)};" if style else f"\\draw {_pt(a)} -- {_pt(b)};")

    def dimension(self, a, b, text: str | None, side: float = 1.0, gap: float = 0.3) -> None:
        """A dimension line beside the segment a-b (on its left for side > 0), labelled."""
        dx, dy = b[0] - a[0], b[1] - a[1]
        length = math.hypot(dx, dy) or 1.0
        normal = (-dy / length * side, dx / length * side)
        a2, b2 = _add(a, normal, gap), _add(b, normal, gap)
        self.add(f"\\draw[gray, very thin] {_pt(a)} -- {_pt(_add(a, normal, gap + 0.08))} "
                 f"{_pt(b)} -- {_pt(_add(b, normal, gap + 0.08))};")
        node = f" node[midway, anchor={_anchor(*normal)}, inner sep=1.5pt] {{${text}$}}" if text else ""
        self.add(f"\\draw[dim] {_pt(a2)} -- {_pt(b2)}{node};")

    def arc(self, center, radius: float, start: float, end: float, text: str | None = None, style: str = "",
            label_radius: float | None = None) -> None:
        """An arc (degrees, counter-clockwise from start to end), labelled at its middle."""
        first = _add(center, _unit(start), radius)
        options = f"[{style}]" if style else ""
        self.add(f"\\draw{options} {_pt(first)} arc[start angle={_f(start)}, end angle={_f(end)}, "
                 f"radius={_f(radius)}];")
        if text:
            middle = _unit((start + end) / 2)
            self.label(_add(center, middle, label_radius or radius + 0.05), middle, f"${text}$")

    def spin(self, center, radius: float, sign: float, text: str | None, at: float = 90.0) -> None:
        """A curved arrow around `center`: counter-clockwise for sign > 0, centered on the angle `at`."""
        start, end = (at - 60, at + 60) if sign >= 0 else (at + 60, at - 60)
        self.arc(center, radius, start, end, text, "->, thick", radius + 0.08)

    def out_of_page(self, point, text: str | None = None, radius: float = 0.12) -> None:
        """A vector out of the page (a circled dot), e.g. an axis or an angular momentum."""
        self.add(f"\\draw[fill=white] {_pt(point)} circle ({_f(radius)}); \\fill {_pt(point)} circle (0.035);")
        self.label(_add(point, (radius, radius)), (1, 1), f"${text}$" if text else None)

    def support(self, point, up: bool) -> None:
        """A pivot: a triangle with a hatched base above the point (hanging) or below it (standing)."""
        s = 1 if up else -1
        left, right = _add(point, (-0.22, 0.38 * s)), _add(point, (0.22, 0.38 * s))
        self.add(f"\\draw[fill=gray!30] {_pt(point)} -- {_pt(left)} -- {_pt(right)} -- cycle;")
        low, high = _add(left, (-0.18, 0)), _add(right, (0.18, 0.14 * s))
        self.add(f"\\fill[pattern=north east lines] {_pt(low)} rectangle {_pt(high)};")
        self.line(_add(left, (-0.18, 0)), _add(right, (0.18, 0)))
        self.add(f"\\draw[fill=white] {_pt(point)} circle (0.06);")

    def axle(self, point) -> None:
        self.out_of_page(point, None, 0.1)

    def ground(self, x0: float, x1: float, y: float = 0.0) -> None:
        self.add(f"\\fill[pattern=north east lines] {_pt((x0, y - 0.18))} rectangle {_pt((x1, y))};")
        self.line((x0, y), (x1, y), "thick")

    def gravity_arrow(self, center, body: Body, length: float = 0.9, toward=None) -> None:
        """The body's weight, down from its center, labelled m g (or g when its mass is open)."""
        weight = self.product(body.mass, self.scene.gravity.g)
        self.arrow(center, (0, -length), "force", f"${weight}$" if weight else "$\\vec g$", toward)

    def text(self) -> str:
        return "\\begin{tikzpicture}[" + STYLES + "]\n" + "\n".join(self.lines) + "\n\\end{tikzpicture}"

    # bodies
    def size(self, body: Body, name: str, default: float) -> float:
        return self.num(body.sizes.get(name), default)

    def body(self, body: Body, center, radius: float, angle: float = 0.0, block: bool = False,
             aspect: float = 0.6) -> None:
        """A body by its shape, centered at `center`; `radius` is its half-size on the figure (cm)."""
        c, r = _pt(center), _f(radius)
        shape = body.shape
        if shape == "point":
            if block:
                self.add(f"\\draw[body] {_pt(_add(center, (-radius, -radius)))} rectangle "
                         f"{_pt(_add(center, (radius, radius)))};")
            else:
                self.add(f"\\fill {c} circle ({_f(min(radius, 0.3))});")
        elif shape == "rod":
            direction = _unit(angle)
            self.add(f"\\draw[line width=3.2pt, line cap=round, gray!60!black] {_pt(_add(center, direction, -radius))}"
                     f" -- {_pt(_add(center, direction, radius))};")
        elif shape in ("ring", "cylindrical_shell", "spherical_shell"):
            self.add(f"\\draw[line width=1.8pt] {c} circle ({r}); \\fill {c} circle (0.04);")
        elif shape in ("sphere", "thick_spherical_shell"):
            self.add(f"\\shade[ball color=gray!35] {c} circle ({r}); \\draw {c} circle ({r});")
        elif shape in ("plate", "box"):
            self.add(f"\\draw[body, rotate around={{{_f(angle)}:{c}}}] {_pt(_add(center, (-radius, -radius * aspect)))}"
                     f" rectangle {_pt(_add(center, (radius, radius * aspect)))};")
        elif shape == "cone":
            self.add(f"\\draw[body] {_pt(_add(center, (-radius, -radius / 2)))} -- "
                     f"{_pt(_add(center, (radius, -radius / 2)))} -- {_pt(_add(center, (0, radius * 1.2)))} -- cycle;")
        elif shape == "custom" and "radius" not in body.sizes:
            self.add(f"\\draw[body, rotate around={{{_f(angle)}:{c}}}] {c} ellipse ({r} and {_f(radius * aspect)});")
        elif body.density is not None:
            inner, outer = self.density_shades(body)
            self.add(f"\\shade[inner color={inner}, outer color={outer}] {c} circle ({r}); \\draw {c} circle ({r});")
        else:
            self.add(f"\\draw[body] {c} circle ({r});")
            if shape == "annulus":
                ratio = self.size(body, "inner_radius", 1) / self.size(body, "outer_radius", 2)
                self.add(f"\\draw[fill=white] {c} circle ({_f(radius * _clamp(ratio, 0.2, 0.85))});")
        if shape not in ("point", "rod", "sphere", "thick_spherical_shell", "ring", "cylindrical_shell",
                         "spherical_shell", "cone"):
            self.add(f"\\fill {c} circle (0.04);")

    def density_shades(self, body: Body) -> tuple[str, str]:
        """Radial shading colors: darker where the density is larger (inner, outer)."""
        coordinates = inertia.SHAPES[body.shape].density_symbols
        radius = body.sizes.get("radius", sp.Integer(1))
        r = coordinates.get("r")
        if r is None:
            return "gray!25", "gray!25"
        near = self.num(body.density.subs(r, radius / 4), 1.0)
        far = self.num(body.density.subs(r, radius * 0.95), 1.0)
        if far > near:
            return "gray!5", "gray!60"
        return ("gray!60", "gray!5") if near > far else ("gray!25", "gray!25")


def tikz(problem) -> str | None:
    """The problem's scene as a ``tikzpicture`` environment, or None when it has nothing to draw."""
    figure = _Figure(problem)
    scene = problem.scene
    for applies, draw in _LAYOUTS:
        if applies(scene):
            draw(figure)
            return figure.text() if figure.lines else None
    return None


# --- scene-level systems ---------------------------------------------------------------------

def _top(fig: _Figure) -> None:
    """A top on its tip: the tilted axis, the body around the center of mass, mg, spin and precession."""
    top = fig.scene.top
    tilt = _clamp(fig.num(top.tilt, 0.5), 0.4, 1.0)
    axis = (math.sin(tilt), math.cos(tilt))
    across = (axis[1], -axis[0])
    axis_degrees = math.degrees(math.atan2(axis[1], axis[0]))
    tip = (0.0, 0.0)
    cm = _add(tip, axis, 2.0)
    fig.ground(-1.2, 1.6)
    fig.add(f"\\draw[axis] {_pt(tip)} -- {_pt((0, 3.4))};")
    fig.add(f"\\draw[body] {_pt(tip)} -- {_pt(_add(cm, across, 0.75))} -- {_pt(_add(cm, across, -0.75))} -- cycle;")
    fig.add(f"\\draw[body, rotate around={{{_f(axis_degrees)}:{_pt(cm)}}}] {_pt(cm)} ellipse (0.22 and 0.75);")
    fig.add(f"\\draw[line width=1.5pt] {_pt(cm)} -- {_pt(_add(tip, axis, 3.3))};")
    fig.line(tip, cm, "thin, dashed")
    fig.add(f"\\fill {_pt(cm)} circle (0.05); \\fill {_pt(tip)} circle (0.05);")
    fig.label(_add(_add(tip, axis, 1.0), across, -0.08), (-across[0], -across[1]), fig.m(top.pivot_distance))
    fig.arc(tip, 2.5, axis_degrees, 90, fig.tex(top.tilt), label_radius=2.55)
    fig.gravity_arrow(cm, Body("top", "custom", top.mass, {}), 1.1, toward=(1, 0))
    # the spin about the axis near the top of the stem, and the precession about the vertical
    spin_at = _add(tip, axis, 3.0)
    fig.add(f"\\draw[->, thick, rotate around={{{_f(axis_degrees)}:{_pt(spin_at)}}}] "
            f"{_pt(_add(spin_at, (0, -0.3)))} arc[start angle=-90, end angle=200, x radius=0.1, y radius=0.3];")
    fig.label(_add(spin_at, across, 0.35), across, fig.m(top.spin))
    fig.add("\\draw[->, thick] (0.45,3.2) arc[start angle=0, end angle=300, x radius=0.45, y radius=0.13];")
    precession = fig.ask_symbol("top") or r"\Omega"
    fig.label((-0.5, 3.2), (-1, 0), f"${precession}$")


def _wheel(fig: _Figure) -> None:
    """A spinning wheel: its angular momentum along the axle, the torque's change of it, the turn."""
    wheel = fig.scene.wheel
    fig.add("\\draw[body] (0,0) ellipse (0.35 and 1.1);")
    fig.line((-0.7, 0), (0, 0), "line width=1.5pt")
    fig.add("\\draw[->, thick] (-0.25,-0.85) arc[start angle=-120, end angle=120, x radius=0.3, y radius=1];")
    fig.label((-0.35, 1.0), (-1, 1), fig.m(wheel.spin))
    length = 3.0
    fig.arrow((0, 0), (length, 0), "very thick, ->", f"$\\vec L = {fig.product(wheel.inertia, wheel.spin)}$")
    change = 0.9
    fig.arrow((length, 0), (0, change), "force", f"$\\Delta L = {fig.product(wheel.torque, wheel.duration)}$")
    fig.arrow((0, 0), (length, change), "thick, dashed, ->")
    angle = math.degrees(math.atan2(change, length))
    fig.arc((0, 0), 1.8, 0, angle, r"\Delta\phi", label_radius=1.85)


def _wave(fig: _Figure) -> None:
    """A standing wave of n wavelengths around a circle of radius r (its two extremes), with L."""
    wave = fig.scene.wave
    n, radius, amplitude = int(fig.num(wave.wavelengths, 1)), 1.4, 0.22
    fig.add(f"\\draw[gray!60] (0,0) circle ({_f(radius)});")
    for sign, style in ((1, "thick, blue!70!black"), (-1, "thick, dashed, blue!70!black")):
        points = [_add((0, 0), _unit(5 * k), radius + sign * amplitude * math.sin(n * math.radians(5 * k)))
                  for k in range(72)]
        fig.add(f"\\draw[{style}] plot[smooth cycle] coordinates {{{' '.join(_pt(p) for p in points)}}};")
    fig.add("\\fill (0,0) circle (0.04);")
    fig.line((0, 0), _add((0, 0), _unit(-40), radius))
    fig.label(_add((0, 0), _unit(-40), radius / 2), (1, 1), fig.m(wave.radius))
    fig.out_of_page((-0.45, 0.35), r"\vec L")
    at = _add((0, 0), _unit(130), radius)
    fig.dot(at, 0.07)
    fig.arrow(at, _add((0, 0), _unit(40), 0.8), "velocity", "$p$")
    wavelengths = fig.tex(wave.wavelengths)
    count = "" if wavelengths == "1" else f"{wavelengths}\\,"
    fig.label((1.7, -1.3), (1, 0), f"${count}\\lambda = 2\\pi {fig.tex(wave.radius)}$")


def _orbit(fig: _Figure) -> None:
    """The orbit: an ellipse about the central mass at its focus, r to the planet; with only the
    angular momentum, the effective potential beside it."""
    orbit = fig.scene.orbit
    given = orbit.eccentricity is not None
    e = _clamp(fig.num(orbit.eccentricity, 0.5), 0.0, 0.75) if given else 0.5
    a = 1.5 if given else 1.1
    b = a * math.sqrt(1 - e * e)
    center = (-a * e, 0.0)
    fig.add(f"\\draw[thick] {_pt(center)} ellipse ({_f(a)} and {_f(b)});")
    fig.add("\\fill (0,0) circle (0.09);")
    fig.label((0.05, -0.12), (1, -1), fig.m(orbit.GM))
    nu = 115.0
    r = a * (1 - e * e) / (1 + e * math.cos(math.radians(nu)))
    planet = _add((0, 0), _unit(nu), r)
    fig.line((0, 0), planet, "thin")
    fig.label(_add((0, 0), _unit(nu), r / 2), _unit(nu - 90), "$r$")
    fig.dot(planet, 0.06)
    # velocity along the tangent: d/dnu of the position on the ellipse
    dr = a * (1 - e * e) * e * math.sin(math.radians(nu)) / (1 + e * math.cos(math.radians(nu))) ** 2
    tangent = (dr * math.cos(math.radians(nu)) - r * math.sin(math.radians(nu)),
               dr * math.sin(math.radians(nu)) + r * math.cos(math.radians(nu)))
    norm = math.hypot(*tangent)
    fig.arrow(planet, (0.7 * tangent[0] / norm, 0.7 * tangent[1] / norm), "velocity", "$v$")
    if given:
        fig.dimension((center[0] - a, -b), (center[0] + a, -b), fig.tex(2 * orbit.semi_major_axis), side=-1, gap=0.25)
        fig.dot(center, 0.03)
        if e > 0.1:
            fig.dimension(center, (0, 0), fig.tex(orbit.semi_major_axis * orbit.eccentricity), side=1, gap=0.3)
        return
    # U_eff(r) = -GM/r + l^2/(2 r^2) in units of the circular radius and the well's depth
    x0, y0, width, height = 1.7, -0.9, 2.6, 2.2
    fig.add(f"\\draw[->] {_pt((x0, y0 + height / 2))} -- {_pt((x0 + width, y0 + height / 2))} node[below] {{$r$}};")
    fig.add(f"\\draw[->] {_pt((x0, y0))} -- {_pt((x0, y0 + height))} node[left] {{$U_{{\\mathrm{{eff}}}}$}};")
    points = []
    for k in range(40):
        x = 0.42 + k * (4.0 - 0.42) / 39
        u = -2 / x + 1 / x**2
        points.append(_pt((x0 + x * width / 4.0, y0 + height / 2 + u * height / 2.4)))
    fig.add(f"\\draw[thick, blue!70!black] plot[smooth] coordinates {{{' '.join(points)}}};")
    bottom = (x0 + width / 4.0, y0 + height / 2 - height / 2.4)
    fig.add(f"\\draw[dotted] {_pt(bottom)} -- {_pt((bottom[0], y0 + height / 2))} node[above] {{$r_c$}};")
    fig.out_of_page((-0.5, -0.45), fig.tex(orbit.angular_momentum))


def _internal(fig: _Figure) -> None:
    """N point masses with equal and opposite forces along the lines between them, r from O."""
    n = fig.scene.internal_forces
    centre, radius = (1.2, 0.9), 1.2
    points = [_add(centre, _unit(90 + 360 * k / n + 15), radius) for k in range(n)]
    origin = (-1.6, -0.6)
    fig.add(f"\\fill {_pt(origin)} circle (0.05) node[below left] {{$O$}};")
    for k, p in enumerate(points, start=1):
        fig.add(f"\\draw[dashed, gray, ->] {_pt(origin)} -- {_pt(p)};")
        fig.dot(p, 0.09)
        outward = (p[0] - centre[0], p[1] - centre[1])
        fig.label(_add(p, outward, 0.12), outward, f"$m_{{{k}}}$")
    for i in range(n):
        for j in range(n):
            if i != j:
                d = (points[j][0] - points[i][0], points[j][1] - points[i][1])
                length = math.hypot(*d)
                text = f"$\\vec F_{{{i + 1}{j + 1}}}$" if (i, j) in ((0, 1), (1, 0)) else None
                fig.arrow(points[i], (0.55 * d[0] / length, 0.55 * d[1] / length), "force", text)


def _rotation(fig: _Figure) -> None:
    """A body turning about the vertical axis through its center, tilted from it; L for a rod."""
    name, rotation = next(iter(fig.scene.rotations.items()))
    body = fig.scene.bodies[name]
    tilt = _clamp(fig.num(rotation.tilt, 0.6), 0.25, 1.35)
    fig.add("\\draw[axis, ->] (0,-2) -- (0,2.2);")
    fig.add("\\draw[->, thick] (0.35,1.75) arc[start angle=0, end angle=300, x radius=0.35, y radius=0.1];")
    fig.label((0.45, 1.8), (1, 0), fig.m(rotation.rate))
    direction = 90 - math.degrees(tilt)
    fig.body(body, (0, 0), 1.6, direction)
    fig.arc((0, 0), 0.8, direction, 90, fig.tex(rotation.tilt), label_radius=0.9)
    if body.shape == "rod":  # a thin rod's L is normal to it, in the plane of the rod and the axis
        fig.arrow((0, 0), _unit(direction + 90), "very thick, ->, green!40!black", r"$\vec L$")


# --- prescribed paths ------------------------------------------------------------------------

def _paths(fig: _Figure) -> None:
    """A point on a prescribed path about the origin O: a circle, a straight line (with its
    distance from O), or a general curve with r, theta and the polar unit vectors."""
    name, body = next((n, b) for n, b in fig.scene.bodies.items() if b.path is not None)
    path = body.path
    fig.add("\\fill (0,0) circle (0.05) node[below left] {$O$};")
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


# --- surfaces --------------------------------------------------------------------------------

def _on_surface(fig: _Figure) -> None:
    """Bodies on an incline or a level floor: the surface, each body touching it, gravity,
    pulls, velocities and a skid's friction."""
    scene = fig.scene
    contacts = [c for c in scene.constraints if isinstance(c, Contact)]
    surface = scene.surfaces[contacts[0].surface]
    if isinstance(surface, Loop):
        _loop(fig, surface, contacts)
        return
    angle = fig.num(surface.angle, 0.5)
    if angle <= 1e-9:
        _floor(fig, contacts)
        return
    angle = _clamp(angle, 0.3, 0.8)
    slope = 5.2
    width, height = slope * math.cos(angle), slope * math.sin(angle)
    fig.add(f"\\draw[fill=gray!10] (0,0) -- {_pt((width, 0))} -- {_pt((0, height))} -- cycle;")
    fig.add(f"\\fill[pattern=north east lines] (-0.2,-0.15) rectangle {_pt((width + 0.3, 0))};")
    fig.arc((width, 0), 0.9, 180 - math.degrees(angle), 180, fig.tex(surface.angle), label_radius=1.0)
    if surface.height is not None:
        fig.dimension((0, 0), (0, height), fig.tex(surface.height), side=1, gap=0.3)
    down, normal = (math.cos(angle), -math.sin(angle)), (math.sin(angle), math.cos(angle))
    reference = _reference_size(fig, surface.height, height)
    several = len(contacts) > 1
    along = 0.5 if several else 1.0
    for contact in contacts:
        body = scene.bodies[contact.body]
        r = _drawn_radius(fig, body, reference)
        along += r
        foot = _add((0, height), down, along)
        center = _add(foot, normal, r)
        fig.body(body, center, r, -math.degrees(angle), block=body.shape == "point")
        if several:
            fig.label(_add(center, normal, r + 0.05), normal, f"\\scriptsize {tex_escape(body.name)}")
        elif scene.gravity is not None:
            fig.gravity_arrow(center, body)
        along += r + 0.4
    if several and scene.gravity is not None:
        fig.arrow((width - 0.3, height - 0.3), (0, -0.7), "force", "$\\vec g$")


def _reference_size(fig: _Figure, size_expr, drawn: float):
    """(metres, cm) of a scene size that body sizes are drawn in proportion to."""
    return (fig.num(size_expr, 0.0), drawn)


def _drawn_radius(fig: _Figure, body: Body, reference, low: float = 0.18, high: float = 0.5,
                  default: float = 0.3) -> float:
    if body.shape == "point":
        return 0.17
    size = body.sizes.get("radius", body.sizes.get("outer_radius"))
    metres, drawn = reference
    if size is None or metres <= 0 or fig.num(size, 0.0) <= 0:
        return default
    return _clamp(fig.num(size, 0.0) / metres * drawn, low, high)


def _floor(fig: _Figure, contacts: list[Contact]) -> None:
    """A level floor: each body on it, with its pulls, launch velocity and a skid's friction."""
    scene = fig.scene
    fig.ground(-0.4, 5.4)
    x = 1.4
    for contact in contacts:
        body = scene.bodies[contact.body]
        pull = next((p for p in scene.pulls if p.body == body.name), None)
        r = 1.0 if pull else 0.7
        center = (x, r)
        fig.body(body, center, r, block=body.shape == "point")
        if pull:
            _spool(fig, body, pull, center, r)
        if scene.gravity is not None:
            fig.gravity_arrow(center, body, r * 0.55, toward=(-1, 0) if pull else (1, 0))
        motion = scene.motions.get(body.name)
        if motion is not None and any(v != 0 for v in motion.velocity):
            v = (fig.num(motion.velocity[0], 1), fig.num(motion.velocity[1], 0))
            n = math.hypot(*v) or 1.0
            fig.arrow(_add(center, (0, r + 0.25)), (1.2 * v[0] / n, 1.2 * v[1] / n), "velocity",
                      fig.m(sp.sqrt(motion.velocity[0] ** 2 + motion.velocity[1] ** 2)))
            skid = next((e for e in scene.events if isinstance(e, Skid) and e.body == body.name), None)
            if skid is not None:
                text = fig.product(skid.friction, body.mass, scene.gravity.g) if scene.gravity else fig.tex(skid.friction)
                fig.arrow((x - 0.05, 0.08), (-1.0 * v[0] / n, 0), "force", f"${text}$" if text else None,
                          toward=(-v[0] / n, 1))
        if "radius" in body.sizes and fig.tex(body.sizes["radius"]) and not pull:
            fig.line(center, _add(center, _unit(150), r), "thin")
            fig.label(_add(center, _unit(150), r * 0.55), (0, 1), fig.m(body.sizes['radius']))
        x += 2 * r + 1.2


def _spool(fig: _Figure, body: Body, pull: HubPull, center, r: float) -> None:
    """A spool: its hub, the cord leaving the hub's underside at the pull's angle, the radii."""
    ratio = _clamp(fig.num(pull.hub_radius, 1) / fig.size(body, "radius", 2), 0.25, 0.7)
    hub = r * ratio
    fig.add(f"\\draw[fill=gray!35] {_pt(center)} circle ({_f(hub)}); \\fill {_pt(center)} circle (0.04);")
    angle = _clamp(fig.num(pull.angle, 0.5), 0.15, 1.2)
    start = _add(center, (math.sin(angle), -math.cos(angle)), hub)
    direction = (math.cos(angle), math.sin(angle))
    fig.line(start, _add(start, direction, 1.4), "thick")
    fig.arrow(_add(start, direction, 1.4), (0.9 * direction[0], 0.9 * direction[1]), "force",
              fig.m(pull.force))
    corner = _add(start, direction, 1.0)
    fig.line(corner, _add(corner, (1.0, 0)), "thin, dashed")
    fig.arc(corner, 0.7, 0, math.degrees(angle), fig.tex(pull.angle), label_radius=0.75)
    fig.line(center, _add(center, _unit(120), r), "thin")
    fig.label(_add(center, _unit(120), r * 0.7), _unit(210), fig.m(body.sizes.get('radius'))
              if fig.tex(body.sizes.get("radius")) else None)
    fig.line(center, _add(center, _unit(200), hub), "thin")
    fig.label(_add(center, _unit(200), hub + 0.02), (-1, 0), fig.m(pull.hub_radius))


def _loop(fig: _Figure, loop: Loop, contacts: list[Contact]) -> None:
    """A loop-the-loop: a ramp from the release height into a circular track, the bodies at the
    top of the ramp, the loop's radius and the release height."""
    scene = fig.scene
    radius = 1.15
    center = (1.2, radius)
    start, c1, c2, end = (-2.6, 3.3), (-1.8, 0.1), (-0.6, 0.0), (1.2, 0.0)
    fig.add(f"\\draw[thick] {_pt(start)} .. controls {_pt(c1)} and {_pt(c2)} .. {_pt(end)};")
    fig.add(f"\\draw[thick] {_pt(center)} circle ({_f(radius)});")
    fig.ground(-2.8, 2.7, 0.0)
    fig.line(center, _add(center, _unit(30), radius), "thin")
    fig.label(_add(center, _unit(30), radius / 2), (-0.5, 1), fig.m(loop.radius))
    fig.dot(center, 0.04)
    reference = (fig.num(loop.radius, 0.0), radius)
    u = 0.0
    for contact in contacts:
        body = scene.bodies[contact.body]
        r = _drawn_radius(fig, body, reference, 0.13, 0.3, 0.2)
        point, tangent = _bezier(start, c1, c2, end, u)
        normal = (-tangent[1], tangent[0])
        centre = _add(point, normal, r)
        fig.body(body, centre, r, block=body.shape == "point")
        if len(contacts) > 1:
            fig.label(_add(centre, normal, r + 0.05), (1, 0.4), f"\\scriptsize {tex_escape(body.name)}")
        u += 0.16
    first, _ = _bezier(start, c1, c2, end, 0.0)
    fig.dimension((-3.0, 0), (-3.0, first[1]), "h", side=-1, gap=0.0)
    if scene.gravity is not None:
        fig.arrow((2.9, 2.6), (0, -0.7), "force", "$\\vec g$")


def _bezier(p0, p1, p2, p3, u: float):
    """Point and unit tangent of a cubic Bezier curve at parameter u."""
    w = (1 - u) ** 3, 3 * u * (1 - u) ** 2, 3 * u * u * (1 - u), u**3
    point = tuple(sum(wi * p[i] for wi, p in zip(w, (p0, p1, p2, p3))) for i in range(2))
    d = 3 * (1 - u) ** 2, 6 * u * (1 - u), 3 * u * u
    tangent = tuple(sum(di * (q[i] - p[i]) for di, p, q in zip(d, (p0, p1, p2), (p1, p2, p3))) for i in range(2))
    norm = math.hypot(*tangent) or 1.0
    return point, (tangent[0] / norm, tangent[1] / norm)


# --- impacts ---------------------------------------------------------------------------------

def _impact(fig: _Figure) -> None:
    """A collision: the struck body at the origin, the incoming body on its line of motion with its
    velocity, and the impact parameter (the line's distance from the struck body's center)."""
    scene = fig.scene
    event = next(e for e in scene.events if isinstance(e, (Stick, Bounce)))
    target_name = event.to if isinstance(event, Stick) else event.off
    target, mover = scene.bodies[target_name], scene.bodies[event.body]
    motion = scene.motions[event.body]
    # the drawing scale: the struck body (or the farthest contact point) is about 1.3 cm
    position = [fig.num(p, 0) for p in motion.position]
    reach = max(math.hypot(*position), fig.size(target, "radius", 0), fig.size(target, "length", 0) / 2, 1e-9)
    scale = (2.4 if target.shape == "rod" else 1.3) / reach
    size = target.sizes.get("radius") or (target.sizes.get("length", 0) / 2)
    drawn = fig.num(size, 0) * scale or 1.3
    pin = next((c for c in scene.constraints if isinstance(c, Pin) and c.body == target_name), None)
    if target.shape == "custom" and "radius" not in target.sizes:
        fig.add(f"\\draw[body] (0,0) circle ({_f(drawn)}); \\fill (0,0) circle (0.04);")
    else:
        fig.body(target, (0, 0), drawn)
    if target.shape == "rod" and fig.tex(target.sizes.get("length")):
        fig.dimension((-drawn, 0), (drawn, 0), fig.tex(target.sizes["length"]), side=-1, gap=0.3)
    if pin is not None:
        fig.axle((0, 0))
    spin = scene.motions.get(target_name)
    if spin is not None and spin.spin != 0:
        sign = 1 if fig.num(spin.spin, 1) > 0 else -1
        fig.spin((0, 0), drawn + 0.25, sign, fig.tex(sp.Abs(spin.spin)), at=135)
    if target.shape == "rod":
        _label_mass(fig, target, (-drawn, 0.12), (1, 1))
    else:
        _label_mass(fig, target, (-0.15, -0.15), (-1, -1))
    v = (fig.num(motion.velocity[0], 1), fig.num(motion.velocity[1], 0))
    speed = math.hypot(*v) or 1.0
    along = (v[0] / speed, v[1] / speed)
    hit = (position[0] * scale, position[1] * scale)
    back = 1.4 if target.shape == "rod" else 1.9
    incoming = _add(hit, along, -back)
    fig.line(incoming, hit, "dashed, gray")
    fig.dot(incoming, 0.09)
    left = (-along[1], along[0])
    _label_mass(fig, mover, _add(incoming, left, -0.12), (along[1], -along[0]))
    fig.arrow(_add(incoming, along, 0.15), (0.85 * along[0], 0.85 * along[1]), "velocity",
              fig.m(sp.sqrt(motion.velocity[0] ** 2 + motion.velocity[1] ** 2)), toward=left)
    fig.add(f"\\fill[red!70!black] {_pt(hit)} circle (0.04);")
    x, y = motion.position
    distance = sp.simplify(abs(x * motion.velocity[1] - y * motion.velocity[0])
                           / sp.sqrt(motion.velocity[0] ** 2 + motion.velocity[1] ** 2))
    foot_length = hit[0] * (-along[1]) + hit[1] * along[0]
    foot = (-along[1] * foot_length, along[0] * foot_length)
    if abs(foot_length) > 0.05:
        side = 1 if (foot[0] * along[1] - foot[1] * along[0]) < 0 else -1
        fig.dimension((0, 0), foot, fig.tex(distance), side=side * (1 if target.shape == "rod" else -1),
                      gap=0.2 if target.shape == "rod" else drawn + 0.35)


def _label_mass(fig: _Figure, body: Body, at, direction) -> None:
    """The body's mass beside it (a custom body of open mass: its moment of inertia)."""
    text = fig.tex(body.mass) or fig.tex(body.given_inertia)
    fig.label(at, direction, f"${text}$" if text else None)


# --- joints and strings ----------------------------------------------------------------------

def _pinned(fig: _Figure) -> None:
    """Bodies on fixed axles or pivots: a pendulum hangs from its pivot (displaced a little, its
    angle to the vertical marked), a body stands on a pivot, bodies share an axle; wound strings
    run from the rim to their hanging loads, with tension and gravity."""
    scene = fig.scene
    pins = [c for c in scene.constraints if isinstance(c, Pin)]
    axles = [p for p in pins if all(fig.num(o, 1) == 0 for o in p.offset)]
    pivots = [p for p in pins if p not in axles]
    x = 0.0
    for pin in pivots:
        _pendulum(fig, scene.bodies[pin.body], pin, (x, 0.0))
        x += 3.0
    if axles:
        _axles(fig, [scene.bodies[p.body] for p in axles], (x, 0.0))


def _pendulum(fig: _Figure, body: Body, pin: Pin, at) -> None:
    offset = fig.num(pin.offset[1], 1)
    hanging = offset > 0
    swing = math.radians(22 if hanging else 12)
    length = 2.0
    axis = (math.sin(swing), -math.cos(swing) if hanging else math.cos(swing))
    cm = _add(at, axis, length)
    angle = math.degrees(math.atan2(axis[1], axis[0]))
    if "radius" in body.sizes or body.shape != "custom":
        fig.body(body, cm, 0.7, angle)
    else:
        blob = _pt(_add(cm, axis, -0.45))  # a body of no particular shape, reaching to its pivot
        fig.add(f"\\draw[body, rotate around={{{_f(angle)}:{blob}}}] {blob} ellipse (1.6 and 0.55);")
    fig.support(at, hanging)
    fig.add(f"\\draw[axis] {_pt(at)} -- {_pt(_add(at, (0, -2.5 if hanging else 2.5)))};")
    fig.line(at, cm, "thin")
    fig.dot(cm, 0.06)
    away = (math.cos(swing), math.sin(swing) * (1 if hanging else -1))  # the side away from the vertical
    fig.label(_add(_add(at, axis, length * (0.5 if hanging else 0.3)), away, 0.05), away,
              fig.m(abs(pin.offset[1])))
    amplitude = next((a.amplitude for a in fig.problem.asks.values() if a.amplitude is not None), None)
    vertical = -90 if hanging else 90
    fig.arc(at, 1.1, min(vertical, angle), max(vertical, angle), fig.tex(amplitude) if amplitude else None,
            label_radius=1.15)
    if fig.scene.gravity is not None:
        fig.gravity_arrow(cm, body, toward=(1, 0))


def _axles(fig: _Figure, bodies: list[Body], at) -> None:
    """Bodies on one fixed axle (concentric, the larger moment outside), strings and internal turns."""
    scene = fig.scene
    ordered = sorted(bodies, key=lambda b: -fig.num(b.inertia, 1.0))
    radii = [1.1] if len(ordered) == 1 else [1.6 - 1.0 * k / (len(ordered) - 1) for k in range(len(ordered))]
    aspect = 1.0 if len(ordered) == 1 else 0.7  # bodies without a radius drawn as ovals
    for k, body in enumerate(ordered):
        if body.shape == "custom" and "radius" not in body.sizes:
            fig.body(body, at, radii[k], aspect=aspect)
        else:
            fig.body(body, at, radii[k])
    for k, body in enumerate(ordered):  # each moment of inertia inside its own ring
        if len(ordered) > 1 and fig.tex(body.inertia):
            where = (-(radii[k] + radii[k + 1]) / 2, 0) if k + 1 < len(radii) else (-radii[k] * 0.55, 0)
            fig.label(_add(at, where), (0, 0), fig.m(body.inertia))
    fig.axle(at)
    reel, r = ordered[0], radii[0]
    for turn in (e for e in scene.events if isinstance(e, InternalTurn)):
        k = next((i for i, b in enumerate(ordered) if b.name == turn.body), 0)
        fig.spin(at, radii[k] * aspect * 0.75, 1, fig.tex(turn.angle), at=-90)
    strings = [c for c in scene.constraints if isinstance(c, WoundString)]
    for cord in strings:
        _string(fig, cord, at, r)
    if fig.tex(reel.sizes.get("radius")):
        angle = 135 if strings and strings[0].side > 0 else 45
        fig.line(at, _add(at, _unit(angle), r), "thin")
        fig.label(_add(at, _unit(angle), r * 0.55), _unit(angle + 90), fig.m(reel.sizes['radius']))
    if len(ordered) == 1:
        _label_mass(fig, reel, _add(at, (0.12, -0.12)), (1, -1))
    if scene.gravity is not None and not strings:
        fig.gravity_arrow(at, reel)


def _string(fig: _Figure, cord: WoundString, center, radius: float) -> None:
    """The cord from the rim (tangent, vertical) down to its load, with tension and gravity."""
    scene = fig.scene
    side = cord.side
    top = _add(center, (side * radius, 0))
    load = scene.bodies[cord.load]
    half = 0.3
    block = _add(top, (0, -2.4))
    fig.line(top, _add(block, (0, half)), "thick")
    fig.body(load, block, half, block=load.shape == "point")
    _label_mass(fig, load, _add(block, (side * (half + 0.05), 0)), (side, 0))
    tension = fig.ask_symbol("force", cord.name, "tension") or "T"
    fig.arrow(_add(block, (0, half)), (0, 0.8), "force", f"${tension}$", toward=(side, 0))
    if scene.gravity is not None:
        fig.gravity_arrow(_add(block, (0, -half)), load, 0.8)


# --- bodies alone ----------------------------------------------------------------------------

def _placed(fig: _Figure) -> None:
    """Bodies at given positions (a molecule): to scale, with the distances and the center of mass."""
    scene = fig.scene
    names = list(scene.motions)
    positions = [tuple(fig.num(p, 0) for p in scene.motions[n].position) for n in names]
    span = max((math.hypot(p[0] - q[0], p[1] - q[1]) for p in positions for q in positions), default=0) or 1.0
    scale = 4.0 / span
    drawn = [(p[0] * scale, p[1] * scale) for p in positions]
    masses = [fig.num(scene.bodies[n].mass, 1) for n in names]
    biggest = max(masses) or 1.0
    for a in range(len(drawn)):
        for b in range(a + 1, len(drawn)):
            fig.line(drawn[a], drawn[b], "thick, gray")
    for name, p, m in zip(names, drawn, masses):
        size = 0.3 * _clamp((m / biggest) ** (1 / 3), 0.5, 1.0)
        fig.add(f"\\shade[ball color=gray!50] {_pt(p)} circle ({_f(size)});")
        _label_mass(fig, scene.bodies[name], _add(p, (0, size + 0.05)), (0, 1))
    if len(names) == 2:
        a, b = (scene.motions[n].position for n in names)
        fig.dimension(drawn[0], drawn[1], fig.tex(sp.sqrt((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2)), side=-1,
                      gap=0.55)
    total = sum(masses) or 1.0
    cm = (sum(m * p[0] for m, p in zip(masses, drawn)) / total, sum(m * p[1] for m, p in zip(masses, drawn)) / total)
    fig.add(f"\\draw {_pt(cm)} circle (0.1); \\draw {_pt(_add(cm, (-0.14, 0)))} -- {_pt(_add(cm, (0.14, 0)))} "
            f"{_pt(_add(cm, (0, -0.14)))} -- {_pt(_add(cm, (0, 0.14)))};")
    fig.label(_add(cm, (0, 0.15)), (0, 1), "cm")


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
            axis = q.detail or inertia.PLANAR_AXIS[body.shape]
            point, direction = shape.axes[axis]
            generic = {shape.sizes[n]: body.sizes[n] for n in shape.sizes if n in body.sizes}
            yield (tuple(fig.num(sp.sympify(c).subs(generic), 0) for c in point), direction, ask.shift)


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
        if shift is not None:
            moved = _add(where, (_clamp(fig.num(shift, 0) * scale, 0.4, half + 0.6), 0))
            fig.dimension(where, moved, fig.tex(shift), side=1, gap=0.45)
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


# --- which layout a scene gets ---------------------------------------------------------------

def _has(kind):
    return lambda scene: any(isinstance(c, kind) for c in scene.constraints)


_LAYOUTS = (
    (lambda s: s.top is not None, _top),
    (lambda s: s.wheel is not None, _wheel),
    (lambda s: s.wave is not None, _wave),
    (lambda s: s.orbit is not None, _orbit),
    (lambda s: s.internal_forces is not None, _internal),
    (lambda s: bool(s.rotations), _rotation),
    (lambda s: any(b.path is not None for b in s.bodies.values()), _paths),
    (_has(Contact), _on_surface),
    (lambda s: any(isinstance(e, (Stick, Bounce)) for e in s.events) and any(
        isinstance(e, (Stick, Bounce)) and e.body in s.motions for e in s.events), _impact),
    (_has(Pin), _pinned),
    (lambda s: bool(s.motions) and all(n in s.motions for n in s.bodies), _placed),
    (lambda s: bool(s.bodies), _specimens),
)
