"""Normal modes of scenes with several degrees of freedom (derive.mechanics.normal_modes): the
matrices, the zero mode, the asks, the simulation, and the refusals. The frequencies themselves
are checked against the books in tests/test_textbook.py (cart_pendulum, double_pendulum,
two_blocks_three_springs, coupled_pendulums, cart_track_bead_oscillation)."""
import json
import math
from pathlib import Path

import pytest
import sympy as sp

from conftest import run_derive, textbook
from derive.checks import simulate
from derive.solution.answers import Solution
from derive.core.errors import EngineLimit, ProblemError
from derive.language.problem import load



def variant(tmp_path, stem: str, old: str, new: str) -> Path:
    """A textbook file with one line changed, written to tmp_path."""
    text = (textbook(stem)).read_text()
    assert old in text
    path = tmp_path / f"{stem}.yaml"
    path.write_text(text.replace(old, new))
    return path


def test_the_new_users_cart_pendulum_is_answered():
    """The trial file that was refused ("small oscillations need one degree of freedom; the scene
    has 2"): omega^2 = g (M + m)/(M l) (Morin ch. 6; Taylor Problem 7.29) at M = 2, m = 1, l = 0.5."""
    result = run_derive("solve", str(textbook("cart_pendulum")), "--set", "M=2", "--set", "m=1",
                        "--set", "l=0.5", "--format", "json", "--digits", "12")
    assert result.returncode == 0, result.stderr
    report = json.loads(result.stdout)
    assert math.isclose(float(report["answers"]["omega"]["value"]), math.sqrt(9.81 * 3 / (2 * 0.5)), rel_tol=1e-11)
    assert report["checks"]["lagrange_vs_newton_euler"]["passed"]


def test_matrices_and_the_zero_mode_of_the_cart_pendulum():
    """In the free coordinates (x_cart, x_bob): M = diag(M, m), K = (m g/l) [[1, -1], [-1, 1]] by
    both routes; the cart and bob moving together is the zero mode (momentum conserved)."""
    problem = load(textbook("cart_pendulum"))
    M, m, l, g = (problem.parameters[n].symbol for n in ("M", "m", "l", "g"))
    solution = Solution(problem)
    for route, modes in solution.normal_modes.items():
        assert [str(c.q) for c in modes.coordinates] == ["x_cart", "x_bob"], route
        assert modes.mass == sp.diag(M, m)
        assert sp.simplify(modes.stiffness - m * g / l * sp.Matrix([[1, -1], [-1, 1]])) == sp.zeros(2, 2)
        assert [list(v) for v in modes.zero_modes] == [[1, 1]]
        assert len(modes.squares) == 1
    (zero,) = [s for s in solution.steps()["lagrange"] if s.text.startswith("A zero mode")]
    assert "its momentum is conserved" in zero.text
    assert [sp.sstr(e) for e in zero.equations] == ["Eq(x_bob, x_cart)"]  # they move together


def test_every_mode_against_a_simulation():
    """Started along each mode's shape (found numerically from K and M by scipy), the integrated
    motion repeats at the derived period, to 1e-6."""
    for stem in ("double_pendulum", "coupled_pendulums", "cart_pendulum"):
        report = simulate.check(Solution(load(textbook(stem))))
        assert report.passed, (stem, report.notes)
        assert report.compared, stem


def test_the_modes_are_numbered_from_the_lowest():
    problem = load(textbook("two_blocks_three_springs"))
    solution = Solution(problem)
    low, high = (solution.expression(n) for n in ("w1", "w2"))
    assert sp.simplify(high**2 / low**2) == 3


def test_omega_alone_is_refused_where_several_modes_oscillate(tmp_path):
    path = variant(tmp_path, "double_pendulum", "small_oscillation.modes.2.omega", "small_oscillation.omega")
    with pytest.raises(ProblemError, match=r"ask\.w2\.of: the scene has 2 normal modes of oscillation: ask "
                                           r"small_oscillation\.modes\.1\.omega, small_oscillation\.modes\.2\.omega"):
        Solution(load(path)).expression("w2")


def test_a_mode_beyond_the_scenes_is_refused(tmp_path):
    path = variant(tmp_path, "double_pendulum", "small_oscillation.modes.2.omega", "small_oscillation.modes.3.omega")
    with pytest.raises(ProblemError, match=r"ask\.w2\.of: the scene has 2 normal modes of oscillation, not 3"):
        Solution(load(path)).expression("w2")


def test_modes_of_one_degree_of_freedom_are_refused(tmp_path):
    path = variant(tmp_path, "simple_pendulum_cord", "small_oscillation.period", "small_oscillation.modes.1.period")
    with pytest.raises(ProblemError, match=r"ask\.T\.of: the scene has one degree of freedom, one mode: ask "
                                           r"small_oscillation\.period"):
        Solution(load(path)).expression("T")


@pytest.mark.parametrize("path", ["small_oscillation.modes.0.omega", "small_oscillation.modes.x.omega",
                                  "small_oscillation.modes.1.shape", "small_oscillation.modes.².omega"])
def test_a_malformed_mode_is_refused_when_read(tmp_path, path):
    with pytest.raises(ProblemError, match=r"ask\.w1\.of: .*modes\.N\.omega and modes\.N\.period"):
        load(variant(tmp_path, "double_pendulum", "small_oscillation.modes.1.omega", path))


def test_a_growth_rate_of_several_modes_is_an_engine_limit(tmp_path):
    path = variant(tmp_path, "double_pendulum", "of: small_oscillation.modes.1.period, unit: s",
                   "of: small_oscillation.growth_rate, unit: 1/s")
    with pytest.raises(EngineLimit, match="derive cannot yet find the growth rate about an equilibrium with several"):
        Solution(load(path)).expression("T1")


INVERTED = """\
id: inverted_double
title: Two rods standing on end, pinned
topic: oscillations
parameters:
  m: {meaning: mass of each rod, unit: kg, range: [0.1, 2], sig_figs: 3}
  L: {meaning: length of each rod, unit: m, range: [0.2, 1.5], sig_figs: 2}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  bodies:
    lower: {shape: rod, mass: m, length: L, at: [0, L/2], angle: pi/2}
    upper: {shape: rod, mass: m, length: L, at: [0, 3*L/2], angle: pi/2}
  joints:
    base: {pin: lower.start}
    knee: {pin: upper.start, to: lower.end}
  loads:
    - gravity: g
ask:
  w: {meaning: angular frequency, of: small_oscillation.modes.1.omega, unit: rad/s}
question: |
  Two rods stand on end.
"""


def test_an_unstable_equilibrium_is_refused(tmp_path):
    """Two rods balanced on end (an inverted double pendulum): both modes have omega^2 < 0."""
    (tmp_path / "inverted.yaml").write_text(INVERTED)
    result = run_derive("solve", str(tmp_path / "inverted.yaml"))
    assert result.returncode == 2 and len(result.stderr.strip().splitlines()) == 1, result.stderr
    assert "ask: the equilibrium is not stable: a normal mode has omega^2 = -" in result.stderr


FREE_PAIR = """\
id: free_pair
title: Two pucks joined by a spring on ice
topic: oscillations
parameters:
  m: {meaning: mass of each puck, unit: kg, range: [0.1, 2], sig_figs: 3}
  k: {meaning: spring constant, unit: N/m, range: [10, 100], sig_figs: 2}
  d: {meaning: rest length, unit: m, range: [0.1, 0.5], sig_figs: 2}
scene:
  bodies:
    a: {shape: point, mass: m, at: [0, 0]}
    b: {shape: point, mass: m, at: [d, 0]}
  loads:
    - spring: {between: [a, b], stiffness: k}
ask:
  w: {meaning: angular frequency, of: small_oscillation.omega, unit: rad/s}
question: |
  Two pucks on ice are joined by a spring.
"""


def test_a_zero_mode_that_is_not_a_free_motion_is_an_engine_limit(tmp_path):
    """Two pucks on ice: pushing one sideways stretches the spring only at second order, so that
    direction has no restoring force to first order, yet it is no free translation: its motion
    is decided by higher orders, which derive does not yet take."""
    (tmp_path / "pair.yaml").write_text(FREE_PAIR)
    result = run_derive("solve", str(tmp_path / "pair.yaml"))
    assert result.returncode == 1 and len(result.stderr.strip().splitlines()) == 1, result.stderr
    assert "derive cannot yet find normal modes about a direction with no restoring force that is not a free " \
           "motion" in result.stderr


def test_damped_normal_modes_are_an_engine_limit(tmp_path):
    path = variant(tmp_path, "two_blocks_three_springs", "    - spring: {between: [first, second], stiffness: k}\n",
                   "    - spring: {between: [first, second], stiffness: k}\n"
                   "    - damper: {between: [first, second], coefficient: b}\n")
    path.write_text(path.read_text().replace("  g: {", "  b: {meaning: damping, unit: N*s/m, range: [0.1, 1], sig_figs: 2}\n  g: {"))
    with pytest.raises(EngineLimit, match="derive cannot yet find damped normal modes of several degrees of freedom"):
        Solution(load(path)).expression("w1")


TWO_PENDULUMS = """\
id: two_pendulums
title: Two pendulums side by side
topic: oscillations
parameters:
  m: {meaning: mass of each bob, unit: kg, range: [0.1, 2], sig_figs: 3}
  a: {meaning: length of the left pendulum, unit: m, range: [0.2, 1], sig_figs: 2}
  b: {meaning: length of the right pendulum, unit: m, range: [0.5, 1.5], sig_figs: 2}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  points:
    left_hook: [0, 0]
    right_hook: [a + b, 0]
  bodies:
    left: {shape: point, mass: m, at: [0, -a]}
    right: {shape: point, mass: m, at: [a + b, -b]}
  cords:
    left_string: [left_hook, left]
    right_string: [right_hook, right]
  loads:
    - gravity: g
ask:
  w1: {meaning: the lower angular frequency, of: small_oscillation.modes.1.omega, unit: rad/s}
question: |
  Two pendulums hang side by side.
"""


def test_a_variant_where_the_modes_change_order_is_refused(tmp_path):
    """Uncoupled pendulums of lengths a and b: the slow mode is the longer one's, g/b at the middle
    of the ranges (a = 0.6, b = 1); where a > b it is g/a, and the answer g/b would be the fast
    mode: those variants are refused, the others answered."""
    (tmp_path / "two.yaml").write_text(TWO_PENDULUMS)
    problem = load(tmp_path / "two.yaml")
    a, b, g = (problem.parameters[n].symbol for n in ("a", "b", "g"))
    solution = Solution(problem)
    assert sp.simplify(solution.expression("w1") - sp.sqrt(g / b)) == 0
    assert solution.violated({a: sp.Rational(1, 2), b: 1, g: sp.Rational(981, 100)}) is None
    assert "the normal modes change order" in solution.violated({a: 1, b: sp.Rational(1, 2), g: sp.Rational(981, 100)})


def test_a_ratio_to_a_coordinate_that_does_not_move_is_refused(tmp_path):
    """The bobs do not rise to first order: a ratio over the upper bob's y has no value."""
    path = variant(tmp_path, "double_pendulum", "modes.1.ratio.lower.x.to.upper.x", "modes.1.ratio.lower.x.to.upper.y")
    with pytest.raises(ProblemError, match=r"ask\.r1\.of: the upper's y does not move in mode 1"):
        Solution(load(path)).expression("r1")


def test_a_ratio_of_a_body_the_scene_lacks_is_refused_when_read(tmp_path):
    path = variant(tmp_path, "double_pendulum", "modes.1.ratio.lower.x.to.upper.x", "modes.1.ratio.lowr.x.to.upper.x")
    with pytest.raises(ProblemError, match=r"ask\.r1\.of: lowr\.x is not a coordinate of the scene in a mode's "
                                           r"ratio; did you mean 'lower'"):
        load(path)
    path = variant(tmp_path, "double_pendulum", "modes.1.ratio.lower.x.to.upper.x", "modes.1.ratio.lower.angle.to.upper.x")
    with pytest.raises(ProblemError, match=r"lower\.angle is not a coordinate of the scene"):
        load(path)
