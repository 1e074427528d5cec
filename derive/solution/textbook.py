"""The student's worked solution: the route a solution manual takes, chosen from the scene and the asks.

One principle a step, each a law the course teaches: speeds between two states by energy
(derive.mechanics.conservation); accelerations and forces at the placement by Newton's second law
along the motion and torques about the center of mass or a fixed pivot (derive.mechanics.along_motion);
the time down a slope from the constant acceleration; the least coefficient of friction from the
friction and normal force found; statics by the balances of forces and of torques about the point
that removes the most unknowns (derive.mechanics.statics); small oscillations about a pivot by
tau = -kappa theta (derive.mechanics.small_swings; a body rocking on its round face, about its point
of contact); a top's steady precession by tau = Omega x L, a skid that ends in rolling, an impact by
the angular momentum about the axle or about the free bodies' center of mass, a cord pulled in through
a hole, an ellipse by the conservation of angular momentum and energy at its turning points, the least
height for a loop by Newton at its top and energy (derive.solution.textbook_routes); a speed and a force at
a state on a circle (a pendulum, a body in a bowl or leaving a dome) by energy and Newton's second law toward the
center (derive.solution.swing_route). Lagrange's method and Newton–Euler stay as the proof (the
instructor's verification): this route is a third one, which must agree with them
(derive.solution.crosschecks: the check textbook_route).

Where an ask lies outside these principles (a longer chain of states, an oscillation's amplitude), no
student route is written (`steps` is None) and the worked solution shows the two routes.

>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> steps = Solution(load("rolling_incline")).student_steps
>>> list(steps)
['Forces and torques along the motion', 'The speed at the bottom, by energy', 'The time to the bottom']
"""
from __future__ import annotations


import sympy as sp

from derive import quantities
from derive.mechanics.along_motion import AlongMotion, NotAlongALine, along_motion
from derive.mechanics.derivation import KINETIC
from derive.text.latex import symbol_latex
from derive.text.steps import Step, renamed
from derive.mechanics.small_swings import SmallSwing, small_swing
from derive.mechanics.statics import statics
from derive.model.scene import Quantity
from derive.parts.contact import Contact
from derive.solution.textbook_routes import TextbookRoute, loop_route, orbit_route, state_route, top_route
from derive.solution.uniform_route import uniform_route
from derive.solution.swing_route import swing_route
from derive.solution.sliding import slide_from_rest
from derive.solution.work_energy import kinetic_energy
from derive.solution.crosschecks import same_at_samples
from derive.parts.surfaces import Plane


def covered(quantity: Quantity) -> bool:
    """Whether the student's route answers the quantity (`QuantityKind.student_route`): an acceleration,
    a force; a quantity read at the placement adds its own section to it (a torque: r x F with the
    forces the route finds)."""
    return quantities.KINDS[quantity.kind].student_route(quantity)


SWINGS = {("small_oscillation", "omega"), ("small_oscillation", "period")}


def route(solution) -> AlongMotion | SmallSwing | TextbookRoute | None:
    """The route along the motion of the solution's scene (or its balance, its small swing about a
    pivot, a top's steady precession, its states: an impact, a skid), where every ask is one the
    student's route answers (None otherwise)."""
    if solution.scene.states:
        return state_route(solution) or uniform_route(solution) or swing_route(solution)
    if solution.scene.orbit is not None:
        return orbit_route(solution)
    loop = loop_route(solution)
    if loop is not None:
        return loop
    asks = solution.problem.asks.values()
    top = top_route(solution) if solution.scene.pivot_points else None
    if top is not None:
        return top
    if asks and {(a.quantity.kind, a.quantity.detail) for a in asks} <= SWINGS and not solution.scene.states:
        try:
            return small_swing(solution.dynamics_scene, solution.coordinates)
        except NotAlongALine:
            return None
    if any((a.quantity.kind, a.quantity.detail) in SWINGS for a in asks):
        return _swing_and_balance(solution)
    if not asks or any(a.state is not None or a.zero_for and not quantities.KINDS[a.quantity.kind].own_section
                       or not covered(a.quantity) for a in asks):
        return None
    if len(solution.regimes) != 1:
        return slide_from_rest(solution, solution._needed_unknowns())
    if all(quantities.KINDS[a.quantity.kind].own_section for a in asks) and not solution._needed_unknowns():
        return None  # no force is asked or read: the quantities' own sections are the solution
    arguments = (solution.dynamics_scene, solution.coordinates, solution.derivations["newton_euler"],
                 solution._sample, solution._needed_unknowns())
    for principle in (along_motion, statics):
        try:
            return principle(*arguments)
        except NotAlongALine:
            continue
    return None


def _swing_and_balance(solution) -> TextbookRoute | None:
    """A body hanging at rest on its pivot, asked the period of its small swings and forces at rest (a hoop on a
    nail: Halliday, Resnick & Walker 10th ed., ch. 15): the small swings by the torque about the pivot, then the
    forces by the balance at rest; None where either is not the student's route."""
    others = [a for a in solution.problem.asks.values() if (a.quantity.kind, a.quantity.detail) not in SWINGS]
    if solution.scene.states or len(solution.regimes) != 1 or any(
            a.state is not None or a.zero_for or not covered(a.quantity) or quantities.KINDS[a.quantity.kind].own_section
            for a in others):
        return None
    try:
        swing = small_swing(solution.dynamics_scene, solution.coordinates)
        balance = statics(solution.dynamics_scene, solution.coordinates, solution.derivations["newton_euler"],
                          solution._sample, solution._needed_unknowns())
    except NotAlongALine:
        return None
    at_rest = solution.derivations["lagrange"].at(solution.coordinates.at_rest_in_reference())
    compared = (("omega^2", swing.omega**2, lambda: solution.oscillations["lagrange"].stiffness),
                *((str(u), value, (lambda u=u: at_rest[u])) for u, value in balance.values.items()))
    sections = {f"Small oscillations about {swing.about}": tuple(renamed(step, _swing_names(solution)) for step in swing.steps),
                "The forces at rest, in balance": balance.steps}
    return TextbookRoute(sections, compared, f"the torque about {swing.about} for the small swings, and the balance "
                                             "of forces at rest", along=balance)


def _swing_names(solution) -> dict[sp.Symbol, sp.Symbol]:
    """The small swings' period and frequency under the names the question asks them by."""
    return {sp.Symbol({"period": "T", "omega": "omega"}[a.quantity.detail]): sp.Symbol(a.name)
            for a in solution.problem.asks.values() if a.quantity.kind == "small_oscillation"}


def student_steps(solution) -> dict[str, list[Step]] | None:
    """The student's worked solution by section, or None where it is not written (`route`)."""
    along = solution.textbook_route
    if along is None:
        return None
    if isinstance(along, SmallSwing):  # the period and the frequency under the names the question asks them by
        return {f"Small oscillations about {along.about}": [renamed(step, _swing_names(solution)) for step in along.steps]}
    if isinstance(along, TextbookRoute):
        change = names(solution)
        return {title: [renamed(step, change) for step in steps] for title, steps in along.sections.items()}
    title = "Forces and torques along the motion" if along.names else "Forces and torques in balance"
    result = {title: list(along.steps)}
    for ask in solution.problem.asks.values():
        if ask.quantity.detail == "min_friction_coefficient":
            result[title].append(_least_coefficient(solution, ask))
    counted = [step for ask in solution.problem.asks.values() if ask.sign is not None
               for step in _counted(solution, along, ask)]
    for body, balance in solution.energy_balances.items():
        result["The speed at the bottom, by energy" if len(solution.energy_balances) == 1
               else f"The speed of the {body} at the bottom, by energy"] = _energy(solution, body, balance, along)
    for ask in solution.problem.asks.values():
        if ask.quantity.detail == "time_to_bottom":
            step = _time_down(solution, ask)
            if step is None:
                return None
            result["The time to the bottom"] = [step]
    change = names(solution)
    shown = {title: [renamed(step, change) for step in steps] for title, steps in result.items()}
    shown[title] += counted  # in the ask's own name, which no renaming of the route's symbols touches
    return {**shown, **solution._quantity_sections()}  # each its own section, after the forces it reads


def names(solution) -> dict[sp.Symbol, sp.Symbol]:
    """How the student's route prints the engine's forces and its own symbols (`_plain_names`,
    `_clashes`): the free-body diagrams beside it label them so too."""
    along = solution.textbook_route
    along = along.along if isinstance(along, TextbookRoute) else along
    if not isinstance(along, AlongMotion):
        return {}
    return {**_plain_names(solution, along), **_clashes(solution, along)}


def _plain_names(solution, along: AlongMotion) -> dict[sp.Symbol, sp.Symbol]:
    """Each constraint force as a textbook names it, where that names one thing: f and N for the one
    contact's friction and normal force (f^ball), T for the one cord's tension (T_string), T_1 and
    T_2 on the two sides of a pulley; two normal forces after their surfaces where a word names each
    (N_floor, N_wall), else after their bodies (N_1, N_2); where a parameter, or an ask of something else, takes the name,
    the force on one body is numbered after it (`Scene.numbers`: f_1), any other keeps the engine's name."""
    plain = {u: _plain(u.name) for u in along.acting}  # the route's and its free-body diagrams' forces
    counts = {}
    for name in plain.values():
        counts[name] = counts.get(name, 0) + 1
    surfaces = {u: part.surface for part in solution.dynamics_scene.constraints if isinstance(part, Contact)
                for u in part.unknowns().values()}
    problem, result = solution.problem, {}
    taken = {symbol_latex(n) for n in (*problem.parameters, *problem.asks)}
    for u, name in plain.items():
        if counts[name] > 1 and u in surfaces:  # two normal forces: N_floor and N_wall, after a surface named by a word
            owner = u.name.partition("^")[2]
            name = f"{name}_{surfaces[u]}" if surfaces[u].isalpha() or owner not in solution.dynamics_scene.bodies \
                else f"{name}_{solution.dynamics_scene.numbers()[owner]}"  # N_1, N_2: no key "left_side" typeset
        if counts.get(name, 0) > 1 or name == u.name:
            continue
        if name in problem.parameters or name in problem.asks and not _same(solution, name, along.acting[u] * along.values[u]):
            # the file's f is another thing (the friction along +x): the ask's own name where an ask is this force
            # (F for a cord's pull beside a period T), else f_1, never f^spool after the body's key
            owner = u.name.partition("^")[2]
            part = next((c.name for c in solution.dynamics_scene.constraints if u in c.unknowns().values()), None)
            asked = next((a for a, ask in problem.asks.items() if ask.quantity.target == part is not None
                          and _same(solution, a, along.acting[u] * along.values[u])), None)
            name = asked or (f"{name}_{solution.dynamics_scene.numbers()[owner]}" if owner in solution.dynamics_scene.bodies
                             else None)
            if name is None or asked is None and symbol_latex(name) in taken:
                continue
        result[u] = sp.Symbol(name, real=True)
    return result


def _plain(name: str) -> str:
    """f^ball -> f, R_x^hinge -> R_x, T_string -> T, T_rope_1 -> T_1."""
    head = name.split("^")[0]
    parts = head.split("_")
    if parts[0] == "T" and len(parts) > 1:
        return "T" + (f"_{parts[-1]}" if parts[-1].isdigit() else "")
    return head


def _same(solution, name: str, value) -> bool:
    """Whether the ask `name` is the quantity `value` (the same expression at points of the ranges)."""
    if value is None:
        return False
    return same_at_samples(solution.problem, solution.expression(name), value)


def _clashes(solution, along: AlongMotion) -> dict[sp.Symbol, sp.Symbol]:
    """The route's own symbols that a problem file's name takes with another meaning (a parameter a,
    or an ask a that is the block's y component, y up), each numbered after its body (`Scene.numbers`: a_1
    for the acceleration along its motion of the block of mass m1; a_1' where a file's name is a_1),
    never subscripted by the body's key, which is the file's and no word of the student's."""
    problem, result = solution.problem, {}
    taken = {symbol_latex(n) for n in (*problem.parameters, *problem.asks)}
    for symbol, value in along.own.items():
        name = str(symbol)
        if name in problem.parameters or name in problem.asks and not _same(solution, name, value):
            owner = next(body for (body, _), named in along.names.items() if named == symbol)
            numbered = f"{name}_{solution.dynamics_scene.numbers()[owner]}"
            result[symbol] = sp.Symbol(numbered if symbol_latex(numbered) not in taken else f"{numbered}'", real=True)
            taken.add(symbol_latex(result[symbol].name))
    return result


def _energy(solution, body: str, balance, along: AlongMotion) -> list[Step]:
    """The work-energy theorem as a textbook writes it: K = M v^2/2 + I omega^2/2, with the moment of
    inertia and the rolling condition omega = v/R put in (derive.solution.work_energy), then energy
    conserved from rest (the balance's own last step)."""
    given, kinetic, _ = kinetic_energy(solution, body, along)
    if not given:
        return [Step("Energy is conserved: only gravity does work", (sp.Eq(KINETIC, kinetic),)), balance.steps[-1]]
    return [Step(f"Energy is conserved: gravity does work, the normal force none, and static friction none either, "
                 f"acting at a point of the {body} that does not slip. Its kinetic energy is that of its center's motion "
                 f"and of its rotation about the center, with its moment of inertia and its rate of turning",
                 (*given, sp.Eq(KINETIC, kinetic), sp.Eq(KINETIC, balance.steps[1].equations[0].rhs))),
            balance.steps[-1]]


def _counted(solution, along: AlongMotion, ask) -> list[Step]:
    """The answer counted the way the question says, where the route found it along the motion the
    other way ("taking up as positive" of a block going down: a = -2 g (m1 - m2)/(M + 2 m1 + 2 m2));
    none where they agree."""
    for value in along.own.values():
        if value is not None and not _same(solution, ask.name, value) and _same(solution, ask.name, -value):
            # the ask's name as the documents print it; real, as the route's own symbols are, so that it
            # is not the engine's growth rate a (derive.publishing.notation would rename it)
            asked = sp.Symbol(ask.name, real=True)
            return [Step(f"With the question's sign convention ({ask.sign}), the answer is the opposite of "
                         "the value found along the motion", (sp.Eq(asked, solution.expression(ask.name)),),
                         role="solve")]
    return []


def _least_coefficient(solution, ask) -> Step:
    """mu_min = f / N, the friction and normal force the route found."""
    forces = solution.dynamics_scene.contact_of(ask.quantity.target).unknowns()
    mu = sp.Symbol(ask.name)
    holds = "It rolls without slipping" if solution.textbook_route.names else "It stays put"
    return Step(f"{holds} while static friction can supply the friction found, that is while that is at most the "
                "coefficient of static friction times the normal force: the least coefficient",
                (sp.Eq(mu, forces["friction"] / forces["normal"]), sp.Eq(mu, solution.expression(ask.name))))


def _time_down(solution, ask) -> Step | None:
    """From rest at the constant acceleration a down the slope's length H / sin(theta): H / sin(theta) = a t^2 / 2."""
    contact = solution.scene.contact_of(ask.quantity.target)
    surface = solution.scene.surfaces[contact.surface]
    if not isinstance(surface, Plane) or surface.height is None:
        return None
    a, t = solution.textbook_route.names[ask.quantity.target, "a"], sp.Symbol("t")
    length = surface.height / sp.sin(surface.angle)
    return Step("From rest at the constant acceleration found, along the slope, whose length is its height over the "
                "sine of its angle", (sp.Eq(length, a * t**2 / 2), sp.Eq(t, solution.expression(ask.name))))
