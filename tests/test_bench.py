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
