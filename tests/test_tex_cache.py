"""A rebuild compiles only the documents whose TeX changed (issue 40: one question's text edited, a
set rebuilt with its PDFs): a PDF compiled before comes from the cache (derive.publishing.tex_cache),
the same bytes as a compile; a damaged entry is compiled again; --no-cache keeps none."""
import os
import shutil
import stat
from pathlib import Path

import pytest

from conftest import copy_library, run_derive

PROBLEMS = ("rod_endpoint", "string_wrapped_disk")


def _build(out: Path, *options: str, library: Path | None = None, env: dict | None = None):
    done = run_derive("sheet", *PROBLEMS, "--variants", "2", "--seed", "5", "--to", "pdf", "--out", str(out),
                      *options, library=library, env=env)
    assert done.returncode == 0, done.stderr
    return {p.name: p.read_bytes() for p in out.glob("*.pdf")}


def _entries() -> list[Path]:
    return sorted(Path(os.environ["DERIVE_CACHE_DIR"]).glob("*.pdf"))


def _no_tex(folder: Path) -> dict:
    """A PATH whose latexmk answers --version as the real one does and fails any compile: a build that
    succeeds with it compiled nothing."""
    folder.mkdir()
    fake = folder / "latexmk"
    fake.write_text(f'#!/bin/sh\n[ "$1" = "--version" ] && exec {shutil.which("latexmk")} "$@"\nexit 1\n')
    fake.chmod(fake.stat().st_mode | stat.S_IEXEC)
    return {"PATH": f"{folder}{os.pathsep}{os.environ['PATH']}"}


def test_a_rebuild_takes_every_pdf_from_the_cache_byte_for_byte(tmp_path):
    first = _build(tmp_path / "first")
    assert len(_entries()) == 3  # the worksheet, the solutions, the key
    again = _build(tmp_path / "again", env=_no_tex(tmp_path / "bin"))
    assert again == first and "worksheet-1.pdf" in again  # each student's pages, split from the cached worksheet


def test_an_edited_question_compiles_only_the_documents_it_changes(tmp_path):
    library = copy_library(tmp_path)
    first = _build(tmp_path / "first", library=library)
    disk = library / "torque" / "string_wrapped_disk.yaml"
    disk.write_text(disk.read_text().replace("A block of mass", "A small block of mass"))
    second = _build(tmp_path / "second", library=library)
    changed = [name for name in ("worksheet.tex", "solutions.tex", "key.tex")
               if (tmp_path / "first" / name).read_bytes() != (tmp_path / "second" / name).read_bytes()]
    assert "worksheet.tex" in changed and len(changed) < 3
    assert len(_entries()) == 3 + len(changed)  # one new entry for each document whose TeX changed
    assert all(second[name] == first[name] for name in ("solutions.pdf", "key.pdf")
               if name.replace(".pdf", ".tex") not in changed)


def test_a_damaged_entry_is_compiled_again_and_no_cache_keeps_none(tmp_path):
    first = _build(tmp_path / "first")
    for entry in _entries():
        entry.write_bytes(entry.read_bytes()[:-100])  # cut short: its digest no longer matches
    with pytest.raises(AssertionError):  # not trusted: the build needs TeX again
        _build(tmp_path / "cut", env=_no_tex(tmp_path / "bin"))
    assert _build(tmp_path / "again") == first
    for entry in _entries():
        entry.unlink()
    _build(tmp_path / "uncached", "--no-cache")
    assert _entries() == []


def test_worked_solutions_and_figures_typeset_once_for_their_derivation(tmp_path):
    """A new seed typesets no worked solution or figure again (derive.publishing.typeset_cache): the
    same LaTeX as a build without the cache; a damaged entry is typeset again."""
    def sheet(out: str, *options: str) -> str:
        done = run_derive("sheet", *PROBLEMS, "--variants", "2", "--seed", "5", "--to", "", "--out",
                          str(tmp_path / out), *options)
        assert done.returncode == 0, done.stderr
        return (tmp_path / out / "solutions.tex").read_text()

    uncached = sheet("uncached", "--no-cache")
    first = sheet("first")
    kept = sorted(Path(os.environ["DERIVE_CACHE_DIR"]).glob("*.json"))
    assert len(kept) == 2 * len(PROBLEMS)  # each problem's worked solution (LaTeX) and figure
    assert sheet("again") == first == uncached
    for entry in kept:
        entry.write_bytes(entry.read_bytes()[:-5])
    assert sheet("damaged") == uncached
