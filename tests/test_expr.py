"""Tests for derive.core.expr, the safe expression parser."""
import decimal
import time

import pytest
import sympy

from derive.core.expr import FUNCTIONS, RESERVED, ExprError, parse

NAMES = ["x", "y", "M", "R", "g", "m", "I", "E", "S", "N", "omega", "beta", "gamma", "lambda_", "e"]
SYM = {n: sympy.Symbol(n) for n in NAMES}
x, y, M, R, g, I, omega = (SYM[n] for n in ["x", "y", "M", "R", "g", "I", "omega"])


def p(text, **kw):
    return parse(text, SYM, **kw)


# --- exact numbers -----------------------------------------------------------

@pytest.mark.parametrize("text, expected", [
    ("0.999999999999", sympy.Rational(999999999999, 10**12)),
    ("1e-12", sympy.Rational(1, 10**12)),
    ("2.35", sympy.Rational(47, 20)),
    ("1.5E3", sympy.Integer(1500)),
    (".5", sympy.Rational(1, 2)),
    ("0.1 + 0.2", sympy.Rational(3, 10)),
    ("0.30000000000000000000000000001", sympy.Rational(30000000000000000000000000001, 10**29)),
    ("42", sympy.Integer(42)),
])
def test_exact_decimals(text, expected):
    result = p(text)
    assert result == expected
    assert isinstance(result, sympy.Rational)
    assert not result.atoms(sympy.Float)


@pytest.mark.parametrize("value, expected", [
    (3, sympy.Integer(3)),
    (2.35, sympy.Rational(47, 20)),
    (0.1, sympy.Rational(1, 10)),
    (decimal.Decimal("0.999999999999"), sympy.Rational(999999999999, 10**12)),
    (decimal.Decimal("-1.5E-12"), sympy.Rational(-3, 2 * 10**12)),
])
def test_numbers_from_yaml(value, expected):
    assert p(value) == expected


@pytest.mark.parametrize("value", [True, None, [1], float("nan"), float("inf"), decimal.Decimal("NaN")])
def test_non_expression_inputs_rejected(value):
    with pytest.raises(ExprError):
        p(value)


# --- operators -----------------------------------------------------------------

@pytest.mark.parametrize("text, expected", [
    ("x^2 + 1", x**2 + 1),           # ^ binds tighter than + (it is a power, not xor)
    ("2*x^2", 2 * x**2),
    ("2^3^2", sympy.Integer(512)),   # right-associative like **
    ("x**2 * y", x**2 * y),
    ("1 + 2*3", sympy.Integer(7)),
    ("(1 + 2)*3", sympy.Integer(9)),
    ("x - y - 1", x - y - 1),
    ("x/y/2", x / (2 * y)),
    ("-x^2", -(x**2)),
    ("-2^2", sympy.Integer(-4)),
    ("-(x + y)", -x - y),
    ("+x", x),
    ("--x", x),
    ("x^-2", x**-2),
    ("M*g*R/I", M * g * R / I),
    ("pi*x", sympy.pi * x),
])
def test_operators_and_precedence(text, expected):
    assert sympy.simplify(p(text) - expected) == 0
    assert p(text) == expected


@pytest.mark.parametrize("name", sorted(FUNCTIONS))
def test_every_function(name):
    expected = sympy.Abs(x) if name == "abs" else getattr(sympy, name)(x)
    assert p(f"{name}(x)") == expected


def test_function_values_are_exact():
    assert p("sqrt(4)") == 2
    assert p("sin(pi/6)") == sympy.Rational(1, 2)
    assert p("abs(-2.5)") == sympy.Rational(5, 2)
    assert p("cos(0)") == 1


def test_reserved_names():
    assert RESERVED == frozenset(FUNCTIONS) | {"pi"}
    assert {"sqrt", "abs", "pi", "log"} <= RESERVED
    with pytest.raises(ExprError, match="reserved"):
        parse("pi", {"pi": sympy.Symbol("pi")})


# --- physics names are plain symbols -------------------------------------------

@pytest.mark.parametrize("name", ["I", "E", "S", "N", "beta", "gamma", "lambda_", "e"])
def test_physics_names_are_ordinary_symbols(name):
    assert p(name) == sympy.Symbol(name)
    assert p(name).is_Symbol


def test_I_is_moment_of_inertia_not_imaginary_unit():
    result = p("I*omega")
    assert result == sympy.Symbol("I") * sympy.Symbol("omega")
    assert not result.has(sympy.I)
    assert p("I^2") == sympy.Symbol("I") ** 2        # would be -1 for the imaginary unit
    assert p("E") != sympy.E
    assert p("S*N") == sympy.Symbol("S") * sympy.Symbol("N")


def test_undeclared_physics_names_are_unknown():
    for name in ["I", "E", "e", "oo", "zoo", "nan"]:
        with pytest.raises(ExprError, match=f"unknown symbol '{name}'"):
            parse(name, {"x": x})


# --- rejections ------------------------------------------------------------------

@pytest.mark.parametrize("text, message", [
    ("__import__('os')", r"function '__import__' is not allowed \(allowed: abs, acos"),
    ("().__class__", "attribute access is not allowed"),
    ("x.real", "attribute access is not allowed"),
    ("x[0]", "subscripts are not allowed"),
    ("lambda: 1", "lambda is not allowed"),
    ("[a for a in x]", "comprehensions are not allowed"),
    ("(a for a in x)", "comprehensions are not allowed"),
    ("'rm -rf'", "string literals are not allowed"),
    ("f'{x}'", "string literals are not allowed"),
    ("sin(x=1)", "keyword arguments are not allowed"),
    ("q + 1", r"unknown symbol 'q' \(declared: E, I, M, N, R, S, beta, e, g, gamma, lambda_, m, omega, x, y\)"),
    ("foo(x)", r"function 'foo' is not allowed \(allowed: abs, acos, asin, atan, cos, cosh, exp, "
               r"log, sin, sinh, sqrt, tan, tanh\)"),
    ("exec('1')", "function 'exec' is not allowed"),
    ("sin(x, y)", r"sin\(\) takes exactly 1 argument \(2 given\)"),
    ("sin()", r"sin\(\) takes exactly 1 argument \(0 given\)"),
    ("sin(*x)", "starred arguments are not allowed"),
    ("sin", "'sin' is a function"),
    ("(x)(y).z", "attribute access is not allowed"),
    ("x(1)", "function 'x' is not allowed"),
    ("1j", "complex literals are not allowed"),
    ("True", "'True' is not allowed"),
    ("None", "'None' is not allowed"),
    ("x // 2", "operator '//' is not allowed"),
    ("x % 2", "operator '%' is not allowed"),
    ("~x", "operator '~' is not allowed"),
    ("not x", "operator 'not' is not allowed"),
    ("x < y", "comparisons are not allowed"),
    ("x and y", "'and'/'or' are not allowed"),
    ("x if y else 1", "conditional expressions are not allowed"),
    ("(x := 1)", "assignments are not allowed"),
    ("x, y", "tuples are not allowed"),
    ("[x]", "lists are not allowed"),
    ("{x: 1}", "dicts are not allowed"),
    ("x +", "syntax error: "),
    ("import os", "syntax error: "),
    ("x; y", "syntax error: "),
    ("-250 cm/s", r"a product is written with \*, and an expression takes no units: give a value with a unit as a "
                  "parameter"),
    ("2 x", r"a product is written with \*"),
    ("", "empty expression"),
    ("   ", "empty expression"),
    ("1/0", "division by zero"),
    ("x/(y - y)", "division by zero"),
    ("0^-1", "division by zero"),
    ("log(0)", "undefined"),
])
def test_rejections(text, message):
    with pytest.raises(ExprError, match=message) as info:
        p(text)
    text_of_error = str(info.value)
    assert "\n" not in text_of_error and "Traceback" not in text_of_error


def test_error_is_value_error():
    assert issubclass(ExprError, ValueError)


@pytest.mark.parametrize("text", ["10**10**10**10", "9**9**9", "9^9^9", "2**(10**1001)",
                                  "(9**999*x)**(10**999)", "(sqrt(2)*x)**100000", "(10**999)**2",
                                  "10.0**1001", "1e1001", "1e-1001", "0.5**2000",
                                  "*".join(["9**999"] * 50)])
def test_huge_numbers_fail_fast(text):
    start = time.perf_counter()
    with pytest.raises(ExprError, match="too large|out of range"):
        p(text)
    assert time.perf_counter() - start < 0.5


def test_large_but_allowed_numbers():
    assert p("10**999") == sympy.Integer(10) ** 999
    assert p("2^-100") == sympy.Rational(1, 2**100)
    assert p("x**100000") == x**100000  # symbolic powers are harmless


def test_overlong_text():
    with pytest.raises(ExprError, match=r"expression too long \(1200 characters; limit 1000\)"):
        p("x+" * 599 + "xy")
    assert p("x", max_length=1) == x
    with pytest.raises(ExprError, match="too long"):
        p("x + y", max_length=3)


@pytest.mark.parametrize("text", ["(" * 200 + "x" + ")" * 200,
                                  "-" * 200 + "x",
                                  "sin(" * 100 + "x" + ")" * 100,
                                  "+".join(["x"] * 100)])
def test_deep_nesting(text):
    start = time.perf_counter()
    with pytest.raises(ExprError, match="nested too deeply"):
        p(text)
    assert time.perf_counter() - start < 0.5


def test_moderate_nesting_is_fine():
    assert p("(" * 20 + "x" + ")" * 20) == x
    assert p("sin(" * 5 + "x" + ")" * 5) == sympy.sin(sympy.sin(sympy.sin(sympy.sin(sympy.sin(x)))))


def test_no_dangerous_calls_in_source():
    import inspect

    import derive.core.expr as module
    source = inspect.getsource(module)
    for forbidden in ["eval(", "exec(", "sympify", "parse_expr", "S(\"", "S('"]:
        assert forbidden not in source.replace('mode="eval"', "")
