r"""Free-body diagrams drawn from the Newton–Euler route: each body alone, with every force of its balance.

`free_bodies(problem, scene, coords)` gives, for each body of a scene, a `FreeBody`: the body's outline
as the general layout draws it (`derive.publishing.figure.parts`: a disk a circle, a rod a bar, a custom body an
oval about its loads or a bar when they lie on one line; a point mass a dot, the particle of a
textbook's diagram, Knight, Physics for Scientists and Engineers, ch. 5), on a scale of its own with
its center of mass at the origin, and every force Newton–Euler applies to it
(`newton_euler.all_forces`: each part's AppliedForce, a world offset from the center and a force) as
an arrow at its point of application, and every couple (AppliedTorque) as a curved arrow about the
center. The forces are those of the step's equations: in the reference configuration at rest, their
directions evaluated at the middle of the parameter ranges (open sizes at 1, as the scene figure).

A force is split along the derivation's unknowns: one arrow per unknown along its coefficient, the
unknown's assumed positive axis (a pin's R_x along +x on its body and along -x on the other, a
normal force off its surface, a rolling contact's friction along the surface's tangent), labelled by
the unknown times that coefficient's length (N, or mu_k N for kinetic friction); what is known (a
weight, an applied force, a stretched spring) is one arrow along itself labelled by its magnitude
(M g). A contact's surface is a short gray line across its normal force, where it pushes from. A force zero there (a spring at its rest length, a damper at rest) is in no equation of the
step and is not drawn. An arrow pulls from its point, or pushes into it where it points into the
body from the rim (a normal force at a contact). Labels are `latex.latex_of`, as the equations
print them. Arrows are of one length: their sizes are not to scale. A force not linear in the
unknowns, one that changes with time (`t`: its sense may too), or a direction that does not
evaluate to a real nonzero vector leaves that body without a diagram (None) rather than with a
wrong one. Same problem, same bytes.

>>> from derive.solution.answers import Solution
>>> from derive.language.problem import load
>>> solution = Solution(load("string_wrapped_disk"))
>>> drawn = free_bodies(solution.problem, solution.dynamics_scene, solution.coordinates)
>>> [(a.label, a.direction) for a in drawn["block"].arrows]
[('T_{\\mathrm{string}}', (0.0, 1.0)), ('g m', (0.0, -1.0))]
>>> drawn["disk"].tikz.startswith(r"\begin{tikzpicture}")
True
>>> drawn["block"].alt
'Free-body diagram of the block: the tension of string, T string; the weight, g m.'

"""
from __future__ import annotations

import math
from dataclasses import dataclass

import sympy as sp

from derive.text.latex import latex_of, spoken
from derive.publishing.figure.canvas import _add, _f, _Figure, _pt, _unit
from derive.publishing.figure.drawn_view import ARROW, DIRECTIONS, LAYERS, Undrawable, _Body, _Scene
from derive.publishing.figure.vectors import _degrees, _on_segment, _perp, _sub
from derive.mechanics.newton_euler import all_forces
from derive.parts import AppliedForce, AppliedTorque
from derive.core.expr import TIME

REACH = {"round": 0.7, "point": 1.0}  # cm: how far the body's outline and loads reach from its center (else 1.1)
OUTSIDE = 0.75  # cm: how far an arrow from a point of the body reaches beyond its outline
SURFACE = 0.6  # cm: half the length of the line a contact's surface is drawn as, across its normal force
REPEAT = 1.4  # an arrow drawn where another already is (the same point and direction) is this much longer


@dataclass(frozen=True)
class Arrow:
    """One force of a diagram: its point (a world offset from the center of mass, m), its unit
    direction, its label (LaTeX), the force it draws (the part's label: "weight") and its label as
    text that reads as math (derive.text.latex.spoken: "M g"), for the diagram's alternative text."""

    offset: tuple[float, float]
    direction: tuple[float, float]
    label: str
    force: str = ""
    text: str = ""


@dataclass(frozen=True)
class Turn:
    """One couple of a diagram: +1 counter-clockwise, -1 clockwise, its label (LaTeX), and as an
    Arrow the couple it draws and its label as plain text."""

    sign: int
    label: str
    force: str = ""
    text: str = ""


@dataclass(frozen=True)
class FreeBody:
    """A body's free-body diagram: its forces and couples, the figure's scale (cm per m, its center
    of mass at the origin) and the ``tikzpicture``."""

    body: str
    arrows: tuple[Arrow, ...]
    turns: tuple[Turn, ...]
    scale: float
    tikz: str

    @property
    def alt(self) -> str:
        """The diagram in words, for an image's alternative text: the body, then each force (and
        couple) with the labels of its arrows, in the order drawn."""
        drawn: dict[str, list[str]] = {}
        for shown in (*self.arrows, *self.turns):
            drawn.setdefault(shown.force, []).append(shown.text)
        forces = "; ".join(f"the {force}, {', '.join(texts)}" for force, texts in drawn.items())
        return f"Free-body diagram of the {self.body}: {forces or 'no forces'}."


def free_bodies(problem, scene, coords, acting: dict | None = None, names: dict | None = None
                ) -> dict[str, FreeBody | None]:
    """Each body's free-body diagram (None where one of its forces cannot be drawn truthfully), from
    Newton–Euler's forces of `scene` in the coordinates `coords` (the derivation's). `acting`: the
    sense each constraint force acts in (-1: against its axis, drawn so, its symbol a magnitude:
    derive.mechanics.along_motion), else every one along its axis; `names`: symbols the labels print
    otherwise (f for f^ball, as the student's route does)."""
    loads = all_forces(scene, coords)
    unknowns = [u for part in scene.constraints for u in part.unknowns().values()]
    rest = {**coords.at_rest_in_reference(), **{u: -u for u, sign in (acting or {}).items() if sign < 0}}
    result = {}
    for name in scene.bodies:
        fig = _Figure(problem)
        view = _Scene(fig)
        try:
            arrows, turns = _forces(view, [f for f in loads if f.body == name], unknowns, rest, names or {})
            result[name] = _draw(fig, view, name, arrows, turns)
        except Undrawable:
            result[name] = None
    return result


def _forces(view: _Scene, loads, unknowns, rest, names: dict) -> tuple[list[Arrow], list[Turn]]:
    """The arrows and turns of a body's loads in the reference configuration at rest."""
    arrows, turns = [], []
    for load in loads:
        if isinstance(load, AppliedForce):
            force, offset = load.force.xreplace(rest), view.vector(load.offset)
            for vector, amount in _split(force, unknowns):
                direction = view.vector(vector)
                length = math.hypot(*direction)
                if length < 1e-9:
                    raise Undrawable(f"the {load.label} has no direction here")
                shown = (_size(vector, length) * amount).xreplace(names)
                arrows.append(Arrow(offset, (direction[0] / length, direction[1] / length), latex_of(shown),
                                    load.label, spoken(shown)))
        elif isinstance(load, AppliedTorque):
            for coefficient, amount in _split(sp.Matrix([load.torque.xreplace(rest)]), unknowns):
                value = view.value(coefficient[0])
                if abs(value) < 1e-12:
                    raise Undrawable(f"the {load.label} has no sense here")
                sign = 1 if value > 0 else -1
                shown = (sp.simplify(sign * coefficient[0]) * amount).xreplace(names)
                turns.append(Turn(sign, latex_of(shown), load.label, spoken(shown)))
    return arrows, turns


def _split(force: sp.Matrix, unknowns) -> list[tuple[sp.Matrix, sp.Expr]]:
    """A force (or a couple) as (coefficient, amount) pairs: each unknown with its coefficient, and
    the known rest with the amount 1; a force zero in the reference configuration has none."""
    if TIME in force.free_symbols:
        raise Undrawable("a force that changes with time (its sense may too)")
    present = [u for u in unknowns if u in force.free_symbols]
    pairs = []
    for u in present:
        coefficient = force.diff(u)
        if coefficient.free_symbols & set(unknowns):
            raise Undrawable(f"a force not linear in {u}")
        pairs.append((coefficient, u))
    known = force.xreplace({u: 0 for u in present}).applyfunc(sp.simplify)
    if known != sp.zeros(*known.shape):
        pairs.append((known, sp.Integer(1)))
    return pairs


def _size(vector: sp.Matrix, length: float) -> sp.Expr:
    """A coefficient's length, exact: 1 for a unit direction (where its value, `length`, is 1 and
    so is its square, not only at these parameters: mu_k may be 1 in the middle of its range)."""
    square = vector.dot(vector)
    if abs(length - 1) < 1e-12 and (sp.simplify(square) == 1 or square.equals(1)):
        return sp.Integer(1)
    return sp.simplify(sp.sqrt(square))


def _draw(fig: _Figure, view: _Scene, name: str, arrows: list[Arrow], turns: list[Turn]) -> FreeBody:
    """The body alone, on its own scale, with its arrows and turns."""
    drawn = _Body(view, name)
    view.origin = drawn.world
    offsets = [a.offset for a in arrows if math.hypot(*a.offset) > 1e-9]
    if drawn.kind == "oval" and not drawn.pieces:
        _bar_or_oval(view, drawn, offsets)
    reach = max([math.hypot(*_sub(p, drawn.world)) for p in drawn.corners_m()] +
                [math.hypot(*o) for o in offsets] + [0.0])
    view.scale = REACH.get(drawn.kind, 1.1) / reach if reach > 1e-9 else 1.0
    if drawn.kind == "oval" and not drawn.pieces:
        drawn.fit_oval([view.at(_add(drawn.world, o)) for o in offsets])
    drawn.shape()
    drawn_at: list = []  # (label, free end, its side)
    placed: list = []  # (point, direction, length) of the arrows drawn so far
    ways = [_way(view, drawn, arrow) for arrow in arrows]
    pushing = [(point, direction) for point, direction, pushes in ways if pushes]
    for arrow, (point, direction, pushes) in zip(arrows, ways):
        if arrow.force == "normal force":  # the surface it pushes from, a short line across the normal
            across = (-direction[1] * SURFACE, direction[0] * SURFACE)
            view.put("surfaces", f"\\draw[thin, gray] {_pt(_add(point, across))} -- {_pt(_add(point, across, -1))};")
            view.ink_line(_add(point, across), _add(point, across, -1))
        _arrow(view, arrow.label, point, direction, pushes, ARROW if pushes else _pull_length(drawn, point, direction, pushing),
               placed, drawn_at)
    for turn in turns:
        _turn(view, drawn, turn)
    for text, point, direction in drawn_at:
        view.label(point, f"${text}$", 0.05, [direction] + DIRECTIONS)
    fig.lines = [line for layer in LAYERS for line in view.layers[layer]]
    return FreeBody(name, tuple(arrows), tuple(turns), view.scale, fig.text())


def _bar_or_oval(view: _Scene, drawn: _Body, offsets) -> None:
    """A body of no particular shape whose loads and center of mass lie on one segment (a ladder
    given by its ends) is a bar between the two farthest apart (in its own frame), else an oval."""
    if len(offsets) < 2:
        return
    p, q = max(((p, q) for p in offsets for q in offsets), key=lambda pq: math.hypot(*_sub(*pq)))
    if math.hypot(*_sub(p, q)) > 1e-9 and all(_on_segment(o, p, q) for o in offsets + [(0.0, 0.0)]):
        back = -drawn.angle  # the world offsets in the body's own frame
        drawn.kind, drawn.ends = "bar", tuple(
            (o[0] * math.cos(back) - o[1] * math.sin(back), o[0] * math.sin(back) + o[1] * math.cos(back)) for o in (p, q))


def _way(view: _Scene, drawn: _Body, arrow: Arrow) -> tuple[tuple[float, float], tuple[float, float], bool]:
    """(its point on the figure, its direction, whether it pushes): a force pushes where it points
    into the body at a point away from its center (a normal force at the rim), else it pulls."""
    point, direction = view.at(_add(drawn.world, arrow.offset)), arrow.direction
    offset = _sub(point, drawn.center)
    pushes = math.hypot(*offset) > 0.5 * drawn.extent > 0 and offset[0] * direction[0] + offset[1] * direction[1] < -1e-9
    return point, direction, pushes


def _pull_length(drawn: _Body, point, direction, pushing) -> float:
    """A pull reaches OUTSIDE beyond the outline, unless it would run into a push along its line the
    other way (a weight down from the center onto a floor's normal force): it stops short of that."""
    length = max(0.0, drawn.reach(point, direction)) + OUTSIDE
    for tip, other in pushing:
        ahead = _sub(tip, point)
        along = ahead[0] * direction[0] + ahead[1] * direction[1]
        if other[0] * direction[0] + other[1] * direction[1] < -0.99 and 0 < along < length and \
                abs(ahead[0] * direction[1] - ahead[1] * direction[0]) < 0.05:
            length = max(0.3, along - 0.12)
    return length


def _arrow(view: _Scene, label: str, point, direction, pushes: bool, length: float, placed: list, labels: list) -> None:
    """A force's arrow from its point, or into it from outside where it pushes; its label goes at
    the free end (placed once everything is drawn)."""
    while any(math.hypot(*_sub(point, p)) < 0.02 and math.hypot(*_sub(direction, d)) < 0.02 and abs(length - k) < 1e-9
              for p, d, k in placed):
        length *= REPEAT  # two forces along one line from one point: both show
    placed.append((point, direction, length))
    start = _add(point, direction, -length) if pushes else point
    end = _add(start, direction, length)
    view.put("arrows", f"\\draw[force] {_pt(start)} -- {_pt(end)};")
    view.ink_line(start, end)
    view.put("joints", f"\\fill[red!70!black] {_pt(point)} circle (0.035);")
    free = start if pushes else end
    labels.append((label, free, direction if not pushes else (-direction[0], -direction[1])))


def _turn(view: _Scene, drawn: _Body, turn: Turn) -> None:
    """A couple: a curved arrow about the center, on its clearest side, labelled at its middle."""
    radius = drawn.extent + 0.25 if drawn.extent <= 1.0 else 0.5
    side = _degrees(view.clearest(drawn.center, radius + 0.3, own=drawn.outline()))
    start, end = (side - 55, side + 55) if turn.sign > 0 else (side + 55, side - 55)
    view.put("arrows", f"\\draw[force] {_pt(_add(drawn.center, _unit(start), radius))} arc[start angle={_f(start)}, "
                       f"end angle={_f(end)}, radius={_f(radius)}];")
    view.ink += [_add(drawn.center, _unit(start + (end - start) * k / 10), radius) for k in range(11)]
    middle = _unit(side)
    view.label(_add(drawn.center, middle, radius), f"${turn.label}$", 0.06, [middle, _perp(middle)] + DIRECTIONS)
