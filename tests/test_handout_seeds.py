"""`derive handout` and `derive check --seeds`."""
import subprocess

from conftest import copy_library, run_derive


def test_handout_presents_the_derivation_and_the_correction(tmp_path):
    done = run_derive("handout", "elroys_beanie", "--out", str(tmp_path / "h"))
    assert done.returncode == 0, done.stderr
    text = subprocess.run(["pdftotext", str(tmp_path / "h" / "elroys_beanie.pdf"), "-"], capture_output=True,
                          text=True).stdout
    for part in ("Setup", "Result", "Checks", "Corrections to the notes", "§6.5"):
        assert part in text, part
    assert "Step 1:" not in text  # a step is its sentence and its equations, not a heading made of a fragment


def test_check_with_seeds_passes_and_prints_the_spread(derive):
    done = derive("check", "--seeds", "5", "string_wrapped_disk")
    assert done.returncode == 0, done.stdout + done.stderr
    assert "every seed: conditions met, key equal to derive solve" in done.stdout
    assert [line.split()[1] for line in done.stdout.splitlines()[1:4]] == ["a", "alpha", "T"]


def test_check_with_seeds_fails_when_no_draw_is_valid(tmp_path):
    library = copy_library(tmp_path)
    path = library / "precession" / "top_precession_exact.yaml"
    path.write_text(path.read_text().replace("range: [300, 1000]", "range: [1, 2]"))
    done = run_derive("check", "--seeds", "3", "top_precession_exact", library=library)
    assert done.returncode == 1 and "FAILED" in done.stdout and "no draw in 200" in done.stdout
