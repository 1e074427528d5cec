"""The derivation cache and the problems derived in parallel (issue 40, items 1 and 2): a build from
the cache, or by several processes, is byte-identical to one derived afresh by one; an entry is
used only for the same derivation (a changed scene or range derives again, a changed question or
seed does not); a damaged or foreign entry is ignored and rebuilt."""
import os
import pickle
import re
import shutil
from pathlib import Path

import pytest

from conftest import ROOT, run_derive
from derive.language.problem import load
from derive.publishing import derivation_cache, deriving

# Held unevaluated forms (a pendulum's root, sqrt(2 g H)), inertia integrals (an integrand 1*f once came back),
# friction regimes, states, impacts, tops and wheels in 3D, rolling bodies, an orbit, polar kinematics.
PROBLEMS = ("compound_pendulum", "string_wrapped_disk", "skid_to_roll", "loop_the_loop", "sticky_impact_pivoted",
            "top_precession_exact", "incline_race", "kepler_orbit", "tugged_spool", "rod_endpoint", "mass_concentration",
            "tilting_wheel", "rigid_body_L", "polar_acceleration")


def _build(out: Path, *options: str, problems=PROBLEMS, env=None) -> str:
    """`derive sheet` of `problems` (3 variants, the keys with distractors, no PDFs) into `out`; its stderr."""
    done = run_derive("sheet", *problems, "--variants", "3", "--seed", "5", "--to", "distractors", "--out", str(out),
                      "--progress", "lines", *options, env=env)
    assert done.returncode == 0, done.stderr
    return done.stderr


def _files(out: Path) -> dict[str, bytes]:
    return {str(p.relative_to(out)): p.read_bytes() for p in sorted(out.rglob("*")) if p.is_file()}


def _derivations() -> list:
    """The cache's derivations (its folder also keeps typeset solutions and PDFs)."""
    return [p for p in derivation_cache.entries() if p.suffix == ".pickle"]


def _cached(stderr: str) -> set[str]:
    return set(re.findall(r"deriving (\w+) \(from the cache\)", stderr))


@pytest.fixture(scope="module")
def afresh(tmp_path_factory):
    """The build derived afresh by one process, without the cache (--no-cache), which the tests below
    compare theirs with: (its files, its stderr, what it left in the cache folder it was given)."""
    folder = tmp_path_factory.mktemp("afresh")
    stderr = _build(folder / "out", "--no-cache", "--jobs", "1", env={"DERIVE_CACHE_DIR": str(folder / "cache")})
    left = sorted((folder / "cache").rglob("*")) if (folder / "cache").exists() else []
    return _files(folder / "out"), stderr, left


def test_a_build_from_the_cache_is_byte_identical_to_one_derived_afresh(afresh, tmp_path):
    reference, fresh, left = afresh
    assert not _cached(fresh) and not left  # --no-cache writes nothing either
    first = _build(tmp_path / "first", "--jobs", "1")
    assert not _cached(first) and len(_derivations()) == len(PROBLEMS)
    warm = _build(tmp_path / "warm", "--jobs", "1")  # another process: only what the files hold
    assert _cached(warm) == set(PROBLEMS)
    assert {"key.json", "solutions.tex", "worksheet.tex"} <= set(reference)
    assert _files(tmp_path / "first") == reference
    assert _files(tmp_path / "warm") == reference


def test_two_jobs_build_the_same_bytes_as_one(afresh, tmp_path):
    reference, one, _ = afresh
    two = _build(tmp_path / "two", "--no-cache", "--jobs", "2")
    assert "running" in two and "running" not in one  # the progress names the derivations under way
    assert _files(tmp_path / "two") == reference


def test_a_new_seed_or_question_derives_nothing_again_a_changed_scene_or_range_does(tmp_path):
    library = tmp_path / "library"
    shutil.copytree(ROOT / "problems", library)
    path = next(library.rglob("string_wrapped_disk.yaml"))
    text = path.read_text()
    env = {"DERIVE_LIBRARY": str(library)}
    assert not _cached(_build(tmp_path / "a", problems=("string_wrapped_disk",), env=env))
    assert _cached(_build(tmp_path / "b", "--seed", "6", problems=("string_wrapped_disk",), env=env))

    path.write_text(re.sub(r"question: (\|?)", r"question: \1\n  A new first sentence.", text, count=1))
    assert load(path).question.startswith("A new first sentence.")
    assert _cached(_build(tmp_path / "c", problems=("string_wrapped_disk",), env=env)) == {"string_wrapped_disk"}
    assert "A new first sentence." in (tmp_path / "c" / "worksheet.tex").read_text()  # the new text, not the cached

    before = derivation_cache.key(load(path))
    path.write_text(text.replace("gravity: g", "gravity: 2*g"))  # the scene changed
    assert derivation_cache.key(load(path)) != before
    assert not _cached(_build(tmp_path / "d", problems=("string_wrapped_disk",), env=env))
    assert (tmp_path / "d" / "key.json").read_bytes() != (tmp_path / "a" / "key.json").read_bytes()


def test_a_range_is_part_of_the_key():
    """Signs are proven, and branches chosen, over the declared ranges: an entry derived over other
    ranges is not used (never stale, at the price of a derivation)."""
    problem = load("string_wrapped_disk")
    text = problem.path.read_text()
    ranged = re.search(r"range: \[([0-9.]+), ([0-9.]+)\]", text)
    assert ranged, "string_wrapped_disk declares a range"
    moved = text.replace(ranged.group(0), f"range: [{ranged.group(1)}, {float(ranged.group(2)) * 2}]", 1)
    from derive.language.problem import parse

    assert derivation_cache.key(parse(moved, problem.path)) != derivation_cache.key(problem)
    reworded = text.replace("title:", "title: Another", 1)
    assert derivation_cache.key(parse(reworded, problem.path)) == derivation_cache.key(problem)


def _planted(problem, content: bytes) -> Path:
    path = derivation_cache.folder() / f"{derivation_cache.key(problem)}.pickle"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(content)
    return path


def _entry(problem) -> bytes:
    derivation_cache.store(problem, derivation_cache.derived(problem))
    return (derivation_cache.folder() / f"{derivation_cache.key(problem)}.pickle").read_bytes()


@pytest.mark.parametrize("damage", ["truncated", "flipped", "plain pickle", "another object", "another key"])
def test_a_damaged_or_foreign_entry_is_ignored_and_rebuilt(damage):
    problem, other = load("string_wrapped_disk"), load("rod_endpoint")
    good = _entry(problem)
    header = derivation_cache.MAGIC + derivation_cache.key(problem).encode() + b"\n"
    payload = pickle.dumps({"a": 1})
    planted = {
        "truncated": good[:len(good) // 2],
        "flipped": good[:-10] + bytes([good[-10] ^ 1]) + good[-9:],
        "plain pickle": pickle.dumps(derivation_cache.fetch(problem).expressions),
        # digests right, but the object is no solution, or the solution of another problem
        "another object": header + derivation_cache.hashlib.sha256(payload).hexdigest().encode() + b"\n" + payload,
        "another key": _entry(other),
    }[damage]
    path = _planted(problem, planted)
    assert derivation_cache.fetch(problem) is None
    [(solution, cached)] = deriving.derive([problem], jobs=1)
    assert not cached and sorted(solution.expressions) == ["T", "a", "alpha"]
    assert path.read_bytes() != planted and derivation_cache.fetch(problem) is not None  # rebuilt


def test_the_cache_keeps_to_its_cap(monkeypatch):
    for name in ("rod_endpoint", "rod_midpoint", "string_wrapped_disk"):
        _entry(load(name))
    sizes = [p.stat().st_size for p in derivation_cache.entries()]
    assert len(sizes) == 3
    monkeypatch.setenv("DERIVE_CACHE_MB", str((sum(sizes) - 1) / 2**20))
    _entry(load("rod_endpoint"))  # used last: kept
    kept = derivation_cache.entries()
    assert len(kept) < 3 and kept[-1].name == f"{derivation_cache.key(load('rod_endpoint'))}.pickle"
    assert sum(p.stat().st_size for p in kept) <= derivation_cache.size_cap()


def test_an_entry_another_build_removes_meanwhile_is_passed_over(monkeypatch):
    """Two builds sharing the folder: an entry listed by one and removed by the other before its size
    or age is read is left out of the trim and the count (it had stopped a textbook sheet with
    FileNotFoundError). Here the entry is there at its first look and gone at every later one."""
    for name in ("rod_endpoint", "rod_midpoint"):
        _entry(load(name))
    gone, other = derivation_cache.entries()
    real_stat, looks = Path.stat, []

    def stat(path, *args, **kwargs):
        if path == gone:
            looks.append(path)
            if len(looks) > 1:
                raise FileNotFoundError(2, "removed by another build", str(path))
        return real_stat(path, *args, **kwargs)

    with monkeypatch.context() as patched:
        patched.setattr(Path, "stat", stat)
        derivation_cache.trim(0)
        assert derivation_cache.info()["entries"] == 0
    assert not other.exists() and looks


def test_derive_cache_info_and_clear(tmp_path):
    _entry(load("rod_endpoint"))
    other = derivation_cache.folder() / "notes.pickle"  # not derive's: kept
    other.write_bytes(b"someone else's")
    info = run_derive("cache", "info")
    assert info.returncode == 0 and f"{os.environ['DERIVE_CACHE_DIR']}: 1 entries" in info.stdout, info.stderr
    cleared = run_derive("cache", "clear")
    assert cleared.returncode == 0 and "removed 1 entries" in cleared.stdout
    assert derivation_cache.entries() == [] and other.read_bytes() == b"someone else's"
    assert "0 entries" in run_derive("cache", "info").stdout


def test_a_bad_cap_is_refused_in_one_line():
    done = run_derive("cache", "info", env={"DERIVE_CACHE_MB": "lots"})
    assert done.returncode == 2 and "DERIVE_CACHE_MB=lots" in done.stderr and len(done.stderr.splitlines()) == 1


def test_the_help_teaches_the_options():
    sheet = run_derive("sheet", "--help").stdout
    assert "--jobs N" in sheet and "--no-cache" in sheet and "derive cache --help" in sheet
    cache = run_derive("cache", "--help").stdout
    assert "DERIVE_CACHE_DIR" in cache and "derive cache clear" in cache and "ranges" in cache


def test_the_api_takes_jobs_and_cache(tmp_path):
    import derive
    from derive.core.errors import InputError

    with pytest.raises(InputError, match="jobs: expected a whole number from 1 to 256"):
        derive.sheet(["rod_endpoint"], tmp_path / "a", to=[], jobs=0)
    derive.sheet(["rod_endpoint"], tmp_path / "b", to=[], jobs=1, cache=False, progress="none")
    assert derivation_cache.entries() == []
    derive.sheet(["rod_endpoint"], tmp_path / "c", to=[], progress="none")
    assert len(_derivations()) == 1
    assert (tmp_path / "b" / "key.json").read_bytes() == (tmp_path / "c" / "key.json").read_bytes()
