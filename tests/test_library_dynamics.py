"""Library problems of the dynamics slice against independent routes (the notes' own method
where it is sound, computed here at 50 digits), through the same code path as `derive solve`."""
import mpmath

from derive.language import problem
from derive.publishing import report
from conftest import close, solve


def test_tugged_spool_against_torque_about_the_contact_point():
    """Notes §4.4: treat the contact point as an instantaneous pivot (I + M R^2) alpha = tau_P."""
    F, M, R, r, I, theta = (mpmath.mpf(x) for x in ("5", "1.3", "0.06", "0.02", "0.0011", "0.7"))
    answers, result = solve("tugged_spool", F=5, M=1.3, R=0.06, r=0.02, I_cm=0.0011, theta=0.7)
    tangent = (r * mpmath.sin(theta), -r * mpmath.cos(theta))      # where the string leaves the hub
    contact = (0, -R)
    force = (F * mpmath.cos(theta), F * mpmath.sin(theta))
    torque = (tangent[0] - contact[0]) * force[1] - (tangent[1] - contact[1]) * force[0]
    alpha = torque / (I + M * R**2)
    assert close(answers["a"], -alpha * R)                          # rolling: v = -omega R
    # Friction from the center's force balance: M a = F cos(theta) + f.
    assert close(answers["f"], abs(M * (-alpha * R) - F * mpmath.cos(theta)))
    assert close(answers["theta_c"], mpmath.acos(r / R))
    assert result["checks"]["lagrange_vs_newton_euler"]["passed"]


def test_spool_rolls_toward_the_pull_below_the_critical_angle_and_away_above():
    below, _ = solve("tugged_spool", F=5, M=1, R=0.06, r=0.02, I_cm=0.001, theta=1.0)
    above, _ = solve("tugged_spool", F=5, M=1, R=0.06, r=0.02, I_cm=0.001, theta=1.4)
    assert below["a"] > 0 > above["a"]


def test_spool_at_the_critical_angle_does_not_accelerate():
    at = mpmath.acos(mpmath.mpf(1) / 3)
    result = report.solve(problem.load("tugged_spool"), {"F": "5", "M": "1", "R": "0.06", "r": "0.02",
                                                         "I_cm": "0.001", "theta": mpmath.nstr(at, 40)}, 15)
    assert abs(mpmath.mpf(result["answers"]["a"]["value"])) < mpmath.mpf(10) ** -30


def test_tightrope_walker_growth_rate():
    answers, _ = solve("tightrope_walker", m=70, h=1.1, I=300)
    assert close(answers["a"], mpmath.sqrt(70 * mpmath.mpf("1.1") * mpmath.mpf("9.81") / 300))


def test_incline_race_matches_equation_12_of_the_notes():
    """gH = (1/2) V^2 (1 + I/(M R^2)): the speed depends only on the shape's I/(M R^2)."""
    answers, result = solve("incline_race", H=2)
    gH = 2 * mpmath.mpf("9.81")
    for name, ratio in (("v_slide", 0), ("v_sphere", mpmath.mpf(2) / 5), ("v_cylinder", mpmath.mpf(1) / 2),
                        ("v_hoop", 1)):
        assert close(answers[name], mpmath.sqrt(2 * gH / (1 + ratio)))
    assert answers["v_slide"] > answers["v_sphere"] > answers["v_cylinder"] > answers["v_hoop"]
    assert result["checks"]["energy_vs_dynamics"]["passed"]


def test_rolling_sphere_on_an_incline():
    answers, _ = solve("rolling_incline", M=1.5, R=0.1, H=1.2, theta=0.6)
    g, H, theta, M = mpmath.mpf("9.81"), mpmath.mpf("1.2"), mpmath.mpf("0.6"), mpmath.mpf("1.5")
    a = g * mpmath.sin(theta) / (1 + mpmath.mpf(2) / 5)
    assert close(answers["a"], a)
    assert close(answers["v"], mpmath.sqrt(2 * a * H / mpmath.sin(theta)))
    assert close(answers["t"], mpmath.sqrt(2 * (H / mpmath.sin(theta)) / a))
    friction = M * g * mpmath.sin(theta) - M * a          # along the slope: M a = M g sin - f
    assert close(answers["f"], friction)
    assert close(answers["mu_min"], friction / (M * g * mpmath.cos(theta)))


def test_large_amplitude_period_against_the_series_and_a_simulated_wide_swing():
    small = mpmath.mpf("0.05")
    answers, _ = solve("compound_pendulum_large", M=2, Rcm=0.3, I_cm=0.05, theta0=small)
    series = answers["T_small"] * (1 + small**2 / 16 + 11 * small**4 / 3072)
    assert abs(answers["T"] / series - 1) < mpmath.mpf("1e-9")   # next term ~ theta0^6
    from derive.checks import simulate
    from derive.solution.answers import Solution
    wide = problem.load("compound_pendulum_large")
    report = simulate.check(Solution(wide))
    assert report.passed and "T" in report.compared
