"""Shared helpers: run the installed `derive` console script as a user would."""
import os
import shutil
import subprocess
import sys
from contextlib import contextmanager
from pathlib import Path
from types import SimpleNamespace

import mpmath
import pytest

mpmath.mp.dps = 50  # references in the tests are computed at 50 digits

ROOT = Path(__file__).resolve().parent.parent
DERIVE = Path(sys.executable).parent / "derive"


def run_derive(*args: str, library: Path | None = None, cwd: Path = ROOT, env: dict | None = None
               ) -> subprocess.CompletedProcess:
    """Run `derive` in `cwd`; `library` replaces the problem library (DERIVE_LIBRARY), `env` sets
    other environment variables."""
    env = {**os.environ, **({"DERIVE_LIBRARY": str(library)} if library else {}), **(env or {})}
    return subprocess.run([str(DERIVE), *args], capture_output=True, text=True, cwd=cwd, timeout=600, env=env)


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


@pytest.fixture
def derive():
    return run_derive


def solve(problem_id: str, **values) -> tuple[dict, dict]:
    """(answers as 50-digit mpmath numbers, the whole result) of `derive solve` at 15 digits."""
    from derive import problem, report

    result = report.solve(problem.load(problem_id), {k: str(v) for k, v in values.items()}, 15)
    return {n: mpmath.mpf(a["value"]) for n, a in result["answers"].items()}, result


def close(value, reference, digits: int = 15) -> bool:
    """Within half a unit of the last of `digits` significant digits of the reference."""
    return abs(value - reference) <= abs(reference) * mpmath.mpf(10) ** (1 - digits) / 2


@contextmanager
def kept_scratch(folder: Path):
    """export.pdf compiling in `folder`, kept afterwards (export deletes its scratch folder): a
    test reads TeX's log there and lists what TeX wrote."""
    from derive import export

    @contextmanager
    def scratch(prefix=""):
        folder.mkdir(parents=True)
        yield str(folder)

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(export, "tempfile", SimpleNamespace(TemporaryDirectory=scratch))
        yield folder


#: What TeX and latexmk write beside a document.tex in their scratch folder (the .aux and .pdf
#: are moved out by export.pdf).
TEX_OWN_FILES = {".tex", ".aux", ".log", ".pdf", ".fls", ".fdb_latexmk"}


def document(body: str) -> str:
    """A document in derive's real preamble (templates/preamble.tex.j2)."""
    from derive import render

    return render.render("preamble.tex.j2") + "\\begin{document}\n" + body + "\n\\end{document}\n"
