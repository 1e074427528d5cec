r"""What each typeset symbol of a worked solution stands for, and the clashes: one symbol, two things.

A document's symbols come from the problem file (its parameters and the names of its asks, which
the results print) and from the engine: the energies and the periods the steps solve for
(`derivation.KINETIC`, `POTENTIAL`, `LAGRANGIAN`, `PERIOD`, `EXACT_PERIOD`, `GROWTH_RATE`), each
route's unknown forces (`T_rope`, `N^ball`, `R_x^pin`) and the coordinates with their rates. Two
of them that typeset alike (as `latex.symbol_latex` prints them) but stand for different things
are a clash: an ask named T for a period where the steps call a tension T, a parameter V where
the Lagrangian's potential energy is V. An ask of the quantity an engine symbol stands for (an ask
`T` of the period, `K` of the kinetic energy) is that symbol, not a clash; any other symbol of the
steps is named by the step that introduces it (Euler's omega_3, a rolling body's M, a size the scene
leaves open) and is the same thing as a problem name typeset alike (a parameter omega3, the spin).

>>> import sympy as sp
>>> tension, period = sp.Symbol("T_cord", real=True), sp.Symbol("T")
>>> [c.latex for c in clashes([("parameters.T_cord", "T_cord", "a parameter")], {tension}, {tension: "a tension"})]
['T_{\\mathrm{cord}}']
>>> clashes([("ask.T", "T", "the period")], {period}, {}, {"ask.T": PERIOD})
[]

Where a problem file's name clashes with one of the engine's symbols of ENGINE, the document
names the engine's quantity otherwise (`ALTERNATIVES`: the potential energy U where a parameter
is V); any other clash it makes is refused, naming its field (`named`).
"""
from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass

import sympy as sp

from derive.core import units
from derive.numbers import range_forms
from derive.text.latex import symbol_latex
from derive.text.steps import renamed as renamed_step
from derive.mechanics.derivation import EXACT_PERIOD, GROWTH_RATE, KINETIC, LAGRANGIAN, PERIOD, POTENTIAL

#: The engine's symbols of a fixed meaning, and the asks (kind, detail; None: any detail) that mean it.
ENGINE = {
    KINETIC: ("the kinetic energy", {("kinetic_energy", None), ("rolling", "kinetic_energy"),
                                     ("bearings", "kinetic_energy")}),
    POTENTIAL: ("the potential energy", set()),
    LAGRANGIAN: ("the Lagrangian", set()),
    PERIOD: ("the period of small oscillations", {("small_oscillation", "period")}),
    EXACT_PERIOD: ("the period at the amplitude asked", {("oscillation", None)}),
    GROWTH_RATE: ("the growth rate of a small displacement", {("small_oscillation", "growth_rate")}),
}


#: What the document calls an engine quantity whose own symbol a problem file's name takes, in order.
ALTERNATIVES = {
    KINETIC: (sp.Symbol("E_k"), sp.Symbol("E_kin")),
    POTENTIAL: (sp.Symbol("U"), sp.Symbol("E_p")),
    PERIOD: (sp.Symbol("P"), sp.Symbol("tau")),
    EXACT_PERIOD: (sp.Symbol("P"), sp.Symbol("tau")),
    GROWTH_RATE: (sp.Symbol("lambda"), sp.Symbol("gamma")),
}


@dataclass(frozen=True)
class Clash:
    """One typeset symbol (`latex`) standing for several things (`meanings`); `field`: the problem
    file's field that made it, None where the engine's own symbols clash."""

    latex: str
    meanings: tuple[str, ...]
    field: str | None
    engine: sp.Symbol | None = None  # the symbol of ENGINE in it, which the document may rename

    def message(self) -> str:
        return f"${self.latex}$ would stand for " + " and for ".join(self.meanings) + " in the worked solution"


def engine_symbol(kind: str, detail: str | None) -> sp.Symbol | None:
    """The engine symbol an ask of this quantity is (None: none).

    >>> engine_symbol("small_oscillation", "period"), engine_symbol("oscillation", None), engine_symbol("mass", None)
    (T, T_exact, None)
    """
    return next((s for s, (_, asks) in ENGINE.items() if (kind, detail) in asks or (kind, None) in asks), None)


def clashes(names: Iterable[tuple[str, str, str]], shown: set[sp.Symbol], engine: Mapping[sp.Symbol, str],
            same: Mapping[str, sp.Symbol] | None = None, origin: Mapping[sp.Symbol, sp.Symbol] | None = None
            ) -> list[Clash]:
    """The clashes among a document's symbols. `names`: the problem file's (field, name, what it
    is); `shown`: every symbol the steps typeset; `engine`: the engine's unknowns and coordinates
    with what each is (the symbols of ENGINE are added); `same`: a field whose name is an engine
    symbol (an ask of the period named T); `origin`: a symbol the steps print for an engine symbol
    (an ask's name for the quantity it asks)."""
    same, origin = same or {}, origin or {}
    fixed = {**{s: meaning for s, (meaning, _) in ENGINE.items()}, **engine}
    things: dict[str, dict[tuple, tuple[str, str | None]]] = {}  # latex -> identity -> (what, field)
    for field, name, what in names:
        identity = ("engine", same[field]) if field in same else ("name", name)
        things.setdefault(symbol_latex(name), {})[identity] = (what, field)
    for symbol in shown:
        entry = things.setdefault(symbol_latex(symbol.name), {})
        named = [i for i, (_, f) in entry.items() if f is not None]  # the file's name typeset alike
        if symbol in origin or symbol in fixed:
            identity = ("engine", origin.get(symbol, symbol))
        else:
            identity = named[0] if named else ("name", symbol.name)
        if identity not in entry:
            entry[identity] = (fixed.get(symbol, f"the steps' {symbol.name}"), None)
    return [Clash(latex, tuple(what for what, _ in entry.values()), next((f for _, f in entry.values() if f), None),
                  next((i[1] for i in entry if i[0] == "engine" and i[1] in ENGINE), None))
            for latex, entry in sorted(things.items()) if len(entry) > 1]


def step_symbols(steps: Iterable) -> set[sp.Symbol]:
    """Every symbol typeset in these steps: their equations and their sentences' math."""
    result = set()
    for step in steps:
        for math in (*step.equations, *(p for s in step.sentences for p in s.pieces if not isinstance(p, str))):
            result |= {s for s in math.free_symbols if isinstance(s, sp.Symbol) and not isinstance(s, sp.Dummy)}
    return result


def asked(problem) -> dict[sp.Symbol, sp.Symbol]:
    """The engine symbols the problem asks for, each by the symbol of the (first) ask of it, where that
    is another (T_small for the period of small oscillations)."""
    result = {}
    for name, ask in problem.asks.items():
        symbol = engine_symbol(ask.quantity.kind, ask.quantity.detail)
        if symbol is not None and symbol != sp.Symbol(name):
            result.setdefault(symbol, sp.Symbol(name))
    return result


def document_clashes(problem, solution, steps: Mapping[str, list]) -> list[Clash]:
    """The clashes of a problem's worked solution (and handout): its parameters and asks against
    the symbols of its steps (`steps`: by route, as `Solution.steps` gives them)."""
    names = [(f"parameters.{n}", n, f"the parameter {n} ({p.meaning})") for n, p in problem.parameters.items()]
    names += [(f"ask.{n}", n, f"the answer {n} ({a.meaning})") for n, a in problem.asks.items()]
    same = {f"ask.{n}": s for n, a in problem.asks.items()
            if (s := engine_symbol(a.quantity.kind, a.quantity.detail)) is not None}
    engine = {}
    for derivation in (vars(solution).get("derivations") or {}).values():  # only where the dynamics were derived
        engine.update({u: f"the force {u.name} the routes solve for" for u in derivation.unknowns})  # accelerations: below
        if derivation.coords is not None:
            engine.update({s: f"the coordinate {s.name}" for c in derivation.coords.all for s in (c.q, c.u, c.a)})
    parameters = {p.symbol for p in problem.parameters.values()}
    shown = {s for s in step_symbols(x for route in steps.values() for x in route) if s not in parameters}
    origin = {target: symbol for symbol, target in asked(problem).items()}
    return clashes(names, shown, {s: w for s, w in engine.items() if s not in parameters}, same, origin)


def renamed(steps: Mapping[str, list], change: Mapping[sp.Symbol, sp.Symbol]) -> dict[str, list]:
    """The steps with symbols replaced (`change`), in their equations and their sentences' math;
    a step nothing changes is the same object (a free-body diagram is found by its step's id)."""
    def one(step):
        return renamed_step(step, change) if step_symbols([step]) & set(change) else step
    return {route: [one(s) for s in route_steps] for route, route_steps in steps.items()}


def printed(problem, solution, steps: Mapping[str, list], letters: Mapping[sp.Symbol, sp.Symbol]) -> dict[str, list]:
    """The steps as the documents and the terminal print them: their symbols `named`, each expression as it
    reads over the parameter ranges (derive.numbers.range_forms: T cos(phi), not T tan(phi) |cos(phi)|), in
    the document's `letters` (derive.publishing.letters: ell beside L_z)."""
    within = range_forms.steps_within(named(problem, solution, steps), range_forms.box(problem))
    return renamed(within, letters)


def shown_expressions(problem, solution, letters: Mapping[sp.Symbol, sp.Symbol] | None = None) -> dict[str, sp.Expr]:
    """Each answer's expression as the documents and the terminal print it: in its ask's unit, as it
    reads over the parameter ranges (derive.numbers.range_forms: pi/2 - alpha, not acos(sin(alpha)); 1/cos(beta),
    not sqrt(tan(beta)**2 + 1)), in the document's `letters`; the keys keep the derived one.

    >>> from derive.language.problem import load
    >>> problem = load("rod_tilted_on_shaft")
    >>> from derive.solution.answers import Solution
    >>> shown_expressions(problem, Solution(problem))["angle"]
    -alpha + pi/2
    """
    ranges = range_forms.box(problem)
    return {name: range_forms.within(units.declared_symbols(units.in_unit(expression, problem.asks[name].unit),
                                                            problem.symbol_units), ranges).xreplace(letters or {})
            for name, expression in solution.expressions.items()}


def named(problem, solution, steps: Mapping[str, list]) -> dict[str, list]:
    """The steps of a worked solution as the document prints them: an engine symbol of ENGINE that an
    ask asks printed by the ask's name, one that a problem file's name takes with another meaning
    renamed to its first free ALTERNATIVES; any other clash refused (an InputError naming the field
    that made it; an engine limit where the engine's own symbols clash).

    >>> from derive.language.problem import load
    >>> from derive.solution.answers import Solution
    >>> solution = Solution(load("compound_pendulum"))
    >>> named(solution.problem, solution, solution.steps()) == solution.steps()
    True
    """
    by_ask = asked(problem)  # printed by the ask's name (T_small for the small-angle period)
    shown = step_symbols(s for route in steps.values() for s in route)
    taken = {symbol_latex(n) for n in (*problem.parameters, *problem.asks)}
    taken |= {symbol_latex(s.name) for s in shown}

    def alternative(symbol):
        free = [a for a in ALTERNATIVES.get(symbol, ()) if symbol_latex(a.name) not in taken]
        if free:
            taken.add(symbol_latex(free[0].name))
        return free[0] if free else None

    change = dict(by_ask)
    for target in by_ask.values():  # an ask's name that is an engine symbol still shown for itself: that gives way
        if target in ENGINE and target not in by_ask and target in shown and (other := alternative(target)) is not None:
            change[target] = other
    steps = renamed(steps, change)
    found = document_clashes(problem, solution, steps)
    change = {c.engine: other for c in found if c.engine is not None and c.field is not None
              and (other := alternative(c.engine)) is not None}
    if change:
        steps = renamed(steps, change)
        found = document_clashes(problem, solution, steps)
    if found:
        clash = found[0]
        if clash.field is None:
            raise problem.limit(f"typeset its worked solution with one symbol for one thing: {clash.message()}")
        raise problem.error(clash.field, f"{clash.message()}; rename it")
    return steps
