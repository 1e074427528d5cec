"""A problem's figures as images, for the Python API: the scene's figure and the free-body diagrams
its worked solution shows, drawn as a worksheet's figures are (derive.publishing.figure_files).

>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> problem = load("string_wrapped_disk")
>>> scene, bodies = shown(problem, Solution(problem))
>>> scene.alt, sorted(bodies)
('Figure of A string wrapped around a disk', ['block', 'disk'])
"""
from __future__ import annotations

from derive.language.problem import Problem
from derive.publishing import figure, figure_files
from derive.publishing.variants import ProblemVariants
from derive.solution.answers import Solution


def shown(problem: Problem, solution: Solution) -> tuple[figure_files.Image | None, dict[str, figure_files.Image]]:
    """The scene's figure (None where the problem has nothing to draw) and each body's free-body
    diagram, compiled in one document, each with what it shows in words (`alt`)."""
    pictures, alts = {}, {}
    scene = figure.tikz(problem)
    if scene:
        pictures[problem.id], alts[problem.id] = scene, f"Figure of {problem.title}"
    bodies = {}
    for diagram in ProblemVariants(problem, solution, []).shown_free_bodies.values():
        name = bodies[diagram.body] = figure_files.free_body_name(problem.id, diagram.body)
        pictures[name], alts[name] = diagram.tikz, diagram.alt
    images = figure_files.drawn(pictures, alts)
    return images.get(problem.id), {body: images[name] for body, name in bodies.items()}
