"""The least release height that carries a body round a vertical loop, as a textbook finds it
(Serway & Jewett, Physics for Scientists and Engineers 9th ed., ch. 8, and Halliday, Resnick &
Walker 10th ed., ch. 8: the loop-the-loop; ch. 11 for a ball that rolls): at the top of the loop
the weight and the track's push both point to the center, m g + N = m v^2 / rho (rho the radius of
the circle its center runs on); it stays on the track while N >= 0, so v^2 >= g rho; energy is
conserved on the way there (the track's push does no work, nor does static friction at a point
that does not slip), m g (h - 2 rho) = m v^2/2 (1 + I/(m r^2) for a ball that rolls), so
h = 2 rho + (1 + I/(m r^2)) rho / 2: 5 R/2 sliding, 27 R/10 for a small solid sphere. The engine
finds the normal force at the top from its equations of motion by each route
(derive.solution.answers: release_height); derive.solution.textbook_routes compares them.

>>> m, g, R, r = sp.symbols("m g R r", positive=True)
>>> loop_top(m, g, R, None, None)[1], loop_top(m, g, R, 2 * m * r**2 / 5, r)[1]
(5*R/2, 27*R/10)
"""
from __future__ import annotations

import sympy as sp

from derive.core.tidying import tidy
from derive.text.steps import Step


def loop_top(mass, g, rho, inertia, radius, name: str = "body") -> tuple[tuple[Step, ...], sp.Expr]:
    """(the steps, the least release height of the center above its lowest point) for a body of `mass`
    whose center runs on a circle of radius `rho` inside the loop; sliding without friction where
    `inertia` is None, else rolling without slipping on its rim of `radius`, its moment of inertia
    `inertia` about its center; `name`: the body in words."""
    N, v, h = sp.Symbol("N", real=True), sp.Symbol("v", positive=True), sp.Symbol("h", positive=True)
    speed = sp.sqrt(g * rho)
    if inertia is None:
        kinetic, turning, rolled = mass * v**2 / 2, (), {}
        why = "the track's push is at right angles to the motion and does no work, and there is no friction"
        what = f"the kinetic energy is that of the {name}'s motion"
    else:
        omega = sp.Symbol("omega", positive=True)
        kinetic, turning, rolled = mass * v**2 / 2 + inertia * omega**2 / 2, (sp.Eq(omega, v / radius),), {omega: v / radius}
        why = (f"the track's push does no work, nor does static friction, acting at a point of the {name} that does not "
               "slip")
        what = (f"the kinetic energy is that of the {name}'s center's motion and of its rotation, rolling at its speed "
                "over its radius")
    (height,) = sp.solve(sp.Eq(mass * g * (h - 2 * rho), kinetic.xreplace(rolled).subs(v, speed)), h)
    height = tidy(height)
    steps = (
        Step(f"Newton's second law toward the center of the loop, at its top: the weight and the track's push both point "
             f"down, toward the center, and together give the {name} its centripetal acceleration",
             (sp.Eq(N + mass * g, mass * v**2 / rho),)),
        Step("It stays on the track while the track still pushes, that is while the normal force is not negative: the "
             "least speed at the top", (sp.Eq(v, speed),), role="solve"),
        Step(f"Energy is conserved from the release, at rest, to the top of the loop: {why}; {what}",
             (*turning, sp.Eq(mass * g * (h - 2 * rho), kinetic))),
        Step("With the least speed at the top, the least release height above the lowest point",
             (sp.Eq(h, height),), role="solve"),
    )
    return steps, height
