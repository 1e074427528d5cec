"""`derive inertia SHAPE`: the integral, the mass from the same density, I and I/(M size^2).

>>> report("rod", "end", {}, 15)["ratio"]
'1/3'
"""
from __future__ import annotations

import json

import sympy as sp

from derive import inertia, numeric, units
from derive.errors import InputError

SIZE_UNITS = {"M": "kg", "L": "m", "R": "m"}


def report(shape: str, axis: str | None, assignments: dict[str, str], digits: int) -> dict:
    if shape not in inertia.SHAPES:
        raise InputError(f"inertia: unknown shape {shape!r} (shapes: {', '.join(inertia.SHAPES)})")
    axis = axis or inertia.PLANAR_AXIS[shape]
    if axis not in inertia.SHAPES[shape].axes:
        raise InputError(f"inertia: --axis of a {shape} is one of: {', '.join(inertia.SHAPES[shape].axes)}")
    result = inertia.moment_of_inertia(shape, axis)
    symbols = {str(s): s for s in result.I.free_symbols}
    values = {}
    for name, text in assignments.items():
        if name not in symbols:
            raise InputError(f"--set {name}: a {shape} has parameters {', '.join(sorted(symbols))}")
        number, unit = units.parse_quantity(text, SIZE_UNITS[name])
        value = units.to_unit(number, unit, SIZE_UNITS[name])
        if value <= 0:
            raise InputError(f"--set {name}={text}: must be positive")
        values[symbols[name]] = value
    return {
        "shape": shape,
        "axis": axis,
        "integral": sp.latex(result.integral),
        "mass": sp.latex(result.mass_integral),
        "I": sp.sstr(result.I),
        "I_latex": sp.latex(result.I),
        "ratio": sp.sstr(result.ratio),
        "value": numeric.evaluate(result.I, values, digits),
        "unit": "kg*m^2",
    }


def as_text(r: dict) -> str:
    value = f"\n  value    = {r['value']} {r['unit']}" if r["value"] else ""
    return (
        f"{r['shape']} about its {r['axis']} axis\n"
        f"  integral : {r['integral']}\n  mass     : M = {r['mass']}\n"
        f"  I        = {r['I']}  ({r['ratio']} of M size^2){value}"
    )


def as_latex(r: dict) -> str:
    return f"\\begin{{align*}}\nM &= {r['mass']} \\\\\nI &= {r['integral']} = {r['I_latex']}\n\\end{{align*}}"


FORMATTERS = {"text": as_text, "latex": as_latex, "json": lambda r: json.dumps(r, indent=2)}
