"""Composite bodies (`shape: composite`, derive.model.composite): parts placed in the body's own frame,
composed by the inertia module, moved as one body by both routes.

Closed forms: the parallel-axis theorem (Halliday, Resnick & Walker, Fundamentals of Physics,
10th ed., §10.6) for the T and the wheel; the physical pendulum omega^2 = M g d / I_pivot
(ibid. §15.6); rolling down an incline a = g sin(theta) / (1 + I / (M R^2)) (ibid. §11.2).
The wheel is also stated as separate bodies held by welds: the two statements agree."""
import pytest
import sympy as sp

from conftest import run_derive
from derive.publishing import figure
from derive.solution.answers import Solution
from derive.language.problem import load

TEE = """\
id: tee
title: A T made of two rods
topic: torque
parameters:
  m: {meaning: mass of each rod, unit: kg, range: [0.2, 2], sig_figs: 3}
  L: {meaning: length of each rod, unit: m, range: [0.2, 1], sig_figs: 3}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  bodies:
    tee:
      shape: composite
      at: [0, 0]
      parts:
        bar: {shape: rod, mass: m, length: L}
        stem: {shape: rod, mass: m, length: L, at: [0, -L/2], angle: pi/2}
      ANGLE
  joints:
    hinge: {pin: PIVOT}
  loads:
    - gravity: g
ask:
  I: {meaning: moment of inertia about the center of mass, of: tee.inertia, unit: kg*m^2}
  w: {meaning: OSCILLATION, of: small_oscillation.OSCILLATION, unit: 1/s}
question: |
  A T made of two rods of mass {{ m }} and length {{ L }}.
"""

WHEEL_PARTS = """\
        rim: {shape: ring, mass: M, radius: R}
        hub: {shape: disk, mass: m, radius: r}
        spoke1: {shape: rod, mass: q, length: R, at: [R/2, 0]}
        spoke2: {shape: rod, mass: q, length: R, at: [0, R/2], angle: pi/2}
        spoke3: {shape: rod, mass: q, length: R, at: [-R/2, 0]}
        spoke4: {shape: rod, mass: q, length: R, at: [0, -R/2], angle: pi/2}
"""

WHEEL = """\
id: spoked_wheel
title: A spoked wheel rolling down an incline
topic: rolling
parameters:
  M: {meaning: mass of the rim, unit: kg, range: [1, 2], sig_figs: 3}
  m: {meaning: mass of the hub, unit: kg, range: [0.2, 0.5], sig_figs: 3}
  q: {meaning: mass of each spoke, unit: kg, range: [0.05, 0.1], sig_figs: 3}
  R: {meaning: radius of the rim, unit: m, range: [0.3, 0.5], sig_figs: 3}
  r: {meaning: radius of the hub, unit: m, range: [0.05, 0.1], sig_figs: 3}
  theta: {meaning: angle of the incline, unit: rad, range: [0.1, 0.5], sig_figs: 3}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  surfaces:
    ramp: {incline: {angle: theta}}
  bodies:
BODIES
  loads:
    - gravity: g
ask:
  a: {meaning: acceleration down the incline, of: ACCELERATION, unit: m/s^2}
question: |
  A wheel rolls down an incline.
"""

COMPOSITE_WHEEL = WHEEL.replace("BODIES", """\
    wheel:
      shape: composite
      on: ramp
      parts:
""" + WHEEL_PARTS).replace("ACCELERATION", "wheel.acceleration.down_incline")

#: The same wheel as separate bodies welded to its rim, placed around the rim's center (CX, CY),
#: where the rim touches the ramp through the origin.
WELDED_WHEEL = WHEEL.replace("BODIES", """\
    rim: {shape: ring, mass: M, radius: R, on: ramp, at: [CX, CY]}
    hub: {shape: disk, mass: m, radius: r, at: [CX, CY]}
    spoke1: {shape: rod, mass: q, length: R, at: [CX + R/2, CY]}
    spoke2: {shape: rod, mass: q, length: R, at: [CX, CY + R/2], angle: pi/2}
    spoke3: {shape: rod, mass: q, length: R, at: [CX - R/2, CY]}
    spoke4: {shape: rod, mass: q, length: R, at: [CX, CY - R/2], angle: pi/2}
  joints:
    glue0: {weld: hub, to: rim}
    glue1: {weld: spoke1, to: rim}
    glue2: {weld: spoke2, to: rim}
    glue3: {weld: spoke3, to: rim}
    glue4: {weld: spoke4, to: rim}""").replace("ACCELERATION", "rim.acceleration.down_incline") \
    .replace("CX", "R*sin(theta)").replace("CY", "R*cos(theta)")


def write(tmp_path, text, name="problem.yaml"):
    path = tmp_path / name
    path.write_text(text)
    return path


def symbols(problem, *names):
    return [problem.parameters[n].symbol for n in names]


def tee(tmp_path, pivot, oscillation="omega", angle=""):
    return load(write(tmp_path, TEE.replace("PIVOT", pivot).replace("OSCILLATION", oscillation)
                      .replace("ANGLE", angle)))


def test_a_tee_of_two_rods_swings_about_its_junction(tmp_path):
    """I_cm = m L^2/12 * 2 + 2 m (L/4)^2 ... = 7 m L^2 / 24; about the junction 5 m L^2 / 12, with
    its center of mass L/4 below: omega^2 = 2 m g (L/4) / (5 m L^2 / 12) = 6 g / (5 L)."""
    problem = tee(tmp_path, "tee.origin")
    m, L, g = symbols(problem, "m", "L", "g")
    solution = Solution(problem)
    assert sp.simplify(solution.expression("I") - 7 * m * L**2 / 24) == 0
    assert sp.simplify(solution.expression("w") - sp.sqrt(6 * g / (5 * L))) == 0
    result = run_derive("solve", str(problem.path))
    assert result.returncode == 0, result.stderr
    assert "[ok] lagrange_vs_newton_euler" in result.stdout and "[ok] tensor_vs_integral:" in result.stdout


def test_a_part_s_named_point_is_a_point_of_the_composite(tmp_path):
    """Balanced on the free end of its stem (the stem's `start`; its `end` is at the bar), the T's
    center of mass is 3 L / 4 above the pin:
    I_pin = 7 m L^2 / 24 + 2 m (3 L / 4)^2 = 17 m L^2 / 12, growth^2 = 2 m g (3 L / 4) / I_pin."""
    problem = tee(tmp_path, "tee.stem.start", "growth_rate")
    m, L, g = symbols(problem, "m", "L", "g")
    growth = Solution(problem).expression("w")
    assert sp.simplify(growth - sp.sqrt(18 * g / (17 * L))) == 0


def test_a_composite_wheel_rolls_as_its_welded_parts_do(tmp_path):
    composite = load(write(tmp_path, COMPOSITE_WHEEL, "composite.yaml"))
    M, m, q, R, r, theta, g = symbols(composite, "M", "m", "q", "R", "r", "theta", "g")
    moment = M * R**2 + m * r**2 / 2 + 4 * q * R**2 / 3  # a spoke from the center to the rim: q R^2 / 3
    mass = M + m + 4 * q
    expected = g * sp.sin(theta) / (1 + moment / (mass * R**2))
    by_composite = Solution(composite).expression("a")
    assert sp.simplify(by_composite - expected) == 0
    welded = load(write(tmp_path, WELDED_WHEEL, "welded.yaml"))
    assert sp.simplify(Solution(welded).expression("a") - by_composite) == 0


def test_a_composite_is_drawn_part_by_part(tmp_path):
    drawn = figure.tikz(load(write(tmp_path, COMPOSITE_WHEEL)))
    assert drawn.count("line cap=round") == 4  # four spokes
    assert drawn.count("line width=1.8pt") == 1  # the rim


@pytest.mark.parametrize("change, message", [
    (("bar: {shape: rod, mass: m, length: L}\n", ""), "scene.bodies.tee.parts: a composite has at least two parts"),
    (("shape: composite\n", "shape: composite\n      mass: m\n"), "scene.bodies.tee.mass: a composite's mass comes "
                                                                 "from its parts"),
    (("shape: composite\n", "shape: rod\n"), "scene.bodies.tee.parts: a composite body has parts"),
    (("{shape: rod, mass: m, length: L}", "{shape: blob, mass: m, length: L}"),
     "scene.bodies.tee.parts.bar.shape: unknown shape 'blob'"),
    (("{shape: rod, mass: m, length: L}", "{shape: rod, mass: m}"), "scene.bodies.tee.parts.bar.length: missing"),
    (("pin: tee.origin", "pin: tee.stem.top"), "scene.joints.hinge.pin: a composite has no point 'stem.top'"),
    (("pin: tee.origin", "pin: {tee: [0, -2*L]}"), "scene.joints.hinge.pin: the point lies"),
], ids=["one-part", "mass", "parts-on-a-rod", "unknown-shape", "missing-size", "unknown-point", "off-the-body"])
def test_composite_mistakes_are_refused_in_one_line(tmp_path, change, message):
    path = write(tmp_path, TEE.replace("PIVOT", "tee.origin").replace("OSCILLATION", "omega").replace("ANGLE", "")
                 .replace(*change))
    result = run_derive("solve", str(path))
    assert result.returncode == 2, result.stdout
    assert result.stderr.strip().count("\n") == 0 and message in result.stderr, result.stderr


def test_a_composite_rolls_on_a_round_part_off_its_center_of_mass(tmp_path):
    """A hoop with a hub and a bead fixed on it, released on an incline: it rolls on the hoop, whose
    center is off its center of mass. At rest the acceleration is alpha about the contact point P,
    the weight's moment about P over I_P, times the center of mass's distance from P; the time to
    the bottom, which takes it constant, is refused."""
    text = COMPOSITE_WHEEL.replace(WHEEL_PARTS, "        rim: {shape: ring, mass: M, radius: R}\n"
                                                "        hub: {shape: disk, mass: m, radius: r, at: [R/2, 0]}\n"
                                                "        bead: {shape: point, mass: q, at: [R, 0]}\n")
    problem = load(str(write(tmp_path, text)))
    M, m, q, R, r, theta, g = (problem.parameters[n].symbol for n in ("M", "m", "q", "R", "r", "theta", "g"))
    total, cx = M + m + q, (m * R / 2 + q * R) / (M + m + q)
    inertia = M * R**2 + m * r**2 / 2 + m * (R / 2 - cx) ** 2 + M * cx**2 + q * (R - cx) ** 2
    arm = sp.Matrix([cx + R * sp.sin(theta), R * sp.cos(theta)])  # from P to the center of mass
    alpha = -arm[0] * total * g / (inertia + total * arm.dot(arm))
    down = alpha * (-arm[1] * sp.cos(theta) - arm[0] * sp.sin(theta))
    assert sp.simplify(Solution(problem).expression("a") - down) == 0
    text = text.replace("ramp: {incline: {angle: theta}}", "ramp: {incline: {angle: theta, height: R}}")
    result = run_derive("solve", str(write(tmp_path, text.replace("wheel.acceleration.down_incline, unit: m/s^2",
                                                                  "wheel.time_to_bottom, unit: s"))))
    assert result.returncode == 2 and "ask.a.of" in result.stderr and "round face off its center of mass" in \
        result.stderr, result.stderr
