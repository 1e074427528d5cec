"""The documentation site (mkdocs.yml, docs/): it builds with `mkdocs build --strict` (a warning or
a broken internal link fails), every part of the scene language has its page written from its
code, every command of the tutorial runs and prints what the tutorial says, every cookbook
problem solves, and the README stays short and names the commands CI runs."""
from __future__ import annotations

import importlib.util
import json
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
import yaml
from click.testing import CliRunner

from derive.cli import main
from derive.language import scene_file

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"


def _hooks():
    spec = importlib.util.spec_from_file_location("docs_hooks", DOCS / "hooks.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _build(config: Path, site: Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "--config-file", str(config),
                           "--site-dir", str(site)], capture_output=True, text=True, cwd=config.parent, timeout=600)


@pytest.fixture(scope="module")
def site(tmp_path_factory):
    site = tmp_path_factory.mktemp("site")
    built = _build(ROOT / "mkdocs.yml", site)
    assert built.returncode == 0, built.stderr[-3000:]
    assert "WARNING" not in built.stderr, built.stderr[-3000:]
    return site


def test_the_site_builds_with_every_page(site):
    pages = sorted(p.relative_to(site) for p in site.rglob("*.html") if p.name != "404.html")
    assert len(pages) >= 40, pages
    for name, *_ in _hooks().PAGES:
        assert (site / "scene" / f"{name}.html").is_file(), name
    for page in ("tutorial.html", "lms.html", "design.html", "reference/cli.html", "reference/api.html",
                 "reference/schema.html", "scene/index.html"):
        assert (site / page).is_file(), page
    assert (site / "schema" / "problem.json").is_file() and (site / "schema" / "set.json").is_file()


def test_a_part_page_lists_the_keys_its_code_reads(site):
    from derive.parts import spring, torque
    for name, keys in (("spring", spring.KEYS), ("torque", torque.KEYS)):
        text = (site / "scene" / f"{name}.html").read_text(encoding="utf-8")
        for key in keys:
            assert f"<code>{key}</code>" in text, (name, key)
        assert keys[next(iter(keys))].meaning.split(",")[0] in text
    pull = (site / "scene" / "pull.html").read_text(encoding="utf-8")
    assert "In the library" in pull and "<code>tugged_spool</code>" in pull  # the problems that use it


def test_the_cli_page_is_clicks_help(site):
    text = (site / "reference" / "cli.html").read_text(encoding="utf-8")
    for command in main.commands:
        assert f'id="derive-{command}"' in text, command


def test_every_part_of_the_scene_has_a_page():
    documented = set()
    for _, _, _, keys, docs in _hooks().PAGES:
        documented |= {r.partition(":")[0] for r in docs + ([keys] if keys else [])}
    for module in (*scene_file.JOINTS.values(), *scene_file.LOADS.values()):
        assert module.__name__ in documented, module.__name__
    sections = {where.split("{")[1].split(":")[0].strip() for _, _, where, *_ in _hooks().PAGES if "scene: {" in where}
    assert set(scene_file.SCENE) - {"joints", "loads"} <= sections | {"points"}, set(scene_file.SCENE) - sections


def test_a_broken_internal_link_fails_the_build(tmp_path):
    shutil.copytree(DOCS, tmp_path / "docs")
    (tmp_path / "docs" / "index.md").write_text("# derive\n\n[gone](no-such-page.md)\n", encoding="utf-8")
    config = yaml.safe_load((ROOT / "mkdocs.yml").read_text(encoding="utf-8"))
    config["hooks"] = [str(tmp_path / "docs" / "hooks.py")]
    config["plugins"][1]["mkdocstrings"]["handlers"]["python"]["paths"] = [str(ROOT)]
    (tmp_path / "mkdocs.yml").write_text(yaml.safe_dump(config), encoding="utf-8")
    built = _build(tmp_path / "mkdocs.yml", tmp_path / "site")
    assert built.returncode != 0 and "no-such-page.md" in built.stderr


def _commands(page: Path) -> list[str]:
    blocks = re.findall(r"```sh\n(.*?)```", page.read_text(encoding="utf-8"), re.S)
    return [line.split("#")[0].strip() for block in blocks for line in block.splitlines() if line.strip()]


def test_every_command_of_the_tutorial_runs(tmp_path):
    shutil.copy(DOCS / "tutorial" / "sphere.yaml", tmp_path / "sphere.yaml")
    commands = _commands(DOCS / "tutorial.md")
    assert [c.split()[:2] for c in commands] == [["derive", "schema"], ["derive", "solve"], ["derive", "solve"],
                                                  ["derive", "sheet"]]
    printed = []
    for command in commands:
        words = shlex.split(command)
        out = None
        if ">" in words:
            words, out = words[:words.index(">")], words[words.index(">") + 1]
        run = subprocess.run([sys.executable, "-m", "derive", *words[1:]], capture_output=True, text=True,
                             cwd=tmp_path, timeout=600)
        assert run.returncode == 0, (command, run.stderr[-2000:])
        if out:
            (tmp_path / out).write_text(run.stdout, encoding="utf-8")
        printed.append(run.stdout)
    import jsonschema
    from derive.language.reader import safe_load
    jsonschema.validate(safe_load((tmp_path / "sphere.yaml").read_text(encoding="utf-8")),
                        json.loads((tmp_path / "problem.schema.json").read_text(encoding="utf-8")))
    text = (DOCS / "tutorial.md").read_text(encoding="utf-8")
    assert "a = 5 g sin(θ)/7" in text and "3.5 m/s²" in text and "3.7 m/s" in text
    assert "5⋅g⋅sin(θ)" in printed[1] and "a = ──────────  [m/s²]" in printed[1]
    assert "= 3.5 m/s²" in printed[2] and "= 3.7 m/s" in printed[2]
    built = tmp_path / "build" / "sphere"
    for name in ("worksheet.pdf", "worksheet-3.pdf", "solutions.pdf", "key.pdf", "key.csv", "key.json"):
        assert (built / name).is_file(), name
    moodle = (built / "moodle.xml").read_text(encoding="utf-8")
    assert moodle.count('<question type="cloze">') == 3 and "$course$/derive/my_sphere/my_sphere" in moodle


def _cookbook_ids() -> list[str]:
    include = _hooks().INCLUDE
    return [reference for page in sorted((DOCS / "cookbook").glob("*.md"))
            for kind, reference in include.findall(page.read_text(encoding="utf-8")) if kind == "problem"]


def test_the_cookbook_has_its_pages():
    ids = _cookbook_ids()
    assert len(ids) >= 8 and len(set(ids)) == len(ids)
    index = (DOCS / "cookbook" / "index.md").read_text(encoding="utf-8")
    for page in (DOCS / "cookbook").glob("*.md"):
        assert page.name == "index.md" or f"({page.name})" in index, page.name


@pytest.mark.parametrize("problem_id", _cookbook_ids())
def test_every_cookbook_problem_solves(problem_id):
    solved = CliRunner().invoke(main, ["solve", problem_id])
    assert solved.exit_code == 0, solved.output
    assert "[FAIL]" not in solved.output and "Answers:" in solved.output


def test_the_readme_is_short_and_names_what_ci_runs():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert len(readme.split()) < 1500, len(readme.split())
    assert "make test" in (ROOT / ".ci" / "run").read_text(encoding="utf-8")
    assert "make test" in readme and "make setup" in readme
    for target in re.findall(r"\]\((docs/[^)#]+)", readme):
        assert (ROOT / target).is_file(), target
    assert max(len(line) for line in readme.splitlines()) < 200
