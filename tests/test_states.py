"""States of a scene (`scene.states`, `in: STATE`; derive.mechanics.states): the closed forms are in
the textbook suite (tests/textbook/states); here the rules a user meets, each refusal, and the
second route (Newton–Euler's motion integrated) shown to catch a wrong state."""
import json
import math
from pathlib import Path

import pytest

from conftest import run_derive, textbook
from derive.language import problem
from derive.publishing import report
from derive.solution.crosschecks import CheckFailure
from derive.core.errors import EngineLimit
from derive.mechanics import durations, first_root, reaching

ROD = """\
id: rod_states
title: A rod pinned at one end
topic: torque
parameters:
  M: {meaning: mass of the rod, unit: kg, range: [0.5, 3], sig_figs: 3}
  L: {meaning: length of the rod, unit: m, range: [0.5, 2], sig_figs: 3}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  bodies:
    rod: {shape: rod, mass: M, length: L, at: [L/2, 0], angle: 0}
  joints:
    hinge: {pin: rod.start}
  loads:
    - gravity: g
  states:
    there: {when: {rod.angle: TARGET}}
ask:
  omega: {meaning: angular velocity, of: rod.angular_velocity, in: there, unit: rad/s}
question: |
  A rod is released from rest horizontal.
"""


def solve(tmp_path, text, *extra):
    path = tmp_path / "problem.yaml"
    path.write_text(text)
    return run_derive("solve", str(path), "--format", "json", *extra)


def with_state(spec: str) -> str:
    """The rod with its state given otherwise: `spec` is the state's mapping."""
    return ROD.replace("    there: {when: {rod.angle: TARGET}}", f"    there: {spec}")


def refused(tmp_path, text, field):
    result = solve(tmp_path, text)
    assert result.returncode == 2, result.stdout + result.stderr
    assert field in result.stderr and len(result.stderr.strip().splitlines()) == 1, result.stderr
    return result.stderr


def test_a_rod_released_horizontal_turns_at_sqrt_3g_over_L_when_vertical(tmp_path):
    result = solve(tmp_path, ROD.replace("TARGET", "-pi/2"), "--set", "L=1.5")
    assert result.returncode == 0, result.stderr
    omega = json.loads(result.stdout)["answers"]["omega"]
    assert omega["value"].startswith("4.429") and omega["direction"] == "clockwise"  # sqrt(3*9.81/1.5)
    assert omega["component"].startswith("-4.429")  # along the file's axes: counter-clockwise positive


def test_a_state_the_motion_does_not_reach_is_refused(tmp_path):
    """Released horizontal, the rod falls: it never gets up to vertical."""
    assert "does not get there" in refused(tmp_path, ROD.replace("TARGET", "pi/2"), "scene.states.there")


def test_a_state_beyond_a_turning_point_is_refused(tmp_path):
    """Clockwise to -pi (horizontal again, at rest) it turns back: hanging down again after a
    whole turn (-5pi/2) is never reached, although the energy there would allow it."""
    result = solve(tmp_path, ROD.replace("TARGET", "-5*pi/2"))
    assert result.returncode == 2 and "stops on its way to the state" in result.stderr, result.stderr


def test_an_ask_in_a_state_the_scene_lacks_is_refused(tmp_path):
    text = ROD.replace("TARGET", "-pi/2").replace("in: there", "in: bottom")
    assert "no state 'bottom'" in refused(tmp_path, text, "ask.omega.in")


def test_a_rate_without_a_state_is_refused(tmp_path):
    text = ROD.replace("TARGET", "-pi/2").replace(", in: there", "")
    assert "is read in a state" in refused(tmp_path, text, "ask.omega.in")


def test_a_state_no_ask_reads_is_refused(tmp_path):
    text = with_state("{when: {rod.angle: -pi/2}}\n    unused: {when: {rod.angle: -1}}")
    assert "no ask is read in this state" in refused(tmp_path, text, "scene.states.unused")


def test_an_ask_that_is_not_read_in_a_state_is_refused(tmp_path):
    text = ROD.replace("TARGET", "-pi/2").replace("of: rod.angular_velocity, in: there, unit: rad/s",
                                                   "of: rod.inertia, in: there, unit: kg*m^2")
    assert "is not read in a state" in refused(tmp_path, text, "ask.omega.in")


def test_rates_that_leave_a_velocity_open_are_refused(tmp_path):
    """The pinned rod given only its center's x rate (zero by the pin): how fast it turns is open."""
    text = with_state("{rates: {rod.velocity.x: 0}}")
    assert "open" in refused(tmp_path, text, "scene.states.there")


def test_rates_that_break_a_constraint_are_refused(tmp_path):
    """The pinned rod's center cannot move along the rod."""
    text = with_state("{rates: {rod.velocity.x: sqrt(g*L)}}")
    assert "break a constraint" in refused(tmp_path, text, "scene.states.there")


def test_a_scene_that_stays_put_never_gets_to_the_state(tmp_path):
    """Hanging straight down at rest, nothing pushes the rod (every acceleration is zero: it is
    refused as a balance, with the push to give)."""
    text = ROD.replace("at: [L/2, 0], angle: 0", "at: [0, -L/2], angle: -pi/2").replace("TARGET", "-1")
    result = solve(tmp_path, text)
    assert result.returncode == 2 and "stays at rest at the start" in result.stderr, result.stderr
    assert "give a state with a rate to start from" in result.stderr


def test_a_damper_is_an_engine_limit(tmp_path):
    text = ROD.replace("TARGET", "-pi/2").replace("    - gravity: g", "    - gravity: g\n    - damper: {on: rod, coefficient: c}")
    text = text.replace("  g: {meaning", "  c: {meaning: damping, unit: N*m*s, range: [0.1, 1], sig_figs: 2}\n  g: {meaning")
    result = solve(tmp_path, text)
    assert result.returncode == 1 and "derive cannot yet" in result.stderr, result.stderr


def test_a_wrong_state_is_caught_by_the_integrated_motion(tmp_path, monkeypatch):
    """The second route: a rate 1% off is found by integrating Newton–Euler's equations."""
    path = tmp_path / "problem.yaml"
    path.write_text(ROD.replace("TARGET", "-pi/2"))
    original = reaching.root
    monkeypatch.setattr(reaching, "root", lambda expr: original(expr) * 101 / 100)
    with pytest.raises(CheckFailure, match="differ"):
        report.solve(problem.load(path), {}, 4)


# Turning points, thresholds and times (`when: stops`, `{leaves: ...}`, `{slack: ...}`, `of: time`).

HANGING = ROD.replace("at: [L/2, 0], angle: 0", "at: [0, -L/2], angle: -pi/2").replace(
    "    there: {when: {rod.angle: TARGET}}",
    "    struck: {rates: {rod.angular_velocity: SPIN}}\n    there: {when: stops, from: struck}").replace(
    "of: rod.angular_velocity, in: there, unit: rad/s", "of: rod.angle, in: there, unit: rad")


def test_a_struck_rod_stops_where_its_energy_runs_out(tmp_path):
    """(1/2)(M L^2/3) w0^2 = M g (L/2)(1 - cos(theta)): w0 = sqrt(3g/L) swings it to the horizontal."""
    result = solve(tmp_path, HANGING.replace("SPIN", "sqrt(3*g/L)"), "--set", "L=1.5")
    assert result.returncode == 0, result.stderr
    assert float(json.loads(result.stdout)["answers"]["omega"]["value"]) == pytest.approx(0, abs=1e-12)


def test_a_rod_struck_over_the_top_never_stops(tmp_path):
    """w0^2 > 12 g/L takes it over the top: it goes round forever, with no turning point."""
    assert "does not stop" in refused(tmp_path, HANGING.replace("SPIN", "4*sqrt(g/L)"), "scene.states.there")


def test_a_misspelled_threshold_is_refused(tmp_path):
    stderr = refused(tmp_path, HANGING.replace("SPIN", "sqrt(g/L)").replace("when: stops", "when: stop"),
                     "scene.states.there.when")
    assert "stops" in stderr


@pytest.mark.parametrize("spec, field", [("{slack: hinge}", "when.slack"), ("{leaves: rod}", "when.leaves")])
def test_a_threshold_of_a_part_that_has_none_is_refused(tmp_path, spec, field):
    """A pin is no cord, and the rod rests on no surface."""
    text = HANGING.replace("SPIN", "sqrt(g/L)").replace("when: stops", f"when: {spec}")
    assert "expected a" in refused(tmp_path, text, f"scene.states.there.{field}")


def test_the_time_of_the_placement_is_refused(tmp_path):
    text = HANGING.replace("SPIN", "sqrt(g/L)").replace("of: rod.angle, in: there", "of: time, in: struck")
    assert "time zero" in refused(tmp_path, text, "ask.omega.in")


#: A ball on a cord given v0 at the bottom, asked where the cord goes slack (from the textbook suite).
BALL = (textbook("ball_circle_slack")).read_text()


def test_a_cord_goes_slack_above_where_the_first_coordinate_turns(tmp_path):
    """Followed along x, the ball's circle ends at x = L (the level of the hook), below where the
    cord goes slack; followed along y (which heads up: the cord pulls the ball up at the bottom)
    it gets there: (v0^2 - 2 g L)/(3 g) above the hook."""
    result = solve(tmp_path, BALL, "--set", "v0=4", "--set", "L=0.4")
    assert result.returncode == 0, result.stderr
    assert float(json.loads(result.stdout)["answers"]["h"]["value"]) == pytest.approx((16 - 2 * 9.81 * 0.4) / (3 * 9.81), rel=1e-3)


def test_a_state_off_the_geometry_at_some_values_is_refused_there(tmp_path):
    """v0^2 > 5 g L takes the ball over the top: the cord never goes slack, and the formula's
    height (v0^2 - 2gL)/(3g) lies above the circle. Such a variant is refused, not answered."""
    from fractions import Fraction

    import sympy as sp

    from derive.solution.answers import Solution
    path = tmp_path / "problem.yaml"
    path.write_text(BALL)
    solution = Solution(problem.load(path))
    symbols = {p.symbol.name: p.symbol for p in solution.problem.parameters.values()}

    def at(v0, L):
        return {symbols["m"]: 1, symbols["g"]: sp.Rational(981, 100), symbols["v0"]: sp.Rational(Fraction(v0)),
                symbols["L"]: sp.Rational(Fraction(L))}
    assert solution.violated(at("4", "0.4")) is None  # 2gL = 7.8 < 16 < 5gL = 19.6
    assert "never gets to the state slack" in solution.violated(at("4.4", "0.3"))  # 19.4 > 5gL = 14.7


def test_a_wrong_threshold_is_caught_by_the_integrated_motion(tmp_path, monkeypatch):
    """The second route for a turning point: its place 1% off is found by Newton–Euler's motion."""
    path = tmp_path / "problem.yaml"
    path.write_text(HANGING.replace("SPIN", "2*sqrt(g/L)"))
    original = first_root.first
    monkeypatch.setattr(first_root, "first", lambda *args: original(*args) * 101 / 100)
    # Caught first by the root's own check (the turning point must be a root of K), an engine
    # limit, not the file's fault; without it, by the motion integrated (no time past the turn).
    with pytest.raises(EngineLimit, match="does not hold at the middle"):
        report.solve(problem.load(path), {}, 4)
    monkeypatch.setattr(first_root, "a_root", lambda *args: [])
    with pytest.raises(CheckFailure, match="differ|not real"):
        report.solve(problem.load(path), {}, 4)


def test_a_wrong_time_is_caught_by_the_integrated_motion(tmp_path, monkeypatch):
    path = tmp_path / "problem.yaml"
    path.write_text(HANGING.replace("SPIN", "2*sqrt(g/L)"))
    original = durations.duration
    monkeypatch.setattr(durations, "duration", lambda *args: (original(*args)[0] * 101 / 100, original(*args)[1]))
    with pytest.raises(CheckFailure, match="differ"):
        report.solve(problem.load(path), {}, 4)


# Found by a new-user trial (a helper writing setups from the README alone).

HOOP = """\
id: hoop_down_ramp
title: A hoop rolls down a ramp from a spot away from the plane's origin
topic: rolling
parameters:
  M: {meaning: mass of the hoop, unit: kg, range: [0.5, 5], sig_figs: 2}
  R: {meaning: radius of the hoop, unit: m, range: [0.05, 0.2], sig_figs: 2}
  H: {meaning: height of the ramp, unit: m, range: [1, 2], sig_figs: 2}
  theta: {meaning: angle of the ramp, unit: rad, range: [0.2, 0.8], sig_figs: 2}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  surfaces:
    ramp: {incline: {angle: theta, height: H}}
  bodies:
    hoop: {shape: ring, mass: M, radius: R, at: [H/tan(theta) + R*sin(theta), -H + R*cos(theta)], on: ramp, contact: rolling}
  loads:
    - gravity: g
  states:
    low: {when: {hoop.y: -H + R*cos(theta) - DROP}}
ask:
  turned: {meaning: angle the hoop has turned through, of: hoop.angle, in: low, unit: rad}
  v: {meaning: speed of its center, of: hoop.speed, in: low, unit: m/s}
question: |
  A hoop rolls down a ramp.
"""


def test_a_hoop_placed_away_from_the_planes_origin_turns_by_the_distance_it_rolls(tmp_path):
    """The rolling gap was measured from the plane's origin, so a body placed elsewhere started
    turned (its angle in a state was off by H/(R sin(theta)); the integration check caught it).
    Dropping h, it rolls h/sin(theta) and turns that over R, clockwise; v = sqrt(g h) for a hoop."""
    path = tmp_path / "problem.yaml"
    path.write_text(HOOP.replace("DROP", "H/2"))
    result = run_derive("solve", str(path), "--format", "json", "--set", "H=1.5", "--set", "R=0.1", "--set", "theta=0.5")
    assert result.returncode == 0, result.stderr
    answers = json.loads(result.stdout)["answers"]
    assert float(answers["turned"]["value"]) == pytest.approx(-0.75 / math.sin(0.5) / 0.1, rel=1e-3)
    assert float(answers["v"]["value"]) == pytest.approx(math.sqrt(9.81 * 0.75), rel=1e-3)


def test_a_state_past_the_bottom_of_a_ramp_of_given_height_is_refused(tmp_path):
    """The ramp's height is how far it drops from where the hoop starts: rolling 2H down would
    leave it, which an endless plane's formula would answer."""
    assert "past the bottom of ramp" in refused(tmp_path, HOOP.replace("DROP", "2*H"), "scene")


def test_a_hoop_rolling_up_a_ramp_of_given_height_is_not_limited_by_it(tmp_path):
    """The height is the drop below the start, not a top: a hoop pushed up the slope at v0 rises
    v0^2/g (K = M v^2 for a rolling hoop), above where it started. It was refused as "above the
    top of ramp" (found by a new-user trial: a block pulled up an incline by a hanging block)."""
    text = HOOP.replace("    low: {when: {hoop.y: -H + R*cos(theta) - DROP}}",
                        "    pushed: {rates: {hoop.velocity.x: -v0*cos(theta), hoop.velocity.y: v0*sin(theta)}}\n"
                        "    top: {from: pushed, when: stops}").replace(
        "  g: {meaning", "  v0: {meaning: speed it is pushed up at, unit: m/s, range: [1, 2], sig_figs: 2}\n  g: {meaning")
    text = text.split("ask:")[0] + ("ask:\n  y: {meaning: height of its center at the top, of: hoop.position.y, in: top, "
                                    "unit: m}\nquestion: A hoop is pushed up a ramp.\n")
    result = solve(tmp_path, text, "--set", "H=1.5", "--set", "R=0.1", "--set", "theta=0.5", "--set", "v0=1.5")
    assert result.returncode == 0, result.stderr
    y = float(json.loads(result.stdout)["answers"]["y"]["value"])
    assert y == pytest.approx(-1.5 + 0.1 * math.cos(0.5) + 1.5**2 / 9.81, rel=1e-9)


ROD_ON_FLOOR = ROD.replace("  joints:\n    hinge: {pin: rod.start}\n", "  surfaces:\n    floor: {plane: {angle: 0, "
                           "through: [0, 0]}}\n  joints:\n    foot: {touches: rod.start, on: floor}\n").replace(
    "at: [L/2, 0], angle: 0", "at: [L/2*cos(1), L/2*sin(1)], angle: 1").replace("TARGET", "1/2")


def test_a_rod_on_a_smooth_floor_falls_with_its_center_straight_down(tmp_path):
    """Two degrees of freedom (it slides and turns), energy fixes one rate: no horizontal force
    acts, so both routes keep its momentum along x, zero from rest, and x_cm stays put
    (derive.mechanics.first_integrals). From 1 rad above the floor to 1/2: with phi from the
    vertical, phi'^2 = 12 g (cos(phi0) - cos(phi))/(L (1 + 3 sin^2(phi))) (tests/test_textbook.py)."""
    result = solve(tmp_path, ROD_ON_FLOOR, "--set", "L=1.5", "--set", "M=2")
    assert result.returncode == 0, result.stderr
    phi0, phi = math.pi / 2 - 1, math.pi / 2 - 0.5
    expected = -math.sqrt(12 * 9.81 * (math.cos(phi0) - math.cos(phi)) / (1.5 * (1 + 3 * math.sin(phi) ** 2)))
    assert float(json.loads(result.stdout)["answers"]["omega"]["component"]) == pytest.approx(expected, rel=1e-9)
    steps = json.dumps(json.loads(result.stdout)["steps"])
    assert "momentum of the whole scene along x is kept" in steps


def test_a_rod_pushed_along_a_smooth_floor_is_refused_at_once(tmp_path):
    """Pushed sideways, its momentum along x is kept but not zero: x_cm moves with time and fixes no
    coordinate, so energy fixes one rate of two: an engine limit, before any gap is solved."""
    text = ROD_ON_FLOOR.replace("    there: {when: {rod.angle: 1/2}}", "    pushed: {rates: {rod.velocity.x: sqrt(g*L), "
                                "rod.velocity.y: 0, rod.angular_velocity: 0}}\n    there: {from: pushed, when: "
                                "{rod.angle: 1/2}}")
    result = solve(tmp_path, text)
    assert result.returncode == 1 and "2 degrees of freedom" in result.stderr, result.stderr


def test_where_the_foot_of_a_rod_on_a_smooth_floor_leaves_it_is_refused(tmp_path):
    """N = M g (4 + 3 (cos(phi) - cos(phi0))^2 - 3 cos^2(phi0))/(1 + 3 sin^2(phi))^2 > 0 all the way
    down (tests/test_textbook.py): the foot never leaves. derive cannot prove the equation N = 0 has
    no root, and says so (an engine limit), rather than answer or call it the file's fault."""
    text = (textbook("rod_falls_on_smooth_floor")).read_text().replace(
        "    tilted: {when: {rod.angle: pi/2 - theta}}\n", "    tilted: {when: {leaves: foot}}\n")
    result = solve(tmp_path, text)
    assert result.returncode == 1 and "derive cannot yet solve" in result.stderr, result.stderr
    assert "scene.states.tilted" in result.stderr and len(result.stderr.strip().splitlines()) == 1


WEDGE = (textbook("ball_bounces_off_wedge")).read_text()


def test_a_flight_that_never_gets_to_its_state_is_refused(tmp_path):
    """At 45 degrees the ball leaves the wedge heading down: it never comes back to where it fell from."""
    text = WEDGE.replace("landed: {from: bounced, when: {ball.y: -H}}", "landed: {from: bounced, when: {ball.y: h}}")
    assert "does not get there" in refused(tmp_path, text, "scene.states.landed")


def test_the_flight_off_the_wedge_matches_a_simulation_and_the_routes_check():
    """The landing found by energy along x (free flight) against a projectile integrated here
    with scipy from the velocity just after the bounce, until it is H below where it struck; and
    the solve's own check, Newton–Euler's equations integrated to each state, passed."""
    from scipy.integrate import solve_ivp

    wedge = problem.load(textbook("ball_bounces_off_wedge"))
    result = report.solve(wedge, {"h": "1", "H": "0.35", "e": "0.85", "m": "0.2"}, 12)
    value = {name: float(a.get("component") or a["value"]) for name, a in result["answers"].items()}
    fall = solve_ivp(lambda t, y: [y[2], y[3], 0, -9.81], (0, 5), [0, 0, value["vx"], value["vy"]],
                     events=lambda t, y: y[1] + 0.35, rtol=1e-12, atol=1e-14, method="DOP853")
    assert fall.t_events[0][0] == pytest.approx(value["t"], rel=1e-9)
    assert fall.y_events[0][0][0] == pytest.approx(value["x"], rel=1e-9)
    assert result["checks"]["states"]["passed"] and "integrated" in result["checks"]["states"]["detail"]


def test_a_flight_through_a_surface_is_refused(tmp_path):
    """Nothing holds a flying ball off the scene's surfaces: a ball struck H = 2 m above the floor
    (h = 0.5 m, e = 0.7) comes back to the wedge's face before it gets that low, and a ball asked
    where its center gets to the floor's level has passed through it: refused, naming why, per
    variant and at the middle of the ranges."""
    result = solve(tmp_path, WEDGE, "--set", "H=2", "--set", "h=0.5", "--set", "e=0.7")
    assert result.returncode == 2 and "would pass through face" in result.stderr, result.stderr
    flies = (textbook("ball_bounces_then_flies")).read_text()
    text = flies.replace("landed: {from: bounced, when: {ball.y: R}}", "landed: {from: bounced, when: {ball.y: 0}}")
    assert "would pass through floor" in refused(tmp_path, text, "scene.states.landed")


def test_a_state_of_a_rate_names_a_rate(tmp_path):
    text = WEDGE.replace("landed: {from: bounced, when: {ball.y: -H}}",
                         "landed: {from: bounced, when: {ball.velocity.z: 0}}")
    assert "x, y, velocity.x, velocity.y" in refused(tmp_path, text, "scene.states.landed.when.ball.velocity.z")


def test_a_state_where_its_coordinate_is_extremal_is_reached_along_another(tmp_path):
    """A bead from the bowl's rim asked at the bottom by its height (y = -R, its minimum): y has
    no rate there, so the motion is followed along x; speed sqrt(2 g R), normal force 3 m g."""
    text = (textbook("block_in_bowl")).read_text()
    result = solve(tmp_path, text.replace("bottom: {when: {bead.x: 0}}", "bottom: {when: {bead.y: -R}}"),
                   "--set", "R=0.5", "--set", "m=0.2")
    assert result.returncode == 0, result.stderr
    answers = json.loads(result.stdout)["answers"]
    assert float(answers["v"]["value"]) == pytest.approx(math.sqrt(2 * 9.81 * 0.5), rel=1e-3)
    assert float(answers["N"]["value"]) == pytest.approx(3 * 0.2 * 9.81, rel=1e-3)


def test_ranges_whose_middle_never_gets_to_the_state_are_refused(tmp_path):
    """derive decides the state's branch at the middle of the ranges: where the motion does not get
    there (a ball pushed too slowly to reach where its cord would go slack), the file is refused
    with the reason, not answered from a branch chosen blind."""
    text = BALL.replace("range: [3.6, 4.4]", "range: [2, 2.5]")
    assert "middle of the parameter ranges" in refused(tmp_path, text, "scene.states.slack")


ATWOOD = (textbook("atwood_pulley_speed")).read_text()


def test_blocks_on_a_cord_move_along_a_line_and_a_given_push_turns_back_where_energy_says(tmp_path):
    """The Atwood machine has three degrees of freedom in derive's coordinates (each block may
    swing), but from rest, or pushed along the cord, its motion is a line: the heavier block
    thrown up at v0 stops after d = v0^2/(2a), a = (m1 - m2) g/(m1 + m2 + M/2)."""
    text = ATWOOD.replace("    fallen: {when: {heavy.y: -10*R - h}}",
                          "    thrown: {rates: {heavy.velocity.y: v0, heavy.velocity.x: 0, light.velocity.x: 0}}\n    top: {from: thrown, when: stops}").replace(
        "  g: {meaning", "  v0: {meaning: speed the heavier block is thrown up at, unit: m/s, range: [0.5, 1], sig_figs: 2}\n"
                        "  g: {meaning").split("ask:")[0] + (
        "ask:\n  y: {meaning: height of the heavier block at the top, of: heavy.position.y, in: top, unit: m}\n"
        "  t: {meaning: time to the top, of: time, in: top, unit: s}\nquestion: The heavier block is thrown up.\n")
    text = "\n".join(line for line in text.splitlines() if not line.startswith("  h: "))
    values = {"m1": 2, "m2": 1, "M": 1, "R": 0.1, "v0": 0.8}
    result = solve(tmp_path, text, *(arg for k, v in values.items() for arg in ("--set", f"{k}={v}")))
    assert result.returncode == 0, result.stderr
    answers = json.loads(result.stdout)["answers"]
    a = (2 - 1) * 9.81 / (2 + 1 + 0.5)
    assert float(answers["y"]["value"]) == pytest.approx(-1 + 0.8**2 / (2 * a), rel=1e-9)
    assert float(answers["t"]["value"]) == pytest.approx(0.8 / a, rel=1e-9)


def test_a_block_pulled_up_past_its_pulley_is_refused_per_variant(tmp_path):
    """Along a line the cord's runs keep their directions only while their ends have not met:
    the lighter block, 10 R below the axle, cannot rise h > 10 R. The middle of the ranges is
    fine; the variant asked is refused, naming the run."""
    text = ATWOOD.replace("range: [0.1, 0.8], sig_figs: 2}", "range: [0.1, 1.5], sig_figs: 2}")
    result = solve(tmp_path, text, "--set", "h=1.4", "--set", "R=0.1")
    assert result.returncode == 2 and "run from pulley to light would shrink to nothing" in result.stderr, result.stderr
    assert solve(tmp_path, text, "--set", "h=0.9", "--set", "R=0.1").returncode == 0


def test_a_motion_that_leaves_its_starting_line_is_refused(tmp_path):
    """A puck held by two springs of different stiffness (at right angles, both stretched) starts
    along (k1, k2) but curves away: energy along that line would be wrong, so derive refuses."""
    text = """id: puck_two_springs
title: A puck between two springs
topic: energy
parameters:
  m: {meaning: mass of the puck, unit: kg, range: [1, 2]}
  k1: {meaning: stiffness of the spring along x, unit: N/m, range: [10, 20]}
  k2: {meaning: stiffness of the spring along y, unit: N/m, range: [40, 50]}
  L: {meaning: distance to each anchor, unit: m, range: [1, 2]}
scene:
  points:
    east: [L, 0]
    north: [0, L]
  bodies:
    puck: {shape: point, mass: m, at: [0, 0]}
  loads:
    - spring: {between: [east, puck], stiffness: k1, rest_length: L/2}
    - spring: {between: [north, puck], stiffness: k2, rest_length: L/2}
  states:
    moved: {when: {puck.x: L/4}}
ask:
  v: {meaning: speed of the puck there, of: puck.speed, in: moved, unit: m/s}
question: A puck is held between two stretched springs and released.
"""
    result = solve(tmp_path, text)
    assert result.returncode == 1 and "2 degrees of freedom whose motion is not a straight line" in result.stderr, \
        result.stderr


# Grips: a contact held by static friction keeps it on the way to every state, or the state is
# where it slips.

DOME = textbook("ball_slips_on_dome").read_text()


def test_a_ball_that_slips_on_its_way_is_not_followed_to_where_it_leaves(tmp_path):
    """Found silently wrong: with mu_s given, a ball on a dome was answered as rolling all the way
    to where it leaves (cos = 10/17), though it slips near 30 degrees from the top for mu_s = 0.3."""
    text = DOME.replace("slipping: {when: {slips: ball}, from: nudged}", "off: {when: {leaves: ball}, from: nudged}")
    text = text.replace("in: slipping", "in: off")
    stderr = refused(tmp_path, text, "scene")
    assert "slips at ball_contact on the way to the state off" in stderr and "when: {slips: ball_contact}" in stderr


def test_where_a_grip_fails_needs_a_coefficient(tmp_path):
    text = DOME.replace(", friction: {static: mu}}", "}").replace(
        "  mu: {meaning: coefficient of static friction, unit: 1, range: [0.2, 0.5], sig_figs: 2}\n", "")
    assert "gives no friction coefficient" in refused(tmp_path, text, "scene.states.slipping.when.slips")


def test_the_slip_point_is_checked_by_the_integrated_motion(tmp_path, monkeypatch):
    """The place where the grip fails, 1% off, is caught by Newton–Euler's motion integrated to
    where mu_s^2 N^2 = f^2 (the root's own check set aside)."""
    path = tmp_path / "problem.yaml"
    path.write_text(DOME)
    original = first_root.first
    monkeypatch.setattr(first_root, "first", lambda *args: original(*args) * 101 / 100)
    monkeypatch.setattr(first_root, "a_root", lambda *args: [])
    with pytest.raises(CheckFailure, match="differ"):
        report.solve(problem.load(path), {}, 4)


def test_an_angle_reached_only_the_other_way_round_is_refused(tmp_path):
    """Found by a new-user trial: a rod turning clockwise asked where its angle is +pi/2 was
    followed on the counter-clockwise branch of its center's circle (an internal error, the
    integrated motion disagreeing); the branch is now the one it turns on, which never gets there."""
    text = with_state("{rates: {rod.angular_velocity: -2*sqrt(g/L)}}").replace(
        "    there: {rates: {rod.angular_velocity: -2*sqrt(g/L)}}",
        "    spun: {rates: {rod.angular_velocity: -2*sqrt(g/L)}}\n    there: {when: {rod.angle: pi/2}, from: spun}")
    assert "does not get there" in refused(tmp_path, text, "scene.states.there")


def test_the_period_by_energy_meets_the_elliptic_integral(monkeypatch):
    """The period at an amplitude of a scene that is not a pendulum is twice the time between its
    turning points, by quadrature: for the library's compound pendulum, forced onto that route, it
    is the elliptic integral's value to 12 digits (amplitude 2.4 rad, near the top)."""
    import sympy as sp

    from derive.solution import answers
    from derive.core import library
    from derive.numbers import numeric
    from derive.solution.answers import Solution
    from derive.solution.crosschecks import sample_points
    from derive.mechanics.oscillation import NotAPendulum

    loaded = problem.load(library.find_problem("compound_pendulum_large"))
    exact = Solution(loaded).signed("T")
    values = {**sample_points(loaded, exact, count=1)[0], next(s for s in exact.free_symbols if s.name == "theta0"):
              sp.Rational(24, 10)}
    elliptic = numeric.evaluate(exact, values, 15)

    def not_a_pendulum(*args):
        raise NotAPendulum("forced")
    monkeypatch.setattr(answers, "exact_period", not_a_pendulum)
    by_energy = Solution(loaded).signed("T")
    assert by_energy.has(sp.Integral)
    assert abs(float(numeric.evaluate(by_energy, values, 15)) - float(elliptic)) <= 1e-12 * abs(float(elliptic))


@pytest.mark.parametrize("change, field", [
    (("in: lowest, unit: rad/s", "in: [lowest], unit: rad/s"), "ask.omega.in"),
    (("lowest: {when: {rod.angle: -pi/2}}", "lowest: {when: {rod.angle: -pi/2}, from: [lowest]}"),
     "scene.states.lowest.from"),
])
def test_a_state_named_by_a_list_is_refused_naming_the_field(change, field):
    """Found by the fuzz test: a list where a state's name goes was a TypeError (an internal error)."""
    text = (textbook("rod_swings_down")).read_text().replace(*change)
    with pytest.raises(problem.ProblemError, match=field.replace(".", r"\.")):
        problem.parse(text, Path("mutated.yaml"))


def test_the_time_up_a_bowl_has_the_units_of_a_time_and_the_quadratures_value(tmp_path):
    """A ball rolling up a bowl: the time to its highest point is an integral whose integrand holds
    atan2 of two lengths, which the dimension check once refused ("atan2() of length", exit 2, no
    file named). Energy gives (7/10) (Rb - r)^2 phi'^2 = (7/10) v0^2 - g (Rb - r)(1 - cos phi), so
    t = integral of d phi / phi' from 0 to the highest angle, here by mpmath's quadrature."""
    import mpmath

    text = (textbook("ball_rolls_up_bowl")).read_text()
    text = text.replace("  N: {meaning: normal force", "  t: {meaning: time to the highest point, of: time, in: highest, "
                        "unit: s}\n  N: {meaning: normal force")
    (tmp_path / "bowl.yaml").write_text(text)
    done = run_derive("solve", str(tmp_path / "bowl.yaml"), "--set", "m=0.3", "--set", "r=0.02", "--set", "Rb=0.4",
                      "--set", "v0=1.2", "--format", "json")
    assert done.returncode == 0, done.stderr
    result = json.loads(done.stdout)
    assert result["checks"]["dimensions"]["passed"]
    mpmath.mp.dps = 30
    g, reach, v0 = mpmath.mpf("9.81"), mpmath.mpf("0.38"), mpmath.mpf("1.2")
    top = mpmath.acos(1 - 7 * v0**2 / (10 * g * reach))
    rate = lambda phi: mpmath.sqrt(v0**2 - 10 * g * reach * (1 - mpmath.cos(phi)) / 7) / reach  # noqa: E731
    expected = mpmath.quad(lambda phi: 1 / rate(phi), [0, top])
    assert float(result["answers"]["t"]["value"]) == pytest.approx(float(mpmath.re(expected)), rel=1e-9)


TABLE_AND_PULLEY = """
id: table_pulley_kinetic
title: A block on a rough table pulled over a pulley
parameters:
  m1: {meaning: mass of the block on the table, unit: kg, value: 4}
  m2: {meaning: mass of the hanging block, unit: kg, value: 3}
  M: {meaning: mass of the pulley, unit: kg, value: 2}
  R: {meaning: radius of the pulley, unit: m, value: 0.1}
  mu: {meaning: coefficient of kinetic friction, unit: "1", value: 0.25}
  D: {meaning: distance of each block from the pulley, unit: m, value: 1.5}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  surfaces:
    table: {plane: {angle: 0, through: [0, R]}}
  bodies:
    pulley: {shape: disk, mass: M, radius: R, at: [0, 0], joint: fixed_axle}
    block: {shape: point, mass: m1, at: [-D, R], on: table, contact: sliding, friction: {kinetic: mu}}
    hanger: {shape: point, mass: m2, at: [R, -D]}
  cords:
    rope: [block, {over: pulley}, hanger]
  loads:
    - gravity: g
  states:
    dropped: {when: {hanger.y: -D - R}}
ask:
  v: {meaning: speed after the drop, of: hanger.speed, in: dropped, unit: m/s}
question: A block on a rough table is tied over a pulley to a hanging block. Find the speed.
"""


def test_a_block_on_a_rough_table_released_from_rest_slides_to_its_state_against_kinetic_friction(tmp_path):
    """A trial's table and pulley (Serway & Jewett ch. 10: (m1 + m2 + M/2) v^2/2 = (m2 - mu_k m1) g h, here h = R)
    was an engine limit ("a state may follow a slide with kinetic friction only on the way to where
    it grips"): the block now slips from rest, as static friction (mu_k where none is given) cannot
    hold it, and its work is mu_k N times the distance slid, N kept from the start."""
    result = solve(tmp_path, TABLE_AND_PULLEY)
    assert result.returncode == 0, result.stderr
    v = float(json.loads(result.stdout)["answers"]["v"]["value"])
    assert v == pytest.approx(math.sqrt(2 * (3 - 0.25 * 4) * 9.81 * 0.1 / (4 + 3 + 2 / 2)), rel=1e-12)  # a drop of R


def test_a_block_static_friction_holds_never_gets_to_its_state(tmp_path):
    """Where static friction holds the block at rest (m2 < mu_s m1), the state is never reached:
    refused at the middle of the ranges, and per variant where the middle slips (a set redraws it)."""
    held = TABLE_AND_PULLEY.replace("friction: {kinetic: mu}", "friction: {static: 0.8, kinetic: mu}")
    message = refused(tmp_path, held, "scene.states.dropped")
    assert "static friction holds the block at rest on table at the start" in message
    ranged = held.replace("m2: {meaning: mass of the hanging block, unit: kg, value: 3}",
                          "m2: {meaning: mass of the hanging block, unit: kg, range: [2, 6]}")
    result = solve(tmp_path, ranged, "--set", "m2=3")
    assert result.returncode == 2 and "static friction holds the block at rest from the start, so it never " \
                                       "gets to the state dropped" in result.stderr, result.stderr
    result = solve(tmp_path, ranged, "--set", "m2=3.3")
    assert result.returncode == 0, result.stderr
    v = float(json.loads(result.stdout)["answers"]["v"]["value"])
    assert v == pytest.approx(math.sqrt(2 * (3.3 - 0.25 * 4) * 9.81 * 0.1 / (4 + 3.3 + 2 / 2)), rel=1e-12)


def test_a_stick_balanced_on_its_end_never_topples_and_is_told_to_start_with_a_push(tmp_path):
    """A trial's stick standing on its pivot at rest: every acceleration is zero, yet the state
    was followed toward the floor, and the time to it (a quadrature that diverges: it takes for
    ever) stopped derive with an internal error. It is refused like a particle at rest on a dome's
    top, with what to write instead."""
    text = """
id: stick_topples
title: A stick standing on its end
parameters:
  M: {meaning: mass of the stick, unit: kg, value: 0.2}
  L: {meaning: length of the stick, unit: m, value: 1}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  bodies:
    stick: {shape: rod, mass: M, length: L, at: [0, L/2], angle: pi/2}
  joints:
    base: {pin: stick.start}
  loads:
    - gravity: g
  states:
    flat: {when: {stick.angle: 0}}
ask:
  w: {meaning: angular speed as it hits the floor, of: stick.angular_velocity, in: flat, unit: rad/s}
question: A stick standing on its end topples. How fast does it turn as it hits the floor?
"""
    (tmp_path / "stick.yaml").write_text(text)
    done = run_derive("solve", str(tmp_path / "stick.yaml"))
    assert done.returncode == 2, done.stderr
    assert "stick.yaml: scene.states.flat: the scene stays at rest at the start" in done.stderr
    assert "moves from a push" in done.stderr and "internal error" not in done.stderr
    nudged = text.replace("    flat: {when: {stick.angle: 0}}", "    nudged: {rates: {stick.angular_velocity: -w0}}\n"
                          "    flat: {from: nudged, when: {stick.angle: 0}}")
    nudged = nudged.replace("  g: {meaning", "  w0: {meaning: the push, unit: rad/s, value: 0.01}\n  g: {meaning")
    (tmp_path / "nudged.yaml").write_text(nudged)
    done = run_derive("solve", str(tmp_path / "nudged.yaml"), "--format", "json")
    assert done.returncode == 0, done.stderr
    w = float(json.loads(done.stdout)["answers"]["w"]["component"])  # (1/2)(M L^2/3)(w^2 - w0^2) = M g L/2
    assert w == pytest.approx(-math.sqrt(3 * 9.81 / 1 + 0.01**2), rel=1e-9)


def test_a_period_asked_of_a_pendulum_placed_away_from_its_equilibrium_names_the_ask_and_the_body(tmp_path):
    """A trial's rod placed at its release angle with `oscillation.period` asked: the refusal read
    "ask: ... xddot_rod is not zero", naming neither the ask nor anything of the file."""
    (tmp_path / "away.yaml").write_text("""
id: rod_placed_away
title: A rod pendulum placed at its release angle
parameters:
  M: {meaning: mass of the rod, unit: kg, value: 1}
  L: {meaning: length of the rod, unit: m, value: 1}
  th0: {meaning: release angle from the vertical, unit: deg, value: 50}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  bodies:
    rod: {shape: rod, mass: M, length: L, at: [L/2*sin(th0), -L/2*cos(th0)], angle: th0 - pi/2}
  joints:
    hinge: {pin: rod.start}
  loads:
    - gravity: g
ask:
  T: {meaning: period at this amplitude, of: oscillation.period, amplitude: th0, unit: s}
question: A rod pivoted at one end swings from its release angle. Find its period.
""")
    done = run_derive("solve", str(tmp_path / "away.yaml"))
    assert done.returncode == 1, done.stderr
    assert "away.yaml: ask.T: derive cannot yet find the equilibrium" in done.stderr
    assert "the rod's angular acceleration is not zero" in done.stderr and "ddot" not in done.stderr


ROUGH_BOWL = """
id: block_in_rough_bowl
title: A block slides in a rough bowl
parameters:
  m: {meaning: mass of the block, unit: kg, value: 1}
  R: {meaning: radius of the bowl, unit: m, value: 2}
  mu: {meaning: coefficient of kinetic friction, unit: "1", value: 0.2}
  v0: {meaning: speed at the bottom, unit: m/s, value: 3}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  surfaces:
    bowl: {circle: {radius: R, center: [0, R], side: inside}}
  bodies:
    block: {shape: point, mass: m, at: [0, 0], on: bowl, contact: sliding, friction: {kinetic: mu}}
  loads:
    - gravity: g
  states:
    sent: {rates: {block.velocity.x: v0}}
    higher: {from: sent, when: {block.y: R/10}}
ask:
  v: {meaning: speed then, of: block.speed, in: higher, unit: m/s}
question: A block slides up a rough bowl. How fast is it moving when it has risen R/10?
"""


def test_kinetic_friction_whose_normal_force_changes_on_the_way_is_an_engine_limit(tmp_path):
    """In a bowl the normal force grows with the speed, so mu_k N is not its start's value along
    the way: derive's check of the kept force (derive.mechanics.work) refuses it, never a wrong number."""
    result = solve(tmp_path, ROUGH_BOWL)
    assert result.returncode == 1, result.stdout + result.stderr
    assert "kinetic friction whose normal force changes on the way (its motion curves" in result.stderr
    # where the motion is a line but the normal force still changes (a cord pulling up at a slant
    # from a high peg), the check along the way refuses it
    peg = TABLE_AND_PULLEY.replace("table: {plane: {angle: 0, through: [0, R]}}", "table: {plane: {angle: 0, through: [0, -R]}}")
    peg = peg.replace("at: [-D, R], on: table", "at: [-D, -R], on: table")
    result = solve(tmp_path, peg)
    assert result.returncode == 1 and "whose normal force N^block changes on the way" in result.stderr, result.stderr


def test_forces_where_a_slide_stops_are_refused_and_the_next_segment_decides_afresh(tmp_path):
    """Where a crate shoved up a rough ramp stops, its friction jumps: forces there are refused.
    From there it slides back where tan(theta) > mu_s, the regime decided at the stop (a variant
    where static friction holds it is refused per variant)."""
    text = (textbook("crate_up_rough_ramp")).read_text()
    asked = text.replace("ask:\n", "ask:\n  N: {meaning: normal force at the top, of: crate.normal_force, in: highest, "
                                   "unit: N}\n")
    assert "where the crate stops sliding, its friction jumps" in refused(tmp_path, asked, "ask.N.in")
    held = text.replace("friction: {kinetic: mu}", "friction: {static: 0.9, kinetic: mu}")
    message = refused(tmp_path, held, "scene.states.back")
    assert "static friction holds the crate at rest on ramp in the state highest" in message
    ranged = text.replace("friction: {kinetic: mu}", "friction: {static: mus, kinetic: mu}").replace(
        "parameters:\n", "parameters:\n  mus: {meaning: coefficient of static friction, unit: '1', range: [0.5, 0.8]}\n")
    result = solve(tmp_path, ranged, "--set", "mus=0.79", "--set", "theta=0.6", "--set", "mu=0.3", "--set", "v0=3",
                   "--set", "m=10")
    assert result.returncode == 2 and "static friction holds the crate at rest in the state highest" in result.stderr
    result = solve(tmp_path, ranged, "--set", "mus=0.5", "--set", "theta=0.6", "--set", "mu=0.3", "--set", "v0=3",
                   "--set", "m=10")
    assert result.returncode == 0, result.stderr
    vb = float(json.loads(result.stdout)["answers"]["vb"]["value"])
    s, c = math.sin(0.6), math.cos(0.6)
    assert vb == pytest.approx(3 * math.sqrt((s - 0.3 * c) / (s + 0.3 * c)), rel=1e-12)


def test_a_regime_condition_that_is_not_real_past_an_earlier_one_is_no_internal_error(tmp_path):
    """With only the hanging mass given, derive looks for a condition every other value breaks; the
    speed's radicand is negative where static friction holds the block, which stopped `derive solve`
    with "is not a real number" (an internal error)."""
    path = textbook("rough_table_hanging_ball")
    result = run_derive("solve", str(path), "--set", "m2=1")
    assert result.returncode == 0 and "internal error" not in result.stderr, result.stderr


def test_an_impact_a_contact_held_by_friction_would_need_to_grip_through_is_an_engine_limit(tmp_path):
    """Clay striking the side of a wheel rolling on a floor with friction coefficients: holding it
    rolling through the impact takes a friction impulse while the floor's normal impulse is not
    zero, and whether mu_s allows that is not decided; refused (exit 1), never a number. (Where
    the normal impulse is zero, as a rolling ball off a cushion, it slides through:
    tests/textbook/states/ball_rolls_into_cushion.yaml.)"""
    (tmp_path / "clay.yaml").write_text(CLAY_ON_WHEEL)
    done = run_derive("solve", str(tmp_path / "clay.yaml"))
    assert done.returncode == 1, done.stdout + done.stderr
    assert "decide whether friction holds the wheel on floor through the impact" in done.stderr


CLAY_ON_WHEEL = """
id: clay_on_wheel
title: Clay strikes a rolling wheel
parameters:
  M: {meaning: mass of the wheel, unit: kg, value: 2}
  m: {meaning: mass of the clay, unit: kg, value: 0.2}
  R: {meaning: radius of the wheel, unit: m, value: 0.3}
  v0: {meaning: speed of the wheel, unit: m/s, value: 2}
  u: {meaning: speed of the clay, unit: m/s, value: 3}
  mu: {meaning: coefficient of friction, unit: "1", value: 0.5}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  surfaces:
    floor: {incline: {angle: 0}}
  bodies:
    wheel: {shape: disk, mass: M, radius: R, at: [0, R], on: floor, contact: rolling, friction: {static: mu, kinetic: mu}}
    clay: {shape: point, mass: m, at: [R, R]}
  loads:
    - gravity: g
  states:
    going: {rates: {wheel.velocity.x: v0, wheel.angular_velocity: -v0/R, clay.velocity.x: -u, clay.velocity.y: 0}}
    stuck: {from: going, event: {stick: clay, to: wheel}}
ask:
  w: {meaning: spin after, of: wheel.angular_velocity, in: stuck, unit: rad/s}
question: Clay strikes a rolling wheel. How fast does it turn after?
"""


def test_a_start_at_rest_in_balance_per_variant_says_so(tmp_path):
    """A trial's ball nudged on a dome's top at v0 in [0, 1]: at v0 = 0 it sits there in balance,
    and the refusal said it left "the other way than at the middle of the ranges"."""
    text = """id: dome_ball_nudged
title: A ball nudged on a dome
""" + DOME_BALL + """question: A ball rolls off a dome. Where does it leave it?
"""
    result = solve(tmp_path, text, "--set", "v0=0")
    assert result.returncode == 2, result.stdout + result.stderr
    assert "the scene stays at rest at the start" in result.stderr and "the other way" not in result.stderr


DOME_BALL = """parameters:
  m: {meaning: mass of the ball, unit: kg, value: 0.2}
  r: {meaning: radius of the ball, unit: m, value: 0.05}
  R: {meaning: radius of the dome, unit: m, value: 1.0}
  v0: {meaning: speed at the top, unit: m/s, range: [0, 1], sig_figs: 2}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  surfaces:
    dome: {circle: {radius: R, center: [0, 0], side: outside}}
  bodies:
    ball: {shape: sphere, mass: m, radius: r, at: [0, R + r], on: dome, contact: rolling}
  loads:
    - gravity: g
  states:
    nudged: {rates: {ball.velocity.x: v0}}
    off: {from: nudged, when: {leaves: ball}}
ask:
  y: {meaning: height of the ball's centre above the dome's centre where it leaves, of: ball.position.y, in: off, unit: m}
  v: {meaning: speed when it leaves, of: ball.speed, in: off, unit: m/s}
  w: {meaning: angular velocity then, of: ball.angular_velocity, in: off, unit: rad/s}
"""


def test_kinetic_friction_asked_in_a_state_opposes_the_slip_there():
    """`block.friction` asked `in:` a state of a slide was a KeyError (an internal error): the
    sliding contact has no friction unknown. It is mu_k N along the surface's tangent, against the
    slip in that state."""
    from derive.solution.answers import Solution
    solution = Solution(problem.load(str(textbook("block_down_rough_incline"))))
    contact = solution.scene_in("lower").constraint("block_contact")
    normal = solution.in_state("lagrange", "lower")[contact.unknowns()["normal"]]
    along = solution.contact_expression("block", "friction", solution.derivations_in("lower")["lagrange"], "lower")
    slip = contact.slip(solution.coordinates).xreplace(solution.states["lower"].values)
    point = {p.symbol: (p.range[0] + p.range[1]) / 2 if p.range else p.value
             for p in solution.problem.parameters.values()}
    assert abs(float(along.xreplace(point))) == pytest.approx(float((contact.kinetic * normal).xreplace(point)))
    assert float((along * slip).xreplace(point)) < 0


def test_rates_of_a_block_over_a_disk_pulley_name_the_velocity_they_leave_open(tmp_path):
    """A trial's table and disk pulley given its rates: block.velocity.x alone was told it left
    ydot_weight open (the cord fixes it; the weight's swing, xdot_weight, is the open one), and
    with both of the weight's given, that the rates broke a constraint: the cord's run |L - 2 r|
    was not read as placed."""
    text = TABLE_AND_PULLEY.replace("    dropped: {when: {hanger.y: -D - R}}",
                                    "    pushed: {rates: {block.velocity.x: v0}}\n"
                                    "    dropped: {from: pushed, when: {hanger.y: -D - R}}").replace(
        "parameters:\n", "parameters:\n  v0: {meaning: speed it is pushed at, unit: m/s, value: 0.5}\n")
    message = refused(tmp_path, text, "scene.states.pushed")
    assert "leave 1 velocity open (xdot_hanger)" in message
    given = text.replace("{block.velocity.x: v0}", "{block.velocity.x: v0, hanger.velocity.x: 0, hanger.velocity.y: -v0}")
    result = solve(tmp_path, given)
    assert result.returncode == 0, result.stderr
    v = float(json.loads(result.stdout)["answers"]["v"]["value"])  # (m1 + m2 + M/2) (v^2 - v0^2)/2 = (m2 - mu m1) g R
    assert v == pytest.approx(math.sqrt(0.25 + 2 * (3 - 0.25 * 4) * 9.81 * 0.1 / (4 + 3 + 2 / 2)), rel=1e-12)


def test_solve_says_how_each_segment_starts_where_friction_decides_it(tmp_path):
    """A trial found `derive solve`'s text showed only the equations held at rest ("Static
    friction ... it grips") for a block that slides in every state: it now says how each segment
    starts, as the worked solution does."""
    path = textbook("crate_up_rough_ramp")
    done = run_derive("solve", str(path))
    assert done.returncode == 0, done.stderr
    assert "to back: the crate slips from the state highest, against kinetic friction" in done.stdout


@pytest.mark.parametrize("change, field, message", [
    (("off: {when: {leaves: bead}, nudged: {bead.x: 1}}", "off: {when: {leaves: bead}}"), "scene.states.off",
     "stays at rest at the start"),
    (("nudged: {bead.x: 1}", "nudged: true"), "scene.states.off.nudged", "needs its position"),
    (("nudged: {bead.x: 1}", "nudged: {bead.x: 2}"), "scene.states.off.nudged.bead.x", "expected 1 or -1"),
    (("  v: {meaning: its speed there, of: bead.speed, in: off, unit: m/s}",
      "  v: {meaning: its speed there, of: bead.speed, in: off, unit: m/s}\n  t: {meaning: time, of: time, in: off, unit: s}"),
     "ask.t.in", "grows without bound"),
])
def test_a_vanishing_push_is_stated_and_read_rightly(tmp_path, change, field, message):
    """From a balance the engine answers the limit of a vanishing push where the file says so (nudged:),
    and refuses otherwise (it would stay at rest), a push without a way, and a time, which is unbounded."""
    text = textbook("particle_off_dome_nudged").read_text()
    assert change[0] in text
    path = tmp_path / "dome.yaml"
    path.write_text(text.replace(*change))
    result = run_derive("solve", str(path))
    assert result.returncode == 2 and field in result.stderr and message in result.stderr, result.stderr


# A place relative to another body (`when: {BODY.x: value, relative_to: OTHER or OTHER.POINT}`): Serway &
# Jewett's block pulled across a board is in the textbook suite.
BOARD = textbook("block_slides_off_plank").read_text()
ACROSS = "{when: {block.x: L/2, relative_to: board}}"


@pytest.mark.parametrize("when, field, words", [
    # the newcomer's first try: where the other body is, in the value
    ("{when: {block.x: board.x + L/2}}", "scene.states.across.when.block.x", "not of where the board is"),
    ("{when: {block.x: L/2, relative_to: plank}}", "scene.states.across.when.relative_to", "no body or point 'plank'"),
    ("{when: {block.velocity.x: 1, relative_to: board}}", "scene.states.across.when.relative_to",
     "of a position"),
    ("{when: {block.x: L/2, relative_to: block}}", "scene.states.across.when.relative_to", "other than that one"),
    ("{when: {slack: rope, relative_to: board}}", "scene.states.across.when.relative_to", "goes with one position"),
    # a newcomer's "how far in the first t1 seconds": no body named time, and what to state instead
    ("{when: {time: 2}}", "scene.states.across.when.time", "a state at a given time is not modelled"),
])
def test_a_wrong_place_relative_to_another_body_is_refused(tmp_path, when, field, words):
    assert words in refused(tmp_path, BOARD.replace(ACROSS, when), field)


def test_a_place_relative_to_a_point_of_the_other_body_is_measured_from_it(tmp_path):
    """`relative_to: {board: [L/2, 0]}` (its far end) at 0 is the state `relative_to: board` at L/2."""
    path = tmp_path / "problem.yaml"
    path.write_text(BOARD.replace(ACROSS, "{when: {block.x: 0, relative_to: {board: [L/2, 0]}}}"))
    moved = report.solve(problem.load(str(path)))["answers"]
    same = report.solve(problem.load(str(textbook("block_slides_off_plank"))))["answers"]
    assert {k: a["expr"] for k, a in moved.items()} == {k: a["expr"] for k, a in same.items()}
