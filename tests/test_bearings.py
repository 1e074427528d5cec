"""A body turning in bearings (derive.mechanics.bearings): Newton–Euler, Lagrange and the integral
agree on every component for every shape; a wrong route is caught; what is not modelled is
refused; a planar problem never builds a 3D frame."""
import pytest
import sympy as sp
from sympy.physics.vector import ReferenceFrame

from conftest import refused
from derive import inertia, report
from derive.answers import Solution
from derive.crosschecks import CheckFailure
from derive.mechanics import bearings
from derive.problem import load

m, w, a, psi, s = sp.symbols("m omega alpha psi s", positive=True)
#: Sizes in proportion, so that no shape is accidentally symmetric (a box of three sides, a cone).
SIZES = {"length": s, "radius": s, "height": 3 * s, "inner_radius": s, "outer_radius": 2 * s,
         "side_a": s, "side_b": 2 * s, "side_c": 3 * s}


@pytest.mark.parametrize("shape", sorted(set(inertia.SHAPES) - {"point"}))
def test_the_routes_agree_for_every_shape(shape):
    sizes = {name: SIZES[name] for name in inertia.SHAPES[shape].sizes}
    tensor = bearings.body_tensor(shape, m, sizes)
    found = [bearings.motion(tensor, w, a, psi, bearings.own_axis(shape), r) for r in bearings.ROUTES]
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
     "ask.x"),  # the weight's share of the bearings' forces
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
