"""Methods whose results the object keeps, as functools.cached_property keeps a property's.

functools.lru_cache on a method keeps its results in one cache of the class, keyed by the
object: they are lost when the object is pickled (a derivation cache's entry, a worker's
result: derive.publishing.derivation_cache), and every object the method ever saw stays alive
in it. `kept` keeps them in the object's own __dict__ instead (the standard library has no
such decorator; methodtools' is a dependency for ten lines).

>>> class Square:
...     calls = 0
...     @kept
...     def of(self, n):
...         Square.calls += 1
...         return n * n
>>> s = Square()
>>> s.of(3), s.of(3), Square.calls
(9, 9, 1)
"""
from __future__ import annotations

import functools

MEMO = "_kept"  # the attribute that holds an object's kept results


def kept(method):
    """The method's results for each set of (hashable) arguments, computed once per object and
    kept in it; an exception is not kept (the next call tries again), as with lru_cache."""
    name = method.__qualname__

    @functools.wraps(method)
    def wrapper(self, *args, **kwargs):
        memo = self.__dict__.setdefault(MEMO, {})
        key = (name, args, tuple(sorted(kwargs.items())))
        if key not in memo:
            memo[key] = method(self, *args, **kwargs)
        return memo[key]

    return wrapper
