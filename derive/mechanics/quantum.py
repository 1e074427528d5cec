"""The notes' §8 estimate: a particle whose de Broglie wavelength fits a circle n times.

Wave route: n h / p = 2 pi r gives p, and L = p r. Operator route: the wave on the circle is
exp(i n phi); L_z = -i hbar d/dphi has the eigenvalue n hbar on it. Both give L = n h / (2 pi).

>>> h, r = sp.symbols("h r", positive=True)
>>> momentum(h, r, 1), angular_momentum(h, r, 1, "wave")
(h/(2*pi*r), h/(2*pi))
"""
from __future__ import annotations

import sympy as sp


def momentum(h, radius, wavelengths) -> sp.Expr:
    p = sp.Symbol("p", positive=True)
    (value,) = sp.solve(sp.Eq(wavelengths * h / p, 2 * sp.pi * radius), p)
    return value


def angular_momentum(h, radius, wavelengths, route: str) -> sp.Expr:
    if route == "wave":
        return sp.simplify(momentum(h, radius, wavelengths) * radius)
    phi = sp.Symbol("phi", real=True)
    wave = sp.exp(sp.I * wavelengths * phi)  # built here, never parsed from a file
    hbar = h / (2 * sp.pi)
    return sp.simplify(-sp.I * hbar * wave.diff(phi) / wave)
