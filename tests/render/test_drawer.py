"""The fast paths of an animation against the plain one: FrameDrawer's frames are frame_image's
byte for byte (bodies that stay, move, stop and start again; labels, contacts, time stamps),
its `changed` boxes cover every pixel that changed, and a GIF on one shared palette stays within
a few levels of the true frames, with the scene's own colours exact and every frame kept."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from conftest import require_module as need
from max2code.render import Body, Circle, Contact, Frame, Polygon, Pose, Segment, Style, View, write_gif
from max2code.render.write import gif_timing

np = need("numpy")
Image = need("PIL.Image")
need("skia")
from max2code.render import palette, raster  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
VIEW = View(0, 0, 8, 6, width=96, height=72)
SHAPES = [Circle(0.7), Polygon(((-0.6, -0.4), (0.6, -0.4), (0.0, 0.7))),
          Segment((-1.0, 0.0), (1.0, 0.3)), Circle(0.4, (0.2, 0.1))]
STYLES = [Style(fill="#4c72b0"), Style(fill="#dd8452", label="A"),
          Style(fill="#9a9a9a", stroke="#3a3a3a", stroke_width=2.0, spoke=False),
          Style(fill="#55a86880", stroke="#000000")]

poses = st.builds(Pose, st.floats(-1, 9), st.floats(-1, 7), st.floats(-4, 4))


@st.composite
def animations(draw):
    """Bodies, and frames in which each body keeps its last pose or takes a new one."""
    n = draw(st.integers(1, 5))
    bodies = [Body(SHAPES[draw(st.integers(0, 3))], STYLES[draw(st.integers(0, 3))])
              for _ in range(n)]
    current = [draw(poses) for _ in range(n)]
    frames = []
    for k in range(draw(st.integers(1, 7))):
        current = [draw(poses) if draw(st.booleans()) else p for p in current]
        contacts = tuple(Contact((draw(st.floats(0, 8)), draw(st.floats(0, 6))), (0.0, 1.0), (0, 0))
                         for _ in range(draw(st.integers(0, 1))))
        frames.append(Frame(k / 10, tuple(current), contacts))
    return bodies, frames


@settings(max_examples=60, deadline=None)
@given(animations())
def test_drawer_frames_are_frame_image_and_changed_covers_the_change(case) -> None:
    bodies, frames = case
    drawer = raster.FrameDrawer(bodies, VIEW)
    before = None
    for frame in frames:
        rgba = drawer.pixels(frame)
        assert (rgba[..., 3] == 255).all()                  # opaque
        got = np.ascontiguousarray(rgba[..., :3])
        assert got.tobytes() == raster.frame_image(bodies, frame, VIEW).tobytes()
        if before is not None and drawer.changed is not None:
            outside = np.ones(got.shape[:2], dtype=bool)
            for j0, j1, i0, i1 in drawer.changed:
                outside[j0:j1, i0:i1] = False
            assert (got[outside] == before[outside]).all()
        before = got


def scene(name: str, seconds: float):
    pytest.importorskip("cffi")
    from max2code.engine.frames import render_bodies, run_frames
    from max2code.engine.scenefile import build_world, load
    from max2code.commands.sim import picture_view
    s = load(str(ROOT / "examples" / "scenes" / f"{name}.toml"))
    world = build_world(s)
    frames = list(run_frames(world, seconds, 30.0))
    bodies = render_bodies(world)
    return bodies, frames, picture_view(s, bodies, frames, 640, 480)


def test_pinball_frames_are_frame_image_and_the_walls_are_painted_once() -> None:
    bodies, frames, view = scene("pinball", 0.5)
    drawer = raster.FrameDrawer(bodies, view)
    for frame in frames:
        assert drawer.image(frame).tobytes() == raster.frame_image(bodies, frame, view).tobytes()
    assert len(drawer.layer_poses) == 12          # 7 rails and 5 bumpers stay put
    assert drawer.layers_painted == 2             # the background, then the walls once


def test_gif_on_one_palette_keeps_every_frame_and_stays_close(tmp_path: Path) -> None:
    bodies, frames, view = scene("pinball", 1.0)
    out = tmp_path / "pinball.gif"
    kept = write_gif(out, bodies, frames, view, 30.0)
    assert kept == len(frames) == 31
    gif = Image.open(out)
    assert gif.n_frames == 31 and gif.size == (640, 480)
    assert sum(gif_timing(len(frames), 30.0)[1]) == 1000 + 30   # 31 frames of 1/30 s
    for k in (0, 15, 30):
        gif.seek(k)
        got = np.asarray(gif.convert("RGB")).astype(int)
        want = np.asarray(raster.frame_image(bodies, frames[k], view)).astype(int)
        err = np.abs(got - want).max(axis=2)
        assert err.mean() < 0.25                      # measured: 0.04 (per-frame median cut: 0.01)
        assert np.percentile(err, 99.9) <= 12         # measured: 5 (median cut: 3)
        exact = (want == 255).all(axis=2)             # the background, a scene colour, kept exactly
        assert exact.mean() > 0.5 and (got[exact] == 255).all()


def test_mapper_maps_palette_colours_to_themselves() -> None:
    entries = palette.choose(["#ffffff", "#000000", "#4c72b0"], [])
    pixels = np.array([[[255, 255, 255], [0, 0, 0], [0x4c, 0x72, 0xb0], [250, 250, 250]]], dtype=np.uint8)
    got = np.asarray(palette.Mapper(entries).mapped(pixels).convert("RGB"))
    assert got[0, :3].tolist() == pixels[0, :3].tolist()
    assert got[0, 3].tolist() == [255, 255, 255]        # nearest


boxes = st.lists(st.tuples(st.integers(0, 71), st.integers(1, 72), st.integers(0, 95), st.integers(1, 96))
                 .filter(lambda b: b[0] < b[1] and b[2] < b[3]), max_size=12)


@settings(max_examples=100, deadline=None)
@given(boxes)
def test_merged_boxes_cover_the_boxes_once(given_boxes) -> None:
    def mask(bs):
        m = np.zeros((72, 96), dtype=int)
        for j0, j1, i0, i1 in bs:
            m[j0:j1, i0:i1] += 1
        return m
    got = raster.merged(given_boxes, 72, 96)
    covered = mask(got)
    assert covered.max(initial=0) <= 1                        # no pixel twice
    assert (covered[mask(given_boxes) > 0] == 1).all()         # every pixel of the boxes
    assert len(got) <= max(len(given_boxes), 1) * 72 // raster.TILE   # few: runs of tiles
    # and no more than the tiles the boxes touch
    t = raster.TILE
    tiles = mask([(j0 // t * t, min(-(-j1 // t) * t, 72), i0 // t * t, min(-(-i1 // t) * t, 96))
                  for j0, j1, i0, i1 in given_boxes])
    assert not (covered.astype(bool) & ~tiles.astype(bool)).any()
