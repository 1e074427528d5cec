"""What a point mass on a prescribed path is asked: `BODY.DETAIL`, one of PATH_QUANTITIES (its
velocity and acceleration components, speed, radial and tangential acceleration, angular momentum
and areal velocity), the path given as r(t), theta(t) or x(t), y(t).

    v = d r/dt        a_r = r'' - r theta'^2        L = m r^2 theta'

Route 0 (the key's): the position differentiated and projected (derive.mechanics.paths.quantity).
Route 1, its check: the same by sympy.physics.mechanics' rotating frames (paths.by_mechanics).
Both through the Solution (`Solution._path`): this layer sits below derive.mechanics.

>>> from derive.language.problem import load
>>> PATH.claims(load("circular_motion_L").scene, "particle", "speed")
Quantity(kind='path', target='particle', detail='speed')
"""
from __future__ import annotations

import sympy as sp

from derive.model.scene import PATH_QUANTITIES, PLANAR_PATH_QUANTITIES, Quantity
from derive.numbers.agreement import agree
from derive.quantities.base import Check, CheckFailure, QuantityKind


class Path(QuantityKind):
    """A quantity of a point mass on a prescribed path (see the module)."""

    kind = "path"
    symbol = "v"
    unit = None  # by what is asked: m/s, m/s^2, kg*m^2/s, m^2/s
    routes = ("the position differentiated and projected", "sympy.physics.mechanics' rotating frames")
    own_section = False

    def claims(self, scene, head: str, rest: str) -> Quantity | None:
        body = scene.bodies.get(head)
        if body is None or body.path is None or rest == "mass":
            return None
        if body.path.z != 0 and rest in PLANAR_PATH_QUANTITIES:
            raise ValueError(f"{rest} is of a path in the plane; the {head}'s leaves it (z): ask "
                             "velocity.x|y, speed, acceleration.x|y, angular_momentum.x|y|z|magnitude")
        if rest not in PATH_QUANTITIES:
            raise ValueError(f"a body on a path has {', '.join(PATH_QUANTITIES)}; not {rest!r}")
        return Quantity(self.kind, head, rest)

    def value(self, solution, ask, route: int) -> sp.Expr:
        return solution._path(ask, route)

    def checks(self, solution, names: list[str]) -> list[Check]:
        """Every path quantity again with sympy.physics.mechanics (a particle, a rotating frame)."""
        for name in names:
            other = self.value(solution, solution.problem.asks[name], 1)
            if agree(other, solution.expressions[name]) is None:
                raise CheckFailure(f"{solution.problem.id}: {name} is {solution.expressions[name]} by projection, "
                                   f"{other} by sympy.physics.mechanics")
        return [Check("path_vs_mechanics", True, "symbolic", "every path quantity agrees",
                      "The kinematics of SymPy's mechanics package (rotating frames) give the same velocities and "
                      "accelerations on the path.")]

    def describe(self, ask) -> str:
        return f"the {ask.quantity.detail.replace('_', ' ').replace('.', ' ')} of the {ask.quantity.target}"


PATH = Path()
