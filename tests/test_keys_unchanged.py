"""An answer key is the same, byte for byte, for the same set and seed, from one version of derive
to the next (issue 17): tests/keys/ holds the keys of a set of six problems (a pulley, a
pendulum, rolling, a collision, an orbit, and a top whose draws must be redrawn where it cannot
precess) at seed 17, as built before the per-variant path was made lean. A key that changes
here must come with a test that shows its old value was wrong; then rebuild it:

    PYTHONHASHSEED=0 derive sheet string_wrapped_disk compound_pendulum rolling_incline beetle_lazy_susan \
        kepler_orbit top_precession_exact --variants 4 --seed 17 --to '' --out /tmp/k
    cp /tmp/k/key.json /tmp/k/key.csv tests/keys/six_problems/
"""
from pathlib import Path

import pytest

from conftest import run_derive

PROBLEMS = ("string_wrapped_disk", "compound_pendulum", "rolling_incline", "beetle_lazy_susan", "kepler_orbit",
            "top_precession_exact")
KEYS = Path(__file__).parent / "keys" / "six_problems"


@pytest.fixture(scope="module")
def built(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("keys") / "k"
    done = run_derive("sheet", *PROBLEMS, "--variants", "4", "--seed", "17", "--to", "", "--out", str(out),
                      env={"PYTHONHASHSEED": "0"})
    assert done.returncode == 0, done.stderr
    return out


@pytest.mark.parametrize("name", ["key.json", "key.csv"])
def test_the_key_is_the_one_built_before(built, name):
    assert (built / name).read_bytes() == (KEYS / name).read_bytes(), __doc__
