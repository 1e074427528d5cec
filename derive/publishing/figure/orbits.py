"""An orbit: the ellipse about the central mass (or, with only L given, the effective potential)."""
from __future__ import annotations

import math

from derive.publishing.figure.canvas import _add, _clamp, _f, _Figure, _pt, _unit


def _orbit(fig: _Figure) -> None:
    """The orbit: an ellipse about the central mass at its focus, r to the planet, with what the file
    gives of it (its axis, or its distance and speed at periapsis); with only the angular momentum,
    the effective potential beside it."""
    orbit = fig.scene.orbit
    given = orbit.eccentricity is not None
    e = _clamp(fig.num(orbit.eccentricity, 0.5), 0.0, 0.75) if given else 0.5
    a = 1.5 if given else 1.1
    b = a * math.sqrt(1 - e * e)
    center = (-a * e, 0.0)
    fig.add(f"\\draw[thick] {_pt(center)} ellipse ({_f(a)} and {_f(b)});")
    fig.add("\\fill (0,0) circle (0.09);")
    fig.label((0.05, -0.12), (1, -1), fig.m(orbit.GM))
    nu = 115.0
    r = a * (1 - e * e) / (1 + e * math.cos(math.radians(nu)))
    planet = _add((0, 0), _unit(nu), r)
    fig.line((0, 0), planet, "thin")
    fig.label(_add((0, 0), _unit(nu), r / 2), _unit(nu - 90), "$r$")
    fig.dot(planet, 0.06)
    # velocity along the tangent: d/dnu of the position on the ellipse
    dr = a * (1 - e * e) * e * math.sin(math.radians(nu)) / (1 + e * math.cos(math.radians(nu))) ** 2
    tangent = (dr * math.cos(math.radians(nu)) - r * math.sin(math.radians(nu)),
               dr * math.sin(math.radians(nu)) + r * math.cos(math.radians(nu)))
    norm = math.hypot(*tangent)
    fig.arrow(planet, (0.7 * tangent[0] / norm, 0.7 * tangent[1] / norm), "velocity", "$v$")
    if orbit.periapsis_speed is not None:
        # given at periapsis: its distance and speed there, never the axis they give (an answer)
        distance, speed = orbit.periapsis_speed
        periapsis = (center[0] + a, 0.0)
        fig.dimension((0.0, 0.0), periapsis, fig.tex(distance), side=-1, gap=0.35)
        fig.dot(periapsis, 0.06)
        fig.arrow(periapsis, (0.0, 0.7), "velocity", fig.m(speed))
        return
    if given:
        fig.dimension((center[0] - a, -b), (center[0] + a, -b), fig.tex(2 * orbit.semi_major_axis), side=-1, gap=0.25)
        fig.dot(center, 0.03)
        if e > 0.1:
            fig.dimension(center, (0, 0), fig.tex(orbit.semi_major_axis * orbit.eccentricity), side=1, gap=0.3)
        return
    # U_eff(r) = -GM/r + l^2/(2 r^2) in units of the circular radius and the well's depth
    x0, y0, width, height = 1.7, -0.9, 2.6, 2.2
    fig.line((x0, y0 + height / 2), (x0 + width, y0 + height / 2), "->")
    fig.label((x0 + width, y0 + height / 2), (0, -1), "$r$")
    fig.line((x0, y0), (x0, y0 + height), "->")
    fig.label((x0, y0 + height), (-1, 0), "$U_{\\mathrm{eff}}$")
    points = []
    for k in range(40):
        x = 0.42 + k * (4.0 - 0.42) / 39
        u = -2 / x + 1 / x**2
        points.append(_pt((x0 + x * width / 4.0, y0 + height / 2 + u * height / 2.4)))
    fig.add(f"\\draw[thick, blue!70!black] plot[smooth] coordinates {{{' '.join(points)}}};")
    bottom = (x0 + width / 4.0, y0 + height / 2 - height / 2.4)
    fig.line(bottom, (bottom[0], y0 + height / 2), "dotted")
    fig.label((bottom[0], y0 + height / 2), (0, 1), "$r_c$")
    fig.out_of_page((-0.5, -0.45), fig.tex(orbit.angular_momentum))
