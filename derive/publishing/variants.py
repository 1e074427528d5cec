"""A problem's variants: each one's draw of the parameters, its certified answers, and its numbers
as the set's documents show them.

Each variant draws its parameters reproducibly from its own generator, rounds them to their
significant figures (exact decimals), and redraws where a condition the answers need fails
(`valid_draws`). A problem's answers are compiled once and evaluated over all its variants
together (derive.numbers.numeric); the text a variant adds (its question, its given values) is filled
into a stencil cut once per problem (derive.text.stencil), not written anew per variant.

>>> import random
>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> problem = load("string_wrapped_disk")
>>> item = ProblemVariants(problem, Solution(problem), [draw(problem, random.Random(n)) for n in (1, 2)])
>>> len(item.questions(siunitx=False)), item.numbers[0]["m"] == numeric.significant(item.draws[0]["m"], 3)
(2, True)
"""
from __future__ import annotations

import random
from collections import Counter
from dataclasses import dataclass, field
from functools import cached_property
from typing import Sequence

import sympy as sp

from derive.text.latex import latex_of
from derive.publishing import distractors, letters, lms, notation, typeset_cache
from derive.text import latex_safety
from derive.numbers import numeric
from derive.core import units
from derive.mechanics.along_motion import AlongMotion
from derive.solution import answer_signs, textbook
from derive.solution.answers import Solution
from derive.core.errors import InputError
from derive.publishing import figure
from derive.publishing.figure import free_body
from derive.language.problem import DEFAULT_SIG_FIGS, Problem
from derive.text.stencil import Stencil


def draw(problem: Problem, rng: random.Random) -> dict[str, sp.Expr]:
    """Parameter values in their declared units: a range is sampled uniformly and rounded
    to the parameter's significant figures (exact decimals: Parameter.draw); a fixed value is kept."""
    values = {}
    for name, p in problem.parameters.items():
        if p.range is None:
            values[name] = p.value
            continue
        values[name] = p.draw(rng)
    return values


MAX_DRAWS = 200


def si_values(problem: Problem, values: dict[str, sp.Expr]) -> dict[sp.Symbol, sp.Expr]:
    """A draw's values (in their declared units) in SI, by symbol."""
    factors = ((name, p.symbol, units.si_factor(p.unit)) for name, p in problem.parameters.items())
    return {symbol: values[name] if factor is sp.S.One else values[name] * factor for name, symbol, factor in factors}


def valid_draws(problem: Problem, solution: Solution, rngs: Sequence[random.Random]) -> list[dict[str, sp.Expr]]:
    """A draw from each generator (a variant's own) that meets every condition the answers need
    (a fast enough top, say): every variant drawn, their conditions certified together, and
    each variant whose draw breaks one redrawn from its own generator, at most MAX_DRAWS times
    (else an error naming the problem). A variant's draw is the same however many are drawn."""
    draws: list[dict[str, sp.Expr] | None] = [None] * len(rngs)
    pending = list(range(len(rngs)))
    broken: Counter = Counter()  # how often each condition broke a draw
    for _ in range(MAX_DRAWS):
        candidates = {i: draw(problem, rngs[i]) for i in pending}
        meanings = solution.violations([si_values(problem, values) for values in candidates.values()])
        for (i, values), meaning in zip(candidates.items(), meanings):
            if meaning is None:
                draws[i] = values
            else:
                broken[meaning] += 1
        pending = [i for i in pending if draws[i] is None]
        if not pending:
            return draws
    meaning, count = broken.most_common(1)[0]
    raise InputError(f"{problem.path}: parameters: no draw in {MAX_DRAWS} meets the problem's conditions; "
                     f"{count} of {sum(broken.values())} draws broke this one: {meaning}: narrow the ranges")


def valid_draw(problem: Problem, solution: Solution, rng: random.Random) -> dict[str, sp.Expr]:
    """One variant's valid_draws."""
    return valid_draws(problem, solution, [rng])[0]


def number_latex(text: str) -> str:
    """A decimal string for LaTeX math: 1.23e-05 as 1.23\\times10^{-5}."""
    mantissa, _, exponent = text.partition("e")
    return f"{mantissa}\\times10^{{{int(exponent)}}}" if exponent else mantissa


def unit_latex(unit: str, siunitx: bool) -> str:
    """A unit as a document typesets it: siunitx's in what LaTeX compiles (the PDFs), plain math in
    what pandoc converts and MathJax shows (units.latex_unit says why)."""
    return units.siunitx_unit(unit) if siunitx else units.latex_unit(unit)


@dataclass
class ProblemVariants:
    """One problem of the set: its derivation (shared) and each variant's numbers."""

    problem: Problem
    solution: Solution
    draws: list[dict[str, sp.Expr]]
    tolerance: str | None = None  # the policy of asks that give none (the course defaults)
    cache: bool = False  # whether its figure may come from the cache (derive.publishing.typeset_cache)
    # A build reads each variant's answers for the solutions, the key and the LMS exports:
    # evaluated once per draw (keyed by the draw, which self.draws keeps alive).
    _answers: dict[int, dict[str, numeric.Certified | None]] = field(default_factory=dict, repr=False)
    _texts: dict[int, dict[str, str | None]] = field(default_factory=dict, repr=False)
    _tolerances: dict[int, dict[str, str | None]] = field(default_factory=dict, repr=False)
    _directions: dict[int, dict[str, str | None]] = field(default_factory=dict, repr=False)
    _wrong: dict[int, dict[str, list[dict[str, str]]]] = field(default_factory=dict, repr=False)
    _questions: dict[bool, list[str]] = field(default_factory=dict, repr=False)  # by siunitx

    def si_values(self, draw: dict[str, sp.Expr]) -> dict[sp.Symbol, sp.Expr]:
        return si_values(self.problem, draw)

    def shown(self, name: str, value: str | None) -> str:
        """LaTeX of an answer: its number, or its expression when it has none (a general result)."""
        return number_latex(value) if value is not None else self.expression_latexes[name]

    @cached_property
    def shown_expressions(self) -> dict[str, sp.Expr]:
        """Each answer's expression as the documents print it: in its ask's unit (`in_unit`), as it reads over the parameter ranges
        (derive.numbers.range_forms: 1/cos(beta), not sqrt(tan(beta)**2 + 1)); the keys keep the derived one."""
        return notation.shown_expressions(self.problem, self.solution, self.letters)

    @cached_property
    def letters(self) -> dict[sp.Symbol, sp.Symbol]:
        """The symbols the documents print otherwise, one letter for one kind of thing (a length L as
        ell beside an angular momentum L_z: derive.publishing.letters)."""
        return letters.of_document(self.problem, self.solution)

    @cached_property
    def expression_latexes(self) -> dict[str, str]:
        """Each answer's expression as LaTeX, for a general (symbolic) result in every variant."""
        return {name: latex_of(expression) for name, expression in self.shown_expressions.items()}

    @cached_property
    def expression_texts(self) -> dict[str, str]:
        """Each answer's expression as text (sympy's str), for the keys of every variant."""
        return {name: sp.sstr(expression) for name, expression in self.solution.expressions.items()}

    @cached_property
    def in_declared_units(self) -> dict[str, sp.Expr]:
        """Each answer divided by its unit's SI factor, built once for every variant."""
        return {name: units.in_unit(self.solution.expressions[name], ask.unit) for name, ask in self.problem.asks.items()}

    @cached_property
    def free_bodies(self) -> dict[int, free_body.FreeBody]:
        """Each body's free-body diagram (derive.publishing.figure.free_body) by the id of the step of
        Newton–Euler's own derivation that states its balance: drawn once for every variant and
        output, labelled with symbols; a body it cannot draw has none, a scene without the route none."""
        solution = self.solution
        if "newton_euler" not in solution.steps():
            return {}
        drawn = free_body.free_bodies(self.problem, solution.dynamics_scene, solution.coordinates, None, self.letters)
        return {id(s): drawn[s.body] for s in solution.derivations["newton_euler"].steps
                if s.body and drawn.get(s.body) is not None}

    @cached_property
    def student_free_bodies(self) -> dict[int, free_body.FreeBody]:
        """Each body's free-body diagram beside the first step of the student's route that states its
        balance (derive.solution.textbook), each force drawn the way it acts, its symbol a magnitude
        (friction up the slope); none where the route is not written."""
        steps, route = self.solution.student_steps, self.solution.textbook_route
        route = getattr(route, "along", None) or route  # the motion between states starts along the motion
        if steps is None or not isinstance(route, AlongMotion):  # a swing, an impact: no body's balance
            return {}
        names = textbook.names(self.solution)  # f for f^ball, then a letter given way (F_x for R_x beside R)
        names = {**self.letters, **{u: self.letters.get(v, v) for u, v in names.items()}}
        scene = getattr(self.solution.textbook_route, "scene", None) or self.solution.dynamics_scene  # a slide's own
        drawn = free_body.free_bodies(self.problem, scene, self.solution.coordinates, route.acting, names)
        result, seen = {}, set()
        for step in (s for section in steps.values() for s in section):
            if step.body and step.body not in seen and drawn.get(step.body) is not None:
                seen.add(step.body)
                result[id(step)] = drawn[step.body]
        return result

    @cached_property
    def shown_free_bodies(self) -> dict[int, free_body.FreeBody]:
        """The diagrams the students' worked solution (and so the LMS feedback) shows: the student's
        route's where it is written, else Newton–Euler's."""
        return self.student_free_bodies if self.solution.student_steps is not None else self.free_bodies

    @cached_property
    def figure(self) -> str | None:
        """The problem's figure (derive.publishing.figure), drawn once for its worksheet, solutions and exports."""
        return typeset_cache.kept(self.problem, "figure", lambda: figure.tikz(self.problem), self.cache)

    @cached_property
    def _evaluator(self) -> numeric.Evaluator:
        return numeric.evaluator(tuple(self.in_declared_units.values()))

    def certified(self, draw: dict[str, sp.Expr]) -> dict[str, numeric.Certified | None]:
        """Each answer's value to its significant figures, with how its digits are vouched for;
        None for a general (symbolic) result. The first time one of this object's own draws is
        asked, every one of them is evaluated, together (one compiled program over the variants)."""
        if id(draw) in self._answers:
            return self._answers[id(draw)]
        draws = self.draws if id(draw) in self._own_draws else [draw]
        digits = [ask.sig_figs or DEFAULT_SIG_FIGS for ask in self.problem.asks.values()]
        results = [dict(zip(self.problem.asks, row))
                   for row in self._evaluator.certified([self.si_values(d) for d in draws], digits)]
        if draws is not self.draws:
            return results[0]
        self._answers.update(zip(map(id, draws), results))
        return self._answers[id(draw)]

    def answers(self, draw: dict[str, sp.Expr]) -> dict[str, str | None]:
        """Each answer's value to its significant figures; None for a general (symbolic) result."""
        return self._once(self._texts, draw, lambda: {name: None if value is None else value.text
                                                      for name, value in self.certified(draw).items()})

    def directions(self, draw: dict[str, sp.Expr]) -> dict[str, str | None]:
        """Which way each asked quantity with a direction points in this variant, in words ("up the
        slope"; derive.solution.answer_signs), its value being the magnitude; None for the others. The
        first time one of this object's own draws is asked, the signs of all of them are found together,
        certified in balls by one compiled program (numeric.Evaluator.signs); a sign the balls leave
        open (a zero, a general result) is answer_signs.direction's."""
        if id(draw) not in self._directions and id(draw) in self._own_draws:
            named = [n for n, sense in self.solution.senses.items() if sense is not None]
            signs = numeric.evaluator(tuple(self.solution.signed_expressions[n] for n in named)).signs(
                [self.si_values(d) for d in self.draws]) if named else [[] for _ in self.draws]
            for d, row in zip(self.draws, signs):
                known = {n: self.solution.senses[n].of(sign) for n, sign in zip(named, row) if sign}
                self._directions[id(d)] = {name: known[name] if name in known else
                                           answer_signs.direction(self.solution, name, self.si_values(d))
                                           for name in self.problem.asks}
        return self._once(self._directions, draw, lambda: {
            name: answer_signs.direction(self.solution, name, self.si_values(draw)) for name in self.problem.asks})

    @cached_property
    def varying_directions(self) -> set[str]:
        """The asks whose direction is not the same in every variant: the LMS exports ask it too."""
        return {name for name in self.problem.asks if len({self.directions(d)[name] for d in self.draws}) > 1}

    def tolerances(self, draw: dict[str, sp.Expr]) -> dict[str, str | None]:
        """Each numeric answer's absolute tolerance in its unit, under the answer's policy; InputError
        where it would grade unfairly (lms.unfair), naming the ask's tolerance or the course's."""
        def derive_tolerances() -> dict[str, str | None]:
            tolerances = {}
            for name, text in self.answers(draw).items():
                policy = self.problem.asks[name].tolerance
                tolerances[name] = None if text is None else lms.tolerance(text, policy or self.tolerance)
                why = text and lms.unfair(text, tolerances[name])
                if why:
                    field = f"ask.{name}.tolerance: {policy}" if policy else \
                        f"ask.{name}: the course's tolerance {self.tolerance} (derive.toml)"
                    raise InputError(f"{self.problem.path}: {field} gives ±{tolerances[name]}, {why}; "
                                     f"give a {'wider' if why.startswith('narrower') else 'narrower'} tolerance")
            return tolerances

        return self._once(self._tolerances, draw, derive_tolerances)

    def wrong(self, draw: dict[str, sp.Expr]) -> dict[str, list[dict[str, str]]]:
        """Each answer's distractors (value, mistake) for multiple choice."""
        def derive_wrong() -> dict[str, list[dict[str, str]]]:
            values, tolerances = self.si_values(draw), self.tolerances(draw)
            return {n: distractors.distractors(self.problem, n, values, a.sig_figs or DEFAULT_SIG_FIGS,
                                               tolerance=tolerances[n])
                    for n, a in self.problem.asks.items()}

        return self._once(self._wrong, draw, derive_wrong)

    def _once(self, store: dict, draw: dict[str, sp.Expr], compute):
        """compute(), once per draw of this object's own."""
        if id(draw) in store:
            return store[id(draw)]
        result = compute()
        if id(draw) in self._own_draws:  # only draws this object keeps alive: their ids stay theirs
            store[id(draw)] = result
        return result

    @cached_property
    def _own_draws(self) -> set[int]:
        return {id(d) for d in self.draws}

    @cached_property
    def numbers(self) -> list[dict[str, str]]:
        """Each variant's parameter values as decimal text to their significant figures, as its
        question, worked solution and key show them."""
        return [self.given(draw) for draw in self.draws]

    def given(self, draw: dict[str, sp.Expr]) -> dict[str, str]:
        """A draw's parameter values as decimal text to their significant figures (a fixed value's
        written once)."""
        fixed = self._fixed_texts
        return {name: fixed.get(name) or numeric.significant(draw[name], p.sig_figs)
                for name, p in self.problem.parameters.items()}

    @cached_property
    def _fixed_texts(self) -> dict[str, str]:
        return {name: numeric.significant(p.value, p.sig_figs) for name, p in self.problem.parameters.items()
                if p.range is None}

    def questions(self, siunitx: bool) -> list[str]:
        """Each variant's question, written once per form for the worksheet, its pandoc outputs and
        the LMS exports (`siunitx`: the PDF's units)."""
        if siunitx not in self._questions:
            self._questions[siunitx] = [self._question(numbers, siunitx) for numbers in self.numbers]
        return self._questions[siunitx]

    def question(self, draw: dict[str, sp.Expr], siunitx: bool = False) -> str:
        """The problem's question with the draw's values (units in siunitx for a PDF)."""
        return self._question(self.given(draw), siunitx)

    def _question(self, numbers: dict[str, str], siunitx: bool) -> str:
        units_tex = self.units_latex[siunitx]
        return self._question_stencil.fill({name: latex_safety.quantity(number_latex(number), units_tex[name])
                                            for name, number in numbers.items()})

    def quantities(self, numbers: dict[str, str], siunitx: bool) -> dict[str, str]:
        """A variant's parameters (`numbers`: their decimal text) as math with their units (no
        space before a degree sign: units.after_number)."""
        units_tex = self.units_latex[siunitx]
        return {name: number_latex(number) + units_tex[name] for name, number in numbers.items()}

    @cached_property
    def _question_stencil(self) -> Stencil:
        """The question read once for every variant (latex_safety.question_stencil)."""
        try:
            return latex_safety.question_stencil(self.problem.question, tuple(self.problem.parameters))
        except latex_safety.LatexError as error:
            raise self.problem.error("question", f"{type(error).__name__}: {error}") from None

    @cached_property
    def units_latex(self) -> dict[bool, dict[str, str]]:
        """What follows each parameter's number, its unit as LaTeX (units.after_number), by whether
        in siunitx (`unit_latex`)."""
        return {siunitx: {name: units.after_number(p.unit, unit_latex(p.unit, siunitx))
                          for name, p in self.problem.parameters.items()} for siunitx in (False, True)}
