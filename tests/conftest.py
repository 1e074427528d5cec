"""Shared helpers: run the installed `derive` console script as a user would."""
import os
import shutil
import subprocess
import sys
from pathlib import Path

import mpmath
import pytest

mpmath.mp.dps = 50  # references in the tests are computed at 50 digits

ROOT = Path(__file__).resolve().parent.parent
DERIVE = Path(sys.executable).parent / "derive"


def run_derive(*args: str, library: Path | None = None) -> subprocess.CompletedProcess:
    """Run `derive`; `library` replaces the problem library (DERIVE_LIBRARY)."""
    env = {**os.environ, "DERIVE_LIBRARY": str(library)} if library else None
    return subprocess.run([str(DERIVE), *args], capture_output=True, text=True, cwd=ROOT, timeout=600, env=env)


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
