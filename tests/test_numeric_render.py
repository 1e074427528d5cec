"""Significant figures, LaTeX escaping, strict sandboxed templates, LaTeX errors reported."""

import tempfile
from pathlib import Path

import jinja2
import pytest
import sympy as sp

from conftest import copy_library, run_derive
from derive.text.latex import tex_escape
from derive.text import latex_safety
from derive.numbers import numeric
from derive.publishing import render


@pytest.mark.parametrize("value, digits, text", [
    (sp.Rational(125, 1000), 2, "0.12"),       # half to even, on the exact value
    (sp.Rational(135, 1000), 2, "0.14"),
    (sp.Rational(9995, 1000), 3, "10.0"),      # rounding up adds a digit before the point
    (sp.Rational(-327, 100), 15, "-3.27000000000000"),
    (sp.Rational(1, 10**30), 3, "1.00e-30"),
    (sp.Integer(10) ** 30 * 7, 2, "7.0e+30"),
    (sp.pi, 20, "3.1415926535897932385"),
    (sp.Integer(0), 5, "0"),
])
def test_significant(value, digits, text):
    assert numeric.significant(value, digits) == text


def test_evaluate_needs_every_symbol():
    x, y = sp.symbols("x y")
    assert numeric.evaluate(x + y, {x: 1}, 3) is None
    assert numeric.evaluate(x + y, {x: 1, y: sp.Rational(1, 3)}, 3) == "1.33"


def test_tex_escape():
    assert tex_escape("50% of $5 & #1_a {b} ~ ^") == (
        r"50\% of \$5 \& \#1\_a \{b\} \textasciitilde{} \textasciicircum{}")


def test_templates_are_strict_and_sandboxed():
    with pytest.raises(latex_safety.LatexError, match=r"\{\{ q \}\}: not a parameter"):
        render.question("mass {{ q }}", {"m": "1"})
    text = "{{ ''.__class__.__mro__[1].__subclasses__() }}"  # questions are no templates: literal text
    assert render.question(text, {}) == tex_escape(text)
    env = render.templates()
    assert env.variable_start_string == r"\VAR{" and env.undefined is jinja2.StrictUndefined
    with pytest.raises(jinja2.UndefinedError):
        env.from_string(r"\VAR{missing}").render()


def one_problem_library(tmp_path):
    library = copy_library(tmp_path)
    (library / "sets" / "one.yaml").write_text("title: One\nproblems: [rod_midpoint]\n")
    return library


def test_undeclared_name_in_question_is_bad_input(tmp_path):
    library = one_problem_library(tmp_path)
    rod = library / "inertia" / "rod_midpoint.yaml"
    rod.write_text(rod.read_text().replace("{{ m }}", "{{ mass }}"))
    done = run_derive("sheet", "one", "--to", "", "--out", str(tmp_path / "out"), library=library)
    # refused when the file is read (derive.text.latex_safety: placeholders of parameters only)
    assert done.returncode == 2 and "rod_midpoint.yaml: question: {{ mass }}: not a parameter" in done.stderr


def test_latex_error_prints_the_log_lines_of_the_error(tmp_path, monkeypatch):
    """A TeX error (no problem text causes one now: derive.text.latex_safety; here a broken TikZ library
    that TeX finds first on TEXINPUTS) is reported with the lines of its log."""
    library = one_problem_library(tmp_path)
    with tempfile.TemporaryDirectory(dir="/tmp") as packages:  # a short path: TeX's log wraps long lines
        (Path(packages) / "tikzlibraryarrows.meta.code.tex").write_text("\\nosuchmacro\n")
        monkeypatch.setenv("TEXINPUTS", f"{packages}:")
        done = run_derive("sheet", "one", "--to", "pdf", "--out", str(tmp_path / "out"), library=library)
    assert done.returncode == 1
    assert "worksheet.tex did not compile" in done.stderr and "Undefined control sequence" in done.stderr
    assert "internal error" not in done.stderr
    assert not (tmp_path / "out").exists()


def test_an_answer_exactly_zero_by_trigonometry_prints_zero():
    """A push that exactly balances a slope: evalf cannot tell the value from zero; the identity
    sin(1) tan(1/2) = 2 sin(1/2)^2 settles it (it crashed with PrecisionExhausted)."""
    import sympy as sp

    from derive.numbers import numeric

    half = sp.Rational(1, 2)
    value = (-981 * sp.sin(1) * sp.tan(half) / 25 + 1962 * sp.sin(half) ** 2 / 25) / (2 * (sp.sin(half) ** 2 + 3))
    assert numeric.significant(value, 15) == "0"
    assert numeric.significant(value + sp.Rational(1, 10**30), 3) == "1.00e-30"
