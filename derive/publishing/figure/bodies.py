"""Bodies at given positions (a molecule): to scale, with their distances and the center of mass."""
from __future__ import annotations

import math

import sympy as sp

from derive.publishing.figure.canvas import _add, _clamp, _f, _Figure, _label_mass, _pt


def _placed(fig: _Figure) -> None:
    """Bodies at given positions (a molecule): to scale, with the distances and the center of mass
    (unless the question asks where it is)."""
    scene = fig.scene
    names = list(scene.motions)
    positions = [tuple(fig.num(p, 0) for p in scene.motions[n].position) for n in names]
    span = max((math.hypot(p[0] - q[0], p[1] - q[1]) for p in positions for q in positions), default=0) or 1.0
    scale = 4.0 / span
    drawn = [(p[0] * scale, p[1] * scale) for p in positions]
    masses = [fig.num(scene.bodies[n].mass, 1) for n in names]
    biggest = max(masses) or 1.0
    for a in range(len(drawn)):
        for b in range(a + 1, len(drawn)):
            fig.line(drawn[a], drawn[b], "thick, gray")
    for name, p, m in zip(names, drawn, masses):
        size = 0.3 * _clamp((m / biggest) ** (1 / 3), 0.5, 1.0)
        fig.add(f"\\shade[ball color=gray!50] {_pt(p)} circle ({_f(size)});")
        _label_mass(fig, scene.bodies[name], _add(p, (0, size + 0.05)), (0, 1))
    if len(names) == 2:
        a, b = (scene.motions[n].position for n in names)
        fig.dimension(drawn[0], drawn[1], fig.tex(sp.sqrt((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2)), side=-1,
                      gap=0.55)
    if any(a.quantity.kind in ("center_of_mass", "position_cm") for a in fig.problem.asks.values()):
        return  # where it is, is what the question asks: the figure does not give it away
    total = sum(masses) or 1.0
    cm = (sum(m * p[0] for m, p in zip(masses, drawn)) / total, sum(m * p[1] for m, p in zip(masses, drawn)) / total)
    fig.add(f"\\draw {_pt(cm)} circle (0.1); \\draw {_pt(_add(cm, (-0.14, 0)))} -- {_pt(_add(cm, (0.14, 0)))} "
            f"{_pt(_add(cm, (0, -0.14)))} -- {_pt(_add(cm, (0, 0.14)))};")
    fig.label(_add(cm, (0, 0.15)), (0, 1), "cm")
