"""Derivations of a scene's motion: Lagrange's method and Newton–Euler, and what follows from them."""
