"""Elroy's beanie on the old `events:` list (derive.mechanics.events, internal_turn) restated in
the general language (`states:` with `event: {turn: ...}`, tests/events_migration): every asked
quantity is the same expression, by sympy and at random draws at 30 digits. Temporary: it goes
with the old route."""
import random
from pathlib import Path

import sympy as sp

from derive import library, problem
from derive.answers import Solution

NEW = Path(__file__).parent / "events_migration"


def test_the_old_internal_turn_and_the_general_turn_give_the_same_answers():
    old = Solution(problem.load(library.find_problem("elroys_beanie")))
    new = Solution(problem.load(NEW / "elroys_beanie.yaml"))
    assert set(old.problem.asks) == set(new.problem.asks)
    assert {n: a.unit for n, a in old.problem.asks.items()} == {n: a.unit for n, a in new.problem.asks.items()}
    rename = {p.symbol: old.problem.parameters[name].symbol for name, p in new.problem.parameters.items()}
    rng = random.Random(12)
    draws = [{p.symbol: sp.Float(rng.uniform(*p.range), 30) for p in old.problem.parameters.values()}
             for _ in range(20)]
    for name in old.problem.asks:
        a, b = old.expression(name), new.expression(name).xreplace(rename)
        assert sp.simplify(a - b) == 0, (name, a, b)
        for draw in draws:
            x, y = sp.N(a.xreplace(draw), 30), sp.N(b.xreplace(draw), 30)
            assert abs(x - y) <= sp.Float("1e-25", 30) * (1 + abs(x)), (name, draw)
