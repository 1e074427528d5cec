"""A problem solved: its Solution, each ask's exact expression, lazily (answers), with the mixins
that give its conditions per variant (answer_conditions), its worked steps (answer_steps), the
asks in a state of a chain (state_answers, state_events, state_conditions, start_regimes), the
bodies that turn in 3D (solid_answers) and the checks every solve runs: Lagrange against
Newton–Euler, dimensions, parallel axis (crosschecks, solid_checks)."""
