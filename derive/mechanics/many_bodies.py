"""The notes' §6: internal central forces do not change the total angular momentum.

N point masses at positions x_i, each pair pulling along the line between them with a
strength f_ij(|x_i - x_j|) = f_ji. Direct route: sum over i of x_i x (sum over j of F_ji),
simplified. Pair route: each pair's two terms combine to (x_i - x_j) x F_ji, parallel vectors.
Both must vanish, for any positions and any force law.

>>> internal_torque(3, "direct")
0
"""
from __future__ import annotations

import itertools

import sympy as sp



def _positions(count: int) -> list[sp.Matrix]:
    return [sp.Matrix(sp.symbols(f"x_{i} y_{i} z_{i}", real=True)) for i in range(1, count + 1)]


def _strength(i: int, j: int, gap: sp.Matrix) -> sp.Expr:
    f = sp.Function(f"f_{min(i, j)}{max(i, j)}")  # the same law for the pair either way round
    return f(sp.sqrt(gap.dot(gap)))


def internal_torque(count: int, route: str) -> sp.Expr:
    """The z component of dL/dt from the internal forces alone (all three components vanish)."""
    x = _positions(count)
    total = sp.zeros(3, 1)
    if route == "direct":
        for i in range(count):
            force = sp.zeros(3, 1)
            for j in range(count):
                if i != j:
                    gap = x[j] - x[i]
                    force += _strength(i, j, gap) * gap  # F_ji: the pull of j on i
            total += x[i].cross(force)
    else:
        for i, j in itertools.combinations(range(count), 2):
            gap = x[j] - x[i]
            total += (x[i] - x[j]).cross(_strength(i, j, gap) * gap)
    return sp.simplify(total.norm())
