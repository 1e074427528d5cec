"""The student's route from one state to the next at constant acceleration: the forces and torques
along the motion (derive.mechanics.along_motion) give the acceleration a (or the angular
acceleration alpha of a body turning on an axle), and the kinematics of constant acceleration take
the motion from its start to where it stops or to where it has gone a given way:

    v^2 = v_0^2 + 2 a d,    v = v_0 + a t        (omega, alpha and the angle theta for a turning body)

as a solution manual solves a cylinder rolling up a slope until it stops (Serway & Jewett ch. 10) or
a grindstone slowed by a constant friction torque (Serway & Jewett ch. 10, rigid body under constant
angular acceleration). Where the end state asks a speed of one moving body, the speed is taken by the
work–energy theorem instead (derive.solution.work_energy: K - K_0 = the work of gravity and of kinetic
friction), and the kinematics only give the time. A body that slides with kinetic friction is followed
where the engine proves it slides the same way all the way (derive.solution.sliding): f = mu_k N
against the slide, N from the balance across it; a slide that stops and goes back is another regime,
refused. Several states asked from one start (where a puck stops, where its speed has halved) each
get a section, titled by what is asked there; a state reached from rest where an asked slide stopped
follows in the same regime (back down a smooth incline).

Offered only where the motion's acceleration along its way is constant: the engine's own states
(derive.mechanics.states, by work and energy) must satisfy v^2 - v_0^2 = 2 a d at points of the
ranges, and every ask must be one the route answers; each of its findings is then compared with the
key's (the check textbook_route).

>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> list(Solution(load("sphere_rolls_down")).textbook_route.sections)
['Forces and torques along the motion', 'The speed by energy, the time at constant acceleration']
"""
from __future__ import annotations

import dataclasses

import sympy as sp

from derive import quantities
from derive.core.tidying import root, tidy
from derive.mechanics.along_motion import AlongMotion, NotAlongALine, along_motion, definite
from derive.parts.contact import Contact
from derive.solution.crosschecks import same_at_samples
from derive.mechanics.derivation import KINETIC
from derive.solution.work_energy import between_states
from derive.solution.sliding import SECTION as FORCES_SECTION, regime_to
from derive.solution.textbook_routes import TextbookRoute
from derive.text.steps import Step

#: The asks of the end state the kinematics answer: (kind, detail); and the forces there, where the motion
#: runs the way it starts from rest (the forces along the motion found at the placement hold all the way).
ANSWERED = {("time", None), ("speed", None), ("angular_velocity", None), ("distance", None), ("turns", None),
            ("position", "x"), ("position", "y"), ("velocity", "x"), ("velocity", "y"), ("kinetic_energy", None)}
#: The asks of the end state the work–energy theorem answers, where the leading body moves along a line.
SPEEDS = {"speed", "angular_velocity", "velocity", "kinetic_energy"}
FORCES = {"force", "contact"}
SECTION = "The motion at constant acceleration"
ENERGY_SECTION = "The speed by energy"
#: The asks at the placement the forces along the motion answer.
AT_PLACEMENT = {"acceleration", "angular_acceleration", "force", "contact"}


def uniform_route(solution) -> TextbookRoute | None:
    """The student's route of a scene of one degree of freedom from its placement (at rest, or at given
    rates) to the states asked, each reached from there at the same constant acceleration; None where the
    scene, its states or its asks are not such."""
    states, asks = solution.scene.states, solution.problem.asks.values()
    ends = [state for name, state in states.items() if any(ask.state == name for ask in asks)]
    stops = {end.name for end in ends if end.until == ("stops", None)}
    roots = {end.start for end in ends} - stops
    if len(roots) != 1 or any(states[end.start].start not in roots for end in ends if end.start in stops):
        return None  # a state reached from another asked one that is not a stop: another segment
    (root,) = roots
    start = states.get(root) if root is not None else None
    if root is not None and (start is None or not start.rates or start.start is not None) or \
            any(end.rates or end.event is not None or end.until not in (None, ("stops", None)) or end.nudge
                or end.relative_to is not None for end in ends):
        return None
    for ask in asks:
        key = (ask.quantity.kind, ask.quantity.detail)
        if ask.finds or ask.state is None and ask.quantity.kind not in AT_PLACEMENT \
                or ask.state is not None and key not in ANSWERED and ask.quantity.kind not in FORCES:
            return None
    regimes = [regime_to(solution, end) for end in ends]
    if any(regime is None for regime in regimes) or len({solution._chain.joints[end.name] for end in ends}) > 1:
        return None  # one end grips, or slides another way than another: back down after a stop, a change of regime
    scene, derivations, opening = regimes[0]
    needed = solution._needed_unknowns().union(*(solution._needed_unknowns(end.name) for end in ends))
    try:
        along = along_motion(scene, solution.coordinates, derivations["newton_euler"], solution._sample, needed)
    except NotAlongALine:
        return None
    sections = {FORCES_SECTION: (*opening, *along.steps)}
    at = None if len(solution.regimes) == 1 else ends[0].name  # where the slide's forces are the engine's
    compared = [(str(u), value, (lambda u=u: solution.in_state("lagrange", at).raw[u]))
                for u, value in along.values.items()]
    for end in ends:
        motion = _Kinematics(solution, along, states[end.start] if end.start is not None else None, end, scene)
        if not motion.uniform():
            return None
        steps = motion.steps()
        if steps is None or any(not motion.same(value, solution.expression(name)) for name, value in motion.answers.items()):
            return None  # an ask the kinematics read otherwise than the key (a signed component): the routes' solution
        first = next(ask for ask in asks if ask.state == end.name)
        sections[motion.title if len(ends) == 1 else quantities.describe_capitalized(first.meaning)] = steps
        compared += [(name, value, (lambda name=name: solution.expression(name))) for name, value in motion.answers.items()]
    return TextbookRoute(sections, tuple(compared), "Newton's second law along the motion, then the kinematics of "
                         "constant acceleration", along, scene)


class _Kinematics:
    """The leading body's motion along its way, in the rate s' of derive.mechanics.along_motion (its
    center's speed, or its rate of turning where it only turns): where it starts, how far it goes,
    how fast it ends, each read from the engine's states; and the steps that find them."""

    def __init__(self, solution, along: AlongMotion, start, end, scene):
        self.solution, self.along, self.end = solution, along, end
        base = along.steps[-1].equations[0].lhs  # the route solves for the leading acceleration first
        self.acceleration = along.own[base]
        self.turning = base in {s for (_, kind), s in along.names.items() if kind == "alpha"}
        self.leader = next(body for (body, _), s in along.names.items() if s == base)
        coordinates = solution.coordinates.all
        self.direction = {c: along.rates[c.a] for c in coordinates}
        self.lead = next(c for c in coordinates if self.direction[c] != 0)
        rest = solution.coordinates.at_rest_in_reference()
        first = solution.states[start.name].values if start is not None else rest
        last = solution.states[end.name].values
        scale = self.direction[self.lead]
        self.rate0 = tidy(first.get(self.lead.u, rest[self.lead.u]) / scale)
        self.rate1 = tidy(last[self.lead.u] / scale)
        self.first, self.rest, self.last, self.scene = first, rest, last, scene
        self.first_values = {**rest, **first}
        self.way = tidy((last[self.lead.q] - self.start_position(self.lead)) / scale)
        self.answers: dict[str, sp.Expr] = {}
        self.kinetic: sp.Expr | None = None  # in the end state, where the work–energy theorem found the speed

    @property
    def title(self) -> str:
        """The section's title: the speed by energy where the work–energy theorem found it."""
        if self.kinetic is None:
            return SECTION
        timed = any(a.quantity.kind == "time" for a in self.solution.problem.asks.values() if a.state == self.end.name)
        return ENERGY_SECTION + (", the time at constant acceleration" if timed else "")

    def _tidier(self, value: sp.Expr) -> sp.Expr:
        """`value`, or the same expression as the key prints it where that is shorter (sqrt(sin^3)/sin
        from a slope's length d sin(theta), where the key has sqrt(10 d g sin(theta)/7))."""
        forms = [value] + ([root(tidy(value**2))] if self.solution._sample(value) > 0 else [])
        forms += [self.solution.expression(ask.name) for ask in self.solution.problem.asks.values()
                  if ask.state == self.end.name and ask.sign is None]
        return min((form for form in forms if form is value or self.same(value, form)), key=sp.count_ops)

    def start_position(self, coordinate) -> sp.Expr:
        return self.first.get(coordinate.q, self.rest[coordinate.q])

    def same(self, a: sp.Expr, b: sp.Expr) -> bool:
        return same_at_samples(self.solution.problem, a, b)

    def uniform(self) -> bool:
        """Whether the engine's states keep the acceleration found at the placement all the way:
        v^2 - v_0^2 = 2 a d."""
        return self.same(self.rate1**2 - self.rate0**2, 2 * self.acceleration * self.way)

    def _symbol(self, names: tuple[str, ...], value: sp.Expr) -> sp.Symbol:
        """The first of `names` that means nothing else in the problem: a parameter's name only where
        it is the value itself (the slope's length d), an ask's only where it asks the value."""
        problem = self.solution.problem
        for name in names:
            if name in problem.parameters:
                if problem.parameters[name].symbol == value:
                    return problem.parameters[name].symbol
                continue
            if name not in problem.asks or self.same(self.solution.expression(name), value):
                return sp.Symbol(name)
        raise AssertionError(names)

    def steps(self) -> list[Step] | None:
        """The kinematics to the end state, then each ask read from them (None where an ask is not)."""
        sample = self.solution._sample
        sign0 = 0 if self.rate0 == 0 else (1 if sample(self.rate0) > 0 else -1)
        stops = self.end.until == ("stops", None)
        if stops and sign0 >= 0:
            return None
        speed0 = definite(sp.Abs(self.rate0), sample)
        found = {"v": self._tidier(definite(sp.Abs(self.rate1), sample)),
                 "d": self._tidier(definite(sp.Abs(self.way), sample)),
                 "t": self._tidier(definite(tidy((self.rate1 - self.rate0) / self.acceleration), sample))}
        letters = {"v0": ("omega_0",) if self.turning else ("v_0", "u"), "v": ("omega", "omega_1") if self.turning
                   else ("v", "v_1"), "d": ("Delta_theta", "phi") if self.turning else ("d", "s", "ell"), "t": ("t", "t_1")}
        v, d, t = (self._symbol(letters[k], found[k]) for k in ("v", "d", "t"))
        v0 = speed0 if isinstance(speed0, sp.Symbol) else self._symbol(letters["v0"], speed0)
        a = self.along.steps[-1].equations[0].lhs
        kinds = {ask.quantity.kind for ask in self.solution.problem.asks.values() if ask.state == self.end.name}
        timed = "time" in kinds
        moving = "turning" if self.turning else "moving"
        if sign0 == 0:
            text = f"The {self.leader} starts from rest and speeds up at the constant acceleration found"
            relations = (sp.Eq(v**2, 2 * a * d), sp.Eq(v, a * t))
        elif sign0 < 0:
            text = f"The {self.leader} starts {moving} against the acceleration found, so it slows down at that constant rate"
            relations = (sp.Eq(v**2, v0**2 - 2 * a * d), sp.Eq(v, v0 - a * t))
        else:
            text = f"The {self.leader} starts {moving} the way of the acceleration found, and speeds up at that constant rate"
            relations = (sp.Eq(v**2, v0**2 + 2 * a * d), sp.Eq(v, v0 + a * t))
        given = (sp.Eq(v0, speed0),) if sign0 and v0 != speed0 else ()
        known = self.end.rate and not self.turning  # the state is where the speed is given (halved): put it in
        if known:
            relations = tuple(r.xreplace({v: found["v"]}) for r in relations)
        energy = None if stops or self.turning or not kinds & SPEEDS else \
            between_states(self.solution, self.along, self.scene, self.leader, (self.first_values, self.last), (self.way, d),
                           ((speed0, found["v"]), (v0 if sign0 else sp.Integer(0), v)), self.same)
        if energy is not None:  # the speed by energy; the kinematics only for the time
            result = [dataclasses.replace(energy[0], equations=(*given, *energy[0].equations)),
                      Step("Where the state is reached", ((sp.Eq(d, found["d"]),) if d != found["d"] and
                                                          any(d in e.free_symbols for e in energy[0].equations) else ())
                           + (sp.Eq(v, found["v"]),), role="solve")]
            if timed:
                result.append(Step(f"{text}: the time it takes", (relations[1], sp.Eq(t, found["t"]))))  # its own relation
            self.kinetic = energy[1]
        elif kinds & {"kinetic_energy"}:
            return None
        else:
            result = [Step(text, (*given, *(relations if timed else relations[:1])), role="equations")]
        if stops:
            solved = (sp.Eq(d, found["d"]),) + ((sp.Eq(t, found["t"]),) if timed else ())
            result.append(Step(f"It stops where its {'rate of turning' if self.turning else 'speed'} has fallen to zero",
                               solved, role="solve"))
        elif energy is None:
            solved = ((sp.Eq(d, found["d"]),) if d != found["d"] else ()) + (() if known else (sp.Eq(v, found["v"]),)) + \
                ((sp.Eq(t, found["t"]),) if timed else ())
            result.append(Step("Where the state is reached", solved, role="solve"))
        symbols = {"v": v, "d": d, "t": t}
        for name, ask in self.solution.problem.asks.items():
            if ask.state != self.end.name:
                continue
            if ask.quantity.kind in FORCES:
                value = self._force(name, ask, sign0, result)
            elif ask.quantity.kind in ("position", "velocity"):
                value = self._component(name, ask, found, result)
            else:
                value = self._read(name, ask, found, symbols, result)
            if value is None:
                return None
            self.answers[name] = value
        return result

    def _force(self, name: str, ask, sign0: int, steps: list) -> sp.Expr | None:
        """A force found along the motion, the same all the way where the motion runs the way it starts
        from rest (a static friction's sense would turn with the motion's), or where it slides with
        kinetic friction all the way (against the slide: mu_k N, read from the normal force found)."""
        sliding = next((c for c in self.scene.constraints if isinstance(c, Contact) and c.regime == "kinetic"
                        and c.body == ask.quantity.target), None)
        if sign0 < 0 and sliding is None:
            return None
        if sliding is not None and (ask.quantity.kind, ask.quantity.detail) == ("contact", "friction"):
            normal = sliding.unknowns()["normal"]
            if normal not in self.along.values:
                return None
            value = tidy(sliding.kinetic * self.along.acting[normal] * self.along.values[normal])
            steps.append(Step(f"Kinetic friction on the {sliding.body} there, its coefficient times the normal force",
                              (sp.Eq(sp.Symbol(name), sliding.kinetic * normal), sp.Eq(sp.Symbol(name), value))))
            return value
        unknowns = quantities.KINDS[ask.quantity.kind].unknowns(self.solution, ask)  # what the ask reads
        if len(unknowns) != 1 or not unknowns <= self.along.acting.keys() & self.along.values.keys():
            return None
        (unknown,) = unknowns
        return tidy(self.along.acting[unknown] * self.along.values[unknown])

    def _component(self, name: str, ask, found: dict, steps: list) -> sp.Expr | None:
        """A body's position or velocity component in the end state, along its share of the way."""
        coordinate = self.solution.coordinates.of(ask.quantity.target, ask.quantity.detail)
        share = self.direction[coordinate]
        sense = 1 if self.solution._sample(self.rate1 if ask.quantity.kind == "velocity" else self.way) >= 0 else -1
        if ask.quantity.kind == "velocity":
            value = definite(tidy(sense * share * found["v"]), self.solution._sample)
        else:
            placed = self.solution.scene.bodies[ask.quantity.target].placed(ask.quantity.detail)
            value = definite(tidy(placed + self.start_position(coordinate) + sense * share * found["d"]),
                             self.solution._sample)
        if ask.sign is None and not self.same(value, self.solution.expression(name)):
            value = -value  # asked as a magnitude, its direction in words
        if any(self.same(value, found[key]) for key in ("v", "d")):
            return value  # the speed or the way found, already shown
        what = "velocity component" if ask.quantity.kind == "velocity" else "position"
        steps.append(Step(f"The {ask.quantity.target}'s {ask.quantity.detail} {what} there follows from the way it went",
                          (sp.Eq(sp.Symbol(name), value),)))
        return value

    def _read(self, name: str, ask, found: dict, symbols: dict, steps: list) -> sp.Expr | None:
        """An ask of the end state from the kinematics (its SI value): the time, the leading body's speed
        or way, another body's (or the leader's turning) in proportion, and the turns, with the step that
        says so (a reading of what the kinematics found, which solves none of its equations: no "from (6)-(7)")."""
        kind, target = ask.quantity.kind, ask.quantity.target
        if kind == "time":
            return found["t"]
        if kind == "kinetic_energy":
            symbol = sp.Symbol(name)
            steps.append(Step("The kinetic energy there follows from the speed found",
                              ((sp.Eq(symbol, KINETIC),) if symbol != KINETIC else ()) + (sp.Eq(symbol, self.kinetic),)))
            return self.kinetic
        coordinates, sample = self.solution.coordinates, self.solution._sample
        if kind in ("speed", "distance"):
            if self.turning:
                return None
            key = "v" if kind == "speed" else "d"
            factor = definite(sp.sqrt(sum(self.direction[coordinates.of(target, k)] ** 2 for k in ("x", "y"))), sample)
        else:  # a rate of turning, or the angle turned (in rad; asked in turns)
            key = "v" if kind == "angular_velocity" else "d"
            factor = definite(sp.Abs(self.direction[coordinates.of(target, "theta")]), sample)
        value = tidy(factor * found[key])
        symbol = sp.Symbol(name)
        if kind == "turns":
            steps.append(Step(_WORDS[kind].format(target=target),
                              (sp.Eq(symbol, factor * symbols[key] / (2 * sp.pi)), sp.Eq(symbol, tidy(value / (2 * sp.pi))))))
        elif kind == "angular_velocity" and self.kinetic is not None and target == self.leader:  # omega = v/R written
            steps.append(Step(_WORDS[kind].format(target=target), (sp.Eq(symbol, value),)))
        elif factor != 1 or target != self.leader:  # v = v said nothing: the constraints tie them one to one
            tie = (sp.Eq(symbol, factor * symbols[key]),) if symbol != factor * symbols[key] else ()
            steps.append(Step(_WORDS[kind].format(target=target), (*tie, sp.Eq(symbol, value))))
        return value


_WORDS = {"speed": "The {target} moves in proportion, as the constraints tie it to the first",
          "distance": "The {target} goes in proportion, as the constraints tie it to the first",
          "angular_velocity": "The {target}'s rate of turning follows from the speed, as the constraints tie them",
          "turns": "The number of turns is the angle turned over the angle of one turn"}
