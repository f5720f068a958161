"""SVG of one frame, parsed back with xml.etree: coordinates against the exact geometry, and labels
that are data."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from max2code.render import (Body, Capsule, Circle, Compound, Contact, Frame, Polygon, Pose, Segment,
                             Style, View, write_svg)
from max2code.render.svg import svg_text
from max2code.render.text import printable

NS = {"s": "http://www.w3.org/2000/svg"}
VIEW = View(-5, -5, 5, 5, width=400, height=400)          # 40 px per unit, (0, 0) at (200, 200)


def parse(text: str) -> ET.Element:
    return ET.fromstring(text.encode("utf-8"))


def px(x: float, y: float) -> tuple[float, float]:
    return 200 + 40 * x, 200 - 40 * y


def test_a_compound_draws_each_part_where_the_pose_puts_it() -> None:
    """A dumbbell (two circles on a capsule) at (1, 2) turned a quarter: one body group with a
    circle at each end, their centres at the pose's image of (-1, 0) and (1, 0)."""
    shape = Compound((Circle(0.5, (-1.0, 0.0)), Circle(0.5, (1.0, 0.0)),
                      Capsule((-1.0, 0.0), (1.0, 0.0), 0.1)))
    root = parse(svg_text([Body(shape, Style(fill="#112233"))], Frame(0.0, (Pose(1, 2, math.pi / 2),)), VIEW))
    groups = root.findall("s:g[@class='body']", NS)
    assert len(groups) == 1
    circles = groups[0].findall("s:circle", NS)
    got = sorted(v for c in circles for v in (float(c.get("cx")), float(c.get("cy"))))
    assert got == pytest.approx(sorted([*px(1, 1), *px(1, 3)]), abs=1e-3)
    assert all(float(c.get("r")) == pytest.approx(20) for c in circles)
    assert len(groups[0].findall("s:path", NS)) == 1         # the capsule


def test_shapes_are_where_the_poses_put_them() -> None:
    a = 0.6
    bodies = [Body(Circle(1.25), Style(fill="#112233", stroke="#445566")),
              Body(Polygon(((0, 0), (2, 0), (0, 1))), Style(fill="#abcdef80", stroke=None)),
              Body(Segment((-4, -4), (4, -4)), Style(stroke="#000000", stroke_width=3)),
              Body(Capsule((-1, 0), (1, 0), 0.5))]
    frame = Frame(2.0, (Pose(1, 2, a), Pose(-1, -1, a), Pose(0, 0), Pose(2, -2, math.pi / 2)),
                  (Contact((1, -4), (0, 1)),))
    root = parse(svg_text(bodies, frame, VIEW))
    assert root.get("width") == "400" and root.get("viewBox") == "0 0 400 400"
    groups = root.findall("s:g[@class='body']", NS)
    assert [g.get("data-index") for g in groups] == ["0", "1", "2", "3"]

    circle = groups[0].find("s:circle", NS)
    assert (float(circle.get("cx")), float(circle.get("cy"))) == pytest.approx(px(1, 2), abs=1e-3)
    assert float(circle.get("r")) == pytest.approx(50, abs=1e-3)
    assert circle.get("fill") == "#112233" and circle.get("stroke") == "#445566"
    spoke = groups[0].find("s:line[@class='spoke']", NS)
    assert (float(spoke.get("x2")), float(spoke.get("y2"))) == pytest.approx(
        px(1 + 1.25 * math.cos(a), 2 + 1.25 * math.sin(a)), abs=1e-3)

    poly = groups[1].find("s:polygon", NS)
    got = [tuple(map(float, p.split(","))) for p in poly.get("points").split()]
    want = [px(-1 + math.cos(a) * u - math.sin(a) * v, -1 + math.sin(a) * u + math.cos(a) * v)
            for u, v in ((0, 0), (2, 0), (0, 1))]
    assert got == [pytest.approx(w, abs=1e-3) for w in want]
    assert poly.get("fill") == "#abcdef" and float(poly.get("fill-opacity")) == pytest.approx(0x80 / 255, abs=1e-3)
    assert poly.get("stroke") == "none"

    line = groups[2].find("s:line", NS)
    assert [float(line.get(k)) for k in ("x1", "y1", "x2", "y2")] == pytest.approx([40, 360, 360, 360])
    assert line.get("stroke-width") == "3"

    d = groups[3].find("s:path", NS).get("d").split()
    # rotated a quarter turn: the axis is vertical through x = 2, from y = -3 to y = -1
    side = 0.5 if float(d[1]) > px(2, 0)[0] else -0.5        # either side of the axis first
    assert d[0] == "M" and (float(d[1]), float(d[2])) == pytest.approx(px(2 + side, -3), abs=1e-3)
    assert (float(d[4]), float(d[5])) == pytest.approx(px(2 + side, -1), abs=1e-3)
    assert (float(d[12]), float(d[13])) == pytest.approx(px(2 - side, -1), abs=1e-3)
    assert (float(d[15]), float(d[16])) == pytest.approx(px(2 - side, -3), abs=1e-3)
    assert d[6] == "A" and float(d[7]) == pytest.approx(20)

    ring = root.find("s:g[@class='contact']/s:circle", NS)
    assert (float(ring.get("cx")), float(ring.get("cy"))) == pytest.approx(px(1, -4))
    assert root.find("s:text[@class='time']", NS).text == "t = 2.000 s"


@pytest.mark.parametrize("label", [
    "</text><script>alert(1)</script>",
    "<![CDATA[x]]> ]]> & &amp; \" ' <",
    "\x00\x01\x1b[31mred\x7f",
    "lone \ud800 surrogate \ufffe",
    "line\nbreak\ttab\rcr",
    "<?xml-stylesheet href='evil'?>",
    "x" * 500,
])
def test_hostile_labels_are_text(tmp_path: Path, label: str) -> None:
    bodies = [Body(Circle(1), Style(label=label))]
    path = tmp_path / "frame.svg"
    write_svg(path, bodies, Frame(0, (Pose(0, 0),)), VIEW)
    data = path.read_bytes()
    root = parse(data.decode("utf-8"))                    # well-formed, valid UTF-8
    texts = root.findall("s:text[@class='label']", NS)
    assert len(texts) == 1 and texts[0].text == printable(label)
    assert not root.findall(".//s:script", NS) and b"<script" not in data
    assert len(root) == 5                                  # title, background, the body, the label, the time
    shown = printable(label)
    assert "\n" not in shown and len(shown) <= 200 and "\x00" not in shown and "\ud800" not in shown


def test_same_frame_same_bytes() -> None:
    bodies = [Body(Circle(1)), Body(Polygon(((0, 0), (1, 0), (0, 1))))]
    frame = Frame(0.1, (Pose(0.1, 0.2, 0.3), Pose(-1, -2, 3)))
    assert svg_text(bodies, frame, VIEW) == svg_text(bodies, frame, VIEW)


def _arc_centre(p1, p2, r, large, sweep):
    """The centre of an SVG arc (a circle, no rotation), by the SVG specification's formulas."""
    x1p, y1p = (p1[0] - p2[0]) / 2, (p1[1] - p2[1]) / 2
    coef = math.sqrt(max(r * r - x1p * x1p - y1p * y1p, 0.0) / (x1p * x1p + y1p * y1p))
    coef = coef if large != sweep else -coef
    return (coef * y1p + (p1[0] + p2[0]) / 2, -coef * x1p + (p1[1] + p2[1]) / 2)


@pytest.mark.parametrize("winding", [1, -1])
def test_rounded_polygon_path_arcs_turn_about_the_vertices(winding: int) -> None:
    tri = ((-1.0, -1.0), (1.5, -1.0), (0.0, 1.2))[::winding]
    body = Body(Polygon(tri, radius=0.5))
    pose = Pose(0.5, -0.5, 0.3)
    root = parse(svg_text([body], Frame(0, (pose,)), VIEW))
    tokens = root.find("s:g/s:path", NS).get("d").split()
    verts = [px(*pose.apply(v)) for v in tri]
    # walk the path: M p L q (A r r 0 0 f p L q)* A r r 0 0 f p0 Z
    k, points, arcs = 0, [], []
    while k < len(tokens):
        op = tokens[k]
        if op in ("M", "L"):
            points.append((float(tokens[k + 1]), float(tokens[k + 2])))
            k += 3
        elif op == "A":
            r, large, sweep = float(tokens[k + 1]), int(tokens[k + 4]), int(tokens[k + 5])
            end = (float(tokens[k + 6]), float(tokens[k + 7]))
            arcs.append(_arc_centre(points[-1], end, r, large, sweep))
            points.append(end)
            k += 8
        else:
            assert op == "Z"
            k += 1
    assert r == pytest.approx(20)
    # every point on the path is 20 px from the nearest vertex's edge; arcs turn about vertices
    assert len(arcs) == 3
    for centre in arcs:
        assert min(math.dist(centre, v) for v in verts) < 1e-2
    for p in points:
        assert min(abs(math.dist(p, v) - 20) for v in verts) < 1e-2
