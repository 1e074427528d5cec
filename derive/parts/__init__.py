"""The parts of a planar scene, each known to both routes of derivation.

A part is one module of this package: a frozen dataclass (what the problem file says) with
the contributions it makes to each route. The two routes never share a formula of a part:

- Lagrange's method reads `gaps` (holonomic constraints g(q) = 0, each paired in order with one
  of `unknowns`, normalized so that its multiplier IS that force: the generalized constraint
  force is lambda dg/dq), `potential` (V), `power` (the power of its non-conservative forces that
  do not depend on the velocities: Q_j = dP/du_j) and `dissipation` (Rayleigh's function D of its
  viscous forces: Q_j = -dD/du_j, their power -2D);
- Newton–Euler reads `loads` (forces at material points and torques on bodies, with the
  unknowns in them) and `conditions` (velocity expressions the part holds at zero, from
  rigid-body kinematics v = v_cm + omega z x r), one per unknown.

Each part also says in words what it contributes to each route (`sentences`, derive.text.prose): the
Lagrange route opens its energies with them, Newton–Euler each body's balance with those about
that body and its constraints with the rest ("The axle pushes on the disk with its reaction ...
at its center of mass, so it exerts no torque about it.").

Bodies bring their kinetic energy and their weight (derive.mechanics); every other physical
contribution comes from a part. `bodies` names the bodies a part couples (a scene's connected
components follow from it), and `signs` the physical signs its forces must keep (a cord's tension
>= 0, a normal force >= 0), checked over the parameter ranges.

Adding a part: write its module here with a dataclass deriving from `Part` and its keys as
`KEYS` (derive.core.keys), override what it contributes, and register the module under its
problem-file key in `derive.language.scene_file` (docs/design.md, Parts).

>>> import sympy as sp
>>> Part().unknowns(), Part().potential(None)
({}, 0)
>>> Part().sentences("lagrange", None)[0].words
'The part adds nothing to the Lagrangian.'
"""
from __future__ import annotations

from dataclasses import dataclass
import re

import sympy as sp

from derive.text.prose import Sentence


@dataclass(frozen=True)
class AppliedForce:
    """A force on a body, applied at a world-frame offset from its center of mass."""

    body: str
    offset: sp.Matrix
    force: sp.Matrix
    label: str


@dataclass(frozen=True)
class AppliedTorque:
    """A pure torque (a couple) on a body, counter-clockwise positive."""

    body: str
    torque: sp.Expr
    label: str


@dataclass(frozen=True)
class Sign:
    """A force that must keep its sign for the scene to be what the file says: `expression` (an
    unknown of the derivation, or an expression of unknowns) must be >= 0, or the `meaning`
    explains what breaks (the cord goes slack). At an equilibrium a small oscillation swings
    about, it must be positive: `unloaded` says what a zero there means ("the cord rope is
    slack"), `force` names it ("its tension")."""

    expression: sp.Expr
    meaning: str
    unloaded: str
    force: str


class Part:
    """What a part contributes to each route; by default nothing. Every part has a `name`."""

    def bodies(self) -> tuple[str, ...]:
        """The bodies this part couples or acts on."""
        return ()

    @property
    def title(self) -> str:
        """How a sentence names it: its kind and its name (the cord rope, the torque torque1)."""
        kind = re.sub(r"(?<=[a-z])(?=[A-Z])", " ", type(self).__name__).lower()
        return f"the {kind} {getattr(self, 'name', '')}".rstrip()

    def unknowns(self) -> dict[str, sp.Symbol]:
        """The constraint forces it exerts, by the names an answer asks for (`tension`, ...)."""
        return {}

    def gaps(self, coords) -> list[sp.Expr]:
        """Lagrange: holonomic constraints, one per unknown, in the order of `unknowns`."""
        return []

    def potential(self, coords) -> sp.Expr:
        """Lagrange: its potential energy."""
        return sp.Integer(0)

    def power(self, coords) -> sp.Expr:
        """Lagrange: the power of its non-conservative forces that do not depend on the velocities."""
        return sp.Integer(0)

    def dissipation(self, coords) -> sp.Expr:
        """Lagrange: Rayleigh's dissipation function of its viscous forces (half their lost power)."""
        return sp.Integer(0)

    def loads(self, coords) -> list[AppliedForce | AppliedTorque]:
        """Newton–Euler: its forces at material points and its torques."""
        return []

    def conditions(self, coords) -> list[sp.Expr]:
        """Newton–Euler: velocity expressions it holds at zero, one per unknown."""
        return []

    def signs(self) -> list[Sign]:
        """Forces that must keep their sign (a taut cord, a body pressing on its surface)."""
        return []

    def extents(self, coords) -> list[tuple[sp.Expr, str]]:
        """Sizes of its geometry, positive in the reference configuration, with what it means for
        one to reach zero: a motion along a straight line of the coordinates
        (derive.mechanics.states) keeps them positive where its line is the part's (a block pulled
        up past its pulley would flip the cord's run)."""
        return []

    def sentences(self, route: str, coords) -> list[Sentence]:
        """What it contributes to `route` ("lagrange" or "newton_euler"), in words with its
        symbols: energies as functions of the coordinates, forces and constraints in the
        reference configuration (positions as placed, velocities left free).
        By default read off its contributions; each part says it in its own words."""
        name = getattr(self, "name", "part")
        if route == "newton_euler":
            result = [Sentence((f"The {name} acts on the {load.body}", *acting(load, coords), "."), load.body)
                      for load in self.loads(coords)]
            if self.conditions(coords):
                result.append(Sentence((f"The {name} holds the velocities of its points as they are constrained.",)))
            return result
        shares = [(f"The {name} adds to the potential energy ", self.potential(coords)),
                  (f"The {name} has the power ", self.power(coords)),
                  (f"The {name} dissipates energy at half the rate ", self.dissipation(coords))]
        result = [Sentence((words, math, ".")) for words, math in shares if math != 0]  # energies in the coordinates
        if self.unknowns():
            result.append(Sentence((f"The {name}'s constraints are held by the multipliers ",
                                    *listed(list(self.unknowns().values())), ".")))
        return result or [Sentence((f"The {name} adds nothing to the Lagrangian.",))]


#: Operations below which `at_placement` folds sin^2 + cos^2, cancels and factors (slow on long ones).
SHORT = 60


def at_placement(expression: sp.Expr, coords) -> sp.Expr:
    """`expression` in the reference configuration (every coordinate where the file places it,
    zero; the velocities left free): a short one in compact form (sin^2 + cos^2 folded,
    cancelled, factored), a long one expanded.

    >>> from derive.model.scene import Body, Scene
    >>> from derive.model.kinematics import Coordinates
    >>> h, r = sp.symbols("h r", positive=True)
    >>> coords = Coordinates(Scene({"disk": Body("disk", "disk", h, {"radius": r})}))
    >>> theta = sp.Symbol("theta_disk", real=True)
    >>> at_placement((h**2 * r**2 + r**4) / (h**2 + r**2) * sp.cos(theta)**2 + r**2 * sp.sin(theta)**2, coords)
    r**2
    """
    if isinstance(expression, sp.MatrixBase):
        return expression.applyfunc(lambda e: at_placement(e, coords))
    expression = sp.sympify(expression).xreplace({c.q: 0 for c in coords.all})  # safe: the engine's own numbers and expressions, never file text
    if sp.count_ops(expression) >= SHORT:
        return sp.expand(expression)
    return sp.factor(sp.cancel(sp.trigsimp(expression)))


def titled(parts) -> str:
    """The parts named as a list reads, each by its title.

    >>> from derive.parts.gravity import Gravity
    >>> titled([Gravity(sp.Symbol("g")), Part()])
    'gravity and the part'
    """
    return "".join(listed([p.title for p in parts]))


def listed(items: list) -> tuple:
    """Pieces of a sentence naming `items` as a list reads: a, b and c.

    >>> listed(["x", "y", "z"])
    ('x', ', ', 'y', ' and ', 'z')
    """
    pieces = []
    for i, item in enumerate(items):
        pieces += ([", "] if 0 < i < len(items) - 1 else [" and "] if i else []) + [item]
    return tuple(pieces)


def acting(load: AppliedForce | AppliedTorque, coords, signed: tuple = ()) -> tuple:
    """The end of a sentence saying where a load acts on its body and, on a turning body, the
    torque about its center of mass it exerts: radius times force, r_x F_y - r_y F_x, in the
    reference configuration. Its sense is said where its sign is known: a product of positive
    factors and forces that keep their sign (`signed`: a tension, a normal force), less a minus
    sign, which is clockwise (an angle's cosine, of either sign to sympy, leaves it unsaid).

    >>> from derive.model.scene import Body, Scene
    >>> from derive.model.kinematics import Coordinates
    >>> R, T, M = sp.symbols("R T M", positive=True)
    >>> coords = Coordinates(Scene({"disk": Body("disk", "disk", M, {"radius": R})}))
    >>> pull = AppliedForce("disk", sp.Matrix([R, 0]), sp.Matrix([0, -T]), "tension")
    >>> "".join(map(str, acting(pull, coords, signed=(T,))))
    ' at a distance R from its center of mass; its torque about it is -R*T, negative: it turns the body clockwise'
    """
    body = coords.scene.bodies[load.body]
    if isinstance(load, AppliedTorque):
        return (" as a couple: it turns the body without pushing its center",)
    offset = at_placement(load.offset, coords)
    if offset == sp.zeros(2, 1):
        return (" at its center of mass, so it exerts no torque about it",) if body.rotates else ("",)
    force = at_placement(load.force, coords)
    torque = at_placement(offset[0] * force[1] - offset[1] * force[0], coords)
    distance = sp.sqrt(at_placement(offset.dot(offset), coords))
    if torque == 0:
        return (" at a distance ", distance, " from its center of mass, along a line through it, so it exerts no "
                "torque about it")
    known = all(f.is_positive or f in signed for f in sp.Mul.make_args(-torque if torque.could_extract_minus_sign()
                                                                        else torque))
    sense = ("" if not known else ", negative: it turns the body clockwise" if torque.could_extract_minus_sign()
             else ", positive: it turns the body counter-clockwise")
    return (" at a distance ", distance, " from its center of mass; its torque about it is ", torque, sense)
