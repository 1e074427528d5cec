"""Problem and set files treated as untrusted: time limits, LaTeX safety, the template sandbox,
output names, interrupted builds, pandoc's arguments."""
import os
import threading
import time
from pathlib import Path

import jinja2
import pytest
from jinja2.exceptions import SecurityError, TemplateNotFound, UndefinedError

from conftest import ROOT, run_derive
from derive import export, latex_safety, library, limits, problem, render
from derive.answers import Solution
from derive.errors import InputError, ProblemError

EXOTIC = """\
id: exotic
title: An exotic density
topic: inertia
parameters:
  M: {meaning: mass, unit: kg, value: 2}
  R: {meaning: radius, unit: m, value: 0.5}
scene:
  bodies:
    plate: {shape: disk, mass: M, radius: R, density: (2+cos(r/R))^7*exp(r/R)^3*sin(phi)^6}
ask:
  I: {meaning: moment of inertia, of: plate.inertia, unit: kg*m^2}
question: |
  Find the moment of inertia of a disk of mass {{ M }} and radius {{ R }}.
"""


def problem_text(question="A disk of mass {{ M }} turns.", title="A disk", meaning="mass", ask_meaning="inertia",
                 problem_id="plain_disk"):
    return f"""\
id: {problem_id}
title: "{title}"
topic: inertia
parameters:
  M: {{meaning: "{meaning}", unit: kg, range: [1, 2], sig_figs: 2}}
  R: {{meaning: radius, unit: m, value: 0.5}}
scene:
  bodies:
    disk: {{shape: disk, mass: M, radius: R}}
ask:
  I: {{meaning: "{ask_meaning}", of: disk.inertia, unit: kg*m^2}}
question: |
  {question}
"""


def one_line_exit_2(result):
    assert result.returncode == 2, (result.returncode, result.stderr)
    assert "Traceback" not in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1, result.stderr
    return result.stderr


# --- time limits -------------------------------------------------------------------------------

def test_exotic_density_gives_up_within_the_limit(tmp_path, monkeypatch):
    """This density kept sympy integrating for minutes; with a 2 s limit the ask stops at once."""
    path = tmp_path / "exotic.yaml"
    path.write_text(EXOTIC)
    monkeypatch.setenv("DERIVE_TIME_LIMIT", "2")
    solution = Solution(problem.load(str(path)))
    start = time.monotonic()
    with pytest.raises(limits.TimeLimitError) as caught:
        solution.expression("I")
    assert time.monotonic() - start < 5
    message = str(caught.value)
    assert message.startswith(f"{path}: ask.I: integrating over the disk: gave up after 2 s")
    assert "DERIVE_TIME_LIMIT" in message and "--time-limit" in message
    assert isinstance(caught.value, InputError)


def test_exotic_density_on_the_command_line(tmp_path):
    path = tmp_path / "exotic.yaml"
    path.write_text(EXOTIC)
    start = time.monotonic()
    result = run_derive("--time-limit", "2", "solve", str(path))
    assert time.monotonic() - start < 15
    assert "ask.I: integrating over the disk: gave up after 2 s" in one_line_exit_2(result)


def test_time_limit_nests_and_cleans_up(monkeypatch):
    monkeypatch.setenv("DERIVE_TIME_LIMIT", "0.3")
    with pytest.raises(limits.TimeLimitError, match=r"^outer: inner: gave up after 0\.3 s"):
        with limits.time_limit("outer"):
            with limits.time_limit("inner"):
                while True:
                    pass
    assert limits.signal.getitimer(limits.signal.ITIMER_REAL) == (0.0, 0.0)
    assert limits.signal.getsignal(limits.signal.SIGALRM) in (limits.signal.SIG_DFL, None)
    with limits.time_limit("quick"):  # after a timeout, the next step runs normally
        assert sum(range(100)) == 4950


def test_time_limit_survives_code_that_swallows_exceptions(monkeypatch):
    """The alarm is a BaseException and repeats: `except Exception: pass` cannot hide it."""
    start = time.monotonic()
    with pytest.raises(limits.TimeLimitError):
        with limits.time_limit("stubborn", seconds=0.2):
            while True:
                try:
                    time.sleep(0.01)
                except Exception:  # noqa: BLE001 - what sympy does in places
                    pass
    assert time.monotonic() - start < 2


@pytest.mark.parametrize("value, expected", [("", 60.0), ("5", 5.0), ("0", None), ("off", None), ("1.5", 1.5)])
def test_time_limit_setting(monkeypatch, value, expected):
    monkeypatch.setenv("DERIVE_TIME_LIMIT", value)
    assert limits.seconds() == expected


def test_time_limit_bad_setting(monkeypatch):
    monkeypatch.setenv("DERIVE_TIME_LIMIT", "soon")
    with pytest.raises(InputError, match="DERIVE_TIME_LIMIT=soon: expected a number of seconds"):
        limits.seconds()


def test_time_limit_off_the_main_thread_runs_unbounded():
    outcome = []

    def work():
        with limits.time_limit("in a thread", seconds=0.05):
            time.sleep(0.2)
            outcome.append("done")

    thread = threading.Thread(target=work)
    thread.start()
    thread.join()
    assert outcome == ["done"]


def test_configure_overrides_the_environment(monkeypatch):
    monkeypatch.setenv("DERIVE_TIME_LIMIT", "5")
    limits.configure(7)
    try:
        assert limits.seconds() == 7
    finally:
        limits.configure(None)
    assert limits.seconds() == 5


# --- LaTeX safety ------------------------------------------------------------------------------

DANGEROUS = [
    r"\write18{rm -rf ~}", r"\immediate\write18{ls}", r"\input{/etc/passwd}", r"\include{../x}",
    r"\openout1=x.tex", r"\catcode`\^=11", r"\csname input\endcsname{/etc/passwd}",
    r"$\csname input\endcsname$", r"$x \input{/etc/passwd}$", r"^^5cinput{/etc/passwd}", r"$^^5c input$",
    r"$\def\x{1}$", r"\makeatletter", r"$\pdffiledump{/etc/passwd}$", r"$\directlua{os.execute('ls')}$",
    r"$\begin{filecontents}{x}\end{filecontents}$", r"$\usepackage{shellesc}$", r"$\InputIfFileExists{x}{}{}$",
    r"$\scantokens{x}$", r"$\expandafter\x$",
]


@pytest.mark.parametrize("text", DANGEROUS)
def test_dangerous_latex_in_the_question_is_refused(text):
    with pytest.raises(ProblemError) as caught:
        problem.parse(problem_text(question=text), Path("evil.yaml"))
    message = str(caught.value)
    assert message.startswith("evil.yaml: question: ") and "\n" not in message


@pytest.mark.parametrize("field", ["title", "meaning", "ask_meaning"])
@pytest.mark.parametrize("text", [r"\\input{/etc/passwd}", r"\\write18{ls}", r"\\csname x\\endcsname", "^^5c"])
def test_dangerous_latex_in_other_text_is_refused(field, text):
    with pytest.raises(ProblemError) as caught:
        problem.parse(problem_text(**{field: text}), Path("evil.yaml"))
    where = {"title": "title", "meaning": "parameters.M.meaning", "ask_meaning": "ask.I.meaning"}[field]
    assert str(caught.value).startswith(f"evil.yaml: {where}: ")


@pytest.mark.parametrize("text, reason", [
    (r"Find \alpha.", "not allowed outside math"),
    (r"Mass $m {{ M }}$.", "outside $...$"),
    (r"Mass {{ Q }}.", "not a parameter"),
    (r"Mass $x % comment$.", "comment"),
    (r"Mass $x}}{{$.", "placeholder"),
    (r"Mass $\frac{1}{2$.", "unbalanced"),
])
def test_question_policy(text, reason):
    with pytest.raises(ProblemError, match="question: .*" + reason.replace("$", r"\$").replace(".", r"\.")):
        problem.parse(problem_text(question=text), Path("q.yaml"))


def test_whitelisted_latex_is_kept_and_specials_are_escaped():
    text = r"A \emph{uniform} disk, 50% of $\omega_0^2 \cdot \frac{1}{2}$ & #1 a_b ~ ^ {x} \% \ldots done"
    out = latex_safety.question_latex(text)
    assert out == (r"A \emph{uniform} disk, 50\% of $\omega_0^2 \cdot \frac{1}{2}$ \& \#1 a\_b "
                   r"\textasciitilde{} \textasciicircum{} \{x\} \% \ldots{} done")
    latex_safety.check(text, question=True)  # accepted when read


def test_render_time_check_catches_text_that_skipped_the_reader():
    with pytest.raises(latex_safety.LatexError):
        render.question("{{ v }}", {"v": r"$\input{/etc/passwd}$"})
    assert render.question("x {{ v }}", {"v": r"\foo"}) == r"x \textbackslash{}foo"


def test_library_questions_are_unchanged_by_the_escaping():
    for path in library.problem_files():
        p = problem.load(str(path))
        values = {name: "$1\\,\\mathrm{kg}$" for name in p.parameters}
        raw = render._questions().from_string(p.question).render(**values)
        assert render.question(p.question, values) == raw, p.id


SPECIAL_TITLE = "Specials 50% & #1 a_b ~x^2 {y} \\\\ $z$"  # YAML "...\\" is one backslash


def test_specials_in_titles_and_meanings_are_escaped_and_compile(tmp_path):
    path = tmp_path / "specials.yaml"
    path.write_text(problem_text(title=SPECIAL_TITLE, ask_meaning="I_z at 100% & more",
                                 question="A disk of mass {{ M }}: 5% off & #1 a_b ~ ^ {x}."))
    (tmp_path / "specials_set.yaml").write_text(f"title: 'Set 100% & #2 ~'\nproblems: [{path}]\n")
    out = tmp_path / "out"
    result = run_derive("sheet", str(tmp_path / "specials_set.yaml"), "--out", str(out), "--to", "pdf")
    assert result.returncode == 0, result.stderr
    worksheet = (out / "worksheet.tex").read_text()
    assert r"Specials 50\% \& \#1 a\_b \textasciitilde{}x\textasciicircum{}2 \{y\} \textbackslash{} \$z\$" in worksheet
    assert r"5\% off \& \#1 a\_b \textasciitilde{} \textasciicircum{} \{x\}." in worksheet
    assert r"Set 100\% \& \#2 \textasciitilde{}" in worksheet
    assert r"I\_z at 100\% \& more" in (out / "solutions.tex").read_text()
    assert (out / "worksheet.pdf").stat().st_size > 0 and (out / "solutions.pdf").stat().st_size > 0


def test_latexmk_runs_without_shell_escape_and_with_paranoid_files(monkeypatch, tmp_path):
    seen = {}

    def fake_run(command, cwd, env, seconds):
        seen.update(args=command, env=env, files=sorted(p.name for p in cwd.iterdir()), cwd=cwd)
        raise export.subprocess.TimeoutExpired(command, seconds)

    monkeypatch.setattr(export, "_run_in_own_group", fake_run)
    (tmp_path / "x.tex").write_text("\\documentclass{article}")
    (tmp_path / "key.csv").write_text("the key")
    with pytest.raises(export.BuildError, match="did not compile within"):
        export.pdf(tmp_path / "x.tex")
    assert "-no-shell-escape" in seen["args"] and not any("shell-escape" in a and "no" not in a for a in seen["args"])
    assert seen["env"]["openin_any"] == "p" and seen["env"]["openout_any"] == "p"
    assert seen["files"] == ["x.tex"] and seen["cwd"] != tmp_path  # a scratch folder with the .tex alone


WRITER = r"""\documentclass{article}
\begin{document}
\immediate\openout1=key.csv \immediate\write1{I = 42}\immediate\closeout1
\immediate\openout2=../key.tex \immediate\write2{forged}\immediate\closeout2
Hello.
\end{document}
"""


def test_tex_cannot_write_beside_its_document(tmp_path):
    """A TeX run that writes files (as a forged key once did) writes only in its scratch folder."""
    (tmp_path / "key.csv").write_text("the key")
    (tmp_path / "w.tex").write_text(WRITER)
    try:
        export.pdf(tmp_path / "w.tex")
    except export.BuildError:
        pass  # TeX may refuse ../key.tex outright
    assert (tmp_path / "key.csv").read_text() == "the key"
    assert not (tmp_path / "key.tex").exists() and not (tmp_path.parent / "key.tex").exists()
    assert sorted(p.name for p in tmp_path.iterdir()) in (["key.csv", "w.tex"], ["key.csv", "w.aux", "w.pdf", "w.tex"])


# --- the template sandbox ----------------------------------------------------------------------

@pytest.mark.parametrize("text", ["{{ ''.__class__.__mro__ }}", "{{ cycler.__init__.__globals__ }}",
                                  "{{ ''.__class__.__mro__[1].__subclasses__() }}", "{{ lipsum.__globals__ }}",
                                  "{{ namespace.__init__.__globals__.os }}"])
def test_question_templates_cannot_reach_python(text):
    with pytest.raises((SecurityError, UndefinedError)):
        render.question(text, {})
    with pytest.raises(ProblemError, match="question: .*only \\{\\{ NAME \\}\\} placeholders"):
        problem.parse(problem_text(question=text), Path("sandbox.yaml"))


@pytest.mark.parametrize("text", ["{% include '/etc/passwd' %}", "{% import '../README.md' as x %}",
                                  "{% for c in ''.__class__.__mro__ %}{{ c }}{% endfor %}"])
def test_question_templates_cannot_include_or_loop(text):
    with pytest.raises(ProblemError, match="question: "):
        problem.parse(problem_text(question=text), Path("sandbox.yaml"))
    with pytest.raises((TypeError, SecurityError, UndefinedError, jinja2.TemplateError)):
        render.question(text, {})


@pytest.mark.parametrize("name", ["../README.md", "/etc/passwd", "../../../../etc/passwd", "./../README.md"])
def test_templates_cannot_include_files_outside_the_folder(name):
    env = render.templates()
    with pytest.raises(TemplateNotFound):
        env.from_string("\\BLOCK{include '" + name + "'}").render()


def test_templates_cannot_reach_python():
    with pytest.raises((SecurityError, UndefinedError)):
        render.templates().from_string("\\VAR{''.__class__.__mro__}").render()


def test_hostile_files_on_the_command_line(tmp_path):
    files = {
        "sandbox.yaml": problem_text(question="{{ ''.__class__.__mro__ }}"),
        "tex.yaml": problem_text(question=r"\input{/etc/passwd}"),
        "tower.yaml": problem_text().replace("value: 0.5", "value: 10**10**10**10"),
        "bomb.yaml": "a: &a [x, x, x, x, x, x, x, x]\nb: &b [*a, *a, *a, *a, *a, *a, *a, *a]\nid: *b\n",
        "junk.yaml": "\x00\x01 not yaml at all: [",
        "nested.yaml": "a: " + "[" * 3000 + "]" * 3000,
    }
    for name, text in files.items():
        (tmp_path / name).write_text(text)
        start = time.monotonic()
        stderr = one_line_exit_2(run_derive("solve", str(tmp_path / name)))
        assert time.monotonic() - start < 15
        assert str(tmp_path / name) in stderr, stderr


# --- output names and interrupted builds -------------------------------------------------------

@pytest.mark.parametrize("bad", ["../evil", "/etc/evil", "a b", "x;rm", "a/b", "_x", "1x", "x.y"])
def test_problem_ids_that_could_leave_the_output_folder_are_refused(bad):
    with pytest.raises(ProblemError, match="id: an id is letters, digits and _"):
        problem.parse(problem_text(problem_id=f'"{bad}"'), Path("ids.yaml"))


@pytest.mark.parametrize("stem", ["a b", "x;y", "-x", "x.y", "$(x)"])
def test_set_ids_from_odd_file_names_are_refused(tmp_path, stem):
    path = tmp_path / f"{stem}.yaml"
    path.write_text("title: x\nproblems: [rod_endpoint]\n")
    with pytest.raises(library.LibraryError, match="a set's id is its file name"):
        library.find_set(str(path))


@pytest.mark.parametrize("reference", ["../../etc/passwd", "/etc/passwd", "..", "../x.yaml"])
def test_set_references_that_are_no_set_files(reference):
    from derive import sheet
    with pytest.raises(InputError):
        sheet.load_set(reference)


def _build(out):
    from derive import sheet
    return sheet.build("demo", variants=2, seed=1, out_dir=str(out), formats=frozenset())


def test_build_writes_only_inside_its_output_folder(tmp_path):
    out = tmp_path / "here" / "out"
    written = _build(out)
    assert written and all(p.resolve().parent == out.resolve() for p in written)
    everything = [p for p in tmp_path.rglob("*")]
    assert all(p == out.parent or out in p.parents or p == out for p in everything), everything


@pytest.mark.parametrize("interrupt", [KeyboardInterrupt, RuntimeError])
def test_interrupted_build_leaves_the_previous_one(tmp_path, monkeypatch, interrupt):
    out = tmp_path / "out"
    _build(out)
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    calls = []
    original = render.render

    def fails_midway(template, **context):
        calls.append(template)
        if len(calls) == 2:
            raise interrupt("stop")
        return original(template, **context)

    monkeypatch.setattr(render, "render", fails_midway)
    with pytest.raises(interrupt):
        _build(out)
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]  # no staging folder left behind


def test_interrupted_build_on_the_command_line(tmp_path):
    """Ctrl-C (SIGINT) in the middle of a build: exit 130, the previous build intact."""
    import signal
    import subprocess
    import sys
    out = tmp_path / "out"
    _build(out)
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    process = subprocess.Popen([str(Path(sys.executable).parent / "derive"), "sheet", "demo", "--variants", "2",
                                "--seed", "1", "--out", str(out), "--to", "pdf"], cwd=ROOT,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline and not any(p.name.startswith(".out.partial") for p in tmp_path.iterdir()):
        time.sleep(0.05)
    process.send_signal(signal.SIGINT)
    process.communicate(timeout=120)
    assert process.returncode in (130, 1, -signal.SIGINT)
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]


# --- pandoc ------------------------------------------------------------------------------------

def test_pandoc_gets_no_filters_and_one_title_argument(monkeypatch, tmp_path):
    import pypandoc
    seen = []
    monkeypatch.setattr(pypandoc, "convert_file", lambda *a, **k: seen.append(k["extra_args"]))
    title = "Week 9 --lua-filter=evil.lua --filter x -F y"
    for target in export.PANDOC_TARGETS:
        export.convert(tmp_path / "w.tex", target, title)
    for args in seen:
        assert not any(a.startswith(("--filter", "--lua-filter", "-F", "-L", "--defaults", "-d")) for a in args), args
        assert f"--metadata=title:{title}" in args and "--sandbox" in args


def test_pandoc_reads_no_file_from_raw_latex(tmp_path):
    secret = tmp_path / "secret.tex"
    secret.write_text("SECRETTEXT")
    tex = tmp_path / "w.tex"
    tex.write_text("\\documentclass{article}\\begin{document}Hello --lua-filter=x.lua \\input{" + str(secret)
                   + "}\\end{document}\n")
    html = export.convert(tex, "html", "t").read_text()
    assert "SECRETTEXT" not in html and "Hello" in html
    assert os.path.exists(secret)


def test_a_compile_past_its_time_limit_is_stopped_with_its_whole_process_group(tmp_path, monkeypatch):
    """TeX looping forever: after the limit every process of the compile is gone (latexmk's
    pdflatex child once kept spinning, re-parented, after latexmk was killed)."""
    (tmp_path / "loop.tex").write_text("\\documentclass{article}\\def\\x{\\x}\\begin{document}\\x\\end{document}\n")
    monkeypatch.setenv("DERIVE_TEX_TIME_LIMIT", "3")
    groups = []
    popen = export.subprocess.Popen

    def recorded(*args, **kwargs):
        process = popen(*args, **kwargs)
        groups.append(process.pid)
        return process

    monkeypatch.setattr(export.subprocess, "Popen", recorded)
    outcome = []

    def compile_it():
        try:
            export.pdf(tmp_path / "loop.tex")
        except export.BuildError as error:
            outcome.append(str(error))

    worker = threading.Thread(target=compile_it, daemon=True)  # a hang fails the test, not the suite
    worker.start()
    worker.join(timeout=60)
    assert not worker.is_alive(), "the compile did not stop at its time limit"
    assert outcome and "did not compile within 3 s" in outcome[0]
    (group,) = groups
    time.sleep(0.2)
    alive = []  # processes of the compile's group not yet dead (a zombie is dead, waiting for its reaper)
    for proc in Path("/proc").iterdir():
        try:
            fields = (proc / "stat").read_text().rsplit(")", 1)[1].split()
        except (OSError, IndexError):
            continue
        if int(fields[2]) == group and fields[0] != "Z":
            alive.append(proc.name)
    assert not alive


def test_tex_time_limit_setting(monkeypatch):
    monkeypatch.setenv("DERIVE_TEX_TIME_LIMIT", "soon")
    with pytest.raises(InputError, match="DERIVE_TEX_TIME_LIMIT=soon"):
        export.tex_time_limit()
    monkeypatch.setenv("DERIVE_TEX_TIME_LIMIT", "45")
    assert export.tex_time_limit() == 45
