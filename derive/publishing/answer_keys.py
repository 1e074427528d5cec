"""A set's answer keys: key.json, key.csv and the rows of key.tex.

key.json records each variant's parameters and answers (the value, its tolerance, the
expression, the unit, the meaning and the certificate of its digits, derive.numbers.numeric; for a
quantity with a direction, its value a magnitude, the direction in words: derive.model.directions);
key.csv and key.tex give one row per answer. Every variant's part has the same layout with other values
in it, so each problem's layout is written once, by the JSON writer, the CSV writer and the
key-row template, with holes where a variant's values go (derive.text.stencil), and each variant
fills them: a key of 300 variants costs a join per problem and variant, not a pass of each
writer (issue 17). The text is that the writers would give (tests/keys holds keys built before).

>>> import json, random
>>> from derive.solution.answers import Solution
>>> from derive.publishing.variants import draw
>>> from derive.language.problem import load
>>> from derive.language.problem_sets import set_of
>>> problem = load("string_wrapped_disk")
>>> item = ProblemVariants(problem, Solution(problem), [draw(problem, random.Random(1))])
>>> keys = write(set_of(["string_wrapped_disk"]), [item], variants=1, seed=0)
>>> json.loads(keys.json)["variants"][0]["problems"]["string_wrapped_disk"]["answers"]["a"]["value"] == \\
...     item.answers(item.draws[0])["a"]
True
>>> keys.csv.splitlines()[0]
'variant,problem,answer,value,tolerance,unit,meaning,direction'
"""
from __future__ import annotations

import csv
import io
from dataclasses import dataclass
from functools import cached_property
from json.encoder import encode_basestring

from derive.text.latex import symbol_latex
from derive.publishing import distractors, json_text, render
from derive.core import units
from derive.publishing.json_text import Raw
from derive.language.problem_sets import ProblemSet
from derive.publishing.spreadsheet import safe_cell
from derive.text.stencil import Stencil, hole
from derive.publishing.variants import ProblemVariants, number_latex

#: What a key of SI answers with no angle, no direction and no sign to state says of its values.
CONVENTIONS = "SI units; values to the significant figures shown"


def conventions(prepared: list[ProblemVariants]) -> str:
    """What a key says of its values, only what holds for its answers (a key of answers in degrees
    said "angles in radians", and "y up" where every direction was in words): their units, the
    angles' unit where an angle is asked, directions in words where an answer has one, and signs as
    the questions state them where a value is negative.

    A key of answers in radians and in degrees, one with a direction, one negative:
    'Each value in the unit its row gives; angles in radians or degrees; a quantity with a direction
    as its magnitude, its direction beside its unit; a negative value's sign as its question states
    it; values to the significant figures shown'
    """
    asks = [(item, name, ask) for item in prepared for name, ask in item.problem.asks.items()]
    said = ["SI units" if all(units.si_factor(units.parse_unit(ask.unit)) == 1 for _, _, ask in asks)
            else "Each value in the unit its row gives"]
    angles = [word for unit, word in (("rad", "radians"), ("deg", "degrees")) if any(a.unit == unit for _, _, a in asks)]
    if angles:
        said.append("angles in " + " or ".join(angles))
    if any(item.solution.senses[name] is not None for item, name, _ in asks):
        said.append("a quantity with a direction as its magnitude, its direction beside its unit")
    if any(value is not None and value.startswith("-") for item in prepared for draw in item.draws
           for value in item.answers(draw).values()):
        said.append("a negative value's sign as its question states it")
    return "; ".join([*said, "values to the significant figures shown"])


#: `direction`: which way a quantity with a direction points, its value the magnitude (derive.model.directions).
CSV_FIELDS = ("variant", "problem", "answer", "value", "tolerance", "unit", "meaning", "direction")


@dataclass(frozen=True)
class Keys:
    """A set's keys as text: key.json, key.csv, the rows of key.tex, and a note for each answer of a
    multiple-choice set that too few mistakes apply to (asked as a number), and for each general
    result that the LMS exports leave out."""

    json: str
    csv: str
    tex_rows: list[str]
    notes: list[str]
    conventions: str = CONVENTIONS


#: Why a general result (an expression) is in no LMS export: key.json's `lms` of the answer.
LEFT_OUT = "not in the Moodle and Canvas exports: {} a general result (an expression), which an LMS cannot grade as a number"


def write(problem_set: ProblemSet, prepared: list[ProblemVariants], variants: int, seed: int,
          with_distractors: bool = False, choice: bool = False, lms: bool = False) -> Keys:
    """The keys of the set's `variants` variants. With `with_distractors` or `choice`, each answer's
    wrong values from mistaken set-ups; with `choice`, an answer too few apply to is marked as
    asked as a number, with why (`numerical`, and a note). With `lms` (the set is exported to an
    LMS), each general result is marked as left out of the exports (`lms`, and a note: a problem
    all of whose answers are general results is missing from the quiz)."""
    keys = [_ProblemKey(item, with_distractors or choice, choice, lms) for item in prepared]
    said = conventions(prepared)
    top = Stencil(json_text.dumps({"set": problem_set.id, "title": problem_set.title, "seed": seed,
                                   "conventions": said, "variants": Raw(hole("variants"))}))
    entry = Stencil(json_text.dumps({"variant": Raw(hole("variant")),
                                     "problems": {key.id: Raw(hole(key.id)) for key in keys}},
                                    top.indents["variants"] + "  "))
    entries, csv_rows, tex_rows, numerical = [], [], [], {}
    for number in range(1, variants + 1):
        values = {"variant": str(number)}
        for key in keys:
            values[key.id] = key.entry(number, entry.indents[key.id], numerical)
            csv_rows += key.csv_rows(number)
            tex_rows += key.tex_rows(number)
        entries.append(entry.fill(values))
    text = top.fill({"variants": json_text.items(entries, top.indents["variants"])})
    header = io.StringIO()
    csv.writer(header, lineterminator="\n").writerow(CSV_FIELDS)
    notes = [f"{problem_id}: ask.{name}, variant{'s' if len(numbers) > 1 else ''} {', '.join(map(str, numbers))}: "
             f"{note}" for (problem_id, name, note), numbers in numerical.items()]
    return Keys(text, header.getvalue() + "".join(csv_rows), tex_rows, notes + [n for key in keys for n in key.left_out],
                said)


def _too_few(found: int) -> str:
    return (f"asked as a number: only {found} distinct wrong option{'' if found == 1 else 's'} derived "
            f"(multiple choice needs {distractors.WANTED})")


def _string(text: str | None) -> str:
    """A JSON token for text or None."""
    return "null" if text is None else encode_basestring(text)


class _ProblemKey:
    """One problem's part of every variant's key: its entry in key.json, its rows of key.csv and
    key.tex, each from a stencil cut once (an entry's stencil once for each of its layouts: how
    each answer's digits are vouched for, whether it is asked as a number)."""

    def __init__(self, item: ProblemVariants, with_distractors: bool, choice: bool, lms: bool):
        self.item, self.id = item, item.problem.id
        self.with_distractors, self.choice, self.lms = with_distractors, choice, lms
        self._entries: dict[tuple, Stencil] = {}
        # the names of the holes (below) of each parameter, and each answer's: v value, t tolerance,
        # r and b the radius and bits of its certificate, d its distractors, w its direction in words
        self._parameter_holes = [f"p:{name}" for name in item.problem.parameters]
        self._answer_holes = [tuple(f"{kind}:{name}" for kind in "vtrbdw") for name in item.problem.asks]

    def entry(self, number: int, indent: str, numerical: dict) -> str:
        """The problem's entry in variant `number` of key.json, written at `indent`; an answer asked
        as a number for too few distractors is added to `numerical` (by problem, answer and why)."""
        item = self.item
        draw = item.draws[number - 1]
        certified = item.certified(draw)
        wrong = item.wrong(draw) if self.with_distractors else {}
        too_few = {name: _too_few(len(wrong[name])) for name, value in certified.items()
                   if self.choice and value is not None and len(wrong[name]) < distractors.WANTED}
        layout = (indent, tuple(None if value is None else value.method for value in certified.values()), tuple(too_few))
        stencil = self._entries.get(layout) or self._entries.setdefault(layout, self._entry(*layout))
        values = {hole_name: encode_basestring(text) for hole_name, text in zip(self._parameter_holes,
                                                                               item.numbers[number - 1].values())}
        tolerances, directions = item.tolerances(draw), item.directions(draw)
        for (name, value), (v, t, r, b, d, w) in zip(certified.items(), self._answer_holes):
            if item.solution.senses[name] is not None:
                values[w] = _string(directions[name])
            if value is not None:
                values[v], values[t] = encode_basestring(value.text), _string(tolerances[name])
                if value.method == "ball":
                    values[r], values[b] = encode_basestring(value.radius_text), str(value.bits)
            if self.with_distractors:
                values[d] = json_text.dumps(wrong[name], stencil.indents[d])
        for name, note in too_few.items():
            values[f"n:{name}"] = encode_basestring(note)
            numerical.setdefault((self.id, name, note), []).append(number)
        return stencil.fill(values)

    def _entry(self, indent: str, methods: tuple, numerical: tuple) -> Stencil:
        """The stencil of an entry whose answers' digits are vouched for by `methods` (None for a
        general result), those in `numerical` asked as numbers."""
        problem = self.item.problem
        answers = {}
        for (name, ask), method in zip(problem.asks.items(), methods):
            general = method is None
            answer = {"value": None if general else Raw(hole(f"v:{name}")),
                      "tolerance": None if general else Raw(hole(f"t:{name}")),
                      "expr": self.item.expression_texts[name], "unit": ask.unit, "meaning": ask.meaning,
                      "certificate": None if general else {"method": method} if method != "ball" else
                      {"method": "ball", "radius": Raw(hole(f"r:{name}")), "bits": Raw(hole(f"b:{name}"))}}
            if self.item.solution.senses[name] is not None:  # its value is a magnitude: which way it points
                answer["direction"] = Raw(hole(f"w:{name}"))
            if self.with_distractors:
                answer["distractors"] = Raw(hole(f"d:{name}"))
            if name in numerical:
                answer["numerical"] = Raw(hole(f"n:{name}"))
            if general and self.lms:
                answer["lms"] = LEFT_OUT.format("it is")
            answers[name] = answer
        parameters = {name: {"value": Raw(hole(f"p:{name}")), "unit": p.unit} for name, p in problem.parameters.items()}
        return Stencil(json_text.dumps({"parameters": parameters, "answers": answers}, indent))

    def csv_rows(self, number: int) -> list[str]:
        """The problem's rows of key.csv in variant `number`: a value and a tolerance are decimals,
        which a CSV writer neither quotes nor marks (spreadsheet.safe_cell)."""
        item = self.item
        draw = item.draws[number - 1]
        answers, tolerances, directions = item.answers(draw), item.tolerances(draw), item.directions(draw)
        return [stencil.fill({"variant": str(number), "value": answers[name] or "", "tolerance": tolerances[name] or "",
                              "direction": directions[name] or ""})
                for name, stencil in self._csv_stencils.items()]

    @cached_property
    def _csv_stencils(self) -> dict[str, Stencil]:
        """Each answer's CSV row, its constant cells written by the CSV writer (a general result's
        value is its expression, the same in every variant)."""
        stencils = {}
        general = self._general
        for name, ask in self.item.problem.asks.items():
            buffer = io.StringIO()
            row = {"variant": hole("variant"), "problem": self.id, "answer": name,
                   "value": self.item.expression_texts[name] if name in general else hole("value"),
                   "tolerance": "" if name in general else hole("tolerance"),
                   "unit": units.unicode_unit(ask.unit), "meaning": ask.meaning, "direction": hole("direction")}
            csv.writer(buffer, lineterminator="\n").writerow([safe_cell(row[f]) for f in CSV_FIELDS])
            stencils[name] = Stencil(buffer.getvalue())
        return stencils

    def tex_rows(self, number: int) -> list[str]:
        """The problem's rows of key.tex in variant `number`."""
        item = self.item
        draw = item.draws[number - 1]
        answers, tolerances, directions = item.answers(draw), item.tolerances(draw), item.directions(draw)
        return [stencil.fill({"variant": str(number), "value": item.shown(name, answers[name]),
                              "direction": f" {directions[name]}" if directions[name] else "",
                              "tolerance": "" if tolerances[name] is None else f"${number_latex(tolerances[name].lower())}$"})
                for name, stencil in self._tex_stencils.items()]

    @cached_property
    def _tex_stencils(self) -> dict[str, Stencil]:
        """Each answer's row of key.tex; a general result's expression spans the value's and the
        tolerance's columns (it has no tolerance, and a long one would run off the page)."""
        general = self._general
        return {name: Stencil(render.render("key-row.tex.j2", variant=hole("variant"), problem=self.id,
                                            symbol=symbol_latex(name), value=f"${hole('value')}$",
                                            tolerance=None if name in general else hole("tolerance"),
                                            unit=units.siunitx_unit(ask.unit), direction=hole("direction")))
                for name, ask in self.item.problem.asks.items()}

    @property
    def left_out(self) -> list[str]:
        """What the LMS exports leave out of this problem, for the terminal: the whole problem where
        every answer is a general result, else each general result; nothing without `lms`."""
        general = [name for name in self.item.problem.asks if name in self._general] if self.lms else []
        if general and len(general) == len(self.item.problem.asks):
            return [f"{self.id}: the whole problem is {LEFT_OUT.format('every answer is')}"]
        return [f"{self.id}: ask.{name}: {LEFT_OUT.format('it is')}" for name in general]

    @cached_property
    def _general(self) -> set[str]:
        """The answers that are general results (an expression in every variant, no number)."""
        return {name for name, value in self.item.certified(self.item.draws[0]).items() if value is None} \
            if self.item.draws else set()
