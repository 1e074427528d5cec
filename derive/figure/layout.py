"""Which layout a scene gets: the first in the table that applies draws the figure."""
from __future__ import annotations

from derive.figure.bodies import _placed
from derive.figure.collisions import _impact
from derive.figure.inertia import _specimens
from derive.figure.joints import _pinned
from derive.figure.orbits import _orbit
from derive.figure.paths import _paths
from derive.figure.surfaces import _on_surface
from derive.figure.systems import _internal, _rotation, _top, _wave, _wheel
from derive.parts.contact import Contact
from derive.parts.pin import Pin
from derive.scene import Bounce, Stick


def _has(kind):
    return lambda scene: any(isinstance(c, kind) for c in scene.constraints)


_LAYOUTS = (
    (lambda s: s.top is not None, _top),
    (lambda s: s.wheel is not None, _wheel),
    (lambda s: s.wave is not None, _wave),
    (lambda s: s.orbit is not None, _orbit),
    (lambda s: s.internal_forces is not None, _internal),
    (lambda s: bool(s.rotations), _rotation),
    (lambda s: any(b.path is not None for b in s.bodies.values()), _paths),
    (_has(Contact), _on_surface),
    (lambda s: any(isinstance(e, (Stick, Bounce)) for e in s.events) and any(
        isinstance(e, (Stick, Bounce)) and e.body in s.motions for e in s.events), _impact),
    (_has(Pin), _pinned),
    (lambda s: bool(s.motions) and all(n in s.motions for n in s.bodies), _placed),
    (lambda s: bool(s.bodies), _specimens),
)
