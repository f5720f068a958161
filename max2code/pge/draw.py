"""A PGE frame as a picture: PGE's look (black background, filled shapes, text), its unit square
filling a square picture, y up. A frame is a list of Items taken at the frame's time; drawing
it is separate, so the same frame goes to the window, a GIF, an MP4 or PNG files."""

from __future__ import annotations

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


@dataclass(frozen=True)
class Frame:
    time: float
    items: tuple[Item, ...]


def image(frame: Frame, size: int, window: int):
    """The frame as an RGB Pillow image of size x size pixels (text scaled from the game's
    `window` size)."""
    from PIL import Image, ImageDraw, ImageFont

    from ..render.text import printable

    img = Image.new("RGB", (size, size), BACKGROUND)
    draw = ImageDraw.Draw(img, "RGBA")
    px = lambda p: (p[0] * size, (1.0 - p[1]) * size)  # noqa: E731
    for it in frame.items:
        if it.kind == "polygon":
            draw.polygon([px(p) for p in it.points], fill=it.colour)
        elif it.kind == "circle":
            (x, y), r = px(it.points[0]), it.radius * size
            draw.ellipse((x - r, y - r, x + r, y + r), fill=it.colour)
        else:
            font = ImageFont.load_default(size=max(6, round(it.size * size / window)))
            draw.text(px(it.points[0]), printable(it.text), fill=it.colour, font=font, anchor="lt")
    return img
