"""Problem sets: variants drawn from the parameter ranges, worksheets, solutions and keys.

Each problem is derived once; each variant draws its parameters reproducibly from the
seed, rounds them to their significant figures (exact decimals), and evaluates the
answers. Everything is built in a temporary folder and moved into place only when the
whole build succeeded, so a failed build leaves the previous one intact.

Called, this module builds a set (read by derive.language.problem_sets): `derive.sheet("demo",
out="build/demo")` is derive.api.sheet.
"""
from __future__ import annotations

import dataclasses
import gc
import random
import sys
from contextlib import contextmanager
from decimal import Decimal
from pathlib import Path
from typing import Sequence

import sympy as sp

from derive.text.latex import latex_of, symbol_latex, tex_escape
from derive.publishing import (answer_keys, canvas, deriving, distractors, export, figure_files, limiting_cases, lms, typeset_cache,
                               notation, output_folder, render)
from derive.text import prose, typesetting
from derive.core import units
from derive.solution.answers import Solution
from derive.language.defaults import Defaults
from derive.core.errors import InputError
from derive.publishing.figure import free_body
from derive.language.problem import Problem, load
from derive.language.problem_sets import ProblemSet, load_sheet
from derive.publishing.progress import Reporter
from derive.publishing.report import route_title
from derive.publishing.wording import Wording
from derive.text.stencil import Stencil, hole
from derive.publishing.variants import ProblemVariants, unit_latex, valid_draws



LONGEST_EQUATION = 700  # characters of LaTeX; longer would overflow the page


TOO_LONG = r"\text{(too long to typeset here: see derive solve --format latex)}"


def typeset(equation: sp.Eq, beside: str = "", tag: str = "", tex: bool = False, left: float | None = None) -> str:
    """An equation for an align environment, a long sum broken across lines (typesetting.rows; a
    row still too wide set smaller where LaTeX compiles it, `tex`), `beside` a note at its first
    row, `tag` its number at its last (`tag`); one too long to typeset at all becomes a short
    note in place of its long side, on the right (`0 = (too long ...)`: on the left, the note
    would widen the column of left sides of every row it aligns with). `left`: how wide the left
    sides of the equations aligned with it are (typesetting.left_column).

    >>> x = sp.Symbol("x")
    >>> print(typeset(sp.Eq(sum(x**k / (k + 1) for k in range(200)), 0)))
    0 &= \\text{(too long to typeset here: see derive solve --format latex)}
    """
    if len(latex_of(equation)) > LONGEST_EQUATION:
        short = [side for side in (equation.lhs, equation.rhs) if len(latex_of(side)) <= LONGEST_EQUATION / 10]
        return (latex_of(short[0]) if short else "") + " &= " + TOO_LONG + beside + tag
    room = typesetting.LINE - (typesetting.TAG if tag else 0)
    return typesetting.rows(equation.lhs, equation.rhs, room=room, beside=beside, tex=tex, left=left) + tag


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


@contextmanager
def _entry(problem_set: ProblemSet, where: str):
    """An error about a problem of the set names the set file and the entry first."""
    try:
        yield
    except InputError as error:
        raise InputError(f"{problem_set.path}: {where}: {error}") from None


def _prepare(problem_set: ProblemSet, variants: int, seed: int, progress: Reporter, jobs: int = 1,
             scheduler: str | None = None,
             cache: bool = True) -> list[ProblemVariants]:
    """Each problem derived (its answers, checks and steps: from the derivation cache, else by `jobs`
    processes), then its variants drawn: the derivations are the set's fixed cost, the draws the
    first step of its cost per variant. The objects alive once the problems are derived are frozen
    (gc.freeze): the caller unfreezes them."""
    problems, ids = [], {}
    for number, (reference, where) in enumerate(zip(problem_set.problems, problem_set.fields)):
        with _entry(problem_set, where):  # then the problem file and its field
            problem = problem_set.loaded[number] if problem_set.loaded else load(reference)
            if problem.id in ids:
                raise InputError(f"{problem.path}: id: {problem.id} is also the id of {ids[problem.id]}; "
                                 "ids in a set must differ")
            ids[problem.id] = f"{where} ({problem.path})"
        problems.append(problem)
    derived = deriving.derive(problems, jobs, cache, progress,
                              where=lambda i: _entry(problem_set, problem_set.fields[i]), scheduler=scheduler)
    gc.freeze()  # every full pass of the collector rescanned them: a fifth of the time per variant
    progress(f"drawing {variants} variant{'s' * (variants > 1)} of each problem")
    prepared = []
    for problem, (solution, _), where in zip(problems, derived, problem_set.fields):
        with _entry(problem_set, where):
            draws = valid_draws(problem, solution, [random.Random(f"{seed}/{problem.id}/{n}")
                                                    for n in range(1, variants + 1)])
        prepared.append(ProblemVariants(problem, solution, draws, problem_set.tolerance, cache))
    return prepared


def _check_latex(check, problem: Problem, siunitx: bool) -> str:
    """A check as a worked solution prints it: its reading, the units of the answers in math."""
    if check.name == "dimensions":
        units_of = ", ".join(f"${symbol_latex(n)}$ in ${unit_latex(a.unit, siunitx)}$" if unit_latex(a.unit, siunitx)
                             else f"${symbol_latex(n)}$ a pure number" for n, a in problem.asks.items())
        return f"Every answer has the units it should: {units_of}."
    return prose.set_as_math(Wording(problem)(check.reading), [*problem.parameters, *problem.asks])


def _solutions_context(item: ProblemVariants, siunitx: bool, cache: bool = False) -> dict:
    """A problem's worked solution for the templates: its routes' steps, its answers, its checks (typeset
    once for its derivation: derive.publishing.typeset_cache, with `cache`), each variant's numbers
    (units in siunitx where LaTeX compiles it: `unit_latex`)."""
    problem = item.problem
    worked = typeset_cache.kept(problem, f"worked, {'siunitx' if siunitx else 'plain'}",
                                lambda: _worked(item, siunitx), cache)
    return {"title": problem.title, "source": problem.source, **worked, "variants": _numbers(item, siunitx),
            "corrections": list(problem.corrections), "figure": item.figure}


def _worked(item: ProblemVariants, siunitx: bool) -> dict:
    """The worked solution's routes, the instructor's verification, the results and the checks."""
    problem, solution = item.problem, item.solution
    numbered = iter(range(1, 10**6))  # the problem's equations, numbered through its routes
    student, proof = solution.student_steps, solution.steps()
    routes = _routes(item, student, numbered, siunitx, item.student_free_bodies) if student is not None else \
        _routes(item, proof, numbered, siunitx, item.free_bodies)
    # Lagrange's method and Newton–Euler in full: the instructor's verification where the student's route is written
    verification = _routes(item, proof, numbered, siunitx, item.free_bodies) if student is not None else []
    results = {n: sp.Eq(sp.Symbol(n), item.shown_expressions[n], evaluate=False) for n in problem.asks}
    left = typesetting.left_column(results.values())  # the results align
    answers = [
        {"symbol": symbol_latex(n), "latex": item.expression_latexes[n], "meaning": a.meaning,
         "rows": typeset(results[n], typesetting.note(prose.set_as_math(a.meaning, [*problem.parameters, *problem.asks]),
                                                      tex=siunitx), tex=siunitx, left=left)}
        for n, a in problem.asks.items()
    ]
    checks = [_check_latex(c, problem, siunitx) for c in solution.checks()]  # the detail stays in `derive check`, the JSON
    return {"routes": routes, "verification": verification, "answers": answers, "checks": checks}


def _routes(item: ProblemVariants, all_steps: dict, numbered, siunitx: bool, diagrams: dict) -> list[dict]:
    """Routes of a worked solution for the templates: each step's text, its equations numbered on
    from `numbered`, the free-body diagram beside a balance (`diagrams`, by the id of its step), the
    parts' sentences."""
    printed = notation.printed(item.problem, item.solution, all_steps, item.letters)  # a step renamed keeps its diagram
    names = symbol_names(item.problem, printed)
    words = Wording(item.problem)  # the file's keys in the engine's words, described
    routes = []
    for route, steps in all_steps.items():
        shown, solved, before = [], [], ""  # the numbers of the equations this route solves; what was just said
        for original, s in zip(steps, printed[route]):
            numbers = [next(numbered) for _ in s.equations]
            solved += numbers if s.role == "equations" else []
            text = words(f"{s.text}, from {equation_numbers(solved)}" if s.role == "solve" and solved else s.text)
            before = words(s.sentences[-1].words) if s.sentences else before
            if before and prose.repeats(before, words(s.text)):
                text = ""  # the sentence just said it (in this step or the one before): no near-copy of it
            before = "" if s.equations else text or before
            left = typesetting.left_column(s.equations, typesetting.LINE - typesetting.TAG)  # the rows align
            shown.append({"text": prose.set_as_math(prose.capital(text), names),
                          "equations": [typeset(e, tag=tag(n, siunitx), tex=siunitx, left=left)
                                        for e, n in zip(s.equations, numbers)],
                          "diagram": diagrams[id(original)].tikz if id(original) in diagrams else "",
                          "body": diagrams[id(original)].body if id(original) in diagrams else "",
                          "sentences": [words.sentence(sentence).latex(tex=siunitx) for sentence in s.sentences]})
        routes.append({"title": prose.set_as_math(prose.capital(words(route_title(route))), names), "steps": shown})
    return routes


def symbol_names(problem: Problem, steps: dict) -> set[str]:
    """The names of a worked solution's symbols, which its prose sets as math (prose.set_as_math):
    the parameters, the asks, and every symbol its steps typeset."""
    return {*problem.parameters, *problem.asks, *(s.name for s in notation.step_symbols(
        step for route in steps.values() for step in route))}


def numbers_context(item: ProblemVariants, siunitx: bool, given: dict[str, str], results: dict[str, str],
                    directions: dict[str, str]) -> dict:
    """A variant's numbers as the templates show them: its given values (`given`: each
    parameter's value and unit as math), its results (`results`: each answer's LaTeX) and which way
    each points (`directions`: LaTeX after the unit, "" for none)."""
    problem = item.problem
    return {"given": [f"${latex_of(item.letters.get(p.symbol, p.symbol))} = {given[n]}$" for n, p in problem.parameters.items()],
            "results": [{"symbol": symbol_latex(n), "value": results[n], "direction": directions[n],
                         "unit": units.after_number(a.unit, unit_latex(a.unit, siunitx))} for n, a in problem.asks.items()]}


def direction_latex(words: str | None) -> str:
    r"""Which way an answer points, after its unit in math ("" for none): words from
    derive.model.directions, a fixed vocabulary (no text from a file).

    >>> direction_latex("up the slope"), direction_latex(None)
    ('\\ \\text{up the slope}', '')
    """
    return rf"\ \text{{{words}}}" if words else ""


def _numbers(item: ProblemVariants, siunitx: bool) -> list[str]:
    """Each variant's numbers in the worked solutions (solutions-numbers.tex.j2), filled into a
    stencil written once for the problem."""
    problem = item.problem
    stencil = Stencil(render.render("solutions-numbers.tex.j2", variant={
        "number": hole("number"), **numbers_context(item, siunitx, {n: hole(f"g:{n}") for n in problem.parameters},
                                                    {n: hole(f"r:{n}") for n in problem.asks},
                                                    {n: hole(f"d:{n}") for n in problem.asks})}))
    texts = []
    for number, (draw, given) in enumerate(zip(item.draws, item.numbers), start=1):
        answers = item.answers(draw)
        values = {f"g:{n}": text for n, text in item.quantities(given, siunitx).items()}
        values.update({f"r:{n}": item.shown(n, answers[n]) for n in problem.asks})
        values.update({f"d:{n}": direction_latex(words) for n, words in item.directions(draw).items()})
        values["number"] = str(number)
        texts.append(stencil.fill(values))
    return texts


def _free_body_figures(prepared: list[ProblemVariants]) -> dict[str, free_body.FreeBody]:
    """Every free-body diagram of the set by its image's name (figure_files.free_body_name): what
    the LMS feedback shows as images, each compiled once whatever the number of variants."""
    return {figure_files.free_body_name(item.problem.id, drawn.body): drawn
            for item in prepared for drawn in item.shown_free_bodies.values()}


def _worked_solutions(prepared: list[ProblemVariants], contexts: list[dict], header: dict) -> dict[tuple[str, int], str]:
    """Each problem's worked solution for each variant as HTML, keyed (problem id, variant): the
    solutions sheet's own template and text, each section one problem with that variant's numbers
    only (no figure: the question shows it), converted by pandoc in one run (export.html_sections).
    pandoc reads no TikZ: each free-body diagram is an image, figures/NAME.png (`free_body_name`),
    which derive.publishing.lms resolves to the file each LMS carries; the same for every variant."""
    keys, problems = [], []
    for item, context in zip(prepared, contexts):
        routes = [{**r, "steps": [{**s, "diagram": _included(item.problem.id, s["body"])} for s in r["steps"]]}
                  for r in context["routes"]]
        for number, variant in enumerate(context["variants"], start=1):
            keys.append((item.problem.id, number))
            problems.append({**context, "figure": "", "routes": routes, "variants": [variant]})
    fragments = export.html_sections(render.render("solutions.tex.j2", set=header, problems=problems, verification=False))
    if len(fragments) != len(keys):
        raise export.BuildError(f"pandoc made {len(fragments)} worked solutions of {len(keys)}")
    return dict(zip(keys, fragments))


def _sources(prepared: list[ProblemVariants]) -> list[dict]:
    """What the instructor's key says of each problem that has a source or corrections to the notes:
    neither reaches the students (their solutions, the LMS feedback)."""
    return [{"title": item.problem.title, "source": item.problem.source, "corrections": list(item.problem.corrections)}
            for item in prepared if item.problem.source or item.problem.corrections]


def _included(problem: str, body: str) -> str:
    r"""A body's free-body diagram as pandoc reads an image ("" for none): its PNG in the figures
    folder, at a path derive.publishing.lms rewrites (with the image's width and alternative text) for each LMS.

    >>> _included("p", "disk"), _included("p", "")
    ('\\includegraphics{figures/p-free-body-disk.png}', '')
    """
    return rf"\includegraphics{{{figure_files.FOLDER}/{figure_files.free_body_name(problem, body)}.png}}" if body else ""


def _lms_items(prepared: list[ProblemVariants], variants: int, choice: bool,
               solutions: dict[tuple[str, int], str]) -> list[lms.Item]:
    """Every numeric answer of every variant, with its question, tolerance and worked solution
    (`solutions`, by problem id and variant), for the LMS exports; with `choice`, with its
    distractors too (an answer with fewer than distractors.WANTED stays numerical)."""
    items = []
    for number in range(1, variants + 1):
        for item in prepared:
            values = item.draws[number - 1]
            answers, tolerances, directions = item.answers(values), item.tolerances(values), item.directions(values)
            wrong = item.wrong(values) if choice else {}
            question = item.questions(siunitx=False)[number - 1]  # MathJax reads no siunitx
            words = Wording(item.problem)  # a mistake's feedback names the file's parts as the solutions do
            for name, ask in item.problem.asks.items():
                if answers[name] is None:
                    continue
                choices = tuple(d["value"] for d in wrong.get(name, ()))
                asked = len(choices) >= distractors.WANTED
                items.append(lms.Item(item.problem.id, item.problem.title, number, question, name, ask.meaning,
                                      answers[name], units.unicode_unit(ask.unit), tolerances[name],
                                      choices if asked else (), solutions[item.problem.id, number],
                                      tuple(words(d["mistake"]) for d in wrong.get(name, ())) if asked else (),
                                      directions[name] or "", _senses(item, name)))
    return items


def _senses(item: ProblemVariants, name: str) -> tuple[str, ...]:
    """The ways an asked quantity can point, where they differ between the problem's variants (the
    LMS exports ask which); none where every variant's is the same (its value, a magnitude, is asked)."""
    sense = item.solution.senses[name]
    return (sense.positive, sense.negative) if sense is not None and name in item.varying_directions else ()


def _worksheet(header: dict, prepared: list[ProblemVariants], variants: int, figures: list[str | None],
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
    stencil = Stencil(render.render("worksheet-variant.tex.j2", set=header, variant={
        "number": hole("number"), "printed": tex, "problems": [{"title": item.problem.title, "question": hole(f"q{i}"), "figure": figure}
                                               for i, (item, figure) in enumerate(zip(prepared, shown))]}))
    questions = [item.questions(tex) for item in prepared]
    return render.render("worksheet.tex.j2", set=header, boxes=boxes, printed=tex, variants=[
        stencil.fill({"number": str(n), **{f"q{i}": asked[n - 1] for i, asked in enumerate(questions)}})
        for n in range(1, variants + 1)])


def _shown(prepared: list[ProblemVariants], images: dict[str, figure_files.Image], target: str) -> list[str | None]:
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
          defaults: Defaults = Defaults(), progress: Reporter = Reporter(), jobs: int = 1,
          cache: bool = True, scheduler: str | None = None) -> list[Path]:
    """Build a set (a set file or its id, problems given by themselves: load_sheet, or a
    ProblemSet: set_of) into its output folder; return the files written. Arguments left None
    take the set file's values (`variants`, `seed`, `outputs`, `questions`), and where it has
    none, the course defaults'. The problems are derived by `jobs` processes, each taken from
    the derivation cache where it holds it (`cache`; derive.publishing.deriving), or by the workers
    of the Dask scheduler at `scheduler` (derive.publishing.cluster); a PDF whose TeX was compiled
    before comes from the cache too (`cache`; derive.publishing.tex_cache)."""
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
    with output_folder.claim(Path("build") / problem_set.id if out_dir is None else out_dir) as out:
        try:  # _prepare froze the derivations (alive to the end of the build) out of the collector's passes
            prepared = _prepare(problem_set, variants, seed, progress, jobs, scheduler, cache)
            header = {"title": problem_set.title, "course": problem_set.course, "due": problem_set.due,
                      "answer_space": problem_set.answer_space}
            drawn = [item.figure for item in prepared]  # one per problem, shared by its variants
            # The figures the outputs beyond the PDFs show as images, by problem id: each compiled once.
            figures = {item.problem.id: tikz for item, tikz in zip(prepared, drawn) if tikz} \
                if formats & figure_files.OUTPUTS else {}
            # The free-body diagrams the LMS feedback shows, by image name: one per body, not per variant.
            diagrams = _free_body_figures(prepared) if formats & {"moodle", "qti"} else {}
            figures.update({name: drawn.tikz for name, drawn in diagrams.items()})
            progress("each variant's answers, certified, and the keys")
            keys = answer_keys.write(problem_set, prepared, variants, seed, "distractors" in formats, choice,
                                     lms=bool(formats & {"moodle", "qti"}))
            for note in keys.notes:  # the set is built; these answers are asked as numbers, or left out of the LMS
                print(f"derive: warning: {note}", file=sys.stderr, flush=True)
            contexts = [_solutions_context(i, siunitx=True, cache=cache) for i in prepared]
            items = []
            if formats & {"moodle", "qti"}:
                progress("the worked solutions as the LMS questions' feedback (pandoc)")
                shown = [_solutions_context(i, siunitx=False, cache=cache) for i in prepared]  # MathJax reads no siunitx
                items = _lms_items(prepared, variants, choice, _worked_solutions(prepared, shown, header))
            for target in sorted(formats & {"moodle", "qti"}):
                lms.check(items, target)  # before anything is written

            with output_folder.staged(out) as staging:
                compiling = "pdf" in formats or bool(figures)
                steps = 1 + compiling + bool(figures) + len(formats & {"html", "md", "docx", "moodle", "qti"})
                with progress.task("writing", steps) as begin:
                    begin("LaTeX")
                    texs = [
                        _write(staging, "worksheet.tex", _worksheet(header, prepared, variants, drawn, tex=True)),
                        _write(staging, "solutions.tex", render.render("solutions.tex.j2", set=header, problems=contexts, verification=True)),
                        _write(staging, "key.tex", render.render("key.tex.j2", set=header, rows=keys.tex_rows,
                                                                   conventions=keys.conventions,
                                                                   sources=_sources(prepared))),
                    ]
                    products = list(texs)
                    compiled = texs if "pdf" in formats else []
                    if figures:  # a scratch document of its own, compiled with the others (no product)
                        compiled = compiled + [_write(staging, "figures.tex", figure_files.document(list(figures.values())))]
                    if compiling:  # each in a scratch folder of its own (export.pdf)
                        begin(f"{len(compiled)} PDF{'s' * (len(compiled) > 1)} (latexmk, {export.workers()} in parallel)")
                        pdfs = export.pdfs(compiled, cache)
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
                    products += [_write(staging, "key.csv", keys.csv), _write(staging, "key.json", keys.json + "\n")]
                    if "moodle" in formats:
                        begin("Moodle XML")
                        products.append(_write(staging, "moodle.xml", lms.moodle(items, problem_set.id, images)))
                    if "qti" in formats:
                        begin("the Canvas QTI zip")
                        path = staging / "canvas-qti.zip"
                        path.write_bytes(canvas.qti(items, problem_set.title, problem_set.id, seed, images))
                        products.append(path)
                return output_folder.commit(staging, out, products)
        finally:
            gc.unfreeze()


def _per_variant(worksheet: Path, variants: int) -> list[Path]:
    """worksheet-NN.pdf for each variant, from the pages the whole worksheet labels as its own
    (each variant starts a page with the set's header; the last runs to the document's end: a
    mark after it would be lost where nothing follows it on its page, as after an answer space)."""
    pages = export.variant_pages(worksheet)
    missing = [str(n) for n in range(1, variants + 1) if str(n) not in pages]
    if missing:
        raise export.BuildError(f"worksheet.pdf: LaTeX recorded no first page for variant {', '.join(missing)}")
    starts = [pages[str(n)] for n in range(1, variants + 1)] + [export.page_count(worksheet.with_suffix(".pdf")) + 1]
    width = len(str(variants))
    return [export.extract_pages(worksheet.with_suffix(".pdf"), starts[n - 1], starts[n] - 1,
                                 worksheet.with_name(f"worksheet-{n:0{width}d}.pdf"))
            for n in range(1, variants + 1)]


def _limits_context(item: ProblemVariants, middle: dict[str, sp.Expr], progress: Reporter) -> list[dict[str, str]]:
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
    return [{"equation": rf"\lim_{{{latex_of(c.symbol)} \to {point[c.point]}}} {symbol_latex(name)} "
                         rf"&= {latex_of(c.value)}"
                         + typesetting.note(tex_escape(limiting_cases.reading(c, ranged[c.symbol][1].meaning)))}
            for name, c in limiting_cases.chosen(cases, varying)]


def handout(reference: str, out_dir: str | None = None, progress: Reporter = Reporter()) -> list[Path]:
    """One problem's derivation as a handout (LaTeX and PDF): setup, each step of each route,
    the result with a worked example at the middle of the parameter ranges, its limiting
    cases, the checks, and the corrections to the notes."""
    problem = load(reference)
    progress(f"deriving {problem.id}")
    solution = Solution(problem)
    middle = {name: p.value if p.range is None else p.at(Decimal("0.5")) for name, p in problem.parameters.items()}
    item = ProblemVariants(problem, solution, [middle])
    answers = item.answers(middle)
    example = numbers_context(item, True, item.quantities(item.numbers[0], siunitx=True),
                              {n: item.shown(n, answers[n]) for n in problem.asks},
                              {n: direction_latex(words) for n, words in item.directions(middle).items()})
    context = {**_solutions_context(item, siunitx=True), "example": example,
               "limits": _limits_context(item, middle, progress)}
    with output_folder.claim(Path("build") / "handouts" / problem.id if out_dir is None else out_dir) as out, \
            output_folder.staged(out) as staging:
        tex = _write(staging, f"{problem.id}.tex", render.render("handout.tex.j2", problem=context,
                                                                   question=item.question(middle, siunitx=True)))
        progress("compiling the PDF")
        return output_folder.commit(staging, out, [tex, export.pdf(tex)])

