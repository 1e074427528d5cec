"""Numeric values of exact answers, correct to the significant digits they show.

Parameter values are exact rationals. Four backends evaluate an answer:

- ``float``: float64 through lambdify (math); fast, not guaranteed (cancellation, extremes);
- ``mpmath``: mpmath at a fixed precision (``digits + 10``) through lambdify;
- ``exact``: sympy's evalf on the exact inputs with strict accuracy (it raises rather than
  return digits it cannot vouch for);
- ``auto`` (the default): float64 and mpmath at ``digits + 20``; when they agree to two digits
  beyond the ones shown (possible for up to 12 digits) the mpmath value is rounded; else mpmath
  again at twice the precision, and when that disagrees too the exact backend decides.
  Disagreement between precisions is what cancellation looks like.

Rounding is half-to-even on the high-precision decimal value, never on a float's repr.

>>> import sympy as sp
>>> m, M, g = sp.symbols("m M g", positive=True)
>>> a = -2*m*g/(M + 2*m)
>>> evaluate(a, {m: sp.Rational(1, 10**12), M: 1, g: sp.Rational(981, 100)}, 15)
'-1.96199999999608e-11'
>>> significant(sp.Rational(1, 3), 3)
'0.333'
"""
from __future__ import annotations

import functools
from decimal import ROUND_HALF_EVEN, Decimal, localcontext
from functools import cached_property, lru_cache

import mpmath
import sympy as sp
from sympy.core.evalf import PrecisionExhausted

GUARD_DIGITS = 10
BACKENDS = ("auto", "float", "mpmath", "exact")


def round_decimal(exact: Decimal, digits: int, rounding: str = ROUND_HALF_EVEN) -> str:
    """A decimal rounded half-to-even (or by `rounding`) to `digits` significant digits, as a string.

    >>> round_decimal(Decimal("0.125"), 2)
    '0.12'
    >>> round_decimal(Decimal("1.41421356237309504880168872420969807856967187537694e998"), 40)
    '1.414213562373095048801688724209698078570e+998'
    """
    if exact == 0:
        return "0"
    with localcontext() as context:  # room for every digit asked (the default holds 28)
        context.prec = max(context.prec, digits + 2)
        quantum = Decimal(1).scaleb(exact.adjusted() - digits + 1)
        rounded = exact.quantize(quantum, rounding=rounding)
        if rounded.adjusted() != exact.adjusted():  # 9.995 -> 10.0: one digit fewer after the point
            rounded = rounded.quantize(quantum.scaleb(1), rounding=rounding)
        exponent = rounded.adjusted()
        if -5 <= exponent < digits:
            return f"{rounded:f}"
        return f"{rounded.scaleb(-exponent):f}e{exponent:+03d}"


def significant(value: sp.Expr, digits: int) -> str:
    """An exact (or exactly evaluable) number as a decimal string with `digits` significant digits."""
    try:
        approx = sp.N(value, digits + GUARD_DIGITS, strict=True) if value != 0 else sp.Integer(0)
    except PrecisionExhausted:  # evalf cannot tell a part from zero: it may be exactly zero (a balance)
        simpler = _by_identities(value)
        try:
            approx = sp.N(simpler, digits + GUARD_DIGITS, strict=True) if simpler != 0 else sp.Integer(0)
        except PrecisionExhausted:
            raise ValueError(f"cannot decide whether {value} is zero") from None
    if not approx.is_real:
        raise ValueError(f"{value} is not a real number")
    return round_decimal(Decimal(str(approx)) if approx != 0 else Decimal(0), digits)


def _by_identities(value: sp.Expr) -> sp.Expr:
    """An exact number simplified by trigonometric identities: its trigonometric functions of
    rational angles written as multiples of one angle x (sin(1) and tan(1/2) as sin(2x) and tan(x)),
    expanded and simplified, x put back (a push that exactly balances a slope cancels to 0)."""
    angles = [f.args[0] for f in value.atoms(sp.sin, sp.cos, sp.tan) if f.args[0].is_Rational]
    if not angles:
        return sp.simplify(value)
    base, x = functools.reduce(sp.gcd, angles), sp.Dummy("x")
    value = value.replace(lambda f: isinstance(f, (sp.sin, sp.cos, sp.tan)) and f.args[0].is_Rational,
                          lambda f: f.func(f.args[0] / base * x))
    return sp.simplify(sp.expand_trig(value)).xreplace({x: base})


def _agree(a, b, digits: int) -> bool:
    return a == b or b != 0 and abs(a - b) <= abs(b) * mpmath.mpf(10) ** -digits


def quadrature(integrand, interval):
    """mpmath's tanh-sinh quadrature of `integrand` over `interval`, each node evaluated at a
    precision that keeps its value: the time along a path (derive.mechanics.states) divides by
    a kinetic energy that is a difference of potential energies, which cancels to zero at the
    nodes tanh-sinh puts next to a start from rest or a turning point. Such a node is evaluated
    again with more digits (its weight is tiny, but a division by zero or the root of a negative
    number is not); whether the result's digits hold
    is decided as for any answer, by agreement between two precisions (Evaluator.value).

    >>> mpmath.nstr(quadrature(lambda x: 1 / mpmath.sqrt(x), (0, 1)), 8)
    '2.0'
    """
    def careful(x):
        digits = mpmath.mp.dps
        for extra in (0, digits, 3 * digits, 7 * digits):
            with mpmath.workdps(digits + extra):
                try:
                    value = integrand(x)
                except ZeroDivisionError:
                    continue
                if not isinstance(value, mpmath.mpc) or value.imag == 0:  # a root of a difference cancelled below 0
                    return +mpmath.re(value)
        raise ValueError(f"the integrand is not real or not finite at {mpmath.nstr(x, 15)}")
    return mpmath.quad(careful, interval)


#: What lambdify calls for an unevaluated integral (sympy's printers write quad(...)).
QUADRATURE = {"quad": quadrature}


class Evaluator:
    """One answer, compiled once for the float and mpmath backends."""

    def __init__(self, expression: sp.Expr):
        self.expression = expression
        self.symbols = sorted(expression.free_symbols, key=str)

    def compile(self) -> "Evaluator":
        """Compile both numeric backends now (a benchmark times evaluation, not compilation)."""
        self._float, self._mpmath  # noqa: B018 - cached_property access compiles
        return self

    @cached_property
    def _float(self):  # compiled on first use: a general answer (with derivatives) never is
        return sp.lambdify(self.symbols, self.expression, [QUADRATURE, "math", "mpmath"])  # mpmath: elliptic_k and the like

    @cached_property
    def _mpmath(self):
        return sp.lambdify(self.symbols, self.expression, [QUADRATURE, "mpmath"])

    def _at(self, values, precision: int):
        with mpmath.workdps(precision):
            exact = (sp.sympify(values[s]) for s in self.symbols)  # safe: derive's own numbers, never text
            arguments = [mpmath.mpf(v.p) / v.q if v.is_Rational else mpmath.mpmathify(sp.N(v, precision + 5))
                         for v in exact]
            result = self._mpmath(*arguments)
            if isinstance(result, mpmath.mpc):
                if abs(result.imag) > abs(result) * mpmath.mpf(10) ** (5 - precision):
                    raise ValueError(f"{self.expression} is not real at these values")
                result = result.real
            return mpmath.mpf(result), Decimal(mpmath.nstr(result, precision, min_fixed=-1, max_fixed=-1)
                                                .replace("e", "E")) if result != 0 else Decimal(0)

    def value(self, values: dict[sp.Symbol, sp.Expr], digits: int, backend: str = "auto") -> str | None:
        """The answer to `digits` significant digits, or None when a symbol has no value."""
        if any(s not in values for s in self.symbols):
            return None
        if not self.symbols or backend == "exact":
            return significant(self.expression.xreplace(values), digits)
        if backend == "float":
            number = float(self._float(*(float(values[s]) for s in self.symbols)))
            return round_decimal(Decimal(repr(number)), digits) if number == number else "nan"
        if backend == "mpmath":
            return round_decimal(self._at(values, digits + GUARD_DIGITS)[1], digits)
        high, high_decimal = self._at(values, digits + 2 * GUARD_DIGITS)
        if digits + 2 <= 14:  # float64 can vouch for this many digits when it agrees
            try:
                fast = mpmath.mpf(float(self._float(*(float(values[s]) for s in self.symbols))))
            except (ValueError, ZeroDivisionError, OverflowError):
                fast = None
            if fast is not None and _agree(fast, high, digits + 2):
                return round_decimal(high_decimal, digits)
        higher, higher_decimal = self._at(values, 2 * (digits + 2 * GUARD_DIGITS))
        if _agree(high, higher, digits + 2):
            return round_decimal(higher_decimal, digits)
        if self.expression.has(sp.Integral):  # evalf's own quadrature is no surer, and far slower
            highest, highest_decimal = self._at(values, 4 * (digits + 2 * GUARD_DIGITS))
            if _agree(higher, highest, digits + 2):
                return round_decimal(highest_decimal, digits)
            raise ValueError(f"the quadrature of {self.expression} does not settle to {digits} digits")
        return significant(self.expression.xreplace(values), digits)  # cancellation: let evalf decide


@lru_cache(maxsize=4096)
def evaluator(expression: sp.Expr) -> Evaluator:
    """The compiled evaluator of an answer (compiled once per answer, however many variants)."""
    return Evaluator(expression)


def evaluate(expression: sp.Expr, values: dict[sp.Symbol, sp.Expr], digits: int, backend: str = "auto") -> str | None:
    """The value of an answer to `digits` significant digits, or None if a symbol has no value."""
    return evaluator(expression).value(values, digits, backend)
