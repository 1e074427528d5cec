"""The JSON Schemas of `derive schema` (derive.language.schema): every library and textbook file
validates, and a misspelt key, which derive refuses, is refused by the schema too."""
from __future__ import annotations

import copy
import json
from pathlib import Path

import jsonschema
import pytest
import yaml
from click.testing import CliRunner

from derive.cli import main
from derive.core import library
from derive.core.errors import InputError
from derive.language.problem import parse
from derive.language.problem_sets import load_set
from derive.language.reader import safe_load
from derive.language.schema import problem_schema, set_schema

ROOT = Path(__file__).resolve().parents[1]
PROBLEM_FILES = sorted(p for p in (ROOT / "problems").rglob("*.yaml") if p.parent.name != "sets") + \
    sorted((ROOT / "tests" / "textbook").glob("*.yaml"))
SET_FILES = sorted((ROOT / "problems" / "sets").glob("*.yaml"))


def _read(path: Path):
    return safe_load(path.read_text(encoding="utf-8"))  # as derive reads


@pytest.fixture(scope="module")
def problems():
    jsonschema.Draft202012Validator.check_schema(problem_schema())
    return jsonschema.Draft202012Validator(problem_schema())


def test_every_library_and_textbook_file_validates(problems):
    assert len(PROBLEM_FILES) >= 100
    invalid = {str(p.relative_to(ROOT)): [e.message for e in problems.iter_errors(_read(p))][:2] for p in PROBLEM_FILES}
    assert {name: errors for name, errors in invalid.items() if errors} == {}


def test_every_set_file_validates():
    jsonschema.Draft202012Validator.check_schema(set_schema())
    assert SET_FILES
    for path in SET_FILES:
        jsonschema.validate(_read(path), set_schema())


def _misspelt(raw: dict, where: tuple, key: str, wrong: str) -> dict:
    raw = copy.deepcopy(raw)
    spec = raw
    for step in where:
        spec = spec[step]
    spec[wrong] = spec.pop(key)
    return raw


#: (file, where the key is, the key, its misspelling): at the top, a parameter, a body, a joint,
#: a load, a cord's end, a surface, a state, an ask.
MISSPELLINGS = [
    ("problems/rolling/rolling_incline.yaml", (), "question", "questoin"),
    ("problems/rolling/rolling_incline.yaml", ("parameters", "M"), "unit", "units"),
    ("problems/rolling/rolling_incline.yaml", ("scene", "bodies", "ball"), "mass", "mas"),
    ("problems/rolling/rolling_incline.yaml", ("scene", "surfaces", "ramp", "incline"), "angle", "angel"),
    ("problems/rolling/rolling_incline.yaml", ("ask",), None, None),
    ("problems/statics/ladder_statics.yaml", ("scene", "joints", "head"), "touches", "touch"),
    ("problems/oscillations/spring_horizontal.yaml", ("scene", "loads", 1, "spring"), "stiffness", "stifness"),
]


@pytest.mark.parametrize("path, where, key, wrong", MISSPELLINGS)
def test_a_misspelt_key_is_refused_by_the_schema_as_by_derive(problems, path, where, key, wrong):
    raw = _read(ROOT / path)
    if key is None:  # the first ask's `meaning`
        where, key, wrong = ("ask", next(iter(raw["ask"]))), "meaning", "meanig"
    assert not list(problems.iter_errors(raw))
    bad = _misspelt(raw, where, key, wrong)
    assert any(wrong in e.message or key in e.message for e in problems.iter_errors(bad)), where
    with pytest.raises(InputError, match=wrong if wrong else key):
        parse(yaml.safe_dump(json.loads(json.dumps(bad, default=str)), sort_keys=False), ROOT / path)


def test_a_cord_end_misspelt_is_refused():
    schema = problem_schema()["properties"]["scene"]["properties"]["cords"]["additionalProperties"]
    jsonschema.validate(["hook", {"over": "pulley"}, {"wound": "reel", "side": "right"}, {"rod": [0, 1]}], schema)
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(["hook", {"wond": "reel", "side": "right"}], schema)


def test_a_misspelt_set_key_is_refused(tmp_path):
    raw = _read(SET_FILES[0])
    raw["varients"] = 3
    with pytest.raises(jsonschema.ValidationError, match="varients"):
        jsonschema.validate(raw, set_schema())
    path = tmp_path / "week.yaml"
    path.write_text(yaml.safe_dump(json.loads(json.dumps(raw, default=str))), encoding="utf-8")
    with pytest.raises(InputError, match="varients"):
        load_set(str(path))


def test_derive_schema_prints_them():
    runner = CliRunner()
    printed = runner.invoke(main, ["schema"])
    assert printed.exit_code == 0 and json.loads(printed.output) == problem_schema()
    printed = runner.invoke(main, ["schema", "--set"])
    assert printed.exit_code == 0 and json.loads(printed.output) == set_schema()


def test_the_library_is_what_the_schema_test_reads():
    assert {p.resolve() for p in library.problem_files()} <= {p.resolve() for p in PROBLEM_FILES}
