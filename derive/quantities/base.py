"""The protocol every quantity of derive.quantities fills in (`QuantityKind`), and the mixin of the
quantities read between two states (`StateChange`).

>>> describe_capitalized("the torque of the rod's weight")
"The torque of the rod's weight"
"""
from __future__ import annotations

from abc import ABC, abstractmethod
from dataclasses import dataclass
from typing import ClassVar

import sympy as sp

from derive.core import units
from derive.core.spelling import did_you_mean
from derive.model.directions import Sense
from derive.model.scene import SYSTEMS, Quantity
from derive.numbers.agreement import agree
from derive.text.steps import Step


class CheckFailure(RuntimeError):
    """Two routes of derivation disagree: a bug in the engine, never bad input."""


@dataclass(frozen=True)
class Check:
    """One independent check: its `name` and `method`, the `detail` `derive check` and the JSON
    give, and its `reading`, one sentence a student can read in a worked solution."""

    name: str
    passed: bool
    method: str
    detail: str
    reading: str


class QuantityKind(ABC):
    """What every quantity gives (one subclass per module of this package).

    kind: the `Quantity.kind` it answers; unit: the SI unit of its dimension; state: "change"
    (read in a state, `in: STATE`, as a change from the state it comes from), "optional" (at the
    placement at rest, or in a state), "never" or "motion" (derive.language.ask_states' rules for the
    quantities of the equations of motion: `ByRoutes`); sense: the words for a positive and a negative value (None: it points no way);
    routes: the two routes' names, in words, the key's first; options: the ask keys it needs
    (`about:`), each required but where `about_default` gives the point; about_in_space: its `about:`
    is a fixed point [x, y, z] (a particle's torque in space), not a point of the plane or of a body;
    about_default: the point where the ask gives no `about:` (None: required); exact_unit: asked in `unit` itself (turns in rev, where rad and
    deg would be the same dimension); own_section: whether the worked solution gives it a section of
    its own (`steps`) that the student's route (derive.solution.textbook) may carry, or its steps are
    those of the derivation it is read from (a moment of inertia's integral, an orbit by Binet's
    equation: derive.solution.answer_steps).
    """

    kind: ClassVar[str]
    symbol: ClassVar[str]  # its letter in the steps where the ask's name is a parameter's (tau, N, d)
    unit: ClassVar[str | None]  # None: by what is asked of it (an orbit's period or energy), the ask's unit checked
    state: ClassVar[str] = "never"
    sense: ClassVar[tuple[str, str] | None] = None
    routes: ClassVar[tuple[str, str]]
    options: ClassVar[tuple[str, ...]] = ()
    about_in_space: ClassVar[bool] = False
    about_default: ClassVar[tuple | None] = None
    exact_unit: ClassVar[bool] = False  # asked in `unit` itself (turns in rev), not any unit of its dimension
    own_section: ClassVar[bool] = True

    @abstractmethod
    def claims(self, scene, head: str, rest: str) -> Quantity | None:
        """The quantity an ask path `head.rest` names, None if it is not this kind's; ValueError
        (one line) where it is this kind's but names nothing in the scene."""

    @abstractmethod
    def value(self, solution, ask, route: int) -> sp.Expr | None:
        """The exact answer by route 0 (the key's) or 1 (its check), in the parameters (SI); None for
        a route 1 that is not a closed form (a simulation: `StateChange`)."""

    @abstractmethod
    def describe(self, ask) -> str:
        """The quantity in words, for a student: "the torque of the rod's weight about the hinge"."""

    def steps(self, solution, ask) -> list[Step]:
        """The worked solution's steps for the quantity: by default its value stated, in its ask's unit
        (`shown`) and under its name (`named`)."""
        return [Step("", (sp.Eq(named(self, ask), shown(self, solution, ask)),))]

    def sense_of(self, quantity: Quantity) -> tuple[str, str] | None:
        """The words for its two signs where what is asked of it points one way or the other: `sense`,
        whatever is asked, by default."""
        return self.sense

    def axis_of(self, quantity: Quantity) -> str | None:
        """The axis ("x", "y", "z") a component asked of it lies along: its sign is the axis's, which the
        question or the ask's meaning names (derive.checks.signs); None (the default) for any other."""
        return None

    def sense_in(self, scene, quantity: Quantity, coords, sample) -> Sense | None:
        """The words for its two signs in the scene (`sample`: an expression's value at the middle of the
        ranges, where the words depend on the geometry): `sense_of`'s, by default."""
        words = self.sense_of(quantity)
        return Sense(*words) if words else None

    def directional(self, quantity: Quantity) -> bool:
        """Whether it points one way or the other, whatever the scene: where `sense_of` has words, by default."""
        return self.sense_of(quantity) is not None

    def checks(self, solution, names: list[str]) -> list[Check] | None:
        """Its checks of the problem's asks `names`, every one of
        this kind, once per problem; None (the default): route 1 against route 0 at points of the ranges,
        by derive.solution.crosschecks."""
        return None

    def symbol_for(self, ask) -> str:
        """Its letter in the steps where the ask's name is a parameter's (`named`)."""
        return self.symbol

    def conditions(self, solution, ask) -> list[tuple[sp.Expr, bool, str]]:
        """(expression, strict, meaning): what must be positive (strict) or not negative in a variant for
        the answer to hold (derive.solution.answer_conditions); none by default."""
        return []

    def reads_motion(self, ask) -> bool:
        """Whether the answer depends on how the scene moves or on its forces (a friction
        coefficient the file gives is then used): by default, where it is read in a state."""
        return ask.state is not None

    def unknowns(self, solution, ask) -> set[sp.Symbol]:
        """The accelerations and forces of the derivation the answer is made of (shown in the steps)."""
        return set()

    def student_route(self, quantity: Quantity) -> bool:
        """Whether the student's route (derive.solution.textbook), at the placement at rest, answers it:
        a quantity with a section of its own adds it there (a torque: r x F with the forces the route finds)."""
        return self.own_section

    def sections(self, solution, ask) -> dict[str, list[Step]]:
        """Sections of the worked solution of its own besides the routes', where it is not `own_section`
        (a loop's least release height: the normal force at its top, and energy to it): none by default."""
        return {}

    def route_steps(self, solution, asks: list, route: str) -> list[Step]:
        """The steps this kind's asks (`asks`, in the problem's order) add to a route's section of the
        worked solution, after the route's equations and their solve (an equilibrium's, a period's):
        none by default."""
        return []


def body_ask(kind: str, held, head: str, rest: str, allowed, what: str, also=()) -> Quantity | None:
    """An ask of a body of one of the 3D kinds (`held`: the scene's bodies of that kind, by name): None
    where `head` is not one of them or its mass or inertia is asked (any body answers those); refused
    unless `rest` is `allowed` (`also`: the paths another module claims of such a body, named too).

    >>> body_ask("bearings", {"disk": None}, "disk", "bearings.torque", ("bearings.torque",), "a body in bearings")
    Quantity(kind='bearings', target='disk', detail='bearings.torque')
    >>> body_ask("bearings", {"disk": None}, "disk", "spin", ("bearings.torque",), "a body in bearings")
    Traceback (most recent call last):
    ValueError: a body in bearings has bearings.torque, mass and inertia
    """
    if head not in held or rest in ("mass", "inertia"):
        return None
    if rest not in allowed:
        raise ValueError(f"{what} has {', '.join((*allowed, *also))}, mass and inertia" + did_you_mean(rest, (*allowed, *also)))
    return Quantity(kind, head, rest)


def system_ask(kind: str, scene, head: str, rest: str) -> Quantity | None:
    """An ask of a quantity of the whole scene named by its kind (`SYSTEMS`: internal_forces.torque,
    standing_wave.momentum): None for another head; refused where the scene has none or `rest` is not one."""
    if head != kind:
        return None
    attribute, allowed = SYSTEMS[head]
    if getattr(scene, attribute) is None or rest not in allowed:
        raise ValueError(f"a scene's {head} has {', '.join(allowed)}")
    return Quantity(kind, None, rest)


def named(kind: QuantityKind, ask) -> sp.Symbol:
    """The quantity's symbol in its steps: the ask's name, or the kind's where the ask finds a parameter
    (the name is the parameter's answer then)."""
    return sp.Symbol(kind.symbol_for(ask) if ask.zero_for else ask.name)


def shown(kind: QuantityKind, solution, ask) -> sp.Expr:
    """The quantity as its steps print it: the answer in its ask's unit (turns in rev, a parameter in rev in
    them too); where the ask finds a parameter, the quantity itself, counted as the question says."""
    if ask.zero_for:
        value, unit = solution.counted(ask.name, kind.value(solution, ask, 0)), kind.unit
    else:
        value, unit = solution.expression(ask.name), ask.unit
    return units.declared_symbols(units.in_unit(value, unit), solution.problem.symbol_units)


def second_route(kind: QuantityKind, solution, names: list[str], check: str) -> list[Check]:
    """The check `check` of a kind a small system of derive.mechanics answers by two routes of its
    own: route 1 equals route 0 for every ask `names`, symbolically (`QuantityKind.checks`)."""
    for name in names:
        first, second = (kind.value(solution, solution.problem.asks[name], r) for r in (0, 1))
        if agree(first, second) is None:
            raise CheckFailure(f"{solution.problem.id}: {name} is {first} one way, {second} the other")
    return [Check(check, True, "symbolic", f"{', '.join(names)} agree",
                  f"A second, independent derivation gives the same {', '.join(names)}.")]


def first_asked(solution, ask, qualifies) -> bool:
    """Whether `ask` is the problem's first ask of its kind, of its target, for which `qualifies(ask)`:
    a condition of the body (a top's spin), said once however many of its asks need it."""
    same = (a for a in solution.problem.asks.values()
            if a.quantity.kind == ask.quantity.kind and a.quantity.target == ask.quantity.target and qualifies(a))
    return next(same, None) is ask


def describe_capitalized(text: str) -> str:
    """A description opening a sentence.

    >>> describe_capitalized("the torque of the rod's weight")
    "The torque of the rod's weight"
    """
    return text[:1].upper() + text[1:]


class StateChange:
    """A quantity read from where the bodies are and how they move in a state, against the state it
    comes from (the placement at rest for a state without `from:`; `at`, mixed in before QuantityKind): route 0 reads the states' closed forms; route 1
    is the motion integrated numerically (derive.checks.chain_simulation reads `at` on its states),
    so `value` gives None for it."""

    state = "change"
    routes = ("the two states' closed forms", "the motion integrated numerically")

    def reads_motion(self, ask) -> bool:
        return True

    def at(self, solution, ask, values: dict, before: dict) -> sp.Expr:
        """The quantity in the state of coordinates and velocities `values`, from those `before`."""
        raise NotImplementedError

    def value(self, solution, ask, route: int) -> sp.Expr | None:
        if route == 1:
            return None
        start = solution.scene.states[ask.state].start
        before = solution.states[start].values if start else solution.coordinates.at_rest_in_reference()
        return self.at(solution, ask, solution.states[ask.state].values, before)
