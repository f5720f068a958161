"""A World as the client sees it: shapes and styles once, motion segments at events.

Shapes and styles are max2code.render's (engine.frames.render_body), so the page draws what
`max2code sim --png` draws. A segment is the body's exact motion from a time t on:

    [id, x, y, angle, vx, vy, omega, ax, ay, alpha, jx, jy, ja]
    pose(t') = (x, y) + v s + a s^2/2 + (jx, jy) s^3/6, angle + omega s + alpha s^2/2 + ja s^3/6

with s = t' - t, and trailing zeros left off (a body at rest is [id, x, y, angle], a body
that neither turns nor accelerates [id, x, y, angle, vx, vy]). Every segment of one message is
given at the message's time, so no segment carries a time of its own. alpha (protocol version
5) and the jerks jx, jy, ja (version 6) are only ever sent for a body the contact solver holds
(reckon.fitted's quadratic and cubic): the core's motions have neither.

A body falling with the room's gravity g (the `world` message's `g`) has its segment in the
message's `fall` list instead, without the acceleration: `[id, x, y, angle, vx, vy, omega]`,
trailing zeros left off, meaning (ax, ay) = g. Why (protocol version 4): in a falling scene
most segments end in g's two numbers, some 10 of their 65 bytes; `split` and `expanded` are
the two directions, and a client that reads both lists holds exactly the segments as before. Numbers have
protocol.NUMBER_DIGITS significant digits, and magnitudes below Zero's (1e-12 of the view's
width, or 1e-12 radians) are sent as 0.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..engine.frames import render_body
from ..engine.world import World
from ..render.model import Capsule, Circle, Compound, Polygon, Segment
from . import reckon
from .protocol import number

Motion = tuple[float, ...]   # the core's (t0, x, y, angle, vx, vy, omega, ax, ay)
ZERO_RELATIVE = 1e-12


@dataclass(frozen=True)
class Zero:
    """Magnitudes sent as 0: lengths (x, y, and their rates) below `length`, angles (and
    omega) below `angle`. Why: the engine's rounding leaves noise such as an angle of -1.2e-15
    or an omega of 5e-17 in bodies at rest or sliding; each costs some 15 characters and is
    worth nothing drawn (1e-12 of the view is 1e-9 of a pixel), and once 0 a trailing one is
    left off. Over a segment's life the error stays that small times the seconds it lasts."""
    length: float = 0.0
    angle: float = 0.0

    @classmethod
    def of(cls, view) -> "Zero":
        """For a view (xmin, ymin, xmax, ymax): ZERO_RELATIVE of its larger side, and radians."""
        side = max(abs(view[2] - view[0]), abs(view[3] - view[1]))
        return cls(ZERO_RELATIVE * side if side < float("inf") else 0.0, ZERO_RELATIVE)

    def limits(self) -> tuple[float, ...]:
        """Per value of a segment (x, y, angle, vx, vy, omega, ax, ay, alpha, jx, jy, ja)."""
        a, l_ = self.angle, self.length
        return (l_, l_, a, l_, l_, a, l_, l_, a, l_, l_, a)


def shape(shape_) -> dict:
    """The render model's shape as JSON: circle {c, r}, polygon {p, r}, segment {s}, capsule {s, r},
    compound {parts: [shape, ...]}."""
    kinds = {
        Circle: lambda s: {"c": [number(v) for v in s.centre], "r": number(s.radius)},
        Polygon: lambda s: {"p": [[number(x), number(y)] for x, y in s.vertices],
                            "r": number(s.radius)},
        Segment: lambda s: {"s": [[number(x), number(y)] for x, y in (s.a, s.b)]},
        Capsule: lambda s: {"s": [[number(x), number(y)] for x, y in (s.a, s.b)],
                            "r": number(s.radius)},
        Compound: lambda s: {"parts": [shape(p) for p in s.parts]},
    }
    return kinds[type(shape_)](shape_)


def body(world: World, i: int) -> dict:
    """What the page needs to draw body i: its shape, style and name."""
    info = world.bodies[i]
    drawn = render_body(info)
    st = drawn.style
    return {"id": i, "name": info.name, "kind": info.kind, "shape": shape(drawn.shape),
            "fill": st.fill, "stroke": st.stroke, "sw": number(st.stroke_width), "spoke": st.spoke}


def at(m: Motion, t: float) -> tuple[float, ...]:
    """The motion (from its own time m[0]) re-expressed from time t >= m[0]: the same formula
    the core evaluates (motion.c), so the client's pose is the engine's to rounding."""
    t0, x, y, th, vx, vy, w, ax, ay = m[:9]
    al = m[9] if len(m) > 9 else 0.0      # (the core's motions have no angular acceleration,
    jx, jy, ja = (tuple(m[10:13]) + (0.0, 0.0, 0.0))[:3]   # nor jerks: a held body's cubic)
    s = t - t0
    if s == 0:
        return (x, y, th, vx, vy, w, ax, ay, al, jx, jy, ja)
    if al or jx or jy or ja:
        return reckon.state_at(m, t)      # a held body's quadratic or cubic: reckon's one formula
    return (x + s * (vx + 0.5 * ax * s), y + s * (vy + 0.5 * ay * s), th + w * s if w else th,
            vx + ax * s, vy + ay * s, w, ax, ay, al, 0.0, 0.0, 0.0)


def _trimmed(i: int, values: list) -> list:
    """Body i's segment of `values`, trailing zeros left off (x, y and angle always kept): the
    one form every segment is sent in, so equal motions are equal lists."""
    values = list(values)
    while len(values) > 3 and values[-1] == 0:
        values.pop()
    return [i] + values


def segment(i: int, m: Motion, t: float, zero: Zero = Zero()) -> list:
    """Body i's segment from time t, trailing zeros left off (and values below `zero` 0)."""
    return _trimmed(i, [0 if abs(v) < z else number(v) for v, z in zip(at(m, t), zero.limits())])


def split(segs: list[list], g: tuple) -> tuple[list[list], list[list]]:
    """Segments (as `segment` makes them) into the message's `seg` and `fall` lists: those
    whose acceleration is g exactly (as sent) go to `fall` without it. g is the room's gravity
    as sent (numbers); with g = (0, 0) nothing is split off (trailing zeros are left off already)."""
    g = list(g)
    if g == [0, 0]:
        return segs, []
    explicit, fall = [], []
    for seg in segs:
        full = (list(seg) + [0] * 13)[:13]
        if full[7:9] != g or any(full[9:]):
            explicit.append(seg)
            continue
        fall.append(_trimmed(seg[0], full[1:7]))
    return explicit, fall


def expanded(message: dict, g: tuple) -> list[list]:
    """A message's segments as `segment` made them: its `seg`, then its `fall` given g's
    acceleration back (g: the `world` message's `g`, default (0, 0))."""
    out = list(message.get("seg", []))
    for seg in message.get("fall", []):   # (trimmed again: g = (1, 0) ends in a zero)
        out.append(_trimmed(seg[0], (list(seg[1:]) + [0] * 6)[:6] + list(g)))
    return out


def pose(seg: list, t: float, t_seg: float) -> tuple[float, float, float]:
    """What the page computes from a segment (client.js poseAt), for tests and the bench."""
    x, y, th, vx, vy, w, ax, ay, al, jx, jy, ja = (list(seg[1:]) + [0.0] * 12)[:12]
    s = t - t_seg
    return (x + s * (vx + s * (0.5 * ax + jx * s / 6)), y + s * (vy + s * (0.5 * ay + jy * s / 6)),
            th + s * (w + s * (0.5 * al + ja * s / 6)))


def motion(seg: list, t: float) -> tuple[float, ...]:
    """A sent segment (from time t) back as the core's motion tuple: what a client holds."""
    return (t,) + tuple((list(seg[1:]) + [0.0] * 12)[:12])
