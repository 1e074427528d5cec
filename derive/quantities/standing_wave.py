"""A particle whose de Broglie wavelength fits a whole number of times around a circle (a standing
wave, the notes' §8): `standing_wave.momentum` and `standing_wave.angular_momentum`.

    p = n h / (2 pi R)        L = p R = n h / (2 pi)

Route 0 (the key's): from the wavelength, 2 pi R / n. Route 1, its check: from the angular
momentum operator -i hbar d/dphi on exp(i n phi). Both derive.mechanics.quantum, through the
Solution (`Solution._standing_wave`: this layer sits below derive.mechanics).

>>> from derive.language.problem import load
>>> STANDING_WAVE.claims(load("angular_momentum_quantization").scene, "standing_wave", "momentum")
Quantity(kind='standing_wave', target=None, detail='momentum')
"""
from __future__ import annotations

import sympy as sp

from derive.model.scene import Quantity
from derive.quantities.base import Check, QuantityKind, second_route, system_ask


class StandingWave(QuantityKind):
    """A standing wave's momentum or angular momentum (see the module)."""

    kind = "standing_wave"
    symbol = "p"
    unit = None  # kg*m/s or kg*m^2/s
    routes = ("the wavelength", "the angular momentum operator")
    own_section = False

    def claims(self, scene, head: str, rest: str) -> Quantity | None:
        return system_ask(self.kind, scene, head, rest)

    def value(self, solution, ask, route: int) -> sp.Expr:
        return solution._standing_wave(ask.quantity.detail, route)

    def checks(self, solution, names: list[str]) -> list[Check]:
        return second_route(self, solution, names, "wave_vs_operator")

    def describe(self, ask) -> str:
        return f"the standing wave's {ask.quantity.detail.replace('_', ' ')}"


STANDING_WAVE = StandingWave()
