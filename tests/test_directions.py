"""A vector asked in a question is answered as a magnitude with its direction in words (issue 37,
item 4): the key and both LMS exports grade the magnitude, so a student who answers "2.13 N" for a
friction of -2.13 N (along an axis the question never named) is graded right. A signed component is
asked only where the question states its sign convention (`sign:`, which the question must say).
Where the direction changes between variants, the LMS exports ask it as a choice.

Each direction is checked against the physics worked independently here, not read back from the engine.
"""
import json
import re
import zipfile
from decimal import Decimal
from pathlib import Path

import pytest
import sympy as sp
from lxml import etree

from conftest import refused, run_derive, write_problem
from derive.language.problem import load
from derive.solution.answers import Solution

ROOT = Path(__file__).resolve().parent.parent


def _key(out: Path) -> dict:
    return json.loads((out / "key.json").read_text())


def _answers(key: dict, problem: str):
    for variant in key["variants"]:
        entry = variant["problems"][problem]
        values = {n: Decimal(p["value"]) for n, p in entry["parameters"].items()}
        yield values, entry["answers"]


@pytest.fixture(scope="module")
def built(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("directions") / "out"
    done = run_derive("sheet", "rolling_incline", "beetle_lazy_susan", "restitution_rod", "string_wrapped_disk",
                      "--variants", "12", "--seed", "3", "--to", "moodle,qti", "--out", str(out))
    assert done.returncode == 0, done.stderr
    return out


def test_the_rolling_spheres_friction_is_a_magnitude_up_the_slope():
    """Halliday, Resnick & Walker, Fundamentals of Physics, ch. 11 (Sample Problem 11.02, a ball
    rolling down a ramp): f = I a / R^2 = (2/7) M g sin(theta), up the ramp; a = (5/7) g sin(theta) down it."""
    solution = Solution(load("rolling_incline"))
    M, g, theta = (sp.Symbol(n, positive=True) for n in ("M", "g", "theta"))
    assert sp.simplify(solution.expression("f") - sp.Rational(2, 7) * M * g * sp.sin(theta)) == 0
    assert sp.simplify(solution.signed_expression("f") + sp.Rational(2, 7) * M * g * sp.sin(theta)) == 0
    assert solution.senses["f"].of(-1) == "up the slope"
    assert solution.senses["a"].of(1) == "down the slope"


def test_the_key_gives_the_friction_as_a_positive_magnitude_and_its_direction(built):
    key = _answers(_key(built), "rolling_incline")
    for values, answers in key:
        f = Decimal(2) / 7 * values["M"] * values["g"] * Decimal(str(sp.sin(sp.Float(str(values["theta"]), 30))))
        assert answers["f"]["direction"] == "up the slope" and answers["a"]["direction"] == "down the slope"
        assert abs(Decimal(answers["f"]["value"]) - f) <= Decimal(answers["f"]["tolerance"])
        assert "direction" not in answers["v"] and "direction" not in answers["mu_min"]  # no direction: none said
    rows = [line.split(",") for line in (built / "key.csv").read_text().splitlines()]
    assert rows[0][-1] == "direction"
    assert {r[-1] for r in rows[1:] if r[1:3] == ["rolling_incline", "f"]} == {"up the slope"}


def test_the_lazy_susan_turns_clockwise_at_a_positive_rate(built):
    """The lazy Susan's question says it turns clockwise and states no sign convention: its rate
    afterwards is a magnitude, and its direction follows from the angular momentum about the axle
    (Halliday ch. 11, conservation of L): L = m R v - I omega0 counter-clockwise, kept when the beetle
    stops, so the rate is |L| / (I + m R^2), counter-clockwise where L > 0. The change of kinetic energy
    is a loss: its magnitude, "lost"."""
    for values, answers in _answers(_key(built), "beetle_lazy_susan"):
        m, v, R, inertia, omega0 = (values[n] for n in ("m", "v", "R", "I", "omega0"))
        L = m * R * v - inertia * omega0
        omega = answers["omega"]
        assert omega["direction"] == ("counter-clockwise" if L > 0 else "clockwise")
        assert abs(Decimal(omega["value"]) - abs(L) / (inertia + m * R * R)) <= Decimal(omega["tolerance"])
        assert answers["dE"]["direction"] == "lost" and not answers["dE"]["value"].startswith("-")


def test_a_ball_that_bounces_back_in_some_variants_is_asked_its_direction_in_both_lms_exports(built):
    """A ball striking a free rod at distance d from its center with restitution e leaves at
    v (m - e M*)/(m + M*), M* = 1/(1/M + d^2/I), I = M L^2/12 (Kleppner & Kolenkow, 2nd ed., ch. 7):
    it keeps going where m > e M*, the way the struck rod goes, and bounces back otherwise."""
    key = _key(built)
    ways = []
    for values, answers in _answers(key, "restitution_rod"):
        M, L, m, v, d, e = (values[n] for n in ("M", "L", "m", "v", "d", "e"))
        effective = 1 / (1 / M + d * d / (M * L * L / 12))
        after = v * (m - e * effective) / (m + effective)
        ball, rod = answers["v_after"], answers["V"]
        assert (ball["direction"] == rod["direction"]) == (after > 0)
        assert abs(Decimal(ball["value"]) - abs(after)) <= Decimal(ball["tolerance"])
        ways.append(ball["direction"])
    assert len(set(ways)) == 2, "the seed was chosen so that the ball goes both ways among the variants"
    questions = etree.parse(str(built / "moodle.xml")).getroot().iter("question")
    moodle = "".join(q.findtext("questiontext/text") for q in questions
                     if q.get("type") == "cloze" and q.findtext("name/text").startswith("restitution_rod"))
    fields = [f for f in re.findall(r"\{1:MULTICHOICE:([^}]*)\}", moodle) if "up" in f]  # the ball's
    assert [re.search(r"=([a-z -]+)", f).group(1) for f in fields] == ways  # variant by variant, the right one marked
    with zipfile.ZipFile(built / "canvas-qti.zip") as archive:
        (name,) = [n for n in archive.namelist() if n.endswith(".xml") and "/" in n and "meta" not in n]
        tree = etree.fromstring(archive.read(name))
    ns = {"q": "http://www.imsglobal.org/xsd/ims_qtiasiv1p2"}
    items = [i for i in tree.iterfind(".//q:item", ns) if i.get("title").endswith("v_after direction")]
    assert len(items) == len(ways)
    for item, way in zip(items, ways):
        right = item.find(".//q:respcondition/q:conditionvar/q:varequal", ns).text
        label = item.find(f".//q:response_label[@ident='{right}']", ns)
        assert label.find(".//q:mattext", ns).text == way


def test_no_asked_magnitude_is_negative_in_the_key_or_either_lms_export(built):
    """Only an answer whose question states its sign convention may be negative (the string-wrapped
    disk's y up and counter-clockwise positive); every other graded value is a magnitude."""
    signed = {"a", "alpha"}
    key = _key(built)
    negative = set()
    for variant in key["variants"]:
        for problem, entry in variant["problems"].items():
            for name, answer in entry["answers"].items():
                if answer["value"] and answer["value"].startswith("-"):
                    negative.add(answer["value"])
                    assert problem == "string_wrapped_disk" and name in signed, (problem, name)
                    assert "direction" not in answer
    assert negative, "the disk's block falls: its y component is negative"
    numerical = re.findall(r"NUMERICAL:=(-?[0-9.eE+-]+):", (built / "moodle.xml").read_text())
    assert {n for n in numerical if n.startswith("-")} <= negative


def test_a_sign_convention_must_be_stated_by_the_question(tmp_path):
    text = (ROOT / "problems" / "torque" / "string_wrapped_disk.yaml").read_text()
    assert "sign: y up" in text
    unstated = text.replace("Taking $y$ up and counter-clockwise rotation as positive, find",
                            "Find")
    assert "does not say 'y up'" in refused(tmp_path, unstated, "ask.a.sign")
    on_a_tension = text.replace("of: string.tension, unit: N}", "of: string.tension, unit: N, sign: x right}")
    assert "does not say 'x right'" in refused(tmp_path, on_a_tension, "ask.T.sign")


def test_without_a_stated_convention_the_block_falls_at_a_magnitude_downward(tmp_path):
    text = (ROOT / "problems" / "torque" / "string_wrapped_disk.yaml").read_text().replace(", sign: y up", "")
    path = tmp_path / "disk.yaml"
    path.write_text(text)
    done = run_derive("solve", str(path), "--set", "M=2", "--set", "m=1", "--set", "R=0.2", "--format", "json")
    assert done.returncode == 0, done.stderr
    a = json.loads(done.stdout)["answers"]["a"]
    # Kleppner & Kolenkow (a mass on a cord wound on a disk): a = 2 m g/(M + 2 m), downward
    assert a["direction"] == "down" and abs(float(a["value"]) - 2 * 9.81 / 4) < 1e-12


def _incline_counted_up_the_slope(convention: str) -> str:
    """The rolling sphere, its question stating a sign convention for its acceleration and friction."""
    text = (ROOT / "problems" / "rolling" / "rolling_incline.yaml").read_text()
    text = text.replace("Find its acceleration,", f"Taking {convention} as positive, find its acceleration,")
    text = text.replace("of: ball.acceleration.down_incline, unit: m/s^2}",
                        f"of: ball.acceleration.down_incline, unit: m/s^2, sign: {convention}}}")
    return text.replace("unit: N, magnitude: true}", f"unit: N, sign: {convention}}}")


def test_a_stated_convention_that_counts_the_other_way_turns_the_answers_round(tmp_path):
    """The question says up the slope is positive; the routes count down it. Halliday, Resnick &
    Walker, Sample Problem 11.02: a = (5/7) g sin(theta) down the ramp, f = (2/7) M g sin(theta) up it,
    so up-the-slope components are -(5/7) g sin(theta) and +(2/7) M g sin(theta)."""
    solution = Solution(load(write_problem(tmp_path, _incline_counted_up_the_slope("up the incline"))))
    M, g, theta = (sp.Symbol(n, positive=True) for n in ("M", "g", "theta"))
    assert sp.simplify(solution.expression("a") + sp.Rational(5, 7) * g * sp.sin(theta)) == 0
    assert sp.simplify(solution.expression("f") - sp.Rational(2, 7) * M * g * sp.sin(theta)) == 0
    assert solution.senses["a"] is None and solution.senses["f"] is None  # no direction in words: the sign says it
    down = Solution(load(write_problem(tmp_path, _incline_counted_up_the_slope("down the ramp"))))
    assert sp.simplify(down.expression("a") - sp.Rational(5, 7) * g * sp.sin(theta)) == 0
    assert sp.simplify(down.expression("f") + sp.Rational(2, 7) * M * g * sp.sin(theta)) == 0


def test_a_convention_that_names_no_way_the_quantity_points_is_refused(tmp_path):
    message = refused(tmp_path, _incline_counted_up_the_slope("toward the wall"), "ask.a.sign")
    assert "'down the slope' or 'up the slope'" in message


def test_derive_check_refuses_a_question_whose_convention_no_ask_gives(tmp_path):
    """The Atwood machine's question says "taking up as positive" of the heavier block, which goes
    down (Serway & Jewett ch. 10: a = (m1 - m2) g/(m1 + m2 + M/2) downward): without `sign:` its key
    would grade +2.91 m/s^2 "down", and a student who counts as told (-2.91) would be marked wrong."""
    from derive.checks import signs
    text = (ROOT / "problems" / "torque" / "atwood_massive_pulley.yaml").read_text()
    assert ", sign: taking up as positive}" in text
    assert signs.ungiven(load(write_problem(tmp_path, text))) == []
    ungiven = signs.ungiven(load(write_problem(tmp_path, text.replace(", sign: taking up as positive}", "}"))))
    assert len(ungiven) == 1 and "question: it states a sign convention ('taking up as positive')" in ungiven[0]
    meaning = text.replace("angular acceleration of the pulley,", "angular acceleration of the pulley (clockwise positive),")
    assert any(u.startswith("ask.alpha: its meaning states a sign convention") for u in signs.ungiven(
        load(write_problem(tmp_path, meaning))))
    solution = Solution(load(write_problem(tmp_path, text)))
    m1, m2, M, g = (sp.Symbol(n, positive=True) for n in ("m1", "m2", "M", "g"))
    assert sp.simplify(solution.expression("a") + 2 * g * (m1 - m2) / (2 * m1 + 2 * m2 + M)) == 0
