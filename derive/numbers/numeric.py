"""Numeric values of exact answers, correct to the significant digits they show.

Parameter values are exact rationals. Five backends evaluate an answer:

- ``auto`` (the default): certified by balls. The answers are compiled once (derive.numbers.balls:
  common subexpressions eliminated, constants folded) and evaluated in ball arithmetic, whose
  ball holds the exact value; the value is accepted when both ends of the ball round to the same
  decimal at the digits asked (every digit shown, and the rounding of the last, is then proven),
  else the precision is doubled up to MAX_BITS, and past that the ``exact`` backend decides. An
  answer with a function derive.numbers.balls does not map (an integral, a derivative) is evaluated by
  the ``agreement`` backend. Both fallbacks are counted in FALLBACKS;
- ``agreement`` (the policy before balls): float64 (an integral by SciPy's QUADPACK) and mpmath
  at ``digits + 20`` (an integral by tanh-sinh); when they agree
  to two digits beyond the ones shown (possible for up to 12 digits) the mpmath value is
  rounded; else mpmath again at twice the precision, and when that disagrees too the exact
  backend decides. Disagreement between precisions is what cancellation looks like;
- ``float``: float64 through lambdify (math); fast, not guaranteed (cancellation, extremes);
- ``mpmath``: mpmath at a fixed precision (``digits + 10``) through lambdify;
- ``exact``: sympy's evalf on the exact inputs with strict accuracy (it raises rather than
  return digits it cannot vouch for).

Rounding is half-to-even on the exact decimal value (a ball's ends, or a high-precision
decimal), never on a float's repr.

>>> import sympy as sp
>>> m, M, g = sp.symbols("m M g", positive=True)
>>> a = -2*m*g/(M + 2*m)
>>> evaluate(a, {m: sp.Rational(1, 10**12), M: 1, g: sp.Rational(981, 100)}, 15)
'-1.96199999999608e-11'
>>> value, = evaluator((a,)).certified([{m: 1, M: 2, g: 10}], [3])[0]
>>> value.text, value.certificate()
('-5.00', {'method': 'ball', 'radius': '0', 'bits': 64})
>>> significant(sp.Rational(1, 3), 3)
'0.333'
"""
from __future__ import annotations

import functools
import math
import warnings
from collections import Counter
from decimal import ROUND_HALF_EVEN, Context, Decimal
from functools import cached_property, lru_cache
from typing import NamedTuple

import mpmath
import numpy
import sympy as sp
from flint import arb
from sympy.core.evalf import PrecisionExhausted

from derive.numbers import balls

GUARD_DIGITS = 10
BACKENDS = ("auto", "agreement", "float", "mpmath", "exact")


def round_decimal(exact: Decimal, digits: int, rounding: str = ROUND_HALF_EVEN) -> str:
    """A decimal rounded half-to-even (or by `rounding`) to `digits` significant digits, as a string.

    >>> round_decimal(Decimal("0.125"), 2)
    '0.12'
    >>> round_decimal(Decimal("1.41421356237309504880168872420969807856967187537694e998"), 40)
    '1.414213562373095048801688724209698078570e+998'
    """
    if exact == 0:
        return "0"
    context = _context(max(28, digits + 2))  # room for every digit asked (the default holds 28)
    quantum = Decimal(1).scaleb(exact.adjusted() - digits + 1, context)
    rounded = exact.quantize(quantum, rounding, context)
    if rounded.adjusted() != exact.adjusted():  # 9.995 -> 10.0: one digit fewer after the point
        rounded = rounded.quantize(quantum.scaleb(1, context), rounding, context)
    exponent = rounded.adjusted()
    if -5 <= exponent < digits:
        return f"{rounded:f}"
    return f"{rounded.scaleb(-exponent, context):f}e{exponent:+03d}"


@lru_cache(maxsize=None)
def _context(precision: int) -> Context:
    return Context(prec=precision)


def significant(value: sp.Expr, digits: int) -> str:
    """An exact (or exactly evaluable) number as a decimal string with `digits` significant
    digits; a rational (a drawn parameter) by integer arithmetic, exactly.

    >>> significant(sp.Rational(-7285, 10**13), 3), significant(sp.Rational(2, 3) * 10**-30, 2)
    ('-7.28e-10', '6.7e-31')
    """
    if isinstance(value, sp.Rational):
        p, q = int(value.p), int(value.q)
        places = q.bit_length()  # as many as any power of ten q divides needs (q = 2^a 5^b: a + b bits at least)
        scale, rest = divmod(POWERS[places], q)
        if not rest and p:  # a decimal, as every drawn parameter is: by integers (a set writes thousands)
            significand, power = rounded(abs(p) * scale, digits)
            return "-" * (p < 0) + _decimal_text(significand, power - places, digits)
        return round_decimal(_decimal_of(p, q, digits), digits)
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


def _decimal_of(numerator: int, denominator: int, digits: int) -> Decimal:
    """A decimal that rounds as numerator/denominator does to `digits` significant digits: its
    leading digits, and a last one that is 0 only where the quotient ends there (a tie stays one).

    >>> _decimal_of(2, 3, 3), _decimal_of(1, 8, 2)
    (Decimal('0.666661'), Decimal('0.12500'))
    """
    if numerator == 0:
        return Decimal(0)
    shift = digits + 2 - (len(str(abs(numerator))) - len(str(denominator)))  # digits + 2 or + 3 before the sticky one
    whole, rest = divmod(abs(numerator) * 10**shift if shift >= 0 else abs(numerator), denominator * 10**max(-shift, 0))
    sign = "-" if numerator < 0 else ""
    return Decimal(f"{sign}{whole}{1 if rest else 0}e{-shift - 1}")


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


class _Lambdified:
    """One answer through lambdify, for the float, mpmath and agreement backends (compiled on first use)."""

    def __init__(self, expression: sp.Expr):
        self.expression = expression
        self.symbols = sorted(expression.free_symbols, key=str)

    @cached_property
    def _float(self):
        """float64 throughout. An integral goes to SciPy's QUADPACK (Gauss-Kronrod), in float64, a
        method independent of the mpmath tanh-sinh it is checked against: where mpmath's functions
        stood in for math's, math.sin of an mpf ran in float64 anyway, so a cancellation next to
        the ends (a start from rest) failed it, and each such value paid for quadratures at two
        higher precisions. Otherwise math, and mpmath for what math lacks (elliptic_k)."""
        if self.expression.has(sp.Integral):
            return sp.lambdify(self.symbols, self.expression, "scipy")
        return sp.lambdify(self.symbols, self.expression, [QUADRATURE, "math", "mpmath"])

    def _fast(self, values) -> float:
        """The float64 value (nan where float64 cannot evaluate it: the root of a negative number,
        a quadrature that does not converge)."""
        with warnings.catch_warnings(), numpy.errstate(all="ignore"):
            warnings.simplefilter("ignore")  # SciPy's IntegrationWarning: the agreement decides
            try:
                return float(self._float(*(float(values[s]) for s in self.symbols)))
            except (ValueError, ZeroDivisionError, OverflowError, TypeError):
                return math.nan

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

    def float(self, values, digits: int) -> str:
        number = float(self._float(*(float(values[s]) for s in self.symbols)))
        return round_decimal(Decimal(repr(number)), digits) if number == number else "nan"

    def mpmath(self, values, digits: int) -> str:
        return round_decimal(self._at(values, digits + GUARD_DIGITS)[1], digits)

    def agreement(self, values, digits: int) -> str:
        """The policy before balls (the module's docstring), the fallback for what balls do not map."""
        high, high_decimal = self._at(values, digits + 2 * GUARD_DIGITS)
        if digits + 2 <= 14:  # float64 can vouch for this many digits when it agrees
            fast = self._fast(values)
            if math.isfinite(fast) and _agree(mpmath.mpf(fast), high, digits + 2):
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


class Certified(NamedTuple):
    """A value's text and how its digits are vouched for: `method` "ball" (radius_text: a bound
    on the distance from the exact value to the ball's centre, rounded up to two digits, every
    point of the ball rounding to `text`; bits: the working precision), "exact" (sympy's strict
    evalf) or "agreement" (two precisions agreed: the fallback for what balls do not map)."""

    text: str
    method: str
    bits: int | None = None
    radius_text: str | None = None

    def certificate(self) -> dict:
        """What a key records of how the value is vouched for.

        >>> certify(arb(1) / 3, 3, 53).certificate()
        {'method': 'ball', 'radius': '5.6e-17', 'bits': 53}
        """
        if self.method != "ball":
            return {"method": self.method}
        return {"method": "ball", "radius": self.radius_text, "bits": self.bits}


def sign_of(text: str) -> int:
    """The sign of a certified value's text, read from its digits: a condition's value may lie
    beyond what a Decimal holds (M**(10**999) > 0 is 1.9e+477121254...).

    >>> sign_of("-2.5e-3"), sign_of("0.000"), sign_of("1.90152e+4771212547196624372950")
    (-1, 0, 1)
    """
    mantissa = text.lower().partition("e")[0]
    if not mantissa.strip("+-0."):
        return 0
    return -1 if mantissa.startswith("-") else 1


def starting_bits(digits: int) -> int:
    """The first working precision for `digits` significant digits: theirs and 24 bits more, up
    to a whole number of 64-bit words (a ball's midpoint is stored in words: the rest is free,
    and it spares a second pass where a few digits cancel).

    >>> starting_bits(3), starting_bits(15), starting_bits(30)
    (64, 128, 128)
    """
    return -(-(math.ceil(digits * math.log2(10)) + 24) // 64) * 64


def certify(ball: arb, digits: int, bits: int) -> Certified | None:
    """The ball's value to `digits` significant digits when both its ends round to it, else None
    (by integers: this writes every value of a set). The ends are those of the ball in decimals
    (arb's mid_rad_10exp, its radius widened to hold the conversion); the end nearer zero is
    rounded, and the far end must lie below the upper edge of that rounding (rounding is monotone).

    >>> from flint import arb
    >>> certify(arb(1) / 3, 15, 53)
    Certified(text='0.333333333333333', method='ball', bits=53, radius_text='5.6e-17')
    >>> certify(arb("0.125 +/- 1e-20"), 2, 64) is None  # straddles the rounding of 0.125
    True
    """
    if not ball.is_finite():
        return None
    middle, radius, exponent = ball.mid_rad_10exp(_decimals(bits))
    middle, radius, exponent = int(middle), int(radius), int(exponent)
    if not radius:
        if not middle:
            return Certified("0", "ball", bits, "0")
        near = far = abs(middle)
    else:
        low, high = middle - radius, middle + radius
        if low <= 0 <= high:
            return None  # the sign is not proven (a zero balls cannot prove)
        near, far = (low, high) if low > 0 else (-high, -low)
    significand, power = rounded(near, digits)
    if radius:
        twice, edge = (2 * far, (2 * significand + 1) * POWERS[power]) if power >= 0 else \
            (2 * far * POWERS[-power], 2 * significand + 1)  # the far end and the upper edge, doubled
        if twice > edge or twice == edge and significand & 1:
            return None  # the far end rounds to the next value up
    bound, place = rounded(radius, 2, up=True) if radius else (0, 0)
    return Certified("-" * (middle < 0) + _decimal_text(significand, power + exponent, digits), "ball", bits,
                     _decimal_text(bound, place + exponent, 2) if radius else "0")


@lru_cache(maxsize=None)
def _decimals(bits: int) -> int:
    """As many decimal digits as `bits` hold, and two more: a ball's ends read to fewer would
    widen it past a near tie."""
    return math.ceil(bits * math.log10(2)) + 2


def _digit_count(whole: int) -> int:
    """The number of decimal digits of a positive whole number, from its bits (str() of a
    40-digit number costs twice as much): log10(2) is 1233/4096 to 1e-6, exact past 100k bits.

    >>> [_digit_count(n) for n in (1, 9, 10, 99, 100, 10**40 - 1, 10**40)]
    [1, 1, 2, 2, 3, 40, 41]
    """
    estimate = whole.bit_length() * 1233 >> 12
    return estimate + (whole >= POWERS[estimate])


def rounded(whole: int, digits: int, up: bool = False) -> tuple[int, int]:
    """A positive whole number rounded half-to-even (or `up`, away from zero) to `digits`
    significant digits, as (significand, power of ten): the same pair for the same value.

    >>> rounded(12345, 3), rounded(12350, 3), rounded(99951, 3), rounded(12, 3), rounded(12301, 3, up=True)
    ((123, 2), (124, 2), (100, 3), (120, -1), (124, 2))
    """
    drop = _digit_count(whole) - digits
    if drop <= 0:
        return whole * POWERS[-drop], drop
    significand, rest = divmod(whole, POWERS[drop])
    half = 5 * POWERS[drop - 1]
    if (rest > 0) if up else (rest > half or rest == half and significand & 1):
        significand += 1
        if significand == POWERS[digits]:
            return significand // 10, drop + 1
    return significand, drop


class _Powers(dict):
    """10**n by n, each computed once (the rounding of every value of a set reads them)."""

    def __missing__(self, n: int) -> int:
        self[n] = 10**n
        return self[n]


POWERS = _Powers()


def _decimal_text(significand: int, power: int, digits: int) -> str:
    """significand x 10^power (a significand of `digits` digits) as round_decimal writes it:
    positional from 10^-5 up to 10^digits, else a mantissa and an exponent (by integers: this
    writes every certified value of a set).

    >>> _decimal_text(123, -5, 3), _decimal_text(5, 2, 1), _decimal_text(560, -19, 3), _decimal_text(100, 0, 3)
    ('0.00123', '5e+02', '5.60e-17', '100')
    """
    exponent = power + digits - 1
    text = str(significand)
    if not -5 <= exponent < digits:
        return f"{text[0]}{'.' * (digits > 1)}{text[1:]}e{exponent:+03d}"
    if power == 0:
        return text
    text = text.rjust(1 - power, "0")
    return f"{text[:power]}.{text[power:]}"


#: How often each fallback decided a value: "exact" (balls undecided at MAX_BITS) and
#: "agreement: NAME" (an answer with a function NAME that balls do not map).
FALLBACKS: Counter = Counter()
MAX_BITS = 4096


class Evaluator:
    """Answers (a problem's, or one) compiled once for every variant."""

    def __init__(self, expressions: tuple[sp.Expr, ...]):
        self.expressions = expressions
        self.symbols = [frozenset(e.free_symbols) for e in expressions]
        self.mapped = [balls.mapped(e) for e in expressions]
        self._in_program = list(enumerate(i for i, m in enumerate(self.mapped) if m))  # (place in the program, answer)
        self._lambdified = [_Lambdified(e) for e in expressions]

    def compile(self) -> "Evaluator":
        """Compile now (a benchmark times evaluation, not compilation)."""
        self._program  # noqa: B018 - cached_property access compiles
        for lambdified in self._lambdified:
            lambdified._float, lambdified._mpmath  # noqa: B018
        return self

    @cached_property
    def _program(self) -> balls.Program:
        return balls.Program([e for e, m in zip(self.expressions, self.mapped) if m])

    def certified(self, rows: list[dict[sp.Symbol, sp.Expr]], digits: list[int]) -> list[list[Certified | None]]:
        """Each row's answers (rows: values of the symbols) to their digits, None where an
        answer has a symbol without a value."""
        results = [[None] * len(self.expressions) for _ in rows]
        if self._in_program:
            symbols = self._keys(rows)
            self._balls(rows, [r for r, row in enumerate(rows) if all(s in row for s in symbols)], digits, results)
        for r, row in enumerate(rows):
            if None not in results[r]:
                continue
            for i, expression in enumerate(self.expressions):
                if results[r][i] is None and all(s in row for s in self.symbols[i]):
                    if self.mapped[i]:  # a row without some other answer's symbol: this answer alone
                        results[r][i] = evaluator((expression,)).certified([row], [digits[i]])[0][0]
                    else:
                        FALLBACKS["agreement: " + ", ".join(sorted(balls.unmapped(expression)))] += 1
                        results[r][i] = Certified(self._lambdified[i].agreement(row, digits[i]), "agreement")
        return results

    def _keys(self, rows: list[dict[sp.Symbol, sp.Expr]]) -> list[sp.Symbol]:
        """The program's symbols as the rows' own keys: an equal Symbol that is another object (sympy's
        cache makes a new one once the old has left it) costs a sympy comparison at every look-up."""
        own = {key: key for key in rows[0]} if rows else {}
        return [own.get(symbol, symbol) for symbol in self._program.symbols]

    def signs(self, rows: list[dict[sp.Symbol, sp.Expr]]) -> list[list[int | None]]:
        """Each row's answers' signs (1, 0 or -1; None where an answer has a symbol without a
        value), certified: a sign is read from the balls at the first working precision where
        they exclude zero (a condition asks no digits), and from certified()'s digits otherwise
        (a zero, a ball that straddles it, what balls do not map)."""
        results: list[list[int | None]] = [[None] * len(self.expressions) for _ in rows]
        if self._in_program:
            symbols = self._keys(rows)
            together = [r for r, row in enumerate(rows) if all(s in row for s in symbols)]
            outcomes = self._program.run([[rows[r][s] for s in symbols] for r in together], starting_bits(1))
            for r, outcome in zip(together, outcomes):
                if not isinstance(outcome, balls.Undecided):
                    for k, i in self._in_program:
                        results[r][i] = 1 if outcome[k] > 0 else -1 if outcome[k] < 0 else None
        undecided = [r for r, row in enumerate(results) if None in row]
        for r, row in zip(undecided, self.certified([rows[r] for r in undecided], [6] * len(self.expressions))):
            for i, value in enumerate(row):
                if results[r][i] is None and value is not None:
                    results[r][i] = sign_of(value.text)
        return results

    def _balls(self, rows, together: list[int], digits: list[int], results) -> None:
        """The program's answers of the rows `together`, precision doubled for what is not yet
        certified; past MAX_BITS, the exact backend."""
        pending = dict.fromkeys(together, self._in_program)
        bits = starting_bits(max(digits[i] for _, i in self._in_program))
        symbols = self._keys(rows)
        while pending and bits <= MAX_BITS:
            outcomes = self._program.run([[rows[r][s] for s in symbols] for r in pending], bits)
            undecided = {}
            for (r, wanted), outcome in zip(pending.items(), outcomes):
                if isinstance(outcome, balls.Undecided):
                    undecided[r] = wanted
                    continue
                row = results[r]
                for k, i in wanted:
                    row[i] = certify(outcome[k], digits[i], bits)
                    if row[i] is None:
                        undecided.setdefault(r, []).append((k, i))
            pending = undecided
            bits *= 2
        for r, left in pending.items():
            for _, i in left:
                FALLBACKS["exact"] += 1
                results[r][i] = Certified(significant(self.expressions[i].xreplace(rows[r]), digits[i]), "exact")

    def value(self, values: dict[sp.Symbol, sp.Expr], digits: int, backend: str = "auto") -> str | None:
        """The (first) answer to `digits` significant digits, or None when a symbol has no value."""
        expression = self.expressions[0]
        if not all(s in values for s in self.symbols[0]):
            return None
        if not self.symbols[0] or backend == "exact":  # a number (a distractor's): evalf, nothing compiled
            return significant(expression.xreplace(values), digits)
        if backend == "auto":
            return self.certified([values], [digits] * len(self.expressions))[0][0].text
        return getattr(self._lambdified[0], backend)(values, digits)


@lru_cache(maxsize=4096)
def evaluator(expressions: tuple[sp.Expr, ...]) -> Evaluator:
    """The compiled evaluator of answers (compiled once, however many variants)."""
    return Evaluator(expressions)


def evaluate(expression: sp.Expr, values: dict[sp.Symbol, sp.Expr], digits: int, backend: str = "auto") -> str | None:
    """The value of an answer to `digits` significant digits, or None if a symbol has no value."""
    return evaluator((expression,)).value(values, digits, backend)
