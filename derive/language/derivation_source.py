"""What a derivation reads of a problem file: its fields but the text no derivation reads (the
question, title, topic, source, corrections, difficulty and tags), as JSON with sorted keys. The
derivation cache keys its entries by it (derive.publishing.derivation_cache), so that a new question
text or a new seed derives nothing again, and a changed scene, ask or range does.

>>> of({"question": "Find a.", "scene": {1: [True, None, 0.5]}})
'{"scene": {"1": [true, null, 0.5]}}'
"""
from __future__ import annotations

import json

TEXT_ONLY = ("question", "title", "topic", "source", "corrections", "difficulty", "tags")  # fields no derivation reads


def of(raw: dict) -> str:
    """The problem file's parsed YAML without TEXT_ONLY, as canonical JSON."""
    return json.dumps(_canonical({k: v for k, v in raw.items() if k not in TEXT_ONLY}), sort_keys=True,
                      ensure_ascii=False)


def _canonical(raw):
    """Parsed YAML as JSON writes it (keys as text; anything else by its repr), for a stable digest."""
    if isinstance(raw, dict):
        return {str(k): _canonical(v) for k, v in raw.items()}
    if isinstance(raw, (list, tuple)):
        return [_canonical(v) for v in raw]
    return raw if isinstance(raw, (str, int, float, bool, type(None))) else repr(raw)
