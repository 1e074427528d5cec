"""`derive bench --only course`: the whole library built as one course's set, cold and again.

Four figures, each a `derive sheet` of every problem of the library (whatever problems/ holds)
with `variants` variants, in a fresh process, over a copy of the library and a derivation
cache of its own (never the user's):

- cold: the cache empty, every problem derived (--jobs: the cores);
- warm: a new seed, every derivation from the cache;
- one question's text changed: that problem's file edited, the set rebuilt (its derivation
  still from the cache: the question is no part of the key);
- peak memory: the largest resident set of any of the build's processes;
- a week's set with PDFs (WEEK problems of the library, the same variants), one question's text
  changed: what an instructor waits for after mending a typo (the documents whose TeX did not
  change come from derive.publishing.tex_cache);
- cold on a Dask cluster (with derive's cluster extra): the same build with `--scheduler`, on a
  LocalCluster of one single-threaded worker process per core, and the cache's size per problem
  (what a worker sends back): the figures docs/design.md scales to a 10,000-problem bank.

A library problem that the set cannot build (an engine limit met, say) is named and left out,
so that the figures stay about the rest; the run says so.

>>> lines = []
>>> course(lines.append, variants=1, limit=2)["warm_hits"]
2
"""
from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from derive.core import library

MAX_LEFT_OUT = 10  # problems a run may leave out before it gives up
WEEK = 10  # the problems of a week's set: the rebuild with PDFs after one question's text changes

#: Runs `derive sheet` and prints its exit status and the peak resident set (KiB) of its processes.
_MEASURED = ("import resource, subprocess, sys; done = subprocess.run(sys.argv[1:], stderr=subprocess.PIPE, text=True); "
             "sys.stderr.write(done.stderr); "
             "print(done.returncode, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)")


def _sheet(ids: list[str], variants: int, seed: int, outputs: str, out: Path, env: dict,
           *options: str) -> tuple[float, float, str, int]:
    """One build in a fresh process: (wall seconds, peak MiB, its progress lines, exit status)."""
    command = [sys.executable, "-m", "derive", "sheet", *ids, "--variants", str(variants), "--seed", str(seed),
               "--to", outputs, "--out", str(out), "--progress", "lines", *options]
    began = time.perf_counter()
    done = subprocess.run([sys.executable, "-c", _MEASURED, *command], capture_output=True, text=True, env=env)
    wall = time.perf_counter() - began
    status, peak = done.stdout.split()[-2:]
    return wall, int(peak) / 1024, done.stderr, int(status)


def _left_out(stderr: str, ids: list[str]) -> str | None:
    """The problem a failed build names in its error, None if it names none of `ids`."""
    error = next((line for line in reversed(stderr.splitlines()) if line.startswith("derive: ")), "")
    return next((i for i in ids if re.search(rf"\b{re.escape(i)}(\.yaml)?\b", error)), None)


def course(say, variants: int = 30, outputs: str = "", limit: int | None = None) -> dict:
    """The four figures over the library (its first `limit` problems), printed through `say` and returned."""
    ids = [p.stem for p in library.problem_files()][:limit]
    figures: dict = {"problems": len(ids), "variants": variants, "outputs": outputs or "LaTeX and keys"}
    with tempfile.TemporaryDirectory() as folder:
        root = Path(folder)
        shutil.copytree(library.problems_dir(), root / "library")
        env = {**os.environ, "DERIVE_LIBRARY": str(root / "library"), "DERIVE_CACHE_DIR": str(root / "cache"),
               "PYTHONHASHSEED": "0"}
        say(f"\nThe library as one course's set: {len(ids)} problems x {variants} variants, outputs: "
            f"{figures['outputs']} (derive sheet, each run a fresh process, --jobs the cores):")
        left_out = []
        while True:
            shutil.rmtree(root / "cache", ignore_errors=True)
            wall, peak, stderr, status = _sheet(ids, variants, 1, outputs, root / "cold", env)
            if status == 0:
                break
            culprit = _left_out(stderr, ids)
            if culprit is None or len(left_out) >= MAX_LEFT_OUT:
                say(f"  the build failed: {stderr.strip().splitlines()[-1] if stderr.strip() else status}")
                return figures
            say(f"  left out {culprit}: {stderr.strip().splitlines()[-1]}")
            left_out.append(culprit)
            ids.remove(culprit)
        entries = sum(f.stat().st_size for f in (root / "cache").rglob("*.pickle"))
        figures.update(cold=wall, cold_peak_mib=peak, left_out=left_out, entry_kib=entries / 1024 / len(ids))
        say(f"  cold (every problem derived):        {wall:7.1f} s   peak {peak:6.0f} MiB   "
            f"cache {entries / 2**20:.1f} MiB, {entries / 1024 / len(ids):.0f} KiB a problem")
        wall, peak, stderr, _ = _sheet(ids, variants, 2, outputs, root / "warm", env)
        hits = stderr.count("(from the cache)")
        figures.update(warm=wall, warm_peak_mib=peak, warm_hits=hits)
        say(f"  warm (a new seed):                   {wall:7.1f} s   peak {peak:6.0f} MiB   "
            f"{hits}/{len(ids)} from the cache")
        _revise(root, ids[0])
        wall, peak, stderr, status = _sheet(ids, variants, 2, outputs, root / "changed", env)
        hits = stderr.count("(from the cache)")
        shown = status == 0 and "(Revised.)" in (root / "changed" / "worksheet.tex").read_text(encoding="utf-8")
        figures.update(changed=wall, changed_peak_mib=peak, changed_hits=hits)
        say(f"  {ids[0]}'s question changed:".ljust(40) + f"{wall:7.1f} s   peak {peak:6.0f} MiB   "
            f"{hits}/{len(ids)} from the cache" + ("" if shown else " (the new text is NOT in the worksheet)"))
        peak = max(figures["cold_peak_mib"], figures["warm_peak_mib"], figures["changed_peak_mib"])
        say(f"  peak memory (the largest process):   {peak:7.0f} MiB")
        week = ids[1:1 + WEEK]
        _sheet(week, variants, 2, "pdf", root / "week", env)  # its PDFs compiled, and kept
        _revise(root, week[0])
        wall, _, _, status = _sheet(week, variants, 2, "pdf", root / "week-changed", env)
        figures.update(week_changed_pdf=wall)
        say(f"  a week's set ({len(week)} problems, PDFs), one question changed: {wall:5.1f} s"
            + ("" if status == 0 else " (the build FAILED)"))
        clustered = _on_a_cluster(ids, variants, outputs, root, env)
        if clustered is not None:
            figures["cluster_cold"] = clustered
            say(f"  cold on a Dask LocalCluster:         {clustered:7.1f} s   ({_cores()} single-threaded workers)")
        say("  " + json.dumps({k: round(v, 1) if isinstance(v, float) else v for k, v in figures.items()}))
    return figures


def _revise(root: Path, problem_id: str) -> None:
    """Edit the text of a problem's question in the library's copy (its derivation stays valid)."""
    edited = next((root / "library").rglob(f"{problem_id}.yaml"))
    edited.write_text(re.sub(r"^question: (\|-?|>-?)?", lambda m: m.group(0) + ("\n  " if m.group(1) else "")
                             + "(Revised.) ", edited.read_text(), count=1, flags=re.M))


def _cores() -> int:
    from derive.publishing.deriving import cores

    return cores()


def _on_a_cluster(ids: list[str], variants: int, outputs: str, root: Path, env: dict) -> float | None:
    """The cold build's wall time with the derivations on a LocalCluster (None without Dask)."""
    try:
        from distributed import LocalCluster
    except ImportError:
        return None
    with LocalCluster(n_workers=_cores(), threads_per_worker=1, processes=True, dashboard_address=None) as local:
        wall, _, _, status = _sheet(ids, variants, 1, outputs, root / "cluster", {**env, "DERIVE_CACHE_DIR": str(
            root / "cluster-cache")}, "--scheduler", local.scheduler_address)
    return wall if status == 0 else None
