"""Written animations decoded again against the frames drawn (render.fidelity): every GIF frame
within a few levels of its RGBA frame, on average and at the bodies, and every MP4 frame within
a PSNR bound; a file whose frames are shifted, repeated or mapped against a stale picture is
caught. The fast paths under them (tile masks for the palette mapping and for restoring a
frame) against the plain ones."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from conftest import require_module as need
from max2code.render import Body, Circle, Contact, Frame, Polygon, Pose, Segment, Style, View
from max2code.render.write import gif_of, mp4_of, write_gif, write_mp4

np = need("numpy")
need("PIL.Image")
need("skia")
from max2code.render import fidelity, palette, raster  # noqa: E402

GIF_MEAN, GIF_BODIES, MP4_PSNR = 0.5, 6.0, 30.0   # as bench/render.py checks
BODIES = [Body(Segment((0, 0.5), (8, 0.5)), Style(stroke="#000000", stroke_width=2)),
          Body(Polygon(((-0.6, -0.4), (0.6, -0.4), (0.0, 0.7))), Style(fill="#dd8452", label="A")),
          Body(Circle(0.9), Style(fill="#4c72b0", stroke="#1b1b1b", stroke_width=1.5)),
          Body(Circle(0.5), Style(fill="#55a868", stroke="#000000"))]


def frames(n: int):
    """Three bodies crossing the picture at different speeds, turning, touching now and then."""
    for i in range(n):
        t = i / 30
        yield Frame(t, (Pose(0, 0), Pose(1 + 3 * t, 2 + t, 2 * t), Pose(7 - 4 * t, 3, -3 * t),
                        Pose(2 + 5 * t, 4.5 - 2 * t, t)),
                    (Contact((1 + 3 * t, 1.0), (0.0, 1.0), (0, 1)),) if i % 4 == 0 else ())


def view(width: int, height: int) -> View:
    return View(0, 0, 8, 6, width=width, height=height)


def drawn(bodies, frames_, v) -> list:
    drawer = raster.FrameDrawer(bodies, v)
    return [drawer.pixels(f).copy() for f in frames_]


def gif_errors(path: Path, want: list, background: str) -> list:
    return [fidelity.frame_error(got, w, background) for got, w in zip(fidelity.gif_frames(path), want)]


@pytest.mark.parametrize("size", [(160, 120), (157, 117)])   # whole tiles, and cut ones
def test_every_gif_frame_is_its_drawn_frame(tmp_path: Path, size) -> None:
    v = view(*size)
    fs = list(frames(30))
    want = drawn(BODIES, fs, v)
    path = tmp_path / "a.gif"
    assert write_gif(path, BODIES, fs, v, 30.0) == 30
    errors = gif_errors(path, want, v.background)
    assert len(errors) == 30
    for e in errors:
        assert e.mean <= GIF_MEAN and e.bodies <= GIF_BODIES, e
    # and the check tells frames apart: each frame against the next is far off
    shifted = gif_errors(path, want[1:], v.background)
    assert sum(e.bodies > GIF_BODIES or e.mean > GIF_MEAN for e in shifted) >= 25


def test_a_gif_mapped_against_a_stale_picture_is_caught(tmp_path: Path) -> None:
    """A palette mapping that skips changed pixels (changed() says nothing changed) keeps the
    first frame's bodies: the check must see it."""
    v = view(160, 120)
    fs = list(frames(12))
    drawer = raster.FrameDrawer(BODIES, v)
    path = tmp_path / "stale.gif"
    gif_of(path, fs, drawer.pixels, 30.0, raster.scene_colours(BODIES, v),
           lambda: np.zeros((15, 20), dtype=bool))
    errors = gif_errors(path, drawn(BODIES, fs, v), v.background)
    assert errors[0].bodies <= GIF_BODIES
    # (every frame then equals the first, and Pillow stores a run of equal frames as one)
    assert len(errors) < 12 or max(e.bodies for e in errors[1:]) > GIF_BODIES


def test_every_mp4_frame_is_its_drawn_frame_and_a_wrong_order_is_caught(tmp_path: Path) -> None:
    need("imageio_ffmpeg")
    v = view(160, 120)
    fs = list(frames(30))
    want = drawn(BODIES, fs, v)
    path = tmp_path / "a.mp4"
    assert write_mp4(path, BODIES, fs, v, 30.0) == 30
    psnrs = [fidelity.psnr(got, w) for got, w in zip(fidelity.mp4_frames(path), want)]
    assert len(psnrs) == 30 and min(psnrs) >= MP4_PSNR
    # frames out of order (each pair swapped): the check sees them
    swapped = [want[i ^ 1] for i in range(30)]
    wrong = tmp_path / "wrong.mp4"
    assert mp4_of(wrong, range(30), swapped.__getitem__, 30.0, v.background) == 30
    psnrs = [fidelity.psnr(got, w) for got, w in zip(fidelity.mp4_frames(wrong), want)]
    assert sum(p < MP4_PSNR for p in psnrs) >= 25


def test_frame_error_and_psnr_measure_what_they_say() -> None:
    want = np.zeros((4, 5, 4), dtype=np.uint8)
    want[..., 3] = 255
    want[1, 1, :3] = 200                  # one body pixel
    got = want[..., :3].copy()
    got[0, 0] = (0, 6, 0)                 # background pixel 6 off
    got[1, 1] = (200, 190, 200)           # body pixel 10 off
    e = fidelity.frame_error(got, want, "#000000")
    assert e == fidelity.FrameError(mean=16 / 20, bodies=10.0, worst=10)
    assert fidelity.psnr(want[..., :3], want) == float("inf")
    assert fidelity.psnr(got, want) == pytest.approx(10 * np.log10(255 ** 2 / ((36 + 100) / 60)))


@st.composite
def repaints(draw):
    """A picture, a mask of 4 x 4 tiles, and the picture repainted inside the masked tiles."""
    rows, cols = draw(st.integers(1, 5)), draw(st.integers(1, 6))
    seed = draw(st.integers(0, 2 ** 32 - 1))
    rng = np.random.default_rng(seed)
    colours = rng.integers(0, 256, (6, 3))          # few colours, as a drawing has
    before = colours[rng.integers(0, 6, (rows * 4, cols * 4))].astype(np.uint8)
    mask = rng.random((rows, cols)) < draw(st.floats(0, 1))
    after = before.copy()
    fresh = rng.integers(0, 256, (rows * 4, cols * 4, 3)).astype(np.uint8)
    big = np.repeat(np.repeat(mask, 4, axis=0), 4, axis=1)
    after[big] = fresh[big]
    return before, after, mask


def rgba(rgb: np.ndarray) -> np.ndarray:
    return np.concatenate([rgb, np.full(rgb.shape[:2] + (1,), 255, dtype=np.uint8)], axis=2)


@settings(max_examples=80, deadline=None)
@given(repaints(), st.booleans())
def test_mapping_only_the_changed_tiles_is_mapping_everything(case, as_rgba) -> None:
    before, after, mask = case
    entries = palette.choose(["#ffffff", "#000000"], [before, after])
    cast = rgba if as_rgba else (lambda a: a)
    mapper = palette.Mapper(entries)
    mapper.mapped(cast(before))
    got = np.asarray(mapper.mapped(cast(after), mask))
    want = np.asarray(palette.Mapper(entries).mapped(cast(after)))
    assert (got == want).all()


@settings(max_examples=60, deadline=None)
@given(st.integers(1, 4), st.integers(1, 4), st.integers(0, 2 ** 32 - 1))
def test_tile_view_reads_and_writes_the_tiles_of_a_mask(rows, cols, seed) -> None:
    rng = np.random.default_rng(seed)
    t = raster.TILE
    a = rng.integers(0, 256, (rows * t, cols * t, 4)).astype(np.uint8)
    b = rng.integers(0, 256, a.shape).astype(np.uint8)
    mask = rng.random((rows, cols)) < 0.5
    want = a.copy()
    for r, c in np.argwhere(mask):
        want[r * t:(r + 1) * t, c * t:(c + 1) * t] = b[r * t:(r + 1) * t, c * t:(c + 1) * t]
    raster.tile_view(a)[mask] = raster.tile_view(b)[mask]
    assert (a == want).all()
