"""One 256-colour palette for a whole GIF, and frames mapped onto it.

A GIF frame holds at most 256 colours. Choosing them per frame (median cut) cost twice as long
as drawing the frame, and let a colour shift from frame to frame. The pictures here have few
colours: the scene's own (background, fills, strokes, contacts, text), which are kept exactly,
and their anti-aliased blends, which a median cut of the distinct colours of a few sample
frames covers (each colour counted once: a median cut of the pixels themselves spends its
entries on the background's area, and took as long as drawing 20 frames). Each frame is
then mapped to its nearest palette entry, without dithering (dither noise would
differ from frame to frame and make the GIF flicker and grow).
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

import numpy as np
from PIL import Image

COLOURS = 256
MOST_KEYS = 64   # the scene's own colours kept exactly; the rest of the palette is blends
Box = tuple[int, int, int, int]   # pixels: left, top, right, bottom (Pillow's order)
KNOWN = np.uint16(0x100)   # Mapper.table: this colour's entry is known


def _rgb(colour: str) -> tuple[int, int, int]:
    """'#rrggbb[aa]' (checked by the model) to bytes; alpha is ignored."""
    return tuple(int(colour[i:i + 2], 16) for i in (1, 3, 5))  # type: ignore[return-value]


def _packed(pixels: np.ndarray) -> np.ndarray:
    """RGB or RGBA bytes (..., 3 or 4) as one 24-bit number each, R + G << 8 + B << 16: the
    order of an RGBA pixel read as a little-endian 32-bit number, so that RGBA frames (which
    FrameDrawer makes) are read as they lie in memory, with one mask for the alpha."""
    words = _words(pixels)
    if words is not None:
        return words & np.uint32(0xFFFFFF)
    return (pixels[..., 0].astype(np.uint32) | (pixels[..., 1].astype(np.uint32) << 8)
            | (pixels[..., 2].astype(np.uint32) << 16))


def _words(pixels: np.ndarray) -> np.ndarray | None:
    """RGBA bytes (rows, columns, 4) read as one 32-bit number a pixel (a view), or None where
    they are not laid out so."""
    if pixels.ndim == 3 and pixels.shape[-1] == 4 and pixels.dtype == np.uint8 \
            and pixels.strides[-2:] == (4, 1) and np.little_endian:
        return pixels.view(np.uint32)[..., 0]
    return None


def _unpacked(packed: np.ndarray) -> np.ndarray:
    """_packed's numbers back to RGB (n x 3)."""
    return np.stack([packed & 255, (packed >> 8) & 255, packed >> 16], axis=1)


def choose(keys: Iterable[str], samples: Sequence[Image.Image | np.ndarray]) -> np.ndarray:
    """COLOURS entries (uint8, COLOURS x 3): the distinct `keys` colours first, then the median
    cut of the samples' distinct colours into the entries left."""
    fixed = list(dict.fromkeys(_rgb(c) for c in keys))[:MOST_KEYS]
    entries = list(fixed)
    if samples:
        distinct = _unpacked(_distinct(samples))
        strip = Image.fromarray(distinct.astype(np.uint8)[None, :, :], "RGB")
        cut = strip.quantize(colors=COLOURS - len(fixed), method=Image.Quantize.MEDIANCUT,
                             dither=Image.Dither.NONE)
        flat = cut.getpalette()[:3 * (COLOURS - len(fixed))]
        used = sorted({c for _, c in cut.getcolors(COLOURS)})
        entries += [tuple(flat[3 * i:3 * i + 3]) for i in used]
    entries += [entries[-1] if entries else (0, 0, 0)] * (COLOURS - len(entries))
    return np.array(entries, dtype=np.uint8)


def _distinct(samples: Sequence[Image.Image | np.ndarray]) -> np.ndarray:
    """The samples' distinct colours, _packed, sorted. Only the first pixel of each run of one
    colour along a row is sorted: these pictures are flat colours, so a few per cent of the
    pixels. (A sort of every pixel, a million, took 60 ms; a table of all 2^24 colours
    marked and scanned, 9 ms; this, 1 ms.)"""
    starts = []
    for sample in samples:
        keys = _packed(np.asarray(sample)).reshape(-1)
        starts += [keys[:1], keys[1:][keys[1:] != keys[:-1]]]
    return np.unique(np.concatenate(starts))


class Mapper:
    """Frames onto one palette, each pixel to its nearest entry (in RGB), exactly: a palette
    colour maps to itself. (Pillow's own mapping looks colours up at reduced precision: white
    came out as 253, 253, 253.) Nearest entries are remembered per colour in a table of all
    2^24 colours, so each new colour is looked up once."""

    def __init__(self, entries: np.ndarray) -> None:
        self.entries = entries
        self.flat = entries.astype(np.uint8).tobytes()   # (putpalette takes bytes as they are)
        # KNOWN | entry; 0: not looked up yet (the entry is then the low byte, one cast).
        # (Written whole now, 32 MB in 6 ms: left to the OS's
        # lazy zero pages, each new colour's first write faulted a page in, 12 us a colour,
        # 97 ms of a 3 s billiards GIF.)
        self.table = np.full(1 << 24, 0, dtype=np.uint16)
        self.index: np.ndarray | None = None               # the last image's entries
        # (the entries themselves, the background among them, known from the start: a first
        # frame is then mostly known colours, not 300,000 pixels for np.unique to sort)
        self._learn(np.unique(_packed(entries)))

    def _learn(self, colours: np.ndarray) -> np.ndarray:
        """Nearest entries of new colours: |c - e|^2 = |c|^2 - 2 c.e + |e|^2, and |c|^2 is the
        same for every entry, in whole numbers (int32: at most 3 x 2 x 255^2), channel by
        channel. (Not a product of matrices: numpy hands that to OpenBLAS, whose threads
        then spin between calls, and a GIF of pile took twice the CPU time and wall time.)"""
        rgb = _unpacked(colours).astype(np.int32)
        e = self.entries.astype(np.int32)
        dot = rgb[:, 0:1] * e[:, 0] + rgb[:, 1:2] * e[:, 1] + rgb[:, 2:3] * e[:, 2]
        d = (e * e).sum(axis=1)[None, :] - 2 * dot
        found = np.argmin(d, axis=1).astype(np.uint16) | KNOWN
        self.table[colours] = found
        return found

    def _entries(self, keys: np.ndarray) -> np.ndarray:
        """The palette entries of colours given as _packed numbers. (New colours are learnt
        and put in place: the lookup is not done again.)"""
        index = self.table[keys]
        if not index.all():
            flat = index.reshape(-1)   # (a view: table[keys] is a new array)
            unknown = np.flatnonzero(flat == 0)
            colours, inverse = np.unique(keys.reshape(-1)[unknown], return_inverse=True)
            flat[unknown] = self._learn(colours)[inverse]
        return index.astype(np.uint8)

    def mapped(self, image: Image.Image | np.ndarray,
               changed: list[tuple[int, int, int, int]] | np.ndarray | None = None) -> Image.Image:
        """`image` (RGB, or its RGB or opaque RGBA bytes) as a 'P' image on the palette.
        `changed`: where `image` may differ from the previous one mapped, as boxes (rows j0:j1,
        columns i0:i1; FrameDrawer.changed) or as a mask of square tiles (FrameDrawer.
        changed_tiles); None: map every pixel."""
        self.update(image, changed)
        return self.image()

    def update(self, image: Image.Image | np.ndarray,
               changed: list[tuple[int, int, int, int]] | np.ndarray | None = None) -> Box | None:
        """Map `image` as mapped() does, into `index`; returns where its entries differ from the
        previous image's, as a box (left, top, right, bottom) around them (the whole picture
        for the first), None where none does. (A GIF frame is then that box only: Pillow
        found it by comparing the whole of both pictures, a fifth of writing a frame.)"""
        pixels = np.asarray(image)
        before = self.index
        if changed is None or before is None or before.shape != pixels.shape[:2]:
            self.index = self._entries(_packed(pixels))
            if before is None or before.shape != self.index.shape:
                return (0, 0, self.index.shape[1], self.index.shape[0])
            return _around(*np.nonzero(before != self.index))
        if isinstance(changed, np.ndarray):
            return self._map_tiles(pixels, changed)
        return self._map_boxes(pixels, changed)

    def image(self, box: Box | None = None) -> Image.Image:
        """The last image's entries (within `box`: left, top, right, bottom) as a 'P' image on
        the palette, a copy."""
        index = self.index if box is None else self.index[box[1]:box[3], box[0]:box[2]]
        out = Image.fromarray(index.copy(), "P")   # (a 'P' image would share the array)
        out.putpalette(self.flat, "RGB")
        return out

    def _map_boxes(self, pixels: np.ndarray, changed: list[tuple[int, int, int, int]]) -> Box | None:
        # (all boxes in one lookup: per box, the lookup's dozen numpy calls cost more
        # than its pixels when a frame has a hundred small boxes)
        boxes = [(slice(j0, j1), slice(i0, i1)) for j0, j1, i0, i1 in changed if j0 < j1 and i0 < i1]
        if not boxes:
            return None
        words = _words(pixels)
        keys = (np.concatenate([words[b].ravel() for b in boxes]) & np.uint32(0xFFFFFF)
                if words is not None else
                np.concatenate([_packed(pixels[b]).ravel() for b in boxes]))
        entries = self._entries(keys)
        at = 0
        rows, cols = [], []
        for b in boxes:
            region = self.index[b]
            new = entries[at:at + region.size].reshape(region.shape)
            r, c = np.nonzero(region != new)
            rows.append(r + b[0].start)
            cols.append(c + b[1].start)
            region[...] = new
            at += region.size
        return _around(np.concatenate(rows), np.concatenate(cols))

    def _map_tiles(self, pixels: np.ndarray, mask: np.ndarray) -> Box | None:
        """The tiles of `mask` (tile rows x tile columns; the picture cut into squares of
        height / tile rows pixels, the last row and column of tiles possibly cut short), in
        one gather and one scatter where the tiles fit the picture, else as boxes."""
        h, w = self.index.shape
        size = -(-h // mask.shape[0])
        words = _words(pixels)
        if words is None or h % size or w % size or w != mask.shape[1] * size:
            return self._map_boxes(pixels, [(r * size, min(r * size + size, h), c * size,
                                             min(c * size + size, w)) for r, c in np.argwhere(mask).tolist()])
        if not mask.any():
            return None
        keys = _tiles_of(words, size)[mask]   # (a copy: masked in place)
        keys &= np.uint32(0xFFFFFF)
        tiles = _tiles_of(self.index, size)
        new = self._entries(keys.ravel()).reshape(keys.shape)
        differ = (tiles[mask] != new).view(np.uint8)
        tiles[mask] = new
        return _changed_box(differ, np.argwhere(mask), size)


def _changed_box(differ: np.ndarray, at: np.ndarray, size: int) -> Box | None:
    """The box around the pixels flagged (1) in `differ`, tiles x size x size bytes whose
    tiles lie at rows, columns `at` (in tiles). Where size is 8 a tile's row is read as one
    64-bit number, and its columns as the bytes of the rows OR-ed together: numpy's any() over
    axes of 8 and nonzero() over every pixel took as long as mapping the pixels."""
    if size == 8 and differ.flags.c_contiguous:
        rows = differ.view(np.uint64)[..., 0]                       # tiles x 8
        cols = np.bitwise_or.reduce(rows, axis=1).view(np.uint8).reshape(-1, 8)
        t, r = np.nonzero(rows)
        u, c = np.nonzero(cols)
    else:
        t, r = np.nonzero(differ.any(axis=2))
        u, c = np.nonzero(differ.any(axis=1))
    return _around(at[t, 0] * size + r, at[u, 1] * size + c)


def _around(rows: np.ndarray, cols: np.ndarray) -> Box | None:
    """The box (left, top, right, bottom) around pixels at `rows`, `cols`; None for none."""
    if not rows.size:
        return None
    return (int(cols.min()), int(rows.min()), int(cols.max()) + 1, int(rows.max()) + 1)


def _tiles_of(a: np.ndarray, size: int) -> np.ndarray:
    """A 2-D array whose sides are multiples of `size` as (tile rows, tile columns, size,
    size), a view (indexed by a tile mask, it reads or writes those tiles)."""
    return np.lib.stride_tricks.as_strided(
        a, (a.shape[0] // size, a.shape[1] // size, size, size),
        (a.strides[0] * size, a.strides[1] * size) + a.strides, writeable=True)
