"""The problem-file language: a problem file (YAML, untrusted) read into a Problem and its Scene,
with one-line errors naming file and field. The YAML loader and the field Reader (reader); a
problem's parameters, asks and conditions (problem); its scene section (scene_file), with its
bodies (body_file), states (state_file) and 3D keys (solid_file); set files (problem_sets) and a
course's defaults, derive.toml (defaults); the JSON Schemas of problem and set files, written from
the keys each reader declares (schema). The language builds the model (derive.model) and
checks its geometry there; it never derives (derive.mechanics)."""
