"""Pictures to files: PNG (one frame or a numbered folder), animated GIF, MP4, SVG.

Every file is written to a temporary name beside it and renamed (output.replaced_atomically), so
an interrupted or failed run leaves the previous file as it was. Frames may come from a generator:
MP4, PNG folders and GIFs are written as they come (a GIF frame by frame, each the box where it
differs from the one before: render.gifstream). A simulation's animations are drawn by
one raster.FrameDrawer (the same pixels as frame_image, faster), and a GIF's
frames share one palette (render.palette).

Timing. An MP4 has `fps` frames per second, exactly. A GIF stores delays in hundredths of a
second and browsers treat delays under 0.02 s as 0.1 s, so above 50 frames per second every k-th
frame is kept (k = ceil(fps / 50)) and delays are rounded cumulatively: the GIF's total duration
is the frames' duration to within 0.01 s, and never drifts.
"""

from __future__ import annotations

import math
import os
import re
import shutil
import tempfile
from collections.abc import Callable, Iterable, Sequence
from pathlib import Path
from typing import TypeVar

from ..diagnostics import Pos, error
from ..output import holds, replaced_atomically, write_if_changed
from .model import Body, Frame, RenderModelError, View

GIF_MAX_FPS = 50
PNG_NAME = "frame-{:05d}.png"
_PNG_NAME = re.compile(r"frame-(\d{5,})\.png")
F = TypeVar("F")


class RenderUnavailable(RuntimeError):
    """A library that this kind of output needs is not installed."""


def drawing_modules() -> tuple[object, object]:
    """raster (numpy, Skia and Pillow), imported on first use so the model works without them."""
    try:
        from . import raster
        from PIL import Image
    except ImportError as exc:
        raise RenderUnavailable(f"pictures need numpy, skia-python and Pillow ({exc.name} is missing): "
                                "pip install 'max2code[render]'") from None
    return raster, Image


# x264's settings for flat-shaded animation (docs/pictures.md, measured on bullet, paddles and
# billiards-break at 640x480, 91 frames): "ultrafast" took 0.24-0.27 s of ffmpeg's CPU where
# "veryfast" took 0.39-0.50 s and the default "medium" 0.6-0.7 s; "-tune animation" and a
# constant rate factor of 20 keep the file 1.3-1.4 times today's "veryfast" at crf 10 (ultrafast
# at crf 10: 2.2-2.6 times) at the same fidelity: PSNR of the decoded frames against the drawn
# ones 40.1-45.5 dB against 40.0-45.2 dB, bounded by yuv420p's halved colour resolution, not by
# the rate factor (crf 16 to 20 moved it by 0.3 dB).
MP4_X264 = ("-preset", "ultrafast", "-tune", "animation", "-crf", "20")
GIF_PALETTE_SAMPLES = 4   # frames whose colours choose a GIF's palette, evenly spaced


def check_fps(fps: float) -> float:
    if isinstance(fps, bool) or not isinstance(fps, (int, float)) or not (math.isfinite(fps) and fps > 0):
        raise RenderModelError(f"fps must be a positive number, not {fps!r}")
    return float(fps)


def write_png(path: str | os.PathLike, bodies: Sequence[Body], frame: Frame, view: View) -> None:
    raster, _ = drawing_modules()
    _save_png(path, raster.frame_image(bodies, frame, view))


def write_png_dir(folder: str | os.PathLike, bodies: Sequence[Body], frames: Iterable[Frame],
                  view: View) -> list[Path]:
    """The frames as a folder of PNGs (png_dir_of below)."""
    raster, _ = drawing_modules()
    return png_dir_of(folder, frames, raster.FrameDrawer(bodies, view).image)


def _save_png(path: str | os.PathLike, image) -> None:
    with replaced_atomically(os.fspath(path)) as tmp:
        image.save(tmp, format="PNG")


def png_dir_of(folder: str | os.PathLike, frames: Iterable[F], draw: Callable[[F], object]) -> list[Path]:
    """frame-00000.png, frame-00001.png, ... in `folder` (made if missing). Numbered frames left
    from an earlier, longer run are removed, so the folder holds exactly this run (other files
    are not touched). The frames are drawn into a hidden folder inside it and moved in only
    once all are drawn: a run that fails or is interrupted while drawing leaves the folder as
    it was, never half this run's frames among the last one's. Returns the paths written."""
    out = Path(folder)
    try:
        out.mkdir(parents=True, exist_ok=True)
        # (inside the folder itself: the same filesystem, so the frames move in by rename, even
        # where the folder is a mount point or a link to another filesystem)
        stage = Path(tempfile.mkdtemp(prefix=".max2code-frames-", dir=out))
    except OSError as exc:
        raise error(Pos(str(out), 1, 1), f"cannot make the frame folder: {exc.strerror}") from None
    try:
        names = []
        for i, frame in enumerate(frames):
            names.append(PNG_NAME.format(i))
            _save_png(stage / names[-1], draw(frame))
        written = []
        for name in names:
            try:
                # (an unchanged frame keeps its time stamp)
                if not (out / name).is_file() or not holds(str(out / name), (stage / name).read_bytes()):
                    os.replace(stage / name, out / name)
            except OSError as exc:
                raise error(Pos(str(out / name), 1, 1),
                            f"cannot write output: {exc.strerror}") from None
            written.append(out / name)
    finally:
        shutil.rmtree(stage, ignore_errors=True)
    for old in out.iterdir():
        m = _PNG_NAME.fullmatch(old.name)
        if m and int(m.group(1)) >= len(written) and old.is_file():
            old.unlink()
    return written


def gif_timing(count: int, fps: float) -> tuple[int, list[int]]:
    """(keep every k-th frame, delay of each kept frame in ms, multiples of 10) for `count`
    frames at `fps`: delays of at least 20 ms, summing to the kept frames' duration."""
    fps = check_fps(fps)
    step = max(1, math.ceil(fps / GIF_MAX_FPS - 1e-9))
    kept = range(0, count, step)
    ends = [min(i + step, count) for i in kept]
    cs = [round(100 * e / fps) for e in ends]
    delays = [10 * (b - a) for a, b in zip([0] + cs[:-1], cs)]
    return step, [max(d, 20) for d in delays]


def write_gif(path: str | os.PathLike, bodies: Sequence[Body], frames: Iterable[Frame], view: View,
              fps: float) -> int:
    """An animated GIF that loops; returns the number of frames kept (see the module's timing)."""
    raster, _ = drawing_modules()
    drawer = raster.FrameDrawer(bodies, view)
    return gif_of(path, frames, drawer.pixels, fps, raster.scene_colours(bodies, view),
                  lambda: drawer.changed_tiles)


def gif_of(path: str | os.PathLike, frames: Iterable[F], draw: Callable[[F], object], fps: float,
           keys: Sequence[str] = (), changed: Callable[[], list | None] = lambda: None) -> int:
    """An animated GIF of draw(frame) (an RGB Pillow image, or its RGB or opaque RGBA bytes) for
    each frame: frames that the timing drops are never drawn. One palette for all (render.palette): the colours
    `keys` exactly, and the blends in GIF_PALETTE_SAMPLES kept frames drawn ahead (draw must
    depend on its frame only). changed(): where the last drawing may differ from the one
    before, as boxes or a tile mask (palette.Mapper.update; None: anywhere), so only those
    are mapped to the palette again, and the frame written is the box where its entries
    changed (render.gifstream: the bytes Pillow's own writer makes of the whole frames)."""
    drawing_modules()
    from . import palette
    from .gifstream import GifStream
    fps = check_fps(fps)
    frames = list(frames)   # (Frame objects are small; their pictures are not kept)
    step, delays = gif_timing(len(frames), fps)
    kept = frames[::step]
    if not kept:
        raise RenderModelError("an animation needs at least one frame")
    picks = sorted({round(i * (len(kept) - 1) / max(GIF_PALETTE_SAMPLES - 1, 1))
                    for i in range(GIF_PALETTE_SAMPLES)})
    # (.copy(): FrameDrawer.pixels reuses its buffer)
    mapper = palette.Mapper(palette.choose(keys, [draw(kept[i]).copy() for i in picks]))
    with replaced_atomically(os.fspath(path)) as tmp, open(tmp, "wb") as out:
        gif = GifStream(out)
        for i, frame in enumerate(kept):
            box = mapper.update(draw(frame), changed() if i else None)
            gif.add(mapper.image(box) if box is not None else None,
                    box[:2] if box is not None else None, delays[i])
        gif.close()
    return len(kept)


def write_mp4(path: str | os.PathLike, bodies: Sequence[Body], frames: Iterable[Frame], view: View,
              fps: float, x264: Sequence[str] = MP4_X264) -> int:
    """An H.264 MP4 of the frames (mp4_of below)."""
    raster, _ = drawing_modules()
    return mp4_of(path, frames, raster.FrameDrawer(bodies, view).pixels, fps,
                  view.background, x264)


def mp4_of(path: str | os.PathLike, frames: Iterable[F], draw: Callable[[F], object], fps: float,
           background: str = "#000000", x264: Sequence[str] = MP4_X264) -> int:
    """An H.264 MP4 (yuv420p, so every player takes it) of draw(frame) for each frame, through
    the ffmpeg binary shipped in the imageio-ffmpeg wheel, encoded by x264 with the options
    `x264` (MP4_X264); odd picture sizes are padded by one pixel of background, as H.264 in
    4:2:0 needs even ones. Frames go to ffmpeg as they are drawn (opaque RGBA, the drawer's own
    buffer written to the pipe as it lies: no RGB copy). Returns the number of frames."""
    drawing_modules()
    fps = check_fps(fps)
    try:
        import imageio.v2 as imageio
        import imageio_ffmpeg  # noqa: F401  (the ffmpeg binary)
        import numpy as np
    except ImportError as exc:
        raise RenderUnavailable(f"MP4 needs imageio and imageio-ffmpeg ({exc.name} is missing): "
                                "pip install 'max2code[render]'") from None
    fill = [int(background[i:i + 2], 16) for i in (1, 3, 5)]
    count = 0
    writer = None
    with replaced_atomically(os.fspath(path)) as tmp:
        try:
            for frame in frames:
                pixels = np.asarray(draw(frame))
                h, w = pixels.shape[:2]
                if w % 2 or h % 2:   # (RGB, or opaque RGBA: ffmpeg takes either)
                    full = np.empty((h + h % 2, w + w % 2, pixels.shape[2]), dtype=np.uint8)
                    full[:] = (fill + [255])[:pixels.shape[2]]
                    full[:h, :w] = pixels
                    pixels = full
                if writer is None:
                    writer = imageio.get_writer(tmp, format="FFMPEG", mode="I", fps=fps,
                                                codec="libx264", pixelformat="yuv420p",
                                                quality=None, macro_block_size=1,
                                                ffmpeg_log_level="error",
                                                output_params=list(x264))
                writer.append_data(pixels)
                count += 1
        finally:
            if writer is not None:
                writer.close()
        if count == 0:
            raise RenderModelError("an animation needs at least one frame")
    return count


def write_svg(path: str | os.PathLike, bodies: Sequence[Body], frame: Frame, view: View) -> None:
    from .svg import svg_text
    write_if_changed(os.fspath(path), svg_text(bodies, frame, view))


def save(path: str | os.PathLike, bodies: Sequence[Body], frames: Sequence[Frame], view: View,
         fps: float = 30.0) -> None:
    """By the file's suffix: .gif and .mp4 animate every frame; .png and .svg show the last one
    (the state at the end of the run)."""
    suffix = Path(path).suffix.lower()
    if suffix == ".gif":
        write_gif(path, bodies, frames, view, fps)
    elif suffix == ".mp4":
        write_mp4(path, bodies, frames, view, fps)
    elif suffix in (".png", ".svg"):
        if not frames:
            raise RenderModelError("no frame to draw")
        (write_png if suffix == ".png" else write_svg)(path, bodies, frames[-1], view)
    else:
        raise RenderModelError(f"unknown picture type {suffix!r}: use .png, .svg, .gif or .mp4")
