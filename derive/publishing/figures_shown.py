"""A problem's figures as images, for the Python API: the scene's figure and the free-body diagrams
its worked solution shows, compiled by TeX in one document and drawn by poppler, as a worksheet's
figures are (derive.publishing.figure_files).

>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> problem = load("string_wrapped_disk")
>>> sorted(images(problem, Solution(problem)))
['string_wrapped_disk', 'string_wrapped_disk-free-body-block', 'string_wrapped_disk-free-body-disk']
"""
from __future__ import annotations

import tempfile
from pathlib import Path

from derive.language.problem import Problem
from derive.publishing import export, figure, figure_files
from derive.publishing.variants import ProblemVariants
from derive.solution.answers import Solution


def images(problem: Problem, solution: Solution) -> dict[str, tuple[figure_files.Image, str]]:
    """Each figure by its image's name (the problem's id, figure_files.free_body_name), with what it
    shows in words; none where the problem has nothing to draw."""
    drawn = {}
    scene = figure.tikz(problem)
    if scene:
        drawn[problem.id] = (scene, f"Figure of {problem.title}")
    for diagram in ProblemVariants(problem, solution, []).shown_free_bodies.values():
        drawn[figure_files.free_body_name(problem.id, diagram.body)] = (diagram.tikz, diagram.alt)
    if not drawn:
        return {}
    export.require("pdftocairo")
    with tempfile.TemporaryDirectory(prefix="derive-figures-") as scratch:
        tex = Path(scratch) / "figures.tex"
        tex.write_text(figure_files.document([tikz for tikz, _ in drawn.values()]), encoding="utf-8")
        pictures = figure_files.images(list(drawn), export.pdf(tex))
    return {name: (pictures[name], alt) for name, (_, alt) in drawn.items()}
