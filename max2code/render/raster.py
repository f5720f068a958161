"""One frame as pixels, with edges anti-aliased from the exact geometry.

Each shape is drawn from its signed distance d (in pixels) at every pixel centre: a fill covers a
pixel by clip(0.5 - d, 0, 1), a stroke of width w by clip(w/2 + 0.5 - |d|, 0, 1). That is the
area of the pixel inside a straight edge through it (exact for an edge parallel to an axis,
within a few percent otherwise), so an edge lands where the geometry puts it, to a fraction of a
pixel, at any zoom: no rounding of coordinates to whole pixels (which Pillow's own drawing
does) and no supersampling. Pixels more than half a pixel inside a shape are exactly its
colour; more than half a pixel outside, untouched; the tests rely on that.

numpy does the geometry over each shape's bounding box only; Pillow draws the text (labels,
time stamp) on top. Both come with `pip install 'max2code[render]'`.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from functools import lru_cache

import numpy as np
from PIL import Image, ImageDraw, ImageFont

from .model import Body, Capsule, Circle, Contact, Frame, Point, Polygon, RenderModelError, Segment, View
from .text import printable, time_stamp

CONTACT_COLOUR = "#d62728"
TEXT_COLOUR = "#000000"


@lru_cache(maxsize=1024)
def rgba(colour: str) -> tuple[float, float, float, float]:
    """'#rrggbb[aa]' (checked by the model) to floats in 0..1."""
    v = [int(colour[i:i + 2], 16) / 255 for i in range(1, len(colour), 2)]
    return (v[0], v[1], v[2], v[3] if len(v) == 4 else 1.0)


def check_frame(bodies: Sequence[Body], frame: Frame) -> None:
    if len(frame.poses) != len(bodies):
        raise RenderModelError(f"frame at t={frame.time} has {len(frame.poses)} poses "
                               f"for {len(bodies)} bodies")


class Canvas:
    """An RGB picture in floats, painted shape by shape with coverage as alpha."""

    def __init__(self, view: View) -> None:
        self.view = view
        self.rgb = np.empty((view.height, view.width, 3), dtype=np.float32)
        self.rgb[:] = rgba(view.background)[:3]

    def grid(self, box: tuple[float, float, float, float]) -> tuple[slice, slice, np.ndarray, np.ndarray] | None:
        """Pixel centres of the pixels a pixel-space box (x0, y0, x1, y1) touches, or None."""
        i0 = max(int(math.floor(box[0])), 0)
        j0 = max(int(math.floor(box[1])), 0)
        i1 = min(int(math.ceil(box[2])), self.view.width)
        j1 = min(int(math.ceil(box[3])), self.view.height)
        if i0 >= i1 or j0 >= j1:
            return None
        xs = np.arange(i0, i1, dtype=np.float32) + np.float32(0.5)
        ys = np.arange(j0, j1, dtype=np.float32) + np.float32(0.5)
        return slice(j0, j1), slice(i0, i1), xs[None, :], ys[:, None]

    def paint(self, rows: slice, cols: slice, coverage: np.ndarray, colour: str) -> None:
        """Blend `colour` over the region by coverage x the colour's alpha."""
        r, g, b, a = rgba(colour)
        alpha = coverage[..., None] if a == 1.0 else (coverage * np.float32(a))[..., None]
        region = self.rgb[rows, cols]
        region += alpha * (np.array((r, g, b), dtype=np.float32) - region)

    def image(self) -> Image.Image:
        return Image.fromarray(np.rint(np.clip(self.rgb, 0, 1) * 255).astype(np.uint8), "RGB")


# --- signed distances in pixel space (negative inside) -----------------------------------------

def _segment_distance(x: np.ndarray, y: np.ndarray, a: Point, b: Point) -> np.ndarray:
    dx, dy = b[0] - a[0], b[1] - a[1]
    length2 = dx * dx + dy * dy
    t = np.clip(((x - a[0]) * dx + (y - a[1]) * dy) / length2, 0.0, 1.0) if length2 > 0 else 0.0
    return np.hypot(x - (a[0] + t * dx), y - (a[1] + t * dy))


def _polygon_distance(x: np.ndarray, y: np.ndarray, pts: Sequence[Point]) -> np.ndarray:
    """Exact signed distance to a convex polygon: the distance to the nearest edge, negative where
    the point is on the inner side of every edge."""
    area2 = sum(pts[i - 1][0] * pts[i][1] - pts[i][0] * pts[i - 1][1] for i in range(len(pts)))
    orient = 1.0 if area2 > 0 else -1.0
    nearest = None
    inside = None
    for i in range(len(pts)):
        a, b = pts[i], pts[(i + 1) % len(pts)]
        d = _segment_distance(x, y, a, b)
        nearest = d if nearest is None else np.minimum(nearest, d)
        side = orient * ((b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])) >= 0
        inside = side if inside is None else inside & side
    return np.where(inside, -nearest, nearest)


def _fill(d: np.ndarray) -> np.ndarray:
    return np.clip(0.5 - d, 0.0, 1.0)


def _stroke(d: np.ndarray, width: float) -> np.ndarray:
    return np.clip(np.minimum(width / 2 + 0.5 - np.abs(d), width), 0.0, 1.0)


class _Outline:
    """One shape placed in pixel space: its bounding box and its signed distance function."""

    def __init__(self, shape: object, pose_apply, view: View) -> None:
        s = view.scale
        px = lambda p: view.to_pixel(pose_apply(p))  # noqa: E731
        self.area = True
        if isinstance(shape, Circle):
            c, r = px(shape.centre), shape.radius * s
            self.box = (c[0] - r, c[1] - r, c[0] + r, c[1] + r)
            self.distance = lambda x, y: np.hypot(x - c[0], y - c[1]) - r
        elif isinstance(shape, Polygon):
            pts = [px(v) for v in shape.vertices]
            r = shape.radius * s
            self.box = (min(p[0] for p in pts) - r, min(p[1] for p in pts) - r,
                        max(p[0] for p in pts) + r, max(p[1] for p in pts) + r)
            self.distance = lambda x, y: _polygon_distance(x, y, pts) - r
        elif isinstance(shape, (Capsule, Segment)):
            a, b = px(shape.a), px(shape.b)
            r = shape.radius * s if isinstance(shape, Capsule) else 0.0
            self.area = isinstance(shape, Capsule)
            self.box = (min(a[0], b[0]) - r, min(a[1], b[1]) - r, max(a[0], b[0]) + r, max(a[1], b[1]) + r)
            self.distance = lambda x, y: _segment_distance(x, y, a, b) - r
        else:
            raise RenderModelError(f"unknown shape {type(shape).__name__}")


def _line(canvas: Canvas, a: Point, b: Point, width: float, colour: str) -> None:
    pad = width / 2 + 1
    g = canvas.grid((min(a[0], b[0]) - pad, min(a[1], b[1]) - pad, max(a[0], b[0]) + pad, max(a[1], b[1]) + pad))
    if g:
        rows, cols, x, y = g
        canvas.paint(rows, cols, _stroke(_segment_distance(x, y, a, b), width), colour)


def _contrast(colour: str | None) -> str:
    """A spoke colour visible on the fill: black on light fills, white on dark ones."""
    if colour is None:
        return "#000000"
    r, g, b, _ = rgba(colour)
    return "#000000" if 0.299 * r + 0.587 * g + 0.114 * b > 0.5 else "#ffffff"


def draw_body(canvas: Canvas, body: Body, pose) -> None:
    view, style, shape = canvas.view, body.style, body.shape
    outline = _Outline(shape, pose.apply, view)
    width = style.stroke_width
    if not outline.area:  # a segment has no inside: its stroke is the whole picture of it
        width = max(width, 1.0)
    pad = width / 2 + 1
    g = canvas.grid((outline.box[0] - pad, outline.box[1] - pad, outline.box[2] + pad, outline.box[3] + pad))
    if g is None:
        return
    rows, cols, x, y = g
    d = outline.distance(x, y)
    if outline.area and style.fill is not None:
        canvas.paint(rows, cols, _fill(d), style.fill)
    line_colour = style.stroke if style.stroke is not None else (None if outline.area else style.fill)
    if line_colour is not None and width > 0:
        canvas.paint(rows, cols, _stroke(d, width), line_colour)
    if isinstance(shape, Circle) and style.spoke:   # the spoke lies inside the circle's box
        centre = view.to_pixel(pose.apply(shape.centre))
        rim = view.to_pixel(pose.apply((shape.centre[0] + shape.radius, shape.centre[1])))
        canvas.paint(rows, cols, _stroke(_segment_distance(x, y, centre, rim), max(width, 1.0)),
                     style.stroke or _contrast(style.fill))


def draw_contact(canvas: Canvas, contact: Contact, size: float) -> None:
    """A ring at the contact point and the normal as a short line from it."""
    p = canvas.view.to_pixel(contact.point)
    g = canvas.grid((p[0] - size - 2, p[1] - size - 2, p[0] + size + 2, p[1] + size + 2))
    if g:
        rows, cols, x, y = g
        canvas.paint(rows, cols, _stroke(np.hypot(x - p[0], y - p[1]) - size, 1.5), CONTACT_COLOUR)
    n = math.hypot(*contact.normal)
    if n > 0:
        q = (p[0] + 2.5 * size * contact.normal[0] / n, p[1] - 2.5 * size * contact.normal[1] / n)
        _line(canvas, p, q, 1.5, CONTACT_COLOUR)


def font(size: int) -> ImageFont.ImageFont | ImageFont.FreeTypeFont:
    return ImageFont.load_default(size=size)


def _text_size(view: View) -> int:
    return max(10, round(min(view.width, view.height) / 32))


def draw_text(image: Image.Image, bodies: Sequence[Body], frame: Frame, view: View) -> None:
    draw = ImageDraw.Draw(image)
    size = _text_size(view)
    label_font = font(size)
    for body, pose in zip(bodies, frame.poses):
        if body.style.label:
            x, y = view.to_pixel((pose.x, pose.y))
            if -size <= x <= view.width + size and -size <= y <= view.height + size:
                draw.text((x, y), printable(body.style.label), fill=_contrast(body.style.fill),
                          font=label_font, anchor="mm")
    if view.show_time:
        text = time_stamp(frame.time)
        left, top, right, bottom = draw.textbbox((6, 6), text, font=label_font)
        draw.rectangle((left - 3, top - 3, right + 3, bottom + 3), fill="#ffffff")
        draw.text((6, 6), text, fill=TEXT_COLOUR, font=label_font)


def frame_image(bodies: Sequence[Body], frame: Frame, view: View) -> Image.Image:
    """The picture of one frame: bodies in their order (later ones on top), contacts, text."""
    check_frame(bodies, frame)
    canvas = Canvas(view)
    for body, pose in zip(bodies, frame.poses):
        draw_body(canvas, body, pose)
    if view.show_contacts:
        size = max(3.0, min(view.width, view.height) / 100)
        for contact in frame.contacts:
            draw_contact(canvas, contact, size)
    image = canvas.image()
    draw_text(image, bodies, frame, view)
    return image
