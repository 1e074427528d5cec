"""Fuzzing the loader and the expression parser with hypothesis (derandomized: the same examples
on every run). Whatever the input, only a one-line InputError escapes, within a time bound, and
nothing runs. The whole file takes about a minute on two cores (max_examples below)."""
import copy
import time
from decimal import Decimal
from pathlib import Path

import pytest
import sympy as sp
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from derive import expr, library, limits, problem
from derive.errors import InputError

FUZZ = settings(derandomize=True, database=None, deadline=None, print_blob=False,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                       HealthCheck.filter_too_much])
BOUND = 20  # seconds any one call may take (a safety net: typical calls take milliseconds)
SYMBOLS = {name: sp.Symbol(name, positive=True) for name in ("x", "y", "m", "R", "E", "I")}


def bounded(call, *args):
    """Call, allowing only InputError with a one-line message out, within BOUND seconds."""
    start = time.monotonic()
    try:
        with limits.time_limit("fuzz", seconds=BOUND):
            result = call(*args)
    except limits.TimeLimitError as error:
        if str(error).startswith("fuzz"):
            pytest.fail(f"{call.__name__} took over {BOUND} s on {args[0]!r:.200}")
        result = error
    except InputError as error:
        result = error
    if isinstance(result, InputError):
        assert str(result) and "\n" not in str(result), repr(str(result))
    assert time.monotonic() - start < BOUND
    return result


# --- expressions -------------------------------------------------------------------------------

EXPRESSION_ALPHABET = "0123456789.eE_+-*/^()[], xymREI" + "sqrtincoaexplgb" + "'\"@%!~<>=&|\\:;{}#\t\n"


@settings(FUZZ, max_examples=2000)
@given(st.one_of(st.text(max_size=120), st.text(alphabet=EXPRESSION_ALPHABET, max_size=120)))
def test_expression_random_text(text):
    result = bounded(expr.parse, text, SYMBOLS)
    assert isinstance(result, (sp.Expr, InputError))


def _numbers():
    return st.one_of(st.integers(-10**6, 10**6).map(str), st.integers(0, 2000).map(lambda k: f"10**{k}"),
                     st.decimals(allow_nan=False, allow_infinity=False, places=4).map(str),
                     st.sampled_from(["1e999", "1e-999", "1e1001", "9**9**9", "10**10**10**10", "0", "0.0"]))


def _expressions():
    leaves = st.one_of(_numbers(), st.sampled_from(sorted(SYMBOLS) + ["pi"]))
    return st.recursive(leaves, lambda inner: st.one_of(
        st.tuples(inner, st.sampled_from(["+", "-", "*", "/", "**", "^"]), inner).map(lambda t: f"({t[0]}{t[1]}{t[2]})"),
        st.tuples(st.sampled_from(sorted(expr.FUNCTIONS)), inner).map(lambda t: f"{t[0]}({t[1]})"),
        inner.map(lambda e: f"-{e}"),
    ), max_leaves=40)


@settings(FUZZ, max_examples=1500)
@given(_expressions())
def test_expression_generated(text):
    result = bounded(expr.parse, text, SYMBOLS)
    if isinstance(result, sp.Expr):
        assert not result.has(sp.zoo, sp.nan, sp.oo)


@settings(FUZZ, max_examples=100)
@given(st.lists(st.sampled_from(["10", "9", "2", "x", "0.5", "(x+1)", "1e300", "-1"]), min_size=2, max_size=12),
       st.sampled_from(["**", "^"]))
def test_power_towers(parts, operator):
    bounded(expr.parse, operator.join(parts), SYMBOLS)


@pytest.mark.parametrize("text", [
    "10**10**10**10", "9**9**9**9", "x**10**10**10", "(x+1)**1000", "x**60*x**60", "(x**20)**20", "2^3^4^5^6",
    "1e100000", "(" * 10000 + "x" + ")" * 10000, "-" * 900 + "x", "+".join(["x"] * 400), "x" * 100000,
    "sqrt(" * 70 + "x" + ")" * 70, "exp(exp(exp(exp(exp(1000)))))",
])
def test_expression_refused_fast_or_kept_small(text):
    start = time.monotonic()
    result = bounded(expr.parse, text, SYMBOLS)
    assert time.monotonic() - start < 2
    assert isinstance(result, InputError) or sp.count_ops(result) < 2000


@pytest.mark.parametrize("text", ["__import__('os').system('echo pwned > /tmp/derive-pwned')",
                                  "().__class__.__bases__[0].__subclasses__()", "open('/etc/passwd')",
                                  "eval('1')", "lambda: 1", "x.__class__", "[x for x in ()]", "exec('x=1')"])
def test_expression_runs_no_code(text):
    result = bounded(expr.parse, text, SYMBOLS)
    assert isinstance(result, InputError)
    assert not Path("/tmp/derive-pwned").exists()


# --- problem files -----------------------------------------------------------------------------

def _yaml_values():
    scalars = st.one_of(st.none(), st.booleans(), st.integers(), st.floats(allow_nan=True), st.text(max_size=30),
                        st.sampled_from(["m", "2*m", "kg", "m/s^2", "disk", "x**10**10", "$\\input{/etc/passwd}$",
                                         "{{ ''.__class__ }}", "1e999"]))
    return st.recursive(scalars, lambda inner: st.one_of(
        st.lists(inner, max_size=4), st.dictionaries(st.text(max_size=12), inner, max_size=4)), max_leaves=25)


@settings(FUZZ, max_examples=1000)
@given(st.one_of(st.text(max_size=300), _yaml_values().map(lambda v: yaml.safe_dump(v, allow_unicode=True))))
def test_problem_random_yaml(text):
    result = bounded(problem.parse, text, Path("fuzz.yaml"))
    assert isinstance(result, (problem.Problem, InputError))


def _library():
    documents = []
    for path in library.problem_files():
        documents.append(yaml.safe_load(path.read_text(encoding="utf-8")))
    return documents


LIBRARY = _library()


def _places(tree, path=()):
    """Every (path, value) of a loaded YAML tree, the root excluded."""
    items = tree.items() if isinstance(tree, dict) else enumerate(tree) if isinstance(tree, list) else []
    for key, value in items:
        yield path + (key,), value
        yield from _places(value, path + (key,))


def _junk():
    return st.one_of(_yaml_values(), _expressions(), st.sampled_from([
        "(x+1)**1000", "10**10**10**10", "exp(exp(exp(1000)))", "r**99*sin(phi)**99", "\\write18{ls}",
        "\\csname input\\endcsname", "^^5cinput{/etc/passwd}", "{% include '/etc/passwd' %}",
        "{{ cycler.__init__.__globals__ }}", "-1", "0", "../../etc", "/etc/passwd", "a" * 5000]))


@settings(FUZZ, max_examples=2500)
@given(st.integers(0, len(LIBRARY) - 1), st.integers(0, 10**6), _junk(), st.booleans())
def test_problem_mutated_library_file(which, where, junk, replace_key):
    document = copy.deepcopy(LIBRARY[which])
    places = list(_places(document))
    path, _ = places[where % len(places)]
    parent = document
    for key in path[:-1]:
        parent = parent[key]
    if replace_key and isinstance(parent, dict) and isinstance(junk, str):
        parent[junk] = parent.pop(path[-1])
    else:
        parent[path[-1]] = junk
    text = yaml.safe_dump(document, allow_unicode=True, sort_keys=False)
    result = bounded(problem.parse, text, Path("mutated.yaml"))
    assert isinstance(result, (problem.Problem, InputError))


# --- fixed hostile inputs ----------------------------------------------------------------------

BILLION_LAUGHS = "\n".join(
    ["a: &a [lol, lol, lol, lol, lol, lol, lol, lol, lol]"]
    + [f"{chr(98 + i)}: &{chr(98 + i)} [{', '.join(['*' + chr(97 + i)] * 9)}]" for i in range(8)]
    + ["id: x", "title: *i"])


@pytest.mark.parametrize("text, reason", [
    (BILLION_LAUGHS, "aliases"),
    ("a: " + "[" * 5000 + "]" * 5000, "nested deeper"),
    ("x: " + "y" * 10**6, "characters"),
    ("x: .inf", "finite"),
    ("x: !!python/object/apply:os.system [ls]", "constructor"),
    ("x: " + "9" * 6000, "cannot read"),
    ("? [a, b]\n: c", "key"),
])
def test_hostile_yaml_refused_fast(text, reason):
    start = time.monotonic()
    result = bounded(problem.parse, text, Path("hostile.yaml"))
    assert time.monotonic() - start < 2
    assert isinstance(result, InputError) and reason in str(result)


def test_library_files_still_load():
    for path in library.problem_files():
        problem.load(str(path))


def test_decimal_keys_and_values_stay_exact():
    from derive.reader import Loader
    assert yaml.load("m: 0.1", Loader=Loader) == {"m": Decimal("0.1")}
