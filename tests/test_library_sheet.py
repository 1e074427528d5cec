"""Every library problem renders and compiles, and its key equals `derive solve` at its parameters."""
import json
import subprocess

import pytest

from conftest import copy_library, run_derive
from derive import library, problem, report


@pytest.fixture(scope="module")
def everything(tmp_path_factory):
    folder = tmp_path_factory.mktemp("all")
    lib = copy_library(folder)
    ids = [p.stem for p in library.problem_files()]
    (lib / "sets" / "everything.yaml").write_text(f"title: Every problem\nproblems: [{', '.join(ids)}]\nseed: 9\n")
    out = folder / "out"
    done = run_derive("sheet", "everything", "--variants", "1", "--out", str(out), library=lib)
    assert done.returncode == 0, done.stderr[-2000:]
    return ids, out


def test_every_problem_renders_and_compiles(everything):
    ids, out = everything
    text = subprocess.run(["pdftotext", str(out / "worksheet.pdf"), "-"], capture_output=True, text=True).stdout
    text = text.replace("\u2019", "'")  # LaTeX typesets ' as a curly apostrophe
    for problem_id in ids:
        title = problem.load(problem_id).title
        assert title.split()[0] in text
    for name in ("worksheet", "solutions", "key"):
        assert (out / f"{name}.pdf").read_bytes().startswith(b"%PDF")


def test_the_key_equals_derive_solve_at_its_parameters(everything):
    ids, out = everything
    key = json.loads((out / "key.json").read_text())
    (variant,) = key["variants"]
    for problem_id, entry in variant["problems"].items():
        p = problem.load(problem_id)
        given = {n: v["value"] for n, v in entry["parameters"].items() if p.parameters[n].range is not None}
        for name, answer in entry["answers"].items():
            digits = p.asks[name].sig_figs or 3
            solved = report.solve(p, given, digits)["answers"][name]["value"]
            assert answer["value"] == solved, (problem_id, name)
