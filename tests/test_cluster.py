"""Derivations on a Dask cluster (issue 40, item 3): `derive sheet --scheduler` on a LocalCluster of
two worker processes builds the same bytes as one process; a wrong or unreachable address, or a
worker whose derive differs, is a clear refusal."""
import re
from pathlib import Path

import pytest
from distributed import Client, LocalCluster

from conftest import run_derive
from derive.core.errors import InputError
from derive.language.problem import load
from derive.publishing import cluster, derivation_cache

PROBLEMS = ("string_wrapped_disk", "rolling_incline", "compound_pendulum", "rod_endpoint")


@pytest.fixture(scope="module")
def scheduler():
    """A cluster of two worker processes (the workers import derive as a remote machine would)."""
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as local:
        yield local.scheduler_address


def _files(out: Path) -> dict[str, bytes]:
    return {str(p.relative_to(out)): p.read_bytes() for p in sorted(out.rglob("*")) if p.is_file()}


def _build(out: Path, *options: str) -> str:
    done = run_derive("sheet", *PROBLEMS, "--variants", "3", "--seed", "2", "--to", "distractors", "--out", str(out),
                      "--progress", "lines", "--no-cache", *options)
    assert done.returncode == 0, done.stderr
    return done.stderr


def test_a_cluster_builds_the_same_bytes_as_one_process(tmp_path, scheduler):
    alone = _build(tmp_path / "alone", "--jobs", "1")
    shared = _build(tmp_path / "cluster", "--scheduler", scheduler)
    assert "on the cluster" not in alone
    done = re.findall(r"deriving (\w+) done on the cluster", shared)
    assert sorted(done) == sorted(PROBLEMS), shared
    reference = _files(tmp_path / "alone")
    assert {"key.json", "solutions.tex", "worksheet.tex"} <= set(reference)
    assert _files(tmp_path / "cluster") == reference


def test_a_problem_that_fails_on_a_worker_is_derived_here_with_its_error(scheduler):
    payloads = dict((n, p) for n, p, _ in cluster.derived([load("rod_endpoint")], scheduler))
    assert derivation_cache.loads(payloads[0], load("rod_endpoint")).expression("I") is not None
    with Client(scheduler) as client:  # a worker's failure comes back as no payload, not as its traceback
        engine, payload = client.submit(cluster._derived_bytes, None, pure=False).result()
    assert engine == derivation_cache.engine() and payload is None


def test_a_worker_running_another_derive_is_refused(scheduler, monkeypatch):
    monkeypatch.setattr(derivation_cache, "engine", lambda: '{"derive": "another"}')
    with pytest.raises(InputError, match=r"its workers run another derive, sympy or python-flint than this one"):
        list(cluster.derived([load("rod_endpoint")], scheduler))


@pytest.mark.parametrize("options, message", [
    (["--scheduler", "10.0.0.5:8786"], "--scheduler 10.0.0.5:8786: expected a Dask scheduler's address, "
                                       "e.g. tcp://host:8786"),
    (["--scheduler", "tcp://127.0.0.1:9", "--jobs", "2"], "--jobs and --scheduler: give one"),
    (["--scheduler", "tcp://127.0.0.1:9"], "--scheduler tcp://127.0.0.1:9: no scheduler answered within 10 s"),
])
def test_a_bad_scheduler_is_refused_in_one_line(tmp_path, options, message):
    done = run_derive("sheet", "rod_endpoint", "--out", str(tmp_path / "out"), "--to", "", "--no-cache", *options)
    assert done.returncode == 2 and done.stderr.startswith(f"derive: error: {message}"), done.stderr
    assert len(done.stderr.splitlines()) == 1 and not (tmp_path / "out").exists()
