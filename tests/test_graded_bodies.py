"""Bodies whose density is not uniform (issue 38: silently wrong, and wrongly refused).

A rod of mass M and length L whose linear density grows from zero at end A, lambda = 2 M u / L^2
with u the distance from A: by integration, I_A = M L^2/2, I_B = M L^2/6 (B the heavy end), its
center of mass 2L/3 from A and I_cm = M L^2/18 (Serway & Jewett, Physics for Scientists and
Engineers, ch. 10, the rod of linear density alpha x; Kleppner & Kolenkow, An Introduction to
Mechanics, ch. 7, the moment of inertia by integration). Hung from A it is a physical pendulum,
T = 2 pi sqrt(I_A / (M g d)) with d = 2L/3, so T = 2 pi sqrt(3L/(4g)) (Serway & Jewett ch. 15, the
physical pendulum). Each closed form is also checked against mpmath's quadrature of the integral.
"""
import mpmath
import pytest

from conftest import close, refused, run_derive, solve, write_problem

M, L, G = mpmath.mpf("1.5"), mpmath.mpf("0.8"), mpmath.mpf("9.81")

GRADED = """\
id: graded_ends
title: A rod whose density grows from its end A
topic: inertia
source: Serway & Jewett ch. 10
parameters:
  M: {meaning: mass of the rod, unit: kg, value: 1.5}
  L: {meaning: length of the rod, unit: m, value: 0.8}
scene:
  bodies:
    rod: {shape: rod, mass: M, length: L, density: (x + L/2)/L}
ask:
  I_A: {meaning: moment of inertia about end A, of: rod.inertia, end: start, unit: kg*m^2}
  I_B: {meaning: moment of inertia about end B, of: rod.inertia, end: far, unit: kg*m^2}
  I_cm: {meaning: moment of inertia about the center of mass, of: rod.inertia, unit: kg*m^2}
question: |
  A rod of mass {{ M }} and length {{ L }} has a density that grows in proportion to the distance from its end A.
"""


def _about(u0: mpmath.mpf, slope=None) -> mpmath.mpf:
    """The rod's moment about a normal axis at distance u0 from A, u from A; density 2M u/L^2, or
    proportional to 1 + slope (u - L/2)/L and scaled to M."""
    profile = (lambda u: u) if slope is None else (lambda u: 1 + slope * (u - L / 2) / L)
    scale = M / mpmath.quad(profile, [0, L])
    return mpmath.quad(lambda u: scale * profile(u) * (u - u0) ** 2, [0, L])


def test_each_end_and_the_center_of_mass_of_a_rod_denser_at_one_end(tmp_path):
    answers, result = solve(str(write_problem(tmp_path, GRADED)))
    assert close(answers["I_A"], M * L**2 / 2) and close(answers["I_A"], _about(0))
    assert close(answers["I_B"], M * L**2 / 6) and close(answers["I_B"], _about(L))
    assert close(answers["I_cm"], M * L**2 / 18) and close(answers["I_cm"], _about(2 * L / 3))
    assert result["checks"]["parallel_axis"]["passed"] and result["checks"]["tensor_vs_integral"]["passed"]


def test_the_parallel_axis_check_of_a_named_axis_is_the_bodys_own(tmp_path):
    """axis: end of the graded rod: I_cm (M L^2/18) + M (2L/3)^2 = M L^2/2; it had compared the uniform
    rod's M L^2/12 + M L^2/4 with the uniform rod's integral, which says nothing of this body."""
    from derive.language import problem
    from derive.quantities.moment_of_inertia import parallel_axis_check, through_center_of_mass
    from derive.solution.answers import Solution

    text = GRADED.replace("end: start", "axis: end")
    solution = Solution(problem.load(str(write_problem(tmp_path, text))))
    check = parallel_axis_check(solution, solution.problem.asks["I_A"])
    assert check.passed and "center of mass" in check.detail
    theorem = through_center_of_mass(solution, solution.scene.bodies["rod"], solution.problem.asks["I_A"])
    assert close(mpmath.mpf(str(theorem.xreplace(solution.problem.values()).evalf(30))), M * L**2 / 2)


@pytest.mark.parametrize("joint", ["joint: {pivot: {distance: 2*L/3}}}",
                                   "angle: -pi/2, at: [0, -2*L/3]}\n  joints:\n    hinge: {pin: rod.start}"])
def test_a_rod_denser_at_one_end_swinging_from_its_light_end(tmp_path, joint):
    """The body turns about its center of mass (M L^2/18), not its middle (M L^2/12); its point start
    lies 2L/3 from its center of mass. Both were silently wrong: T = 2 pi sqrt(2L/(3g)), checks passing."""
    text = f"""\
id: graded_pendulum
title: A graded rod swinging from its light end
topic: torque
parameters:
  M: {{meaning: mass of the rod, unit: kg, value: 1.5}}
  L: {{meaning: length of the rod, unit: m, value: 0.8}}
  g: {{meaning: gravitational acceleration, unit: m/s^2, value: 9.81}}
scene:
  bodies:
    rod: {{shape: rod, mass: M, length: L, density: (x + L/2)/L, {joint}
  loads:
    - gravity: g
ask:
  T: {{meaning: period of small oscillations, of: small_oscillation.period, unit: s}}
question: |
  A rod of mass {{{{ M }}}} and length {{{{ L }}}}, denser toward its lower end, swings from its light end.
"""
    answers, _ = solve(str(write_problem(tmp_path, text)))
    assert close(answers["T"], 2 * mpmath.pi * mpmath.sqrt(3 * L / (4 * G)))
    assert close(answers["T"], 2 * mpmath.pi * mpmath.sqrt(_about(0) / (M * G * 2 * L / 3)))


@pytest.mark.parametrize("change, field, words", [
    ("end: far, unit", "ask.I_B.end", "leave axis: out"),  # both axis: and end:
    ("end: middle, unit", "ask.I_A.end", "expected start or far"),
])
def test_an_end_is_named_once_and_rightly(tmp_path, change, field, words):
    text = GRADED.replace("end: far, unit", "axis: center, end: far, unit") if "far" in change else \
        GRADED.replace("end: start, unit", change)
    assert words in refused(tmp_path, text, field)


def test_an_end_is_a_rods(tmp_path):
    text = GRADED.replace("shape: rod, mass: M, length: L, density: (x + L/2)/L", "shape: disk, mass: M, radius: L")
    text = text.replace("  I_B: {meaning: moment of inertia about end B, of: rod.inertia, end: far, unit: kg*m^2}\n", "")
    assert "end of a rod" in refused(tmp_path, text, "ask.I_A.end")


def test_a_distance_alone_from_an_end_is_refused(tmp_path):
    text = GRADED.replace("end: far, unit", "end: far, shift: L/4, unit")
    assert "[dx, dy]" in refused(tmp_path, text, "ask.I_B.shift")


LINEAR = """\
id: linear_rod
title: A rod whose density changes linearly along it
topic: inertia
source: Serway & Jewett ch. 10
parameters:
  M: {meaning: mass of the rod, unit: kg, value: 1.5}
  L: {meaning: length of the rod, unit: m, value: 0.8}
  k: {meaning: slope of the density profile, unit: "1", range: [0.5, HIGH], sig_figs: 2}
scene:
  bodies:
    rod: {shape: rod, mass: M, length: L, density: 1 + k*x/L}
ask:
  I_A: {meaning: moment of inertia about end A, of: rod.inertia, end: start, unit: kg*m^2}
question: |
  A rod of mass {{ M }} and length {{ L }} has a density proportional to 1 + k x/L, x from its middle, with k = {{ k }}.
"""


def test_a_density_positive_over_the_declared_range_is_taken(tmp_path):
    """1 + k x/L is positive on the rod for k < 2: it was refused as "negative on the rod (at L=1, k=3,
    x=-1/2)", k = 3 lying outside the file's range. By integration I_A = M L^2 (4 + k)/12."""
    answers, _ = solve(str(write_problem(tmp_path, LINEAR.replace("HIGH", "1.5"))), k="1.2")
    k = mpmath.mpf("1.2")
    assert close(answers["I_A"], M * L**2 * (4 + k) / 12) and close(answers["I_A"], _about(0, k))


def test_a_density_negative_inside_the_declared_range_is_refused_where_it_is(tmp_path):
    stderr = refused(tmp_path, LINEAR.replace("HIGH", "3"), "scene.bodies.rod.density")
    assert "negative on the rod where x=-L/2, k=19/8" in stderr  # 1 - 19/16 < 0, k inside [0.5, 3]


def test_a_value_outside_the_range_a_density_was_proven_over_is_refused(tmp_path):
    done = run_derive("solve", str(write_problem(tmp_path, LINEAR.replace("HIGH", "1.5"))), "--set", "k=3")
    assert done.returncode == 2 and "--set k=3: outside k's range" in done.stderr
