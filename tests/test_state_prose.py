"""Issues 12 and 15: a worked solution shows each state of a chain (the start, each segment of
motion, each impact, move or turn) as its own section, headed in words and in the file's order, and
says in sentences the principle each of its steps uses, from the facts the derivation holds (which
parts do no work, about which point a momentum is kept, the restitution, the kinetic friction), in
the parts' Sentence machinery (derive.text.prose)."""
import functools
from decimal import Decimal
from pathlib import Path
from types import SimpleNamespace

import pytest
import sympy as sp

from conftest import derived, textbook
from derive.core import library
from derive.publishing import render, variants, worksheets
from derive.solution.answers import Solution
from derive.language.problem import load
from test_check import PSEUDO_MATH

#: Every library and textbook problem with states, and those whose steps follow a motion along its
#: path (a swing's period at its amplitude: a turning point, its time by quadrature).
STEPPED = sorted([str(p) for p in library.problem_files() if "states:" in p.read_text()]
                 + [str(textbook("torsion_pendulum_wide_swing"))])
CHAINS = [p for p in STEPPED if "states:" in Path(p).read_text()]


@functools.lru_cache(maxsize=None)
def _solved(reference: str) -> tuple[Solution, dict]:
    solution = derived(reference)
    return solution, solution.steps()


def _principles(solution: Solution, name: str) -> list[str]:
    """What the sentences of a state's section must name, by the kind of state: the rates given,
    an impact's impulses and its kind (inelastic, locked, restitution), a move's kept momentum by
    Noether's theorem, a segment's energy (conserved, or the work-energy theorem) and how it ends,
    a slip's kinetic friction and constant accelerations, a time's constant acceleration or quadrature;
    the regime a contact with friction starts in, and the work of kinetic friction on the way."""
    state = solution.scene.states[name]
    if state.rates:
        return ["at the rates given"]
    if state.event is not None:
        kind = state.event.kind
        if kind in ("move", "turn"):
            return ["Noether's theorem", "angular momentum", "kinetic energy"]
        own = {"stick": "perfectly inelastic", "lock": "turn as one", "bounce": "law of restitution",
               "transfer": "tangent there"}[kind]
        return ["give no impulse", own, "Kinetic energy is"]
    if state.until and state.until[0] == "grips":
        return ["kinetic", "the accelerations are constant", "it grips"]
    ends = {None: [], "stops": ["A turning point"], "leaves": ["leaves the", "first falls to zero"],
            "slack": ["goes slack where it first falls to zero"], "slips": ["starts to slip where it first falls"]}
    timed = any(a.state == name and a.quantity.kind == "time" for a in solution.problem.asks.values())
    scene = solution.scene_in(name)
    rubbing = any(getattr(c, "regime", None) == "kinetic" for c in scene.constraints)
    work = ["Kinetic friction at", "work-energy theorem"] if rubbing else \
        ["no work" if scene.constraints else "energy", "energy"]
    held = ["Held by static friction"] if solution.starts.get(name) else []
    return (held + work + ends[state.until[0] if state.until else None] + (["time"] if timed else []))


@pytest.mark.parametrize("reference", CHAINS, ids=lambda p: Path(p).stem)
def test_each_state_is_a_section_whose_sentences_name_its_principle(reference):
    solution, steps = _solved(reference)
    names = solution._on_the_way()
    headings = [solution.state_heading(n) for n in names]
    assert names and all(h in steps for h in headings)
    assert [h for h in steps if h in headings] == headings  # in the file's order
    for name, heading in zip(names, headings):
        said = " ".join(s.words for step in steps[heading] for s in step.sentences)
        missing = [p for p in _principles(solution, name) if p.lower() not in said.lower()]
        assert not missing, (name, missing, said)
        assert heading[:1].isupper() and not any(p in heading for p in PSEUDO_MATH)


@pytest.mark.parametrize("reference", STEPPED, ids=lambda p: Path(p).stem)
def test_chain_steps_read_as_prose(reference):
    """The golden prose check of tests/test_check.py, over every chain problem's steps: words in the
    step texts and sentences, never ASCII pseudo-math (the math is the sentences' sympy pieces)."""
    solution, steps = _solved(reference)
    meanings = {a.meaning for a in solution.problem.asks.values()}
    texts = [s.text for route in steps.values() for s in route if s.text not in meanings]
    assert not [t for t in texts if any(p in t for p in PSEUDO_MATH)], texts
    said = [s.words for route in steps.values() for step in route for s in step.sentences]
    assert not [w for w in said if any(p in w for p in PSEUDO_MATH) or not w[:1].isupper() or not w.endswith(".")]
    for route in steps.values():  # each sentence prints both ways
        for step in route:
            assert all(s.latex() and s.text() for s in step.sentences)


def _kept_sentence(solution: Solution, steps: dict, name: str):
    (kept,) = [s for step in steps[solution.state_heading(name)] for s in step.sentences
               if "angular momentum about that point is conserved" in s.words]
    return kept


def _rod_struck(tmp_path: Path, hinge: str) -> Solution:
    """The rod ballistic pendulum up to the impact, its hinge at `hinge`."""
    text = (textbook("rod_ballistic_pendulum")).read_text()
    text = text.replace("    hinge: {pin: rod.start}\n", f"    hinge: {{pin: {hinge}}}\n")
    text = text.replace("    highest: {when: stops, from: struck}\n", "")
    asked = next(line for line in text.splitlines(keepends=True) if line.startswith("  angle: "))
    assert "in: highest" in asked
    text = text.replace(asked, "")
    path = tmp_path / "rod_ballistic_pendulum.yaml"
    path.write_text(text)
    return Solution(load(path))


def test_the_kept_angular_momentum_is_said_about_the_pin_where_the_derivation_has_it(tmp_path):
    """The sentence's point is the pin's, where the impact finds it: moved from the rod's top to its
    center, the sentence moves with it; a joint to the ground other than a pin (a block's cord)
    gives an impulse the engine keeps no momentum against, and the sentence says so."""
    L = sp.Symbol("L", positive=True)
    top = _rod_struck(tmp_path, "rod.start")
    kept = _kept_sentence(top, top.steps(), "struck")
    assert "the axle" not in kept.words and "the pin hinge" in kept.words
    assert sp.Tuple(0, 0) in kept.pieces
    middle = _rod_struck(tmp_path, "rod.center")
    moved = _kept_sentence(middle, middle.steps(), "struck")
    assert sp.Tuple(0, -L / 2) in moved.pieces and sp.Tuple(0, 0) not in moved.pieces
    assert r"\left( 0, \  - \frac{L}{2}\right)" in moved.latex()
    held, steps = _solved(str(textbook("ballistic_pendulum_block")))  # a block hung by a cord
    intro = steps[held.state_heading("struck")][0]
    said = " ".join(s.words for s in intro.sentences)
    assert "of the cord cord, does not act at one pin: no momentum is named" in said
    assert not [s for step in steps[held.state_heading("struck")] for s in step.sentences
                if "is conserved through the impact" in s.words]


def test_the_energy_sentences_name_the_parts_that_do_work():
    """Energy is conserved where only gravity works (a rod swinging down); with a torque, the
    work-energy theorem, the torque's power the one the Lagrangian's generalized force has."""
    rod, rod_steps = _solved(str(textbook("rod_swings_down")))
    (name,) = rod._on_the_way()
    said = [s.words for step in rod_steps[rod.state_heading(name)] for s in step.sentences]
    assert "Gravity stores potential energy: its work is the drop in ." in said
    assert any(w.startswith("So energy is conserved") for w in said)
    assert any(w.startswith("The pin hinge does no work") for w in said)
    wheel, wheel_steps = _solved(str(textbook("flywheel_torque_work")))
    (name,) = wheel._on_the_way()
    (torque,) = [p for p in wheel.scene.loads if type(p).__name__ == "Torque"]
    (working,) = [s for step in wheel_steps[wheel.state_heading(name)] for s in step.sentences
                  if s.words.startswith(f"The torque {torque.name} does work at the rate")]
    assert working.pieces[1] == torque.power(wheel.coordinates)
    assert any(s.words.startswith("So, by the work-energy theorem") and f"the work of the torque {torque.name}"
               in s.words for step in wheel_steps[wheel.state_heading(name)] for s in step.sentences)


def test_a_move_says_noethers_theorem_about_the_axle():
    solution, steps = _solved(str(textbook("child_walks_to_center")))
    (kept,) = [s for step in steps[solution.state_heading("centered")] for s in step.sentences
               if "Noether's theorem" in s.words]
    assert kept.words.startswith("Turning the whole scene rigidly about  changes none of the gaps of the axle and the "
                                 "pin feet")
    assert sp.Tuple(0, 0) in kept.pieces


def test_a_grip_is_timed_once():
    """A grip's time is one of its own steps: the worked solution shows it once."""
    solution, steps = _solved(str(textbook("flywheel_brake_grips")))
    (name,) = [n for n in solution._on_the_way() if solution.scene.states[n].until]
    texts = [s.text for s in steps[solution.state_heading(name)]]
    assert texts.count("The slip rate falls steadily from where it starts, and reaches zero at") == 1


def test_solutions_print_the_state_sentences_and_headings():
    problem = load(str(textbook("clutch_disks_brake")))
    middle = {name: p.value if p.range is None else p.at(Decimal("0.5")) for name, p in problem.parameters.items()}
    solution, _ = _solved(str(textbook("clutch_disks_brake")))
    context = worksheets._solutions_context(variants.ProblemVariants(problem, solution, [middle]), siunitx=True)
    sheet = render.render("solutions.tex.j2", problems=[context], verification=True,
                          set=SimpleNamespace(title="Week 9", course="Mechanics", due="Friday"))
    # the states and parts by what they are, not by the file's keys (derive.publishing.wording), in the
    # verification by two routes (the student's route, the angular momentum about the axle, comes first)
    order = [r"\section*{Verification by two routes}",
             r"\subsubsection*{The start: the placement moving at the given rates}",
             r"\subsubsection*{The impact: the upper disk and the lower disk lock together}",
             r"The only impulse from outside the bodies is that of the axle, at $\left( 0, \  0\right)$",
             r"\subsubsection*{From the impact: the motion until it stops}",
             r"The applied torque does work at the rate $- \tau \dot{\theta}_{\mathrm{lower}}$",
             r"So, by the work-energy theorem, the kinetic energy at each $\theta_{\mathrm{lower}}$",
             r"A turning point: the motion, with $\theta_{\mathrm{lower}}$ increasing"]
    places = [sheet.index(said) for said in order]
    assert places == sorted(places)
