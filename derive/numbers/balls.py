"""Answers compiled once into straight-line programs of balls (python-flint's `arb`).

A ball is a midpoint and a radius; every operation on balls rounds outward, so the exact value
of an answer lies in the ball its program returns, whatever the precision (derive.numbers.numeric
decides from the ball which digits are proven). `Program` compiles a problem's answers together,
once for every variant: common subexpressions are eliminated across them (sympy.cse), each
subexpression without a symbol (pi, sqrt(70)/5) is folded into one ball per working precision,
and what remains is written as one Python function of the parameters' balls. Nothing is ever
printed from a name: parameters are x0, x1, ..., temporaries t0, t1, ..., constants K[0], K[1], ...

The functions mapped (`CALLS`) are those the answers use and their relatives; an answer with
anything else (an unevaluated integral, a derivative, an unknown function) is not compiled
(`mapped` is False for it) and derive.numbers.numeric evaluates it by its fallback. A comparison in a
Piecewise that the balls cannot decide at this precision raises Undecided.

>>> import sympy as sp
>>> x, y = sp.symbols("x y", positive=True)
>>> program = Program([sp.sqrt(x) * sp.pi, sp.Piecewise((x, x > y), (y, True))])
>>> root, larger = program.balls({x: sp.Rational(2), y: sp.Rational(3)}, bits=64)
>>> root.contains(sp.pi.evalf(30) * sp.sqrt(2).evalf(30)), larger
(True, 3.00000000000000)
"""
from __future__ import annotations

import functools
import itertools
from typing import Callable, Sequence

import sympy as sp
from flint import acb, arb, ctx, fmpq


class Undecided(ArithmeticError):
    """A comparison the balls cannot decide at this precision (the two sides overlap)."""


def _elliptic_k(m: arb) -> arb:
    """K(m) = pi / (2 agm(1, sqrt(1 - m))), for m < 1 (sympy's parameter convention)."""
    return arb.pi() / (2 * arb(1).agm((1 - m).sqrt()))


def _elliptic_e(m: arb) -> arb:
    value = acb(m).elliptic_e()
    return value.real if value.imag == 0 else arb.nan()


def _undefined():
    raise Undecided("no piece of the Piecewise holds")


def power(base, exponent: int) -> arb:
    """base**exponent for an integer exponent: python-flint's ** gives nan for a ball around 0
    (sqrt(x^2)**2 where x vanishes), so such a ball is raised by products (square and multiply).

    >>> power(arb("0 +/- 1e-20"), 3).contains(0), power(arb(-2), -3)
    (True, -0.125000000000000)
    """
    base = arb(base)
    if not base.contains(0) or exponent < 0:
        return base ** exponent
    result = arb(1)
    for bit in bin(exponent)[2:]:
        result = result * result
        if bit == "1":
            result = result * base
    return result


def _max(*values) -> arb:
    return functools.reduce(lambda a, b: arb(a).max(b), values)


def _min(*values) -> arb:
    return functools.reduce(lambda a, b: arb(a).min(b), values)


#: The sympy functions a program can call, and what it calls for each.
CALLS: dict[type, Callable] = {
    sp.sin: arb.sin, sp.cos: arb.cos, sp.tan: arb.tan, sp.asin: arb.asin, sp.acos: arb.acos, sp.atan: arb.atan,
    sp.sinh: arb.sinh, sp.cosh: arb.cosh, sp.tanh: arb.tanh, sp.asinh: arb.asinh, sp.acosh: arb.acosh,
    sp.atanh: arb.atanh, sp.exp: arb.exp, sp.log: arb.log, sp.gamma: arb.gamma, sp.Abs: abs, sp.sign: arb.sgn,
    sp.atan2: arb.atan2, sp.elliptic_k: _elliptic_k, sp.elliptic_e: _elliptic_e, sp.Max: _max, sp.Min: _min,
}


def _decided(difference, strict: bool) -> bool:
    """Whether a ball is > 0 (strict) or >= 0, decided, else Undecided."""
    difference = arb(difference)
    if difference > 0:
        return True
    if difference < 0:
        return False
    if difference.is_zero():  # exactly zero
        return not strict
    raise Undecided


def _equal(difference) -> bool:
    difference = arb(difference)
    if difference.is_zero():
        return True
    if difference > 0 or difference < 0:
        return False
    raise Undecided


#: Relations, as (left - right, strict) for _decided (a < b is b - a > 0).
_RELATIONS = {sp.StrictGreaterThan: (False, True), sp.GreaterThan: (False, False),
              sp.StrictLessThan: (True, True), sp.LessThan: (True, False)}

_STRUCTURE = (sp.Add, sp.Mul, sp.Pow, sp.Piecewise, sp.functions.elementary.piecewise.ExprCondPair,
              sp.And, sp.Or, sp.Not, sp.Eq, sp.Ne, *_RELATIONS)
_ATOMS = (sp.Symbol, sp.Rational, sp.Float, sp.logic.boolalg.BooleanAtom)


def unmapped(expression: sp.Basic) -> set[str]:
    """The kinds of the outermost nodes of an expression that have no ball (none: it compiles;
    derive.numbers.numeric's fallback evaluates the others).

    >>> t = sp.Symbol("t")
    >>> unmapped(sp.elliptic_k(sp.sin(t) ** 2)), unmapped(2 * sp.Integral(sp.exp(-t**2), (t, 0, 1)))
    (set(), {'Integral'})
    """
    if isinstance(expression, _STRUCTURE + _ATOMS) or expression in (sp.pi, sp.E) or type(expression) in CALLS:
        return set().union(*map(unmapped, expression.args))
    return {type(expression).__name__}


def mapped(expression: sp.Basic) -> bool:
    """Whether an expression compiles into a program of balls (a condition alone is no number; a
    symbol, which sympy counts as a Boolean too, is one: an eccentricity's e >= 0)."""
    return not unmapped(expression) and (expression.is_Symbol or not isinstance(expression, sp.logic.boolalg.Boolean))


def constant(expression: sp.Expr) -> arb:
    """The ball of an expression without symbols, at the current precision (ctx.prec).

    >>> constant(sp.sqrt(70) / 5 + sp.pi / 180 * sp.Rational(3, 2))
    [1.69949999184807 +/- 5.72e-15]
    """
    if expression.is_Rational:
        return arb(fmpq(int(expression.p), int(expression.q)))
    if expression.is_Float:
        sign, mantissa, exponent, _ = expression._mpf_
        mantissa = -mantissa if sign else mantissa
        return arb(fmpq(mantissa * 2**exponent, 1) if exponent >= 0 else fmpq(mantissa, 2**-exponent))
    if expression is sp.pi:
        return arb.pi()
    if expression is sp.E:
        return arb.const_e()
    arguments = [constant(a) for a in expression.args]
    if isinstance(expression, sp.Add):
        return sum(arguments[1:], arguments[0])
    if isinstance(expression, sp.Mul):
        return functools.reduce(lambda a, b: a * b, arguments)
    if isinstance(expression, sp.Pow):
        base, exponent = arguments
        if expression.exp.is_Integer:
            return power(base, int(expression.exp))
        if expression.exp == sp.S.Half:
            return base.sqrt()
        return base ** exponent
    if type(expression) in CALLS:
        return CALLS[type(expression)](*arguments)
    raise ValueError(f"no ball for {type(expression).__name__}")


class Program:
    """Expressions (every one `mapped`) compiled together into one function of balls."""

    def __init__(self, expressions: Sequence[sp.Expr]):
        self.expressions = list(expressions)
        self.symbols = sorted(set().union(*(e.free_symbols for e in self.expressions)), key=str)
        replacements, reduced = sp.cse(self.expressions, symbols=(sp.Dummy() for _ in itertools.count()))
        self._names = {s: f"x{i}" for i, s in enumerate(self.symbols)}
        self._constants: list[sp.Expr] = []
        self._calls: dict[Callable, str] = {}
        lines = []
        for i, (temporary, value) in enumerate(replacements):
            lines.append(f"    t{i} = {self._code(value)}")
            self._names[temporary] = f"t{i}"
        lines.append(f"    return ({''.join(f'arb({self._code(e)}), ' for e in reduced)})")  # a piece may be an integer
        source = f"def program(K, {', '.join(self._names[s] for s in self.symbols)}):\n" + "\n".join(lines)
        namespace = {"arb": arb, "_power": power, "_decided": _decided, "_equal": _equal, "_undefined": _undefined,
                     **{name: call for call, name in self._calls.items()}}
        # safe: the source holds only generated names (x0, t0, K[0], _f0) and integers printed by
        # int(), never a symbol's name or any text of a problem file
        exec(compile(source, "<derive.numbers.balls>", "exec"), namespace)  # noqa: S102  # safe: generated source only (above)
        self.source = source
        self._function = namespace["program"]
        self._folded: dict[int, tuple[arb, ...]] = {}

    def balls(self, values: dict[sp.Symbol, sp.Expr], bits: int) -> tuple[arb, ...]:
        """Each expression's ball at `bits` of working precision (values: exact numbers)."""
        return self.run([[values[s] for s in self.symbols]], bits)[0]

    def run(self, rows: Sequence[Sequence[sp.Expr]], bits: int) -> list[tuple[arb, ...] | Exception]:
        """Each row's balls (a row: the values of self.symbols, in order), or the Undecided it raised."""
        saved, ctx.prec = ctx.prec, bits
        try:
            folded = self._folded.get(bits)
            if folded is None:
                folded = self._folded[bits] = tuple(constant(c) for c in self._constants)
            results = []
            for row in rows:
                try:
                    results.append(self._function(folded, *map(_argument, row)))
                except Undecided as undecided:
                    results.append(undecided)
            return results
        finally:
            ctx.prec = saved

    # --- the printer: sympy nodes as Python source over balls ---------------------------------

    def _code(self, node: sp.Basic) -> str:
        if node in self._names:
            return self._names[node]
        if node.is_Integer:
            return str(int(node))  # exact in every operation with a ball
        if not node.free_symbols and isinstance(node, sp.Expr):  # folded: one ball per precision
            if node not in self._constants:
                self._constants.append(node)
            return f"K[{self._constants.index(node)}]"
        if isinstance(node, sp.Add):
            return "(" + " + ".join(self._code(a) for a in node.args) + ")"
        if isinstance(node, sp.Mul):
            return self._product(node)
        if isinstance(node, sp.Pow):
            return self._power(node.base, node.exp)
        if isinstance(node, sp.Piecewise):
            code = "_undefined()"
            for value, condition in reversed(node.args):
                code = self._code(value) if condition is sp.true else \
                    f"({self._code(value)} if {self._code(condition)} else {code})"
            return code
        if type(node) in _RELATIONS:
            swap, strict = _RELATIONS[type(node)]
            left, right = (node.rhs, node.lhs) if swap else (node.lhs, node.rhs)
            return f"_decided({self._code(left)} - {self._code(right)}, {strict})"
        if isinstance(node, (sp.Eq, sp.Ne)):
            return f"{'' if isinstance(node, sp.Eq) else 'not '}_equal({self._code(node.lhs)} - {self._code(node.rhs)})"
        if isinstance(node, (sp.And, sp.Or)):
            return "(" + (" and " if isinstance(node, sp.And) else " or ").join(self._code(a) for a in node.args) + ")"
        if isinstance(node, sp.Not):
            return f"(not {self._code(node.args[0])})"
        if node is sp.true or node is sp.false:
            return str(bool(node))
        call = CALLS[type(node)]
        name = self._calls.setdefault(call, f"_f{len(self._calls)}")
        return f"{name}({', '.join(self._code(a) for a in node.args)})"

    def _product(self, node: sp.Mul) -> str:
        coefficient, factors = node.as_coeff_mul()
        top, bottom = [], []
        for factor in factors:
            if factor.is_Pow and factor.free_symbols and factor.exp.is_Rational and factor.exp.is_negative:
                bottom.append(self._power(factor.base, -factor.exp))
            else:
                top.append(self._code(factor))
        p, q = (int(coefficient.p), int(coefficient.q)) if coefficient.is_Rational else (1, 1)
        if not coefficient.is_Rational:  # a float coefficient: its own ball
            top.insert(0, self._code(coefficient))
        if abs(p) != 1 or not top:
            top.append(str(abs(p)))
        if q != 1:
            bottom.append(str(q))
        code = "*".join(top) + (f"/({'*'.join(bottom)})" if bottom else "")
        return f"(-{code})" if p < 0 else f"({code})"

    def _power(self, base: sp.Expr, exponent: sp.Expr) -> str:
        code = self._code(base)
        code = code if code.isidentifier() else f"({code})"
        if exponent == 1:
            return code
        if exponent.is_Integer:
            return f"_power({code}, {int(exponent)})"
        if exponent.is_Rational and exponent.q == 2:
            root = f"{code}.sqrt()" if exponent > 0 else f"{code}.rsqrt()"
            return root if abs(exponent.p) == 1 else f"_power({root}, {abs(int(exponent.p))})"
        if exponent.is_Rational:
            return f"_power({code}.root({int(exponent.q)}), {int(exponent.p)})"
        return f"{code}**{self._code(exponent)}"


def _argument(value: sp.Expr | arb | int | float) -> arb:
    """A parameter's ball: an exact rational to the working precision, a ball as it is (a value
    solved in balls), else its constant's ball."""
    if isinstance(value, arb):
        return value
    if isinstance(value, sp.Rational):
        return arb(fmpq(value.p, value.q))
    if isinstance(value, (int, float)):
        return arb(value)
    return constant(value)
