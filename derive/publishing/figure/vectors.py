"""Plane vectors as pairs of floats, for the figures' layout (cm): differences, dot products,
unit and perpendicular vectors, where lines cross.
"""
from __future__ import annotations

import math

from derive.publishing.figure.canvas import _add


def _sub(p, q):
    return (p[0] - q[0], p[1] - q[1])


def _dot(p, q):
    return p[0] * q[0] + p[1] * q[1]


def _norm(p):
    length = math.hypot(*p)
    return (p[0] / length, p[1] / length) if length > 1e-12 else (0.0, 0.0)


def _perp(p):
    return (-p[1], p[0])


def _degrees(p) -> float:
    return math.degrees(math.atan2(p[1], p[0]))




def _on_segment(point, p, q) -> bool:
    """Whether `point` lies on the segment from p to q (to a millionth of its length)."""
    length = math.hypot(*_sub(q, p))
    direction, offset, tolerance = _norm(_sub(q, p)), _sub(point, p), 1e-6 * length
    return abs(_dot(offset, _perp(direction))) <= tolerance and -tolerance <= _dot(offset, direction) <= length + tolerance


def _crossing(p, u, q, v):
    """Where the line through p along u crosses the line through q along v; None if they are parallel."""
    cross = u[0] * v[1] - u[1] * v[0]
    if abs(cross) < 1e-9:
        return None
    t = ((q[0] - p[0]) * v[1] - (q[1] - p[1]) * v[0]) / cross
    return _add(p, u, t)


def _scale_vec(p, k: float):
    return (p[0] * k, p[1] * k)
