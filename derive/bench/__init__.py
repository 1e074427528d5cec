"""`derive bench`: the benchmarks (runs): evaluation methods, answer keys, a set build, mechanics
alone, integrators; derive against sympy.physics.mechanics (engines) on the same scenes written
with KanesMethod (anchors), some of them from problem files of their own (scenes/)."""
