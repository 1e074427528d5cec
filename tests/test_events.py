"""The library's events against independent closed forms: the beetle (lecture notes §6.3), a
sticky impact with a pivoted sphere (§6.4.1) and with a free one (§6.4.2, by the parallel-axis
route), a ball bouncing off a free rod (the effective-mass formula of an impact with restitution),
Elroy's beanie (§6.5, against a simulation) and a skid that turns into rolling (against a
simulation of the slipping phase), all events of scene.states: impacts and grips
(derive.mechanics.impacts, grips) and Elroy's turn (derive.mechanics.moves)."""
import math

import mpmath
import sympy as sp
from scipy.integrate import solve_ivp

from derive.language import problem
from derive.core import units
from derive.solution.answers import Solution
from derive.mechanics import impacts
from conftest import close, solve


def test_beetle_matches_the_notes_and_loses_energy():
    answers, result = solve("beetle_lazy_susan", m="0.004", v="0.2", R="0.25", I="0.005", omega0="0.6")
    m, v, R, I, w0 = (mpmath.mpf(x) for x in ("0.004", "0.2", "0.25", "0.005", "0.6"))
    omega = (m * v * R - I * w0) / (m * R**2 + I)
    assert close(answers["omega"], omega)
    before = I * w0**2 / 2 + m * v**2 / 2
    after = I * omega**2 / 2 + m * (R * omega) ** 2 / 2
    assert close(answers["dE"], after - before, 12)
    assert answers["dE"] < 0
    assert result["checks"]["states"]["passed"]


def test_beetle_running_against_the_spin_keeps_its_digits():
    """v = R omega0 (1 + 1e-12): the final rate is a near-cancellation; the exact form keeps 15 digits."""
    answers, _ = solve("beetle_lazy_susan", m="0.004", v="0.150000000000000000000000000000015", R="0.25",
                       I="0.001", omega0="0.6")
    m, v, R, I, w0 = (mpmath.mpf(x) for x in ("0.004", "0.150000000000000000000000000000015", "0.25", "0.001", "0.6"))
    assert close(answers["omega"], (m * v * R - I * w0) / (m * R**2 + I))


def test_pivoted_sphere_matches_the_notes():
    answers, _ = solve("sticky_impact_pivoted", m="0.05", M="2", R="0.3", b="0.1", v="8")
    m, M, R, b, v = (mpmath.mpf(x) for x in ("0.05", "2", "0.3", "0.1", "8"))
    assert close(answers["omega"], m * b * v / (mpmath.mpf(2) / 5 * M * R**2 + m * R**2))


def test_notes_6_4_1_angular_momentum_has_one_factor_of_v():
    """The notes write L = m v b y-hat x v x-hat: that has the dimension of kg m^3/s^2, not of angular
    momentum. The derived L about the pivot is -m b v (z)."""
    m, v, b = sp.symbols("m v b", positive=True)
    dims = {m: "kg", v: "m/s", b: "m"}
    assert units.expression_dimension(m * v * b * v, dims) != units.dimension(units.parse_unit("kg*m^2/s"))
    pivoted = Solution(problem.load("sticky_impact_pivoted"))
    flying = pivoted.states["flying"].values
    kept = impacts.conserved(pivoted.scene_in("struck"), pivoted.coordinates, flying, pivoted.states["struck"].values)
    before = kept.equations[0].rhs  # the angular momentum about the axle, before the impact
    mass, speed, impact = (pivoted.problem.parameters[n].symbol for n in ("m", "v", "b"))
    assert sp.simplify(before + mass * impact * speed) == 0
    assert pivoted.problem.corrections[0]["where"].startswith("§6.4.1")


def test_free_sphere_matches_the_notes_parallel_axis_route():
    answers, _ = solve("sticky_impact_free", m="0.2", M="3", R="0.25", v="6")
    m, M, R, v = (mpmath.mpf(x) for x in ("0.2", "3", "0.25", "6"))
    d = m * R / (m + M)
    inertia = mpmath.mpf(2) / 5 * M * R**2 + M * d**2 + m * (R - d) ** 2
    assert close(answers["V_cm"], m * v / (M + m))
    assert close(answers["omega"], m * (R - d) * v / inertia)
    kinetic_after = (M + m) * (m * v / (M + m)) ** 2 / 2 + inertia * (m * (R - d) * v / inertia) ** 2 / 2
    assert close(answers["dE"], kinetic_after - m * v**2 / 2, 12)


def test_notes_6_5_elroy_numerator_is_I2():
    """Simulate the two ovals with a motor between them (equal and opposite torques driving the
    relative angle to 2 pi); the outer oval ends up turned by -2 pi I2/(I1+I2), not -2 pi I1/(I1+I2)."""
    I1, I2 = 0.05, 0.02
    answers, _ = solve("elroys_beanie", I1=I1, I2=I2)
    k, c = 4.0, 0.6  # the motor: a stiff, damped servo on the relative angle toward 2 pi t / 10

    def rhs(t, y):
        theta1, theta2, w1, w2 = y
        target = 2 * math.pi * min(t / 10, 1)
        torque = k * (target - (theta2 - theta1)) - c * (w2 - w1)
        return [w1, w2, -torque / I1, torque / I2]

    run = solve_ivp(rhs, (0, 40), [0, 0, 0, 0], rtol=1e-11, atol=1e-13)
    theta1, theta2 = run.y[0, -1], run.y[1, -1]
    assert math.isclose(theta2 - theta1, 2 * math.pi, rel_tol=1e-6)
    assert math.isclose(theta1, -2 * math.pi * I2 / (I1 + I2), rel_tol=1e-6)
    assert math.isclose(float(answers["dtheta"]), -theta1, rel_tol=1e-6)  # asked as the angle, turned the other way
    assert not math.isclose(theta1, -2 * math.pi * I1 / (I1 + I2), rel_tol=1e-2)


def test_notes_6_5_elroy_from_the_notes_equation():
    """The notes' I1 d(theta) + I2 (d(psi) + d(theta)) = 0, integrated over psi from 0 to 2 pi, is
    the derived expression exactly."""
    solution = Solution(problem.load("elroys_beanie"))
    I1, I2 = (solution.problem.parameters[n].symbol for n in ("I1", "I2"))
    dtheta, dpsi, psi = sp.symbols("dtheta dpsi psi")
    rate = sp.solve(I1 * dtheta + I2 * (dpsi + dtheta), dtheta)[0] / dpsi
    turned = sp.integrate(rate, (psi, 0, 2 * sp.pi))  # negative: the other way to the inner oval's turn
    assert sp.simplify(solution.signed("dtheta") + turned) == 0  # asked as the angle
    assert solution.problem.corrections[0]["where"].startswith("§6.5")


def test_bounce_off_a_rod_against_the_effective_mass_formula():
    m, M, L, d, v = (mpmath.mpf(x) for x in ("0.2", "1.1", "0.9", "0.2", "3"))
    for e in ("0", "0.6", "1"):
        answers, result = solve("restitution_rod", m="0.2", M="1.1", L="0.9", d="0.2", v="3", e=e)
        ee = mpmath.mpf(e)
        inertia = M * L**2 / 12
        impulse = (1 + ee) * v / (1 / m + 1 / M + d**2 / inertia)   # along +y on the rod... on the ball
        assert close(answers["V"], -impulse / M)
        assert close(answers["omega"], -impulse * d / inertia)
        assert close(answers["v_after"], -v + impulse / m)
        reduced = 1 / (1 / m + 1 / M + d**2 / inertia)
        if ee == 1:
            assert answers["dE"] == 0            # elastic: exactly no loss, no cancellation
        else:
            assert close(answers["dE"], -(1 - ee**2) * reduced * v**2 / 2, 14)
        assert result["checks"]["states"]["passed"]
    # e = 0: the ball and the struck point of the rod leave with the same normal velocity.
    answers, _ = solve("restitution_rod", m="0.2", M="1.1", L="0.9", d="0.2", v="3", e="0")
    assert close(answers["v_after"], answers["V"] + answers["omega"] * d, 14)


def test_restitution_outside_0_1_is_refused(tmp_path):
    from conftest import copy_library, run_derive
    library = copy_library(tmp_path)
    path = library / "conservation" / "restitution_rod.yaml"
    path.write_text(path.read_text().replace("range: [0, 1], sig_figs: 2}", "range: [0, 1.5], sig_figs: 2}"))
    done = run_derive("solve", "restitution_rod", library=library)
    assert done.returncode == 2 and "coefficient of restitution lies in [0, 1]" in done.stderr


def test_skid_to_roll_against_a_simulation_of_the_slipping_phase():
    M, R, v0, mu, g = 6.0, 0.11, 8.0, 0.2, 9.81
    answers, result = solve("skid_to_roll", M="6", R="0.11", v0="8", mu="0.2")
    inertia = 2 / 5 * M * R**2

    def rhs(t, y):  # x, V, omega; kinetic friction opposes the slip V + omega R
        friction = -mu * M * g
        return [y[1], friction / M, friction * R / inertia]

    def rolls(t, y):
        return y[1] + y[2] * R
    rolls.terminal = True
    run = solve_ivp(rhs, (0, 10), [0.0, v0, 0.0], rtol=1e-12, atol=1e-14, events=rolls)
    t_roll = run.t_events[0][0]
    x, V, omega = run.y[:, -1]
    assert math.isclose(float(answers["t"]), t_roll, rel_tol=1e-9)
    assert math.isclose(float(answers["d"]), x, rel_tol=1e-9)
    assert math.isclose(float(answers["V"]), V, rel_tol=1e-9)
    kinetic_after = M * V**2 / 2 + inertia * omega**2 / 2
    assert math.isclose(float(answers["dE"]), kinetic_after - M * v0**2 / 2, rel_tol=1e-9)
    assert result["checks"]["states"]["passed"]
