"""The problems' TikZ figures as SVG and PNG images, for the outputs that cannot hold TikZ: HTML and
Markdown (SVG files beside them, figures/ID.svg), DOCX (PNG, through pandoc) and the LMS exports
(PNG files inside the Moodle XML and the Canvas zip).

A build's figures are one LaTeX document (`document`) in the worksheet's preamble, each figure a
page of its own cropped to it (the preview package's tightpage). export.pdfs compiles it with the
build's other documents, in parallel; a figure is drawn from its problem, not from a variant's
numbers, so each is compiled once however many variants show it. poppler's pdftocairo then draws
each page as SVG and as PNG (`images`, one pdftocairo per image, in parallel).

Why pdftocairo: poppler-utils is installed already (pdftotext, for the tests); one PDF gives both
images through one renderer (cairo), so the web's figures are the print figures, from the same
compile and fonts; and cairo writes each glyph as a path, so the SVG needs no font. dvisvgm would
need a DVI run of its own and gives no PNG; pdf2svg makes the same poppler and cairo calls as
`pdftocairo -svg`.

>>> image = Image("rod_endpoint", b"<svg/>", b"", 156.6)
>>> image.latex("figures/rod_endpoint.svg", "Figure of problem 1")
'\\\\includegraphics[width=156.6pt,alt={Figure of problem 1}]{figures/rod_endpoint.svg}'
>>> image.pixels, image.file("svg")
(209, 'rod_endpoint.svg')
"""
from __future__ import annotations

import base64
import subprocess
import tempfile
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Sequence

from derive.publishing import export, render

#: The outputs that show the figures as images.
OUTPUTS = frozenset({"html", "md", "docx", "moodle", "qti"})
#: The folder of the SVG files beside the HTML and the Markdown.
FOLDER = "figures"
#: The PNG's resolution: twice CSS's 96 pixels per inch, sharp on high-density screens (each <img>
#: is given the figure's printed width, `pixels`).
PNG_DPI = 192
#: pdftocairo's arguments for each image, before the page, the PDF and `-` (standard output).
FORMATS = {"svg": ["-svg"], "png": ["-png", "-singlefile", "-r", str(PNG_DPI)]}
SECONDS = 60  # for one pdftocairo run (a figure takes milliseconds)


@dataclass(frozen=True)
class Image:
    """One figure: its name (the problem's id, or a free-body diagram's `free_body_name`), its SVG
    and PNG bytes, its printed width and what it shows in words (an <img>'s alt; "": the page says)."""

    name: str
    svg: bytes
    png: bytes
    width: float  # points (1/72 inch)
    alt: str = ""

    def file(self, kind: str) -> str:
        return f"{self.name}.{kind}"

    @property
    def pixels(self) -> int:
        """The printed width in CSS pixels (96 per inch), for an <img width>."""
        return round(self.width * 96 / 72)

    def latex(self, source: str, alt: str) -> str:
        """An \\includegraphics of the figure at its printed width, for pandoc: `source` is a path
        or a data URI; `alt` becomes the image's alternative text as written (pandoc reads it
        verbatim: it must be words, with none of LaTeX's special characters)."""
        return f"\\includegraphics[width={self.width:g}pt,alt={{{alt}}}]{{{source}}}"

    def data_uri(self) -> str:
        """The PNG as a data URI: pandoc embeds it in a DOCX without reading a file (--sandbox)."""
        return "data:image/png;base64," + base64.b64encode(self.png).decode("ascii")


def free_body_name(problem: str, body: str) -> str:
    """The name of a body's free-body diagram, unlike any problem's id (which holds no `-`).

    >>> free_body_name("string_wrapped_disk", "disk")
    'string_wrapped_disk-free-body-disk'
    """
    return f"{problem}-free-body-{body}"


def document(figures: Sequence[str]) -> str:
    """The LaTeX document of the figures (tikzpicture environments), one page each."""
    return render.render("figures.tex.j2", figures=list(figures))


def images(names: Sequence[str], pdf: Path) -> dict[str, Image]:
    """Each page of the compiled `document` as an Image, by name (`names`, in the pages' order)."""
    import pikepdf

    with pikepdf.open(pdf) as compiled:
        widths = [float(page.mediabox[2] - page.mediabox[0]) for page in compiled.pages]
    if len(widths) != len(names):
        raise export.BuildError(f"{pdf.name}: {len(widths)} pages for {len(names)} figures")
    jobs = [(page, kind) for page in range(1, len(names) + 1) for kind in FORMATS]
    with ThreadPoolExecutor(max_workers=export.workers()) as pool:
        drawn = dict(zip(jobs, pool.map(lambda job: _draw(pdf, *job), jobs)))
    return {name: Image(name, drawn[page, "svg"], drawn[page, "png"], round(width, 3))
            for page, (name, width) in enumerate(zip(names, widths), start=1)}


def drawn(pictures: dict[str, str], alts: dict[str, str] | None = None) -> dict[str, Image]:
    """Each named tikzpicture as an Image, compiled on their own (one document in a scratch folder),
    outside a build: the catalogue's figures, a figure in a notebook; `alts` says what each shows."""
    if not pictures:
        return {}
    export.require("pdftocairo")
    with tempfile.TemporaryDirectory(prefix="derive-figures-") as scratch:
        tex = Path(scratch) / "figures.tex"
        tex.write_text(document(list(pictures.values())), encoding="utf-8")
        found = images(list(pictures), export.pdf(tex))
    return {name: replace(image, alt=(alts or {}).get(name, "")) for name, image in found.items()}


def _draw(pdf: Path, page: int, kind: str) -> bytes:
    """One page of a PDF as an image (pdftocairo, to standard output)."""
    command = ["pdftocairo", *FORMATS[kind], "-f", str(page), "-l", str(page), str(pdf), "-"]
    try:
        done = subprocess.run(command, capture_output=True, timeout=SECONDS, stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        raise export.BuildError(f"pdftocairo did not draw page {page} of {pdf.name} within {SECONDS} s") from None
    if done.returncode != 0 or not done.stdout:
        message = done.stderr.decode(errors="replace").strip().splitlines()
        raise export.BuildError(f"pdftocairo could not draw page {page} of {pdf.name} as {kind}: "
                                + (message[-1] if message else f"exit status {done.returncode}"))
    return done.stdout
