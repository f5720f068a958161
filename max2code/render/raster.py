"""One frame as pixels, drawn by Skia (skia-python): anti-aliased shapes, in RGB bytes.

Skia computes each pixel's coverage of a shape from the exact outline (analytic anti-aliasing,
the quality of a browser's canvas): a pixel inside a shape by more than half its diagonal is
exactly the shape's colour, one outside by as much is untouched, and the coverage of the band
between adds up to the shape's area. Coordinates stay fractional: an edge lands where the
geometry puts it, at any zoom. Colours are blended in their sRGB values, as a browser does.
Pillow draws the text (labels, time stamp) on top. Both come with
`pip install 'max2code[render]'`.

Until issue 37 the shapes were drawn by numpy from signed distances at each pixel centre; that
drew a pile of 43 bodies at 37 frames a second, mostly in Python and numpy calls per shape and
contact. Skia draws a body in a few microseconds (bench/render.py measures it).

A shape is drawn from its outline, one function per kind of shape (OUTLINES): a Skia path in
pixel space, its bounding box, whether it has an inside, and a circle's spoke. An animation
is drawn by a FrameDrawer, which gives the same pixels as frame_image (the tests compare them
byte for byte): the bodies at the front of the list that stay put (walls, resting bodies)
are drawn once into a layer, and each frame starts from a copy of that layer.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
import skia
from PIL import Image, ImageDraw, ImageFont

from .model import (Body, Capsule, Circle, Compound, Contact, Frame, Point, Polygon, RenderModelError,
                    Segment, Style, View)
from .glyphs import GlyphCache, TextMask, ink_table
from .text import printable, time_stamp

CONTACT_COLOUR = "#d62728"
TEXT_COLOUR = "#000000"
CONTACT_WIDTH = 1.5   # pixels, of the ring and of the normal's line
CONTACT_REACH = 2.5   # the normal's line, in ring radii


@lru_cache(maxsize=1024)
def rgba(colour: str) -> tuple[float, float, float, float]:
    """'#rrggbb[aa]' (checked by the model) to floats in 0..1."""
    v = [int(colour[i:i + 2], 16) / 255 for i in range(1, len(colour), 2)]
    return (v[0], v[1], v[2], v[3] if len(v) == 4 else 1.0)


@lru_cache(maxsize=1024)
def _skia_colour(colour: str) -> int:
    v = [int(colour[i:i + 2], 16) for i in range(1, len(colour), 2)]
    return skia.Color(v[0], v[1], v[2], v[3] if len(v) == 4 else 255)


@lru_cache(maxsize=1024)
def _paint(colour: str, width: float | None) -> skia.Paint:
    """An anti-aliased paint: a fill (width None), or a stroke of `width` pixels with round
    joins and caps (the pixels within width/2 of the outline, as the distance drawing was)."""
    if width is None:
        return skia.Paint(AntiAlias=True, Color=_skia_colour(colour))
    return skia.Paint(AntiAlias=True, Color=_skia_colour(colour), Style=skia.Paint.kStroke_Style,
                      StrokeWidth=width, StrokeJoin=skia.Paint.kRound_Join,
                      StrokeCap=skia.Paint.kRound_Cap)


def _opaque(colour: str) -> bool:
    """'#rrggbb', or '#rrggbbaa' with alpha ff."""
    return len(colour) == 7 or colour[7:].lower() == "ff"


def check_frame(bodies: Sequence[Body], frame: Frame) -> None:
    if len(frame.poses) != len(bodies):
        raise RenderModelError(f"frame at t={frame.time} has {len(frame.poses)} poses "
                               f"for {len(bodies)} bodies")


Box = tuple[int, int, int, int]   # rows j0:j1, columns i0:i1 of a picture


TILE = 8   # pixels: boxes are merged on a grid of tiles this size


def tiles(boxes: Sequence[Box] | set[Box], height: int, width: int) -> np.ndarray:
    """The TILE x TILE tiles that `boxes` touch, as a mask (one spare column, always clear)."""
    mask = np.zeros((-(-height // TILE), -(-width // TILE) + 1), dtype=np.int8)
    for j0, j1, i0, i1 in boxes:
        mask[j0 // TILE:(j1 - 1) // TILE + 1, i0 // TILE:(i1 - 1) // TILE + 1] = 1
    return mask


def runs(mask: np.ndarray, height: int, width: int) -> list[Box]:
    """A tile mask as boxes that do not overlap: runs of tiles along a row, and runs of the same
    columns in the rows below as one box."""
    flat = mask.ravel()
    edges = np.diff(flat, prepend=0)    # (the spare last column ends every row's last run)
    cols = mask.shape[1]
    starts, ends = np.flatnonzero(edges == 1).tolist(), np.flatnonzero(edges == -1).tolist()
    open_boxes: dict[tuple[int, int], list[int]] = {}   # columns -> [first row, last row]
    out = []
    for start, end in zip(starts, ends):
        r, key = start // cols, (start % cols, end % cols)
        box = open_boxes.get(key)
        if box is not None and box[1] == r - 1:   # the same columns as the row above: one box
            box[1] = r
            continue
        if box is not None:
            out.append((box[0], box[1], *key))
        open_boxes[key] = [r, r]
    out += [(r0, r1, *key) for key, (r0, r1) in open_boxes.items()]
    return [(r0 * TILE, min((r1 + 1) * TILE, height), c0 * TILE, min(c1 * TILE, width))
            for r0, r1, c0, c1 in out]


def merged(boxes: Sequence[Box] | set[Box], height: int, width: int) -> list[Box]:
    """The pixels of `boxes` as few boxes that do not overlap, on a grid of tiles (tiles, runs).
    (A frame's boxes overlap: a contact found at one place in ten frames, a ring over a body.
    Converted, restored and looked up box by box, the same pixels were done many times.)"""
    boxes = list(boxes)
    return boxes if len(boxes) <= 1 else runs(tiles(boxes, height, width), height, width)


def tile_view(store: np.ndarray) -> np.ndarray:
    """A picture padded to whole tiles (rows, columns, ...) as (tile rows, tile columns, TILE,
    TILE, ...), a view: indexed by a tile mask (tiles()[:, :-1] as bool) it reads or writes
    those tiles' pixels, all in one call."""
    rows, cols = store.shape[0] // TILE, store.shape[1] // TILE
    return np.lib.stride_tricks.as_strided(
        store, (rows, cols, TILE, TILE) + store.shape[2:],
        (store.strides[0] * TILE, store.strides[1] * TILE) + store.strides, writeable=True)


class Canvas:
    """An RGBA picture (rows, columns, 4 bytes, opaque) that Skia draws into in place; `painted`
    keeps the pixel boxes touched since it was made, so that a FrameDrawer converts and restores
    those only.

    Skia draws into `store`, the picture padded to whole TILE x TILE tiles (Skia takes only
    contiguous rows, so the picture is its top-left view, `pixels`): a FrameDrawer then copies
    whole tiles by a mask in one numpy call (tile_view), where box by box the Python of a
    hundred small boxes cost more than their pixels. The padding is painted by shapes at the
    edge but is never part of a picture."""

    def __init__(self, view: View, store: np.ndarray | None = None) -> None:
        """A fresh picture of the background, or one drawing into `store` itself (padded)."""
        self.view = view
        self.painted: set[Box] = set()
        if store is None:
            store = np.empty((-(-view.height // TILE) * TILE, -(-view.width // TILE) * TILE, 4),
                             dtype=np.uint8)
            # (as one 32-bit number a pixel: numpy broadcasting four bytes over the picture
            # took 1.4 ms, most of a new layer's cost)
            store.view(np.uint32)[:] = np.frombuffer(bytes(
                [int(view.background[i:i + 2], 16) for i in (1, 3, 5)] + [255]), dtype=np.uint32)[0]
        self.store = store
        self.pixels = store[:view.height, :view.width]
        self.surface = skia.Surface(store)
        self.skia = self.surface.getCanvas()

    def box(self, x0: float, y0: float, x1: float, y1: float) -> Box | None:
        """The pixels a pixel-space box touches (rows, columns), clipped to the picture, or None."""
        # (floor and ceil, clipped to the picture: int() is floor from 0 up; a frame asks
        # this for every body and contact, and min, max and floor took twice as long)
        w, h = self.view.width, self.view.height
        i0 = int(x0) if x0 > 0 else 0
        j0 = int(y0) if y0 > 0 else 0
        i1 = w if x1 >= w else math.ceil(x1)
        j1 = h if y1 >= h else math.ceil(y1)
        if i0 >= i1 or j0 >= j1:
            return None
        return (j0, j1, i0, i1)

    def rgb(self) -> np.ndarray:
        """The picture's RGB bytes (rows, columns, 3), a copy."""
        return np.ascontiguousarray(self.pixels[..., :3])

    def image(self) -> Image.Image:
        return rgb_image(self.pixels)


def rgb_image(pixels: np.ndarray) -> Image.Image:
    """Opaque RGBA bytes as an RGB Pillow image."""
    return Image.fromarray(np.ascontiguousarray(pixels[..., :3]), "RGB")


# --- outlines in pixel space ------------------------------------------------------------------

ToPixel = Callable[[Point], Point]


@dataclass(frozen=True)
class Outline:
    """One shape placed in pixel space: its outline as a Skia path, its bounding box (x0, y0,
    x1, y1), whether it has an inside (a segment has none), the spoke that shows a circle's
    turn, and a circle's centre and radius (x, y, r) where it is drawn as one (draw_body).
    A disc's path is None, made only where it is drawn as a path (path_of): the ring and fill
    of most balls are two circles, and the path was a tenth of drawing one."""
    path: skia.Path | None
    box: tuple[float, float, float, float]
    area: bool = True
    spoke: tuple[Point, Point] | None = None
    disc: tuple[float, float, float] | None = None


def path_of(shape: Outline) -> skia.Path:
    if shape.path is not None:
        return shape.path
    x, y, r = shape.disc
    return skia.Path().addCircle(x, y, r)


def _box_around(points: Sequence[Point], r: float) -> tuple[float, float, float, float]:
    return (min(p[0] for p in points) - r, min(p[1] for p in points) - r,
            max(p[0] for p in points) + r, max(p[1] for p in points) + r)


def _rounded(points: Sequence[Point], r: float) -> skia.Path:
    """Every point within r of a convex polygon (2 points: a capsule): each edge moved out by r,
    joined by arcs of radius r around the vertices."""
    pts = [p for i, p in enumerate(points) if p != points[i - 1]] or [points[0]]
    path = skia.Path()
    if len(pts) == 1:
        return path.addCircle(pts[0][0], pts[0][1], r)
    n = len(pts)
    area2 = sum(pts[i - 1][0] * pts[i][1] - pts[i][0] * pts[i - 1][1] for i in range(n))
    orient = 1.0 if area2 >= 0 else -1.0
    normals = []
    for i in range(n):
        (ax, ay), (bx, by) = pts[i], pts[(i + 1) % n]
        length = math.hypot(bx - ax, by - ay)
        normals.append((orient * (by - ay) / length, -orient * (bx - ax) / length))
    for i in range(n):   # (the arc at vertex i turns from edge i-1's normal to edge i's)
        (ux, uy), (vx, vy) = normals[i - 1], normals[i]
        turn = math.degrees(math.atan2(abs(ux * vy - uy * vx), ux * vx + uy * vy))
        x, y = pts[i]
        path.arcTo(skia.Rect(x - r, y - r, x + r, y + r), math.degrees(math.atan2(uy, ux)),
                   orient * turn, i == 0)
    return path.close()


def _polygon_path(points: Sequence[Point], r: float) -> skia.Path:
    if r > 0:
        return _rounded(points, r)
    return skia.Path().addPoly([skia.Point(x, y) for x, y in points], True)


BIG = 2.0 ** 14   # pixels: a circle this large is drawn as a polygon (_circle_path)
SAGITTA = 0.01    # pixels: how far that polygon's edges may pass inside the circle


def _circle_path(c: Point, r: float, view: View) -> skia.Path:
    """A circle's outline. Skia computes in 32-bit floats: a circle of radius 1e9 pixels (a
    planet under a zoomed-in view) came out as the whole picture. One larger than BIG is drawn
    as the part of it within `reach` of the picture: its arc as a polygon computed in 64-bit
    floats (edges within SAGITTA of the circle), closed through points 2 x reach inside it,
    whose edges lie at least reach from the picture's centre, so their stroke is not seen."""
    if r <= BIG:
        return skia.Path().addCircle(c[0], c[1], r)
    px, py = view.width / 2, view.height / 2
    reach = math.hypot(view.width, view.height) + 16.0
    dx, dy = px - c[0], py - c[1]
    dist = math.hypot(dx, dy)
    if dist + reach <= r:                       # the picture lies inside
        return skia.Path().addRect(px - reach, py - reach, px + reach, py + reach)
    if dist - reach >= r:                       # the picture lies outside
        return skia.Path()
    half = math.acos(max(-1.0, min(1.0, (r * r + dist * dist - reach * reach) / (2 * r * dist))))
    n = max(2, math.ceil(2 * half / math.sqrt(8 * SAGITTA / r)))
    toward = math.atan2(dy, dx)
    angles = [toward - half + 2 * half * k / n for k in range(n + 1)]
    arc = [(c[0] + r * math.cos(a), c[1] + r * math.sin(a)) for a in angles]
    inside = [(c[0] + (r - 2 * reach) * math.cos(a), c[1] + (r - 2 * reach) * math.sin(a))
              for a in (angles[-1], angles[0])]
    return skia.Path().addPoly([skia.Point(x, y) for x, y in arc + inside], True)


def _circle(shape: Circle, px: ToPixel, view: View) -> Outline:
    c, r = px(shape.centre), shape.radius * view.scale
    rim = px((shape.centre[0] + shape.radius, shape.centre[1]))
    box = (c[0] - r, c[1] - r, c[0] + r, c[1] + r)
    if r <= BIG:   # (_circle_path's circle, made where it is needed)
        return Outline(None, box, spoke=(c, rim), disc=(c[0], c[1], r))
    return Outline(_circle_path(c, r, view), box, spoke=(c, rim))


def _polygon(shape: Polygon, px: ToPixel, view: View) -> Outline:
    pts, r = [px(v) for v in shape.vertices], shape.radius * view.scale
    return Outline(_polygon_path(pts, r), _box_around(pts, r))


def _capsule(shape: Capsule, px: ToPixel, view: View) -> Outline:
    a, b, r = px(shape.a), px(shape.b), shape.radius * view.scale
    return Outline(_rounded([a, b], r), _box_around([a, b], r))


def _segment(shape: Segment, px: ToPixel, view: View) -> Outline:
    a, b = px(shape.a), px(shape.b)
    return Outline(skia.Path().moveTo(*a).lineTo(*b), _box_around([a, b], 0.0), area=False)


def _compound(shape: Compound, px: ToPixel, view: View) -> Outline:
    """The union of the parts' outlines (one fill, one outline around it: Skia's path ops); a
    thin segment part joins as a line a pixel wide (filled with the body, so it shows with no
    stroke colour too)."""
    parts = [OUTLINES[type(p)](p, px, view) for p in shape.parts]
    path = None
    for o in parts:
        area = path_of(o)
        if not o.area:
            area = skia.Path()
            LINE.getFillPath(path_of(o), area)
        path = area if path is None else (skia.Op(path, area, skia.PathOp.kUnion_PathOp)
                                          or path.addPath(area))
    box = (min(o.box[0] for o in parts) - 0.5, min(o.box[1] for o in parts) - 0.5,
           max(o.box[2] for o in parts) + 0.5, max(o.box[3] for o in parts) + 0.5)
    return Outline(path, box)


LINE = skia.Paint(Style=skia.Paint.kStroke_Style, StrokeWidth=1.0, StrokeCap=skia.Paint.kRound_Cap)


OUTLINES: dict[type, Callable[[object, ToPixel, View], Outline]] = {
    Circle: _circle, Polygon: _polygon, Capsule: _capsule, Segment: _segment, Compound: _compound}


def outline(shape: object, pose_apply: ToPixel, view: View) -> Outline:
    """The shape at a pose, in the view's pixels (OUTLINES: one function per kind of shape)."""
    make = OUTLINES.get(type(shape))
    if make is None:
        raise RenderModelError(f"unknown shape {type(shape).__name__}")
    return make(shape, lambda p: view.to_pixel(pose_apply(p)), view)


def contrast(colour: str | None) -> str:
    """A spoke colour visible on the fill: black on light fills, white on dark ones."""
    if colour is None:
        return "#000000"
    r, g, b, _ = rgba(colour)
    return "#000000" if 0.299 * r + 0.587 * g + 0.114 * b > 0.5 else "#ffffff"


@dataclass(frozen=True)
class Look:
    """How draw_body paints a style on a shape with or without an inside, worked out once per
    style (look): the stroke's width, the fill's and the line's paints (None: not drawn),
    whether a disc is drawn as two circles (ring), and the spoke's paint."""
    width: float
    fill: skia.Paint | None
    line: skia.Paint | None
    ring: skia.Paint | None
    spoke: skia.Paint


@lru_cache(maxsize=1024)
def look(style: Style, area: bool) -> Look:
    width = style.stroke_width
    if not area:  # a segment has no inside: its stroke is the whole picture of it
        width = max(width, 1.0)
    line_colour = style.stroke if style.stroke is not None else (None if area else style.fill)
    fill = _paint(style.fill, None) if area and style.fill is not None else None
    line = _paint(line_colour, width) if line_colour is not None and width > 0 else None
    # an opaque ring around an opaque fill: the disc out to the ring's outer edge in the
    # ring's colour, then the disc inside its inner edge in the fill's (the same regions;
    # 60 us a ball where the fill and Skia's stroke of the circle took 108: the stroker
    # builds the ring's outline anew each time)
    ring = (_paint(line_colour, None) if style.fill is not None and line is not None
            and _opaque(style.fill) and _opaque(line_colour) else None)
    return Look(width, fill, line, ring,
                _paint(style.stroke or contrast(style.fill), max(width, 1.0)))


def draw_body(canvas: Canvas, body: Body, pose) -> None:
    """Fill, then stroke, then a circle's spoke; nothing of a body wholly outside the picture."""
    style = body.style
    shape = outline(body.shape, pose.apply, canvas.view)
    paint = look(style, shape.area)
    width = paint.width
    pad = width / 2 + 1
    box = canvas.box(shape.box[0] - pad, shape.box[1] - pad, shape.box[2] + pad, shape.box[3] + pad)
    if box is None:
        return
    sk = canvas.skia
    if shape.disc is not None and paint.ring is not None:
        x, y, r = shape.disc
        sk.drawCircle(x, y, r + width / 2, paint.ring)
        if r > width / 2:
            sk.drawCircle(x, y, r - width / 2, paint.fill)
    else:
        if paint.fill is not None:
            sk.drawPath(path_of(shape), paint.fill)
        if paint.line is not None:
            sk.drawPath(path_of(shape), paint.line)
    if shape.spoke is not None and style.spoke:   # (it lies inside the circle's box)
        (x0, y0), (x1, y1) = shape.spoke
        sk.drawLine(x0, y0, x1, y1, paint.spoke)
    canvas.painted.add(box)


CONTACT_STEP = 8       # contacts are placed to 1/8 pixel and their normals to a degree ...


def _distinct_contacts(contacts: Sequence[Contact], view: View) -> list[tuple[float, float, float | None]]:
    """... and drawn once per place and normal: (x, y, normal's angle in radians, None for
    none) in pixels, in numpy (a frame can have thousands). A pile settling has 9,000 contacts
    in a frame at a dozen places, the same resting contacts found again and again; drawn one
    over the other they were a blot (each ring's soft edge darkened by every copy) and took
    40 ms. (An eighth of a pixel and a degree are below what the eye sees: the normal's line is
    12 pixels long.)"""
    if not contacts:
        return []
    world = np.array([(c.point[0], c.point[1], c.normal[0], c.normal[1]) for c in contacts])
    s = view.scale
    x = view.width / 2 + (world[:, 0] - (view.xmin + view.xmax) / 2) * s
    y = view.height / 2 - (world[:, 1] - (view.ymin + view.ymax) / 2) * s
    far = view.width + view.height          # pixels from the centre: no ring reaches in from there
    near = (np.abs(x - view.width / 2) < far) & (np.abs(y - view.height / 2) < far)
    turn = np.rint(np.degrees(np.arctan2(-world[:, 3], world[:, 2]))) % 360
    turn[(world[:, 2] == 0) & (world[:, 3] == 0)] = 360         # no normal: no line
    # (one whole number per contact: np.unique of rows sorted ten times slower)
    span = 2 * far * CONTACT_STEP + 1
    i = np.rint(x[near] * CONTACT_STEP).astype(np.int64) + far * CONTACT_STEP
    j = np.rint(y[near] * CONTACT_STEP).astype(np.int64) + far * CONTACT_STEP
    keys = np.unique((i * span + j) * 361 + turn[near].astype(np.int64))
    t, ij = keys % 361, keys // 361
    return [(a / CONTACT_STEP - far, b / CONTACT_STEP - far, None if c == 360 else math.radians(c))
            for a, b, c in zip((ij // span).tolist(), (ij % span).tolist(), t.tolist())]


def draw_contacts(canvas: Canvas, contacts: Sequence[Contact], size: float) -> None:
    """Each contact as a ring of radius `size` at its point and its normal as a line from it,
    CONTACT_REACH rings long. The contacts near one another (in one square cell, 2 x reach a
    side) are drawn as one path of rings and one of lines, so where their rings overlap the
    union is covered, with one anti-aliased edge; cells are drawn one by one, as Skia walks
    every row of a path's bounds (one path across the whole picture took twice as long)."""
    reach = math.ceil(CONTACT_REACH * size + CONTACT_WIDTH / 2 + 1.5)
    cells: dict[tuple[int, int], tuple[skia.Path, skia.Path]] = {}
    outer, inner = size + CONTACT_WIDTH / 2, max(size - CONTACT_WIDTH / 2, 0.0)
    length = CONTACT_REACH * size
    pad = outer + 1
    w, h = canvas.view.width, canvas.view.height
    for x, y, turn in _distinct_contacts(contacts, canvas.view):
        # (canvas.box(x - reach, y - reach, x + reach + 1, y + reach + 1) is None, inline)
        if x + reach + 1 <= 0 or y + reach + 1 <= 0 or x - reach >= w or y - reach >= h:
            continue
        cell = (int(x // (2 * reach)), int(y // (2 * reach)))
        if cell not in cells:
            cells[cell] = (skia.Path(), skia.Path())
        rings, lines = cells[cell]
        rings.addCircle(x, y, outer)
        if inner > 0:
            rings.addCircle(x, y, inner, skia.PathDirection.kCCW)
        x0, y0, x1, y1 = x - pad, y - pad, x + pad, y + pad
        if turn is not None:
            ex, ey = x + length * math.cos(turn), y + length * math.sin(turn)
            lines.moveTo(x, y).lineTo(ex, ey)
            # (the box painted: the ring's and the line's, a pixel of soft edge around them;
            # the square of the line's reach every way had 2-3 times their area to restore
            # and to map to a GIF's palette again)
            x0, y0 = min(x0, ex - CONTACT_WIDTH / 2 - 1), min(y0, ey - CONTACT_WIDTH / 2 - 1)
            x1, y1 = max(x1, ex + CONTACT_WIDTH / 2 + 1), max(y1, ey + CONTACT_WIDTH / 2 + 1)
        box = canvas.box(x0, y0, x1 + 1, y1 + 1)
        if box is not None:
            canvas.painted.add(box)
    for rings, lines in cells.values():
        canvas.skia.drawPath(rings, _paint(CONTACT_COLOUR, None))
        if not lines.isEmpty():
            canvas.skia.drawPath(lines, _paint(CONTACT_COLOUR, CONTACT_WIDTH))


def draw_contact(canvas: Canvas, contact: Contact, size: float) -> None:
    """A ring at the contact point and the normal as a short line from it."""
    draw_contacts(canvas, [contact], size)


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


@lru_cache(maxsize=16)
def glyph_cache(size: int) -> GlyphCache:
    """The glyphs of font(size), rendered once each (render.glyphs)."""
    return GlyphCache(font(size))


def _text_items(bodies: Sequence[Body], frame: Frame, view: View) -> list[tuple]:
    """What draw_text writes: (anchor point, text, colour, anchor, white box behind it or None,
    the text's mask put together from cached glyphs or None: Pillow renders it)."""
    size = text_size(view)
    label_font = font(size)
    items = []
    for body, pose in zip(bodies, frame.poses):
        if body.style.label:
            x, y = view.to_pixel((pose.x, pose.y))
            if -size <= x <= view.width + size and -size <= y <= view.height + size:
                items.append(((x, y), printable(body.style.label), contrast(body.style.fill),
                              "mm", None, None))
    if view.show_time:
        text = time_stamp(frame.time)
        # (a new string every frame, at a whole pixel: from the cached glyphs where it can be)
        mask = glyph_cache(size).text_mask(text)
        left, top, right, bottom = mask.box if mask is not None else label_font.getbbox(text, anchor="la")
        items.append(((6, 6), text, TEXT_COLOUR, "la",
                      (6 + left - 3, 6 + top - 3, 6 + right + 3, 6 + bottom + 3), mask))
    return items


def _draw_items(draw: ImageDraw.ImageDraw, items: list[tuple], size: int,
                offset: tuple[int, int] = (0, 0)) -> None:
    label_font = font(size)
    for (x, y), text, colour, anchor, box, mask in items:
        if box is not None:
            draw.rectangle((box[0] - offset[0], box[1] - offset[1], box[2] - offset[0],
                            box[3] - offset[1]), fill="#ffffff")
        if mask is not None:   # (x, y whole: ImageDraw.text blends its mask so, at this place)
            draw.bitmap((x + mask.left - offset[0], y + mask.top - offset[1]),
                        Image.fromarray(mask.mask, "L"), fill=colour)
        else:
            draw.text((x - offset[0], y - offset[1]), text, fill=colour, font=label_font, anchor=anchor)


def draw_text(image: Image.Image, bodies: Sequence[Body], frame: Frame, view: View) -> None:
    """Labels and the time stamp, drawn by Pillow."""
    _draw_items(ImageDraw.Draw(image), _text_items(bodies, frame, view), text_size(view))


def _draw_text_boxed(pixels: np.ndarray, bodies: Sequence[Body], frame: Frame, view: View) -> list[Box]:
    """draw_text into opaque RGBA bytes, each text on a crop of its own box only (the same
    pixels: whole-pixel offsets keep Pillow's fractional placement); returns the boxes."""
    size = text_size(view)
    label_font = font(size)
    boxes = []
    for item in _text_items(bodies, frame, view):
        (x, y), text, _, anchor, back, _ = item
        if back is not None:   # (the text lies inside its box: no second measuring)
            left, top, right, bottom = back[0] - x, back[1] - y, back[2] - x, back[3] - y
        else:
            left, top, right, bottom = label_font.getbbox(text, anchor=anchor)
        j0, j1, i0, i1 = box = _box(view, x + left, y + top, x + right, y + bottom)
        if j0 >= j1 or i0 >= i1:
            continue
        if back is not None and item[5] is not None:
            _paint_boxed(pixels, (x, y), item[2], back, item[5])
            boxes.append(box)
            continue
        crop = Image.fromarray(pixels[j0:j1, i0:i1], "RGBA")
        _draw_items(ImageDraw.Draw(crop), [item], size, (i0, j0))
        pixels[j0:j1, i0:i1] = np.asarray(crop)
        boxes.append(box)
    return boxes


def _clip(pixels: np.ndarray, i0: int, j0: int, i1: int, j1: int) -> tuple[slice, slice, slice, slice]:
    """Pixels columns i0:i1, rows j0:j1 (which may reach past the picture) as (rows, columns)
    of the picture, and the same pixels' (rows, columns) in an array whose corner is (i0, j0)."""
    h, w = pixels.shape[:2]
    a, b, c, d = max(j0, 0), min(j1, h), max(i0, 0), min(i1, w)
    return slice(a, max(b, a)), slice(c, max(d, c)), slice(a - j0, max(b, a) - j0), slice(c - i0, max(d, c) - i0)


def _paint_boxed(pixels: np.ndarray, at: tuple[int, int], colour: str, back: tuple, mask: TextMask) -> None:
    """_draw_items' white box `back` and the text of `mask` at `at` in `colour` over it, in
    numpy: Pillow's rectangle covers its corners inclusive, and its blend onto the white is
    a lookup (glyphs.ink_table)."""
    rows, cols, _, _ = _clip(pixels, back[0], back[1], back[2] + 1, back[3] + 1)
    pixels[rows, cols] = 255
    x, y = at[0] + mask.left, at[1] + mask.top
    rows, cols, mrows, mcols = _clip(pixels, x, y, x + mask.mask.shape[1], y + mask.mask.shape[0])
    pixels[rows, cols] = ink_table(colour, "#ffffff")[mask.mask[mrows, mcols]]


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
    _draw_text_boxed(canvas.pixels, bodies, frame, view)
    return canvas.image()


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

    Drawing is in order (later bodies over earlier ones), so what can be kept from frame to
    frame is a prefix: the leading bodies whose poses did not change since the previous frame
    are drawn once into a layer. A frame draws the other bodies into a working copy of the
    layer, after putting back the layer's pixels where the previous frame drew: the cost
    follows the area drawn, not the picture's. A body of that prefix that moves later makes
    the layer be drawn again, shorter: never a wrong picture, at worst the cost of frame_image.

    Frames stay RGBA (opaque) from Skia to the writers: ffmpeg takes them as they are, a GIF
    palette looks them up as one 32-bit number a pixel, and no RGB copy is made (it was a
    fifth of a frame's drawing). `changed_tiles` says where the last frame may differ from the
    one before, as a mask of TILE x TILE tiles (None: anywhere), so a GIF palette
    (palette.Mapper) maps only those pixels again; `changed` says it as boxes."""

    def __init__(self, bodies: Sequence[Body], view: View) -> None:
        self.bodies = list(bodies)
        self.view = view
        self.previous: tuple | None = None
        self.layers_painted = 0
        self._paint_layer(())
        self.changed_tiles: np.ndarray | None = None

    def _paint_layer(self, poses: tuple) -> None:
        canvas = Canvas(self.view)
        for body, pose in zip(self.bodies, poses):
            draw_body(canvas, body, pose)
        self.layer_poses, self.layer = poses, canvas.store
        self.work = Canvas(self.view, self.layer.copy())
        self._layer_tiles, self._work_tiles = tile_view(self.layer), tile_view(self.work.store)
        # the tiles of the working copy that are not the layer's
        self._drawn = np.zeros(self._layer_tiles.shape[:2], dtype=bool)
        self.layers_painted += 1

    def pixels(self, frame: Frame) -> np.ndarray:
        """The frame's opaque RGBA bytes (height x width x 4): a buffer of the drawer's own,
        valid until the next call (copy it to keep it)."""
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
        work, h, w = self.work, self.view.height, self.view.width
        if self._drawn.any():
            self._work_tiles[self._drawn] = self._layer_tiles[self._drawn]
        work.painted = set()
        for body, pose in zip(self.bodies[kept:], poses[kept:]):
            draw_body(work, body, pose)
        _draw_contacts(work, frame)
        work.painted.update(_draw_text_boxed(work.pixels, self.bodies, frame, self.view))
        drawn = tiles(work.painted, h, w)[:, :-1].astype(bool)
        self.changed_tiles = None if rebuilt or first else drawn | self._drawn
        self._drawn = drawn
        return work.pixels

    @property
    def changed(self) -> list[Box] | None:
        """changed_tiles as boxes that do not overlap (None: anywhere)."""
        if self.changed_tiles is None:
            return None
        h, w = self.view.height, self.view.width
        return runs(np.pad(self.changed_tiles, ((0, 0), (0, 1))).astype(np.int8), h, w)

    def image(self, frame: Frame) -> Image.Image:
        return rgb_image(self.pixels(frame))
