"""Output folders belong to the user: derive removes or replaces only what it can prove it wrote,
and swaps a finished build into place so that a kill at any instant leaves the old build or the
new one.

- A folder derive built holds a manifest, `.derive-build.json`, listing the files it wrote with
  the sha256 of each (of each file inside a folder it wrote). A build may go into a new folder,
  an empty one, or one derive built before; any other non-empty folder is refused (`--out
  ~/course` never deletes the instructor's notes). In a folder derive built, a file is derive's
  only while its content is the one the manifest records: a file the user added or changed, or
  one that a manifest without hashes (an older derive's, or one copied in) lists, is kept, and
  never replaced: a build with a product of its name is refused.
- `--out` is resolved first: a symlink builds where it points. The current folder (or one that
  holds it) is refused, since a build replaces its folder as a whole; so is an empty name.
- One build at a time writes a folder: from start to end a build holds an advisory lock (flock)
  on `.NAME.lock` beside it, and another build of that folder refuses at once. The lock file
  carries derive's mark (derive.leftovers) and is removed at the end; a killed build's lock file
  locks nothing (a flock ends with its process) and is removed by the next build.
- A build is made in a hidden staging folder beside the output, `.NAME.partial-PID`, marked as
  derive's, and swapped in with one atomic exchange of the two folders (Linux renameat2
  RENAME_EXCHANGE). Where the file system cannot exchange, the old folder is first renamed to
  `.NAME.old-PID`.
- Every build starts, under the lock, by recovering what killed builds left beside its folder,
  and only what it can prove derive's: an old build left without a build by a killed swap goes
  back into place when its manifest proves it a derive build; a staging folder carrying derive's
  mark, or a left folder each of whose files its manifest proves derive's or is the very file
  (hard link) the build folder holds, is removed. Another folder merely named so is left alone,
  with a warning.
- A full disk, a read-only folder, a missing permission or any OS error on the output's own path
  is an OutputError naming --out (one line, exit 2), and the staging folder is removed.

`fault(point)` is the hook of the fault-injection test: with DERIVE_FAULT_AT=POINT the process
kills itself (SIGKILL) there; `no-exchange` in that comma-separated list takes the rename path.

>>> MANIFEST
'.derive-build.json'
"""
from __future__ import annotations

import ctypes
import errno
import fcntl
import hashlib
import json
import os
import re
import shutil
import signal
import stat
import sys
import threading
import time
from contextlib import contextmanager, suppress
from pathlib import Path
from typing import Iterator, NamedTuple

from derive.core.library import version
from derive.core.errors import InputError
from derive.publishing import leftovers

MANIFEST = ".derive-build.json"
#: OS errors that are the output folder's fault, not derive's: reported in one line, exit 2.
OUTPUT_ERRNOS = {errno.ENOSPC, errno.EDQUOT, errno.EROFS, errno.EACCES, errno.EPERM, errno.ENOTDIR, errno.EEXIST,
                 errno.ENAMETOOLONG, errno.EMLINK, errno.EFBIG, errno.ENOLCK}
#: OS errors that are the output folder's fault where they name one of its paths (`--out /proc/x`,
#: a symlink loop, a folder in the way); on any other path they would be derive's own.
PATH_ERRNOS = {errno.ENOENT, errno.ELOOP, errno.ENOTEMPTY, errno.EISDIR, errno.EBUSY}
_LEFTOVER = re.compile(r"\.(?P<name>.+)\.(?P<kind>partial|old)-[1-9]\d*")


class OutputError(InputError):
    """An output folder derive may not or cannot write."""


class Manifest(NamedTuple):
    """What a derive build wrote: its products' names, and the sha256 of each file among them by
    its path in the build (none in an older derive's manifest)."""
    files: frozenset[str]
    sha256: dict[str, str]


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


def _sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def _hashes(staging: Path, names: set[str]) -> dict[str, str]:
    """The sha256 of each file of the products `names` (files, or folders of them) in `staging`, by
    its path in the build."""
    paths = [p for name in sorted(names) for p in (staging / name, *(staging / name).rglob("*")) if p.is_file()]
    return {p.relative_to(staging).as_posix(): _sha256(p) for p in paths}


def _written(path: Path, name: str, hashes: dict[str, str], twin: Path | None = None) -> bool:
    """Whether nothing at `path` (at `name` in its build folder) is the user's alone: it is a file
    whose sha256 `hashes` records for `name`, or a folder of such files; or, given `twin` (the
    build folder beside a leftover), the very file at `name` in `twin` (a user's file the next
    build carried over by a hard link, or a symlink alike)."""
    if twin is not None and _same(path, twin / name):
        return True
    if path.is_symlink():
        return False
    if path.is_dir():
        return all(_written(child, f"{name}/{child.name}", hashes, twin) for child in path.iterdir())
    return path.is_file() and hashes.get(name) == _sha256(path)


def _same(path: Path, other: Path) -> bool:
    """Whether `other` is the file `path` is (one inode), or a symlink to the same place."""
    try:
        mine, theirs = path.lstat(), other.lstat()
    except OSError:
        return False
    if stat.S_ISLNK(mine.st_mode) and stat.S_ISLNK(theirs.st_mode):
        return os.readlink(path) == os.readlink(other)
    return os.path.samestat(mine, theirs)


def _is_build(folder: Path) -> bool:
    """Whether `folder` is a derive build: its manifest records hashes, and each product it lists
    that the folder holds is as derive wrote it."""
    try:
        manifest = _manifest(folder)
    except OutputError:
        return False
    return manifest is not None and bool(manifest.sha256) and all(
        _written(folder / name, name, manifest.sha256) for name in manifest.files if os.path.lexists(folder / name))


def _derives(folder: Path, out: Path) -> bool:
    """Whether a folder left beside `out` is derive's to remove: it carries derive's mark (a
    staging folder still being written), or removing it loses nothing of the user's (each file in
    it is one its manifest proves derive's, or the very file `out` holds at its place)."""
    if leftovers.marked(folder):
        return True
    try:
        manifest = _manifest(folder)
    except OutputError:  # a manifest derive cannot read proves nothing
        manifest = None
    hashes = manifest.sha256 if manifest else {}
    return all(entry.name == MANIFEST or _written(entry, entry.name, hashes, out) for entry in folder.iterdir())


def recover(out: Path) -> None:
    """Restore or remove what killed builds left beside `out`, only what derive can prove its own
    (see the module); warn of folders merely named so. Call it holding the lock of `out` (claim
    does): then no build of `out` is under way, and what builds left beside it is of ended ones."""
    if not out.parent.is_dir():
        return
    left = []
    for entry in out.parent.iterdir():
        match = _LEFTOVER.fullmatch(entry.name)
        if match and match["name"] == out.name and entry.is_dir() and not entry.is_symlink():
            left.append((match["kind"], entry))
    if not out.exists():
        builds = sorted((e for kind, e in left if kind == "old" and _is_build(e)), key=lambda e: e.stat().st_mtime)
        if builds:
            builds[-1].rename(out)
            left = [(k, e) for k, e in left if e != builds[-1]]
    for _, entry in left:
        if _derives(entry, out):
            shutil.rmtree(entry, ignore_errors=True)
        else:
            print(f"derive: warning: {entry}: named like a folder a killed build leaves, but derive cannot prove "
                  "it made it; left as it is", file=sys.stderr, flush=True)


def _manifest(folder: Path) -> Manifest | None:
    """What a derive build in `folder` wrote; None when it is no derive build."""
    path = folder / MANIFEST
    if not path.is_file():
        return None
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
        files, hashes = data["files"], data.get("sha256", {})
        if not isinstance(files, list) or not all(isinstance(f, str) and "/" not in f for f in files) \
                or not isinstance(hashes, dict) or not all(isinstance(h, str) for h in hashes.values()):
            raise ValueError
    except (OSError, ValueError, KeyError, TypeError, AttributeError):
        raise OutputError(f"{path}: not a manifest derive can read; move the folder away or empty it") from None
    return Manifest(frozenset(files), hashes)


def _resolved(given: str) -> Path:
    """The folder `--out given` names, resolved; refused when empty, or the current folder or
    one that holds it."""
    if not given:
        raise OutputError("--out '': an empty folder name; give a folder, such as --out build/week3")
    try:
        path = Path(given).expanduser().resolve()
    except (OSError, RuntimeError) as error:  # a symlink loop
        raise OutputError(f"--out {given}: cannot resolve: {error}") from None
    here = Path.cwd().resolve()
    if path == here or path in here.parents:
        raise OutputError(f"--out {given}: is the current folder or holds it; a build replaces its folder as a "
                          f"whole: give a folder of its own, such as --out {Path(given) / 'build'}")
    return path


@contextmanager
def claim(out: str | Path) -> Iterator[Path]:
    """Hold the output folder for a build: the resolved folder, once it is known that a build may
    go there (see the module), locked against other builds until the block ends; restores or
    cleans what killed builds left. OutputError otherwise."""
    given = str(out)
    path = _resolved(given)
    with _locked(path, given):
        with output_errors(path):
            recover(path)
            if path.exists() and not path.is_dir():
                raise OutputError(f"--out {given}: is a file, not a folder")
            if path.is_dir() and any(path.iterdir()) and _manifest(path) is None:
                raise OutputError(f"--out {given}: the folder is not empty and derive did not build it; derive "
                                  "never deletes files it did not write: give a new or empty folder")
        yield path


@contextmanager
def _locked(out: Path, given: str) -> Iterator[None]:
    """Hold the advisory lock of building `out` (flock on `.NAME.lock` beside it, made with its
    folders), or refuse at once while another build holds it. The lock file is removed at the end
    when it is derive's (a user's file of that name locks as well, and stays)."""
    lock = out.with_name(f".{out.name}.lock")
    with output_errors(out):
        out.parent.mkdir(parents=True, exist_ok=True)
        descriptor = _lock(lock, given)
    try:
        yield
    finally:
        if _holds(descriptor, lock) and _derives_lock(descriptor, lock):
            with suppress(OSError):  # a lock file left behind locks nothing
                lock.unlink()
        os.close(descriptor)


def _lock(lock: Path, given: str) -> int:
    """A descriptor of the file `lock`, flocked, that is still the file of that name (made, with
    derive's mark as its content, where there is none)."""
    while True:
        try:
            descriptor = os.open(lock, os.O_RDWR | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW | os.O_CLOEXEC, 0o644)
            made = True
        except FileExistsError:
            try:
                descriptor = os.open(lock, os.O_RDONLY | os.O_NOFOLLOW | os.O_CLOEXEC)
            except FileNotFoundError:  # removed meanwhile by the build that held it: make it
                continue
            made = False
        try:
            fcntl.flock(descriptor, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(descriptor)
            raise OutputError(f"--out {given}: another derive build is writing to this folder; wait for it or "
                              "choose another --out") from None
        if _holds(descriptor, lock):
            break
        os.close(descriptor)  # the build that held it removed this file before letting go: lock anew
    if made:
        os.write(descriptor, leftovers.text(lock.name).encode())
    return descriptor


def _holds(descriptor: int, path: Path) -> bool:
    """Whether the open file `descriptor` is still the file named `path`."""
    try:
        return os.path.samestat(os.fstat(descriptor), path.lstat())
    except FileNotFoundError:
        return False


def _derives_lock(descriptor: int, lock: Path) -> bool:
    """Whether the open lock file is derive's: a file whose content is derive's mark for its name."""
    mark = leftovers.text(lock.name).encode()
    return stat.S_ISREG(os.fstat(descriptor).st_mode) and os.pread(descriptor, len(mark) + 1, 0) == mark


def _of_output(filename: str | bytes | None, out: Path) -> bool:
    """Whether an OS error's `filename` is a path of the output: `out` or a path in it, a folder
    that holds it, or one of the `.NAME.*` paths beside it (lock, staging folder) or in them."""
    if filename is None:
        return False
    path = Path(os.fsdecode(filename))
    return path in out.parents or any(p == out or (p.parent == out.parent and p.name.startswith(f".{out.name}."))
                                      for p in (path, *path.parents))


@contextmanager
def output_errors(out: Path) -> Iterator[None]:
    """An OS error that is the output folder's fault as an OutputError naming `out` (see
    OUTPUT_ERRNOS and PATH_ERRNOS)."""
    try:
        yield
    except OSError as error:
        ours = _of_output(error.filename, out)
        if error.errno not in OUTPUT_ERRNOS and not (error.errno in PATH_ERRNOS and ours):
            raise
        where = f" ({os.fsdecode(error.filename)})" if ours and Path(os.fsdecode(error.filename)) != out else ""
        raise OutputError(f"--out {out}: cannot write the build: {error.strerror}{where}") from None


@contextmanager
def staged(out: Path) -> Iterator[Path]:
    """A hidden staging folder beside `out` (which `claim` holds), marked as derive's and removed
    however the build ends; OS errors of the output folder become OutputErrors."""
    with output_errors(out):
        staging = out.parent / f".{out.name}.partial-{os.getpid()}"
        try:
            staging.mkdir()
        except FileExistsError:  # recover removed every such folder it could prove derive's
            raise OutputError(f"{staging}: in the way of the build's staging folder, and derive cannot prove it "
                              "made it; move it away") from None
        try:
            leftovers.mark(staging)
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
    """Files in `out` that derive cannot prove it wrote (a product of the manifest, as it recorded
    it), linked into the staging folder so that the swap keeps them; one of them named like a new
    product is refused."""
    previous = _manifest(out) or Manifest(frozenset(), {})
    for entry in out.iterdir():
        if entry.name == MANIFEST or entry.name in previous.files and _written(entry, entry.name, previous.sha256):
            continue  # derive's: replaced by the new build, or gone with the old one
        if entry.name in products and previous.files and not previous.sha256:
            raise OutputError(f"--out {out}: built by an earlier derive, whose manifest records no hash of its files, "
                              "so derive cannot prove which are its own and will replace none: move the folder away "
                              "or empty it (once; later builds record the hashes)")
        if entry.name in products:
            why = "changed since derive wrote it" if entry.name in previous.files else "derive did not write this file"
            raise OutputError(f"{entry}: {why}; derive will not replace it: move it away")
        target = staging / entry.name
        if entry.is_dir() and not entry.is_symlink():
            shutil.copytree(entry, target, symlinks=True, copy_function=os.link)
        elif entry.is_symlink():
            os.symlink(os.readlink(entry), target)
        else:
            os.link(entry, target)


def commit(staging: Path, out: Path, products: list[Path]) -> list[Path]:
    """Make the finished `products` (files, or folders of them, in `staging`) the build at `out`, with a manifest,
    keeping the files of `out` that derive cannot prove it wrote; return the products' paths in `out`."""
    names = {p.name for p in products}
    if any(p.parent != staging for p in products):
        raise AssertionError("products are files of the staging folder")
    with output_errors(out):
        for entry in list(staging.iterdir()):  # scratch files that are no product
            if entry.name not in names | {leftovers.MARK}:
                shutil.rmtree(entry) if entry.is_dir() else entry.unlink()
        manifest = {"derive": version(), "files": sorted(names), "sha256": _hashes(staging, names)}
        (staging / MANIFEST).write_text(json.dumps(manifest, indent=1) + "\n", encoding="utf-8")
        if out.is_dir():
            _carry_over(out, staging, names)
        (staging / leftovers.MARK).unlink()  # from here its manifest proves the folder derive's (recover)
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
