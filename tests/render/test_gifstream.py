"""GIFs written frame by frame (render.gifstream, palette.Mapper.update's boxes) against Pillow's
own writer given every whole frame: the same bytes, for moving, still and single-frame runs, at
picture sizes whose tiles fit and do not; and Mapper.update's box against comparing the two
whole pictures."""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from conftest import require_module as need
from max2code.render import Body, Circle, Frame, Pose, Segment, Style, View, write_gif
from max2code.render.write import gif_timing

np = need("numpy")
need("skia")
from PIL import Image  # noqa: E402

from max2code.render import palette, raster  # noqa: E402

BODIES = [Body(Segment((0, 0.5), (10, 0.5)), Style(stroke="#000000", stroke_width=2)),
          Body(Circle(1.0), Style(fill="#ff0000", stroke="#202020", label="b")),
          Body(Circle(0.5), Style(fill="#3060c0", stroke=None))]


def run(xs: list[float], fps: float) -> list[Frame]:
    """The big ball at each x in turn (a repeated x: a frame like the one before), the small
    one still."""
    return [Frame(i / fps, (Pose(0, 0), Pose(x, 2.5, x), Pose(5, 1, 0))) for i, x in enumerate(xs)]


def pillows_gif(bodies, frames, view, fps) -> bytes:
    """The old way: every kept frame mapped whole to write_gif's palette, and Pillow's writer
    finding where each differs from the last."""
    step, delays = gif_timing(len(frames), fps)
    kept = frames[::step]
    picks = sorted({round(i * (len(kept) - 1) / 3) for i in range(4)})
    pictures = [np.asarray(raster.frame_image(bodies, f, view)) for f in kept]
    mapper = palette.Mapper(palette.choose(raster.scene_colours(bodies, view),
                                           [pictures[i] for i in picks]))
    images = [palette.Mapper(mapper.entries).mapped(p) for p in pictures]
    out = io.BytesIO()
    images[0].save(out, format="GIF", save_all=True, append_images=images[1:], duration=delays,
                   loop=0, disposal=1, optimize=False)
    return out.getvalue()


@pytest.mark.parametrize("size", [(200, 100), (97, 61)])
@pytest.mark.parametrize("xs, fps", [
    ([1 + 0.37 * i for i in range(20)], 30.0),            # moving every frame
    ([1, 1, 2, 2, 2, 3, 3.5, 3.5, 1], 25.0),              # still for a while, and back
    ([4.0] * 6, 30.0),                                    # one distinct frame: Pillow writes it
    ([1 + 0.1 * i for i in range(12)], 120.0)])           # frames dropped by the timing
@pytest.mark.parametrize("show_time", [False, True])
def test_the_bytes_are_pillows(tmp_path: Path, size, xs, fps, show_time) -> None:
    view = View(0, 0, 10, 5, width=size[0], height=size[1], show_time=show_time)
    frames = run(xs, fps)
    write_gif(tmp_path / "a.gif", BODIES, frames, view, fps)
    assert (tmp_path / "a.gif").read_bytes() == pillows_gif(BODIES, frames, view, fps)


@pytest.mark.parametrize("size", [(200, 100), (97, 61)])
def test_update_boxes_what_changed(size) -> None:
    """The box Mapper.update returns is the box around the entries that differ from the last
    picture's (found here by comparing the two whole index arrays), None for none."""
    view = View(0, 0, 10, 5, width=size[0], height=size[1])
    frames = run([1, 1.2, 1.2, 6, 9.5, 9.5, 0.3], 30.0)
    drawer = raster.FrameDrawer(BODIES, view)
    pictures = [drawer.pixels(f).copy() for f in frames]
    entries = palette.choose(raster.scene_colours(BODIES, view), pictures[:2])
    mapper, whole = palette.Mapper(entries), palette.Mapper(entries)
    drawer = raster.FrameDrawer(BODIES, view)
    last = None
    for i, frame in enumerate(frames):
        box = mapper.update(drawer.pixels(frame), drawer.changed_tiles if i else None)
        now = np.asarray(whole.mapped(pictures[i]))
        assert (mapper.index == now).all()
        if last is None:
            assert box == (0, 0, size[0], size[1])
        else:
            rows, cols = np.nonzero(now != last)
            assert box == ((cols.min(), rows.min(), cols.max() + 1, rows.max() + 1) if rows.size else None)
        last = now


@pytest.mark.parametrize("seed", range(5))
def test_distinct_colours_are_every_pixels(seed) -> None:
    """palette._distinct (run starts only) against np.unique of every pixel, on pictures of
    runs of few colours, a run crossing from one row into the next, and a lone last pixel."""
    rng = np.random.default_rng(seed)
    pictures = []
    for _ in range(3):
        colours = rng.integers(0, 256, (5, 4), dtype=np.uint8)
        runs = np.repeat(rng.integers(0, 5, 40), rng.integers(1, 30, 40))[:17 * 23]
        picture = colours[np.resize(runs, 17 * 23)].reshape(17, 23, 4)
        picture[-1, -1] = rng.integers(0, 256, 4, dtype=np.uint8)
        pictures.append(picture)
    want = np.unique(np.concatenate([p[..., :3].reshape(-1, 3) for p in pictures]), axis=0)
    got = palette._unpacked(palette._distinct(pictures))
    assert sorted(map(tuple, got.tolist())) == sorted(map(tuple, want.tolist()))


def test_each_colour_maps_to_its_nearest_entry() -> None:
    """Mapper's entries against the nearest by squared distance in Python's whole numbers (the
    first of equals), for random colours and a random palette with repeated entries."""
    rng = np.random.default_rng(7)
    entries = rng.integers(0, 256, (256, 3), dtype=np.uint8)
    entries[200:] = entries[:56]                         # ties: the first entry wins
    pixels = rng.integers(0, 256, (1, 3000, 3), dtype=np.uint8)
    got = np.asarray(palette.Mapper(entries).mapped(pixels))[0]
    table = entries.astype(int).tolist()
    for colour, index in zip(pixels[0].astype(int).tolist(), got.tolist()):
        d = [sum((c - e) ** 2 for c, e in zip(colour, entry)) for entry in table]
        assert index == d.index(min(d))
