"""Names in problem files are ASCII: a look-alike character is refused with the ASCII it suggests.

Python's parser folds identifiers to Unicode's NFKC form, so a fullwidth `ｍ` in an expression
would silently mean `m`, and a parameter named `ｍ` would be a second symbol that prints like
`m`. derive refuses every non-ASCII character in a name or an expression instead, and suggests
what to write: the NFKC form (`ｍ` -> `m`), a Greek letter's name (`μ` -> `mu`, `Ω` -> `Omega`,
which derive typesets as the letter) or the letter without its accent (`é` -> `e`).

>>> suggest("ｍ*g"), suggest("μ_k"), suggest("Ω")
('m*g', 'mu_k', 'Omega')
>>> check("m_block", "a name")
>>> check("μ", "a name")
Traceback (most recent call last):
ValueError: a name must be ASCII: 'μ' (U+03BC GREEK SMALL LETTER MU): write 'mu'
"""
from __future__ import annotations

import re
import unicodedata

_GREEK = re.compile(r"GREEK (SMALL|CAPITAL) LETTER ([A-Z]+)")


def _ascii_for(character: str) -> str | None:
    folded = unicodedata.normalize("NFKC", character)
    if folded.isascii() and folded.isprintable():
        return folded
    greek = _GREEK.fullmatch(unicodedata.name(character, ""))
    if greek:
        word = greek[2].lower()
        return word if greek[1] == "SMALL" else word.capitalize()
    bare = "".join(c for c in unicodedata.normalize("NFKD", character) if not unicodedata.combining(c))
    return bare if bare.isascii() and bare.isprintable() and bare else None


def suggest(text: str) -> str | None:
    """`text` with each non-ASCII character replaced by the ASCII it stands for; None when one
    of them stands for nothing."""
    parts = [c if c.isascii() else _ascii_for(c) for c in text]
    return None if None in parts else "".join(parts)


def check(text: str, what: str) -> None:
    """Raise ValueError (one line) when `text` holds a non-ASCII character, naming it and what to
    write instead."""
    if text.isascii():
        return
    character = next(c for c in text if not c.isascii())
    described = f"{character!r} (U+{ord(character):04X} {unicodedata.name(character, 'unnamed character')})"
    better = suggest(text)
    hint = f": write {better!r}" if better else ""
    raise ValueError(f"{what} must be ASCII: {described}{hint}")
