"""Files: frame counts and durations read back with Pillow and imageio, the picture inside them,
atomic replacement, and paths that are data."""

from __future__ import annotations

import math
import os
from pathlib import Path

import pytest

from conftest import require_module as need
from max2code.diagnostics import Max2CodeError
from max2code.render import (Body, Circle, Frame, Pose, RenderModelError, Segment, Style, View, save,
                             write_gif, write_mp4, write_png, write_png_dir)
from max2code.render.write import gif_timing

np = need("numpy")
Image = need("PIL.Image")

BODIES = [Body(Segment((0, 0.5), (10, 0.5)), Style(stroke="#000000", stroke_width=2)),
          Body(Circle(1.0), Style(fill="#ff0000", stroke=None, spoke=False))]
VIEW = View(0, 0, 10, 5, width=200, height=100, show_time=False)   # 20 px per unit


def frames(n: int, fps: float):
    """The ball rolls from x = 1 to x = 9 over the n frames."""
    for i in range(n):
        yield Frame(i / fps, (Pose(0, 0), Pose(1 + 8 * i / max(n - 1, 1), 2.5, -i / fps)))


def red_centre(rgb) -> tuple[float, float]:
    a = np.asarray(rgb).astype(int)
    red = (a[..., 0] > 200) & (a[..., 1] < 80) & (a[..., 2] < 80)
    ys, xs = np.nonzero(red)
    return xs.mean() + 0.5, ys.mean() + 0.5


def gif_frames(path: Path) -> tuple[list, list[int]]:
    im = Image.open(path)
    out, delays = [], []
    for k in range(im.n_frames):
        im.seek(k)
        out.append(im.convert("RGB"))
        delays.append(im.info["duration"])
    return out, delays


@pytest.mark.parametrize("n,fps,kept", [(90, 30, 90), (25, 24, 25), (120, 60, 60), (50, 50, 50), (7, 144, 3)])
def test_gif_frame_count_and_duration(tmp_path: Path, n: int, fps: float, kept: int) -> None:
    path = tmp_path / "run.gif"
    assert write_gif(path, BODIES, frames(n, fps), VIEW, fps) == kept
    images, delays = gif_frames(path)
    assert len(images) == kept
    assert min(delays) >= 20 and all(d % 10 == 0 for d in delays)
    assert abs(sum(delays) / 1000 - n / fps) <= 0.01 + 1e-9 or kept * 20 > 1000 * n / fps
    # the ball is where the frame puts it: first and last kept frames
    step = math.ceil(fps / 50)
    for k in (0, kept - 1):
        i = k * step
        x = 1 + 8 * i / max(n - 1, 1)
        cx, cy = red_centre(images[k])
        assert abs(cx - 20 * x) < 0.5 and abs(cy - 50) < 0.5


def test_gif_timing_never_drifts() -> None:
    step, delays = gif_timing(3000, 30)          # 100 s at 30 fps: 33.3 ms a frame
    assert step == 1 and set(delays) == {30, 40} and sum(delays) == 100_000
    step, delays = gif_timing(600, 240)
    assert step == 5 and len(delays) == 120 and set(delays) == {20, 30} and sum(delays) == 2500


def test_mp4_frame_count_rate_and_picture(tmp_path: Path) -> None:
    imageio = need("imageio.v2")
    path = tmp_path / "run.mp4"
    view = View(0, 0, 10, 5, width=201, height=101, show_time=False)     # odd: padded to even
    assert write_mp4(path, BODIES, frames(45, 30), view, 30) == 45
    reader = imageio.get_reader(path)
    try:
        meta = reader.get_meta_data()
        got = [f for f in reader]  # noqa: C416  (len(reader) is inf: list() would try to size it)
    finally:
        reader.close()
    assert meta["codec"] == "h264" and meta["fps"] == 30.0 and meta["size"] == (202, 102)
    assert meta["duration"] == pytest.approx(1.5, abs=0.04)
    assert len(got) == 45
    for i in (0, 22, 44):
        x = 1 + 8 * i / 44
        cx, cy = red_centre(got[i])
        assert abs(cx - view.to_pixel((x, 2.5))[0]) < 1.0 and abs(cy - view.to_pixel((x, 2.5))[1]) < 1.0


def test_png_and_png_dir(tmp_path: Path) -> None:
    out = tmp_path / "frames"
    out.mkdir()
    (out / "frame-00009.png").write_bytes(b"stale")          # from a longer run: removed
    (out / "notes.txt").write_text("mine")                   # not ours: kept
    paths = write_png_dir(out, BODIES, frames(4, 10), VIEW)
    assert [p.name for p in paths] == [f"frame-{i:05d}.png" for i in range(4)]
    assert sorted(p.name for p in out.iterdir()) == [f"frame-{i:05d}.png" for i in range(4)] + ["notes.txt"]
    im = Image.open(paths[3])
    assert im.format == "PNG" and im.size == (200, 100)
    assert red_centre(im.convert("RGB"))[0] == pytest.approx(180, abs=0.5)
    assert not [p for p in out.iterdir() if p.name.startswith(".max2code-")]


def test_failure_leaves_the_old_file_and_no_temporary(tmp_path: Path) -> None:
    for name in ("a.gif", "a.mp4", "a.png"):
        path = tmp_path / name
        path.write_bytes(b"previous")

        def broken():
            yield from frames(3, 10)
            yield Frame(1.0, (Pose(0, 0),))                  # one pose for two bodies

        with pytest.raises(RenderModelError):
            if name == "a.png":
                write_png(path, BODIES, Frame(0, (Pose(0, 0),)), VIEW)
            else:
                (write_gif if name == "a.gif" else write_mp4)(path, BODIES, broken(), VIEW, 10)
        assert path.read_bytes() == b"previous"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.gif", "a.mp4", "a.png"]


def test_unwritable_place_is_a_diagnostic(tmp_path: Path) -> None:
    with pytest.raises(Max2CodeError) as info:
        write_png(tmp_path / "missing" / "x.png", BODIES, next(frames(1, 1)), VIEW)
    assert str(info.value).startswith(f"{tmp_path / 'missing' / 'x.png'}:1:1: error: cannot write output")
    (tmp_path / "dir.gif").mkdir()
    with pytest.raises(Max2CodeError):
        write_gif(tmp_path / "dir.gif", BODIES, frames(2, 10), VIEW, 10)
    assert (tmp_path / "dir.gif").is_dir()


@pytest.mark.parametrize("name", ["-rf.gif", "a b'\"; rm -rf x.mp4", "$(touch pwned).png", "ünï cødé ✓.gif",
                                  "--help.mp4", "x.svg"])
def test_hostile_file_names_are_just_names(tmp_path: Path, name: str) -> None:
    cwd = os.getcwd()
    os.chdir(tmp_path)
    try:
        save(name, BODIES, list(frames(3, 10)), VIEW, fps=10)
        assert sorted(os.listdir(".")) == [name]
    finally:
        os.chdir(cwd)


def test_save_refuses_unknown_types_and_no_frames(tmp_path: Path) -> None:
    with pytest.raises(RenderModelError):
        save(tmp_path / "x.jpg", BODIES, list(frames(2, 10)), VIEW)
    with pytest.raises(RenderModelError):
        save(tmp_path / "x.gif", BODIES, [], VIEW)
    with pytest.raises(RenderModelError):
        write_gif(tmp_path / "x.gif", BODIES, frames(2, 10), VIEW, fps=0)
    assert list(tmp_path.iterdir()) == []


def test_png_dir_interrupted_while_drawing_keeps_the_last_run(tmp_path: Path) -> None:
    """The frames go to a hidden folder first: a failure (or an interrupt) while drawing leaves
    the folder exactly as the last run left it, not half of each run's frames; a second run
    over the same frames keeps their time stamps."""
    out = tmp_path / "frames"
    first = write_png_dir(out, BODIES, frames(4, 10), VIEW)
    before = {p.name: (p.read_bytes(), p.stat().st_mtime_ns) for p in first}

    def broken():
        yield from frames(6, 20)                             # other pictures, more of them
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        write_png_dir(out, BODIES, broken(), VIEW)
    assert {p.name: (p.read_bytes(), p.stat().st_mtime_ns) for p in out.iterdir()} == before
    assert [p.name for p in tmp_path.iterdir()] == ["frames"]
    assert not [p for p in out.iterdir() if p.name.startswith(".")]  # no hidden folder left
    again = write_png_dir(out, BODIES, frames(4, 10), VIEW)
    assert {p.name: (p.read_bytes(), p.stat().st_mtime_ns) for p in again} == before
