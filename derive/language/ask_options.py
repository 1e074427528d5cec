"""What an ask may say besides what it asks (derive.language.problem reads the rest): the tolerance an
LMS grades it with, an inertia axis shifted, a pendulum's amplitude, sizes taken to zero.

>>> tolerance_policy("2%")
'2%'
"""
from __future__ import annotations

from dataclasses import dataclass
from decimal import Decimal, InvalidOperation

import sympy as sp

from derive.core.keys import Key, Keys
from derive.core import units
from derive.language.reader import Reader
from derive.model.scene import Quantity, Scene
from derive.parts.pin import Pin
from derive.parts.places import Places
from derive import quantities

#: An ask's entry under `ask:`.
ASK = Keys(meaning=Key("text", "what the answer is, in words", required=True),
           of=Key("text", "the quantity asked: BODY.acceleration.y, ROPE.tension, BODY.inertia, ...", required=True),
           unit=Key("text", "its unit (m/s^2, N, kg m^2, deg, ...)", required=True),
           axis=Key("any", "the axis a moment of inertia is about: a name (see derive inertia --help), or a direction "
                           "[x, y, z] in the body's frame through its center of mass (a plate's diagonal: [a, b, 0])"),
           sig_figs=Key("integer", "significant figures of the answer (default 3 in a set)"),
           magnitude=Key("boolean", "ask its magnitude (default false)"),
           zero_for=Key("name", "ask instead the parameter's value at which the quantity vanishes (find: with "
                                "equals: 0)"),
           find=Key("name", "ask instead the parameter's value at which the quantity equals `equals:` (an inverse "
                            "question: the turns that turn a satellite by 30 deg); its unit is the ask's"),
           equals=Key("quantity", "the value the quantity takes, for find: (an expression of the other parameters, "
                                  "or a number with its unit: 30 deg, 2.5 m/s)"),
           small=Key("any", "a size (BODY.SIZE), or a list of them, taken to zero in the answer"),
           shift=Key("any", "the axis moved parallel to itself: [dx, dy] in the body's frame, or a distance"),
           end=Key("name", "a rod's end the axis passes through, normal to the rod: start (its point start, x = -L/2, "
                           "where axis: end passes) or far (its point end, x = L/2)"),
           amplitude=Key("expression", "a pendulum's amplitude: the period at it"),
           exact=Key("name", "the ask this one approximates (its relative error is reported)"),
           tolerance=Key("any", "what an LMS accepts around the answer: 2% or an amount in its unit"),
           sign=Key("text", "the sign convention the question states, in its words (up positive, down the "
                            "incline positive): the answer is then the component along the way it names positive; "
                            "without it a quantity with a direction is asked as its magnitude"),
           about=Key("any", "the point a torque is taken about: a joint's name (the point it holds), BODY (its "
                            "center of mass), BODY.POINT, {BODY: [x, y]} or [x, y] (a fixed point); a particle's torque on a "
                            "path in space, or its angular momentum: [x, y, z] (a fixed point; the origin by default for the angular momentum)"),
           **{"in": Key("name", "the state the quantity is asked in")})


@dataclass(frozen=True)
class Point:
    """A point an ask names (`about:`): a body's (`offset` in its frame, from its center of mass) or,
    with `body` None, the ground's (x, y; or x, y, z for a quantity in space, `fixed_point`); `words`
    name it for a student ("the hinge")."""

    body: str | None
    offset: tuple[sp.Expr, ...]
    words: str


def about(reader: Reader, raw, field: str, scene: Scene, quantity: Quantity) -> Point | None:
    """`about: hinge`: the point the quantity is taken about, where its kind takes one (a torque);
    refused where it does not (a key nothing uses), and required where it does.

    >>> from derive.language.problem import load
    >>> scene = load("rod_endpoint").scene
    >>> about(Reader("x.yaml"), "rod.end", "ask.t.about", scene, Quantity("torque", "rod", None))
    Point(body='rod', offset=(L/2, 0), words="the rod's end")
    """
    kind = quantities.KINDS[quantity.kind]
    takes = "about" in kind.options
    if raw is None and takes and kind.about_default is not None:
        raw = list(kind.about_default)  # a particle's angular momentum: about the origin unless told
    if raw is None:
        if takes:
            raise reader.fail(field, f"a {quantity.kind} is taken about a point: give about: " + (
                "[x, y, z] (a fixed point)" if kind.about_in_space else
                "a joint's name, BODY, BODY.POINT, {BODY: [x, y]} or [x, y]"))
        return None
    if not takes:
        raise reader.fail(field, "only a torque or a particle's angular momentum in space is taken about a point: "
                                 "leave about: out")
    if kind.about_in_space:
        return fixed_point(reader, raw, field)
    pins = {c.name: c for c in scene.constraints if isinstance(c, Pin)}
    if isinstance(raw, str) and raw in pins:
        return Point(pins[raw].body, pins[raw].offset, f"the {raw.replace('_', ' ')}")
    body, offset = Places(reader, scene.bodies, {}, scene.surfaces).point(raw, field)
    if body is None:
        return Point(None, offset, f"the point ({sp.sstr(offset[0])}, {sp.sstr(offset[1])})")
    if isinstance(raw, str):
        named = raw.partition(".")[2]
        return Point(body, offset, f"the {body}'s {named}" if named and named != "center" else
                     f"the {body}'s center of mass")
    return Point(body, offset, f"a point of the {body}")


def fixed_point(reader: Reader, raw, field: str) -> Point:
    """`[x, y, z]`, or `[x, y]` in the plane z = 0: a point fixed in space, which a quantity in space is
    taken about (a particle's torque on a path in space); a point of a body, which may move, is refused.

    >>> fixed_point(Reader("x.yaml"), [0, 0], "ask.t.about")
    Point(body=None, offset=(0, 0, 0), words='the origin')
    >>> fixed_point(Reader("x.yaml"), "particle", "ask.t.about")
    Traceback (most recent call last):
    derive.core.errors.ProblemError: x.yaml: ask.t.about: a torque in space is taken about a fixed point: [x, y, z], or [x, y] (z = 0)
    """
    if not isinstance(raw, list) or len(raw) not in (2, 3):
        raise reader.fail(field, "a torque in space is taken about a fixed point: [x, y, z], or [x, y] (z = 0)")
    x, y, z = (*(reader.dimensioned(v, field, "m", "a coordinate") for v in raw), sp.Integer(0))[:3]
    words = "the origin" if x == y == z == 0 else f"the point ({sp.sstr(x)}, {sp.sstr(y)}, {sp.sstr(z)})"
    return Point(None, (x, y, z), words)



def sought(reader: Reader, spec: dict, field: str, parameters: dict, quantity: Quantity) -> tuple[str | None, str, sp.Expr]:
    """(the parameter an inverse ask finds, the key that names it, the value the quantity takes
    there, in SI): `find: N` with `equals: VALUE`, or `zero_for: N` (equals 0); (None, "", 0) for
    an ask of the quantity itself."""
    if spec.get("find") is not None and spec.get("zero_for") is not None:
        raise reader.fail(f"{field}.find", "give find: with equals:, or zero_for:, not both")
    key = "find" if spec.get("find") is not None else "zero_for"
    name = spec.get(key)
    if spec.get("equals") is not None and key != "find":
        raise reader.fail(f"{field}.equals", "equals: is the value the quantity takes for find: PARAMETER: give find:")
    if name is None:
        return None, "", sp.S.Zero
    if name not in parameters:
        raise reader.fail(f"{field}.{key}", f"expected a parameter (parameters: {', '.join(parameters)})")
    if key == "zero_for":
        return name, key, sp.S.Zero
    if spec.get("equals") is None:
        raise reader.fail(f"{field}.equals", f"find: {name} needs the value the quantity takes: equals: VALUE")
    if quantities.directional(quantity) and spec.get("sign") is None and not spec.get("magnitude"):
        raise reader.fail(f"{field}.equals", f"{spec['of']} points one way or the other: say which way its value "
                                             "counts as positive, in the question's words, with sign:, or that "
                                             "equals: is its magnitude, with magnitude: true")
    return name, key, in_si(reader, spec["equals"], f"{field}.equals")


def in_si(reader: Reader, raw, field: str) -> sp.Expr:
    """A value as the engine computes in SI: a number with its unit (30 deg, 2 rev, 2.5 km/h), converted
    exactly, or an expression of the parameters (whose symbols stand for SI values).

    >>> from pathlib import Path
    >>> in_si(Reader(Path("p.yaml")), "30 deg", "equals"), in_si(Reader(Path("p.yaml")), "2 rev", "equals")
    (pi/6, 4*pi)
    """
    if isinstance(raw, str):
        try:
            number, given = units.parse_quantity(raw, "")
        except units.UnitError:
            given = ""
        if given:
            return number * units.si_factor(given)
    return reader.expression(raw, field)


def tolerance(reader: Reader, raw, field: str) -> str | None:
    """`tolerance: 2%` (of the answer) or `tolerance: 0.05` (in the answer's unit): what an
    LMS accepts around the answer; by default one unit in the last significant digit shown."""
    try:
        return tolerance_policy(raw)
    except ValueError as error:
        raise reader.fail(field, str(error)) from None


def tolerance_policy(raw) -> str | None:
    """An answer's tolerance as an ask (or the course defaults, derive.language.defaults) gives it: "P%"
    or a positive amount, normalized; None (not given) stays None; ValueError says what is wrong.

    >>> tolerance_policy("2.50 %"), tolerance_policy(Decimal("0.050")), tolerance_policy(None)
    ('2.5%', '0.05', None)
    """
    if raw is None:
        return None
    text = str(raw).strip()
    amount = text[:-1].strip() if text.endswith("%") else text
    try:
        number = Decimal(amount)
    except InvalidOperation:
        number = None
    if isinstance(raw, bool) or number is None or not number.is_finite() or number <= 0:
        raise ValueError(f"expected a percentage such as 2% or a positive amount in the answer's unit, got {text!r}")
    if text.endswith("%") and number >= 100:
        raise ValueError(f"{text} of the answer would accept zero and the wrong sign")
    if not -300 <= number.adjusted() <= 300:  # 1e-999999999 would be written as 0, 1e999999999 overflow
        raise ValueError(f"{text} is narrower than the digits any answer shows" if number < 1 else
                         f"{text} lies outside what an LMS stores (1e-300 to 1e300)")
    return f"{number.normalize():f}%" if text.endswith("%") else f"{number.normalize():f}"


def sign(reader: Reader, raw, field: str, quantity: Quantity, question) -> str | None:
    """`sign: y up`: the sign convention the question states, in its own words (which the question
    must contain): for a quantity with a direction the answer is then the signed component (without
    it, its magnitude with its direction in words: derive.model.directions); for another quantity
    that may come out negative (a precession that may be retrograde, "negative: retrograde"), it says
    that the question states what its sign means, which `derive check` asks of every negative value
    (derive.checks.signs), so that no student is graded wrong for a sign nothing told them."""
    if raw is None:
        return None
    text = reader.text(raw, field, 80)
    if _plain(text) not in _plain(str(question)):
        raise reader.fail(field, f"the question must state the sign convention: it does not say {text!r}")
    return text


def _plain(text: str) -> str:
    """Text compared for a stated convention: lower case, no math dollars or braces, spaces collapsed."""
    return " ".join(text.lower().replace("$", " ").replace("{", " ").replace("}", " ").split())


def shift(reader: Reader, raw, field: str, quantity: Quantity) -> sp.Expr | tuple[sp.Expr, sp.Expr, sp.Expr] | None:
    """`shift: [dx, dy]`: the asked axis moved parallel to itself by that vector in the body's frame
    (a rod along x); `shift: h`: by the distance h, which needs no direction only where the axis
    passes through the body's center of mass (every direction then gives the same moment: the
    Solution refuses it elsewhere)."""
    if raw is None:
        return None
    if quantity.kind != "inertia" or quantity.detail is None:
        raise reader.fail(field, "a shift moves a named inertia axis (give axis: too)")
    if isinstance(raw, list):
        dx, dy = reader.vector(raw, field, "m", "a shift", " in the body's frame (x along a rod)")
        if dx == 0 and dy == 0:
            raise reader.fail(field, "a shift of [0, 0] moves nothing: leave it out")
        return (dx, dy, sp.S.Zero)
    return reader.positive(raw, field, "m", "a shift")


#: A rod's ends by `end:`, and the named axis each is measured from (its `end` axis passes through `start`).
ENDS = {"start": 0, "far": 1}


def end_axis(reader: Reader, spec: dict, field: str, scene: Scene) -> str | None:
    """The axis an ask names: `axis:` as written, or `end` (the axis through the rod's start) for `end:`."""
    if spec.get("end") is None:
        return direction(reader, spec["axis"], f"{field}.axis") if isinstance(spec.get("axis"), list) else spec.get("axis")
    body = scene.bodies.get(str(spec.get("of")).partition(".")[0])
    if body is None or body.shape != "rod" or not str(spec.get("of")).endswith(".inertia"):
        raise reader.fail(f"{field}.end", "end: names an end of a rod for its moment of inertia (BODY.inertia)")
    if spec.get("axis") is not None:
        raise reader.fail(f"{field}.end", "end: names the axis itself (normal to the rod through that end): "
                                          "leave axis: out")
    if spec["end"] not in ENDS:
        raise reader.fail(f"{field}.end", f"expected start or far, got {spec['end']!r}")
    return "end"


def direction(reader: Reader, raw: list, field: str) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """`axis: [x, y, z]`: a direction in the body's frame (lengths, or numbers), not zero."""
    if len(raw) != 3:
        raise reader.fail(field, "expected a direction [x, y, z] in the body's frame")
    vector = tuple(reader.expression(v, field) for v in raw)
    if all(v == 0 for v in vector):
        raise reader.fail(field, "[0, 0, 0] is no direction")
    return vector


def end_shift(reader: Reader, spec: dict, field: str, scene: Scene, quantity: Quantity, shift):
    """The shift of an ask that says `end: far`: the rod's length along it from the start, where the named
    `end` axis passes (plus a `shift: [dx, dy]` given with it); an ask without `end:` keeps its shift.

    A density that grows from one end makes the two ends different: a rod with density growing from
    its start has I = M L^2/2 about `end: start` and M L^2/6 about `end: far`.
    """
    if spec.get("end") is None:
        return shift
    body = scene.bodies[quantity.target]  # a rod (end_axis)
    if shift is not None and not isinstance(shift, tuple):
        raise reader.fail(f"{field}.shift", "a shift from a rod's end needs its direction: give [dx, dy]")
    along = (ENDS[spec["end"]] * body.sizes["length"], sp.S.Zero, sp.S.Zero)
    moved = along if shift is None else tuple(a + b for a, b in zip(along, shift))
    return None if all(c == 0 for c in moved) else moved


def amplitude(reader: Reader, raw, field: str, quantity: Quantity) -> sp.Expr | None:
    if (raw is None) != (quantity.kind != "oscillation"):
        raise reader.fail(field, "oscillation.period needs an amplitude, and only it takes one")
    return None if raw is None else reader.positive(raw, field, "rad", "an amplitude")


def small(reader: Reader, raw, field: str, scene: Scene) -> tuple[sp.Symbol, ...]:
    """`small: ball.radius` (or a list): sizes taken to zero in the answer (the notes' r << R)."""
    if raw is None:
        return ()
    result = []
    for item in raw if isinstance(raw, list) else [raw]:
        body, _, size = str(item).partition(".")
        value = scene.bodies[body].sizes.get(size) if body in scene.bodies else None
        if not isinstance(value, sp.Symbol):
            raise reader.fail(field, f"{item!r} is not a size of a body (BODY.SIZE, e.g. ball.radius)")
        result.append(value)
    return tuple(result)
