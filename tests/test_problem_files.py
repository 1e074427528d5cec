"""Problem files: the library loads, and every kind of bad file is one clear line, exit 2."""
import textwrap

import pytest
import sympy as sp

from derive.language import problem
from derive.core.library import problem_files

GOOD = textwrap.dedent("""\
    id: hanging
    title: A disk and a block
    parameters:
      M: {meaning: disk mass, unit: kg, range: [1, 5]}
      R: {meaning: disk radius, unit: m, value: 0.2}
      m: {meaning: block mass, unit: kg, value: 0.5}
      g: {meaning: gravity, unit: m/s^2, value: 9.81}
    scene:
      bodies:
        disk: {shape: disk, mass: M, radius: R, joint: fixed_axle}
        block: {shape: point, mass: m}
      constraints:
        - string: {wound_on: disk, hangs: block}
      loads:
        - gravity: g
    ask:
      a: {meaning: acceleration, of: block.acceleration.y, unit: m/s^2}
    question: A block of mass {{ m }} hangs from a disk.
    """)


def write(tmp_path, text):
    path = tmp_path / "broken.yaml"
    path.write_text(text)
    return path


def test_every_library_problem_loads():
    files = problem_files()
    assert len(files) >= 150 and len({f.stem for f in files}) == len(files)  # ids are unique
    for path in files:
        loaded = problem.load(str(path))
        assert loaded.id == path.stem and path.parent.name == loaded.topic  # problems/TOPIC/ID.yaml
        assert loaded.source and loaded.difficulty and loaded.tags, path  # what the catalogue shows


def test_good_file_loads_with_exact_values(tmp_path):
    p = problem.load(str(write(tmp_path, GOOD)))
    assert p.parameters["g"].value == sp.Rational(981, 100)
    assert p.parameters["M"].symbol.is_positive


@pytest.mark.parametrize("change, field, reason", [
    (lambda t: t.replace("id: hanging", "id: [unclosed"), "line", "invalid YAML"),
    (lambda t: t + "colour: red\n", "colour", "unknown key"),
    (lambda t: t.replace("mass: M, radius", "mass: Q, radius"), "scene.bodies.disk.mass", "unknown symbol 'Q'"),
    (lambda t: t.replace("mass: M, radius", "mass: \"__import__('os')\", radius"), "scene.bodies.disk.mass", "not allowed"),
    (lambda t: t.replace("mass: M, radius", "mass: -M, radius"), "scene.bodies.disk.mass", "must be positive"),
    (lambda t: t.replace("value: 0.5}", "value: -0.5}"), "scene.bodies.block.mass", "must be positive"),
    (lambda t: t.replace("{meaning: disk mass, unit: kg", "{meaning: disk mass, unit: m"), "scene.bodies.disk.mass", "dimension"),
    (lambda t: t.replace("unit: m/s^2}\nquestion", "unit: kg}\nquestion"), "ask.a.unit", "declared kg"),
    (lambda t: t.replace("unit: m/s^2, value", "unit: furlong, value"), "parameters.g.unit", "furlong"),
    (lambda t: t.replace("hangs: block", "hangs: crate"), "scene.constraints[0].string.hangs", "no body 'crate'"),
    (lambda t: t.replace("block.acceleration.y", "block.velocity"), "ask.a.of", "not 'velocity'"),
    (lambda t: t.replace("range: [1, 5]", "range: [5, 1]"), "parameters.M.range", "below"),
    (lambda t: t.replace("shape: disk", "shape: cube"), "scene.bodies.disk.shape", "unknown shape"),
    (lambda t: t.replace("  R: {meaning", "  M: {meaning"), "line", "duplicate key"),
    (lambda t: t.replace("mass: M, radius", "mass: 10**10**10**10, radius"), "scene.bodies.disk.mass", ""),
    (lambda t: t + "difficulty: tricky\n", "difficulty", "expected one of easy, medium, hard, got 'tricky'"),
    (lambda t: t + "tags: [pulley, rollin]\n", "tags[1]", "unknown tag 'rollin'"),
    (lambda t: t + "tags: [pulley, pulley]\n", "tags[1]", "listed twice"),
    (lambda t: t + "tags: pulley\n", "tags", "expected a list of tags"),
])
def test_bad_files_fail_with_one_line_naming_file_and_field(tmp_path, derive, change, field, reason):
    path = write(tmp_path, change(GOOD))
    done = derive("solve", str(path), "--set", "M=2")
    assert done.returncode == 2, (done.stdout, done.stderr)
    message = done.stderr.strip()
    assert len(message.splitlines()) == 1, message
    assert str(path) in message and f": {field}" in message and reason in message, message


def test_a_problem_file_never_runs_code(tmp_path, derive):
    marker = tmp_path / "pwned"
    text = GOOD.replace("mass: M, radius", f"mass: \"open('{marker}', 'w')\", radius")
    done = derive("solve", str(write(tmp_path, text)))
    assert done.returncode == 2 and not marker.exists()
