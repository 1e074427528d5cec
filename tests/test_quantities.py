"""The quantities of derive.quantities, asked of setups from textbooks (tests/asks/*.yaml) and
checked against the closed forms the books print; and the inverse asks (`find:` with `equals:`).

Each file cites its source. The closed forms live here, one dict per file, in the file's parameter
symbols, as the magnitude the key gives (with its direction in words: `DIRECTIONS`).
"""
from pathlib import Path
from types import SimpleNamespace

import pytest
import sympy as sp

from conftest import run_derive
from derive import quantities
from derive.language.problem import load
from derive.numbers import numeric
from derive.publishing import report
from derive.solution.answers import Solution

ASKS = Path(__file__).parent / "asks"
FILES = sorted(ASKS.glob("*.yaml"))

#: file stem -> {ask: closed form of the parameter symbols (a namespace)}, the magnitude the key gives.
EXPECTED = {
    # Serway & Jewett ch. 10: a rod pinned at one end, released horizontal: tau = M g L/2 about the hinge,
    # alpha = 3g/(2L), so I_cm alpha = M g L/8 about the center, where only the hinge's force has a moment.
    "rod_hinge_torques": {
        "tau": lambda s: s.M * s.g * s.L / 2, "net": lambda s: s.M * s.g * s.L / 2,
        "netc": lambda s: s.M * s.g * s.L / 8, "Rt": lambda s: s.M * s.g * s.L / 8,
    },
    # Serway & Jewett ch. 10: a solid ball rolls up an incline at v0 a distance 7 v0^2/(10 g sin(theta)),
    # turning once per 2 pi R of it.
    "ball_rolls_up_incline": {
        "d": lambda s: 7 * s.v0**2 / (10 * s.g * sp.sin(s.theta)),
        "n": lambda s: 7 * s.v0**2 / (10 * s.g * sp.sin(s.theta)) / s.R,  # in rad, SI; the key gives rev
    },
    # Serway & Jewett ch. 10: from rest under a constant torque, omega^2 = 2 (tau/I) phi, so the angle
    # that reaches w1 is I w1^2/(2 tau), with I = M R^2/2 for a disk.
    "flywheel_turns_to_speed": {"n": lambda s: s.M * s.R**2 * s.w1**2 / (4 * s.tau)},
    # Serway & Jewett ch. 9, example 9.11: the center of mass of three particles.
    "three_masses_center": {
        "x": lambda s: s.m2 * s.a / (s.m1 + s.m2 + s.m3), "y": lambda s: s.m3 * s.b / (s.m1 + s.m2 + s.m3),
    },
}
#: The direction in words each directed answer is given with, in every variant.
DIRECTIONS = {("rod_hinge_torques", "tau"): "clockwise", ("rod_hinge_torques", "netc"): "clockwise",
              ("ball_rolls_up_incline", "n"): "counter-clockwise"}


def test_every_file_has_its_closed_forms():
    assert {f.stem for f in FILES} == set(EXPECTED)


@pytest.mark.parametrize("path", FILES, ids=[f.stem for f in FILES])
def test_a_textbook_ask_of_a_quantity_gives_the_books_closed_form(path):
    problem = load(str(path))
    assert problem.source
    solution = Solution(problem)
    symbols = SimpleNamespace(**{name: p.symbol for name, p in problem.parameters.items()})
    assert set(EXPECTED[path.stem]) == set(problem.asks)
    for name, closed_form in EXPECTED[path.stem].items():
        assert sp.simplify(solution.expression(name) - closed_form(symbols)) == 0, (name, solution.expression(name))
    result = report.solve(problem, solution=solution)
    assert result["checks"] and all(c["passed"] for c in result["checks"].values())
    # every quantity of derive.quantities is checked by a second route: its own, or the motion simulated
    for name, ask in problem.asks.items():
        kind = quantities.KINDS.get(ask.quantity.kind)
        if kind is not None:
            assert kind.kind in result["checks"] or "states" in result["checks"], name
    for (stem, name), words in DIRECTIONS.items():
        if stem == path.stem:
            assert result["answers"][name]["direction"] == words


def test_turns_are_given_in_rev_and_their_formula_too():
    problem = load(str(ASKS / "ball_rolls_up_incline.yaml"))
    result = report.solve(problem, {"M": "1", "R": "0.1", "theta": "0.5", "v0": "2"})
    # n = 7 v0^2/(10 g sin(theta)) / (2 pi R) turns
    expected = 7 * 4 / (10 * 9.81 * float(sp.sin(sp.Rational(1, 2)))) / (2 * float(sp.pi) * 0.1)
    assert abs(float(result["answers"]["n"]["value"]) - expected) < 1e-2 * expected
    text = run_derive("solve", str(ASKS / "ball_rolls_up_incline.yaml")).stdout
    assert "20⋅π⋅R⋅g⋅sin(θ)" in text  # the formula printed in turns, not radians


def test_the_torque_check_catches_a_wrong_lever_arm(monkeypatch):
    """Route 0 planted wrong (the weight's point moved): the check by Lagrange's route fails."""
    from derive.quantities import torque
    from derive.solution.crosschecks import CheckFailure

    problem = load(str(ASKS / "rod_hinge_torques.yaml"))
    real = torque.Torque.value

    def planted(self, solution, ask, route):
        value = real(self, solution, ask, route)
        return value * 2 if route == 0 and ask.quantity.detail is None else value

    monkeypatch.setattr(torque.Torque, "value", planted)
    with pytest.raises(CheckFailure, match="net"):
        Solution(problem).checks()


REFUSED = [
    ({"of": "rod.weight.torque", "unit": "N*m"}, "about", "a torque is taken about a point"),
    ({"of": "rod.angular_acceleration", "about": "hinge", "unit": "rad/s^2"}, "about", "only a torque"),
    ({"of": "rod.spring.torque", "about": "hinge", "unit": "N*m"}, "of", "bears no load 'spring'"),
    ({"of": "rod.weight.torque", "about": "rod.middle", "unit": "N*m"}, "about", "has no point 'middle'"),
    ({"of": "rod.weight.torque", "about": "hinge", "unit": "N"}, "unit", "a torque is in N*m"),
    ({"of": "rod.weight.torque", "about": "hinge", "unit": "N*m", "find": "M"}, "equals", "needs the value"),
    ({"of": "rod.weight.torque", "about": "hinge", "unit": "kg", "find": "M", "equals": "2 N*m"}, "equals",
     "points one way or the other"),
    ({"of": "rod.weight.torque", "about": "hinge", "unit": "kg", "zero_for": "M", "equals": "2 N*m"}, "equals",
     "give find:"),
    ({"of": "center_of_mass.position.z", "unit": "m"}, "of", "position.x and position.y"),
]


@pytest.mark.parametrize("ask, field, message", REFUSED, ids=[r[2] for r in REFUSED])
def test_an_ask_that_cannot_mean_anything_is_refused_naming_its_field(tmp_path, ask, field, message):
    text = (ASKS / "rod_hinge_torques.yaml").read_text()
    head = text.split("ask:")[0]
    path = tmp_path / "p.yaml"
    body = ", ".join(f"{k}: {v}" for k, v in ask.items())
    path.write_text(head + f"ask:\n  q: {{meaning: a quantity, {body}}}\nquestion: |\n  Find it.\n")
    result = run_derive("solve", str(path))
    assert result.returncode == 2, result.stdout + result.stderr
    assert f"ask.q.{field}" in result.stderr and message in result.stderr, result.stderr


def test_turns_of_a_point_mass_and_in_radians_are_refused(tmp_path):
    text = (ASKS / "ball_rolls_up_incline.yaml").read_text()
    for old, new, field, message in (("unit: rev}", "unit: rad}", "ask.n.unit", "asked in rev"),
                                     ("in: highest, unit: rev", "unit: rev", "ask.n.in", "give in: STATE")):
        path = tmp_path / "p.yaml"
        path.write_text(text.replace(old, new))
        result = run_derive("solve", str(path))
        assert result.returncode == 2 and field in result.stderr and message in result.stderr, result.stderr


def test_an_inverse_ask_solves_for_the_parameter_and_refuses_more_than_one_root(tmp_path):
    """The rod's weight about the hinge with the rod at theta from the horizontal: M g L cos(theta)/2,
    clockwise. Asked where it is M g L/4 (counted clockwise), theta = pi/3 in [0.1, 1.5]; over
    [0.1, 6] there is a second root, 5 pi/3, and the ask is refused."""
    text = (ASKS / "rod_hinge_torques.yaml").read_text().split("ask:")[0]
    text = text.replace("angle: 0}", "angle: -theta}").replace(
        "  g: {meaning", "  theta: {meaning: angle below the horizontal, unit: rad, range: [0.1, 1.5], sig_figs: 2}\n"
                         "  g: {meaning")
    ask = ("ask:\n  th: {meaning: angle where the torque is half its greatest, of: rod.weight.torque, about: hinge,"
           " find: theta, equals: M*g*L/4, sign: clockwise positive, unit: rad}\n"
           "question: |\n  At what angle is the torque of its weight (clockwise positive) half its greatest?\n")
    path = tmp_path / "p.yaml"
    path.write_text(text + ask)
    solution = Solution(load(str(path)))
    assert solution.expression("th") == sp.pi / 3
    path.write_text(text.replace("[0.1, 1.5]", "[0.1, 6]") + ask)
    result = run_derive("solve", str(path))
    assert result.returncode == 2 and "ask.th.find" in result.stderr and "not one" in result.stderr, result.stderr


def test_an_inverse_ask_checks_its_root_against_a_scan_of_the_range():
    """sympy solves tan(x) = 1 with one root, pi/4; over [0.1, 4] the scan of the sign finds 5 pi/4 too."""
    from derive.solution import inverse

    theta = sp.Symbol("theta", positive=True)
    parameter = SimpleNamespace(name="theta", symbol=theta, range=(0.1, 4), si_ends=(sp.Rational(1, 10), 4))
    problem = SimpleNamespace(parameters={"theta": parameter}, error=lambda field, text: ValueError(f"{field}: {text}"))
    with pytest.raises(ValueError, match="times in its range"):
        inverse._check(problem, "ask.x.find", sp.sin(theta) - sp.cos(theta), theta, sp.pi / 4, {}, parameter)
    inverse._check(problem, "ask.x.find", sp.sin(theta) - sp.cos(theta), theta, sp.pi / 4, {},
                   SimpleNamespace(name="theta", symbol=theta, range=(0.1, 3), si_ends=(sp.Rational(1, 10), 3)))
    assert numeric.evaluate(sp.pi / 4, {}, 5) == "0.78540"
