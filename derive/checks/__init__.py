"""The answers checked against numbers no closed form gave: a scene's motion integrated from a
random admissible state (simulate), a chain of states simulated link by link (chain_simulation),
and the 3D answers against a rigid body's full motion (simulate_solid). `derive check` (derive.audit)
runs them for every problem."""
