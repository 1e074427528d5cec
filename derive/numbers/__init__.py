"""Values of exact expressions to certified digits: answers compiled into programs of arb balls
(balls), the evaluation policy that proves each value's digits or falls back to mpmath and evalf
(numeric), and the same policy for comparing two routes' numbers (agreement)."""
