"""Shared helpers: run the installed `derive` console script as a user would."""
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
DERIVE = Path(sys.executable).parent / "derive"


def run_derive(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess:
    return subprocess.run([str(DERIVE), *args], capture_output=True, text=True, cwd=cwd or ROOT, timeout=600)


@pytest.fixture
def derive():
    return run_derive
