"""Output folders belong to the user (derive.publishing.output_folder): refusals, kept files, symlinks, a
kill at every step of the swap, full and read-only disks."""
import json
import os
import shutil
import signal
import subprocess
import sys
import threading
from pathlib import Path

import pytest

from conftest import ROOT
from derive.publishing import output_folder

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
    (out / output_folder.MANIFEST).write_text(json.dumps({"files": ["key.tex"]}))
    before = contents(out)
    stderr = one_line_exit_2(build(small_set, out))
    assert "derive did not write this file and will not replace it" in stderr and "key.csv" in stderr
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
    old = contents(out)
    new_dir = tmp_path / "reference"
    assert build(small_set, new_dir, "--seed", "2").returncode == 0
    new = contents(new_dir)
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
    assert again.returncode == 0, again.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out", "reference", "small.yaml"]  # ... is gone


def test_recover_restores_an_old_build_cut_off_between_the_renames(tmp_path):
    old = tmp_path / ".out.old-999999999"
    old.mkdir()
    (old / "key.csv").write_text("old")
    partial = tmp_path / ".out.partial-999999998"
    partial.mkdir()
    output_folder.recover(tmp_path / "out")
    assert (tmp_path / "out" / "key.csv").read_text() == "old"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]


def test_recover_leaves_the_folders_of_a_build_still_running(tmp_path):
    running = tmp_path / f".out.partial-{os.getppid()}"
    running.mkdir()
    output_folder.recover(tmp_path / "out")
    assert running.is_dir()


def test_ctrl_c_during_the_renames_waits_until_the_new_build_is_in_place(tmp_path, monkeypatch):
    out = tmp_path / "out"
    out.mkdir()
    (out / "key.csv").write_text("old")
    (out / output_folder.MANIFEST).write_text(json.dumps({"files": ["key.csv"]}))
    staging = tmp_path / ".out.partial-1"
    staging.mkdir()
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
