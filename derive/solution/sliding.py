"""Which regime the student's route takes where a contact's friction coefficients decide it: the
body slides with kinetic friction, f = mu_k N against the slide, all the way the route follows it.

The engine proves it. To a state, its chain of states (derive.solution.state_answers) slides given
rates against their slip, and decides a start from rest by the forces (derive.solution.start_regimes,
a variant that starts otherwise refused); a contact that grips on the way, or a slide that stops and
goes on, is another regime, which the route does not take. At the placement, with no states, the
slip must hold at every value of the ranges: the friction the block would need to stay put, f, with
the normal force N, is proven over the ranges' box to exceed what static friction gives,
|f| > mu_s N (derive.numbers.intervals), the way f points.

>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> route = Solution(load("block_incline_kinetic")).textbook_route
>>> [str(e) for step in route.sections["Forces and torques along the motion"] for e in step.equations][-2:]
['Eq(a, g*(-mu_k*cos(theta) + sin(theta)))', 'Eq(N^block, g*m*cos(theta))']
"""
from __future__ import annotations

import sympy as sp

from derive import quantities
from derive.core.tidying import tidy
from derive.mechanics import friction
from derive.mechanics.along_motion import NotAlongALine, along_motion
from derive.numbers import range_forms
from derive.numbers.intervals import positive_over
from derive.solution.textbook_routes import TextbookRoute
from derive.text.steps import Step, renamed

SECTION = "Forces and torques along the motion"
#: The asks the no-state route's Newton along the motion answers with steps of their own (derive.solution.textbook).
OWN_STEPS = {"min_friction_coefficient", "time_to_bottom", "speed_at_bottom"}


def regime_to(solution, end) -> tuple | None:
    """(the scene, its derivations, the steps that say why) of the motion to the state `end`: the
    scene's own where no contact's friction coefficients decide a regime; else the one the engine's
    chain proves it slides in with kinetic friction all the way. None where the contact grips on the
    way, or the slide stops and starts again (another regime)."""
    if len(solution.regimes) == 1:
        return solution.dynamics_scene, solution.derivations, ()
    contact = solution._sliding
    part = next((j for j in solution._chain.joints[end.name] if j.name == contact.name), None)
    if part is None or part.regime != "kinetic":
        return None
    start = solution.starts.get(end.name)
    opening = (held_or_slips(solution, start.step, contact),) if start is not None else (sent_sliding(contact),)
    return solution.scene_in(end.name), solution.derivations_in(end.name), opening


def sent_sliding(contact) -> Step:
    """Why kinetic friction acts, and which way, on a body sent sliding (mu_k N, in the balance along
    the motion that follows)."""
    return Step(f"The {contact.body} is sent sliding on the {contact.surface}: kinetic friction, its coefficient times "
                "the normal force, acts against the slide as long as it slides")


def held_or_slips(solution, step: Step, contact) -> Step:
    """The step that decides whether the body grips or slips (derive.solution.start_regimes), the
    friction it would need named f_s, static friction's, as a textbook does (f^block is the engine's)."""
    if "f_s" in {*solution.problem.parameters, *solution.problem.asks}:
        return step
    needed = solution.dynamics_scene.constraint(contact.name).unknowns()["friction"]
    return renamed(step, {needed: sp.Symbol("f_s", real=True)})


def slide_from_rest(solution, needed: set) -> TextbookRoute | None:
    """Newton's second law along the motion of a body released on a surface where friction's
    coefficients decide its regime and the ranges prove it slips, the same way, at every value
    (None elsewhere): the step that says why, then the route along the motion in the slipping
    regime, each of its findings beside the regime's own derivation by Lagrange's method."""
    contact = friction.frictional(solution.scene)
    if contact is None or contact.kinetic is None or any(
            ask.sign is not None or quantities.KINDS[ask.quantity.kind].own_section or ask.quantity.detail in OWN_STEPS
            for ask in solution.problem.asks.values()):
        return None  # a sign convention, or an ask with steps of its own, which this route does not write
    normal, needs = solution._grip("lagrange")
    ratio, box = tidy(needs / normal), range_forms.box(solution.problem)
    index = next((k for k, regime in enumerate(solution.regimes) if regime.direction
                  and positive_over(regime.direction * ratio - friction.static_coefficient(contact), box)), None)
    if index is None:
        return None  # static friction may hold it, or it may slip either way, at some values of the ranges
    regime, derivations = solution.regimes[index], solution._regime_derivations(index)
    try:
        along = along_motion(regime.scene, solution.coordinates, derivations["newton_euler"], solution._sample, needed)
    except NotAlongALine:
        return None
    if not needed <= along.values.keys():
        return None  # an ask read from what the slide has not (the static friction a stuck block needs)
    held = solution.dynamics_scene.constraint(contact.name)
    step = held_or_slips(solution, solution._start_step(contact, held, regime, tidy(normal), tidy(needs), "at the start"),
                         contact)
    reference = solution._solved(derivations["lagrange"], solution.coordinates.at_rest_in_reference())
    compared = tuple((str(u), value, (lambda u=u: reference.raw[u])) for u, value in along.values.items())
    return TextbookRoute({SECTION: (step, *along.steps)}, compared,
                         "Newton's second law along the motion of a body that slides", along, regime.scene)
