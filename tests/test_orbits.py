"""Kepler orbits: derived closed forms against a numerical integration of the orbit."""
import math
from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from conftest import copy_library, run_derive
from derive.language import problem
from derive.publishing import report
from derive.mechanics import orbits

GM, l, a = sp.symbols("GM l a", positive=True)
e = sp.Symbol("e", nonnegative=True)


def test_radial_equation_by_both_routes_and_effective_potential():
    lagrange = orbits.radial_acceleration(GM, l, "lagrange")
    newton = orbits.radial_acceleration(GM, l, "newton_euler")
    assert sp.simplify(lagrange - newton) == 0
    assert sp.simplify(lagrange - (l**2 / orbits.r**3 - GM / orbits.r**2)) == 0
    assert sp.simplify(orbits.effective_potential(GM, l) - (l**2 / (2 * orbits.r**2) - GM / orbits.r)) == 0


def test_orbit_is_a_conic_and_period_is_independent_of_e():
    conic, e_symbol = orbits.conic(GM, l)
    assert sp.simplify(conic - l**2 / GM / (1 + e_symbol * sp.cos(orbits.f))) == 0
    k = orbits.kepler(GM, a, e)
    assert e not in k["period"].free_symbols
    assert sp.simplify(k["period"] - 2 * sp.pi * sp.sqrt(a**3 / GM)) == 0
    assert sp.simplify(k["angular_momentum"] ** 2 - GM * a * (1 - e**2)) == 0


@pytest.mark.parametrize("ecc", [0.0, 0.3, 0.9])
def test_simulated_orbit_matches_period_apoapsis_and_energy(ecc):
    GMv, av = 1.0, 1.0
    k = {name: float(v.subs({GM: GMv, a: av, e: ecc})) for name, v in orbits.kepler(GM, a, e).items()}
    rp = k["periapsis"]
    vp = k["angular_momentum"] / rp

    def rhs(t, y):
        r3 = (y[0] ** 2 + y[1] ** 2) ** 1.5
        return [y[2], y[3], -GMv * y[0] / r3, -GMv * y[1] / r3]

    def back_at_periapsis(t, y):  # crossing the +x axis upward
        return y[1]
    back_at_periapsis.direction = 1

    run = solve_ivp(rhs, (0, 1.5 * k["period"]), [rp, 0, 0, vp], method="DOP853", rtol=1e-12, atol=1e-14,
                    events=back_at_periapsis, dense_output=True)
    returns = [t for t in run.t_events[0] if t > 1e-6]
    assert math.isclose(returns[0], k["period"], rel_tol=1e-8)
    radii = np.hypot(*run.sol(np.linspace(0, k["period"], 4001))[:2])
    assert math.isclose(radii.max(), k["apoapsis"], rel_tol=1e-6)
    x, y, vx, vy = run.y[:, -1]
    assert math.isclose(0.5 * (vx**2 + vy**2) - GMv / math.hypot(x, y), k["energy"], rel_tol=1e-9)


def test_earth_year():
    result = report.solve(problem.load("kepler_orbit"), {"a": "1.496e11", "e": "0.0167"}, 6)
    assert abs(float(result["answers"]["P"]["value"]) / 86400 - 365.26) < 0.05  # GM, a to 4 digits


def test_an_open_orbit_is_refused(tmp_path):
    library = copy_library(tmp_path)
    path = library / "orbits" / "kepler_orbit.yaml"
    path.write_text(path.read_text().replace("range: [0, 0.9]", "range: [0, 1.2]"))
    done = run_derive("solve", "kepler_orbit", library=library)
    assert done.returncode == 2 and "scene.orbit.eccentricity: an ellipse has 0 <= e < 1" in done.stderr


@pytest.mark.parametrize("speeds, message", [("[4.5e4, 5.2e4]", "must be bound"), ("[3.0e4, 3.5e4]", "the apoapsis")])
def test_an_orbit_from_a_periapsis_that_is_not_one_is_refused(tmp_path, speeds, message):
    """Above the escape speed at the closest point the orbit is open; below the circular speed the
    point given is the farthest, not the closest."""
    text = (Path(__file__).parent / "textbook" / "comet_from_periapsis.yaml").read_text()
    path = tmp_path / "comet.yaml"
    path.write_text(text.replace("[4.3e4, 5.0e4]", speeds))
    result = run_derive("solve", str(path))
    assert result.returncode == 2 and "scene.orbit.speed_at_periapsis" in result.stderr, result.stderr
    assert message in result.stderr
