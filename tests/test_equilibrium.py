"""Where a scene rests (`BODY.equilibrium.angle|x|y`, derive.mechanics.equilibrium): closed forms
in the textbook suite (bob_pushed_aside, rod_pushed_aside, spring_incline_rest); here the rules a
user meets: the nearest stable equilibrium, and each refusal."""
import pytest

from conftest import run_derive

SPRING = """\
id: hanging_spring
title: A block hanging from a spring
topic: statics
parameters:
  m: {meaning: mass of the block, unit: kg, range: [0.5, 3], sig_figs: 3}
  k: {meaning: stiffness, unit: N/m, range: [50, 300], sig_figs: 3}
  L0: {meaning: rest length, unit: m, range: [0.2, 0.5], sig_figs: 2}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  points:
    hook: [0, 0]
  bodies:
    block: {shape: point, mass: m, at: [0, -L0]}
  joints:
    rail: {slider: block, angle: pi/2}
  loads:
    - gravity: g
    - spring: {between: [hook, block], stiffness: k, rest_length: L0}
ask:
  y: {meaning: where the block rests, of: block.equilibrium.y, unit: m}
question: |
  A block hangs from a spring.
"""


def solve(tmp_path, text, *extra):
    path = tmp_path / "problem.yaml"
    path.write_text(text)
    return run_derive("solve", str(path), "--format", "json", *extra)


def test_a_block_on_a_spring_rests_below_its_hook_not_at_the_mirror_image_above(tmp_path):
    """Along its line the spring also holds the block still above the hook, compressed: the
    engine takes the stable equilibrium nearest where the file places the block."""
    import json
    result = solve(tmp_path, SPRING, "--set", "m=1", "--set", "k=100", "--set", "L0=0.3")
    assert result.returncode == 0, result.stderr
    value = float(json.loads(result.stdout)["answers"]["y"]["value"])
    assert abs(value - (-0.3 - 9.81 / 100)) < 1e-12


@pytest.mark.parametrize("change, status, reason", [
    ({"of: block.equilibrium.y": "of: block.equilibrium.angle"}, 2, "ask.y.of: "),  # a point mass has no angle
    ({"    - spring: {between: [hook, block], stiffness: k, rest_length: L0}\n": "",
      "  k: {meaning: stiffness, unit: N/m, range: [50, 300], sig_figs: 3}\n": ""}, 2, "no stable equilibrium"),
    ({"  joints:\n    rail: {slider: block, angle: pi/2}\n": ""}, 2, "one degree of freedom; the scene has 2"),
])
def test_a_scene_without_one_resting_place_is_refused(tmp_path, change, status, reason):
    text = SPRING
    for old, new in change.items():
        assert old in text
        text = text.replace(old, new)
    result = solve(tmp_path, text)
    assert result.returncode == status, result.stdout
    line = result.stderr.strip()
    assert line.count("\n") == 0 and "problem.yaml: " in line and reason in line, line
