"""The state an ask is read in (`in: STATE`): which quantities need one, which take one, and which
states can give them.

>>> from derive.language.problem import load
>>> load("block_up_incline").asks["h"].state
'highest'
"""
from __future__ import annotations

from derive import quantities
from derive.core.spelling import no_such
from derive.language.reader import Reader
from derive.model.scene import DYNAMIC_KINDS, RATE_KINDS, STATE_KINDS, Quantity, Scene
from derive.parts.slipping_clutch import SlippingClutch


def _of_kind(reader: Reader, raw, field: str, scene: Scene, kind, path: str) -> str | None:
    """The state an ask of a quantity of derive.quantities is read in, as its kind's `state` says:
    "never", "optional" (the placement at rest without `in:`) or "change" (from the state that
    state comes from, or the placement at rest; a move, made however one likes, leaves it
    undetermined)."""
    if raw is None:
        if kind.state == "change":
            raise reader.fail(field, f"{path} is a change from one state to the next: give in: STATE (states: "
                                     f"{', '.join(scene.states) or 'none; add scene.states'})")
        return None
    if kind.state == "never":
        raise reader.fail(field, f"{path} is not read in a state: leave in: out")
    if not isinstance(raw, str) or raw not in scene.states:
        raise reader.fail(field, no_such("state", raw, scene.states, "states") + ("; add scene.states" if not scene.states else ""))
    state = scene.states[raw]
    if kind.state == "change" and state.start is None and state.rates:
        raise reader.fail(field, f"{path} is a change from one state to the next, and the state {raw} is the "
                                 "placement moving at its rates: ask it in a state the motion gets to")
    if state.event and state.event.kind in ("move", "turn", "pull"):
        raise reader.fail(field, f"after a {state.event.kind}, where the bodies are depends on how it is made: ask "
                                 f"{path} in a state the motion gets to")
    return raw


def state(reader: Reader, raw, field: str, scene: Scene, quantity: Quantity, path: str) -> str | None:
    """The state an ask is read in (`in: vertical`): rates need one; accelerations and forces take one."""
    slipping = next((p.name for p in scene.loads if isinstance(p, SlippingClutch)), None)
    if raw is None and slipping and quantity.kind in DYNAMIC_KINDS:
        raise reader.fail(field, f"the clutch {slipping} slips only while its plates turn at different rates: ask "
                                 "in a state where they do (in: STATE)")
    kind = quantities.KINDS[quantity.kind]
    if kind.state != "motion":
        return _of_kind(reader, raw, field, scene, kind, path)
    if raw is None:
        if quantity.kind in RATE_KINDS:
            raise reader.fail(field, f"{path} is read in a state: give in: STATE (states: "
                                     f"{', '.join(scene.states) or 'none; add scene.states'})")
        return None
    if not isinstance(raw, str) or raw not in scene.states:
        raise reader.fail(field, no_such("state", raw, scene.states, "states") + ("; add scene.states" if not scene.states else ""))
    if quantity.kind not in STATE_KINDS or quantity.kind == "contact" and quantity.detail not in ("normal_force",
                                                                                                  "friction"):
        raise reader.fail(field, f"{path} is not read in a state: only accelerations, forces, positions and rates are")
    if quantity.kind == "time" and scene.states[raw].nudge:
        raise reader.fail(field, f"the motion to {raw} starts with a vanishing push (nudged:), and the time it takes "
                                 "grows without bound as the push vanishes: ask where it gets and how fast")
    if quantity.kind == "time" and scene.states[raw].rates:
        raise reader.fail(field, f"the state {raw} is the placement, at time zero: ask the time in a state the "
                                 "motion gets to (when:)")
    if quantity.kind == "kinetic_energy_change" and scene.states[raw].start is None:
        raise reader.fail(field, f"the state {raw} comes from no other state: ask the change of kinetic energy in a "
                                 "state with from:")
    event = scene.states[raw].event
    tension = event is not None and event.kind == "pull" and quantity.kind == "force" and \
        quantity.target == event.joint and quantity.detail == "tension"  # along the cord, wherever the body is
    if event and event.kind in ("move", "pull") and not tension and quantity.kind not in (
            "angular_velocity", "kinetic_energy", "kinetic_energy_change", "speed"):
        raise reader.fail(field, f"after a {event.kind}, where the bodies are depends on how it is made (a turntable "
                                 f"turns while a child walks on it), and so do the directions of their velocities and "
                                 f"forces: in the state {raw} ask an angular velocity, a speed or the kinetic energy"
                                 + (f" (or the tension of the cord {event.joint})" if event.kind == "pull" else ""))
    if quantity.kind == "impulse" and not (event and event.kind in ("stick", "lock", "bounce")):
        raise reader.fail(field, f"an impulse is given in an impact: the state {raw} is not just after one (a state "
                                 "with event: {stick|lock|bounce: ...})")
    if quantity.kind == "time" and event:
        raise reader.fail(field, f"the state {raw} is just after an impact, which takes no time: ask the time in a "
                                 "state the motion gets to (when:)")
    return raw
