"""`derive inertia SHAPE`: the integral, the mass from the same density, I, I/(M size^2), the tensor.

Expressions from the command line (--axis directions, --about, --density) go through
`derive.core.expr.parse`: names are the shape's symbols (M and its sizes), its coordinates
(in --density only), and any other name becomes a positive parameter given with --set.

>>> report("rod", "end", {}, 15)["ratio"]
'1/3'
>>> report("disk", None, {"M": "2", "R": "50 cm"}, 15)["value"]
'0.250000000000000'
"""
from __future__ import annotations

import ast
import json

import sympy as sp

from derive.core import expr, units
from derive.model import inertia
from derive.numbers import numeric
from derive.core.errors import InputError
from derive.text.terminal import indented, pretty
from derive.core.spelling import did_you_mean

JSON_KEYS = ("shape", "axis", "integral", "mass", "I", "ratio", "tensor", "value")


class _Names:
    """The names options may use: M and the sizes of the shape, and parameters as they appear
    (each with the unit its --set value is read in)."""

    def __init__(self, shape: inertia.Shape) -> None:
        self.symbols = {"M": inertia.M, **{str(s): s for s in shape.sizes.values()}}
        self.units = {inertia.M: "kg", **{s: "m" for s in shape.sizes.values()}}

    def parse(self, text: str, option: str, unit: str, coordinates: dict[str, sp.Symbol] | None = None) -> sp.Expr:
        """Parse `text`; new names become positive parameters read in `unit`."""
        coordinates = coordinates or {}
        try:
            tree, _ = expr._syntax_tree(text, 1000)
        except InputError as error:
            raise InputError(f"{option} {text!r}: {error}") from None
        names = {n.id for n in ast.walk(tree) if isinstance(n, ast.Name)} - expr.RESERVED
        for name in sorted(names - set(self.symbols) - set(coordinates)):
            if name in inertia.COORDINATE_SYMBOLS:
                where = f"its coordinates are {', '.join(coordinates)}" if coordinates else "use sizes and numbers"
                raise InputError(f"{option} {text!r}: {name} is not a coordinate here ({where})")
            self.symbols[name] = sp.Symbol(name, positive=True)
            self.units[self.symbols[name]] = unit
        try:
            return expr.parse(text, {**self.symbols, **coordinates})
        except InputError as error:
            raise InputError(f"{option} {text!r}: {error}") from None

    def vector(self, text: str, option: str, unit: str) -> tuple[sp.Expr, ...]:
        parts = text.split(",")
        if len(parts) != 3:
            raise InputError(f"{option} {text!r}: give 3 components x,y,z, e.g. 0,0,h/2")
        return tuple(self.parse(part, option, unit) for part in parts)


def _checked(option: str, call, *args):
    """Call the inertia module, naming the option when it refuses the input."""
    try:
        return call(*args)
    except InputError as error:
        raise InputError(f"{option}: {error}") from None


def _values(names: _Names, assignments: dict[str, str], shape: str) -> dict:
    """--set values, exact and in SI, each positive and for a name the shape or an option uses."""
    values = {}
    for name, text in assignments.items():
        if name not in names.symbols:
            raise InputError(f"--set {name}: the {shape} has {', '.join(names.symbols)}; {name} is none of them")
        symbol = names.symbols[name]
        unit = names.units[symbol]
        try:
            number, given = units.parse_quantity(text, unit)
            value = units.to_unit(number, given, unit)
        except InputError as error:
            raise InputError(f"--set {name}={text}: {error}") from None
        if value <= 0:
            raise InputError(f"--set {name}={text}: must be positive")
        values[symbol] = value
    if inertia.R1 in values and inertia.R2 in values and values[inertia.R1] >= values[inertia.R2]:
        raise InputError("--set R1: the inner radius must be less than the outer radius R2")
    return values


def report(shape: str, axis: str | None, assignments: dict[str, str], digits: int, about: str | None = None,
           density: str | None = None, show_tensor: bool = False) -> dict:
    """Everything `derive inertia` prints; the keys of `JSON_KEYS` are the JSON output."""
    if shape not in inertia.SHAPES:
        raise InputError(f"SHAPE: unknown shape {shape!r} (shapes: {', '.join(inertia.SHAPES)})"
                         + did_you_mean(shape, inertia.SHAPES))
    body = inertia.SHAPES[shape]
    names = _Names(body)
    axis = axis or inertia.PLANAR_AXIS[shape]
    point = names.vector(about, "--about", "m") if about else None
    if "," in axis:
        line, label = (point or inertia.ORIGIN, names.vector(axis, "--axis", "1")), f"along ({axis})"
    elif axis in body.axes:
        line, label = (axis, axis) if point is None else ((point, body.axes[axis][1]), f"{axis} direction")
    else:
        raise InputError(f"--axis {axis}: a {shape} has axes {', '.join(body.axes)}, or give a direction such as 1,0,0"
                         + did_you_mean(axis, body.axes))
    label += f" through ({about})" if about else ""
    rho = names.parse(density, "--density", "1", body.density_symbols) if density else None
    values = _values(names, assignments, shape)  # checked before anything is integrated
    center = _checked("--density", inertia.center_of_mass, shape, rho)
    result = _checked("--axis", inertia.moment_of_inertia, shape, line, rho)
    tensor = inertia.tensor(shape, point or center, rho) if show_tensor else None
    return {
        "shape": shape,
        "axis": label,
        "integral": sp.latex(result.integral),
        "mass": sp.sstr(result.mass),
        "I": sp.sstr(result.I),
        "ratio": sp.sstr(result.ratio),
        "tensor": None if tensor is None else [[sp.sstr(e) for e in row] for row in tensor.tolist()],
        "value": numeric.evaluate(result.I, values, digits),
        "size": sp.sstr(inertia.M * body.scale**2),
        "tensor_about": f"({about})" if about else f"the center of mass {tuple(center)}",
        "expressions": {"integral": result.integral, "mass_integral": result.mass_integral, "mass": result.mass,
                        "I": result.I, "ratio": result.ratio, "size": inertia.M * body.scale**2, "tensor": tensor},
        "latex": {"mass_integral": sp.latex(result.mass_integral), "mass": sp.latex(result.mass),
                  "I": sp.latex(result.I), "ratio": sp.latex(result.ratio), "size": sp.latex(inertia.M * body.scale**2),
                  "tensor": None if tensor is None else sp.latex(tensor)},
    }


def as_text(r: dict) -> str:
    """The report for a terminal: its integrals and results drawn by sympy's pretty-printer."""
    e = r["expressions"]
    lines = [f"{r['shape']}, axis {r['axis']}"]
    chain = list(dict.fromkeys([e["integral"], e["I"]]))  # a point mass has no integral to show
    lines += indented(pretty("I = ", *[part for x in chain for part in (x, " = ")], e["ratio"], "⋅", e["size"]))
    if e["mass_integral"] != e["mass"]:
        lines += indented(pretty("M = ", e["mass_integral"], " = ", e["mass"]))
    if e["tensor"] is not None:
        lines.append(f"  tensor about {r['tensor_about']}:")
        lines += indented(pretty("I = ", e["tensor"]), "    ")
    if r["value"] is not None:
        lines.append(f"  value: I = {r['value']} kg·m²")
    return "\n".join(lines)


def as_latex(r: dict) -> str:
    tex = r["latex"]
    rows = [f"M &= {tex['mass_integral']} = {tex['mass']}",
            f"I &= {r['integral']} = {tex['I']} = {tex['ratio']}\\,{tex['size']}"]
    if tex["tensor"] is not None:
        rows.append(f"\\mathbf{{I}} &= {tex['tensor']}")
    return "\\begin{align*}\n" + " \\\\\n".join(rows) + "\n\\end{align*}"


def as_json(r: dict) -> str:
    return json.dumps({key: r[key] for key in JSON_KEYS}, indent=2)


FORMATTERS = {"text": as_text, "latex": as_latex, "json": as_json}
