"""The Python API (derive.load, derive.solve, derive.sheet): the command line's results and
errors, math in Jupyter, and the example notebook run by a real kernel."""
import json
import os
import re
import subprocess
import sys

import lxml.etree
import lxml.html
import nbformat
import pytest
from nbclient import NotebookClient

import sympy as sp
from decimal import Decimal

import derive
from conftest import ROOT, run_derive, write_problem
from derive.core.errors import InputError
from test_hardening import problem_text

NOTEBOOK = ROOT / "docs" / "examples" / "api.ipynb"


def test_import_stays_light_and_the_api_loads_on_use():
    code = ("import sys, derive; light = 'sympy' not in sys.modules; "
            "solve, load, sheet = derive.solve, derive.load, derive.sheet; "
            "from derive import api; "
            "print(light, 'sympy' in sys.modules, callable(sheet), sheet is api.sheet)")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    assert result.stdout.split() == ["True", "True", "True", "True"], result.stderr


def test_solve_gives_what_derive_solve_prints():
    cli = run_derive("solve", "string_wrapped_disk", "--set", "m=2", "--set", "M=4", "--set", "R=30 cm",
                     "--format", "json", "--digits", "6")
    assert cli.returncode == 0, cli.stderr
    result = derive.solve(derive.load("string_wrapped_disk"), {"m": 2, "M": 4, "R": "30 cm"}, digits=6)
    assert result.report == json.loads(cli.stdout)
    assert result.as_json() == cli.stdout.rstrip("\n")
    a = result["a"]
    assert (a.text, a.unit, str(a.expression)) == ("-4.90500", "m/s^2", "-2*g*m/(M + 2*m)")
    assert a.value == Decimal("-4.90500") and str(a.value) == "-4.90500"  # the digits asked, kept
    assert result.at({"m": "500 g"})["a"].value == derive.solve("string_wrapped_disk", {"m": 0.5, "M": 4, "R": 0.3},
                                                                 digits=6)["a"].value


def test_answers_are_sympy_in_the_problems_own_symbols():
    result = derive.solve("string_wrapped_disk", {"m": 2, "M": 4, "R": 0.3})
    s = result.symbols
    assert sp.simplify(result["a"].expression + 2 * s.g * s.m / (s.M + 2 * s.m)) == 0
    plain = sp.symbols("g m M")  # no assumptions: sympy holds them to be other symbols
    assert sp.simplify(result["a"].expression + 2 * plain[0] * plain[1] / (plain[2] + 2 * plain[1])) != 0
    assert {n for n in vars(s)} == {"m", "M", "R", "g"} and s.M.is_positive
    assert result.symbols == result.problem.symbols
    for route in ("lagrange", "newton_euler"):
        assert result.equations[route] and all(isinstance(e, sp.Eq) for e in result.equations[route])
    assert [sp.sstr(e) for e in result.equations["newton_euler"]] == result.report["equations_of_motion"]["newton_euler"]
    assert derive.solve("rod_endpoint").equations == {}  # nothing moves


def test_an_answer_with_a_direction_is_a_magnitude_and_words():
    result = derive.solve("rolling_incline", {"M": 2, "R": 0.1, "H": 1, "theta": 0.5, "mu_s": 0.5}, digits=4)
    along = next(a for a in result.answers.values() if a.direction)
    assert along.value > 0 and along.direction in repr(along)
    assert f"{along.name} = {along.text} {along.unit} {along.direction}" in repr(result)  # "a = 3.36 m/s^2 down the slope"
    assert along.direction == result.report["answers"][along.name]["direction"]


def test_a_problem_built_in_python_is_a_files_problem(tmp_path):
    text = (ROOT / "problems").rglob("rod_endpoint.yaml").__next__().read_text()
    import yaml
    mapping = yaml.safe_load(text)
    from_python, from_file = derive.solve(mapping, digits=6), derive.solve("rod_endpoint", digits=6)
    assert from_python.report["answers"] == from_file.report["answers"]
    assert from_python.problem.path.name == "<python>"
    with pytest.raises(derive.core.errors.ProblemError, match=r"^<python>: parameters\.m\.sig_figs: "):
        derive.load({**mapping, "parameters": {**mapping["parameters"], "m": {**mapping["parameters"]["m"], "sig_figs": 0}}})
    with pytest.raises(InputError, match=r"^<python>: parameters\.m\.value: expected text, a number, .* got Symbol"):
        derive.load({**mapping, "parameters": {**mapping["parameters"], "m": {**mapping["parameters"]["m"],
                                                                           "value": sp.Symbol("x")}}})


def test_figures_show_as_svg_in_jupyter(tmp_path):
    result = derive.solve("string_wrapped_disk")
    figure = result.figure
    tree = lxml.etree.fromstring(figure._repr_svg_().encode())
    assert tree.tag == "{http://www.w3.org/2000/svg}svg" and len(tree.findall(".//{*}path")) > 5
    assert set(result.free_bodies) == {"disk", "block"}
    assert result.free_bodies["block"].alt.startswith("Free-body diagram of the block: ")
    assert result.free_bodies["disk"].svg != figure.svg
    saved = figure.save(tmp_path / "disk.svg")
    assert saved.read_text() == figure.svg
    assert derive.solve("rod_endpoint").free_bodies == {}  # no dynamics: no balance of forces drawn


def test_solutions_and_answers_show_as_math():
    result = derive.solve("string_wrapped_disk", {"m": 2, "M": 4}, digits=4)  # R has no value: alpha has none
    latex = result._repr_latex_()
    assert latex.startswith("$$\\begin{aligned}") and latex.endswith("\\end{aligned}$$")
    assert "a &= - g \\frac{2 m}{M + 2 m} = -4.905\\,\\mathrm{m}/\\mathrm{s}^{2} \\\\" in latex
    assert "\\alpha &= - \\frac{g}{R} \\frac{2 m}{M + 2 m} \\\\" in latex  # no value without R
    assert "&\\text{at } M = 4.000\\,\\mathrm{kg}, m = 2.000\\,\\mathrm{kg}, g = 9.810" in latex
    page = lxml.html.fragment_fromstring(result._repr_html_())
    rows = [[cell.text_content() for cell in row] for row in page.iter("tr")]
    assert rows[0] == ["acceleration of the block (y up)",
                       "\\(a = - g \\frac{2 m}{M + 2 m} = -4.905\\,\\mathrm{m}/\\mathrm{s}^{2}\\)"]
    assert [row[0] for row in rows] == [result[n].meaning for n in ("a", "alpha", "T")]
    assert result["T"]._repr_latex_() == "$$T = g m \\frac{M}{M + 2 m} = 9.810\\,\\mathrm{N}$$"


def test_html_shows_a_files_text_as_written(tmp_path):
    title, meaning = "Disk <script>alert(1)</script> & co", "inertia <b>about</b> z & 'more'"
    path = write_problem(tmp_path, problem_text(title=title, ask_meaning=meaning))
    result = derive.solve(path, {"M": 2})
    page = lxml.html.fragment_fromstring(result._repr_html_())
    assert not list(page.iter("script", "b"))
    assert title in page.text_content() and meaning in page.text_content()
    answer = lxml.html.fragment_fromstring(result["I"]._repr_html_())
    assert answer.text_content().startswith(f"{meaning}: \\(I = ")


@pytest.mark.parametrize("cli, call", [
    (["solve", "string_wraped_disk"], lambda: derive.load("string_wraped_disk")),
    (["solve", "string_wrapped_disk", "--set", "q=1"], lambda: derive.solve("string_wrapped_disk", {"q": 1})),
    (["solve", "string_wrapped_disk", "--set", "m=2 s"], lambda: derive.solve("string_wrapped_disk", {"m": "2 s"})),
    (["solve", "string_wrapped_disk", "--set", "m=-1"], lambda: derive.solve("string_wrapped_disk", {"m": -1})),
    (["sheet", "no_such_set"], lambda: derive.sheet("no_such_set")),
    (["sheet", "demo", "--to", "pdf,pfd"], lambda: derive.sheet("demo", to=["pdf", "pfd"])),
])
def test_errors_are_the_command_lines(cli, call):
    result = run_derive(*cli)
    assert result.returncode == 2, result.stderr
    with pytest.raises(InputError) as error:
        call()
    assert result.stderr == f"derive: error: {error.value}\n"


@pytest.mark.parametrize("call, message", [
    (lambda: derive.solve("rod_endpoint", ["m=2"]), "values: expected a mapping of parameter names"),
    (lambda: derive.solve("rod_endpoint", digits=0), "digits: expected a whole number from 1 to 50, got 0"),
    (lambda: derive.sheet(["rod_endpoint", "rod_endpont"]),
     "derive.sheet: problems[1]: no problem file or library id 'rod_endpont' (see `derive list`); "
     "did you mean 'rod_endpoint'?"),
    (lambda: derive.sheet([]), "derive.sheet: problems: expected a list of problem ids"),
    (lambda: derive.sheet("demo", title="Week 3"), "title: a set file gives its own title"),
    (lambda: derive.sheet(["rod_endpoint"], title="\\input{x}"), "derive.sheet: title: "),
    (lambda: derive.sheet(["rod_endpoint"], variants=True), "variants: expected a whole number from 1 to 1000"),
    (lambda: derive.sheet(["rod_endpoint"], questions="essay"), "questions: expected one of numerical, choice"),
    (lambda: derive.sheet(["rod_endpoint"], progress="loud"), "progress: expected one of auto, bar, lines, none"),
    (lambda: derive.sheet(42), "ids_or_set: expected a set file or id, or a list of problem ids or files"),
])
def test_the_apis_own_arguments_are_checked(call, message):
    with pytest.raises(InputError, match="^" + re.escape(message)):
        call()


def test_sheet_of_listed_problems_builds_as_a_set_file_does(tmp_path):
    set_file = tmp_path / "week.yaml"
    set_file.write_text("title: Problems\nproblems: [rod_endpoint, {topic: rolling, count: 1}]\nvariants: 2\n")
    cli = run_derive("sheet", str(set_file), "--out", str(tmp_path / "cli"), "--to", "", "--progress", "none")
    assert cli.returncode == 0, cli.stderr
    files = derive.sheet(["rod_endpoint", {"topic": "rolling", "count": 1}], tmp_path / "api", variants=2, to=[],
                         progress="none")
    assert sorted(f.name for f in files) == ["key.csv", "key.json", "key.tex", "solutions.tex", "worksheet.tex"]
    for name in ("key.csv", "solutions.tex", "worksheet.tex"):
        assert (tmp_path / "api" / name).read_text() == (tmp_path / "cli" / name).read_text(), name
    api_key, cli_key = (json.loads((tmp_path / side / "key.json").read_text()) for side in ("api", "cli"))
    assert api_key.pop("set") == "problems" and cli_key.pop("set") == "week"
    assert api_key == cli_key


def test_example_notebook_runs_and_shows_math(tmp_path):
    """docs/examples/api.ipynb in a kernel of this virtual environment (ipykernel installed in it,
    this checkout first on its path), with the bundles Jupyter displays."""
    notebook = nbformat.read(NOTEBOOK, as_version=4)
    notebook.cells.append(nbformat.v4.new_code_cell("import sys\nprint(sys.prefix)\nprint(derive.__file__)"))
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(filter(None, [str(ROOT), os.environ.get("PYTHONPATH")]))}
    NotebookClient(notebook, kernel_name="python3", timeout=600,
                   resources={"metadata": {"path": str(tmp_path)}}).execute(env=env)
    code = [cell for cell in notebook.cells if cell.cell_type == "code"]
    outputs = {cell.source.splitlines()[-1]: cell.outputs for cell in code}
    assert outputs["problem.title"][0]["data"]["text/plain"] == "'A string wrapped around a disk'"

    solved = outputs["result"][0]["data"]
    assert solved["text/latex"] == derive.solve("string_wrapped_disk", {"m": 2, "M": 4, "R": 0.3}, 4)._repr_latex_()
    assert "T &= g m \\frac{M}{M + 2 m} = 9.810\\,\\mathrm{N}" in solved["text/latex"]
    html = lxml.html.fragment_fromstring(solved["text/html"])
    assert "\\(\\alpha = - \\frac{g}{R} \\frac{2 m}{M + 2 m} = -16.35" in html.text_content()
    assert solved["text/plain"].startswith("Result(string_wrapped_disk: a = -4.905 m/s^2")

    answer = outputs['result["a"]'][0]["data"]
    assert answer["text/latex"] == "$$a = - g \\frac{2 m}{M + 2 m} = -4.905\\,\\mathrm{m}/\\mathrm{s}^{2}$$"
    assert answer["text/html"].startswith("<p>acceleration of the block (y up): \\(a = ")
    assert outputs["T.value, T.text"][0]["data"]["text/plain"] == "(Decimal('6.540'), '6.540')"
    assert outputs['sp.simplify(result["a"].expression - (-2 * s.g * s.m / (s.M + 2 * s.m)))'][0]["data"]["text/plain"] == "0"
    assert outputs['result.equations["newton_euler"][:3]'][0]["data"]["text/plain"].startswith("[Eq(")
    for shown in ("result.figure", 'result.free_bodies["disk"]'):
        assert outputs[shown][0]["data"]["image/svg+xml"].lstrip().startswith("<?xml"), shown
    assert outputs['derive.solve(rod, digits=3)["I"]'][0]["data"]["text/plain"] == "Answer(I = L**2*m/3 = 0.667 kg*m^2)"
    lighter = outputs['result.at({"m": 1})["T"]'][0]["data"]
    assert lighter["text/latex"] == "$$T = g m \\frac{M}{M + 2 m} = 6.540\\,\\mathrm{N}$$"
    built = outputs["sorted(path.name for path in files)"][0]["data"]["text/plain"]
    assert built == "['key.csv', 'key.json', 'key.tex', 'solutions.tex', 'worksheet.tex']"
    assert (tmp_path / "build" / "notebook-sheet" / "key.json").is_file()

    prefix, module = code[-1].outputs[0]["text"].split()
    assert prefix == sys.prefix and module == str(ROOT / "derive" / "__init__.py")
