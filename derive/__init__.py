"""derive: a symbolic mechanics engine and worksheet generator for rigid-body rotation.

The package stays light to import: `derive --help` must not load sympy.
"""
__version__ = "0.1.0"

#: The most variants one build makes, from the command line or a set file (a course of a few
#: hundred students; a set file cannot ask for unbounded work).
MAX_VARIANTS = 1000
