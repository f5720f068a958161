"""A camera that shows everything: the world rectangle covered by bodies over a run of frames."""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from typing import Any

from .model import Body, Capsule, Circle, Compound, Frame, Polygon, Pose, RenderModelError, Segment, Shape, View


# The points a shape's extent is taken over and the radius around them, per kind of shape
# (one table, as the rasteriser's OUTLINES: a new shape kind is one line here).
EXTENT_POINTS: dict[type, Callable[[Any], tuple[Sequence[tuple[float, float]], float]]] = {
    Circle: lambda s: ((s.centre,), s.radius),
    Polygon: lambda s: (s.vertices, s.radius),
    Capsule: lambda s: ((s.a, s.b), s.radius),
    Segment: lambda s: ((s.a, s.b), 0.0),
}


def world_extent(shape: Shape, pose: Pose) -> tuple[float, float, float, float]:
    """(xmin, ymin, xmax, ymax) of a shape at a pose, exact for every shape kind (a compound:
    the box around its parts')."""
    if isinstance(shape, Compound):
        boxes = [world_extent(p, pose) for p in shape.parts]
        return (min(b[0] for b in boxes), min(b[1] for b in boxes),
                max(b[2] for b in boxes), max(b[3] for b in boxes))
    points = EXTENT_POINTS.get(type(shape))
    if points is None:
        raise RenderModelError(f"unknown shape {type(shape).__name__}")
    local, pad = points(shape)
    pts = [pose.apply(v) for v in local]
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    return (min(xs) - pad, min(ys) - pad, max(xs) + pad, max(ys) + pad)


def fit_view(bodies: Sequence[Body], frames: Iterable[Frame], width: int = 640, height: int = 480,
             margin: float = 0.05, **options: object) -> View:
    """The smallest view holding every body in every frame, widened by `margin` (a fraction of
    the larger side) so outlines are not cut at the border. `options` go to View."""
    box = [float("inf"), float("inf"), float("-inf"), float("-inf")]
    for frame in frames:
        if len(frame.poses) != len(bodies):
            raise RenderModelError(f"frame at t={frame.time} has {len(frame.poses)} poses "
                                   f"for {len(bodies)} bodies")
        for body, pose in zip(bodies, frame.poses):
            e = world_extent(body.shape, pose)
            box = [min(box[0], e[0]), min(box[1], e[1]), max(box[2], e[2]), max(box[3], e[3])]
    if box[0] == float("inf"):
        raise RenderModelError("no frames to fit a view to")
    side = max(box[2] - box[0], box[3] - box[1], 1e-9)
    pad = margin * side
    return View(box[0] - pad, box[1] - pad, box[2] + pad, box[3] + pad, width, height, **options)
