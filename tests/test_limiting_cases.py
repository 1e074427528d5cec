"""Limiting cases in handouts: each varying parameter to 0 (a mass to infinity too), left out
where sympy has no definite, finite or quick answer or where the problem's conditions break on the
way; at most limiting_cases.MOST per problem, masses first."""
import re

import sympy as sp

from conftest import run_derive
from derive.solution.answers import Solution
from derive.publishing import limiting_cases as lc
from derive.publishing.limiting_cases import limiting_cases
from derive.language.problem import load

m, M, g, theta = sp.symbols("m M g theta", positive=True)


def test_a_massless_disk_lets_the_block_fall_freely():
    p = load("string_wrapped_disk")
    a = Solution(p).expression("a")
    M_, m_, g_ = (p.parameters[n].symbol for n in ("M", "m", "g"))
    cases = {(c.symbol, c.point): c.value for c in limiting_cases(a, {M_: "kg", m_: "kg"})}
    assert cases == {(M_, 0): -g_, (M_, sp.oo): 0, (m_, 0): 0, (m_, sp.oo): -g_}


def test_angles_go_to_zero_only_infinite_values_and_slow_functions_are_left_out():
    cases = limiting_cases(g * theta / (1 + theta), {theta: "rad"})
    assert [(c.point, c.value) for c in cases] == [(0, 0)]
    assert [(c.point, c.value) for c in limiting_cases(g * sp.cos(theta), {theta: "rad"})] == [(0, g)]
    assert limiting_cases(g * sp.exp(theta), {theta: "rad"}) == []  # only sines, cosines, tangents at zero
    assert [(c.point, c.value) for c in limiting_cases(m / M, {M: "kg"})] == [(sp.oo, 0)]  # not M -> 0: infinite
    assert limiting_cases(m / M, {M: "kg"}, allowed=lambda symbol, point: point == 0) == []


def test_the_handout_lists_the_limiting_cases(tmp_path):
    done = run_derive("handout", "string_wrapped_disk", "--out", str(tmp_path / "h"), "--progress", "none")
    assert done.returncode == 0, done.stderr
    tex = (tmp_path / "h" / "string_wrapped_disk.tex").read_text()
    assert r"\section*{Limiting cases}" in tex
    assert r"\lim_{M \to 0} a &= - g && \parbox[t]{0.3\linewidth}{\raggedright\small as the mass of the disk goes to zero}" in tex
    assert r"\lim_{m \to \infty} a &= - g && \parbox" in tex and "as the mass of the block grows without bound" in tex
    assert r"\lim_{m \to 0} T &= 0" in tex  # each answer in turn, each limit once before any twice


def test_the_handout_keeps_to_the_problems_conditions_and_shows_at_most_five(tmp_path):
    """tugged_spool holds r < R: R -> 0 breaks it, so no case has R going to zero; its masses come
    first."""
    done = run_derive("handout", "tugged_spool", "--out", str(tmp_path / "h"), "--progress", "none")
    assert done.returncode == 0, done.stderr
    tex = (tmp_path / "h" / "tugged_spool.tex").read_text()
    shown = re.findall(r"\\lim_\{(.*?) \\to (0|\\infty)\}", tex)
    assert 1 <= len(shown) <= lc.MOST and ("R", "0") not in shown and shown[0][0] == "M", shown
    problem = load("tugged_spool")
    R = problem.parameters["R"].symbol
    a = Solution(problem).signed("a")  # the component: the answer is its magnitude, the spool rolling either way
    assert any(c.symbol == R for c in limiting_cases(a, {R: "m"}))  # the limit exists: the conditions leave it out
