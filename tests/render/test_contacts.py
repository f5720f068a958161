"""Contacts (raster.draw_contacts) against their geometry: a ring of radius SIZE around each
contact point and its normal as a line CONTACT_REACH rings long, both CONTACT_WIDTH pixels wide.
Pixels on a ring's or a line's centre are red, pixels clear of every ring and line untouched, a
contact found many times is drawn as once and in any order the same picture, and the painted
boxes cover every changed pixel; contacts overlap, lie on the picture's edge or outside it, and
have normals of zero length."""

from __future__ import annotations

import math

from hypothesis import given, settings, strategies as st

from conftest import require_module as need
from max2code.render import Contact, View

np = need("numpy")
need("PIL")
need("skia")
from max2code.render import raster  # noqa: E402

VIEW = View(0, 0, 10, 8, width=100, height=80)   # 10 px per unit
SIZE = 4.0
RED = (0xd6, 0x27, 0x28)
# a pixel's square reaches 0.71 from its centre; contacts are placed to 1/16 pixel and their
# normals to half a degree (0.09 pixels at the end of the line): farther from every ring and line
# than this, a pixel is untouched
CLEAR = raster.CONTACT_WIDTH / 2 + 0.71 + 0.07 + 0.09


def drawn(contacts) -> tuple[np.ndarray, raster.Canvas]:
    canvas = raster.Canvas(VIEW)
    raster.draw_contacts(canvas, contacts, SIZE)
    return canvas.rgb().astype(int), canvas


def distances(contacts) -> tuple[np.ndarray, np.ndarray]:
    """Each pixel centre's distance to the nearest ring's centre line and to the nearest normal's
    line (inf where there is none), in pixels: the oracle, independent of raster."""
    x = np.arange(VIEW.width, dtype=np.float64)[None, :] + 0.5
    y = np.arange(VIEW.height, dtype=np.float64)[:, None] + 0.5
    ring = np.full((VIEW.height, VIEW.width), np.inf)
    line = np.full((VIEW.height, VIEW.width), np.inf)
    for c in contacts:
        p = VIEW.to_pixel(c.point)
        ring = np.minimum(ring, np.abs(np.hypot(x - p[0], y - p[1]) - SIZE))
        n = math.hypot(*c.normal)
        if n > 0:
            dx, dy = raster.CONTACT_REACH * SIZE * c.normal[0] / n, -raster.CONTACT_REACH * SIZE * c.normal[1] / n
            t = np.clip(((x - p[0]) * dx + (y - p[1]) * dy) / (dx * dx + dy * dy), 0, 1)
            line = np.minimum(line, np.hypot(x - p[0] - t * dx, y - p[1] - t * dy))
    return ring, line


coordinate = st.floats(-3, 13, allow_nan=False)
normal = st.sampled_from([(0.0, 0.0), (0.0, 1.0), (1.0, 0.0), (-0.6, 0.8), (3.0, -4.0)])
contact = st.builds(Contact, st.tuples(coordinate, coordinate), normal)


@settings(max_examples=60, deadline=None)
@given(st.lists(contact, max_size=12), st.booleans())
def test_contacts_are_their_rings_and_lines(contacts, clustered) -> None:
    if clustered:   # overlapping rings and lines
        contacts = [Contact((5 + (c.point[0] - 5) / 10, 4 + (c.point[1] - 5) / 10), c.normal)
                    for c in contacts]
    got, canvas = drawn(contacts)
    ring, line = distances(contacts)
    near = np.minimum(ring, line)
    assert (got[near > CLEAR] == 255).all()                         # clear of them: untouched
    on = near < 0.1                                                 # on a centre line: red
    coverage = (255 - got[..., 1]) / (255 - RED[1])
    assert (coverage[on] > 0.6).all()
    assert (got[coverage > 0.999] == RED).all()
    # painted boxes cover every changed pixel
    changed = (got != 255).any(axis=2)
    covered = np.zeros_like(changed)
    for j0, j1, i0, i1 in canvas.painted:
        covered[j0:j1, i0:i1] = True
    assert not (changed & ~covered).any()


@settings(max_examples=30, deadline=None)
@given(st.lists(contact, min_size=1, max_size=6), st.integers(2, 5), st.randoms())
def test_a_contact_found_again_is_drawn_once_and_order_does_not_matter(contacts, copies, rnd) -> None:
    once = drawn(contacts)[0]
    again = contacts * copies
    rnd.shuffle(again)
    assert (drawn(again)[0] == once).all()


def test_a_contact_is_red_at_its_ring_and_along_its_normal() -> None:
    got = drawn([Contact((5.05, 3.95), (1.0, 0.0))])[0]        # pixel (50, 40)
    assert tuple(got[40 + 4, 50]) == RED                        # on the ring, below
    assert tuple(got[40, 50 + 8]) == RED                        # on the normal, past the ring
    assert tuple(got[40 - 8, 50]) == (255, 255, 255)            # above: no line, white
    assert tuple(got[40, 50 - 2]) == (255, 255, 255)            # inside the ring, behind: white
