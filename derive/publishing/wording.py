"""What a student's documents call the things a problem file names, in place of the file's keys.

The engine's sentences name each body, part and state by its key ("Newton's second law for the
left", "the cord rope", "The start, sent:"), which is the problem file's business, not the
student's. The documents (the worked solutions, the handout, the LMS feedback) reword them here:

- a body by its mass parameter's meaning ("mass of the heavier block": the heavier block), else by
  its shape (the disk; a point mass is a block), placed where the key is a place (`left`: the left
  block) or numbered where two share a shape (the first disk), never by the key;
- a cord as the cord (the string), or the cord of the body it holds where there are several; a pin
  to the ground as the axle (at a center) or the pivot, a joint between bodies as the pin; a load by
  its kind (the applied torque, the spring), by the body it acts on where several share one;
- a state by what it is: the start, the impact (the bounce, the move), where the motion stops.

>>> from derive.language.problem import load
>>> words = Wording(load("atwood_smooth"))
>>> words("Newton's second law for the left along its motion, down")
"Newton's second law for the left block along its motion, down"
>>> words("the part of the cord rope that runs from the right, around the pulley; to the left")
'the part of the cord that runs from the right block, around the pulley; to the left'
"""
from __future__ import annotations

import dataclasses
import re
from collections import Counter

import sympy as sp

from derive.parts.cord import Cord
from derive.parts.pin import Pin
from derive.parts.surfaces import Plane
from derive.text.prose import Sentence

#: Keys that say where a body is, which a description keeps (`left`: the left block).
PLACES = ("left", "right", "upper", "lower", "inner", "outer", "top", "bottom", "front", "back", "near", "far",
          "first", "second", "third", "heavy", "light", "big", "small", "large", "inside", "outside")
#: Words that, after "to the", are a direction, not a body (a body named `left`).
DIRECTIONS = ("left", "right", "top", "bottom")
ORDINALS = ("first", "second", "third", "fourth", "fifth", "sixth")
#: What a body of a shape is called where nothing else names it.
SHAPES = {"point": "block", "disk": "disk", "ring": "ring", "rod": "rod", "sphere": "ball", "spherical_shell": "shell",
          "cylinder": "cylinder", "cone": "cone", "box": "box"}
#: What a part is called, by its kind (its class).
PARTS = {"Cord": "cord", "Slider": "guide", "Weld": "weld", "Clutch": "clutch", "SlippingClutch": "clutch",
         "Torque": "applied torque", "Force": "applied force", "Spring": "spring", "Damper": "damper",
         "TorsionalSpring": "torsion spring"}
#: The kind words the engine puts before a part's or a state's key (Part.title: "the cord rope").
KINDS = ("slipping clutch", "torsional spring", "cord", "pin", "slider", "weld", "clutch", "contact", "torque", "force",
         "spring", "damper", "joint", "couple", "bounce", "impact", "move", "turn", "transfer", "pull", "state")
#: Words before "of KEY" in the engine's lists of forces ("reaction of hinge, tension of rope").
OF = ("reaction", "tension", "force", "torque", "couple", "stretch", "length", "run", "multiplier", "multipliers", "plates")
#: How a state's coordinate reads in words.
COORDINATES = {"x": "horizontal position", "y": "height", "angle": "angle"}


def _noun_phrase(meaning: str) -> tuple[str | None, str | None]:
    """(what a mass parameter's meaning names, the noun it shares with other bodies):
    "mass of the pulley (a uniform disk)" names the pulley; "mass of each bob" shares bob."""
    found = re.fullmatch(r"(?:the )?(?:total )?mass of (?:the |a |an )?(.+)", meaning.strip(), re.I)
    if not found:
        return None, None
    phrase = re.sub(r"\s*\([^)]*\)", "", found[1]).split(",")[0].strip()
    if phrase.startswith(("each ", "either ", "one ")):
        return None, phrase.split(" ", 1)[1]
    return (phrase, None) if phrase else (None, None)


def _place(key: str) -> str | None:
    word = re.match(r"[a-z]+", key.lower())
    return word[0] if word and word[0] in PLACES else None


def _numbered(phrases: dict[str, str]) -> dict[str, str]:
    """Each phrase that two keys share numbered in the file's order (the first disk, the second disk)."""
    counts, seen = Counter(phrases.values()), Counter()
    result = {}
    for key, phrase in phrases.items():
        if counts[phrase] > 1 and seen[phrase] < len(ORDINALS):
            result[key] = f"{ORDINALS[seen[phrase]]} {phrase}"
            seen[phrase] += 1
        else:
            result[key] = phrase
    return result


def bodies(problem) -> dict[str, str]:
    """Each body's description, without its article.

    >>> from derive.language.problem import load
    >>> bodies(load("coupled_pendulums")), bodies(load("rolling_incline"))
    ({'left': 'left bob', 'right': 'right bob'}, {'ball': 'sphere'})
    """
    meanings = {p.symbol: p.meaning for p in problem.parameters.values()}
    named, shared = {}, {}
    for key, body in problem.scene.bodies.items():
        named[key], shared[key] = _noun_phrase(meanings.get(body.mass, ""))
    unique = Counter(p for p in named.values() if p)
    result = {key: phrase for key, phrase in named.items() if phrase and unique[phrase] == 1}
    rest = {}
    for key, body in problem.scene.bodies.items():
        if key not in result:
            noun = shared[key] if shared[key] not in (None, "object", "body") else SHAPES.get(body.shape, "body")
            if noun == "body" and problem.scene.gravity is not None and any(
                    isinstance(c, Pin) and c.body == key and c.to is None and any(x != 0 for x in c.offset)
                    for c in problem.scene.constraints):
                noun = "pendulum"  # a body of parts that swings under its weight from a pivot off its center
            # a key that is a word of the question (the beam, the wheel), not an abbreviation (pend, cyl)
            word = re.fullmatch(r"[a-z]+", key) and not shared[key] and body.shape in ("custom", "composite", "box") \
                and re.search(rf"\b{key}\b", f"{problem.title} {problem.question}", re.I)
            rest[key] = f"{_place(key)} {noun}" if _place(key) else key if word else noun
    return {key: result.get(key) or _numbered(rest)[key] for key in problem.scene.bodies}


def _surfaces(problem) -> dict[str, str]:
    rest = {}
    for key, surface in problem.scene.surfaces.items():
        if re.fullmatch(r"[a-z]+", key) and key not in PLACES:
            rest[key] = key  # a word: the ramp, the floor, the bowl
            continue
        noun = "circular track" if not isinstance(surface, Plane) else "floor" if surface.angle == 0 else \
            "wall" if sp.simplify(surface.angle - sp.pi / 2) == 0 else "incline"
        rest[key] = f"{_place(key)} {noun}" if _place(key) else noun
    return _numbered(rest)


def _state_nouns(problem) -> dict[str, str]:
    """A state by what happens: the start, the impact (the bounce, the move, the turn), the stop."""
    nouns = {}
    for key, state in problem.scene.states.items():
        if state.rates:
            nouns[key] = "start"
        elif state.event is not None:
            nouns[key] = "impact" if state.event.kind in ("stick", "lock") else state.event.kind
        elif state.until is not None and state.until[0] == "stops":
            nouns[key] = "stop"
        else:
            nouns[key] = "position reached"
    return _numbered(nouns)


class Wording:
    """A problem's engine text reworded for students: `words(text)`; `None` where nothing needs it."""

    def __init__(self, problem):
        self.problems_bodies = bodies(problem)
        self.surfaces = _surfaces(problem)
        self.states = _state_nouns(problem)
        self.state_kinds = {k: s for k, s in problem.scene.states.items()}
        self.parts = self._parts(problem)
        self.contacts = {c.name: f"the {self.surfaces.get(c.surface, c.surface)}" for c in problem.scene.constraints
                         if type(c).__name__ == "Contact"}
        keys = sorted({*self.problems_bodies, *self.surfaces, *self.states, *self.parts}, key=lambda k: (-len(k), k))
        kinds = "|".join(KINDS)
        self._pattern = re.compile(
            r"(?<![\w\\$])(?:(?P<lead>[Tt]he|[Ii]ts|[Aa]fter|[Ff]rom) (?:(?P<kind>" + kinds + r") )?|(?P<of>(?:"
            + "|".join(OF) + r") of )|(?P<bare>" + kinds + r") )?(?P<key>" + "|".join(map(re.escape, keys))
            + r")(?![\w])") if keys else None

    def _parts(self, problem) -> dict[str, str]:
        scene, named = problem.scene, self.problems_bodies
        made = {}
        for part in (*scene.constraints, *scene.loads):
            name = getattr(part, "name", None)
            if not name:
                continue
            if isinstance(part, Pin):
                made[name] = ("axle" if part.offset == (0, 0) else "pivot") if part.to is None else "pin"
            elif isinstance(part, Cord) and sum(isinstance(p, Cord) for p in scene.constraints) == 1:
                made[name] = "string" if name == "string" else "cord"
            elif type(part).__name__ == "Contact":
                made[name] = f"contact of the {named.get(part.body, 'body')}"
            else:
                made[name] = PARTS.get(type(part).__name__, "joint")
        counts = Counter(made.values())
        parts = [p for p in (*scene.constraints, *scene.loads) if getattr(p, "name", None) in made]
        for part in parts:
            if counts[made[part.name]] == 1:
                continue
            noun = PARTS.get(type(part).__name__, made[part.name])
            ends = getattr(part, "ends", None)
            if ends is not None:  # a spring or a damper: between its ends
                made[part.name] = f"{noun} between " + " and ".join(
                    f"the {named[e]}" if e in named else "the support" for e in ends)
                continue
            others = {b for p in parts if p is not part and made[p.name] == made[part.name] for b in p.bodies()}
            owners = [b for b in part.bodies() if b in named and b not in others]
            free = [f"{noun} of the {named[b]}" for b in owners if f"{noun} of the {named[b]}" not in made.values()]
            made[part.name] = free[0] if free else made[part.name]  # three forces on one wheel: numbered, all of them
        for key, state in problem.scene.states.items():  # the joint an impact or a move makes is named after its state
            made.setdefault(key, "bounce" if state.event and state.event.kind == "bounce" else f"joint of the {self.states[key]}")
        return _numbered(made)

    def __call__(self, text: str) -> str:
        if self._pattern is None or not text:
            return text
        text = self._headings(text)
        text = re.sub(r"'s (x|y|angle) gets to its value", lambda m: f"'s {COORDINATES[m[1]]} reaches its given value", text)
        return self._pattern.sub(self._replaced, text)

    def sentence(self, sentence: Sentence) -> Sentence:
        """A part's sentence (derive.text.prose) with its words reworded, its math as it is."""
        return dataclasses.replace(sentence, pieces=tuple(self(p) if isinstance(p, str) else p for p in sentence.pieces))

    def _headings(self, text: str) -> str:
        """A state's heading (Solution.state_heading) by what happens in it."""
        def after(start):
            state = self.state_kinds.get(start)  # after an impact or a move; a start or a position needs no word
            return f", after the {self.states[start]}" if state is not None and state.event is not None else ""
        text = re.sub(r"^The start, \w+: ", "The start: ", text)
        text = re.sub(r"^The (impact|move|turn|transfer) \w+, just after (\w+): ",
                      lambda m: f"The {m[1]}{after(m[2])}: ", text)
        text = re.sub(r"^From rest at the placement to \w+: ", "From rest at the placement: ", text)
        return re.sub(r"^From (\w+) to \w+: ", lambda m: f"From the {self.states.get(m[1], m[1])}: "
                      if m[1] in self.states and self.states[m[1]] != "position reached" else "From there: ", text)

    def _replaced(self, match: re.Match) -> str:
        key, lead, kind = match["key"], match["lead"], match["kind"]
        whole = match[0]
        if kind is None and match["bare"] is None and match["of"] is None and lead is None:
            if key in self.contacts and match.string[max(0, match.start() - 3):match.start()] == "at ":
                return f"its contact with {self.contacts[key]}"  # the normal force on the ball at ball_contact
            return whole if re.fullmatch(r"[a-z]+", key) else self._phrase(key, None, "the")
        if lead and lead.lower() == "the" and kind is None and self.only_a_state(key) and re.fullmatch(r"[a-z]+", key):
            return whole  # "the lowest point" of a route's words, beside a state named lowest: English, not the key
        if lead and lead.lower() == "its":
            return f"{lead} {self._phrase(key, kind, '')}"
        if lead and lead.lower() != "the":
            return f"{lead} {self._phrase(key, kind, 'the')}"
        if key in DIRECTIONS and lead and kind is None and match.string[max(0, match.start() - 3):match.start()] == "to " \
                and not match.string.startswith("'s", match.end()):
            return whole  # "to the left": a direction, though a body is named left
        if match["of"]:
            return match["of"] + self._phrase(key, None, "the")
        if match["bare"] == "couple":
            return f"couple of {self._phrase(key, match['bare'], 'the')}"
        if match["bare"]:
            return self._phrase(key, match["bare"], "")
        return self._phrase(key, kind, lead)

    def only_a_state(self, key: str) -> bool:
        """Whether `key` names a state and nothing else (no body, surface or part of the file)."""
        made_for_the_state = key not in self.parts or self.parts[key].startswith(("joint of the ", "bounce"))
        return key in self.states and key not in self.problems_bodies and key not in self.surfaces and made_for_the_state

    def _phrase(self, key: str, kind: str | None, article: str) -> str:
        if kind == "state" and key in self.states:
            phrase = f"state at the {self.states[key]}" if self.states[key] == "start" else \
                f"state just after the {self.states[key]}" if self.state_kinds[key].event else "state reached"
        elif kind in ("bounce", "impact", "move", "turn", "transfer", "pull") and key in self.states:
            phrase = self.states[key]
        elif kind is not None and key in self.parts:
            phrase = self.parts[key]
        elif key in self.problems_bodies:
            phrase = self.problems_bodies[key]
        elif key in self.surfaces:
            phrase = self.surfaces[key]
        elif key in self.parts:
            phrase = self.parts[key]
        else:
            phrase = self.states[key]
        return f"{article} {phrase}".strip()
