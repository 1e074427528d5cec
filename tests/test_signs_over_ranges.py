"""A size's sign proven over the ranges the file declares (issue 38: right files wrongly refused):
sympy's assumptions know only that a symbol is positive, so `height: d*sin(theta)` with theta in
[0.05, 0.15] and a semi-major axis rp/(2 - rp vp^2/GM) were refused as not positive. derive proves
them in balls over the ranges (derive.numbers.intervals), and then holds `--set` to those ranges."""
import math

import mpmath
import pytest
import sympy as sp

from conftest import close, refused, run_derive, solve, write_problem
from derive.numbers import intervals

SLOPE = """\
id: tilted_drop
title: A ball released on a slope
topic: rolling
parameters:
  M: {meaning: mass of the ball, unit: kg, range: [1, 3], sig_figs: 2}
  R: {meaning: radius of the ball, unit: m, value: 0.1}
  d: {meaning: distance along the slope, unit: m, range: [1, 2], sig_figs: 2}
  theta: {meaning: slope angle, unit: rad, range: [THETA], sig_figs: 2}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  surfaces:
    ramp: {incline: {angle: theta, height: d*sin(theta)}}
  bodies:
    ball: {shape: sphere, mass: M, radius: R, on: ramp, contact: rolling}
  loads:
    - gravity: g
ask:
  v: {meaning: speed at the bottom, of: ball.speed_at_bottom, unit: m/s}
question: |
  A solid ball rolls from rest a distance {{ d }} down a slope at {{ theta }}.
"""


def test_a_height_positive_over_the_declared_ranges_is_taken(tmp_path):
    """Serway & Jewett ch. 10: a solid sphere rolling from rest down a height h has v = sqrt(10 g h / 7)."""
    answers, _ = solve(str(write_problem(tmp_path, SLOPE.replace("THETA", "0.05, 0.15"))), M="2", d="1.5",
                       theta="0.1")
    h = mpmath.mpf("1.5") * mpmath.sin(mpmath.mpf("0.1"))
    assert close(answers["v"], mpmath.sqrt(10 * mpmath.mpf("9.81") * h / 7))


def test_a_value_outside_the_range_the_proof_used_is_refused(tmp_path):
    path = write_problem(tmp_path, SLOPE.replace("THETA", "0.05, 0.15"))
    done = run_derive("solve", str(path), "--set", "theta=4")
    assert done.returncode == 2 and "--set theta=4: outside theta's range (0.05 to 0.15 rad)" in done.stderr


def test_a_height_not_positive_over_the_ranges_is_still_refused(tmp_path):
    refused(tmp_path, SLOPE.replace("THETA", "-0.1, 0.1"), "scene.surfaces.ramp.incline.height")


def test_an_orbit_from_its_perihelion_distance_and_speed(tmp_path):
    """Kleppner & Kolenkow ch. 10 (Kepler's laws): a = rp / (2 - rp vp^2/GM), e = rp vp^2/GM - 1,
    the aphelion a (1 + e) and the period 2 pi sqrt(a^3/GM). The Earth: rp = 1.471e11 m."""
    text = """\
id: earth_orbit
title: The Earth's orbit from its perihelion
topic: orbits
parameters:
  GM: {meaning: gravitational parameter of the Sun, unit: m^3/s^2, value: 1.327e20, sig_figs: 4}
  rp: {meaning: perihelion distance, unit: m, range: [1.46e11, 1.48e11], sig_figs: 3}
  vp: {meaning: speed at perihelion, unit: m/s, range: [3.03e4, 3.05e4], sig_figs: 3}
scene:
  orbit: {GM: GM, semi_major_axis: rp/(2 - rp*vp**2/GM), eccentricity: rp*vp**2/GM - 1}
ask:
  P: {meaning: orbital period, of: orbit.period, unit: s}
  r_apo: {meaning: aphelion distance, of: orbit.apoapsis, unit: m}
question: |
  The Earth passes perihelion {{ rp }} from the Sun ($GM =$ {{ GM }}) at {{ vp }}.
"""
    answers, _ = solve(str(write_problem(tmp_path, text)), rp="1.471e11", vp="30400")
    GM, rp, vp = mpmath.mpf("1.327e20"), mpmath.mpf("1.471e11"), mpmath.mpf(30400)
    a, e = rp / (2 - rp * vp**2 / GM), rp * vp**2 / GM - 1
    assert close(answers["r_apo"], a * (1 + e)) and close(answers["P"], 2 * mpmath.pi * mpmath.sqrt(a**3 / GM))
    assert math.isclose(float(answers["P"]) / 86400, 369.7, rel_tol=1e-3)  # about a year


def test_signs_proven_in_balls():
    x, y = sp.symbols("x y", positive=True)
    assert intervals.positive_over(x - y, {x: (2, 3), y: (0, 1)})
    assert not intervals.positive_over(x - y, {x: (2, 3), y: (0, 2)})  # zero at x = y = 2
    assert intervals.positive_over(x - y + 1, {x: (2, 3), y: (0, 2)}, strict=False)
    assert not intervals.positive_over(x - y, {x: (2, 3), y: (0, sp.Rational(21, 10))}, strict=False)
    assert not intervals.positive_over(x * sp.Symbol("z"), {x: (1, 2)})  # a symbol without a range: unproven


@pytest.mark.parametrize("low", ["0.05", "0.001"])
def test_a_narrow_range_near_zero_is_still_proven(tmp_path, low):
    answers, _ = solve(str(write_problem(tmp_path, SLOPE.replace("THETA", f"{low}, 0.15"))), M="2", d="1.5",
                       theta="0.1")
    assert answers["v"] > 0
