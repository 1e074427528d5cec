"""Shared helpers: run the installed `derive` console script as a user would."""
import html
import os
import re
import shutil
import subprocess
import sys
import tempfile
import zipfile
from contextlib import contextmanager
from pathlib import Path
from types import SimpleNamespace

import mpmath
import pytest
from lxml import etree

mpmath.mp.dps = 50  # references in the tests are computed at 50 digits
# A derivation's time limit (60 s for a user, derive.core.limits) is a timing assertion on a shared, noisy machine:
# the slowest problem takes half of it on an idle machine and gave up under load. The tests of the limit set their
# own; `derive bench` prints the times.
os.environ.setdefault("DERIVE_TIME_LIMIT", "600")
# Never the user's derivation cache: a folder of the test run's own (fixtures of a module's scope
# use it), and each test one of its own (derivation_cache_of_its_own).
os.environ["DERIVE_CACHE_DIR"] = tempfile.mkdtemp(prefix="derive-test-cache-")

ROOT = Path(__file__).resolve().parent.parent
DERIVE = Path(sys.executable).parent / "derive"


def run_derive(*args: str, library: Path | None = None, cwd: Path = ROOT, env: dict | None = None,
               timeout: float = 600) -> subprocess.CompletedProcess:
    """Run `derive` in `cwd`; `library` replaces the problem library (DERIVE_LIBRARY), `env` sets
    other environment variables."""
    env = {**os.environ, **({"DERIVE_LIBRARY": str(library)} if library else {}), **(env or {})}
    return subprocess.run([str(DERIVE), *args], capture_output=True, text=True, cwd=cwd, timeout=timeout, env=env)


#: The sources of the lecture notes' problems; every other library problem is a textbook setup.
NOTES = ("lecture notes", "beyond the notes")


def _cites_a_book(path: Path) -> bool:
    import yaml

    return not str(yaml.safe_load(path.read_text()).get("source", "")).startswith(NOTES)


def textbook_files() -> list[Path]:
    """The textbook setups (tests/test_textbook.py): library problems whose source is a book, and
    those kept in tests/textbook."""
    from derive.core import library

    return [p for p in library.problem_files() if _cites_a_book(p)] + sorted((ROOT / "tests" / "textbook").glob("*.yaml"))


def notes_files() -> list[Path]:
    """The library problems of the lecture notes (their `source` is the notes)."""
    from derive.core import library

    return [p for p in library.problem_files() if not _cites_a_book(p)]


def textbook(stem: str) -> Path:
    """The file of a textbook setup (tests/test_textbook.py checks each against its book's closed
    form): a library problem, problems/TOPIC/STEM.yaml, or one kept in tests/textbook."""
    found = sorted(ROOT.glob(f"problems/*/{stem}.yaml")) + sorted(ROOT.glob(f"tests/textbook/{stem}.yaml"))
    assert len(found) == 1, f"no single textbook file {stem}.yaml: {found}"
    return found[0]


def write_problem(folder: Path, text: str) -> Path:
    """A problem file with `text`, in `folder`."""
    path = folder / "problem.yaml"
    path.write_text(text)
    return path


def refused(folder: Path, text: str, field: str, *options: str, exit_code: int = 2) -> str:
    """`derive solve` of a problem file with `text` (and `options`): the exit status `exit_code`
    and one line of error naming `field`, which is returned."""
    result = run_derive("solve", str(write_problem(folder, text)), *options)
    assert result.returncode == exit_code, result.stdout + result.stderr
    assert field in result.stderr and len(result.stderr.strip().splitlines()) == 1, result.stderr
    return result.stderr


def copy_library(folder: Path) -> Path:
    """A private copy of the problem library that a test may break."""
    library = folder / "library"
    shutil.copytree(ROOT / "problems", library)
    return library


#: Where the read-only tests over the library keep each problem's derivation for the whole run, shared by
#: the workers: `derived`. The controller names it before it starts the workers, which inherit its
#: environment; it removes it when the run ends (pytest_sessionfinish).
if "DERIVE_TEST_SHARED" not in os.environ:
    os.environ["DERIVE_TEST_SHARED"] = tempfile.mkdtemp(prefix="derive-test-derivations-")
SHARED = Path(os.environ["DERIVE_TEST_SHARED"])
_DERIVED: dict = {}


def derived(reference):
    """A problem (a library id or a file) derived once for the whole test run, with its answers, checks
    and worked steps, for the tests that read every library and textbook problem (their prose, notation,
    printed forms, closed forms, simulations): about seven derivations of each problem had made CI
    twice its 30 minutes. Kept in this worker's memory, and in the run's derivation cache, which every
    worker reads (derive.publishing.derivation_cache: an entry loads byte-identical to a fresh
    derivation, as tests/test_derivation_cache.py proves); the first test to need it derives it afresh.
    A test that changes a solution (or proves a check catches an error) derives its own."""
    from derive.language.problem import load
    from derive.publishing import derivation_cache

    problem = load(str(reference))
    if problem.path not in _DERIVED:
        saved = os.environ.get("DERIVE_CACHE_DIR")
        os.environ["DERIVE_CACHE_DIR"] = str(SHARED)
        try:
            solution = derivation_cache.fetch(problem)
            if solution is None:
                solution = derivation_cache.derived(problem)
                derivation_cache.store(problem, solution, trimmed=False)
        finally:
            os.environ["DERIVE_CACHE_DIR"] = saved
        _DERIVED[problem.path] = solution
    return _DERIVED[problem.path]


_STUDENT: dict = {}


def student_solution(reference) -> tuple[str, bool]:
    """(the worked solution a student is given of a problem, as LaTeX, whether it takes the student's
    route): the solutions sheet of that problem alone at the middle of its ranges, without the
    instructor's verification by two routes, its figures and free-body diagrams left out (TikZ,
    no text); derived once for the run (`derived`)."""
    return _solutions_sheet(reference, verification=False)


def instructors_solution(reference) -> str:
    """The worked solution as the instructor's solutions PDF prints it (`student_solution`), the
    verification by Lagrange and Newton–Euler included where the student's route is written."""
    return _solutions_sheet(reference, verification=True)[0]


def _solutions_sheet(reference, verification: bool) -> tuple[str, bool]:
    from decimal import Decimal

    from derive.publishing import render, variants, worksheets

    solution = derived(reference)
    if (solution.problem.path, verification) not in _STUDENT:
        problem = solution.problem
        middle = {n: p.value if p.range is None else p.at(Decimal("0.5")) for n, p in problem.parameters.items()}
        context = worksheets._solutions_context(variants.ProblemVariants(problem, solution, [middle]), siunitx=True)
        context["figure"] = ""
        for route in (*context["routes"], *context["verification"]):
            for step in route["steps"]:
                step["diagram"] = ""
        tex = render.render("solutions.tex.j2", problems=[context], verification=verification,
                            set=SimpleNamespace(title="Week 1", course="Mechanics", due="Friday"))
        _STUDENT[problem.path, verification] = (tex, solution.student_steps is not None)
    return _STUDENT[solution.problem.path, verification]


@pytest.fixture(autouse=True)
def derivation_cache_of_its_own(tmp_path_factory, monkeypatch):
    """Each test its own empty derivation cache, never the user's (derive and the processes it starts
    read DERIVE_CACHE_DIR): no test finds a derivation another test made."""
    monkeypatch.setenv("DERIVE_CACHE_DIR", str(tmp_path_factory.mktemp("derivation-cache")))


@pytest.fixture
def derive():
    return run_derive


def solve(problem_id: str, **values) -> tuple[dict, dict]:
    """(answers as 50-digit mpmath numbers, the whole result) of `derive solve` at 15 digits; a
    magnitude given with its direction in words (derive.model.directions) is turned back into the
    component along the file's axes (y up, counter-clockwise positive), which the books' formulas give."""
    from derive.language import problem
    from derive.publishing import report
    from derive.solution.answers import Solution

    solution = Solution(problem.load(problem_id))
    result = report.solve(solution.problem, {k: str(v) for k, v in values.items()}, 15, solution=solution)
    answers = {}
    for n, a in result["answers"].items():
        sense = solution.senses[n]
        sign = -1 if a["direction"] and not solution.problem.asks[n].magnitude and a["direction"] == sense.negative else 1
        answers[n] = sign * mpmath.mpf(a["value"])
    return answers, result


def close(value, reference, digits: int = 15) -> bool:
    """Within half a unit of the last of `digits` significant digits of the reference."""
    return abs(value - reference) <= abs(reference) * mpmath.mpf(10) ** (1 - digits) / 2


@contextmanager
def kept_scratch(folder: Path):
    """export.pdf compiling in `folder`, kept afterwards (export deletes its scratch folder): a
    test reads TeX's log there and lists what TeX wrote."""
    from derive.publishing import export

    @contextmanager
    def scratch(prefix=""):
        folder.mkdir(parents=True)
        yield str(folder)

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(export, "tempfile", SimpleNamespace(TemporaryDirectory=scratch, gettempdir=tempfile.gettempdir))
        yield folder


#: What TeX and latexmk write beside a document.tex in their scratch folder (the .aux and .pdf
#: are moved out by export.pdf).
TEX_OWN_FILES = {".tex", ".aux", ".log", ".pdf", ".fls", ".fdb_latexmk"}


def document(body: str) -> str:
    """A document in derive's real preamble (templates/preamble.tex.j2)."""
    from derive.publishing import render

    return render.render("preamble.tex.j2") + "\\begin{document}\n" + body + "\n\\end{document}\n"


#: Moodle's cloze parser, question/type/multianswer/questiontype.php (qtype_multianswer_extract_question
#: and its regexes ANSWER_REGEX, ANSWER_ALTERNATIVE_REGEX), in Python: a look-behind of one width
#: per alternative, as Python's re wants, for PCRE's `(?<!\\|&|&amp;)`.
_CLOZE_ALTERNATIVE = (r"(=|%(-?[0-9]+(?:[.,][0-9]*)?)%)?"
                      r"(.+?(?<!\\)(?<!&)(?<!&amp;)(?=[~#}]|$))"
                      r"(#(.*?(?<!\\)(?=[~}]|$)))?")
_CLOZE_TYPES = ("(NUMERICAL|NM)|(MULTICHOICE|MC)|(MULTICHOICE_V|MCV)|(MULTICHOICE_H|MCH)|(SHORTANSWER|SA|MW)|"
                "(SHORTANSWER_C|SAC|MWC)|(MULTICHOICE_S|MCS)|(MULTICHOICE_VS|MCVS)|(MULTICHOICE_HS|MCHS)|"
                "(MULTIRESPONSE|MR)|(MULTIRESPONSE_H|MRH)|(MULTIRESPONSE_S|MRS)|(MULTIRESPONSE_HS|MRHS)")
_CLOZE_FIELD = re.compile(r"\{([0-9]*):(" + _CLOZE_TYPES + r"):(?P<alternatives>" + _CLOZE_ALTERNATIVE
                          + "(~" + _CLOZE_ALTERNATIVE + r")*)\}", re.S)


def moodle_cloze(text: str, feedback: bool = False) -> tuple[str, list[tuple[str, list[tuple[str, ...]]]]]:
    """A cloze question's HTML as Moodle reads it on import: (the text with each field as {#N},
    [(field type, [(fraction mark, answer as Moodle stores it)])]), each answer with its feedback
    too where `feedback`. A choice and a feedback are html_entity_decode()d and only `\\}` and `\\#`
    are unescaped; a number is kept as written."""
    fields = []
    while match := _CLOZE_FIELD.search(text):
        kind, remaining, answers = match.group(2), match.group("alternatives"), []
        while alternative := re.search("~?" + _CLOZE_ALTERNATIVE, remaining, re.S):
            answer = alternative.group(3)
            if not kind.startswith(("NUMERICAL", "NM")):
                answer = html.unescape(answer).replace("\\}", "}").replace("\\#", "#")
            said = html.unescape(alternative.group(5) or "").replace("\\}", "}").replace("\\#", "#")
            answers.append((alternative.group(1) or "", answer, said) if feedback else (alternative.group(1) or "", answer))
            remaining = remaining.split(alternative.group(0), 1)[1]
        fields.append((kind, answers))
        text = text.replace(match.group(0), f"{{#{len(fields)}}}", 1)
    return text, fields


def qti_package(archive: zipfile.ZipFile) -> tuple[etree._Element, etree._Element, etree._Element]:
    """(manifest, assessment, quiz metadata) of a Canvas QTI zip, parsed, once the manifest is found
    to list every other file of the zip and nothing else, in Canvas's layout: the assessment
    resource's file is ID/ID.xml (ID its identifier and the assessment's ident), with a dependency
    on a learning-application-resource whose file is ID/assessment_meta.xml."""
    manifest = etree.fromstring(archive.read("imsmanifest.xml"))
    listed = [f.get("href") for f in manifest.iter("{*}file")]
    assert sorted(listed + ["imsmanifest.xml"]) == sorted(archive.namelist())
    (quiz,) = [r for r in manifest.iter("{*}resource") if r.get("type") == "imsqti_xmlv1p2"]
    ident = quiz.get("identifier")
    assert [f.get("href") for f in quiz.iter("{*}file")] == [f"{ident}/{ident}.xml"]
    (dependency,) = quiz.iter("{*}dependency")
    (meta,) = [r for r in manifest.iter("{*}resource") if r.get("identifier") == dependency.get("identifierref")]
    assert meta.get("type") == "associatedcontent/imscc_xmlv1p1/learning-application-resource"
    assert [f.get("href") for f in meta.iter("{*}file")] == [meta.get("href")] == [f"{ident}/assessment_meta.xml"]
    assessment = etree.fromstring(archive.read(f"{ident}/{ident}.xml"))
    assert assessment.find("{*}assessment").get("ident") == ident
    return manifest, assessment, etree.fromstring(archive.read(meta.get("href")))


def image_kind(data: bytes) -> str:
    """"svg" or "png" for a valid image of that kind (an SVG document that parses, with a size; a
    PNG that Pillow reads whole, at least 16 pixels wide); an AssertionError otherwise."""
    import io

    from PIL import Image

    if data.startswith(b"\x89PNG"):
        with Image.open(io.BytesIO(data)) as image:
            image.load()  # decodes every pixel: a truncated or corrupt PNG raises
            assert image.format == "PNG" and image.width >= 16 and image.height >= 1, image
        return "png"
    root = etree.fromstring(data)
    assert root.tag == "{http://www.w3.org/2000/svg}svg", root.tag
    assert float(root.get("width").removesuffix("pt")) > 0 and float(root.get("height").removesuffix("pt")) > 0
    assert len(root.findall(".//{http://www.w3.org/2000/svg}path")) > 0  # it draws something
    return "svg"


def pytest_sessionfinish(session):
    """The run's shared derivations go with it, removed by the controller once every worker has ended
    (a worker that ended first and removed them broke another's sheet that was reading them)."""
    if not hasattr(session.config, "workerinput"):
        shutil.rmtree(SHARED, ignore_errors=True)
