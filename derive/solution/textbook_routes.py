"""The student's routes that are not Newton's second law along the motion at the placement
(derive.solution.textbook): a top's steady precession by tau = Omega x L (derive.mechanics.steady_top),
a ball that skids and then rolls (derive.mechanics.skidding), an impact that sticks or locks by the
angular momentum about the axle or, of free bodies, the momentum and the angular momentum about
their center of mass (derive.mechanics.angular_momentum), a pair on an axle braked to rest after
a clutch locks, a cord pulled in through a hole (derive.mechanics.pulled_in), an ellipse by the
conservation of angular momentum and of energy (derive.mechanics.orbit_by_conservation) and the least
height for a loop (derive.mechanics.loop_top).

Each gives its sections and what it finds beside what the engine finds for the same thing (the
rates or accelerations its two routes give, the answers the key prints): the check textbook_route
(derive.solution.crosschecks) compares every pair.

>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> route = Solution(load("skid_to_roll")).textbook_route
>>> list(route.sections)
['The skid, by Newton along the motion and the torque about the center']
"""
from __future__ import annotations

import dataclasses
from collections.abc import Callable
from dataclasses import dataclass

import sympy as sp

from derive.core.tidying import tidy
from derive.mechanics import fixed_point
from derive.mechanics.along_motion import NotAlongALine
from derive.mechanics.angular_momentum import about_axle, about_center_of_mass, about_each_axle, slowed_to_rest
from derive.mechanics import orbits
from derive.mechanics.derivation import EXACT_PERIOD, GROWTH_RATE, KINETIC, LAGRANGIAN, PERIOD, POTENTIAL
from derive.mechanics.loop_top import loop_top
from derive.mechanics.orbit_by_conservation import DETAILS, by_conservation
from derive.mechanics.pulled_in import pulled_in
from derive.mechanics.skidding import skidding
from derive.mechanics.steady_top import TOP_RATES, as_a_textbook_writes, steady_precession
from derive.model.directions import TURNS
from derive.numbers import intervals, range_forms
from derive.parts.contact import Contact
from derive.parts.pin import Pin
from derive.parts.rims import Rims
from derive.parts.surfaces import Plane
from derive.parts.torque import Torque
from derive.solution.state_events import in_place
from derive.text.latex import symbol_latex
from derive.text.steps import Step, renamed


@dataclass(frozen=True)
class TextbookRoute:
    """A student's route by section, and its findings beside the engine's: (what, the route's value,
    a function giving the engine's) for each."""

    sections: dict[str, tuple]
    compared: tuple[tuple[str, sp.Expr, Callable[[], sp.Expr]], ...]
    principle: str
    along: object = None  # the route along the motion it starts from (derive.mechanics.along_motion), if any
    scene: object = None  # the scene `along` is written in, where not the engine's stuck one (a slide's)

    def agreement(self, agree: Callable, failure: Callable) -> set[str]:
        """The methods by which each finding agrees with the engine's (`agree(a, b)`: a method, or None
        where they differ); raises `failure(what, mine, engine's)` at the first that differs."""
        methods = set()
        for what, value, engine in self.compared:
            expected = engine()
            method = agree(value, expected)
            if method is None:
                raise failure(what, value, expected)
            methods.add(method)
        return methods


def top_route(solution) -> TextbookRoute | None:
    """tau = Omega x L for a top's steady precessions, and a fast top's nutation about them, where every
    ask is one of them (None otherwise)."""
    asks = list(solution.problem.asks.values())
    if not asks or any(a.quantity.kind != "pivot_point" or a.quantity.detail not in TOP_RATES or a.state
                       for a in asks) or len({a.quantity.target for a in asks}) != 1:
        return None
    name = asks[0].quantity.target
    tensor, mass, g, distance = solution.standing_top(name)
    point = solution.scene.pivot_points[name]
    try:
        I1, I3 = fixed_point.moments(tensor, mass, distance)
    except fixed_point.NotSymmetric:
        return None
    top = steady_precession(I1, I3, mass, g, distance, point.spin, point.tilt, {a.quantity.detail for a in asks})
    shown = as_a_textbook_writes(I1, point.tilt, {p.symbol for p in solution.problem.parameters.values()})
    steps = tuple(dataclasses.replace(s, equations=tuple(e.xreplace(shown) for e in s.equations)) for s in top.steps)
    compared = tuple((f"{a.name} by {route}", top.rates[a.quantity.detail],
                      (lambda a=a, route=route: solution._pivot_point(a.quantity, route)))
                     for a in asks for route in ("lagrange", "newton_euler"))
    return TextbookRoute({"Steady precession, by the torque about the tip": steps}, compared,
                         "the torque about the tip, tau = Omega x L")


def loop_route(solution) -> TextbookRoute | None:
    """The least release height that carries a body round a loop, by Newton's second law at the top, the
    normal force not negative there, and energy from the release, where every ask is one (None
    otherwise): a section for each ask, checked against each engine route's normal force at the top."""
    asks = solution.problem.asks
    if not asks or any(a.quantity.kind != "contact" or a.quantity.detail != "min_release_height" or a.state
                       for a in asks.values()):
        return None
    taken = {p.symbol.name for p in solution.problem.parameters.values()}
    sections, compared = {}, []
    for name, ask in asks.items():
        body, contact = solution.scene.bodies[ask.quantity.target], solution.scene.contact_of(ask.quantity.target)
        if not contact.rolling and contact.has_friction:
            return None  # friction takes energy on the way: the engine's routes
        small = {x: 0 for x in ask.small}
        radius = body.sizes.get("radius", sp.Integer(0))
        rho = solution.scene.surfaces[contact.surface].path_radius(radius).xreplace(small)
        plain = {old: sp.Symbol(new, positive=True) for old, new in ((body.mass, "m"), (radius, "r"))
                 if isinstance(old, sp.Symbol) and old.name not in taken and new not in taken}  # m_ball -> m
        steps, height = loop_top(body.mass, solution.scene.gravity.g, rho, body.inertia if contact.rolling else None,
                                 radius, body.name)
        if ask.exact in asks and set(ask.small) == {radius}:  # the exact ask's steps with the small sizes dropped: its last line only
            steps = (Step(f"As above, with the {body.name}'s radius dropped beside the loop's", steps[-1].equations,
                          role="solve"),)
        sections[ask.meaning[0].upper() + ask.meaning[1:]] = tuple(
            dataclasses.replace(step, equations=tuple(e.xreplace(plain) for e in step.equations)) for step in steps)
        compared += [(f"{name} by {route}", height,
                      (lambda target=ask.quantity.target, route=route, small=small:
                       solution.release_height(target, route)[0].xreplace(small))) for route in ("lagrange", "newton_euler")]
        compared.append((name, height, (lambda name=name: solution.expression(name))))
    return TextbookRoute(sections, tuple(compared), "Newton's second law at the top of the loop and the conservation "
                                                    "of energy")


def orbit_route(solution) -> TextbookRoute | None:
    """An ellipse given by its semi-major axis and eccentricity, by the conservation of angular momentum
    and of energy at its closest and farthest points, where every ask is one of what that finds (None
    otherwise). Its angular momentum is compared with each engine route's: the one that makes the two
    distances turning points of the route's radial equation (no net change of the radial speed between them)."""
    orbit, asks = solution.scene.orbit, solution.problem.asks
    if orbit.semi_major_axis is None or orbit.periapsis_speed is not None or not asks \
            or any(a.quantity.kind != "orbit" or a.quantity.detail not in DETAILS for a in asks.values()):
        return None
    route = by_conservation(orbit.GM, orbit.semi_major_axis, orbit.eccentricity, {a.quantity.detail for a in asks.values()})
    compared = [(f"the angular momentum by {way}", route.values["angular_momentum"],
                 (lambda way=way: _turning_momentum(orbit.GM, route.values["periapsis"], route.values["apoapsis"], way)))
                for way in ("lagrange", "newton_euler")]
    compared += [(name, route.values[a.quantity.detail], (lambda name=name: solution.expression(name)))
                 for name, a in asks.items()]
    return TextbookRoute({"The orbit, by the conservation of angular momentum and of energy": route.steps},
                         tuple(compared), "the conservation of angular momentum and of energy at the turning points")


def _turning_momentum(GM, near, far, way: str) -> sp.Expr:
    """The angular momentum per unit mass for which `near` and `far` are the turning points of the radial
    equation by `way` (derive.mechanics.orbits): the radial acceleration integrated between them is zero."""
    l = sp.Symbol("l", positive=True)
    change = sp.integrate(orbits.radial_acceleration(GM, l, way), (orbits.r, near, far))
    (value,) = [x for x in sp.solve(change, l) if x.is_positive is not False]
    return value


def state_route(solution) -> TextbookRoute | None:
    """The route of a scene's states: a skid that ends in rolling, or an impact (and a braking after
    it), where every ask is one of what it finds (None otherwise)."""
    return _skid_route(solution) or _impact_route(solution) or _pull_route(solution)


#: What each route's findings answer: (the ask's kind, detail) -> the finding's name.
SKID = {("acceleration", "x"): "a", ("time", None): "time", ("position", "x"): "distance",
        ("velocity", "x"): "speed", ("kinetic_energy", None): "K1", ("kinetic_energy_change", None): "lost",
        ("angular_velocity", None): "rate"}
IMPACT = {("angular_velocity", None): "omega", ("kinetic_energy_change", None): "lost", ("kinetic_energy", None): "K1",
          ("center_of_mass_velocity", "x"): "V_x", ("center_of_mass_velocity", "y"): "V_y"}


def _skid_route(solution) -> TextbookRoute | None:
    """One body launched on a level floor with kinetic friction, with or without spin (friction against
    its bottom's sliding, backward or forward), asked about the skid (from the launch) and the state
    where it grips."""
    states = solution.scene.states
    grip = [s for s in states.values() if s.until and s.until[0] == "grips"]
    if len(states) != 2 or len(grip) != 1 or len(solution.scene.bodies) != 1:
        return None
    (state,), (body,) = grip, solution.scene.bodies.values()
    start = states.get(state.start)
    contact = next((c for c in solution.scene.constraints if isinstance(c, Contact) and c.body == body.name), None)
    if start is None or contact is None or contact.rolling or contact.kinetic is None or "radius" not in body.sizes:
        return None
    surface = solution.scene.surfaces[contact.surface]
    rates = {k: v for _, k, v in start.rates}
    launch, turning = rates.get("x"), rates.get("theta")
    if not isinstance(surface, Plane) or surface.angle != 0 or launch is None or turning is None \
            or _sign_over(solution, launch) != 1:
        return None
    spin = -turning  # the way it rolls forward, +x: clockwise, against the engine's angle
    sliding = _sign_over(solution, launch - body.sizes["radius"] * spin)  # its bottom's velocity over the floor
    if sliding is None or spin != 0 and _sign_over(solution, spin) is None:
        return None  # friction's direction, or the spin's, changes over the ranges: the engine's routes
    asks = solution.problem.asks
    for ask in asks.values():
        key = (ask.quantity.kind, ask.quantity.detail)
        if key not in SKID or ask.state != (start.name if key == ("acceleration", "x") else state.name):
            return None
    asked = {SKID[a.quantity.kind, a.quantity.detail] for a in asks.values()}
    skid = skidding(body.mass, body.inertia, body.sizes["radius"], contact.kinetic, solution.scene.gravity.g, launch,
                    spin, asked, sliding, spin != 0 and _sign_over(solution, spin) < 0)
    x, theta = (solution.coordinates.of(body.name, k).a for k in ("x", "theta"))
    engine = {x: skid.values["a"], theta: -skid.values["alpha"]}  # forward is +x: it turns clockwise
    compared = [(f"{a} by {route}", value, (lambda a=a, route=route: solution.in_state(route, start.name).raw[a]))
                for a, value in engine.items() for route in ("lagrange", "newton_euler")]
    found = {**skid.values, "a": -skid.values["a"]}  # the key's answers are magnitudes, a direction in words
    compared += [(name, found[SKID[a.quantity.kind, a.quantity.detail]], (lambda name=name: solution.expression(name)))
                 for name, a in asks.items()]
    return TextbookRoute({"The skid, by Newton along the motion and the torque about the center": skid.steps},
                         tuple(compared), "Newton's second law along the motion and the torque about the center")


#: What the pull's route finds: (the ask's kind, detail) -> the finding's name.
PULL = {("speed", None): "speed", ("kinetic_energy_change", None): "work", ("force", "tension"): "tension"}


def _pull_route(solution) -> TextbookRoute | None:
    """A point mass circling a hole at the end of a cord through it, pulled in slowly to a smaller circle,
    asked its speed, the pull's work and the cord's tension there."""
    states = solution.scene.states
    pulls = [s for s in states.values() if s.event is not None and s.event.kind == "pull"]
    if len(states) != 2 or len(pulls) != 1 or len(solution.scene.bodies) != 1 or len(solution.scene.constraints) != 1 \
            or solution.scene.loads:  # on a level table: no load in its plane
        return None
    (state,), (body,) = pulls, solution.scene.bodies.values()
    start, cord = states.get(state.start), solution.scene.constraint(state.event.joint)
    holes = [a.offset for a in cord.path if a.body is None]
    if start is None or body.shape != "point" or len(holes) != 1 or len(cord.path) != 2:
        return None
    velocity = sp.Matrix([next((v for _, k, v in start.rates if k == axis), 0) for axis in ("x", "y")])
    reach = sp.Matrix(body.at) - sp.Matrix(holes[0])
    if tidy(velocity.dot(reach)) != 0 or any(k not in ("x", "y") for _, k, _ in start.rates):
        return None  # not circling: a speed along the cord too
    asks = solution.problem.asks
    if any(a.state != state.name or PULL.get((a.quantity.kind, a.quantity.detail)) is None
           or a.quantity.target not in (None, body.name, cord.name) for a in asks.values()):
        return None
    route = pulled_in(body.mass, tidy(sp.sqrt(reach.dot(reach))), state.event.length,
                      tidy(sp.sqrt(velocity.dot(velocity))), {PULL[a.quantity.kind, a.quantity.detail] for a in asks.values()}, body.name)
    after = solution.states[state.name].values
    x, y = (solution.coordinates.of(body.name, k).u for k in ("x", "y"))
    compared = [("the speed after the pull", route.values["speed"], lambda: sp.sqrt(after[x]**2 + after[y]**2))]
    compared += [(name, route.values[PULL[a.quantity.kind, a.quantity.detail]], (lambda name=name: solution.expression(name)))
                 for name, a in asks.items()]
    return TextbookRoute({"The pull, by the angular momentum about the hole": route.steps}, tuple(compared),
                         "the angular momentum about the hole, and the work-energy theorem")


def _sign_over(solution, expr: sp.Expr) -> int | None:
    """+1 or -1 where `expr` keeps that strict sign over the whole box of the parameter ranges (proven
    in balls, derive.numbers.intervals), None where it is not proven to."""
    box = range_forms.box(solution.problem)
    if not expr.free_symbols <= set(box):
        return None
    return 1 if intervals.positive_over(expr, box) else -1 if intervals.positive_over(-expr, box) else None


def _impact_route(solution) -> TextbookRoute | None:
    """A sticking or locking impact from a state moving at given rates: about the axle, or of free
    bodies about their center of mass; then, about an axle, a constant torque that stops them."""
    states = solution.scene.states
    impact = [s for s in states.values() if s.event is not None]
    if len(impact) != 1 or impact[0].event.kind not in ("stick", "lock"):
        return None
    (state,) = impact
    start = states.get(state.start)
    stop = [s for s in states.values() if s.start == state.name and s.until == ("stops", None)]
    if start is None or not start.rates or len(states) != 2 + len(stop) or len(stop) > 1:
        return None
    asks = solution.problem.asks
    axles = {p.name for p in solution.scene.constraints if isinstance(p, Pin) and p.to is None}
    impulses = tuple(sorted({a.quantity.detail for a in asks.values() if a.quantity.kind == "impulse"}))
    for ask in asks.values():
        key = (ask.quantity.kind, ask.quantity.detail)
        fits = (ask.state == state.name and key in IMPACT or ask.state == start.name and key == ("kinetic_energy", None)
                or stop and ask.state == stop[0].name and key in (("time", None), ("angle", None))
                or ask.state == state.name and ask.quantity.kind == "impulse" and ask.quantity.target in axles
                and len(axles) == 1 and ask.quantity.detail in ("x", "y"))
        if not fits:
            return None
    scene = solution._scene_with(in_place(solution._struck_with(state.name), solution._chain.made[state.name]))
    energy = any(a.quantity.kind.startswith("kinetic_energy") for a in asks.values())
    before, after = solution.states[start.name].values, solution.states[state.name].values
    made = solution._chain.made[state.name]
    try:
        if isinstance(made, Rims):  # two axles: the angular impulse about each
            route = about_each_axle(scene, solution.coordinates, before, made, energy=energy)
            title = "The impact, by the angular impulse about each axle"
        else:
            route = about_axle(scene, solution.coordinates, before, after, solution._sample, energy=energy,
                               impulse=impulses)
            title = "The impact, by the angular momentum about the axle"
    except NotAlongALine:
        try:
            route = about_center_of_mass(scene, solution.coordinates, before, after, solution._sample, energy=energy)
        except NotAlongALine:
            return None
        title = "The impact, by the momentum and the angular momentum about the center of mass"
    sections = {title: route.steps}
    if stop:
        braking = _braking(solution, scene, route, after)
        if braking is None:
            return None
        sections["Braked to rest, by the torque about the axle"] = braking
    found = {**route.found}
    compared = [(str(u), value, (lambda u=u: solution.states[state.name].values[u])) for u, value in route.values.items()]
    for name, ask in asks.items():
        if ask.quantity.kind == "angular_velocity" and ask.quantity.target in route.rates:  # a body's own, signed
            compared.append((name, route.rates[ask.quantity.target], (lambda name=name: solution.signed(name))))
            continue
        key = "K0" if ask.state == start.name else "t" if ask.quantity.kind == "time" else "turn" \
            if ask.quantity.kind == "angle" else f"J_{ask.quantity.detail}" if ask.quantity.kind == "impulse" \
            else IMPACT[ask.quantity.kind, ask.quantity.detail]
        if key not in found:
            return None  # an axle's impulse where the route is not about the axle
        value = found[key] if key not in ("V_x", "V_y", "J_x", "J_y") else sp.Abs(found[key]) if found[key] != 0 \
            else found[key]
        compared.append((name, value, (lambda name=name: solution.expression(name))))
    return TextbookRoute(_in_the_asks_names(solution, sections, start.name, state.name), tuple(compared),
                         "the angular momentum about the point where no outside impulse has a moment")


#: The impact routes' own symbols of the kinetic energy just before and just after; the engine's symbols,
#: which the documents print by the asks' names (derive.publishing.notation), never taken for them.
K_BEFORE, K_AFTER = sp.Symbol("K_0"), sp.Symbol("K_1")
ENGINE = {KINETIC, POTENTIAL, LAGRANGIAN, PERIOD, EXACT_PERIOD, GROWTH_RATE}


def _in_the_asks_names(solution, sections: dict, before: str, after: str) -> dict:
    """The impact's sections with the kinetic energies under the names the question asks them by (K1 for
    the energy before), and one that prints as an ask's name does (K_1 beside an ask K1 that is the
    energy before) as a textbook's K_i, K_f: one symbol, one thing."""
    change = {}
    for name, ask in solution.problem.asks.items():
        if ask.quantity.kind == "kinetic_energy" and ask.state in (before, after) and sp.Symbol(name) not in ENGINE:
            change[K_BEFORE if ask.state == before else K_AFTER] = sp.Symbol(name)  # (K is the engine's: as it is)
    asked = {symbol_latex(name) for name in solution.problem.asks}
    for symbol, other in ((K_BEFORE, "K_i"), (K_AFTER, "K_f")):
        if symbol not in change and symbol_latex(symbol.name) in asked:
            change[symbol] = sp.Symbol(other)
    if len({symbol_latex(s.name) for s in change.values()}) < len(change):
        return sections  # two asks of one thing: the route's own names
    return {title: tuple(renamed(step, change) for step in steps) for title, steps in sections.items()}


def _braking(solution, scene, route, after) -> tuple | None:
    """The pair on the axle slowed to rest by the constant couples on it (None where they do not slow it)."""
    if "I_axle" not in route.found:
        return None
    couple = sum((p.torque for p in scene.loads if isinstance(p, Torque) and p.axis is None), sp.Integer(0))
    if any(not isinstance(p, Torque) for p in scene.loads) or couple == 0:
        return None
    turning = next(c for c in solution.coordinates.all if c.kind == "theta" and route.values.get(c.u, 0) != 0)
    sense = 1 if solution._sample(after[turning.u]) > 0 else -1
    against = -sense * couple
    if solution._sample(against) <= 0:
        return None
    return slowed_to_rest(route.found, against, TURNS[0] if sense > 0 else TURNS[1])
