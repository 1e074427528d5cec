r"""Where a figure's labels go: each where its drawing asks, unless a stroke or a label placed before is
there; then at the nearest clear place beside the same point.

The canvas (`derive.publishing.figure.canvas._Figure`) keeps every label it is asked for (a label, an
arrow's at its tip, a dimension's at its middle) until the whole picture is drawn, then `placed` sets
them in the order asked, against the picture's strokes (`strokes`) and the labels set before it. A
label whose own place is clear stays there; the others move to the cheapest candidate (`candidates`).
The labels come last in the picture, over the strokes.

Why by hand: TikZ knows a path's geometry only when it compiles the picture, and the labels must be
placed before. `strokes` samples the paths of the small TikZ subset the canvas writes (straight
segments, circles, ellipses, rectangles, arcs, plots, curves by their control points, a rotation
about a point); it never reads a problem file's text.

>>> strokes([r"\draw (0,0) -- (0.08,0);"])
[(0.0, 0.0), (0.04, 0.0), (0.08, 0.0)]
>>> label = Label((0, 0), "west", "$M g$")
>>> [place[1:] for place in placed([label], strokes([r"\draw (0.2,-1) -- (0.2,1);"]))]  # a stroke there: moved
[((0, 0), 'south east', True)]
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass

import numpy as np

STEP = 0.04  # cm between the sample points of a stroke
FILL = 0.08  # cm between the sample points inside a dark fill
HEIGHT = 0.42  # cm: a label's height at \small, with its inner sep
SEP = 0.05  # cm: TikZ's inner sep of 1.5pt, around a label's text
#: The anchors a label may take, each with the direction from its point to the label's middle.
ANCHORS = {"west": (1, 0), "south west": (1, 1), "south": (0, 1), "south east": (-1, 1), "east": (-1, 0),
           "north east": (-1, -1), "north": (0, -1), "north west": (1, -1)}


@dataclass(frozen=True)
class Label:
    """A label asked for: its text beside `point` (cm) by its `anchor`; `options` more TikZ node
    options; `fixed`: kept where asked (a label turned with its surface); `inline`: the node as its
    path writes it, kept there while the place asked is clear."""

    point: tuple[float, float]
    anchor: str
    text: str
    options: str = ""
    fixed: bool = False
    inline: str = ""  # the node as written on its path (an arrow's at its tip), where it stays if clear



def size(text: str) -> tuple[float, float]:
    r"""A label's width and height (cm) at \small: a fraction as wide as its wider part, twice as tall.

    >>> [round(x, 2) for x in size("$\\frac{3 h}{4}$")]
    [0.43, 0.62]
    """
    if "\\vec" in text or "\\hat" in text:  # an accent over the letter
        return text_width(text), HEIGHT + 0.08
    fractions = re.findall(r"\\[dt]?frac\{([^{}]*)\}\{([^{}]*)\}", text)
    if not fractions:
        return text_width(text), HEIGHT
    rest = re.sub(r"\\[dt]?frac\{[^{}]*\}\{[^{}]*\}", "", text)
    parts = sum(max(text_width(f"${a}$"), text_width(f"${b}$")) - 2 * SEP for a, b in fractions)
    return text_width(rest) + parts, 0.62


def text_width(text: str) -> float:
    r"""A label's width (cm) at \small, from its letters' widths in Latin Modern (measured on the
    library's figures): M and m widest, capitals, lower case, digits narrowest; a Greek letter or a
    symbol as a lower-case letter; subscripts at 0.7; plus the inner sep on both sides.

    >>> round(text_width("$M\\,g$"), 2), round(text_width("$\\mu\\,M\\,g$"), 2)  # TeX: 0.61 cm, 0.85 cm, and the seps
    (0.68, 0.92)
    """
    scale = 0.75 if "\\scriptsize" in text or "\\scriptstyle" in text else 1.0
    spaces = 0.05 * text.count("\\,")
    text = re.sub(r"\\(scriptsize|scriptstyle|vec|mathrm|mathit|left|right)(?![A-Za-z])|\\[,!;]", " ", text)
    text = re.sub(r"\\[A-Za-z]+", "x", text)  # a Greek letter or a symbol: one character
    subscripts = "".join(a or b for a, b in re.findall(r"_\{([^}]*)\}|_(.)", text))
    text = re.sub(r"_\{[^}]*\}|_.", "", text)
    return scale * (spaces + sum(map(_letter, re.sub(r"[${}^\\ ]", "", text)))
                    + 0.7 * sum(map(_letter, re.sub(r"[${}^\\ ]", "", subscripts)))) + 2 * SEP


def _letter(character: str) -> float:
    r"""One letter's width (cm) at \small."""
    if character in "MW":
        return 0.34
    if character in "mw":
        return 0.31
    if character.isupper():
        return 0.26
    if character.isdigit():
        return 0.14
    return 0.19


def box(point, anchor: str, width: float, height: float = HEIGHT):
    """The box (x0, y0, x1, y1) of a node of that size anchored at `point`."""
    x, y = point
    dx = {"west": 0, "east": -width, "north": -width / 2, "south": -width / 2, "center": -width / 2}
    dy = {"south": 0, "north": -height, "west": -height / 2, "east": -height / 2, "center": -height / 2}
    horizontal = next((k for k in ("west", "east") if k in anchor), anchor if anchor in ("north", "south") else "center")
    vertical = next((k for k in ("south", "north") if k in anchor), anchor if anchor in ("west", "east") else "center")
    x0, y0 = x + dx[horizontal], y + dy[vertical]
    return (x0, y0, x0 + width, y0 + height)


def grown(rectangle, margin: float):
    return (rectangle[0] - margin, rectangle[1] - margin, rectangle[2] + margin, rectangle[3] + margin)


def overlap(a, b) -> float:
    """The area two boxes share."""
    return max(0.0, min(a[2], b[2]) - max(a[0], b[0])) * max(0.0, min(a[3], b[3]) - max(a[1], b[1]))


def covered(rectangle, points) -> int:
    """How many of the points (a list, or an array of rows) lie in the box."""
    points = np.asarray(points, dtype=float).reshape(-1, 2)
    return int(((points[:, 0] >= rectangle[0]) & (points[:, 0] <= rectangle[2])
                & (points[:, 1] >= rectangle[1]) & (points[:, 1] <= rectangle[3])).sum())


def candidates(label: Label):
    """Where a label may go, in order, each with what it costs to move it there: the place asked first,
    then each other anchor at the same point (the nearer the side asked, the sooner), then each anchor
    a little further out (the farther, the later)."""
    yield 0.0, label.point, label.anchor
    order = list(ANCHORS)
    asked = order.index(label.anchor) if label.anchor in ANCHORS else 0
    for step, anchor in enumerate(order):
        turn = min((step - asked) % 8, (asked - step) % 8)
        if turn:
            yield 0.2 + 0.05 * turn, label.point, anchor
    for reach in (0.15, 0.3, 0.45, 0.6, 0.8):
        for anchor, (dx, dy) in ANCHORS.items():
            length = math.hypot(dx, dy)
            yield 0.3 + 2 * reach, (label.point[0] + reach * dx / length, label.point[1] + reach * dy / length), anchor


def placed(labels: list[Label], ink: list[tuple[float, float]]) -> list[tuple[Label, tuple[float, float], str, bool]]:
    """Each label with its point and anchor, and whether that place is clear of the strokes: the first
    candidate clear of the strokes and of the labels placed before it (and far enough from them not to
    read as one), with no stroke between it and its point; else the first clear of the labels with no
    stroke between, to be set on a patch over the strokes; else the first clear of the labels; else the
    place asked."""
    boxes, result = [], []
    ink = np.asarray(ink, dtype=float).reshape(-1, 2)
    for label in labels:
        width, height = size(label.text)
        chosen = patched = beyond = None
        for _, point, anchor in (candidates(label) if not label.fixed else [(0.0, label.point, label.anchor)]):
            inner = grown(box(point, anchor, width, height), -SEP)  # the text itself, within its inner sep
            if any(overlap(inner, grown(other, 0.1)) for other in boxes):
                continue
            if _cut_off(label.point, inner, ink):
                beyond = beyond or (point, anchor, inner, label.fixed)
            elif not covered(inner, ink):
                chosen = (point, anchor, inner, True)
                break
            else:
                patched = patched or (point, anchor, inner, label.fixed)
        if chosen is None:  # a label turned with its surface is set as its layout sets it
            chosen = patched or beyond or (label.point, label.anchor,
                                           grown(box(label.point, label.anchor, width, height), -SEP), label.fixed)
        point, anchor, inner, clear = chosen
        boxes.append(inner)
        result.append((label, point, anchor, clear))
    return result


def _cut_off(point, inner, ink) -> bool:
    """Whether a stroke runs between a label's point and its text (a weight's label under the ground
    it stands on): ink within 0.03 cm of the straight way from the point to the text's middle, away
    from the point itself."""
    middle = np.array([(inner[0] + inner[2]) / 2, (inner[1] + inner[3]) / 2])
    start = np.asarray(point, dtype=float)
    way = middle - start
    length = float(np.hypot(*way))
    if length < 0.1 or not len(ink):
        return False
    along = np.clip((ink - start) @ way / length**2, 0, 1)
    nearest = start + along[:, None] * way
    return bool(((np.hypot(*(ink - nearest).T) < 0.03) & (np.hypot(*(ink - start).T) > 0.15)).any())


_NUMBER = r"(-?\d+(?:\.\d+)?)"
_POINT = re.compile(rf"\(\s*{_NUMBER}\s*,\s*{_NUMBER}\s*\)")
_TOKENS = re.compile(
    rf"(?P<point>\(\s*{_NUMBER}\s*,\s*{_NUMBER}\s*\))"
    rf"|circle\s*\(\s*(?P<radius>{_NUMBER})\s*\)"
    rf"|ellipse\s*\(\s*(?P<rx>{_NUMBER})\s+and\s+(?P<ry>{_NUMBER})\s*\)"
    r"|arc\s*\[(?P<arc>[^\]]*)\]"
    r"|(?P<rectangle>rectangle)"
    r"|(?P<line>--|\.\.)"
    r"|(?P<cycle>cycle)"
    r"|plot\s*\[[^\]]*\]\s*coordinates\s*\{(?P<plot>[^}]*)\}"
    r"|node\s*\[[^\]]*\]\s*\{(?:[^{}]|\{[^{}]*\})*\}")
_ROTATE = re.compile(rf"rotate around=\{{{_NUMBER}:\(\s*{_NUMBER}\s*,\s*{_NUMBER}\s*\)\}}")


def strokes(lines: list[str]) -> list[tuple[float, float]]:
    """Points every STEP cm along the strokes the TikZ lines draw, the edges of what they fill, and the
    inside of what they fill dark (a bearing's block, a hatched ground): no label is legible there."""
    points = []
    for line in lines:
        for statement in line.split(";"):
            command = re.match(r"\s*\\(draw|fill|shade|filldraw)\b(\[[^\]]*\])?", statement)
            if not command:
                continue
            options = command.group(2) or ""
            shapes = _path(statement[command.end():])
            if _dark(command.group(1), options):
                shapes.append(_inside(shapes, "even odd" in options))
            elif "ball color" in options:  # a ball's shading darkens toward its rim away from its highlight
                shapes += [_shadow(shape) for shape in shapes]
            drawn = [p for shape in shapes for p in shape]
            turn = _ROTATE.search(options)
            points += _rotated(drawn, *map(float, turn.groups())) if turn else drawn
    return [(round(x, 6), round(y, 6)) for x, y in points]


def _dark(command: str, options: str) -> bool:
    """Whether a path is filled too dark to write on: black, a pattern, gray at half or more, a color
    mixed with black (light fills, a body's gray, white, are written on)."""
    fill = re.search(r"(?:^|[\[,]\s*)fill=([^,\]]+)", options)
    if command in ("fill", "filldraw") and fill is None:
        color = re.match(r"\[\s*([a-z]+(?:![0-9]+)*(?:![a-z]+)?)\s*[,\]]", options)
        if "pattern" in options or color is None:
            return True
        fill = color
    if fill is None:
        return False
    color = fill.group(1).strip()
    shade = re.fullmatch(r"[a-z]+!([0-9]+)", color)
    return color == "black" or "!black" in color or (shade is not None and int(shade.group(1)) >= 50)


def _shadow(shape) -> list[tuple[float, float]]:
    """The dark part of a ball's shading: inside its outline, farther than 0.95 of its radius from the
    highlight, a quarter of the radius up and to the left of its middle."""
    xs, ys = [p[0] for p in shape], [p[1] for p in shape]
    radius = (max(xs) - min(xs)) / 2
    light = ((max(xs) + min(xs)) / 2 - radius / 4, (max(ys) + min(ys)) / 2 + radius / 4)
    return [p for p in _inside([shape]) if math.hypot(p[0] - light[0], p[1] - light[1]) > 0.95 * radius]


def _inside(shapes, even_odd: bool = False) -> list[tuple[float, float]]:
    """Points on a grid of FILL cm inside the closed outlines: inside any (TikZ's nonzero rule, for
    outlines apart), or inside an odd number of them (the even-odd rule: a ring between two circles).
    A point is inside an outline when a ray to its right crosses it an odd number of times."""
    shapes = [np.array(shape) for shape in shapes if len(shape) >= 3]
    if not shapes:
        return []
    everything = np.concatenate(shapes)
    low, high = everything.min(axis=0), everything.max(axis=0)
    xs, ys = np.meshgrid(np.arange(low[0] + FILL, high[0], FILL), np.arange(low[1] + FILL, high[1], FILL))
    x, y = xs.ravel()[:, None], ys.ravel()[:, None]
    count = np.zeros(x.shape[0], dtype=int)
    for shape in shapes:
        a, b = shape, np.roll(shape, -1, axis=0)
        spans = (a[:, 1] > y) != (b[:, 1] > y)
        with np.errstate(divide="ignore", invalid="ignore"):
            crossing = x < a[:, 0] + (y - a[:, 1]) * (b[:, 0] - a[:, 0]) / (b[:, 1] - a[:, 1])
        count += (spans & crossing).sum(axis=1) % 2
    inside = count % 2 == 1 if even_odd else count > 0
    return list(zip(x[inside, 0].tolist(), y[inside, 0].tolist()))


def _path(path: str) -> list[list[tuple[float, float]]]:
    """The sample points of one path, shape by shape (each run of joined segments, circle, rectangle)."""
    shapes, here, start, joined, rectangle = [], None, None, False, False
    for token in _TOKENS.finditer(path):
        kind = token.lastgroup
        if kind == "point":
            there = (float(token.group(2)), float(token.group(3)))
            if rectangle and here is not None:
                corners = [here, (there[0], here[1]), there, (here[0], there[1]), here]
                shapes[-1:] = [[p for a, b in zip(corners, corners[1:]) for p in _segment(a, b)[1:]]]
            elif joined and here is not None:
                shapes[-1] += _segment(here, there)[1:]
            else:
                start = there
                shapes.append([there])
            here, joined, rectangle = there, False, False
        elif kind == "line":
            joined = True
        elif kind == "rectangle":
            rectangle = True
        elif kind == "cycle" and joined and here is not None and start is not None:
            shapes[-1] += _segment(here, start)[1:]
            here, joined = start, False
        elif kind in ("radius", "ry") and here is not None:  # a circle, an ellipse (its last group)
            rx = float(token.group("radius") or token.group("rx"))
            ry = float(token.group("ry") or rx)
            shapes.append(_ellipse(here, rx, ry, 0.0, 360.0))
        elif kind == "arc" and here is not None:
            options = dict(re.findall(rf"(start angle|end angle|x radius|y radius|radius)={_NUMBER}", token.group("arc")))
            rx = float(options.get("x radius", options.get("radius", 0)))
            ry = float(options.get("y radius", options.get("radius", 0)))
            first, last = float(options.get("start angle", 0)), float(options.get("end angle", 0))
            center = (here[0] - rx * math.cos(math.radians(first)), here[1] - ry * math.sin(math.radians(first)))
            drawn = _ellipse(center, rx, ry, first, last)
            shapes[-1] += drawn[1:]
            here = drawn[-1]
        elif kind == "plot":
            plot = [(float(x), float(y)) for x, y in _POINT.findall(token.group("plot"))]
            shapes.append([p for a, b in zip(plot, plot[1:]) for p in _segment(a, b)[1:]] or plot)
    return shapes


def _segment(a, b) -> list[tuple[float, float]]:
    steps = max(1, math.ceil(math.hypot(b[0] - a[0], b[1] - a[1]) / STEP))
    return [(a[0] + (b[0] - a[0]) * k / steps, a[1] + (b[1] - a[1]) * k / steps) for k in range(steps + 1)]


def _ellipse(center, rx: float, ry: float, first: float, last: float) -> list[tuple[float, float]]:
    sweep = math.radians(last - first)
    steps = max(4, math.ceil(abs(sweep) * max(rx, ry) / STEP))
    return [(center[0] + rx * math.cos(math.radians(first) + sweep * k / steps),
             center[1] + ry * math.sin(math.radians(first) + sweep * k / steps)) for k in range(steps + 1)]


def _rotated(points, degrees: float, x0: float, y0: float) -> list[tuple[float, float]]:
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return [(x0 + c * (x - x0) - s * (y - y0), y0 + s * (x - x0) + c * (y - y0)) for x, y in points]

