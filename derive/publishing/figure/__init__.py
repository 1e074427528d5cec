r"""A problem's scene drawn as a TikZ figure, from the scene's own geometry.

`tikz(problem)` returns a ``tikzpicture`` environment (about 6 cm wide) or None when the
scene has nothing to draw. Bodies are drawn by shape (a disk a circle with its center, a
ring a thick circle, a rod a thick bar, a sphere a shaded ball, a point a dot or a block),
joints as a hatched support (a pivot) or a circled dot (an axle), surfaces as an incline,
a floor or a loop, and forces (gravity, pulls, tension), velocities and spins as arrows,
each labelled with the problem's own symbols (``latex.latex_of``). Relative sizes come from the
middle of each parameter's range (or its value), clamped so that the figure stays legible.
The scene-level systems (orbit, spinning wheel, standing wave, internal forces, a turning body,
prescribed paths) have schematics of their own; bodies in 3D (in bearings, on a fixed point, rolling
on an edge, turning freely) are drawn in an oblique projection with their axes and omega and L
from their derivations (`derive.publishing.figure.solids`); so do the classic scenes whose
every part a schematic draws (an incline, a floor, a loop, a pendulum, bodies on one axle, a
collision, a ball bouncing off a floor or a wedge). Any other scene of parts is drawn in its reference configuration to scale, every part
from its own geometry (`derive.publishing.figure.parts`); a part it cannot draw leaves the figure out (None)
rather than draw it wrong. Each contact is marked with its regime: no slip, smooth or rough.
Same problem, same bytes.

>>> from derive.language.problem import load
>>> figure = tikz(load("rolling_incline"))
>>> figure.startswith(r"\begin{tikzpicture}") and r"$\theta$" in figure
True
"""
from __future__ import annotations

from derive.publishing.figure.canvas import LIBRARIES, STYLES, WIDTH, _Figure
from derive.publishing.figure.layout import _LAYOUTS
from derive.publishing.figure.drawn_view import Undrawable

__all__ = ["LIBRARIES", "STYLES", "WIDTH", "tikz"]


def tikz(problem) -> str | None:
    """The problem's scene as a ``tikzpicture`` environment, or None when it has nothing to draw
    (or a part it cannot draw truthfully: the documents then go without a figure)."""
    figure = _Figure(problem)
    for applies, draw in _LAYOUTS:
        if applies(problem):
            try:
                draw(figure)
            except Undrawable:
                return None
            return figure.text() if figure.lines else None
    return None
