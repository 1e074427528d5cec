r"""The 3D slices drawn in the oblique projection (`derive.publishing.figure.oblique`), omega and L from their derivations.

A body in bearings, on a fixed point (a top, a gyroscope), rolling on its edge (a coin on its circle)
or turning freely is drawn as a solid with its own axes (x', y', z'), and its angular velocity
omega (blue, "velocity") and angular momentum L (green) as arrows, each labelled. Their directions
are the derivation's vectors at the middle of the parameter ranges (a size or angle the file leaves
open at the value the figure draws it at); their lengths are not to scale (L and omega have
different units). Each figure turns its derivation's frame so that omega and L lie in the
page's true-shape plane where they can: the drawn angle between them is then the true one.

- bearings: L = I·omega about the center of mass by `derive.mechanics.bearings` (Newton–Euler),
  omega along the shaft; the shaft, its rate, the bearings A and B, the tilt, the weight;
- a fixed point: omega = spin e3 + Omega z and L about the point by `derive.mechanics.fixed_point`
  in steady precession at the slow rate, L's parts along the axis and across it, the precession
  axis and its rate, the tilt, the weight, the floor (a post for a level axle);
- rolling on its edge: omega and L about the center by `derive.mechanics.rolling_coin` in the
  steady motion, the contact point P, the circle it traces on the floor and its axis, the lean, the
  center's velocity; upright rolling: the coin on the floor, omega along its axle;
- free rotation: L up the page, the symmetry axis and omega in its plane (L = I·omega with the
  moments `derive.mechanics.free_rotation` finds principal), the axis's precession about L.

>>> from derive.language.problem import load
>>> from derive.publishing.figure import tikz
>>> r"{$\vec L$}" in tikz(load("rigid_body_L")) and r"{$\vec\omega$}" in tikz(load("rigid_body_L"))
True
"""
from __future__ import annotations

import math

import sympy as sp

from derive.solution.answers import Solution
from derive.publishing.figure.canvas import _clamp, _f, _Figure, _pt
from derive.publishing.figure.oblique import Oblique, along, page, silhouette
from derive.publishing.figure.drawn_view import Undrawable
from derive.mechanics import bearings, fixed_point, free_rotation, rolling_coin
from derive.model.solid_scene import own_axis

OMEGA_LABEL, MOMENTUM_LABEL = r"$\vec\omega$", r"$\vec L$"
OMEGA_STYLE, MOMENTUM_STYLE = "velocity", "very thick, ->, green!40!black"


def numbers(fig: _Figure, matrix, fixed: dict | None = None) -> tuple[float, ...]:
    """A vector's components at the middle of the ranges, open symbols at `fixed`; Undrawable where
    one does not evaluate to a real number."""
    values = []
    for component in sp.Matrix(matrix):
        value = component.xreplace(fixed or {}).subs(fig.values)
        number = complex(sp.N(value)) if not value.free_symbols else None
        if number is None or abs(number.imag) > 1e-9 * (1 + abs(number.real)):
            raise Undrawable(f"{component} does not evaluate")
        values.append(number.real)
    return tuple(values)


def _columns(fig: _Figure, matrix, fixed=None):
    matrix = sp.Matrix(matrix)
    return tuple(numbers(fig, matrix[:, k], fixed) for k in range(matrix.shape[1]))


def _scaled(vector, k: float):
    return tuple(k * c for c in vector)


def _vectors(view: Oblique, at, omega, momentum, lengths=(1.7, 2.2), beside=None) -> None:
    """omega and L (derivation's frame) from a world point, at fixed lengths; omega's label on the
    page side `beside` of its tip. Where the two lie within 15 degrees on the page, each label goes
    on the side away from the other arrow (a gyroscope's omega and L: their labels, the spin's and
    the body's axes would otherwise meet at the tips)."""
    omega, momentum = view.world(omega), view.world(momentum)
    runs = [page(v) for v in (omega, momentum)]
    turn = runs[0][0] * runs[1][1] - runs[0][1] * runs[1][0]  # > 0: L lies counter-clockwise of omega
    apart = math.degrees(abs(math.atan2(turn, runs[0][0] * runs[1][0] + runs[0][1] * runs[1][1])))
    away = None
    if beside is None and apart < 15:
        side = -1.0 if turn > 0 else 1.0  # omega's label clockwise of it where L is counter-clockwise
        beside = (-side * runs[0][1], side * runs[0][0])
        across = (side * runs[1][1], -side * runs[1][0])
        away = (runs[1][0] + across[0], runs[1][1] + across[1])  # beyond L's tip, on its other side
    view.arrow(at, omega, lengths[0], OMEGA_STYLE, OMEGA_LABEL, toward=beside)
    view.arrow(at, momentum, lengths[1], MOMENTUM_STYLE, MOMENTUM_LABEL, toward=away)


def _bearings(fig: _Figure) -> None:
    """A body turning about its shaft, tilted from it. Without gravity the shaft is up the page
    (N.z) and the body's own axis leans to the right in the page (N's xz plane): omega and L are in
    the page, at their true angle. Under gravity the page is the vertical plane of the shaft (N.z at
    its incline to the right, N.y up, N.x into the page), with the weight."""
    name, rotation = next(iter(fig.scene.bearings.items()))
    body = fig.scene.bodies[name]
    weighed = fig.scene.gravity is not None
    axis = own_axis(body.shape)
    found = Solution(fig.problem).bearing_motion(name, "newton_euler")
    momentum = numbers(fig, found["angular_momentum"])
    if weighed:
        c, s = math.cos(fig.num(rotation.incline, 0.0)), math.sin(fig.num(rotation.incline, 0.0))
        view = Oblique(fig, ((0, -s, c), (1, 0, 0), (0, c, s)))
    else:  # the instant turned about the shaft (the motion is steady) to bring L into the page
        turn = math.atan2(momentum[1], momentum[0]) if abs(momentum[0]) + abs(momentum[1]) > 1e-12 else 0.0
        c, s = math.cos(turn), math.sin(turn)
        view = Oblique(fig, ((c, s, 0), (-s, c, 0), (0, 0, 1)))
    rate = fig.num(rotation.rate, 1.0)
    omega = (0.0, fig.num(rotation.turned, 0.0), rate)  # the shaft's own turn about N.y, where it is turned
    if body.composite is not None:
        reach = fig.num(body.composite.extent(), 1.0)
    else:  # the drawn half-size, 1.6, is a rod's half-length, else the largest size
        reach = max((fig.num(v, 1.0) / (2 if body.shape == "rod" else 1) for v in body.sizes.values()), default=1.0)
    scale = 1.6 / reach if reach > 0 else 1.0
    offset = numbers(fig, bearings.center_offset(rotation.tilt, rotation.roll, axis, rotation.through))
    cm = view.world(_scaled(offset, scale))
    shaft = view.world((0, 0, 1))
    view.line(_scaled(shaft, -2), _scaled(shaft, 2.2), "axis, ->")
    view.turning(_scaled(shaft, 1.95), shaft, 0.35, fig.m(rotation.rate))
    if rotation.turned != 0:  # the shaft turned about N.y, drawn as an axis of its own
        turning = view.world((0, 1, 0))
        view.line(_scaled(turning, -1.8), _scaled(turning, 2.0), "axis, ->")
        view.turning(_scaled(turning, 1.75), turning, 0.3, fig.m(rotation.turned))
    if any(abs(c) > 1e-9 for c in cm):
        view.line((0, 0, 0), cm, "thin, dashed")
        view.dot((0, 0, 0))
    own = [view.world(column) for column in _columns(fig, bearings.own_axes(rotation.tilt, rotation.roll, axis))]
    view.solid(body, cm, own, scale)
    view.axes(cm, own)
    if weighed:
        fig.gravity_arrow(page(cm), body)
    elif fig.num(rotation.tilt, 0.0) != 0 and abs(own["xyz".index(axis)][1]) < 1e-9:  # the own axis in the page
        leaning = page(own["xyz".index(axis)])
        direction = math.degrees(math.atan2(leaning[1], leaning[0]))
        fig.arc(page(cm), 0.8, direction, 90, fig.tex(rotation.tilt), label_radius=0.9)
    across = page(view.world((0, 1, 0))) if weighed else (1.0, 0.0)  # on the page, across the shaft (N.y, N.x)
    _vectors(view, cm, omega, momentum, (1.4, 2.2), beside=(-across[0], -across[1]))  # away from A and B's
    if rotation.apart is not None:  # over the body, inside the rate's arrow
        half = _clamp(fig.num(rotation.apart, 1.0) * scale / 2, 1.0, 1.5)
        turn = math.degrees(math.atan2(*reversed(page(shaft))))
        for label, sign in (("A", 1), ("B", -1)):
            at = page(_scaled(shaft, sign * half))
            fig.add(f"\\fill[gray!60, draw=black, rotate around={{{_f(turn)}:{_pt(at)}}}] "
                    f"{_pt((at[0] - 0.12, at[1] - 0.2))} rectangle {_pt((at[0] + 0.12, at[1] + 0.2))};")
            fig.label((at[0] + 0.25 * across[0], at[1] + 0.25 * across[1]), across, f"${label}$")


def _top_state(fig: _Figure, name: str, top) -> tuple[dict, float]:
    """The fixed point's steady motion as drawn: (open symbols' values, the precession rate). An
    open tilt is drawn at 0.5 rad, or upright where only a sleeping top is asked (then an open
    spin is its least spin); a moment left open (it cancels from the answers) at zero; the rate
    is the slow steady precession's, its fast-top limit where only that is asked (none upright)."""
    point = fig.scene.pivot_points[name]
    fixed = {s: sp.Integer(0) for s in top[0].free_symbols - fig.values.keys()}
    if any(a.quantity.kind == "conical" for a in fig.problem.asks.values()):  # turning as one in a cone
        rate = math.sqrt(numbers(fig, [fixed_point.conical_squared(*top, point.tilt, "lagrange")], fixed)[0])
        if point.spin.free_symbols - fig.values.keys():
            fixed[point.spin] = sp.Float(rate) * sp.cos(point.tilt)
        return fixed, rate
    asked = {a.quantity.detail for a in fig.problem.asks.values() if a.quantity.kind == "pivot_point"}
    sleeping = asked <= {"sleeping.min_spin"}
    if point.tilt.free_symbols - fig.values.keys():
        fixed[point.tilt] = sp.Integer(0) if sleeping else sp.Rational(1, 2)
    if point.spin.free_symbols - fig.values.keys():
        fixed[point.spin] = fixed_point.min_spin(*top, "lagrange")
    tilt = numbers(fig, [point.tilt], fixed)[0]
    if tilt == 0:
        return fixed, 0.0
    slow, _ = fixed_point.roots(*top, point.spin, point.tilt)
    if asked & {"precession.slow", "precession.fast", "nutation.frequency"} or "precession.fast_top" not in asked:
        return fixed, numbers(fig, [slow], fixed)[0]
    return fixed, numbers(fig, [fixed_point.fast_top(slow, point.spin, point.tilt)], fixed)[0]


def _pivot_point(fig: _Figure) -> None:
    """A body on a fixed point (the pivot at the origin, N.z up), its axis e3 leaning to the right
    in the page by its tilt, in steady precession: omega, L about the point and L's parts along the
    axis and across it, all in the page; the precession axis and rate, the spin, mg."""
    name, point = next(iter(fig.scene.pivot_points.items()))
    body = fig.scene.bodies[name]
    try:
        top = Solution(fig.problem).standing_top(name)
        fixed, rate = _top_state(fig, name, top)
    except fixed_point.NotSymmetric as error:
        raise Undrawable(str(error)) from None
    tensor, mass, _, distance = top
    found = fixed_point.steady_vectors(tensor, mass, distance, point.spin, point.tilt, sp.Float(rate))
    omega, momentum = numbers(fig, found["omega"], fixed), numbers(fig, found["momentum"], fixed)
    axes = _columns(fig, found["axes"], fixed)
    view = Oblique(fig)
    e3, tilt = axes[2], numbers(fig, [point.tilt], fixed)[0]
    level = abs(tilt - math.pi / 2) < 1e-9
    floor = -1.6 if level else 0.0
    if level:  # a post under the pivot
        fig.line((0, floor), (0, 0), "line width=1.5pt")
    if point.hangs:  # hung from a support above the point
        fig.support((0, 0), True)
    else:
        fig.ground(-1.2, 1.6, floor)
    view.line((0, 0, floor), (0, 0, 3.4), "axis")
    cm = _scaled(e3, 2.0)
    size = _clamp(fig.num(body.sizes.get("radius"), 0.0) * 2.0 / fig.num(distance, 1.0), 0.5, 1.0) \
        if "radius" in body.sizes else 0.75
    if body.shape in ("disk", "ring", "annulus", "cylinder"):
        fig.line(page((0, 0, 0)), page(_scaled(e3, 2.4)), "line width=1.5pt")
        view.circle(cm, e3, size, "line width=1.8pt" if body.shape == "ring" else "body")
    elif body.shape == "rod":  # a bar from the point through its center
        fig.line(page((0, 0, 0)), page(_scaled(e3, 4.0)), "line width=3pt, line cap=round, gray!60!black")
    elif body.shape == "cone":
        base = _scaled(e3, 2.0 * 4 / 3)
        view.circle(base, e3, size)
        for side in silhouette(base, e3, size, (0, 0, 0)):
            view.line(side, (0, 0, 0))
    else:  # a top: a cone from the tip to a rim about the center, a stem beyond
        view.circle(cm, e3, size)
        for side in silhouette(cm, e3, size, (0, 0, 0)):
            view.line(side, (0, 0, 0))
        fig.line(page(cm), page(_scaled(e3, 3.0)), "line width=1.5pt")
    fig.line(page((0, 0, 0)), page(cm), "thin, dashed")
    fig.add(f"\\fill {_pt(page(cm))} circle (0.05); \\fill (0,0) circle (0.05);")
    across = (e3[2], -e3[0])  # on the page, to the right of the axis
    label_at = page(_scaled(e3, 1.4))
    fig.label((label_at[0] - 0.08 * across[0], label_at[1] - 0.08 * across[1]), (-across[0], -across[1]),
              fig.m(distance))
    if tilt > 0:
        fig.arc((0, 0), 0.7, 90 - math.degrees(tilt), 90, fig.tex(point.tilt), label_radius=0.75)
    fig.gravity_arrow(page(cm), body, 1.1, toward=(1, 0))
    view.axes(cm, axes, 0.8)
    view.turning(_scaled(e3, 2.6), e3, 0.25, fig.m(point.spin) if point.spin not in fixed else None)
    if rate != 0:
        precession = (fig.ask_symbol("pivot_point", name, "precession.slow")
                      or fig.ask_symbol("pivot_point", name) or fig.ask_symbol("conical", name) or r"\Omega")
        view.turning((0, 0, 3.1), (0, 0, 1), 0.45, f"${precession}$")
    _vectors(view, (0, 0, 0), omega, momentum, (3.0, 3.5))
    along = sum(m * e for m, e in zip(momentum, e3))
    length = math.sqrt(sum(c * c for c in momentum))
    axial = _scaled(e3, 3.5 * along / length)
    rest = tuple(3.5 * m / length - a for m, a in zip(momentum, axial))
    if math.sqrt(sum(c * c for c in rest)) > 0.15:  # L's part from the precession, where it shows
        if abs(along) > 0.05 * length:  # and along the axis (a thin rod has none)
            view.arrow((0, 0, 0), axial, 3.5 * abs(along) / length, "->, thin, dashed, green!40!black")
        view.arrow(axial, rest, math.sqrt(sum(c * c for c in rest)), "->, thin, dashed, green!40!black")


def _rolls_on_edge(fig: _Figure) -> None:
    """A body rolling on its edge. In a steady motion on a circle: the page is the vertical plane
    through the circle's axis and the contact point P (N.y to the right, so the axis at the left, the
    heading N.x out of the page), the coin leaning toward the axis by its tilt, the circle P traces on
    the floor, omega and L about the center in the page, the center's velocity out of it. Upright:
    the coin in the page rolling to the right, omega and L along its axle into the page."""
    name, coin = next(iter(fig.scene.rolls_on_edge.items()))
    body = fig.scene.bodies[name]
    I1, I3, mass, g, radius = Solution(fig.problem).rolling_coin(name)
    speed_symbol = fig.ask_symbol("rolls_on_edge", name, "steady.speed") or fig.ask_symbol(
        "rolls_on_edge", name, "upright.min_speed") or "v"
    if coin.tilt is None:
        view = Oblique(fig)
        found = rolling_coin.upright_vectors(I1, I3, mass, g, radius)
        fixed = {s: sp.Integer(1) for s in radius.free_symbols - fig.values.keys()}
        center, scale = (0.0, 0.0, 1.0), 1.0
    else:
        view = Oblique(fig, ((0, 1, 0), (-1, 0, 0), (0, 0, 1)))
        ratio = fig.num(coin.circle / coin.radius, 3.0)
        drawn = _clamp(ratio, 1.6, 2.4)
        fixed = {s: coin.circle / sp.Float(drawn) for s in radius.free_symbols - fig.values.keys()}
        found = rolling_coin.steady_vectors(I1, I3, mass, g, radius, coin.tilt, coin.circle)
        scale = 1.0 / numbers(fig, [radius], fixed)[0]
        center = view.world(_scaled(numbers(fig, found["center"], fixed), scale))
    omega, momentum = numbers(fig, found["omega"], fixed), numbers(fig, found["momentum"], fixed)
    axes = [view.world(c) for c in _columns(fig, found["axes"], fixed)]
    velocity = view.world(numbers(fig, found["velocity"], fixed))
    if coin.tilt is None:
        fig.ground(-1.6, 1.6)
    else:
        middle = _scaled(view.world(numbers(fig, found["axis"], fixed)), drawn / numbers(fig, [coin.circle])[0])
        view.circle(middle, (0, 0, 1), math.hypot(middle[0], middle[1]), "thin, dashed", start=(1, 0, 0))
        view.line(middle, (middle[0], middle[1], 2.6), "axis")
        fig.dimension(page(middle), (0, 0), fig.tex(coin.circle), side=-1, gap=0.45)
        rate = fig.ask_symbol("rolls_on_edge", name, "steady.precession") or r"\Omega"
        view.turning((middle[0], middle[1], 2.4), (0, 0, 1), 0.4, f"${rate}$")
        fig.line((0, 0), (0, 1.6), "thin, dashed")
        fig.arc((0, 0), 1.35, 90, 90 + math.degrees(numbers(fig, [coin.tilt])[0]), fig.tex(coin.tilt),
                label_radius=1.4)
    view.circle(center, axes[1], 1.0, "line width=1.8pt" if body.shape == "ring" else "body")
    fig.add(f"\\fill {_pt(page(center))} circle (0.04); \\fill (0,0) circle (0.04);")
    fig.label((0.1, -0.05), (1, -1), "$P$")
    fig.line(page(center), page(along(center, axes[2], -1.0)), "thin")
    fig.label(page(along(center, axes[2], -0.5)), (1, 0), fig.m(coin.radius))
    view.axes(center, axes, 0.7)
    view.arrow(center, velocity, 1.2, "velocity, dashed", f"${speed_symbol}$")
    fig.gravity_arrow(page(center), body, 0.8, toward=(1 if coin.tilt is not None else -1, 0))
    _vectors(view, center, omega, momentum, (1.5, 1.9))


def _free_rotation(fig: _Figure) -> None:
    """A body turning freely, asked of its symmetry axis: L up the page, the axis and omega in the
    page at their angles from it (omega beyond L for a flat body, I3 > I1, between the axis and L for
    a long one), the body about its axis, the axis's precession about L. Any other body in free
    rotation: the body with its own axes and its spin about z."""
    name, free = next(iter(fig.scene.free_rotations.items()))
    body = fig.scene.bodies[name]
    moments = Solution(fig.problem).free_moments(name)
    try:
        transverse, axial, _ = free_rotation.symmetric(moments)
    except free_rotation.NotModelled:
        transverse = None
    own = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
    if transverse is None or not any(a.quantity.kind == "free_rotation" and a.quantity.detail in
                                     free_rotation.SYMMETRIC for a in fig.problem.asks.values()):
        view = Oblique(fig)
        _free_solid(view, body, own, moments)
        view.axes((0, 0, 0), own, 1.6)
        view.turning((0, 0, 1.9), (0, 0, 1), 0.4, fig.m(free.spin))
        return
    fixed = {s: free.spin * sp.Rational(2, 5) for s in free.across.free_symbols - fig.values.keys()}  # open: drawn at
    omega = numbers(fig, (free.across, 0, free.spin), fixed)  # 0.4 of the spin (it cancels from the answers)
    momentum = numbers(fig, sp.diag(transverse, transverse, axial) * sp.Matrix(omega))
    lean = math.atan2(momentum[0], momentum[2])  # the axis from L
    view = Oblique(fig, ((math.cos(lean), 0, -math.sin(lean)), (0, 1, 0), (math.sin(lean), 0, math.cos(lean))))
    axes = [view.world(e) for e in own]
    _free_solid(view, body, axes, moments)
    view.line(_scaled(axes[2], -1), _scaled(axes[2], 2.4), "axis")
    fig.add("\\fill (0,0) circle (0.05);")
    view.axes((0, 0, 0), axes[:2], 1.0)
    _vectors(view, (0, 0, 0), omega, momentum, (2.1, 2.6))
    axis_degrees = math.degrees(math.atan2(*reversed(page(axes[2]))))
    fig.arc((0, 0), 1.5, 90, axis_degrees, fig.ask_symbol("free_rotation", name, "angle_L_axis"), label_radius=1.55)
    if abs(lean) > 1e-6:
        top = _scaled(axes[2], 2.4)
        view.circle((0, 0, top[2]), (0, 0, 1), abs(top[0]), "dashed, gray", start=(-1, 0, 0))
        view.circle((0, 0, top[2]), (0, 0, 1), abs(top[0]), "->, thick", start=(-1, 0, 0), sweep=60)
        precession = fig.ask_symbol("free_rotation", name, "free_precession.space")
        view.label((top[0] - 0.1, 0, top[2]), (-1, 0, 0), f"${precession}$" if precession else None)


def _free_solid(view: Oblique, body, axes, moments) -> None:
    """The freely turning body: its shape to scale (largest half-size 1.3 cm), a custom body flat
    (a disk, I3 > I1) or long (a rod) by its principal moments."""
    fig = view.fig
    if body.shape == "custom":
        flat = fig.num(moments[2] - moments[0], 0.0) >= 0
        view.circle((0, 0, 0), axes[2], 1.3 if flat else 0.3, "body")
        if not flat:
            fig.bar(page(_scaled(axes[2], -1.3)), page(_scaled(axes[2], 1.3)))
        return
    if body.composite is not None:
        reach = fig.num(body.composite.extent(), 1.0)
    else:
        reach = max((fig.num(v, 1.0) / (2 if body.shape in ("rod", "plate", "box") or k == "height" else 1)
                     for k, v in body.sizes.items()), default=1.0)
    view.solid(body, (0, 0, 0), axes, 1.3 / reach if reach > 0 else 1.0)
