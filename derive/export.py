"""Compile LaTeX to PDF with latexmk and convert it to HTML with pandoc.

latexmk runs without shell escape, stops at the first error, and on failure the
error lines of the LaTeX log are raised in a BuildError. Several documents compile
in parallel on the available cores.

>>> first_errors("x\\n./a.tex:12: Undefined control sequence.\\nl.12 \\\\foo\\n")
['./a.tex:12: Undefined control sequence.', 'l.12 \\\\foo']
"""
from __future__ import annotations

import os
import re
import shutil
import subprocess
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

LATEXMK = ["latexmk", "-pdf", "-interaction=nonstopmode", "-halt-on-error", "-file-line-error",
           "-no-shell-escape", "-quiet"]
LATEX_TIMEOUT = 300
# "! message" (TeX's own form) or "./file.tex:12: message" (with -file-line-error).
ERROR_LINE = re.compile(r"^(! |\S+\.tex:\d+: )")


class BuildError(RuntimeError):
    """A document did not compile or convert."""


def first_errors(log: str, context: int = 1) -> list[str]:
    """The lines of a LaTeX log that report the first error, with the line after each."""
    lines = log.splitlines()
    for i, line in enumerate(lines):
        if ERROR_LINE.match(line):
            return lines[i : i + 1 + context]
    return lines[-5:]


def missing_tool(name: str) -> str | None:
    """None when the tool is on PATH, else the command that installs it."""
    if shutil.which(name):
        return None
    return {
        "latexmk": "apt-get install -y --no-install-recommends texlive-latex-base texlive-latex-recommended "
        "texlive-pictures texlive-science latexmk lmodern",
    }.get(name, f"install {name}")


def pdf(tex: Path) -> Path:
    """Compile one .tex file in its own folder; return the PDF."""
    install = missing_tool("latexmk")
    if install:
        raise BuildError(f"latexmk is not installed; as root run: {install}")
    env = {**os.environ, "openin_any": "p", "openout_any": "p", "SOURCE_DATE_EPOCH": "0",
           "FORCE_SOURCE_DATE": "1"}
    done = subprocess.run([*LATEXMK, tex.name], cwd=tex.parent, env=env, capture_output=True, text=True,
                          timeout=LATEX_TIMEOUT, stdin=subprocess.DEVNULL)
    if done.returncode != 0:
        log = tex.with_suffix(".log")
        text = log.read_text(errors="replace") if log.exists() else done.stdout + done.stderr
        raise BuildError(f"{tex.name} did not compile: " + " | ".join(first_errors(text)))
    return tex.with_suffix(".pdf")


def variant_pages(tex: Path) -> dict[str, int]:
    """The absolute page of each \\markvariant{NAME} of a compiled worksheet, from its .aux."""
    aux = tex.with_suffix(".aux").read_text(encoding="utf-8", errors="replace")
    return {name: int(page) for name, page in re.findall(r"\\variantpage\{([^}]+)\}\{(\d+)\}", aux)}


def extract_pages(pdf_path: Path, first: int, last: int, out: Path) -> Path:
    """Pages first..last of a PDF as a PDF of their own (pikepdf, i.e. qpdf: a split costs
    milliseconds where compiling the pages again would cost a LaTeX run), with an /ID derived
    from the content so that the same pages give the same bytes."""
    import pikepdf

    with pikepdf.open(pdf_path) as whole, pikepdf.new() as part:
        part.pages.extend(whole.pages[first - 1:last])
        part.save(out, deterministic_id=True)
    return out


def workers() -> int:
    """How many latexmk runs at once: the cores this process may use."""
    return max(1, len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1)


def pdfs(texs: list[Path]) -> list[Path]:
    """Compile several documents in parallel, one per available core."""
    with ThreadPoolExecutor(max_workers=workers()) as pool:
        return list(pool.map(pdf, texs))


#: pandoc targets: (writer, file suffix, extra arguments). Math stays math in each: MathML in
#: HTML, $...$ in Markdown, Word equations in DOCX. No filters, and nothing from a problem file
#: reaches pandoc's options: the title is one `--metadata=title:...` argument; and pandoc runs
#: with --sandbox, so an \input or \includegraphics in the LaTeX reads no file.
PANDOC_SAFETY = ["--sandbox"]
PANDOC_TARGETS = {
    "html": ("html5", ".html", ["--standalone", "--mathml"]),
    "md": ("markdown", ".md", ["--standalone"]),
    "docx": ("docx", ".docx", []),
}


def convert(tex: Path, target: str, title: str) -> Path:
    """Convert a .tex document with pandoc to html, md or docx (see PANDOC_TARGETS)."""
    import pypandoc

    writer, suffix, extra = PANDOC_TARGETS[target]
    out = tex.with_suffix(suffix)
    try:
        pypandoc.convert_file(str(tex), writer, format="latex", outputfile=str(out),
                              extra_args=[*extra, *PANDOC_SAFETY, f"--metadata=title:{title}"])
    except (RuntimeError, OSError) as error:
        raise BuildError(f"pandoc could not convert {tex.name}: {str(error).strip().splitlines()[-1]}") from None
    return out
