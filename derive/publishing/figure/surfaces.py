"""Bodies on a surface: an incline, a level floor (with a pulled spool or a body that skids), a loop-the-loop."""
from __future__ import annotations

import math

import sympy as sp

from derive.publishing.figure.canvas import _add, _clamp, _f, _Figure, _pt, _unit, given_motion, regime_text
from derive.text.latex import tex_escape
from derive.parts.contact import Contact
from derive.parts.cord import Cord
from derive.parts.surfaces import Circle
from derive.model.scene import Body


def _on_surface(fig: _Figure) -> None:
    """Bodies on an incline or a level floor: the surface, each body touching it, gravity,
    pulls, velocities and the kinetic friction of a skid."""
    scene = fig.scene
    contacts = [c for c in scene.constraints if isinstance(c, Contact)]
    surface = scene.surfaces[contacts[0].surface]
    if isinstance(surface, Circle):
        _loop(fig, surface, contacts)
        return
    angle = fig.num(surface.angle, 0.5)
    if angle <= 1e-9:
        _floor(fig, contacts)
        return
    angle = _clamp(angle, 0.3, 0.8)
    slope = 5.2
    width, height = slope * math.cos(angle), slope * math.sin(angle)
    fig.add(f"\\draw[fill=gray!10] (0,0) -- {_pt((width, 0))} -- {_pt((0, height))} -- cycle;")
    fig.add(f"\\fill[pattern=north east lines] (-0.2,-0.15) rectangle {_pt((width + 0.3, 0))};")
    fig.arc((width, 0), 0.9, 180 - math.degrees(angle), 180, fig.tex(surface.angle), label_radius=1.0)
    down, normal = (math.cos(angle), -math.sin(angle)), (math.sin(angle), math.cos(angle))
    reference = _reference_size(fig, surface.height, height)
    several = len(contacts) > 1
    along = 0.45 if several else 1.0
    previous = None  # the foot of the body before, when several: their regimes, along the slope, must not meet
    for contact in contacts:
        body = scene.bodies[contact.body]
        r = _drawn_radius(fig, body, reference)
        along += r
        if previous is not None:
            along = max(along, previous + 1.08)
        foot = _add((0, height), down, along)
        center = _add(foot, normal, r)
        fig.body(body, center, r, -math.degrees(angle), block=body.shape == "point", face=True)
        regime = regime_text(fig, contact)
        if several:  # each body's name above it, its regime along the slope under it
            fig.label(_add(center, normal, r + 0.05), normal, f"\\scriptsize {tex_escape(body.name)}")
            fig.label(_add(foot, normal, -0.03), (0, -1), regime, f"rotate={_f(-math.degrees(angle))}")
        else:
            fig.label(_add(_add(foot, down, r + 0.12), normal, 0.02), _add(normal, down), regime)
            if scene.gravity is not None:
                fig.gravity_arrow(fig.mass_center(body, center, r, -math.degrees(angle)), body)
        previous = along
        along += r + 0.4
    if surface.height is not None:
        # the height a body drops to the foot of the incline: one body's from where it is drawn (its
        # point of contact, whose drop its center's equals), several bodies' from the top
        top = height if several else foot[1]
        if not several:
            fig.line((0, top), foot, "gray, very thin, dashed")
        fig.dimension((0, 0), (0, top), fig.tex(surface.height), side=1, gap=0.3)
    if several and scene.gravity is not None:
        fig.arrow((width, 0.85 * height), (0, -0.7), "force", "$\\vec g$")


def _reference_size(fig: _Figure, size_expr, drawn: float):
    """(metres, cm) of a scene size that body sizes are drawn in proportion to."""
    return (fig.num(size_expr, 0.0), drawn)


def _drawn_radius(fig: _Figure, body: Body, reference, low: float = 0.18, high: float = 0.5,
                  default: float = 0.3) -> float:
    if body.shape == "point":
        return 0.17
    size = body.sizes.get("radius", body.sizes.get("outer_radius"))
    metres, drawn = reference
    if size is None or metres <= 0 or fig.num(size, 0.0) <= 0:
        return default
    return _clamp(fig.num(size, 0.0) / metres * drawn, low, high)


def _floor(fig: _Figure, contacts: list[Contact]) -> None:
    """A level floor: each body on it, with its pulls, launch velocity and the kinetic friction of a skid."""
    scene = fig.scene
    fig.ground(-0.4, 5.4)
    x = 1.4
    for contact in contacts:
        body = scene.bodies[contact.body]
        pull = next((p for p in scene.loads if isinstance(p, Cord) and p.path[0].body == body.name
                     and p.path[-1].kind == "pulled"), None)
        r = 1.0 if pull else 0.8
        center = (x, r)
        fig.body(body, center, r, block=body.shape == "point", face=True)
        fig.label((x + r + 0.12, 0.02), (1, 1), regime_text(fig, contact))
        if pull:
            _spool(fig, body, pull, center, r)
        if scene.gravity is not None:
            fig.gravity_arrow(fig.mass_center(body, center, r), body, r * 0.55, toward=(-1, 0) if pull else (1, 0))
        motion = given_motion(scene, body.name)
        if motion is not None and any(v != 0 for v in motion.velocity):
            v = (fig.num(motion.velocity[0], 1), fig.num(motion.velocity[1], 0))
            n = math.hypot(*v) or 1.0
            fig.arrow(_add(center, (0, r + 0.25)), (1.2 * v[0] / n, 1.2 * v[1] / n), "velocity",
                      fig.m(sp.sqrt(motion.velocity[0] ** 2 + motion.velocity[1] ** 2)))
        if motion is not None and contact.kinetic is not None and not contact.rolling:
            # kinetic friction against the slip of the contact point, a radius below the center
            slip = fig.num(motion.velocity[0] + motion.spin * body.sizes.get("radius", 0), 0)
            way = -1 if slip > 0 else 1
            text = fig.product(contact.kinetic, body.mass, scene.gravity.g) if scene.gravity else fig.tex(contact.kinetic)
            fig.arrow((x + 0.05 * way, 0.08), (way * 1.0, 0), "force", f"${text}$" if text else None,
                      toward=(way, 1))
        if "radius" in body.sizes and fig.tex(body.sizes["radius"]) and not pull:
            fig.line(center, _add(center, _unit(150), r), "thin")
            fig.label(_add(center, _unit(150), r * 0.55), (0, 1), fig.m(body.sizes['radius']))
        x += 2 * r + 1.2


def _spool(fig: _Figure, body: Body, cord: Cord, center, r: float) -> None:
    """A spool: its hub, the cord leaving the hub's underside at the pull's angle, the radii."""
    hub_radius, pull = cord.path[0].radius, cord.path[-1]
    ratio = _clamp(fig.num(hub_radius, 1) / fig.size(body, "radius", 2), 0.25, 0.7)
    hub = r * ratio
    fig.add(f"\\draw[fill=gray!35] {_pt(center)} circle ({_f(hub)}); \\fill {_pt(center)} circle (0.04);")
    angle = _clamp(fig.num(pull.angle, 0.5), 0.15, 1.2)
    start = _add(center, (math.sin(angle), -math.cos(angle)), hub)
    direction = (math.cos(angle), math.sin(angle))
    fig.line(start, _add(start, direction, 1.4), "thick")
    fig.arrow(_add(start, direction, 1.4), (0.9 * direction[0], 0.9 * direction[1]), "force",
              fig.m(pull.force))
    corner = _add(start, direction, 1.0)
    fig.line(corner, _add(corner, (1.0, 0)), "thin, dashed")
    fig.arc(corner, 0.7, 0, math.degrees(angle), fig.tex(pull.angle), label_radius=0.75)
    fig.line(center, _add(center, _unit(120), r), "thin")
    fig.label(_add(center, _unit(120), r * 0.7), _unit(210), fig.m(body.sizes.get('radius'))
              if fig.tex(body.sizes.get("radius")) else None)
    fig.line(center, _add(center, _unit(200), hub), "thin")
    fig.label(_add(center, _unit(200), hub + 0.02), (-1, 0), fig.m(hub_radius))


def _loop(fig: _Figure, loop: Circle, contacts: list[Contact]) -> None:
    """A loop-the-loop: a ramp from the release height into a circular track, the bodies at the
    top of the ramp, the loop's radius and the release height."""
    scene = fig.scene
    radius = 1.15
    center = (1.2, radius)
    start, c1, c2, end = (-2.6, 3.3), (-1.8, 0.1), (-0.6, 0.0), (1.2, 0.0)
    fig.add(f"\\draw[thick] {_pt(start)} .. controls {_pt(c1)} and {_pt(c2)} .. {_pt(end)};")
    fig.add(f"\\draw[thick] {_pt(center)} circle ({_f(radius)});")
    fig.ground(-2.8, 2.7, 0.0)
    fig.line(center, _add(center, _unit(30), radius), "thin")
    fig.label(_add(center, _unit(30), radius / 2), (-0.5, 1), fig.m(loop.radius))
    fig.dot(center, 0.04)
    reference = (fig.num(loop.radius, 0.0), radius)
    u = 0.0
    for contact in contacts:
        body = scene.bodies[contact.body]
        r = _drawn_radius(fig, body, reference, 0.13, 0.3, 0.2)
        point, tangent = _bezier(start, c1, c2, end, u)
        normal = (-tangent[1], tangent[0])
        centre = _add(point, normal, r)
        fig.body(body, centre, r, block=body.shape == "point", face=True)
        regime = regime_text(fig, contact)
        if len(contacts) > 1:
            regime = regime.replace("scriptsize ", f"scriptsize {tex_escape(body.name)}: ")
        fig.label(_add(centre, normal, r + 0.05), (1, 0.4), regime)
        u += 0.16
    first, _ = _bezier(start, c1, c2, end, 0.0)
    fig.dimension((-3.0, 0), (-3.0, first[1]), "h", side=-1, gap=0.0)
    if scene.gravity is not None:
        fig.arrow((2.9, 2.6), (0, -0.7), "force", "$\\vec g$")


def _bezier(p0, p1, p2, p3, u: float):
    """Point and unit tangent of a cubic Bezier curve at parameter u."""
    w = (1 - u) ** 3, 3 * u * (1 - u) ** 2, 3 * u * u * (1 - u), u**3
    point = tuple(sum(wi * p[i] for wi, p in zip(w, (p0, p1, p2, p3))) for i in range(2))
    d = 3 * (1 - u) ** 2, 6 * u * (1 - u), 3 * u * u
    tangent = tuple(sum(di * (q[i] - p[i]) for di, p, q in zip(d, (p0, p1, p2), (p1, p2, p3))) for i in range(2))
    norm = math.hypot(*tangent) or 1.0
    return point, (tangent[0] / norm, tangent[1] / norm)
