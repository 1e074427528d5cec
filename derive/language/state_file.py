"""The states section of a scene (`scene.states`): named states, each the placement moving at given
rates or where the motion from another state gets to (a position, a stop, a force falling to
zero). derive.mechanics.states finds them; derive.solution.state_answers answers in them.

>>> from derive.language.problem import load
>>> load("rod_swings_down").scene.states["lowest"].when[:2]
('rod', 'theta')
"""
from __future__ import annotations

import re

import sympy as sp

from derive.core.keys import Key, Keys
from derive.parts import contact
from derive.parts.contact import Contact
from derive.parts.cord import Cord
from derive.language.reader import Reader
from derive.parts.pin import Pin
from derive.parts.slipping_clutch import SlippingClutch
from derive.model.scene import Body, Event, State
from derive.core.spelling import no_such

#: How a state names a body's coordinates: (kind, unit) of a position (`when:`) and of a rate (`rates:`).
STATE_POSITIONS = {"x": ("x", "m"), "y": ("y", "m"), "angle": ("theta", "rad")}
STATE_RATES = {"velocity.x": ("x", "m/s"), "velocity.y": ("y", "m/s"), "angular_velocity": ("theta", "rad/s")}


def read(reader: Reader, raw, places, constraints: list) -> dict[str, State]:
    """`states: {spinning: {rates: {wheel.angular_velocity: w0}}, vertical: {when: {rod.angle: -pi/2},
    from: spinning}}`: each state's `from` one named above it (no state reached from itself).
    `when:` gives a position (`{BODY.x|y|angle: value}`) or a rate (`{BODY.velocity.x|y|angular_velocity:
    value}`: a ball at the top of its flight, `{ball.velocity.y: 0}`), or the first point where the motion
    stops (`stops`), a body leaves its surface (`{leaves: BODY or CONTACT}`), a cord goes slack
    (`{slack: CORD}`), a contact's grip fails (`{slips: BODY or CONTACT}`, friction: {static:
    mu_s}) or a slipping clutch or a sliding body grips (`{grips: CLUTCH or BODY}`). `event:` is
    an impact, a move, a turn or a transfer onto another surface in the state from: (see EVENTS),
    and the state is the one just after it."""
    result, bodies = {}, places.bodies
    taken = {*bodies, *(p.name for p in constraints), "placement", "ground"}  # an impact's joint is named so
    for name, spec in reader.named(raw, "states").items():
        field = f"scene.states.{name}"
        if name in taken:
            raise reader.fail(field, f"the name {name!r} is taken: name the state otherwise")
        spec = reader.mapping(spec, field, keys=STATE)
        if not isinstance(spec.get("from", ""), str):
            raise reader.fail(f"{field}.from", "the name of a state above this one")
        earlier = result.get(spec.get("from"))
        moves_on = isinstance(spec.get("event"), dict) and {"move", "turn"} & set(spec["event"])
        pulls_on = isinstance(spec.get("event"), dict) and "pull" in spec["event"]
        if earlier and earlier.event and earlier.event.kind == "pull" and not pulls_on:
            raise reader.fail(f"{field}.from", f"where the bodies are after the pull {earlier.name} depends on how it "
                                               "is made: only another pull may follow it")
        if earlier and earlier.event and earlier.event.kind == "move" and not moves_on:
            raise reader.fail(f"{field}.from", f"where the bodies are after the move {earlier.name} depends on how it "
                                               "is made (a turntable turns while a child walks on it): only another "
                                               "move or a turn may follow it")
        if sum(key in spec for key in ("rates", "when", "event")) != 1:
            raise reader.fail(field, "a state gives rates: (at the placement), when: (a position reached) or event: "
                                     "(an impact, a move or a turn in the state from:)")
        if "nudged" in spec and "when" not in spec:
            raise reader.fail(f"{field}.nudged", "a vanishing push starts a motion: it goes with when:")
        if "event" in spec:
            result[name] = _event(reader, name, spec, field, places, constraints, result)
            continue
        if "rates" in spec:
            if "from" in spec:
                raise reader.fail(f"{field}.from", "rates: are given at the placement; from: goes with when:")
            rates = reader.mapping(spec["rates"], f"{field}.rates", free=True)
            if not rates:
                raise reader.fail(f"{field}.rates", "give at least one rate, e.g. wheel.angular_velocity: omega0")
            result[name] = State(name, rates=tuple(_state_entry(reader, key, value, f"{field}.rates", bodies, STATE_RATES)
                                                   for key, value in rates.items()))
            continue
        nudge = _nudge(reader, spec.get("nudged"), f"{field}.nudged", bodies)
        if nudge and (not isinstance(spec["when"], dict) or any(k in THRESHOLDS for k in spec["when"])) \
                and nudge is True:
            raise reader.fail(f"{field}.nudged", "a push toward the state needs its position (when: {BODY.x|y|angle: "
                                                 "value}); otherwise say which way it moves: {BODY.x|y|angle: 1 or -1}")
        start = spec.get("from")
        if start is not None and start not in result:
            raise reader.fail(f"{field}.from", f"expected a state named above this one (states: "
                                               f"{', '.join(result) or 'none'})")
        if spec["when"] == "stops":
            result[name] = State(name, start=start, until=("stops", None), nudge=nudge)
            continue
        if not isinstance(spec["when"], dict):
            raise reader.fail(f"{field}.when", "expected stops, or one of {BODY.x|y|angle: value}, {BODY.velocity.x|y: value}, "
                                               "{leaves: BODY}, "
                                               "{slack: CORD}, {slips: BODY} and {grips: CLUTCH or BODY}")
        when = reader.mapping(spec["when"], f"{field}.when", free=True)
        relative = _relative(reader, when.pop("relative_to", None), f"{field}.when", places, when)
        if len(when) != 1:
            raise reader.fail(f"{field}.when", "give one position (rod.angle: -pi/2) or rate (ball.velocity.y: 0), or stops, "
                                               "{leaves: BODY}, "
                                               "{slack: CORD}, {slips: BODY} or {grips: CLUTCH or BODY}")
        (key, value), = when.items()
        if key in THRESHOLDS:
            result[name] = State(name, start=start, until=(key, _threshold_part(reader, key, value, f"{field}.when.{key}",
                                                                                constraints)), nudge=nudge)
            continue
        rate = str(key).partition(".")[2] in STATE_RATES
        if relative and (rate or relative[0] == str(key).partition(".")[0]):
            raise reader.fail(f"{field}.when.relative_to", "a place relative to another body is of a position "
                                                           "(x, y or angle) of a body other than that one")
        result[name] = State(name, when=_state_entry(reader, key, value, f"{field}.when", bodies,
                                                     STATE_RATES if rate else {**STATE_POSITIONS, **STATE_RATES}),
                             start=start, rate=rate, nudge=nudge, relative_to=relative)
    return result


def _relative(reader: Reader, raw, field: str, places, when: dict) -> tuple | None:
    """`relative_to: BODY` or a point of it (`plank.end`, `{rod: [x, y]}`): the state's position is
    measured from that point in that body's frame (None where not given)."""
    if raw is None:
        return None
    if len(when) != 1 or any(k in THRESHOLDS for k in when):
        raise reader.fail(f"{field}.relative_to", "relative_to goes with one position: {BODY.x|y|angle: value, "
                                                  "relative_to: OTHER or OTHER.POINT}")
    return places.point(raw, f"{field}.relative_to", ground=False)


def _nudge(reader: Reader, raw, field: str, bodies: dict[str, Body]) -> bool | tuple[str, str, int]:
    """`nudged: true` or `nudged: {BODY.x|y|angle: 1 or -1}` (see State.nudge); False where not given."""
    if raw is None or raw is False:
        return False
    if raw is True:
        return True
    spec = reader.mapping(raw, field, free=True) if isinstance(raw, dict) else None
    if not spec or len(spec) != 1:
        raise reader.fail(field, "expected true, or one coordinate and the way it first moves: {BODY.x|y|angle: 1 or -1}")
    (key, way), = spec.items()
    body, kind, _ = _state_entry(reader, key, 0, field, bodies, STATE_POSITIONS)
    if way not in (1, -1):
        raise reader.fail(f"{field}.{key}", "expected 1 or -1: the way the coordinate first moves")
    return (body, kind, way)


#: The events a state may follow: what each makes of the two bodies.
EVENTS = {"stick": "the body sticks to the other where it touches it",
          "lock": "the two turning bodies turn together from then on (a clutch); with at: rims, two round bodies on "
                  "fixed axles touching at their rims roll on each other from then on",
          "bounce": "a point mass or a round body bounces off a rod or a round body, or off a fixed surface, with "
                    "restitution: e; smooth, or rough with friction: {static: mu} or grips: true",
          "move": "a point mass pinned to a body is carried to the point to: of that body by the scene's own forces "
                  "(a child walking to a turntable's center)",
          "turn": "a turning body turns through angle: relative to the body relative_to: by a couple between them "
                  "(Elroy's beanie)",
          "transfer": "a body resting on a surface (or a contact joint) passes onto the surface to:, where it "
                      "touches both and the two meet tangentially (a ball rolling down a ramp into a loop)",
          "pull": "a cord tied to a ground point (a hole in a table) and to a point mass is drawn in, or let out, "
                  "slowly through that point until its length is length: (a puck on a table pulled in by its cord)"}

#: `event:` what happens in the state `from:` (exactly one of EVENTS, with what it takes).
EVENT = Keys(**{kind: Key("name", f"the body (or contact) of the event: {meaning}") for kind, meaning in EVENTS.items()},
             to=Key("point", "the other body, surface or point of the event"),
             restitution=Key("expression", "a bounce's coefficient of restitution, e"),
             relative_to=Key("name", "a turn's other body"),
             angle=Key("quantity", "the angle a turn turns through"),
             friction=Key("mapping", "a rough bounce's coefficients", keys=contact.FRICTION),
             grips=Key("boolean", "a rough bounce that grips (default false)"),
             length=Key("quantity", "the length a pull leaves the cord at"),
             at=Key("name", "a lock of two round bodies on fixed axles at their rims: rims (they slip until their rims "
                            "move together, then roll on each other)"))
#: A state's entry under `scene.states`: exactly one of rates, when and event.
STATE = Keys(rates=Key("mapping", "rates at the placement: {BODY.angular_velocity: w0, BODY.velocity.x: v0, ...}"),
             when=Key("any", "where the motion from from: gets to: stops, {BODY.x|y|angle: value} (measured from "
                             "another body or its point with relative_to: OTHER), "
                             "{BODY.velocity.x|y: value}, {leaves: BODY}, {slack: CORD}, {slips: BODY}, {grips: NAME}"),
             event=Key("mapping", "an impact, a move, a turn or a transfer in the state from:", keys=EVENT),
             nudged=Key("any", "the motion from a balance it would never leave (a rod on its end, a ball on a dome's "
                               "top) starts with a vanishing push: true (toward where this state is) or "
                               "{BODY.x|y|angle: 1 or -1} (the way it first moves); the answers are the limit"),
             **{"from": Key("name", "the state this one follows (default: the placement, at rest)")})



def _event(reader: Reader, name: str, spec: dict, field: str, places, constraints: list,
           found: dict[str, State]) -> State:
    """`{from: STATE, event: {stick: BODY, to: OTHER}}`, `{lock: BODY, to: OTHER}`, `{bounce:
    BODY, to: OTHER or SURFACE, restitution: e}` with, rough, `friction: {static: mu}` or `grips:
    true` (the state just after an impact in the state from:),
    `{move: BODY, to: OTHER.POINT}` (the state after the move), `{turn: BODY, relative_to:
    OTHER, angle: psi}` (the state after the turn) or `{transfer: BODY or CONTACT, to: SURFACE}`
    (the state just after its contact passes onto the surface)."""
    bodies = places.bodies
    if spec.get("from") not in found:
        raise reader.fail(f"{field}.from", f"an event happens in a state: give from: a state named above this one "
                                           f"(states: {', '.join(found) or 'none'})")
    raw = reader.mapping(spec["event"], f"{field}.event", keys=EVENT)
    kinds = [k for k in EVENTS if k in raw]
    if len(kinds) != 1:
        raise reader.fail(f"{field}.event", "give one of " + "; ".join(f"{k}: BODY ({m})" for k, m in EVENTS.items()))
    kind = kinds[0]
    body = raw[kind]
    if kind == "pull":
        return State(name, start=spec["from"], event=_pull(reader, body, raw, f"{field}.event", places, constraints))
    if "length" in raw:
        raise reader.fail(f"{field}.event.length", f"a {kind} has no length (a pull has)")
    # a transfer may name a contact joint (a ladder's foot): the point that passes onto the other surface
    touching = {c.name for c in constraints if isinstance(c, Contact) and c.point is not None} if kind == "transfer" \
        else set()
    if not isinstance(body, str) or body not in bodies and body not in touching:
        raise reader.fail(f"{field}.event.{kind}", no_such("body", body, bodies, "bodies"))
    wanted = ("relative_to", "angle") if kind == "turn" else ("to",)
    for key in ("to", "relative_to", "angle"):
        if key in raw and key not in wanted:
            raise reader.fail(f"{field}.event.{key}", f"a {kind} has no {key}: it gives {' and '.join(wanted)}")
        if key not in raw and key in wanted:
            raise reader.fail(f"{field}.event.{key}", f"missing: a {kind} gives {' and '.join(wanted)}")
    if kind == "turn":
        return State(name, start=spec["from"], event=_turn(reader, body, raw, f"{field}.event", bodies))
    to = raw["to"]
    for key in ("restitution", "friction", "grips"):
        if key in raw and kind != "bounce":
            raise reader.fail(f"{field}.event.{key}", f"a {kind} has no {key} (a bounce has)")
    if "at" in raw and (kind != "lock" or raw["at"] != "rims"):
        raise reader.fail(f"{field}.event.at", "expected at: rims, of a lock (two round bodies on fixed axles that "
                                               "roll on each other at their rims from then on)")
    if kind == "transfer":
        return State(name, start=spec["from"], event=_transfer(reader, body, to, f"{field}.event", places,
                                                               constraints, spec["from"], found))
    if kind == "move":
        return State(name, start=spec["from"], event=_move(reader, body, to, f"{field}.event", places, constraints,
                                                           spec["from"], found))
    if kind == "bounce" and isinstance(to, str) and to not in bodies and to in places.surfaces:
        return State(name, start=spec["from"], event=_bounce(reader, body, to, raw, f"{field}.event"))
    if not isinstance(to, str) or to not in bodies:
        raise reader.fail(f"{field}.event.to", no_such("body", to, bodies, "bodies"))
    if body == to:
        raise reader.fail(f"{field}.event.to", f"an impact joins two bodies: not the {body} to itself")
    if kind == "lock" and not (bodies[body].rotates and bodies[to].rotates):
        raise reader.fail(f"{field}.event", "lock joins two turning bodies (a point mass does not turn): "
                                            "a point mass sticks (stick:)")
    if kind == "bounce":
        return State(name, start=spec["from"], event=_bounce(reader, body, to, raw, f"{field}.event"))
    if kind == "lock":
        _lock(reader, body, to, "at" in raw, f"{field}.event", places, constraints)
    return State(name, start=spec["from"], event=Event(kind, body, to, rims="at" in raw))


def _lock(reader: Reader, body: str, to: str, rims: bool, field: str, places, constraints: list) -> None:
    """A lock's bodies: a clutch's turn about one axle (their centers held together, or apart only
    where something else holds them: not two fixed axles); at the rims, two round bodies each on a
    fixed axle at its center (`joint: fixed_axle`)."""
    axles = {c.body for c in constraints if isinstance(c, Pin) and c.to is None and not any(c.offset)}
    if rims:
        for name in (body, to):
            if name not in axles or "radius" not in places.bodies[name].sizes:
                raise reader.fail(field, f"a lock at the rims joins two round bodies each on a fixed axle at its "
                                         f"center (joint: fixed_axle): the {name} is not")
    elif {body, to} <= axles and any(sp.simplify(a - b) != 0 for a, b in zip(places.bodies[body].at,
                                                                               places.bodies[to].at)):
        raise reader.fail(field, f"the {body} and the {to} turn on two fixed axles: a clutch cannot join them; two "
                                 "round bodies pressed together at their rims lock with at: rims")


def _bounce(reader: Reader, body: str, to: str, raw: dict, field: str) -> Event:
    """A bounce off a body or a surface: its coefficient of restitution and, rough, the friction
    at the contact (`friction: {static: mu_s, kinetic: mu_k}`: it grips where that needs at most
    mu_s times the normal impulse, else slides with mu_k, mu_s where only that is given) or
    `grips: true` (a contact that always grips)."""
    if "restitution" not in raw:
        raise reader.fail(f"{field}.restitution", "missing: a bounce gives its coefficient of restitution "
                                                  "(1 elastic, 0 they move together along the normal)")
    restitution = _restitution(reader, raw["restitution"], f"{field}.restitution")
    if "grips" in raw and "friction" in raw:
        raise reader.fail(f"{field}.grips", "a rough bounce gives friction: {static: mu} (it grips or slides, "
                                            "decided per variant) or grips: true (it always grips), not both")
    if "grips" in raw and raw["grips"] is not True:
        raise reader.fail(f"{field}.grips", "expected true (a contact that always grips); leave it out for a "
                                            "smooth one")
    static, kinetic = contact.coefficients(reader, raw, field)
    friction = None if static is None and kinetic is None else (
        static if static is not None else kinetic, kinetic if kinetic is not None else static)
    return Event("bounce", body, to, restitution, friction=friction, grips="grips" in raw)


def _transfer(reader: Reader, which: str, to, field: str, places, constraints: list, start: str,
              found: dict[str, State]) -> Event:
    """A body's contact (`transfer: BODY`, resting on a surface by `on:`) or a contact joint's
    (`transfer: CONTACT`, a point touching a surface) passes onto the surface `to:` in the state
    from:. The event's `body` is the body, its `joint` the contact; `to` the surface."""
    held = [c for c in constraints if isinstance(c, Contact) and (c.name == which or c.body == which and c.point is None)]
    if not held:
        raise reader.fail(f"{field}.transfer", f"the {which} rests on no surface (on: SURFACE): a transfer moves a "
                                               "body's contact onto another surface")
    contact = held[0]
    if not isinstance(to, str) or to not in places.surfaces:
        raise reader.fail(f"{field}.to", no_such("surface", to, places.surfaces, "surfaces"))
    if places.surfaces[to].carrier == contact.body:
        raise reader.fail(f"{field}.to", f"the {contact.body} carries {to}: it cannot rest on it")
    surface, state = contact.surface, found.get(start)  # where the chain has it in the state from:
    while state is not None and not (state.event and state.event.kind == "transfer"
                                     and state.event.joint == contact.name):
        state = found.get(state.start)
    surface = state.event.to if state is not None else surface
    if surface == to:
        raise reader.fail(f"{field}.to", f"the {contact.body} is on {to} already in the state {start}")
    return Event("transfer", contact.body, to, joint=contact.name)


def _turn(reader: Reader, body: str, raw: dict, field: str, bodies: dict[str, Body]) -> Event:
    """A turn of one turning body through an angle relative to another, by a couple between them."""
    other = raw["relative_to"]
    if not isinstance(other, str) or other not in bodies:
        raise reader.fail(f"{field}.relative_to", no_such("body", other, bodies, "bodies"))
    if other == body or not (bodies[body].rotates and bodies[other].rotates):
        raise reader.fail(field, "a turn is of one turning body relative to another (a point mass does not turn)")
    return Event("turn", body, other, angle=reader.dimensioned(raw["angle"], f"{field}.angle", "rad", "an angle"))


def _restitution(reader: Reader, raw, field: str):
    """A coefficient of restitution: a number, or parameters whose ranges keep it, in [0, 1]."""
    e = reader.dimensioned(raw, field, "1", "a coefficient of restitution")
    bounds = [p.si_ends for p in reader.parameters.values() if p.symbol in e.free_symbols]
    if e.is_negative or (not e.free_symbols and e > 1) or any(b[0] < 0 or b[1] > 1 for b in bounds):
        raise reader.fail(field, "a coefficient of restitution lies in [0, 1]")
    return e


def _pull(reader: Reader, cord: str, raw: dict, field: str, places, constraints: list) -> Event:
    """A pull of a straight cord from a ground point (a hole) to a point mass, to a new length: the
    event's `body` is the point mass, its `joint` and `to` the cord."""
    cords = {c.name: c for c in constraints if isinstance(c, Cord)}
    if not isinstance(cord, str) or cord not in cords:
        raise reader.fail(f"{field}.pull", no_such("cord", cord, cords, "cords"))
    path = cords[cord].path
    ends = sorted(path, key=lambda a: a.body is not None)
    if len(path) != 2 or any(a.kind != "point" for a in path) or ends[0].body is not None or ends[1].body is None \
            or places.bodies[ends[1].body].rotates:
        raise reader.fail(f"{field}.pull", f"a pull draws in a straight cord tied to a ground point (the hole it runs "
                                           f"through) and to a point mass: {cord}: [hole, puck]")
    extra = sorted(set(raw) - {"pull", "length"})
    if extra:
        raise reader.fail(f"{field}.{extra[0]}", "a pull gives the cord (pull:) and its new length (length:) only")
    if "length" not in raw:
        raise reader.fail(f"{field}.length", "missing: a pull gives the cord's new length (length: r2)")
    length = reader.positive(raw["length"], f"{field}.length", "m", "the cord's new length")
    return Event("pull", ends[1].body, cord, joint=cord, length=length)


def _move(reader: Reader, body: str, to, field: str, places, constraints: list, start: str,
          found: dict[str, State]) -> Event:
    """A move of a point mass held by one pin to another body (a joint of the scene, or the pin
    a stick on the way from the state `start` made), to a point of that body."""
    if places.bodies[body].rotates:
        raise reader.fail(f"{field}.move", f"the {body} turns: a move carries a point mass (shape: point) on the "
                                           "body it is pinned to")
    holding = [p for p in constraints if body in p.bodies()]
    pins = [(p.name, p.to if p.body == body else p.body) for p in holding if isinstance(p, Pin) and p.to is not None]
    # an impact on the way that stuck the point mass to a body pinned it there, by a pin named after its state
    state = found.get(start)
    while state is not None:
        if state.event and state.event.kind == "stick" and body in (state.event.body, state.event.to):
            pins.append((state.name, state.event.to if state.event.body == body else state.event.body))
            holding.append(state)
        state = found.get(state.start)
    if len(holding) != 1 or len(pins) != 1:
        raise reader.fail(f"{field}.move", f"a move carries a point mass held by one pin to another body (the {body} "
                                           f"is held by {', '.join(p.name for p in holding) or 'nothing'})")
    (joint, host), = pins
    where, place = places.point(to, f"{field}.to", ground=False)
    if where != host:
        raise reader.fail(f"{field}.to", f"the {body} moves on the {host}, which its pin {joint} holds it to: "
                                         f"give a point of the {host} ({host}.POINT or {{{host}: [x, y]}})")
    places.on_body(host, place, f"{field}.to")
    return Event("move", body, host, place=place, joint=joint)


#: The states where a part's force falls to zero (the part's kind and the force's key), or where a
#: slipping clutch's plates come to turn together.
THRESHOLDS = {"leaves": (Contact, "normal"), "slack": (Cord, None), "slips": (Contact, "friction"),
              "grips": ((SlippingClutch, Contact), None)}


def _threshold_part(reader: Reader, kind: str, raw, field: str, constraints: list) -> str:
    """The part whose force falls to zero: a contact (named, or by its body) or a cord of one tension."""
    part_type, _ = THRESHOLDS[kind]
    fitting = {c.name: c for c in constraints if isinstance(c, part_type)}
    if part_type in (Contact, (SlippingClutch, Contact)):
        fitting.update({c.body: c for c in constraints if isinstance(c, Contact) and c.point is None})
    if not isinstance(raw, str) or raw not in fitting:
        what = {Contact: "a contact (a body on a surface, or a contact joint)", Cord: "a cord",
                (SlippingClutch, Contact): "a slipping clutch (a joint {clutch: BODY, to: OTHER, slipping: C}) or a "
                                           "contact with kinetic friction"}[part_type]
        raise reader.fail(field, f"expected {what} of the scene ({', '.join(fitting) or 'none'})")
    part = fitting[raw]
    if kind == "grips" and not isinstance(part, SlippingClutch) and part.kinetic is None:
        raise reader.fail(field, f"the contact {raw} gives no kinetic friction: where it grips needs friction: "
                                 "{kinetic: mu_k}")
    if kind == "slips" and not part.has_friction:
        raise reader.fail(field, f"the contact {raw} gives no friction coefficient: where it slips needs "
                                 "friction: {static: mu_s}")
    if part_type is Cord and len(part.unknowns()) != 1:
        raise reader.fail(field, f"the cord {raw} has {len(part.unknowns())} tensions: slack is for a cord of one")
    return part.name


def _state_entry(reader: Reader, key, value, field: str, bodies: dict[str, Body], kinds: dict) -> tuple:
    """(body, coordinate kind, value) from `BODY.angle: -pi/2` (or a rate)."""
    head, _, rest = str(key).partition(".")
    if head == "time" and head not in bodies:
        raise reader.fail(f"{field}.{key}", "a state at a given time is not modelled: state where the motion gets "
                                            "(BODY.angle, BODY.x, a rate, or stops) and ask `of: time` there, or ask "
                                            "that state's time back for the parameter it needs (find: with equals:)")
    if head not in bodies:
        raise reader.fail(f"{field}.{key}", no_such("body", head, bodies, "bodies"))
    if rest not in kinds or kinds[rest][0] == "theta" and not bodies[head].rotates:
        allowed = [k for k, (kind, _) in kinds.items() if kind != "theta" or bodies[head].rotates]
        raise reader.fail(f"{field}.{key}", f"a state gives {head}'s {', '.join(allowed)}")
    kind, unit = kinds[rest]
    named = re.search(r"\b(" + "|".join(map(re.escape, bodies)) + r")\.[A-Za-z_]", str(value)) if bodies else None
    if named:  # where another body is: a state of the scene, not a value the file gives
        raise reader.fail(f"{field}.{key}", f"a state's value is an expression of the parameters, not of where the "
                                            f"{named[1]} is ({value}): give the {head}'s {rest} as a number of them, "
                                            f"or measured from the {named[1]} with relative_to: {named[1]} (or a point "
                                            f"of it, {named[1]}.end)")
    return head, kind, reader.dimensioned(value, f"{field}.{key}", unit, "a position" if unit in ("m", "rad") else "a rate")
