"""An animated GIF written frame by frame, each frame the box where it differs from the last.

Pillow's writer (Image.save with append_images) takes every frame at once and finds where each
differs from the one before by comparing the two whole pictures; a palette.Mapper already knows
(it maps only the changed tiles again, and sees which entries change), so here each frame is
given with its box and encoded as it comes: no comparison of whole pictures, no copy of every
frame held to the end. The file is the one Pillow writes for the same frames (save_all, loop=0,
disposal=1, optimize=False; tests/render/test_write.py compares the bytes): its header, then per
frame a graphic control extension and the image in Pillow's own encoding (GifImagePlugin.
getdata), with the palette repeated as a local colour table after the first frame as Pillow
does; a frame that equals the one before adds its delay to it; a GIF of one distinct frame is
left to Pillow whole, which writes it otherwise (interlaced).
"""

from __future__ import annotations

import struct
from typing import BinaryIO

from PIL import GifImagePlugin, Image

DISPOSAL = 1   # each frame stays beneath the next (the next draws only its box over it)


class GifStream:
    """Frames appended one by one (add), the file finished by close()."""

    def __init__(self, out: BinaryIO) -> None:
        self.out = out
        self.pending: list | None = None   # [image, offset, delay]: its delay may still grow
        self.started = False

    def add(self, image: Image.Image, offset: tuple[int, int] | None, delay: int) -> None:
        """`image` ('P', with its palette) drawn at `offset`, shown `delay` ms; offset None: the
        frame equals the one before (image is then ignored)."""
        if offset is None and self.pending is not None:
            self.pending[2] += delay
            return
        if self.pending is not None:
            self._write(*self.pending)
        self.pending = [image, offset or (0, 0), delay]

    def _write(self, image: Image.Image, offset: tuple[int, int], delay: int) -> None:
        first = not self.started
        if first:
            self.out.write(_header(image))
            self.started = True
        # (after the first frame Pillow gives each frame its palette again, as a local table)
        for chunk in GifImagePlugin.getdata(image, offset, duration=delay, disposal=DISPOSAL,
                                            include_color_table=not first):
            self.out.write(chunk)

    def close(self) -> None:
        if self.pending is None:
            raise ValueError("a GIF needs at least one frame")
        image, _, delay = self.pending
        if not self.started:   # one distinct frame: Pillow's own single-frame GIF
            image.save(self.out, format="GIF", save_all=True, duration=[delay], loop=0,
                       disposal=DISPOSAL, optimize=False)
            return
        self._write(*self.pending)
        self.out.write(b";")


def _header(image: Image.Image) -> bytes:
    """GIF89a, the picture's size, the first frame's palette as the global colour table (256
    entries), background entry 0, and the loop-forever extension (NETSCAPE2.0, 0 loops)."""
    palette = bytes(image.palette.palette)[:768].ljust(768, b"\0")
    return (b"GIF89a" + struct.pack("<HHBBB", image.width, image.height, 0x80 | 7, 0, 0) + palette
            + b"!\xff\x0bNETSCAPE2.0\x03\x01" + struct.pack("<H", 0) + b"\0")
