"""Safe parser for expressions taken from untrusted problem files.

Text is parsed with ``ast.parse(mode="eval")`` and the sympy tree is built by
hand from a whitelist of node types; nothing is ever evaluated by Python or by
sympy's own string parser.  Number literals become exact sympy Rationals taken
from their source text (``2.35`` -> 47/20), never floats.  ``^`` means power
(it is rewritten to ``**`` before parsing, so it also gets power precedence).
Names resolve only to the symbols the caller declares, plus the constant
``pi``; ``E``, ``I``, ``e``, ``N``, ``S``... are ordinary symbol names.
Inputs are size-limited so that hostile text fails fast instead of hanging.
"""
from __future__ import annotations

import ast
import decimal
import math
import operator
import re
from typing import Callable, Mapping

import sympy

from derive.core import names
from derive.core.errors import InputError

__all__ = ["ExprError", "FUNCTIONS", "RESERVED", "TIME", "parse", "parse_condition"]


class ExprError(InputError):
    """A one-line, human-readable reason why an expression was refused."""


FUNCTIONS: dict[str, Callable] = {
    "sqrt": sympy.sqrt, "sin": sympy.sin, "cos": sympy.cos, "tan": sympy.tan,
    "asin": sympy.asin, "acos": sympy.acos, "atan": sympy.atan,
    "sinh": sympy.sinh, "cosh": sympy.cosh, "tanh": sympy.tanh,
    "exp": sympy.exp, "log": sympy.log, "abs": sympy.Abs,
}
RESERVED: frozenset[str] = frozenset(FUNCTIONS) | {"pi"}

#: The time, in an expression that varies with it (a force, a prescribed path): the same symbol as
#: sympy.physics.mechanics' dynamicsymbols._t.
TIME = sympy.Symbol("t")

MAX_DEPTH = 60
MAX_LOG10 = 1000  # numbers beyond 10**±1000 are refused
MAX_DEGREE = 100  # (x + 1)**100 at most (a power of one symbol may be higher): (x + 1)**1000 would
# make expansions hang later
_OP_TEXT = {ast.FloorDiv: "//", ast.Mod: "%", ast.MatMult: "@", ast.LShift: "<<",
            ast.RShift: ">>", ast.BitOr: "|", ast.BitAnd: "&", ast.Not: "not", ast.Invert: "~"}
_NOT_ALLOWED = {ast.Attribute: "attribute access is", ast.Subscript: "subscripts are",
                ast.Slice: "slices are", ast.Lambda: "lambda is", ast.ListComp: "comprehensions are",
                ast.SetComp: "comprehensions are", ast.DictComp: "comprehensions are",
                ast.GeneratorExp: "comprehensions are", ast.Compare: "comparisons are",
                ast.BoolOp: "'and'/'or' are", ast.IfExp: "conditional expressions are",
                ast.NamedExpr: "assignments are", ast.Tuple: "tuples are", ast.List: "lists are",
                ast.Dict: "dicts are", ast.Set: "sets are", ast.Starred: "starred arguments are",
                ast.JoinedStr: "string literals are", ast.Await: "await is", ast.Yield: "yield is",
                ast.YieldFrom: "yield is"}


_LIMIT = 10**MAX_LOG10


def _check_numbers(expr: sympy.Expr) -> sympy.Expr:
    if any(abs(r.p) > _LIMIT or r.q > _LIMIT for r in expr.atoms(sympy.Rational)):
        raise ExprError(f"number out of range (limit 10**{MAX_LOG10})")
    for power in expr.atoms(sympy.Pow):  # also x**60*x**60 and (x**20)**20, which sympy combines
        if isinstance(power.exp, sympy.Number) and abs(power.exp) > MAX_DEGREE and not (
                power.base.is_Number or power.base.is_Symbol):  # x**100000 alone is harmless
            raise ExprError(f"power {power.exp} of {power.base} is too high (limit {MAX_DEGREE} but for a "
                            "single symbol)")
    return expr


def _rational(digits: str) -> sympy.Rational:
    """Exact Rational from decimal text such as '2.35' or '-1.5e-12'."""
    try:
        d = decimal.Decimal(digits.replace("_", ""))
    except decimal.InvalidOperation:
        raise ExprError(f"not a number: {digits!r}") from None
    if not d.is_finite():
        raise ExprError(f"not a finite number: {digits!r}")
    if d and abs(d.adjusted()) > MAX_LOG10:
        raise ExprError(f"number out of range (limit 10**{MAX_LOG10})")
    return _check_numbers(sympy.Rational(*d.as_integer_ratio()))


def _power(base: sympy.Expr, expo: sympy.Expr) -> sympy.Expr:
    # check sizes BEFORE sympy computes the power, so 9**9**9 fails fast; sympy also
    # distributes numeric powers over products, (2*x)**n -> 2**n*x**n, so check every number in base
    if isinstance(expo, sympy.Number):
        if base.is_zero and expo < 0:
            raise ExprError("division by zero")
        if isinstance(base, sympy.Number) and abs(expo) > MAX_LOG10:
            raise ExprError(f"exponent too large (limit {MAX_LOG10})")
        for r in base.atoms(sympy.Rational):
            if r and abs(expo) * abs(math.log10(abs(r.p)) - math.log10(r.q)) > MAX_LOG10:
                raise ExprError(f"power out of range (limit 10**{MAX_LOG10})")
    return sympy.Pow(base, expo)


_BIG = sympy.Float(f"1e{MAX_LOG10}")
_GROWING = ("exp", "sinh", "cosh")  # exp(10**999) is a number of 10**998 digits: refuse its argument


def _bounded(value: sympy.Expr, what: str = "number") -> sympy.Expr:
    """A constant that is not a plain number (pi**2000, exp(900)*exp(900), log(-1)) must
    evaluate within 10**±MAX_LOG10; expressions of symbols pass (nothing to evaluate)."""
    if value.free_symbols or isinstance(value, sympy.Rational) or value.has(sympy.zoo, sympy.nan, sympy.oo):
        return value
    try:
        parts = value.evalf(3).as_real_imag()
        large = any(part.is_Float and abs(part) > _BIG for part in parts)
    except (ArithmeticError, ValueError, TypeError, RecursionError):
        large = True
    if large:
        raise ExprError(f"{what} out of range (limit 10**{MAX_LOG10})")
    return value


_OPS = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
        ast.Div: operator.truediv, ast.Pow: _power, ast.BitXor: _power}  # ^ is rewritten to ** anyway


_WITH_UNIT = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?\s+[A-Za-z]")


def _syntax_tree(text: str, max_length: int) -> tuple[ast.Expression, str]:
    """Length-check, parse and depth-check ``text``; return (tree, source) (package-internal)."""
    if len(text) > max_length:
        raise ExprError(f"expression too long ({len(text)} characters; limit {max_length})")
    try:  # Python's parser would fold a fullwidth ｍ into m without a word
        names.check(text, "an expression")
    except ValueError as error:
        raise ExprError(str(error)) from None
    text = text.strip().replace("^", "**")
    if not text:
        raise ExprError("empty expression")
    level = deepest = 0  # redundant parentheses leave no AST node, so count them in the text
    for ch in text:
        level += (ch in "([{") - (ch in ")]}")
        deepest = max(deepest, level)
    if deepest > MAX_DEPTH:
        raise ExprError(f"expression nested too deeply (limit {MAX_DEPTH})")
    try:
        tree = ast.parse(text, mode="eval")
    except SyntaxError as e:
        hint = ""
        if _WITH_UNIT.match(text):  # "-250 cm/s": a quantity where an expression goes, or "2 x" for 2*x
            hint = (f" ({text!r}: a product is written with *, and an expression takes no units: give a value with "
                    "a unit as a parameter, and write the parameter here)")
        raise ExprError(f"syntax error: {e.msg}{hint}") from None
    except (ValueError, RecursionError, MemoryError) as e:
        raise ExprError(f"syntax error: {str(e).splitlines()[0] if str(e) else 'too complex'}") from None
    stack = [(tree.body, 1)]  # iterative, so depth itself cannot blow the stack
    while stack:
        node, depth = stack.pop()
        if depth > MAX_DEPTH:
            raise ExprError(f"expression nested too deeply (limit {MAX_DEPTH})")
        stack.extend((c, depth + 1) for c in ast.iter_child_nodes(node) if isinstance(c, ast.expr))
    return tree, text


def _build(tree: ast.Expression, source: str, resolve: Callable[[str], sympy.Expr],
           functions: Mapping[str, Callable]) -> sympy.Expr:
    """Turn a checked syntax tree into sympy from whitelisted nodes only (package-internal)."""
    def build(node: ast.AST) -> sympy.Expr:
        if isinstance(node, ast.BinOp) and type(node.op) in _OPS:
            a, b = build(node.left), build(node.right)
            if isinstance(node.op, ast.Div) and b.is_zero:
                raise ExprError("division by zero")
            return _bounded(_check_numbers(_OPS[type(node.op)](a, b)))
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
            v = build(node.operand)
            return -v if isinstance(node.op, ast.USub) else v
        if isinstance(node, (ast.BinOp, ast.UnaryOp)):
            raise ExprError(f"operator '{_OP_TEXT.get(type(node.op), type(node.op).__name__)}' is not allowed")
        if isinstance(node, ast.Constant):
            v = node.value
            if isinstance(v, bool) or v is None or v is Ellipsis:
                raise ExprError(f"'{v}' is not allowed")
            if isinstance(v, int):
                return _check_numbers(sympy.Integer(v))
            if isinstance(v, float):
                return _rational(ast.get_source_segment(source, node))
            kind = {str: "string", bytes: "bytes", complex: "complex"}.get(type(v), type(v).__name__)
            raise ExprError(f"{kind} literals are not allowed")
        if isinstance(node, ast.Name):
            if node.id in functions:
                raise ExprError(f"'{node.id}' is a function; write {node.id}(...)")
            return resolve(node.id)
        if isinstance(node, ast.Call):
            if not isinstance(node.func, ast.Name):
                raise ExprError("only calls of named functions are allowed")
            name = node.func.id
            if name not in functions:
                allowed = f" (allowed: {', '.join(sorted(functions))})" if functions else ""
                raise ExprError(f"function '{name}' is not allowed{allowed}")
            if node.keywords:
                raise ExprError(f"keyword arguments are not allowed (in {name}(...))")
            if len(node.args) != 1:
                raise ExprError(f"{name}() takes exactly 1 argument ({len(node.args)} given)")
            argument = build(node.args[0])
            if name in _GROWING and not argument.free_symbols:
                try:
                    too_large = abs(sympy.re(argument).evalf(3)) > MAX_LOG10 * math.log(10)
                except (ArithmeticError, ValueError, TypeError):
                    too_large = True
                if too_large:
                    raise ExprError(f"{name}() of a number that large is out of range (limit 10**{MAX_LOG10})")
            return _bounded(functions[name](argument))
        what = _NOT_ALLOWED.get(type(node), f"'{type(node).__name__}' syntax is")
        raise ExprError(f"{what} not allowed")

    result = build(tree.body)
    if result.has(sympy.zoo, sympy.nan, sympy.oo, -sympy.oo):
        raise ExprError("expression is undefined (division by zero?)")
    return result


def parse(text: str | int | float | decimal.Decimal, symbols: Mapping[str, sympy.Symbol], *,
          max_length: int = 1000) -> sympy.Expr:
    """Parse untrusted ``text`` into an exact sympy expression over ``symbols``.

    >>> import sympy
    >>> I, w = sympy.symbols("I omega")
    >>> parse("I*omega^2/2 + 0.25", {"I": I, "omega": w})
    I*omega**2/2 + 1/4

    Numbers already decoded by YAML (int, float, Decimal) are accepted and made
    exact.  Any refusal raises ExprError with a one-line message.
    """
    if isinstance(text, bool):
        raise ExprError("expected an expression, got a boolean")
    if isinstance(text, int):
        return _check_numbers(sympy.Integer(text))
    if isinstance(text, float):
        return _rational(repr(text))
    if isinstance(text, decimal.Decimal):
        return _rational(str(text))
    if not isinstance(text, str):
        raise ExprError(f"expected an expression, got {type(text).__name__}")
    return _build(*_syntax_tree(text, max_length), _resolver(symbols), FUNCTIONS)


def _resolver(symbols: Mapping[str, sympy.Symbol]) -> Callable[[str], sympy.Expr]:
    """Names to the declared symbols (and pi); anything else is an ExprError."""
    clash = sorted(RESERVED & set(symbols))
    if clash:
        raise ExprError(f"symbol name {clash[0]!r} is reserved")
    declared = ", ".join(sorted(symbols)) or "none"

    def resolve(name: str) -> sympy.Expr:
        if name == "pi":
            return sympy.pi
        if name not in symbols:
            raise ExprError(f"unknown symbol '{name}' (declared: {declared})")
        return symbols[name]

    return resolve


_COMPARISONS = {ast.Lt: (1, True), ast.LtE: (1, False), ast.Gt: (-1, True), ast.GtE: (-1, False)}


def parse_condition(text: str, symbols: Mapping[str, sympy.Symbol], *,
                    max_length: int = 1000) -> list[tuple[sympy.Expr, bool]]:
    """Parse an inequality such as ``r < R`` or ``0 <= e < 1`` (chains allowed) into
    (expression, strict) pairs: each expression must be positive (strict) or not negative.

    >>> import sympy
    >>> r, R = sympy.symbols("r R")
    >>> parse_condition("r < R", {"r": r, "R": R})
    [(R - r, True)]
    """
    if not isinstance(text, str):
        raise ExprError(f"expected an inequality such as 'r < R', got {type(text).__name__}")
    tree, source = _syntax_tree(text, max_length)
    if not isinstance(tree.body, ast.Compare):
        raise ExprError("expected an inequality such as 'r < R' (with <, <=, > or >=)")
    resolve = _resolver(symbols)
    sides = [_build(ast.Expression(body=node), source, resolve, FUNCTIONS)
             for node in (tree.body.left, *tree.body.comparators)]
    result = []
    for (left, right), op in zip(zip(sides, sides[1:]), tree.body.ops):
        if type(op) not in _COMPARISONS:
            shown = {ast.Eq: "==", ast.NotEq: "!=", ast.Is: "is", ast.IsNot: "is not", ast.In: "in",
                     ast.NotIn: "not in"}.get(type(op), type(op).__name__)
            raise ExprError(f"comparison '{shown}' is not allowed (use <, <=, > or >=)")
        sign, strict = _COMPARISONS[type(op)]
        result.append((sign * (right - left), strict))
    return result
