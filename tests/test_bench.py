"""`derive bench` prints its figures; the sampler redraws until a problem's conditions hold."""
import random


from conftest import copy_library, run_derive
from derive import bench, problem, sheet
from derive.answers import Solution


def test_bench_sections_print_figures():
    lines = []
    solutions = {"string_wrapped_disk": Solution(problem.load("string_wrapped_disk"))}
    bench.backends(lines.append, solutions, samples=1)
    bench.answer_key(lines.append, solutions, variants=5)
    text = "\n".join(lines)
    for backend in ("float", "mpmath", "auto", "exact"):
        assert f"  {backend} " in text
    assert "Answer key: 1 problems x 5 variants" in text


def test_sampler_redraws_until_the_top_can_precess():
    p = problem.load("top_precession_exact")
    solution = Solution(p)
    (condition, _, _), = solution.conditions
    for n in range(20):
        values = sheet.valid_draw(p, solution, random.Random(n))
        si = p.values({k: str(v) for k, v in values.items()})
        assert float(condition.xreplace(si)) >= 0


def test_unsatisfiable_conditions_are_an_error_naming_the_problem(tmp_path):
    library = copy_library(tmp_path)
    path = library / "precession" / "top_precession_exact.yaml"
    path.write_text(path.read_text().replace("range: [300, 1000]", "range: [1, 2]"))
    (library / "sets" / "top.yaml").write_text("title: Top\nproblems: [top_precession_exact]\n")
    done = run_derive("sheet", "top", "--to", "", "--out", str(tmp_path / "out"), library=library)
    assert done.returncode == 2 and "top_precession_exact.yaml: parameters: no draw in 200" in done.stderr


# --- derive against sympy.physics.mechanics (derive.bench_anchors) ---------------------------------

import pytest  # noqa: E402
import sympy as sp  # noqa: E402

from derive import bench_anchors  # noqa: E402
from derive.mechanics import lagrange  # noqa: E402
from derive.mechanics.kinematics import Coordinates  # noqa: E402


def _point(p, names) -> dict[str, sp.Expr]:
    """One parameter point: the middle of each range (or the value), other sizes at 3/10, 4/10, ..."""
    point = {n: q.value if q.value is not None else (q.range[0] + q.range[1]) / 2 for n, q in p.parameters.items()}
    others = sorted(set(names) - set(point))
    point.update({n: sp.Rational(3 + k, 10) for k, n in enumerate(others)})
    return point


def _agree(p, derived: dict[str, sp.Expr], anchored: dict[str, sp.Expr]) -> list[str]:
    names = {str(s) for e in [*derived.values(), *anchored.values()] for s in e.free_symbols}
    point = _point(p, names)

    def value(e):
        return sp.N(e.xreplace({s: point[str(s)] for s in e.free_symbols}), 30)

    wrong = [f"{k}: derive {derived[k]}, anchor {anchored[k]}" for k in derived
             if abs(value(derived[k]) - value(anchored[k])) > 1e-20 * (1 + abs(value(derived[k])))]
    return wrong


def _reference_solution(p) -> dict[str, sp.Expr]:
    """derive's Lagrange route at the reference configuration at rest: every acceleration and force."""
    coords = Coordinates(p.scene)
    solved = lagrange.derive(p.scene, coords).at(coords.at_rest_in_reference()).raw
    return {str(u): v for u, v in solved.items()}


@pytest.mark.parametrize("scene", list(bench_anchors.SCENES))
def test_each_anchor_scene_has_derives_accelerations_and_forces(scene, tmp_path):
    """The benchmark compares the same physics: at one parameter point, every acceleration and
    constraint force derive computes equals the KanesMethod anchor's, and the anchor has no other."""
    anchor = bench_anchors.SCENES[scene]
    p = problem.load(anchor.reference(tmp_path))
    derived = _reference_solution(p)
    anchored = anchor.build().in_derive_terms()
    assert set(anchored) == set(derived)
    assert _agree(p, derived, anchored) == []


@pytest.mark.parametrize("kind, n", [("pendulum links", 1), ("pendulum links", 3), ("disks on cords", 1),
                                     ("disks on cords", 2)])
def test_the_chains_are_the_same_physics(kind, n, tmp_path):
    write, build = bench_anchors.CHAINS[kind]
    path = tmp_path / "chain.yaml"
    path.write_text(write(n))
    p = problem.load(str(path))
    derived = _reference_solution(p)
    anchored = build(n).in_derive_terms()
    assert set(anchored) == set(derived)
    assert _agree(p, derived, anchored) == []


@pytest.mark.parametrize("scene, ours, theirs, power", [
    ("compound_pendulum", "omega", "omega^2", 2),
    ("tightrope_walker", "a", "omega^2", -2),  # a growth rate: omega^2 = -a^2
    ("loop_the_loop", "h_slide", "h_slide", 1),
    ("loop_the_loop", "h_roll", "h_roll", 1),
    pytest.param("loop_the_loop_ball", "h_roll", "h_roll", 1, marks=pytest.mark.xfail(
        strict=True, reason="derive puts the ball's center at y = 2R - r + r at the top (the absolute top as a "
                            "displacement from its reference position): the normal force there uses a radius R, "
                            "not R - r, and h_roll comes out 27R/10 - r instead of 27R/10 - 17r/10")),
])
def test_what_else_the_anchor_computes_agrees(scene, ours, theirs, power):
    anchor = bench_anchors.SCENES[scene]
    p = problem.load(anchor.source)
    derived = Solution(p).expression(ours)
    expected = {1: derived, 2: derived**2, -2: -derived**2}[power]
    assert _agree(p, {ours: expected}, {ours: anchor.run()[theirs]}) == []


def test_the_engines_section_prints_both_engines_cold(monkeypatch):
    monkeypatch.setattr(bench, "REPEATS", 1)
    lines = []
    figures = bench.engines(lines.append, scenes=["compound_pendulum"], sizes=[1, 2], chains=["pendulum links"])
    text = "\n".join(lines)
    assert "compound_pendulum" in text and "A chain of n pendulum links" in text
    ours, theirs = figures["scenes"]["compound_pendulum"]
    assert ours["total"] > 0 and theirs["total"] > 0 and ours["lagrange"] > 0 and ours["newton_euler"] > 0
    assert [n for n, _, _ in figures["chains"]["pendulum links"]] == [1, 2]


def test_bench_only_names_every_section():
    from derive import cli

    option = next(o for o in cli.bench.params if o.name == "only")
    assert tuple(option.type.choices) == bench.SECTIONS
