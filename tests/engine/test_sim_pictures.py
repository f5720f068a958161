"""From the engine to pictures: shapes as the engine holds them (rounding kept), poses copied in
bulk, a view that holds every frame, and `max2code sim`'s behaviour when a picture cannot be made
(a clear line and a non-zero exit, no partial file) or a window cannot be opened (a note, and
the run goes on)."""

from __future__ import annotations

import math
import sys
from pathlib import Path

import pytest

from conftest import require_module as need

ROUNDED = [(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)]

# a red ball leaving a short floor at 4 m/s: by t = 2 it is 8 m to the right of everything
# that the first frame shows
TRAVEL = """\
name = "travel"
until = 2

[[bodies]]
name = "floor"
kind = "static"
shape = "segment"
points = [[-1, -1], [1, -1]]

[[bodies]]
name = "ball"
shape = "circle"
radius = 0.25
position = [0, 0]
velocity = [4, 0]
color = "#ff0000"
"""


def test_rendered_shapes_keep_their_radius(engine) -> None:
    from max2code.engine.frames import render_body
    from max2code.render import Capsule, Circle, Polygon, Segment

    w = engine.World()
    box = w.add_polygon(ROUNDED, radius=0.2, position=(5.0, 0.0))
    cap = w.add_segment((0.0, 3.0), (2.0, 3.0), radius=0.3)
    wall = w.add_segment((0.0, -3.0), (2.0, -3.0))
    ball = w.add_circle((-5.0, 0.0), 0.7)
    assert render_body(w.body(box)).shape == Polygon(tuple(ROUNDED), 0.2)
    assert render_body(w.body(cap)).shape == Capsule((0.0, 3.0), (2.0, 3.0), 0.3)
    assert render_body(w.body(wall)).shape == Segment((0.0, -3.0), (2.0, -3.0))
    assert render_body(w.body(ball)).shape == Circle(0.7)


def test_rounded_polygon_is_drawn_rounded(engine) -> None:
    """A pixel 0.1 outside the square's edge lies inside its 0.2 rounding: it is filled."""
    need("PIL")
    from max2code.engine.frames import frame, render_bodies
    from max2code.render import View
    from max2code.render.raster import frame_image

    w = engine.World()
    w.add_polygon(ROUNDED, radius=0.2, color="#00ff00", kind="static")
    view = View(-1, -1, 1, 1, width=200, height=200)   # 100 pixels per unit
    image = frame_image(render_bodies(w), frame(w, 0.0), view)
    assert image.getpixel((100, 100 - 60)) == (0, 255, 0)       # y = 0.6: in the rounding
    assert image.getpixel((100, 100 - 75)) == (255, 255, 255)   # y = 0.75: beyond it
    corner = 0.5 + 0.2 / math.sqrt(2) - 0.03                    # just inside the rounded corner
    assert image.getpixel((round(100 + 100 * corner), round(100 - 100 * corner))) == (0, 255, 0)
    outside = 0.5 + 0.2 / math.sqrt(2) + 0.04                   # outside it (a sharp corner's box)
    assert image.getpixel((round(100 + 100 * outside), round(100 - 100 * outside))) == (255, 255, 255)


def test_poses_in_bulk_equal_each_pose(engine) -> None:
    w = engine.World(gravity=(0.0, -2.0))
    w.add_segment((-9.0, -9.0), (9.0, -9.0))
    w.add_circle((1.0, 2.0), 0.1, velocity=(3.0, 1.0), omega=0.5)
    w.add_polygon(ROUNDED, position=(-3.0, 0.0), velocity=(0.0, 1.0), omega=2.0, angle=0.3)
    for t in (0.0, 0.25, 1.0):
        want = [w.pose(i, t) for i in range(len(w.bodies))]
        assert w.poses(t) == want
        assert w.poses_array(t).tolist() == [list(p) for p in want]
    w.add_circle((6.0, 6.0), 0.5)                               # the buffer grows with the world
    assert w.poses(1.0)[-1] == (6.0, 5.0, 0.0)  # falls 2 t^2 / 2 and len(w.poses(1.0)) == 4
    assert engine.World().poses() == []


def _sim(argv: list[str], capsys: pytest.CaptureFixture) -> tuple[int, str]:
    from max2code.commands import sim
    rc = sim.main(argv)
    return rc, capsys.readouterr().err


def test_view_holds_every_frame(engine, tmp_path: Path, capsys: pytest.CaptureFixture) -> None:
    need("PIL")
    from PIL import Image
    scene = tmp_path / "travel.toml"
    scene.write_text(TRAVEL)
    png = tmp_path / "end.png"
    rc, err = _sim([str(scene), "--png", str(png), "--fps", "10", "--size", "400x100"], capsys)
    assert rc == 0, err
    image = Image.open(png).convert("RGB")
    data = image.tobytes()
    red = sum(1 for i in range(0, len(data), 3) if data[i:i + 3] == b"\xff\x00\x00")
    assert red > 20          # the ball at x = 8, where it ends, is in the picture of the last frame
    # and the view holds every body in every frame
    from max2code.engine.frames import render_bodies, run_frames
    from max2code.engine.scenefile import build_world, load
    from max2code.render.fit import world_extent
    from max2code.commands.sim import picture_view
    world = build_world(load(str(scene)))
    frames = list(run_frames(world, 2.0, 10.0))
    bodies = render_bodies(world)
    view = picture_view(load(str(scene)), bodies, frames, 400, 100)
    for f in frames:
        for body, pose in zip(bodies, f.poses):
            x0, y0, x1, y1 = world_extent(body.shape, pose)
            assert view.xmin <= x0 and x1 <= view.xmax and view.ymin <= y0 and y1 <= view.ymax


def test_live_without_pygame_goes_on(engine, tmp_path: Path, capsys: pytest.CaptureFixture,
                                     monkeypatch: pytest.MonkeyPatch) -> None:
    need("PIL")
    monkeypatch.setitem(sys.modules, "pygame", None)        # import pygame now raises ImportError
    scene = tmp_path / "travel.toml"
    scene.write_text(TRAVEL)
    png = tmp_path / "end.png"
    events = tmp_path / "events.jsonl"
    rc, err = _sim([str(scene), "--live", "--png", str(png), "--events", str(events)], capsys)
    assert rc == 0, err
    assert "note:" in err and "pygame" in err and "error" not in err
    assert png.is_file() and events.is_file()
    rc, err = _sim([str(scene), "--live"], capsys)           # the window alone: still a run
    assert rc == 0 and "note:" in err


def test_picture_writer_errors_are_reported(engine, tmp_path: Path, capsys: pytest.CaptureFixture,
                                            monkeypatch: pytest.MonkeyPatch) -> None:
    need("PIL")
    scene = tmp_path / "travel.toml"
    scene.write_text(TRAVEL)
    blocker = tmp_path / "a-file"
    blocker.write_text("x")
    for option in ("--gif", "--png", "--svg"):
        target = blocker / f"out{option.replace('--', '.')}"   # its folder is a file
        rc, err = _sim([str(scene), "--until", "0.2", option, str(target)], capsys)
        assert rc == 1 and f"{target}:1:1: error: cannot write output" in err, err
        assert "Traceback" not in err
    # a library failing below the atomic writer (a full disk, say): reported, nothing left
    from max2code.render import write
    gif = tmp_path / "out.gif"
    gif.write_bytes(b"the previous run's")

    def full(*args, **kwargs):
        raise OSError(28, "No space left on device", str(gif))

    monkeypatch.setattr(write, "write_gif", full)
    rc, err = _sim([str(scene), "--until", "0.2", "--gif", str(gif)], capsys)
    assert rc == 1 and f"{gif}: error: cannot write output: No space left on device" in err, err
    assert gif.read_bytes() == b"the previous run's"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a-file", "out.gif", "travel.toml"]


def test_every_picture_kind(engine, tmp_path: Path, capsys: pytest.CaptureFixture) -> None:
    """--gif, --mp4, --png-dir and --svg: one frame per 1/fps from 0 to T inclusive (11 here)."""
    need("PIL")
    from PIL import Image
    scene = tmp_path / "travel.toml"
    scene.write_text(TRAVEL)
    common = [str(scene), "--until", "1", "--fps", "10", "--size", "160x120"]
    rc, err = _sim(common + ["--gif", str(tmp_path / "a.gif")], capsys)
    assert rc == 0, err
    with Image.open(tmp_path / "a.gif") as gif:
        assert gif.n_frames == 11 and gif.size == (160, 120)
    rc, err = _sim(common + ["--png-dir", str(tmp_path / "frames")], capsys)
    assert rc == 0, err
    assert sorted(p.name for p in (tmp_path / "frames").iterdir()) == [f"frame-{i:05d}.png" for i in range(11)]
    rc, err = _sim(common + ["--svg", str(tmp_path / "end.svg")], capsys)
    assert rc == 0, err
    text = (tmp_path / "end.svg").read_text()
    assert text.lstrip().startswith(("<svg", "<?xml")) and 'width="160"' in text and "#ff0000" in text
    need("imageio_ffmpeg")
    rc, err = _sim(common + ["--mp4", str(tmp_path / "a.mp4")], capsys)
    assert rc == 0, err
    import imageio.v2 as imageio
    with imageio.get_reader(str(tmp_path / "a.mp4"), format="FFMPEG") as video:
        assert sum(1 for _ in video) == 11
