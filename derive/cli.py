"""The `derive` command line: parse, call, print. Nothing else lives here.

Heavy modules (sympy and what uses it) are imported inside the commands, so that
`derive --help` starts fast. Exit status: 0 success, 2 bad input (one line on stderr),
3 a missing external program (with the command that installs it), 1 an internal error,
130 Ctrl-C and 143 SIGTERM (either after cleaning up).
"""
from __future__ import annotations

import contextlib
import functools
import os
import signal
import sys
import threading
import traceback
from pathlib import Path

import click

from derive.core.library import DISTRIBUTION, version
from derive.core.limits import MAX_DIGITS, MAX_VARIANTS
from derive.core.errors import EngineLimit, InputError, MissingTool, Terminated
from derive.language import labels

from derive.cli_options import BadInput, FiniteRange, Seconds, check_environment, derives_options, parse_assignments

FORMATS = click.Choice(["text", "latex", "json"])


def progress_option(command):
    """`--progress auto|bar|lines|none`, handed to the command as a derive.publishing.progress.Reporter."""

    @click.option("--progress", "progress_mode", type=click.Choice(["auto", "bar", "lines", "none"]),
                  default="auto", show_default=True,
                  help="Progress on stderr: a bar on a terminal and lines otherwise (auto), or as chosen.")
    @functools.wraps(command)
    def wrapper(*args, progress_mode: str, **kwargs):
        from derive.publishing.progress import Reporter  # light: no sympy

        progress = Reporter(progress_mode)
        with progress.steps_shown():
            return command(*args, progress=progress, **kwargs)

    return wrapper


def reports_errors(command):
    """Turn bad input into exit 2 with one line, and anything unexpected into exit 1."""

    @functools.wraps(command)
    def wrapper(*args, **kwargs):
        try:
            return command(*args, **kwargs)
        except click.ClickException:
            raise
        except InputError as error:
            raise BadInput(str(error)) from None
        except MissingTool as error:
            click.echo(f"derive: error: {error}", err=True)
            sys.exit(3)
        except RuntimeError as error:
            from derive.publishing.export import BuildError

            if not isinstance(error, (BuildError, EngineLimit)):
                _internal(error)  # a check between routes that fails (CheckFailure) is an engine bug
            click.echo(f"derive: error: {error}", err=True)
            sys.exit(1)
        except KeyboardInterrupt as interruption:
            _interrupted(interruption)
        except BrokenPipeError:  # the reader stopped (derive list | head): stop quietly
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
            sys.exit(0)
        except Exception as error:  # an engine bug: say so, exit 1
            _internal(error)

    return wrapper


def _interrupted(interruption: BaseException | None):
    """Ctrl-C (exit status 130) or SIGTERM (143, derive.core.errors.Terminated), each as 128 + the
    signal, once the build has cleaned up: one line."""
    if isinstance(interruption, Terminated):
        click.echo("derive: terminated", err=True)
        sys.exit(128 + signal.SIGTERM)
    click.echo("derive: interrupted", err=True)
    sys.exit(128 + signal.SIGINT)


def _raise_terminated(signum, frame):
    """The SIGTERM handler of _sigterm_as_ctrl_c."""
    raise Terminated()


@contextlib.contextmanager
def _sigterm_as_ctrl_c():
    """SIGTERM raises derive.core.errors.Terminated in the main thread while the command runs, so that
    it cleans up as on Ctrl-C (staging and scratch folders removed, every TeX run stopped) instead
    of dying at once."""
    if threading.current_thread() is not threading.main_thread():  # only the main thread handles signals
        yield
        return
    previous = signal.signal(signal.SIGTERM, _raise_terminated)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, signal.SIG_DFL if previous is None else previous)  # None: set outside Python


def _internal(error: Exception):
    """An engine bug: one line, exit 1 (DERIVE_DEBUG=1 prints the traceback too)."""
    if os.environ.get("DERIVE_DEBUG"):
        traceback.print_exc()
    click.echo(f"derive: internal error: {type(error).__name__}: {error}", err=True)
    sys.exit(1)


def _show_version(ctx: click.Context, _param, shown: bool) -> None:
    """`derive --version`: the version importlib.metadata gives for the distribution."""
    if shown:
        click.echo(f"derive {version()}")
        ctx.exit()


def course_digits(digits: int | None, otherwise: int | None = 15) -> int | None:
    """--digits, else the course defaults' (derive.toml), else `otherwise`."""
    if digits is not None:
        return digits
    from derive.language import defaults  # light: no sympy

    return defaults.load().digits or otherwise


#: click 8.2 and later raise this usage error for a group called without a command (8.1 shows the help).
_NO_ARGS_IS_HELP = getattr(click.exceptions, "NoArgsIsHelpError", ())


class DeriveGroup(click.Group):
    """click's group with derive's errors: a usage error is one line on stderr (what is wrong and
    where the help is), exit status 2, instead of click's usage block."""

    def main(self, args=None, prog_name=None, **extra):
        try:
            with _sigterm_as_ctrl_c():
                status = super().main(args, prog_name or "derive", standalone_mode=False, **extra)
        except _NO_ARGS_IS_HELP as error:  # `derive` alone: its help, as --help shows it
            click.echo(error.ctx.get_help())
            sys.exit(0)
        except click.UsageError as error:
            command = error.ctx.command_path if error.ctx else "derive"
            message = " ".join(error.format_message().split())
            where = command.partition(" ")[2]  # the subcommand, as every other error names its field
            click.echo(f"derive: error: {where + ': ' if where else ''}{message} (see '{command} --help')", err=True)
            sys.exit(2)
        except click.ClickException as error:
            error.show()
            sys.exit(error.exit_code)
        except click.Abort as abort:  # click's word for a KeyboardInterrupt no command caught
            _interrupted(abort.__cause__)
        sys.exit(status if isinstance(status, int) else 0)


@click.group(cls=DeriveGroup, context_settings={"help_option_names": ["-h", "--help"], "max_content_width": 100})
@click.option("--version", is_flag=True, expose_value=False, is_eager=True,
              callback=_show_version,
              help="Print derive's version (of the distribution " + DISTRIBUTION + ") and exit.")
@click.option("--time-limit", type=Seconds(), default=None, metavar="SECONDS",
              help="Give up a symbolic step (an integral, a simplification, a derivation) after SECONDS, "
                   "with exit status 2. [default: $DERIVE_TIME_LIMIT, else 60; 0 or off: no limit]")
def main(time_limit: float | None) -> None:
    """Derive the mechanics of rotating bodies, and build problem sets from it.

    A problem file describes a scene (bodies, pivots, strings, gravity) and the
    quantities it asks for; derive finds the equations of motion by Lagrange's method
    and by Newton–Euler, checks that they agree, and answers exactly and numerically.

    \b
    Examples:
      derive list
      derive solve string_wrapped_disk --set m=1 --set M=2 --set R=0.2
      derive solve problems/torque/compound_pendulum.yaml --format json
      derive inertia rod --axis end
      derive sheet demo --variants 5 --seed 7 --out build/demo
      derive check
      derive bench --quick
    """
    check_environment()
    if time_limit is not None:
        from derive.core import limits  # light: no sympy

        limits.configure(time_limit)


@main.command()
@click.argument("problem")
@click.option("--set", "assignments", multiple=True, metavar="NAME=VALUE",
              help='Give a parameter a value: "m=2" (in its declared unit) or "m=200 g". Repeatable.')
@click.option("--format", "fmt", type=FORMATS, default="text", show_default=True, help="Output format.")
@click.option("--digits", type=click.IntRange(1, MAX_DIGITS), default=None,
              help="Significant digits of every value (each one correct to the digits shown). "
                   "[default: derive.toml's digits, else the significant figures the inputs support "
                   "(15 in JSON)]")
@click.option("--proof", is_flag=True,
              help="Also print the equations of motion by Lagrange's method and by Newton–Euler, which the "
                   "checks compare (printed anyway where no textbook route is written).")
@reports_errors
def solve(problem: str, assignments: tuple[str, ...], fmt: str, digits: int | None, proof: bool) -> None:
    """Derive a problem and print its solution, answers and checks.

    PROBLEM is a problem file or a library id (see `derive list`). An answer gets a
    value when every parameter it uses has one (declared in the file or given with
    --set); otherwise only its exact expression is printed. The solution is the route
    a textbook takes (Newton's second law along the motion, energy, torques about a
    pivot), where derive writes one; both routes' equations of motion with --proof.

    \b
    Examples:
      derive solve sphere_rolls_incline
      derive solve string_wrapped_disk --set m=1 --set M=2 --set R=0.5 --proof
      derive solve problems/torque/seesaw.yaml --format json
    """
    from derive import api
    from derive.publishing.progress import Reporter

    shown = Reporter("bar" if sys.stderr.isatty() else "none")  # a spinner at a terminal; nothing in a pipe
    with shown.waiting(f"deriving {problem}"), shown.steps_shown():
        result = api.solve(problem, parse_assignments(assignments), course_digits(digits, 15 if fmt == "json" else None))
    click.echo(result.as_text(proof) if fmt == "text" else {"latex": result.as_latex, "json": result.as_json}[fmt]())


@main.command()
@click.argument("shape")
@click.option("--axis", default=None, metavar="NAME|X,Y,Z",
              help="An axis of the shape (see the table) or a direction such as 1,0,1. [default: the axis "
                   "the shape turns about in a planar scene]")
@click.option("--about", default=None, metavar="X,Y,Z",
              help="A point the axis passes through (a named axis is moved parallel to itself), and the "
                   "point --tensor is taken about; e.g. 0,0,h/2.")
@click.option("--density", default=None, metavar="EXPR",
              help="A density in the shape's coordinates instead of a uniform mass M, e.g. \"rho0*(r/R)^2\" "
                   "(SI: kg/m, kg/m^2 or kg/m^3 for curves, surfaces, solids; must not be negative).")
@click.option("--set", "assignments", multiple=True, metavar="NAME=VALUE",
              help="A value: M in kg, sizes and --about names in m (or with a unit: \"R=5 cm\"), other "
                   "names as SI numbers. Repeatable; each must be positive.")
@click.option("--tensor", "show_tensor", is_flag=True, help="Also print the inertia tensor.")
@click.option("--format", "fmt", type=FORMATS, default="text", show_default=True, help="Output format.")
@click.option("--digits", type=click.IntRange(1, MAX_DIGITS), default=None,
              help="Significant digits of the value. [default: derive.toml's digits, else 15]")
@reports_errors
def inertia(shape: str, axis: str | None, about: str | None, density: str | None, assignments: tuple[str, ...],
            show_tensor: bool, fmt: str, digits: int | None) -> None:
    """Moment of inertia of a SHAPE by integrating rho d^2 over it.

    Prints the integral set up, the total mass from the same density, I exactly and
    as a multiple of M size^2, the inertia tensor with --tensor (about the center of
    mass, or about --about), and with --set a value of I. Expressions may use M, the
    shape's size symbols, pi, sqrt, sin, ...; any other name is a parameter (positive)
    that --set can give a value.

    \b
    SHAPE                  axes                sizes (name symbol)               coordinates
    point                  center              -                                 -
    rod                    center, end         length L                          x
    ring                   symmetry, diameter  radius R                          phi
    disk                   symmetry, diameter  radius R                          r, phi
    annulus                symmetry, diameter  inner_radius R1, outer_radius R2  r, phi
    cylinder               symmetry, diameter  radius R, height h                z, r, phi
    cylindrical_shell      symmetry, diameter  radius R, height h                z, phi
    sphere                 symmetry            radius R                          r, theta, phi
    spherical_shell        symmetry            radius R                          theta, phi
    thick_spherical_shell  symmetry            inner_radius R1, outer_radius R2  r, theta, phi
    plate                  symmetry, a, b      side_a a, side_b b                x, y
    box                    symmetry, a, b, c   side_a a, side_b b, side_c c      x, y, z
    cone                   symmetry, diameter  radius R, height h                z, r, phi

    \b
    Every shape lies centered on the origin, its center of mass (the cone's is h/4 above
    its base): a rod along x, flat shapes in the xy plane, symmetry axes along z, a
    diameter along x, a plate's or box's axis a, b, c along its sides. A density may
    use the shape's coordinates and Cartesian x, y, z.

    \b
    Examples:
      derive inertia rod --axis end --set M=2 --set L=3
      derive inertia cone --axis diameter --tensor --format json
      derive inertia cylinder --axis diameter --about 0,0,h/2
      derive inertia box --axis 1,1,1 --set M=12 --set a=1 --set b=2 --set c=3
      derive inertia disk --density "rho0*(r/R)^k" --set rho0=3 --set k=2 --set R=0.5
      derive inertia point --axis 0,0,1 --about d,0,0
    """
    from derive.publishing import inertia_report

    result = inertia_report.report(shape, axis, parse_assignments(assignments), course_digits(digits), about, density,
                                   show_tensor)
    click.echo(inertia_report.FORMATTERS[fmt](result))


@main.command(name="list")
@click.option("--topic", default=None, help="Only problems of this topic.")
@click.option("--search", default=None, metavar="WORDS",
              help="Only problems whose id, title, question, source or tags hold every one of these words "
                   "(any case; a word of four letters or more also finds longer ones: pulley finds pulleys).")
@click.option("--difficulty", type=click.Choice(labels.DIFFICULTIES), default=None,
              help="Only problems of this difficulty.")
@click.option("--tag", "tags", multiple=True, type=click.Choice(labels.TAGS), metavar="TAG",
              help=f"Only problems with this tag (repeat for several: all of them). Tags: {', '.join(labels.TAGS)}.")
@reports_errors
def list_problems(topic: str | None, search: str | None, difficulty: str | None, tags: tuple[str, ...]) -> None:
    """List the problems of the library: id, topic, difficulty and title.

    \b
    Examples:
      derive list --topic rolling
      derive list --search "wrapped disk"
      derive list --topic rolling --search yo-yo
      derive list --difficulty easy --tag pulley
    """
    from derive.core import library
    from derive.language import problem

    rows = []
    for path in library.problem_files():
        p = problem.heading(path)
        if topic in (None, p.topic) and difficulty in (None, p.difficulty) and set(tags) <= set(p.tags) \
                and library.matches(search or "", p.id, p.title, p.question, p.source, *p.tags):
            rows.append((p.id, p.topic, p.difficulty or "-", p.title))
    if not rows:
        asked = " and ".join(x for x in (topic and f"of topic {topic!r}", difficulty and f"of difficulty {difficulty!r}",
                                         tags and f"tagged {', '.join(tags)}", search and f"matching {search!r}") if x)
        raise BadInput(f"no problems {asked}")
    widths = [max(len(r[k]) for r in rows) for k in (0, 1, 2)]  # aligned columns, the title last
    for row in rows:
        click.echo("  ".join(f"{cell:<{width}}" for cell, width in zip(row, widths)) + f"  {row[3]}")


@main.command()
@click.option("--out", type=click.Path(dir_okay=False, path_type=Path), default=Path("build/catalogue.html"),
              show_default=True, help="The HTML file to write (replaced whole, or left as it was on an error).")
@click.option("--figures/--no-figures", default=True, show_default=True,
              help="Draw each problem's figure (TeX and pdftocairo, about a minute for the library).")
@reports_errors
def catalogue(out: Path, figures: bool) -> None:
    """Write the library as one self-contained HTML page, for choosing a week's set: each
    problem's title, topic, difficulty, tags, source, statement, figure, and what it gives and asks.

    \b
    Examples:
      derive catalogue
      derive catalogue --out ~/public_html/problems.html --no-figures
    """
    from derive.core import library
    from derive.language import problem
    from derive.publishing import catalogue as pages

    entries = pages.entries([problem.load(str(path)) for path in library.problem_files()], figures)
    pages.write(out, pages.page(entries, "The derive problem library", version()))
    click.echo(f"{out}: {len(entries)} problems")


@main.command()
@click.option("--set", "of_set", is_flag=True, help="The schema of a set file instead of a problem file.")
@reports_errors
def schema(of_set: bool) -> None:
    """Print the JSON Schema of a problem file (or, with --set, of a set file).

    An editor's YAML support then completes and checks keys as you type. Save it and name it on
    the first line of a problem file:

    \b
      derive schema > problem.schema.json
      # yaml-language-server: $schema=problem.schema.json
    """
    import json

    from derive.language import schema as schemas

    click.echo(json.dumps(schemas.set_schema() if of_set else schemas.problem_schema(), indent=1))


@main.command()
@click.argument("problems", nargs=-1)
@click.option("--seeds", type=click.IntRange(1, 10000), default=None,
              help="Instead: draw each problem's parameters with N seeds and check every draw (conditions "
                   "met, key equal to derive solve, a chain of states simulated); print each answer's range.")
@progress_option
@reports_errors
def check(problems: tuple[str, ...], seeds: int | None, progress) -> None:
    """Run every cross-check over the library (or the PROBLEMS given) and print a table.

    For each problem: the independent routes of derivation (Lagrange and Newton–Euler,
    energy, conservation and impulses, integration and the parallel-axis theorem, ...),
    the dimensions of every answer, and a numerical simulation where the scene moves (a
    chain of states link by link). Exit status 1 if any check fails.

    \b
    Examples:
      derive check
      derive check tugged_spool compound_pendulum
      derive check --seeds 50 top_precession_exact
    """
    from derive import audit

    if seeds is not None:
        spreads, failures = audit.stress(list(problems), seeds, progress=progress)
        click.echo(audit.spread_table(spreads, failures))
        sys.exit(1 if failures else 0)
    rows = audit.audit(list(problems), progress=progress)
    click.echo(audit.table(rows))
    if not all(r.passed for r in rows):
        sys.exit(1)


@main.command()
@click.option("--quick", is_flag=True,
              help="A shorter run: fewer problems, samples and variants; 4 scenes and chains up to n = 3.")
# The sections of derive.bench.runs.SECTIONS (not imported here: the command line starts without sympy)
@click.option("--only", type=click.Choice(["startup", "derivations", "backends", "answer_key", "set_rate", "sheet",
                                           "mechanics_alone", "work_precision", "engines", "solution_length",
                                           "course"]),
              default=None, help="Run one section (engines: derive against sympy.physics.mechanics; course: the "
                                 "library as one set, cold, warm, one question changed, peak memory; "
                                 "solution_length: the displayed equations of every worked solution).")
@click.option("--variants", type=click.IntRange(1, MAX_VARIANTS), default=30, show_default=True,
              help="Course: variants per problem.")
@click.option("--to", "outputs", default="", metavar="LIST", help="Course: the outputs, as derive sheet --to takes "
                                                                "them. [default: LaTeX and the keys only]")
@click.option("--json", "as_json", is_flag=True,
              help="Print the engines section's figures as one JSON document on stdout (the other "
                   "sections' lines and the progress go to stderr).")
@click.option("--scenes", default=None, metavar="LIST",
              help="Engines: these scenes only (comma-separated ids of derive.bench.anchors.SCENES).")
@click.option("--max-n", type=click.IntRange(1, 12), default=None,
              help="Engines: the n-link pendulum up to this n (default 6; 3 with --quick).")
@click.option("--repeats", type=click.IntRange(1, 20), default=3, show_default=True,
              help="Engines: runs of a job under 20 s, whose median is shown.")
@click.option("--limit", type=FiniteRange(1), default=None, metavar="SECONDS",
              help="Engines: CPU seconds a run may take before it is stopped and shown as "
                   "'over limit' (default 300; 60 with --quick).")
@reports_errors
def bench(quick: bool, only: str | None, as_json: bool, scenes: str | None, max_n: int | None, repeats: int,
          limit: float | None, variants: int, outputs: str) -> None:
    """Measure speed against accuracy and print the figures (never pass/fail).

    CLI start-up; derivation per problem, cold and cached; answers per second, worst
    relative error and wrong values of each evaluation method (naive evalf, float, mpmath,
    the agreement policy, auto one at a time and over variants) against a 50-digit
    reference, at typical and extreme parameters; a 30-problem x 300-variant answer key;
    the marginal answers per second of a whole set build (300 variants against 1);
    sympy.physics.mechanics alone on the same systems; a work-precision table of scipy's
    integrators and a symplectic one. Only when asked (--only course): the whole library as
    one set of --variants, cold, warm (a new seed), one question changed, and peak memory.

    \b
    Engines (derive against sympy.physics.mechanics, in the same run):
    - 14 scenes (pendulums, Atwood machine, cords over pulleys, rolling, loops, a yo-yo,
      a spring, pin linkages), each a problem file derive reads and the same physics built
      with KanesMethod (derive.bench.anchors). Both must give the same accelerations,
      constraint forces and answers at a sample point; a scene where they differ is
      reported, with no timing.
    - derive's time: the problem read, Lagrange and Newton-Euler (equations formed and
      solved), the inertia integrals, every answer and cross-check (`derive check` without
      its simulation); the anchor's: its model, Kane's equations and their solution.
    - The n-link pendulum (rods pinned end to end), n = 1..6: derive's Lagrange route,
      its Newton-Euler route, its whole solve, and the KanesMethod n-link pendulum.
    Each run is a fresh child of one worker (imports paid once, every cache empty); the
    figures are the median wall seconds of up to --repeats runs and the rise of peak
    resident memory (MiB). A run over --limit CPU seconds shows 'over limit'.
    """
    import json

    from derive.bench import runs as benchmarks

    options = {"repeats": repeats, "max_n": max_n, "limit": limit, "variants": variants, "outputs": outputs}
    if scenes:
        from derive.bench.anchors import SCENES

        options["scenes"] = [s.strip() for s in scenes.split(",") if s.strip()]
        unknown = [s for s in options["scenes"] if s not in SCENES]
        if unknown:
            raise click.BadParameter(f"{', '.join(unknown)} (known: {', '.join(SCENES)})", param_hint="--scenes")

    def progress(line: str) -> None:
        click.echo(line, err=True)

    say = progress if as_json else click.echo
    figures = benchmarks.run(say, quick=quick, only=only, note=progress, **options)
    if as_json:
        click.echo(json.dumps(figures, indent=1))


@main.command()
@click.argument("problem")
@click.option("--out", "out_dir", default=None,
              help="Output folder (default: build/handouts/<id>).")
@progress_option
@reports_errors
def handout(problem: str, out_dir: str | None, progress) -> None:
    """A step-by-step handout of one problem's derivation, in LaTeX and PDF.

    Setup, each step of each route of derivation, the result with a worked example at the
    middle of the parameter ranges, the independent checks, and any correction to the notes.

    \b
    Example:  derive handout tugged_spool --out build/spool
    """
    from derive.publishing import worksheets as sheets

    for path in sheets.handout(problem, out_dir, progress=progress):
        click.echo(str(path))


@main.command()
@click.argument("references", metavar="SET | PROBLEM...", nargs=-1, required=True)
@click.option("--variants", type=click.IntRange(1, MAX_VARIANTS), default=None,
              help="Variants per problem (default: the set's, else 1).")
@click.option("--seed", type=int, default=None, help="Seed of the parameter draws (default: the set's).")
@click.option("--out", "out_dir", default=None,
              help="Output folder (default: build/<set id>).")
@click.option("--to", "formats", default=None, metavar="LIST",
              help="Outputs besides .tex and the keys (CSV, JSON), comma-separated: any of pdf, html, md, docx, "
                   "moodle, qti; distractors adds wrong answers from common mistakes to key.json. "
                   "[default: the set's outputs, else pdf,html]")
@click.option("--questions", type=click.Choice(["numerical", "choice"]), default=None,
              help="How the Moodle and Canvas exports ask: a number with a tolerance, or multiple choice "
                   "among wrong answers derived from common mistakes. [default: the set's, else numerical]")
@derives_options
@progress_option
@reports_errors
def sheet(references: tuple[str, ...], variants: int | None, seed: int | None, out_dir: str | None,
          formats: str | None, questions: str | None, progress, jobs: int, cache: bool,
          scheduler: str | None) -> None:
    """Build a problem set: worksheet, worked solutions and answer key.

    SET is a set file or the id of one in problems/sets/; or give one or more PROBLEMs
    (library ids or problem files), built as a set of their own (one variant, seed 0,
    output in build/<ids>). Each variant draws the parameters from their declared ranges
    (reproducibly from the seed) and rounds them to their significant figures. Writes .tex
    files, PDFs (latexmk), HTML (pandoc) and the answer key as CSV and JSON; with --to also
    Markdown and DOCX (pandoc), Moodle XML (a cloze question per problem and variant) and a
    QTI 1.2 zip for Canvas. A derive.toml in the working folder gives course defaults
    (see the documentation: Course defaults). Each problem's derivation is kept in the derivation
    cache (`derive cache --help`): a rebuild after a new seed or a question's text derives nothing;
    the others are derived --jobs at a time, or by a Dask cluster's workers (--scheduler).

    \b
    Examples:
      derive sheet demo --variants 30 --seed 7 --to pdf,moodle
      derive sheet rod_endpoint tugged_spool --out build/two
      derive sheet demo --jobs 1 --no-cache
      derive sheet bank.yaml --scheduler tcp://10.0.0.5:8786

    \b
    A set file needs a title and its problems; the rest has defaults:
      title: Rotation, week 3
      problems: [rod_endpoint, problems/torque/tugged_spool.yaml, {topic: rolling, count: 2}]
      course: PHY141            due: 2026-12-01        variants: 30      seed: 141
      outputs: [pdf, moodle]    questions: choice      (options given here override it)
    """
    from derive.language import defaults
    from derive.publishing import worksheets as sheets

    wanted = None if formats is None else defaults.outputs(formats, "--to")
    built = sheets.build(references, variants=variants, seed=seed, out_dir=out_dir, formats=wanted,
                         questions=questions, defaults=defaults.load(), progress=progress, jobs=jobs, cache=cache,
                         scheduler=scheduler)
    for path in built:
        click.echo(str(path))


@main.command()
@click.argument("action", type=click.Choice(["info", "clear"]))
@reports_errors
def cache(action: str) -> None:
    """The derivation cache: each problem's derivation, kept for the next build. info prints
    its folder, entries, size and cap; clear removes every entry.

    An entry is keyed by what the derivation reads (the scene, the asks and the parameters
    with their ranges, not the question's text, title or source) and by derive's, sympy's
    and python-flint's versions; an entry that does not match is never used. It lives in the
    user's cache folder, or $DERIVE_CACHE_DIR, capped at $DERIVE_CACHE_MB megabytes (512):
    the entries used longest ago go first. `derive sheet --no-cache` neither reads nor writes it.

    \b
    Examples:
      derive cache info
      derive cache clear
      DERIVE_CACHE_DIR=/tmp/derive-cache derive sheet demo
    """
    from derive.publishing import derivation_cache

    if action == "clear":
        click.echo(f"removed {derivation_cache.clear()} entries from {derivation_cache.folder()}")
        return
    shown = derivation_cache.info()
    click.echo(f"{shown['folder']}: {shown['entries']} entries, {shown['bytes'] / 2**20:.1f} MB of "
               f"{shown['cap'] / 2**20:.0f} MB")


if __name__ == "__main__":
    main()
