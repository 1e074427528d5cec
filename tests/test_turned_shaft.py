"""A body in bearings whose shaft is itself turned (`bearings: {turned: Omega}`, a ship's turbine as
the ship turns), and a custom rotor in bearings (`inertia: {axial, transverse}`): the gyroscopic
torque against an independent closed form, and what is refused, in one line naming its field. The
ship's turbine against its book is in tests/test_textbook.py."""
import pytest
import sympy as sp

from conftest import refused, textbook
from derive.language.problem import load
from derive.solution.answers import Solution

SHIP = textbook("ship_turbine_turning").read_text()
CYLINDER = """\
id: cylinder_turned_shaft
title: A tilted cylinder on a turned shaft
topic: angular_momentum
source: "Kleppner & Kolenkow, An Introduction to Mechanics 2nd ed., ch. 7"
parameters:
  M: {meaning: mass, unit: kg, range: [1, 4]}
  R: {meaning: radius, unit: m, range: [0.1, 0.5]}
  h: {meaning: height, unit: m, range: [0.2, 1]}
  beta: {meaning: tilt of its axis from the shaft, unit: rad, range: [0.1, 0.5]}
  omega: {meaning: spin about the shaft, unit: rad/s, range: [10, 40]}
  Omega: {meaning: rate the shaft turns at, unit: rad/s, range: [0.5, 2]}
scene:
  bodies:
    rotor: {shape: cylinder, mass: M, radius: R, height: h, bearings: {rate: omega, tilt: beta, roll: 1/3, turned: Omega}}
ask:
  tx: {meaning: x torque, of: rotor.bearings.torque.x, unit: N*m}
  ty: {meaning: y torque, of: rotor.bearings.torque.y, unit: N*m}
  tz: {meaning: z torque, of: rotor.bearings.torque.z, unit: N*m}
question: |
  A cylinder of mass {{ M }}, radius {{ R }} and height {{ h }}, tilted {{ beta }} on its shaft, spins at
  {{ omega }} while the shaft turns at {{ Omega }}. Find the torque the bearings exert.
"""


def test_a_tilted_cylinder_on_a_turned_shaft_needs_omega_x_L_plus_I_omega_dot(tmp_path):
    """A uniform cylinder, its axis n tilted by beta from the shaft (z) toward x, spins at w about the
    shaft while the shaft turns at W about y: omega = w z + W y, d omega/dt = w W x, and
    tau = omega x (I omega) + I d omega/dt with I = I1 + (I3 - I1) n n^T, I3 = M R^2/2,
    I1 = M (3 R^2 + h^2)/12 (Kleppner & Kolenkow ch. 7: dL/dt = tau)."""
    path = tmp_path / "cylinder.yaml"
    path.write_text(CYLINDER)
    problem = load(str(path))
    M, R, h, beta, w, W = (problem.parameters[n].symbol for n in ("M", "R", "h", "beta", "omega", "Omega"))
    n = sp.Matrix([sp.sin(beta), 0, sp.cos(beta)])
    I1, I3 = M * (3 * R**2 + h**2) / 12, M * R**2 / 2
    tensor = I1 * sp.eye(3) + (I3 - I1) * n * n.T
    omega = sp.Matrix([0, W, w])
    expected = omega.cross(tensor * omega) + tensor * sp.Matrix([w * W, 0, 0])
    solution = Solution(problem)
    for name, value in zip(("tx", "ty", "tz"), expected):
        assert sp.simplify(solution.signed(name) - value) == 0, (name, solution.signed(name))
    assert all(c.passed for c in solution.checks())


@pytest.mark.parametrize("old, new, field, message", [
    ("inertia: {axial: I}", "inertia: I", "scene.bodies.rotor.inertia", "inertia: {axial: I3, transverse: I1}"),
    ("turned: Omega}", "turned: Omega, through: [0, 0, d]}", "scene.bodies.rotor.bearings.turned",
     "passes through the center of mass"),
    ("shape: custom, mass: M, inertia: {axial: I}", "shape: point, mass: M", "scene.bodies.rotor.bearings",
     "or a custom body with inertia"),
], ids=["scalar-inertia", "turned-off-center", "point"])
def test_what_a_turned_shaft_cannot_mean_is_refused_in_one_line(tmp_path, old, new, field, message):
    assert message in refused(tmp_path, SHIP.replace(old, new), f"{field}: ")
