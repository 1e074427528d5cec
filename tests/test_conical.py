"""A body hanging below its fixed point and turning steadily in a cone (`BODY.conical.rate`, a
`pivot_point` with a tilt beyond pi/2): its closed form is in tests/test_textbook.py; here what is
refused, each in one line naming its field."""
import pytest
import sympy as sp

from conftest import refused, textbook
from derive.language.problem import load
from derive.solution.answers import Solution

ROD = textbook("rod_conical_pendulum").read_text()


@pytest.mark.parametrize("old, new, field, message", [
    ("tilt: pi - theta}", "tilt: pi - theta, spin: 0}", "scene.bodies.rod.pivot_point.spin", "leave it out"),
    ("tilt: pi - theta}", "tilt: pi/2 + theta - 0.5}", "scene.bodies.rod.pivot_point.tilt", "on one side of pi/2"),
    ("rod.conical.rate", "rod.precession.slow", "ask.W.of", "hangs below its point"),
    ("rod.conical.rate", "rod.conical.speed", "ask.W.of", "has conical.rate"),
    ("tilt: pi - theta}", "tilt: theta}", "scene", "no steady conical motion of the rod"),
], ids=["zero-spin", "tilt-across-the-horizontal", "precession-of-a-hanging-body", "unknown-detail", "standing-rod"])
def test_what_a_cone_cannot_mean_is_refused_in_one_line(tmp_path, old, new, field, message):
    assert message in refused(tmp_path, ROD.replace(old, new), f"{field}: ")


def test_a_hanging_disk_turns_in_a_cone_at_its_moments_difference(tmp_path):
    """A uniform disk hung from a point on its axis a distance d above its center, turning as one:
    (I1 - I3) Omega^2 cos(tilt) + m g d = 0 with I1 = m R^2/4 + m d^2, I3 = m R^2/2 about the point
    (Kleppner & Kolenkow ch. 7's rod with the disk's moments): where I1 > I3 it hangs in a cone."""
    path = tmp_path / "disk.yaml"
    path.write_text(ROD.replace("rod: {shape: rod, mass: m, length: L, pivot_point: {at: end,",
                                "rod: {shape: disk, mass: m, radius: L/4, pivot_point: {at: L,"))
    problem = load(str(path))
    m, L, theta, g = (problem.parameters[n].symbol for n in ("m", "L", "theta", "g"))
    I1, I3 = m * (L / 4) ** 2 / 4 + m * L**2, m * (L / 4) ** 2 / 2
    expected = sp.sqrt(m * g * L / ((I1 - I3) * sp.cos(theta)))
    assert sp.simplify(Solution(problem).expression("W") - expected) == 0
