"""What a state gives (`in: STATE`, derive.model.scene's RATE_KINDS but the impulse): a body's
velocity along an axis, speed, angular velocity, position and angle there, the kinetic energy of
every body (or its change from the state it comes from), the velocity of their center of mass, and
the time the motion takes to get there. Each is read from the state's closed form
(`Solution.rate_in`: derive.solution.state_answers; derive.mechanics.states, from energy and the
momenta kept), which no route of the derivation gives alone, so both routes read the same value;
the states check (derive.solution.crosschecks) integrates Newton–Euler's equations against it.

    K = sum (M v_cm^2 / 2 + I_cm omega^2 / 2)        v_cm = sum M v / sum M

The kinds share everything but their names: one class, an instance of each (`RATES`).

>>> RATES[0].kind, RATES[0].symbol
('velocity', 'v')
"""
from __future__ import annotations

import sympy as sp

from derive.quantities.by_routes import ByRoutes


class Rate(ByRoutes):
    """A quantity of a state (see the module): `kind` one of RATE_KINDS, `symbol` its letter."""

    def __init__(self, kind: str, symbol: str):
        self.kind, self.symbol = kind, symbol

    def on_route(self, solution, ask, route: str) -> sp.Expr:
        return solution.rate_in(ask.quantity, ask.state)


#: One of each kind, with its letter.
RATES = tuple(Rate(kind, symbol) for kind, symbol in (
    ("velocity", "v"), ("angular_velocity", "omega"), ("speed", "v"), ("position", "x"), ("angle", "theta"),
    ("time", "t"), ("kinetic_energy", "K"), ("kinetic_energy_change", "Delta_K"), ("center_of_mass_velocity", "v_cm")))
