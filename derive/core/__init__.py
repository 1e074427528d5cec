"""The ground every layer stands on: errors and their one-line messages (errors), names and their
spelling (names, spelling), the limits on work (limits), the expression language of problem files
(expr, ASCII names to sympy) and its units (units), exact expressions in their readable forms
(tidying; sympy's trigsimp remembering its subexpressions: trig_memo), where the library's files are (library), and the keys a file's mapping may hold,
declared once for the reader, the schema and the documentation (keys). Nothing here knows mechanics."""
