"""Issue 15 item 1: every part of a scene says in a sentence what it contributes to each route, with
its own symbols, written once per part (derive.parts, Part.sentences), and the worked solutions
open each route's steps with those sentences."""
import importlib
import pkgutil
from decimal import Decimal
from types import SimpleNamespace

import pytest
import sympy as sp

import derive.parts
from conftest import textbook
from derive.publishing import render, report, variants, worksheets
from derive.solution.answers import Solution
from derive.mechanics.impacts import Touch
from derive.model.kinematics import Coordinates
from derive.mechanics.moves import _Couple
from derive.parts import Part
from derive.parts.clutch import Clutch
from derive.parts.contact import Contact
from derive.parts.cord import Attachment, Cord
from derive.parts.damper import Damper
from derive.parts.force import Force
from derive.parts.gravity import Gravity
from derive.parts.pin import Pin
from derive.parts.rims import Rims
from derive.parts.slider import Slider
from derive.parts.slipping_clutch import SlippingClutch
from derive.parts.spring import Spring
from derive.parts.surfaces import Plane
from derive.parts.torque import Torque
from derive.parts.torsional_spring import TorsionalSpring
from derive.parts.weld import Weld
from derive.language.problem import load
from derive.model.scene import Body, Scene
from test_check import PSEUDO_MATH

M, m, R, r, F, C, k, b, c, kappa, mu, tau, g = sp.symbols("M m R r F C k b c kappa mu_k tau g", positive=True)


def _every_part_kind():
    """A scene of two disks, a rod, a block and a cart with one of each kind of part (and each
    regime of a contact, and the parts impacts and turns make): geometry enough for every
    sentence, not a scene to solve."""
    bodies = {"wheel": Body("wheel", "disk", M, {"radius": R}),
              "hub": Body("hub", "disk", m, {"radius": r}),
              "rod": Body("rod", "rod", m, {"length": R}, at=(sp.Integer(4), sp.Integer(0))),
              "block": Body("block", "point", m, {}, at=(R, sp.Integer(-3))),
              "cart": Body("cart", "point", m, {}, at=(sp.Integer(6), -R))}
    floor = Plane("floor", sp.Integer(0), through=(sp.Integer(0), -R))
    parts = [Pin("axle", "wheel", (0, 0)), Pin("hinge", "rod", (R / 2, 0), "cart", (0, 0)),
             Slider("rail", "cart", (0, 0), sp.Integer(0), turns=True), Slider("guide", "rod", (0, 0), sp.pi / 6),
             Weld("glue", "hub", "wheel"), Weld("bracket", "rod", None),
             Clutch("plates", "hub", "wheel"), Clutch("brake", "hub", None), SlippingClutch("felt", "hub", "wheel", C),
             Cord("string", (Attachment("wound", "wheel", radius=R, turn=-1, grips=True), Attachment("point", "block"))),
             Cord("pull", (Attachment("wound", "hub", radius=r, turn=1, grips=True),
                           Attachment("pulled", force=F, angle=sp.Integer(0)))),
             Contact("wheel_contact", "wheel", "floor", True), Contact("cart_contact", "cart", "floor", False),
             Contact("skid", "cart", "floor", False, kinetic=mu, direction=-1),
             Contact("foot", "rod", "floor", True, point=(-R / 2, 0)),
             Gravity(g), Force("push", "rod", (R / 2, 0), F, sp.pi / 2), Torque("motor", "wheel", tau),
             Spring("coil", ("block", None), ((0, 0), (R, 0)), k, R),
             TorsionalSpring("twist", "rod", "wheel", kappa, sp.Integer(0)),
             Damper("dashpot", ("cart", None), ((0, 0), (0, 0)), b),
             Damper("drag", ("wheel", None), ((0, 0), (0, 0)), c, rotational=True),
             Touch("hit", "block", "rod", (R / 2, 0), (sp.Integer(0), sp.Integer(1)), rough=True),
             Touch("drop", "cart", None, (0, 0), (sp.Integer(0), sp.Integer(1)), surface="floor"),
             Rims("rims", "wheel", "hub", (sp.Integer(1), sp.Integer(0)), R, -r),
             _Couple("hub", "wheel")]
    return parts, Coordinates(Scene(bodies, surfaces={"floor": floor}))


def _reads_as_prose(sentence) -> bool:
    words = sentence.words
    return words[:1].isupper() and words.endswith(".") and not any(p in words for p in PSEUDO_MATH)


def test_every_part_kind_says_what_it_contributes_to_each_route():
    for module in pkgutil.iter_modules(derive.parts.__path__):
        importlib.import_module(f"derive.parts.{module.name}")
    kinds, stack = set(), [Part]
    while stack:
        for sub in stack.pop().__subclasses__():
            kinds.add(sub)
            stack.append(sub)
    parts, coords = _every_part_kind()
    assert kinds == {type(p) for p in parts}, "a part kind with no example here: add it to _every_part_kind"
    assert all("sentences" in kind.__dict__ for kind in kinds), [k for k in kinds if "sentences" not in k.__dict__]
    for part in parts:
        for route in ("lagrange", "newton_euler"):
            said = part.sentences(route, coords)
            assert said and all(_reads_as_prose(s) for s in said), (part.name, route, [s.words for s in said])
            assert all(s.latex() and s.text() for s in said)
        acted_on = {load.body for load in part.loads(coords)}
        assert acted_on <= {s.body for s in part.sentences("newton_euler", coords)}, part.name  # one per body it acts on


def _latex(reference) -> str:
    problem = load(reference)
    return report.as_latex(report.solve(problem, solution=Solution(problem)))


def _torques_said(solution: Solution) -> dict[str, sp.Expr]:
    """Per body, the sum of the torques the Newton–Euler sentences state ("its torque about it is X")."""
    result = {}
    for step in solution.derivations["newton_euler"].steps:
        for sentence in step.sentences:
            pieces = list(sentence.pieces)
            for i, piece in enumerate(pieces[:-1]):
                if isinstance(piece, str) and piece.endswith("its torque about it is "):
                    result[sentence.body] = result.get(sentence.body, 0) + pieces[i + 1]
    return result


@pytest.mark.parametrize("reference, body", [("string_wrapped_disk", "disk"),
                                             (textbook("atwood_massive_pulley"), "pulley"),
                                             (textbook("ladder_statics"), "ladder"),
                                             ("rolling_incline", "ball")])
def test_the_torques_the_sentences_state_are_the_torque_balance(reference, body):
    """Radius times force, said part by part, adds up to the right side of the body's torque balance."""
    solution = Solution(load(reference))
    (balance,) = [s for s in solution.derivations["newton_euler"].steps if s.text.startswith(f"Forces and torques on the {body} ")]
    assert sp.simplify(_torques_said(solution)[body] - balance.equations[2].rhs) == 0


def test_string_wrapped_disk_says_each_part():
    text = _latex("string_wrapped_disk")
    for said in (
            r"The axle holds the disk's center in place: the gap between the two points is held by the multipliers "
            r"$R_{x}^{\mathrm{axle}}$ and $R_{y}^{\mathrm{axle}}$, the components of its reaction.",
            r"The cord string runs from the disk, wound on it, to the block; it does not stretch, so its length stays "
            r"what it is, and the multiplier of that constraint is its tension $T_{\mathrm{string}}$.",
            r"It does not slip on the disk, so the disk's rim moves with it: the arc of its turn, "
            r"$R \theta_{\mathrm{disk}}$, counts in the length.",
            r"Gravity gives each body the potential energy of its weight times its height above where it is placed: "
            r"$M g y_{\mathrm{disk}} + g m y_{\mathrm{block}}$.",
            r"The axle pushes on the disk with its reaction at its center of mass, so it exerts no torque about it.",
            r"The cord string pulls the disk along its run with the tension $T_{\mathrm{string}}$ at a distance $R$ "
            r"from its center of mass; its torque about it is $- R T_{\mathrm{string}}$, negative: it turns the body "
            r"clockwise.",
            r"The weight of the block, $g m$, pulls it straight down.",
            r"The cord string does not stretch, and does not slip on the disk, so the rates at which its runs lengthen "
            r"add up to zero: $R \dot{\theta}_{\mathrm{disk}} - \dot{y}_{\mathrm{block}} + \dot{y}_{\mathrm{disk}} = 0$."):
        assert said in text, said
    lagrange, newton_euler = text.split(r"\subsection*{Newton–Euler}")
    assert "The axle holds" in lagrange and "The axle pushes" in newton_euler  # each route its own sentences


def test_atwood_machine_says_each_run_of_the_rope():
    text = _latex(textbook("atwood_massive_pulley"))
    for said in (r"The part of the cord rope that runs from the left, around the pulley; it does not stretch",
                 r"its tension $T_{\mathrm{rope},1}$.", r"its tension $T_{\mathrm{rope},2}$.",
                 r"its torque about it is $R T_{\mathrm{rope},1}$, positive: it turns the body counter-clockwise.",
                 r"its torque about it is $- R T_{\mathrm{rope},2}$, negative: it turns the body clockwise.",
                 r"It does not slip on the pulley, so the pulley's rim moves with it: the arc of its turn, "
                 r"$R \theta_{\mathrm{pulley}}$, counts in the length."):
        assert said in text, said


def test_ladder_says_where_the_floor_and_the_wall_push():
    text = _latex(textbook("ladder_statics"))
    for said in (r"The ladder's foot rests on the floor and does not slip: it keeps touching it, a gap held by the "
                 r"normal force $N^{\mathrm{foot}}$, and it does not slide along it, held by the friction "
                 r"$f^{\mathrm{foot}}$.",
                 r"The ladder's head rests on the wall without friction: it keeps touching it, a gap held by the normal "
                 r"force $N^{\mathrm{head}}$.",
                 r"The wall pushes the ladder's head with the normal force $N^{\mathrm{head}}$ at a distance "
                 r"$\frac{L}{2}$ from its center of mass; its torque about it is "
                 r"$- \frac{L N^{\mathrm{head}} \sin{\left(\theta \right)}}{2}$.",  # sin(theta): its sign unsaid
                 r"The ladder's foot does not move into the floor, nor along it: it grips."):
        assert said in text, said


def test_rolling_incline_says_the_friction_turns_the_ball():
    text = _latex("rolling_incline")
    for said in (r"The ball rests on the ramp and does not slip: it keeps touching it, a gap held by the normal force "
                 r"$N^{\mathrm{ball}}$, and the distance along it, with its radius times its turn, stays what it is, "
                 r"held by the friction $f^{\mathrm{ball}}$.",
                 r"The ramp pushes the ball with the normal force $N^{\mathrm{ball}}$ at a distance $R$ from its center "
                 r"of mass, along a line through it, so it exerts no torque about it.",
                 r"its torque about it is $R f^{\mathrm{ball}}$."):  # the friction may point either way
        assert said in text, said


def test_spring_says_its_energy_and_its_pull():
    solution = Solution(load(textbook("spring_horizontal")))
    (spring,) = [p for p in solution.scene.loads if type(p).__name__ == "Spring"]
    energy = solution.derivations["lagrange"].steps[0]
    said = [s for s in energy.sentences if s.words.startswith("The spring spring1 stores")]
    assert said and said[0].pieces[1] == spring.potential(solution.coordinates)  # the V the Lagrangian holds
    text = report.as_text(report.solve(solution.problem, solution=solution), solution)
    assert "The spring spring1 stores half its stiffness times the square of its stretch:" in text
    assert "The spring spring1 has its rest length where the block is placed, so it pulls it with no force there" in text
    assert "The floor pushes the block with the normal force N__block." in text


def test_solutions_and_handout_print_the_sentences():
    """The sheet's worked solutions (before each step, in the proof by two routes of the appendix) and
    the handout (its proof), and so pandoc's HTML, Markdown and DOCX made from the same LaTeX, print the
    parts' sentences."""
    problem = load("string_wrapped_disk")
    middle = {name: p.value if p.range is None else p.at(Decimal("0.5")) for name, p in problem.parameters.items()}
    context = worksheets._solutions_context(variants.ProblemVariants(problem, Solution(problem), [middle]), siunitx=True)
    handout = render.render("handout.tex.j2", problem={**context, "limits": [], "example": {"given": [], "results": []}},
                            question="")
    sheet = render.render("solutions.tex.j2", problems=[context], verification=True,
                          set=SimpleNamespace(title="Week 9", course="Mechanics", due="Friday"))
    # the student's route comes first; the routes, with the parts' sentences, are the proof after it
    assert context["verification"] and "Forces and torques along the motion" in sheet.split("\\appendix")[0]
    for tex in (handout, sheet):
        assert r"The string pulls the disk along its run with the tension $T_{\mathrm{string}}$" in tex  # its key, described
        assert tex.index("The axle holds the disk's center in place") < tex.index(r"K &=")  # before the energies


@pytest.mark.parametrize("problem_id, said", [
    ("restitution_rod", r"In the bounce bounced the ball strikes the rod: the gap between the two points along the normal "
                        r"is held by the multiplier $J^{\mathrm{bounced}}$, the impulse."),
    ("beetle_lazy_susan", r"The pin stopped holds the beetle's center to the susan's point there: the gap between the two "
                          r"points is held by the multipliers $R_{x}^{\mathrm{stopped}}$ and $R_{y}^{\mathrm{stopped}}$"),
    ("elroys_beanie", r"The couple that turns the inner relative to the outer, of any size $\tau_{\mathrm{turn}}$, does "
                      r"work at the rate of the couple times their relative angular velocity")])
def test_events_say_the_joint_or_couple_they_make(problem_id, said):
    """An impact's step opens with the sentence of the joint it makes; a turn's with its couple."""
    assert said in _latex(problem_id)
