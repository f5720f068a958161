"""What a renderer needs to know, and nothing of the engine: the data passed from a simulation to
`max2code.render`.

The split is deliberate. The engine knows physics (masses, orbits, events); the renderer knows
pixels. Between them sits this module: a body is a shape in its own coordinates plus a style,
a frame is where every body is at one instant. A renderer never imports the engine, and the
engine never imports Pillow, so either can change (or be absent) without the other.

Conventions (the engine's, so nothing is converted twice):

* World coordinates are right-handed, y up, in the scene's length unit.
* A shape is given in *body coordinates*: relative to the body's origin, which the engine takes as
  the centre of mass. A pose (x, y, angle) puts that origin at (x, y) and rotates the shape by
  `angle` radians counter-clockwise: world = (x, y) + R(angle) . body_point.
* Static walls are ordinary bodies (usually a Segment or a Polygon) whose pose never changes.
* A frame lists one pose per body, in the order of the bodies.

Every value is checked when it is made (finite numbers, positive radii, convex polygons, colours
of the form #rrggbb or #rrggbbaa), so a renderer can trust what it is given and a label or a
colour read from a scene file can never smuggle markup into an SVG: colours are checked
here, and labels are escaped where they are written (they are data, never markup).
"""

from __future__ import annotations

import math
from functools import cached_property
import re
from dataclasses import dataclass, field
from typing import Union

Point = tuple[float, float]

_COLOUR = re.compile(r"#[0-9a-fA-F]{6}([0-9a-fA-F]{2})?")


class RenderModelError(ValueError):
    """A value that no picture can be made of (a negative radius, a concave polygon, ...)."""


def _finite(name: str, value: float) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise RenderModelError(f"{name} must be a number, not {type(value).__name__}")
    if not math.isfinite(value):
        raise RenderModelError(f"{name} must be finite, not {value!r}")
    return float(value)


def _point(name: str, p: Point) -> Point:
    if not isinstance(p, (tuple, list)) or len(p) != 2:
        raise RenderModelError(f"{name} must be a pair (x, y), not {p!r}")
    return (_finite(f"{name}.x", p[0]), _finite(f"{name}.y", p[1]))


def _colour(name: str, value: str | None) -> None:
    if value is not None and not (isinstance(value, str) and _COLOUR.fullmatch(value)):
        raise RenderModelError(f"{name} must be a colour '#rrggbb' or '#rrggbbaa', not {value!r}")


def _set(obj: object, name: str, value: object) -> None:
    """Store a normalised value on a frozen dataclass (inside __post_init__ only)."""
    object.__setattr__(obj, name, value)


# --- shapes, in body coordinates ---------------------------------------------------------------

@dataclass(frozen=True)
class Circle:
    """A disc of `radius` centred on the body's origin, offset by `centre` (default: on it)."""

    radius: float
    centre: Point = (0.0, 0.0)

    def __post_init__(self) -> None:
        _set(self, "radius", _finite("circle radius", self.radius))
        _set(self, "centre", _point("circle centre", self.centre))
        if self.radius <= 0:
            raise RenderModelError(f"circle radius must be positive, not {self.radius!r}")


@dataclass(frozen=True)
class Polygon:
    """A convex polygon; vertices in order (either winding: renderers do not care). A `radius`
    rounds it: every point within radius of the polygon (the engine's rounded polygons)."""

    vertices: tuple[Point, ...]
    radius: float = 0.0

    def __post_init__(self) -> None:
        vs = tuple(_point(f"polygon vertex {i}", v) for i, v in enumerate(self.vertices))
        _set(self, "vertices", vs)
        _set(self, "radius", _finite("polygon radius", self.radius))
        if self.radius < 0:
            raise RenderModelError(f"polygon radius must not be negative, not {self.radius!r}")
        if len(vs) < 3:
            raise RenderModelError(f"a polygon needs at least 3 vertices, not {len(vs)}")
        signs, turning = set(), 0.0
        for i in range(len(vs)):
            (ax, ay), (bx, by), (cx, cy) = vs[i], vs[(i + 1) % len(vs)], vs[(i + 2) % len(vs)]
            cross = (bx - ax) * (cy - by) - (by - ay) * (cx - bx)
            dot = (bx - ax) * (cx - bx) + (by - ay) * (cy - by)
            turning += math.atan2(cross, dot)
            if cross != 0:
                signs.add(cross > 0)
        # one sign of turn at every vertex, and once around (a pentagram turns twice)
        if len(signs) != 1 or abs(abs(turning) - 2 * math.pi) > 1e-6:
            raise RenderModelError("a polygon must be convex with non-zero area "
                                   "(vertices in order around it)")


@dataclass(frozen=True)
class Segment:
    """A line segment from `a` to `b` (a thin wall); drawn with the style's stroke width."""

    a: Point
    b: Point

    def __post_init__(self) -> None:
        _set(self, "a", _point("segment a", self.a))
        _set(self, "b", _point("segment b", self.b))
        if self.a == self.b:
            raise RenderModelError("a segment needs two different end points")


@dataclass(frozen=True)
class Capsule:
    """Every point within `radius` of the segment a-b (a stadium)."""

    a: Point
    b: Point
    radius: float

    def __post_init__(self) -> None:
        _set(self, "a", _point("capsule a", self.a))
        _set(self, "b", _point("capsule b", self.b))
        _set(self, "radius", _finite("capsule radius", self.radius))
        if self.radius <= 0:
            raise RenderModelError(f"capsule radius must be positive, not {self.radius!r}")


PART_SHAPES = (Circle, Polygon, Segment, Capsule)


@dataclass(frozen=True)
class Compound:
    """Several shapes on one body (the engine's compound bodies): drawn as their union, in one
    style; each part in body coordinates."""

    parts: tuple[Union[Circle, Polygon, Segment, Capsule], ...]

    def __post_init__(self) -> None:
        parts = tuple(self.parts) if isinstance(self.parts, (tuple, list)) else ()
        if not parts:
            raise RenderModelError("a compound needs at least one part")
        for k, p in enumerate(parts):
            if not isinstance(p, PART_SHAPES):
                raise RenderModelError(f"compound part {k} must be a circle, polygon, segment or "
                                       f"capsule, not {type(p).__name__}")
        _set(self, "parts", parts)


Shape = Union[Circle, Polygon, Segment, Capsule, Compound]
SHAPES = (Circle, Polygon, Segment, Capsule, Compound)


def shape_from_vertices(vertices: tuple[Point, ...] | list[Point], radius: float = 0.0) -> Shape:
    """The engine's way of giving a shape, as a Shape: one vertex and a radius is a circle
    (centred on the vertex), two vertices a segment (a capsule with a radius), three or more a
    convex polygon (rounded by the radius)."""
    vs = tuple(vertices)
    if len(vs) == 1:
        return Circle(radius, vs[0])
    if len(vs) == 2:
        return Capsule(vs[0], vs[1], radius) if radius > 0 else Segment(vs[0], vs[1])
    return Polygon(vs, radius)


def shape_from_parts(parts) -> Shape:
    """The engine's compound body, its parts each (vertices, radius): one part is that shape,
    more a Compound."""
    shapes = tuple(shape_from_vertices(v, r) for v, r in parts)
    return shapes[0] if len(shapes) == 1 else Compound(shapes)


# The basic colour names of HTML and CSS, for scene files written by hand.
NAMED_COLOURS = {
    "black": "#000000", "silver": "#c0c0c0", "gray": "#808080", "grey": "#808080",
    "white": "#ffffff", "maroon": "#800000", "red": "#ff0000", "purple": "#800080",
    "fuchsia": "#ff00ff", "green": "#008000", "lime": "#00ff00", "olive": "#808000",
    "yellow": "#ffff00", "navy": "#000080", "blue": "#0000ff", "teal": "#008080",
    "aqua": "#00ffff", "orange": "#ffa500",
}


def colour(text: str) -> str:
    """A colour as the model takes it (#rrggbb or #rrggbbaa) from what a person writes: those,
    #rgb, or a basic name (NAMED_COLOURS). Anything else is refused, with the forms allowed."""
    if isinstance(text, str):
        t = text.strip().lower()
        if t in NAMED_COLOURS:
            return NAMED_COLOURS[t]
        if re.fullmatch(r"#[0-9a-f]{3}", t):
            return "#" + "".join(c * 2 for c in t[1:])
        if _COLOUR.fullmatch(t):
            return t
    raise RenderModelError(f"unknown colour {text!r}: use #rrggbb, #rrggbbaa, #rgb or one of "
                           + ", ".join(sorted(NAMED_COLOURS)))


# --- style, pose, frame, view ------------------------------------------------------------------

@dataclass(frozen=True)
class Style:
    """How one body looks. `fill` None draws the outline only; `stroke_width` is in pixels of the
    final picture (so thin walls stay visible whatever the zoom); `label` is text drawn at the
    body's position (plain text: escaped in SVG, never interpreted)."""

    fill: str | None = "#4c72b0"
    stroke: str | None = "#1b1b1b"
    stroke_width: float = 1.5
    label: str | None = None
    spoke: bool = True  # a radius line on circles, so that rotation is visible

    def __post_init__(self) -> None:
        _colour("fill", self.fill)
        _colour("stroke", self.stroke)
        _set(self, "stroke_width", _finite("stroke_width", self.stroke_width))
        if self.stroke_width < 0:
            raise RenderModelError("stroke_width must not be negative")
        if self.label is not None and not isinstance(self.label, str):
            raise RenderModelError(f"label must be text, not {type(self.label).__name__}")


@dataclass(frozen=True)
class Body:
    """One drawable body: its shape in body coordinates and its style."""

    shape: Shape
    style: Style = field(default_factory=Style)

    def __post_init__(self) -> None:
        if not isinstance(self.shape, SHAPES):
            raise RenderModelError(f"unknown shape {type(self.shape).__name__}")
        if not isinstance(self.style, Style):
            raise RenderModelError(f"style must be a Style, not {type(self.style).__name__}")


@dataclass(frozen=True)
class Pose:
    """Where a body is: its origin at (x, y), turned `angle` radians counter-clockwise."""

    x: float
    y: float
    angle: float = 0.0

    def __post_init__(self) -> None:
        _set(self, "x", _finite("pose x", self.x))
        _set(self, "y", _finite("pose y", self.y))
        _set(self, "angle", _finite("pose angle", self.angle))

    @cached_property
    def _turn(self) -> tuple[float, float]:
        return math.cos(self.angle), math.sin(self.angle)

    def apply(self, p: Point) -> Point:
        """Body coordinates to world coordinates."""
        c, s = self._turn
        return (self.x + c * p[0] - s * p[1], self.y + s * p[0] + c * p[1])


@dataclass(frozen=True)
class Contact:
    """A collision to highlight: where it happened and the unit normal (world coordinates),
    optionally which bodies (indices into the body list)."""

    point: Point
    normal: Point
    bodies: tuple[int, int] | None = None

    def __post_init__(self) -> None:
        _set(self, "point", _point("contact point", self.point))
        _set(self, "normal", _point("contact normal", self.normal))
        if self.bodies is not None:
            if len(self.bodies) != 2 or not all(isinstance(b, int) and b >= 0 for b in self.bodies):
                raise RenderModelError(f"contact bodies must be two indices, not {self.bodies!r}")
            _set(self, "bodies", tuple(self.bodies))


@dataclass(frozen=True)
class Frame:
    """The exact state at one instant: one pose per body (in body order), and the contacts
    since the previous frame (drawn as highlights; empty when nothing happened)."""

    time: float
    poses: tuple[Pose, ...]
    contacts: tuple[Contact, ...] = ()

    def __post_init__(self) -> None:
        _set(self, "time", _finite("frame time", self.time))
        _set(self, "poses", tuple(self.poses))
        _set(self, "contacts", tuple(self.contacts))
        if not all(isinstance(p, Pose) for p in self.poses):
            raise RenderModelError("frame poses must be Pose values")
        if not all(isinstance(c, Contact) for c in self.contacts):
            raise RenderModelError("frame contacts must be Contact values")


@dataclass(frozen=True)
class View:
    """The camera: the world rectangle [xmin, xmax] x [ymin, ymax] shown in a picture of
    width x height pixels. The scale is the same on both axes; the rectangle is centred and
    widened along one axis if its aspect differs from the picture's (nothing is stretched)."""

    xmin: float
    ymin: float
    xmax: float
    ymax: float
    width: int = 640
    height: int = 480
    background: str = "#ffffff"
    show_time: bool = True      # a time stamp in the top-left corner
    show_contacts: bool = True  # highlight the frame's contacts

    def __post_init__(self) -> None:
        for name in ("xmin", "ymin", "xmax", "ymax"):
            _set(self, name, _finite(name, getattr(self, name)))
        if not (self.xmax > self.xmin and self.ymax > self.ymin):
            raise RenderModelError("a view needs xmax > xmin and ymax > ymin")
        for name in ("width", "height"):
            v = getattr(self, name)
            if isinstance(v, bool) or not isinstance(v, int) or not 1 <= v <= 16384:
                raise RenderModelError(f"{name} must be a whole number of pixels in 1..16384, not {v!r}")
        _colour("background", self.background)

    @cached_property
    def scale(self) -> float:
        """Pixels per world unit. (Cached, as is _placing: a frozen view's fields never change,
        and an animation asks for them a few thousand times a frame.)"""
        return min(self.width / (self.xmax - self.xmin), self.height / (self.ymax - self.ymin))

    @cached_property
    def _placing(self) -> tuple[float, float, float, float, float]:
        """to_pixel's numbers: scale, the world centre, the picture's centre."""
        return (self.scale, (self.xmin + self.xmax) / 2, (self.ymin + self.ymax) / 2,
                self.width / 2, self.height / 2)

    def to_pixel(self, p: Point) -> Point:
        """World to pixel coordinates (origin top-left, y down; pixel centres at +0.5)."""
        s, cx, cy, px, py = self._placing
        return (px + (p[0] - cx) * s, py - (p[1] - cy) * s)
