"""Issue 11's rules: friction regimes decided by the engine, physical signs checked over the
parameters, every key used or refused, engine limits reported as such, and small
oscillations about equilibria on curved surfaces. Closed forms are from the texts cited."""
import json
import math

import pytest
import sympy as sp

from conftest import run_derive, textbook
from derive.checks import simulate
from derive.solution.answers import Solution
from derive.language.problem import load

G = 9.81

SPHERE = """\
id: steep_sphere
title: A sphere on an incline
topic: rolling
parameters:
  M: {meaning: mass of the sphere, unit: kg, range: [0.2, 5], sig_figs: 2}
  R: {meaning: radius of the sphere, unit: m, range: [0.02, 0.2], sig_figs: 2}
  theta: {meaning: angle of the incline, unit: rad, range: [0.1, 1.2], sig_figs: 2}
  mu_s: {meaning: static friction coefficient, unit: "1", range: [0.2, 0.4], sig_figs: 2}
  mu_k: {meaning: kinetic friction coefficient, unit: "1", range: [0.1, 0.2], sig_figs: 2}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  surfaces:
    ramp: {incline: {angle: theta}}
  bodies:
    ball: {shape: sphere, mass: M, radius: R, on: ramp, contact: rolling, FRICTION}
  loads:
    - gravity: g
ask:
  a: {meaning: acceleration down the incline, of: ball.acceleration.down_incline, unit: m/s^2}
  alpha: {meaning: angular acceleration, of: ball.angular_acceleration, unit: rad/s^2}
  f: {meaning: friction, of: ball.friction, unit: N}
question: |
  A sphere of mass {{ M }} on an incline at {{ theta }}.
"""


def write(tmp_path, text, name="problem.yaml"):
    path = tmp_path / name
    path.write_text(text)
    return path


def values(problem, **given):
    return {problem.parameters[k].symbol: sp.nsimplify(v) for k, v in given.items()} | problem.values()


def number(solution, name, at):
    return float(sp.N(solution.signed(name).xreplace(at), 20))


def test_a_sphere_rolls_or_slips_as_its_friction_allows(tmp_path):
    """Rolling: a = 5/7 g sin(theta) while mu_s >= 2/7 tan(theta); slipping: a = g (sin - mu_k
    cos), alpha = 5 mu_k g cos / (2 R) (Kleppner & Kolenkow, An Introduction to Mechanics, 2nd
    ed., ch. 7, a ball on an incline; the slipping case is Newton's second law with kinetic
    friction and the torque mu_k N R about the center)."""
    problem = load(write(tmp_path, SPHERE.replace("FRICTION", "friction: {static: mu_s, kinetic: mu_k}")))
    solution = Solution(problem)
    gentle = values(problem, M=1, R="0.1", theta="0.3", mu_s="0.3", mu_k="0.1")
    assert solution.regime_at(gentle) == "rolls"
    assert number(solution, "a", gentle) == pytest.approx(5 / 7 * G * math.sin(0.3), rel=1e-12)
    assert number(solution, "f", gentle) == pytest.approx(-2 / 7 * G * math.sin(0.3), rel=1e-12)
    steep = values(problem, M=1, R="0.1", theta="1.2", mu_s="0.2", mu_k="0.1")
    assert solution.regime_at(steep) == "slips"
    assert number(solution, "a", steep) == pytest.approx(G * (math.sin(1.2) - 0.1 * math.cos(1.2)), rel=1e-12)
    assert abs(number(solution, "alpha", steep)) == pytest.approx(5 * 0.1 * G * math.cos(1.2) / (2 * 0.1), rel=1e-12)
    assert abs(number(solution, "f", steep)) == pytest.approx(0.1 * G * math.cos(1.2), rel=1e-12)
    # The worked solution derives the slipping too, by both routes, after the grip that decides.
    steps = solution.steps()
    assert "which regime: rolls or slips" in steps
    assert {"lagrange, where the ball slips (friction along -t)",
            "newton-euler, where the ball slips (friction along -t)"} <= set(steps)
    # The boundary between the regimes is stated: mu_s = 2/7 tan(theta).
    boundary = values(problem, M=1, R="0.1", theta="1.0", mu_s=sp.Rational(2, 7) * sp.tan(1), mu_k="0.1")
    assert solution.regime_at(boundary) == "rolls"
    result = run_derive("solve", str(tmp_path / "problem.yaml"), "--set", "theta=1.2", "--set", "mu_s=0.2",
                        "--set", "mu_k=0.1", "--set", "M=1", "--set", "R=0.1")
    assert result.returncode == 0, result.stderr
    assert "rolls: where μₛ ≥" in result.stdout and "2⋅│tan(θ)│" in result.stdout  # mu_s >= 2 |tan(theta)|/7
    assert "at these parameters the body slips" in result.stdout
    assert ": where True" not in result.stdout and "otherwise" in result.stdout  # the last regime, the rest


def test_the_simulation_follows_the_regime_that_applies(tmp_path):
    problem = load(write(tmp_path, SPHERE.replace("FRICTION", "friction: {static: mu_s, kinetic: mu_k}")
                         .replace("range: [0.1, 1.2]", "range: [1.1, 1.2]")))
    report = simulate.check(Solution(problem))
    assert report.passed, report.notes
    assert "a" in report.compared


def test_without_mu_k_a_slipping_variant_is_refused(tmp_path):
    write(tmp_path, SPHERE.replace("FRICTION", "friction: {static: mu_s}").replace(
        "  mu_k: {meaning: kinetic friction coefficient, unit: \"1\", range: [0.1, 0.2], sig_figs: 2}\n", ""))
    result = run_derive("solve", str(tmp_path / "problem.yaml"), "--set", "theta=1.2", "--set", "mu_s=0.2",
                        "--set", "M=1", "--set", "R=0.1")
    assert result.returncode == 2
    assert "the ball slips: it needs mu_s >= 2*Abs(tan(theta))/7" in result.stderr


BLOCK = """\
id: block_kinetic
title: A block on an incline with friction
topic: dynamics
parameters:
  m: {meaning: mass, unit: kg, range: [1, 2], sig_figs: 2}
  theta: {meaning: angle of the incline, unit: rad, range: [0.1, 1.2], sig_figs: 2}
  mu_k: {meaning: kinetic friction coefficient, unit: "1", range: [0.1, 0.3], sig_figs: 2}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  surfaces:
    ramp: {incline: {angle: theta}}
  bodies:
    block: {shape: point, mass: m, on: ramp, contact: sliding, friction: {kinetic: mu_k}}
  loads:
    - gravity: g
ask:
  a: {meaning: acceleration down the incline, of: block.acceleration.down_incline, unit: m/s^2}
  f: {meaning: friction, of: block.friction, unit: N}
question: |
  A block of mass {{ m }} on an incline at {{ theta }}.
"""


def test_a_block_stays_or_slides_with_kinetic_friction(tmp_path):
    """a = g (sin(theta) - mu_k cos(theta)) once it slides; it stays while tan(theta) <= mu
    (Halliday, Resnick & Walker, Fundamentals of Physics, ch. 6, friction on an incline)."""
    problem = load(write(tmp_path, BLOCK))
    solution = Solution(problem)
    stays = values(problem, m=1, theta="0.05", mu_k="0.2")
    assert solution.regime_at(stays) == "stays" and number(solution, "a", stays) == 0
    assert number(solution, "f", stays) == pytest.approx(-G * math.sin(0.05), rel=1e-12)
    slides = values(problem, m=1, theta="0.9", mu_k="0.2")
    assert solution.regime_at(slides) == "slips"
    assert number(solution, "a", slides) == pytest.approx(G * (math.sin(0.9) - 0.2 * math.cos(0.9)), rel=1e-12)


SLACK = """\
id: slack_cord
title: A block on a cord, pushed up
topic: dynamics
parameters:
  m: {meaning: mass, unit: kg, range: [1, 2], sig_figs: 2}
  F: {meaning: upward push, unit: N, range: [1, 30], sig_figs: 2}
  L: {meaning: length of the cord, unit: m, value: 1}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  points:
    hook: [0, L]
  bodies:
    block: {shape: point, mass: m, at: [0, 0]}
  cords:
    rope: [hook, block]
  loads:
    - gravity: g
    - force: {on: block, magnitude: F, angle: pi/2}
ask:
  T: {meaning: tension, of: rope.tension, unit: N}
question: |
  A block of mass {{ m }} hangs from a cord of length {{ L }} and is pushed up by {{ F }}.
"""


def test_a_cord_that_would_push_is_refused(tmp_path):
    write(tmp_path, SLACK)
    taut = run_derive("solve", str(tmp_path / "problem.yaml"), "--set", "m=1", "--set", "F=5")
    assert taut.returncode == 0 and "= 4.8 N" in taut.stdout  # the 2 figures of m and F
    slack = run_derive("solve", str(tmp_path / "problem.yaml"), "--set", "m=1", "--set", "F=20")
    assert slack.returncode == 2
    assert slack.stderr.strip().endswith("parameters: the cord rope goes slack (its tension would be negative)")


@pytest.mark.parametrize("change, field", [
    (lambda t: t.replace("  g: {meaning: grav", "  H: {meaning: height, unit: m, value: 1}\n  g: {meaning: grav"),
     "parameters.H: no part of the scene"),
    (lambda t: t.split("ask:")[0] + "ask:\n  I: {meaning: inertia, of: ball.inertia, unit: kg*m^2}\n"
     "question: |\n  A sphere of mass {{ M }}, {{ R }}, {{ theta }}, {{ mu_s }}, {{ mu_k }}.\n",
     "scene.bodies.ball.friction: nothing asked depends on the motion"),
], ids=["parameter", "friction"])
def test_a_key_nothing_uses_is_refused(tmp_path, change, field):
    write(tmp_path, change(SPHERE.replace("FRICTION", "friction: {static: mu_s, kinetic: mu_k}")))
    result = run_derive("solve", str(tmp_path / "problem.yaml"))
    assert result.returncode == 2 and len(result.stderr.strip().splitlines()) == 1, result.stderr
    assert field in result.stderr


def test_the_old_events_list_is_refused_with_how_to_write_it_as_states(tmp_path):
    text = SPHERE.replace("FRICTION", "friction: {static: mu_s, kinetic: mu_k}")
    write(tmp_path, text.replace("ask:", "  events:\n    - stick: {body: ball, to: ball}\nask:"))
    result = run_derive("solve", str(tmp_path / "problem.yaml"))
    assert result.returncode == 2 and len(result.stderr.strip().splitlines()) == 1, result.stderr
    assert "problem.yaml" in result.stderr and "scene.events: write events as states:" in result.stderr
    assert "event: {stick: bullet, to: rod}" in result.stderr


def test_kinetic_friction_above_static_is_refused(tmp_path):
    write(tmp_path, SPHERE.replace("FRICTION", "friction: {static: mu_s, kinetic: mu_k}"))
    result = run_derive("solve", str(tmp_path / "problem.yaml"), "--set", "mu_s=0.2", "--set", "mu_k=0.3",
                        "--set", "theta=0.3", "--set", "M=1", "--set", "R=0.1")
    assert result.returncode == 2 and "mu_k > mu_s" in result.stderr


def test_an_engine_limit_is_exit_1_and_not_blamed_on_the_file(tmp_path):
    text = SPHERE.replace("FRICTION", "friction: {static: mu_s, kinetic: mu_k}").replace(
        "    ball: {", "    box: {shape: point, mass: M, on: ramp, contact: sliding, at: [4*R, -4*R*tan(theta)],"
                      " friction: {kinetic: mu_k}}\n    ball: {")
    write(tmp_path, text)
    result = run_derive("solve", str(tmp_path / "problem.yaml"))
    assert result.returncode == 1, result.stderr
    assert "derive cannot yet decide the friction regimes of two contacts at once" in result.stderr
    assert "internal error" not in result.stderr and len(result.stderr.strip().splitlines()) == 1


BOWL = """\
id: ball_in_bowl
title: A ball rolling in a bowl
topic: oscillations
parameters:
  m: {meaning: mass of the ball, unit: kg, range: [0.1, 1], sig_figs: 2}
  r: {meaning: radius of the ball, unit: m, range: [0.01, 0.05], sig_figs: 2}
  R: {meaning: radius of the bowl, unit: m, range: [0.3, 1], sig_figs: 2}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  surfaces:
    bowl: {circle: {radius: R, center: [0, R], side: SIDE}}
  bodies:
    ball: {shape: sphere, mass: m, radius: r, on: bowl, contact: rolling}
  loads:
    - gravity: g
ask:
  omega: {meaning: angular frequency, of: small_oscillation.omega, unit: rad/s}
question: |
  A ball of mass {{ m }} and radius {{ r }} rolls in a bowl of radius {{ R }}.
"""


def test_small_oscillations_on_a_curved_surface(tmp_path):
    """omega = sqrt(5 g / (7 (R - r))) for a solid ball rolling at the bottom of a bowl
    (Kleppner & Kolenkow, An Introduction to Mechanics, 2nd ed., ch. 7 problems; Taylor,
    Classical Mechanics, ch. 7). The simulation's period agrees."""
    problem = load(write(tmp_path, BOWL.replace("SIDE", "inside")))
    solution = Solution(problem)
    at = values(problem, m="0.5", r="0.02", R="0.5")
    assert number(solution, "omega", at) == pytest.approx(math.sqrt(5 * G / (7 * 0.48)), rel=1e-12)
    report = simulate.check(solution)
    assert report.passed and "omega" in report.compared, report.notes


def test_on_top_of_a_dome_it_is_unstable(tmp_path):
    """On top of a dome the same motion grows: growth rate sqrt(5 g / (7 (R + r)))."""
    text = BOWL.replace("SIDE", "outside").replace("center: [0, R]", "center: [0, -R]").replace(
        "of: small_oscillation.omega, unit: rad/s", "of: small_oscillation.growth_rate, unit: 1/s")
    problem = load(write(tmp_path, text))
    at = values(problem, m="0.5", r="0.02", R="0.5")
    assert number(Solution(problem), "omega", at) == pytest.approx(math.sqrt(5 * G / (7 * 0.52)), rel=1e-12)


ON_TABLE_AND_HANGING = """\
id: both
title: A block on a table hanging from a cord
topic: dynamics
parameters:
  m: {meaning: mass, unit: kg, range: [1, 2], sig_figs: 2}
  L: {meaning: length, unit: m, value: 1}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  points:
    hook: [0, L]
  surfaces:
    table: {plane: {angle: 0}}
  bodies:
    block: {shape: point, mass: m, on: table, contact: sliding}
  cords:
    rope: [hook, block]
  loads:
    - gravity: g
ask:
  a: {meaning: acceleration, of: block.acceleration.x, unit: m/s^2}
question: |
  A block of mass {{ m }} on a table hangs from a cord of length {{ L }}.
"""
PIN_OFF_THE_ROD = """\
id: both
title: A block on a table hanging from a cord
topic: dynamics
parameters:
  m: {meaning: mass, unit: kg, range: [1, 2], sig_figs: 2}
  L: {meaning: length, unit: m, value: 1}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  points:
    hook: [0, L]
  bodies:
    block: {shape: rod, mass: m, length: L, at: [0, 0]}
  cords:
    rope: [hook, block]
  joints:
    p: {pin: {block: [L, 0]}}
  loads:
    - gravity: g
ask:
  a: {meaning: acceleration, of: block.acceleration.x, unit: m/s^2}
question: |
  A block of mass {{ m }} on a table hangs from a cord of length {{ L }}.
"""


@pytest.mark.parametrize("text, message", [
    (ON_TABLE_AND_HANGING, "scene.cords.rope: the cord pulls the block straight along the normal of table"),
    (PIN_OFF_THE_ROD, "scene.joints.p.pin: the point lies L from the block's center, outside the rod"),
    (PIN_OFF_THE_ROD.replace("p: {pin: {block: [L, 0]}}", "p: {pin: {block: [L/2, 0]}, to: bob}").replace(
        "    block: {shape: rod", "    bob: {shape: point, mass: m, at: [L/2, -L]}\n    block: {shape: rod"),
     "scene.joints.p.to: the two points of the pin are apart in the reference configuration ([L/2, 0] and "
     "[L/2, -L]): place the bodies with at (a massless arm or string between two points is a cord: a cords: entry, "
     "`NAME: [POINT, POINT]`)"),
    (PIN_OFF_THE_ROD.replace("hook: [0, L]", "hook: [1, L]"), "scene.points.hook: a position must have the "
     "dimension of m, but 1 has no dimension: a bare number other than 0 has no unit (an expression takes none); "
     "write it with a parameter in m, or as a multiple of one"),
], ids=["on-a-table-and-hanging", "pin-off-the-body", "pin-apart", "bare-number"])
def test_geometry_that_does_not_fit_is_refused(tmp_path, text, message):
    write(tmp_path, text)
    result = run_derive("solve", str(tmp_path / "problem.yaml"))
    assert result.returncode == 2 and len(result.stderr.strip().splitlines()) == 1, result.stderr
    assert message in result.stderr


SPRING_AWAY_FROM_EQUILIBRIUM = """\
id: spring_incline
title: A block on a spring on an incline
topic: oscillations
parameters:
  m: {meaning: mass, unit: kg, range: [0.5, 2], sig_figs: 2}
  k: {meaning: spring constant, unit: N/m, range: [50, 200], sig_figs: 2}
  theta: {meaning: angle of the incline, unit: rad, range: [0.2, 0.8], sig_figs: 2}
  L: {meaning: distance from the wall, unit: m, value: 0.5}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  points:
    wall: [-L*cos(theta), L*sin(theta)]
  surfaces:
    ramp: {incline: {angle: theta}}
  bodies:
    block: {shape: point, mass: m, on: ramp, contact: sliding}
  loads:
    - gravity: g
    - spring: {between: [wall, block], stiffness: k}
ask:
  omega: {meaning: angular frequency, of: small_oscillation.omega, unit: rad/s}
question: |
  A block of mass {{ m }} on an incline at {{ theta }} hangs on a spring of constant {{ k }} from a point {{ L }} up the incline.
"""


def test_an_oscillation_away_from_the_equilibrium_is_an_engine_limit(tmp_path):
    """The spring is unstretched where the block is placed: the equilibrium lies elsewhere, and
    derive says it cannot yet find it (exit 1), rather than blaming the file or answering."""
    write(tmp_path, SPRING_AWAY_FROM_EQUILIBRIUM)
    result = run_derive("solve", str(tmp_path / "problem.yaml"))
    assert result.returncode == 1 and len(result.stderr.strip().splitlines()) == 1, result.stderr
    assert "derive cannot yet find the equilibrium of a scene placed away from it" in result.stderr


DAMPED = """\
id: damped_block
title: A block on a spring with a dashpot
topic: torque
parameters:
  m: {meaning: mass of the block, unit: kg, range: [1, 2], sig_figs: 3}
  k: {meaning: spring constant, unit: N/m, range: [50, 100], sig_figs: 3}
  b: {meaning: damping coefficient, unit: N*s/m, range: [RANGE], sig_figs: 3}
  L: {meaning: length of the spring, unit: m, value: 0.5}
scene:
  surfaces:
    floor: {plane: {angle: 0}}
  points:
    wall: [0, 0]
  bodies:
    block: {shape: point, mass: m, at: [L, 0], on: floor, contact: sliding}
  loads:
    - spring: {between: [wall, block], stiffness: k}
    - damper: {between: [wall, block], coefficient: b}
ask:
  omega: {meaning: angular frequency of the damped oscillations, of: small_oscillation.omega, unit: rad/s}
question: |
  A block of mass {{ m }} on a smooth floor, held by a spring and a dashpot.
"""


def test_a_damper_slows_the_small_oscillation(tmp_path):
    """omega' = sqrt(k/m - b^2/(4 m^2)) (Halliday, Resnick & Walker, Fundamentals of Physics,
    10th ed., §15.6, damped simple harmonic motion). It was sqrt(k/m), the damper left out:
    the linearization was taken at rest, where a dashpot exerts no force."""
    problem = load(write(tmp_path, DAMPED.replace("RANGE", "2, 10")))
    m, k, b = (problem.parameters[n].symbol for n in ("m", "k", "b"))
    omega = Solution(problem).signed("omega")
    assert sp.simplify(omega**2 - (k / m - b**2 / (4 * m**2))) == 0
    result = run_derive("check", str(problem.path))  # against the period of a simulated motion
    assert result.returncode == 0 and "ok: omega" in result.stdout, result.stdout + result.stderr


def test_an_overdamped_variant_is_refused(tmp_path):
    """With b up to 40 N s/m, k/m - b^2/(4 m^2) < 0 for some variants: it does not oscillate."""
    path = write(tmp_path, DAMPED.replace("RANGE", "2, 40"))
    result = run_derive("solve", str(path), "--set", "b=30", "--set", "m=1", "--set", "k=50")
    assert result.returncode == 2 and "overdamped" in result.stderr, result.stdout + result.stderr
    assert run_derive("solve", str(path), "--set", "b=5").returncode == 0


def test_a_pull_that_lifts_a_body_off_its_surface_is_refused():
    """Pulled straight up with more than its weight, the yo-yo leaves the floor: N = M g - F < 0."""
    path = str(textbook("yoyo_pulled_up_rolls_left"))
    result = run_derive("solve", path, "--set", "F=10", "--set", "M=0.3")
    assert result.returncode == 2 and "normal" in result.stderr, result.stdout + result.stderr
    assert run_derive("solve", path, "--set", "F=1", "--set", "M=0.3").returncode == 0


def test_a_velocity_of_a_body_that_does_not_roll_is_refused_with_the_states_form(tmp_path):
    write(tmp_path, SPHERE.replace("contact: rolling, FRICTION", "contact: sliding, velocity: [sqrt(g*R), 0]"))
    result = run_derive("solve", str(tmp_path / "problem.yaml"))
    assert result.returncode == 2 and len(result.stderr.strip().splitlines()) == 1, result.stderr
    assert "scene.bodies.ball.velocity: a velocity is the speed of a body rolling without slipping" in result.stderr
    assert "states: {moving: {rates: {ball.velocity.x: v}}}" in result.stderr


def test_a_run_derived_as_placed_is_refused_where_a_variant_turns_it_over():
    """A block hanging at depth d below a pulley of radius r has a run d - r long, not |d - r|: the
    derivation takes the sign the file's placement gives it (so the answer reads the book's
    a = m g/(M + m), Halliday ch. 5), and values that turn the run over are refused, not answered
    by the same formula."""
    path = str(textbook("table_block_smooth_pulley"))
    placed = run_derive("solve", path, "--set", "M=3", "--set", "m=1", "--set", "r=0.03", "--set", "d=0.5",
                        "--format", "json")
    assert placed.returncode == 0, placed.stderr
    assert json.loads(placed.stdout)["answers"]["a"]["expr"] == "g*m/(M + m)"
    over = run_derive("solve", path, "--set", "M=3", "--set", "m=1", "--set", "r=0.03", "--set", "d=0.01")
    assert over.returncode == 2
    assert "not placed as at the middle of the ranges, where d - r > 0" in over.stderr


#: The new-user trial's file: the block sits between a spring (at its rest length) and a cord wound
#: on a pulley, so at the equilibrium the cord holds nothing and would have to push for half of
#: every swing; derive once answered omega = sqrt(2k/(M + 2m)) with every check passing.
SLACK_AT_EQUILIBRIUM = """\
id: spring_block_massive_pulley
title: A block on a spring tied to a cord wound on a massive pulley
topic: oscillations
parameters:
  m: {meaning: mass of the block, unit: kg, range: [0.2, 2], sig_figs: 3}
  M: {meaning: mass of the pulley, unit: kg, range: [0.2, 2], sig_figs: 3}
  R: {meaning: radius of the pulley, unit: m, range: [0.05, 0.2], sig_figs: 3}
  k: {meaning: spring constant, unit: N/m, range: [10, 200], sig_figs: 3}
  d: {meaning: distance from the block to the wall and to the pulley, unit: m, value: 0.5}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  points:
    wall: [-d, 0]
  surfaces:
    table: {incline: {angle: 0, through: [0, 0]}}
  bodies:
    block: {shape: point, mass: m, at: [0, 0], on: table, contact: sliding}
    pulley: {shape: disk, mass: M, radius: R, at: [d, -R], joint: fixed_axle}
  cords:
    cord: [block, {wound: pulley, side: top}]
  loads:
    - gravity: g
    - spring: {between: [wall, block], stiffness: k}
ask:
  omega: {meaning: angular frequency of small oscillations, of: small_oscillation.omega, unit: rad/s}
question: |
  A block of mass {{ m }} between a spring of constant {{ k }} and a cord wound on a pulley ({{ M }}, {{ R }}).
"""


def test_a_cord_slack_at_the_equilibrium_is_refused_for_small_oscillations(tmp_path):
    result = run_derive("solve", str(write(tmp_path, SLACK_AT_EQUILIBRIUM)))
    assert result.returncode == 2 and len(result.stderr.strip().splitlines()) == 1, result.stderr
    assert "problem.yaml: ask.omega.of: the cord cord is slack at the equilibrium: its tension is 0 there" \
        in result.stderr


def test_a_cord_slack_at_the_equilibrium_for_some_parameters_is_refused_for_those(tmp_path):
    """The same block with a couple tau on the pulley and the spring stretched by tau/(R k) to
    balance it: the cord holds tau/R at the equilibrium. Positive, the block swings at
    omega^2 = k/(m + I/R^2), I = M R^2/2 (Serway & Jewett ch. 15); zero or negative, those values
    are refused (a sheet redraws them)."""
    text = SLACK_AT_EQUILIBRIUM.replace(
        "  g: {meaning: grav", "  tau: {meaning: couple on the pulley, unit: N*m, range: [-0.5, 2], sig_figs: 2}\n"
        "  g: {meaning: grav").replace(
        "    - spring: {between: [wall, block], stiffness: k}",
        "    - spring: {between: [wall, block], stiffness: k, rest_length: d - tau/(R*k)}\n"
        "    - torque: {on: pulley, magnitude: -tau}").replace("({{ M }}, {{ R }})", "({{ M }}, {{ R }}, {{ tau }})")
    path = write(tmp_path, text)
    problem = load(path)
    m, M, k = (problem.parameters[n].symbol for n in ("m", "M", "k"))
    assert sp.simplify(Solution(problem).signed("omega") - sp.sqrt(k / (m + M / 2))) == 0
    given = ("--set", "m=1", "--set", "M=1", "--set", "R=0.1", "--set", "k=100")
    assert run_derive("solve", str(path), *given, "--set", "tau=1").returncode == 0
    slack = run_derive("solve", str(path), *given, "--set", "tau=0")
    assert slack.returncode == 2
    assert slack.stderr.strip().endswith("parameters: the cord cord is slack at the equilibrium at these parameters: "
                                         "its tension there is not positive, and a small oscillation needs it positive")
    pushing = run_derive("solve", str(path), *given, "--set", "tau=-0.2")
    assert pushing.returncode == 2 and "the cord cord goes slack" in pushing.stderr


def test_a_contact_that_carries_nothing_along_the_swing_is_not_refused(tmp_path):
    """A block on a smooth floor with no gravity: its normal force is zero at the equilibrium and
    stays zero along the swing, so it never has to pull (omega^2 = k/m, Halliday ch. 15)."""
    path = write(tmp_path, DAMPED.replace("RANGE", "2, 10").replace(
        "    - damper: {between: [wall, block], coefficient: b}\n", "").replace(
        "  b: {meaning: damping coefficient, unit: N*s/m, range: [2, 10], sig_figs: 3}\n", ""))
    problem = load(path)
    m, k = (problem.parameters[n].symbol for n in ("m", "k"))
    assert sp.simplify(Solution(problem).signed("omega") - sp.sqrt(k / m)) == 0
