"""The top: both routes, the fast-top limit, and a simulation of the full Euler-angle motion."""
import math

import numpy as np
import sympy as sp
from scipy.integrate import solve_ivp

from derive import problem, report
from derive.errors import InputError
from derive.mechanics import top

m, g, R, I1, I3, w, th = sp.symbols("m g R I_1 I_3 omega theta", positive=True)


def test_both_routes_give_the_same_condition_and_the_notes_limit():
    lagrange = top.precession_condition(m, g, R, I1, I3, w, th, "lagrange")
    newton = top.precession_condition(m, g, R, I1, I3, w, th, "newton_euler")
    assert sp.simplify(lagrange - newton) == 0
    assert top.fast_top_limit(m, g, R, I1, I3, w, th) == m * g * R / (I3 * w)
    slow, fast = top.roots(m, g, R, I1, I3, w, th)
    assert sp.simplify(lagrange.subs(top.OMEGA, slow)) == 0 and sp.simplify(lagrange.subs(top.OMEGA, fast)) == 0


def _euler_angle_motion(values):
    """Numerical equations of the top from its Lagrangian, for (theta, phi, psi) and rates."""
    t = sp.Symbol("t")
    q = [sp.Function(n)(t) for n in ("theta", "phi", "psi")]
    qd = [f.diff(t) for f in q]
    lag = (I1 * (qd[0] ** 2 + qd[1] ** 2 * sp.sin(q[0]) ** 2) / 2 + I3 * (qd[2] + qd[1] * sp.cos(q[0])) ** 2 / 2
           - m * g * R * sp.cos(q[0])).subs(values)
    eqs = [sp.diff(lag, d).diff(t) - sp.diff(lag, f) for f, d in zip(q, qd)]
    acc = sp.solve(eqs, [d.diff(t) for d in qd])
    a, b = sp.symbols("a0:3"), sp.symbols("b0:3")
    back = {**dict(zip(qd, b)), **dict(zip(q, a))}
    exprs = [acc[d.diff(t)].subs(back) for d in qd]
    return sp.lambdify([*a, *b], exprs, "numpy")


def test_the_slow_root_is_a_steady_precession_in_simulation():
    values = {m: sp.Rational(2, 10), g: sp.Rational(981, 100), R: sp.Rational(5, 100), I1: sp.Rational(5, 10000),
              I3: sp.Rational(5, 100000), w: 300, th: sp.Rational(1, 2)}
    slow = float(top.roots(m, g, R, I1, I3, w, th)[0].subs(values))
    rates = _euler_angle_motion(values)
    tilt, spin = 0.5, 300.0
    start = [tilt, 0.0, 0.0, 0.0, slow, spin - slow * math.cos(tilt)]
    run = solve_ivp(lambda t, y: [*y[3:], *rates(*y)], (0, 2.0), start, method="DOP853", rtol=1e-12, atol=1e-12)
    assert np.max(np.abs(run.y[0] - tilt)) < 1e-7          # no nutation: theta stays put
    assert math.isclose(run.y[1, -1] / run.t[-1], slow, rel_tol=1e-7)
    # The notes' rate is only the fast-top limit: started there the top nods noticeably.
    approximate = float((m * g * R / (I3 * w)).subs(values))
    start[4] = approximate
    run = solve_ivp(lambda t, y: [*y[3:], *rates(*y)], (0, 2.0), start, method="DOP853", rtol=1e-12, atol=1e-12)
    assert np.max(np.abs(run.y[0] - tilt)) > 1e-4


def test_too_slow_a_spin_is_refused_with_a_clear_message():
    try:
        report.solve(problem.load("top_precession_exact"), {"m": "0.2", "Rcm": "0.05", "I3": "5e-5", "I1": "5e-4",
                                                            "theta": "0.5", "omega": "30"}, 15)
    except InputError as error:
        assert "no steady precession" in str(error)
    else:
        raise AssertionError("a spin too slow for steady precession was accepted")


def test_library_top_answers():
    result = report.solve(problem.load("top_precession"), {"m": "0.2", "Rcm": "0.05", "I": "5e-5", "omega": "300"}, 15)
    assert result["answers"]["Omega"]["value"] == "6.54000000000000"
