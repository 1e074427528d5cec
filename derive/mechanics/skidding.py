"""A ball launched without spin that skids on a level floor, then rolls, as a textbook solves it
(Serway & Jewett, Physics for Scientists and Engineers 9th ed., ch. 10 problems; Kleppner &
Kolenkow 2nd ed., ch. 7): while its bottom slides forward, kinetic friction mu M g acts backward
on it; Newton's second law along the motion slows its center at a = -mu g, the torque of friction
about its center spins it up at alpha = mu M g R / I. It rolls once v = R omega: at
t = v0 / (mu g (1 + M R^2 / I)), having skidded d = v0 t - mu g t^2 / 2; its speed then is
v0 / (1 + I / (M R^2)), 5 v0/7 for a solid sphere, and friction has taken the kinetic energy lost.
The engine finds the same motion from its equations of motion with kinetic friction
(derive.mechanics.states); derive.solution.crosschecks compares them.

>>> M, R, mu, g, v0 = sp.symbols("M R mu g v0", positive=True)
>>> skid = skidding(M, 2 * M * R**2 / 5, R, mu, g, v0, energy=True)
>>> skid.values["time"], skid.values["speed"], skid.values["lost"]
(2*v0/(7*g*mu), 5*v0/7, M*v0**2/7)
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


def skidding(mass, inertia, radius, mu, g, launch, energy: bool = False) -> Skid:
    """The route for a body of `mass`, moment of inertia `inertia` about its center and `radius`
    launched at the speed `launch` without spin along a level floor of kinetic friction `mu`;
    `energy`: the kinetic energy once it rolls and the energy lost too."""
    a, alpha, t = sp.Symbol("a", real=True), sp.Symbol("alpha", real=True), sp.Symbol("t", positive=True)
    f, N, v, omega = (sp.Symbol(n, positive=True) for n in ("f", "N", "v", "omega"))
    moment = sp.Symbol("I") if not isinstance(inertia, sp.Symbol) else inertia
    deceleration = mu * g
    spin_up = tidy(mu * mass * g * radius / inertia)
    time = tidy(launch / (deceleration + radius * spin_up))
    speed = tidy(launch - deceleration * time)
    distance = tidy(launch * time - deceleration * time**2 / 2)
    values = {"a": -deceleration, "alpha": spin_up, "time": time, "distance": distance, "speed": speed,
              "rate": tidy(speed / radius)}
    given = (sp.Eq(moment, inertia),) if moment != inertia else ()
    steps = [
        Step("Newton's second law along the lane, the way the ball is launched counted positive: while it skids, its "
             "bottom slides forward over the lane, so kinetic friction acts on it backward, its size the coefficient "
             "of kinetic friction times the normal force, which balances the weight across the lane",
             (sp.Eq(N, mass * g), sp.Eq(f, mu * N), sp.Eq(mass * a, -f), sp.Eq(a, -deceleration))),
        Step("Torque about the center: friction acts at the bottom, a distance R below the center, and turns the ball "
             "the way it rolls forward; the normal force and the weight pass through the center",
             (*given, sp.Eq(moment * alpha, f * radius), sp.Eq(alpha, spin_up))),
        Step("At these constant accelerations, from the launch speed and no spin, the speed falls and the rate of "
             "turning grows", (sp.Eq(v, launch + a * t), sp.Eq(omega, alpha * t))),
        Step("It rolls without slipping once its bottom no longer slides over the lane, when its speed is its radius "
             "times its rate of turning", (sp.Eq(launch - deceleration * t, radius * spin_up * t), sp.Eq(t, time)),
             role="solve"),
        Step("Then its speed, and the distance it skidded at the constant acceleration",
             (sp.Eq(sp.Symbol("V"), speed), sp.Eq(sp.Symbol("d"), distance)), role="solve"),
    ]
    if energy:
        K0, K1 = sp.Symbol("K_0"), sp.Symbol("K_1")
        final = tidy(mass * speed**2 / 2 + inertia * values["rate"]**2 / 2)
        values.update(K1=final, lost=tidy(mass * launch**2 / 2 - final))
        steps.append(Step("The kinetic energy at the launch, all in the motion of the center, and once it rolls, of its "
                          "center's motion and its rotation: kinetic friction does negative work on the sliding ball, "
                          "and the kinetic energy lost to it is the difference",
                          (sp.Eq(K0, mass * launch**2 / 2), sp.Eq(K1, mass * v**2 / 2 + moment * omega**2 / 2),
                           sp.Eq(K1, final), sp.Eq(K0 - K1, values["lost"]))))
    return Skid(tuple(steps), values)
