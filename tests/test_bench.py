"""`derive bench` prints its figures; the sampler redraws until a problem's conditions hold."""
import random


from conftest import copy_library, run_derive
from derive.bench import runs as bench, engines as bench_engines
from derive.language import problem
from derive.publishing import variants
from derive.solution.answers import Solution


def test_bench_sections_print_figures():
    lines = []
    solutions = {"string_wrapped_disk": Solution(problem.load("string_wrapped_disk"))}
    rates = bench.backends(lines.append, solutions, samples=2, repeats=1)
    bench.answer_key(lines.append, solutions, count=5)
    text = "\n".join(lines)
    for method in bench.METHODS:
        assert f"  {method} " in text
        assert rates[method, "typical"] > 0 and rates[method, "extreme"] > 0
    assert "Answer key: 1 problems x 5 variants" in text


def test_the_set_rate_is_printed():
    """The figures are printed (2 variants against 1: the rate itself is noise here, never asserted)."""
    lines = []
    bench.set_rate(lines.append, variants=2, repeats=1)
    rate = next(i for i, line in enumerate(lines) if "marginal:" in line)
    assert "1 variant: 17 answers" in lines[rate - 1] and "2 variants: 34 answers" in lines[rate - 1]
    assert "naive evalf" in lines[rate] and "where the marginal CPU time goes" in lines[rate + 1]
    floor = next(i for i, line in enumerate(lines) if "whatever writes its documents" in line)
    steps = [line.split(" us")[0].rsplit(None, 1)[0].strip() for line in lines[rate + 2:floor]]
    assert steps[0] == "drawing" and "each variant's answers, certified, and the keys" in steps
    parts = [float(line.split(" us")[0].rsplit(None, 1)[1]) for line in lines[floor + 1:]]
    assert len(parts) == 4 and all(part > 0 for part in parts)
    total = float(lines[floor].split(" us in all")[0].rsplit(None, 1)[1])
    # each of the 4 parts and the total printed rounded to 0.1 s: off by at most 5 x 0.05 s (a run was 0.2000000000000028)
    assert abs(total - sum(parts)) <= 0.25


def test_the_sheet_section_says_where_the_time_goes():
    lines = []
    bench.sheet_build(lines.append, with_pdfs=False)
    steps = [line.split()[0] for line in lines[1:]]
    assert "30 variants" in lines[0] and steps[:3] == ["start-up", "derivations", "drawing"]
    assert "each variant's answers, certified, and the keys" in "\n".join(lines)


def test_sampler_redraws_until_the_top_can_precess():
    p = problem.load("top_precession_exact")
    solution = Solution(p)
    (condition, _, _), = solution.conditions
    for n in range(20):
        values = variants.valid_draw(p, solution, random.Random(n))
        si = p.values({k: str(v) for k, v in values.items()})
        assert float(condition.xreplace(si)) >= 0


def test_unsatisfiable_conditions_are_an_error_naming_the_problem(tmp_path):
    library = copy_library(tmp_path)
    path = library / "precession" / "top_precession_exact.yaml"
    path.write_text(path.read_text().replace("range: [300, 1000]", "range: [1, 2]"))
    (library / "sets" / "top.yaml").write_text("title: Top\nproblems: [top_precession_exact]\n")
    done = run_derive("sheet", "top", "--to", "", "--out", str(tmp_path / "out"), library=library)
    assert done.returncode == 2 and "top_precession_exact.yaml: parameters: no draw in 200" in done.stderr


# --- derive against sympy.physics.mechanics (derive.bench.anchors) ---------------------------------

import json  # noqa: E402

import pytest  # noqa: E402

from derive.bench import anchors as bench_anchors  # noqa: E402
from derive.mechanics import lagrange  # noqa: E402
from derive.model.kinematics import Coordinates  # noqa: E402

def _lagrange_at_rest(p) -> dict:
    """derive's Lagrange route in the reference configuration at rest: every acceleration and force."""
    coords = Coordinates(p.scene)
    raw = lagrange.derive(p.scene, coords).at(coords.at_rest_in_reference()).raw
    return {str(k): v for k, v in raw.items()}


@pytest.mark.parametrize("scene", list(bench_anchors.SCENES))
def test_each_anchor_gives_derives_accelerations_and_forces(scene):
    """The bench compares the same physics: at the sample point every acceleration derive computes,
    and each constraint force the anchor computes, is the KanesMethod anchor's."""
    anchor = bench_anchors.SCENES[scene]
    p = problem.load(anchor.reference())
    point = bench_anchors.sample_point(p)
    ours = bench_anchors.numbers(_lagrange_at_rest(p), point)
    theirs = bench_anchors.numbers(anchor.build().in_derive_terms(), point)
    assert {k for k in ours if "ddot" in k} <= set(theirs)
    assert bench_anchors.disagreements(ours, theirs) == []


@pytest.mark.parametrize("scene, ask", [
    ("compound_pendulum", "omega"), ("tightrope_walker", "a"), ("loop_the_loop", "h_slide"),
    ("loop_the_loop", "h_roll"),
    ("loop_the_loop_ball", "h_roll"),  # 27(R - r)/10: derive said 27R/10 - r until the anchor found it
])
def test_the_answers_an_anchor_computes_are_derives(scene, ask):
    anchor = bench_anchors.SCENES[scene]
    p = problem.load(anchor.reference())
    _, answers = anchor.run()
    point = bench_anchors.sample_point(p)
    ours = bench_anchors.numbers({ask: Solution(p).expression(ask)}, point)
    assert bench_anchors.disagreements(ours, bench_anchors.numbers({ask: answers[ask]}, point)) == []


def test_a_disagreement_or_a_missing_quantity_is_reported():
    ours = {"a": [1.0, 0.0], "b": [2.0, 0.0]}
    theirs = {"a": [1.0 + 1e-6, 0.0], "b": [2.0, 0.0], "c": [0.0, 0.0]}
    assert bench_anchors.disagreements(ours, theirs) == ["a: derive 1, anchor 1.000001", "c: not in derive's solution"]


def test_a_scene_whose_anchor_disagrees_shows_no_timing():
    figures = {"seconds": 1.0, "peak_mib": 1.0, "lagrange": 0.1, "newton_euler": 0.1, "inertia": 0.0, "runs": 1,
               "numbers": {"h": [1.0, 0.0]}}
    rows = [{"scene": "good", "derive": figures, "anchor": dict(figures, seconds=0.5), "disagreements": [],
             "agrees": True},
            {"scene": "bad", "derive": dict(figures, seconds=7.0), "anchor": dict(figures, seconds=9.0),
             "disagreements": ["h: derive 1, anchor 2"], "agrees": False}]
    table = bench_engines.scenes_table(rows)
    good, bad = (next(line for line in table.splitlines() if name in line) for name in ("good", "bad"))
    assert "2.0x" in good and "yes (1)" in good
    assert "NO: h: derive 1, anchor 2" in bad and "7.00" not in bad and "9.00" not in bad


def test_derive_bench_json_has_both_engines_and_the_chain_by_each_route():
    """`derive bench --only engines --json` on one scene and n = 1, 2: exit 0, figures for both
    engines and for each route of the chain, derive agreeing with the anchor (no timing is asserted)."""
    done = run_derive("bench", "--only", "engines", "--json", "--scenes", "compound_pendulum", "--max-n", "2",
                      "--repeats", "1")
    assert done.returncode == 0, done.stderr
    figures = json.loads(done.stdout)
    (pendulum,) = figures["scenes"]
    assert pendulum["scene"] == "compound_pendulum" and pendulum["agrees"] and pendulum["disagreements"] == []
    for engine in ("derive", "anchor"):
        assert pendulum[engine]["seconds"] > 0 and pendulum[engine]["peak_mib"] >= 0 and pendulum[engine]["numbers"]
    assert pendulum["derive"]["lagrange"] > 0 and pendulum["derive"]["newton_euler"] > 0
    assert "[1/1] compound_pendulum" in done.stderr and "chain n=2" in done.stderr
    assert [row["n"] for row in figures["chain"]] == [1, 2]
    for row in figures["chain"]:
        assert all(row[route]["seconds"] > 0 for route in bench_engines.ROUTES) and row["disagreements"] == []
        assert row["solve"]["numbers"] and row["anchor"]["numbers"]
    assert figures["settings"] == {"repeats": 1, "limit_cpu_seconds": 300, "max_n": 2, "quick": False}


def test_bench_only_names_every_section():
    from derive import cli

    option = next(o for o in cli.bench.params if o.name == "only")
    assert tuple(option.type.choices) == bench.SECTIONS


def test_each_solution_of_the_extreme_cases_keeps_its_own_group():
    """Solutions made one after another in a generator and freed each keep their own group (keyed
    by id(), a freed solution's id went to the next and merged two problems' groups)."""
    cases = [("string_wrapped_disk", {"m": "1", "M": "2", "R": "0.2"}),
             ("rod_endpoint", {"m": "1", "L": "2"})] * 3
    groups = bench._groups((Solution(problem.load(p)), problem.load(p).values(o)) for p, o in cases)
    assert len(groups) == len(cases)
    for expressions, rows, _ in groups:
        assert all(e.free_symbols <= set(row) for e in expressions for row in rows)
