"""Physical units for problem files, on top of ``sympy.physics.units``.

Unit strings come from untrusted files and the command line, so they are parsed like
expressions in ``derive.core.expr`` (an ``ast`` whitelist; ``*``, ``/``, ``**``, ``^``, numbers; a
space between units means multiplication: "kg m^2", "N m"; ``°`` is ``deg``). A name is looked
up in ``UNITS``, else as an attribute of ``sympy.physics.units`` that is a Quantity ("eV",
"day", "lightyear", "inch", ...): never sympified. Conversions are exact (sympy Rationals and
``pi``; a constant sympy stores as a decimal, such as G, is taken at its decimal digits).

Convention: angles are dimensionless, as in SI (and in sympy's ``dimsys_SI``):
``rad`` has dimension {} and ``deg``/``rev``/``rpm`` differ from ``rad``/``rad/s``
only by an exact factor (pi/180, 2*pi, pi/30).  Dimensions are dicts of plain
base-dimension names to exponents, e.g. {"length": 1, "time": -2}; {} is
dimensionless.
"""
from __future__ import annotations

import ast
import decimal
import re
from functools import lru_cache
from typing import Mapping

import sympy
from sympy.core.function import AppliedUndef
from sympy.physics import units as u
from sympy.physics.units import Quantity, convert_to
from sympy.physics.units.systems.si import SI, dimsys_SI
from sympy.printing.pretty import pretty_symbology

from derive.core.errors import InputError
from derive.core.expr import ExprError, _build, _rational, _syntax_tree
from derive.core.spelling import did_you_mean

__all__ = ["UnitError", "UNITS", "parse_unit", "dimension", "si_factor", "in_unit", "declared_symbols", "parse_quantity",
           "to_unit", "expression_dimension", "same_dimension", "latex_unit", "siunitx_unit", "unicode_unit", "superscript",
           "sympy_units"]


class UnitError(InputError):
    """A one-line, human-readable unit problem."""


_REV = 2 * sympy.pi * u.radian
_AU = 149597870700 * u.meter
UNITS: dict[str, sympy.Expr] = {
    "kg": u.kilogram, "g": u.gram, "mg": u.milligram, "t": u.tonne,
    "m": u.meter, "cm": u.centimeter, "mm": u.millimeter, "km": u.kilometer,
    "um": u.micrometer, "nm": u.nanometer,
    "s": u.second, "ms": u.millisecond, "min": u.minute, "h": u.hour,
    "N": u.newton, "J": u.joule, "W": u.watt, "Pa": u.pascal, "Hz": u.hertz,
    "rad": u.radian, "deg": u.degree, "rev": _REV, "rpm": _REV / u.minute,
    "Nm": u.newton * u.meter,
    # sympy's astronomical unit is the value before the IAU fixed it (2012) at exactly 149597870700 m
    "AU": _AU, "au": _AU, "astronomical_unit": _AU, "astronomical_units": _AU,
}
#: N, J, W, Pa and Hz with a prefix of a thousand's power: mN, kJ, MW, GPa, kHz.
PREFIXED: dict[str, sympy.Expr] = {prefix + name: factor * UNITS[name] for name in ("N", "J", "W", "Pa", "Hz")
                                   for prefix, factor in (("m", sympy.Rational(1, 1000)), ("k", 1000),
                                                          ("M", 10**6), ("G", 10**9))}
_SI_BASE = [u.kilogram, u.meter, u.second, u.ampere, u.kelvin, u.mole, u.candela]
_ORDER = ["mass", "length", "time", "current", "temperature", "amount_of_substance",
          "luminous_intensity"]
_MAX_UNIT_LENGTH = 200
_SPACE = re.compile(r"(?<=[\w)])\s+(?=[A-Za-z_(])")
_QUANTITY = re.compile(r"([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)\s*(.*)", re.S | re.ASCII)  # 3, not ٣


def _show(text: str) -> str:
    return repr(text if len(text) <= 40 else text[:37] + "...")


def _unit_tree(text: str) -> tuple[ast.Expression, str]:
    if not isinstance(text, str):
        raise UnitError(f"a unit must be a string, got {type(text).__name__}")
    try:
        return _syntax_tree(_SPACE.sub("*", text.strip().replace("°", " deg ").strip()), _MAX_UNIT_LENGTH)
    except ExprError as e:
        raise UnitError(f"invalid unit {_show(text)}: {e}") from None


@lru_cache(maxsize=1)
def sympy_units() -> dict[str, Quantity]:
    """Every unit sympy.physics.units names (295 in sympy 1.14), by attribute name."""
    return {name: value for name, value in vars(u).items()
            if not name.startswith("_") and isinstance(value, Quantity)}


def _lookup(name: str) -> sympy.Expr:
    if name in UNITS:
        return UNITS[name]
    if name in PREFIXED:
        return PREFIXED[name]
    if name in sympy_units():
        return sympy_units()[name]
    raise UnitError(f"unknown unit '{name}' (known: {', '.join(UNITS)}; N, J, W, Pa and Hz with m, k, M or G before "
                    "them, as kN or MPa; or any name of sympy.physics.units)"
                    + did_you_mean(name, [*UNITS, *PREFIXED, *sympy_units()]))


@lru_cache(maxsize=256)  # a unit string parses to one immutable expression
def parse_unit(text: str) -> sympy.Expr:
    """Parse a unit string: ``parse_unit("m/s^2") == meter/second**2``; "" and "1" give 1."""
    if isinstance(text, str) and text.strip() in ("", "1"):
        return sympy.Integer(1)
    try:
        unit = _build(*_unit_tree(text), _lookup, {})
    except ExprError as e:
        raise UnitError(f"invalid unit {_show(text)}: {e}") from None
    if any(not p.exp.is_Number for p in unit.atoms(sympy.Pow)):
        raise UnitError(f"invalid unit {_show(text)}: exponents must be numbers")
    return unit


def _clean(dim: Mapping) -> dict:
    """Plain-string keys in a fixed order, int exponents where whole, no zeros."""
    out = {str(k): sympy.Rational(v) for k, v in dim.items() if v != 0}
    keys = sorted(out, key=lambda k: (_ORDER.index(k) if k in _ORDER else len(_ORDER), k))
    return {k: int(out[k]) if out[k].is_Integer else out[k] for k in keys}


def _describe(dim: Mapping) -> str:
    if not dim:
        return "dimensionless"
    keys = list(_clean(dim))
    part = lambda k, e: k if e == 1 else f"{k}^{e}"  # noqa: E731
    num = "*".join(part(k, dim[k]) for k in keys if dim[k] > 0) or "1"
    den = "*".join(part(k, -dim[k]) for k in keys if dim[k] < 0)
    return f"{num}/{den}" if den else num


def dimension(unit: sympy.Expr | str) -> dict:
    """Base-dimension exponents of a unit, e.g. {"length": 1, "time": -2}; {} if dimensionless."""
    unit = parse_unit(unit) if isinstance(unit, str) else unit
    deps = dimsys_SI.get_dimensional_dependencies(SI.get_dimensional_expr(unit))
    return _clean({d.name: e for d, e in deps.items()})


def same_dimension(a: Mapping, b: Mapping) -> bool:
    return _clean(a) == _clean(b)


def _quantity_factor(q: Quantity) -> sympy.Expr:
    # convert_to mishandles dimensionless targets (1 -> radian, deg**2 -> rad), so convert per quantity
    if dimension(q):
        f = convert_to(q, _SI_BASE).xreplace({b: sympy.Integer(1) for b in _SI_BASE})
    else:
        f = convert_to(q, u.radian).xreplace({u.radian: sympy.Integer(1)})
    if f.atoms(Quantity):
        raise UnitError(f"cannot express {q} in SI units")
    return f.xreplace({x: sympy.Rational(str(x)) for x in f.atoms(sympy.Float)})


@lru_cache(maxsize=256)
def si_factor(unit: sympy.Expr | str) -> sympy.Expr:
    """Exact factor to the coherent SI unit: g -> 1/1000, deg -> pi/180, rpm -> pi/30."""
    unit = parse_unit(unit) if isinstance(unit, str) else unit
    return unit.xreplace({q: _quantity_factor(q) for q in unit.atoms(Quantity)})


def in_unit(value_si: sympy.Expr, unit: str) -> sympy.Expr:
    """An answer derived in SI, as a number of `unit`: what a key gives, and what its formula is
    printed as (an angle asked in deg is 180/pi times the radians; turns in rev, 1/(2 pi) of them).

    >>> in_unit(sympy.Symbol("x"), "deg"), in_unit(sympy.Integer(3), "N")
    (180*x/pi, 3)
    """
    factor = si_factor(unit)
    return value_si if factor == 1 else value_si / factor


#: Units a parameter's symbol stands for in a printed formula, not for its SI value: a number of turns (N
#: rev is 2 pi N rad) and a rate of them; an angle in degrees outside a sine or cosine (inside one,
#: sin(theta) with theta in degrees is how a textbook writes it).
COUNTED = ("rev", "rpm")


def declared_symbols(expression: sympy.Expr, units_of: dict) -> sympy.Expr:
    """A formula derived in SI, written in the parameters' declared units where a reader counts in them:
    each parameter in rev or rpm (and in deg, outside a trigonometric function) is its SI value, so the
    formula holds the symbol times its unit's factor.

    >>> N, theta = sympy.symbols("N theta", positive=True)
    >>> declared_symbols(N * sympy.sin(theta) + theta, {N: "rev", theta: "deg"})
    2*pi*N*sin(theta) + pi*theta/180
    """
    factors = {s: si_factor(u) for s, u in units_of.items()
               if s in expression.free_symbols and (u in COUNTED or u == "deg")}
    if not factors:
        return expression
    trig = {t: sympy.Dummy() for t in expression.atoms(sympy.sin, sympy.cos, sympy.tan)
            if any(units_of.get(s) == "deg" for s in t.free_symbols)}
    scaled = expression.xreplace(trig).xreplace({s: s * f for s, f in factors.items()})
    return scaled.xreplace({d: t for t, d in trig.items()})


def _exact(value) -> sympy.Expr:
    """Exact sympy number for a decimal string, int, float or Decimal (sympy input passes through)."""
    if isinstance(value, sympy.Basic):
        return value
    if isinstance(value, bool) or not isinstance(value, (str, int, float, decimal.Decimal)):
        raise UnitError(f"expected a number, got {type(value).__name__}")
    try:
        return _rational(repr(value) if isinstance(value, float) else str(value))
    except ExprError as e:
        raise UnitError(str(e)) from None


def parse_quantity(text: str | int | float | decimal.Decimal,
                   default_unit: str) -> tuple[sympy.Expr, str]:
    """Split "200 g" into (Rational(200), "g"); a bare number gets ``default_unit``."""
    if isinstance(text, str):
        m = _QUANTITY.fullmatch(text.strip()) if len(text) <= 1000 else None
        if not m and any(c.isdigit() and not c.isascii() for c in text):  # as a problem file reads numbers
            raise UnitError(f"a number is written with the digits 0-9, got {_show(text.strip())}")
        if not m:
            raise UnitError(f"expected a number and a unit, got {_show(text.strip())}")
        value, unit = _exact(m.group(1)), m.group(2).strip() or default_unit
    else:
        value, unit = _exact(text), default_unit
    parse_unit(unit)  # validate
    return value, unit


def to_unit(value: sympy.Expr, from_unit: str, to_unit: str) -> sympy.Expr:
    """Exactly convert ``value`` from one unit to another: to_unit(200, "g", "kg") == 1/5."""
    a, b = parse_unit(from_unit), parse_unit(to_unit)
    da, db = dimension(a), dimension(b)
    if da != db:
        raise UnitError(f"cannot convert {from_unit} to {to_unit}: {_describe(da)} vs {_describe(db)}")
    return _exact(value) * si_factor(a) / si_factor(b)


def _scale(dim: Mapping, k: sympy.Expr) -> dict:
    return _clean({n: e * k for n, e in dim.items()})


def _add(a: Mapping, b: Mapping) -> dict:
    return _clean({n: a.get(n, 0) + b.get(n, 0) for n in {*a, *b}})


def expression_dimension(expr: sympy.Expr, symbol_units: Mapping[sympy.Symbol, str]) -> dict:
    """Dimension of ``expr`` whose symbols carry ``symbol_units``; UnitError if inconsistent.

    Keys of ``symbol_units`` may also be applied functions or other subexpressions,
    e.g. ``theta(t)``; derivatives divide by the dimension of the variable.
    """
    # hand-written: sympy's dimension checker works only on Quantities (not Symbols carrying
    # units), is private (SI._collect_factor_and_dimension) and gives unhelpful messages
    dims = {k: dimension(parse_unit(v)) for k, v in symbol_units.items()}

    def walk(e: sympy.Expr) -> dict:
        if e in dims:
            return dims[e]
        if isinstance(e, Quantity):
            return dimension(e)
        if e.is_Symbol:
            raise UnitError(f"symbol '{e}' has no unit")
        if e.is_Number or isinstance(e, sympy.NumberSymbol):
            return {}
        if e.is_Add:
            first, *rest = [walk(a) for a in e.args]
            for d in rest:
                if d != first:
                    raise UnitError(f"adds {_describe(first)} to {_describe(d)}")
            return first
        if e.is_Mul:
            out: dict = {}
            for a in e.args:
                out = _add(out, walk(a))
            return out
        if e.is_Pow:
            base, ex = walk(e.base), walk(e.exp)
            if ex:
                raise UnitError(f"exponent has dimension {_describe(ex)}")
            if base and not e.exp.is_Rational:
                raise UnitError(f"{_describe(base)} raised to a non-numeric power {e.exp}")
            return _scale(base, e.exp) if base else {}
        if isinstance(e, sympy.Derivative):
            out = walk(e.expr)
            for var, n in e.variable_count:
                out = _add(out, _scale(walk(var), -n))
            return out
        if isinstance(e, sympy.Abs):
            return walk(e.args[0])
        if isinstance(e, sympy.Integral):  # each variable has the dimension of its limits
            for var, *ends in e.limits:
                dims[var] = walk(next((end for end in ends if end != 0), sympy.Integer(0)))
            out = walk(e.function)
            for var, *_ in e.limits:
                out = _add(out, dims.pop(var))
            return out
        if isinstance(e, sympy.Piecewise):  # each branch the same; each condition consistent
            found = [walk(value) for value, _ in e.args if value != 0]  # zero has every dimension
            first, *rest = found or [{}]
            for d in rest:
                if d != first:
                    raise UnitError(f"one case has {_describe(first)}, another {_describe(d)}")
            for _, condition in e.args:
                for relation in condition.atoms(sympy.core.relational.Relational):
                    walk(relation.lhs - relation.rhs)
            return first
        if isinstance(e, sympy.atan2):  # the angle of a point: its coordinates alike, any dimension
            found = [walk(a) for a in e.args if a != 0]  # zero has every dimension
            if len(found) == 2 and found[0] != found[1]:
                raise UnitError(f"atan2() of {_describe(found[0])} and {_describe(found[1])}; its arguments "
                                "must have one dimension")
            return {}
        if isinstance(e, sympy.Function) and not isinstance(e, AppliedUndef):  # sin, exp, log, ...
            for d in map(walk, e.args):
                if d:
                    raise UnitError(f"{e.func.__name__}() of {_describe(d)}; "
                                    "its argument must be dimensionless")
            return {}
        raise UnitError(f"cannot find the dimension of {e} (unit not declared?)")

    return walk(_exact(expr))


def _written(text: str, name, times: str, power) -> str:
    """A unit written out by the rules given: `name(unit name)`, the product's separator and
    `power(base, exponent)`; "" for a pure number ("" or "1"). The one walk of the unit's syntax
    tree behind latex_unit and unicode_unit."""
    if isinstance(text, str) and text.strip() in ("", "1"):
        return ""
    parse_unit(text)  # validates everything below
    tree, source = _unit_tree(text)

    def write(n: ast.AST) -> str:
        if isinstance(n, ast.Name):
            return name(n.id)
        if isinstance(n, ast.Constant):
            return ast.get_source_segment(source, n)
        if isinstance(n, ast.UnaryOp):
            return ("-" if isinstance(n.op, ast.USub) else "") + write(n.operand)
        group = lambda c: f"({write(c)})" if isinstance(c, (ast.BinOp, ast.UnaryOp)) else write(c)  # noqa: E731
        if isinstance(n.op, (ast.Pow, ast.BitXor)):
            return power(group(n.left), write(n.right))
        if isinstance(n.op, ast.Div):
            right = write(n.right) if isinstance(n.right, ast.BinOp) and isinstance(n.right.op, ast.Pow) \
                else group(n.right)
            return f"{write(n.left)}/{right}"
        right = group(n.right) if isinstance(n.right, ast.BinOp) and isinstance(n.right.op, ast.Div) \
            else write(n.right)
        return f"{write(n.left)}{times}{right}"

    return write(tree.body)


_DEGREES = ("deg", "degree", "degrees")


def after_number(text: str, tex: str) -> str:
    r"""What follows a number in a unit `text` typeset as `tex` (latex_unit or siunitx_unit): a thin
    space and the unit, but nothing between a number and a degree sign (30°, as SI writes it), whose
    superscript then rests on the number: latex_unit's empty base `{}`, which a unit alone needs, is
    an empty box in pandoc's DOCX (25.0□°).

    >>> after_number("kg", r"\mathrm{kg}"), after_number("deg", r"{}^{\circ}"), after_number("1", "")
    ('\\,\\mathrm{kg}', '^{\\circ}', '')
    """
    if text.strip() in _DEGREES:
        return tex.removeprefix("{}")
    return tex and r"\," + tex


def _tex_name(name: str) -> str:
    """A unit's name as TeX text: sympy's long names have underscores (astronomical_unit)."""
    return name.replace("_", r"\_")


@lru_cache(maxsize=256)  # a unit is typeset in every variant
def latex_unit(text: str) -> str:
    r"""LaTeX (math mode, amsmath only) for a unit: "m/s^2" -> r"\mathrm{m}/\mathrm{s}^{2}".

    For what pandoc converts (HTML, Markdown, DOCX) and MathJax shows (the LMS questions): neither
    reads siunitx (pandoc's texmath takes its literal units for italic letters). The PDFs use
    siunitx_unit.

    >>> latex_unit("kg*m^2"), latex_unit("1")
    ('\\mathrm{kg}\\,\\mathrm{m}^{2}', '')
    """
    special = {**dict.fromkeys(_DEGREES, r"{}^{\circ}"), "um": r"\mu\mathrm{m}"}
    return _written(text, lambda n: special.get(n, rf"\mathrm{{{_tex_name(n)}}}"), r"\,", lambda b, e: f"{b}^{{{e}}}")


@lru_cache(maxsize=256)
def siunitx_unit(text: str) -> str:
    r"""A unit for the documents LaTeX compiles: siunitx's ``\unit`` in its literal form (``.`` a
    product, ``/`` as written, ``^{}`` a power; ``\degree`` and ``\micro`` its own), so the PDFs'
    units follow one typographic convention (upright, thin spaces) and siunitx sets the spacing.

    >>> siunitx_unit("kg*m^2/s"), siunitx_unit("um"), siunitx_unit("1")
    ('\\unit{kg.m^{2}/s}', '\\unit{\\micro m}', '')
    """
    special = {**dict.fromkeys(_DEGREES, r"\degree"), "um": r"\micro m"}
    written = _written(text, lambda n: special.get(n, _tex_name(n)), ".", lambda b, e: f"{b}^{{{e}}}")
    return rf"\unit{{{written}}}" if written else ""


def superscript(text: str) -> str | None:
    """`text` in Unicode superscript characters (sympy's pretty printer's own table), or None
    where one has none (a `/` or a `.`).

    >>> superscript("-27"), superscript("1/2")
    ('⁻²⁷', None)
    """
    written = [pretty_symbology.sup.get(c) for c in text]
    return None if None in written else "".join(written)


@lru_cache(maxsize=256)  # a unit is written in every row of key.csv
def unicode_unit(text: str) -> str:
    """A unit as plain text reads it: "kg*m^2" -> "kg·m²", "m/s^2" -> "m/s²"; "" for a pure number.
    An exponent with no superscript form stays `^(1/2)`.

    sympy's pretty printer would spell the units out (kilogram⋅meter²) and reorder them, so the
    unit is written as its author wrote it, by the walk that writes its LaTeX.

    >>> unicode_unit("kg*m^2/s"), unicode_unit("N m"), unicode_unit("1/s"), unicode_unit("1")
    ('kg·m²/s', 'N·m', '1/s', '')
    """
    special = {**dict.fromkeys(_DEGREES, "°"), "um": "μm"}

    def power(base: str, exponent: str) -> str:
        raised = superscript(exponent)
        return base + raised if raised else f"{base}^({exponent})"

    return _written(text, lambda n: special.get(n, n), "·", power)
