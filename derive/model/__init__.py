"""What a scene is, in the engine's terms: the bodies' shapes and inertia (inertia), bodies made of
parts (composite), the Scene that holds the bodies with their parts, loads, surfaces and states
(scene), the bodies that turn in 3D (solid_scene), and the planar coordinates of a scene with the
positions and velocities of its points (kinematics). No file is read here (derive.language) and
nothing is derived (derive.mechanics)."""
