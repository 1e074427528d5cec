"""A problem's typeset worked solution and figure, kept beside its derivation.

A warm rebuild (a new seed, a mended question) derives nothing again, but it used to typeset every
problem's worked solution again: its steps through sympy's printer and derive's textbook forms, and
its figure, half of such a build's time. They depend on the derivation and on the file's fields a
derivation reads (the parameters' meanings name the bodies, the ranges size the figure), never on
the question, the title or the seed: so each is kept under the derivation cache's key and what it is
("worked, LaTeX", "worked, HTML", "figure"), as JSON, in an entry file of the derivation cache's
folder (derive.publishing.derivation_cache: trusted only whole, under its cap, cleared with it,
bypassed by --no-cache). What is not JSON (a structure some future step adds) is not kept.

>>> import tempfile, os
>>> from derive.language.problem import load
>>> os.environ["DERIVE_CACHE_DIR"] = tempfile.mkdtemp()
>>> problem, made = load("rod_endpoint"), []
>>> kept(problem, "figure", lambda: made.append(1) or "\\\\draw (0,0) -- (1,0);")
'\\\\draw (0,0) -- (1,0);'
>>> kept(problem, "figure", lambda: made.append(1) or "never made"), len(made)
('\\\\draw (0,0) -- (1,0);', 1)
"""
from __future__ import annotations

import hashlib
import json
from typing import Callable, TypeVar

from derive.language.problem import Problem
from derive.publishing import derivation_cache

SUFFIX = ".json"
T = TypeVar("T")


def kept(problem: Problem, what: str, make: Callable[[], T], cache: bool = True) -> T:
    """What `make()` gives for `problem`, from the cache where it holds it, else made and kept (with
    `cache`; without it, or for a problem not read from a file's text, always made)."""
    derivation = derivation_cache.key(problem) if cache else None
    if derivation is None:
        return make()
    entry = hashlib.sha256(f"{derivation}\n{what}".encode()).hexdigest()
    payload = derivation_cache.read_entry(entry, SUFFIX)
    if payload is not None:
        try:
            return json.loads(payload)
        except ValueError:  # a trusted digest over text that is no JSON: made again, below
            pass
    made = make()
    try:
        text = json.dumps(made, ensure_ascii=False, sort_keys=True)
    except (TypeError, ValueError):
        return made
    if json.loads(text) == made:  # kept only what comes back the same (no tuples, no non-string keys)
        derivation_cache.write_entry(entry, text.encode(), SUFFIX)
    return made
