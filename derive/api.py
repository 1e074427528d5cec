r"""The Python API, for notebooks and scripts: `derive.load`, `derive.solve` and `derive.sheet`.

They do what `derive solve` and `derive sheet` do (the command line calls them), and raise
derive.core.errors.InputError with the command line's one-line message on bad input. A solved
problem and each of its answers show as math in Jupyter (`_repr_latex_`, `_repr_html_`).

>>> import derive
>>> result = derive.solve("string_wrapped_disk", {"m": 2, "M": 4, "R": "30 cm"}, digits=4)
>>> result
Result(string_wrapped_disk: a = -4.905 m/s^2, alpha = -16.35 rad/s^2, T = 9.810 N)
>>> result["a"]
Answer(a = -2*g*m/(M + 2*m) = -4.905 m/s^2)
>>> result["a"]._repr_latex_()
'$$a = - g \\frac{2 m}{M + 2 m} = -4.905\\,\\mathrm{m}/\\mathrm{s}^{2}$$'
>>> result.at({"m": 1})["T"].value  # the same derivation, m changed
Decimal('6.540')

An answer's `expression` is in the problem's own symbols, which carry sympy's assumptions
(positive=True for a mass or a length): compare with `result.symbols`, not with a plain
`sp.symbols("m M g")`, which sympy holds to be other symbols.

>>> s = result.symbols
>>> sp.simplify(result["a"].expression + 2 * s.g * s.m / (s.M + 2 * s.m))
0
>>> newton_euler = result.equations["newton_euler"]  # sympy equations, at rest in the reference state
>>> newton_euler[2]  # the disk's torque balance
Eq(M*R**2*thetaddot_disk/2, -R*T_string)
"""
from __future__ import annotations

import html
import os
from collections.abc import Mapping
from dataclasses import dataclass
from decimal import Decimal
from functools import cached_property
from pathlib import Path
from types import SimpleNamespace

import sympy as sp

from derive.text.latex import latex_of
from derive.language import defaults, problem_sets
from derive.publishing import cluster, report, worksheets as sheets
from derive.core import units
from derive.core.limits import MAX_DIGITS, MAX_VARIANTS
from derive.solution.answers import Solution
from derive.core.errors import InputError
from derive.language.problem import Problem
from derive.language import problem as problem_files
from derive.publishing.progress import MODES, Reporter

__all__ = ["load", "solve", "sheet", "Result", "Answer", "Figure"]


@dataclass(frozen=True)
class Answer:
    """One asked quantity at the values solved for: its exact `expression` (sympy, in the
    parameters' symbols, SI) and its `value` in its declared `unit`, a Decimal of the digits asked,
    each of them certified by interval arithmetic (None when a parameter it uses has no value);
    `text` is the value as `derive solve` prints it, `direction` its direction in words where the
    quantity has one (the value is then its magnitude)."""

    name: str
    meaning: str
    expression: sp.Expr
    unit: str
    text: str | None
    direction: str | None
    equation: str  # LaTeX: "a = expression = value unit", as `derive solve --format latex` prints it

    @property
    def value(self) -> Decimal | None:
        return None if self.text is None else Decimal(self.text)

    def __repr__(self) -> str:
        toward = f" {self.direction}" if self.direction else ""
        shown = f" = {self.text}{_unit_text(self.unit)}{toward}" if self.text is not None else ""
        return f"Answer({self.name} = {sp.sstr(self.expression)}{shown})"

    def _repr_latex_(self) -> str:
        return f"$${self.equation}$$"

    def _repr_html_(self) -> str:
        return f"<p>{html.escape(self.meaning)}: {_math(self.equation)}</p>"


class Result:
    """A problem solved at some parameter values (a variant): `result["a"]` and `result.answers`
    (Answer), the derivation (`solution`, an answers.Solution) and the report `derive solve`
    prints (`report`, the JSON contract; `as_text()`, `as_latex()`, `as_json()`)."""

    def __init__(self, problem: Problem, solution: Solution, values: Mapping | None, digits: int | None):
        self.problem, self.solution, self.digits = problem, solution, digits
        self.values = _overrides(values)  # as `--set` takes them
        self.report = report.solve(problem, self.values, digits, solution)
        self.answers = {
            name: Answer(name, a["meaning"], solution.expressions[name], a["unit"], a["value"], a["direction"],
                         report.answer_latex(name, a))
            for name, a in self.report["answers"].items()
        }

    @property
    def symbols(self) -> SimpleNamespace:
        """The problem's symbols by name (`result.symbols.M`), as its expressions hold them."""
        return self.problem.symbols

    @cached_property
    def equations(self) -> dict[str, list[sp.Eq]]:
        """Each route's equations of motion ("lagrange", "newton_euler") at rest in the reference
        configuration, as sympy equations; empty where nothing asked moves."""
        return report.equations_of_motion(self.solution)

    @cached_property
    def _figures(self) -> tuple[Figure | None, dict[str, Figure]]:
        from derive.publishing import figures_shown  # TeX and poppler: only where a figure is asked for

        scene, bodies = figures_shown.shown(self.problem, self.solution)
        return (Figure.of(scene) if scene else None), {body: Figure.of(image) for body, image in bodies.items()}

    @property
    def figure(self) -> Figure | None:
        """The scene's figure, as the worksheet draws it (SVG; compiled by TeX on first use), or
        None where the problem has none."""
        return self._figures[0]

    @property
    def free_bodies(self) -> dict[str, Figure]:
        """The free-body diagrams the worked solution shows, by body."""
        return self._figures[1]

    def __getitem__(self, name: str) -> Answer:
        if name not in self.answers:
            raise KeyError(f"{self.problem.id} asks no {name!r} (asks: {', '.join(self.answers)})")
        return self.answers[name]

    def at(self, values: Mapping | None = None, digits: int | None = None) -> Result:
        """The same problem with these values changed (the derivation is not repeated)."""
        return Result(self.problem, self.solution, {**self.values, **_overrides(values)},
                      _digits(self.digits if digits is None else digits))

    def as_text(self, proof: bool = False) -> str:
        """The terminal's report (`proof`: with both routes' equations of motion)."""
        return report.as_text(self.report, self.solution, proof)

    def as_latex(self) -> str:
        return report.as_latex(self.report)

    def as_json(self) -> str:
        return report.as_json(self.report)

    def __repr__(self) -> str:
        shown = ", ".join(f"{a.name} = {a.text}{_unit_text(a.unit)}{' ' + a.direction if a.direction else ''}"
                          if a.text is not None
                          else f"{a.name} = {sp.sstr(a.expression)}" for a in self.answers.values())
        return f"Result({self.problem.id}: {shown})"

    def _given(self) -> list[str]:
        """The parameters that have values, as LaTeX: M = 4.000\\,\\mathrm{kg}."""
        return [f"{latex_of(self.problem.parameters[n].symbol)} = {p['value']}\\,{units.latex_unit(p['unit'])}"
                for n, p in self.report["parameters"].items() if p["value"] is not None]

    def _repr_latex_(self) -> str:
        rows = " \\\\\n".join(report.aligned(a.equation) for a in self.answers.values())
        given = f" \\\\\n&\\text{{at }} {', '.join(self._given())}" if self._given() else ""
        return f"$$\\begin{{aligned}}\n{rows}{given}\n\\end{{aligned}}$$"

    def _repr_html_(self) -> str:
        rows = "".join(
            f"<tr><td>{html.escape(a.meaning)}</td><td>{_math(a.equation)}</td></tr>" for a in self.answers.values())
        given = f"<p>at {', '.join(map(_math, self._given()))}</p>" if self._given() else ""
        return (f"<div><p><strong>{html.escape(self.problem.title)}</strong> "
                f"(<code>{html.escape(self.problem.id)}</code>)</p><table>{rows}</table>{given}</div>")


@dataclass(frozen=True)
class Figure:
    """A figure as SVG, which Jupyter shows: `svg` its text, `alt` what it shows in words."""

    name: str
    svg: str
    alt: str

    @classmethod
    def of(cls, image) -> Figure:
        """The figure of a figure_files.Image."""
        return cls(image.name, image.svg.decode("utf-8"), image.alt)

    def _repr_svg_(self) -> str:
        return self.svg

    def save(self, path: str | os.PathLike) -> Path:
        """Write the SVG file; return its path."""
        path = Path(path)
        path.write_text(self.svg, encoding="utf-8")
        return path


def load(problem: str | os.PathLike | Mapping) -> Problem:
    """A problem from its file, its library id, or a mapping built in Python with the keys and
    values a problem file holds (checked as a file is; errors name `<python>` for the file).

    >>> rod = {"id": "my_rod", "title": "A rod", "question": "Find the rod's moment of inertia about an end.",
    ...        "parameters": {"m": {"meaning": "mass", "unit": "kg", "value": 2},
    ...                       "L": {"meaning": "length", "unit": "m", "value": 1}},
    ...        "scene": {"bodies": {"rod": {"shape": "rod", "mass": "m", "length": "L"}}},
    ...        "ask": {"I": {"meaning": "moment of inertia about an end", "of": "rod.inertia", "axis": "end",
    ...                      "unit": "kg*m^2"}}}
    >>> solve(rod, digits=4)["I"]
    Answer(I = L**2*m/3 = 0.6667 kg*m^2)
    >>> load({**rod, "colour": "red"})
    Traceback (most recent call last):
    ...
    derive.core.errors.ProblemError: <python>: colour: unknown key (allowed: ask, conditions, corrections, difficulty, id, ...)
    """
    if isinstance(problem, Mapping):
        return problem_files.parse(_as_yaml(problem), Path("<python>"))
    return problem_files.load(problem)


def _as_yaml(value: Mapping) -> str:
    """A mapping of plain values (text, numbers, lists, mappings) as the YAML of a problem file."""
    import yaml

    def plain(v, where):
        if isinstance(v, Mapping):
            return {str(k): plain(item, f"{where}.{k}" if where else str(k)) for k, item in v.items()}
        if isinstance(v, (list, tuple)):
            return [plain(item, f"{where}[{i}]") for i, item in enumerate(v)]
        if v is None or isinstance(v, (str, int, float, bool)):
            return v
        raise InputError(f"<python>: {where}: expected text, a number, a list or a mapping, as a problem file "
                         f"holds, got {type(v).__name__} (write an expression as text: \"M*R**2/2\")")

    return yaml.safe_dump(plain(value, ""), sort_keys=False, allow_unicode=True)


def _math(latex: str) -> str:
    """Inline math in HTML, which Jupyter's MathJax typesets."""
    return f"\\({html.escape(latex)}\\)"


def _unit_text(unit: str) -> str:
    return "" if unit in ("", "1") else f" {unit}"


def _overrides(values: Mapping | None) -> dict[str, str]:
    """Parameter values as `--set` takes them: {"m": 2, "M": "200 g"} -> {"m": "2", "M": "200 g"}."""
    if values is None:
        return {}
    if not isinstance(values, Mapping):
        raise InputError(f"values: expected a mapping of parameter names to values, e.g. {{'m': 2, 'M': '200 g'}}, "
                         f"got {type(values).__name__}")
    return {str(name): str(value) for name, value in values.items()}


def _whole(name: str, value, low: int | None = None, high: int | None = None) -> int:
    """A whole number the caller gave, within [low, high] where given."""
    if (isinstance(value, bool) or not isinstance(value, int) or (low is not None and value < low)
            or (high is not None and value > high)):
        within = f" from {low} to {high}" if high is not None else ""
        raise InputError(f"{name}: expected a whole number{within}, got {value!r}")
    return value


def _digits(digits) -> int | None:
    return None if digits is None else _whole("digits", digits, 1, MAX_DIGITS)


def solve(problem: Problem | str | os.PathLike | Mapping, values: Mapping | None = None, digits: int | None = 15) -> Result:
    """Derive a problem (a Problem, a problem file or a library id) and answer it at `values`:
    {name: value}, a number in the parameter's declared unit or a text with a unit ("200 g"), as
    `derive solve --set` takes them. Parameters not given keep the file's value; an answer that
    uses one with no value has its expression only. Values have `digits` significant digits
    (None: each answer the significant figures its inputs support).

    >>> solve("rod_endpoint", digits=3)["I"]
    Answer(I = L**2*m/3)
    >>> solve("rod_endpoint", {"q": 1})
    Traceback (most recent call last):
    ...
    derive.core.errors.ProblemError: --set q: rod_endpoint has no parameter 'q' (parameters: m, L)
    """
    problem = problem if isinstance(problem, Problem) else load(problem)
    return Result(problem, Solution(problem), values, _digits(digits))


def sheet(ids_or_set: str | os.PathLike | list, out: str | os.PathLike | None = None, *, variants: int | None = None,
          seed: int | None = None, to: str | list[str] | None = None, questions: str | None = None,
          title: str | None = None, progress: str | Reporter = "auto", jobs: int = 1, cache: bool = True,
          scheduler: str | None = None) -> list[Path]:
    """Build a problem set as `derive sheet` does, into `out` (default build/<set id>); return
    the files written.

    `ids_or_set` is a set file or the id of one, or a list of problems as a set file lists them
    (ids, files, {"topic": "rolling", "count": 2}), which builds with a set file's defaults into
    build/problems, under `title`. `variants`, `seed`, `to` (outputs besides the .tex files and
    the keys: "pdf,html" or a list; [] for none), `questions` ("numerical" or "choice") override
    the set's. `progress`: "auto", "bar", "lines" or "none" (stderr). `jobs` processes derive the
    problems; `cache`: take each derivation from the derivation cache where it holds it, and keep
    the others there; `scheduler`: a Dask scheduler's address, whose workers derive them (as
    `derive sheet --jobs`, `--no-cache`, `--scheduler`).

    >>> sheet(["rod_endpoint"], to="pfd")
    Traceback (most recent call last):
    ...
    derive.core.errors.InputError: --to: unknown output 'pfd' (outputs: pdf, html, md, docx, moodle, qti, distractors); did you mean 'pdf'?
    """
    course = defaults.load()  # derive.toml or [tool.derive] of the working folder, as for `derive sheet`
    if isinstance(ids_or_set, (str, os.PathLike)):
        if title is not None:
            raise InputError("title: a set file gives its own title")
        problem_set = str(ids_or_set)
    elif isinstance(ids_or_set, (list, tuple)):
        problem_set = problem_sets.set_of([str(p) if isinstance(p, os.PathLike) else p for p in ids_or_set], title, course)
    else:
        raise InputError(f"ids_or_set: expected a set file or id, or a list of problem ids or files, got "
                         f"{type(ids_or_set).__name__}")
    if isinstance(progress, str):
        if progress not in MODES:
            raise InputError(f"progress: expected one of {', '.join(MODES)}, got {progress!r}")
        progress = Reporter(progress)
    if questions not in (None, *problem_sets.QUESTIONS):
        raise InputError(f"questions: expected one of {', '.join(problem_sets.QUESTIONS)}, got {questions!r}")
    return sheets.build(
        problem_set, out_dir=out, questions=questions, progress=progress, defaults=course,
        jobs=_whole("jobs", jobs, 1, 256), cache=bool(cache),
        scheduler=None if scheduler is None else cluster.check_address(str(scheduler)),
        variants=None if variants is None else _whole("variants", variants, 1, MAX_VARIANTS),
        seed=None if seed is None else _whole("seed", seed),
        formats=None if to is None else defaults.outputs(to if isinstance(to, str) else ",".join(to), "--to"))
