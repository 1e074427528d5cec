"""MkDocs hooks (mkdocs.yml: `hooks:`) that write the pages which must follow the code, at every build:

- one page per part of the scene language (`PAGES`), from the module that reads it: its docstring,
  the reading function's docstring (the file syntax) and its keys (derive.core.keys, the same
  declarations the reader checks and `derive schema` is written from), with their kinds and meanings;
- the JSON Schemas of `derive schema`, as files of the site (schema/problem.json, schema/set.json);
- a cookbook page's line `--8<-- problem: ID` becomes the library problem's file, as a YAML block
  (tests/test_docs.py runs `derive solve ID` for each); `--8<-- file: PATH` a file of docs/ (the
  tutorial's problem file, which the test runs too).

A page written here cannot drift from the code: a key added to a part appears on its page at the
next build, and a page whose module lost its keys fails the build.
"""
from __future__ import annotations

import importlib
import inspect
import json
import re
from pathlib import Path

from mkdocs.structure.files import File

from derive.core.keys import KINDS, Key, Keys
from derive.quantities import KINDS as QUANTITIES
from derive.core.library import find_problem

#: The generated pages: (file name, title, where it is written in a problem file, the keys as
#: "module:NAME", the docstrings to show as "module" or "module:function").
PAGES = [
    ("problem-file", "The problem file", "the top level", "derive.language.problem:PROBLEM",
     ["derive.language.problem"]),
    ("parameters", "Parameters", "parameters: {NAME: ...}", "derive.language.problem:PARAMETER", []),
    ("asks", "Asks", "ask: {NAME: ...}", "derive.language.ask_options:ASK", ["derive.language.ask_options"]),
    ("bodies", "Bodies", "scene: {bodies: {NAME: ...}}", "derive.language.body_file:BODY",
     ["derive.language.body_file", "derive.language.body_file:_joint"]),
    ("surfaces", "Surfaces", "scene: {surfaces: {NAME: ...}}", "derive.language.scene_file:SURFACE",
     ["derive.parts.surfaces", "derive.language.scene_file:_surfaces"]),
    ("pin", "Pin", "scene: {joints: {NAME: {pin: ...}}}", "derive.parts.pin:KEYS",
     ["derive.parts.pin", "derive.parts.pin:read"]),
    ("slider", "Slider", "scene: {joints: {NAME: {slider: ...}}}", "derive.parts.slider:KEYS",
     ["derive.parts.slider", "derive.parts.slider:read"]),
    ("weld", "Weld", "scene: {joints: {NAME: {weld: ...}}}", "derive.parts.weld:KEYS",
     ["derive.parts.weld", "derive.parts.weld:read"]),
    ("clutch", "Clutch", "scene: {joints: {NAME: {clutch: ...}}}", "derive.parts.clutch:KEYS",
     ["derive.parts.clutch", "derive.parts.slipping_clutch", "derive.parts.clutch:read"]),
    ("contact", "Contact at a point", "scene: {joints: {NAME: {touches: ...}}}", "derive.parts.contact:KEYS",
     ["derive.parts.contact", "derive.parts.contact:read"]),
    ("cord", "Cords", "scene: {cords: {NAME: [END, ..., END]}}", "derive.parts.cord:WOUND",
     ["derive.parts.cord", "derive.parts.cord:read"]),
    ("string", "String (shorthand)", "scene: {constraints: [{string: ...}]}", "derive.language.scene_file:STRING",
     ["derive.language.scene_file:_string"]),
    ("gravity", "Gravity", "scene: {loads: [{gravity: g}]}", None, ["derive.parts.gravity", "derive.parts.gravity:read"]),
    ("force", "Force", "scene: {loads: [{force: ...}]}", "derive.parts.force:KEYS",
     ["derive.parts.force", "derive.parts.force:read"]),
    ("torque", "Torque", "scene: {loads: [{torque: ...}]}", "derive.parts.torque:KEYS",
     ["derive.parts.torque", "derive.parts.torque:read"]),
    ("spring", "Spring", "scene: {loads: [{spring: ...}]}", "derive.parts.spring:KEYS",
     ["derive.parts.spring", "derive.parts.spring:read"]),
    ("torsional-spring", "Torsional spring", "scene: {loads: [{torsional_spring: ...}]}",
     "derive.parts.torsional_spring:KEYS", ["derive.parts.torsional_spring", "derive.parts.torsional_spring:read"]),
    ("damper", "Damper", "scene: {loads: [{damper: ...}]}", "derive.parts.damper:KEYS",
     ["derive.parts.damper", "derive.parts.damper:read"]),
    ("pull", "Pull (shorthand)", "scene: {loads: [{pull: ...}]}", "derive.language.scene_file:PULL",
     ["derive.language.scene_file:_pull"]),
    ("states", "States and events", "scene: {states: {NAME: ...}}", "derive.language.state_file:STATE",
     ["derive.language.state_file", "derive.language.state_file:read", "derive.language.state_file:_event"]),
    ("bearings", "Bearings (3D)", "scene: {bodies: {NAME: {bearings: ...}}}", "derive.language.solid_file:BEARINGS",
     ["derive.language.solid_file", "derive.language.solid_file:bearings"]),
    ("pivot-point", "Fixed point (3D)", "scene: {bodies: {NAME: {pivot_point: ...}}}",
     "derive.language.solid_file:PIVOT_POINT", ["derive.language.solid_file:pivot_point"]),
    ("rolls-on-edge", "Rolling on its edge (3D)", "scene: {bodies: {NAME: {rolls_on_edge: ...}}}",
     "derive.language.solid_file:ROLLS_ON_EDGE", ["derive.language.solid_file:rolls_on_edge"]),
    ("free-rotation", "Free rotation (3D)", "scene: {bodies: {NAME: {free_rotation: ...}}}",
     "derive.language.solid_file:FREE_ROTATION", ["derive.language.solid_file:free_rotation"]),
    ("orbit", "Orbit", "scene: {orbit: ...}", "derive.language.scene_file:ORBIT", []),
    ("standing-wave", "Standing wave", "scene: {standing_wave: ...}", "derive.language.scene_file:STANDING_WAVE", []),
    ("internal-forces", "Internal forces", "scene: {internal_forces: ...}",
     "derive.language.scene_file:INTERNAL_FORCES", []),
    ("set-file", "The set file", "a set file (problems/sets/)", "derive.language.problem_sets:SET",
     ["derive.language.problem_sets:load_set"]),
]
#: One page per module of derive.quantities, from its docstring: a quantity added there has its page (the
#: kinds of one module, the states' rates, on one page named after the first).
MODULES: dict[str, list[str]] = {}
for kind, quantity in QUANTITIES.items():
    MODULES.setdefault(type(quantity).__module__, []).append(kind)
PAGES += [(f"quantity-{kinds[0].replace('_', '-')}", f"Asking: {', '.join(k.replace('_', ' ') for k in kinds)}",
           "ask: {NAME: {of: ...}}", None, [module]) for module, kinds in MODULES.items()]
#: Where a page's part shows in a file's scene: (the scene's section, the key within an entry), to list
#: the library problems that use it.
USES = {"bodies": ("bodies", None), "surfaces": ("surfaces", None), "pin": ("joints", "pin"),
        "slider": ("joints", "slider"), "weld": ("joints", "weld"), "clutch": ("joints", "clutch"),
        "contact": ("joints", "touches"), "cord": ("cords", None), "string": ("constraints", "string"),
        "gravity": ("loads", "gravity"), "force": ("loads", "force"), "torque": ("loads", "torque"),
        "spring": ("loads", "spring"), "torsional-spring": ("loads", "torsional_spring"),
        "damper": ("loads", "damper"), "pull": ("loads", "pull"), "states": ("states", None),
        "bearings": ("bodies", "bearings"), "pivot-point": ("bodies", "pivot_point"),
        "rolls-on-edge": ("bodies", "rolls_on_edge"), "free-rotation": ("bodies", "free_rotation"),
        "orbit": ("orbit", None), "standing-wave": ("standing_wave", None), "internal-forces": ("internal_forces", None)}
SECTION = "Scene language"
INCLUDE = re.compile(r"^--8<-- (problem|file): (\S+)$", re.M)


def _lookup(reference: str):
    module, _, name = reference.partition(":")
    found = importlib.import_module(module)
    return getattr(found, name) if name else found


def _prose(reference: str) -> str:
    """A docstring as prose: up to its first example (`>>>`)."""
    text = inspect.getdoc(_lookup(reference)) or ""
    if not text:
        raise ValueError(f"{reference} has no docstring to document it with")
    return text.split("\n>>>")[0].strip()


def _cell(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def _table(keys: Keys, heading: str, level: int) -> list[str]:
    """The keys as a table, and a table of their own for each key whose value has keys."""
    lines = [f"{'#' * level} {heading}", "", "| key | required | value | meaning |", "|---|---|---|---|"]
    nested = []
    for name, key in keys.items():
        kind = _cell(KINDS[key.kind]) + (f"; one of {', '.join(f'`{c}`' for c in key.choices)}" if key.choices else "")
        lines.append(f"| `{name}` | {'yes' if key.required else ''} | {kind} | {_cell(key.meaning)} |")
        for what, inner in (("keys", key.keys), ("each entry", key.values), ("each item", key.items)):
            if isinstance(inner, Keys):
                nested.append((f"`{name}`: {what}", inner))
            elif isinstance(inner, Key):
                lines[-1] = lines[-1][:-2] + f"; {what}: {_cell(KINDS[inner.kind])} |"
    lines.append("")
    for title, inner in nested:
        lines += _table(inner, title, min(level + 1, 6))
    return lines


def _library() -> dict[str, dict]:
    """Each library problem's scene, read as derive reads YAML."""
    import yaml

    from derive.core.library import problem_files
    from derive.language.reader import Loader
    return {path.stem: yaml.load(path.read_text(encoding="utf-8"), Loader=Loader).get("scene") or {}  # noqa: S506
            for path in problem_files()}


def users(name: str, scenes: dict[str, dict]) -> list[str]:
    """The library problems whose scene uses the part of page `name`."""
    if name not in USES:
        return []
    section, key = USES[name]
    found = []
    for problem_id, scene in sorted(scenes.items()):
        entries = scene.get(section)
        if entries is None:
            continue
        entries = list(entries.values()) if isinstance(entries, dict) else entries  # named, or a list
        if key is None or any(isinstance(e, dict) and key in e for e in entries):
            found.append(problem_id)
    return found


def page(name: str, title: str, where: str, keys: str | None, docs: list[str], scenes: dict | None = None) -> str:
    """The Markdown of one generated page."""
    modules = sorted({d.partition(":")[0] for d in docs + ([keys] if keys else [])})
    lines = [f"# {title}", "",
             f"*Written:* `{where}`. *Read by:* {', '.join(f'`{m}`' for m in modules)}. This page is written "
             "from that code at every build of the documentation.", ""]
    for reference in docs:
        lines += [_prose(reference), ""]
    if name == "cord":
        from derive.parts import cord
        lines += ["## The elements of a path", "",
                  "Each element is a point (`block`, `rod.end`, `{rod: [x, y]}`, `[x, y]`, a ground point) or one of "
                  "the mappings below.", ""]
        lines += _table(cord.WOUND, "A wound end", 3) + _table(cord.PULLED, "A pulled end", 3)
        lines += _table(cord.AROUND["over"], "Around a body or a point on the way (`over`, `under`, `left`, "
                                             "`right`, `top` or `bottom`)", 3)
    elif name == "gravity":
        lines += ["## Value", "", "`gravity:` takes one expression, the field strength in m/s^2, along -y.", ""]
    elif keys:
        lines += _table(_lookup(keys), "Keys", 2)
    used = users(name, scenes or {})
    if used:
        lines += ["## In the library", "", "Problems of the library that use it (`derive solve ID` derives one; "
                  "`derive list` shows them all): " + ", ".join(f"`{u}`" for u in used) + ".", ""]
    return "\n".join(lines)


def on_config(config):
    """The generated pages, listed in the navigation's scene-language section after its overview."""
    for entry in config["nav"]:
        if isinstance(entry, dict) and SECTION in entry:
            entry[SECTION] += [{title: f"scene/{name}.md"} for name, title, *_ in PAGES]
    return config


def on_files(files, config):
    scenes = _library()
    for name, title, where, keys, docs in PAGES:
        files.append(File.generated(config, f"scene/{name}.md", content=page(name, title, where, keys, docs, scenes)))
    from derive.language.schema import problem_schema, set_schema
    for name, schema in (("problem", problem_schema()), ("set", set_schema())):
        files.append(File.generated(config, f"schema/{name}.json", content=json.dumps(schema, indent=1)))
    return files


def on_page_markdown(markdown, page, config, files):
    """`--8<-- problem: ID` in a page: the library problem's file, as YAML in a block of its own;
    `--8<-- file: PATH` (in a block already), the file of the documentation at PATH."""
    def included(match):
        kind, reference = match.groups()
        if kind == "file":
            return (Path(config["docs_dir"]) / reference).read_text(encoding="utf-8").rstrip()
        path = find_problem(reference)
        return f"```yaml\n{path.read_text(encoding='utf-8').rstrip()}\n```"
    return INCLUDE.sub(included, markdown)
