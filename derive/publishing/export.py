"""Compile LaTeX to PDF with latexmk and convert it to HTML with pandoc.

latexmk runs without shell escape, stops at the first error, and on failure the
error lines of the LaTeX log are raised in a BuildError. Several documents compile
in parallel on the available cores.

>>> first_errors("x\\n./a.tex:12: Undefined control sequence.\\nl.12 \\\\foo\\n")
['./a.tex:12: Undefined control sequence.', 'l.12 \\\\foo']
"""
from __future__ import annotations

import functools
import io
import os
import re
import shutil
import signal
import stat
import subprocess
import tempfile
import threading
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from derive.core.errors import InputError, MissingTool
from derive.publishing import leftovers, output_folder, tex_cache

LATEXMK = ["latexmk", "-interaction=nonstopmode", "-halt-on-error", "-file-line-error", "-no-shell-escape",
           "-quiet"]
#: latexmk's switch for each engine.
ENGINES = {"pdflatex": "-pdf", "lualatex": "-lualatex"}
#: Characters pdflatex typesets with the preamble's T1 Latin Modern (LaTeX's utf8 input): ASCII, the
#: Latin-1 letters and the punctuation derive itself writes. A document with any other character
#: (Greek or Cyrillic text, CJK) compiles with LuaLaTeX, whose fallback fonts cover those scripts
#: (templates/preamble.tex.j2); pdflatex stays the default because it starts about five times faster.
PDFLATEX_TEXT = frozenset(map(chr, range(32, 127))) | frozenset("\n\t") | frozenset(
    chr(c) for c in range(0xC0, 0x100) if c not in (0xD7, 0xF7)) | frozenset("§–—‘’“”…±°")
DEFAULT_TEX_TIME_LIMIT = 120.0  # seconds for one document's latexmk run, all passes
#: The name of each compile's scratch folder in the temporary folder begins with this and derive's pid.
SCRATCH = "derive-tex-"
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


#: The command that installs each external program derive runs (Debian; as root). TeX Live's
#: packages are those of scripts/install-tools that a compile needs (preview-latex-style: the
#: figures' own document, derive.publishing.figure_files).
TEX_LIVE = ("apt-get install -y --no-install-recommends texlive-latex-base texlive-latex-recommended "
            "texlive-pictures texlive-science texlive-luatex latexmk lmodern fonts-dejavu-core fonts-noto-cjk "
            "preview-latex-style")
INSTALL = {"latexmk": TEX_LIVE, "pdflatex": TEX_LIVE, "lualatex": TEX_LIVE,
           "pdftocairo": "apt-get install -y --no-install-recommends poppler-utils",
           "pandoc": "pip install pypandoc-binary (or: apt-get install -y pandoc)"}


def require(tool: str) -> None:
    """Raise MissingTool (exit status 3) with the command that installs `tool` unless it is on PATH.

    >>> require("sh")
    """
    if not shutil.which(tool):
        raise MissingTool(tool, INSTALL.get(tool, f"install {tool}"))


def engine(text: str) -> str:
    """pdflatex for a document of Latin text (PDFLATEX_TEXT), else lualatex.

    >>> engine("A disk of mass $m$, § 4"), engine("Диск массой $m$")
    ('pdflatex', 'lualatex')
    """
    return "pdflatex" if set(text) <= PDFLATEX_TEXT else "lualatex"


def tex_time_limit() -> float:
    """Seconds one document may compile: DERIVE_TEX_TIME_LIMIT, else DEFAULT_TEX_TIME_LIMIT."""
    text = os.environ.get("DERIVE_TEX_TIME_LIMIT", "").strip()
    if not text:
        return DEFAULT_TEX_TIME_LIMIT
    try:
        seconds = float(text)
    except ValueError:
        seconds = -1.0
    if not 0 < seconds < float("inf"):
        raise InputError(f"DERIVE_TEX_TIME_LIMIT={text}: expected a positive number of seconds")
    return seconds


_running: set[int] = set()  # process groups of the compiles under way
_running_lock = threading.Lock()


def _run_in_own_group(command: list[str], cwd: Path, env: dict, seconds: float) -> subprocess.CompletedProcess:
    """Run a command in a process group of its own; past `seconds` (or on any interruption) the
    whole group is killed, so that no TeX child outlives its latexmk."""
    process = subprocess.Popen(command, cwd=cwd, env=env, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True, start_new_session=True)
    with _running_lock:
        _running.add(process.pid)
    try:
        stdout, stderr = process.communicate(timeout=seconds)
    except BaseException:  # the time limit, Ctrl-C, anything: nothing of the group survives
        _kill_group(process.pid)
        process.communicate()
        raise
    finally:
        _kill_group(process.pid)  # a child left behind, if any
        with _running_lock:
            _running.discard(process.pid)
    return subprocess.CompletedProcess(command, process.returncode, stdout, stderr)


def _kill_group(group: int) -> None:
    try:
        os.killpg(group, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass


def kill_compiles() -> None:
    """Stop every compile under way (their whole process groups)."""
    with _running_lock:
        groups = list(_running)
    for group in groups:
        _kill_group(group)


def pdf(tex: Path, cache: bool = False) -> Path:
    """Compile one .tex file; return its PDF, beside it (with its .aux, for variant_pages). With
    `cache`, a document compiled before from the same text is taken from derive.publishing.tex_cache,
    and a new compile is kept there.

    The compile runs in a scratch folder of its own that holds only a copy of the .tex (every
    figure is inline TikZ), with TeX's paranoid file access (openin_any/openout_any = p: no
    absolute paths, no `..`), so TeX can write nothing but its own scratch files; and with a
    time limit (tex_time_limit), past which its whole process group is killed. The scratch folder
    is named for this process and marked as derive's (derive.leftovers): one that a kill left
    behind is removed by a later run (_sweep_scratch).
    """
    text = tex.read_text(encoding="utf-8")
    for tool in ("latexmk", engine(text)):
        require(tool)
    _sweep_scratch()
    kept = tex_cache.fetch(text, engine(text)) if cache else None
    if kept is not None:
        tex.with_suffix(".pdf").write_bytes(kept[0])
        tex.with_suffix(".aux").write_bytes(kept[1])
        return tex.with_suffix(".pdf")
    env = {**os.environ, "openin_any": "p", "openout_any": "p", "SOURCE_DATE_EPOCH": "0",
           "FORCE_SOURCE_DATE": "1"}
    seconds = tex_time_limit()
    with tempfile.TemporaryDirectory(prefix=f"{SCRATCH}{os.getpid()}-") as scratch:
        folder = Path(scratch)
        leftovers.mark(folder)
        output_folder.fault("tex-scratch")  # the fault test: killed with the scratch folder made
        (folder / tex.name).write_text(text, encoding="utf-8")
        command = [*LATEXMK, ENGINES[engine(text)], tex.name]
        try:
            done = _run_in_own_group(command, folder, env, seconds)
        except subprocess.TimeoutExpired:
            raise BuildError(f"{tex.name} did not compile within {seconds:g} s (DERIVE_TEX_TIME_LIMIT); "
                             "TeX was stopped") from None
        if done.returncode != 0:
            log = folder / tex.with_suffix(".log").name
            text = log.read_text(errors="replace") if log.exists() else done.stdout + done.stderr
            raise BuildError(f"{tex.name} did not compile: " + " | ".join(first_errors(text)))
        for suffix in (".aux", ".pdf"):
            shutil.move(folder / tex.with_suffix(suffix).name, tex.with_suffix(suffix))
    if cache:
        tex_cache.store(text, engine(text), tex.with_suffix(".pdf").read_bytes(), tex.with_suffix(".aux").read_bytes())
    return tex.with_suffix(".pdf")


@functools.cache  # once a process
def _sweep_scratch() -> None:
    """Remove the TeX scratch folders that derive runs killed outright (SIGKILL) left in the
    temporary folder (see _ended_scratch); nothing else, whatever its name."""
    for folder in Path(tempfile.gettempdir()).glob(f"{SCRATCH}*"):
        if _ended_scratch(folder):
            shutil.rmtree(folder, ignore_errors=True)


def _ended_scratch(folder: Path) -> bool:
    """Whether `folder` is the scratch folder of a derive run that has ended: named for a pid whose
    process is gone, this user's, and carrying derive's mark (or empty, or holding only a mark cut
    short: killed before marking it, or while)."""
    match = re.fullmatch(rf"{SCRATCH}(?P<pid>[1-9]\d*)-\w+", folder.name)
    process = leftovers.pid(match["pid"]) if match else None
    try:
        info = folder.lstat()
        if process is None or not stat.S_ISDIR(info.st_mode) or info.st_uid != os.getuid():
            return False
        return not leftovers.alive(process) and (leftovers.marked(folder) or leftovers.being_marked(folder)
                                                 or not any(folder.iterdir()))
    except OSError:  # gone meanwhile, or not ours to read
        return False


def variant_pages(tex: Path) -> dict[str, int]:
    """The absolute page of each \\markvariant{NAME} of a compiled worksheet, from its .aux."""
    aux = tex.with_suffix(".aux").read_text(encoding="utf-8", errors="replace")
    return {name: int(page) for name, page in re.findall(r"\\variantpage\{([^}]+)\}\{(\d+)\}", aux)}


def page_count(pdf_path: Path) -> int:
    """How many pages a PDF has (pikepdf)."""
    import pikepdf

    with pikepdf.open(pdf_path) as pdf:
        return len(pdf.pages)


def extract_pages(pdf_path: Path, first: int, last: int, out: Path) -> Path:
    """Pages first..last of a PDF as a PDF of their own (pikepdf, i.e. qpdf: a split costs
    milliseconds where compiling the pages again would cost a LaTeX run), with an /ID derived
    from the content so that the same pages give the same bytes.

    qpdf saves into memory and Python writes the file: a write error inside qpdf (a full disk)
    would abort the whole process, where Python raises an OSError.
    """
    import pikepdf

    buffer = io.BytesIO()
    with pikepdf.open(pdf_path) as whole, pikepdf.new() as part:
        part.pages.extend(whole.pages[first - 1:last])
        part.save(buffer, deterministic_id=True)
    out.write_bytes(buffer.getvalue())
    return out


def workers() -> int:
    """How many latexmk runs at once: the cores this process may use."""
    return max(1, len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1)


def pdfs(texs: list[Path], cache: bool = False) -> list[Path]:
    """Compile several documents in parallel, one per available core (each from the cache where it
    holds it: `pdf`); an error or Ctrl-C in this thread stops every compile (none keeps running in
    the pool)."""
    with ThreadPoolExecutor(max_workers=workers()) as pool:
        try:
            return list(pool.map(functools.partial(pdf, cache=cache), texs))
        except BaseException:
            pool.shutdown(wait=False, cancel_futures=True)
            kill_compiles()
            raise


#: pandoc targets: (writer, file suffix, extra arguments). Math stays math in each: MathML in
#: HTML, $...$ in Markdown, Word equations in DOCX. No filters, and nothing from a problem file
#: reaches pandoc's options: the title is one `--metadata=title:...` argument; and pandoc runs
#: with --sandbox, so an \input or \includegraphics in the LaTeX reads no file (HTML and Markdown
#: only refer to their figures' files; a DOCX's figures come as data URIs, which pandoc decodes).
PANDOC_SAFETY = ["--sandbox"]
PANDOC_TARGETS = {
    # LaTeX's center environment is a div of class center in pandoc's HTML, which its template leaves unstyled
    "html": ("html5", ".html", ["--standalone", "--mathml",
                                "--variable=header-includes:<style>div.center { text-align: center; }</style>"]),
    # without divs: pandoc's fenced divs (::: center, :::: minipage) are LaTeX's layout, noise in Markdown
    "md": ("markdown-fenced_divs-native_divs-raw_html", ".md", ["--standalone"]),
    "docx": ("docx", ".docx", []),
}


def convert(tex: str, out: Path, target: str, title: str) -> Path:
    """Convert a LaTeX document with pandoc to html, md or docx (see PANDOC_TARGETS): the file
    `out` with the target's suffix."""
    import pypandoc

    try:
        pypandoc.get_pandoc_path()
    except OSError:
        raise MissingTool("pandoc", INSTALL["pandoc"]) from None
    writer, suffix, extra = PANDOC_TARGETS[target]
    out = out.with_suffix(suffix)
    try:
        pypandoc.convert_text(tex, writer, format="latex", outputfile=str(out),
                              extra_args=[*extra, *PANDOC_SAFETY, f"--metadata=title:{title}"])
    except (RuntimeError, OSError) as error:
        raise BuildError(f"pandoc could not convert {out.name}: {str(error).strip().splitlines()[-1]}") from None
    return out


#: pandoc's HTML for an LMS: math as MathJax reads it (\( \) and \[ \]), no generated ids (a quiz
#: page holds many questions), a \section one level below the page's headings (h3).
LMS_HTML = ["--mathjax", "--section-divs", "--shift-heading-level-by=2"]


def html_sections(tex: str, mathml: bool = False) -> list[str]:
    """The body of each \\section of a LaTeX document as an HTML fragment, in order, without the
    section's own heading (pandoc, as `convert`, with LMS_HTML): what an LMS shows as a question's
    feedback, each from one section of the same document (one pandoc run for them all). `mathml`:
    the math as MathML, for a page that must show it without MathJax (derive catalogue)."""
    import lxml.html
    import pypandoc

    options = [("--mathml" if mathml and option == "--mathjax" else option) for option in LMS_HTML]
    try:
        html = pypandoc.convert_text(tex, "html5", format="latex-auto_identifiers", extra_args=[*options, *PANDOC_SAFETY])
    except (RuntimeError, OSError) as error:
        raise BuildError(f"pandoc could not convert the worked solutions: {str(error).strip().splitlines()[-1]}") from None
    fragments = []
    for section in lxml.html.fragments_fromstring(html):
        if isinstance(section, str) and not section.strip():
            continue
        if isinstance(section, str) or section.tag != "section":
            raise BuildError(f"pandoc's HTML of the worked solutions has {str(section)[:40]!r} outside a section")
        heading = section[0]
        section.text = heading.tail  # the heading goes, its tail stays
        section.remove(heading)
        for inner in section.findall(".//section"):  # subsections: their headings and content, unwrapped
            inner.drop_tag()
        fragments.append((section.text or "").lstrip() + "".join(
            lxml.html.tostring(child, encoding="unicode") for child in section))
    return fragments
