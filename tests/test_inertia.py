"""Moments of inertia and tensors by integration, against independent routes: Monte Carlo in
Cartesian coordinates, other coordinate systems, limits, the parallel-axis theorem, rotations."""
import mpmath
import numpy as np
import pytest
import sympy as sp

from derive.model import inertia
from derive.core import units
from derive.core.errors import InputError
from derive.model.inertia import R1, R2, L, M, R, a, b, c, h, phi, r, x, y, z

NUMBERS = {L: 2.0, R: 1.5, R1: 0.8, R2: 1.5, h: 2.5, a: 1.0, b: 2.0, c: 3.0}  # sizes for the Monte Carlo
N = 1_000_000


def in_box(rng, half, keep=None, n=N):
    """Uniform points in the box [-half, half] (a zero half-width flattens it), kept where `keep`."""
    points = rng.uniform(-1, 1, size=(n, 3)) * np.array(half)
    return points if keep is None else points[keep(points)]


def on_circle(angle, radius, height):
    return np.column_stack([radius * np.cos(angle), radius * np.sin(angle), np.broadcast_to(height, angle.shape)])


def cone_points(rng):
    """A solid cone with its base at z = 0 (a quarter of its box: 4 N tries), moved to the mean of its points."""
    Rn, hn = NUMBERS[R], NUMBERS[h]
    points = in_box(rng, (Rn, Rn, hn / 2), n=4 * N) + [0, 0, hn / 2]
    points = points[np.hypot(points[:, 0], points[:, 1]) <= Rn * (1 - points[:, 2] / hn)]
    return points - points.mean(axis=0)


def radial(p):
    return np.hypot(p[:, 0], p[:, 1])


def distance(p):
    return np.linalg.norm(p, axis=1)


Ln, Rn, R1n, R2n, hn, an, bn, cn = (NUMBERS[s] for s in (L, R, R1, R2, h, a, b, c))
# Uniform samples of each shape: rejection in a bounding box for solids and flat regions,
# a uniform parametrization for curves and thin shells.
SAMPLERS = {
    "rod": lambda g: in_box(g, (Ln / 2, 0, 0)),
    "ring": lambda g: on_circle(g.uniform(0, 2 * np.pi, N), Rn, 0),
    "disk": lambda g: in_box(g, (Rn, Rn, 0), lambda p: radial(p) <= Rn),
    "annulus": lambda g: in_box(g, (R2n, R2n, 0), lambda p: (R1n <= radial(p)) & (radial(p) <= R2n)),
    "cylinder": lambda g: in_box(g, (Rn, Rn, hn / 2), lambda p: radial(p) <= Rn),
    "cylindrical_shell": lambda g: on_circle(g.uniform(0, 2 * np.pi, N), Rn, g.uniform(-hn / 2, hn / 2, N)),
    "sphere": lambda g: in_box(g, (Rn, Rn, Rn), lambda p: distance(p) <= Rn),
    "spherical_shell": lambda g: (lambda p: Rn * p / distance(p)[:, None])(g.normal(size=(N, 3))),
    "thick_spherical_shell": lambda g: in_box(g, (R2n,) * 3, lambda p: (R1n <= distance(p)) & (distance(p) <= R2n)),
    "plate": lambda g: in_box(g, (an / 2, bn / 2, 0)),
    "box": lambda g: in_box(g, (an / 2, bn / 2, cn / 2)),
    "cone": cone_points,
}


def numeric(expr, shape):
    return float(sp.sympify(expr).subs({M: 1, **{s: NUMBERS[s] for s in inertia.SHAPES[shape].sizes.values()}}))


def test_every_shape_has_a_sampler_and_a_planar_axis():
    assert set(SAMPLERS) == set(inertia.SHAPES) - {"point"}
    assert set(inertia.PLANAR_AXIS) == set(inertia.SHAPES)
    for shape, axis in inertia.PLANAR_AXIS.items():
        assert axis in inertia.SHAPES[shape].axes


@pytest.mark.parametrize("shape", sorted(SAMPLERS))
def test_every_axis_and_the_tensor_against_monte_carlo(shape):
    points = SAMPLERS[shape](np.random.default_rng(2024))
    for axis, (point, direction) in inertia.SHAPES[shape].axes.items():
        offset = points - [numeric(v, shape) for v in point]
        d2 = (offset**2).sum(axis=1) - (offset @ np.array(direction, float))**2
        estimate, error = d2.mean(), d2.std() / np.sqrt(len(d2))
        exact = numeric(inertia.moment_of_inertia(shape, axis).I, shape)
        assert error < 1.5e-3 * exact, (shape, axis)
        assert abs(estimate - exact) < 4 * error, (shape, axis, estimate, exact)
    squared = (points**2).sum(axis=1).mean()
    estimate = squared * np.eye(3) - points.T @ points / len(points)
    exact = np.array(inertia.tensor(shape).subs({M: 1, **NUMBERS}).tolist(), float)
    assert np.abs(estimate - exact).max() < 4e-3 * np.abs(exact).max(), (shape, estimate, exact)


def test_the_cone_center_of_mass_is_derived_a_quarter_height_above_the_base():
    base = inertia.SHAPES["cone"].coordinates[0]
    assert base[0] == z and base[1] == -h / 4 and base[2] == 3 * h / 4
    assert inertia.center_of_mass("cone") == (0, 0, 0)
    rng = np.random.default_rng(5)
    points = in_box(rng, (Rn, Rn, hn / 2)) + [0, 0, hn / 2]
    heights = points[np.hypot(points[:, 0], points[:, 1]) <= Rn * (1 - points[:, 2] / hn), 2]
    assert abs(heights.mean() - hn / 4) < 4 * heights.std() / np.sqrt(len(heights))


def test_uniform_shapes_have_their_center_of_mass_at_the_origin():
    for shape in inertia.SHAPES:
        assert inertia.center_of_mass(shape) == (0, 0, 0), shape


def test_rod_about_center_and_end_by_integration():
    assert inertia.moment_of_inertia("rod", "center").I == M * L**2 / 12
    assert inertia.moment_of_inertia("rod", "end").I == M * L**2 / 3


def test_rod_end_against_numerical_quadrature():
    # The integral of lambda x^2 from 0 to L for M = 2, L = 3, computed by mpmath.
    quadrature = mpmath.quad(lambda s: (2 / 3) * s**2, [0, 3])
    derived = inertia.moment_of_inertia("rod", "end").I.subs({M: 2, L: 3})
    assert abs(float(derived) - float(quadrature)) < 1e-12


def test_disk_diameter_in_cartesian_coordinates():
    X, Y = sp.symbols("X Y", real=True)
    half_chord = sp.sqrt(R**2 - X**2)
    cartesian = M / (sp.pi * R**2) * sp.integrate(Y**2, (Y, -half_chord, half_chord), (X, -R, R))
    assert sp.simplify(cartesian - inertia.moment_of_inertia("disk", "diameter").I) == 0


def test_sphere_in_cylindrical_coordinates():
    s, height = sp.symbols("s height", real=True)
    slices = 2 * sp.pi * sp.integrate(s**3, (s, 0, sp.sqrt(R**2 - height**2)), (height, -R, R))
    volume = 2 * sp.pi * sp.integrate(s, (s, 0, sp.sqrt(R**2 - height**2)), (height, -R, R))
    assert sp.simplify(M * slices / volume - inertia.moment_of_inertia("sphere", "symmetry").I) == 0


def test_point_mass_at_a_distance():
    d = sp.Symbol("d", positive=True)
    assert inertia.moment_of_inertia("point", "center").I == 0
    assert inertia.moment_of_inertia("point", ((d, 0, 0), (0, 0, 5))).I == M * d**2
    assert inertia.tensor("point", about=(d, 0, 0)) == sp.diag(0, M * d**2, M * d**2)


def test_thin_shapes_are_limits_of_thick_ones():
    I = {(s, ax): inertia.moment_of_inertia(s, ax).I for s, ax in [
        ("thick_spherical_shell", "symmetry"), ("spherical_shell", "symmetry"), ("sphere", "symmetry"),
        ("annulus", "symmetry"), ("annulus", "diameter"), ("ring", "symmetry"), ("ring", "diameter"),
        ("cylinder", "diameter"), ("disk", "diameter"), ("rod", "center"), ("cylindrical_shell", "diameter")]}
    thick = I["thick_spherical_shell", "symmetry"]
    assert sp.limit(thick, R1, R2) == I["spherical_shell", "symmetry"].subs(R, R2)
    assert sp.limit(thick, R1, 0) == I["sphere", "symmetry"].subs(R, R2)
    for axis in ("symmetry", "diameter"):
        assert sp.limit(I["annulus", axis], R1, R2) == I["ring", axis].subs(R, R2)
    assert sp.limit(I["cylinder", "diameter"], h, 0) == I["disk", "diameter"]
    assert sp.limit(I["cylinder", "diameter"], R, 0) == I["rod", "center"].subs(L, h)
    assert sp.limit(I["cylindrical_shell", "diameter"], h, 0) == I["ring", "diameter"]


def test_a_flattened_cone_is_a_disk_thicker_at_its_center():
    # A cone of height h -> 0 is not a uniform disk: its surface density falls linearly from the
    # center to the rim, sigma ~ 1 - r/R. (Its symmetry moment, 3/10 M R^2, does not depend on h.)
    tapered = sp.Integer(1) - r / R
    for axis in ("symmetry", "diameter"):
        cone = inertia.moment_of_inertia("cone", axis).ratio
        disk = inertia.moment_of_inertia("disk", axis, density=tapered).ratio
        assert sp.limit(cone, h, 0) == disk
    assert inertia.moment_of_inertia("cone", "symmetry").ratio != inertia.moment_of_inertia("disk", "symmetry").ratio


def test_a_cone_squeezed_to_its_axis_is_a_rod_denser_toward_the_base():
    # Cross-sections grow as the square of the distance from the apex: a rod of length h with
    # density (L/2 - x)^2 (apex at x = L/2), about a normal axis through its center of mass.
    rod = inertia.moment_of_inertia("rod", "center", density=(L / 2 - x)**2)
    about_center = sp.simplify((rod.I - rod.mass * rod.distance_from_center**2) / (rod.mass * L**2))
    cone = inertia.moment_of_inertia("cone", "diameter").ratio
    assert sp.limit(cone * R**2 / h**2, R, 0) == about_center == sp.Rational(3, 80)
    assert inertia.center_of_mass("rod", (L / 2 - x)**2) == (-L / 4, 0, 0)


def test_mass_concentration_of_the_notes():
    # §1.3: a disk with surface density ~ (r/R)^k, k > -2 (written k = K - 2 with K > 0): I/(M R^2) = (k+2)/(k+4).
    K = sp.Symbol("K", positive=True)
    k = sp.Symbol("k")
    result = inertia.moment_of_inertia("disk", "symmetry", density=(r / R)**(K - 2))
    assert sp.simplify(result.ratio - ((k + 2) / (k + 4)).subs(k, K - 2)) == 0
    assert sp.simplify(result.mass - 2 * sp.pi * R**2 / K) == 0
    assert result.ratio.subs(K, 2) == sp.Rational(1, 2)  # k = 0: the uniform disk
    assert sp.limit(result.ratio, K, sp.oo) == 1  # mass at the rim: the ring
    assert sp.limit(result.ratio, K, 0) == 0  # mass at the center


def test_density_in_cartesian_or_natural_coordinates_agree():
    natural = inertia.moment_of_inertia("sphere", "symmetry", density=r**2)
    cartesian = inertia.moment_of_inertia("sphere", "symmetry", density=x**2 + y**2 + z**2)
    assert natural.I == cartesian.I == 8 * sp.pi * R**7 / 21
    assert natural.mass == cartesian.mass == 4 * sp.pi * R**5 / 5
    assert natural.ratio == sp.Rational(10, 21)


def test_off_center_density_moves_the_center_of_mass_and_the_parallel_axis_still_holds():
    rho = 1 + x / R
    assert inertia.center_of_mass("disk", rho) == (R / 4, 0, 0)
    center_axis = inertia.moment_of_inertia("disk", ((R / 4, 0, 0), (0, 0, 1)), density=rho)
    symmetry = inertia.moment_of_inertia("disk", "symmetry", density=rho)
    assert symmetry.mass == sp.pi * R**2 and symmetry.distance_from_center == R / 4
    assert sp.simplify(inertia.parallel_axis(center_axis.I, symmetry.mass, R / 4) - symmetry.I) == 0


@pytest.mark.parametrize("density", [sp.cos(phi), x, 1 - sp.Symbol("k", positive=True) * r / R, sp.Integer(0),
                                     sp.Symbol("theta", real=True)])
def test_bad_densities_are_refused(density):
    if density == x:
        with pytest.raises(InputError, match="negative"):
            inertia.moment_of_inertia("rod", "center", density=density)
        return
    with pytest.raises(InputError):
        inertia.moment_of_inertia("disk", "symmetry", density=density)


def test_a_nonnegative_density_sympy_cannot_prove_passes_the_sample_points():
    result = inertia.moment_of_inertia("disk", "symmetry", density=1 + sp.cos(phi))
    assert result.mass == sp.pi * R**2 and result.I == sp.pi * R**4 / 2


def test_text_is_never_parsed():
    with pytest.raises(InputError):
        inertia.moment_of_inertia("disk", "symmetry", density="__import__('os')")
    with pytest.raises(InputError):
        inertia.moment_of_inertia("disk", ((0, 0, 0), ("1", 0, 0)))


def test_unknown_shapes_and_axes_are_input_errors():
    with pytest.raises(InputError, match="shape"):
        inertia.moment_of_inertia("cube", "symmetry")
    with pytest.raises(InputError, match="axes center, end"):
        inertia.moment_of_inertia("rod", "symmetry")
    with pytest.raises(InputError, match="zero"):
        inertia.moment_of_inertia("rod", ((0, 0, 0), (0, 0, 0)))


@pytest.mark.parametrize("shape, axis, point, distance", [
    ("rod", "center", (L / 2, 0, 0), L / 2),
    ("annulus", "symmetry", (R2, 0, 0), R2),
    ("cylinder", "diameter", (0, 0, h / 2), h / 2),
    ("sphere", "symmetry", (R, 0, 0), R),
    ("plate", "a", (0, b / 2, 0), b / 2),
    ("box", "c", (a / 2, b / 2, 0), sp.sqrt(a**2 + b**2) / 2),
    ("cone", "diameter", (0, 0, 3 * h / 4), 3 * h / 4),  # through the apex
])
def test_parallel_axis_theorem_against_direct_integration(shape, axis, point, distance):
    central = inertia.moment_of_inertia(shape, axis)
    shifted = inertia.moment_of_inertia(shape, (point, inertia.SHAPES[shape].axes[axis][1]))
    assert shifted.distance_from_center == distance
    assert sp.simplify(inertia.parallel_axis(central.I, M, distance) - shifted.I) == 0


@pytest.mark.parametrize("shape, point, direction", [
    ("box", (a / 2, 0, 0), (1, 1, 1)),
    ("cone", (0, 0, h / 2), (1, 0, 1)),
    ("cylindrical_shell", (R, 0, 0), (0, 1, 2)),
])
def test_tensor_about_a_point_gives_the_moment_about_any_axis_through_it(shape, point, direction):
    n = sp.Matrix(direction) / sp.sqrt(sum(d**2 for d in direction))
    about = inertia.tensor(shape, about=point)
    assert sp.simplify((n.T * about * n)[0] - inertia.moment_of_inertia(shape, (point, direction)).I) == 0
    theorem = inertia.parallel_axis_tensor(inertia.tensor(shape), M, point)
    assert sp.simplify(theorem - about) == sp.zeros(3)


CAYLEY = sp.Matrix([[2, -1, 2], [2, 2, -1], [-1, 2, 2]]) / 3  # a rotation with rational entries


def test_tensor_invariants_under_rotation():
    box = inertia.tensor("box")
    turned = inertia.composite_tensor([inertia.Part("box", M, {"side_a": a, "side_b": b, "side_c": c},
                                                    (0, 0, 0), CAYLEY)]).tensor
    assert turned == sp.simplify(CAYLEY * box * CAYLEY.T) and not turned.is_diagonal()
    assert sp.simplify(turned.trace() - box.trace()) == 0
    assert {sp.factor(v): n for v, n in turned.eigenvals().items()} == {sp.factor(v): 1 for v in box.diagonal()}


def test_principal_moments_and_axes_undo_the_rotation():
    turned = CAYLEY * inertia.tensor("box").subs({M: 12, a: 1, b: 2, c: 3}) * CAYLEY.T  # diag(13, 10, 5) turned
    moments, axes = inertia.principal(turned)
    assert sorted(moments) == [5, 10, 13]
    for moment, axis in zip(moments, axes):
        column = CAYLEY[:, [13, 10, 5].index(moment)]
        assert axis in (column, -column)


def test_principal_axes_of_a_numeric_tensor_fall_back_to_mpmath():
    irreducible = sp.Matrix([[2, 1, 0], [1, 3, 1], [0, 1, 5]])  # its characteristic cubic does not factor
    moments, axes = inertia.principal(irreducible)
    assert all(isinstance(m, sp.Float) for m in moments)
    assert np.allclose(sorted(map(float, moments)), np.linalg.eigvalsh(np.array(irreducible.tolist(), float)))
    for moment, axis in zip(moments, axes):
        assert max(abs(e) for e in irreducible * axis - moment * axis) < 1e-25


def test_composite_dumbbell_and_the_reduced_mass_of_the_notes():
    m, l = sp.symbols("m l", positive=True)
    dumbbell = inertia.composite_tensor([inertia.Part("point", m, {}, (s * l / 2, 0, 0)) for s in (-1, 1)])
    assert dumbbell.mass == 2 * m and dumbbell.center == sp.zeros(3, 1)
    assert dumbbell.tensor == sp.diag(0, m * l**2 / 2, m * l**2 / 2)
    m1, m2, d = sp.symbols("m1 m2 d", positive=True)  # §1.2.4: I = mu d^2 about the center of mass
    atoms = [inertia.Part("point", m1, {}, (0, 0, 0)), inertia.Part("point", m2, {}, (d, 0, 0))]
    molecule = inertia.composite_tensor(atoms)
    assert sp.simplify(molecule.tensor[2, 2] - m1 * m2 / (m1 + m2) * d**2) == 0
    assert sp.simplify(molecule.center[0] - m2 * d / (m1 + m2)) == 0


def test_composite_disk_with_a_rod_handle():
    md, mr, Rd, Lr = sp.symbols("m_d m_r R_d L_r", positive=True)
    disk = inertia.Part("disk", md, {"radius": Rd}, (0, 0, 0))
    reach = Rd + Lr / 2
    along_x = inertia.composite_tensor([disk, inertia.Part("rod", mr, {"length": Lr}, (reach, 0, 0))], about=(0, 0, 0))
    expected_zz = md * Rd**2 / 2 + mr * Lr**2 / 12 + mr * reach**2
    assert sp.simplify(along_x.tensor[2, 2] - expected_zz) == 0
    assert sp.simplify(along_x.tensor[0, 0] - md * Rd**2 / 4) == 0  # the rod lies on the x axis
    assert sp.simplify(along_x.center[0] - mr * reach / (md + mr)) == 0
    quarter_turn = sp.Matrix([[0, -1, 0], [1, 0, 0], [0, 0, 1]])
    along_y = inertia.composite_tensor([disk, inertia.Part("rod", mr, {"length": Lr}, (0, reach, 0), quarter_turn)],
                                       about=(0, 0, 0))
    assert sp.simplify(along_y.tensor - quarter_turn * along_x.tensor * quarter_turn.T) == sp.zeros(3)


def test_composite_spool_hub_and_two_flanges():
    mh, mf, rh, Rf, w = sp.symbols("m_h m_f r_h R_f w", positive=True)
    hub = inertia.Part("cylinder", mh, {"radius": rh, "height": w}, (0, 0, 0))
    flanges = [inertia.Part("disk", mf, {"radius": Rf}, (0, 0, s * w / 2)) for s in (-1, 1)]
    spool = inertia.composite_tensor([hub, *flanges])
    assert spool.mass == mh + 2 * mf and spool.center == sp.zeros(3, 1)
    assert sp.simplify(spool.tensor[2, 2] - (mh * rh**2 / 2 + mf * Rf**2)) == 0
    assert sp.simplify(spool.tensor[0, 0] - (mh * (3 * rh**2 + w**2) / 12 + 2 * (mf * Rf**2 / 4 + mf * w**2 / 4))) == 0
    rolling = inertia.composite_tensor([hub, *flanges], about=(Rf, 0, 0))  # about the line of contact
    assert sp.simplify(rolling.tensor[2, 2] - spool.tensor[2, 2] - (mh + 2 * mf) * Rf**2) == 0


def test_composite_parts_are_checked():
    with pytest.raises(InputError, match="negative"):
        inertia.composite_tensor([inertia.Part("disk", -1, {"radius": 1}, (0, 0, 0))])
    with pytest.raises(InputError, match="needs radius"):
        inertia.composite_tensor([inertia.Part("disk", 1, {"length": 1}, (0, 0, 0))])
    with pytest.raises(InputError, match="rotation"):
        inertia.composite_tensor([inertia.Part("disk", 1, {"radius": 1}, (0, 0, 0), 2 * sp.eye(3))])


def test_every_result_has_dimension_mass_length_squared():
    symbol_units = {M: "kg", **{s: "m" for s in (L, R, R1, R2, h, a, b, c)}}
    for name, shape in inertia.SHAPES.items():
        for axis in shape.axes:
            result = inertia.moment_of_inertia(name, axis)
            if result.I != 0:  # 0: a point mass about an axis through it
                assert units.expression_dimension(result.I, symbol_units) == {"mass": 1, "length": 2}, (name, axis)
            assert units.expression_dimension(result.ratio, symbol_units) == {}, (name, axis)
        for entry in inertia.tensor(name):
            if entry != 0:
                assert units.expression_dimension(entry, symbol_units) == {"mass": 1, "length": 2}, (name, entry)


def test_perpendicular_axis_theorem_for_planar_shapes():
    for shape in ("disk", "ring", "annulus"):
        normal = inertia.moment_of_inertia(shape, "symmetry").I
        diameter = inertia.moment_of_inertia(shape, "diameter").I
        assert sp.simplify(normal - 2 * diameter) == 0
    plate = {axis: inertia.moment_of_inertia("plate", axis).I for axis in ("symmetry", "a", "b")}
    assert sp.simplify(plate["symmetry"] - plate["a"] - plate["b"]) == 0


def test_mass_integral_gives_the_mass():
    for shape, axis in (("rod", "end"), ("disk", "symmetry"), ("ring", "diameter"), ("cone", "diameter")):
        result = inertia.moment_of_inertia(shape, axis)
        assert result.mass == M and sp.simplify(result.mass_integral.doit() - M) == 0


def test_central_moment_substitutes_body_sizes():
    m, s = sp.symbols("m s", positive=True)
    assert inertia.central_moment("disk", m, {"radius": s}) == m * s**2 / 2
    assert inertia.central_moment("cylinder", m, {"radius": s, "height": 2 * s}) == m * s**2 / 2
    assert inertia.central_moment("point", m, {}) == 0


def test_results_are_cached_for_300_variants():
    assert inertia.moment_of_inertia("rod", "end") is inertia.moment_of_inertia("rod", "end")
    k = sp.Symbol("k", positive=True)
    rho0 = sp.Symbol("rho0", positive=True)
    first = inertia.moment_of_inertia("disk", "symmetry", density=rho0 * (r / R)**k)
    for n in range(300):
        variant = inertia.moment_of_inertia("disk", "symmetry", density=rho0 * (r / R)**k)
        assert variant is first
        assert variant.I.xreplace({rho0: 1, k: 2, R: sp.Integer(1 + n)}) == sp.pi * (1 + n)**4 / 3
    assert inertia.tensor("cone", about=(0, 0, h)) is inertia.tensor("cone", about=(0, 0, h))


def test_text_is_never_parsed_by_the_inertia_api():
    import pytest

    from derive.core.errors import InputError
    with pytest.raises(InputError):
        inertia.moment_of_inertia("disk", "symmetry", density="__import__('os')")
