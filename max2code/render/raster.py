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
from collections.abc import Callable, Sequence
from dataclasses import dataclass
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
    """Planar floats (3, rows, columns) to RGB bytes (rows, columns, 3) (a view: assign or copy)."""
    return np.rint(_clip01(rgb) * 255).astype(np.uint8).transpose(1, 2, 0)


class Canvas:
    """An RGB picture in floats, painted shape by shape with coverage as alpha; `painted` keeps
    the pixel boxes (rows, columns) touched since it was made, so that only those need converting
    to bytes when the rest is known (FrameDrawer).

    `rgb` is planar, (3, rows, columns): numpy's loops run along the last axis, and a blend over
    (rows, columns, 3) ran them three values long, which made painting three times slower."""

    def __init__(self, view: View, rgb: np.ndarray | None = None) -> None:
        """A fresh picture of the background, or one painting into `rgb` itself."""
        self.view = view
        self.painted: set[Box] = set()
        if rgb is not None:
            self.rgb = rgb
        else:
            self.rgb = np.empty((3, view.height, view.width), dtype=np.float32)
            self.rgb[:] = _rgb32(view.background)[:, None, None]

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
        alpha = coverage if a == 1.0 else coverage * np.float32(a)
        region = self.rgb[:, rows, cols]
        region += alpha * (_rgb32(colour)[:, None, None] - region)
        self.painted.add((rows.start, rows.stop, cols.start, cols.stop))

    def image(self) -> Image.Image:
        return Image.fromarray(np.ascontiguousarray(_to_bytes(self.rgb)), "RGB")


# --- signed distances in pixel space (negative inside) -----------------------------------------

def _norm(dx: np.ndarray, dy: np.ndarray) -> np.ndarray:
    """np.hypot(dx, dy), which took twice as long (no overflow guard is needed: pixels)."""
    return np.sqrt(dx * dx + dy * dy)


def _segment_distance(x: np.ndarray, y: np.ndarray, a: Point, b: Point) -> np.ndarray:
    dx, dy = b[0] - a[0], b[1] - a[1]
    length2 = dx * dx + dy * dy
    t = _clip01(((x - a[0]) * dx + (y - a[1]) * dy) / length2) if length2 > 0 else 0.0
    return _norm(x - (a[0] + t * dx), y - (a[1] + t * dy))


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


Distance = Callable[[np.ndarray, np.ndarray], np.ndarray]
ToPixel = Callable[[Point], Point]


@dataclass(frozen=True)
class Outline:
    """One shape placed in pixel space: its bounding box (x0, y0, x1, y1), its signed distance,
    whether it has an inside (a segment has none), and the spoke that shows a circle's turn."""
    box: tuple[float, float, float, float]
    distance: Distance
    area: bool = True
    spoke: tuple[Point, Point] | None = None


def _box_around(points: Sequence[Point], r: float) -> tuple[float, float, float, float]:
    return (min(p[0] for p in points) - r, min(p[1] for p in points) - r,
            max(p[0] for p in points) + r, max(p[1] for p in points) + r)


def _circle(shape: Circle, px: ToPixel, scale: float) -> Outline:
    c, r = px(shape.centre), shape.radius * scale
    rim = px((shape.centre[0] + shape.radius, shape.centre[1]))
    return Outline(_box_around([c], r), lambda x, y: _norm(x - c[0], y - c[1]) - r, spoke=(c, rim))


def _polygon(shape: Polygon, px: ToPixel, scale: float) -> Outline:
    pts, r = [px(v) for v in shape.vertices], shape.radius * scale
    return Outline(_box_around(pts, r), lambda x, y: _polygon_distance(x, y, pts) - r)


def _capsule(shape: Capsule, px: ToPixel, scale: float) -> Outline:
    a, b, r = px(shape.a), px(shape.b), shape.radius * scale
    return Outline(_box_around([a, b], r), lambda x, y: _segment_distance(x, y, a, b) - r)


def _segment(shape: Segment, px: ToPixel, scale: float) -> Outline:
    a, b = px(shape.a), px(shape.b)
    return Outline(_box_around([a, b], 0.0), lambda x, y: _segment_distance(x, y, a, b), area=False)


OUTLINES: dict[type, Callable[[object, ToPixel, float], Outline]] = {
    Circle: _circle, Polygon: _polygon, Capsule: _capsule, Segment: _segment}


def outline(shape: object, pose_apply: ToPixel, view: View) -> Outline:
    """The shape at a pose, in the view's pixels (OUTLINES: one function per kind of shape)."""
    make = OUTLINES.get(type(shape))
    if make is None:
        raise RenderModelError(f"unknown shape {type(shape).__name__}")
    return make(shape, lambda p: view.to_pixel(pose_apply(p)), view.scale)


def contrast(colour: str | None) -> str:
    """A spoke colour visible on the fill: black on light fills, white on dark ones."""
    if colour is None:
        return "#000000"
    r, g, b, _ = rgba(colour)
    return "#000000" if 0.299 * r + 0.587 * g + 0.114 * b > 0.5 else "#ffffff"


def draw_body(canvas: Canvas, body: Body, pose) -> None:
    style = body.style
    shape = outline(body.shape, pose.apply, canvas.view)
    width = style.stroke_width
    if not shape.area:  # a segment has no inside: its stroke is the whole picture of it
        width = max(width, 1.0)
    pad = width / 2 + 1
    g = canvas.grid((shape.box[0] - pad, shape.box[1] - pad, shape.box[2] + pad, shape.box[3] + pad))
    if g is None:
        return
    rows, cols, x, y = g
    d = shape.distance(x, y)
    if shape.area and style.fill is not None:
        canvas.paint(rows, cols, _fill(d), style.fill)
    line_colour = style.stroke if style.stroke is not None else (None if shape.area else style.fill)
    if line_colour is not None and width > 0:
        canvas.paint(rows, cols, _stroke(d, width), line_colour)
    if shape.spoke is not None and style.spoke:   # (it lies inside the circle's box)
        canvas.paint(rows, cols, _stroke(_segment_distance(x, y, *shape.spoke), max(width, 1.0)),
                     style.stroke or contrast(style.fill))


def draw_contact(canvas: Canvas, contact: Contact, size: float) -> None:
    """A ring at the contact point and the normal as a short line from it."""
    draw_contacts(canvas, [contact], size)


CONTACT_WIDTH = 1.5   # pixels, of the ring and of the normal's line
CONTACT_REACH = 2.5   # the normal's line, in ring radii


def draw_contacts(canvas: Canvas, contacts: Sequence[Contact], size: float) -> None:
    """Each contact as a ring of radius `size` at its point and its normal as a line from it,
    all contacts at once: every one is a patch of the same size around its point, so numpy
    computes their distances in one (contacts x rows x columns) array. One opaque colour
    blended over and over in any order leaves 1 - prod(1 - coverage) of it, so the patches are
    merged by multiplying what each leaves uncovered (np.multiply.at), then painted once, in
    tiles of a patch's size (only those that a patch touches: contacts far apart do not paint
    the picture between them). (A pile of 40 bodies has 120 contacts a frame: one at a time,
    they cost 80% of it.)"""
    view = canvas.view
    reach = math.ceil(CONTACT_REACH * size + CONTACT_WIDTH / 2 + 1.5)
    side = 2 * reach + 1
    points = np.array([view.to_pixel(c.point) for c in contacts], dtype=np.float64).reshape(-1, 2)
    normals = np.array([c.normal for c in contacts], dtype=np.float64).reshape(-1, 2)
    near = ((points[:, 0] > -reach) & (points[:, 0] < view.width + reach)
            & (points[:, 1] > -reach) & (points[:, 1] < view.height + reach))
    if not near.any():
        return
    points, normals = points[near], normals[near]
    length = np.sqrt((normals * normals).sum(axis=1))
    unit = np.divide(normals, length[:, None], out=np.zeros_like(normals), where=length[:, None] > 0)
    corner = np.floor(points).astype(np.int64) - reach                      # patches' (i0, j0)
    steps = np.arange(side)
    # (float32 from here, relative to each patch's corner: small numbers, exact enough)
    p = (points - corner).astype(np.float32)[:, :, None, None]
    d = (CONTACT_REACH * size * unit * np.array([1.0, -1.0])).astype(np.float32)[:, :, None, None]
    x = (steps.astype(np.float32) + np.float32(0.5))[None, None, :]
    y = x.reshape(1, side, 1)
    rx, ry = x - p[:, 0], y - p[:, 1]
    ring = _stroke(_norm(rx, ry) - np.float32(size), CONTACT_WIDTH)
    dx, dy = d[:, 0], d[:, 1]
    length2 = np.maximum(dx * dx + dy * dy, np.float32(1e-30))
    t = _clip01((rx * dx + ry * dy) / length2)
    line = _stroke(_norm(rx - t * dx, ry - t * dy), CONTACT_WIDTH)
    line *= (length > 0).astype(np.float32)[:, None, None]
    left = (1 - ring) * (1 - line)
    j0, i0 = corner[:, 1].min(), corner[:, 0].min()
    h, w = corner[:, 1].max() - j0 + side, corner[:, 0].max() - i0 + side
    flat = ((corner[:, 1, None, None] - j0 + steps[None, :, None]) * w
            + (corner[:, 0, None, None] - i0 + steps[None, None, :]))
    uncovered = np.ones(h * w, dtype=np.float32)
    np.multiply.at(uncovered, flat.ravel(), left.ravel())
    uncovered = uncovered.reshape(h, w)
    # (a patch meets at most 2 x 2 tiles: its first and last rows' and columns')
    rows = np.stack([corner[:, 1] // side, (corner[:, 1] + side - 1) // side], axis=1)
    cols = np.stack([corner[:, 0] // side, (corner[:, 0] + side - 1) // side], axis=1)
    pairs = np.stack([np.repeat(rows, 2, axis=1), np.tile(cols, 2)], axis=2).reshape(-1, 2)
    tiles = [(int(a), int(b)) for a, b in np.unique(pairs, axis=0)]
    j0, i0, h, w = int(j0), int(i0), int(h), int(w)
    for tj, first, last in _runs(tiles):   # (each run of tiles side by side is one paint)
        r0, r1 = max(tj * side, 0, j0), min((tj + 1) * side, view.height, j0 + h)
        c0, c1 = max(first * side, 0, i0), min((last + 1) * side, view.width, i0 + w)
        if r0 < r1 and c0 < c1:
            canvas.paint(slice(r0, r1), slice(c0, c1),
                         1 - uncovered[r0 - j0:r1 - j0, c0 - i0:c1 - i0], CONTACT_COLOUR)


def _runs(tiles: list[tuple[int, int]]) -> list[tuple[int, int, int]]:
    """Sorted (row, column) tiles as (row, first column, last column) runs of neighbours."""
    runs: list[list[int]] = []
    for row, col in tiles:
        if runs and runs[-1][0] == row and runs[-1][2] == col - 1:
            runs[-1][2] = col
        else:
            runs.append([row, col, col])
    return [(r, a, b) for r, a, b in runs]


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
        if back is not None:   # (the text lies inside its box: no second measuring)
            left, top, right, bottom = back[0] - x, back[1] - y, back[2] - x, back[3] - y
        else:
            left, top, right, bottom = label_font.getbbox(text, anchor=anchor)
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
        draw_contacts(canvas, frame.contacts, max(3.0, min(view.width, view.height) / 100))


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
        self.layer_bytes = np.ascontiguousarray(_to_bytes(canvas.rgb))
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
            self.work[:, j0:j1, i0:i1] = self.layer[:, j0:j1, i0:i1]
            self.work_bytes[j0:j1, i0:i1] = self.layer_bytes[j0:j1, i0:i1]
        canvas = Canvas(self.view, self.work)
        for body, pose in zip(self.bodies[kept:], poses[kept:]):
            draw_body(canvas, body, pose)
        _draw_contacts(canvas, frame)
        for j0, j1, i0, i1 in canvas.painted:
            self.work_bytes[j0:j1, i0:i1] = _to_bytes(self.work[:, j0:j1, i0:i1])
        text = _draw_text_boxed(self.work_bytes, self.bodies, frame, self.view)
        # (text is in the bytes only: put back like paint, where the floats are the layer's)
        self._painted = canvas.painted | set(text)
        self.changed = None if rebuilt or first else list(restored | self._painted)
        return self.work_bytes

    def image(self, frame: Frame) -> Image.Image:
        return Image.fromarray(self.pixels(frame), "RGB")
