"""An inextensible light cord: a path of attachments joined by straight runs.

Each end is tied to a point (of a body or of the ground), wound on a body (it unwinds from a rim
without slipping) or pulled by a given force in a fixed direction. In between the cord passes
around circles: a pulley that turns with it (a body with an inertia: the cord does not slip on
it) or a smooth one (a peg, a massless pulley, a pulley marked smooth: the cord slides). Each
straight run goes wherever the geometry takes it, tangent to the circles it joins.

The circles that grip the cord (wound ends and turning pulleys) cut it into segments; each
segment has one tension, an unknown, unless a force pulls its free end (then the tension is that
force).

Geometry. A circle of radius r that the cord goes around counter-clockwise has signed radius
rho = +r, clockwise rho = -r (a point: 0). A run from a circle (C_a, rho_a) to (C_b, rho_b) has
D = C_b - C_a, e = D/|D|, c = (rho_b - rho_a)/|D|, h = sqrt(1 - c^2); its left normal is
n = c e + h e_perp and its direction d = h e - c e_perp; it touches at T = C - rho n; its length
is sqrt(|D|^2 - (rho_b - rho_a)^2).

Lagrange: each segment's length is constant, g = l(0) - l(q) (multiplier: its tension, which
pulls the ends together). l is the exact length: the runs, the arcs on smooth circles
(r times the turn of the cord between its tangent points) and, at a gripping circle, the arc from
a mark on the body to the tangent point. A pulled segment's tension is known: its power is
P = -F dl/dt, l measured to a fixed line across the pull.

Newton–Euler: the tension acts at each tangent point along the run (on a smooth circle the two
torques cancel); the segment's length does not change: the sum over its runs of d . (w_b - w_a)
vanishes, where w is the velocity of the attachment's center (a point, a smooth circle) or of
the body's material point at the tangent point (a gripping circle: the cord moves with the rim).

>>> import sympy as sp
>>> R, m = sp.symbols("R m", positive=True)
>>> reel = Attachment("wound", "disk", radius=R, turn=-1)
>>> cord = Cord("string", (reel, Attachment("point", "block")))
>>> [s.tension_name for s in cord.segments()]
['tension']
>>> from derive.model.scene import Body, Scene
>>> from derive.model.kinematics import Coordinates
>>> scene = Scene({"disk": Body("disk", "disk", m, {"radius": R}), "block": Body("block", "point", m, {})})
>>> cord.sentences("lagrange", Coordinates(scene))[1].latex()
"It does not slip on the disk, so the disk's rim moves with it: the arc of its turn, $R \\\\theta_{\\\\mathrm{disk}}$, counts in the length."
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import sympy as sp

from derive.core.keys import Key, Keys
from derive.parts import AppliedForce, Part, Sign, acting, at_placement
from derive.text.prose import Sentence

ZERO = (sp.Integer(0), sp.Integer(0))


@dataclass(frozen=True)
class Attachment:
    """One element of a cord's path.

    kind: "point" (an end tied to a point), "wound" (an end wound on a body), "pulled" (a free end
    pulled with `force` toward `angle`), "around" (the cord passes around a circle on the way).
    `body` None is the ground; `offset` is the point (the circle's center) in the body's frame
    from its center of mass, or on the ground. `turn` is +1 when the cord goes around the circle
    counter-clockwise, -1 clockwise (0 for a point). `grips`: the cord does not slip on it.
    `side`: the side the file named, which chose `turn`; `other_sides`: the sides that would have
    chosen the other sense (and so the other tangent from a neighbour).
    """

    kind: str
    body: str | None = None
    offset: tuple[sp.Expr, sp.Expr] = ZERO
    radius: sp.Expr = sp.Integer(0)
    turn: int = 0
    grips: bool = False
    force: sp.Expr | None = None
    angle: sp.Expr | None = None
    side: str = ""
    other_sides: tuple[str, ...] = ()

    @property
    def rho(self) -> sp.Expr:
        return self.turn * self.radius

    def center(self, coords) -> sp.Matrix:
        return coords.position(self.body, self.offset)

    def rotation(self, coords) -> sp.Expr:
        return coords.angle(self.body) if self.body is not None else sp.Integer(0)


@dataclass(frozen=True)
class Run:
    """A straight run at a configuration: its direction d, left normal n, tangent points, length."""

    start: Attachment
    end: Attachment
    direction: sp.Matrix
    normal: sp.Matrix
    start_point: sp.Matrix
    end_point: sp.Matrix
    length: sp.Expr | None  # None for a run to a pulled end (its length is not the cord's)


def _perp(v: sp.Matrix) -> sp.Matrix:
    return sp.Matrix([-v[1], v[0]])


def run(a: Attachment, b: Attachment, coords) -> Run:
    """The straight run from a to b, tangent to both (see the module's geometry)."""
    if a.kind == "pulled" or b.kind == "pulled":
        pulled = a if a.kind == "pulled" else b
        toward = sp.Matrix([sp.cos(pulled.angle), sp.sin(pulled.angle)])  # from the cord toward the puller
        d = toward if b is pulled else -toward
        n = _perp(d)
        fixed = b if a is pulled else a
        point = fixed.center(coords) - fixed.rho * n
        return Run(a, b, d, n, point, point, None)
    ca, cb = a.center(coords), b.center(coords)
    offset = cb - ca
    distance = sp.sqrt(offset.dot(offset))
    e = offset / distance
    c = (b.rho - a.rho) / distance
    h = sp.sqrt(1 - c**2)
    n = c * e + h * _perp(e)
    d = h * e - c * _perp(e)
    length = sp.sqrt(offset.dot(offset) - (b.rho - a.rho) ** 2)
    return Run(a, b, d, n, ca - a.rho * n, cb - b.rho * n, length)


def _turn(r: Run, a: Attachment, b: Attachment, coords) -> sp.Expr:
    """How far the run's normal has turned from the reference configuration: the turn of the
    line between the centers, plus the change of acos((rho_b - rho_a)/|D|), the normal's angle
    from that line (written this way, and not as the angle of n itself, the expression stays
    small enough to differentiate twice, and has no branch cut near the reference)."""
    if r.length is None:
        return sp.Integer(0)  # a pulled run keeps its direction
    offset = b.center(coords) - a.center(coords)
    reference = offset.xreplace(coords.at_rest_in_reference())
    turned = sp.atan2(reference[0] * offset[1] - reference[1] * offset[0], reference.dot(offset))
    spread = b.rho - a.rho
    if spread == 0:
        return turned
    return turned + sp.acos(spread / sp.sqrt(offset.dot(offset))) - sp.acos(spread / sp.sqrt(reference.dot(reference)))


@dataclass(frozen=True)
class Segment:
    """The attachments between two that grip the cord (or its ends), with one tension."""

    attachments: tuple[Attachment, ...]
    tension_name: str
    symbol: sp.Symbol | None  # the unknown tension; None when a force pulls the free end

    @property
    def pulled(self) -> Attachment | None:
        return next((a for a in self.attachments if a.kind == "pulled"), None)

    @property
    def tension(self) -> sp.Expr:
        return self.symbol if self.symbol is not None else self.pulled.force

    def runs(self, coords) -> list[Run]:
        return [run(a, b, coords) for a, b in zip(self.attachments, self.attachments[1:])]

    def length(self, coords) -> sp.Expr:
        """The exact length, up to a constant: the runs, the arcs on smooth circles, the arcs from
        the marks of gripping ends (a pulled end: to a fixed line across the pull)."""
        runs = self.runs(coords)
        turn = [_turn(r, a, b, coords) for r, a, b in zip(runs, self.attachments, self.attachments[1:])]
        total = sp.Integer(0)
        for r in runs:
            if r.length is not None:
                total += r.length
            else:  # the distance from the tangent point to a fixed line across the pull
                total += (1 if r.end.kind == "pulled" else -1) * -r.direction.dot(
                    r.start_point if r.end.kind == "pulled" else r.end_point)
        for i, a in enumerate(self.attachments):
            arc = a.turn * a.radius
            if a.kind == "around" and not a.grips and 0 < i < len(self.attachments) - 1:
                total += arc * (turn[i] - turn[i - 1])
            elif a.grips or a.kind == "wound":
                if i == 0:
                    total += arc * (turn[0] - a.rotation(coords))
                else:
                    total += arc * (a.rotation(coords) - turn[-1])
        return total

    def rate(self, coords) -> sp.Expr:
        """The rate of change of the length, from the velocities of the attachments (rigid-body
        kinematics): the sum over the runs of d . (w_b - w_a)."""
        total = sp.Integer(0)
        for r in self.runs(coords):
            ends = []
            for a, point in ((r.start, r.start_point), (r.end, r.end_point)):
                if a.kind == "pulled":
                    ends.append(sp.zeros(2, 1))  # the length is measured to a fixed line across the pull
                elif a.body is None:
                    ends.append(sp.zeros(2, 1))
                else:
                    at = point if (a.grips or a.kind == "wound") else a.center(coords)
                    ends.append(coords.velocity(a.body, at - coords.position(a.body)))
            total += r.direction.dot(ends[1] - ends[0])
        return total


@dataclass(frozen=True)
class Cord(Part):
    """A cord along `path` (Attachments, end to end); `drawn`: how much shorter a pull has left it
    than where the file places it (derive.mechanics.moves.pull)."""

    name: str
    path: tuple[Attachment, ...]
    drawn: sp.Expr = sp.Integer(0)

    def bodies(self) -> tuple[str, ...]:
        return tuple(dict.fromkeys(a.body for a in self.path if a.body is not None))

    def segments(self) -> list[Segment]:
        cuts = [i for i, a in enumerate(self.path) if 0 < i < len(self.path) - 1 and a.grips]
        bounds = [0, *cuts, len(self.path) - 1]
        pieces = [self.path[s:e + 1] for s, e in zip(bounds, bounds[1:])]
        result = []
        for k, piece in enumerate(pieces, start=1):
            name = "tension" if len(pieces) == 1 else f"tension_{k}"
            pulled = any(a.kind == "pulled" for a in piece)
            symbol = None if pulled else sp.Symbol(f"T_{self.name}" + ("" if len(pieces) == 1 else f"_{k}"), real=True)
            result.append(Segment(piece, name, symbol))
        return result

    def unknowns(self) -> dict[str, sp.Symbol]:
        return {s.tension_name: s.symbol for s in self.segments() if s.symbol is not None}

    def gaps(self, coords) -> list[sp.Expr]:
        rest = coords.at_rest_in_reference()
        result = []
        for s in self.segments():
            if s.symbol is not None:
                length = s.length(coords)
                result.append(length.xreplace(rest) - self.drawn - length)
        return result

    def power(self, coords) -> sp.Expr:
        return sum((-s.tension * coords.ddt(s.length(coords)) for s in self.segments() if s.symbol is None),
                   sp.Integer(0))

    def loads(self, coords) -> list[AppliedForce]:
        result = []
        for s in self.segments():
            label = f"tension of {self.name}"
            for r in s.runs(coords):
                for a, point, sign in ((r.start, r.start_point, 1), (r.end, r.end_point, -1)):
                    if a.body is None or a.kind == "pulled":
                        continue
                    result.append(AppliedForce(a.body, point - coords.position(a.body),
                                               sign * s.tension * r.direction, label))
        return result

    def conditions(self, coords) -> list[sp.Expr]:
        return [s.rate(coords) for s in self.segments() if s.symbol is not None]

    def sentences(self, route: str, coords) -> list[Sentence]:
        result = []
        for s in self.segments():
            gripping = [a for a in s.attachments if a.grips or a.kind == "wound"]
            if route == "lagrange":
                path = ", ".join(_where(a, i == 0) for i, a in enumerate(s.attachments))
                subject = f"The cord {self.name}" if len(self.segments()) == 1 else f"The part of the cord {self.name} that"
                if s.symbol is None:
                    result.append(Sentence((f"{subject} runs {path}; the force ", s.pulled.force, " that pulls "
                                            "its free end does work at the rate of the force times how fast the end "
                                            "moves out: its power.")))
                else:
                    result.append(Sentence((f"{subject} runs {path}; it does not stretch, so its length "
                                            "stays what it is, and the multiplier of that constraint is its tension ",
                                            s.symbol, ".")))
                result += [Sentence((f"It does not slip on the {a.body}, so the {a.body}'s rim moves with it: the arc of "
                                     "its turn, ", a.radius * coords.angle(a.body), ", counts in the length."))
                           for a in gripping]
                continue
            for r in s.runs(coords):
                for a, point, sign in ((r.start, r.start_point, 1), (r.end, r.end_point, -1)):
                    if a.body is None or a.kind == "pulled":
                        continue
                    load = AppliedForce(a.body, point - coords.position(a.body), sign * s.tension * r.direction, "")
                    result.append(Sentence((f"The cord {self.name} pulls the {a.body} along its run with the tension ",
                                            s.tension, *acting(load, coords, (s.tension,)), "."), a.body))
            if s.symbol is not None:
                slip = ", and does not slip on the " + " or the ".join(a.body for a in gripping) if gripping else ""
                rate = at_placement(s.rate(coords), coords)
                math = (": ", sp.Eq(rate, 0)) if sp.count_ops(rate) < 40 else ()
                result.append(Sentence((f"The cord {self.name} does not stretch{slip}, so the rates at which its runs "
                                        "lengthen add up to zero", *math, ".")))
        return result

    def windings(self, coords, sample) -> list[str]:
        """How the cord goes round each circle its file names a `side:` of, in words: the sense that
        side chose, where the runs touch the circle (in the reference configuration, `sample`
        giving an expression's value at the middle of the parameter ranges) and the sides that would
        take the other sense, and so the other tangent from a neighbour.

        >>> from derive.model.kinematics import Coordinates
        >>> from derive.model.scene import Body, Scene
        >>> R = sp.Symbol("R", positive=True)
        >>> reel = Attachment("wound", "disk", radius=R, turn=-1, side="right", other_sides=("left",))
        >>> scene = Scene({"disk": Body("disk", "disk", 1, {"radius": R}), "block": Body("block", "point", 1, {},
        ...                at=(R, -3 * R))})
        >>> Cord("string", (reel, Attachment("point", "block"))).windings(Coordinates(scene), lambda e: float(e.subs(R, 1)))
        ['The cord string is wound on the disk clockwise (side: right) and leaves it at its right (0 degrees round from its right, counter-clockwise), toward the block; side: left would wind it the other way, on the other tangent.']
        """
        rest = coords.at_rest_in_reference()
        runs = [run(a, b, coords) for a, b in zip(self.path, self.path[1:])]
        result = []
        for i, a in enumerate(self.path):
            if not a.side:
                continue
            touches = ([runs[i - 1].end_point] if i > 0 else []) + ([runs[i].start_point] if i < len(runs) else [])
            where = [_on_circle(sample, (t - a.center(coords)).xreplace(rest)) for t in touches]
            sense = "counter-clockwise" if a.turn > 0 else "clockwise"
            other = (f"; side: {', '.join(a.other_sides)} would {'wind' if a.kind == 'wound' else 'take'} it the "
                     "other way, on the other tangent" if a.other_sides else "")
            if a.kind == "wound" and sample((touches[0] - a.center(coords)).xreplace(rest).dot(sp.Matrix(SIDES[a.side]))) < 0:
                # the sense the side chose leaves the cord on the opposite half of the circle
                other += f"; that is not on its {a.side} half: the cord leaves from the far side of the circle"
            if a.kind == "wound":
                toward = self.path[1] if i == 0 else self.path[-2]
                result.append(f"The cord {self.name} is wound on {_named(a)} {sense} (side: {a.side}) and "
                              f"leaves it at {where[0]}, toward {_named(toward)}{other}.")
            else:
                result.append(f"The cord {self.name} goes round {_named(a)} {sense} (side: {a.side}), from "
                              f"{where[0]} to {where[1]}{other}.")
        return result

    def extents(self, coords) -> list[tuple[sp.Expr, str]]:
        """Each straight run measured along its direction in the reference configuration: its
        length there, zero where its ends meet, negative where they have crossed. A drawn cord's
        run, its own length: after a pull the body may be anywhere about the point (the puck circles)."""
        rest = coords.at_rest_in_reference()
        result = []
        for s in self.segments():
            for r in s.runs(coords):
                if r.length is not None:
                    along = r.length if self.drawn != 0 else r.direction.xreplace(rest).dot(r.end_point - r.start_point)
                    result.append((along,
                                   f"the cord {self.name}'s run from {describe(r.start)} to {describe(r.end)} would "
                                   "shrink to nothing (its ends would meet)"))
        return result

    def signs(self) -> list[Sign]:
        return [Sign(s.symbol, f"the cord {self.name} goes slack (its tension would be negative)",
                     f"the cord {self.name} is slack", f"its {s.tension_name.replace('_', ' ')}")
                for s in self.segments() if s.symbol is not None]


#: Where a cord touches a circle it goes around (or leaves a body it is wound on).
SIDES = {"over": (0, 1), "under": (0, -1), "left": (-1, 0), "right": (1, 0), "top": (0, 1), "bottom": (0, -1)}

#: The elements of a cord's path that are mappings (an element may also be a point).
PULL = Keys(force=Key("expression", "the force pulling the free end, in N", required=True),
            angle=Key("quantity", "its direction from +x, counter-clockwise (default 0)"))
PULLED = Keys(pulled=Key("mapping", "an end of the cord pulled by a given force", required=True, keys=PULL))
WOUND = Keys(wound=Key("point", "an end wound on this body, unwinding from its rim", required=True),
             side=Key("name", "the side of the body the cord leaves it from", required=True, choices=tuple(SIDES)),
             radius=Key("expression", "the radius it is wound at, in m (default: the body's radius)"))
AROUND = {side: Keys(**{side: Key("point", f"the cord passes around this body or point, touching its {side} side",
                                  required=True)},
                     radius=Key("expression", "the radius of the circle it goes around, in m (default: the body's)"),
                     smooth=Key("boolean", "the cord slides over it (default false: a pulley turns with the cord)"))
          for side in SIDES}


def read(reader, places, name: str, path, field: str) -> Cord:
    """A cord's path: a list from one end to the other.

    Ends: a point (`block`, `rod.end`, `{rod: [x, y]}`, `[x, y]`, a name from `points`);
    `{wound: BODY, side: right, radius: r}` (wound on the body, leaving it on that side; the
    radius is the body's unless given: a stepped pulley, a yo-yo's axle); `{pulled: {force: F,
    angle: EXPR}}` (a free end pulled toward that angle). In between: `{over: PULLEY}` (also
    `under`, `left`, `right`: the side of the circle the cord touches) with `radius` (the body's
    unless given) and `smooth: true` (the cord slides: a frictionless pulley); a pulley that turns
    on an axle grips the cord. A point in between is a smooth peg of no size.
    """
    if not isinstance(path, list) or len(path) < 2:
        raise reader.fail(field, "expected a list of at least two attachments, from one end of the cord to the other")
    elements = [_element(reader, places, value, f"{field}[{i}]", i in (0, len(path) - 1))
                for i, value in enumerate(path)]
    if sum(e["kind"] == "pulled" for e in elements) > 1:
        raise reader.fail(field, "a cord has at most one pulled end (the other is tied, wound or held)")
    centers = [places.world(e["body"], e["offset"]) for e in elements]
    attachments = []
    for i, e in enumerate(elements):
        where = f"{field}[{i}]"
        if "side" in e:  # a peg (a point in between) has no size: no side to go round
            before = centers[i - 1] if i > 0 else centers[i]
            after = centers[i + 1] if i + 1 < len(centers) else centers[i]
            travel = after - before
            for neighbour, sense in ((i + 1, 1), (i - 1, -1)):  # a pulled neighbour fixes the direction
                if 0 <= neighbour < len(elements) and elements[neighbour]["kind"] == "pulled":
                    angle = elements[neighbour]["angle"]
                    travel = sense * sp.Matrix([sp.cos(angle), sp.sin(angle)])
            crossings = {side: places.sample(v[0] * travel[1] - v[1] * travel[0]) for side, v in SIDES.items()}
            if abs(crossings[e["side_name"]]) < 1e-12:
                raise reader.fail(where, f"the cord runs straight at the {e['side_name']} of the circle: it does not "
                                         "go around it there (check the side and the positions)")
            e["turn"] = 1 if crossings[e["side_name"]] > 0 else -1
            e["other_sides"] = tuple(side for side, crossing in crossings.items() if crossing * e["turn"] < -1e-12)
        attachments.append(Attachment(e["kind"], e["body"], e["offset"], e.get("radius", sp.Integer(0)),
                                      e.get("turn", 0), e.get("grips", False), e.get("force"), e.get("angle"),
                                      e.get("side_name", ""), e.get("other_sides", ())))
    return Cord(name, tuple(attachments))


def _element(reader, places, value, field: str, end: bool) -> dict:
    if isinstance(value, dict) and set(value) & {"wound", "pulled", *SIDES}:
        keys = set(value) & {"wound", "pulled", *SIDES}
        if len(keys) != 1:
            raise reader.fail(field, f"expected one of wound, pulled, {', '.join(SIDES)}")
        (kind,) = keys
        if kind == "pulled":
            if not end:
                raise reader.fail(field, "a pulled end is an end of the cord")
            reader.mapping(value, field, keys=PULLED)
            pull = reader.mapping(value["pulled"], f"{field}.pulled", keys=PULL)
            return {"kind": "pulled", "body": None, "offset": ZERO,
                    "force": reader.positive(pull["force"], f"{field}.pulled.force", "N", "a pulling force"),
                    "angle": reader.dimensioned(pull.get("angle", 0), f"{field}.pulled.angle", "rad", "an angle")}
        if kind == "wound":
            if not end:
                raise reader.fail(field, "a cord is wound on a body at one of its ends; in between it goes around "
                                         "(over, under, left, right)")
            spec = reader.mapping(value, field, keys=WOUND)
            side = spec["side"]
        else:
            spec = reader.mapping(value, field, keys=AROUND[kind])
            side = kind
        if side not in SIDES:
            raise reader.fail(f"{field}.side", f"expected one of {', '.join(SIDES)}")
        body, offset = places.point(spec[kind], f"{field}.{kind}", ground=kind != "wound")
        rigid = places.bodies.get(body)
        if "radius" in spec:
            radius = reader.positive(spec["radius"], f"{field}.radius", "m", "a radius")
        elif rigid is not None and "radius" in rigid.sizes and not any(offset) and rigid.round_center is None:
            radius = rigid.sizes["radius"]
        else:
            raise reader.fail(f"{field}.radius", "give the radius the cord goes around (this has none of its own)")
        if body is not None:
            places.on_body(body, (offset[0] + radius, offset[1]) if not any(offset) else offset, f"{field}.radius")
        smooth = spec.get("smooth", False)
        if not isinstance(smooth, bool):
            raise reader.fail(f"{field}.smooth", "expected true or false")
        turns = rigid is not None and rigid.rotates and not any(offset)
        if kind == "wound" and not (rigid is not None and rigid.rotates):
            raise reader.fail(f"{field}.wound", "a cord is wound on a turning body (a disk, a reel, a spool)")
        return {"kind": "wound" if kind == "wound" else "around", "body": body, "offset": offset, "radius": radius,
                "side": SIDES[side], "side_name": side, "grips": kind == "wound" or (turns and not smooth)}
    body, offset = places.point(value, field)
    if body is not None:
        places.on_body(body, offset, field)
    return {"kind": "point" if end else "around", "body": body, "offset": offset}


def _where(a: Attachment, first: bool) -> str:
    """How a sentence names a place on a cord's path: from the disk, around the pulley, ..."""
    end = "from" if first else "to"
    if a.kind == "pulled":
        return f"{end} its free end, pulled"
    if a.kind == "wound":
        return f"{end} the {a.body}, wound on it"
    if a.kind == "point":
        return f"{end} the {a.body}" if a.body is not None else f"{end} a point of the ground"
    if a.body is None:
        return "around a smooth peg"
    return f"around the {a.body}" + ("" if a.grips else ", sliding over it")


#: The eighths of a circle, counter-clockwise from its right, as a figure's reader names them.
OCTANTS = ("right", "upper right", "top", "upper left", "left", "lower left", "bottom", "lower right")


def _on_circle(sample, offset: sp.Matrix) -> str:
    """Where a point offset from a circle's center lies on it, in words and degrees."""
    degrees = round(math.degrees(math.atan2(sample(offset[1]), sample(offset[0])))) % 360
    return f"its {OCTANTS[round(degrees / 45) % 8]} ({degrees} degrees round from its right, counter-clockwise)"


def _named(a: Attachment) -> str:
    """An attachment as a sentence names it: the disk, the ground point, the pull."""
    return "the pull" if a.kind == "pulled" else f"the {a.body}" if a.body is not None else describe(a)


def describe(a: Attachment) -> str:
    """An attachment by its body's name, or "the ground point"."""
    return a.body if a.body is not None else "the ground point"
