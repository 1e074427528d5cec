"""Time limits on symbolic steps (simplification, integration, a derivation), and the bounds on a
build's work (variants, digits).

sympy is pure Python, so a SIGALRM timer interrupts it between bytecodes: `time_limit`
arms `signal.setitimer(ITIMER_REAL)` and turns the alarm into a `TimeLimitError`, an
InputError (exit 2, one line) naming the steps that were running:

    problems/x.yaml: ask.I: integrating over the disk: gave up after 2 s (limit: ...)

Steps nest. The outermost `time_limit` arms the timer for the whole of what it encloses;
inner ones only add their name to the message (so a problem's ask is bounded as a whole,
whatever steps it runs). The limit is `DERIVE_TIME_LIMIT` seconds (default 60; 0 or "off"
turns it off) or `derive --time-limit`, which calls `configure`.

Signals reach only the main thread: off it (a thread pool), `time_limit` names the step but
sets no timer, and the work runs unbounded. The alarm raises `_Alarm`, a BaseException, so
that sympy's own `except Exception` / `except ValueError` handlers cannot swallow it; the
timer repeats every half second until the outermost step ends, in case one does.

This module imports nothing heavy (the command line imports it before any command runs).

>>> with time_limit("a quick step", seconds=5):
...     sum(range(10))
45
"""
from __future__ import annotations

import math
import os
import signal
import threading
import time
from contextlib import contextmanager

from derive.core.errors import InputError

DEFAULT_SECONDS = 60.0
#: The most variants one build makes, from the command line or a set file (a course of a few
#: hundred students; a set file cannot ask for unbounded work).
MAX_VARIANTS = 1000
#: The most significant digits a value is computed to (`--digits`, `digits=`).
MAX_DIGITS = 50
ENVIRONMENT = "DERIVE_TIME_LIMIT"
_REPEAT = 0.5  # seconds between alarms once the limit has passed

_configured: float | None = None  # set by --time-limit; None: read the environment
_steps: list[str] = []  # the names of the steps running now, outermost first
_faster: list[str] = []  # the restatements known to be faster of the steps running now that have one
_armed: dict = {}  # while a timer runs: "seconds", "handler" (the previous one), "names" when fired


class TimeLimitError(InputError):
    """A symbolic step ran longer than the time limit."""


class _Alarm(BaseException):
    """Raised by the SIGALRM handler; turned into TimeLimitError by the outermost step."""


def configure(seconds: float | None) -> None:
    """Set the limit for this process (`derive --time-limit`); None: back to the environment."""
    global _configured
    _configured = seconds


def seconds() -> float | None:
    """The limit now in force, in seconds; None when there is none."""
    if _configured is not None:
        return _configured if _configured > 0 else None
    text = os.environ.get(ENVIRONMENT, "").strip().lower()
    if not text:
        return DEFAULT_SECONDS
    return parse(text, f"{ENVIRONMENT}={text}") or None


#: The longest limit (11 days): a timer cannot be armed for infinity; 0 means no limit.
MAX_SECONDS = 1e6


def parse(text: str, where: str) -> float:
    """A limit in seconds as given (`--time-limit`, DERIVE_TIME_LIMIT): 0 (or off, none, no) for no
    limit, else a number up to MAX_SECONDS; InputError naming `where` otherwise (inf, nan, -1).

    >>> parse("90", "--time-limit"), parse("off", "--time-limit")
    (90.0, 0.0)
    >>> parse("inf", "--time-limit inf")
    Traceback (most recent call last):
    derive.core.errors.InputError: --time-limit inf: expected a number of seconds up to 1000000 (0 or off: no limit)
    """
    if text.strip().lower() in ("0", "off", "none", "no"):
        return 0.0
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not 0 <= value <= MAX_SECONDS:  # NaN, negative, infinite or past a timer's reach
        raise InputError(f"{where}: expected a number of seconds up to {MAX_SECONDS:.0f} (0 or off: no limit)")
    return value


def _on_alarm(signum, frame):
    if "names" not in _armed:
        _armed["names"], _armed["faster"] = list(_steps), list(_faster)
    raise _Alarm()


def _message(names: list[str], limit: float, faster: list[str] = ()) -> str:
    shown = f"{limit:g}"
    return (f"{': '.join(names) or 'a symbolic step'}: gave up after {shown} s "
            f"(limit: {ENVIRONMENT} / --time-limit)" + (f"; faster: {faster[-1]}" if faster else ""))


@contextmanager
def time_limit(what: str, seconds: float | None = None, faster: str | None = None):
    """Run the enclosed step within the time limit (`seconds`, default the configured one).

    `what` names the step in the error. Inside another `time_limit`, only the name is added.
    `faster`: a restatement of the problem known to be faster where this step is slow, which the
    error suggests (the innermost step's that has one).

    >>> with time_limit("finding the state top", seconds=0.2, faster="start the chain at a later state"):
    ...     while True:
    ...         pass
    Traceback (most recent call last):
    ...
    derive.core.limits.TimeLimitError: finding the state top: gave up after 0.2 s (limit: ...); faster: start the chain at a later state
    """
    _steps.append(what)
    if faster:
        _faster.append(faster)
    outermost = not _armed
    limit = globals()["seconds"]() if seconds is None else (seconds if seconds > 0 else None)
    arm = outermost and limit is not None and threading.current_thread() is threading.main_thread()
    try:
        if arm:
            _armed.update(seconds=limit, handler=signal.signal(signal.SIGALRM, _on_alarm))
            signal.setitimer(signal.ITIMER_REAL, limit, _REPEAT)
        try:
            yield
        except _Alarm:
            if not arm:
                raise
            names = _armed.get("names") or list(_steps)
            raise TimeLimitError(_message(names, limit, _armed.get("faster", _faster))) from None
    finally:
        if arm:
            try:
                _disarm()
            except _Alarm:  # fired while disarming: the work is done, drop it
                _disarm()
        _steps.pop()
        if faster:
            _faster.pop()


def _disarm() -> None:
    """Stop the timer and restore the previous handler; an alarm already on its way is dropped."""
    signal.signal(signal.SIGALRM, signal.SIG_IGN)  # first: a pending alarm now does nothing
    signal.setitimer(signal.ITIMER_REAL, 0)
    handler = _armed.pop("handler", signal.SIG_DFL)
    _armed.clear()
    signal.signal(signal.SIGALRM, handler if handler is not None else signal.SIG_DFL)


def elapsed(start: float) -> float:
    """Seconds since a `time.monotonic()` reading (for messages and tests)."""
    return time.monotonic() - start
