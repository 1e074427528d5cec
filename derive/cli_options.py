"""The command line's option types and the parsing of its values (derive.cli declares the commands):
one-line errors with exit status 2 (BadInput), a time limit, a finite number, `--set NAME=VALUE`.

>>> parse_assignments(("m=2", "M = 200 g"))
{'m': '2', 'M': '200 g'}
"""
from __future__ import annotations

import functools
import math
import os
import re

import click

from derive.core.errors import InputError


class BadInput(click.ClickException):
    """Bad input from a file or the command line: one line, exit status 2."""

    exit_code = 2

    def show(self, file=None) -> None:
        click.echo(f"derive: error: {self.format_message()}", err=True)


class Seconds(click.ParamType):
    """A time limit in seconds: 0 or off for none, else a finite number up to limits.MAX_SECONDS."""

    name = "seconds"

    def convert(self, value, param, ctx) -> float:
        from derive.core import limits  # light: no sympy

        try:
            return limits.parse(str(value), f"--time-limit {value}")
        except InputError as error:
            raise BadInput(str(error)) from None


class FiniteRange(click.FloatRange):
    """click's FloatRange, which lets nan and inf through its bounds' comparisons, without them."""

    def convert(self, value, param, ctx) -> float:
        number = super().convert(value, param, ctx)
        if not math.isfinite(number):
            self.fail(f"{value!r} is not a finite number", param, ctx)
        return number


def check_environment() -> None:
    """Refuse what the environment sets wrongly for a library derive imports: an empty or malformed
    SOURCE_DATE_EPOCH stops numpy.f2py's import (scipy's integrators import it) with a ValueError.
    derive's builds are reproducible without it (its LaTeX runs set their own)."""
    epoch = os.environ.get("SOURCE_DATE_EPOCH")
    if epoch is not None and not re.fullmatch(r"[0-9]+", epoch):
        raise BadInput(f"SOURCE_DATE_EPOCH={epoch!r}: expected a whole number of seconds since 1970; derive's builds "
                       "are the same without it: unset it (unset SOURCE_DATE_EPOCH)")


def parse_assignments(assignments: tuple[str, ...]) -> dict[str, str]:
    """`--set m=2 --set "M=200 g"` as {"m": "2", "M": "200 g"}."""
    result = {}
    for text in assignments:
        name, sep, value = text.partition("=")
        if not sep or not name.strip() or not value.strip():
            raise BadInput(f"--set {text}: expected NAME=VALUE, e.g. --set m=2 or --set \"m=200 g\"")
        result[name.strip()] = value.strip()
    return result


def derives_options(command):
    """`--jobs N` (default: the cores), `--no-cache` and `--scheduler ADDRESS`, handed to the command
    as jobs, cache and scheduler."""

    @click.option("--jobs", type=click.IntRange(1, 256), default=None, metavar="N",
                  help="Derive the problems in N processes at once (the output is the same). [default: the cores]")
    @click.option("--no-cache", "no_cache", is_flag=True,
                  help="Derive every problem again, neither reading nor writing the derivation cache "
                       "(see `derive cache --help`).")
    @click.option("--scheduler", default=None, metavar="ADDRESS",
                  help="Derive the problems on the workers of this Dask scheduler (tcp://host:8786) in place of "
                       "--jobs processes; needs derive's cluster extra (pip install 'derive[cluster]') here and the "
                       "same derive on the workers.")
    @functools.wraps(command)
    def wrapper(*args, jobs: int | None, no_cache: bool, scheduler: str | None, **kwargs):
        from derive.publishing.deriving import cores  # light: no sympy

        if scheduler is not None and jobs is not None:
            raise BadInput("--jobs and --scheduler: give one (the scheduler's workers derive in place of the processes)")
        if scheduler is not None:
            from derive.publishing.cluster import check_address  # light

            try:
                check_address(scheduler)
            except InputError as error:
                raise BadInput(str(error)) from None
        return command(*args, jobs=jobs or cores(), cache=not no_cache, scheduler=scheduler, **kwargs)

    return wrapper
