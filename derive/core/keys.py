"""The keys a mapping of a problem or set file may hold, declared once beside the code that reads
them: the Reader checks a mapping against them (`reader.mapping(spec, field, keys=SPRING)`), and
the JSON Schema (derive.language.schema) and the documentation's page of each part are written
from them, so that none of the three can drift from the others.

A key has a kind (what its value is: `KINDS`), a meaning, and whether it is required; a key
whose value is itself a mapping of fixed keys gives them (`keys`), one whose value maps names the
file chooses to mappings gives those (`values`), and a list of mappings its `items`.

>>> SPRING = Keys(between=Key("points", "the two points it joins", required=True),
...               stiffness=Key("expression", "its stiffness, in N/m", required=True),
...               rest_length=Key("expression", "its length unstretched, in m"))
>>> SPRING.required, SPRING.optional
(('between', 'stiffness'), ('rest_length',))
>>> sorted(SPRING)
['between', 'rest_length', 'stiffness']
"""
from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

#: What a key's value may be, in words (the documentation's column "value").
KINDS = {
    "expression": "a number or an expression (`2*m`, `pi/2`)",
    "quantity": "a number, an expression or a value with a unit (`25 deg`)",
    "name": "a name",
    "text": "text",
    "point": "a point (`BODY`, `BODY.POINT`, `{BODY: [x, y]}`, `[x, y]`, a ground point)",
    "points": "two points",
    "vector": "`[x, y]` (in 3D `[x, y, z]`), each an expression",
    "boolean": "`true` or `false`",
    "integer": "a whole number",
    "list": "a list",
    "mapping": "a mapping",
    "any": "see the meaning",
}


@dataclass(frozen=True)
class Key:
    """One key of a mapping: its value's `kind` (one of KINDS), what it means, and whether the
    mapping must have it. `choices` lists the words a name may be; `keys` the fixed keys of a
    mapping value; `values` the keys (or the Key) of each entry of a mapping of names the file chooses;
    `items` the keys of each mapping in a list."""

    kind: str
    meaning: str
    required: bool = False
    choices: tuple[str, ...] = ()
    keys: Keys | None = None
    values: Keys | Key | None = None
    items: Keys | None = None

    def __post_init__(self):
        if self.kind not in KINDS:
            raise ValueError(f"unknown kind {self.kind!r} (kinds: {', '.join(KINDS)})")


class Keys(Mapping):
    """The keys of one kind of mapping, in the order the documentation lists them."""

    def __init__(self, **keys: Key):
        self._keys = dict(keys)

    def __getitem__(self, name: str) -> Key:
        return self._keys[name]

    def __iter__(self):
        return iter(self._keys)

    def __len__(self) -> int:
        return len(self._keys)

    def __repr__(self) -> str:
        return f"Keys({', '.join(self._keys)})"

    @property
    def required(self) -> tuple[str, ...]:
        return tuple(name for name, key in self._keys.items() if key.required)

    @property
    def optional(self) -> tuple[str, ...]:
        return tuple(name for name, key in self._keys.items() if not key.required)
