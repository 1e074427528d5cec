"""Limiting cases in handouts: each varying parameter to 0 (and to infinity when it has a
dimension and is not an angle), left out where sympy has no definite or quick answer."""
import sympy as sp

from conftest import run_derive
from derive.answers import Solution
from derive.limiting_cases import limiting_cases
from derive.problem import load

m, M, g, theta = sp.symbols("m M g theta", positive=True)


def test_a_massless_disk_lets_the_block_fall_freely():
    p = load("string_wrapped_disk")
    a = Solution(p).expression("a")
    M_, m_, g_ = (p.parameters[n].symbol for n in ("M", "m", "g"))
    cases = {(c.symbol, c.point): c.value for c in limiting_cases(a, {M_: "kg", m_: "kg"})}
    assert cases == {(M_, 0): -g_, (M_, sp.oo): 0, (m_, 0): 0, (m_, sp.oo): -g_}


def test_angles_and_pure_numbers_go_to_zero_only_and_functions_of_them_are_left_out():
    cases = limiting_cases(g * theta / (1 + theta), {theta: "rad"})
    assert [(c.point, c.value) for c in cases] == [(0, 0)]
    assert limiting_cases(g * sp.sin(theta), {theta: "rad"}) == []
    assert [c.value for c in limiting_cases(m / M, {M: "kg"})] == [sp.oo, 0]


def test_the_handout_lists_the_limiting_cases(tmp_path):
    done = run_derive("handout", "string_wrapped_disk", "--out", str(tmp_path / "h"), "--progress", "none")
    assert done.returncode == 0, done.stderr
    tex = (tmp_path / "h" / "string_wrapped_disk.tex").read_text()
    assert r"\section*{Limiting cases}" in tex
    assert r"\lim_{M \to 0} a &= - g && \text{mass of the disk}" in tex
    assert r"\lim_{m \to \infty} T &= \frac{M g}{2}" in tex
