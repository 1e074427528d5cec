"""Words and math as they are printed: what text from a problem file may hold and how TeX reads it
(latex_characters, latex_grammar, latex_safety), text and sympy as LaTeX (latex) in the textbook's
grouping (printed_form) or for a terminal (terminal), long equations cut into lines (typesetting),
sentences of words and math (prose), and text cut once at its holes (stencil)."""
