"""What a state gives (`in: STATE`, derive.model.scene's RATE_KINDS but the impulse): a body's
velocity along an axis, speed, angular velocity, position and angle there, the kinetic energy of
every body (or its change from the state it comes from), the velocity of their center of mass, and
the time the motion takes to get there. Each but the time is read at the state's coordinates and
velocities (`Rate.at`): of its closed form (`Solution.states`, derive.mechanics.states, from energy
and the momenta kept), which no route of the derivation gives alone, so both routes read the same
value; the states check (derive.solution.crosschecks) and derive.checks.chain_simulation read `at`
on Newton–Euler's motion integrated against it.

    K = sum (M v_cm^2 / 2 + I_cm omega^2 / 2)        v_cm = sum M v / sum M        |v| = sqrt(vx^2 + vy^2)

>>> RATES[0].kind, RATES[0].symbol
('velocity', 'v')
"""
from __future__ import annotations

from abc import abstractmethod

import sympy as sp

from derive.core.tidying import root, tidy
from derive.quantities.by_routes import ByRoutes


class Rate(ByRoutes):
    """A quantity of a state but the time (see the module)."""

    def on_route(self, solution, ask, route: str) -> sp.Expr:
        start = solution.scene.states[ask.state].start
        states = solution.states
        return self.at(solution, ask, states[ask.state].values, states[start].values if start else None)

    @abstractmethod
    def at(self, solution, ask, values: dict, before: dict | None) -> sp.Expr:
        """The quantity at the coordinates and velocities `values` (a change: from those `before`)."""


class Velocity(Rate):
    """A body's velocity along x or y."""

    kind, symbol = "velocity", "v"

    def at(self, solution, ask, values: dict, before: dict | None) -> sp.Expr:
        return values[solution.coordinates.of(ask.quantity.target, ask.quantity.detail).u]


class AngularVelocity(Rate):
    """A body's angular velocity, counter-clockwise positive."""

    kind, symbol = "angular_velocity", "omega"

    def at(self, solution, ask, values: dict, before: dict | None) -> sp.Expr:
        return values[solution.coordinates.of(ask.quantity.target, "theta").u]


class Speed(Rate):
    """A body's speed: its velocity's magnitude."""

    kind, symbol = "speed", "v"

    def at(self, solution, ask, values: dict, before: dict | None) -> sp.Expr:
        coords, body = solution.coordinates, ask.quantity.target
        return root(values[coords.of(body, "x").u] ** 2 + values[coords.of(body, "y").u] ** 2)


class Position(Rate):
    """A body's position along x or y: where it is placed, and its coordinate's displacement."""

    kind, symbol = "position", "x"

    def _coordinate(self, quantity) -> str:
        return quantity.detail

    def at(self, solution, ask, values: dict, before: dict | None) -> sp.Expr:
        body, coordinate = ask.quantity.target, self._coordinate(ask.quantity)
        return tidy(solution.scene.bodies[body].placed(coordinate) + values[solution.coordinates.of(body, coordinate).q])


class Angle(Position):
    """A body's angle, counter-clockwise positive, from where it is placed."""

    kind, symbol = "angle", "theta"

    def _coordinate(self, quantity) -> str:
        return "theta"


class KineticEnergy(Rate):
    """The kinetic energy of every body."""

    kind, symbol = "kinetic_energy", "K"

    def at(self, solution, ask, values: dict, before: dict | None) -> sp.Expr:
        return tidy(solution.kinetic_energy.xreplace(values))


class KineticEnergyChange(Rate):
    """The change of every body's kinetic energy from the state the state comes from."""

    kind, symbol = "kinetic_energy_change", "Delta_K"

    def at(self, solution, ask, values: dict, before: dict | None) -> sp.Expr:
        return tidy(solution.kinetic_energy.xreplace(values) - solution.kinetic_energy.xreplace(before))


class CenterOfMassVelocity(Rate):
    """The velocity of the center of mass of every body, along x or y."""

    kind, symbol = "center_of_mass_velocity", "v_cm"

    def at(self, solution, ask, values: dict, before: dict | None) -> sp.Expr:
        coords, bodies = solution.coordinates, solution.scene.bodies.values()
        momentum = sum((b.mass * values[coords.of(b.name, ask.quantity.detail).u] for b in bodies), sp.Integer(0))
        return tidy(momentum / sum((b.mass for b in bodies), sp.Integer(0)))


class Time(ByRoutes):
    """The time the motion takes to the state from the state it comes from (`Solution.duration`)."""

    kind, symbol = "time", "t"

    def on_route(self, solution, ask, route: str) -> sp.Expr:
        return solution.duration(ask.state)[0]


#: One of each kind.
RATES = (Velocity(), AngularVelocity(), Speed(), Position(), Angle(), Time(), KineticEnergy(), KineticEnergyChange(),
         CenterOfMassVelocity())
