"""Contacts drawn all at once (raster.draw_contacts) against drawing them one at a time, ring then
normal, each blended over the last: the same picture (to float rounding), with contacts that
overlap, lie on the picture's edge or outside it, and normals of zero length."""

from __future__ import annotations

import math

from hypothesis import given, settings, strategies as st

from conftest import require_module as need
from max2code.render import Contact, View

np = need("numpy")
need("PIL")
from max2code.render import raster  # noqa: E402

VIEW = View(0, 0, 10, 8, width=100, height=80)   # 10 px per unit
SIZE = 4.0


def one_at_a_time(contacts) -> np.ndarray:
    """The oracle: every pixel of the picture, each contact's ring and then its line blended."""
    canvas = raster.Canvas(VIEW)
    x = np.arange(VIEW.width, dtype=np.float64)[None, :] + 0.5
    y = np.arange(VIEW.height, dtype=np.float64)[:, None] + 0.5
    every = (slice(0, VIEW.height), slice(0, VIEW.width))
    for c in contacts:
        p = VIEW.to_pixel(c.point)
        ring = np.clip(np.minimum(1.25 - np.abs(np.hypot(x - p[0], y - p[1]) - SIZE), 1.5), 0, 1)
        canvas.paint(*every, ring.astype(np.float32), raster.CONTACT_COLOUR)
        n = math.hypot(*c.normal)
        if n > 0:
            q = (p[0] + 2.5 * SIZE * c.normal[0] / n, p[1] - 2.5 * SIZE * c.normal[1] / n)
            dx, dy = q[0] - p[0], q[1] - p[1]
            t = np.clip(((x - p[0]) * dx + (y - p[1]) * dy) / (dx * dx + dy * dy), 0, 1)
            d = np.hypot(x - p[0] - t * dx, y - p[1] - t * dy)
            line = np.clip(np.minimum(1.25 - d, 1.5), 0, 1)
            canvas.paint(*every, line.astype(np.float32), raster.CONTACT_COLOUR)
    return canvas.rgb.transpose(1, 2, 0)


coordinate = st.floats(-3, 13, allow_nan=False)
normal = st.sampled_from([(0.0, 0.0), (0.0, 1.0), (1.0, 0.0), (-0.6, 0.8), (3.0, -4.0)])
contact = st.builds(Contact, st.tuples(coordinate, coordinate), normal)


@settings(max_examples=60, deadline=None)
@given(st.lists(contact, max_size=12), st.booleans())
def test_all_at_once_is_one_at_a_time(contacts, clustered) -> None:
    if clustered:   # overlapping rings and lines
        contacts = [Contact((5 + (c.point[0] - 5) / 10, 4 + (c.point[1] - 5) / 10), c.normal)
                    for c in contacts]
    canvas = raster.Canvas(VIEW)
    raster.draw_contacts(canvas, contacts, SIZE)
    got = canvas.rgb.transpose(1, 2, 0)     # (planar: channel, row, column)
    expected = one_at_a_time(contacts)
    assert np.abs(got - expected).max() < 1e-4
    # painted boxes cover every changed pixel
    changed = (canvas.rgb != raster.Canvas(VIEW).rgb).any(axis=0)
    covered = np.zeros_like(changed)
    for j0, j1, i0, i1 in canvas.painted:
        covered[j0:j1, i0:i1] = True
    assert not (changed & ~covered).any()


def test_a_contact_is_red_at_its_ring_and_along_its_normal() -> None:
    canvas = raster.Canvas(VIEW)
    raster.draw_contacts(canvas, [Contact((5.05, 3.95), (1.0, 0.0))], SIZE)   # pixel (50, 40)
    rgb = canvas.rgb.transpose(1, 2, 0)
    red = np.array(raster.rgba(raster.CONTACT_COLOUR)[:3], dtype=np.float32)
    assert np.allclose(rgb[40 + 4, 50], red, atol=1e-6)       # on the ring, below
    assert np.allclose(rgb[40, 50 + 8], red, atol=1e-6)       # on the normal, past the ring
    assert np.allclose(rgb[40 - 8, 50], 1.0)                  # above: no line, white
    assert np.allclose(rgb[40, 50 - 2], 1.0)                  # inside the ring, behind: white
