"""Time stamps from cached glyphs (render.glyphs) against Pillow rendering them whole: the same
mask and box for any time and font size, the same pixels in a frame, and Pillow's own path
where the glyphs cannot be reused."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from conftest import require_module as need
from max2code.render import Frame, View
from max2code.render.text import time_stamp

np = need("numpy")
need("skia")
from PIL import Image, ImageDraw, ImageFont  # noqa: E402

from max2code.render import raster  # noqa: E402
from max2code.render.glyphs import GlyphCache  # noqa: E402

times = st.one_of(st.floats(-1e6, 1e6, allow_nan=False), st.floats(0, 60), st.integers(0, 10 ** 5))


def pillow_mask(font, text: str) -> tuple[np.ndarray, tuple[int, int]]:
    core, offset = font.getmask2(text, "L", anchor="la")
    w, h = core.size
    return np.frombuffer(bytes(core), dtype=np.uint8).reshape(h, w), offset


@settings(max_examples=300, deadline=None)
@given(times, st.integers(10, 120))
def test_time_stamp_mask_and_box_are_pillows(t, size) -> None:
    font = raster.font(size)
    text = time_stamp(t)
    got = raster.glyph_cache(size).text_mask(text)
    assert got is not None                      # the default font: whole advances, no kerning
    want, offset = pillow_mask(font, text)
    assert got.box == font.getbbox(text, anchor="la")
    assert (got.left, got.top) == offset
    assert got.mask.shape == want.shape and (got.mask == want).all()


@settings(max_examples=40, deadline=None)
@given(times, st.sampled_from([(320, 240), (640, 480), (1280, 720), (97, 61)]))
def test_a_frames_time_stamp_is_pillows_drawing(t, size) -> None:
    """The whole picture, time stamp drawn from glyphs, against Pillow's ImageDraw.text on the
    background with the same white box."""
    view = View(0, 0, 4, 3, width=size[0], height=size[1], background="#2e6b3a")
    got = np.asarray(raster.frame_image([], Frame(t, ()), view))
    font = raster.font(raster.text_size(view))
    text = time_stamp(t)
    left, top, right, bottom = font.getbbox(text, anchor="la")
    want = Image.new("RGB", size, view.background)
    draw = ImageDraw.Draw(want)
    draw.rectangle((6 + left - 3, 6 + top - 3, 6 + right + 3, 6 + bottom + 3), fill="#ffffff")
    draw.text((6, 6), text, fill="#000000", font=font, anchor="la")
    assert got.tobytes() == want.tobytes()


class Fractional:
    """A font whose advances are not whole pixels, or whose pairs are kerned."""

    def __init__(self, font, advance_off: float = 0.0, kern: float = 0.0) -> None:
        self.font, self.advance_off, self.kern = font, advance_off, kern

    def getmetrics(self):
        return self.font.getmetrics()

    def getlength(self, text: str) -> float:
        return self.font.getlength(text) + self.advance_off * len(text) + self.kern * (len(text) > 1)

    def getmask2(self, *args, **kwargs):
        return self.font.getmask2(*args, **kwargs)


def test_glyphs_that_cannot_be_reused_are_left_to_pillow() -> None:
    font = ImageFont.load_default(size=15)
    assert GlyphCache(font).text_mask("t = 1.000 s") is not None
    assert GlyphCache(Fractional(font, advance_off=0.5)).text_mask("t = 1.000 s") is None
    assert GlyphCache(Fractional(font, kern=-1.0)).text_mask("t = 1.000 s") is None
    assert GlyphCache(font).text_mask("") is None
