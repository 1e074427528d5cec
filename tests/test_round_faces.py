"""A body whose round face is centered off its center of mass (a hemisphere's `round_center`, a
composite's round part off its center of mass) rocks on a surface; what derive cannot yet follow
such a body to is refused in one line. Its closed forms are in tests/test_textbook.py."""
import pytest

from conftest import run_derive, textbook
from derive.core.errors import EngineLimit, ProblemError
from derive.language.problem import load
from derive.publishing.figure import tikz

HEMISPHERE = textbook("hemisphere_rocking").read_text()


def _with(tmp_path, old, new):
    assert old in HEMISPHERE
    path = tmp_path / "hemisphere.yaml"
    path.write_text(HEMISPHERE.replace(old, new))
    return str(path)


def test_a_round_face_off_a_uniform_shape_or_outside_its_radius_is_refused(tmp_path):
    result = run_derive("solve", _with(tmp_path, "shape: custom, mass: m, radius: R, inertia: 83*m*R^2/320,",
                                       "shape: disk, mass: m, radius: R,"))
    assert result.returncode == 2 and "scene.bodies.hemisphere.round_center" in result.stderr, result.stderr
    assert "only a custom body" in result.stderr and len(result.stderr.strip().splitlines()) == 1
    with pytest.raises(ProblemError, match="round_center: the round face's center is off the center of mass by less"):
        load(_with(tmp_path, "round_center: [0, 3*R/8]", "round_center: [0, 2*R]"))


@pytest.mark.parametrize("old, new, field", [
    ("    - gravity: g\n", "    - gravity: g\n  states:\n    back: {when: stops}\n", "scene.states"),
    ("contact: rolling}", "contact: rolling, velocity: [R, 0]}", "scene.bodies.hemisphere.on"),
])
def test_what_derive_cannot_yet_follow_a_rocking_body_to_is_said(tmp_path, old, new, field):
    with pytest.raises(EngineLimit, match=f"{field}: derive cannot yet follow"):
        load(_with(tmp_path, old, new))


def test_a_hemisphere_is_drawn_as_its_dome_with_its_center_of_mass_off_the_face_center():
    drawn = tikz(load(str(textbook("hemisphere_rocking"))))
    assert "arc (-180:0:" in drawn and "-- cycle;" in drawn  # the dome below its flat face
