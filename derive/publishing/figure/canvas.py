"""The shared canvas: TikZ styles, coordinates, the problem's numbers and symbols, drawing primitives."""
from __future__ import annotations

import math

import sympy as sp

from derive.text.latex import latex_of, symbol_latex
from derive.model import inertia
from derive.core import units
from derive.core.expr import TIME
from derive.model.scene import Body, Motion
from derive.publishing.figure import label_places

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


def given_motion(scene, name: str) -> Motion | None:
    """A body's motion as the file gives it: its `velocity:` (a body rolling at a given speed),
    else its rates in the first state given by rates (`states:`), where it is placed; None where
    neither moves it."""
    given = scene.motions.get(name)
    if given is not None and any(v != 0 for v in given.velocity):
        return given
    first = next((s for s in scene.states.values() if s.rates), None)
    rates = {kind: value for body, kind, value in (first.rates if first else ()) if body == name}
    if not any(v != 0 for v in rates.values()):
        return None
    zero = sp.Integer(0)
    return Motion(scene.bodies[name].at, (rates.get("x", zero), rates.get("y", zero)), rates.get("theta", zero))


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


#: A plate's or box's height against its width as drawn (not to scale: its sides are labelled).
ASPECT = 0.6


class _Figure:
    """The lines of one picture, and the problem's numbers and symbols to draw it with."""

    def __init__(self, problem):
        self.problem = problem
        self.scene = problem.scene
        self.lines: list[str] = []
        self.labels: list[label_places.Label] = []  # set when the picture is drawn (`text`)
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
            value = sp.sympify(expression, strict=True).subs(self.values)  # safe: scene values, strict refuses text
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
        expression = sp.sympify(expression, strict=True)  # safe: scene values, strict refuses text
        if not expression.free_symbols <= self.parameters:
            return None
        return latex_of(expression)

    def m(self, expression) -> str | None:
        """The expression as inline math for a label, or None."""
        text = self.tex(expression)
        return f"${text}$" if text else None

    def product(self, *factors) -> str | None:
        """LaTeX of a product in the order given (m g, not g m; a sum in parentheses, (M + m) g); None
        if a factor is open."""
        parts = [self.tex(f) for f in factors]
        if None in parts:
            return None
        return r"\,".join(rf"\left({p}\right)" if isinstance(f, sp.Add) else p
                           for f, p in zip(factors, parts))

    def ask_symbol(self, kind: str, target=None, detail=None) -> str | None:
        """The LaTeX name of the first ask of that kind (the asked quantity as the problem names it)."""
        for name, ask in self.problem.asks.items():
            q = ask.quantity
            if q.kind == kind and (target is None or q.target == target) and (detail is None or q.detail == detail):
                return symbol_latex(name)
        return None

    # drawing
    def add(self, line: str) -> None:
        self.lines.append(line)

    def dot(self, point, radius: float = 0.05, style: str = "") -> None:
        self.add(f"\\fill{f'[{style}]' if style else ''} {_pt(point)} circle ({_f(radius)});")

    def label(self, point, direction, text: str | None, options: str = "") -> None:
        """A label beside `point`, away from it along `direction`, unless a stroke or another label is
        there when the picture is drawn (derive.publishing.figure.label_places); turned (`rotate=`), it stays."""
        if text:
            self.labels.append(label_places.Label(point, _anchor(*direction), text, options, "rotate" in options))

    def arrow(self, start, vector, style: str, text: str | None = None, toward=None) -> None:
        """An arrow from `start` along `vector`, labelled at its tip (on the side `toward`, if given)."""
        end = _add(start, vector)
        self._labelled(f"\\draw[{style}] {_pt(start)} -- {_pt(end)}", end, toward or vector, text)

    def _labelled(self, path: str, point, direction, text: str | None, place: str = "") -> None:
        """A path with its label written on it (`place`: TikZ's position on the path, `midway`), which
        `text` moves off the path if a stroke or a label is there."""
        if not text:
            self.add(path + ";")
            return
        anchor = _anchor(*direction)
        node = f" node[{place}{', ' if place else ''}anchor={anchor}, inner sep=1.5pt] {{{text}}}"
        self.add(path + node + ";")
        self.labels.append(label_places.Label(point, anchor, text, inline=node))

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
        self._labelled(f"\\draw[dim] {_pt(a2)} -- {_pt(b2)}", _add(a2, (b2[0] - a2[0], b2[1] - a2[1]), 0.5), normal,
                       f"${text}$" if text else None, "midway")

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
        """The picture: its strokes, then its labels over them, each at its clearest place
        (derive.publishing.figure.label_places); a label written on its path stays there if clear."""
        lines, nodes = list(self.lines), []
        for label, point, anchor, clear in label_places.placed(self.labels, label_places.strokes(self.lines)):
            # a label written on its path; where a layout rewrote that path without it, placed as any other
            at = next((i for i, line in enumerate(lines) if label.inline + ";" in line), None) if label.inline else None
            if at is not None:
                if clear and (point, anchor) == (label.point, label.anchor):
                    continue
                lines[at] = lines[at].replace(label.inline + ";", ";", 1)
            options = [label.options] if label.options else []
            if not clear:  # no place beside its point is clear: the label on a white patch, legible over what it covers
                options.append("fill=white, fill opacity=0.8, text opacity=1")
            nodes.append(f"\\node[anchor={anchor}, inner sep=1.5pt{''.join(', ' + o for o in options)}] "
                         f"at {_pt(point)} {{{label.text}}};")
        return "\\begin{tikzpicture}[" + STYLES + "]\n" + "\n".join(lines + nodes) + "\n\\end{tikzpicture}"

    # bodies
    def size(self, body: Body, name: str, default: float) -> float:
        return self.num(body.sizes.get(name), default)

    def body(self, body: Body, center, radius: float, angle: float = 0.0, block: bool = False,
             aspect: float = ASPECT, face: bool = False) -> None:
        """A body by its shape, centered at `center`; `radius` is its half-size on the figure (cm).
        `face`: `center` is its round face's center, which a hemisphere's is off its center of mass
        (where it rests on a surface); else `center` is its center of mass."""
        c, r = _pt(center), _f(radius)
        if body.face_center is not None and not face:  # from the center of mass back to the face's center
            center = _add(center, _unit(self._toward_mass(body, angle)), -self._mass_offset(body, radius))
        mass = self.mass_center(body, center, radius, angle)
        shape = body.shape
        if shape == "point":
            if block:
                self.add(f"\\draw[body] {_pt(_add(center, (-radius, -radius)))} rectangle "
                         f"{_pt(_add(center, (radius, radius)))};")
            else:
                self.add(f"\\fill {c} circle ({_f(min(radius, 0.3))});")
        elif shape == "rod":
            direction = _unit(angle)
            self.bar(_add(center, direction, -radius), _add(center, direction, radius))
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
        elif shape == "custom" and body.round_center is not None:  # a hemisphere: its round face about `center`
            toward = self._toward_mass(body, angle)
            self.add(f"\\draw[body] {_pt(_add(center, _unit(toward - 90), radius))} arc ({_f(toward - 90)}:"
                     f"{_f(toward + 90)}:{r}) -- cycle;")
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
                         "spherical_shell", "cone"):  # the center of mass, off a round face's center (a hemisphere)
            self.add(f"\\fill {_pt(mass)} circle (0.04);")

    def _toward_mass(self, body: Body, angle: float) -> float:
        """The direction (degrees) from a round face's center to the center of mass, turned by `angle`."""
        off = [self.num(v, 0.0) for v in body.face_center]
        return math.degrees(math.atan2(-off[1], -off[0])) + angle

    def mass_center(self, body: Body, center, radius: float, angle: float = 0.0):
        """Where the center of mass of a body drawn about `center` (its round face's center, `radius`
        on the figure) is drawn: off it for a round face off the center of mass (a hemisphere)."""
        if body.face_center is None:
            return center
        return _add(center, _unit(self._toward_mass(body, angle)), self._mass_offset(body, radius))

    def _mass_offset(self, body: Body, radius: float) -> float:
        """How far the center of mass is drawn from the round face's center (`radius` on the figure)."""
        return math.hypot(*(self.num(v, 0.0) for v in body.face_center)) / self.num(body.sizes["radius"], 1.0) * radius

    def bar(self, a, b) -> None:
        """A rod, or any body drawn as a thick bar, from `a` to `b`."""
        self.add(f"\\draw[line width=3.2pt, line cap=round, gray!60!black] {_pt(a)} -- {_pt(b)};")

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


def _label_mass(fig: _Figure, body: Body, at, direction) -> None:
    """The body's mass beside it (a custom body of open mass: its moment of inertia)."""
    text = fig.tex(body.mass) or fig.tex(body.given_inertia)
    fig.label(at, direction, f"${text}$" if text else None)


def regime_text(fig: _Figure, contact) -> str:
    """What a textbook writes at a contact: "no slip" (rolling without slipping, with mu_s when
    given), "smooth" (sliding without friction), "rough, mu_s, mu_k" (the coefficients the file gives)."""
    static, kinetic = fig.tex(contact.static), fig.tex(contact.kinetic)
    if contact.rolling:
        words = ["no slip"] + [f"${t}$" for t in (static, kinetic) if t]
    elif contact.has_friction:  # the engine decides whether it holds: both coefficients the file gives
        words = ["rough"] + [f"${t}$" for t in (static, kinetic) if t]
    else:
        words = ["smooth"]
    return "\\scriptsize " + ", ".join(words)
