"""Distractors are derived from mistaken set-ups, and differ from the answer and each other."""
import json

import mpmath

from conftest import copy_library, run_derive
from derive import distractors
from derive.problem import load


def test_rolling_sphere_distractors_are_the_classic_mistakes():
    p = load("rolling_incline")
    values = p.values({"M": "1", "R": "0.1", "H": "1", "theta": "0.5"})
    found = {d["mistake"]: d["value"] for d in distractors.distractors(p, "a", values, 3, limit=10)}
    g_sin = 9.81 * float(mpmath.sin(0.5))
    assert abs(float(found["sliding instead of rolling (ball)"]) - g_sin) < 0.01
    assert abs(float(found["the inertia of a ring for the sphere"]) - g_sin / 2) < 0.01
    assert abs(float(found["the inertia of a disk for the sphere"]) - 2 * g_sin / 3) < 0.01
    right = 5 * g_sin / 7
    assert all(abs(float(v) - right) > 0.005 for v in found.values())
    assert len(set(found.values())) == len(found)


def test_forgotten_parallel_axis_term():
    p = load("parallel_axis_rod")
    found = {d["mistake"]: d["value"] for d in distractors.distractors(p, "I", p.values({"M": "2", "L": "1", "h": "0.3"}), 3)}
    assert found["the parallel-axis term forgotten"] == "0.167"   # M L^2 / 12


def test_sheet_key_carries_distractors(tmp_path):
    library = copy_library(tmp_path)
    (library / "sets" / "roll.yaml").write_text("title: Roll\nproblems: [rolling_incline]\nvariants: 2\n")
    out = tmp_path / "out"
    done = run_derive("sheet", "roll", "--to", "distractors", "--out", str(out), library=library)
    assert done.returncode == 0, done.stderr
    key = json.loads((out / "key.json").read_text())
    answer = key["variants"][0]["problems"]["rolling_incline"]["answers"]["a"]
    assert answer["distractors"] and all(d["value"] != answer["value"] for d in answer["distractors"])
