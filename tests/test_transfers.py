"""A body's contact passing onto another surface (`event: {transfer: BODY, to: SURFACE}`, issue
12's chains from one surface to another): kept speed and spin where the paths are tangent, proved
by both impact routes (every impulse zero), and refused where the body is not at the junction, where
the paths meet at a kink, and where the file names what cannot pass."""

import sympy as sp

from conftest import refused, textbook
from derive.checks import chain_simulation
from derive.solution.answers import Solution
from derive.language.problem import load

LOOP = (textbook("block_ramp_into_loop")).read_text()


def test_a_tangent_transfer_needs_no_impulse_by_either_route_and_keeps_the_velocities():
    solution = Solution(load(str(textbook("block_ramp_into_loop"))))
    before, after = solution.states["entering"].values, solution.states["looping"].values
    assert after == before
    for route in ("lagrange", "newton_euler"):
        impact = solution._impact_by("looping", route)
        assert impact.impulses and all(sp.simplify(j) == 0 for j in impact.impulses.values()), route
        assert all(sp.simplify(v - before[u]) == 0 for u, v in impact.velocities.items()), route
    # after it the block is held by the loop, by the same contact and normal force
    contact = solution.scene_in("top").constraint("block_contact")
    assert contact.surface == "loop" and solution.scene_in("entering").constraint("block_contact").surface == "ramp"
    assert "passes from the ramp onto the loop" in solution.state_heading("looping")


def test_a_rolling_ball_keeps_its_spin_through_the_transfer():
    solution = Solution(load(str(textbook("ball_floor_into_loop"))))
    spin = solution.coordinates.of("ball", "theta").u
    assert solution.states["looping"].values[spin] == solution.states["rolling"].values[spin]
    assert all(sp.simplify(j) == 0 for j in solution._chain.impacts["looping"].impulses.values())


def test_a_ball_rolls_down_a_ramp_and_round_a_loop_as_the_books_and_the_simulation_have_it():
    """Serway & Jewett ch. 10 and ch. 6, Halliday ch. 11: (7/10) m v^2 = m g times the drop of the
    ball's center, N + m g = m v^2/(R - r) at the top, and it stays on when its center starts at
    least 2.7 (R - r) above its center at the loop's bottom. Its linear solve at the top took past
    250 s (sympy's domain built by expanding sums that are (R - r)^2 in disguise)."""
    solution = Solution(load(str(textbook("ball_ramp_into_loop"))))
    m, R, r, d, g = (solution.problem.parameters[n].symbol for n in ("m", "R", "r", "d", "g"))
    gap = sp.Symbol("gap", positive=True)  # R - r: the ball fits inside the loop
    inside = {R: r + gap}
    drop = (R + 3 * d - r) / 5  # from its release to the loop's bottom
    v_top = sp.sqrt(sp.Rational(10, 7) * g * (drop - 2 * (R - r)))
    books = {"v": sp.sqrt(sp.Rational(10, 7) * g * drop), "v_top": v_top,
             "N_top": m * v_top**2 / (R - r) - m * g}
    for name, book in books.items():
        assert sp.simplify((solution.expression(name) - book).xreplace(inside)) == 0, name
    least = solution.expression("d_min")
    assert sp.simplify(drop.xreplace({d: least}).xreplace(inside) - sp.Rational(27, 10) * gap) == 0
    # as placed, R - r > 0 (kept in every variant): the answers read R - r, not |R - r|
    assert R - r in solution.scene.placed
    assert not any(solution.expression(n).has(sp.Abs) for n in ("N_top", "d_min")), solution.expression("N_top")
    # it spins as it rolls: omega = -v/r at the top (clockwise), kept through the transfer
    spin = solution.coordinates.of("ball", "theta").u
    assert solution.states["looping"].values[spin] == solution.states["entering"].values[spin]
    top = solution.states["top"].values
    assert sp.simplify((top[spin] + v_top / r).xreplace(inside)) == 0
    # derive check's chain simulation: ramp, transfer and loop integrated link by link
    report = chain_simulation.simulate(solution)
    assert report.passed, report.notes
    assert {"v", "v_top", "N_top", "state top"} <= set(report.compared)


def test_the_top_of_the_loop_is_reached_by_its_height_as_by_its_x(tmp_path):
    """The ball's height is extremal at the top, so the state is followed along x; the rolled angle,
    which the rolling gap holds linearly, is not tried before it (sympy's solve of that gap for the
    ball's position, inside the arc's atan2, ran past the limit)."""
    text = (textbook("ball_ramp_into_loop")).read_text()
    path = tmp_path / "ball_ramp_into_loop.yaml"
    path.write_text(text.replace("top: {from: above, when: {ball.x: 0}}", "top: {from: above, when: {ball.y: 2*R - r}}"))
    by_height, by_x = Solution(load(str(path))), Solution(load(str(textbook("ball_ramp_into_loop"))))
    assert by_height.scene.states["top"].when[1] == "y" and by_x.scene.states["top"].when[1] == "x"
    assert by_height.states["top"].values == by_x.states["top"].values
    assert by_height.states["top"].path.s == by_x.coordinates.of("ball", "x").q
    assert by_height.expression("N_top") == by_x.expression("N_top")


def test_a_transfer_where_the_body_does_not_touch_the_new_surface_is_refused(tmp_path):
    text = LOOP.replace("entering: {when: {block.x: -3*R/5}}", "entering: {when: {block.x: -3*R/5 - d/4}}")
    error = refused(tmp_path, text, "scene.states.looping")
    assert "does not touch loop" in error and "touches both surfaces" in error


def test_a_kink_is_refused_naming_the_impulse_it_would_take(tmp_path):
    text = LOOP.replace("loop: {circle: {radius: R, center: [0, R], side: inside}}",
                        "loop: {circle: {radius: R, center: [0, R], side: inside}}\n"
                        "    floor: {plane: {angle: 0, through: [0, 0]}}")
    text = text.replace("through: [-3*R/5, R/5]", "through: [0, 0]")
    text = text.replace("at: [-(3*R + 4*d)/5, (R + 3*d)/5]", "at: [-4*d/5, 3*d/5]")
    text = text.replace("entering: {when: {block.x: -3*R/5}}", "entering: {when: {block.x: 0}}")
    text = text.replace("transfer: block, to: loop", "transfer: block, to: floor")
    text = text.replace("    bottom: {from: looping, when: {block.x: 0}}\n", "    bottom: {from: looping, when: {block.x: R}}\n")
    text = text.split("    above:")[0] + "ask:\n  v: {meaning: speed, of: block.speed, in: bottom, unit: m/s}\n" \
        + "question: |\n  A block of mass {{ m }} slides {{ d }} down a ramp onto a floor by a loop of radius {{ R }}.\n"
    error = refused(tmp_path, text, "scene.states.looping")
    assert "kink" in error and "N^block" in error and "tangentially" in error


def test_what_cannot_pass_is_refused_by_name(tmp_path):
    error = refused(tmp_path, LOOP.replace("transfer: block, to: loop", "transfer: block, to: lop"),
                    "scene.states.looping.event.to")
    assert "did you mean" in error and "loop" in error
    error = refused(tmp_path, LOOP.replace("transfer: block, to: loop", "transfer: block, to: ramp"),
                    "scene.states.looping.event.to")
    assert "on ramp already" in error
    error = refused(tmp_path, LOOP.replace("transfer: block, to: loop", "transfer: block, to: loop, restitution: 1"),
                    "scene.states.looping.event.restitution")
    assert "a transfer has no restitution" in error
