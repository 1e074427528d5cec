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
