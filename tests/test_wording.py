"""Issue 37, item 5: no key of the problem file in a student's text, and one letter for one kind of thing.

The engine names a body, a part and a state by its key ("Newton's second law for the left", "the
cord rope", "The start, sent:"); the documents describe them (derive.publishing.wording). A length L
beside an angular momentum L_z, an incline's theta beside a body's turn theta_ball: the documents
print ell and phi (derive.publishing.letters).
"""
import re

import pytest
import sympy as sp

from conftest import derived, notes_files, student_solution, textbook, textbook_files
from derive.core import library
from derive.language.problem import load
from derive.publishing import letters
from derive.publishing.wording import DIRECTIONS, Wording, bodies
from derive.text.latex import symbol_latex

LIBRARY = [p.stem for p in library.problem_files()]


def test_a_body_is_described_by_its_mass_or_its_shape_and_place():
    """A body by its mass parameter's meaning (the heavier block), by its place and the noun the bodies
    share (each bob: the left bob), by its shape, numbered where two share one; never by its key."""
    assert bodies(load("atwood_smooth")) == {"left": "left block", "right": "right block"}
    assert bodies(load("atwood_pulley_speed"))["heavy"] == "heavier block"
    assert bodies(load("coupled_pendulums")) == {"left": "left bob", "right": "right bob"}
    assert bodies(load("stepped_pulley"))["block1"] == "block on the small step"
    assert set(bodies(load("mass_concentration")).values()) == {"first disk", "second disk", "ring"}


def test_the_engines_words_are_reworded_and_a_direction_stays_one():
    words = Wording(load("atwood_smooth"))
    assert words("Newton's second law for the left along its motion, down") == \
        "Newton's second law for the left block along its motion, down"
    assert words("The weight of the right, g m_2, pulls it to the left.") == \
        "The weight of the right block, g m_2, pulls it to the left."
    assert words("The cord rope runs from the left's point") == "The cord runs from the left block's point"
    springs = Wording(load("two_blocks_three_springs"))
    assert springs("Forces on the first (spring spring1, spring spring2)") == \
        "Forces on the first block (spring between the support and the first block, " \
        "spring between the first block and the second block)"


def test_a_word_that_names_a_state_stays_english_in_a_routes_sentence():
    """rod_swings_down's state is named lowest: the swing route's "to the lowest point" had become "to the
    joint of the position reached point"; the state named with its kind is still reworded."""
    words = Wording(load("rod_swings_down"))
    assert words("Energy is conserved from the release to the lowest point") == \
        "Energy is conserved from the release to the lowest point"
    assert words("the state lowest") == "the state reached"
    tex, student = student_solution("rod_swings_down")
    assert student and "the lowest point" in tex and "position reached point" not in tex


def test_a_states_heading_says_what_happens():
    """"The start, sent:" and "The impact bounced, just after coming:" named the file's states."""
    words = Wording(load("ball_bounces_off_rod"))
    assert words("The start, coming: the placement moving at the given rates") == \
        "The start: the placement moving at the given rates"
    assert words("The impact bounced, just after coming: the ball bounces off the rod") == \
        "The impact: the ball bounces off the rod"
    assert words("In the bounce bounced the ball strikes the rod") == "In the bounce the ball strikes the rod"
    stick = Wording(load("child_jumps_then_walks_in"))
    assert stick("The move inside, just after aboard: the child is carried to a new place on the platform") == \
        "The move, after the impact: the child is carried to a new place on the merry-go-round"
    assert stick("Forces on the child (reaction of aboard)") == "Forces on the child (reaction of the joint of the impact)"
    assert Wording(load("block_up_incline"))("From rest at the placement to back: the motion until the block's x "
                                             "gets to its value") == \
        "From rest at the placement: the motion until the block's horizontal position reaches its given value"


def _prose(tex: str) -> str:
    """A worked solution's words: no math, no section titles (the file's title is the instructor's)."""
    tex = tex.split(r"\maketitle", 1)[1].split(r"\subsection*{Numbers for", 1)[0]
    tex = re.sub(r"\\begin\{align\*\}.*?\\end\{align\*\}|\$[^$]*\$|\\section\{[^}]*\}", " ", tex, flags=re.S)
    return tex.replace(r"\_", "_")


@pytest.mark.parametrize("problem_id", LIBRARY)
def test_no_key_of_the_file_in_a_students_solution(problem_id):
    """Over the worked solution a student is given of each library problem: no key of a body, a
    part (a cord, a joint, a load), a surface or a state that is no word (block1, ball_contact,
    spring1, arms_in) appears in the prose; one whose description is other than itself (a body left,
    the left block; a pin hinge, the pivot) never follows "the" (but a direction: to the left); no
    state's key heads a step ("The start, sent:")."""
    tex, _ = student_solution(problem_id)
    prose, scene = _prose(tex), derived(problem_id).problem.scene
    words = Wording(derived(problem_id).problem)
    described = {**words.problems_bodies, **words.surfaces, **words.parts, **words.states}
    keys = {*scene.bodies, *scene.surfaces, *scene.states, *(getattr(p, "name", "") for p in (*scene.constraints, *scene.loads))}
    said = {w for d in described.values() for w in d.split()}  # "the stool" of "the student and the stool"
    found = []
    for key in sorted(k for k in keys if k):
        if not re.fullmatch(r"[a-z]+", key):
            found += re.findall(r"(?<![\w\\])" + re.escape(key) + r"(?!\w)", prose)
        elif described.get(key, key) != key and key not in said and not words.only_a_state(key):
            # (a state named by a word, lowest: "the lowest point" is the route's English; the engine names
            # a state with its kind, "the state lowest", which is reworded)
            found += [m[0] for m in re.finditer(r"(?<!to )\b[Tt]he " + key + r"\b", prose)
                      if not (key in DIRECTIONS and prose[m.start() - 3:m.start()] == "to ")]
        found += re.findall(r"The start, " + re.escape(key) + r"\b|just after " + re.escape(key) + r"\b", prose)
    assert not found, found


@pytest.mark.parametrize("problem_id", LIBRARY)
def test_one_letter_for_one_kind_of_thing(problem_id):
    """In each library problem's worked solution, a length L is not printed beside an L with a
    subscript (rigid_body_L's L_z = L^2 m omega sin^2(alpha)/12 printed the rod's length and its
    angular momentum with one letter), and where the file names an angle theta no body's turn is
    printed theta_body (the incline's theta beside the ball's theta_ball)."""
    tex, _ = student_solution(problem_id)
    problem = derived(problem_id).problem
    math = " ".join(a or b for a, b in re.findall(r"\\begin\{align\*\}(.*?)\\end\{align\*\}|\$([^$]*)\$", tex, flags=re.S))
    math = math.replace(r"\mathcal{L}", " ")  # the Lagrangian's script L is a letter of its own
    if "L" in problem.parameters:
        assert not (re.search(r"(?<![\\\w])L(?![_\w])", math) and re.search(r"(?<![\\\w])L_\{", math)), "L and L_..."
    if any(re.match(r"theta(_|\d|$)", n) for n in (*problem.parameters, *problem.asks)):
        turns = [b for b in problem.scene.bodies if rf"\theta_{{\mathrm{{{b}}}}}" in math or rf"\theta}}_{{\mathrm{{{b}}}}}" in math]
        assert not turns, turns


def test_a_joint_force_gives_way_to_a_radius():
    """Issue 37: a hoop's radius R beside the nail's force R_x^nail printed one letter for two kinds of
    thing; the force is printed F_x^nail (the problem's names, and so its key, are its own)."""
    tex, _ = student_solution("hoop_on_nail")
    math = " ".join(a or b for a, b in re.findall(r"\\begin\{align\*\}(.*?)\\end\{align\*\}|\$([^$]*)\$", tex, flags=re.S))
    assert re.search(r"(?<![\\\w])R(?![_\w])", math) and not re.search(r"(?<![\\\w])R_\{[xy]\}", math)
    assert "F_{x}" in math


def test_the_letters_give_way_only_to_a_clash():
    """ell only where another L is printed, phi only where the file names a theta, psi where it names phi too."""
    L, theta = sp.Symbol("L", positive=True), sp.Symbol("theta", positive=True)
    turn = sp.Symbol("theta_rod", real=True)
    assert letters.printed({"L": L}, (), {sp.Symbol("L_O")}) == {L: sp.Symbol("ell", positive=True)}
    assert letters.printed({"L": L}, (), {sp.Symbol("M")}) == {}
    assert letters.printed({"L": L, "ell": sp.Symbol("ell")}, (), {sp.Symbol("L_O")}) == {}
    assert letters.printed({"theta": theta}, (), {turn}) == {turn: sp.Symbol("phi_rod", real=True)}
    assert letters.printed({"theta": theta, "phi": sp.Symbol("phi")}, (), {turn}) == {turn: sp.Symbol("psi_rod", real=True)}
    assert letters.printed({"alpha": theta}, (), {turn}) == {}


def test_a_body_of_parts_is_called_what_it_is_never_an_abbreviated_key():
    """A newcomer's clock pendulum (a rod and a disk, `pend:`) read "The pend turns about its pivot" in
    its worked solution and its LMS feedback: a body of parts that swings from a pivot is the pendulum;
    a key the question uses as a word (the ladder, the top) stays."""
    words = Wording(load(textbook("rod_disk_clock_pendulum")))
    assert words("The pend turns about its pivot") == "The pendulum turns about its pivot"
    assert bodies(load("ladder_firefighter"))["ladder"] == "ladder"
    assert bodies(load("elroys_beanie"))["outer"] == "outer body"  # turning in space, about its center: no pendulum


@pytest.mark.parametrize("path", [*notes_files(), *textbook_files()], ids=lambda p: p.stem)
def test_no_body_key_as_a_subscript_in_the_students_route(path):
    """Issue 37, item 5: where no plain name is free, the student's route numbers a symbol by its
    body's place in the scene (a_1, f_1, omega_1'), never by the body's key (a_block, f^spool,
    omega_large' had been printed). The parameters' and asks' own names (m_ball) are the file's words
    in the question too. Only a problem whose student solution takes the student's route: the others
    still print the engine's coordinates (x_ball, theta_ball), which issue 37 leaves open."""
    tex, route = student_solution(path)
    if not route:
        return
    problem = derived(path).problem
    math = " ".join(a or b for a, b in re.findall(r"\\begin\{align\*\}(.*?)\\end\{align\*\}|\$([^$]*)\$", tex, flags=re.S))
    for written in sorted({symbol_latex(n) for n in (*problem.parameters, *problem.asks)} - {*problem.parameters, *problem.asks},
                          key=len, reverse=True):  # m_{\mathrm{ball}}, not a plain a
        math = math.replace(written, " ")
    found = [m[0] for key in problem.scene.bodies
             for m in re.finditer(r"[_^]\{(?:\\mathrm\{)?" + re.escape(key) + r"'?\}", math)]
    assert not found, found
