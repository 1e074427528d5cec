"""Normal modes of small oscillations about the reference configuration, several degrees of freedom.

As for one degree of freedom (derive.mechanics.oscillation), the constraints are linearized, not
solved: their Jacobian at the reference has n free directions, n of the coordinates (angles
first) measure them, s, and each route's accelerations along each direction give, to first order,
s'' = -D s. The kinetic energy gives the mass matrix M in s, and K = M D is the stiffness matrix
(symmetric: a check that the forces come from a potential), so M s'' + K s = 0. The squared
frequencies are the roots of det(K - w^2 M) = 0 (those of det(D - w^2) = 0). A zero root is a
zero mode: a free motion (the bodies shifted or turned together with no restoring force at any
displacement, so its momentum is conserved), reported and left out of the modes, which are
numbered from the lowest frequency.

>>> import sympy as sp
>>> from derive.parts.slider import Slider
>>> from derive.parts.spring import Spring
>>> from derive.model.scene import Body, Scene
>>> from derive.mechanics import lagrange
>>> m, k = sp.symbols("m k", positive=True)
>>> bodies = {n: Body(n, "point", m, {}, at=(x, 0)) for n, x in (("a", 1), ("b", 2))}
>>> rails = tuple(Slider(f"rail_{n}", n, (0, 0), sp.Integer(0), turns=True) for n in bodies)
>>> ends = [((None, "a"), (0, 0)), (("a", "b"), (0, 0)), (("b", None), (3, 0))]
>>> springs = tuple(Spring(f"s{i}", pair, ((0, 0), far) if pair[0] else (far, (0, 0)), k, 1)
...                 for i, (pair, far) in enumerate(ends))
>>> scene = Scene(bodies, rails, loads=springs)
>>> modes = normal_modes(scene, lagrange.derive(scene))
>>> [modes.quantity(f"modes.{i}.omega") for i in (1, 2)]
[sqrt(k/m), sqrt(3*k/m)]
"""
from __future__ import annotations

import functools
from dataclasses import dataclass

import sympy as sp

from derive.mechanics.derivation import Derivation
from derive.text.steps import Step
from derive.core.tidying import root, tidy
from derive.model.kinematics import Coordinate, Coordinates
from derive.mechanics.lagrange import energies
from derive.mechanics.oscillation import (OscillationError, OscillationLimit, at_equilibrium, first_order,
                                          free_directions)
from derive.model.scene import Scene

#: The angular frequency, as the worked solution writes the characteristic equation.
OMEGA = sp.Symbol("omega")


@dataclass(frozen=True)
class NormalModes:
    """The linearized motion M s'' + K s = 0 in the free coordinates s, and its modes."""

    coordinates: tuple[Coordinate, ...]
    #: Every coordinate of the scene, in the order of the rows of `directions`.
    every: tuple[Coordinate, ...]
    #: Each column: every coordinate's displacement when one free coordinate moves by 1 (first order).
    directions: sp.Matrix
    mass: sp.Matrix
    stiffness: sp.Matrix
    #: omega^2 of each oscillating mode, lowest first.
    squares: tuple[sp.Expr, ...]
    #: Each zero mode's displacements of the free coordinates.
    zero_modes: tuple[sp.Matrix, ...]
    steps: tuple[Step, ...]
    #: (expression, strict, meaning): what the modes' order and stability need where the symbols'
    #: assumptions do not prove it (read at sample parameters; Solution.conditions checks each variant).
    conditions: tuple = ()

    def quantity(self, name: str) -> sp.Expr:
        """omega or period of the one oscillating mode, or modes.N.omega|period (N from 1, lowest
        frequency first), or modes.N.ratio.BODY.KIND.to.BODY.KIND (the amplitudes' ratio in the mode)."""
        if name == "growth_rate":
            raise OscillationLimit("find the growth rate about an equilibrium with several degrees of freedom")
        if name.startswith("modes."):
            _, number, name, *ratio = name.split(".")
            if int(number) > len(self.squares):
                raise OscillationError(f"the scene has {len(self.squares)} normal modes of oscillation, not {number}")
            if name == "ratio":
                return self.ratio(int(number), (ratio[0], ratio[1]), (ratio[3], ratio[4]))
            square = self.squares[int(number) - 1]
        elif len(self.squares) == 1:
            (square,) = self.squares
        else:
            raise OscillationError(f"the scene has {len(self.squares)} normal modes of oscillation: ask "
                                   + ", ".join(f"small_oscillation.modes.{i}.{name}"
                                               for i in range(1, len(self.squares) + 1)) + " (lowest frequency first)")
        return _frequency(square) if name == "omega" else 2 * sp.pi / _frequency(square)


    def ratio(self, number: int, moving: tuple[str, str], to: tuple[str, str]) -> sp.Expr:
        """The amplitude of one coordinate (body, x|y|angle) over another's in mode `number`: the
        mode's shape is a column of the adjugate of K - w^2 M (singular, of rank n - 1 where no other
        mode has its frequency)."""
        square = self.squares[number - 1]
        if self.squares.count(square) > 1:
            raise OscillationError(f"two normal modes share the frequency of mode {number}: its shape is not determined")
        adjugate = (self.stiffness - square * self.mass).adjugate()
        column = next((adjugate[:, j] for j in range(adjugate.cols) if any(tidy(e) != 0 for e in adjugate[:, j])), None)
        if column is None:
            raise OscillationError(f"the shape of mode {number} is not determined")
        shape = self.directions * column
        kinds = {"angle": "theta", "x": "x", "y": "y"}
        top, bottom = (shape[next(i for i, c in enumerate(self.every) if (c.body, c.kind) == (body, kinds[kind]))]
                       for body, kind in (moving, to))
        if tidy(bottom) == 0:
            raise OscillationError(f"the {to[0]}'s {to[1]} does not move in mode {number}: ask the ratio the other way")
        return _plainest(sp.radsimp(tidy(top / bottom)))


def normal_modes(scene: Scene, derivation: Derivation, sample=None) -> NormalModes:
    """The normal modes of a scene of several degrees of freedom about its reference configuration,
    which must be an equilibrium; `sample` (an expression's float value at sample parameters)
    decides what the symbols' assumptions leave open: the modes' order and their stability."""
    coords = Coordinates(scene)
    if any(part.dissipation(coords) != 0 for part in scene.parts):
        raise OscillationLimit("find damped normal modes of several degrees of freedom")
    free = free_directions(scene, coords)
    chosen = _measured_by(coords, sp.Matrix.hstack(*free))
    directions = (sp.Matrix.hstack(*free) * sp.Matrix.hstack(*free)[chosen, :].inv()).applyfunc(tidy)
    accelerations = [coords.all[i].a for i in chosen]
    equilibrium = at_equilibrium(derivation, coords)
    columns = []
    for j in range(len(chosen)):
        slopes = first_order(derivation, coords, directions[:, j], equilibrium)
        columns.append([tidy(-slopes[a]) for a in accelerations])
    dynamical = sp.Matrix(columns).T  # s'' = -D s
    kinetic = energies(scene, coords)[0]
    velocities = [c.u for c in coords.all]
    mass = (directions.T * sp.hessian(kinetic, velocities).xreplace(coords.at_rest_in_reference())
            * directions).applyfunc(tidy)
    stiffness = (mass * dynamical).applyfunc(tidy)
    if any(tidy(stiffness[i, j] - stiffness[j, i]) != 0 for i in range(len(chosen)) for j in range(i)):
        raise OscillationLimit("find normal modes where the forces do not come from a potential (K is not symmetric)")
    square = sp.Dummy("w2")
    polynomial = sp.Poly(sp.numer(sp.together((dynamical - square * sp.eye(len(chosen))).det())), square)
    zero_count, squares = _roots(polynomial)
    zero_modes = tuple(v.applyfunc(tidy) for v in dynamical.nullspace(simplify=True)) if zero_count else ()
    if len(zero_modes) != zero_count:
        raise OscillationLimit("find normal modes where a zero frequency repeats with fewer free motions than it repeats")
    for mode in zero_modes:
        _free_motion(scene, coords, derivation, directions * mode)
    if not squares:
        raise OscillationError("nothing oscillates: every direction is a free motion")
    squares, conditions = _ordered(squares, sample)
    symbols = [c.q for c in (coords.all[i] for i in chosen)]
    steps = _steps(coords, chosen, directions, mass, stiffness, symbols, accelerations, zero_modes, squares)
    return NormalModes(tuple(coords.all[i] for i in chosen), tuple(coords.all), directions, mass, stiffness,
                       tuple(squares), zero_modes, steps, tuple(conditions))


def _measured_by(coords: Coordinates, free: sp.Matrix) -> list[int]:
    """The coordinates that measure the free directions: angles first, then in the scene's order,
    each taken where it adds a direction the ones before it do not measure."""
    order = sorted(range(len(coords.all)), key=lambda i: (coords.all[i].kind != "theta", i))
    chosen: list[int] = []
    for i in order:
        if free[chosen + [i], :].rank(simplify=True) > len(chosen):
            chosen.append(i)
        if len(chosen) == free.cols:
            return sorted(chosen)
    raise AssertionError("the free directions are independent")


def _roots(polynomial: sp.Poly) -> tuple[int, list[sp.Expr]]:
    """(how many roots are zero, the others with their multiplicity) of the characteristic
    polynomial in omega^2, factor by factor; a factor of degree 3 or more is an engine limit."""
    zero_count, squares = 0, []
    for factor, multiplicity in sp.factor_list(polynomial)[1]:
        if factor.degree() == 0:
            continue
        if factor.degree() > 2:
            raise OscillationLimit(f"solve a characteristic equation of degree {factor.degree()} in omega^2 for its "
                                   "normal modes in closed form")
        if factor.as_expr() == factor.gen:
            zero_count += multiplicity
            continue
        found = sp.roots(factor, multiple=True)
        squares += [_plainest(r) for r in found for _ in range(multiplicity)]
    return zero_count, squares


def _frequency(square: sp.Expr) -> sp.Expr:
    """sqrt(omega^2), one root of the radicand as `_plainest` wrote it (derive.core.tidying.root
    would put it back in compact form), unless it is a perfect square."""
    value = root(square)
    return sp.Pow(square, sp.S.Half, evaluate=False) if value == sp.Pow(tidy(square), sp.S.Half, evaluate=False) else value


def _plainest(square: sp.Expr) -> sp.Expr:
    """A root in its compact form, or expanded with common factors pulled out where that is
    shorter, as books write them: g*(2 - sqrt(2))/L, g/l + 2*k/m.

    >>> g, l, k, m = sp.symbols("g l k m", positive=True)
    >>> _plainest((g*m + 2*k*l)/(l*m))
    g/l + 2*k/m
    """
    compact = tidy(square)
    expanded = sp.factor_terms(sp.expand(compact))
    return expanded if sp.count_ops(expanded) < sp.count_ops(compact) else compact


def _ordered(squares: list[sp.Expr], sample) -> tuple[list[sp.Expr], list]:
    """The squared frequencies lowest first, each positive (stable); where the assumptions do not
    prove an order or a sign, the sample decides and a condition records it."""
    conditions = []
    for w2 in squares:
        if w2.is_positive:
            continue
        if w2.is_negative is True or w2.is_real is False or sample is None:
            raise OscillationError(f"the equilibrium is not stable: a normal mode has omega^2 = {sp.sstr(w2)}")
        try:
            value = sample(w2)
        except TypeError:  # not real at the sample
            value = None
        if value is None or value <= 0:
            raise OscillationError(f"the equilibrium is unstable at these parameters: a normal mode has "
                                   f"omega^2 = {sp.sstr(w2)}")
        conditions.append((w2, True, f"the equilibrium is unstable at these parameters (omega^2 = {sp.sstr(w2)})"))
    if len(squares) > 1:
        squares = sorted(squares, key=sample or functools.cmp_to_key(_proven_order))
        for low, high in zip(squares, squares[1:]):
            gap = tidy(high - low)
            if gap.is_nonnegative is not True:
                conditions.append((gap, False, f"the normal modes change order at these parameters "
                                               f"(omega^2 = {sp.sstr(low)} and {sp.sstr(high)})"))
    return squares, conditions


def _proven_order(low: sp.Expr, high: sp.Expr) -> int:
    """-1, 0 or 1 as low is below, equal to or above high for every value of the symbols."""
    gap = tidy(high - low)
    if gap.is_zero or gap.is_positive or gap.is_negative:
        return 0 if gap.is_zero else (-1 if gap.is_positive else 1)
    raise OscillationError(f"cannot order the normal modes omega^2 = {sp.sstr(low)} and {sp.sstr(high)} without "
                           "sample parameters")


def _free_motion(scene: Scene, coords: Coordinates, derivation: Derivation, direction: sp.Matrix) -> None:
    """A zero mode must be a free motion: along q = direction * s the constraints hold and nothing
    accelerates, at any s (a free translation or turn; its momentum is conserved). Otherwise the
    motion along it is decided by higher orders: an engine limit."""
    s = sp.Dummy("s")
    line = {c.q: direction[i] * s for i, c in enumerate(coords.all)}
    gaps = [g.xreplace(line) for c in scene.constraints for g in c.gaps(coords)]
    solved = derivation.at({**line, **{c.u: 0 for c in coords.all}}).raw
    if any(tidy(g) != 0 for g in gaps) or any(tidy(solved[c.a]) != 0 for c in coords.all):
        moving = next(c.q for i, c in enumerate(coords.all) if direction[i] != 0)
        raise OscillationLimit("find normal modes about a direction with no restoring force that is not a free "
                               f"motion ({moving})")


def _steps(coords, chosen, directions, mass, stiffness, symbols, accelerations, zero_modes, squares) -> tuple[Step, ...]:
    """The worked solution: the free coordinates, M s'' + K s = 0, the characteristic equation,
    the zero modes and the frequencies."""
    n = len(chosen)
    others = [sp.Eq(c.q, sum((directions[i, j] * symbols[j] for j in range(n)), sp.Integer(0)))
              for i, c in enumerate(coords.all) if i not in chosen]
    follow = tuple(e for e in others if e.lhs != e.rhs)
    words = [f"the {c.body}'s {'angle' if c.kind == 'theta' else c.kind}" for c in (coords.all[i] for i in chosen)]
    steps = [Step(f"Small displacements from the equilibrium: {n} free coordinates, " + ", ".join(words[:-1])
                  + f" and {words[-1]}" + ("; to first order the others follow them" if follow else ""), follow)]
    rows = tuple(sp.Eq(sum((mass[i, j] * accelerations[j] + stiffness[i, j] * symbols[j] for j in range(n)),
                           sp.Integer(0)), 0) for i in range(n))
    steps.append(Step("The equations of motion to first order: the mass matrix (from the kinetic energy) times the "
                      "accelerations plus the stiffness matrix times the displacements vanishes", rows))
    characteristic = (stiffness - OMEGA**2 * mass).det()
    steps.append(Step("A normal mode moves every coordinate in step at one angular frequency: the determinant of the "
                      "stiffness matrix less its square times the mass matrix vanishes",
                      (sp.Eq(sp.factor(characteristic), 0),)))
    for mode in zero_modes:
        lead = next(j for j in range(n) if mode[j] != 0)
        steps.append(Step("A zero mode, of zero frequency: a free motion, with no restoring force at any displacement "
                          "(its momentum is conserved), along",
                          tuple(sp.Eq(symbols[j], tidy(mode[j] / mode[lead]) * symbols[lead])
                                for j in range(n) if j != lead)))
    if len(squares) == 1:
        steps.append(Step("The angular frequency of the one mode that oscillates", (sp.Eq(OMEGA, _frequency(squares[0])),)))
    else:
        steps.append(Step("The angular frequencies of the normal modes, lowest first",
                          tuple(sp.Eq(sp.Symbol(f"omega_{i}"), _frequency(w2)) for i, w2 in enumerate(squares, start=1))))
    return tuple(steps)
