"""Tests for derive.core.units."""
import subprocess
import time

import pytest
import sympy
from sympy.physics import units as u

from derive.core.units import (UNITS, UnitError, dimension, expression_dimension, latex_unit, siunitx_unit, unicode_unit, parse_quantity, parse_unit, same_dimension, si_factor, to_unit)

pi = sympy.pi

TABLE = {  # unit: (sympy quantity, dimension, exact SI factor)
    "kg": (u.kilogram, {"mass": 1}, 1),
    "g": (u.gram, {"mass": 1}, sympy.Rational(1, 1000)),
    "mg": (u.milligram, {"mass": 1}, sympy.Rational(1, 10**6)),
    "t": (u.tonne, {"mass": 1}, 1000),
    "m": (u.meter, {"length": 1}, 1),
    "cm": (u.centimeter, {"length": 1}, sympy.Rational(1, 100)),
    "mm": (u.millimeter, {"length": 1}, sympy.Rational(1, 1000)),
    "km": (u.kilometer, {"length": 1}, 1000),
    "um": (u.micrometer, {"length": 1}, sympy.Rational(1, 10**6)),
    "nm": (u.nanometer, {"length": 1}, sympy.Rational(1, 10**9)),
    "s": (u.second, {"time": 1}, 1),
    "ms": (u.millisecond, {"time": 1}, sympy.Rational(1, 1000)),
    "min": (u.minute, {"time": 1}, 60),
    "h": (u.hour, {"time": 1}, 3600),
    "N": (u.newton, {"mass": 1, "length": 1, "time": -2}, 1),
    "J": (u.joule, {"mass": 1, "length": 2, "time": -2}, 1),
    "W": (u.watt, {"mass": 1, "length": 2, "time": -3}, 1),
    "Pa": (u.pascal, {"mass": 1, "length": -1, "time": -2}, 1),
    "Hz": (u.hertz, {"time": -1}, 1),
    "rad": (u.radian, {}, 1),
    "deg": (u.degree, {}, pi / 180),
    "rev": (2 * pi * u.radian, {}, 2 * pi),
    "rpm": (2 * pi * u.radian / u.minute, {"time": -1}, pi / 30),
    "Nm": (u.newton * u.meter, {"mass": 1, "length": 2, "time": -2}, 1),
    "AU": (149597870700 * u.meter, {"length": 1}, 149597870700),  # the IAU's (2012); sympy's predates it
    "au": (149597870700 * u.meter, {"length": 1}, 149597870700),
    "astronomical_unit": (149597870700 * u.meter, {"length": 1}, 149597870700),
    "astronomical_units": (149597870700 * u.meter, {"length": 1}, 149597870700),
}


def test_table_is_complete():
    assert set(UNITS) == set(TABLE)


@pytest.mark.parametrize("name", sorted(TABLE))
def test_each_table_unit(name):
    quantity, dim, factor = TABLE[name]
    unit = parse_unit(name)
    assert unit == quantity
    assert dimension(unit) == dim
    assert all(isinstance(k, str) for k in dimension(unit))
    assert sympy.simplify(si_factor(unit) - factor) == 0


@pytest.mark.parametrize("text", ["", "1", "  ", " 1 "])
def test_dimensionless(text):
    assert parse_unit(text) == 1
    assert dimension(parse_unit(text)) == {}
    assert si_factor(parse_unit(text)) == 1


@pytest.mark.parametrize("text, expected", [
    ("m/s^2", u.meter / u.second**2),
    ("m/s**2", u.meter / u.second**2),
    ("m s^-2", u.meter / u.second**2),
    ("kg m^2", u.kilogram * u.meter**2),
    ("kg*m^2", u.kilogram * u.meter**2),
    ("kg  m^2 s^-2", u.kilogram * u.meter**2 / u.second**2),
    ("N m", u.newton * u.meter),
    ("m/(kg s)", u.meter / (u.kilogram * u.second)),
    ("1/s", 1 / u.second),
    ("rad/s", u.radian / u.second),
])
def test_compound_units(text, expected):
    assert parse_unit(text) == expected


def test_dimension_examples():
    assert dimension(parse_unit("m/s^2")) == {"length": 1, "time": -2}
    assert dimension(parse_unit("N*m")) == dimension(parse_unit("J"))
    assert same_dimension(dimension(parse_unit("N m")), dimension(parse_unit("J")))
    assert not same_dimension(dimension(parse_unit("N")), dimension(parse_unit("J")))
    assert same_dimension({"length": 1, "time": 0}, {"length": 1})
    assert dimension(parse_unit("m^(1/2)")) == {"length": sympy.Rational(1, 2)}


def test_si_factor_examples():
    assert si_factor(parse_unit("g")) == sympy.Rational(1, 1000)
    assert si_factor(parse_unit("deg")) == pi / 180
    assert si_factor(parse_unit("rpm")) == pi / 30
    assert si_factor(parse_unit("kg*m^2")) == 1
    assert si_factor(parse_unit("g cm^2")) == sympy.Rational(1, 10**7)
    assert si_factor(parse_unit("km/h")) == sympy.Rational(5, 18)
    assert si_factor(parse_unit("deg^2")) == pi**2 / 32400


@pytest.mark.parametrize("text, default, expected", [
    ("200 g", "kg", (200, "g")),
    ("2", "kg", (2, "kg")),
    ("9.81 m/s^2", "m/s^2", (sympy.Rational(981, 100), "m/s^2")),
    ("-1.5e-12 kg", "kg", (sympy.Rational(-3, 2 * 10**12), "kg")),
    ("30 deg", "rad", (30, "deg")),
    ("30deg", "rad", (30, "deg")),
    ("  0.999999999999  ", "m", (sympy.Rational(999999999999, 10**12), "m")),
    ("+.5 kg m^2", "kg*m^2", (sympy.Rational(1, 2), "kg m^2")),
    (2, "s", (2, "s")),
    (0.1, "s", (sympy.Rational(1, 10), "s")),
])
def test_parse_quantity(text, default, expected):
    value, unit = parse_quantity(text, default)
    assert (value, unit) == expected
    assert isinstance(value, sympy.Rational)


@pytest.mark.parametrize("text", ["abc", "g 200", "1,5 kg", "2 furlong", "1_000 kg", "0x10 m",
                                  "2 kg; import os", "nan kg", "inf", "1e99999 kg", "x" * 2000])
def test_parse_quantity_rejects(text):
    with pytest.raises(UnitError):
        parse_quantity(text, "kg")


def test_parse_quantity_checks_default_unit():
    with pytest.raises(UnitError, match="unknown unit 'parsec'"):
        parse_quantity("2", "parsec")


def test_to_unit_exact():
    assert to_unit(200, "g", "kg") == sympy.Rational(1, 5)
    value, unit = parse_quantity("200 g", "kg")
    assert to_unit(value, unit, "kg") == sympy.Rational(1, 5)
    assert to_unit(30, "deg", "rad") == pi / 6
    assert to_unit(180, "deg", "rad") == pi
    assert to_unit(60, "rpm", "rad/s") == 2 * pi
    assert to_unit(1, "rpm", "Hz") == pi / 30   # rad/s and Hz are both 1/time (radians are dimensionless)
    assert to_unit(1, "rev", "deg") == 360
    assert to_unit(36, "km/h", "m/s") == 10
    assert to_unit(1, "N m", "J") == 1
    assert to_unit(sympy.Rational(1, 2), "h", "min") == 30
    assert to_unit(sympy.Symbol("x"), "cm", "m") == sympy.Symbol("x") / 100
    assert not to_unit(2.35, "g", "kg").atoms(sympy.Float)


@pytest.mark.parametrize("text, declared, si", [
    ("30°", "rad", pi / 6), ("30 °", "rad", pi / 6), ("30 degrees", "rad", pi / 6), ("30 deg", "rad", pi / 6),
    ("30 degree", "rad", pi / 6), ("90 °/s", "rad/s", pi / 2),
    ("60 rev/min", "rad/s", 2 * pi), ("60 rpm", "rad/s", 2 * pi),
    ("2 N m", "J", 2), ("2 Nm", "J", 2), ("2 N*m", "J", 2),
    ("1 eV", "J", sympy.Rational("1.602176634e-19")), ("1 AU", "m", 149597870700), ("1 day", "s", 86400),
    # any other name of sympy.physics.units, looked up as an attribute
    ("2 inch", "m", sympy.Rational("0.0508")), ("1 lightyear", "m", 9460730472580800), ("3 hours", "s", 10800),
    ("1 G", "m^3/(kg*s^2)", sympy.Rational("6.6743e-11")), ("5 percent", "1", sympy.Rational(1, 20)),
])
def test_set_spellings_give_their_si_value(text, declared, si):
    """What `--set NAME=VALUE` takes (Problem.values: parse_quantity, then the declared unit)."""
    value, unit = parse_quantity(text, declared)
    assert to_unit(value, unit, declared) * si_factor(declared) == si


def test_every_sympy_unit_converts_or_is_refused_in_one_line():
    from derive.core.units import sympy_units

    refused = set()
    for name in sympy_units():
        try:
            factor = si_factor(name)
        except UnitError as error:
            assert "cannot express" in str(error) and "\n" not in str(error)
            refused.add(name)
            continue
        assert not factor.atoms(sympy.Float), name  # exact: a decimal constant is taken at its digits
    assert len(sympy_units()) - len(refused) >= 270  # sympy 1.14: 274 of 295; bits, bytes, sr, mil refused
    assert {"bit", "byte", "steradian"} <= refused


def test_unit_names_are_looked_up_never_evaluated():
    for text in ("__class__", "__dict__", "Quantity", "convert_to", "si", "length"):
        with pytest.raises(UnitError, match="unknown unit"):
            parse_unit(text)


def test_unknown_unit_suggests():
    with pytest.raises(UnitError, match="did you mean 'eV'"):
        parse_unit("eVv")
    with pytest.raises(UnitError, match="did you mean 'day'"):
        parse_unit("dya")
    for word in ("revolutions", "turn"):  # a trial's "revolutions" was offered 'volts'
        with pytest.raises(UnitError, match="did you mean 'rev'"):
            parse_unit(word)


def test_to_unit_dimension_mismatch():
    with pytest.raises(UnitError, match="cannot convert g to m: mass vs length"):
        to_unit(1, "g", "m")
    with pytest.raises(UnitError, match="cannot convert N to J"):
        to_unit(1, "N", "J")


@pytest.mark.parametrize("text, message", [
    ("furlong", "unknown unit 'furlong'"),
    ("kg*parsec", "unknown unit 'parsec'"),
    ("pi", "unknown unit 'pi'"),
    ("__import__('os')", "not allowed"),
    ("m.__class__", "attribute access is not allowed"),
    ("sqrt(m)", "function 'sqrt' is not allowed"),
    ("m^m", "exponents must be numbers"),
    ("'m'", "string literals are not allowed"),
    ("m/", "syntax error"),
    ("m" * 300, "too long"),
    ("(" * 70 + "m" + ")" * 70, "nested too deeply"),
    ("m^(10**10**10)", "too large|out of range"),
])
def test_parse_unit_rejects(text, message):
    start = time.perf_counter()
    with pytest.raises(UnitError, match=message) as info:
        parse_unit(text)
    assert "\n" not in str(info.value)
    assert time.perf_counter() - start < 0.5


def test_unit_error_is_value_error():
    assert issubclass(UnitError, ValueError)


# --- expression_dimension -------------------------------------------------------

M, g, R, I, t, x = sympy.symbols("M g R I t x")
UNITS_OF = {M: "kg", g: "m/s^2", R: "m", I: "kg*m^2", t: "s"}


def test_expression_dimension_physical_pendulum():
    assert expression_dimension(sympy.sqrt(M * g * R / I), UNITS_OF) == {"time": -1}
    assert expression_dimension(M * g * R, UNITS_OF) == dimension(parse_unit("J"))
    assert expression_dimension(2 * pi * sympy.sqrt(I / (M * g * R)), UNITS_OF) == {"time": 1}
    assert expression_dimension(sympy.Integer(3), UNITS_OF) == {}


def test_expression_dimension_sums_and_functions():
    energy = I * (g / R) / 2 + M * g * R * (1 - sympy.cos(g * t**2 / R))
    assert expression_dimension(energy, UNITS_OF) == {"mass": 1, "length": 2, "time": -2}
    assert expression_dimension(sympy.exp(-t * sympy.sqrt(g / R)), UNITS_OF) == {}
    assert expression_dimension(sympy.Abs(R), UNITS_OF) == {"length": 1}
    assert expression_dimension(R**2 / R**sympy.Rational(1, 2), UNITS_OF) == {"length": sympy.Rational(3, 2)}


def test_expression_dimension_derivatives_and_functions_of_time():
    theta = sympy.Function("theta")(t)
    eq = I * theta.diff(t, 2) + M * g * R * sympy.sin(theta)
    assert expression_dimension(eq, {**UNITS_OF, theta: "rad"}) == dimension(parse_unit("N m"))


def test_adding_length_and_mass_raises():
    with pytest.raises(UnitError, match="adds (length to mass|mass to length)"):
        expression_dimension(R + M, UNITS_OF)


def test_function_of_dimensional_argument_raises():
    with pytest.raises(UnitError, match=r"sin\(\) of length"):
        expression_dimension(sympy.sin(R), UNITS_OF)
    with pytest.raises(UnitError, match=r"exp\(\) of"):
        expression_dimension(sympy.exp(t), UNITS_OF)
    with pytest.raises(UnitError, match=r"log\(\) of"):
        expression_dimension(sympy.log(M), UNITS_OF)


def test_bad_powers_raise():
    with pytest.raises(UnitError, match="exponent has dimension"):
        expression_dimension(2**R, UNITS_OF)
    with pytest.raises(UnitError, match="non-numeric power"):
        expression_dimension(R**(t / t + x), {**UNITS_OF, x: "1"})


def test_symbol_without_unit_raises():
    with pytest.raises(UnitError, match="symbol 'x' has no unit"):
        expression_dimension(M * x, UNITS_OF)


# --- latex_unit -----------------------------------------------------------------

LATEX = {
    "m/s^2": r"\mathrm{m}/\mathrm{s}^{2}",
    "kg*m^2": r"\mathrm{kg}\,\mathrm{m}^{2}",
    "kg m^2": r"\mathrm{kg}\,\mathrm{m}^{2}",
    "m s^-2": r"\mathrm{m}\,\mathrm{s}^{-2}",
    "m/(kg s)": r"\mathrm{m}/(\mathrm{kg}\,\mathrm{s})",
    "deg": r"{}^{\circ}",
    "deg/s": r"{}^{\circ}/\mathrm{s}",
    "°": r"{}^{\circ}",
    "degrees": r"{}^{\circ}",
    "N m": r"\mathrm{N}\,\mathrm{m}",
    "eV": r"\mathrm{eV}",
    "um": r"\mu\mathrm{m}",
    "rad/s": r"\mathrm{rad}/\mathrm{s}",
    "N": r"\mathrm{N}",
    "1/s": r"1/\mathrm{s}",
    "m^(1/2)": r"\mathrm{m}^{1/2}",
    "": "",
    "1": "",
}


@pytest.mark.parametrize("text", sorted(LATEX))
def test_latex_unit(text):
    assert latex_unit(text) == LATEX[text]


def test_latex_unit_rejects_bad_units():
    with pytest.raises(UnitError, match="unknown unit"):
        latex_unit("furlong")
    with pytest.raises(UnitError):
        latex_unit(r"\input{/etc/passwd}")


def test_latex_unit_compiles(tmp_path):
    body = "\n".join(rf"$2\,{latex_unit(name)}$\par" for name in [*TABLE, *LATEX])
    (tmp_path / "u.tex").write_text(
        "\\documentclass{article}\\usepackage{amsmath}\\begin{document}\n" + body + "\n\\end{document}\n")
    run = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", "u.tex"],
                         cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stdout[-2000:]


SIUNITX = {"m/s^2": r"\unit{m/s^{2}}", "kg m^2": r"\unit{kg.m^{2}}", "m/(kg s)": r"\unit{m/(kg.s)}",
           "deg/s": r"\unit{\degree/s}", "um": r"\unit{\micro m}", "astronomical_unit": r"\unit{astronomical\_unit}",
           "1": "", "": ""}


@pytest.mark.parametrize("text", sorted(SIUNITX))
def test_siunitx_unit(text):
    assert siunitx_unit(text) == SIUNITX[text]


def test_siunitx_units_compile_and_read_as_written(tmp_path):
    """Every unit of the table in the PDFs' form compiles with siunitx and reads as it should."""
    names = [*TABLE, *LATEX, *SIUNITX]
    body = "\n".join(rf"$2\,{siunitx_unit(name)}$\par" for name in names)
    (tmp_path / "u.tex").write_text("\\documentclass{article}\\usepackage[T1]{fontenc}\\usepackage{lmodern}"
                                    "\\usepackage{amsmath}\\usepackage{siunitx}\\begin{document}\n" + body + "\n\\end{document}\n")
    run = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", "u.tex"],
                         cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stdout[-2000:]
    text = subprocess.run(["pdftotext", "u.pdf", "-"], cwd=tmp_path, capture_output=True, text=True).stdout
    lines = [line.strip() for line in text.splitlines() if line.strip()]
    assert "2 kg m2" in lines and "2 m/s2" in lines and "2 µm" in lines and "2 astronomical_unit" in lines


def test_latex_unit_readable_by_pandoc():
    import pypandoc
    source = " ".join(rf"$2\,{latex_unit(name)}$" for name in ["m/s^2", "kg m^2", "deg", "rpm"])
    text = pypandoc.convert_text(source, "plain", format="latex").replace("\u2006", " ")
    assert "m/s²" in text and "kg m²" in text and "∘" in text and "rpm" in text


# --- unicode_unit: a unit as text shows it (LMS questions, key.csv) ------------------

UNICODE = {
    "m/s^2": "m/s²", "kg*m^2": "kg·m²", "kg m^2": "kg·m²", "N*m": "N·m", "N m": "N·m", "rad/s": "rad/s",
    "1/s": "1/s", "J": "J", "kg*m^2/s": "kg·m²/s", "m^2/s": "m²/s", "m^3/s^2": "m³/s²", "J*s": "J·s",
    "J/kg": "J/kg", "kg/m^3": "kg/m³", "kg*m/s": "kg·m/s", "rad/s^2": "rad/s²", "m s^-2": "m·s⁻²",
    "m/(kg s)": "m/(kg·s)", "(kg*m)^2": "(kg·m)²", "deg": "°", "deg/s": "°/s", "°": "°", "um": "μm",
    "eV": "eV", "rpm": "rpm", "m^(1/2)": "m^(1/2)", "": "", "1": "", " 1 ": "",
}


@pytest.mark.parametrize("text", sorted(UNICODE))
def test_unicode_unit(text):
    assert unicode_unit(text) == UNICODE[text]


def test_every_library_unit_reads_as_text_without_operators():
    """No `*`, `^` or a lone "1" in any unit a library problem declares, written as text."""
    from derive.core import library
    from derive.language.problem import load
    problems = [load(path) for path in library.problem_files()]
    declared = {q.unit for p in problems for q in [*p.parameters.values(), *p.asks.values()]}
    assert {"1", "kg*m^2", "m/s^2"} <= declared
    for unit in declared:
        assert not set(unicode_unit(unit)) & set("*^"), unit
    assert unicode_unit("1") == ""
    with pytest.raises(UnitError, match="unknown unit"):
        unicode_unit("furlong")


@pytest.mark.parametrize("text, factor, dim", [
    ("mN", sympy.Rational(1, 1000), {"mass": 1, "length": 1, "time": -2}),
    ("kJ", 1000, {"mass": 1, "length": 2, "time": -2}),
    ("MW", 10**6, {"mass": 1, "length": 2, "time": -3}),
    ("GPa", 10**9, {"mass": 1, "length": -1, "time": -2}),
    ("kHz", 1000, {"time": -1}),
    ("kN*m", 1000, {"mass": 1, "length": 2, "time": -2}),
])
def test_derived_units_take_a_prefix_of_a_thousands_power(text, factor, dim):
    """mN, kJ, MPa: a newcomer's units (a trial's mN and mJ were refused with "did you mean 'm'?")."""
    unit = parse_unit(text)
    assert si_factor(unit) == factor and dimension(unit) == dim
    assert unicode_unit(text) == text.replace("*", "·") and siunitx_unit(text) == rf"\unit{{{text.replace('*', '.')}}}"


def test_atan2_of_two_lengths_is_an_angle():
    """atan2(y, x) is dimensionless when its coordinates share a dimension (a ball in a bowl: its
    answer held atan2 of two lengths, refused as "atan2() of length")."""
    x, y, t = sympy.symbols("x y t", real=True)  # positive x: sympy writes atan(y/x)
    found = {x: "m", y: "m", t: "s"}
    assert expression_dimension(sympy.atan2(y, x), found) == {}
    assert expression_dimension(sympy.atan2(0, x), found) == {}
    with pytest.raises(UnitError, match="must have one dimension"):
        expression_dimension(sympy.atan2(y, t), found)


def test_a_derived_answer_whose_dimension_cannot_be_found_is_an_engine_limit_naming_the_ask(monkeypatch):
    """Not the file's fault: an engine limit (exit 1) naming the file and the ask, not a bare
    "derive: error: atan2() of length" with exit 2, which read as bad input and named nothing."""
    from derive.solution import crosschecks
    from derive.solution.answers import Solution
    from derive.core.errors import EngineLimit
    from derive.language.problem import load

    def refuse(expression, symbol_units):
        raise UnitError("atan2() of length; its argument must be dimensionless")

    solution = Solution(load("string_wrapped_disk"))
    solution.expressions  # noqa: B018 - derived before the dimension check is broken
    monkeypatch.setattr(crosschecks.units, "expression_dimension", refuse)
    with pytest.raises(EngineLimit, match=r"string_wrapped_disk.yaml: ask\.\w+: derive cannot yet find the dimension"):
        solution.checks()
