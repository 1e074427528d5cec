"""Issue 37, item 6: results in the form a teacher writes them. The LaTeX of every library problem's
worked solution (the textbook setups are library problems) is scanned for what no solution manual
prints: acos(sin(alpha)) for pi/2 - alpha, a double negative (-F R (-R cos(theta) + r) for
F R (R cos(theta) - r)), sqrt(tan^2(beta) + 1) for 1/cos(beta), a fraction inside a fraction (which
prints in a script size). Scanned: the results of every problem, and the whole solution where the
student's route is written (derive.solution.textbook; elsewhere the steps shown are the engine's two
routes, the instructor's proof, issue 37 item 3). Quadratures (a period at an amplitude as an integral
over w) and derivatives (d/dt, which print as fractions) are not scanned for fractions. The rewrites:
derive.numbers.range_forms (over the parameter ranges) and derive.text.printed_form (for every value)."""
import re
from pathlib import Path

import pytest
import sympy as sp

from conftest import instructors_solution, student_solution, textbook_files
from derive.core import library
from derive.text.latex import latex_of

PROBLEMS = library.problem_files()


def _group(tex: str, start: int) -> int:
    """The index just past the brace group that opens at `start`."""
    depth = 0
    for i in range(start, len(tex)):
        depth += {"{": 1, "}": -1}.get(tex[i], 0)
        if depth == 0:
            return i + 1
    return len(tex)


def nested_fractions(tex: str) -> list[str]:
    r"""Each \frac with a \frac in its numerator or denominator (a derivative's d/dt left aside)."""
    found = []
    for match in re.finditer(r"\\frac\{", tex):
        middle = _group(tex, match.end() - 1)
        end = _group(tex, middle)
        inside = re.sub(r"\\frac\{d(\^\{\d+\})?\}\{d", "", tex[match.end():end])
        if r"\frac{" in inside and not tex[match.start():end].startswith(r"\frac{d"):
            found.append(tex[match.start():end])
    return found


def inverse_of_cofunction(tex: str) -> list[str]:
    r"""acos(sin ...) and asin(cos ...): pi/2 - the angle."""
    return re.findall(r"\\operatorname\{a(?:cos|sin)\}\{\\left\(\\(?:sin|cos)[^$&]{0,40}", tex)


def tangent_squared_plus_one(tex: str) -> list[str]:
    r"""tan^2(x) + 1: 1/cos^2(x)."""
    found = []
    for match in re.finditer(r"\\tan\^\{2\}\{", tex):
        after = _group(tex, match.end() - 1)
        if re.match(r" \+ 1(?![\d.])", tex[after:]):
            found.append(tex[match.start():after + 4])
    return found


def double_negatives(tex: str) -> list[str]:
    r"""A term with a minus sign whose factor is a parenthesis that opens with one, - F R (- R + r),
    its factors read at the term's own level (and in the numerator and denominator of a fraction
    that is the term)."""
    found = []
    for match in re.finditer(r"(?:^|= |\{|\\left\() ?- ", tex):
        start = match.end()
        parts = [start]
        if tex.startswith(r"\frac{", start):
            parts = [start + 5, _group(tex, start + 5)]
        for part in parts:
            depth, i = 0, part + (1 if tex[part] == "{" else 0)
            while i < len(tex):
                if tex.startswith(r"\left(", i):
                    if depth == 0 and tex.startswith(r"\left(- ", i):
                        found.append(tex[match.start():i + 12])
                    depth += 1
                    i += 6
                    continue
                if tex.startswith(r"\right)", i):
                    depth -= 1
                    i += 7
                    continue
                c = tex[i]
                if c == "{":
                    i = _group(tex, i)
                    continue
                if c in "}&" or depth == 0 and tex.startswith((" + ", " - "), i) or depth < 0:
                    break
                i += 1
    return found


SCANS = {"a fraction in a fraction": nested_fractions, "acos(sin) or asin(cos)": inverse_of_cofunction,
         "tan^2 + 1": tangent_squared_plus_one, "a double negative": double_negatives}


def _equations(tex: str) -> list[str]:
    """The displayed equations of `tex` (its align environments), quadratures left out."""
    return [line for block in re.findall(r"\\begin\{align\*\}(.*?)\\end\{align\*\}", tex, re.S)
            for line in block.split("\\\\\n") if r"\int" not in line]


def unteacherly(tex: str) -> dict[str, list[str]]:
    """What each scan finds in the displayed equations of `tex`."""
    equations = _equations(tex)
    found = {name: [hit for line in equations for hit in scan(line)] for name, scan in SCANS.items()}
    return {name: hits for name, hits in found.items() if hits}


def test_the_scans_find_what_sympy_prints_untidied():
    """Each scan finds its pattern in sympy's own LaTeX of the issue's examples, and none in the
    printed forms derive gives them."""
    F, R, r, theta, alpha, beta, h, w, W = sp.symbols("F R r theta alpha beta h omega_t omega_3", positive=True)
    examples = {"a double negative": -F * R * (-R * sp.cos(theta) + r) / (R**2 + r**2),
                "acos(sin) or asin(cos)": sp.acos(sp.sin(alpha)),
                "tan^2 + 1": sp.sqrt(sp.tan(beta)**2 + 1),
                "a fraction in a fraction": w * (3 + h**2 / R**2) / (6 * W)}
    for name, example in examples.items():
        raw = f"\\begin{{align*}}\nx &= {sp.latex(example)}\n\\end{{align*}}"
        assert list(unteacherly(raw)) == [name], (name, raw)
    from derive.numbers import range_forms
    ranges = {alpha: (0, sp.pi / 3), beta: (0, sp.pi / 4)}
    for name, example in examples.items():
        printed = f"\\begin{{align*}}\nx &= {latex_of(range_forms.within(example, ranges))}\n\\end{{align*}}"
        assert unteacherly(printed) == {}, printed


@pytest.mark.parametrize("path", PROBLEMS, ids=lambda p: Path(p).stem)
def test_results_are_in_textbook_form(path):
    tex, student_route = student_solution(path)
    shown = tex if student_route else tex[tex.index(r"\subsection*{Results}"):]
    assert unteacherly(shown) == {}


@pytest.mark.parametrize("path", sorted({*PROBLEMS, *textbook_files()}), ids=lambda p: Path(p).stem)
def test_the_proof_by_two_routes_has_no_fraction_in_a_fraction(path):
    """The instructor's verification by Lagrange and Newton–Euler (or the two routes where they are
    the worked solution) prints a fraction inside a fraction's numerator or denominator flat, a/b
    (derive.text.latex): sticky_impact_pivoted's b v (5 m/(2 M + 5 m)) sqrt(...)/R^2 and the
    bounce's and the pulley's forces had printed one in a script size."""
    found = [hit for line in _equations(instructors_solution(path)) for hit in nested_fractions(line)]
    assert found == []
