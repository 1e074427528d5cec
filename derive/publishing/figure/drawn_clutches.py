r"""Clutches and brakes of the general layout (derive.publishing.figure.parts).

- a clutch to the ground (a brake): a pad pressed on the body's rim on its clearest side, held
  by a hatched anchor behind it;
- a clutch between two bodies on one axis (a record dropped on a turntable): a dotted band just
  inside the smaller body's rim, where their plates (a felt) meet; bodies apart are `Undrawable`
  (no picture says where their plates are);

each labelled with its name and, slipping, the friction couple (`rough`, as a contact's regime is),
or "no slip" where it holds.

>>> from derive.language.problem import load
>>> from derive.publishing.figure import tikz
>>> drawn = tikz(load("flywheel_brake_grips"))
>>> "pad, rough, $C$" in drawn and "pattern=north east lines" in drawn
True
"""
from __future__ import annotations

import math

from derive.publishing.figure.canvas import _add, _f, _pt, _unit
from derive.publishing.figure.drawn_view import Undrawable
from derive.publishing.figure.vectors import _perp, _scale_vec, _sub
from derive.parts.clutch import Clutch
from derive.parts.slipping_clutch import SlippingClutch
from derive.text.latex import tex_escape

PAD = (0.5, 0.14)  # cm: a brake pad's length along the rim and its thickness
BAND = 0.09  # cm: the width of the dotted band where two bodies' plates meet


class ClutchDrawings:
    """How the general layout draws clutches and brakes (a mixin of parts._Layout)."""

    def _clutch_text(self, clutch) -> str:
        """Its name and regime: "pad, rough, $C$" while it slips, "felt, no slip" where it holds."""
        couple = self.fig.tex(clutch.couple) if isinstance(clutch, SlippingClutch) else None
        regime = f"rough, ${couple}$" if couple else "rough" if isinstance(clutch, SlippingClutch) else "no slip"
        return f"\\scriptsize {tex_escape(clutch.name)}, {regime}"

    def _clutch(self, clutch: Clutch | SlippingClutch) -> None:
        if clutch.to is None:
            self._brake(clutch)
        else:
            self._plates(clutch)

    def _brake(self, clutch) -> None:
        """A pad on the body's rim (its outline), on its clearest side, with a hatched anchor behind."""
        view = self.view
        drawn = self.bodies[clutch.body]
        center = drawn.center
        side = view.clearest(center, drawn.extent + 0.9, own=drawn.outline(), beyond=drawn.extent + 0.02)
        rim = _add(center, side, drawn.reach(center, side) + 0.01)
        across = _perp(side)
        length, thick = PAD
        corners = [_add(_add(rim, across, k * length / 2), side, d) for k, d in ((1, 0), (-1, 0), (-1, thick), (1, thick))]
        view.put("joints", f"\\draw[fill=gray!55] {' -- '.join(_pt(p) for p in corners)} -- cycle;")
        view.ink_polyline(corners + corners[:1])
        back = _add(rim, side, thick)
        anchor = _add(back, side, 0.22)
        view.put("supports", f"\\draw[thick] {_pt(back)} -- {_pt(anchor)};")
        view.ink_line(back, anchor)
        self._ground_anchor(anchor, _scale_vec(side, -1), width=0.6)
        self.later(self._clutch_text(clutch), _add(anchor, side, 0.14), 0.04, [side, across, _scale_vec(across, -1)])

    def _plates(self, clutch) -> None:
        """A dotted band inside the smaller body's rim, where two bodies on one axis meet."""
        view = self.view
        one, other = self.bodies[clutch.body], self.bodies[clutch.to]
        if math.hypot(*_sub(one.center, other.center)) > 1e-6:
            raise Undrawable(f"the figure does not draw a clutch between bodies apart ({clutch.name})")
        inner, outer = sorted((one, other), key=lambda drawn: drawn.extent)
        radius = inner.extent - BAND / 2 - 0.02
        center = inner.center
        view.put("marks", f"\\draw[line width={_f(BAND * 28.35)}pt, gray!60, densely dotted] {_pt(center)} "
                          f"circle ({_f(radius)});")
        view.ink_circle(center, radius)
        side = view.clearest(center, outer.extent + 0.8, own=one.outline() + other.outline(),
                             candidates=[_unit(a) for a in (45, 135, 315, 225)])
        view.put("marks", f"\\draw[thin] {_pt(_add(center, side, radius))} -- {_pt(_add(center, side, outer.extent + 0.2))};")
        view.ink_line(_add(center, side, radius), _add(center, side, outer.extent + 0.2))
        self.later(self._clutch_text(clutch), _add(center, side, outer.extent + 0.2), 0.04, [side])
