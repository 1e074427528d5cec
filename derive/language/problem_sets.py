"""Problem sets: a set file (`problems/sets/*.yaml`) read and checked, or problems given by
themselves as a set of their own (`derive sheet ID...`, derive.sheet([...])): the problems it
names (ids, files, a topic's), its variants, seed, outputs, questions and answer space, each key
refused with the file and the field where it does not fit. derive.publishing.worksheets builds a set.

>>> problem_set = load_set("demo")
>>> problem_set.problems[0]
'rod_endpoint'
"""
from __future__ import annotations

import datetime
import random
import re
from dataclasses import dataclass
from decimal import Decimal
from pathlib import Path
from typing import Sequence

import yaml

from derive.text import latex_safety
from derive.core import library
from derive.core.limits import MAX_VARIANTS
from derive.language.defaults import DEFAULT_OUTPUTS, OUTPUTS, Defaults, outputs
from derive.core.errors import InputError
from derive.core.keys import Key, Keys
from derive.language.problem import load
from derive.language.reader import safe_load
from derive.core.spelling import did_you_mean

#: A problem of a set by topic: `{topic: rolling}` (all of them) or `{topic: rolling, count: 2}`.
TOPIC = Keys(topic=Key("text", "a library topic (derive list shows them)", required=True),
             count=Key("integer", "how many of its problems, picked by the seed (default all)"))
#: The keys of a set file.
SET = Keys(title=Key("text", "the set's title, printed on every page", required=True),
           problems=Key("list", "library ids, problem files, or {topic: TOPIC, count: N}", required=True, items=TOPIC),
           course=Key("text", "the course named in the header (default: derive.toml's course)"),
           due=Key("text", "when it is due, as text"),
           variants=Key("integer", "how many variants, one per student (default 1)"),
           seed=Key("integer", "the seed the variants are drawn with (default 0)"),
           outputs=Key("list", "what derive sheet writes (default pdf and html)", choices=OUTPUTS),
           questions=Key("name", "how the LMS exports ask (default numerical)", choices=("numerical", "choice")),
           answer_space=Key("text", "room to write under each problem of the printed worksheet: 6cm, 40mm, 2in"))
#: `answer_space:` of a set file: room left under each problem of the printed worksheet.
ANSWER_SPACE = re.compile(r"(?:\d+(?:\.\d+)?)(?:cm|mm|in)")
#: How the LMS exports ask: a number with a tolerance, or a choice among distractors.
QUESTIONS = SET["questions"].choices


@dataclass(frozen=True)
class ProblemSet:
    id: str
    title: str
    course: str
    due: str
    problems: tuple[str, ...]  # library ids or problem files, topics resolved
    fields: tuple[str, ...]  # where each problem comes from in the set file: "problems[2]"
    variants: int
    seed: int
    path: Path | str  # the set file, or COMMAND_LINE for problems given by themselves
    outputs: frozenset[str] = DEFAULT_OUTPUTS
    questions: str = "numerical"
    tolerance: str | None = None  # the LMS tolerance of asks that give none (derive.language.defaults)
    answer_space: str = ""  # a TeX length left under each problem of the worksheet ("6cm"), or none
    loaded: tuple = ()  # the problems already read to name the set (given by themselves), in order; else none


def _topic(path: Path, index: int, entry: dict, seed: int) -> list[str]:
    """`{topic: rolling}` (every library problem of that topic, by id) or `{topic: rolling,
    count: 2}` (that many of them, picked by the set's seed)."""
    field = f"problems[{index}]"
    unknown = sorted(set(entry) - {"topic", "count"})
    if unknown or "topic" not in entry:
        raise InputError(f"{path}: {field}: expected a library id, a problem file or {{topic: TOPIC, count: N}}")
    found = sorted((p.id, str(p.path)) for p in map(load, library.problem_files()) if p.topic == entry["topic"])
    if not found:
        topics = sorted({p.topic for p in map(load, library.problem_files())})
        raise InputError(f"{path}: {field}.topic: no problem of topic {entry['topic']!r} (topics: {', '.join(topics)})"
                         + did_you_mean(entry["topic"], topics))
    count = entry.get("count", len(found))
    if not isinstance(count, int) or isinstance(count, bool) or not 1 <= count <= len(found):
        raise InputError(f"{path}: {field}.count: expected a whole number from 1 to {len(found)}")
    chosen = sorted(random.Random(f"{seed}/{entry['topic']}").sample(found, count))
    return [reference for _, reference in chosen]


#: Bounds of a set file, so that no file can ask for unbounded work: the same variant cap as
#: `derive sheet --variants`, and lengths of its texts (a title is repeated on every page).
MAX_PROBLEMS = 200
MAX_SEED = 2**63 - 1
TEXT_LIMITS = {"title": 200, "course": 200, "due": 100}


def _set_text(path: Path, raw: dict, key: str) -> str:
    """A text field of a set file: plain text within its length, passed by the LaTeX policy."""
    value = raw.get(key, "")
    if isinstance(value, (int, Decimal, datetime.date)) and not isinstance(value, bool) and key != "title":
        value = str(value)  # `due: 2026` or `due: 2026-12-01` (YAML's date) is a date the author meant as text
    if not isinstance(value, str) or (key == "title" and not value.strip()):
        raise InputError(f"{path}: {key}: expected {'non-empty ' if key == 'title' else ''}text")
    try:
        latex_safety.check_plain(value, TEXT_LIMITS[key])
    except latex_safety.LatexError as error:
        raise InputError(f"{path}: {key}: {error}") from None
    return value


def _whole(path: Path, raw: dict, key: str, default: int, low: int, high: int) -> int:
    value = raw.get(key, default)
    if not isinstance(value, int) or isinstance(value, bool) or not low <= value <= high:
        raise InputError(f"{path}: {key}: expected a whole number from {low} to {high}")
    return value


def _read_set(path: Path):
    try:
        return safe_load(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, yaml.YAMLError) as error:
        raise InputError(f"{path}: invalid set file: {str(error).splitlines()[0]}") from None


def _is_set(path: Path) -> bool:
    """A set file, not a problem: one of problems/sets/, or any other file but a library problem
    and a mapping with `id` or `scene` and no `problems` (an unreadable file is a set's, as
    before problems could be given by themselves, and load_set says what is wrong)."""
    if path.resolve() in {p.resolve() for p in library.set_files()}:
        return True
    if path.resolve() in {p.resolve() for p in library.problem_files()}:
        return False
    try:
        raw = _read_set(path)
    except InputError:
        return True
    return not (isinstance(raw, dict) and "problems" not in raw and {"id", "scene"} & set(raw))


#: What errors name for problems given on the command line, in place of a set file.
COMMAND_LINE = "derive sheet"
LONGEST_ID = 60  # of a set of problems given by themselves: it names the output folder


def load_sheet(references: Sequence[str], defaults: Defaults = Defaults()) -> ProblemSet:
    """What `derive sheet` builds: one set (a set file, or the id of one in problems/sets/), or
    the problems given (library ids or problem files) as a set of their own, with one variant,
    seed 0, its problem's title (or theirs) and id (build/<id>).

    >>> load_sheet(["rod_endpoint", "rod_midpoint"]).id
    'rod_endpoint-rod_midpoint'
    """
    paths = [library.find_set_or_problem(r) for r in references]
    sets = [r for r, path in zip(references, paths) if _is_set(path)]
    if sets and len(references) == 1:
        return load_set(references[0], defaults)
    if sets:
        raise InputError(f"{COMMAND_LINE}: {sets[0]} is a set: a set is built by itself (derive sheet SET)")
    problems, fields = _problems(COMMAND_LINE, list(references), 0, lambda i: f"argument {i + 1}")
    loaded = [load(reference) for reference in problems]
    titles = "; ".join(p.title for p in loaded)
    if len(titles) > TEXT_LIMITS["title"]:
        titles = f"{loaded[0].title} and {len(loaded) - 1} more"
    ids = "-".join(p.id for p in loaded)
    return ProblemSet(
        id=ids if len(ids) <= LONGEST_ID else f"{loaded[0].id}-and-{len(loaded) - 1}-more", title=titles,
        course=defaults.course, due="", problems=tuple(problems), fields=tuple(fields), variants=1, seed=0,
        path=COMMAND_LINE, outputs=DEFAULT_OUTPUTS if defaults.outputs is None else defaults.outputs, tolerance=defaults.tolerance,
        loaded=tuple(loaded),
    )


def load_set(reference: str, defaults: Defaults = Defaults()) -> ProblemSet:
    """A set file by path or id; only `title` and `problems` are required. The course defaults
    give its `course` and `outputs` where it names none, and the tolerance of asks."""
    path = library.find_set(reference)
    raw = _read_set(path)
    if not isinstance(raw, dict):
        raise InputError(f"{path}: expected a mapping with {', '.join(SET.required)}")
    for key in raw:
        if key not in SET:
            raise InputError(f"{path}: {key}: unknown key (allowed: {', '.join(SET)})"
                             + did_you_mean(key, SET))
    for key in SET.required:
        if key not in raw:
            raise InputError(f"{path}: {key}: missing")
    variants = _whole(path, raw, "variants", 1, 1, MAX_VARIANTS)
    seed = _whole(path, raw, "seed", 0, 0, MAX_SEED)
    entries = raw["problems"]
    if not isinstance(entries, list) or not entries or not all(isinstance(p, (str, dict)) for p in entries):
        raise InputError(f"{path}: problems: expected a list of problem ids, files or {{topic: TOPIC}}")
    problems, fields = _problems(path, entries, seed, lambda i: f"problems[{i}]")
    listed = raw.get("outputs", ",".join(sorted(DEFAULT_OUTPUTS if defaults.outputs is None else defaults.outputs)))
    if isinstance(listed, list) and all(isinstance(o, str) for o in listed):
        listed = ",".join(listed)
    if not isinstance(listed, str):
        raise InputError(f"{path}: outputs: expected a list of outputs ({', '.join(OUTPUTS)})")
    questions = raw.get("questions", "numerical")
    if questions not in QUESTIONS:
        raise InputError(f"{path}: questions: expected one of {', '.join(QUESTIONS)}")
    space = raw.get("answer_space", "")
    if not isinstance(space, str) or space and not ANSWER_SPACE.fullmatch(space):
        raise InputError(f"{path}: answer_space: expected a length in cm, mm or in, such as 6cm")
    return ProblemSet(
        id=path.stem, title=_set_text(path, raw, "title"),
        course=_set_text(path, raw, "course") if "course" in raw else defaults.course,
        due=_set_text(path, raw, "due"), problems=tuple(problems), fields=tuple(fields), variants=variants, seed=seed,
        path=path, outputs=outputs(listed, f"{path}: outputs"), questions=questions, tolerance=defaults.tolerance,
        answer_space=space,
    )


#: How errors name a set given as a list of problems rather than a file (derive.sheet([...])).
LISTED = Path("derive.sheet")


def set_of(entries: list, title: str | None = None, defaults: Defaults = Defaults()) -> ProblemSet:
    """A set of the problems listed as a set file's `problems:` would list them, with a set file's
    defaults (one variant, seed 0, the course defaults' outputs) and `title` (default
    "Problems"); its id, and so its folder, is `problems`.

    >>> set_of(["rod_endpoint", "tugged_spool"]).fields
    ('problems[0]', 'problems[1]')
    >>> set_of(["rod_endpoint", "rod_endpoint"])
    Traceback (most recent call last):
    ...
    derive.core.errors.InputError: derive.sheet: problems[1]: rod_endpoint is already problems[0]; ...
    """
    if not isinstance(entries, list) or not entries or not all(isinstance(p, (str, dict)) for p in entries):
        raise InputError(f"{LISTED}: problems: expected a list of problem ids, files or {{topic: TOPIC}}")
    problems, fields = _problems(LISTED, entries, 0, lambda i: f"problems[{i}]")
    title = _set_text(LISTED, {"title": "Problems" if title is None else title}, "title")
    return ProblemSet(id="problems", title=title, course=defaults.course, due="", problems=tuple(problems),
                      fields=tuple(fields), variants=1, seed=0, path=LISTED,
                      outputs=DEFAULT_OUTPUTS if defaults.outputs is None else defaults.outputs,
                      tolerance=defaults.tolerance)


def _problems(where: Path | str, entries: list, seed: int, field_of) -> tuple[list[str], list[str]]:
    """The problems of a set's entries (ids, files, topics), each once, and the field each comes
    from (`field_of(index)`), for errors."""
    if len(entries) > MAX_PROBLEMS:
        raise InputError(f"{where}: problems: {len(entries)} entries (limit {MAX_PROBLEMS})")
    problems, fields, files = [], [], []
    for i, entry in enumerate(entries):
        for reference in [entry] if isinstance(entry, str) else _topic(where, i, entry, seed):
            field = field_of(i) + (f" (topic {entry['topic']})" if isinstance(entry, dict) else "")
            try:
                file = library.find_problem(reference).resolve()
            except library.LibraryError as error:
                beside = Path(where).parent / reference if isinstance(where, Path) else None
                hint = (f" (a path in a set file is read from the working folder, not the set file's: "
                        f"write {beside} to name the one beside it)") if beside is not None and beside.is_file() else ""
                raise InputError(f"{where}: {field}: {error}{hint}") from None
            if file in files:
                raise InputError(f"{where}: {field}: {reference} is already {fields[files.index(file)]}; "
                                 "a problem appears once in a set")
            problems.append(reference)
            fields.append(field)
            files.append(file)
    if len(problems) > MAX_PROBLEMS:
        raise InputError(f"{where}: problems: {len(problems)} problems (limit {MAX_PROBLEMS})")
    return problems, fields
