"""A set's derivations on a Dask cluster (`derive sheet --scheduler tcp://host:8786`), for a bank
larger than one machine derives in the time wanted.

The derivations are independent, so this is the same work as the local pool's
(derive.publishing.deriving): each problem goes to a worker, which derives it and sends back the
bytes the derivation cache writes, with the `derivation_cache.engine()` it ran (derive's sources
and the versions of sympy, python-flint and Python); the parent loads them exactly as it loads a
cache entry. A worker that runs another engine is refused: its numbers could differ from this
derive's. Dask's distributed scheduler does the rest (queues, placing, a worker lost): why Dask,
and the figures for a 10,000-problem bank, are in docs/design.md ("Beyond one machine").

The cluster is trusted as Dask trusts it: its results are unpickled, so point derive only at a
scheduler of your own.

>>> check_address("tcp://10.0.0.5:8786")
'tcp://10.0.0.5:8786'
>>> check_address("10.0.0.5")
Traceback (most recent call last):
...
derive.core.errors.InputError: --scheduler 10.0.0.5: expected a Dask scheduler's address, e.g. tcp://host:8786
"""
from __future__ import annotations

import re
from collections.abc import Iterator, Sequence
from typing import TYPE_CHECKING

from derive.core.errors import InputError

if TYPE_CHECKING:  # the command line checks an address without loading sympy
    from derive.language.problem import Problem

#: How long to wait for the scheduler to answer.
CONNECT_SECONDS = 10
_ADDRESS = re.compile(r"(tcp|tls|ws|wss|ucx|inproc)://[A-Za-z0-9.\-_:\[\]/]+")


def check_address(address: str) -> str:
    """A scheduler's address as Dask writes them (PROTOCOL://host:port), else an InputError."""
    if not _ADDRESS.fullmatch(address):
        raise InputError(f"--scheduler {address}: expected a Dask scheduler's address, e.g. tcp://host:8786")
    return address


def derived(problems: Sequence[Problem], address: str) -> Iterator[tuple[int, bytes | None, None]]:
    """Each problem's derivation as the cache's bytes (None where it failed on the worker: the parent
    derives it again, to report its error), by index, as the workers finish them."""
    from derive.publishing import derivation_cache

    try:
        from distributed import Client, as_completed
    except ImportError:
        raise InputError(f"--scheduler {address}: Dask's distributed is not installed here "
                         "(pip install 'derive[cluster]')") from None
    try:
        client = Client(check_address(address), timeout=CONNECT_SECONDS, set_as_default=False)
    except (OSError, TimeoutError) as error:
        raise InputError(f"--scheduler {address}: no scheduler answered within {CONNECT_SECONDS} s ({error})") from None
    with client, client.as_current():  # Dask's own calls find this client, not a default one of the caller's
        futures = {client.submit(_derived_bytes, problem, pure=False): n for n, problem in enumerate(problems)}
        try:
            for future in as_completed(futures):
                engine, payload = future.result()
                if engine != derivation_cache.engine():
                    raise InputError(f"--scheduler {address}: its workers run another derive, sympy or python-flint "
                                     "than this one (install the same versions on them)")
                yield futures[future], payload, None
        finally:
            client.cancel(list(futures))


def _derived_bytes(problem: Problem) -> tuple[str, bytes | None]:
    """On a worker: the engine it runs and the problem's derivation as bytes (None if it failed)."""
    from derive.publishing import derivation_cache

    try:
        payload = derivation_cache.dumps(derivation_cache.derived(problem))
    except Exception:  # noqa: BLE001 - reported by the parent's own attempt
        payload = None
    return derivation_cache.engine(), payload
