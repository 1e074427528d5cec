"""A body's moment of inertia: `BODY.inertia` (about the axis normal to the plane through its
center of mass), with `axis:` a named axis of its shape or a direction through its center of mass,
`end:` an end of a rod, and `shift:` the axis moved (a vector in the body's frame, or a distance
across a named axis through the center of mass).

    I = integral of r_perp^2 dm          I = I_cm + M h^2   (h from the center of mass, always)

Route 0 (the key's): the integral over the body (derive.model.inertia.body_moment), its density's
branches resolved over the parameter ranges. Route 1, its check: n^T I n from the inertia tensor
(a different integral; a composite's parts' tensors composed against the scalar parallel-axis sum);
a custom body's moment is given, not derived, and has none. The parallel-axis theorem checks an
axis off the center of mass, through the parallel axis through the center of mass.

The path is read with the ask's `axis:` (derive.model.scene.parse_quantity), not by `claims`.

>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> solution = Solution(load("rod_endpoint"))
>>> MOMENT_OF_INERTIA.value(solution, solution.problem.asks["I"], 1)
L**2*m/3
"""
from __future__ import annotations

from dataclasses import replace

import sympy as sp

from derive.model import composite, inertia
from derive.model.scene import Quantity
from derive.numbers.agreement import agree
from derive.quantities.base import Check, CheckFailure, QuantityKind

#: The parallel-axis check, as a worked solution reads it.
PARALLEL_AXIS = "The parallel-axis theorem gives the same moment of inertia as direct integration."
ROUTES = ("integral", "tensor")


def shift_vector(solution, ask) -> tuple[sp.Expr, sp.Expr, sp.Expr] | None:
    """How far an ask's axis is moved, as a vector in the body's frame: as the file gives it, or a
    distance along `inertia.across` the axis, which is allowed only where the named axis passes
    through the center of mass (else the direction decides the moment: a rod denser at one end
    has I = ML^2/3 a half-length across its middle axis, ML^2/6 along it to its heavy end)."""
    if ask.shift is None or isinstance(ask.shift, tuple):
        return ask.shift
    body = solution.scene.bodies[ask.quantity.target]
    if inertia.off_axis(body.shape, ask.quantity.detail, body.sizes, body.density) != 0:
        raise solution.problem.error(
            f"ask.{ask.name}.shift", f"the {body.name}'s {ask.quantity.detail} axis does not pass through its center "
            f"of mass, so the moment about an axis {ask.shift} from it depends on the direction it is moved: give "
            f"the shift as [dx, dy] in the {body.name}'s frame, e.g. shift: [{ask.shift}, 0]")
    return tuple(ask.shift * e for e in inertia.across(inertia.SHAPES[body.shape].axes[ask.quantity.detail][1]))


def through_center_of_mass(solution, body, ask) -> sp.Expr:
    """The parallel-axis theorem for a shifted axis: the moment about the parallel axis through the
    center of mass, integrated, plus M d^2, d the distance between the two axes. Through the
    center of mass always: from any other axis the theorem does not hold (a rod denser at one end)."""
    mass, central = inertia.central_body_moment(body.shape, ask.quantity.detail, body.mass, body.sizes, body.density)
    apart = inertia.off_axis(body.shape, ask.quantity.detail, body.sizes, body.density,
                             shift_vector(solution, ask) or (0, 0, 0))
    return solution._within_ranges(central + mass * apart)


def parallel_axis_check(solution, ask) -> Check | None:
    """The parallel-axis theorem against the integral, for a named axis off the center of mass (None
    where the axis passes through it: the theorem adds nothing)."""
    body = solution.scene.bodies[ask.quantity.target]
    derived = inertia.moment_of_inertia(body.shape, ask.quantity.detail)
    answer = solution.expressions[ask.name]
    if ask.shift is not None or body.density is not None:  # the body's own axis, against I_cm + M d^2 through
        if ask.shift is None and inertia.off_axis(body.shape, ask.quantity.detail, body.sizes, body.density) == 0:
            return None  # its center of mass: the theorem adds nothing
        theorem = through_center_of_mass(solution, body, ask)
        if agree(theorem, answer) is None:
            raise CheckFailure(f"{solution.problem.id}: the {'shifted ' * (ask.shift is not None)}axis gives "
                               f"{answer}, the parallel-axis theorem {theorem}")
        return Check("parallel_axis", True, "symbolic",
                     f"{ask.name}: integration about the {'shifted ' * (ask.shift is not None)}axis equals I_cm + "
                     f"M h^2, I_cm about the parallel axis through the {body.name}'s center of mass", PARALLEL_AXIS)
    if derived.distance_from_center == 0:
        return None
    central = inertia.moment_of_inertia(body.shape, inertia.PLANAR_AXIS[body.shape]).I
    theorem = inertia.parallel_axis(central, inertia.M, derived.distance_from_center)
    if agree(theorem, derived.I) is None:
        raise CheckFailure(f"{solution.problem.id}: the parallel-axis theorem gives {theorem}, integration {derived.I}")
    return Check("parallel_axis", True, "symbolic",
                 f"{ask.name}: integration equals I_cm + M d^2 with d = {derived.distance_from_center}", PARALLEL_AXIS)


class MomentOfInertia(QuantityKind):
    """A body's moment of inertia about an axis (see the module)."""

    kind = "inertia"
    symbol = "I"
    unit = "kg*m^2"
    routes = ("the integral over the body", "n^T I n from the inertia tensor")
    own_section = False

    def claims(self, scene, head: str, rest: str) -> Quantity | None:
        return None  # read with the ask's axis: derive.model.scene.parse_quantity

    def value(self, solution, ask, route: int) -> sp.Expr | None:
        body = solution.scene.bodies[ask.quantity.target]
        if ask.quantity.detail is None and route == 0:
            return solution._within_ranges(body.inertia)
        if ask.quantity.detail is None:
            if body.composite is not None:  # the parts' tensors composed, against the scalar parallel-axis sum
                return composite.moment_by_sum(body.composite)
            if body.shape not in inertia.SHAPES:
                return None  # a custom body's inertia is given, not derived
            ask = replace(ask, quantity=Quantity("inertia", body.name, inertia.PLANAR_AXIS[body.shape]),
                          shift=None if body.density is None else  # through its center of mass
                          inertia.body_center(body.shape, body.sizes, body.density))
        axis = ask.quantity.detail
        along = None if isinstance(axis, str) else axis  # a direction through the center of mass
        moment = inertia.body_moment(body.shape, None if along else axis, body.mass, body.sizes, body.density,
                                     ROUTES[route], shift_vector(solution, ask), along)[1]
        return solution._within_ranges(moment)

    def checks(self, solution, names: list[str]) -> list[Check]:
        """Each moment again from the inertia tensor; an axis off the center of mass by the parallel-axis theorem."""
        compared = []
        for name in names:
            other = self.value(solution, solution.problem.asks[name], 1)
            if other is None:
                continue
            if agree(other, solution.expressions[name]) is None:
                raise CheckFailure(f"{solution.problem.id}: {name} is {solution.expressions[name]} integrated, "
                                   f"{other} from the tensor")
            compared.append(name)
        result = [Check("tensor_vs_integral", True, "symbolic", ", ".join(compared) or "no derived moment",
                        "The inertia tensor gives the same moments of inertia as direct integration.")]
        for name in names:
            ask = solution.problem.asks[name]
            if isinstance(ask.quantity.detail, str):  # a named axis
                result += [c for c in (parallel_axis_check(solution, ask),) if c]
        return result

    def describe(self, ask) -> str:
        return f"the moment of inertia of the {ask.quantity.target}"


MOMENT_OF_INERTIA = MomentOfInertia()
