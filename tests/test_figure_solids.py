"""The 3D slices' figures (derive.publishing.figure.solids in the oblique projection of derive.publishing.figure.oblique):
the omega and L arrows read back from the TikZ point along the derived vectors' projections, the
angle between them is the derived one, and every 3D file of the library and the textbook set has a
figure that compiles."""
from __future__ import annotations

import math
import re
from pathlib import Path

import pytest
import sympy as sp

from conftest import textbook
from derive.publishing import export, figure, render
from derive.solution.answers import Solution
from derive.publishing.figure import label_places
from derive.publishing.figure.canvas import _Figure
from derive.publishing.figure.oblique import page
from derive.language.problem import load

ROOT = Path(__file__).resolve().parent.parent
SOLIDS = ["rigid_body_L", "top_precession", "top_precession_exact"] + [
    textbook(name) for name in (
        "rod_tilted_on_shaft", "disk_tilted_on_shaft", "dumbbell_tilted_shaft", "rotor_static_imbalance",
        "shaft_dynamic_imbalance", "gyroscope_wheel", "sleeping_cone", "top_two_precessions", "coin_rolls_in_circle",
        "disk_rolls_upright", "hoop_rolls_upright", "earth_free_precession", "football_free_precession",
        "tennis_racket", "thrown_plate_wobble")]
ARROW = re.compile(r"^\\draw\[([^\]]*)\] \(([-\d.]+),([-\d.]+)\) -- \(([-\d.]+),([-\d.]+)\)"
                   r"(?: node\[anchor=([a-z ]+), inner sep=1.5pt\] \{(.*)\})?;$", re.M)
NODE = re.compile(r"^\\node\[anchor=([a-z ]+), inner sep=1.5pt[^\]]*\] at \(([-\d.]+),([-\d.]+)\) \{(.*)\};$", re.M)


def labelled(drawn: str) -> dict[str, tuple[tuple[float, float], str]]:
    """Each labelled straight arrow's run on the page and its label's anchor, by its label: written on
    the arrow, or moved off it to one of the places derive.publishing.figure.label_places offers
    beside the arrow's tip."""
    found, tips = {}, []
    for style, x0, y0, x1, y1, anchor, label in ARROW.findall(drawn):
        run = (float(x1) - float(x0), float(y1) - float(y0))
        if label:
            found[label] = (run, anchor)
        tips.append(((float(x1), float(y1)), run))
    for anchor, x, y, label in NODE.findall(drawn):
        for tip, run in tips:
            offered = label_places.candidates(label_places.Label(tip, "west", label))
            if any(a == anchor and abs(p[0] - float(x)) <= 0.011 and abs(p[1] - float(y)) <= 0.011 for _, p, a in offered):
                found.setdefault(label, (run, anchor))
    return found


def arrows(drawn: str) -> dict[str, tuple[float, float]]:
    """Each labelled straight arrow's run on the page, by its label."""
    return {label: run for label, (run, _) in labelled(drawn).items()}


def degrees(u, v) -> float:
    return math.degrees(math.atan2(abs(u[0] * v[1] - u[1] * v[0]), u[0] * v[0] + u[1] * v[1]))


def middle(problem, expression) -> float:
    return float(sp.N(sp.sympify(expression).subs(_Figure(problem).values)))


def at_middle(problem, vector) -> tuple[float, ...]:
    return tuple(middle(problem, c) for c in vector)


def test_a_tilted_rod_on_bearings_draws_l_across_the_rod_at_the_derived_angle_from_omega():
    """Kleppner & Kolenkow, ch. 7, the rotating skew rod: L is normal to the rod, at pi/2 - alpha
    from omega; the drawn arrows make the derived angle (acos(sin(alpha))), omega up the shaft."""
    for source in ("rigid_body_L", textbook("rod_tilted_on_shaft")):
        problem = load(source)
        drawn = arrows(figure.tikz(problem))
        omega, momentum = drawn[r"$\vec\omega$"], drawn[r"$\vec L$"]
        assert omega[0] == 0 and omega[1] > 0  # along the shaft, up the page
        angle = middle(problem, Solution(problem).expression("angle"))
        alpha = middle(problem, problem.parameters["alpha"].symbol)
        assert math.isclose(math.radians(degrees(omega, momentum)), angle, abs_tol=math.radians(0.5))
        assert math.isclose(angle, math.pi / 2 - alpha, rel_tol=1e-12)
        bar = re.search(r"line cap=round, gray!60!black\] \(([-\d.]+),([-\d.]+)\) -- \(([-\d.]+),([-\d.]+)\)",
                        figure.tikz(problem)).groups()
        rod = (float(bar[2]) - float(bar[0]), float(bar[3]) - float(bar[1]))
        assert math.isclose(degrees(rod, momentum), 90, abs_tol=0.5)  # L normal to the rod


@pytest.mark.parametrize("name", ["disk_tilted_on_shaft", "dumbbell_tilted_shaft", "shaft_dynamic_imbalance",
                                  "rotor_static_imbalance"])
def test_bearings_arrows_are_the_derived_l_and_omega_projected(name):
    """L by the Lagrange route (the figure draws Newton–Euler's), turned as the figure turns the instant
    (about the shaft to bring L into the page; under gravity the shaft to the right, N.y up, N.x into
    the page), projected, against the drawn arrow; omega along the shaft."""
    problem = load(textbook(name))
    body = next(iter(problem.scene.bearings))
    momentum = at_middle(problem, Solution(problem).bearing_motion(body, "lagrange")["angular_momentum"])
    if problem.scene.gravity is not None:  # a level shaft
        world, shaft = (momentum[2], momentum[0], momentum[1]), (1, 0, 0)
    else:
        world, shaft = (math.hypot(momentum[0], momentum[1]), 0.0, momentum[2]), (0, 0, 1)
    drawn = arrows(figure.tikz(problem))
    assert degrees(drawn[r"$\vec L$"], page(world)) < 0.5
    assert degrees(drawn[r"$\vec\omega$"], page(shaft)) < 0.5
    if problem.scene.gravity is None:  # L and omega in the page: their true angle
        true = math.degrees(math.acos(momentum[2] / math.sqrt(sum(c * c for c in momentum))))
        assert math.isclose(degrees(drawn[r"$\vec L$"], drawn[r"$\vec\omega$"]), true, abs_tol=0.5)


SLOW_TOP = """id: slow_top
title: A slow top
topic: precession
parameters:
  M: {meaning: mass, unit: kg, value: 0.2}
  R: {meaning: tip to center, unit: m, value: 0.05}
  I3: {meaning: axial moment, unit: kg*m^2, value: 1e-4}
  I1: {meaning: transverse moment about the tip, unit: kg*m^2, value: 3e-4}
  theta: {meaning: tilt, unit: rad, value: 1}
  w: {meaning: spin, unit: rad/s, value: 90}
  g: {meaning: gravity, unit: m/s^2, value: 9.81}
scene:
  bodies:
    top:
      shape: custom
      mass: M
      inertia: {axial: I3, transverse: I1}
      inertia_about: pivot
      pivot_point: {at: R, tilt: theta, spin: w}
  loads:
    - gravity: g
ask:
  slow: {meaning: slow precession, of: top.precession.slow, unit: rad/s}
question: A top spins slowly.
"""


@pytest.mark.parametrize("name", ["top_two_precessions", "gyroscope_wheel", "slow_top"])
def test_a_tops_omega_and_l_are_the_steady_precessions_own(name, tmp_path):
    """Taylor, Classical Mechanics, ch. 10: in steady precession at the slow rate Omega (the asked
    answer), omega = Omega z + psi' e3 with omega3 = psi' + Omega cos(theta), and L about the tip is
    I1 (omega's part across e3) + I3 omega3 e3, I1 about the tip: written here by hand, the figure's
    by sympy's RigidBody; both in the page, e3 leaning right by the tilt. A slow top (spun just above
    the least spin of a steady precession) shows L's two parts dashed: along the axis, and the rest
    from its tip to L's."""
    if name == "slow_top":
        (tmp_path / "slow_top.yaml").write_text(SLOW_TOP)
        problem = load(tmp_path / "slow_top.yaml")
    else:
        problem = load(textbook(name))
    solution = Solution(problem)
    rate = middle(problem, solution.expression("Omega" if name == "gyroscope_wheel" else "slow"))
    point = next(iter(problem.scene.pivot_points.values()))
    tensor, mass, _, distance = solution.standing_top(next(iter(problem.scene.pivot_points)))
    I1 = middle(problem, tensor[0, 0] + mass * distance**2)
    I3, spin, tilt = (middle(problem, e) for e in (tensor[2, 2], point.spin, point.tilt))
    axis = (math.sin(tilt), 0.0, math.cos(tilt))
    omega = tuple(rate * z + (spin - rate * math.cos(tilt)) * e for z, e in zip((0, 0, 1), axis))
    along = sum(w * e for w, e in zip(omega, axis))
    momentum = tuple(I1 * (w - along * e) + I3 * along * e for w, e in zip(omega, axis))
    drawn = arrows(figure.tikz(problem))
    assert degrees(drawn[r"$\vec\omega$"], page(omega)) < 0.5
    assert degrees(drawn[r"$\vec L$"], page(momentum)) < 0.5
    parts = re.findall(r"\\draw\[->, thin, dashed, green!40!black\] \(([-\d.]+),([-\d.]+)\) -- \(([-\d.]+),([-\d.]+)\);",
                       figure.tikz(problem))
    assert len(parts) == (2 if name == "slow_top" else 0)  # a fast top's L is along its axis within 0.15 cm
    if parts:
        (x0, y0, x1, y1), (x2, y2, x3, y3) = [tuple(map(float, p)) for p in parts]
        assert (x0, y0) == (0, 0) and (x1, y1) == (x2, y2) and degrees((x1, y1), page(axis)) < 0.5
        tip = re.search(r"green!40!black\] \(0,0\) -- \(([-\d.]+),([-\d.]+)\) node", figure.tikz(problem)).groups()
        assert (x3, y3) == tuple(map(float, tip))


def test_a_rolling_coins_omega_and_l_follow_its_steady_spin_and_precession(tmp_path):
    """The coin's steady motion (Kleppner & Kolenkow, ch. 8): omega = Omega z + w s, s the symmetry
    axis (across the coin, tilted up by the tilt away from the circle's axis), its part along s
    minus the asked spin; L about the center I1 omega + (I3 - I1)(omega.s) s, I3 = 2 I1 for a disk.
    The page is the vertical plane through the axis and the contact point, the axis to the left."""
    path = tmp_path / "coin.yaml"
    path.write_text(COIN)
    problem = load(path)
    solution = Solution(problem)
    rate, spin = (middle(problem, solution.expression(n)) for n in ("W", "w"))
    theta = 0.3
    s = (math.cos(theta), 0.0, math.sin(theta))  # the lean frame's y: away from the axis, which is at the left
    c = -spin - rate * s[2]  # omega . s = -spin
    omega = tuple(rate * z + c * e for z, e in zip((0, 0, 1), s))
    along = sum(w * e for w, e in zip(omega, s))
    momentum = tuple(w + along * e for w, e in zip(omega, s))  # I1 = 1, I3 = 2
    drawn = arrows(figure.tikz(problem))
    assert degrees(drawn[r"$\vec\omega$"], page(omega)) < 0.5
    assert degrees(drawn[r"$\vec L$"], page(momentum)) < 0.5
    assert "{$P$}" in figure.tikz(problem)  # the contact point


COIN = """id: coin
title: A coin
topic: precession
parameters:
  m: {meaning: mass, unit: kg, value: 0.01}
  a: {meaning: radius, unit: m, value: 0.05}
  R: {meaning: circle, unit: m, value: 0.11}
  g: {meaning: gravity, unit: m/s^2, value: 9.81}
scene:
  bodies:
    coin: {shape: disk, mass: m, radius: a, rolls_on_edge: {tilt: 0.3, circle: R}}
  loads:
    - gravity: g
ask:
  W: {meaning: precession, of: coin.steady.precession, unit: rad/s}
  w: {meaning: spin, of: coin.steady.spin, unit: rad/s}
question: A coin rolls on a circle of {{ R }}.
"""


def test_an_upright_coin_spins_about_its_axle_into_the_page():
    problem = load(textbook("disk_rolls_upright"))
    drawn = arrows(figure.tikz(problem))
    omega, momentum = drawn[r"$\vec\omega$"], drawn[r"$\vec L$"]
    assert degrees(omega, page((0, 1, 0))) < 0.5 and degrees(momentum, page((0, 1, 0))) < 0.5  # rolling to +x
    assert drawn["$v_{\\mathrm{min}}$"][0] > 0 and drawn["$v_{\\mathrm{min}}$"][1] == 0


def test_a_thrown_plates_arrows_make_the_derived_angles_with_its_axis():
    """Taylor §10.8: L up the page, omega and the axis at the derived angles from it, omega beyond L."""
    problem = load(textbook("thrown_plate_wobble"))
    picture = figure.tikz(problem)
    drawn = arrows(picture)
    axis = re.search(r"\\draw\[axis\] \(([-\d.]+),([-\d.]+)\) -- \(([-\d.]+),([-\d.]+)\)", picture).groups()
    axis = (float(axis[2]) - float(axis[0]), float(axis[3]) - float(axis[1]))
    solution = Solution(problem)
    for label, ask in ((r"$\vec L$", "L_axis"), (r"$\vec\omega$", "omega_axis")):
        assert math.isclose(math.radians(degrees(drawn[label], axis)), middle(problem, solution.expression(ask)),
                            abs_tol=math.radians(0.5))
    assert drawn[r"$\vec L$"][0] == 0 and drawn[r"$\vec\omega$"][0] > 0 > axis[0]


def test_every_3d_file_has_a_figure_with_omega_and_l_that_compiles(tmp_path):
    """Each 3D slice of the library and the textbook set: omega and L labelled (the tennis racket's
    three rotations in turn have no single omega: its axes and spin), the same bytes twice, at most
    6.5 cm either way, and one document of them all compiles."""
    drawn = []
    for source in SOLIDS:
        picture = figure.tikz(load(source))
        assert picture is not None and picture == figure.tikz(load(source)), source
        if "tennis_racket" not in str(source):
            assert {r"$\vec\omega$", r"$\vec L$"} <= set(arrows(picture)), source
        assert "$\\scriptstyle x'$" in picture, source  # the body's axes
        points = [(float(x), float(y)) for x, y in re.findall(r"\((-?[\d.]+),(-?[\d.]+)\)", picture)]
        for k in (0, 1):  # the library's figure size (tests/test_figure.py)
            assert max(p[k] for p in points) - min(p[k] for p in points) <= 6.5, source
        drawn.append(picture)
    tex = tmp_path / "figures.tex"
    tex.write_text(render.render("preamble.tex.j2") + "\\begin{document}\n" + "\n\n".join(drawn)
                   + "\n\\end{document}\n", encoding="utf-8")
    assert export.pdf(tex).exists()


@pytest.mark.parametrize("name", ["gyroscope_wheel", "top_precession"])
def test_omega_and_l_close_on_the_page_are_labelled_on_their_far_sides(name):
    """A gyroscope's omega and L lie a degree or two apart on the page: each label goes beyond its
    own arrow on the side away from the other (omega's once sat on L's line, among the spin's and the
    body axes' labels). The side is read from the label's anchor: a node anchored at its north sits
    below the point."""
    problem = load(textbook(name)) if name == "gyroscope_wheel" else load(name)
    drawn = figure.tikz(problem)
    runs = arrows(drawn)
    omega, momentum = runs[r"$\vec\omega$"], runs[r"$\vec L$"]
    assert degrees(omega, momentum) < 15
    ccw = omega[0] * momentum[1] - omega[1] * momentum[0] > 0  # L counter-clockwise of omega
    anchors = {label: anchor for label, (_, anchor) in labelled(drawn).items()}
    directions = {"north": (0, -1), "south": (0, 1), "east": (-1, 0), "west": (1, 0), "north east": (-1, -1),
                  "north west": (1, -1), "south east": (-1, 1), "south west": (1, 1)}  # where the label lies
    for label, run, sign in ((r"$\vec\omega$", omega, -1 if ccw else 1), (r"$\vec L$", momentum, 1 if ccw else -1)):
        lies = directions[anchors[label]]
        side = run[0] * lies[1] - run[1] * lies[0]  # > 0: the label lies counter-clockwise of its arrow
        assert side * sign > 0, (label, anchors[label])
