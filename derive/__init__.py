"""derive: a symbolic mechanics engine and worksheet generator for rigid-body rotation.

The package stays light to import: `derive --help` must not load sympy.
"""
__version__ = "0.1.0"
