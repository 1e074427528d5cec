"""The tilting wheel, the quantization estimate, internal forces, and L of a tilted rod."""
import math

import mpmath
import sympy as sp
from scipy.integrate import solve_ivp

from derive.mechanics import many_bodies
from conftest import solve


def test_tilting_wheel_against_a_simulation_of_dL_dt():
    answers, result = solve("tilting_wheel", tau="1.5", dt="0.4", I="0.1", omega="20")
    run = solve_ivp(lambda t, L: [0.0, 1.5], (0, 0.4), [0.1 * 20, 0.0], rtol=1e-12, atol=1e-14)
    turned = math.atan2(run.y[1, -1], run.y[0, -1])
    assert math.isclose(float(answers["dphi_exact"]), turned, rel_tol=1e-10)
    assert math.isclose(float(answers["dphi"]), 1.5 * 0.4 / (0.1 * 20), rel_tol=1e-14)
    assert answers["dphi"] > answers["dphi_exact"]  # the small-angle estimate overshoots
    assert result["checks"]["impulse_vs_euler"]["passed"]


def test_quantization_gives_hbar():
    answers, _ = solve("angular_momentum_quantization", r="1e-10")
    assert abs(answers["L"] / mpmath.mpf("1.054571817646156e-34") - 1) < mpmath.mpf("1e-14")


def test_internal_central_forces_conserve_L_and_other_forces_do_not():
    for count in (2, 3, 4):
        assert many_bodies.internal_torque(count, "direct") == 0
        assert many_bodies.internal_torque(count, "pairs") == 0
    # A control: equal and opposite forces NOT along the line between the bodies exert a torque.
    x1, x2 = sp.Matrix(sp.symbols("a1 b1 c1", real=True)), sp.Matrix(sp.symbols("a2 b2 c2", real=True))
    sideways = sp.Matrix([0, 0, 1]).cross(x2 - x1)
    torque = x1.cross(sideways) + x2.cross(-sideways)
    assert sp.simplify(torque.norm()) != 0


def test_tilted_rod_angular_momentum_by_quadrature():
    answers, result = solve("rigid_body_L", m="1.3", L="0.8", omega="7", alpha="0.6")
    m, length, w, a = (mpmath.mpf(v) for v in ("1.3", "0.8", "7", "0.6"))
    lam = m / length

    def element(s, i):  # dL of the element at s along the rod: lambda r x (omega z x r)
        r = [s * mpmath.sin(a), 0, s * mpmath.cos(a)]
        v = [-w * r[1], w * r[0], 0]
        cross = [r[1] * v[2] - r[2] * v[1], r[2] * v[0] - r[0] * v[2], r[0] * v[1] - r[1] * v[0]]
        return lam * cross[i]

    Lz = mpmath.quad(lambda s: element(s, 2), [-length / 2, length / 2])
    Lx = mpmath.quad(lambda s: element(s, 0), [-length / 2, length / 2])
    assert abs(answers["L_z"] - Lz) < mpmath.mpf("1e-14") * abs(Lz)
    # the rod's upper end leans toward +x and L_x < 0: asked as its magnitude toward the lower end's side
    assert Lx < 0 and abs(answers["L_x"] + Lx) < mpmath.mpf("1e-14") * abs(Lx)
    assert abs(answers["angle"] - (mpmath.pi / 2 - a)) < mpmath.mpf("1e-14")
    assert result["checks"]["angular_momentum_by_integral"]["passed"]
    assert result["checks"]["lagrange_vs_newton_euler"]["passed"]
