"""A library problem's difficulty and tags: the words an instructor filters on (`derive list
--difficulty`, `--tag`, the catalogue), each from a fixed list, so that a misspelt tag is refused
rather than silently never found.

>>> read_difficulty("medium", "difficulty"), read_tags(["rolling", "yo-yo"], "tags")
('medium', ('rolling', 'yo-yo'))
>>> read_tags(["rolling", "rollin"], "tags")
Traceback (most recent call last):
...
ValueError: tags[1]: unknown tag 'rollin' (see derive list --help); did you mean 'rolling'?
"""
from __future__ import annotations

from derive.core.spelling import did_you_mean

#: From a first exercise on one idea to a problem of several steps or a 3D motion.
DIFFICULTIES = ("easy", "medium", "hard")

#: What a problem is about, beyond its topic: the bodies, the parts, the method.
TAGS = (
    "3d", "atwood", "ballistic-pendulum", "bearings", "bounce", "collision", "cord", "cylinder", "damping",
    "disk", "energy", "equilibrium", "flywheel", "free-precession", "friction", "gyroscope", "hoop", "impulse",
    "incline", "ladder", "leaves-surface", "loop", "merry-go-round", "momentum", "normal-modes", "orbit",
    "oscillation", "pendulum", "plank", "point-mass", "polar-coordinates", "precession", "projectile", "pulley",
    "rod", "rolling", "skidding", "sphere", "spring", "stability", "top", "torque", "torsion", "wedge", "yo-yo",
)


def read_difficulty(value, field: str) -> str:
    """One of DIFFICULTIES; anything else is a ValueError naming `field`."""
    if value not in DIFFICULTIES:
        raise ValueError(f"{field}: expected one of {', '.join(DIFFICULTIES)}, got {value!r}"
                         + did_you_mean(value, DIFFICULTIES))
    return value


def read_tags(value, field: str) -> tuple[str, ...]:
    """A list of distinct TAGS, in the file's order; anything else is a ValueError naming the entry."""
    if not isinstance(value, list):
        raise ValueError(f"{field}: expected a list of tags, got {type(value).__name__}")
    for i, tag in enumerate(value):
        if tag not in TAGS:
            raise ValueError(f"{field}[{i}]: unknown tag {tag!r} (see derive list --help)"
                             + did_you_mean(tag, TAGS))
        if tag in value[:i]:
            raise ValueError(f"{field}[{i}]: tag {tag!r} is listed twice")
    return tuple(value)
