"""`derive bench --only solution_length`: how long the students' worked solutions are.

For every library problem (the lecture notes' and the textbook setups), the number
of displayed equations in the worked solution a student reads: the student's route where it is
written (derive.solution.textbook), else the engine's (the two routes, an integral, an orbit's
equation), which is what the students read there. Printed per problem, then the median and the worst of each kind;
a one-body problem should need about eight. A figure, not a test: it says where the worked
solutions are still the machine's.

>>> lines = []
>>> counted = count(["rolling_incline"], lines.append)
>>> counted["rolling_incline"][0]
'textbook'
"""
from __future__ import annotations

import statistics
from pathlib import Path

from derive.core import library
from derive.core.errors import InputError
from derive.language.problem import load
from derive.solution.answers import Solution

def references() -> list[str]:
    """The library's problems."""
    return [p.stem for p in library.problem_files()]


def count(refs: list[str], say) -> dict[str, tuple[str, int]]:
    """Each problem's (route the students read, displayed equations), printed as it goes."""
    result = {}
    for ref in refs:
        name = Path(ref).stem
        try:
            solution = Solution(load(ref))
            student = solution.student_steps
            steps = student if student is not None else solution.steps()
        except (InputError, ValueError) as error:  # a problem the engine refuses: said, not counted
            say(f"  {name:<40} refused: {str(error)[:60]}")
            continue
        kind = "textbook" if student is not None else "engine"
        result[name] = (kind, sum(len(step.equations) for section in steps.values() for step in section))
        say(f"  {name:<40} {kind:<11} {result[name][1]:>4} equations")
    return result


def solution_length(say) -> None:
    """The figures: per problem, then the median and worst by the route the students read."""
    say("Displayed equations in the students' worked solution (issue 37: a one-body problem needs about 8):")
    counted = count(references(), say)
    for kind in ("textbook", "engine"):
        numbers = [n for k, n in counted.values() if k == kind]
        if numbers:
            worst = max((n, name) for name, (k, n) in counted.items() if k == kind)
            say(f"  {kind}: {len(numbers)} problems, median {statistics.median(numbers):g}, "
                f"worst {worst[0]} ({worst[1]})")
