"""Progress on stderr: lines in logs, a rich bar on a terminal, nothing when asked."""
from conftest import run_derive
from derive.publishing.progress import Reporter


def test_lines_name_each_step_with_its_count(capsys):
    report = Reporter("lines")
    with report.task("deriving", 2) as begin:
        begin("rod_endpoint")
        begin("tugged_spool")
    report("compiling the PDF")
    assert capsys.readouterr().err.splitlines() == [
        "deriving rod_endpoint (1/2)", "deriving tugged_spool (2/2)", "compiling the PDF"]


def test_the_bar_counts_the_steps_and_leaves_no_trace(capsys):
    report = Reporter("bar")
    with report.task("deriving", 3) as begin:
        for name in ("a", "b", "c"):
            begin(name)
            assert report._bar.tasks[0].completed == "abc".index(name)
        report("a note while the bar runs")  # shown in the bar, not printed
    assert report._bar is None
    assert "a note" not in capsys.readouterr().err


def test_auto_is_lines_off_a_terminal_and_none_is_silent(tmp_path, capsys):
    assert Reporter("auto").mode == "lines"  # pytest captures stderr: not a terminal
    done = run_derive("sheet", "demo", "--variants", "1", "--to", "md", "--out", str(tmp_path / "a"), "--jobs", "1")
    assert done.returncode == 0 and "deriving rod_endpoint (1/3)" in done.stderr
    assert "writing 3 figures as SVG and PNG (pdftocairo) (3/4)" in done.stderr
    assert "writing the worksheet as md (pandoc) (4/4)" in done.stderr
    quiet = run_derive("sheet", "demo", "--variants", "1", "--to", "md", "--out", str(tmp_path / "b"),
                       "--progress", "none")
    assert quiet.returncode == 0 and quiet.stderr == ""


def test_a_chain_of_states_says_which_state_it_is_finding(tmp_path):
    """A long derivation shows its progress (issue 40, item 5): each state of a chain as it is
    found, among the build's steps; `derive solve` and --progress none stay silent."""
    done = run_derive("sheet", "skid_to_roll", "--to", "", "--out", str(tmp_path / "a"), "--jobs", "1", "--no-cache",
                      "--progress", "lines")
    assert done.returncode == 0, done.stderr
    lines = done.stderr.splitlines()
    found = [lines.index(f"  skid_to_roll: finding the state {s} ({n} of 2)") for n, s in ((1, "launched"), (2, "rolling"))]
    assert lines.index("deriving skid_to_roll (1/1)") < found[0] < found[1] < lines.index("drawing 1 variant of each problem")
    quiet = run_derive("sheet", "skid_to_roll", "--to", "", "--out", str(tmp_path / "b"), "--no-cache", "--progress", "none")
    assert quiet.returncode == 0 and quiet.stderr == ""
    solved = run_derive("solve", "skid_to_roll")
    assert solved.returncode == 0 and solved.stderr == ""


def test_derive_solve_spins_at_a_terminal_and_is_silent_in_a_pipe(capsys):
    """A derivation of a few seconds is not silent where someone watches (a newcomer waited 4 s for
    `derive solve` with nothing on the screen), and prints nothing where a program reads the output."""
    report = Reporter("bar")
    with report.waiting("deriving rolling_incline"):
        report("  rolling_incline: finding the state vertical (1 of 2)")  # a step, shown in the spinner
        assert report._status is not None and "finding the state" in str(report._status.status)
    assert report._status is None and "finding the state" not in capsys.readouterr().err
    done = run_derive("solve", "rod_endpoint")
    assert done.returncode == 0 and done.stderr == ""  # not a terminal: no spinner
