"""Distractors are derived from mistaken set-ups, and differ from the answer and each other."""
import collections
import dataclasses
import json
import random
from decimal import Decimal

import mpmath
import pytest

from conftest import copy_library, notes_files, run_derive
from derive.publishing import distractors, variants
from derive.solution.answers import Solution
from derive.language.problem import load


def test_rolling_sphere_distractors_are_the_classic_mistakes():
    p = load("rolling_incline")
    values = p.values({"M": "1", "R": "0.1", "H": "1", "theta": "0.5"})
    found = {d["mistake"]: d["value"] for d in distractors.distractors(p, "a", values, 3, limit=10)}
    g_sin = 9.81 * float(mpmath.sin(0.5))
    assert abs(float(found["sliding instead of rolling (ball)"]) - g_sin) < 0.01
    assert abs(float(found["the inertia of a ring for the sphere"]) - g_sin / 2) < 0.01
    assert abs(float(found["the inertia of a disk for the sphere"]) - 2 * g_sin / 3) < 0.01
    right = 5 * g_sin / 7
    assert all(abs(float(v) - right) > 0.005 for v in found.values())
    assert len(set(found.values())) == len(found)


def test_forgotten_parallel_axis_term():
    p = load("parallel_axis_rod")
    found = {d["mistake"]: d["value"] for d in distractors.distractors(p, "I", p.values({"M": "2", "L": "1", "h": "0.3"}), 3,
                                                                          limit=10)}
    assert found["the parallel-axis term forgotten"] == "0.167"   # M L^2 / 12


def test_sheet_key_carries_distractors(tmp_path):
    library = copy_library(tmp_path)
    (library / "sets" / "roll.yaml").write_text("title: Roll\nproblems: [rolling_incline]\nvariants: 2\n")
    out = tmp_path / "out"
    done = run_derive("sheet", "roll", "--to", "distractors", "--out", str(out), library=library)
    assert done.returncode == 0, done.stderr
    key = json.loads((out / "key.json").read_text())
    answer = key["variants"][0]["problems"]["rolling_incline"]["answers"]["a"]
    assert answer["distractors"] and all(d["value"] != answer["value"] for d in answer["distractors"])
    assert "numerical" not in answer  # only a multiple-choice build says how an answer is asked


def _found(problem_id, name, values, digits=3):
    p = load(problem_id)
    return {d["mistake"]: float(d["value"]) for d in distractors.distractors(p, name, p.values(values), digits, limit=20)}


def test_a_pivoted_body_gets_the_parallel_axis_term_forgotten_doubled_and_its_inertia_forgotten():
    """omega = sqrt(M g d / (I_cm + M d^2)); forgotten: I_cm; doubled: I_cm + 2 M d^2; the body's
    own inertia forgotten: the simple pendulum sqrt(g / d)."""
    found = _found("compound_pendulum", "omega", {"M": "2", "Rcm": "0.5", "I_cm": "0.1"})
    assert found["the parallel-axis term forgotten (pendulum about its pivot)"] == pytest.approx((2 * 9.81 * 0.5 / 0.1) ** 0.5, 1e-2)
    assert found["the parallel-axis term counted twice (pendulum about its pivot)"] == pytest.approx((9.81 / 1.1) ** 0.5, 1e-2)
    assert found["the pendulum's rotational inertia forgotten"] == pytest.approx((9.81 / 0.5) ** 0.5, 1e-2)


def test_the_small_angle_formula_outside_its_range():
    found = _found("compound_pendulum_large", "T", {"M": "2", "Rcm": "0.5", "I_cm": "0.1", "theta0": "2"})
    small = 2 * 3.14159265 * (0.6 / (2 * 9.81 * 0.5)) ** 0.5
    assert found["the approximation T_small (small-angle period) outside its range"] == pytest.approx(small, 1e-2)


def test_a_sign_error_on_the_torque_and_an_angle_from_the_vertical():
    """The tugged spool: the string leaving the hub from above, a = F (cos(theta) + r/R) / (M + I/R^2);
    its angle taken from the vertical, F (sin(theta) - r/R) / (M + I/R^2)."""
    values = {"F": "5", "M": "1", "R": "0.05", "r": "0.02", "I_cm": "0.001", "theta": "0.5"}
    found = _found("tugged_spool", "a", values)
    mass = 1 + 0.001 / 0.05**2
    assert found["a sign error on the torque of pull1"] == pytest.approx(5 * (mpmath.cos(0.5) + 0.4) / mass, 1e-2)
    assert found["the angle of pull1 measured from the vertical"] == pytest.approx(5 * (mpmath.sin(0.5) - 0.4) / mass, 1e-2)


def test_the_wrong_point_and_the_wrong_kind_of_collision():
    """The struck rod held at its center (L = m v d = I omega), and the bounce taken as elastic or
    perfectly inelastic."""
    values = {"m": "0.2", "M": "1", "L": "1", "d": "0.2", "v": "5", "e": "0.5"}
    found = _found("restitution_rod", "omega", values)
    held = _found("restitution_rod", "omega", {**values, "e": "1"})
    assert found["the collision taken as elastic"] == pytest.approx(float(distractors._value(
        Solution(load("restitution_rod")), "omega", load("restitution_rod").values({**values, "e": "1"}), 6)), 1e-2)
    assert "the collision taken as elastic" not in held  # it is elastic: no such mistake
    assert "the collision taken as perfectly inelastic" in found
    assert any(m.startswith("angular momentum about the rod's center") for m in found)


def test_a_mistaken_set_up_the_engine_cannot_derive_is_no_option(monkeypatch):
    """A mistake whose derivation fails in any way (the loop-the-loop's sliding ball failed with an
    IndexError and took the whole set down) gives no option, and no error."""
    p = load("rolling_incline")
    broken = dataclasses.replace(p, id="broken")
    original = distractors.perturbations
    monkeypatch.setattr(distractors, "perturbations", lambda problem: [("broken", broken), *original(problem)])
    monkeypatch.setattr(distractors, "Solution", lambda problem: _Failing() if problem.id == "broken" else Solution(problem))
    values = p.values({"M": "1", "R": "0.1", "H": "1", "theta": "0.5"})
    found = distractors.distractors(p, "a", values, 3)
    assert len(found) == 3 and "broken" not in {d["mistake"] for d in found}


class _Failing:
    def __getattr__(self, name):
        raise IndexError("list index out of range")


def _library_items(count=3):
    """(problem, answer, right value, wrong values) of every numeric answer of the lecture notes'
    problems (with the textbook setups of the library this one test took over 9 minutes of CPU)."""
    for path in notes_files():
        problem = load(str(path))
        solution = Solution(problem)
        draws = [variants.valid_draw(problem, solution, random.Random(f"1/{problem.id}/{n}")) for n in range(count)]
        item = variants.ProblemVariants(problem, solution, draws)
        for draw in draws:
            answers, wrong, tolerances = item.answers(draw), item.wrong(draw), item.tolerances(draw)
            for name in problem.asks:
                if answers[name] is not None:
                    yield problem.id, name, answers[name], [d["value"] for d in wrong[name]], tolerances[name]


def test_over_the_library_options_are_distinct_and_the_right_one_is_not_guessed_by_rank():
    """Every multiple-choice item has four options differing at the digits shown, and the right
    answer's rank among the sorted options is spread: no rank holds more than 40% of the items,
    and each end at least 10% (with three options, half, the answer and double, it was always
    the middle one)."""
    ranks, items = collections.Counter(), 0
    for problem_id, name, right, wrong, tolerance in _library_items():
        assert len(wrong) <= distractors.WANTED
        shown = [Decimal(v) for v in [right, *wrong]]
        assert len(set(shown)) == len(shown), (problem_id, name, right, wrong)
        # no option the right answer's own tolerance accepts: it would be no wrong answer
        assert all(abs(v - Decimal(right)) > Decimal(tolerance) for v in shown[1:]), (problem_id, name, right, wrong)
        if len(wrong) == distractors.WANTED:
            items += 1
            ranks[sorted(shown).index(Decimal(right))] += 1
    assert items >= 100
    assert max(ranks.values()) <= 0.4 * items, ranks
    assert min(ranks[0], ranks[3]) >= 0.1 * items, ranks


def test_the_factor_of_two_only_when_too_few_mistakes_apply_and_never_both():
    p = load("rolling_incline")  # many mistakes apply: no factor of 2
    values = p.values({"M": "1", "R": "0.1", "H": "1", "theta": "0.5"})
    assert not any("factor of 2" in d["mistake"] for d in distractors.distractors(p, "a", values, 3))
    p = load("compound_pendulum")
    for limit in (3, 6, 10):  # more options asked than mistakes apply: one factor of 2 at most
        found = distractors.distractors(p, "T", p.values({"M": "2", "Rcm": "0.5", "I_cm": "0.1"}), 3, limit=limit)
        assert sum("factor of 2" in d["mistake"] for d in found) <= 1


def test_choice_builds_with_the_loop_problems_and_too_few_options_stay_numerical(tmp_path):
    """`--questions choice` on the loop-the-loop problems (it crashed with an IndexError) builds;
    an answer with fewer than three wrong options is asked as a number, with a warning and a note
    in key.json."""
    library_copy = copy_library(tmp_path)
    (library_copy / "sets" / "loops.yaml").write_text(
        "title: Loops\nproblems: [loop_the_loop, loop_the_loop_ball, rod_midpoint]\nvariants: 2\n")
    out = tmp_path / "out"
    done = run_derive("sheet", "loops", "--to", "moodle", "--questions", "choice", "--out", str(out),
                      library=library_copy)
    assert done.returncode == 0, done.stderr
    key = json.loads((out / "key.json").read_text())
    answers = key["variants"][0]["problems"]
    assert "numerical" not in answers["loop_the_loop_ball"]["answers"]["h_roll"]
    assert len(answers["loop_the_loop_ball"]["answers"]["h_roll"]["distractors"]) == 3
    note = answers["rod_midpoint"]["answers"]["I"]["numerical"]
    assert "multiple choice needs 3" in note
    assert f"derive: warning: rod_midpoint: ask.I, variants 1, 2: {note}" in done.stderr
    xml = (out / "moodle.xml").read_text()
    assert xml.count("MULTICHOICE") >= 2 * 2 and "NUMERICAL" in xml
