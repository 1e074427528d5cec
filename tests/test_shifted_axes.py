"""Moments of inertia about shifted axes (issue 38's silently wrong case): a shift says its direction
where the direction matters, the parallel-axis check goes through the center of mass, and a body's
own sizes in its density or its shift are its own.

A rod of mass M and length L whose linear density grows from zero at end A, lambda = 2M u/L^2 with
u the distance from A: I about A is M L^2/2 and about B, the heavy end, M L^2/6; its center of mass
is 2L/3 from A (Serway & Jewett, Physics for Scientists and Engineers, ch. 10, the nonuniform rod
of linear density alpha x; Halliday, Resnick & Walker, Fundamentals of Physics, ch. 10). Each
closed form below is also checked against mpmath's quadrature of the same integral.
"""
import mpmath
import pytest

from conftest import close, refused, solve, write_problem

GRADED_ROD = """\
id: graded_rod
title: A rod whose density grows along it
topic: inertia
source: Serway & Jewett ch. 10
parameters:
  M: {meaning: mass of the rod, unit: kg, value: 1.5}
  L: {meaning: length of the rod, unit: m, value: 0.8}
scene:
  bodies:
    rod: {shape: rod, mass: M, length: L, density: (x + L/2)/L}
ask:
  I_B: {meaning: moment of inertia about the heavy end B, of: rod.inertia, axis: center, shift: SHIFT_B, unit: kg*m^2}
  I_A: {meaning: moment of inertia about the light end A, of: rod.inertia, axis: center, shift: [-L/2, 0], unit: kg*m^2}
  I_side: {meaning: moment of inertia about an axis beside the middle, of: rod.inertia, axis: center, shift: [0, L/2], unit: kg*m^2}
question: |
  A rod of mass {{ M }} and length {{ L }} has a density that grows in proportion to the distance from its end A.
"""

M, L = mpmath.mpf("1.5"), mpmath.mpf("0.8")


def _quadrature(about: mpmath.mpf, beside: mpmath.mpf = 0) -> mpmath.mpf:
    """The rod's moment about a normal axis through (about, beside), x from the middle."""
    density = lambda x: 2 * M * (x + L / 2) / L**2  # noqa: E731
    return mpmath.quad(lambda x: density(x) * ((x - about) ** 2 + beside**2), [-L / 2, L / 2])


def test_a_rod_denser_at_one_end_about_each_end_and_beside_its_middle(tmp_path):
    answers, result = solve(str(write_problem(tmp_path, GRADED_ROD.replace("SHIFT_B", "[L/2, 0]"))))
    assert close(answers["I_B"], M * L**2 / 6) and close(answers["I_B"], _quadrature(L / 2))
    assert close(answers["I_A"], M * L**2 / 2) and close(answers["I_A"], _quadrature(-L / 2))
    assert close(answers["I_side"], M * L**2 / 3) and close(answers["I_side"], _quadrature(0, L / 2))
    assert result["checks"]["parallel_axis"]["passed"]


def test_a_distance_without_a_direction_is_refused_where_the_direction_decides(tmp_path):
    """`shift: L/2` from the center of such a rod was answered M L^2/3 (across the rod) where the file
    meant its end B, M L^2/6, with every check passing."""
    stderr = refused(tmp_path, GRADED_ROD.replace("SHIFT_B", "L/2"), "ask.I_B.shift")
    assert "does not pass through its center of mass" in stderr and "shift: [L/2, 0]" in stderr


def test_the_parallel_axis_check_goes_through_the_center_of_mass(tmp_path):
    """I_cm about the parallel axis through the center of mass (2L/3 from A), plus M d^2: not the
    named axis's moment plus M h^2, which is M L^2/3 for end B, twice the right M L^2/6."""
    from derive.language import problem
    from derive.quantities.moment_of_inertia import through_center_of_mass
    from derive.solution.answers import Solution

    solution = Solution(problem.load(str(write_problem(tmp_path, GRADED_ROD.replace("SHIFT_B", "[L/2, 0]")))))
    rod = solution.scene.bodies["rod"]
    values = solution.problem.values()
    for name in ("I_B", "I_A", "I_side"):
        theorem = through_center_of_mass(solution, rod, solution.problem.asks[name])
        assert float(theorem.xreplace(values)) == pytest.approx(float(solution.expressions[name].xreplace(values)), 1e-14)
    naive = M * L**2 / 12 + M * (L / 2) ** 2  # about the middle plus M h^2: the old check's
    assert not close(naive, float(solution.expressions["I_B"].xreplace(values)), 3)


def test_a_density_in_the_rods_own_length_is_not_refused(tmp_path):
    """(x + L/2)/L was refused as "negative on the rod (at L=1, _L=1/3, x=-1/2)": the file's L
    and the rod's were tested as two numbers."""
    answers, _ = solve(str(write_problem(tmp_path, GRADED_ROD.replace("SHIFT_B", "[L/2, 0]"))))
    assert answers["I_B"] > 0


def test_a_shift_in_a_symbol_the_shape_table_also_uses_is_the_files(tmp_path):
    """A disk of radius 2R about an axis R from its center: M(2R)^2/2 + M R^2 = 3 M R^2. The file's
    R was read as the table's radius R and mapped to 2R, 6 M R^2 (stopped by the check, as an
    internal error)."""
    text = """\
id: disk_shift
title: A disk about an axis off its center
topic: inertia
parameters:
  M: {meaning: mass of the disk, unit: kg, value: 2}
  R: {meaning: half the disk's radius, unit: m, value: 0.3}
scene:
  bodies:
    disk: {shape: disk, mass: M, radius: 2*R}
ask:
  I: {meaning: moment of inertia about an axis R from the center, of: disk.inertia, axis: symmetry, shift: R, unit: kg*m^2}
question: |
  A disk of mass {{ M }} and radius twice {{ R }} turns about an axis a distance R from its center.
"""
    answers, result = solve(str(write_problem(tmp_path, text)))
    assert close(answers["I"], 3 * 2 * mpmath.mpf("0.3") ** 2) and result["checks"]["parallel_axis"]["passed"]


def test_a_uniform_rods_shift_needs_no_direction():
    answers, _ = solve("parallel_axis_rod", M="2", L="1.2", h="0.5")
    assert close(answers["I"], 2 * mpmath.mpf("1.2") ** 2 / 12 + 2 * mpmath.mpf("0.5") ** 2)
