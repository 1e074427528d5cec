"""Progress of long commands on stderr: a rich progress bar on a terminal, one line per step
otherwise (logs, CI, pipes), nothing when silent.

A command reports single steps (`report("compiling the PDF")`) and counted tasks:

>>> report = Reporter("lines")
>>> with report.task("deriving", total=2) as begin:
...     begin("rod_endpoint")
...     begin("tugged_spool")
"""
from __future__ import annotations

import logging
import sys
from contextlib import contextmanager
from typing import Callable, Iterator

MODES = ("auto", "bar", "lines", "none")


class Reporter:
    """Where progress goes: `mode` is bar (rich), lines (stderr), none, or auto (a bar when
    stderr is a terminal, else lines)."""

    def __init__(self, mode: str = "none"):
        if mode == "auto":
            mode = "bar" if sys.stderr.isatty() else "lines"
        self.mode = mode
        self._bar = None
        self._status = None

    def __call__(self, message: str) -> None:
        """One step: a line, or the bar's (or the spinner's) current description."""
        if self.mode == "bar" and self._status is not None:
            self._status.update(message.strip())
        elif self.mode == "bar" and self._bar is not None:
            self._bar.update(self._task, description=message)
        elif self.mode != "none":
            print(message, file=sys.stderr, flush=True)

    @contextmanager
    def steps_shown(self) -> Iterator[None]:
        """While the command runs, derive's INFO log lines are shown as steps (a long derivation's
        progress: each state of a chain as it is found, derive.solution.state_answers); nothing
        when silent. Without it (`derive solve`, the API) they go nowhere."""
        if self.mode == "none":
            yield
            return
        logger, handler = logging.getLogger("derive"), _Shown(self)
        level = logger.level
        logger.addHandler(handler)
        logger.setLevel(logging.INFO)
        try:
            yield
        finally:
            logger.removeHandler(handler)
            logger.setLevel(level)

    @contextmanager
    def waiting(self, description: str) -> Iterator[None]:
        """One long step of unknown length (a derivation for `derive solve`): a spinner with its
        description and the steps it reports, gone when it ends; nothing unless the mode is bar."""
        if self.mode != "bar":
            yield
            return
        from rich.console import Console

        with Console(stderr=True).status(description) as status:
            self._status = status
            try:
                yield
            finally:
                self._status = None

    @contextmanager
    def task(self, description: str, total: int) -> Iterator[Callable[[str], None]]:
        """A task of `total` steps; the context yields `begin(detail)`, called as each step starts
        (a line names it; the bar counts the steps finished)."""
        started = 0
        if self.mode != "bar":
            def begin(detail: str) -> None:
                nonlocal started
                started += 1
                self(f"{description} {detail} ({started}/{total})")

            yield begin
            return
        from rich.console import Console
        from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

        with Progress(TextColumn("{task.description:<40}"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(),
                      console=Console(stderr=True), transient=True) as bar:
            task = bar.add_task(description, total=total)
            self._bar, self._task = bar, task

            def begin(detail: str) -> None:
                nonlocal started
                bar.update(task, completed=started, description=f"{description} {detail}")
                started += 1

            try:
                yield begin
                bar.update(task, completed=total)
            finally:
                self._bar = None


class _Shown(logging.Handler):
    """A log record as a step of the Reporter."""

    def __init__(self, report: Reporter):
        super().__init__(logging.INFO)
        self.report = report

    def emit(self, record: logging.LogRecord) -> None:
        self.report(f"  {record.getMessage()}")
