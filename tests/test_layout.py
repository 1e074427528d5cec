"""The package's layout is its architecture (docs/design.md, Layout): each layer a package of one
responsibility, said in its docstring; a module imports only from its own layer and the layers
below it, never up and never from a sibling of its layer; no import cycle among the modules; no
module over 600 lines. Imports inside functions count: a cycle hidden by a deferred import is
still a cycle."""
import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parent.parent / "derive"

#: The layers, lowest first, declared once. Packages on one line are siblings: neither imports the
#: other. The modules at the top of derive/ (the command line, the API, `derive check`'s table)
#: sit above every layer.
LAYERS = (
    ("core",),                    # errors, names, limits, expressions, units, where files are
    ("numbers", "text"),          # values to certified digits | words and math as LaTeX and text
    ("parts",),                   # the parts of a scene, each known to both routes
    ("model",),                   # bodies, inertia, the Scene, its coordinates
    ("quantities",),              # what a problem asks, one module per quantity, and how each computes it
    ("language", "mechanics"),    # problem and set files read | the derivations
    ("solution",),                # a problem solved: its answers, their conditions, steps and checks
    ("checks",),                  # simulations against the closed forms
    ("publishing",),              # sheets, keys, LMS exports, figures, reports
    ("bench",),                   # the benchmarks
)
TOP = ("derive", "derive.__main__", "derive.api", "derive.audit", "derive.cli", "derive.cli_options")
MAX_LINES = 600


def _modules() -> dict[str, Path]:
    found = {}
    for path in PACKAGE.rglob("*.py"):
        parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts.pop()
        found[".".join(parts)] = path
    return found


MODULES = _modules()


def _target(name: str) -> str | None:
    """The module `name` is or lies in (derive.a.b.C -> derive.a.b)."""
    while name and name not in MODULES:
        name = name.rpartition(".")[0]
    return name or None


def imports(module: str) -> set[str]:
    """The derive modules `module` imports, at its top or inside a function."""
    path = MODULES[module]
    found = set()
    for node in ast.walk(ast.parse(path.read_text(), str(path))):
        if isinstance(node, ast.Import):
            found |= {_target(a.name) for a in node.names if a.name.split(".")[0] == "derive"}
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                here = module.split(".") if path.name == "__init__.py" else module.split(".")[:-1]
                base = ".".join(here[:len(here) - node.level + 1] + ([base] if base else []))
            if base.split(".")[0] != "derive":
                continue
            found |= {_target(f"{base}.{a.name}") or _target(base) for a in node.names}
        elif (isinstance(node, ast.Call) and getattr(node.func, "attr", getattr(node.func, "id", None))
              in ("import_module", "_import_module") and node.args and isinstance(node.args[0], ast.Constant)
              and str(node.args[0].value).startswith("derive")):
            found.add(_target(node.args[0].value))
    return found - {None, module}


GRAPH = {m: imports(m) for m in MODULES}


def layer_of(module: str) -> tuple[int, str]:
    """(the layer's rank, its package); the top of derive/ ranks above every layer."""
    if module in TOP:
        return len(LAYERS), "derive"
    package = module.split(".")[1]
    for rank, siblings in enumerate(LAYERS):
        if package in siblings:
            return rank, package
    raise AssertionError(f"{module} is in no layer: put it in a layer's package (LAYERS)")


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan)."""
    index, low, stack, on, found, counter = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def violations(graph: dict[str, set[str]]) -> list[str]:
    """Every import up a layer, or across to a sibling of its layer."""
    found = []
    for module, targets in sorted(graph.items()):
        rank, package = layer_of(module)
        for target in sorted(targets):
            to_rank, to_package = layer_of(target)
            if to_rank > rank:
                found.append(f"{module} imports {target}, a higher layer")
            elif to_rank == rank and to_package != package:
                found.append(f"{module} imports {target}, a sibling of its layer")
    return found


def test_every_module_is_in_a_layer():
    for module in MODULES:
        layer_of(module)


def test_no_import_cycles():
    assert cycles(GRAPH) == []


def test_imports_go_down_the_layers():
    assert violations(GRAPH) == []


def test_the_checks_catch_a_planted_upward_import_and_a_cycle():
    planted = {**GRAPH, "derive.core.units": GRAPH["derive.core.units"] | {"derive.publishing.report"}}
    assert violations(planted) == ["derive.core.units imports derive.publishing.report, a higher layer"]
    sideways = {**GRAPH, "derive.language.reader": GRAPH["derive.language.reader"] | {"derive.mechanics.states"}}
    assert violations(sideways) == ["derive.language.reader imports derive.mechanics.states, a sibling of its layer"]
    looped = {**GRAPH, "derive.core.expr": GRAPH["derive.core.expr"] | {"derive.core.units"}}
    assert cycles(looped) == [["derive.core.expr", "derive.core.units"]]


def test_a_function_level_import_counts():
    assert "derive.mechanics.kinematics" not in MODULES  # the layers' own names, not the old ones
    assert "derive.model.kinematics" in GRAPH["derive.language.scene_file"]  # imported inside a function


@pytest.mark.parametrize("package", sorted({m for m in MODULES if MODULES[m].name == "__init__.py"}))
def test_each_package_says_what_it_is(package):
    assert ast.get_docstring(ast.parse(MODULES[package].read_text())), f"{package} has no docstring"


def test_the_layers_are_the_packages():
    declared = {p for siblings in LAYERS for p in siblings}
    folders = {p.name for p in PACKAGE.iterdir() if (p / "__init__.py").exists()}
    assert folders == declared


@pytest.mark.parametrize("module", sorted(MODULES))
def test_no_module_is_over_600_lines(module):
    lines = MODULES[module].read_text().count("\n")
    assert lines <= MAX_LINES, f"{module}: {lines} lines (at most {MAX_LINES}: split it along a responsibility)"
