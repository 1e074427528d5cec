"""`derive check` passes on every problem of the library (issue 39): the routes agree, every answer
has its unit's dimensions, and the simulation (of the motion, a chain of states, or a 3D body)
agrees with the closed forms. One test per problem, so that the workers share them (about four
minutes of CPU for the library's 163)."""
import pytest

from conftest import derived
from derive import audit
from derive.core import library

IDS = [path.stem for path in library.problem_files()]


@pytest.mark.slow
@pytest.mark.parametrize("problem_id", IDS)
def test_derive_check_passes(problem_id):
    row = audit.row_of(derived(problem_id))  # the derivation the other tests over the library share
    assert row.passed, row.failure
    assert row.dimensions == "ok" and row.routes != "-", row  # every problem has a second route


def test_the_library_is_large():
    assert len(IDS) == len(set(IDS)) >= 150
