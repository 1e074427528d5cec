"""Scene-level systems: a spinning wheel (a body on a fixed point at its center of mass under a couple
for a time), a standing wave, internal forces (the 3D bodies: derive.publishing.figure.solids)."""
from __future__ import annotations

import math

from derive.publishing.figure.canvas import _add, _f, _Figure, _pt, _unit


def _wheel(fig: _Figure) -> None:
    """A body on a fixed point at its center of mass under a couple for a time, drawn as a wheel in
    the ground's xz plane (z up the page): its axle at its tilt, L0 along it, the couple's angular
    impulse (its part in the page), L after it dashed and the angle between."""
    name, point = next((n, p) for n, p in fig.scene.pivot_points.items() if p.centered)
    body = fig.scene.bodies[name]
    couple = next(p for p in fig.scene.loads if getattr(p, "body", None) == name)
    tilt = fig.num(point.tilt, math.pi / 2)
    axis = (math.sin(tilt), math.cos(tilt))
    turn = math.degrees(math.atan2(axis[1], axis[0]))
    change = (fig.num(couple.axis[0], 0.0), fig.num(couple.axis[2], 1.0))
    if math.hypot(*change) < 0.2:  # the couple's impulse lies across the page: draw it across the axle
        change = (-axis[1], axis[0])
    change = (change[0] / math.hypot(*change), change[1] / math.hypot(*change))
    fig.add(f"\\draw[body, rotate around={{{_f(turn)}:(0,0)}}] (0,0) ellipse (0.35 and 1.1);")
    fig.line(_add((0, 0), axis, -0.7), (0, 0), "line width=1.5pt")
    fig.add("\\fill (0,0) circle (0.05);")
    fig.add(f"\\draw[->, thick, rotate around={{{_f(turn)}:(0,0)}}] (-0.25,-0.85) arc[start angle=-120, "
            "end angle=120, x radius=0.3, y radius=1];")
    fig.label(_add((0, 0), axis, -0.9), (-axis[0], -axis[1]), fig.m(point.spin))
    length, size = 3.0, 0.9
    end = _add((0, 0), axis, length)
    momentum = fig.product(body.inertia, point.spin) if body.shape == "custom" else None
    fig.arrow((0, 0), _add((0, 0), axis, length), "very thick, ->",
              f"$\\vec L_0 = {momentum}$" if momentum else "$\\vec L_0$")
    impulse = fig.product(couple.torque, couple.duration)
    fig.arrow(end, (change[0] * size, change[1] * size), "force", f"$\\Delta L = {impulse}$" if impulse else None)
    after = _add(end, change, size)
    fig.arrow((0, 0), after, "thick, dashed, ->")
    fig.arc((0, 0), 1.8, turn, math.degrees(math.atan2(after[1], after[0])), r"\Delta\phi", label_radius=1.85)


def _wave(fig: _Figure) -> None:
    """A standing wave of n wavelengths around a circle of radius r (its two extremes), with L."""
    wave = fig.scene.wave
    n, radius, amplitude = int(fig.num(wave.wavelengths, 1)), 1.4, 0.22
    fig.add(f"\\draw[gray!60] (0,0) circle ({_f(radius)});")
    for sign, style in ((1, "thick, blue!70!black"), (-1, "thick, dashed, blue!70!black")):
        points = [_add((0, 0), _unit(5 * k), radius + sign * amplitude * math.sin(n * math.radians(5 * k)))
                  for k in range(72)]
        fig.add(f"\\draw[{style}] plot[smooth cycle] coordinates {{{' '.join(_pt(p) for p in points)}}};")
    fig.add("\\fill (0,0) circle (0.04);")
    fig.line((0, 0), _add((0, 0), _unit(-40), radius))
    fig.label(_add((0, 0), _unit(-40), radius / 2), (1, 1), fig.m(wave.radius))
    fig.out_of_page((-0.45, 0.35), r"\vec L")
    at = _add((0, 0), _unit(130), radius)
    fig.dot(at, 0.07)
    fig.arrow(at, _add((0, 0), _unit(40), 0.8), "velocity", "$p$")
    wavelengths = fig.tex(wave.wavelengths)
    count = "" if wavelengths == "1" else f"{wavelengths}\\,"
    fig.label((1.7, -1.3), (1, 0), f"${count}\\lambda = 2\\pi {fig.tex(wave.radius)}$")


def _internal(fig: _Figure) -> None:
    """N point masses with equal and opposite forces along the lines between them, r from O."""
    n = fig.scene.internal_forces
    centre, radius = (1.2, 0.9), 1.2
    points = [_add(centre, _unit(90 + 360 * k / n + 15), radius) for k in range(n)]
    origin = (-1.6, -0.6)
    fig.dot(origin)
    fig.label(origin, (-1, -1), "$O$")
    for k, p in enumerate(points, start=1):
        fig.add(f"\\draw[dashed, gray, ->] {_pt(origin)} -- {_pt(p)};")
        fig.dot(p, 0.09)
        outward = (p[0] - centre[0], p[1] - centre[1])
        fig.label(_add(p, outward, 0.12), outward, f"$m_{{{k}}}$")
    for i in range(n):
        for j in range(n):
            if i != j:
                d = (points[j][0] - points[i][0], points[j][1] - points[i][1])
                length = math.hypot(*d)
                text = f"$\\vec F_{{{i + 1}{j + 1}}}$" if (i, j) in ((0, 1), (1, 0)) else None
                fig.arrow(points[i], (0.55 * d[0] / length, 0.55 * d[1] / length), "force", text)
