"""Derivations kept on disk, so that a set rebuilt after a typo or with a new seed derives nothing again.

An entry is one problem's derived `Solution` (its answers, checks and worked steps), pickled
(cloudpickle: the derivations hold functions written inside functions, which the standard
pickle refuses; python-flint's balls are written exactly, `_arb`). Its key is a SHA-256 of what
the derivation reads, never of a file's name or time:

- the problem file's parsed content less the text the derivation never reads (the question,
  title, topic, source, corrections and labels: Problem.derivation_source): so the scene, the asks and the parameters, ranges
  included, since the signs of the answers are proven over the ranges (derive.numbers.intervals)
  and their branches chosen by them: a changed range derives again, never stale;
- derive's version and a digest of its own source files (an engine changed in place derives
  again), and the versions of Python, sympy, python-flint and cloudpickle.

A file is trusted only if it starts with MAGIC, names the key asked for, and its payload has
the SHA-256 it records; anything else (truncated, foreign, another key) is ignored and
rebuilt. The folder is DERIVE_CACHE_DIR, else the user's cache folder (platformdirs), capped
at DERIVE_CACHE_MB megabytes (default 512): the entries used longest ago go first.

>>> import tempfile, os
>>> from derive.language.problem import load
>>> os.environ["DERIVE_CACHE_DIR"] = tempfile.mkdtemp()
>>> problem = load("rod_endpoint")
>>> fetch(problem) is None
True
>>> store(problem, derived(problem))
True
>>> fetch(problem).expressions
{'I': L**2*m/3}
"""
from __future__ import annotations

import functools
import hashlib
import io
import json
import os
import pickle
import re
import stat
import sys
import tempfile
from pathlib import Path

import cloudpickle
import flint
import platformdirs
import sympy as sp

from derive.core.library import version
from derive.language.problem import Problem
from derive.solution.answers import Solution

MAGIC = b"derive derivation cache 2\n"
DEFAULT_MB = 512
#: An entry's file: its key, and what it holds (a derivation; a compiled document: tex_cache; a typeset
#: worked solution or figure: typeset_cache).
ENTRY_NAME = re.compile(r"[0-9a-f]{64}\.(pickle|pdf|json)")
FOLDER_VARIABLE, SIZE_VARIABLE = "DERIVE_CACHE_DIR", "DERIVE_CACHE_MB"


def folder() -> Path:
    """Where the entries are: DERIVE_CACHE_DIR, else derive's folder in the user's cache folder."""
    given = os.environ.get(FOLDER_VARIABLE, "").strip()
    return Path(given) if given else Path(platformdirs.user_cache_dir("derive")) / "derivations"


def size_cap() -> int:
    """The cap in bytes (DERIVE_CACHE_MB, default DEFAULT_MB); a value that is not a number is refused."""
    text = os.environ.get(SIZE_VARIABLE, "").strip()
    try:
        megabytes = float(text) if text else DEFAULT_MB
    except ValueError:
        megabytes = -1
    if not megabytes >= 0:
        from derive.core.errors import InputError

        raise InputError(f"{SIZE_VARIABLE}={text}: expected a size in megabytes (0 or more)")
    return int(megabytes * 2**20)


@functools.lru_cache(maxsize=1)
def engine() -> str:
    """What a derivation's result depends on besides the problem: the versions and derive's own sources."""
    sources = hashlib.sha256()
    package = Path(__file__).resolve().parents[1]
    for path in sorted(package.rglob("*.py")):
        sources.update(path.relative_to(package).as_posix().encode() + b"\0" + path.read_bytes() + b"\0")
    return json.dumps({"derive": version(), "sources": sources.hexdigest(), "sympy": sp.__version__,
                       "python-flint": flint.__version__, "cloudpickle": cloudpickle.__version__,
                       "python": list(sys.version_info[:2])})


def key(problem: Problem) -> str | None:
    """The entry's key: what the derivation reads of the file (module docstring), and `engine()`;
    None for a problem not read from a file's text (nothing to key it by: not cached)."""
    if not problem.derivation_source:
        return None
    return hashlib.sha256(f"{engine()}\n{problem.derivation_source}".encode()).hexdigest()


def derived(problem: Problem) -> Solution:
    """A problem derived as a set needs it: its answers, their checks and the worked steps, and what
    each variant is checked and answered against (the conditions of its answers, the signed answers
    whose directions it gives): kept in the entry, none of it is derived again by a warm build."""
    solution = Solution(problem)
    solution.expressions
    solution.checks()
    solution.steps()
    solution.conditions
    solution.signed_expressions
    return solution


def _arb(ball: flint.arb):
    """A ball written exactly: its midpoint and radius as (mantissa, exponent), which flint.arb
    reads back bit for bit whatever the working precision (python-flint pickles none)."""
    if not (ball.mid().is_finite() and ball.rad().is_finite()):
        raise pickle.PicklingError("a ball that is not finite is not cached")
    return flint.arb, (ball.mid().man_exp(), ball.rad().man_exp())


_PLAIN = frozenset({"_mhash", "_args", "_assumptions", "__weakref__"})  # what sympy.Basic.__new__ sets


@functools.lru_cache(maxsize=None)
def _slots(cls: type) -> tuple[str, ...]:
    """The slots of a sympy class beyond Basic's own."""
    names = []
    for klass in cls.__mro__:
        slots = klass.__dict__.get("__slots__", ())
        names += [slots] if isinstance(slots, str) else list(slots)
    return tuple(n for n in names if n not in _PLAIN)


def _expression(obj: sp.Basic):
    """A compound expression written as its class, its arguments and its commutativity where it
    keeps it (Add, Mul, Pow), rebuilt by `_rebuilt` without running its constructor; None for one
    that holds more (a matrix, a polynomial, a finite set), which pickles as sympy pickles it.
    sympy's own pickling calls the constructor on the arguments, which evaluates again what derive
    held unevaluated (sqrt(M g R/I) became a product of roots, an integral's integrand 1*f)."""
    extra = {n for n in _slots(type(obj)) if hasattr(obj, n)} | set(getattr(obj, "__dict__", ()))
    if extra - {"is_commutative"}:
        return None
    return _rebuilt, (type(obj), obj.args, (obj.is_commutative,) if extra else ())


def _rebuilt(cls: type, args: tuple, commutative: tuple) -> sp.Basic:
    """The expression of class `cls` with exactly these arguments (sympy's Basic.__new__, no
    evaluation) and the commutativity its constructor had set, if any."""
    obj = sp.Basic.__new__(cls, *args)
    if commutative:
        obj.is_commutative = commutative[0]
    return obj


class _Pickler(cloudpickle.Pickler):
    """cloudpickle's, writing compound sympy expressions as they are (`_expression`) and
    python-flint's balls exactly (`_arb`)."""

    def reducer_override(self, obj):
        if type(obj) is flint.arb:
            return _arb(obj)
        if isinstance(obj, sp.Basic) and obj.args and not obj.is_Atom:
            written = _expression(obj)
            if written is not None:
                return written
        return super().reducer_override(obj)


def dumps(solution: Solution) -> bytes | None:
    """The solution's bytes, None where something in it cannot be written (it is then not cached)."""
    buffer = io.BytesIO()
    try:
        _Pickler(buffer, protocol=pickle.HIGHEST_PROTOCOL).dump(solution)
    except (pickle.PicklingError, TypeError, AttributeError, RecursionError):
        return None
    return buffer.getvalue()


def loads(payload: bytes, problem: Problem) -> Solution | None:
    """The solution in `payload` for `problem` (which replaces the one it was derived with: the
    same content but for the text), None if the bytes hold anything else."""
    try:
        with sp.evaluate(False):  # what pickles as sympy pickles it (a matrix) rebuilt with its entries as they are
            solution = pickle.loads(payload)  # noqa: S301 - bytes this module wrote, their digest checked
    except Exception:  # noqa: BLE001 - whatever a damaged pickle raises: not an entry
        return None
    if not isinstance(solution, Solution) or getattr(solution, "problem", None) is None \
            or solution.problem.id != problem.id:
        return None
    solution.problem = problem
    return solution


def _path(entry: str, suffix: str = ".pickle") -> Path:
    return folder() / f"{entry}{suffix}"


def read_entry(entry: str, suffix: str = ".pickle") -> bytes | None:
    """The payload of an entry file that can be trusted (MAGIC, this key, its SHA-256), else None;
    a trusted one is marked used now (the last to go when the cap is reached)."""
    path = _path(entry, suffix)
    try:
        data = path.read_bytes()
    except OSError:
        return None
    header = MAGIC + entry.encode() + b"\n"
    digest_end = len(header) + 65
    if not data.startswith(header) or len(data) < digest_end:
        return None
    digest, payload = data[len(header):digest_end - 1].decode("ascii", "replace"), data[digest_end:]
    if hashlib.sha256(payload).hexdigest() != digest:
        return None
    try:
        os.utime(path)
    except OSError:
        pass
    return payload


def write_entry(entry: str, payload: bytes, suffix: str = ".pickle", trimmed: bool = True) -> bool:
    """Write an entry file (atomically: a reader sees the old file or the new one); False where the
    folder cannot be written. Then trim the folder to its cap (unless not `trimmed`)."""
    where = folder()
    try:
        where.mkdir(parents=True, exist_ok=True)
        with tempfile.NamedTemporaryFile(dir=where, prefix=".writing-", delete=False) as file:
            file.write(MAGIC + entry.encode() + b"\n" + hashlib.sha256(payload).hexdigest().encode() + b"\n" + payload)
        os.replace(file.name, _path(entry, suffix))
    except OSError:
        return False
    if trimmed:
        trim(size_cap())
    return True


def fetch(problem: Problem, entry: str | None = None) -> Solution | None:
    """The cached solution of `problem`, None where there is none to trust (missing, damaged, foreign)."""
    entry = entry or key(problem)
    payload = None if entry is None else read_entry(entry)
    return None if payload is None else loads(payload, problem)


def store(problem: Problem, solution: Solution, entry: str | None = None, payload: bytes | None = None,
          trimmed: bool = True) -> bool:
    """Write the entry; False where the solution cannot be written or the folder cannot be. Then trim
    the folder to its cap (unless not `trimmed`: a caller storing many trims once, after the last)."""
    payload = dumps(solution) if payload is None else payload
    entry = entry or key(problem)
    if payload is None or entry is None:
        return False
    return write_entry(entry, payload, trimmed=trimmed)


def _listed() -> list[tuple[Path, os.stat_result]]:
    """The entry files with their status, the least recently used first. Another process sharing the
    folder (two builds at once) may remove a file between the listing and its status: it is left out."""
    listed = []
    try:  # only derive's own names: a folder given by DERIVE_CACHE_DIR may hold other files
        names = [p for p in folder().iterdir() if ENTRY_NAME.fullmatch(p.name)]
    except OSError:
        return []
    for path in names:
        try:
            status = path.stat()
        except OSError:
            continue
        if stat.S_ISREG(status.st_mode):
            listed.append((path, status))
    return sorted(listed, key=lambda listing: listing[1].st_mtime)


def entries() -> list[Path]:
    """The entry files, the least recently used first."""
    return [path for path, _ in _listed()]


def trim(cap: int) -> None:
    """Remove the least recently used entries until the folder holds at most `cap` bytes."""
    listed = _listed()
    total = sum(status.st_size for _, status in listed)
    for path, status in listed:
        if total <= cap:
            return
        total -= status.st_size
        path.unlink(missing_ok=True)


def clear() -> int:
    """Remove every entry (and any file left half written); return how many entries there were."""
    files = entries()
    for path in files + [p for p in folder().glob(".writing-*") if p.is_file()]:
        path.unlink(missing_ok=True)
    return len(files)


def info() -> dict:
    """The folder, its entries, their size and the cap, as `derive cache info` prints them."""
    listed = _listed()
    return {"folder": str(folder()), "entries": len(listed), "bytes": sum(status.st_size for _, status in listed),
            "cap": size_cap()}
