r"""Answers printed in the grouping a textbook prints them in; for printing only: the value is the same.

sympy's canonical forms are not the notes': it keeps cos(θ)·tan(θ) where sin(θ) is meant, splits
the root of a product of positive symbols into one root per symbol, 2π √(I + M R²)/(√M √R √g), and
leaves sin²(α)/|sin(α)|. `textbook` rewrites a product's sines, cosines and tangents of one angle
as few functions as it can (cos·tan as sin; sin/cos as tan, where that leaves no fraction of them),
x²/|x| of a real x as |x|, the square roots of a product or a quotient as one root (rebuilt
unevaluated, so that sympy does not split it again), and a product over a sum that holds one of the
sum's terms as a scale times that term's share of the sum, g·2m/(M + 2m) as the notes write it.

>>> theta, M, R, g, I = sp.symbols("theta M R g I", positive=True)
>>> textbook(sp.cos(theta) * sp.tan(theta)), textbook(g * sp.sin(theta) / sp.cos(theta))
(sin(theta), g*tan(theta))
>>> sp.latex(textbook(2 * sp.pi * sp.sqrt(I + M * R**2) / (sp.sqrt(M) * sp.sqrt(R) * sp.sqrt(g))))
'2 \\pi \\sqrt{\\frac{I + M R^{2}}{M R g}}'
"""
from __future__ import annotations

from collections import defaultdict

import sympy as sp

HALF = sp.Rational(1, 2)


def textbook(expression):
    """`expression` in the textbook's grouping (a number or a non-sympy object as it is)."""
    if not isinstance(expression, sp.Basic):
        return expression
    expression = unnested(plus_first(complements(expression)))
    return roots_beside(collected_roots(shares(_absolute(_trigonometric(expression)))))


def _trigonometric(expression: sp.Basic) -> sp.Basic:
    """Each product's sin^s cos^c tan^t of one angle as sin^(s+t) cos^(c-t), then as tan^n where
    sin^n/cos^n is all of it.

    A double angle's sine beside the angle's own functions is 2 sin cos first (a time up a slope,
    3 v0 cos(x)/(g sin(2x)), is 3 v0/(2 g sin(x))).

    >>> x, v, g = sp.symbols("x v g")
    >>> _trigonometric(sp.sin(x)**2 / sp.cos(x)**2), _trigonometric(sp.sin(x)**2 / sp.cos(x)), _trigonometric(sp.tan(x) / sp.sin(x))
    (tan(x)**2, sin(x)**2/cos(x), 1/cos(x))
    >>> _trigonometric(3 * v * sp.cos(x) / (g * sp.sin(2 * x))), _trigonometric(g * sp.sin(2 * x))
    (3*v/(2*g*sin(x)), g*sin(2*x))
    """
    def trigonometric_product(e) -> bool:
        return isinstance(e, sp.Mul) and sum(1 for f in e.args if _trig_power(f) is not None) > 1

    def rewritten(product: sp.Mul) -> sp.Expr:
        powers, rest = defaultdict(lambda: {sp.sin: 0, sp.cos: 0}), []
        angles = {found[1] for found in map(_trig_power, product.args) if found is not None}
        for factor in product.args:
            found = _trig_power(factor)
            if found is None:
                rest.append(factor)
                continue
            function, angle, n = found
            if function is sp.sin and angle / 2 in angles:  # sin(2x) beside x's: 2 sin(x) cos(x), to cancel
                angle = angle / 2
                powers[angle][sp.sin] += n
                powers[angle][sp.cos] += n
                rest.append(sp.Integer(2) ** n)
            elif function is sp.tan:
                powers[angle][sp.sin] += n
                powers[angle][sp.cos] -= n
            else:
                powers[angle][function] += n
        for angle, p in powers.items():
            s, c = p[sp.sin], p[sp.cos]
            if s != 0 and s == -c:  # sin^n/cos^n: tan^n
                rest.append(sp.tan(angle) ** s)
            else:
                rest += [sp.sin(angle) ** s, sp.cos(angle) ** c]
        return sp.Mul(*rest)

    return expression.replace(trigonometric_product, rewritten)


def shares(expression: sp.Basic) -> sp.Basic:
    r"""A product over a sum, c X t/(t + u + ...), where exactly one term t of the sum divides
    the numerator with a whole number c left, as c X times t's share of the sum, t/(t + u + ...):
    a dimensionless ratio beside the scale, as the notes write a = -g 2m/(M + 2m) and
    T = m g M/(M + 2m). The share is kept unevaluated (sympy would merge it back); a numerator
    that holds two of the terms (m1 m2/(m1 + m2)) or none is left as it is.

    >>> g, m, M, I, R = sp.symbols("g m M I R", positive=True)
    >>> sp.latex(shares(-2*g*m/(M + 2*m))), sp.latex(shares(g*m*M/(M + 2*m)))
    ('- g \\frac{2 m}{M + 2 m}', 'g m \\frac{M}{M + 2 m}')
    >>> sp.latex(shares(-2*g*m/(R*(M + 2*m)))), shares(m*M/(m + M))
    ('- \\frac{g}{R} \\frac{2 m}{M + 2 m}', M*m/(M + m))
    """
    def over_a_sum(e) -> bool:
        return isinstance(e, sp.Mul) and _share(e) is not None

    def rewritten(product: sp.Mul) -> sp.Expr:
        term, total = _share(product)
        share = term / total
        return sp.Mul(product / share, sp.UnevaluatedExpr(share), evaluate=False)

    return expression.replace(over_a_sum, rewritten)


def _share(product: sp.Mul) -> tuple[sp.Expr, sp.Add] | None:
    """(t, the sum) for `shares`, or None."""
    sums = [f.base for f in product.args if isinstance(f, sp.Pow) and f.exp == -1 and isinstance(f.base, sp.Add)]
    if len(sums) != 1:
        return None
    (total,) = sums
    numerator = sp.Mul(*(f for f in product.args if not (isinstance(f, sp.Pow) and f.exp.is_negative)))
    found = []
    for term in total.args:
        left = numerator / term
        coefficient, rest = left.as_coeff_Mul()
        if term.is_number or term.as_coeff_Mul()[0] < 0 or not coefficient.is_Integer or rest == 1 and abs(coefficient) == 1:
            continue
        if all(not (isinstance(f, sp.Pow) and f.exp.is_negative) for f in sp.Mul.make_args(rest)):
            found.append(term)
    return (found[0], total) if len(found) == 1 else None


def _trig_power(factor):
    """(sin, cos or tan, its angle, its integer power) of a factor that is one, else None."""
    base, exponent = factor.as_base_exp()
    if isinstance(base, (sp.sin, sp.cos, sp.tan)) and exponent.is_Integer:
        return type(base), base.args[0], int(exponent)
    return None


def _absolute(expression: sp.Basic) -> sp.Basic:
    """x^2/|x| of a real x as |x|.

    >>> a = sp.Symbol("a", real=True)
    >>> _absolute(sp.acos(sp.sin(a)**2 / sp.Abs(sp.sin(a))))
    acos(Abs(sin(a)))
    """
    def squared_over_absolute(e) -> bool:
        return isinstance(e, sp.Mul) and any(_cancels(e, f) for f in e.args)

    def rewritten(product: sp.Mul) -> sp.Expr:
        factor = next(f for f in product.args if _cancels(product, f))
        x = factor.base.args[0]
        return product / (x**2 / sp.Abs(x)) * sp.Abs(x)

    return expression.replace(squared_over_absolute, rewritten)


def _cancels(product: sp.Mul, factor) -> bool:
    """Whether `factor` is 1/|x| of a real x and the product has x^2 too."""
    return (isinstance(factor, sp.Pow) and factor.exp == -1 and isinstance(factor.base, sp.Abs)
            and factor.base.args[0].is_real is True and sp.Pow(factor.base.args[0], 2) in product.args)


def collected_roots(expression):
    r"""The square roots of a product written as one, as a textbook writes them: sympy splits
    sqrt(I g l m) into four roots when the symbols are positive, so the printed form is rebuilt
    unevaluated. Roots over and under the fraction bar become one root of the quotient where every
    base is nonnegative (sqrt(a)/sqrt(b) is sqrt(a/b) only there); a product nested in a product
    (2 pi (sqrt(A)/sqrt(B))) is read as one.

    >>> I, g, l, m = sp.symbols("I g l m", positive=True)
    >>> sp.latex(collected_roots(2 * sp.sqrt(I * g * l * m) / 3)), sp.latex(collected_roots(1 / sp.sqrt(I * g)))
    ('\\frac{2 \\sqrt{I g l m}}{3}', '\\frac{1}{\\sqrt{I g}}')
    >>> sp.latex(collected_roots(sp.sqrt(g) / sp.sqrt(l))), sp.latex(collected_roots(sp.sqrt(sp.Symbol("x")) / sp.sqrt(l)))
    ('\\sqrt{\\frac{g}{l}}', '\\frac{\\sqrt{x}}{\\sqrt{l}}')
    >>> sp.latex(collected_roots(2 * sp.pi * l**sp.Rational(3, 2) / sp.sqrt(g)))
    '2 \\pi \\sqrt{\\frac{l^{3}}{g}}'
    >>> sp.latex(collected_roots(sp.sqrt(3) * sp.sqrt(g) * sp.sqrt(l) / 3)), sp.latex(collected_roots(2 * sp.sqrt(6) * sp.sqrt(l) / (3 * sp.sqrt(g))))
    ('\\sqrt{\\frac{g l}{3}}', '2 \\sqrt{\\frac{2 l}{3 g}}')
    """
    if not isinstance(expression, sp.Basic):
        return expression

    def combined(product):
        roots = {1: [], -1: []}
        rest = []
        for factor in _flat(product):
            if _is_root(factor):
                roots[1 if factor.exp > 0 else -1].append(_radicand(factor))
            else:
                rest.append(factor)
        rest = _coefficient_into_root(rest, roots)
        if roots[1] and roots[-1] and all(b.is_nonnegative for b in roots[1] + roots[-1]):
            quotient = sp.Mul(*roots[1]) / sp.Mul(*roots[-1])  # the root itself unevaluated: sympy would split it
            return sp.Mul(*rest, sp.Pow(quotient, HALF, evaluate=False), evaluate=False)
        for sign, bases in roots.items():
            if len(bases) > 1:  # one root; under a fraction bar as 1/root, which the printer keeps whole
                root = sp.Pow(sp.Mul(*bases, evaluate=False), HALF, evaluate=False)
                rest.append(root if sign > 0 else sp.Pow(root, -1, evaluate=False))
            else:
                rest += [sp.Pow(b, sign * HALF, evaluate=False) for b in bases]
        return sp.Mul(*rest, evaluate=False)

    def several_roots(e) -> bool:
        return isinstance(e, sp.Mul) and sum(1 for f in _flat(e) if _is_root(f)) > 1

    return expression.replace(several_roots, combined)


def _coefficient_into_root(rest: list, roots: dict) -> list:
    """The factors outside the roots with their rational numbers as one coefficient, first; its
    denominator's part that divides the whole number under a root of nonnegative symbols taken into
    the root: sqrt(3 a g)/3 as sqrt(a g/3), 2 sqrt(6 L/g)/3 as 2 sqrt(2 L/(3 g)) (`roots` changed in
    place)."""
    coefficient = sp.Mul(*(f for f in rest if f.is_Rational))
    rest = [f for f in rest if not f.is_Rational]
    number = sp.Mul(*(b for b in roots[1] if b.is_Integer))
    symbols = [b for b in roots[1] + roots[-1] if not b.is_Integer]
    d = sp.igcd(coefficient.q, number) if number.is_Integer else 1
    if d > 1 and any(not b.is_Integer for b in roots[1]) and all(b.is_nonnegative for b in symbols):
        roots[1][:] = ([number / d] if number != d else []) + [b for b in roots[1] if not b.is_Integer]
        roots[-1].append(sp.Integer(d))
        coefficient *= d
    return ([coefficient] if coefficient != 1 else []) + rest


def _is_root(factor) -> bool:
    """A square root or its reciprocal; a power k/2 (k odd) of a nonnegative base too (a^(3/2) is
    sqrt(a^3))."""
    if not isinstance(factor, sp.Pow) or not factor.exp.is_Rational or factor.exp.q != 2:
        return False
    return abs(factor.exp) == HALF or factor.base.is_nonnegative is True


def _radicand(factor: sp.Pow) -> sp.Expr:
    """What a root (`_is_root`) takes the square root of: a for sqrt(a) and 1/sqrt(a), a^3 for a^(3/2)."""
    return factor.base ** abs(factor.exp.p)


def _flat(product: sp.Mul) -> list:
    """The factors of a product, a product among them opened (2*pi*(a*b) as 2, pi, a, b)."""
    return [g for f in product.args for g in (_flat(f) if isinstance(f, sp.Mul) else [f])]


def complements(expression: sp.Basic) -> sp.Basic:
    """pi/2 - acos(y) as asin(y) and pi/2 - asin(y) as acos(y) (the two add up to pi/2 for every y):
    the angle a teacher writes.

    >>> y = sp.Symbol("y")
    >>> complements(sp.pi / 2 - sp.acos(1 - y)), complements(sp.pi / 2 + sp.asin(y))
    (asin(1 - y), asin(y) + pi/2)
    """
    other = {sp.acos: sp.asin, sp.asin: sp.acos}

    def complement(e) -> bool:
        return isinstance(e, sp.Add) and sp.pi / 2 in e.args and any(_negated_inverse(t) for t in e.args)

    def rewritten(e: sp.Add) -> sp.Expr:
        term = next(t for t in e.args if _negated_inverse(t))
        inverse = -term
        return e - sp.pi / 2 - term + other[type(inverse)](inverse.args[0], evaluate=False)  # asin(1 - y), not -asin(y - 1)

    return expression.replace(complement, rewritten)


def _negated_inverse(term) -> bool:
    return isinstance(-term, (sp.acos, sp.asin))


def plus_first(expression: sp.Basic) -> sp.Basic:
    """No double negative: a product with a minus sign and a factor (a sum, or a sum's odd power)
    with at least as many minus signs as it has turned, the two minus signs taken out:
    -F R (-R cos(theta) + r) as F R (R cos(theta) - r). Of several such factors, the one that turns
    with the fewest minus signs left in it (a denominator's -R + r before a numerator's
    -27 R g + 27 g r + 7 v^2). The printer opens a sum with a positive term (derive.text.latex).

    >>> F, R, r, x = sp.symbols("F R r x", positive=True)
    >>> plus_first(-F * R * (-R * sp.cos(x) + r)), plus_first(-F / (x * (-R + r)))
    (F*R*(R*cos(x) - r), F/(x*(R - r)))
    """
    def double(e) -> bool:
        return isinstance(e, sp.Mul) and e.as_coeff_Mul()[0].is_negative and bool(_turnable(e))

    def rewritten(product: sp.Mul) -> sp.Expr:
        factor = min(_turnable(product), key=lambda f: _minus_signs(-f.as_base_exp()[0]))
        base, exponent = factor.as_base_exp()
        rest = sp.Mul.make_args(-(product / factor))  # unevaluated: sympy would spread the 7 of F/(7 (R - r)) over R - r
        return sp.Mul(*rest, sp.Pow(-base, exponent), evaluate=False)

    return expression.replace(double, rewritten)


def _turnable(product: sp.Mul) -> list:
    """The factors of a product that are a sum, or a sum to an odd power, with at least as many
    minus signs as the sum turned: -2 d g (mu cos(theta) - sin(theta)) is 2 d g (sin(theta) - mu cos(theta))."""
    found = []
    for factor in product.args:
        base, exponent = factor.as_base_exp()
        if isinstance(base, sp.Add) and exponent.is_Integer and exponent % 2 == 1 \
                and _minus_signs(-base) <= _minus_signs(base):
            found.append(factor)
    return found


def _minus_signs(total: sp.Expr) -> int:
    return sum(1 for t in sp.Add.make_args(total) if t.could_extract_minus_sign())




def unnested(expression: sp.Basic) -> sp.Basic:
    """No fraction inside a fraction's numerator or denominator, where it would print in a script
    size: a sum holding fractions, inside a product that prints as one, over one denominator
    (sympy's together): omega_t (3 + h^2/R^2)/(6 omega_3) as omega_t (3 R^2 + h^2)/(6 R^2 omega_3).

    >>> h, R, w, W = sp.symbols("h R omega_t omega_3", positive=True)
    >>> unnested(w * (3 + h**2 / R**2) / (6 * W))
    omega_t*(3*R**2 + h**2)/(6*R**2*omega_3)
    """
    def nested(e) -> bool:
        return isinstance(e, sp.Mul) and any(f.as_base_exp()[1].is_negative for f in e.args) \
            and any(_fractional_sum(a) for a in e.atoms(sp.Add))

    def rewritten(product: sp.Mul) -> sp.Expr:
        return product.replace(_fractional_sum, sp.together)

    return expression.replace(nested, rewritten)


def _fractional_sum(e) -> bool:
    """A sum one of whose terms has a symbol in a denominator, or a rational coefficient."""
    return isinstance(e, sp.Add) and not e.has(sp.Derivative, sp.Integral) and any(
        sp.fraction(t)[1] != 1 for t in e.args)


def roots_beside(expression):
    r"""A root whose radicand is a fraction, in a product that is a fraction itself, printed beside
    that fraction, not in its numerator (where the radicand's fraction would print in a script size):
    sqrt(10 g h/7)/R as (1/R) sqrt(10 g h/7). For printing only: the product is left unevaluated.

    >>> g, h, R = sp.symbols("g h R", positive=True)
    >>> sp.latex(roots_beside(sp.Mul(sp.Pow(10 * g * h / 7, HALF, evaluate=False), 1 / R, evaluate=False)))
    '\\frac{1}{R} \\sqrt{\\frac{10 g h}{7}}'
    """
    if not isinstance(expression, sp.Basic):
        return expression

    def fraction_root(f) -> bool:
        return isinstance(f, sp.Pow) and f.exp == HALF and sp.fraction(sp.together(f.base))[1] != 1

    def beside(e) -> bool:
        if not isinstance(e, sp.Mul):
            return False
        factors = _flat(e)
        return any(fraction_root(f) for f in factors) and any(
            f.as_base_exp()[1].is_negative or f.is_Rational and f.q != 1 for f in factors if not fraction_root(f))

    def rewritten(product: sp.Mul) -> sp.Expr:
        factors = _flat(product)
        roots = [f for f in factors if fraction_root(f)]
        rest = sp.Mul(*(f for f in factors if not fraction_root(f)))
        sign = -1 if rest.could_extract_minus_sign() else 1
        return sp.Mul(*([-1] if sign < 0 else []), sp.UnevaluatedExpr(sign * rest), *roots, evaluate=False)

    return expression.replace(beside, rewritten)
