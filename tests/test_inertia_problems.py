"""The inertia problems of the library against quadrature (mpmath, 50 digits) and the notes."""
import mpmath
import pytest

from derive.language import problem
from conftest import close, solve


def test_solid_cylinder_by_quadrature():
    answers, _ = solve("solid_cylinder", R="0.3", h="0.7", rho="7800")
    R, h, rho = mpmath.mpf("0.3"), mpmath.mpf("0.7"), mpmath.mpf(7800)
    mass = mpmath.quad(lambda r: 2 * mpmath.pi * h * rho * r, [0, R])
    moment = mpmath.quad(lambda r: 2 * mpmath.pi * h * rho * r**3, [0, R])
    assert close(answers["M"], mass) and close(answers["I"], moment)
    assert close(answers["I"], answers["M"] * R**2 / 2)


def test_diatomic_molecule():
    answers, result = solve("diatomic_molecule", m1="1.674e-27", m2="2.657e-26", d="1.128e-10")
    m1, m2, d = mpmath.mpf("1.674e-27"), mpmath.mpf("2.657e-26"), mpmath.mpf("1.128e-10")
    # asked as distances from the center of mass, on either side of it
    assert close(answers["x1"], d * m2 / (m1 + m2)) and close(answers["x2"], d * m1 / (m1 + m2))
    assert close(answers["x1"] + answers["x2"], d)
    assert close(answers["mu"], m1 * m2 / (m1 + m2))
    assert result["checks"]["system_inertia"]["passed"]


def test_notes_1_2_4_second_term_is_m2_x2_squared():
    """I = m1 x1^2 + m2 x2^2 with the derived positions equals mu d^2 (the notes print m2 x^2)."""
    answers, _ = solve("diatomic_molecule", m1="2e-26", m2="3e-26", d="1.5e-10")
    assert close(answers["I"], mpmath.mpf("2e-26") * answers["x1"] ** 2 + mpmath.mpf("3e-26") * answers["x2"] ** 2, 14)
    assert close(answers["I"], answers["mu"] * mpmath.mpf("1.5e-10") ** 2, 14)
    assert problem.load("diatomic_molecule").corrections[0]["where"].startswith("§1.2.4")


@pytest.mark.parametrize("k", ["-1.5", "0", "2.5"])
def test_mass_concentration_by_quadrature(k):
    answers, _ = solve("mass_concentration", M="2", R="0.4", k=k)
    M, R, kk = mpmath.mpf(2), mpmath.mpf("0.4"), mpmath.mpf(k)
    profile = lambda r: (r / R) ** kk  # noqa: E731
    moment = M * mpmath.quad(lambda r: profile(r) * r**3, [0, R]) / mpmath.quad(lambda r: profile(r) * r, [0, R])
    assert close(answers["I_concentrated"], moment, 14)
    assert close(answers["I_ring"], M * R**2) and close(answers["I_disk"], M * R**2 / 2)
    # More mass toward the rim, more inertia: ring > disk with k > 0 > uniform disk > k < 0.
    assert (answers["I_concentrated"] > answers["I_disk"]) == (kk > 0)


def test_parallel_axis_rod_by_quadrature():
    answers, result = solve("parallel_axis_rod", M="1.2", L="0.9", h="0.35")
    M, L, h = mpmath.mpf("1.2"), mpmath.mpf("0.9"), mpmath.mpf("0.35")
    moment = mpmath.quad(lambda x: M / L * (x**2 + h**2), [-L / 2, L / 2])
    assert close(answers["I"], moment)
    assert result["checks"]["parallel_axis"]["passed"]
