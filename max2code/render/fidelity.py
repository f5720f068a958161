"""How close a written animation's frames are to the frames drawn: each GIF or MP4 frame decoded
again (Pillow, imageio's ffmpeg) and compared with the RGBA frame it was made from.

The writers take shortcuts for speed (one palette for a whole GIF, only the changed tiles mapped
to it again; x264's fastest preset), so bench/render.py and the tests check the result, not the
shortcut: a frame mapped against a stale picture, a frame dropped or repeated, or a colour
table gone wrong shows up here as a large error.

A GIF frame is compared pixel by pixel, in levels of 255 (the largest of the three channels'
differences): on average over the picture, and on average over the bodies (the pixels drawn
SOLID levels or more from the background, where a wrong frame differs most). An MP4 stores
colour at half resolution (yuv420p) and is lossy, so it is compared by PSNR, the usual measure
of a video's fidelity, frame by frame.
"""

from __future__ import annotations

import math
import os
from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np

SOLID = 96   # levels of 255 from the background: a pixel of a body, not of its soft edge


@dataclass(frozen=True)
class FrameError:
    """One decoded frame against its drawn frame, in levels of 255."""
    mean: float     # over every pixel
    bodies: float   # over the pixels drawn SOLID or more from the background (0 if none)
    worst: int      # the largest


def rgb_of(background: str) -> np.ndarray:
    return np.array([int(background[i:i + 2], 16) for i in (1, 3, 5)])


def frame_error(got: np.ndarray, want: np.ndarray, background: str) -> FrameError:
    """`got` (a decoded frame, RGB) against `want` (the drawn frame, RGB or RGBA)."""
    want = np.asarray(want)[..., :3].astype(np.int16)
    err = np.abs(np.asarray(got)[..., :3].astype(np.int16) - want).max(axis=2)
    bodies = np.abs(want - rgb_of(background)).max(axis=2) >= SOLID
    return FrameError(float(err.mean()), float(err[bodies].mean()) if bodies.any() else 0.0,
                      int(err.max()))


def psnr(got: np.ndarray, want: np.ndarray) -> float:
    """Peak signal-to-noise ratio of `got` against `want` (RGB), in dB (inf: equal)."""
    d = np.asarray(got)[..., :3].astype(np.float64) - np.asarray(want)[..., :3]
    mse = float((d * d).mean())
    return math.inf if mse == 0 else 10 * math.log10(255 ** 2 / mse)


def gif_frames(path: str | os.PathLike) -> Iterator[np.ndarray]:
    """Each frame of a GIF as a viewer shows it (RGB), decoded by Pillow."""
    from PIL import Image
    with Image.open(path) as im:
        for k in range(im.n_frames):
            im.seek(k)
            yield np.asarray(im.convert("RGB"))


def mp4_frames(path: str | os.PathLike) -> Iterator[np.ndarray]:
    """Each frame of a video (RGB), decoded by imageio's ffmpeg."""
    import imageio.v2 as imageio
    reader = imageio.get_reader(path)
    try:
        yield from reader
    finally:
        reader.close()
