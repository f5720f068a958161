"""Text masks put together from cached glyph masks: the pixels of Pillow's own, faster.

Pillow renders a string glyph by glyph (FreeType) into one coverage mask, each glyph at its pen
position and laid over those before it (coverage a over b: a + b - a b / 255, rounded), then
blends the text's colour through that mask. A time stamp is a new string every frame, so every
frame rendered its dozen glyphs again: 250 us, a fifth of drawing a frame of billiards. Where a
glyph's mask cannot depend on where it lies (the text starts on a whole pixel, the advances of
its characters are whole pixels and no pair of them is kerned), each glyph is rendered once and
a string's mask is put together from them; anything else returns None and is Pillow's to draw.
tests/render/test_glyphs.py compares the two, mask and box, over many strings and font sizes.

Pillow then blends the colour through the mask (ImageDraw.bitmap), pixel by pixel a function of
the coverage and of the pixel below only: on a box of one colour (the time stamp's white box),
that is a table of 256 entries, which Pillow itself fills once (ink_table), and the text's
pixels are one lookup (numpy) where the crop, ImageDraw and the blend took 60 us a frame.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from PIL import Image, ImageDraw, ImageFont


@dataclass(frozen=True)
class Glyph:
    """One character's coverage (rows x columns), its top-left corner from the pen's place on
    the baseline, and how far it moves the pen."""
    mask: np.ndarray
    left: int
    top: int
    advance: int


@dataclass(frozen=True)
class TextMask:
    """A string's coverage and its top-left corner from the text's anchor (left, ascender):
    what FreeTypeFont.getmask2(text, "L", anchor="la") gives, and getbbox's box."""
    mask: np.ndarray
    left: int
    top: int

    @property
    def box(self) -> tuple[int, int, int, int]:
        return (self.left, self.top, self.left + self.mask.shape[1], self.top + self.mask.shape[0])


def _over(below: np.ndarray, above: np.ndarray) -> np.ndarray:
    """Coverage `above` laid over `below` (uint8): a + b - a b / 255, rounded as Pillow does."""
    b, a = below.astype(np.uint32), above.astype(np.uint32)
    t = b * (255 - a) + 128
    return (a + (((t >> 8) + t) >> 8)).astype(np.uint8)


class GlyphCache:
    """The glyphs of one font, rendered once each (see the module)."""

    def __init__(self, font: ImageFont.FreeTypeFont) -> None:
        self.font = font
        self.ascent = font.getmetrics()[0]
        self._glyphs: dict[str, Glyph | None] = {}
        self._kerned: dict[tuple[str, str], bool] = {}

    def glyph(self, ch: str) -> Glyph | None:
        """The glyph of `ch`, or None if its advance is not a whole number of pixels."""
        if ch not in self._glyphs:
            advance = self.font.getlength(ch)
            if advance != int(advance):
                self._glyphs[ch] = None
            else:
                core, (left, top) = self.font.getmask2(ch, "L", anchor="ls")
                w, h = core.size
                mask = np.frombuffer(bytes(core), dtype=np.uint8).reshape(h, w) if w and h else \
                    np.zeros((h, w), dtype=np.uint8)
                self._glyphs[ch] = Glyph(mask, left, top, int(advance))
        return self._glyphs[ch]

    def _kerned_pair(self, a: str, b: str) -> bool:
        if (a, b) not in self._kerned:
            self._kerned[a, b] = self.font.getlength(a + b) != self.font.getlength(a) + self.font.getlength(b)
        return self._kerned[a, b]

    def text_mask(self, text: str) -> TextMask | None:
        """`text`'s mask anchored at its left and the font's ascender, or None where the glyphs
        cannot be reused (a fractional advance, a kerned pair, no text)."""
        if not text:
            return None
        glyphs = []
        pen = 0
        for i, ch in enumerate(text):
            g = self.glyph(ch)
            if g is None or (i and self._kerned_pair(text[i - 1], ch)):
                return None
            glyphs.append((g, pen))
            pen += g.advance
        left = min([0] + [pen_x + g.left for g, pen_x in glyphs])
        top = min(self.ascent + g.top for g, _ in glyphs)
        right = max([pen] + [pen_x + g.left + g.mask.shape[1] for g, pen_x in glyphs])
        bottom = max(self.ascent + g.top + g.mask.shape[0] for g, _ in glyphs)
        mask = np.zeros((bottom - top, right - left), dtype=np.uint8)
        reached = 0   # columns left of this are the only ones drawn on so far
        for g, pen_x in glyphs:
            if g.mask.size:
                x, y = pen_x + g.left - left, self.ascent + g.top - top
                region = mask[y:y + g.mask.shape[0], x:x + g.mask.shape[1]]
                # (over nothing, a glyph is itself: a copy, where the blend was half the time)
                region[...] = g.mask if x >= reached else _over(region, g.mask)
                reached = max(reached, x + g.mask.shape[1])
        return TextMask(mask, left, top)


@lru_cache(maxsize=64)
def ink_table(colour: str, under: str) -> np.ndarray:
    """What ImageDraw.bitmap in `colour` makes of an opaque RGBA pixel of colour `under` at each
    coverage 0..255 (256 x 4 bytes), drawn by Pillow itself, so a lookup is its pixels exactly."""
    picture = Image.new("RGBA", (256, 1), under)
    ramp = Image.fromarray(np.arange(256, dtype=np.uint8)[None, :], "L")
    ImageDraw.Draw(picture).bitmap((0, 0), ramp, fill=colour)
    table = np.asarray(picture)[0].copy()
    table.setflags(write=False)
    return table
