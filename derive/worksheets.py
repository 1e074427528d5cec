"""Problem sets: variants drawn from the parameter ranges, worksheets, solutions and keys.

Each problem is derived once; each variant draws its parameters reproducibly from the
seed, rounds them to their significant figures (exact decimals), and evaluates the
answers. Everything is built in a temporary folder and moved into place only when the
whole build succeeded, so a failed build leaves the previous one intact.

Called, this module builds a set (read by derive.problem_sets): `derive.sheet("demo",
out="build/demo")` is derive.api.sheet.
"""
from __future__ import annotations

import csv
import dataclasses
import gc
import io
import random
import sys
from contextlib import contextmanager
from dataclasses import dataclass, field
from decimal import Decimal
from functools import cached_property, lru_cache
from pathlib import Path
from typing import Sequence

import sympy as sp

from derive import (distractors, export, figure, figure_files, json_text, limiting_cases, lms, notation, numeric,
                    output_folder, render, typesetting, units)
from derive.answers import Solution
from derive.defaults import Defaults
from derive.errors import InputError
from derive.figure import free_body
from derive.problem import DEFAULT_SIG_FIGS, Problem, load
from derive.problem_sets import ProblemSet, load_sheet
from derive.progress import Reporter
from derive.report import route_title
from derive.spreadsheet import safe_cell



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
    for _ in range(MAX_DRAWS):
        candidates = {i: draw(problem, rngs[i]) for i in pending}
        broken = solution.violations([si_values(problem, values) for values in candidates.values()])
        for (i, values), meaning in zip(candidates.items(), broken):
            if meaning is None:
                draws[i] = values
        pending = [i for i in pending if draws[i] is None]
        if not pending:
            return draws
    raise InputError(f"{problem.path}: parameters: no draw in {MAX_DRAWS} meets the problem's conditions "
                     f"({'; '.join(m for _, _, m in solution.conditions)}): narrow the ranges")


def valid_draw(problem: Problem, solution: Solution, rng: random.Random) -> dict[str, sp.Expr]:
    """One variant's valid_draws."""
    return valid_draws(problem, solution, [rng])[0]


LONGEST_EQUATION = 700  # characters of LaTeX; longer would overflow the page


def typeset(equation: sp.Eq, beside: str = "", tag: str = "") -> str:
    """An equation for an align environment, a long sum broken across lines (typesetting.rows),
    `beside` a note at its first row, `tag` its number at its last (`tag`); one too long to
    typeset at all becomes a short note."""
    if len(render.latex_of(equation)) > LONGEST_EQUATION:
        return (render.latex_of(equation.lhs) + r" &= \text{(too long to typeset here: see derive solve "
                r"--format latex)}" + beside + tag)
    return typesetting.rows(equation.lhs, equation.rhs, beside=beside) + tag


def tag(number: int, tex: bool) -> str:
    """An equation's number: amsmath's \\tag where LaTeX compiles it, else "(n)" after it, which
    pandoc (which drops a \\tag from MathML) and MathJax both show."""
    return rf" \tag{{{number}}}" if tex else rf" \qquad \text{{({number})}}"


def equation_numbers(numbers: list[int]) -> str:
    """Equation numbers as a worked solution refers to them, runs joined.

    >>> equation_numbers([4, 5, 6, 7, 9, 10]), equation_numbers([3])
    ('(4)–(7) and (9)–(10)', '(3)')
    """
    runs: list[list[int]] = []
    for n in numbers:
        if runs and n == runs[-1][-1] + 1:
            runs[-1].append(n)
        else:
            runs.append([n])
    shown = [f"({r[0]})" if len(r) == 1 else f"({r[0]})–({r[-1]})" for r in runs]
    return shown[0] if len(shown) == 1 else ", ".join(shown[:-1]) + " and " + shown[-1]


def number_latex(text: str) -> str:
    """A decimal string for LaTeX math: 1.23e-05 as 1.23\\times10^{-5}."""
    mantissa, _, exponent = text.partition("e")
    return f"{mantissa}\\times10^{{{int(exponent)}}}" if exponent else mantissa


def unit_latex(unit: str, siunitx: bool) -> str:
    """A unit as a document typesets it: siunitx's in what LaTeX compiles (the PDFs), plain math in
    what pandoc converts and MathJax shows (units.latex_unit says why)."""
    return units.siunitx_unit(unit) if siunitx else units.latex_unit(unit)


@lru_cache(maxsize=None)
def quantity_latex(value: sp.Expr, unit: str, sig_figs: int, siunitx: bool) -> str:
    """A given value as math, with its unit (`unit_latex`)."""
    number = number_latex(numeric.significant(value, sig_figs))
    unit_tex = unit_latex(unit, siunitx)
    return f"{number}\\,{unit_tex}" if unit_tex else number


@dataclass
class _ProblemVariants:
    """One problem of the set: its derivation (shared) and each variant's numbers."""

    problem: Problem
    solution: Solution
    draws: list[dict[str, sp.Expr]]
    tolerance: str | None = None  # the policy of asks that give none (the course defaults)
    # A build reads each variant's answers for the solutions, the key and the LMS exports:
    # evaluated once per draw (keyed by the draw, which self.draws keeps alive).
    _answers: dict[int, dict[str, numeric.Certified | None]] = field(default_factory=dict, repr=False)
    _wrong: dict[int, dict[str, list[dict[str, str]]]] = field(default_factory=dict, repr=False)
    _questions: dict[bool, list[str]] = field(default_factory=dict, repr=False)  # by siunitx

    def si_values(self, draw: dict[str, sp.Expr]) -> dict[sp.Symbol, sp.Expr]:
        return si_values(self.problem, draw)

    def shown(self, name: str, value: str | None) -> str:
        """LaTeX of an answer: its number, or its expression when it has none (a general result)."""
        return number_latex(value) if value is not None else self.expression_latexes[name]

    @cached_property
    def expression_latexes(self) -> dict[str, str]:
        """Each answer's expression as LaTeX, for a general (symbolic) result in every variant."""
        return {name: render.latex_of(expression) for name, expression in self.solution.expressions.items()}

    @cached_property
    def expression_texts(self) -> dict[str, str]:
        """Each answer's expression as text (sympy's str), for the keys of every variant."""
        return {name: sp.sstr(expression) for name, expression in self.solution.expressions.items()}

    @cached_property
    def in_declared_units(self) -> dict[str, sp.Expr]:
        """Each answer divided by its unit's SI factor, built once for every variant."""
        return {name: self.solution.expressions[name] / units.si_factor(units.parse_unit(ask.unit))
                for name, ask in self.problem.asks.items()}

    @cached_property
    def free_bodies(self) -> dict[int, free_body.FreeBody]:
        """Each body's free-body diagram (derive.figure.free_body) by the id of the step of
        Newton–Euler's own derivation that states its balance: drawn once for every variant and
        output, labelled with symbols; a body it cannot draw has none, a scene without the route none."""
        solution = self.solution
        if "newton_euler" not in solution.steps():
            return {}
        drawn = free_body.free_bodies(self.problem, solution.dynamics_scene, solution.coordinates)
        return {id(s): drawn[s.body] for s in solution.derivations["newton_euler"].steps
                if s.body and drawn.get(s.body) is not None}

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
        return {name: None if value is None else value.text for name, value in self.certified(draw).items()}

    def tolerances(self, draw: dict[str, sp.Expr]) -> dict[str, str | None]:
        """Each numeric answer's absolute tolerance in its unit, under the answer's policy."""
        return {name: None if value is None else
                lms.tolerance(value.text, self.problem.asks[name].tolerance or self.tolerance)
                for name, value in self.certified(draw).items()}

    def wrong(self, draw: dict[str, sp.Expr]) -> dict[str, list[dict[str, str]]]:
        """Each answer's distractors (value, mistake) for multiple choice."""
        def derive_wrong(values: dict[sp.Symbol, sp.Expr]) -> dict[str, list[dict[str, str]]]:
            return {n: distractors.distractors(self.problem, n, values, a.sig_figs or DEFAULT_SIG_FIGS)
                    for n, a in self.problem.asks.items()}

        return self._once(self._wrong, draw, derive_wrong)

    def _once(self, store: dict, draw: dict[str, sp.Expr], compute):
        """compute(SI values of the draw), once per draw of this object's own."""
        if id(draw) in store:
            return store[id(draw)]
        result = compute(self.si_values(draw))
        if id(draw) in self._own_draws:  # only draws this object keeps alive: their ids stay theirs
            store[id(draw)] = result
        return result

    @cached_property
    def _own_draws(self) -> set[int]:
        return {id(d) for d in self.draws}

    def questions(self, siunitx: bool) -> list[str]:
        """Each variant's question, read once per form for the worksheet, its pandoc outputs and the
        LMS exports (`siunitx`: the PDF's units)."""
        if siunitx not in self._questions:
            self._questions[siunitx] = [self.question(draw, siunitx) for draw in self.draws]
        return self._questions[siunitx]

    def question(self, draw: dict[str, sp.Expr], siunitx: bool = False) -> str:
        """The problem's question with the draw's values (units in siunitx for a PDF)."""
        shown = {
            name: f"${quantity_latex(draw[name], p.unit, p.sig_figs, siunitx)}$"
            for name, p in self.problem.parameters.items()
        }
        try:
            return render.question(self.problem.question, shown)
        except Exception as error:  # jinja's errors: an undeclared name or bad syntax in the file
            raise self.problem.error("question", f"{type(error).__name__}: {error}") from None


@contextmanager
def _entry(problem_set: ProblemSet, where: str):
    """An error about a problem of the set names the set file and the entry first."""
    try:
        yield
    except InputError as error:
        raise InputError(f"{problem_set.path}: {where}: {error}") from None


def _prepare(problem_set: ProblemSet, variants: int, seed: int, progress: Reporter) -> list[_ProblemVariants]:
    """Each problem derived (its answers and checks), then its variants drawn: the derivations
    are the set's fixed cost, the draws the first step of its cost per variant. The objects alive
    once the problems are derived are frozen (gc.freeze): the caller unfreezes them."""
    derived, ids = [], {}
    with progress.task("deriving", len(problem_set.problems)) as begin:
        for reference, where in zip(problem_set.problems, problem_set.fields):
            with _entry(problem_set, where):  # then the problem file and its field
                problem = load(reference)
                if problem.id in ids:
                    raise InputError(f"{problem.path}: id: {problem.id} is also the id of {ids[problem.id]}; "
                                     "ids in a set must differ")
                ids[problem.id] = f"{where} ({problem.path})"
                begin(problem.id)
                solution = Solution(problem)
                solution.expressions  # derive once, for every variant
                solution.checks()
            derived.append((problem, solution, where))
    gc.freeze()  # every full pass of the collector rescanned them: a fifth of the time per variant
    progress(f"drawing {variants} variant{'s' * (variants > 1)} of each problem")
    prepared = []
    for problem, solution, where in derived:
        with _entry(problem_set, where):
            draws = valid_draws(problem, solution, [random.Random(f"{seed}/{problem.id}/{n}")
                                                    for n in range(1, variants + 1)])
        prepared.append(_ProblemVariants(problem, solution, draws, problem_set.tolerance))
    return prepared


def _check_latex(check, problem: Problem, siunitx: bool) -> str:
    """A check as a worked solution prints it: its reading, the units of the answers in math."""
    if check.name == "dimensions":
        units_of = ", ".join(f"${render.symbol_latex(n)}$ in ${unit_latex(a.unit, siunitx)}$" if unit_latex(a.unit, siunitx)
                             else f"${render.symbol_latex(n)}$ a pure number" for n, a in problem.asks.items())
        return f"Every answer has the units it should: {units_of}."
    return render.tex_escape(check.reading)


def _solutions_context(item: _ProblemVariants, siunitx: bool) -> dict:
    """A problem's worked solution for the templates: its routes' steps, its answers, each variant's
    numbers (units in siunitx where LaTeX compiles it: `unit_latex`), its checks."""
    problem, solution = item.problem, item.solution
    numbered = iter(range(1, 10**6))  # the problem's equations, numbered through its routes
    routes = []
    all_steps = solution.steps()
    diagrams = item.free_bodies
    printed = notation.named(problem, solution, all_steps)  # one symbol, one thing (a step renamed keeps its diagram)
    for route, steps in all_steps.items():
        shown, solved = [], []  # the numbers of the equations this route solves
        for original, s in zip(steps, printed[route]):
            numbers = [next(numbered) for _ in s.equations]
            solved += numbers if s.role == "equations" else []
            text = f"{s.text}, from {equation_numbers(solved)}" if s.role == "solve" and solved else s.text
            shown.append({"text": text, "equations": [typeset(e, tag=tag(n, siunitx)) for e, n in zip(s.equations, numbers)],
                          "diagram": diagrams[id(original)].tikz if id(original) in diagrams else "",
                          "body": diagrams[id(original)].body if id(original) in diagrams else "",
                          "sentences": [sentence.latex() for sentence in s.sentences]})
        routes.append({"title": route_title(route), "steps": shown})
    answers = [
        {"symbol": render.symbol_latex(n), "latex": item.expression_latexes[n], "meaning": a.meaning,
         "rows": typeset(sp.Eq(sp.Symbol(n), solution.expression(n), evaluate=False),
                         typesetting.note(render.tex_escape(a.meaning), tex=siunitx))}
        for n, a in problem.asks.items()
    ]
    symbols = {n: render.latex_of(p.symbol) for n, p in problem.parameters.items()}
    variants = []
    for number, values in enumerate(item.draws, start=1):
        results = item.answers(values)
        variants.append({
            "number": number,
            "given": [f"${symbols[n]} = {quantity_latex(values[n], p.unit, p.sig_figs, siunitx)}$"
                      for n, p in problem.parameters.items()],
            "results": [{"symbol": render.symbol_latex(n), "value": item.shown(n, results[n]),
                         "unit": unit_latex(a.unit, siunitx)} for n, a in problem.asks.items()],
        })
    checks = [_check_latex(c, problem, siunitx) for c in solution.checks()]  # the detail stays in `derive check`, the JSON
    return {"title": problem.title, "source": problem.source, "routes": routes, "answers": answers,
            "variants": variants, "checks": checks, "corrections": list(problem.corrections),
            "figure": figure.tikz(problem)}


def _free_body_figures(prepared: list[_ProblemVariants]) -> dict[str, free_body.FreeBody]:
    """Every free-body diagram of the set by its image's name (figure_files.free_body_name): what
    the LMS feedback shows as images, each compiled once whatever the number of variants."""
    return {figure_files.free_body_name(item.problem.id, drawn.body): drawn
            for item in prepared for drawn in item.free_bodies.values()}


def _keys(problem_set: ProblemSet, prepared: list[_ProblemVariants], variants: int, seed: int,
          with_distractors: bool = False, choice: bool = False):
    """(rows of the CSV key, the JSON key). With `choice`, an answer that too few mistakes apply
    to is marked in the JSON key as asked as a number, with why (`numerical`)."""
    rows, key = [], {"set": problem_set.id, "title": problem_set.title, "seed": seed,
                     "conventions": "SI units; angles in radians (rad is dimensionless); y up; counter-clockwise "
                                    "positive; values to the significant figures shown",
                     "variants": []}
    for number in range(1, variants + 1):
        entry = {"variant": number, "problems": {}}
        for item in prepared:
            values = item.draws[number - 1]
            answers, tolerances, certified = item.answers(values), item.tolerances(values), item.certified(values)
            entry["problems"][item.problem.id] = {
                "parameters": {n: {"value": numeric.significant(values[n], p.sig_figs), "unit": p.unit}
                               for n, p in item.problem.parameters.items()},
                "answers": {n: {"value": answers[n], "tolerance": tolerances[n],
                                "expr": item.expression_texts[n], "unit": a.unit, "meaning": a.meaning,
                                "certificate": None if certified[n] is None else certified[n].certificate()}
                            for n, a in item.problem.asks.items()},
            }
            if with_distractors or choice:  # wrong answers for multiple choice, from mistaken set-ups
                for n, wrong in item.wrong(values).items():
                    entry["problems"][item.problem.id]["answers"][n]["distractors"] = wrong
                    if choice and answers[n] is not None and len(wrong) < distractors.WANTED:
                        entry["problems"][item.problem.id]["answers"][n]["numerical"] = _too_few(len(wrong))
            for n, a in item.problem.asks.items():
                rows.append({"variant": number, "problem": item.problem.id, "answer": n,
                             "value": answers[n] if answers[n] is not None else item.expression_texts[n],
                             "tolerance": tolerances[n] or "", "unit": a.unit, "meaning": a.meaning,
                             "latex": item.shown(n, answers[n])})
        key["variants"].append(entry)
    return rows, key


def _too_few(found: int) -> str:
    return (f"asked as a number: only {found} distinct wrong option{'' if found == 1 else 's'} derived "
            f"(multiple choice needs {distractors.WANTED})")


def _numerical_notes(key: dict) -> list[str]:
    """One line per answer that stays numerical in a multiple-choice set, with its variants."""
    variants: dict[tuple[str, str, str], list[int]] = {}
    for entry in key["variants"]:
        for problem_id, problem in entry["problems"].items():
            for name, answer in problem["answers"].items():
                if "numerical" in answer:
                    variants.setdefault((problem_id, name, answer["numerical"]), []).append(entry["variant"])
    return [f"{problem_id}: ask.{name}, variant{'s' if len(numbers) > 1 else ''} {', '.join(map(str, numbers))}: "
            f"{note}" for (problem_id, name, note), numbers in variants.items()]


def _worked_solutions(prepared: list[_ProblemVariants], contexts: list[dict], header: dict) -> dict[tuple[str, int], str]:
    """Each problem's worked solution for each variant as HTML, keyed (problem id, variant): the
    solutions sheet's own template and text, each section one problem with that variant's numbers
    only (no figure: the question shows it), converted by pandoc in one run (export.html_sections).
    pandoc reads no TikZ: each free-body diagram is an image, figures/NAME.png (`free_body_name`),
    which derive.lms resolves to the file each LMS carries; the same for every variant."""
    keys, problems = [], []
    for item, context in zip(prepared, contexts):
        routes = [{**r, "steps": [{**s, "diagram": _included(item.problem.id, s["body"])} for s in r["steps"]]}
                  for r in context["routes"]]
        for variant in context["variants"]:
            keys.append((item.problem.id, variant["number"]))
            problems.append({**context, "figure": "", "routes": routes, "variants": [variant]})
    fragments = export.html_sections(render.render("solutions.tex.j2", set=header, problems=problems))
    if len(fragments) != len(keys):
        raise export.BuildError(f"pandoc made {len(fragments)} worked solutions of {len(keys)}")
    return dict(zip(keys, fragments))


def _included(problem: str, body: str) -> str:
    r"""A body's free-body diagram as pandoc reads an image ("" for none): its PNG in the figures
    folder, at a path derive.lms rewrites (with the image's width and alternative text) for each LMS.

    >>> _included("p", "disk"), _included("p", "")
    ('\\includegraphics{figures/p-free-body-disk.png}', '')
    """
    return rf"\includegraphics{{{figure_files.FOLDER}/{figure_files.free_body_name(problem, body)}.png}}" if body else ""


def _lms_items(prepared: list[_ProblemVariants], variants: int, choice: bool,
               solutions: dict[tuple[str, int], str]) -> list[lms.Item]:
    """Every numeric answer of every variant, with its question, tolerance and worked solution
    (`solutions`, by problem id and variant), for the LMS exports; with `choice`, with its
    distractors too (an answer with fewer than distractors.WANTED stays numerical)."""
    items = []
    for number in range(1, variants + 1):
        for item in prepared:
            values = item.draws[number - 1]
            answers, tolerances = item.answers(values), item.tolerances(values)
            wrong = item.wrong(values) if choice else {}
            question = item.questions(siunitx=False)[number - 1]  # MathJax reads no siunitx
            for name, ask in item.problem.asks.items():
                if answers[name] is None:
                    continue
                choices = tuple(d["value"] for d in wrong.get(name, ()))
                asked = len(choices) >= distractors.WANTED
                items.append(lms.Item(item.problem.id, item.problem.title, number, question, name, ask.meaning,
                                      answers[name], units.unicode_unit(ask.unit), tolerances[name],
                                      choices if asked else (), solutions[item.problem.id, number],
                                      tuple(d["mistake"] for d in wrong.get(name, ())) if asked else ()))
    return items


def _worksheet(header: dict, prepared: list[_ProblemVariants], variants: int, figures: list[str | None],
               tex: bool) -> str:
    """The worksheet's LaTeX: each variant's problems, each shown with its figure (`figures`, one
    per problem, None for none: TikZ for the PDF, an \\includegraphics of its image for pandoc).
    `tex` (for LaTeX to compile, not for pandoc, which reads neither): units in siunitx, and each
    figure drawn once, into a box at the start
    of the document that every variant shows (TikZ drew the 300 pictures of 10 problems x 30
    variants in 5 s a pass, the 10 boxes in a tenth of that)."""
    names = [rf"\derivefigure{''.join(chr(ord('A') + int(d)) for d in str(n))}" for n in range(len(figures))]
    boxes = [{"name": name, "figure": drawn} for name, drawn in zip(names, figures) if drawn and tex]
    shown = [rf"\usebox{{{name}}}" if drawn and tex else drawn for name, drawn in zip(names, figures)]
    return render.render("worksheet.tex.j2", set=header, boxes=boxes, variants=[
        {"number": n, "problems": [{"title": item.problem.title, "question": item.questions(tex)[n - 1],
                                    "figure": figure} for item, figure in zip(prepared, shown)]}
        for n in range(1, variants + 1)])


def _shown(prepared: list[_ProblemVariants], images: dict[str, figure_files.Image], target: str) -> list[str | None]:
    """Each problem's figure for pandoc's `target`: its SVG file beside the HTML or the Markdown, or
    in a DOCX its PNG as a data URI (pandoc's --sandbox reads no image file); None without one."""
    shown = []
    for number, item in enumerate(prepared, start=1):
        image = images.get(item.problem.id)
        source = image and (image.data_uri() if target == "docx" else f"{figure_files.FOLDER}/{image.file('svg')}")
        shown.append(image and image.latex(source, f"Figure of problem {number}"))
    return shown


def _write(folder: Path, name: str, text: str) -> Path:
    path = folder / name
    path.write_text(text, encoding="utf-8")
    return path


def build(references: str | Sequence[str] | ProblemSet, *, variants: int | None = None, seed: int | None = None,
          out_dir: str | None = None, formats: frozenset[str] | None = None, questions: str | None = None,
          defaults: Defaults = Defaults(), progress: Reporter = Reporter()) -> list[Path]:
    """Build a set (a set file or its id, problems given by themselves: load_sheet, or a
    ProblemSet: set_of) into its output folder; return the files written. Arguments left None
    take the set file's values (`variants`, `seed`, `outputs`, `questions`), and where it has
    none, the course defaults'."""
    problem_set = references if isinstance(references, ProblemSet) else \
        load_sheet([references] if isinstance(references, str) else references, defaults)
    variants = variants or problem_set.variants
    seed = problem_set.seed if seed is None else seed
    formats = problem_set.outputs if formats is None else formats
    choice = (questions or problem_set.questions) == "choice"
    if formats & ({"pdf"} | figure_files.OUTPUTS):
        export.require("latexmk")  # at once, not after the derivations
    if formats & figure_files.OUTPUTS:
        export.require("pdftocairo")  # the figures as images
    out = output_folder.claim(out_dir or Path("build") / problem_set.id)
    try:  # _prepare froze the derivations (alive to the end of the build) out of the collector's passes
        prepared = _prepare(problem_set, variants, seed, progress)
        header = {"title": problem_set.title, "course": problem_set.course, "due": problem_set.due,
                  "answer_space": problem_set.answer_space}
        drawn = [figure.tikz(item.problem) for item in prepared]  # one per problem, shared by its variants
        # The figures the outputs beyond the PDFs show as images, by problem id: each compiled once.
        figures = {item.problem.id: tikz for item, tikz in zip(prepared, drawn) if tikz} \
            if formats & figure_files.OUTPUTS else {}
        # The free-body diagrams the LMS feedback shows, by image name: one per body, not per variant.
        diagrams = _free_body_figures(prepared) if formats & {"moodle", "qti"} else {}
        figures.update({name: drawn.tikz for name, drawn in diagrams.items()})
        progress("each variant's answers, certified, and the keys")
        rows, key = _keys(problem_set, prepared, variants, seed, "distractors" in formats, choice)
        for note in _numerical_notes(key):  # the set is built; these answers are asked as numbers
            print(f"derive: warning: {note}", file=sys.stderr, flush=True)
        contexts = [_solutions_context(i, siunitx=True) for i in prepared]
        items = []
        if formats & {"moodle", "qti"}:
            progress("the worked solutions as the LMS questions' feedback (pandoc)")
            shown = [_solutions_context(i, siunitx=False) for i in prepared]  # MathJax reads no siunitx
            items = _lms_items(prepared, variants, choice, _worked_solutions(prepared, shown, header))
        for target in sorted(formats & {"moodle", "qti"}):
            lms.check(items, target)  # before anything is written
        key_rows = [{**r, "symbol": render.symbol_latex(r["answer"]), "value": f"${r['latex']}$",
                     "unit": units.siunitx_unit(r["unit"])} for r in rows]

        with output_folder.staged(out) as staging:
            compiling = "pdf" in formats or bool(figures)
            steps = 1 + compiling + bool(figures) + len(formats & {"html", "md", "docx", "moodle", "qti"})
            with progress.task("writing", steps) as begin:
                begin("LaTeX")
                texs = [
                    _write(staging, "worksheet.tex", _worksheet(header, prepared, variants, drawn, tex=True)),
                    _write(staging, "solutions.tex", render.render("solutions.tex.j2", set=header, problems=contexts)),
                    _write(staging, "key.tex", render.render("key.tex.j2", set=header, rows=key_rows)),
                ]
                products = list(texs)
                compiled = texs if "pdf" in formats else []
                if figures:  # a scratch document of its own, compiled with the others (no product)
                    compiled = compiled + [_write(staging, "figures.tex", figure_files.document(list(figures.values())))]
                if compiling:  # each in a scratch folder of its own (export.pdf)
                    begin(f"{len(compiled)} PDF{'s' * (len(compiled) > 1)} (latexmk, {export.workers()} in parallel)")
                    pdfs = export.pdfs(compiled)
                if "pdf" in formats:
                    products += pdfs[:len(texs)]
                    if variants > 1:  # each student's own worksheet: the whole set's pages, split
                        products += _per_variant(texs[0], variants)
                images = {}
                if figures:
                    begin(f"{len(figures)} figures as SVG and PNG (pdftocairo)")
                    images = {name: dataclasses.replace(image, alt=diagrams[name].alt) if name in diagrams else image
                              for name, image in figure_files.images(list(figures), pdfs[-1]).items()}
                shown_images = [image for name, image in images.items() if name not in diagrams]  # the problems'
                if shown_images and formats & {"html", "md"}:  # the SVG files they refer to
                    folder = staging / figure_files.FOLDER
                    folder.mkdir()
                    for image in shown_images:
                        (folder / image.file("svg")).write_bytes(image.svg)
                    products.append(folder)
                for target in ("html", "md", "docx"):
                    if target in formats:
                        begin(f"the worksheet as {target} (pandoc)")
                        shown = _shown(prepared, images, target)
                        products.append(export.convert(_worksheet(header, prepared, variants, shown, tex=False),
                                                       staging / "worksheet",
                                                       target, problem_set.title))
                # The keys and the LMS files are written by Python after every TeX run, so no TeX run
                # could have touched them.
                buffer = io.StringIO()
                writer = csv.DictWriter(buffer, fieldnames=["variant", "problem", "answer", "value", "tolerance", "unit",
                                                            "meaning"], lineterminator="\n", extrasaction="ignore")
                writer.writeheader()
                writer.writerows({k: safe_cell(v) for k, v in {**r, "unit": units.unicode_unit(r["unit"])}.items()}
                                 for r in rows)  # no formulas; the unit as text reads it (kg·m², none for a pure number)
                products += [_write(staging, "key.csv", buffer.getvalue()),
                             _write(staging, "key.json", json_text.dumps(key) + "\n")]
                if "moodle" in formats:
                    begin("Moodle XML")
                    products.append(_write(staging, "moodle.xml", lms.moodle(items, problem_set.id, images)))
                if "qti" in formats:
                    begin("the Canvas QTI zip")
                    path = staging / "canvas-qti.zip"
                    path.write_bytes(lms.qti(items, problem_set.title, problem_set.id, seed, images))
                    products.append(path)
            return output_folder.commit(staging, out, products)
    finally:
        gc.unfreeze()


def _per_variant(worksheet: Path, variants: int) -> list[Path]:
    """worksheet-NN.pdf for each variant, from the pages the whole worksheet labels as its own
    (each variant starts a page with the set's header)."""
    pages = export.variant_pages(worksheet)
    starts = [pages[str(n)] for n in range(1, variants + 1)] + [pages["end"] + 1]
    width = len(str(variants))
    return [export.extract_pages(worksheet.with_suffix(".pdf"), starts[n - 1], starts[n] - 1,
                                 worksheet.with_name(f"worksheet-{n:0{width}d}.pdf"))
            for n in range(1, variants + 1)]


def _limits_context(item: _ProblemVariants, middle: dict[str, sp.Expr], progress: Reporter) -> list[dict[str, str]]:
    """The handout's limiting cases (limiting_cases.chosen): each answer's as a parameter with a
    range goes to 0 (or infinity), where the problem's conditions still hold close to it, the
    other parameters at `middle` (a millionth of its range's low end, or a million times its high
    end, stands for the limit)."""
    progress("limiting cases")
    problem, solution = item.problem, item.solution
    ranged = {p.symbol: (name, p) for name, p in problem.parameters.items() if p.range is not None}
    varying = {symbol: p.unit for symbol, (_, p) in ranged.items()}

    def allowed(symbol: sp.Symbol, point: sp.Expr) -> bool:
        name, p = ranged[symbol]
        low, high = p.bounds()
        near = sp.Rational(str(low)) / 10**6 if point == 0 else sp.Rational(str(high)) * 10**6
        try:
            return solution.violated(item.si_values({**middle, name: near})) is None
        except (ArithmeticError, ValueError):  # a condition with no value there: no case to show
            return False

    cases = [(name, c) for name in problem.asks
             for c in limiting_cases.limiting_cases(solution.expression(name), varying, allowed)]
    point = {0: "0", sp.oo: r"\infty"}
    return [{"equation": rf"\lim_{{{render.latex_of(c.symbol)} \to {point[c.point]}}} {render.symbol_latex(name)} "
                         rf"&= {render.latex_of(c.value)}"
                         + typesetting.note(render.tex_escape(limiting_cases.reading(c, ranged[c.symbol][1].meaning)))}
            for name, c in limiting_cases.chosen(cases, varying)]


def handout(reference: str, out_dir: str | None = None, progress: Reporter = Reporter()) -> list[Path]:
    """One problem's derivation as a handout (LaTeX and PDF): setup, each step of each route,
    the result with a worked example at the middle of the parameter ranges, its limiting
    cases, the checks, and the corrections to the notes."""
    problem = load(reference)
    progress(f"deriving {problem.id}")
    solution = Solution(problem)
    middle = {name: p.value if p.range is None else p.at(Decimal("0.5")) for name, p in problem.parameters.items()}
    item = _ProblemVariants(problem, solution, [middle])
    context = {**_solutions_context(item, siunitx=True), "limits": _limits_context(item, middle, progress)}
    out = output_folder.claim(out_dir or Path("build") / "handouts" / problem.id)
    with output_folder.staged(out) as staging:
        tex = _write(staging, f"{problem.id}.tex", render.render("handout.tex.j2", problem=context,
                                                                   question=item.question(middle, siunitx=True)))
        progress("compiling the PDF")
        return output_folder.commit(staging, out, [tex, export.pdf(tex)])

