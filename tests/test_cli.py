"""The command-line contract of DESIGN.md: solve, inertia, list, exit codes, start-up."""
import json
import shutil
import subprocess
import sys

import mpmath
import pytest

from conftest import ROOT, close, refused, run_derive
from derive.language.problem import load


def close_to_digits(value: str, reference, digits: int = 15) -> bool:
    """A decimal string is correct to `digits` significant digits: within half a unit of the last."""
    return close(mpmath.mpf(value), mpmath.mpf(reference), digits)


def solve_json(derive, problem, *assignments, digits=15):
    args = ["solve", problem, "--format", "json", "--digits", str(digits)]
    for a in assignments:
        args += ["--set", a]
    done = derive(*args)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


@pytest.mark.parametrize("m, M", [("1.3", "2.9"), ("1e-12", "1"), ("1e12", "1"), ("0.999999999999", "1.000000000001")])
def test_disk_values_correct_to_15_digits(derive, m, M):
    result = solve_json(derive, "string_wrapped_disk", f"m={m}", f"M={M}", "R=0.37")
    mm, MM, g, R = mpmath.mpf(m), mpmath.mpf(M), mpmath.mpf("9.81"), mpmath.mpf("0.37")
    answers = result["answers"]
    assert close_to_digits(answers["a"]["value"], -2 * mm * g / (MM + 2 * mm))
    assert close_to_digits(answers["alpha"]["value"], -2 * mm * g / (R * (MM + 2 * mm)))
    assert close_to_digits(answers["T"]["value"], mm * g * MM / (MM + 2 * mm))
    assert result["checks"]["lagrange_vs_newton_euler"]["passed"] is True


def test_json_contract_keys(derive):
    result = solve_json(derive, "string_wrapped_disk")
    assert {"id", "title", "parameters", "answers", "equations_of_motion", "checks"} <= set(result)
    a = result["answers"]["a"]
    assert set(a) >= {"expr", "latex", "unit", "value"}
    assert a["value"] is None  # m, M, R have no value: only g does
    assert a["expr"] == "-2*g*m/(M + 2*m)"
    assert set(result["equations_of_motion"]) == {"lagrange", "newton_euler"}


def test_pendulum_values(derive):
    result = solve_json(derive, "compound_pendulum", "M=2", "Rcm=0.3", "I_cm=0.05", digits=20)
    omega = mpmath.sqrt(2 * mpmath.mpf("0.3") * mpmath.mpf("9.81") / (mpmath.mpf("0.05") + 2 * mpmath.mpf("0.09")))
    assert close_to_digits(result["answers"]["omega"]["value"], omega, 20)
    assert close_to_digits(result["answers"]["T"]["value"], 2 * mpmath.pi / omega, 20)


def test_set_converts_units(derive):
    grams = solve_json(derive, "string_wrapped_disk", "m=200 g", "M=1", "R=0.2")
    kilograms = solve_json(derive, "string_wrapped_disk", "m=0.2", "M=1", "R=0.2")
    assert grams["answers"] == kilograms["answers"]
    assert grams["parameters"]["m"]["value"] == "0.200000000000000"


def test_rod_inertia_values(derive):
    mid = solve_json(derive, "rod_midpoint", "m=3", "L=2")
    end = solve_json(derive, "rod_endpoint", "m=3", "L=2")
    assert mid["answers"]["I"]["value"] == "1.00000000000000"
    assert end["answers"]["I"]["value"] == "4.00000000000000"
    assert end["checks"]["parallel_axis"]["passed"] is True


def test_text_and_latex_formats(derive):
    text = derive("solve", "string_wrapped_disk", "--set", "m=1", "--set", "M=2", "--set", "R=0.5")
    assert text.returncode == 0
    assert "The solution, as a textbook writes it" in text.stdout and "Equations of motion" not in text.stdout
    proof = derive("solve", "string_wrapped_disk", "--set", "m=1", "--set", "M=2", "--set", "R=0.5", "--proof")
    assert "Equations of motion, Newton–Euler" in proof.stdout
    lines = text.stdout.splitlines()
    at = lines.index("           2⋅m")  # sympy's unicode pretty-printer: the fraction over three lines
    assert lines[at + 1:at + 3] == ["  a = -g⋅─────── = -4.90 m/s²", "         M + 2⋅m"]  # the inputs' 3 figures
    assert "**" not in text.stdout and "m/s^2" not in text.stdout
    assert "[ok] dimensions: Every answer has the units it should: a in m/s², alpha in rad/s², T in N." in text.stdout
    six = derive("solve", "string_wrapped_disk", "--set", "m=1", "--set", "M=2", "--set", "R=0.5", "--digits", "6")
    assert "  a = -g⋅─────── = -4.90500 m/s²" in six.stdout
    latex = derive("solve", str(ROOT / "problems/torque/compound_pendulum.yaml"), "--format", "latex")
    assert latex.returncode == 0 and r"\begin{align*}" in latex.stdout and r"\omega" in latex.stdout


def test_inertia_command(derive):
    done = derive("inertia", "rod", "--axis", "end", "--set", "M=2", "--set", "L=3", "--format", "json")
    assert done.returncode == 0, done.stderr
    result = json.loads(done.stdout)
    assert result["I"] == "L**2*M/3" and result["ratio"] == "1/3" and result["value"] == "6.00000000000000"
    assert r"\int" in result["integral"]
    assert derive("inertia", "cube").returncode == 2


def test_inertia_text_is_drawn_math_not_latex_source(derive):
    done = derive("inertia", "rod", "--axis", "end", "--set", "M=2", "--set", "L=3", "--tensor")
    assert done.returncode == 0, done.stderr
    assert "\\" not in done.stdout and "**" not in done.stdout and "⌠" in done.stdout  # an integral sign
    assert "value: I = 6.00000000000000 kg·m²" in done.stdout and "⎡" in done.stdout  # the tensor as a matrix


def test_list(derive):
    done = derive("list")
    assert done.returncode == 0
    titles = {line.index(title) for line in done.stdout.splitlines() for title in [line.split(None, 3)[3]]}
    assert len(titles) == 1  # the titles in one column
    ids = [line.split()[0] for line in done.stdout.splitlines()]
    assert {"rod_midpoint", "rod_endpoint", "string_wrapped_disk", "compound_pendulum", "yoyo_falls"} <= set(ids)
    assert len(ids) == len(set(ids)) >= 150  # the lecture notes' problems and the textbook setups, each id once
    torque = derive("list", "--topic", "torque").stdout
    assert "string_wrapped_disk" in torque and "rod_midpoint" not in torque


@pytest.mark.parametrize("args, fragment", [
    (["solve", "no_such_problem"], "no problem file or library id"),
    (["solve", "string_wrapped_disk", "--set", "m"], "expected NAME=VALUE"),
    (["solve", "string_wrapped_disk", "--set", "q=2"], "has no parameter 'q'"),
    (["solve", "string_wrapped_disk", "--set", "m=2 m"], "m=2 m"),
    (["solve", "string_wrapped_disk", "--set", "m=__import__('os')"], "m="),
    (["solve", "missing/file.yaml"], "no such problem file"),
    (["solve", "beetle_lazy_susan", "--set", "v=-0.15"], "v must be positive"),
])
def test_bad_command_line_input_exits_2_with_one_line(derive, args, fragment):
    done = derive(*args)
    assert done.returncode == 2
    assert len(done.stderr.strip().splitlines()) == 1, done.stderr
    assert fragment in done.stderr


def test_every_subcommand_has_help(derive):
    for command in ("solve", "inertia", "sheet", "list"):
        done = derive(command, "--help")
        assert done.returncode == 0 and "Usage" in done.stdout
    assert derive("--version").stdout.strip().endswith("0.1.0")


def test_help_does_not_import_sympy():
    code = ("import sys\nfrom derive.cli import main\ntry:\n    main(['--help'])\nexcept SystemExit:\n    pass\n"
            "print('sympy' in sys.modules, 'yaml' in sys.modules)")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.stdout.strip().splitlines()[-1] == "False False"


def test_output_into_a_closed_pipe_stops_quietly():
    from conftest import DERIVE
    done = subprocess.run(f"{DERIVE} list | head -1", shell=True, capture_output=True, text=True)
    assert done.stdout.count("\n") == 1 and "Error" not in done.stderr and "error" not in done.stderr


# --- the command line and the package (issue 16, item 6) ---

def _key(folder):
    return json.loads((folder / "key.json").read_text())


def test_sheet_builds_problems_without_a_set_file(tmp_path):
    one = run_derive("sheet", "rod_endpoint", "--to", "", cwd=tmp_path)  # default folder: build/<id>
    assert one.returncode == 0, one.stderr
    key = _key(tmp_path / "build" / "rod_endpoint")
    assert key["set"] == "rod_endpoint" and key["title"] == "Moment of inertia of a rod about its endpoint"
    assert [list(v["problems"]) for v in key["variants"]] == [["rod_endpoint"]]  # one variant
    two = run_derive("sheet", "rod_endpoint", str(ROOT / "problems/torque/string_wrapped_disk.yaml"), "--variants", "2",
                     "--to", "", "--out", str(tmp_path / "two"))
    assert two.returncode == 0, two.stderr
    key = _key(tmp_path / "two")
    assert key["set"] == "rod_endpoint-string_wrapped_disk" and len(key["variants"]) == 2
    assert list(key["variants"][1]["problems"]) == ["rod_endpoint", "string_wrapped_disk"]
    assert "A string wrapped around a disk" in key["title"]


def test_sheet_of_a_set_file_is_unchanged(tmp_path):
    week = tmp_path / "week.yaml"
    week.write_text("title: Week 9\nproblems: [rod_endpoint]\ncourse: PHY141\n")
    done = run_derive("sheet", str(week), "--to", "", "--out", str(tmp_path / "out"))
    assert done.returncode == 0, done.stderr
    assert _key(tmp_path / "out")["title"] == "Week 9" and "PHY141" in (tmp_path / "out/worksheet.tex").read_text()


@pytest.mark.parametrize("args, fragment", [
    (["sheet", "rod_endpoint", "demo"], "demo is a set: a set is built by itself"),
    (["sheet", "rod_endpoint", "rod_endpoint"], "argument 2: rod_endpoint is already argument 1"),
    (["sheet"], "Missing argument"),
])
def test_sheet_of_problems_refuses(args, fragment):
    done = run_derive(*args)
    assert done.returncode == 2 and fragment in done.stderr and len(done.stderr.strip().splitlines()) == 1, done.stderr


@pytest.mark.parametrize("args, suggestion", [
    (["solve", "rod_endpiont"], "did you mean 'rod_endpoint'?"),  # a library id
    (["sheet", "dmeo"], "did you mean 'demo'?"),  # a set id
    (["inertia", "cylindr"], "did you mean 'cylinder'?"),  # a shape
    (["inertia", "rod", "--axis", "ned"], "did you mean 'end'?"),  # an axis
    (["solve", "string_wrapped_disk", "--set", "MM=2"], "did you mean 'M'?"),  # a parameter
    (["solve", "string_wrapped_disk", "--set", "m=2 kgg"], "did you mean 'kg'?"),  # a unit
    (["sheet", "demo", "--to", "pfd"], "did you mean 'pdf'?"),  # an output
])
def test_did_you_mean_on_the_command_line(args, suggestion):
    done = run_derive(*args)
    assert done.returncode == 2 and len(done.stderr.strip().splitlines()) == 1, done.stderr
    assert done.stderr.strip().endswith(suggestion), done.stderr


DISK = (ROOT / "problems/torque/string_wrapped_disk.yaml").read_text()


@pytest.mark.parametrize("old, new, field, suggestion", [
    ("shape: disk,", "shape: disc,", "scene.bodies.disk.shape", "'disk'"),  # a shape
    ("mass: M,", "mas: M,", "scene.bodies.disk.mas", "'mass'"),  # a key of a body
    ("ask:", "asks:", "asks", "'ask'"),  # a top-level key
    ("- gravity: g", "- gravty: g", "scene.loads[0].gravty", "'gravity'"),  # a part (a load)
    ("hangs: block", "hangs: blok", "scene.constraints", "'block'"),  # a body
    ("of: block.acceleration.y", "of: blok.acceleration.y", "ask.a.of", "'block'"),  # a body an ask names
    ("shape: disk,", "shape: cylinder, length: R,", "scene.bodies.disk.length", "'height'"),  # another word for a size
    ("of: block.acceleration.y", "of: block.acceleraton.y", "ask.a.of", "'acceleration.y'"),  # what a body has
    ("of: string.tension", "of: string.tensoin", "ask.T.of", "'tension'"),  # what a part has (a trial's typo)
])
def test_did_you_mean_in_problem_files(tmp_path, old, new, field, suggestion):
    assert old in DISK
    stderr = refused(tmp_path, DISK.replace(old, new, 1), field)
    assert stderr.strip().endswith(f"did you mean {suggestion}?"), stderr


def test_did_you_mean_for_joints_and_points(tmp_path):
    text = DISK.replace("joint: fixed_axle}", "}").replace("  constraints:", "  joints:\n    axle: {pinn: disk.centre}\n"
                                                                               "  constraints:")
    assert refused(tmp_path, text, "scene.joints.axle").strip().endswith("did you mean 'pin'?")
    text = text.replace("pinn:", "pin:")
    assert refused(tmp_path, text, "scene.joints.axle").strip().endswith("did you mean 'center'?")


def test_did_you_mean_in_set_files(tmp_path):
    week = tmp_path / "week.yaml"
    week.write_text("titel: Week 9\nproblems: [rod_endpoint]\n")
    done = run_derive("sheet", str(week))
    assert done.returncode == 2 and done.stderr.strip().endswith("did you mean 'title'?"), done.stderr


def test_set_takes_degrees_rpm_and_newton_metres(derive):
    tilted = solve_json(derive, "rigid_body_L", "alpha=30°", "omega=60 rpm", "m=1", "L=1")
    assert tilted["parameters"]["alpha"]["value"] == "0.523598775598299"  # pi/6 rad
    assert tilted["parameters"]["omega"]["value"] == "6.28318530717959"  # 2 pi rad/s
    assert solve_json(derive, "rigid_body_L", "alpha=30 degrees", "omega=60 rev/min", "m=1", "L=1") == tilted
    wheel = solve_json(derive, "tilting_wheel", "tau=0.5 N m")
    assert wheel["parameters"]["tau"]["value"] == solve_json(derive, "tilting_wheel", "tau=0.5 Nm")[
        "parameters"]["tau"]["value"] == "0.500000000000000"


def test_version_is_the_distributions(monkeypatch):
    import tomllib
    from importlib import metadata

    import derive

    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    assert project["name"] == derive.DISTRIBUTION == "derive-mechanics" and project["scripts"]["derive"]
    assert run_derive("--version").stdout == f"derive {project['version']}\n"
    asked = []
    monkeypatch.setattr(metadata, "version", lambda name: asked.append(name) or "7.7.7")
    assert derive.version() == "7.7.7" and asked == ["derive-mechanics"]


def test_a_missing_tool_exits_3_with_its_install_command(tmp_path):
    (tmp_path / "bin").mkdir()
    done = run_derive("sheet", "rod_endpoint", "--to", "pdf", "--out", str(tmp_path / "out"), "--progress", "none",
                      env={"PATH": str(tmp_path / "bin")})
    assert done.returncode == 3 and len(done.stderr.strip().splitlines()) == 1, done.stderr
    assert "latexmk is not installed; install it with: apt-get install" in done.stderr
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


def test_figures_as_images_need_pdftocairo(tmp_path):
    (tmp_path / "bin").mkdir()
    (tmp_path / "bin" / "latexmk").symlink_to(shutil.which("latexmk"))
    done = run_derive("sheet", "rod_endpoint", "--to", "html", "--out", str(tmp_path / "out"), "--progress", "none",
                      env={"PATH": str(tmp_path / "bin")})
    assert done.returncode == 3 and len(done.stderr.strip().splitlines()) == 1, done.stderr
    assert "pdftocairo is not installed; install it with: apt-get install -y --no-install-recommends poppler-utils" \
        in done.stderr


def test_missing_pandoc_is_a_missing_tool(tmp_path, monkeypatch):
    import pypandoc

    from derive.publishing import export
    from derive.core.errors import MissingTool

    def nowhere():
        raise OSError("No pandoc was found")

    monkeypatch.setattr(pypandoc, "get_pandoc_path", nowhere)
    with pytest.raises(MissingTool, match="pandoc is not installed; install it with: pip install pypandoc-binary"):
        export.convert("", tmp_path / "worksheet", "html", "T")


def test_course_defaults_file(tmp_path):
    (tmp_path / "derive.toml").write_text('course = "PHY141 Mechanics"\ndigits = 5\ntolerance = "2%"\noutputs = []\n')
    solved = run_derive("solve", "rod_endpoint", "--set", "m=3", "--set", "L=2", "--format", "json", cwd=tmp_path)
    assert json.loads(solved.stdout)["answers"]["I"]["value"] == "4.0000"  # 5 digits
    solved = run_derive("solve", "rod_endpoint", "--set", "m=3", "--set", "L=2", "--format", "json", "--digits", "3",
                        cwd=tmp_path)
    assert json.loads(solved.stdout)["answers"]["I"]["value"] == "4.00"  # the option wins
    built = run_derive("sheet", "rod_endpoint", cwd=tmp_path)
    assert built.returncode == 0, built.stderr
    out = tmp_path / "build" / "rod_endpoint"
    assert {p.suffix for p in out.iterdir() if p.is_file()} == {".tex", ".csv", ".json"}  # outputs = []: no PDF, HTML
    assert "PHY141 Mechanics" in (out / "worksheet.tex").read_text()
    answer = _key(out)["variants"][0]["problems"]["rod_endpoint"]["answers"]["I"]
    assert mpmath.mpf(answer["tolerance"]) == mpmath.mpf(answer["value"]) * mpmath.mpf("0.02")


def test_course_defaults_in_pyproject(tmp_path):
    (tmp_path / "pyproject.toml").write_text('[project]\nname = "course"\n\n[tool.derive]\ndigits = 4\n')
    solved = run_derive("inertia", "rod", "--set", "M=3", "--set", "L=2", "--format", "json", cwd=tmp_path)
    assert json.loads(solved.stdout)["value"] == "1.000"


@pytest.mark.parametrize("file, text, fragment", [
    ("derive.toml", "digitz = 5\n", "derive.toml: digitz: unknown key (allowed: course, outputs, digits, tolerance); "
                                    "did you mean 'digits'?"),
    ("pyproject.toml", "[tool.derive]\ncourse = 3\n", "pyproject.toml: tool.derive.course: expected text"),
    ("derive.toml", "digits = 99\n", "derive.toml: digits: expected a whole number from 1 to 50"),
    ("derive.toml", 'outputs = ["pfd"]\n', "derive.toml: outputs: unknown output 'pfd'"),
    ("derive.toml", 'tolerance = "150%"\n', "derive.toml: tolerance: 150% of the answer would accept zero"),
    ("derive.toml", "course = \n", "derive.toml: invalid TOML"),
])
def test_course_defaults_refused(tmp_path, file, text, fragment):
    (tmp_path / file).write_text(text)
    done = run_derive("solve", "rod_endpoint", cwd=tmp_path)
    assert done.returncode == 2 and len(done.stderr.strip().splitlines()) == 1, done.stderr
    assert str(tmp_path / fragment.split(":")[0]) in done.stderr and fragment in done.stderr


def test_a_set_files_due_date_may_be_written_as_yaml_reads_a_date(tmp_path):
    """`due: 2026-12-01` (as `derive sheet --help` shows it) is a YAML date: it is the text written."""
    from derive.language import problem_sets

    week = tmp_path / "week.yaml"
    week.write_text("title: Week 9\nproblems: [rod_endpoint]\ndue: 2026-12-01\n")
    assert problem_sets.load_set(str(week)).due == "2026-12-01"


def test_a_set_files_path_is_read_from_the_working_folder_and_the_error_says_so(tmp_path):
    """A newcomer names a problem beside the set file; derive reads paths from the working folder
    and says how to name that one."""
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "set.yaml").write_text("title: T\nproblems: [p.yaml]\n")
    (tmp_path / "sub" / "p.yaml").write_text(next(ROOT.glob("problems/*/rod_endpoint.yaml")).read_text())
    done = run_derive("sheet", "sub/set.yaml", "--to", "", cwd=tmp_path)
    assert done.returncode == 2
    assert done.stderr.strip().endswith("p.yaml: no such problem file (a path in a set file is read from the working "
                                        "folder, not the set file's: write sub/p.yaml to name the one beside it)")


# --- bad input: one line, exit 2, one prefix (issue 35, items 10 to 13) ---------------------------

@pytest.mark.parametrize("args, line", [
    (["--time-limit", "inf", "solve", "rod_endpoint"], "derive: error: --time-limit inf: expected a number of seconds"),
    (["--time-limit", "nan", "solve", "rod_endpoint"], "derive: error: --time-limit nan: expected a number of seconds"),
    (["--time-limit", "1e400", "solve", "rod_endpoint"], "derive: error: --time-limit 1e400: expected a number"),
    (["bench", "--limit", "nan"], "derive: error: bench: Invalid value for '--limit': 'nan' is not a finite number"),
    (["sheet"], "derive: error: sheet: Missing argument"),  # was 'derive sheet: error:'
    (["solve", "rod_endpoint", "--bogus"], "derive: error: solve: No such option '--bogus'"),
    (["--bogus"], "derive: error: No such option '--bogus'"),
    (["solve", "string_wrapped_disk", "--set", "m=\u0663"],  # an Arabic-Indic 3, refused as a file refuses it
     "derive: error: --set m=\u0663: a number is written with the digits 0-9"),
])
def test_bad_command_lines_are_one_line_with_one_prefix(args, line):
    done = run_derive(*args)
    assert done.returncode == 2 and len(done.stderr.strip().splitlines()) == 1, done.stderr
    assert done.stderr.startswith(line), done.stderr


def test_a_time_limit_of_off_or_a_number_is_taken():
    done = run_derive("--time-limit", "off", "solve", "rod_endpoint")
    assert done.returncode == 0, done.stderr


@pytest.mark.parametrize("epoch", ["", "yesterday", "-5"])
def test_a_malformed_source_date_epoch_is_one_line_not_an_internal_error(epoch):
    """numpy.f2py's import (through scipy) reads SOURCE_DATE_EPOCH with int(): set but empty, every
    PDF build stopped with an internal ValueError."""
    done = run_derive("solve", "rod_endpoint", env={"SOURCE_DATE_EPOCH": epoch})
    assert done.returncode == 2 and len(done.stderr.strip().splitlines()) == 1, done.stderr
    assert done.stderr.startswith(f"derive: error: SOURCE_DATE_EPOCH={epoch!r}: expected a whole number"), done.stderr
    assert run_derive("solve", "rod_endpoint", env={"SOURCE_DATE_EPOCH": "1700000000"}).returncode == 0


def test_a_condition_beyond_what_a_decimal_holds_is_decided(tmp_path):
    """M**(10**999) > 0: its certified value, 1.9e+477121254..., stopped the draw with an internal
    InvalidOperation when read as a Decimal; its sign is read from its digits."""
    text = load("rolling_incline").path.read_text()
    old = "- {holds: mu_s >= mu_min,"
    assert old in text
    problem = tmp_path / "p.yaml"
    problem.write_text(text.replace(old, "- {holds: M**(10**999) > 0, because: it is positive}\n  " + old))
    done = run_derive("sheet", str(problem), "--to", "", "--out", str(tmp_path / "out"))
    assert done.returncode == 0, done.stderr
    problem.write_text(text.replace(old, "- {holds: -M**(10**999) > 0, because: it is never so}\n  " + old))
    done = run_derive("sheet", str(problem), "--to", "", "--out", str(tmp_path / "out2"))
    assert done.returncode == 2 and "it is never so" in done.stderr.strip().splitlines()[-1], done.stderr


def test_derive_alone_shows_its_help():
    done = run_derive()
    assert done.returncode == 0 and done.stdout.startswith("Usage: derive") and "Commands:" in done.stdout, done.stderr


def test_list_searches_the_library_by_words_and_topic():
    found = run_derive("list", "--search", "wrapped disk")
    assert found.returncode == 0 and found.stdout.split()[0] == "string_wrapped_disk", found.stdout
    assert [line.split()[0] for line in run_derive("list", "--topic", "rolling", "--search", "loop").stdout.splitlines()] \
        == ["loop_the_loop", "loop_the_loop_ball"]
    pulled = [line.split()[0] for line in run_derive("list", "--search", "pulle").stdout.splitlines()]
    assert "tugged_spool" in pulled  # four letters or more: the start of a word ("pulled")
    yo = [line.split()[0] for line in run_derive("list", "--search", "yo").stdout.splitlines()]
    assert yo and all(i.startswith("yoyo") for i in yo)  # under four: whole words only (yo-yo, not "you")
    yoyos = [line.split()[0] for line in run_derive("list", "--topic", "rolling", "--search", "yo-yo").stdout.splitlines()]
    assert "yoyo_pulled_horizontal" in yoyos and all(i.startswith("yoyo") for i in yoyos)
    none = run_derive("list", "--topic", "torque", "--search", "zzz")
    assert none.returncode == 2 and none.stderr.strip() == "derive: error: no problems of topic 'torque' and matching 'zzz'"


def test_list_filters_by_difficulty_and_tags():
    easy_pulleys = run_derive("list", "--difficulty", "easy", "--tag", "pulley")
    rows = [line.split() for line in easy_pulleys.stdout.splitlines()]
    assert easy_pulleys.returncode == 0 and rows and all(row[2] == "easy" for row in rows), easy_pulleys.stdout
    assert "atwood_smooth" in [row[0] for row in rows] and "atwood_massive_pulley" not in [row[0] for row in rows]
    both = [line.split()[0] for line in run_derive("list", "--tag", "rolling", "--tag", "yo-yo").stdout.splitlines()]
    assert both and "yoyo_falls" not in both  # every tag given: a falling yo-yo does not roll on a floor
    for args in (["--difficulty", "tricky"], ["--tag", "pully"]):
        bad = run_derive("list", *args)
        assert bad.returncode == 2 and "Invalid value" in bad.stderr, bad.stderr
    none = run_derive("list", "--topic", "inertia", "--tag", "yo-yo")
    assert none.returncode == 2 and none.stderr.strip() == "derive: error: no problems of topic 'inertia' and tagged yo-yo"


def test_solve_prints_the_textbook_route_and_the_two_routes_with_proof(derive):
    """A rolling sphere: the student's route (Newton's second law along the slope, the torque about the
    center, rolling without slipping) in a few lines; the two routes' equations of motion only with --proof."""
    text = derive("solve", "sphere_rolls_incline").stdout
    assert "The solution, as a textbook writes it" in text and "Newton's second law for the sphere" in text
    assert "Equations of motion" not in text and "ẋ_ball" not in text
    proof = derive("solve", "sphere_rolls_incline", "--proof").stdout
    assert "Equations of motion, Lagrange's method" in proof and "Equations of motion, Newton–Euler" in proof
    assert "The solution, as a textbook writes it:" in proof


def test_solve_prints_the_answers_as_the_documents_do(derive):
    """The terminal printed acos(sin(alpha)) and |sin(2 alpha)| where the documents print pi/2 - alpha and
    sin(2 alpha) over the ranges, and the rod's length L beside its angular momentum |L|: now the
    documents' forms (derive.numbers.range_forms) and letters (the length as the script l, said so)."""
    text = derive("solve", "rod_tilted_on_shaft").stdout
    answers = text.split("Answers:")[1].split("Checks")[0]
    assert "acos" not in answers and "│" not in answers and "π" in answers, answers
    assert "Printed here: ℓ is the length of the rod (the file's L)" in text and "M⋅ℓ" in answers and "L ⋅M" not in answers


def test_solve_prints_the_students_route_in_the_documents_letters(derive):
    """A door's width L beside the angular momentum L: the terminal's student route printed L = L m v/2;
    now the width is the script l there too, and the report says so before the solution."""
    text = derive("solve", str(ROOT / "tests" / "textbook" / "bullet_into_door.yaml")).stdout
    route = text.split("The solution, as a textbook writes it")[1].split("Answers:")[0]
    assert text.index("Printed here: ℓ is the width of the door (the file's L)") < text.index("The solution")
    assert "ℓ⋅m⋅v" in route and "L⋅m⋅v" not in route


def test_solve_prints_the_students_route_as_it_reads_over_the_ranges(derive):
    """A beam held by a cable at phi (Serway & Jewett ex. 12.2): the terminal printed T tan(phi) |cos(phi)|
    where the documents print T sin(phi) over the ranges (derive.numbers.range_forms)."""
    text = derive("solve", str(ROOT / "tests" / "textbook" / "beam_cable_person.yaml")).stdout
    route = text.split("The solution, as a textbook writes it")[1].split("Answers:")[0]
    assert "│" not in route, route


def test_solve_prints_a_change_as_delta_and_its_letter(derive):
    """A grindstone's angle turned printed as a Delta with the word theta in small subscript letters (a
    newcomer's report); it is the documents' Delta theta."""
    text = derive("solve", str(ROOT / "tests" / "textbook" / "grindstone_slowed_by_friction.yaml")).stdout
    assert "Δθ" in text and "ₜₕₑₜₐ" not in text


def test_solve_writes_a_greek_letter_named_in_a_steps_words_as_the_letter(derive):
    """A newcomer read "the bodies turn together about the axle at the rate omega" beside equations that
    print ω: the terminal writes the letter, as the documents set the name as math."""
    text = derive("solve", "sticky_impact_pivoted").stdout
    assert "at the rate ω" in text and "rate omega" not in text
