"""Documents from solutions: `derive solve`'s report (report, notation, inertia_report), a set's
build (worksheets) with its variants (variants), answer keys (answer_keys, json_text,
spreadsheet), the templates (render), figures (figure, figure_files), handouts (limiting_cases),
LaTeX and pandoc (export), the LMS exports (lms) with their multiple choice (distractors), the
output folder (output_folder) and a build's progress (progress)."""
