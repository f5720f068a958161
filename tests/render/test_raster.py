"""Pixels against exact geometry: every pixel whose square lies inside a shape is exactly its
colour, every pixel whose square lies outside is untouched; the band between is anti-aliased.
A pixel's square reaches half its diagonal (0.71 pixels) from its centre: EDGE adds 0.04 for
Skia's curves, which it draws as short straight pieces. Skia samples a pixel's coverage on a
sub-grid, so a pixel just inside a curve may be one level of 255 short of its colour (solid)."""

from __future__ import annotations

import math

import pytest

from conftest import require_module as need
from max2code.render import (Body, Capsule, Circle, Compound, Contact, Frame, Polygon, Pose,
                             RenderModelError, Segment, Style, View)

np = need("numpy")
need("PIL")
need("skia")
from max2code.render.raster import frame_image  # noqa: E402

WHITE = (255, 255, 255)
EDGE = math.sqrt(0.5) + 0.04   # pixels


def solid(img, mask, colour) -> bool:
    """Every pixel of `mask` is `colour`, to one level of 255."""
    return bool((np.abs(img[mask] - np.array(colour)) <= 1).all())
VIEW = View(0, 0, 10, 10, width=200, height=200, show_time=False)   # 20 px per unit


def pixels(bodies, poses, view=VIEW, contacts=(), time=0.0):
    return np.asarray(frame_image(bodies, Frame(time, tuple(poses), tuple(contacts)), view)).astype(int)


def centres(view=VIEW):
    """Pixel centres in world coordinates (independent of View.to_pixel)."""
    s = 20.0
    i = np.arange(view.width) + 0.5
    j = np.arange(view.height) + 0.5
    return (i / s)[None, :] + 0 * j[:, None], (10 - j / s)[:, None] + 0 * i[None, :]


@pytest.mark.parametrize("x,y,r", [(4.1, 5.7, 1.3), (5.0, 5.0, 0.2), (0.3, 9.9, 2.0)])
def test_circle_covers_the_disc(x: float, y: float, r: float) -> None:
    img = pixels([Body(Circle(r), Style(fill="#ff0000", stroke=None, spoke=False))], [Pose(x, y, 1.0)])
    wx, wy = centres()
    d = (np.hypot(wx - x, wy - y) - r) * 20          # distance in pixels
    inside, outside = d <= -EDGE, d >= EDGE
    assert inside.any()
    assert solid(img, inside, (255, 0, 0))
    assert (img[outside] == WHITE).all()
    # coverage adds up to the disc's area (when all of it is in the picture), to within a
    # tenth of a pixel along the rim (measured: 0.07 for r = 26 px, 0.08 for 4 px)
    coverage = (255 - img[..., 1]).sum() / 255
    if 0.5 < x - r and x + r < 9.5 and 0.5 < y - r and y + r < 9.5:
        assert abs(coverage - math.pi * (20 * r) ** 2) < 0.1 * 2 * math.pi * 20 * r


@pytest.mark.parametrize("angle", [0.0, 0.3, 0.7, math.pi / 4, 2.0, -1.1])
def test_rotated_square_has_its_vertices_where_the_rotation_puts_them(angle: float) -> None:
    half = 1.5
    cx, cy = 5.2, 4.7
    square = Polygon(((-half, -half), (half, -half), (half, half), (-half, half)))
    img = pixels([Body(square, Style(fill="#0000ff", stroke=None))], [Pose(cx, cy, angle)])
    c, s = math.cos(angle), math.sin(angle)
    verts = [(cx + c * u - s * v, cy + s * u + c * v) for u, v in ((-half, -half), (half, -half), (half, half), (-half, half))]
    wx, wy = centres()
    # signed distance to each edge's line (positive outside, counter-clockwise vertices)
    dist = []
    for (ax, ay), (bx, by) in zip(verts, verts[1:] + verts[:1]):
        ex, ey = bx - ax, by - ay
        n = math.hypot(ex, ey)
        dist.append(((wx - ax) * ey - (wy - ay) * ex) / n * 20)
    outer = np.max(dist, axis=0)
    assert solid(img, outer <= -EDGE, (0, 0, 255))
    assert (img[outer >= EDGE] == WHITE).all()
    coverage = (255 - img[..., 0]) / 255
    assert coverage.sum() == pytest.approx((2 * half * 20) ** 2, rel=2e-3)
    # each vertex: the covered pixel farthest towards it lies within a pixel of it
    for vx, vy in verts:
        ux, uy = (vx - cx) / math.hypot(vx - cx, vy - cy), (vy - cy) / math.hypot(vx - cx, vy - cy)
        reach = ((wx - cx) * ux + (wy - cy) * uy)[coverage > 0.05].max() * 20
        assert abs(reach - math.hypot(vx - cx, vy - cy) * 20) < 1.0


@pytest.mark.parametrize("angle", [0.0, 1.0, 2.5, -2.0])
def test_circle_spoke_shows_the_rotation(angle: float) -> None:
    r = 2.0
    img = pixels([Body(Circle(r), Style(fill="#00ff00", stroke="#000000", stroke_width=3))], [Pose(5, 5, angle)])
    to_px = lambda wx, wy: (int(wy_px(wy)), int(wx * 20))  # noqa: E731
    wy_px = lambda wy: (10 - wy) * 20  # noqa: E731
    along = to_px(5 + 0.6 * r * math.cos(angle), 5 + 0.6 * r * math.sin(angle))
    against = to_px(5 - 0.6 * r * math.cos(angle), 5 - 0.6 * r * math.sin(angle))
    assert tuple(img[along]) == (0, 0, 0)
    assert tuple(img[against]) == (0, 255, 0)


def test_segment_is_a_line_of_the_stroke_width() -> None:
    img = pixels([Body(Segment((1, 5), (9, 5)), Style(stroke="#000000", stroke_width=2))], [Pose(0, 0)])
    column = img[:, 100, 0]
    # y = 5 is the border between pixel rows 99 and 100: a 2 px line covers both fully
    assert (column[99:101] == 0).all()
    assert (column[:98] == 255).all() and (column[102:] == 255).all()
    assert (img[:, 10:15] == WHITE).all()           # x < 1 - 0.1: beyond the end cap's reach


def test_capsule_is_every_point_within_its_radius_of_the_segment() -> None:
    img = pixels([Body(Capsule((-2, 0), (2, 0), 1.0), Style(fill="#ff00ff", stroke=None))],
                 [Pose(5, 5, math.pi / 3)])
    wx, wy = centres()
    c, s = math.cos(math.pi / 3), math.sin(math.pi / 3)
    a, b = np.array((5 - 2 * c, 5 - 2 * s)), np.array((5 + 2 * c, 5 + 2 * s))
    t = np.clip(((wx - a[0]) * (b - a)[0] + (wy - a[1]) * (b - a)[1]) / 16.0, 0, 1)
    d = (np.hypot(wx - (a[0] + t * (b - a)[0]), wy - (a[1] + t * (b - a)[1])) - 1.0) * 20
    assert solid(img, d <= -EDGE, (255, 0, 255))
    assert (img[d >= EDGE] == WHITE).all()


def test_a_compound_is_the_union_of_its_parts_painted_once() -> None:
    """Two overlapping discs and a square on one body, half-transparent: every pixel inside
    any part is the fill blended once over white (the overlap is not painted twice), every
    pixel outside all parts is untouched, and a thin segment part is drawn as a line."""
    shape = Compound((Circle(1.5, (-1.0, 0.0)), Circle(1.5, (1.0, 0.0)),
                      Polygon(((-0.5, 1.0), (0.5, 1.0), (0.5, 3.0), (-0.5, 3.0))),
                      Segment((0.0, -1.5), (0.0, -3.5))))
    img = pixels([Body(shape, Style(fill="#0000ff80", stroke=None, spoke=False))],
                 [Pose(5, 5, 0.4)])
    wx, wy = centres()
    c, s = math.cos(0.4), math.sin(0.4)
    bx, by = c * (wx - 5) + s * (wy - 5), -s * (wx - 5) + c * (wy - 5)   # body coordinates
    d = np.minimum(np.hypot(bx + 1, by) - 1.5, np.hypot(bx - 1, by) - 1.5)
    box = np.maximum(np.abs(bx) - 0.5, np.abs(by - 2.0) - 1.0)
    d = np.minimum(d, box) * 20
    a = 0x80 / 255
    assert solid(img, d <= -EDGE, (round(255 * (1 - a)), round(255 * (1 - a)), 255))
    line = (np.abs(bx) * 20 <= 0.2) & (by < -1.6) & (by > -3.4)
    assert (img[(d >= EDGE) & ~(np.abs(bx) * 20 < 1.5)] == WHITE).all()
    assert (img[line] != WHITE).any(axis=-1).all()
    with pytest.raises(RenderModelError, match="at least one part"):
        Compound(())
    with pytest.raises(RenderModelError, match="part 0"):
        Compound((shape,))


def test_alpha_fill_blends_and_later_bodies_are_on_top() -> None:
    bodies = [Body(Circle(2), Style(fill="#000000", stroke=None, spoke=False)),
              Body(Circle(1), Style(fill="#0000ff80", stroke=None, spoke=False))]
    img = pixels(bodies, [Pose(5, 5), Pose(5, 5)])
    a = 0x80 / 255
    assert tuple(img[100, 100]) == (0, 0, round(255 * a))                  # blue over black
    img = pixels(bodies[1:], [Pose(5, 5)])
    assert tuple(img[100, 100]) == (round(255 * (1 - a)), round(255 * (1 - a)), 255)  # over white


def test_time_stamp_is_drawn_in_the_corner_only() -> None:
    body = [Body(Circle(0.5), Style(spoke=False))]
    view = View(0, 0, 10, 10, width=200, height=200, show_time=True)
    a = pixels(body, [Pose(5, 5)], view, time=1.0)
    b = pixels(body, [Pose(5, 5)], view, time=2.5)
    off = pixels(body, [Pose(5, 5)], VIEW, time=1.0)
    differs = (a != b).any(axis=2)
    ys, xs = np.nonzero(differs)
    assert len(ys) > 10 and ys.max() < 30 and xs.max() < 120
    assert (a[:30, :120] != off[:30, :120]).any() and (a[30:] == off[30:]).all()
    assert (off[:30, :120] == WHITE).all()


def test_contact_highlight_is_at_the_contact_point() -> None:
    img = pixels([Body(Segment((0, 2), (10, 2)), Style(stroke="#000000"))], [Pose(0, 0)],
                 contacts=[Contact((7.0, 2.0), (0.0, 1.0))])
    red = (img == (0xd6, 0x27, 0x28)).all(axis=2) | ((img[..., 0] > 150) & (img[..., 1] < 120))
    ys, xs = np.nonzero(red)
    assert len(xs) > 5
    assert abs(xs.mean() + 0.5 - 140) < 3                    # x = 7 -> 140 px
    assert ys.max() + 0.5 <= 160 + 3 + 2                     # ring around y = 2 -> 160 px, normal points up
    assert ys.min() < 160 - 4


def test_hostile_labels_are_drawn_as_text() -> None:
    for label in ["</text><script>alert(1)</script>", "\x00\x1b[31m\ud800", "&amp; \u202e" * 50, "a\nb\tc"]:
        img = pixels([Body(Circle(1.5), Style(fill="#ffffff", label=label, spoke=False))], [Pose(5, 5)])
        assert (img[85:115, 75:125] < 128).any()            # some dark text near the body's centre


def test_rounded_polygon_is_every_point_within_its_radius() -> None:
    tri = ((-1.0, -1.0), (1.5, -1.0), (0.0, 1.2))
    r = 0.4
    img = pixels([Body(Polygon(tri, radius=r), Style(fill="#00ffff", stroke=None))], [Pose(5, 5, 0.8)])
    c, s = math.cos(0.8), math.sin(0.8)
    verts = [(5 + c * u - s * v, 5 + s * u + c * v) for u, v in tri]
    wx, wy = centres()

    def seg(a, b):
        ex, ey = b[0] - a[0], b[1] - a[1]
        t = np.clip(((wx - a[0]) * ex + (wy - a[1]) * ey) / (ex * ex + ey * ey), 0, 1)
        return np.hypot(wx - a[0] - t * ex, wy - a[1] - t * ey)

    edge = np.min([seg(verts[i], verts[(i + 1) % 3]) for i in range(3)], axis=0)
    inside = np.ones_like(edge, dtype=bool)
    for i in range(3):
        (ax, ay), (bx, by) = verts[i], verts[(i + 1) % 3]
        inside &= (bx - ax) * (wy - ay) - (by - ay) * (wx - ax) >= 0      # counter-clockwise
    d = np.where(inside, -edge, edge) * 20 - r * 20
    assert solid(img, d <= -EDGE, (0, 255, 255))
    assert (img[d >= EDGE] == WHITE).all()


@pytest.mark.parametrize("r,turn", [(1000.0, 0.3), (1e6, -0.2), (1e9, 0.0), (1e9, 2.0)])
def test_a_huge_circle_keeps_its_edge(r: float, turn: float) -> None:
    """A planet under a zoomed-in view: Skia's 32-bit floats put a circle of radius 1e9 pixels
    over the whole picture; its edge must cross the picture where the geometry puts it."""
    x, y = 5 + (r - 0.2) * math.sin(turn), 5 - (r - 0.2) * math.cos(turn)   # edge 0.2 past the middle
    img = pixels([Body(Circle(r), Style(fill="#ff0000", stroke=None, spoke=False))], [Pose(x, y)])
    wx, wy = centres()
    d = (np.hypot(wx - x, wy - y) - r) * 20
    assert (d <= -EDGE).sum() > 1000 and (d >= EDGE).sum() > 1000      # the edge crosses it
    assert solid(img, d <= -EDGE, (255, 0, 0))
    assert (img[d >= EDGE] == WHITE).all()
