"""Compiled documents kept on disk, so that a rebuild compiles only the documents whose TeX changed.

A set's PDFs are most of a warm rebuild's time (latexmk runs each document two or three times).
After one question's text is edited, the worksheet changes, but the solutions and the key often
do not, and a new seed changes every document. A document's compile reads nothing but its .tex
(export.pdf compiles a lone copy of it: every figure is inline TikZ) and the TeX programs, and
runs with a fixed date (SOURCE_DATE_EPOCH), so its PDF is a function of its text, its engine and
the programs' versions: that is the key, a SHA-256, never a file's name or time. An entry holds
the PDF and the .aux (export.variant_pages reads the worksheet's pages from it), in an entry file
of the derivation cache's folder (derive.publishing.derivation_cache: trusted only whole, under
the same cap, `derive cache clear` and `--no-cache`).

>>> import tempfile, os
>>> os.environ["DERIVE_CACHE_DIR"] = tempfile.mkdtemp()
>>> text = "\\\\documentclass{article}\\\\begin{document}x\\\\end{document}"
>>> fetch(text, "pdflatex") is None
True
>>> store(text, "pdflatex", b"%PDF-1.5 ...", b"\\\\relax")
True
>>> fetch(text, "pdflatex")
(b'%PDF-1.5 ...', b'\\\\relax')
"""
from __future__ import annotations

import functools
import hashlib
import subprocess

from derive.publishing import derivation_cache

SUFFIX = ".pdf"


@functools.lru_cache(maxsize=None)
def _versions(engine: str) -> str:
    """The first line of `latexmk --version` and of the engine's (a TeX Live of another year compiles
    to other bytes); empty where a program is missing (export.require refuses to build then)."""
    lines = []
    for program in ("latexmk", engine):
        try:
            done = subprocess.run([program, "--version"], capture_output=True, text=True, timeout=30)
        except (OSError, subprocess.TimeoutExpired):
            return ""
        lines.append(next((line for line in done.stdout.splitlines() if line.strip()), ""))
    return "\n".join(lines)


def key(text: str, engine: str) -> str:
    return hashlib.sha256(f"{_versions(engine)}\n{engine}\n{text}".encode()).hexdigest()


def fetch(text: str, engine: str) -> tuple[bytes, bytes] | None:
    """The PDF and .aux a compile of `text` by `engine` made before, None where none can be trusted."""
    payload = derivation_cache.read_entry(key(text, engine), SUFFIX)
    if payload is None:
        return None
    size, _, rest = payload.partition(b"\n")
    if not size.isdigit() or int(size) > len(rest):
        return None
    return rest[:int(size)], rest[int(size):]


def store(text: str, engine: str, pdf: bytes, aux: bytes) -> bool:
    """Keep a compile's PDF and .aux; False where the folder cannot be written."""
    return derivation_cache.write_entry(key(text, engine), b"%d\n" % len(pdf) + pdf + aux, SUFFIX)
