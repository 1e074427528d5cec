"""The keys filled into stencils (derive.publishing.answer_keys) are the text the JSON and CSV writers give
for the same key written whole, whatever layout each variant's entry takes: digits vouched for by
balls, by the exact fallback or by agreement, distractors, answers asked as numbers in some
variants only (issue 17: the per-variant path made lean, its text unchanged)."""
import csv
import json
import io
import random

import pytest

from derive.publishing import answer_keys, distractors, json_text, variants
from derive.numbers import numeric
from derive.core import units
from derive.solution.answers import Solution
from derive.language.problem import load
from derive.language.problem_sets import set_of
from derive.publishing.spreadsheet import safe_cell
from derive.text.stencil import Stencil, hole


def _whole(problem_set, prepared, count, seed, with_distractors, choice):
    """The key written whole, as derive wrote it before the stencils: dicts, then the writers."""
    key = {"set": problem_set.id, "title": problem_set.title, "seed": seed, "conventions": answer_keys.conventions(prepared),
           "variants": []}
    rows = []
    for number in range(1, count + 1):
        entry = {"variant": number, "problems": {}}
        for item in prepared:
            draw = item.draws[number - 1]
            certified, tolerances, directions = item.certified(draw), item.tolerances(draw), item.directions(draw)
            answers = {}
            for name, ask in item.problem.asks.items():
                value = certified[name]
                answers[name] = {"value": value and value.text, "tolerance": tolerances[name],
                                 "expr": item.expression_texts[name], "unit": ask.unit, "meaning": ask.meaning,
                                 "certificate": value and value.certificate()}
                if item.solution.senses[name] is not None:
                    answers[name]["direction"] = directions[name]
                if with_distractors or choice:
                    wrong = item.wrong(draw)[name]
                    answers[name]["distractors"] = wrong
                    if choice and value is not None and len(wrong) < distractors.WANTED:
                        answers[name]["numerical"] = answer_keys._too_few(len(wrong))
                rows.append([number, item.problem.id, name, value.text if value else item.expression_texts[name],
                             tolerances[name] or "", units.unicode_unit(ask.unit), ask.meaning, directions[name] or ""])
            entry["problems"][item.problem.id] = {
                "parameters": {n: {"value": numeric.significant(draw[n], p.sig_figs), "unit": p.unit}
                               for n, p in item.problem.parameters.items()},
                "answers": answers}
        key["variants"].append(entry)
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(answer_keys.CSV_FIELDS)
    writer.writerows([safe_cell(cell) for cell in row] for row in rows)
    return json_text.dumps(key), buffer.getvalue()


@pytest.fixture(scope="module")
def prepared():
    items = []
    for problem_id in ("string_wrapped_disk", "kepler_orbit"):
        problem = load(problem_id)
        solution = Solution(problem)
        draws = variants.valid_draws(problem, solution, [random.Random(f"7/{problem_id}/{n}") for n in range(1, 5)])
        items.append(variants.ProblemVariants(problem, solution, draws))
    return items


@pytest.mark.parametrize("with_distractors, choice", [(False, False), (True, False), (True, True)])
def test_the_stencils_write_what_the_writers_write(prepared, with_distractors, choice):
    problem_set = set_of(["string_wrapped_disk", "kepler_orbit"])
    items = [variants.ProblemVariants(i.problem, i.solution, i.draws) for i in prepared]
    disk = items[0]
    for draw, method in zip(disk.draws[1:3], ("exact", "agreement")):  # layouts that vary by variant
        disk.certified(draw)[next(iter(disk.problem.asks))] = numeric.Certified(
            disk.certified(draw)[next(iter(disk.problem.asks))].text, method)
    if choice:  # an answer asked as a number in one variant only
        disk.wrong(disk.draws[3])[next(iter(disk.problem.asks))][1:] = []
    keys = answer_keys.write(problem_set, items, 4, 7, with_distractors, choice)
    expected_json, expected_csv = _whole(problem_set, items, 4, 7, with_distractors, choice)
    assert keys.json == expected_json
    assert keys.csv == expected_csv
    assert len(keys.tex_rows) == 4 * sum(len(i.problem.asks) for i in items)
    assert ('"method": "exact"' in keys.json) and ('"method": "agreement"' in keys.json)
    if choice:
        assert any("variant 4:" in note for note in keys.notes)


def test_a_stencil_keeps_braces_and_names_each_holes_indent():
    stencil = Stencil("\\frac{" + hole("a") + "}{2}\n    {" + hole("b") + "}")
    assert stencil.fill({"a": "{x}", "b": "1"}) == "\\frac{{x}}{2}\n    {1}"
    assert stencil.indents == {"a": "", "b": "    "}
    with pytest.raises(KeyError):
        stencil.fill({"a": "1"})


def test_a_key_says_only_what_holds_for_its_answers(tmp_path):
    """With an answer in cm/s^2 the key said "SI units; angles in radians"; with directions in words,
    "y up; counter-clockwise positive" (issue 37, degrees). A key says each row's unit where one is not
    SI, an angle's unit only where an angle is asked (in the unit asked), directions in words where an
    answer has one, and a sign convention only where a value is negative."""
    from conftest import run_derive

    def said(problem: str, *replaced: tuple[str, str]) -> str:
        text = load(problem).path.read_text()
        for old, new in replaced:
            assert old in text, old
            text = text.replace(old, new)
        path = tmp_path / f"{problem}.yaml"
        path.write_text(text)
        out = tmp_path / problem
        done = run_derive("sheet", str(path), "--to", "", "--out", str(out), "--variants", "2", "--jobs", "1")
        assert done.returncode == 0, done.stderr
        key = json.loads((out / "key.json").read_text())["conventions"]
        assert f"{key}." in (out / "key.tex").read_text()
        return key

    asked = "of: block.acceleration.y, unit: m/s^2"
    assert said("string_wrapped_disk", (asked, asked.replace("m/s^2", "cm/s^2"))) == (
        "Each value in the unit its row gives; a negative value's sign as its question states it; "
        "values to the significant figures shown")
    degrees = ("unit: rad, range: [0.1, 1.2]", "unit: deg, range: [6, 68]")  # an incline stated in degrees
    assert said("rolling_incline", degrees) == (
        "SI units; a quantity with a direction as its magnitude, its direction beside its unit; "
        "values to the significant figures shown")
    angle, direction = "of: rod.angle, in: highest, unit: rad", "a quantity with a direction as its magnitude, " \
                                                                "its direction beside its unit"  # the pin's force
    assert said("rod_swing_stops", (angle, angle.replace("rad", "deg"))) == (
        f"Each value in the unit its row gives; angles in degrees; {direction}; values to the significant figures shown")
    assert said("rod_swing_stops") == f"SI units; angles in radians; {direction}; values to the significant figures shown"
    assert said("rod_endpoint") == answer_keys.CONVENTIONS
