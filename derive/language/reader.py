"""Reading a problem file's fields: safe YAML, and one-line errors naming the file and field.

The YAML loader keeps decimals exact, refuses duplicate keys and reads only true/false as
booleans. The Reader checks mappings, texts, expressions (through `derive.core.expr`), units and
dimensions, and names `FILE: FIELD` in every error.

>>> safe_load("m: 0.1")["m"]
Decimal('0.1')
"""
from __future__ import annotations

import re
from decimal import Decimal
from pathlib import Path

import sympy as sp
import yaml

from derive.core import expr, names, units
from derive.numbers import intervals
from derive.text import latex_safety
from derive.core.errors import ProblemError
from derive.core.keys import Keys
from derive.core.spelling import did_you_mean

MAX_CHARACTERS = 200_000  # a library problem file is a few thousand
MAX_NESTING = 40  # a problem file nests 4 or 5 levels deep


#: libyaml's parser (PyYAML's wheels carry it) where there is one: the pure-Python one took 13 ms a
#: problem file, a tenth of a warm build's time per problem; the constructors stay Python's (below).
_PARSER = yaml.CSafeLoader if yaml.__with_libyaml__ else yaml.SafeLoader


class Loader(_PARSER):
    """Safe YAML that keeps decimals exact (as Decimal), refuses duplicate keys, and reads
    only true/false as booleans (YAML 1.2), so that `on:` and `no` stay words. Read a text with
    `safe_load`, which refuses hostile input first."""

    def get_single_data(self):
        try:
            return super().get_single_data()
        except yaml.YAMLError:
            raise
        except (ValueError, TypeError, AttributeError, ArithmeticError, RecursionError, MemoryError) as error:
            reason = str(error).splitlines()[0] if str(error) else type(error).__name__
            raise yaml.constructor.ConstructorError(None, None, f"cannot read a value: {reason}") from None


def safe_load(text: str):
    """A problem or set file's YAML, read by `Loader`. Hostile input fails fast with a
    yaml.YAMLError, from the parser's events, before any node is composed: a text over
    MAX_CHARACTERS, nesting deeper than MAX_NESTING, any alias (`*name`: no billion laughs); then
    a value no constructor can make (`.inf`, `!!timestamp junk`, an integer of 5000 digits).

    >>> safe_load("a: [1, 2]")["a"]
    [1, 2]
    """
    if len(text) > MAX_CHARACTERS:
        raise yaml.YAMLError(f"the file has {len(text)} characters (limit {MAX_CHARACTERS})")
    depth = 0
    for event in yaml.parse(text, Loader=_PARSER):
        if isinstance(event, yaml.AliasEvent):
            raise yaml.composer.ComposerError(None, None, "aliases (*name) are not allowed", event.start_mark)
        if isinstance(event, yaml.CollectionStartEvent):
            depth += 1
            if depth > MAX_NESTING:
                raise yaml.composer.ComposerError(None, None, f"nested deeper than {MAX_NESTING} levels",
                                                  event.start_mark)
        elif isinstance(event, yaml.CollectionEndEvent):
            depth -= 1
    return yaml.load(text, Loader=Loader)  # noqa: S506 - Loader is a SafeLoader


Loader.yaml_implicit_resolvers = {
    first: [(tag, regexp) for tag, regexp in resolvers if tag != "tag:yaml.org,2002:bool"]
    for first, resolvers in yaml.SafeLoader.yaml_implicit_resolvers.items()
}
Loader.add_implicit_resolver("tag:yaml.org,2002:bool", re.compile(r"^(?:true|True|TRUE|false|False|FALSE)$"),
                              list("tTfF"))


def _decimal(loader: yaml.SafeLoader, node: yaml.Node) -> Decimal:
    text = loader.construct_scalar(node)
    try:
        value = Decimal(text.replace("_", ""))
    except ArithmeticError:  # .inf, .nan: YAML floats that are no decimals
        value = None
    if value is None or not value.is_finite():
        raise yaml.constructor.ConstructorError(None, None, f"{text!r} is not a finite number", node.start_mark)
    return value


def _mapping(loader: yaml.SafeLoader, node: yaml.MappingNode) -> dict:
    seen = set()
    for key_node, _ in node.value:
        key = loader.construct_object(key_node)
        if not isinstance(key, (str, int, Decimal)) or isinstance(key, bool):
            raise yaml.constructor.ConstructorError(None, None, f"a key must be a name, not {type(key).__name__}",
                                                    key_node.start_mark)
        if key in seen:
            raise yaml.constructor.ConstructorError(None, None, f"duplicate key {key!r}", key_node.start_mark)
        seen.add(key)
    return loader.construct_mapping(node, deep=True)


Loader.add_constructor("tag:yaml.org,2002:float", _decimal)
Loader.add_constructor("tag:yaml.org,2002:map", _mapping)


#: Keys whose values are names (of shapes, bodies, parameters, asks, sides): text, never a list.
NAME_KEYS = frozenset({"shape", "zero_for", "exact", "on", "contact", "wound_on", "hangs", "side", "body", "to",
                       "off", "relative_to", "of", "holds"})


NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*")


class Reader:
    """Reads one problem file, naming the file and the field in every error."""

    def __init__(self, path: Path):
        self.path = path
        self.symbols: dict[str, sp.Symbol] = {}
        self.symbol_units: dict[sp.Symbol, str] = {}
        self.parameters: dict = {}  # name -> derive.language.problem.Parameter, as they are read
        self.used: set[sp.Symbol] = set()  # the symbols the expressions read so far name
        self.held_to_range: set[sp.Symbol] = set()  # parameters a sign was proven over the ranges of

    def fail(self, field: str, message: str) -> ProblemError:
        return ProblemError(f"{self.path}: {field}: {message}")

    def mapping(self, value, field: str, required=(), optional=(), free: bool = False, points=(),
                keys: Keys | None = None) -> dict:
        """A mapping with the given keys, or those `keys` declares (derive.core.keys); `free` allows
        any keys (names of parameters, bodies, ...); `points`: keys whose values are points
        (`BODY.POINT`, `{BODY: [x, y]}`, `[x, y]`), which `derive.parts.places` reads, rather than names."""
        if keys is not None:
            required, optional = keys.required, (*optional, *keys.optional)
            points = (*points, *(name for name, key in keys.items() if key.kind == "point"))
        if not isinstance(value, dict):
            raise self.fail(field, f"expected a mapping, got {type(value).__name__}")
        unknown = [] if free else [k for k in value if k not in required and k not in optional]
        if unknown:
            allowed = ", ".join(sorted({*required, *optional}))
            raise self.fail(f"{field}.{unknown[0]}" if field else str(unknown[0]),
                            f"unknown key (allowed: {allowed})" + did_you_mean(unknown[0], {*required, *optional}))
        for key in required:
            if key not in value:
                raise self.fail(f"{field}.{key}" if field else key, "missing")
        for key in () if free else NAME_KEYS.difference(points).intersection(value):  # looked up in tables
            if not isinstance(value[key], str):
                raise self.fail(f"{field}.{key}" if field else key, f"expected a name, got {type(value[key]).__name__}")
        return value

    def name(self, value, field: str, what: str) -> str:
        """A name the file declares (a parameter, an ask, a body, ...): ASCII letters, digits and
        _, starting with a letter; a look-alike such as a fullwidth `ｍ` is refused (derive.core.names)."""
        if isinstance(value, str):
            try:
                names.check(value, what)
            except ValueError as error:
                raise self.fail(field, str(error)) from None
        if not isinstance(value, str) or not NAME.fullmatch(value):
            raise self.fail(field, f"{what} is a letter followed by letters, digits or _")
        return value

    def named(self, raw, section: str) -> dict:
        """A section of the scene that maps declared names to their specs (`scene.joints`,
        `scene.states`, ...): a mapping, possibly absent, every key a name."""
        raw = self.mapping(raw or {}, f"scene.{section}", free=True)
        for name in raw:
            self.name(name, f"scene.{section}.{name}", f"a name in {section}")
        return raw

    def text(self, value, field: str, limit: int) -> str:
        """Non-empty text of at most `limit` characters that TeX may safely see
        (derive.text.latex_safety): plain text, but for the `question` field, checked as LaTeX with
        `{{ NAME }}` placeholders of the parameters read so far."""
        if not isinstance(value, str) or not value.strip():
            raise self.fail(field, "expected non-empty text")
        try:
            if field == "question":
                latex_safety.check_question(value, self.parameters, limit)
            else:
                latex_safety.check_plain(value, limit)
        except latex_safety.LatexError as error:
            raise self.fail(field, str(error)) from None
        return value

    def expression(self, value, field: str, allowed=None) -> sp.Expr:
        try:
            result = expr.parse(value, self.symbols if allowed is None else allowed)
        except expr.ExprError as error:
            raise self.fail(field, str(error)) from None
        except TypeError:
            raise self.fail(field, f"expected an expression, got {type(value).__name__}") from None
        if not result.free_symbols and result.is_extended_real is not True:  # sqrt(-1), log(-1)
            raise self.fail(field, f"{result} is not a real number")
        self.used |= result.free_symbols
        return result

    def unit(self, value, field: str) -> str:
        text = self.text(value, field, latex_safety.NAME_LIMIT) if not isinstance(value, (int, Decimal)) else str(value)
        try:
            units.parse_unit(text)
        except units.UnitError as error:
            raise self.fail(field, str(error)) from None
        return text

    def dimensioned(self, value, field: str, unit: str, what: str, allowed=None) -> sp.Expr:
        """An expression of declared (or `allowed`) symbols that must have the dimension of `unit`."""
        result = self.expression(value, field, allowed)
        if result == 0:  # zero has every dimension
            return result
        try:
            found = units.expression_dimension(result, self.symbol_units)
        except units.UnitError as error:
            raise self.fail(field, str(error)) from None
        wanted = units.dimension(units.parse_unit(unit))
        if not units.same_dimension(found, wanted):
            bare = "" if result.free_symbols else (f": a bare number other than 0 has no unit (an expression takes none); "
                                                   f"write it with a parameter in {unit}, or as a multiple of one")
            raise self.fail(field, f"{what} must have the dimension of {unit}, but {result} has {describe(found)}{bare}")
        return result

    def vector(self, value, field: str, unit: str = "m", what: str = "a coordinate",
               where: str = "") -> tuple[sp.Expr, sp.Expr]:
        """`[x, y]`, each of the dimension of `unit` (`where`: the frame, for the error)."""
        if not isinstance(value, list) or len(value) != 2:
            raise self.fail(field, f"expected [x, y]{where}")
        return tuple(self.dimensioned(v, field, unit, what) for v in value)

    def unspecified(self, name: str, unit: str) -> sp.Symbol:
        """A positive symbol for a size the problem leaves open; answers must not depend on it."""
        symbol = sp.Symbol(name, positive=True)
        self.symbol_units[symbol] = unit
        return symbol

    def positive(self, value, field: str, unit: str, what: str) -> sp.Expr:
        """An expression of the dimension of `unit`, positive for every value the parameters may take:
        by sympy's assumptions, else proven in balls over the ranges the file declares (d*sin(theta)
        with theta in [0.05, 0.15]; sympy knows only that theta is positive)."""
        result = self.dimensioned(value, field, unit, what)
        if result.is_positive is not True and not self.proven_over_ranges(result):
            raise self.fail(field, f"{what} must be positive for every allowed parameter value (got {result})")
        return result


    def proven_over_ranges(self, expression: sp.Expr, strict: bool = True) -> bool:
        """Whether `expression` is proven positive (not `strict`: not negative) over the declared
        ranges of the parameters it uses (each its SI ends); False where it uses a symbol that is no
        parameter read so far. The parameters are then held to their ranges (Problem.values)."""
        ends = {p.symbol: p.si_ends for p in self.parameters.values()}
        proven = expression.free_symbols <= set(ends) and intervals.positive_over(
            expression, {s: ends[s] for s in expression.free_symbols}, strict)
        if proven:  # a value given outside its range (derive solve --set) could break it
            self.held_to_range |= expression.free_symbols
        return proven


def describe(dimension: dict) -> str:
    return " ".join(f"{k}^{v}" if v != 1 else k for k, v in sorted(dimension.items())) or "no dimension"

