"""Scene-level systems: a top (a body on a fixed point), a coin rolling on its edge, a spinning wheel
(a body on a fixed point at its center of mass under a couple for a time), a
standing wave, internal forces, a turning body, a body turning freely."""
from __future__ import annotations

import math

import sympy as sp

from derive.figure.canvas import _add, _clamp, _f, _Figure, _pt, _unit
from derive.mechanics import bearings, free_rotation


def _pivot_point(fig: _Figure) -> None:
    """A body on a fixed point, drawn as a top on its tip: the tilted axis, the body around the
    center of mass, mg, spin and precession."""
    name, top = next(iter(fig.scene.pivot_points.items()))
    tilt = _clamp(fig.num(top.tilt, 0.5), 0.4, 1.0)
    axis = (math.sin(tilt), math.cos(tilt))
    across = (axis[1], -axis[0])
    axis_degrees = math.degrees(math.atan2(axis[1], axis[0]))
    tip = (0.0, 0.0)
    cm = _add(tip, axis, 2.0)
    fig.ground(-1.2, 1.6)
    fig.add(f"\\draw[axis] {_pt(tip)} -- {_pt((0, 3.4))};")
    fig.add(f"\\draw[body] {_pt(tip)} -- {_pt(_add(cm, across, 0.75))} -- {_pt(_add(cm, across, -0.75))} -- cycle;")
    fig.add(f"\\draw[body, rotate around={{{_f(axis_degrees)}:{_pt(cm)}}}] {_pt(cm)} ellipse (0.22 and 0.75);")
    fig.add(f"\\draw[line width=1.5pt] {_pt(cm)} -- {_pt(_add(tip, axis, 3.3))};")
    fig.line(tip, cm, "thin, dashed")
    fig.add(f"\\fill {_pt(cm)} circle (0.05); \\fill {_pt(tip)} circle (0.05);")
    distance = sp.sqrt(sum(c**2 for c in top.offset))
    fig.label(_add(_add(tip, axis, 1.0), across, -0.08), (-across[0], -across[1]), fig.m(distance))
    fig.arc(tip, 2.5, axis_degrees, 90, fig.tex(top.tilt), label_radius=2.55)
    fig.gravity_arrow(cm, fig.scene.bodies[name], 1.1, toward=(1, 0))
    # the spin about the axis near the top of the stem, and the precession about the vertical
    spin_at = _add(tip, axis, 3.0)
    fig.add(f"\\draw[->, thick, rotate around={{{_f(axis_degrees)}:{_pt(spin_at)}}}] "
            f"{_pt(_add(spin_at, (0, -0.3)))} arc[start angle=-90, end angle=200, x radius=0.1, y radius=0.3];")
    fig.label(_add(spin_at, across, 0.35), across, fig.m(top.spin))
    fig.add("\\draw[->, thick] (0.45,3.2) arc[start angle=0, end angle=300, x radius=0.45, y radius=0.13];")
    precession = fig.ask_symbol("pivot_point", name) or r"\Omega"
    fig.label((-0.5, 3.2), (-1, 0), f"${precession}$")


def _rolls_on_edge(fig: _Figure) -> None:
    """A body rolling on its edge on a level floor. In a steady motion on a circle, seen along its
    heading: the coin edge-on, leaning by its tilt toward the circle's axis (dashed), the circle's
    radius from the axis to the contact point, mg and the turning rate. Upright, seen from the side:
    the disk on the floor, its radius and its velocity."""
    name, coin = next(iter(fig.scene.rolls_on_edge.items()))
    body = fig.scene.bodies[name]
    if coin.tilt is None:
        fig.ground(-1.6, 1.6)
        fig.add("\\draw[body] (0,1) circle (1); \\fill (0,1) circle (0.04);")
        fig.line((0, 1), (0.71, 1.71), "thin")
        fig.label((0.3, 1.4), (1, -1), fig.m(coin.radius))
        speed = fig.ask_symbol("rolls_on_edge", name, "upright.min_speed") or "v"
        fig.arrow((0, 1), (1.3, 0), "velocity", f"${speed}$")
        fig.gravity_arrow((0, 1), body, 0.8, toward=(-1, 0))
        return
    tilt = _clamp(fig.num(coin.tilt, 0.4), 0.25, 0.8)
    lean = (-math.sin(tilt), math.cos(tilt))  # from the contact point to the center, toward the axis
    center = _add((0.0, 0.0), lean, 1.0)
    axis_x = -_clamp(fig.num(coin.circle, 3.0) / fig.num(coin.radius, 1.0), 1.6, 3.0)
    fig.ground(axis_x - 0.6, 1.2)
    fig.line((axis_x, 0), (axis_x, 2.6), "axis")
    fig.add(f"\\draw[body, rotate around={{{_f(math.degrees(tilt))}:{_pt(center)}}}] {_pt(center)} "
            "ellipse (0.12 and 1);")
    fig.add(f"\\fill {_pt(center)} circle (0.04); \\fill (0,0) circle (0.04);")
    fig.line((0, 0), (0, 1.6), "thin, dashed")
    fig.arc((0, 0), 1.35, 90, 90 + math.degrees(tilt), fig.tex(coin.tilt), label_radius=1.4)
    fig.dimension((axis_x, 0), (0, 0), fig.tex(coin.circle), side=-1, gap=0.45)
    fig.gravity_arrow(center, body, 0.8, toward=(1, 0))
    fig.add(f"\\draw[->, thick] ({_f(axis_x + 0.4)},2.4) arc[start angle=0, end angle=300, x radius=0.4, "
            "y radius=0.12];")
    rate = fig.ask_symbol("rolls_on_edge", name, "steady.precession") or r"\Omega"
    fig.label((axis_x - 0.45, 2.4), (-1, 0), f"${rate}$")


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
    fig.add(f"\\fill {_pt(origin)} circle (0.05) node[below left] {{$O$}};")
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


def _bearings(fig: _Figure) -> None:
    """A body turning about its shaft, tilted from it; L for a rod. Without gravity the page is the
    plane of the shaft and the own axis (the shaft up the page); under gravity it is the vertical
    plane of the shaft (y up, the shaft at its incline, the own axis's lean toward the reader not
    shown) with the weight. The body sits at its center of mass, off the shaft where `through` puts
    it; the bearings A (toward +z) and B where `apart` is given."""
    name, rotation = next(iter(fig.scene.bearings.items()))
    body = fig.scene.bodies[name]
    tilt = _clamp(fig.num(rotation.tilt, 0.6), 0.25, 1.35)
    weighed = fig.scene.gravity is not None
    incline = _clamp(fig.num(rotation.incline, 0.0), -1.4, 1.4)
    shaft = (math.cos(incline), math.sin(incline)) if weighed else (0.0, 1.0)
    across = (-shaft[1], shaft[0]) if weighed else (1.0, 0.0)  # N.y under gravity, else N.x
    center = bearings.center_offset(rotation.tilt, rotation.roll, bearings.own_axis(body.shape), rotation.through)
    if body.composite is not None:
        reach = fig.num(body.composite.extent(), 1.0)
    else:  # the drawn half-size, 1.6, is a rod's half-length, else the largest size
        reach = max((fig.num(v, 1.0) / (2 if body.shape == "rod" else 1) for v in body.sizes.values()), default=1.0)
    scale = 1.6 / reach if reach > 0 else 1.0
    side = _clamp(fig.num(center[1 if weighed else 0], 0.0) * scale, -1.2, 1.2)
    along = _clamp(fig.num(center[2], 0.0) * scale, -1.2, 1.2)
    cm = _add(_add((0, 0), across, side), shaft, along)
    turn = math.degrees(math.atan2(shaft[1], shaft[0]))  # the shaft's direction on the page
    fig.add(f"\\draw[axis, ->] {_pt(_add((0, 0), shaft, -2))} -- {_pt(_add((0, 0), shaft, 2.2))};")
    rotated = f", rotate around={{{_f(turn - 90)}:{_pt(_add((0, 0), shaft, 1.75))}}}" if weighed else ""
    fig.add(f"\\draw[->, thick{rotated}] {_pt((1.75 * shaft[0] + 0.35, 1.75 * shaft[1]))} "
            "arc[start angle=0, end angle=300, x radius=0.35, y radius=0.1];")
    fig.label(_add(_add((0, 0), shaft, 1.8), across, 0.45), across, fig.m(rotation.rate))
    if side != 0 or along != 0:
        fig.line((0, 0), cm, "thin, dashed")
        fig.dot((0, 0), 0.05)
    if weighed:  # seen from the side: the own axis leans toward the reader
        fig.body(body, cm, 0.9, turn)
        fig.gravity_arrow(cm, body)
    else:
        direction = 90 - math.degrees(tilt)
        fig.body(body, cm, 1.6, direction)
        if rotation.tilt != 0:
            fig.arc(cm, 0.8, direction, 90, fig.tex(rotation.tilt), label_radius=0.9)
        if body.shape == "rod":  # a thin rod's L is normal to it, in the plane of the rod and the axis
            fig.arrow(cm, _unit(direction + 90), "very thick, ->, green!40!black", r"$\vec L$")
    if rotation.apart is not None:  # over the body, inside the rate's arrow
        half = _clamp(fig.num(rotation.apart, 1.0) * scale / 2, 1.0, 1.5)
        for label, sign in (("A", 1), ("B", -1)):
            at = _add((0, 0), shaft, sign * half)
            fig.add(f"\\fill[gray!60, draw=black, rotate around={{{_f(turn)}:{_pt(at)}}}] "
                    f"{_pt(_add(at, (-0.12, -0.2)))} rectangle {_pt(_add(at, (0.12, 0.2)))};")
            fig.label(_add(at, across, -0.25), tuple(-c for c in across), f"${label}$")


def _free_rotation(fig: _Figure) -> None:
    """A body turning freely, asked of its symmetry axis: L up the page, the axis and omega in the
    plane they share at their angles from it (omega beyond L for a flat body, I3 > I1, between the
    axis and L for a long one), the body across or along its axis, the axis's precession about L;
    any other body in free rotation: the body with a spin about its own axis."""
    name, free = next(iter(fig.scene.free_rotations.items()))
    body = fig.scene.bodies[name]
    if free.inertia is not None:
        tensor = sp.diag(*free.inertia)
    else:
        parts = body.composite.parts if body.composite is not None else None
        tensor = bearings.body_tensor(body.shape, body.mass, body.sizes, parts)
    try:
        transverse, axial, _ = free_rotation.symmetric(free_rotation.principal_moments(tensor))
    except (free_rotation.NotModelled, free_rotation.NotPrincipal):
        transverse = None
    if transverse is None or not any(a.quantity.kind == "free_rotation" and a.quantity.detail in
                                     free_rotation.SYMMETRIC for a in fig.problem.asks.values()):
        fig.body(body, (0, 0), 1.2)
        fig.spin((0, 0), 0.5, 1, fig.m(free.spin))
        return
    ratio = _clamp(fig.num(axial / transverse, 2.0), 0.2, 5.0)  # I3/I1: the same for every mass
    across = _clamp(fig.num(free.across / free.spin, 0.4), 0.1, 1.0)  # tan of omega's angle
    tilt = _clamp(math.atan(across / ratio), math.radians(10), math.radians(40))  # the axis from L
    omega_tilt = _clamp(math.atan(ratio * math.tan(tilt)), math.radians(5), math.radians(70))
    axis = 90 + math.degrees(tilt)  # leaning left of L
    omega = 90 + math.degrees(tilt) - math.degrees(omega_tilt)
    flat = ratio > 1
    fig.add(f"\\draw[body, rotate around={{{_f(axis)}:(0,0)}}] (0,0) ellipse "
            f"({_f(0.25 if flat else 1.3)} and {_f(1.3 if flat else 0.45)});")
    fig.add(f"\\draw[axis] {_pt(_unit(axis + 180))} -- {_pt(_add((0, 0), _unit(axis), 2.4))};")
    fig.add("\\fill (0,0) circle (0.05);")
    fig.arrow((0, 0), (0, 2.6), "very thick, ->, green!40!black", r"$\vec L$")
    fig.arrow((0, 0), _add((0, 0), _unit(omega), 2.1), "velocity", r"$\vec\omega$")
    fig.arc((0, 0), 1.5, 90, axis, fig.ask_symbol("free_rotation", name, "angle_L_axis"), label_radius=1.55)
    lean = 2.4 * math.sin(tilt)
    fig.add(f"\\draw[dashed, gray] (0,{_f(2.4 * math.cos(tilt))}) ellipse ({_f(lean)} and {_f(0.25 * lean)});")
    fig.add(f"\\draw[->, thick] ({_f(lean)},{_f(2.4 * math.cos(tilt))}) arc[start angle=0, end angle=60, "
            f"x radius={_f(lean)}, y radius={_f(0.25 * lean)}];")
    precession = fig.ask_symbol("free_rotation", name, "free_precession.space")
    fig.label((lean + 0.1, 2.4 * math.cos(tilt)), (1, 0), f"${precession}$" if precession else None)
