"""Shared helpers: run the installed `derive` console script as a user would."""
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

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
