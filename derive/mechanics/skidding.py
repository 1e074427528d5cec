"""A ball launched along a level floor that skids, then rolls, as a textbook solves it (Serway &
Jewett, Physics for Scientists and Engineers 9th ed., ch. 10 problems: the bowling ball; Kleppner &
Kolenkow 2nd ed., ch. 7: the cue ball struck low, with backspin): while its bottom slides over the
floor, kinetic friction mu M g acts on it against that sliding; Newton's second law along the motion
gives its center a = -/+ mu g, the torque of friction about its center its angular acceleration
alpha = +/- mu M g R / I. It rolls once v = R omega: at t = |v0 - R omega0| / (mu g (1 + M R^2 / I)),
having skidded d = v0 t + a t^2 / 2; without spin its speed then is v0 / (1 + I / (M R^2)), 5 v0/7
for a solid sphere, and friction has taken the kinetic energy lost.
The engine finds the same motion from its equations of motion with kinetic friction
(derive.mechanics.states); derive.solution.crosschecks compares them.

>>> M, R, mu, g, v0, w0 = sp.symbols("M R mu g v0 w0", positive=True)
>>> skid = skidding(M, 2 * M * R**2 / 5, R, mu, g, v0, asked={"speed", "lost"})
>>> skid.values["time"], skid.values["speed"], skid.values["lost"]
(2*v0/(7*g*mu), 5*v0/7, M*v0**2/7)
>>> skidding(M, 2 * M * R**2 / 5, R, mu, g, v0, spin=-w0, asked={"speed"}).values["speed"]
(-2*R*w0 + 5*v0)/7
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.core.tidying import tidy
from derive.text.steps import Step


@dataclass(frozen=True)
class Skid:
    """The steps, and what they find: the acceleration a and angular acceleration alpha while it
    skids (forward positive, its rate of turning the way it rolls forward), the time, the distance,
    the speed and the rate of turning once it rolls, its kinetic energy then and the kinetic energy lost."""

    steps: tuple[Step, ...]
    values: dict[str, sp.Expr]


def skidding(mass, inertia, radius, mu, g, launch, spin=sp.Integer(0), asked=frozenset(), sense: int = 1,
             backspin: bool = False) -> Skid:
    """The route for a body of `mass`, moment of inertia `inertia` about its center and `radius`
    launched at the speed `launch` turning at `spin` the way it rolls forward (negative: backspin)
    along a level floor of kinetic friction `mu`; `sense`: +1 where its bottom slides forward at the
    launch (friction acts backward), -1 where it slides backward; `backspin`: whether `spin` turns it
    against the way it rolls forward. The steps show what `asked` names
    of the values (the time always): "distance", "speed", "K1", "lost"."""
    a, alpha, t = sp.Symbol("a", real=True), sp.Symbol("alpha", real=True), sp.Symbol("t", positive=True)
    V, d, omega = sp.Symbol("V"), sp.Symbol("d"), sp.Symbol("omega")
    deceleration = sense * mu * g
    spin_up = tidy(sense * mu * mass * g * radius / inertia)
    time = tidy((launch - radius * spin) / (deceleration + radius * spin_up))
    speed = tidy(launch - deceleration * time)
    distance = tidy(launch * time - deceleration * time**2 / 2)
    values = {"a": -deceleration, "alpha": spin_up, "time": time, "distance": distance, "speed": speed,
              "rate": tidy(speed / radius)}
    slides, acts = ("forward", "backward") if sense > 0 else ("backward", "forward")
    spun = "" if spin == 0 else ", the backspin adding to its forward motion there" if backspin else \
        ", the topspin taking from its forward motion there" if sense > 0 else \
        ", the topspin carrying it back faster than the ball moves forward"
    steps = [
        Step(f"Newton's second law along the lane, the way the ball is launched counted positive: while it skids, its "
             f"bottom slides {slides} over the lane{spun}, so kinetic friction acts on it {acts}, its size the "
             "coefficient of kinetic friction times the normal force, which balances the weight across the lane",
             (sp.Eq(mass * a, -sense * mu * mass * g), sp.Eq(a, -deceleration))),
        Step("Torque about the center: friction acts at the bottom, a distance R below the center, and turns the ball "
             f"{'the way it rolls forward' if sense > 0 else 'against the way it rolls forward'}; the normal force and "
             "the weight pass through the center",
             (sp.Eq(inertia * alpha, sense * mu * mass * g * radius), sp.Eq(alpha, spin_up))),
        Step("It rolls without slipping once its bottom no longer slides over the lane, when its speed is its radius "
             "times its rate of turning; at these constant accelerations its speed changes from the launch speed, "
             f"and its rate of turning from {'zero' if spin == 0 else 'the spin it is launched with'}, in proportion "
             "to the time", (sp.Eq(launch - deceleration * t, sp.expand(radius * (spin + spin_up * t))), sp.Eq(t, time)),
             role="solve"),
    ]
    energy = {"K1", "lost"} & set(asked)
    then = tuple(e for name, e in (("speed", sp.Eq(V, speed)), ("distance", sp.Eq(d, distance)))
                 if name in asked or name == "speed" and energy)
    if then:
        words = {V: "its speed", d: "the distance it skidded at the constant acceleration"}
        steps.append(Step("Then " + ", and ".join(words[e.lhs] for e in then), then, role="solve"))
    if energy:
        K0, K1 = sp.Symbol("K_0"), sp.Symbol("K_1")
        rolling = mass * V**2 / 2 + inertia * omega**2 / 2
        final = tidy(mass * speed**2 / 2 + inertia * values["rate"]**2 / 2)
        start = mass * launch**2 / 2 + inertia * spin**2 / 2
        values.update(K1=final, lost=tidy(start - final))
        lost = (sp.Eq(K0 - K1, start - rolling), sp.Eq(K0 - K1, values["lost"]))
        rolled = (sp.Eq(K1, rolling), sp.Eq(K1, final))
        equations = (rolled if "K1" in asked else ()) + (lost if "lost" in asked else ())
        steps.append(Step("The kinetic energy once it rolls is that of its center's motion and of its rotation at the "
                          "rate its speed over its radius" + (": kinetic friction does negative work on the sliding ball, and the kinetic "
                                        "energy lost to it is the difference from the launch" if "lost" in asked else ""),
                          equations if "K1" not in asked or "lost" not in asked else (*rolled, lost[1])))
    return Skid(tuple(steps), values)
