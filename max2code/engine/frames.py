"""From a World to the pictures' data (max2code.render.model): bodies and exact frames.

Frames never touch the physics: the world is stepped to each frame time (processing the
events before it) and every pose is evaluated there exactly. The contacts of a frame are the
collisions since the previous frame, for highlighting.
"""

from __future__ import annotations

from collections.abc import Iterator

from ..render.model import Body, Contact, Frame, Pose, Style, shape_from_parts
from .world import BodyInfo, Event, World

PALETTE = ("#4c72b0", "#dd8452", "#55a868", "#c44e52", "#8172b3", "#937860", "#da8bc3",
           "#8c8c8c", "#ccb974", "#64b5cd")
STATIC = Style(fill="#9a9a9a", stroke="#3a3a3a", stroke_width=2.0, spoke=False)
KINEMATIC = "#e0a030"


def render_body(info: BodyInfo) -> Body:
    shape = shape_from_parts(info.shapes)
    if info.kind == "static":
        style = STATIC if info.color is None else Style(fill=info.color, stroke="#3a3a3a",
                                                        stroke_width=2.0, spoke=False)
    else:
        fill = info.color or (KINEMATIC if info.kind == "kinematic" else PALETTE[info.id % len(PALETTE)])
        style = Style(fill=fill)
    return Body(shape, style)


def render_bodies(world: World) -> list[Body]:
    return [render_body(b) for b in world.bodies]


def frame(world: World, t: float, events: list[Event] = ()) -> Frame:
    contacts = tuple(Contact(e.point, e.normal, (e.a, e.b)) for e in events
                     if e.kind == "collision")
    return Frame(t, tuple(Pose(x, y, a) for x, y, a in world.poses(t)), contacts)


def run_frames(world: World, until: float, fps: float, log: list[Event] | None = None,
               end_frame: bool = False) -> Iterator[Frame]:
    """Step the world to each frame time 0, 1/fps, ... <= until (and to `until` itself) and yield
    the frames; every event goes to `log` when given.  end_frame: a last frame at `until`
    itself when it is not a frame time (the state at T, for a single picture)."""
    k = 0
    while True:
        t = k / fps
        if t > until:
            break
        events = world.step_to(t)
        if log is not None:
            log.extend(events)
        yield frame(world, t, events)
        k += 1
    if world.time < until:
        events = world.step_to(until)
        if log is not None:
            log.extend(events)
        if end_frame:
            yield frame(world, until, events)
