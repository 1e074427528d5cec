"""Output folders belong to the user (derive.publishing.output_folder): refusals, kept files, symlinks, a
kill at every step of the swap, full and read-only disks."""
import hashlib
import json
import os
import shutil
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from conftest import ROOT
from derive.publishing import export, leftovers, output_folder

DERIVE = Path(sys.executable).parent / "derive"


@pytest.fixture
def small_set(tmp_path):
    path = tmp_path / "small.yaml"
    path.write_text("title: A small set\nproblems: [rod_endpoint]\n")
    return path


def build(set_path, out, *extra, cwd=None, env=None):
    return subprocess.run([str(DERIVE), "sheet", str(set_path), "--out", str(out), "--to", "", "--progress", "none", *extra],
                          capture_output=True, text=True, cwd=cwd or ROOT, timeout=300,
                          env={**os.environ, **(env or {})})


def contents(folder: Path) -> dict[str, bytes]:
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


def write_build(folder: Path, files: dict[str, str]) -> None:
    """A derive build by hand: `files` (name: text) and a manifest with their hashes."""
    folder.mkdir()
    for name, text in files.items():
        (folder / name).write_text(text)
    hashes = {name: hashlib.sha256(text.encode()).hexdigest() for name, text in files.items()}
    (folder / output_folder.MANIFEST).write_text(json.dumps({"files": sorted(files), "sha256": hashes}))


def one_line_exit_2(result):
    assert result.returncode == 2, (result.returncode, result.stderr)
    assert len(result.stderr.strip().splitlines()) == 1, result.stderr
    assert "Traceback" not in result.stderr
    return result.stderr


def test_a_folder_derive_did_not_build_is_refused_and_untouched(tmp_path, small_set):
    course = tmp_path / "course"
    course.mkdir()
    (course / "notes.md").write_text("my notes")
    stderr = one_line_exit_2(build(small_set, course))
    assert "not empty and derive did not build it" in stderr
    assert contents(course) == {"notes.md": b"my notes"}
    assert sorted(p.name for p in tmp_path.iterdir()) == ["course", "small.yaml"]


def test_a_new_or_empty_folder_gets_a_build_with_its_manifest(tmp_path, small_set):
    empty = tmp_path / "empty"
    empty.mkdir()
    for out in (tmp_path / "new" / "deep", empty):
        assert build(small_set, out).returncode == 0
        manifest = json.loads((out / output_folder.MANIFEST).read_text())
        assert set(manifest["files"]) == {"worksheet.tex", "solutions.tex", "key.tex", "key.csv", "key.json"}
        assert set(contents(out)) == set(manifest["files"]) | {output_folder.MANIFEST}


def test_files_the_user_added_to_a_build_are_kept_and_never_replaced(tmp_path, small_set):
    out = tmp_path / "out"
    assert build(small_set, out).returncode == 0
    (out / "notes.txt").write_text("mine")
    (out / "extra").mkdir()
    (out / "extra" / "a.txt").write_text("a")
    assert build(small_set, out, "--variants", "2").returncode == 0
    assert (out / "notes.txt").read_text() == "mine" and (out / "extra" / "a.txt").read_text() == "a"
    assert "notes.txt" not in json.loads((out / output_folder.MANIFEST).read_text())["files"]
    # A file of the user's with a product's name: refused, nothing changed.
    (out / output_folder.MANIFEST).write_text(json.dumps({"files": ["key.tex"], "sha256": {"key.tex": "0" * 64}}))
    before = contents(out)
    stderr = one_line_exit_2(build(small_set, out))
    assert "derive will not replace it" in stderr and ("key.csv" in stderr or "key.tex" in stderr)
    assert contents(out) == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out", "small.yaml"]


def test_out_dot_and_a_folder_holding_the_current_one_are_refused_in_one_line(tmp_path, small_set):
    here = tmp_path / "work"
    here.mkdir()
    for out in (".", "..", str(here)):
        stderr = one_line_exit_2(build(small_set, out, cwd=here))
        assert "is the current folder or holds it" in stderr
    assert list(here.iterdir()) == []


def test_a_symlinked_out_builds_where_the_link_points(tmp_path, small_set):
    target = tmp_path / "target"
    link = tmp_path / "link"
    link.symlink_to(target)
    assert build(small_set, link).returncode == 0
    assert link.is_symlink() and os.readlink(link) == str(target)
    assert (target / "key.json").is_file()
    assert build(small_set, link).returncode == 0  # and again, over the first build
    assert link.is_symlink() and (target / "key.json").is_file()


def test_a_file_as_out_is_refused(tmp_path, small_set):
    path = tmp_path / "file"
    path.write_text("x")
    assert "is a file, not a folder" in one_line_exit_2(build(small_set, path))
    assert path.read_text() == "x"


# --- a kill at every step of the swap ----------------------------------------------------------

SWAP_STEPS = [("swap",), ("swapped",), ("swap", "no-exchange"), ("renamed-old", "no-exchange"),
              ("swapped", "no-exchange")]


@pytest.mark.parametrize("faults", SWAP_STEPS, ids=["+".join(f) for f in SWAP_STEPS])
def test_a_kill_at_each_step_of_the_swap_leaves_the_old_or_the_new_build(tmp_path, small_set, faults):
    out = tmp_path / "out"
    assert build(small_set, out, "--seed", "1").returncode == 0
    (out / "notes.txt").write_text("mine")  # carried over by a hard link: a leftover holding it is derive's
    old = contents(out)
    new_dir = tmp_path / "reference"
    assert build(small_set, new_dir, "--seed", "2").returncode == 0
    new = {**contents(new_dir), "notes.txt": b"mine"}
    assert old != new
    killed = build(small_set, out, "--seed", "2", env={"DERIVE_FAULT_AT": ",".join(faults)})
    assert killed.returncode == -signal.SIGKILL, killed.stderr
    if out.exists():
        assert contents(out) in (old, new)
    else:  # killed between the two renames: the old build waits beside it, restored by the next run
        assert faults == ("renamed-old", "no-exchange")
        (left,) = [p for p in tmp_path.iterdir() if p.name.startswith(".out.old-")]
        assert contents(left) == old
    leftovers = [p.name for p in tmp_path.iterdir() if p.name.startswith(".out.")]
    assert leftovers  # what the kill left behind ...
    again = build(small_set, out, "--seed", "3")
    assert again.returncode == 0 and "warning" not in again.stderr, again.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out", "reference", "small.yaml"]  # ... is gone
    assert (out / "notes.txt").read_text() == "mine"


def test_recover_restores_an_old_build_cut_off_between_the_renames(tmp_path):
    old = tmp_path / ".out.old-999999999"
    write_build(old, {"key.csv": "old"})
    partial = tmp_path / ".out.partial-999999998"
    partial.mkdir()
    output_folder.recover(tmp_path / "out")
    assert (tmp_path / "out" / "key.csv").read_text() == "old"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]


def test_ctrl_c_during_the_renames_waits_until_the_new_build_is_in_place(tmp_path, monkeypatch):
    out = tmp_path / "out"
    write_build(out, {"key.csv": "old"})
    staging = tmp_path / ".out.partial-1"
    staging.mkdir()
    leftovers.mark(staging)
    (staging / "key.csv").write_text("new")
    monkeypatch.setenv("DERIVE_FAULT_AT", "no-exchange")  # the path with two renames
    rename = Path.rename

    def interrupted_rename(self, target):
        if self == out:
            os.kill(os.getpid(), signal.SIGINT)  # Ctrl-C between moving the old build away and the new in
        return rename(self, target)

    monkeypatch.setattr(Path, "rename", interrupted_rename)
    done = threading.Event()
    other = threading.Thread(target=done.wait, args=(10,))  # as latexmk's pool: the signal may land there
    other.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            output_folder.commit(staging, out, [staging / "key.csv"])
    finally:
        done.set()
        other.join()
    assert (out / "key.csv").read_text() == "new"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]  # the old build removed


# --- only what derive can prove its own is removed or replaced (issue 35) -----------------------

def test_a_users_folders_named_like_leftovers_are_kept(tmp_path, small_set):
    out = tmp_path / "out"
    assert build(small_set, out).returncode == 0
    thesis = tmp_path / ".out.old-1999"
    thesis.mkdir()
    (thesis / "thesis.tex").write_text("my thesis")
    notes = tmp_path / ".out.partial-1999"
    notes.mkdir()
    (notes / "notes.md").write_text("my notes")
    copied = tmp_path / ".out.old-1998"  # a copy of a build, and a file of the user's in it
    shutil.copytree(out, copied)
    (copied / "draft.tex").write_text("my draft")
    done = build(small_set, out, "--seed", "5")
    assert done.returncode == 0, done.stderr
    assert contents(thesis) == {"thesis.tex": b"my thesis"} and contents(notes) == {"notes.md": b"my notes"}
    assert (copied / "draft.tex").read_text() == "my draft"
    assert done.stderr.count("cannot prove it made it; left as it is") == 3, done.stderr


@pytest.mark.parametrize("manifest", [None, {"files": ["thesis.tex"]}])
def test_a_users_folder_named_like_an_old_build_is_not_restored_into_place(tmp_path, small_set, manifest):
    thesis = tmp_path / ".out.old-1999"
    thesis.mkdir()
    (thesis / "thesis.tex").write_text("my thesis")
    if manifest:  # one of an older derive, without hashes: it proves nothing
        (thesis / output_folder.MANIFEST).write_text(json.dumps(manifest))
    before = contents(thesis)
    out = tmp_path / "out"
    assert build(small_set, out).returncode == 0
    assert contents(thesis) == before and not (out / "thesis.tex").exists() and (out / "key.csv").is_file()


@pytest.mark.parametrize("sha256", [None, "0" * 64], ids=["no-hash", "wrong-hash"])
def test_a_planted_manifest_listing_a_users_file_does_not_make_a_build_delete_it(tmp_path, small_set, sha256):
    out = tmp_path / "out"
    assert build(small_set, out).returncode == 0
    (out / "notes.txt").write_text("mine")
    manifest = json.loads((out / output_folder.MANIFEST).read_text())
    manifest["files"].append("notes.txt")
    if sha256:
        manifest.setdefault("sha256", {})["notes.txt"] = sha256
    else:
        manifest.pop("sha256", None)
    (out / output_folder.MANIFEST).write_text(json.dumps(manifest))
    for name in {"key.tex", "key.csv", "key.json", "solutions.tex", "worksheet.tex"}:  # so that none collides
        (out / name).unlink()
    assert build(small_set, out, "--seed", "4").returncode == 0
    assert (out / "notes.txt").read_text() == "mine"


def test_a_product_the_user_changed_is_never_replaced(tmp_path, small_set):
    out = tmp_path / "out"
    assert build(small_set, out).returncode == 0
    (out / "key.tex").write_text("my corrected key")
    before = contents(out)
    stderr = one_line_exit_2(build(small_set, out, "--seed", "4"))
    assert "key.tex: changed since derive wrote it" in stderr and "derive will not replace it" in stderr
    assert contents(out) == before


def test_a_folder_an_earlier_derive_built_is_refused_once_with_what_to_do(tmp_path, small_set):
    """A manifest of an earlier derive records no hashes: none of its files can be proven derive's,
    so the build says so for the folder, in one line, and changes nothing."""
    out = tmp_path / "out"
    assert build(small_set, out).returncode == 0
    manifest = json.loads((out / output_folder.MANIFEST).read_text())
    manifest.pop("sha256")
    (out / output_folder.MANIFEST).write_text(json.dumps(manifest))
    before = contents(out)
    stderr = one_line_exit_2(build(small_set, out, "--seed", "4"))
    assert f"--out {out}: built by an earlier derive, whose manifest records no hash" in stderr
    assert "move the folder away or empty it" in stderr and contents(out) == before


def test_a_folder_among_the_products_is_derives_only_while_each_file_in_it_is(tmp_path):
    out = tmp_path / "out"

    def commit(with_figures: bool):
        with output_folder.staged(out) as staging:
            (staging / "key.csv").write_text("key")
            products = [staging / "key.csv"]
            if with_figures:
                (staging / "figures").mkdir()
                (staging / "figures" / "a.svg").write_text("<svg/>")
                products.append(staging / "figures")
            output_folder.commit(staging, out, products)

    commit(True)
    assert set(json.loads((out / output_folder.MANIFEST).read_text())["sha256"]) == {"key.csv", "figures/a.svg"}
    commit(True)  # derive's folder, replaced
    (out / "figures" / "mine.svg").write_text("mine")
    with pytest.raises(output_folder.OutputError, match="figures: changed since derive wrote it"):
        commit(True)
    commit(False)  # kept, with the user's file in it
    assert contents(out / "figures") == {"a.svg": b"<svg/>", "mine.svg": b"mine"}
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]


def test_a_leftover_named_for_a_pid_out_of_range_does_not_stop_builds(tmp_path, small_set):
    huge = tmp_path / ".out.partial-99999999999999999999"
    huge.mkdir()
    (huge / "notes.md").write_text("mine")
    done = build(small_set, tmp_path / "out")
    assert done.returncode == 0, done.stderr
    assert contents(huge) == {"notes.md": b"mine"}


# --- one build at a time ------------------------------------------------------------------------

def test_a_second_build_of_a_folder_refuses_while_the_first_holds_it(tmp_path, small_set):
    out = tmp_path / "new"
    with output_folder.claim(out):  # the first build, under way
        stderr = one_line_exit_2(build(small_set, out))
        assert f"--out {out}: another derive build is writing to this folder" in stderr
        assert not out.exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["small.yaml"]  # the lock file is gone
    assert build(small_set, out).returncode == 0


def test_a_killed_builds_lock_file_is_removed_and_a_users_file_of_that_name_kept(tmp_path, small_set):
    lock = tmp_path / ".out.lock"
    lock.write_text(leftovers.text(lock.name))  # a SIGKILLed build's
    assert build(small_set, tmp_path / "out").returncode == 0
    assert not lock.exists()
    lock.write_text("my lock notes")
    assert build(small_set, tmp_path / "out").returncode == 0
    assert lock.read_text() == "my lock notes"


# --- SIGTERM, SIGKILL and TeX's scratch folders -------------------------------------------------

def _processes_in(folder: Path) -> list[int]:
    """The pids of processes whose working folder lies in `folder` (a TeX run left behind)."""
    found = []
    for entry in Path("/proc").iterdir():
        try:
            if entry.name.isdigit() and Path(os.readlink(entry / "cwd")).is_relative_to(folder):
                found.append(int(entry.name))
        except OSError:
            continue
    return found


def test_sigterm_during_the_compiles_cleans_up_as_ctrl_c_does(tmp_path, small_set):
    out, scratch = tmp_path / "out", tmp_path / "tmp"
    scratch.mkdir()
    assert build(small_set, out).returncode == 0
    before = contents(out)
    process = subprocess.Popen([str(DERIVE), "sheet", str(small_set), "--variants", "3", "--out", str(out), "--to",
                                "pdf", "--progress", "none"], cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               text=True, env={**os.environ, "TMPDIR": str(scratch)})
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and not any(scratch.glob("derive-tex-*")) and process.poll() is None:
        time.sleep(0.02)
    assert any(scratch.glob("derive-tex-*")), "no compile started"
    process.terminate()
    _, stderr = process.communicate(timeout=120)
    assert process.returncode == 143 and stderr.strip().splitlines()[-1] == "derive: terminated", stderr
    assert list(scratch.iterdir()) == [] and _processes_in(scratch) == []
    assert contents(out) == before and sorted(p.name for p in tmp_path.iterdir()) == ["out", "small.yaml", "tmp"]


def test_scratch_a_killed_build_left_is_swept_by_the_next(tmp_path, small_set):
    scratch = tmp_path / "tmp"
    scratch.mkdir()
    env = {"TMPDIR": str(scratch)}
    killed = build(small_set, tmp_path / "out", "--to", "pdf", env={**env, "DERIVE_FAULT_AT": "tex-scratch"})
    assert killed.returncode == -signal.SIGKILL, killed.stderr
    # one compile's scratch, or two: the documents compile in parallel, and the kill can fall in another's
    # marking (its folder then empty, or holding a mark cut short); the next build sweeps each
    left = list(scratch.iterdir())
    assert any(leftovers.marked(p) for p in left), left
    assert all(p.name.startswith("derive-tex-") and (leftovers.marked(p) or leftovers.being_marked(p)
                                                     or not any(p.iterdir())) for p in left), left
    again = build(small_set, tmp_path / "out", "--to", "pdf", env=env)
    assert again.returncode == 0, again.stderr
    assert list(scratch.iterdir()) == []


def test_the_sweep_removes_only_scratch_derive_can_prove_its_own(tmp_path, monkeypatch):
    monkeypatch.setattr(export.tempfile, "tempdir", str(tmp_path))
    ended = subprocess.Popen(["true"])
    ended.wait()  # a pid whose process is gone

    def folder(name: str, marked: bool, content: bool = True) -> Path:
        path = tmp_path / name
        path.mkdir()
        if marked:
            leftovers.mark(path)
        if content:
            (path / "work.tex").write_text("mine")
        return path

    swept = [folder(f"derive-tex-{ended.pid}-ab12", marked=True), folder(f"derive-tex-{ended.pid}-cd", False, False)]
    cut_short = folder(f"derive-tex-{ended.pid}-kl", False, False)  # killed while its mark was written
    (cut_short / leftovers.MARK).write_text(leftovers.text(cut_short.name)[:9], encoding="utf-8")
    swept.append(cut_short)
    kept = [folder(f"derive-tex-{ended.pid}-ef34", marked=False),  # a user's, named so
            folder(f"derive-tex-{os.getpid()}-gh56", marked=True),  # a compile under way
            folder("derive-tex-99999999999999999999-ij", marked=True),  # no process has that pid
            folder(f"derive-tex-{ended.pid}", marked=True)]  # not a name derive gives
    link = tmp_path / f"derive-tex-{ended.pid}-kl78"
    link.symlink_to(swept[0].with_name("target"))
    folder("target", marked=True)
    export._sweep_scratch.__wrapped__()
    assert not any(p.exists() for p in swept)
    assert all(p.is_dir() for p in kept) and link.is_symlink() and (tmp_path / "target").is_dir()


# --- a bad --out --------------------------------------------------------------------------------

@pytest.mark.parametrize("out", ["", "/proc/x", "/proc/self/x", "loop/x"])
def test_an_out_that_cannot_be_a_folder_is_a_one_line_error(tmp_path, small_set, out):
    (tmp_path / "loop").symlink_to(tmp_path / "loop")
    stderr = one_line_exit_2(build(small_set, out, cwd=tmp_path))
    assert stderr.startswith("derive: error: --out "), stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["loop", "small.yaml"]  # no build/ made


# --- full and read-only disks ------------------------------------------------------------------

def _in_small_mount(tmp_path, options: str, script: str) -> subprocess.CompletedProcess:
    """Run `script` (sh) in a mount namespace of its own where MOUNT is a tmpfs mounted with
    `options` (unshare -rm: works for any user with user namespaces)."""
    assert shutil.which("unshare"), "util-linux's unshare is part of every Debian"
    mount = tmp_path / "mount"
    mount.mkdir(exist_ok=True)
    command = f"mount -t tmpfs -o {options} tmpfs {mount} && cd {ROOT} && {script.replace('MOUNT', str(mount))}"
    return subprocess.run(["unshare", "-rm", "sh", "-c", command], capture_output=True, text=True, timeout=300)


#: Disk sizes that run out while writing the .tex files, the PDFs, the split worksheets (where
#: qpdf once aborted the whole process on a full disk) and the keys.
FULL_DISKS = ["12k", "100k", "200k", "300k", "400k", "500k"]


@pytest.mark.parametrize("size", FULL_DISKS)
def test_a_full_disk_is_a_one_line_error_and_leaves_no_staging_folder(tmp_path, small_set, size):
    result = _in_small_mount(tmp_path, f"size={size}", f"{DERIVE} sheet {small_set} --variants 3 --out MOUNT/out "
                             "--to pdf --progress none; echo exit=$?; ls -A MOUNT")
    lines = result.stdout.strip().splitlines()
    assert lines and lines[-1] == "exit=2", (result.stdout, result.stderr)  # the mount is empty again
    assert result.stderr.count("\n") == 1 and result.stderr.startswith("derive: error: "), result.stderr
    assert "No space left on device" in result.stderr


def test_a_read_only_folder_is_a_one_line_error(tmp_path, small_set):
    result = _in_small_mount(tmp_path, "ro,size=1m", f"{DERIVE} sheet {small_set} --out MOUNT/out --to ''; "
                             "echo exit=$?")
    assert result.stdout.strip().splitlines()[-1] == "exit=2", (result.stdout, result.stderr)
    errors = [line for line in result.stderr.splitlines() if line.startswith("derive:")]
    assert len(errors) == 1 and "Read-only file system" in errors[0], result.stderr
