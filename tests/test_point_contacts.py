"""A body touching a surface at one of its material points (`joints: {NAME: {touches: BODY.POINT,
on: SURFACE}}`), and walls (`surfaces: {NAME: {wall: {facing: right}}}`): a ladder stands on a
floor and leans on a wall.

Closed forms: the textbook suite (tests/test_textbook.py: Halliday ch. 12 and Sample Problem
12.02; Kleppner & Kolenkow ch. 7). Here: the ladder slipping with kinetic friction at its foot,
against Newton's laws written out by hand for it, and every refusal the part adds."""
import pytest
import sympy as sp

from conftest import run_derive
from derive.solution.answers import Solution
from derive.language.problem import load

LADDER = """\
id: ladder
title: A ladder against a smooth wall
topic: statics
parameters:
  M: {meaning: mass of the ladder, unit: kg, range: [5, 20], sig_figs: 3}
  L: {meaning: length of the ladder, unit: m, range: [2, 5], sig_figs: 2}
  theta: {meaning: angle of the ladder above the floor, unit: rad, range: [0.9, 1.3], sig_figs: 2}
  PARAMETERS
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  surfaces:
    floor: {plane: {angle: 0}}
    wall: {wall: {facing: right}}
  bodies:
    ladder: {shape: rod, mass: M, length: L, at: [L*cos(theta)/2, L*sin(theta)/2], angle: pi - theta}
  joints:
    foot: {touches: ladder.start, on: floor, FOOT}
    head: {touches: ladder.end, on: wall}
  loads:
    - gravity: g
    LOADS
ask:
  N: {meaning: normal force of the floor, of: foot.normal, unit: N}
  P: {meaning: push of the wall, of: head.normal, unit: N}
  ASKS
question: |
  A ladder leans against a wall.
"""


def ladder(tmp_path, foot="grips: true", parameters="", loads="", asks="", **replace):
    text = LADDER.replace("FOOT", foot).replace("PARAMETERS", parameters).replace("LOADS", loads)
    text = text.replace("ASKS", asks)
    for old, new in replace.items():
        text = text.replace(old, new)
    path = tmp_path / "ladder.yaml"
    path.write_text(text)
    return path


def test_a_ladder_that_slips_moves_as_newtons_laws_written_by_hand_say(tmp_path):
    """Kinetic friction mu_k N at the foot, against the foot's slide away from the wall; smooth
    wall. Newton by hand, phi the angle above the floor, at rest: the center accelerates
    (-(L/2) sin(phi), (L/2) cos(phi)) phi''; M a = forces; (M L^2/12)(-phi'') = torques about the
    center."""
    path = ladder(tmp_path, foot="friction: {static: mu_s, kinetic: mu_k}",
                  parameters='mu_s: {meaning: static coefficient, unit: "1", range: [0.1, 0.3], sig_figs: 2}\n'
                             '  mu_k: {meaning: kinetic coefficient, unit: "1", range: [0.05, 0.1], sig_figs: 2}',
                  asks="alpha: {meaning: angular acceleration, of: ladder.angular_acceleration, unit: rad/s^2}")
    problem = load(str(path))
    solution = Solution(problem)
    s = {p.symbol.name: p.symbol for p in problem.parameters.values()}
    M, L, th, g, mu = s["M"], s["L"], s["theta"], s["g"], s["mu_k"]
    phidd, N, P = sp.symbols("phidd N P")
    ax, ay = -L / 2 * sp.sin(th) * phidd, L / 2 * sp.cos(th) * phidd
    torque = L / 2 * (N * sp.cos(th) - mu * N * sp.sin(th)) - L / 2 * sp.sin(th) * P
    hand = sp.solve([M * ax - (P - mu * N), M * ay - (N - M * g), -M * L**2 / 12 * phidd - torque], [phidd, N, P])
    expected = {"alpha": -hand[phidd], "N": hand[N], "P": hand[P]}
    # mu_s below cot(theta)/2 everywhere in these ranges: the ladder slips in every variant.
    values = {M: 10, L: 3, th: sp.Rational(11, 10), g: sp.Rational(981, 100), mu: sp.Rational(7, 100),
              s["mu_s"]: sp.Rational(1, 5)}
    assert solution.regime_at(values) == "slips"
    for name, ask in problem.asks.items():
        got = solution.expression(name).xreplace(values)
        assert abs(sp.N(got - expected[name].xreplace(values), 30)) < 1e-20, name
    # Held, it would need mu_s >= cot(theta)/2: at mu_s = 0.8 it stays, and nothing moves.
    held = {**values, s["mu_s"]: sp.Rational(4, 5)}
    assert solution.regime_at(held) == "stays"
    assert solution.expression("alpha").xreplace(held) == 0


def test_a_grip_that_cannot_hold_is_refused_without_mu_k(tmp_path):
    path = ladder(tmp_path, foot="friction: {static: mu_s}",
                  parameters='mu_s: {meaning: static coefficient, unit: "1", range: [0.2, 0.8], sig_figs: 2}')
    result = run_derive("solve", str(path), "--set", "mu_s=0.1", "--set", "theta=0.9")
    assert result.returncode == 2
    assert "the ladder slips: it needs mu_s >= 1/(2*Abs(tan(theta)))" in result.stderr
    assert run_derive("solve", str(path), "--set", "mu_s=0.6", "--set", "theta=0.9").returncode == 0


def test_a_wall_that_would_have_to_pull_is_refused(tmp_path):
    """A rope pulls the ladder's middle away from the wall: beyond (M g/2) cot(theta) the wall
    would have to pull (N < 0); that variant is refused, one that keeps the push is answered."""
    path = ladder(tmp_path, parameters="F: {meaning: pull away from the wall, unit: N, range: [1, 200], sig_figs: 3}",
                  loads="- force: {on: ladder, magnitude: F, angle: 0, name: pull}")
    answers = run_derive("solve", str(path), "--set", "F=1", "--set", "M=10", "--set", "theta=1", "--format", "json")
    assert answers.returncode == 0, answers.stderr
    refused = run_derive("solve", str(path), "--set", "F=200", "--set", "M=10", "--set", "theta=1")
    assert refused.returncode == 2
    assert "the ladder leaves the surface wall at head" in refused.stderr


@pytest.mark.parametrize("change, field, reason", [
    ({"ladder.start, on: floor": "ladder.end, on: floor"}, "scene.joints.foot.touches",
     "the ladder does not touch floor there"),
    ({"on: floor,": "on: roof,"}, "scene.joints.foot.on", "no surface 'roof'"),
    ({"touches: ladder.start": "touches: [1, 0]"}, "scene.joints.foot.touches", "expected a point of a body"),
    ({"touches: ladder.start": "touches: {ladder: [2*L, 0]}"}, "scene.joints.foot.touches", "outside the rod"),
    ({"facing: right": "facing: up"}, "scene.surfaces.wall.wall.facing", "left or right"),
    ({"grips: true": "grips: yes please"}, "scene.joints.foot.grips", "expected true or false"),
    ({"grips: true": "grips: true, friction: {kinetic: 0.2}"}, "scene.joints.foot.grips", "give friction.static"),
    ({"grips: true": "grips: true, friction: {static: 0.5}"}, "scene.joints.foot.grips", "leave grips out"),
    ({"head: {touches": "orbit: {touches", "of: head.normal": "of: orbit.normal"}, "scene", "reserved"),
])
def test_a_touching_point_that_does_not_fit_is_refused_naming_the_field(tmp_path, change, field, reason):
    result = run_derive("solve", str(ladder(tmp_path, **change)))
    assert result.returncode == 2, result.stdout
    line = result.stderr.strip()
    assert line.count("\n") == 0 and f"ladder.yaml: {field}: " in line and reason in line, line


def test_a_force_and_a_pin_take_any_point_of_a_body(tmp_path):
    """`{BODY: [x, y]}` is a point wherever a part takes one (a force's `on`, a pin's `to`): a
    weight hung at a third of the ladder's length from its foot shifts the wall's push by
    (m g/3) cot(theta), by the torques about the foot."""
    path = ladder(tmp_path, parameters="m: {meaning: mass of a load on the ladder, unit: kg, range: [1, 5], sig_figs: 3}",
                  loads="- force: {on: {ladder: [-L/6, 0]}, magnitude: m*g, angle: -pi/2, name: load}")
    problem = load(str(path))
    s = {p.symbol.name: p.symbol for p in problem.parameters.values()}
    push = Solution(problem).expression("P")
    expected = (s["M"] / 2 + s["m"] / 3) * s["g"] / sp.tan(s["theta"])
    assert sp.simplify(push - expected) == 0



@pytest.mark.parametrize("change, status, reason", [
    # both ends grip: only the sum of the two frictions is fixed (statically indeterminate)
    ({"head: {touches: ladder.end, on: wall}": "head: {touches: ladder.end, on: wall, grips: true}"}, 2,
     "scene: the constraints do not determine every force"),
    # a smooth floor: nothing pushes the ladder against the rough wall, whose friction cannot hold it
    ({"FOOT": "", "head: {touches: ladder.end, on: wall}":
      "head: {touches: ladder.end, on: wall, friction: {static: 0.5}}"}, 2, "presses on wall with no force at head"),
    ({"FOOT": "", "head: {touches: ladder.end, on: wall}": "head: {touches: ladder.end, on: wall, grips: true}"},
     2, "presses on wall with no force at head"),
    ({"FOOT": "", "head: {touches: ladder.end, on: wall}":
      "head: {touches: ladder.end, on: wall, friction: {kinetic: 0.3}}"}, 1, "derive cannot yet decide whether"),
    # a wall facing away from the ladder would have to pull it, whatever the parameters
    ({"facing: right": "facing: left"}, 2, "leaves the surface wall at head (its normal force would be negative), "
                                           "at every sample of the parameter ranges"),
])
def test_a_ladder_that_cannot_stand_as_stated_is_refused_with_a_reason(tmp_path, change, status, reason):
    change = dict(change)
    foot = change.pop("FOOT", "grips: true")
    result = run_derive("solve", str(ladder(tmp_path, foot=foot, **change)))
    assert result.returncode == status, result.stdout + result.stderr
    line = result.stderr.strip()
    assert line.count("\n") == 0 and reason in line, line
