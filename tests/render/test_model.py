"""The data interface: what is refused, and the two transforms every renderer relies on."""

from __future__ import annotations

import math

import pytest

from max2code.render import (Body, Capsule, Circle, Contact, Frame, Polygon, Pose, RenderModelError,
                             Segment, Style, View, fit_view, world_extent)


@pytest.mark.parametrize("make", [
    lambda: Circle(0),
    lambda: Circle(-1),
    lambda: Circle(float("nan")),
    lambda: Circle(True),
    lambda: Circle("1"),
    lambda: Capsule((0, 0), (1, 0), -0.1),
    lambda: Segment((1, 1), (1, 1)),
    lambda: Polygon(((0, 0), (1, 0))),
    lambda: Polygon(((0, 0), (1, 0), (2, 0))),                      # no area
    lambda: Polygon(((0, 0), (2, 0), (2, 2), (1, 0.5), (0, 2))),     # concave
    lambda: Polygon(tuple((math.cos(4 * math.pi * k / 5), math.sin(4 * math.pi * k / 5))
                          for k in range(5))),                       # pentagram: turns twice
    lambda: Polygon(((0, 0), (1, 0), (float("inf"), 1))),
    lambda: Polygon(((0, 0), (1, 0), (0, 1)), radius=-0.1),
    lambda: Pose(0, float("nan")),
    lambda: Style(fill="red"),
    lambda: Style(fill='#ffffff" onload="alert(1)'),
    lambda: Style(stroke="#12345"),
    lambda: Style(stroke_width=-1),
    lambda: Style(label=3),
    lambda: View(0, 0, 0, 1),
    lambda: View(0, 0, 1, 1, width=0),
    lambda: View(0, 0, 1, 1, height=2.5),
    lambda: View(0, 0, 1, 1, background="#ffffff<"),
    lambda: Contact((0, 0), (1, 0), bodies=(0, -1)),
    lambda: Frame(0.0, (Pose(0, 0), "pose")),
    lambda: Body("circle"),
])
def test_refused(make) -> None:
    with pytest.raises(RenderModelError):
        make()


def test_accepted_forms() -> None:
    # either winding, alpha colours, integers for floats
    assert Polygon(((0, 0), (0, 1), (1, 1), (1, 0))).vertices[2] == (1.0, 1.0)
    assert Style(fill="#11223344", stroke=None).fill == "#11223344"
    assert Circle(2).radius == 2.0 and isinstance(Circle(2).radius, float)


def test_pose_rotates_counter_clockwise_about_the_origin() -> None:
    p = Pose(1.0, 2.0, math.pi / 2).apply((3.0, 0.0))
    assert p == pytest.approx((1.0, 5.0), abs=1e-15)
    p = Pose(0.0, 0.0, math.pi / 6).apply((2.0, 0.0))
    assert p == pytest.approx((math.sqrt(3), 1.0), abs=1e-15)


def test_view_maps_world_to_pixels_with_one_scale_and_y_down() -> None:
    v = View(-2, -1, 2, 1, width=400, height=300)   # world aspect 2, picture 4/3: x limits
    assert v.scale == 100.0
    assert v.to_pixel((0, 0)) == (200.0, 150.0)
    assert v.to_pixel((-2, 1)) == (0.0, 50.0)        # y up in the world, down in the picture
    assert v.to_pixel((2, -1)) == (400.0, 250.0)


def test_world_extent_of_each_shape() -> None:
    pose = Pose(1, 1, math.pi / 4)
    assert world_extent(Circle(0.5, (1, 0)), pose) == pytest.approx(
        (1 + math.sqrt(0.5) - 0.5, 1 + math.sqrt(0.5) - 0.5, 1 + math.sqrt(0.5) + 0.5, 1 + math.sqrt(0.5) + 0.5))
    square = Polygon(((-1, -1), (1, -1), (1, 1), (-1, 1)))
    h = math.sqrt(2)
    assert world_extent(square, pose) == pytest.approx((1 - h, 1 - h, 1 + h, 1 + h))
    assert world_extent(Capsule((-1, 0), (1, 0), 0.25), Pose(0, 0, math.pi / 2)) == pytest.approx(
        (-0.25, -1.25, 0.25, 1.25))


def test_fit_view_holds_every_body_in_every_frame() -> None:
    bodies = [Body(Circle(1)), Body(Segment((-1, 0), (1, 0)))]
    frames = [Frame(0, (Pose(0, 0), Pose(5, 5))), Frame(1, (Pose(10, -3), Pose(5, 5)))]
    v = fit_view(bodies, frames, margin=0.0)
    assert (v.xmin, v.ymin, v.xmax, v.ymax) == (-1.0, -4.0, 11.0, 5.0)  # the segment spans x 4..6 at y 5
    with pytest.raises(RenderModelError):
        fit_view(bodies, [Frame(0, (Pose(0, 0),))])


def test_shape_from_vertices_follows_the_engine_convention() -> None:
    from max2code.render import shape_from_vertices
    assert shape_from_vertices([(0.5, 0)], 0.2) == Circle(0.2, (0.5, 0))
    assert shape_from_vertices([(0, 0), (1, 0)]) == Segment((0, 0), (1, 0))
    assert shape_from_vertices([(0, 0), (1, 0)], 0.1) == Capsule((0, 0), (1, 0), 0.1)
    assert shape_from_vertices([(0, 0), (1, 0), (0, 1)], 0.05) == Polygon(((0, 0), (1, 0), (0, 1)), 0.05)
    with pytest.raises(RenderModelError):
        shape_from_vertices([(0, 0)], 0.0)          # a point is no circle


def test_colour_names_and_forms() -> None:
    from max2code.render import colour
    assert colour("Red") == "#ff0000" and colour(" navy ") == "#000080"
    assert colour("#1aF") == "#11aaff" and colour("#11223344") == "#11223344"
    for bad in ("reddish", "#12", "rgb(1,2,3)", "#fff\" onload=\"x", 7):
        with pytest.raises(RenderModelError, match="use #rrggbb"):
            colour(bad)
