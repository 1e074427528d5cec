"""Output folders belong to the user: derive writes only what it creates, and swaps a finished
build into place so that a kill at any instant leaves the old build or the new one.

- A folder derive built holds a manifest, `.derive-build.json`, listing the files it wrote.
  A build may go into a new folder, an empty one, or one derive built before; any other
  non-empty folder is refused (`--out ~/course` never deletes the instructor's notes). In a
  folder derive built, files it did not write are kept, and never replaced.
- `--out` is resolved first: a symlink builds where it points. The current folder (or one that
  holds it) is refused, since a build replaces its folder as a whole.
- A build is made in a hidden staging folder beside the output, `.NAME.partial-PID`, and swapped
  in with one atomic exchange of the two folders (Linux renameat2 RENAME_EXCHANGE). Where the
  file system cannot exchange, the old folder is first renamed to `.NAME.old-PID`. Every build
  starts by restoring an old folder left without a build by a killed swap and by removing what
  killed builds left behind.
- A full disk, a read-only folder or a missing permission is an OutputError (one line, exit 2),
  and the staging folder is removed.

`fault(point)` is the hook of the fault-injection test: with DERIVE_FAULT_AT=POINT the process
kills itself (SIGKILL) there; `no-exchange` in that comma-separated list takes the rename path.

>>> MANIFEST
'.derive-build.json'
"""
from __future__ import annotations

import ctypes
import errno
import json
import os
import re
import shutil
import signal
import threading
import time
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator

from derive.core.library import version
from derive.core.errors import InputError

MANIFEST = ".derive-build.json"
#: OS errors that are the output folder's fault, not derive's: reported in one line, exit 2.
OUTPUT_ERRNOS = {errno.ENOSPC, errno.EDQUOT, errno.EROFS, errno.EACCES, errno.EPERM, errno.ENOTDIR, errno.EEXIST,
                 errno.ENAMETOOLONG, errno.EMLINK, errno.EFBIG}
_LEFTOVER = re.compile(r"\.(?P<name>.+)\.(?P<kind>partial|old)-(?P<pid>\d+)")


class OutputError(InputError):
    """An output folder derive may not or cannot write."""


def fault(point: str) -> None:
    """The fault-injection hook: kill this process at `point` when DERIVE_FAULT_AT names it."""
    if point in _faults():
        os.kill(os.getpid(), signal.SIGKILL)


def _faults() -> list[str]:
    return os.environ.get("DERIVE_FAULT_AT", "").split(",")


def _exchange(first: Path, second: Path) -> bool:
    """Swap two folders atomically (renameat2 RENAME_EXCHANGE); False where not supported.
    By hand through ctypes: Python's os module has no renameat2."""
    if "no-exchange" in _faults():
        return False
    try:
        renameat2 = ctypes.CDLL(None, use_errno=True).renameat2
    except (AttributeError, OSError):
        return False
    at_cwd, rename_exchange = -100, 2
    if renameat2(at_cwd, os.fsencode(first), at_cwd, os.fsencode(second), rename_exchange) == 0:
        return True
    code = ctypes.get_errno()
    if code in (errno.EINVAL, errno.ENOSYS, errno.EOPNOTSUPP):
        return False
    raise OSError(code, os.strerror(code), str(second))


def _alive(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def recover(out: Path) -> None:
    """Restore or remove what killed builds left beside `out`: an old build whose swap was cut
    between its two renames goes back into place; staging folders and old builds of processes
    that are gone are removed."""
    if not out.parent.is_dir():
        return
    leftovers = []
    for entry in out.parent.iterdir():
        match = _LEFTOVER.fullmatch(entry.name)
        if match and match["name"] == out.name and entry.is_dir() and not entry.is_symlink() \
                and not _alive(int(match["pid"])):
            leftovers.append((match["kind"], entry))
    if not out.exists():
        olds = sorted((e for kind, e in leftovers if kind == "old"), key=lambda e: e.stat().st_mtime)
        if olds:
            olds[-1].rename(out)
            leftovers = [(k, e) for k, e in leftovers if e != olds[-1]]
    for _, entry in leftovers:
        shutil.rmtree(entry, ignore_errors=True)


def _manifest(folder: Path) -> frozenset[str] | None:
    """The files a derive build in `folder` wrote; None when it is no derive build."""
    path = folder / MANIFEST
    if not path.is_file():
        return None
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
        files = data["files"]
        if not isinstance(files, list) or not all(isinstance(f, str) and "/" not in f for f in files):
            raise ValueError
    except (OSError, ValueError, KeyError, TypeError):
        raise OutputError(f"{path}: not a manifest derive can read; move the folder away or empty it") from None
    return frozenset(files)


def claim(out: str | Path) -> Path:
    """The resolved output folder, once it is known that a build may go there (see the module);
    restores or cleans what killed builds left. OutputError otherwise."""
    given = str(out)
    path = Path(out).expanduser()
    try:
        path = path.resolve()
    except (OSError, RuntimeError) as error:  # a symlink loop
        raise OutputError(f"--out {given}: cannot resolve: {error}") from None
    here = Path.cwd().resolve()
    if path == here or path in here.parents:
        raise OutputError(f"--out {given}: is the current folder or holds it; a build replaces its folder as a "
                          f"whole: give a folder of its own, such as --out {Path(given) / 'build'}")
    with output_errors(path):
        recover(path)
        if path.exists() and not path.is_dir():
            raise OutputError(f"--out {given}: is a file, not a folder")
        if path.is_dir() and any(path.iterdir()) and _manifest(path) is None:
            raise OutputError(f"--out {given}: the folder is not empty and derive did not build it; derive never "
                              "deletes files it did not write: give a new or empty folder")
    return path


@contextmanager
def output_errors(out: Path) -> Iterator[None]:
    """A full disk, a read-only folder or a missing permission as an OutputError naming `out`."""
    try:
        yield
    except OSError as error:
        if error.errno not in OUTPUT_ERRNOS:
            raise
        raise OutputError(f"{out}: cannot write the build: {error.strerror}") from None


@contextmanager
def staged(out: Path) -> Iterator[Path]:
    """A hidden staging folder beside `out` (which `claim` resolved), removed however the build
    ends; OS errors of the output folder become OutputErrors."""
    with output_errors(out):
        out.parent.mkdir(parents=True, exist_ok=True)
        staging = out.parent / f".{out.name}.partial-{os.getpid()}"
        shutil.rmtree(staging, ignore_errors=True)
        try:
            staging.mkdir()
            yield staging
        finally:
            _remove(staging)


def _remove(folder: Path, tries: int = 40) -> None:
    """rmtree, again while something still writes into the folder: under load a Ctrl-C once left
    a staging folder behind (a file landing in it while rmtree ran, which then cannot remove the
    folder itself); the tries are 25 ms apart, a second at most."""
    for _ in range(tries):
        shutil.rmtree(folder, ignore_errors=True)
        if not folder.exists():
            return
        time.sleep(0.025)


@contextmanager
def _uninterrupted() -> Iterator[None]:
    """Ctrl-C and SIGTERM wait until the enclosed renames are done (then arrive as usual)."""
    if threading.current_thread() is not threading.main_thread():  # only the main thread handles them
        yield
        return
    # Held by handlers, not by a signal mask: a signal masked in this thread would reach another
    # thread (latexmk's pool) and still interrupt this one.
    received: list[int] = []
    previous = {s: signal.signal(s, lambda signum, frame: received.append(signum))
                for s in (signal.SIGINT, signal.SIGTERM)}
    try:
        yield
    finally:
        for s, handler in previous.items():
            signal.signal(s, handler)
        for s in received:
            signal.raise_signal(s)


def _carry_over(out: Path, staging: Path, products: set[str]) -> None:
    """Files in `out` that the previous build did not write, linked into the staging folder so
    that the swap keeps them; one of them named like a new product is refused."""
    previous = _manifest(out) or frozenset()
    for entry in out.iterdir():
        if entry.name in previous or entry.name == MANIFEST:
            continue
        if entry.name in products:
            raise OutputError(f"{entry}: derive did not write this file and will not replace it; move it away")
        target = staging / entry.name
        if entry.is_dir() and not entry.is_symlink():
            shutil.copytree(entry, target, symlinks=True, copy_function=os.link)
        elif entry.is_symlink():
            os.symlink(os.readlink(entry), target)
        else:
            os.link(entry, target)


def commit(staging: Path, out: Path, products: list[Path]) -> list[Path]:
    """Make the finished `products` (files, or folders of them, in `staging`) the build at `out`, with a manifest,
    keeping the files of `out` that derive did not write; return the products' paths in `out`."""
    names = {p.name for p in products}
    if any(p.parent != staging for p in products):
        raise AssertionError("products are files of the staging folder")
    with output_errors(out):
        for entry in list(staging.iterdir()):  # scratch files that are no product
            if entry.name not in names:
                shutil.rmtree(entry) if entry.is_dir() else entry.unlink()
        (staging / MANIFEST).write_text(json.dumps({"derive": version(), "files": sorted(names)}, indent=1) + "\n",
                                        encoding="utf-8")
        if out.is_dir():
            _carry_over(out, staging, names)
        with _uninterrupted():
            fault("swap")
            if not out.exists():
                staging.rename(out)
                fault("swapped")
            elif _exchange(staging, out):
                fault("swapped")  # the old build now lies in the staging folder, removed on the way out
            else:
                old = out.with_name(f".{out.name}.old-{os.getpid()}")
                out.rename(old)
                fault("renamed-old")
                staging.rename(out)
                fault("swapped")
                shutil.rmtree(old, ignore_errors=True)
    return [out / p.name for p in products]
