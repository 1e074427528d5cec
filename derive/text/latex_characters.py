"""Which characters text from a problem file may hold: what the preamble's fonts can typeset.

ASCII's printable characters may always appear (newlines where a caller allows them). Beyond
ASCII, only the letters, digits, punctuation, symbols and spaces of the `SUPPORTED` ranges
(Latin, Greek, Cyrillic, Han, kana, Hangul) and the signs of `SYMBOLS`, which Latin Modern,
DejaVu Serif and Noto Serif CJK all have. Control and format characters (bidi overrides,
zero-width joiners), combining marks, private-use, unassigned and surrogate code points are
refused with a reason; so is any other script. derive.text.latex_safety applies this to every text
field and reads the LaTeX of the question.

>>> refusal("é") is None, refusal("\u202e")
(True, 'an invisible format character (a bidi override, a zero-width joiner...)')
"""
from __future__ import annotations

import unicodedata
from functools import lru_cache

from derive.core.errors import InputError


class LatexError(InputError):
    """Text from a problem file that derive will not typeset."""


#: Where text may go beyond ASCII: ranges of code points (inclusive) whose letters, digits,
#: punctuation, symbols and spaces the preamble's fonts (Latin Modern, then DejaVu Serif and
#: Noto Serif CJK) all have; tests/test_hardening.py typesets every one (Han and Hangul: samples).
SUPPORTED = (
    ("Latin-1", 0x00A0, 0x00FF), ("Latin", 0x0100, 0x024F), ("Latin", 0x1E00, 0x1EF9),
    ("Greek", 0x0370, 0x03E1), ("Greek", 0x03F0, 0x03FF), ("Greek", 0x1F00, 0x1FFE),
    ("Cyrillic", 0x0400, 0x045F), ("Cyrillic", 0x0490, 0x0491),
    ("punctuation", 0x2010, 0x2027), ("punctuation", 0x2030, 0x203E), ("superscripts", 0x2070, 0x208E),
    ("number forms", 0x2150, 0x2185), ("arrows", 0x2190, 0x21FF),
    ("CJK punctuation", 0x3000, 0x303F), ("Hiragana", 0x3041, 0x309F), ("Katakana", 0x30A0, 0x30FF),
    ("Hangul", 0x3131, 0x318E), ("Han", 0x4E00, 0x9FEA), ("Hangul", 0xAC00, 0xD7A3),
    ("fullwidth forms", 0xFF01, 0xFF9F), ("fullwidth forms", 0xFFE0, 0xFFE6),
)
#: Common signs outside those ranges: currency, letterlike and mathematical.
SYMBOLS = frozenset("€₩₴₹₽℃℉ℏℓ№™Ω∀∂∃∅∆∇∈∉∏∑−∓∗∘∙√∝∞∠∣∥∧∨∩∪∫∬∮∴∵∼≃≅≈≠≡≤≥≪≫⊂⊃⊆⊇⊕⊗⊥⋅")
SUPPORTED_TEXT = ("Latin, Greek, Cyrillic, Chinese, Japanese and Korean letters, digits, and common "
                  "punctuation and symbols")
_CATEGORY_REASONS = {
    "Cc": "a control character", "Cf": "an invisible format character (a bidi override, a zero-width joiner...)",
    "Co": "a private-use character", "Cn": "an unassigned code point", "Cs": "a lone surrogate",
    "Zl": "a line separator", "Zp": "a paragraph separator",
    "Mn": "a combining mark: write the accented letter itself", "Mc": "a combining mark", "Me": "a combining mark",
}


def describe(character: str) -> str:
    """A character as U+XXXX and its Unicode name.

    >>> describe("😀"), describe("\\t")
    ('U+1F600 GRINNING FACE', 'U+0009')
    """
    name = unicodedata.name(character, "")
    return f"U+{ord(character):04X}" + (f" {name}" if name else "")


@lru_cache(maxsize=4096)
def refusal(character: str) -> str | None:
    """Why a character may not be typeset (None: it may). ASCII's printable characters may,
    and newlines where a caller allows them."""
    if " " <= character <= "~":
        return None
    category = unicodedata.category(character)
    if category in _CATEGORY_REASONS:
        return _CATEGORY_REASONS[category]
    code = ord(character)
    if character in SYMBOLS or any(first <= code <= last for _, first, last in SUPPORTED):
        return None
    return f"not in a script the fonts cover (supported: {SUPPORTED_TEXT})"


def check_characters(text: str, newlines: bool = False) -> None:
    """Refuse the first character that may not be typeset (see `refusal`)."""
    for character in text:
        if character == "\n":
            if not newlines:
                raise LatexError("U+000A is not allowed: a line break (this text is one line)")
            continue
        reason = refusal(character)
        if reason:
            raise LatexError(f"{describe(character)} is not allowed: {reason}")
