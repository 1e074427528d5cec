"""A parameter's value and the ends of its range as a problem file writes them: an expression in the
parameter's unit (2.5, pi/6), or a number with a unit of the same dimension (25°, 250 g), converted
exactly; and the unit a value is written in, where the file gives no `unit:`.

>>> from pathlib import Path
>>> amount(Reader(Path("p.yaml")), "25°", "value", "rad")
5*pi/36
"""
from __future__ import annotations

import sympy as sp

from derive.core import units
from derive.language.reader import Reader


def amount(reader: Reader, raw, field: str, unit: str) -> sp.Expr:
    """A parameter's value or a range's end in the parameter's `unit`: an expression (2.5, pi/6), or
    a number with a unit of the same dimension, converted exactly (25°, 25 deg, 250 g for kg).

    >>> from pathlib import Path
    >>> reader = Reader(Path("p.yaml"))
    >>> amount(reader, "25°", "value", "deg"), amount(reader, "250 g", "value", "kg"), amount(reader, 3, "value", "m")
    (25, 1/4, 3)
    """
    if isinstance(raw, str):
        try:
            number, given = units.parse_quantity(raw, "")
        except units.UnitError:
            given = ""  # not a number with a unit: an expression, read below
        if given:
            try:
                return units.to_unit(number, given, unit)
            except units.UnitError as error:
                raise reader.fail(field, f"{raw}: {error}") from None
    return reader.expression(raw, field, {})


def written_unit(reader: Reader, spec: dict, field: str) -> str:
    """The unit a parameter's value (or its range's low end) is written with, where the file gives no
    `unit:` (value: 25° is in deg); refused where it is a bare number.

    >>> from pathlib import Path
    >>> written_unit(Reader(Path("p.yaml")), {"value": "25°"}, "parameters.theta")
    'deg'
    """
    written = spec["value"] if "value" in spec else (spec["range"][0] if isinstance(spec["range"], list)
                                                      and spec["range"] else None)
    try:
        _, unit = units.parse_quantity(written, "") if isinstance(written, str) else (None, "")
        unit = "deg" if unit == "°" else unit
    except units.UnitError:
        unit = ""
    if not unit:
        raise reader.fail(f"{field}.unit", "missing: give the unit (unit: kg), or write the value with one (value: 25°)")
    return unit
