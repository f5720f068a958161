"""Frames as lists of things to draw (PGE's look: black background, filled shapes, text), for
games whose bodies come and go: a frame is a list of Items taken at its time, in world
coordinates, drawn into a square picture of the view [x0, x0 + side] x [y0, y0 + side], y up
(PGE's unit square by default). Drawing is separate, so the same frames go to a window, a GIF,
an MP4 or PNG files (write.gif_of, mp4_of, png_dir_of)."""

from __future__ import annotations

import math
from dataclasses import dataclass

Vec = tuple[float, float]
RGBA = tuple[int, int, int, int]
BACKGROUND = (0, 0, 0)


@dataclass(frozen=True)
class Item:
    """One thing drawn: a filled polygon (points), circle (points[0] and radius) or text (at
    points[0], its top edge there as PGE places it; size in pixels of the game's window)."""
    kind: str
    colour: RGBA
    points: tuple[Vec, ...]
    radius: float = 0.0
    text: str = ""
    size: int = 0


def body_item(vertices, radius: float, pose: tuple[float, float, float], colour: RGBA) -> Item:
    """The Item of an engine body (its BodyInfo's vertices about its reference point, and its
    radius) at a pose: a circle for one vertex, else a polygon (a capsule's rounding is not
    drawn)."""
    x, y, a = pose
    c, s = math.cos(a), math.sin(a)
    pts = tuple((x + c * u - s * v, y + s * u + c * v) for u, v in vertices)
    if len(vertices) == 1:
        return Item("circle", colour, pts, radius)
    return Item("polygon", colour, pts)


@dataclass(frozen=True)
class Frame:
    time: float
    items: tuple[Item, ...]


def image(frame: Frame, size: int, window: int, view: tuple[float, float, float] = (0.0, 0.0, 1.0)):
    """The frame as an RGB Pillow image of size x size pixels (text sizes are pixels of a
    window `window` pixels wide, scaled) showing the square view (x0, y0, side)."""
    from PIL import Image, ImageDraw, ImageFont

    from .text import printable

    img = Image.new("RGB", (size, size), BACKGROUND)
    draw = ImageDraw.Draw(img, "RGBA")
    x0, y0, side = view
    k = size / side
    px = lambda p: ((p[0] - x0) * k, (side - (p[1] - y0)) * k)  # noqa: E731
    for it in frame.items:
        if it.kind == "polygon":
            draw.polygon([px(p) for p in it.points], fill=it.colour)
        elif it.kind == "circle":
            (x, y), r = px(it.points[0]), it.radius * k
            draw.ellipse((x - r, y - r, x + r, y + r), fill=it.colour)
        else:
            font = ImageFont.load_default(size=max(6, round(it.size * size / window)))
            draw.text(px(it.points[0]), printable(it.text), fill=it.colour, font=font, anchor="lt")
    return img
