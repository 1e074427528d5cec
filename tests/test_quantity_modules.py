"""The kinds moved onto the protocol of derive.quantities (issue 38): each module claims its own paths,
with the reader's one-line refusals, and says where its answers come from and how they are checked."""
import pytest

from derive import quantities
from derive.language.problem import load
from derive.model.scene import Quantity


@pytest.mark.parametrize("problem, path, expected", [
    ("kepler_orbit", "orbit.period", Quantity("orbit", None, "period")),
    ("diatomic_molecule", "system.reduced_mass", Quantity("system", None, "reduced_mass")),
    ("diatomic_molecule", "atom1.mass", Quantity("mass", "atom1", None)),
    ("disk_tilted_on_shaft", "disk.mass", Quantity("mass", "disk", None)),
    ("disk_tilted_on_shaft", "disk.bearings.force", Quantity("bearings", "disk", "bearings.force")),
    ("tilting_wheel", "wheel.turn.axle", Quantity("angular_impulse", "wheel", "turn.axle")),
    ("top_precession_exact", "top.nutation.frequency", Quantity("pivot_point", "top", "nutation.frequency")),
    ("tennis_racket", "book.rotation.greatest.wobble", Quantity("free_rotation", "book", "rotation.greatest.wobble")),
    ("rolling_kinetic_energy", "wheel.rolling.kinetic_energy", Quantity("rolling", "wheel", "kinetic_energy")),
    ("angular_momentum_quantization", "standing_wave.momentum", Quantity("standing_wave", None, "momentum")),
    ("circular_motion_L", "particle.acceleration.radial", Quantity("path", "particle", "acceleration.radial")),
    ("circular_motion_L", "particle.torque.z", Quantity("particle_torque", "particle", "torque.z")),
])
def test_a_module_claims_its_paths(problem, path, expected):
    assert quantities.parse(load(problem).scene, path) == expected


@pytest.mark.parametrize("problem, path, words", [
    ("kepler_orbit", "orbit.speed", "an orbit has circular_radius"),
    ("rod_endpoint", "orbit.period", "the scene has no orbit"),
    ("rod_endpoint", "system.reduced_mass", "a reduced mass is for a system of two bodies"),
    ("tennis_racket", "book.rotation.intermediate.wobble", "unstable (the tennis-racket theorem)"),
    ("disk_tilted_on_shaft", "disk.bearings.torqe.x", "did you mean"),
    ("rolling_kinetic_energy", "wheel.rolling.speed", "a rolling body has rolling.angular_velocity"),
    ("circular_motion_L", "particle.inertia", "a body on a path has"),
    ("circular_motion_L", "particle.torque", "the torque on a body on a path is a vector: ask particle.torque.x"),
    ("circular_motion_L", "particle.weight.torque.z", "the particle bears no force 'weight' (no gravity)"),
])
def test_a_module_refuses_a_path_of_its_kind_that_names_nothing(problem, path, words):
    with pytest.raises(ValueError, match=words.replace("(", r"\(").replace(")", r"\)")):
        quantities.parse(load(problem).scene, path)


def test_a_kind_whose_unit_depends_on_the_ask_leaves_the_dimension_to_the_answer():
    """An orbit's period and energy have different units: the kind has none; a torque has one."""
    assert quantities.KINDS["orbit"].unit is None and quantities.KINDS["internal_forces"].unit == "N*m"
    assert quantities.directional(Quantity("rolling", "wheel", "angular_velocity"))
    assert not quantities.directional(Quantity("rolling", "wheel", "kinetic_energy"))
