"""One frame as SVG, written as text: a picture that stays sharp at any size, for a README or a
paper. Coordinates are the raster's pixel coordinates (View.to_pixel), so a PNG and an SVG of the
same frame line up exactly.

Labels are data: they pass through text.printable (no character XML forbids) and are escaped;
colours were checked by the model (#rrggbb[aa]); numbers are formatted by us. Nothing from a scene
reaches the file unescaped.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from xml.sax.saxutils import escape

from .model import Body, Capsule, Circle, Compound, Frame, Point, Polygon, RenderModelError, Segment, View
from .raster import CONTACT_COLOUR, TEXT_COLOUR, contrast, text_size, check_frame
from .text import printable, time_stamp


def num(v: float) -> str:
    """A coordinate to a thousandth of a pixel, without trailing zeros."""
    text = f"{v:.3f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def _paint(attr: str, colour: str | None) -> str:
    """fill/stroke attributes; an alpha channel becomes *-opacity (SVG 1.1 has no #rrggbbaa)."""
    if colour is None:
        return f' {attr}="none"'
    out = f' {attr}="{colour[:7]}"'
    if len(colour) == 9:
        out += f' {attr}-opacity="{num(int(colour[7:9], 16) / 255)}"'
    return out


def _capsule_path(a: Point, b: Point, r: float) -> str:
    """The stadium around a-b: two sides and two half circles (pixel space, y down)."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    n = math.hypot(dx, dy)
    ox, oy = (-dy / n * r, dx / n * r) if n > 0 else (0.0, r)
    p1, p2 = (a[0] + ox, a[1] + oy), (b[0] + ox, b[1] + oy)
    p3, p4 = (b[0] - ox, b[1] - oy), (a[0] - ox, a[1] - oy)
    rr = num(r)
    return (f"M {num(p1[0])} {num(p1[1])} L {num(p2[0])} {num(p2[1])} "
            f"A {rr} {rr} 0 0 0 {num(p3[0])} {num(p3[1])} L {num(p4[0])} {num(p4[1])} "
            f"A {rr} {rr} 0 0 0 {num(p1[0])} {num(p1[1])} Z")


def _rounded_path(pts: list[Point], r: float) -> str:
    """A convex polygon grown by r: each edge moved out by r, joined by arcs about the vertices
    (pixel space, either winding)."""
    area2 = sum(pts[i - 1][0] * pts[i][1] - pts[i][0] * pts[i - 1][1] for i in range(len(pts)))
    sign = 1.0 if area2 > 0 else -1.0          # outward normal of edge (dx, dy): sign * (dy, -dx)
    rr = num(r)
    parts = []
    n = len(pts)
    for i in range(n):
        a, b = pts[i], pts[(i + 1) % n]
        dx, dy = b[0] - a[0], b[1] - a[1]
        length = math.hypot(dx, dy)
        ox, oy = sign * dy / length * r, -sign * dx / length * r
        start, end = (a[0] + ox, a[1] + oy), (b[0] + ox, b[1] + oy)
        parts.append(f"{'M' if i == 0 else 'A'} " + (f"{rr} {rr} 0 0 {1 if sign > 0 else 0} " if i else "")
                     + f"{num(start[0])} {num(start[1])} L {num(end[0])} {num(end[1])}")
    first = pts[0]
    dx, dy = pts[1][0] - first[0], pts[1][1] - first[1]
    length = math.hypot(dx, dy)
    close = (first[0] + sign * dy / length * r, first[1] - sign * dx / length * r)
    parts.append(f"A {rr} {rr} 0 0 {1 if sign > 0 else 0} {num(close[0])} {num(close[1])} Z")
    return " ".join(parts)


def _circle(shape: Circle, style, px, s: float, paint: str) -> list[str]:
    c = px(shape.centre)
    out = [f'<circle cx="{num(c[0])}" cy="{num(c[1])}" r="{num(shape.radius * s)}"{paint}/>']
    if style.spoke:
        rim = px((shape.centre[0] + shape.radius, shape.centre[1]))
        colour = style.stroke or contrast(style.fill)
        out.append(f'<line class="spoke" x1="{num(c[0])}" y1="{num(c[1])}" x2="{num(rim[0])}" '
                   f'y2="{num(rim[1])}"{_paint("stroke", colour)} '
                   f'stroke-width="{num(max(style.stroke_width, 1.0))}"/>')
    return out


def _polygon(shape: Polygon, style, px, s: float, paint: str) -> list[str]:
    if shape.radius > 0:
        return [f'<path d="{_rounded_path([px(v) for v in shape.vertices], shape.radius * s)}"{paint}/>']
    points = " ".join(f"{num(x)},{num(y)}" for x, y in (px(v) for v in shape.vertices))
    return [f'<polygon points="{points}"{paint} stroke-linejoin="round"/>']


def _capsule(shape: Capsule, style, px, s: float, paint: str) -> list[str]:
    return [f'<path d="{_capsule_path(px(shape.a), px(shape.b), shape.radius * s)}"{paint}/>']


def _segment(shape: Segment, style, px, s: float, paint: str) -> list[str]:
    """No inside: drawn as a line in the stroke colour (or the fill's)."""
    a, b = px(shape.a), px(shape.b)
    colour = style.stroke if style.stroke is not None else style.fill
    return [f'<line x1="{num(a[0])}" y1="{num(a[1])}" x2="{num(b[0])}" y2="{num(b[1])}"'
            f'{_paint("stroke", colour)} stroke-width="{num(max(style.stroke_width, 1.0))}" '
            f'stroke-linecap="round"/>']


def _compound(shape: Compound, style, px, s: float, paint: str) -> list[str]:
    """Each part in the body's style (their outlines show where the parts meet)."""
    return [line for part in shape.parts for line in ELEMENTS[type(part)](part, style, px, s, paint)]


# One SVG writer per kind of shape (as the rasteriser's OUTLINES).
ELEMENTS: dict[type, Callable[..., list[str]]] = {
    Circle: _circle, Polygon: _polygon, Capsule: _capsule, Segment: _segment, Compound: _compound}


def _body(i: int, body: Body, pose, view: View) -> list[str]:
    style, shape = body.style, body.shape
    px = lambda p: view.to_pixel(pose.apply(p))  # noqa: E731
    width = num(style.stroke_width)
    paint = _paint("fill", style.fill) + _paint("stroke", style.stroke) + f' stroke-width="{width}"'
    write = ELEMENTS.get(type(shape))
    if write is None:
        raise RenderModelError(f"unknown shape {type(shape).__name__}")
    return [f'<g class="body" data-index="{i}">', *write(shape, style, px, view.scale, paint), "</g>"]


def svg_text(bodies: Sequence[Body], frame: Frame, view: View) -> str:
    """The SVG document of one frame."""
    check_frame(bodies, frame)
    size = text_size(view)
    w, h = view.width, view.height
    lines = ['<?xml version="1.0" encoding="UTF-8"?>',
             f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}">',
             f'<title>{escape(time_stamp(frame.time))}</title>',
             f'<rect class="background" x="0" y="0" width="{w}" height="{h}"{_paint("fill", view.background)}/>']
    for i, (body, pose) in enumerate(zip(bodies, frame.poses)):
        lines += _body(i, body, pose, view)
    if view.show_contacts:
        r = max(3.0, min(w, h) / 100)
        for c in frame.contacts:
            p = view.to_pixel(c.point)
            n = math.hypot(*c.normal) or 1.0
            q = (p[0] + 2.5 * r * c.normal[0] / n, p[1] - 2.5 * r * c.normal[1] / n)
            lines.append(f'<g class="contact"><circle cx="{num(p[0])}" cy="{num(p[1])}" r="{num(r)}" '
                         f'fill="none" stroke="{CONTACT_COLOUR}" stroke-width="1.5"/>'
                         f'<line x1="{num(p[0])}" y1="{num(p[1])}" x2="{num(q[0])}" y2="{num(q[1])}" '
                         f'stroke="{CONTACT_COLOUR}" stroke-width="1.5"/></g>')
    font = f'font-family="sans-serif" font-size="{size}"'
    for body, pose in zip(bodies, frame.poses):
        if body.style.label:
            x, y = view.to_pixel((pose.x, pose.y))
            lines.append(f'<text class="label" x="{num(x)}" y="{num(y)}" {font} text-anchor="middle" '
                         f'dominant-baseline="central"{_paint("fill", contrast(body.style.fill))}>'
                         f'{escape(printable(body.style.label))}</text>')
    if view.show_time:
        lines.append(f'<text class="time" x="6" y="{6 + size}" {font} fill="{TEXT_COLOUR}" '
                     f'stroke="#ffffff" stroke-width="3" paint-order="stroke">'
                     f'{escape(time_stamp(frame.time))}</text>')
    lines.append("</svg>")
    return "\n".join(lines) + "\n"

