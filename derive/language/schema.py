"""JSON Schemas of the problem file and the set file, written from the keys the reader checks
(derive.core.keys, declared beside the code that reads each mapping), so that an editor's YAML
support completes and checks keys as an instructor types (`derive schema`).

The schema checks the keys and the shape of the values; what only the derivation can judge (a
body that is not declared, an expression's dimension) the reader refuses when derive loads the
file. A key the reader refuses is refused by the schema too (every mapping of fixed keys has
`additionalProperties: false`).

>>> schema = problem_schema()
>>> sorted(schema["required"])
['ask', 'id', 'parameters', 'question', 'scene', 'title']
>>> schema["properties"]["scene"]["properties"]["loads"]["items"]["maxProperties"]
1
"""
from __future__ import annotations

from derive.core.keys import Key, Keys
from derive.language import problem, problem_sets, scene_file
from derive.parts import cord

DIALECT = "https://json-schema.org/draft/2020-12/schema"
EXPRESSION = {"type": ["string", "number"]}
#: A point: `BODY.POINT` or a ground point's name, `[x, y]`, or `{BODY: [x, y]}` (one key, a list).
POINT = {"anyOf": [{"type": "string"}, {"type": "array", "items": EXPRESSION},
                   {"type": "object", "minProperties": 1, "maxProperties": 1, "additionalProperties": {"type": "array"}}]}

#: JSON Schema of each kind of value (derive.core.keys.KINDS).
KINDS = {
    "expression": EXPRESSION,
    "quantity": EXPRESSION,
    "name": {"type": "string"},
    "text": {"type": ["string", "number"]},  # YAML reads `due: 2026` or an id `1` as a number
    "point": POINT,
    "points": {"type": "array", "items": POINT, "minItems": 2, "maxItems": 2},
    "vector": {"type": "array", "items": EXPRESSION},
    "boolean": {"type": "boolean"},
    "integer": {"type": "integer"},
    "list": {"type": "array"},
    "mapping": {"type": "object"},
    "any": {},
}


def value(key: Key) -> dict:
    """The schema of one key's value."""
    result = {"description": key.meaning, **KINDS[key.kind]}
    if key.keys is not None:
        result.update(mapping(key.keys))
    if key.values is not None:
        each = value(key.values) if isinstance(key.values, Key) else mapping(key.values)
        result["additionalProperties"] = each
    if key.items is not None:
        result["items"] = mapping(key.items)
    if key.choices and key.kind == "list":
        result.update({"type": ["array", "string"], "items": {"enum": list(key.choices)}})  # or "pdf,html"
    elif key.choices:
        result["enum"] = list(key.choices)
    return result


def mapping(keys: Keys) -> dict:
    """The schema of a mapping with these keys and no others."""
    result = {"type": "object", "properties": {name: value(key) for name, key in keys.items()},
              "additionalProperties": False}
    if keys.required:
        result["required"] = list(keys.required)
    return result


def one_of(kinds: dict[str, dict], description: str) -> dict:
    """A mapping with exactly one of `kinds` as its key (a joint, a load): each kind's schema
    holds for its own value."""
    return {"type": "object", "description": description, "properties": kinds, "additionalProperties": False,
            "minProperties": 1, "maxProperties": 1}


def _part(keys: Keys, kind: str) -> dict:
    """A joint's schema: its kind key is one of its own keys (`{pin: rod.start, to: ...}`)."""
    return {**mapping(keys), "required": [kind, *(k for k in keys.required if k != kind)]}


def problem_schema() -> dict:
    """The JSON Schema of a problem file."""
    schema = {"$schema": DIALECT, "title": "derive problem file", **mapping(problem.PROBLEM)}
    scene = schema["properties"]["scene"]["properties"]
    joints = [_part(module.KEYS, kind) for kind, module in scene_file.JOINTS.items()]
    scene["joints"]["additionalProperties"] = {"oneOf": joints}
    loads = {kind: mapping(module.KEYS) for kind, module in scene_file.LOADS.items() if kind != "gravity"}
    loads["gravity"] = {"description": "gravity's field strength along -y, in m/s^2", **EXPRESSION}
    loads["pull"] = mapping(scene_file.PULL)
    scene["loads"]["items"] = one_of(loads, "one load")
    ends = [_part(cord.WOUND, "wound"), _part(cord.PULLED, "pulled"),
            *(_part(keys, side) for side, keys in cord.AROUND.items())]
    scene["cords"]["additionalProperties"] = {"type": "array", "minItems": 2, "items": {"anyOf": [POINT, *ends]}}
    return schema


def set_schema() -> dict:
    """The JSON Schema of a set file."""
    schema = {"$schema": DIALECT, "title": "derive set file", **mapping(problem_sets.SET)}
    problems = schema["properties"]["problems"]
    problems["items"] = {"anyOf": [{"type": "string"}, problems["items"]]}  # an id or a file, or a topic
    return schema
