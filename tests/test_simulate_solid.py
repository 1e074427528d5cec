"""The 3D answers against the full nonlinear motion (derive.checks.simulate_solid, derive.mechanics.rigid_motion): every
textbook file of a top, a rolling coin, a free body and a body in bearings agrees with its simulation
(rates, angles and forces to 1e-6 relative, most to 1e-9), and an answer 1 % off, or a start off the
steady motion, is caught. The numerical model itself keeps what it must: energy, L_z about the
fixed point, the rolling condition."""
import math

import numpy as np
import pytest
import sympy as sp

from conftest import run_derive, textbook, write_problem
from derive.mechanics import rigid_motion
from derive.checks import simulate_solid
from derive.solution.answers import Solution
from derive.language.problem import load

#: Each textbook file's asks the simulation compares (the fast-top limits are not simulated).
SIMULATED = {
    "top_two_precessions": ["slow", "fast"],
    "gyroscope_wheel": ["Omega"],
    # a custom wheel given only its axial moment (the transverse one, open, does not change a level axle's
    # precession: the simulation draws it; it had stopped derive check with "Cannot convert expression to float")
    "bicycle_wheel_gyroscope": ["Omega"],
    "sleeping_cone": ["omega_min"],
    "coin_rolls_in_circle": ["V", "N", "f"],
    "disk_rolls_upright": ["v_min", "omega_min"],
    "hoop_rolls_upright": None,  # whatever it asks: each one compared
    "tennis_racket": ["least", "middle", "greatest"],
    "thrown_plate_wobble": ["body", "space", "L_axis", "omega_axis"],
    "football_free_precession": ["body", "space", "L_axis"],
    "earth_free_precession": ["Omega"],
    "rotor_static_imbalance": ["F", "FAx", "FAy", "tau", "Q"],
    "shaft_dynamic_imbalance": ["F", "tau", "FA", "FB"],
    "rod_tilted_on_shaft": None,
    "disk_tilted_on_shaft": None,
    "dumbbell_tilted_shaft": None,
}
#: The top of top_two_precessions asked its nutation frequency (not only the fast-top limit).
NUTATING = (textbook("top_two_precessions")).read_text().replace(
    "of: top.nutation.fast_top", "of: top.nutation.frequency")


def _relative_differences(report, limits: bool = False) -> list[float]:
    """The relative differences of the report's figure lines (of the small-size limits', or of the others)."""
    return [float(line.rpartition("relative difference ")[2]) for line in report.figures
            if "relative difference" in line and ("small-size limit;" in line) == limits]


@pytest.mark.parametrize("problem_id", sorted(SIMULATED))
def test_every_textbook_3d_answer_agrees_with_its_simulation(problem_id):
    solution = Solution(load(textbook(problem_id)))
    report = simulate_solid.check(solution)
    assert report.passed, report.notes
    expected = SIMULATED[problem_id] or [n for n, a in solution.problem.asks.items()
                                         if a.quantity.kind in simulate_solid.KINDS]
    assert list(dict.fromkeys(report.compared)) == expected
    assert all(d < 1e-8 for d in _relative_differences(report)), report.figures
    assert all(d < simulate_solid.LIMIT_TOLERANCE for d in _relative_differences(report, limits=True)), report.figures


def test_the_nutation_frequency_is_the_simulated_one(tmp_path):
    """Nudged off its slow steady precession, the top nutates at the derived frequency (the period
    between the tilt's upward crossings of its steady value, over 5 periods)."""
    report = simulate_solid.check(Solution(load(write_problem(tmp_path, NUTATING))))
    assert report.passed and report.compared == ["slow", "fast", "nutation"], report.notes
    line = next(f for f in report.figures if f.startswith("nutation:"))
    assert "5 nutation periods" in line and _relative_differences(report)[-1] < 1e-8


def _one_percent_off(solution: Solution, name: str) -> Solution:
    solution.expressions[name] = solution.expressions[name] * sp.Rational(101, 100)
    return solution


@pytest.mark.parametrize("problem_id, name", [
    ("top_two_precessions", "slow"), ("gyroscope_wheel", "Omega"), ("sleeping_cone", "omega_min"),
    ("coin_rolls_in_circle", "V"), ("disk_rolls_upright", "v_min"), ("tennis_racket", "middle"),
    ("tennis_racket", "greatest"), ("football_free_precession", "body"), ("thrown_plate_wobble", "space"),
    ("rotor_static_imbalance", "FAy"), ("rotor_static_imbalance", "Q"), ("shaft_dynamic_imbalance", "tau"),
    ("rod_tilted_on_shaft", "K"), ("disk_tilted_on_shaft", "F"),
])
def test_an_answer_one_percent_off_is_caught(problem_id, name):
    report = simulate_solid.check(_one_percent_off(Solution(load(textbook(problem_id))), name))
    assert not report.passed and any(n.startswith(f"{name}:") for n in report.notes), report.notes


def test_a_least_spin_one_percent_low_is_caught_too():
    solution = Solution(load(textbook("sleeping_cone")))
    solution.expressions["omega_min"] = solution.expressions["omega_min"] * sp.Rational(99, 100)
    report = simulate_solid.check(solution)
    assert not report.passed and "the tilt does not turn back" in report.notes[0]


def test_a_nutation_frequency_one_percent_off_is_caught(tmp_path):
    solution = _one_percent_off(Solution(load(write_problem(tmp_path, NUTATING))), "nutation")
    report = simulate_solid.check(solution)
    assert not report.passed and report.notes[0].startswith("nutation:")


def test_a_start_off_the_steady_motion_is_caught(monkeypatch):
    """Were the derived steady rate 1 % off, the start would not be steady: the tilt wanders, though
    the answer and the start agree."""
    solution = Solution(load(textbook("top_two_precessions")))
    right = Solution._pivot_point
    monkeypatch.setattr(Solution, "_pivot_point", lambda self, q, route="lagrange": right(self, q, route) * 1.01)
    report = simulate_solid.check(solution)
    assert not report.passed and any("the tilt wanders" in n for n in report.notes), report.notes


def test_a_coin_started_off_its_steady_circle_is_caught(monkeypatch):
    solution = Solution(load(textbook("coin_rolls_in_circle")))
    right = Solution._rolls_on_edge
    monkeypatch.setattr(Solution, "_rolls_on_edge", lambda self, q, route="lagrange": right(self, q, route) * 1.01)
    report = simulate_solid.check(solution)
    assert not report.passed and any("the lean wanders" in n for n in report.notes), report.notes


def test_the_top_keeps_its_energy_and_its_momentum_about_the_vertical():
    """The numerical model: a heavy top (about its fixed point I1 = 2, I3 = 1, its center 1 above)
    launched off any steady motion keeps T + V and L_z, and so does a rolling coin its energy,
    the rim's point at the contact at rest."""
    tensor, mass, g, arm = np.diag([2.0, 2.0, 1.0]), 1.0, 9.81, 1.0
    tilt = 0.7
    turn = np.array([[math.cos(tilt), 0, math.sin(tilt)], [0, 1, 0], [-math.sin(tilt), 0, math.cos(tilt)]])
    state = rigid_motion.start(turn, [0.3, -1.0, 20.0])
    run = rigid_motion.integrate(rigid_motion.about_point(tensor, mass, g, (0, 0, arm)), state, 2.0)

    def energy_and_momentum(y):
        axes, omega = rigid_motion.axes(y), y[4:7]
        return 0.5 * omega @ tensor @ omega + mass * g * arm * axes[2, 2], (axes @ tensor @ omega)[2]
    first, last = energy_and_momentum(run.y[:, 0]), energy_and_momentum(run.y[:, -1])
    assert np.allclose(first, last, rtol=1e-10) and abs(last[1]) > 1

    I1, I3, radius = 0.25, 0.5, 1.0  # a uniform disk of unit mass and radius
    upright = np.array([[1.0, 0, 0], [0, 0, 1], [0, -1, 0]])  # rolling along x, its axis along y
    coin = rigid_motion.start(upright, [0.5, 10.0, 0.2], 0.0, 0.0, radius)  # leaning and turning a little
    run = rigid_motion.integrate(rigid_motion.rolling_on_rim(I1, I3, 1.0, g, radius), coin, 3.0)

    def coin_energy(y):
        axes, omega = rigid_motion.axes(y), y[4:7]
        velocity = np.cross(axes @ omega, y[7:10] - rigid_motion.contact_point(y, radius))
        return 0.5 * omega @ np.diag([I1, I1, I3]) @ omega + 0.5 * velocity @ velocity + g * y[9]
    assert math.isclose(coin_energy(run.y[:, 0]), coin_energy(run.y[:, -1]), rel_tol=1e-10)
    assert max(abs(rigid_motion.contact_point(y, radius)[2]) for y in run.y.T) < 1e-9  # on the floor all along
    assert max(abs(rigid_motion.axes(y)[2, 2]) for y in run.y.T) > 0.01  # it did lean


def test_check_prints_a_figure_line_for_each_3d_ask():
    done = run_derive("check", "top_precession_exact", "rigid_body_L")
    assert done.returncode == 0, done.stdout + done.stderr
    assert "ok: Omega_slow, Omega_fast" in done.stdout and "ok: L_z, L_x, angle" in done.stdout
    lines = done.stdout.splitlines()
    figures = lines[lines.index("simulated in 3D (derive.checks.simulate_solid):") + 1:]
    slow = next(f for f in figures if f.strip().startswith("top_precession_exact: Omega_slow:"))
    assert "steady precession" in slow and float(slow.rpartition("relative difference ")[2]) < 1e-6
    assert any("Omega_approx: top.precession.fast_top not simulated (a fast-top limit)" in f for f in figures)


def test_a_3d_simulation_that_fails_fails_derive_check(monkeypatch):
    from derive import audit
    monkeypatch.setattr(simulate_solid, "TOLERANCE", -1.0)  # no difference is small enough
    (row,) = audit.audit(["rigid_body_L"])
    assert not row.passed and row.simulation == "FAILED" and row.failure.startswith("L_z: turned once on its shaft")
    assert "FAILED rigid_body_L: L_z" in audit.table([row])


def test_an_integration_that_gives_up_is_a_failed_check(monkeypatch):
    def gives_up(*args, **kwargs):
        raise RuntimeError("the integration failed: step size too small")
    monkeypatch.setattr(rigid_motion, "integrate", gives_up)
    report = simulate_solid.check(Solution(load("rigid_body_L")))
    assert not report.passed and report.notes[0] == "L_z: the integration failed: step size too small"


def test_a_tilted_disk_off_an_inclined_shaft_loads_its_bearings_as_simulated(tmp_path):
    """Every bearing quantity of a disk tilted 0.3 rad on an inclined shaft through a point R/5 from
    its center, a thrust bearing at A: the supports' force and torque from the simulated motion."""
    from test_bearings import INCLINED
    text = INCLINED.replace("tilt: 0, apart", "tilt: 0.3, through: [R/5, 0, 0], apart").replace("question:", """\
  T: {meaning: energy, of: disk.kinetic_energy, unit: J}
  Q: {meaning: drive, of: disk.bearings.drive_torque, unit: N*m}
  F: {meaning: total, of: disk.bearings.total_force.magnitude, unit: N}
  B: {meaning: B, of: disk.bearings.B.force.magnitude, unit: N}
question:""")
    report = simulate_solid.check(Solution(load(write_problem(tmp_path, text))))
    assert report.passed and report.compared == ["Ay", "Az", "By", "Bz", "Bx", "T", "Q", "F", "B"], report.notes
    assert max(_relative_differences(report)) < 1e-9


#: The coin of coin_rolls_in_circle with its radius given and every steady quantity asked, exactly.
COIN = (textbook("coin_rolls_in_circle")).read_text().replace(
    "  g: {meaning", "  a: {meaning: radius of the coin, unit: m, range: [0.01, 0.03], sig_figs: 2}\n  g: {meaning").replace(
    "shape: disk, mass: M,", "shape: disk, mass: M, radius: a,").replace(", small: coin.radius", "").replace(
    "question:", """  W: {meaning: heading rate, of: coin.steady.precession, unit: rad/s}
  w: {meaning: spin, of: coin.steady.spin, unit: rad/s}
question:""")


def test_a_coin_s_steady_circle_holds_with_its_derived_rates(tmp_path):
    solution = Solution(load(write_problem(tmp_path, COIN)))
    report = simulate_solid.check(solution)
    assert report.passed and report.compared == ["V", "N", "f", "W", "w"], report.notes
    assert max(_relative_differences(report)) < 1e-8
    for name in ("W", "w"):
        report = simulate_solid.check(_one_percent_off(Solution(load(write_problem(tmp_path, COIN))), name))
        assert not report.passed and report.notes[0].startswith(f"{name}:")


def test_a_start_that_is_no_real_number_is_a_failed_check(monkeypatch):
    solution = Solution(load("top_precession_exact"))
    solution.expressions  # the answers as derived; then a root of the start made imaginary
    imaginary = sp.sqrt(-sp.Symbol("m", positive=True))
    monkeypatch.setattr(Solution, "_pivot_point", lambda self, q, route="lagrange": imaginary)
    report = simulate_solid.check(solution)
    assert not report.passed and report.notes[0].startswith("Omega_slow: I*sqrt(m) is")
    assert report.notes[0].endswith("not a real number")
