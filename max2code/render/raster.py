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

An animation is drawn by a FrameDrawer, which gives the same pixels as frame_image (the tests
compare them byte for byte) at a fraction of the cost: the bodies at the front of the list that
stay put (static walls, resting bodies) are painted once into a cached layer, and only the
pixels painted over that layer are converted to bytes again (bench/render.py measures it).
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


@lru_cache(maxsize=1024)
def _rgb32(colour: str) -> np.ndarray:
    return np.array(rgba(colour)[:3], dtype=np.float32)


def check_frame(bodies: Sequence[Body], frame: Frame) -> None:
    if len(frame.poses) != len(bodies):
        raise RenderModelError(f"frame at t={frame.time} has {len(frame.poses)} poses "
                               f"for {len(bodies)} bodies")


def _clip01(x: np.ndarray) -> np.ndarray:
    """np.clip(x, 0, 1) (a new array): the same values, without np.clip's Python wrapper,
    which cost more than the arithmetic on a small shape's box."""
    y = np.maximum(x, 0)
    return np.minimum(y, 1, out=y)


Box = tuple[int, int, int, int]   # rows j0:j1, columns i0:i1 of a picture


def _to_bytes(rgb: np.ndarray) -> np.ndarray:
    return np.rint(_clip01(rgb) * 255).astype(np.uint8)


class Canvas:
    """An RGB picture in floats, painted shape by shape with coverage as alpha; `painted` keeps
    the pixel boxes (rows, columns) touched since it was made, so that only those need converting
    to bytes when the rest is known (FrameDrawer)."""

    def __init__(self, view: View, rgb: np.ndarray | None = None) -> None:
        """A fresh picture of the background, or one painting into `rgb` itself."""
        self.view = view
        self.painted: set[Box] = set()
        if rgb is not None:
            self.rgb = rgb
        else:
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
        a = rgba(colour)[3]
        alpha = coverage[..., None] if a == 1.0 else (coverage * np.float32(a))[..., None]
        region = self.rgb[rows, cols]
        region += alpha * (_rgb32(colour) - region)
        self.painted.add((rows.start, rows.stop, cols.start, cols.stop))

    def image(self) -> Image.Image:
        return Image.fromarray(_to_bytes(self.rgb), "RGB")


# --- signed distances in pixel space (negative inside) -----------------------------------------

def _segment_distance(x: np.ndarray, y: np.ndarray, a: Point, b: Point) -> np.ndarray:
    dx, dy = b[0] - a[0], b[1] - a[1]
    length2 = dx * dx + dy * dy
    t = _clip01(((x - a[0]) * dx + (y - a[1]) * dy) / length2) if length2 > 0 else 0.0
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
    return _clip01(0.5 - d)


def _stroke(d: np.ndarray, width: float) -> np.ndarray:
    return _clip01(np.minimum(width / 2 + 0.5 - np.abs(d), width))


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


def contrast(colour: str | None) -> str:
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
                     style.stroke or contrast(style.fill))


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


@lru_cache(maxsize=16)
def font(size: int) -> ImageFont.ImageFont | ImageFont.FreeTypeFont:
    """(cached: loading the font took longer than drawing a frame's shapes)"""
    return ImageFont.load_default(size=size)


def text_size(view: View) -> int:
    return max(10, round(min(view.width, view.height) / 32))


def _box(view: View, left: float, top: float, right: float, bottom: float) -> Box:
    """The pixels a Pillow box covers, two pixels of margin around it, clipped to the picture."""
    return (max(math.floor(top) - 2, 0), min(math.ceil(bottom) + 2, view.height),
            max(math.floor(left) - 2, 0), min(math.ceil(right) + 2, view.width))


def _text_items(bodies: Sequence[Body], frame: Frame, view: View) -> list[tuple]:
    """What draw_text writes: (anchor point, text, colour, anchor, white box behind it or None)."""
    size = text_size(view)
    label_font = font(size)
    items = []
    for body, pose in zip(bodies, frame.poses):
        if body.style.label:
            x, y = view.to_pixel((pose.x, pose.y))
            if -size <= x <= view.width + size and -size <= y <= view.height + size:
                items.append(((x, y), printable(body.style.label), contrast(body.style.fill),
                              "mm", None))
    if view.show_time:
        text = time_stamp(frame.time)
        left, top, right, bottom = label_font.getbbox(text, anchor="la")
        items.append(((6, 6), text, TEXT_COLOUR, "la",
                      (6 + left - 3, 6 + top - 3, 6 + right + 3, 6 + bottom + 3)))
    return items


def _draw_items(draw: ImageDraw.ImageDraw, items: list[tuple], size: int,
                offset: tuple[int, int] = (0, 0)) -> None:
    label_font = font(size)
    for (x, y), text, colour, anchor, box in items:
        if box is not None:
            draw.rectangle((box[0] - offset[0], box[1] - offset[1], box[2] - offset[0],
                            box[3] - offset[1]), fill="#ffffff")
        draw.text((x - offset[0], y - offset[1]), text, fill=colour, font=label_font, anchor=anchor)


def draw_text(image: Image.Image, bodies: Sequence[Body], frame: Frame, view: View) -> None:
    """Labels and the time stamp, drawn by Pillow."""
    _draw_items(ImageDraw.Draw(image), _text_items(bodies, frame, view), text_size(view))


def _draw_text_boxed(pixels: np.ndarray, bodies: Sequence[Body], frame: Frame, view: View) -> list[Box]:
    """draw_text into RGB bytes, each text on a crop of its own box only (the same pixels:
    whole-pixel offsets keep Pillow's fractional placement); returns the boxes."""
    size = text_size(view)
    label_font = font(size)
    boxes = []
    for item in _text_items(bodies, frame, view):
        (x, y), text, _, anchor, back = item
        left, top, right, bottom = label_font.getbbox(text, anchor=anchor)
        if back is not None:
            left, top, right, bottom = back[0] - x, back[1] - y, back[2] - x, back[3] - y
        j0, j1, i0, i1 = box = _box(view, x + left, y + top, x + right, y + bottom)
        if j0 >= j1 or i0 >= i1:
            continue
        crop = Image.fromarray(pixels[j0:j1, i0:i1], "RGB")
        _draw_items(ImageDraw.Draw(crop), [item], size, (i0, j0))
        pixels[j0:j1, i0:i1] = np.asarray(crop)
        boxes.append(box)
    return boxes


def _draw_contacts(canvas: Canvas, frame: Frame) -> None:
    view = canvas.view
    if view.show_contacts:
        size = max(3.0, min(view.width, view.height) / 100)
        for contact in frame.contacts:
            draw_contact(canvas, contact, size)


def frame_image(bodies: Sequence[Body], frame: Frame, view: View) -> Image.Image:
    """The picture of one frame: bodies in their order (later ones on top), contacts, text."""
    check_frame(bodies, frame)
    canvas = Canvas(view)
    for body, pose in zip(bodies, frame.poses):
        draw_body(canvas, body, pose)
    _draw_contacts(canvas, frame)
    image = canvas.image()
    draw_text(image, bodies, frame, view)
    return image


def scene_colours(bodies: Sequence[Body], view: View) -> list[str]:
    """The colours a frame is painted with before blending: background, fills, strokes, the
    spokes' and labels' contrast colours, contacts, text and its box (a GIF palette keeps them
    exactly)."""
    out = [view.background, TEXT_COLOUR, "#ffffff", CONTACT_COLOUR]
    for body in bodies:
        style = body.style
        out += [c for c in (style.fill, style.stroke, contrast(style.fill)) if c is not None]
    return out


def _common_prefix(a: Sequence, b: Sequence) -> int:
    n = 0
    for x, y in zip(a, b):
        if x != y:
            break
        n += 1
    return n


class FrameDrawer:
    """The frames of one animation, each the same pixels as frame_image's, faster.

    Painting is in order (later bodies over earlier ones), so what can be kept from frame to
    frame is a prefix: the leading bodies whose poses did not change since the previous frame
    are painted once into a layer (floats, and their bytes). A frame paints the other bodies
    into a working copy of the layer, after putting back the layer's pixels where the previous
    frame painted: the cost follows the area painted, not the picture's. A body of that prefix
    that moves later makes the layer be painted again, shorter: never a wrong picture, at worst
    the cost of frame_image.

    `changed` says where the last image may differ from the one before (None: anywhere), so a
    GIF palette maps only those pixels again (palette.Mapper)."""

    def __init__(self, bodies: Sequence[Body], view: View) -> None:
        self.bodies = list(bodies)
        self.view = view
        self.previous: tuple | None = None
        self.layers_painted = 0
        self._paint_layer(())
        self.changed: list[Box] | None = None
        self._painted: set[Box] = set()      # the working copy's pixels that are not the layer's

    def _paint_layer(self, poses: tuple) -> None:
        canvas = Canvas(self.view)
        for body, pose in zip(self.bodies, poses):
            draw_body(canvas, body, pose)
        self.layer_poses, self.layer = poses, canvas.rgb
        self.layer_bytes = _to_bytes(canvas.rgb)
        self.work, self.work_bytes = self.layer.copy(), self.layer_bytes.copy()
        self._painted = set()
        self.layers_painted += 1

    def pixels(self, frame: Frame) -> np.ndarray:
        """The frame's RGB bytes (height x width x 3): a buffer of the drawer's own, valid
        until the next call (copy it to keep it)."""
        check_frame(self.bodies, frame)
        poses = tuple(frame.poses)
        still = _common_prefix(poses, self.previous) if self.previous is not None else 0
        first = self.previous is None
        self.previous = poses
        kept = len(self.layer_poses)
        rebuilt = poses[:kept] != self.layer_poses or still > kept
        if rebuilt:
            self._paint_layer(poses[:still])
            kept = still
        restored = self._painted
        for j0, j1, i0, i1 in restored:
            self.work[j0:j1, i0:i1] = self.layer[j0:j1, i0:i1]
            self.work_bytes[j0:j1, i0:i1] = self.layer_bytes[j0:j1, i0:i1]
        canvas = Canvas(self.view, self.work)
        for body, pose in zip(self.bodies[kept:], poses[kept:]):
            draw_body(canvas, body, pose)
        _draw_contacts(canvas, frame)
        for j0, j1, i0, i1 in canvas.painted:
            self.work_bytes[j0:j1, i0:i1] = _to_bytes(self.work[j0:j1, i0:i1])
        text = _draw_text_boxed(self.work_bytes, self.bodies, frame, self.view)
        # (text is in the bytes only: put back like paint, where the floats are the layer's)
        self._painted = canvas.painted | set(text)
        self.changed = None if rebuilt or first else [*restored, *self._painted]
        return self.work_bytes

    def image(self, frame: Frame) -> Image.Image:
        return Image.fromarray(self.pixels(frame), "RGB")
