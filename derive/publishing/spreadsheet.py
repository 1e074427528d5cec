"""Cells of the CSV answer key that a spreadsheet opens as text, never as a formula.

A spreadsheet reads a cell that begins with = + - @ (or a tab or a carriage return) as a formula,
which can fetch URLs or run commands (CSV injection). Such a cell gets a leading single quote,
the OWASP defence; a plain decimal number keeps its sign, so the key's values stay numeric.

>>> [safe_cell("=1+1"), safe_cell("-4.44"), safe_cell("1.2e-05"), safe_cell("-g*sin(theta)/2"), safe_cell(3)]
["'=1+1", '-4.44', '1.2e-05', "'-g*sin(theta)/2", 3]
"""
from __future__ import annotations

import re

FORMULA_START = ("=", "+", "-", "@", "\t", "\r")
_DECIMAL = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?")


def safe_cell(value: object) -> object:
    """Text that a spreadsheet would read as a formula, prefixed with a single quote; anything
    else (a number, a plain decimal such as -4.44, other text) as it is."""
    if isinstance(value, str) and value.startswith(FORMULA_START) and not _DECIMAL.fullmatch(value):
        return "'" + value
    return value
