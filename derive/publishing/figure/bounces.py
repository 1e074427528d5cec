r"""A bounce off a fixed surface: the surface (a hatched floor, or a fixed wedge whose face it strikes),
the ball where the scene places it, and how it comes in.

The ball is drawn where the scene places it: touching the surface when it strikes from there (its
incoming velocity an arrow onto it, from the state given by rates), or above it when it is released
from rest and falls onto it (a dashed drop to the point it strikes, the height dimensioned). A
wedge reaches down to the floor where the ball lands (the lowest height a later state gives the
ball), dimensioned too. The contact's regime and the coefficient of restitution are written at
the point it strikes; the angle of the incoming path to the surface's normal is marked when a
parameter names it.

>>> from derive.language.problem import load
>>> from derive.publishing.figure import tikz
>>> drawn = tikz(load("sphere_bounces_gripping"))
>>> "pattern=north east lines" in drawn and "[velocity]" in drawn and r"{$\theta$}" in drawn
True
"""
from __future__ import annotations

import math

import sympy as sp

from derive.publishing.figure.canvas import _add, _clamp, _f, _Figure, _label_mass, _pt, given_motion
from derive.publishing.figure.drawn_view import BALL, Undrawable
from derive.publishing.figure.vectors import _degrees, _norm, _scale_vec
from derive.model.scene import Event
from derive.parts.surfaces import Plane

SPHERE = 0.4  # cm: a round ball's radius on the figure (nothing else in the scene gives it a scale)
DROP = 3.0  # cm: the longest height on the figure (a drop, a wedge's)
APRON = 1.6  # cm: the surface on either side of the point struck


def bounce_off_surface(scene) -> Event | None:
    """The scene's first bounce off a fixed surface (a state's `event:`), or None."""
    return next((s.event for s in scene.states.values() if s.event and s.event.kind == "bounce"
                 and s.event.to in scene.surfaces), None)


def bounces(problem) -> bool:
    """A lone body bouncing off a fixed plane, with gravity at most: what `_bounce` draws."""
    scene = problem.scene
    event = bounce_off_surface(scene)
    return event is not None and len(scene.bodies) == 1 and not scene.constraints and not scene.loads \
        and isinstance(scene.surfaces[event.to], Plane) and scene.surfaces[event.to].carrier is None


def _regime(fig: _Figure, event: Event) -> str:
    """The bounce's surface in words (smooth, rough with its coefficient, no slip where it grips),
    and its coefficient of restitution."""
    if event.grips:
        words = ["no slip"]
    elif event.friction is not None:
        words = ["rough"] + [f"${t}$" for t in dict.fromkeys(fig.tex(f) for f in event.friction) if t]
    else:
        words = ["smooth"]
    restitution = fig.tex(event.restitution)
    return "\\scriptsize " + ", ".join(words + ([f"$e = {restitution}$"] if restitution not in (None, "e") else
                                                ["$e$"] if restitution else []))


def _named_angle(fig: _Figure, along, normal) -> sp.Expr | None:
    """The parameter that is the angle between the direction `along` and `normal` (sympy vectors), or None."""
    for symbol in sorted(fig.parameters, key=str):
        for sign in (1, -1):
            candidate = sp.cos(symbol) * normal + sign * sp.sin(symbol) * sp.Matrix([normal[1], -normal[0]])
            if sp.simplify(along[0] * candidate[1] - along[1] * candidate[0]) == 0 \
                    and fig.num(along.dot(candidate), 0) > 0:
                return symbol
    return None


def _bounce(fig: _Figure) -> None:
    """The surface, the ball placed or falling onto it, its incoming velocity or drop (see the module)."""
    scene = fig.scene
    event = bounce_off_surface(scene)
    plane = scene.surfaces[event.to]
    ball = scene.bodies[event.body]
    radius = ball.sizes.get("radius", sp.Integer(0))
    center = sp.Matrix(ball.at)
    normal = plane.normal
    gap = sp.simplify(plane.gap(center, radius))
    if fig.num(gap, -1) < -1e-9 or (fig.num(gap, 0) > 1e-9 and given_motion(scene, event.body) is not None):
        raise Undrawable("a ball that strikes the surface from elsewhere than straight below it at rest")
    hit = center - sp.Matrix([0, gap / normal[1]]) - radius * normal  # the point struck: it falls straight down
    floors = [value for s in scene.states.values() if s.when and not s.rate and s.when[0] == event.body and s.when[1] == "y"
              for value in (s.when[2] - radius,) if fig.num(value, 0) < fig.num(hit[1], 0)]
    floor = min(floors, key=lambda value: fig.num(value, 0)) if floors else None
    heights = [fig.num(center[1] - hit[1], 0)] + ([fig.num(hit[1] - floor, 0)] if floor is not None else [])
    scale = DROP / max(sum(heights), 1e-9)
    size = SPHERE if radius != 0 else BALL
    down = _norm((fig.num(plane.down[0], 1), fig.num(plane.down[1], 0)))
    n = _norm((fig.num(normal[0], 0), fig.num(normal[1], 1)))
    struck = (0.0, 0.0)
    ball_at = _add(struck, n, size) if fig.num(gap, 0) <= 1e-9 else (0.0, heights[0] * scale)
    rises = -1 if down[0] > 0 else 1  # the side the surface rises to: the dimensions go there
    back = _surface(fig, plane, struck, down, floor, heights, scale)
    ruler = (min if rises < 0 else max)(ball_at[0] + rises * size, back) + rises * 0.35
    if ball.shape == "point":
        fig.add(f"\\shade[ball color=gray!60] {_pt(ball_at)} circle ({_f(size)}); \\draw {_pt(ball_at)} circle ({_f(size)});")
    else:
        fig.body(ball, ball_at, size)
    fig.add(f"\\fill[red!70!black] {_pt(struck)} circle (0.04);")
    motion = given_motion(scene, event.body)
    away = (1, 0) if (motion is None and rises < 0) or (motion is not None and fig.num(motion.velocity[0], 0) >= 0) \
        else (-1, 0)
    _label_mass(fig, ball, _add(ball_at, _norm((away[0], 1)), size + 0.03), (away[0], 1))
    if motion is not None:
        _incoming(fig, motion, normal, ball_at, size)
    elif heights[0] > 1e-9:  # dropped from rest: straight down to the point struck
        fig.line(_add(ball_at, (0, -size)), _add(struck, n, 0.04 / max(n[1], 0.1)), "dashed, gray")
        fig.dimension((ball_at[0], struck[1]), ball_at, fig.tex(center[1] - radius - hit[1]), side=-rises,
                      gap=abs(ball_at[0] - ruler))
    if floor is not None:
        foot = (struck[0], struck[1] - heights[1] * scale)
        fig.dimension(foot, struck, fig.tex(hit[1] - floor), side=-rises, gap=abs(struck[0] - ruler))
    fig.label(_add(_add(struck, down, max(0.45, size + 0.15)), n, 0.04), _add(down, n), _regime(fig, event))
    if scene.gravity is not None:
        top = (APRON + 0.5, heights[0] * scale if motion is None else 2 * size + 0.9)
        fig.arrow(top, (0, -0.7), "force", "$\\vec g$", (1, 0))


def _surface(fig: _Figure, plane: Plane, struck, down, floor, heights, scale: float) -> float:
    """A level plane a hatched floor; an inclined one a fixed wedge down to the floor, its angle
    marked. Returns the x (cm) of its side toward where it rises (a wedge's back)."""
    if abs(down[1]) < 1e-9:
        fig.ground(struck[0] - APRON, struck[0] + APRON, struck[1])
        return struck[0]
    foot_drop = heights[1] * scale if floor is not None else 1.2
    run = foot_drop / -down[1]  # along the face, from the point struck to the foot
    top, foot = _add(struck, down, -_clamp(run, 0.8, APRON)), _add(struck, down, run)
    corner = (top[0], foot[1])
    beyond = _add(foot, (1 if down[0] > 0 else -1, 0), APRON)
    fig.add(f"\\draw[fill=gray!10] {_pt(top)} -- {_pt(foot)} -- {_pt(corner)} -- cycle;")
    fig.ground(min(corner[0], beyond[0]) - 0.2, max(corner[0], beyond[0]), foot[1])
    angle = math.degrees(math.atan2(-down[1], abs(down[0])))
    start, end = (180 - angle, 180) if down[0] > 0 else (0, angle)
    radius = min(0.7, 0.45 * math.hypot(foot[0] - corner[0], foot[1] - corner[1]))
    fig.arc(foot, radius, start, end, fig.tex(plane.angle))
    return corner[0]


def _incoming(fig: _Figure, motion, normal, ball_at, size: float) -> None:
    """The velocity it strikes with, an arrow onto the ball, its angle to the normal marked when a parameter names it."""
    velocity = sp.Matrix(motion.velocity)
    along = _norm((fig.num(velocity[0], 0), fig.num(velocity[1], -1)))
    tip = _add(ball_at, along, -size - 0.06)
    start = _add(tip, along, -1.0)
    fig.arrow(start, _scale_vec(along, 1.0), "velocity")
    fig.label(start, _scale_vec(along, -1), fig.m(sp.simplify(sp.sqrt(velocity.dot(velocity)))))
    angle = _named_angle(fig, velocity, -normal)
    if angle is None:
        return
    n = _norm((fig.num(normal[0], 0), fig.num(normal[1], 1)))
    fig.line(ball_at, _add(ball_at, n, size + 1.0), "dashed, gray")
    reach = size + 0.6
    back, up = _degrees(_scale_vec(along, -1)), _degrees(n)
    fig.arc(ball_at, reach, min(back, up), max(back, up), fig.tex(angle))
