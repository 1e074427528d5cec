"""Moments of inertia by integration, against independent routes."""
import mpmath
import numpy as np
import sympy as sp

from derive import inertia
from derive.inertia import L, M, R


def test_rod_about_center_and_end_by_integration():
    assert inertia.moment_of_inertia("rod", "center").I == M * L**2 / 12
    assert inertia.moment_of_inertia("rod", "end").I == M * L**2 / 3


def test_rod_end_by_parallel_axis_equals_integration():
    central = inertia.moment_of_inertia("rod", "center").I
    end = inertia.moment_of_inertia("rod", "end")
    assert end.distance_from_center == L / 2
    assert sp.simplify(inertia.parallel_axis(central, M, end.distance_from_center) - end.I) == 0


def test_rod_end_against_numerical_quadrature():
    # The integral of lambda x^2 from 0 to L for M = 2, L = 3, computed by mpmath.
    quadrature = mpmath.quad(lambda x: (2 / 3) * x**2, [0, 3])
    derived = inertia.moment_of_inertia("rod", "end").I.subs({M: 2, L: 3})
    assert abs(float(derived) - float(quadrature)) < 1e-12


def test_disk_against_monte_carlo_in_cartesian_coordinates():
    # Uniform points in the unit square, kept inside the unit disk: mean of x^2 + y^2 is I/(M R^2).
    points = np.random.default_rng(1).uniform(-1, 1, size=(400_000, 2))
    r2 = (points**2).sum(axis=1)
    estimate = r2[r2 <= 1].mean()
    assert abs(estimate - 0.5) < 2e-3
    assert inertia.moment_of_inertia("disk", "symmetry").ratio == sp.Rational(1, 2)
    assert inertia.moment_of_inertia("ring", "symmetry").ratio == 1


def test_perpendicular_axis_theorem_for_planar_shapes():
    for shape in ("disk", "ring"):
        normal = inertia.moment_of_inertia(shape, "symmetry").I
        diameter = inertia.moment_of_inertia(shape, "diameter").I
        assert sp.simplify(normal - 2 * diameter) == 0


def test_mass_integral_gives_the_mass():
    for shape, axis in (("rod", "end"), ("disk", "symmetry"), ("ring", "diameter")):
        assert sp.simplify(inertia.moment_of_inertia(shape, axis).mass_integral.doit() - M) == 0


def test_central_moment_substitutes_body_sizes():
    m, a = sp.symbols("m a", positive=True)
    assert inertia.central_moment("disk", m, {"radius": a}) == m * a**2 / 2
    assert inertia.central_moment("point", m, {}) == 0


def test_results_are_cached():
    assert inertia.moment_of_inertia("rod", "end") is inertia.moment_of_inertia("rod", "end")
