"""Problem files (YAML) into validated Problem objects.

A problem file declares parameters (meaning, unit, a value or a range, significant
figures), a scene (bodies, constraints, loads), the quantities it asks for and the
question text. Every expression goes through `derive.core.expr` (never eval or sympify),
every unit through `derive.core.units`; anything wrong is a ProblemError whose one-line
message names the file and the field.

>>> problem = load("string_wrapped_disk")
>>> sorted(problem.asks)
['T', 'a', 'alpha']
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field as dataclass_field
from decimal import ROUND_CEILING, ROUND_FLOOR, Context, Decimal, localcontext
from functools import cached_property
from pathlib import Path
from types import SimpleNamespace

import sympy as sp
import yaml

from derive.core import expr, library, units
from derive.numbers import numeric
from derive.text.latex_safety import (CORRECTION_LIMIT, MEANING_LIMIT, NAME_LIMIT, QUESTION_LIMIT, SOURCE_LIMIT, TITLE_LIMIT, TOPIC_LIMIT)
from derive.core.errors import EngineLimit, ProblemError
from derive.core.keys import Key, Keys
from derive import quantities
from derive.language import amounts, ask_options, ask_states, derivation_source, labels
from derive.language.reader import Reader, safe_load
from derive.parts.contact import Contact
from derive.model.scene import Quantity, Scene, parse_quantity
from derive.language.scene_file import SCENE, read_scene
from derive.core.spelling import did_you_mean

DEFAULT_SIG_FIGS = 3
#: A parameter's entry under `parameters:`.
PARAMETER = Keys(meaning=Key("text", "what it is, in words", required=True),
                 unit=Key("text", "its unit (kg, m, rad, deg, m/s^2, ...); may be left out where the value or the "
                                  "range's ends are written with one (value: 25°)"),
                 value=Key("quantity", "a fixed value (or give a range)"),
                 range=Key("list", "[low, high]: each variant draws a value in it"),
                 sig_figs=Key("integer", "significant figures of a drawn value, 1 to 15 (default 3)"))
CONDITION = Keys(holds=Key("text", "an inequality among parameters and asks, in SI (mu_s >= mu_min)", required=True),
                 because=Key("text", "why the answers need it", required=True))
CORRECTION = Keys(where=Key("text", "where in the notes", required=True),
                  notes=Key("text", "what the notes say", required=True),
                  derived=Key("text", "what derive derives", required=True),
                  proof=Key("text", "the test that proves it"))
#: The top level of a problem file (the scene's keys: derive.language.scene_file.SCENE).
PROBLEM = Keys(id=Key("text", "its id: letters, digits and _", required=True),
               title=Key("text", "its title", required=True),
               topic=Key("text", "its topic (derive list --topic)"),
               source=Key("text", "where the setup comes from"),
               difficulty=Key("name", "easy, medium or hard (derive list --difficulty)", choices=labels.DIFFICULTIES),
               tags=Key("list", "words an instructor filters on (derive list --tag), each one of derive.language.labels.TAGS"),
               parameters=Key("mapping", "the parameters, by name", required=True, values=PARAMETER),
               scene=Key("mapping", "the physical setup", required=True, keys=SCENE),
               ask=Key("mapping", "the quantities asked, by name", required=True, values=ask_options.ASK),
               question=Key("text", "the question for students (LaTeX; {{ NAME }} prints a parameter)", required=True),
               corrections=Key("list", "errors of the notes this problem corrects", items=CORRECTION),
               conditions=Key("list", "what the answers need to make sense; a variant is redrawn until they hold",
                              items=CONDITION))
def exact_decimal(value: sp.Expr) -> Decimal:
    """A number of a problem file as a decimal: exact for a decimal literal, 60 digits otherwise.

    >>> exact_decimal(sp.Rational(3, 10**330)), exact_decimal(sp.pi / 4)
    (Decimal('3E-330'), Decimal('0.785398163397448309615660845819875721049292349843776455243736'))
    """
    with localcontext() as context:
        context.prec = 60
        if value.is_Rational:
            return Decimal(value.p) / Decimal(value.q)
        return Decimal(str(sp.N(value, 60)))


def _figures(value: sp.Expr) -> int | None:
    """The significant figures of a value written as a decimal (at most 15), None for another
    number (pi/6, 1/3: printed rounded, as any reader would).

    >>> _figures(sp.Rational(1829, 100)), _figures(sp.Integer(1800)), _figures(sp.pi / 6)
    (4, 2, None)
    """
    if not value.is_Rational or value == 0 or any(p not in (2, 5) for p in sp.factorint(value.q)):
        return None
    with localcontext() as context:
        context.prec = 60
        return min(len((Decimal(abs(value.p)) / Decimal(value.q)).normalize().as_tuple().digits), 15)


_WIDE = Context(prec=60)  # a draw's arithmetic: room for any range's digits
_FRACTION = Context(prec=28)  # a draw's fraction: the decimal module's default, which it once read
_TWO_64, _FIVE_64 = Decimal(2**64), 5**64


@dataclass(frozen=True)
class Parameter:
    name: str
    symbol: sp.Symbol
    meaning: str
    unit: str
    value: sp.Expr | None
    range: tuple[sp.Expr, sp.Expr] | None
    sig_figs: int

    @cached_property
    def si_ends(self) -> tuple[sp.Expr, sp.Expr]:
        """The least and greatest value in SI units, what the derivation's symbol stands for: the
        range's ends, or the fixed value twice (a range of 10 to 30 deg is 10*pi/180 to 30*pi/180).

        >>> Parameter("t", sp.Symbol("t"), "tilt", "deg", None, (sp.Integer(10), sp.Integer(30)), 2).si_ends
        (pi/18, pi/6)
        """
        factor = units.si_factor(units.parse_unit(self.unit))
        low, high = self.range or (self.value, self.value)
        return low * factor, high * factor

    def bounds(self) -> tuple[Decimal, Decimal]:
        """The range's ends rounded inward to the significant figures: every draw lies between
        them (a range that holds no such value is refused when the file is read)."""
        return self._bounds

    @cached_property
    def _bounds(self) -> tuple[Decimal, Decimal]:  # one parameter is drawn for every variant
        low, high = (exact_decimal(v) for v in self.range)
        return (Decimal(numeric.round_decimal(low, self.sig_figs, ROUND_CEILING)),
                Decimal(numeric.round_decimal(high, self.sig_figs, ROUND_FLOOR)))

    def at(self, fraction: Decimal) -> sp.Rational:
        """The value this fraction (0 to 1) of the way through the range, rounded to the
        significant figures: exact decimals throughout, never a float, so any range the file
        may give (1e-320 kg, 1e400 kg) is drawn inside itself."""
        low, high = self.bounds()
        value = Decimal(numeric.round_decimal(_WIDE.add(low, _WIDE.multiply(_WIDE.subtract(high, low), fraction)),
                                              self.sig_figs))
        return sp.Rational(*min(max(value, low), high).as_integer_ratio())

    def draw(self, rng) -> sp.Rational:
        """A value drawn uniformly from the range by `rng` (a random.Random): `at` the fraction
        k / 2**64 of 64 random bits k, rounded to 28 digits (_FRACTION: every variant's draw since
        the first). By integers where no step of `at` rounds (_exact_steps), else by `at` itself.

        >>> import random
        >>> p = Parameter("m", sp.Symbol("m"), "mass", "kg", None, (sp.Integer(1), sp.Integer(5)), 3)
        >>> p.draw(random.Random(1)) == p.at(_FRACTION.divide(Decimal(random.Random(1).getrandbits(64)), _TWO_64))
        True
        """
        bits = rng.getrandbits(64)
        if self._exact_steps is None:
            return self.at(_FRACTION.divide(Decimal(bits), _TWO_64))
        low, high, exponent = self._exact_steps
        if not bits:
            return sp.Rational(*self.bounds()[0].as_integer_ratio())
        # Hand-written: the decimal module's steps cost 1.8 us a draw, and a set draws thousands.
        # k / 2**64 = k * 5**64 / 10**64, rounded to 28 digits as significand * 10**power:
        significand, power = numeric.rounded(bits * _FIVE_64, 28)
        whole = low * numeric.POWERS[64 - power] + (high - low) * significand  # the value, times 10**-exponent
        exponent += power - 64
        digits, place = numeric.rounded(abs(whole), self.sig_figs) if whole else (0, 0)
        place += exponent
        value = digits if whole > 0 else -digits
        return sp.Integer(value * numeric.POWERS[place]) if place >= 0 else sp.Rational(value, numeric.POWERS[-place])

    @cached_property
    def _exact_steps(self) -> tuple[int, int, int] | None:
        """The range's ends as whole numbers times one power of ten, (low, high, exponent), where
        every step of `at` is exact, the 60 digits of _WIDE holding each: from the fraction's
        lowest digit (10**-47: 28 digits of at least 2**-64) times the ends' to the ends' highest
        and one more (a carry). None where they are not (a range 1e-300 to 1e300)."""
        low, high = self.bounds()
        exponent = min(low.as_tuple().exponent, high.as_tuple().exponent)
        top = max(low.adjusted(), high.adjusted()) + 1
        if top - (exponent - 47) + 1 > _WIDE.prec:
            return None
        return int(low.scaleb(-exponent)), int(high.scaleb(-exponent)), exponent


@dataclass(frozen=True)
class Ask:
    name: str
    meaning: str
    path: str
    quantity: Quantity
    unit: str
    sig_figs: int | None
    magnitude: bool = False
    zero_for: str | None = None
    small: tuple[sp.Symbol, ...] = ()
    shift: sp.Expr | tuple[sp.Expr, sp.Expr, sp.Expr] | None = None  # a distance, or a vector in the body's frame
    amplitude: sp.Expr | None = None
    exact: str | None = None  # this ask approximates that one
    tolerance: str | None = None  # "2%" or an absolute amount in `unit`; None: the last digit shown
    state: str | None = None  # read in this state of the scene (`in:`); None: the placement at rest
    sign: str | None = None  # the sign convention the question states (`sign:`); None: a magnitude and a direction
    about: "ask_options.Point | None" = None  # the point a torque is taken about (`about:`)
    equals: sp.Expr = sp.S.Zero  # the value the quantity takes where `zero_for` (`find:`) is sought, in SI
    finds: str = ""  # the key that names the parameter sought: "find" or "zero_for" ("" for none)


@dataclass(frozen=True)
class Condition:
    """A declared condition for the answers to make physical sense (`holds: r < R`), as
    (expression, strict) pairs: each expression, in SI units, must be positive (strict) or
    not negative. `answers` maps the placeholders of asked quantities to their names."""

    text: str
    because: str
    parts: tuple[tuple[sp.Expr, bool], ...]
    answers: dict[sp.Symbol, str]


@dataclass(frozen=True)
class Problem:
    id: str
    title: str
    topic: str
    source: str
    path: Path
    parameters: dict[str, Parameter]
    scene: Scene
    asks: dict[str, Ask]
    question: str
    corrections: tuple[dict[str, str], ...]
    scene_units: dict[sp.Symbol, str]
    conditions: tuple[Condition, ...] = ()
    held_to_range: frozenset[sp.Symbol] = frozenset()  # parameters the file's signs were proven over the ranges of
    # What a derivation reads of the file: its fields but the text (derive.language.derivation_source; the
    # derivation cache's key: derive.publishing.derivation_cache).
    derivation_source: str = dataclass_field(default="", repr=False, compare=False)
    difficulty: str = ""  # derive.language.labels: "" where the file gives none
    tags: tuple[str, ...] = ()

    def error(self, field: str, message: str) -> ProblemError:
        return ProblemError(f"{self.path}: {field}: {message}")

    def limit(self, what: str) -> EngineLimit:
        """An engine limit met by this problem: "FILE: derive cannot yet WHAT" (exit 1)."""
        return EngineLimit(str(self.path), what)

    @property
    def symbols(self) -> SimpleNamespace:
        """The symbols the answers are written in, by name (`problem.symbols.M`): the parameters and
        the sizes the scene leaves open, with their assumptions (a mass is positive=True), so that
        an expression built from them compares with the answers as sympy compares.

        >>> load("rod_endpoint").symbols
        namespace(m=m, L=L)
        """
        named = {p.symbol.name: p.symbol for p in self.parameters.values()}
        return SimpleNamespace(**named, **{s.name: s for s in self.scene_units if s.name not in named})

    @property
    def symbol_units(self) -> dict[sp.Symbol, str]:
        """Units of every symbol: the parameters and the sizes the scene leaves open."""
        return self.scene_units

    def values(self, overrides: dict[str, str] | None = None) -> dict[sp.Symbol, sp.Expr]:
        """Exact SI values of the parameters that have one: declared values and `--set` overrides.

        An override is "2" (in the parameter's unit) or "200 g" (converted).
        """
        result = {}
        for p in self.parameters.values():
            if p.value is not None:
                result[p.symbol] = p.value * units.si_factor(units.parse_unit(p.unit))
        for name, text in (overrides or {}).items():
            if name not in self.parameters:
                raise ProblemError(
                    f"--set {name}: {self.id} has no parameter {name!r} (parameters: {', '.join(self.parameters)})"
                    + did_you_mean(name, self.parameters)
                )
            p = self.parameters[name]
            try:
                number, unit = units.parse_quantity(text, p.unit)
            except units.UnitError as error:
                try:  # an exact number written as an expression, in the parameter's unit: acos(1/3), pi/4
                    number, unit = expr.parse(text, {}), p.unit
                except expr.ExprError:
                    raise ProblemError(f"--set {name}={text}: {error}") from None
            try:
                result[p.symbol] = units.to_unit(number, unit, p.unit) * units.si_factor(units.parse_unit(p.unit))
            except units.UnitError as error:
                raise ProblemError(f"--set {name}={text}: {error}") from None
            low, high = p.si_ends
            if p.symbol in self.held_to_range and not low <= result[p.symbol] <= high:
                raise ProblemError(f"--set {name}={text}: outside {name}'s range ({float(p.range[0]):g} to {float(p.range[1]):g} {p.unit}), "
                                   "over which the file's sizes were proven positive: give a value within it, or widen "
                                   "the range in the file")
            if p.symbol.is_positive and not result[p.symbol] > 0:
                # The derivation assumed it positive (its range is): a value of the other sign is invalid.
                raise ProblemError(f"--set {name}={text}: {name} must be positive (its range is "
                                   f"{p.range[0] if p.range else p.value} to {p.range[1] if p.range else p.value})")
        return result



def _parameters(reader: Reader, raw) -> dict[str, Parameter]:
    raw = reader.mapping(raw, "parameters", free=True)
    result = {}
    for name, spec in raw.items():
        field = f"parameters.{name}"
        reader.name(name, field, "a parameter name")
        if name in expr.RESERVED:
            raise reader.fail(field, f"{name!r} is reserved for a function or constant")
        spec = reader.mapping(spec, field, keys=PARAMETER)
        if "value" not in spec and "range" not in spec:
            raise reader.fail(field, "needs a value or a range")
        unit = reader.unit(spec["unit"] if "unit" in spec else amounts.written_unit(reader, spec, field), f"{field}.unit")
        value = amounts.amount(reader, spec["value"], f"{field}.value", unit) if "value" in spec else None
        bounds = None
        if "range" in spec:
            if not isinstance(spec["range"], list) or len(spec["range"]) != 2:
                raise reader.fail(f"{field}.range", "expected [low, high]")
            bounds = tuple(amounts.amount(reader, v, f"{field}.range", unit) for v in spec["range"])
            if (bounds[1] - bounds[0]).is_positive is not True:  # sympy decides it, or the range is refused
                raise reader.fail(f"{field}.range", f"low ({bounds[0]}) must be below high ({bounds[1]}), by a "
                                                    "difference that can be told from zero")
            if value is not None and not ((value - bounds[0]).is_nonnegative and (bounds[1] - value).is_nonnegative):
                raise reader.fail(f"{field}.value", f"{value} lies outside the range")
        sig_figs = spec.get("sig_figs", DEFAULT_SIG_FIGS)
        if not isinstance(sig_figs, int) or isinstance(sig_figs, bool) or not 1 <= sig_figs <= 15:
            raise reader.fail(f"{field}.sig_figs", "expected a whole number from 1 to 15")
        written = _figures(value) if value is not None and bounds is None else None
        if written is not None and written > sig_figs:  # a fixed value is printed as the answers use it
            if "sig_figs" in spec:
                raise reader.fail(f"{field}.sig_figs", f"the value {spec['value']} has {written} significant figures: "
                                  f"printed to {sig_figs} the worksheet would differ from the value the answers use; "
                                  f"give sig_figs: {written}, or the value rounded")
            sig_figs = written
        if bounds is not None:
            low, high = Parameter(name, None, "", "", None, bounds, sig_figs).bounds()
            if low > high:
                raise reader.fail(f"{field}.range", f"[{bounds[0]}, {bounds[1]}] holds no value of {sig_figs} "
                                  "significant figures: widen the range or give more sig_figs")
        lowest = bounds[0] if bounds else value
        if value is not None:
            lowest = min(lowest, value)
        symbol = sp.Symbol(name, positive=True) if lowest > 0 else sp.Symbol(name, real=True)
        reader.symbols[name] = symbol
        reader.symbol_units[symbol] = unit
        result[name] = Parameter(name, symbol, reader.text(spec["meaning"], f"{field}.meaning", MEANING_LIMIT), unit, value, bounds,
                                 sig_figs)
        reader.parameters[name] = result[name]
    return result



def _asks(reader: Reader, raw, scene: Scene, parameters: dict[str, Parameter], raw_question) -> dict[str, Ask]:
    raw = reader.mapping(raw, "ask", free=True)
    if not raw:
        raise reader.fail("ask", "a problem asks for at least one quantity")
    result = {}
    for name, spec in raw.items():
        field = f"ask.{name}"
        reader.name(name, field, "an answer name")
        if name in parameters:
            raise reader.fail(field, f"{name!r} is already a parameter")
        spec = reader.mapping(spec, field, keys=ask_options.ASK)
        if not isinstance(spec.get("magnitude", False), bool):
            raise reader.fail(f"{field}.magnitude", "expected true or false")
        path = reader.text(spec["of"], f"{field}.of", NAME_LIMIT)
        try:
            quantity = quantities.parse(scene, path) or parse_quantity(scene, path, ask_options.end_axis(reader, spec, field, scene))
        except ValueError as error:
            raise reader.fail(f"{field}.of", str(error)) from None
        zero_for, finds, equals = ask_options.sought(reader, spec, field, parameters, quantity)
        kind = quantities.KINDS[quantity.kind]
        if kind.exact_unit and not zero_for and str(spec["unit"]).strip() != kind.unit:
            raise reader.fail(f"{field}.unit", f"{path} is asked in {kind.unit}, not {spec['unit']!r}")
        sig_figs = spec.get("sig_figs")
        if sig_figs is not None and (not isinstance(sig_figs, int) or not 1 <= sig_figs <= 15):
            raise reader.fail(f"{field}.sig_figs", "expected a whole number from 1 to 15")
        result[name] = Ask(
            name, reader.text(spec["meaning"], f"{field}.meaning", MEANING_LIMIT), path, quantity,
            reader.unit(spec["unit"], f"{field}.unit"), sig_figs, spec.get("magnitude", False), zero_for,
            ask_options.small(reader, spec.get("small"), f"{field}.small", scene),
            ask_options.end_shift(reader, spec, field, scene, quantity,
                                  ask_options.shift(reader, spec.get("shift"), f"{field}.shift", quantity)),
            ask_options.amplitude(reader, spec.get("amplitude"), f"{field}.amplitude", quantity),
            spec.get("exact"),
            ask_options.tolerance(reader, spec.get("tolerance"), f"{field}.tolerance"),
            ask_states.state(reader, spec.get("in"), f"{field}.in", scene, quantity, path),
            ask_options.sign(reader, spec.get("sign"), f"{field}.sign", quantity, raw_question),
            ask_options.about(reader, spec.get("about"), f"{field}.about", scene, quantity),
            equals, finds,
        )
    for name, ask in result.items():
        if ask.exact is not None and (ask.exact not in result or ask.exact == name):
            raise reader.fail(f"ask.{name}.exact", f"expected another ask of this problem (asks: {', '.join(result)})")
    _bearings_used(reader, scene, result)
    return result


#: What each optional key of `bearings:` changes (derive.mechanics.bearings), by the asks' prefixes:
#: the bearings' distance each one's force; the shaft's point off the center of mass the center's
#: motion, so the bearings' forces, the drive's couple and the kinetic energy (not L or the torque
#: about the center).
BEARING_KEY_ASKS = {
    "apart": (("bearings.force", "bearings.A.", "bearings.B."), "each bearing's force"),
    "through": (("bearings.A.", "bearings.B.", "bearings.total_force.", "bearings.drive_torque", "kinetic_energy"),
                "the bearings' forces, the drive's couple and the kinetic energy"),
}


def _bearings_used(reader: Reader, scene: Scene, asks: dict[str, Ask]) -> None:
    """Refuse a body's `bearings: {apart, through}` that no ask needs (a key nothing uses)."""
    for body, held in scene.bearings.items():
        asked = [a.quantity.detail for a in asks.values() if a.quantity.kind == "bearings" and a.quantity.target == body]
        for key, (needs, what) in BEARING_KEY_ASKS.items():
            given = held.apart is not None if key == "apart" else any(c != 0 for c in held.through)
            if given and not any(detail.startswith(needs) for detail in asked):
                raise reader.fail(f"scene.bodies.{body}.bearings.{key}", f"no ask uses it: it changes only {what}")


def _conditions(reader: Reader, raw, asks: dict[str, Ask]) -> tuple[Condition, ...]:
    """`conditions: [{holds: "b <= R", because: the ball hits the disk}]`: inequalities among
    parameters and asked quantities, compared in SI units, that each draw must meet."""
    if raw is None:
        return ()
    if not isinstance(raw, list):
        raise reader.fail("conditions", "expected a list of {holds: INEQUALITY, because: TEXT}")
    placeholders = {name: sp.Dummy(name, real=True) for name in asks}
    symbol_units = {**reader.symbol_units, **{placeholders[n]: a.unit for n, a in asks.items()}}
    result = []
    for i, spec in enumerate(raw):
        field = f"conditions[{i}]"
        spec = reader.mapping(spec, field, keys=CONDITION)
        try:
            parts = expr.parse_condition(spec["holds"], {**reader.symbols, **placeholders})
        except expr.ExprError as error:
            raise reader.fail(f"{field}.holds", str(error)) from None
        for difference, _ in parts:
            try:
                units.expression_dimension(difference, symbol_units)
            except units.UnitError as error:
                raise reader.fail(f"{field}.holds", f"compares quantities of different dimensions ({error}); "
                                  "numbers stand only for dimensionless quantities") from None
        used = {d for difference, _ in parts for d in difference.free_symbols}
        result.append(Condition(spec["holds"], reader.text(spec["because"], f"{field}.because", MEANING_LIMIT), tuple(parts),
                                {d: n for n, d in placeholders.items() if d in used}))
    return tuple(result)


@dataclass(frozen=True)
class Heading:
    """What a problem file says of itself, before its scene: how `derive list` finds a problem without
    deriving or even reading its scene (a tenth of a second for the library, where loading each is seconds).

    >>> heading("rolling_incline").topic
    'rolling'
    """

    id: str
    title: str
    topic: str
    source: str
    question: str
    difficulty: str
    tags: tuple[str, ...]


def _opened(text: str, path: Path) -> tuple[Reader, dict, str, dict]:
    """(the reader, the file's mapping, its id, its parameters): the YAML, the id and the parameters validated,
    first of all, in that order."""
    reader = Reader(path)
    try:
        raw = safe_load(text)
    except yaml.YAMLError as error:
        mark = getattr(error, "problem_mark", None) or getattr(error, "context_mark", None)
        where = f"line {mark.line + 1}" if mark else "yaml"
        reason = getattr(error, "problem", None) or str(error).splitlines()[0]
        raise ProblemError(f"{path}: {where}: invalid YAML: {reason}") from None
    raw = reader.mapping(raw, "", keys=PROBLEM)
    problem_id = reader.text(raw["id"], "id", NAME_LIMIT)
    if not library.ID_PATTERN.fullmatch(problem_id):
        raise reader.fail("id", "an id is letters, digits and _, starting with a letter")
    return reader, raw, problem_id, _parameters(reader, raw["parameters"])


def _heading(reader: Reader, raw: dict, problem_id: str) -> Heading:
    """The heading's fields validated (the question's placeholders name the parameters read): last, after the
    scene and the asks, so that a file's first error is reported as it always was."""
    try:
        difficulty = labels.read_difficulty(raw["difficulty"], "difficulty") if "difficulty" in raw else ""
        tags = labels.read_tags(raw["tags"], "tags") if "tags" in raw else ()
    except ValueError as error:
        raise ProblemError(f"{reader.path}: {error}") from None
    return Heading(
        id=problem_id,
        title=reader.text(raw["title"], "title", TITLE_LIMIT),
        topic=reader.text(raw.get("topic", "general"), "topic", TOPIC_LIMIT),
        source=reader.text(raw["source"], "source", SOURCE_LIMIT) if "source" in raw else "",
        question=reader.text(raw["question"], "question", QUESTION_LIMIT),
        difficulty=difficulty,
        tags=tags)


def parse(text: str, path: Path) -> Problem:
    """Validate the text of a problem file; `path` names it in errors."""
    reader, raw, problem_id, parameters = _opened(text, path)
    reader.used = set()
    scene = read_scene(reader, raw["scene"])
    asks = _asks(reader, raw["ask"], scene, parameters, raw["question"])
    conditions = _conditions(reader, raw.get("conditions"), asks)
    _check_used(reader, raw, scene, asks, parameters, conditions)
    corrections = raw.get("corrections") or []
    if not isinstance(corrections, list):
        raise reader.fail("corrections", "expected a list")
    corrections = tuple(
        {key: reader.text(text, f"corrections[{i}].{key}", CORRECTION_LIMIT) for key, text in
         reader.mapping(c, f"corrections[{i}]", keys=CORRECTION).items()}
        for i, c in enumerate(corrections))
    head = _heading(reader, raw, problem_id)
    return Problem(
        id=head.id,
        title=head.title,
        topic=head.topic,
        source=head.source,
        path=path,
        parameters=parameters,
        scene=scene,
        asks=asks,
        question=head.question,
        corrections=corrections,
        scene_units=dict(reader.symbol_units),
        conditions=conditions,
        held_to_range=frozenset(reader.held_to_range),
        derivation_source=derivation_source.of(raw),
        difficulty=head.difficulty,
        tags=head.tags,
    )


def _check_used(reader: Reader, raw: dict, scene: Scene, asks: dict, parameters: dict, conditions) -> None:
    """Every key is used or refused by name: a parameter that neither the scene, the asks, the
    conditions nor the question names; states no ask reads; friction coefficients where
    nothing asked depends on the motion."""
    used = reader.used | {s for c in conditions for difference, _ in c.parts for s in difference.free_symbols}
    shown = set(re.findall(r"\{\{\s*([A-Za-z][A-Za-z0-9_]*)\s*\}\}", str(raw["question"])))
    for name, p in parameters.items():
        if p.symbol not in used and name not in shown:
            raise reader.fail(f"parameters.{name}", "no part of the scene, no ask, condition or the question uses it")
    read = {a.state for a in asks.values()} | {s.start for s in scene.states.values()}
    unread = next((name for name in scene.states if name not in read), None)
    if unread is not None:
        raise reader.fail(f"scene.states.{unread}", "no ask is read in this state (in: STATE) and no state starts "
                                                    "from it: remove it, or ask what it holds")
    for name, coin in scene.rolls_on_edge.items():
        if coin.tilt is not None and not any(a.quantity.kind == "rolls_on_edge" and a.quantity.target == name
                                             and a.quantity.detail.startswith("steady.") for a in asks.values()):
            raise reader.fail(f"scene.bodies.{name}.rolls_on_edge.tilt", "no ask reads the steady motion on a circle "
                                                                          "(steady.*): leave out tilt and circle")
    symbols = {p.symbol for p in parameters.values()}
    for name, free in scene.free_rotations.items():  # omega across the axis, given where nothing reads it
        reads = {a.quantity.detail for a in asks.values()
                 if a.quantity.kind == "free_rotation" and a.quantity.target == name}
        if free.across.free_symbols <= symbols and not reads & {"free_precession.space", "angle_L_axis",
                                                                 "angle_omega_axis"}:
            raise reader.fail(f"scene.bodies.{name}.free_rotation.across", "no ask reads it (the precession in "
                                                                          "space and the angles of L and omega do)")
    for name, point in scene.pivot_points.items():  # a moment across the axle only the axle's turn reads
        if point.centered and point.inertia is not None and point.inertia[0].free_symbols <= symbols \
                and not any(a.quantity.kind == "angular_impulse" and a.quantity.detail == "turn.axle"
                            and a.quantity.target == name for a in asks.values()):
            raise reader.fail(f"scene.bodies.{name}.inertia.transverse", "no ask reads it (the axle's turn, "
                                                                         "turn.axle, does; L's turn does not)")
    if not any(quantities.KINDS[a.quantity.kind].reads_motion(a) for a in asks.values()):
        for c in scene.constraints:
            if isinstance(c, Contact) and c.has_friction:
                where = f"scene.bodies.{c.body}" if c.point is None else f"scene.joints.{c.name}"
                raise reader.fail(f"{where}.friction", "nothing asked depends on the motion or the forces, so no "
                                                       "friction coefficient is used")


def load(reference: str | Path) -> Problem:
    """Load a problem by file path or library id."""
    path, text = _text(reference)
    return parse(text, path)


def heading(reference: str | Path) -> Heading:
    """The heading of a problem (`Heading`) by file path or library id, its scene not read."""
    path, text = _text(reference)
    return _heading(*_opened(text, path)[:3])


def _text(reference: str | Path) -> tuple[Path, str]:
    """(the path, the text) of a problem file by file path or library id."""
    try:
        path = library.find_problem(str(reference))
    except library.LibraryError as error:
        raise ProblemError(str(error)) from None
    try:
        return path, path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as error:
        raise ProblemError(f"{path}: cannot read: {error}") from None
