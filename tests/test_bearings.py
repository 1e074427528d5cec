"""A body turning in bearings (derive.mechanics.bearings): Newton–Euler, Lagrange and the integral
agree on every component for every shape; a shaft off the center of mass and the weight load the
bearings as kinematics and statics say; a wrong route is caught; what is not modelled is refused;
a planar problem never builds a 3D frame."""

import pytest
import sympy as sp
from sympy.physics.vector import ReferenceFrame

from conftest import refused, textbook, write_problem
from derive.publishing import export, figure, render, report
from derive.model import inertia
from derive.solution.answers import Solution
from derive.solution.crosschecks import CheckFailure
from derive.mechanics import bearings
from derive.language.problem import load
from derive.model.solid_scene import own_axis

m, w, a, psi, s, e, d, g = sp.symbols("m omega alpha psi s e d g", positive=True)
#: Sizes in proportion, so that no shape is accidentally symmetric (a box of three sides, a cone).
SIZES = {"length": s, "radius": s, "height": 3 * s, "inner_radius": s, "outer_radius": 2 * s,
         "side_a": s, "side_b": 2 * s, "side_c": 3 * s}


@pytest.mark.parametrize("shape", sorted(set(inertia.SHAPES) - {"point"}))
def test_the_routes_agree_for_every_shape(shape):
    sizes = {name: SIZES[name] for name in inertia.SHAPES[shape].sizes}
    tensor = bearings.body_tensor(shape, m, sizes)
    found = [bearings.motion(tensor, w, a, psi, own_axis(shape), r) for r in bearings.ROUTES]
    for key in ("angular_momentum", "torque", "kinetic_energy"):
        assert sp.simplify(sp.Matrix([found[0][key] - found[1][key]])).is_zero_matrix, key
    momentum, torque = found[0]["angular_momentum"], found[0]["torque"]
    assert sp.simplify(torque - sp.Matrix([0, 0, w]).cross(momentum)) == sp.zeros(3, 1)  # steady: tau = omega x L
    assert sp.simplify(found[0]["kinetic_energy"] - w * momentum[2] / 2) == 0
    if shape in ("rod", "disk", "box", "cone"):  # the integral route, where it is quick
        integral = bearings.angular_momentum_by_integral(shape, m, tuple(sizes.items()), w, a, psi)
        assert sp.simplify(integral - momentum) == sp.zeros(3, 1)


def test_a_symmetric_body_on_its_axis_needs_no_torque():
    disk = bearings.body_tensor("disk", m, {"radius": s})
    found = bearings.motion(disk, w, 0, psi, "z", "lagrange")
    assert found["torque"] == sp.zeros(3, 1) and found["angular_momentum"] == sp.Matrix([0, 0, m * s**2 * w / 2])


def _turned(tilt, roll) -> sp.Matrix:
    """The body's own frame in the ground's, by hand: turned by `roll` about its own z, then its z
    tilted toward +x by `tilt` (active rotations about y, then z)."""
    tilted = sp.Matrix([[sp.cos(tilt), 0, sp.sin(tilt)], [0, 1, 0], [-sp.sin(tilt), 0, sp.cos(tilt)]])
    return tilted * sp.Matrix([[sp.cos(roll), -sp.sin(roll), 0], [sp.sin(roll), sp.cos(roll), 0], [0, 0, 1]])


def test_an_offset_shaft_under_gravity_loads_the_bearings_as_statics_says(monkeypatch):
    """A box turned by roll and tilted on a level shaft that misses its center of mass: both routes
    agree on every force; the supports' force is m a_cm less the weight, a_cm the center's
    centripetal acceleration found by hand; the bearings' forces add up to it and, with the
    drive's couple, give the torque dL/dt about the center of mass (Hibbeler ch. 21)."""
    # its speed is derive bench's to measure: under the wall-clock limit it took 14 s alone and
    # once ran past 60 s on the shared 2-core machine, two test workers at once
    monkeypatch.setenv("DERIVE_TIME_LIMIT", "off")
    tensor = bearings.body_tensor("box", m, {"side_a": s, "side_b": 2 * s, "side_c": 3 * s})
    through, gravity = (e, 0, s), (0, -g, 0)
    found = [bearings.motion(tensor, w, a, psi, "z", r, m, through, gravity, d, None) for r in bearings.ROUTES]
    for key in found[0]:
        assert sp.simplify(sp.Matrix([found[0][key] - found[1][key]])).is_zero_matrix, key
    found = found[0]
    center = -_turned(a, psi) * sp.Matrix(through)
    shaft = sp.Matrix([0, 0, w])
    assert sp.simplify(found["force"] - m * shaft.cross(shaft.cross(center)) + m * sp.Matrix(gravity)) == sp.zeros(3, 1)
    assert sp.simplify(found["bearing.A"] + found["bearing.B"] - found["force"]) == sp.zeros(3, 1)
    z = sp.Matrix([0, 0, 1])
    moment = ((d / 2 * z - center).cross(found["bearing.A"]) + (-d / 2 * z - center).cross(found["bearing.B"])
              + found["drive"] * z)
    assert sp.simplify(moment - found["torque"]) == sp.zeros(3, 1)
    assert sp.simplify(found["torque"] - shaft.cross(found["angular_momentum"])) == sp.zeros(3, 1)
    assert found["bearing.A"][2] == found["bearing.B"][2] == 0  # a level shaft: nothing along it


INCLINED = """id: inclined
title: A disk on an inclined shaft
topic: angular_momentum
parameters:
  M: {meaning: mass, unit: kg, range: [1, 5]}
  R: {meaning: radius, unit: m, range: [0.1, 0.3]}
  omega: {meaning: rate, unit: rad/s, range: [10, 100]}
  beta: {meaning: incline of the shaft, unit: rad, range: [0.1, 1.2]}
  d: {meaning: apart, unit: m, range: [0.2, 0.8]}
  g: {meaning: gravity, unit: m/s^2, value: 9.81}
scene:
  bodies:
    disk: {shape: disk, mass: M, radius: R, bearings: {rate: omega, tilt: 0, apart: d, incline: beta, thrust: A}}
  loads:
    - gravity: g
ask:
  Ay: {meaning: A across, of: disk.bearings.A.force.y, unit: N}
  Az: {meaning: A along, of: disk.bearings.A.force.z, unit: N}
  By: {meaning: B across, of: disk.bearings.B.force.y, unit: N}
  Bz: {meaning: B along, of: disk.bearings.B.force.z, unit: N}
  Bx: {meaning: B sideways, of: disk.bearings.B.force.x, unit: N}
question: A disk turns on an inclined shaft.
"""


def test_an_inclined_shaft_puts_the_weight_along_it_on_the_thrust_bearing(tmp_path):
    """A balanced disk midway between the bearings of a shaft inclined at beta (statics of a shaft
    with a thrust bearing, Hibbeler ch. 21): each bearing carries M g cos(beta)/2 across the shaft
    and the thrust bearing A the whole M g sin(beta) along it."""
    solution = Solution(load(write_problem(tmp_path, INCLINED)))
    big_m, beta, big_g = (solution.problem.parameters[n].symbol for n in ("M", "beta", "g"))
    expected = {"Ay": big_m * big_g * sp.cos(beta) / 2, "By": big_m * big_g * sp.cos(beta) / 2,
                "Az": big_m * big_g * sp.sin(beta), "Bz": 0, "Bx": 0}
    for name, value in expected.items():
        assert sp.simplify(solution.expression(name) - value) == 0, name
    assert all(c.passed for c in solution.checks())


def test_a_wrong_bearing_force_is_caught(monkeypatch):
    problem = load(textbook("rotor_static_imbalance"))
    right = bearings.motion

    def wrong(*args):
        found = right(*args)
        return {**found, "bearing.A": found["bearing.A"] * (2 if args[5] == "lagrange" else 1)}

    monkeypatch.setattr(bearings, "motion", wrong)
    with pytest.raises(CheckFailure, match="bearing.A"):
        Solution(problem).checks()


def test_a_wrong_route_is_caught(monkeypatch):
    problem = load("rigid_body_L")
    right = bearings.motion

    def wrong(tensor, rate, tilt, roll, axis, route, *args):
        found = right(tensor, rate, tilt, roll, axis, route, *args)
        return {**found, "torque": found["torque"] * (2 if route == "lagrange" else 1)}  # sympy's sign, say

    monkeypatch.setattr(bearings, "motion", wrong)
    with pytest.raises(CheckFailure, match="torque"):
        Solution(problem).checks()


ROD = """id: spun
title: A rod in bearings
topic: angular_momentum
parameters:
  m: {meaning: mass, unit: kg, value: 1}
  L: {meaning: length, unit: m, value: 1}
  omega: {meaning: rate, unit: rad/s, value: 3}
  alpha: {meaning: tilt, unit: rad, range: [0.2, 1.4]}
scene:
  bodies:
    rod: {shape: rod, mass: m, length: L, BEARINGS}
ask:
  x: {meaning: asked, of: ASK, unit: UNIT}
question: A rod spins.
"""


@pytest.mark.parametrize("bearings_key, ask, unit, field", [
    ("bearings: {rate: omega, tilt: alpha}", "rod.bearings.force", "N", "ask.x"),  # no apart: given
    ("bearings: {rate: omega, tilt: alpha + 2}", "rod.angle_L_omega", "rad", "scene.bodies.rod.bearings.tilt"),
    ("bearings: {rate: omega, tilt: alpha}, joint: fixed_axle", "rod.angle_L_omega", "rad", "scene.bodies.rod.joint"),
    ("rotation: {rate: omega, tilt: alpha}", "rod.angle_L_omega", "rad", "scene.bodies.rod"),  # retired
    ("bearings: {rate: omega, tilt: alpha}", "rod.acceleration.x", "m/s^2", "ask.x"),
    ("bearings: {rate: omega, tilt: alpha, apart: L}}\n  loads:\n    - gravity: omega**2*L\n#", "rod.bearings.force", "N",
     "ask.x"),  # the weight makes the bearings' forces differ: ask each
    ("bearings: {rate: omega, tilt: alpha, apart: L, through: [L, 0, 0]}", "rod.bearings.force", "N", "ask.x"),
    ("bearings: {rate: omega, tilt: alpha, through: [L, 0, 0]}", "rod.bearings.A.force.x", "N", "ask.x"),  # no apart
    ("bearings: {rate: omega, tilt: alpha, apart: L}", "rod.angle_L_omega", "rad",
     "scene.bodies.rod.bearings.apart"),  # a key nothing uses
    ("bearings: {rate: omega, tilt: alpha, through: [L, 0, 0]}", "rod.bearings.torque.y", "N*m",
     "scene.bodies.rod.bearings.through"),  # the torque about the center does not depend on it
    ("bearings: {rate: omega, tilt: alpha, through: [L, 0]}", "rod.angle_L_omega", "rad",
     "scene.bodies.rod.bearings.through"),
    ("bearings: {rate: omega, tilt: alpha, through: hub}", "rod.angle_L_omega", "rad",
     "scene.bodies.rod.bearings.through"),  # a rod has no hub
    ("bearings: {rate: omega, tilt: alpha, through: [L, 0, omega]}", "rod.angle_L_omega", "rad",
     "scene.bodies.rod.bearings.through[2]"),  # not a length
    ("bearings: {rate: omega, tilt: alpha, incline: alpha}", "rod.angle_L_omega", "rad",
     "scene.bodies.rod.bearings.incline"),  # no gravity
    ("bearings: {rate: omega, tilt: alpha, apart: L, incline: alpha}}\n  loads:\n    - gravity: omega**2*L\n#",
     "rod.bearings.A.force.x", "N", "scene.bodies.rod.bearings.thrust"),  # who takes the weight along the shaft?
    ("bearings: {rate: omega, tilt: alpha, apart: L, thrust: A}}\n  loads:\n    - gravity: omega**2*L\n#",
     "rod.bearings.A.force.x", "N", "scene.bodies.rod.bearings.thrust"),  # a level shaft has no thrust
    ("bearings: {rate: omega, tilt: alpha, apart: L, incline: 2}}\n  loads:\n    - gravity: omega**2*L\n#",
     "rod.bearings.A.force.x", "N", "scene.bodies.rod.bearings.incline"),  # past the vertical
    ("bearings: {rate: omega, tilt: alpha, apart: L}}\n  loads:\n    - torque: {on: rod, magnitude: m*L**2*omega**2}"
     "\n#", "rod.bearings.A.force.x", "N", "ask.x"),  # another load
])
def test_what_bearings_do_not_model_is_refused(tmp_path, bearings_key, ask, unit, field):
    refused(tmp_path, ROD.replace("BEARINGS", bearings_key).replace("ASK", ask).replace("UNIT", unit), field)


def test_a_point_mass_has_no_bearings(tmp_path):
    text = ROD.replace("{shape: rod, mass: m, length: L, BEARINGS}", "{shape: point, mass: m, "
                       "bearings: {rate: omega, tilt: alpha}}").replace("ASK", "rod.angle_L_omega").replace("UNIT", "rad")
    assert "uniform shape" in refused(tmp_path, text.replace("  L: {meaning: length, unit: m, value: 1}\n", ""),
                                      "scene.bodies.rod.bearings")


def test_a_planar_problem_builds_no_3d_frames(monkeypatch):
    def no_frames(*args, **kwargs):
        raise AssertionError("a planar scene built a 3D frame")

    monkeypatch.setattr(ReferenceFrame, "__init__", no_frames)
    result = report.solve(load("string_wrapped_disk"))
    assert all(c["passed"] for c in result["checks"].values())
    with pytest.raises(AssertionError, match="3D frame"):  # the guard itself works
        report.solve(load("rigid_body_L"))


def test_the_figure_shows_the_bearings_the_weight_and_the_center_off_the_shaft(tmp_path):
    """Under gravity the shaft is drawn level with the weight, (M + m) g, below the center; the
    bearings A and B sit on the shaft; a center of mass off the shaft is joined to it by a dashed
    line; every figure compiles."""
    rotor = figure.tikz(load(textbook("rotor_static_imbalance")))
    assert "\\draw[axis, ->] (-2,0) -- (2.2,0);" in rotor and "$\\left(M + m\\right)\\,g$" in rotor
    assert "{$A$}" in rotor and "{$B$}" in rotor
    offset = load(write_problem(tmp_path, ROD.replace("BEARINGS", "bearings: {rate: omega, tilt: alpha, apart: L, "
                                                                  "through: [L/4, 0, 0]}")
                                .replace("ASK", "rod.bearings.A.force.x").replace("UNIT", "N")))
    drawn = figure.tikz(offset)
    assert "\\draw[thin, dashed] (0,0) -- " in drawn and "\\vec L" in drawn and "[force]" not in drawn
    assert "{$0$}" not in figure.tikz(load(textbook("shaft_dynamic_imbalance")))  # no tilt, no angle
    tex = tmp_path / "figures.tex"
    tex.write_text(render.render("preamble.tex.j2") + "\\begin{document}\n" + "\n\n".join((rotor, drawn))
                   + "\n\\end{document}\n", encoding="utf-8")
    assert export.pdf(tex).exists()
