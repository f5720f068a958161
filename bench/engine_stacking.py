"""Sustained contact in bench/engine.py (issue 34, item 5): the tilted drop, columns, a pyramid and
dense inelastic collapse, the same bodies in every engine, and what is measured on them.

Unlike the other scenes of bench/engine.py these are about bodies that stay in contact, so every
engine runs as a physics programmer would run it for stacking: friction on, sleeping allowed, our
engine with its contact solver (`World(contact_step=)`, its default step when it has one, else
1/240 s). A contact's coefficients are the scene's (`Scene.friction`, `Scene.restitution`); each
engine's adapter sets its shapes so that its own mixing rule gives them (pymunk multiplies both
coefficients, Box2D takes sqrt(fa fb) for friction and max(ea, eb) for restitution, ours
sqrt(fa fb) and ea eb).

What is reported, measured here from each engine's states (never from what it says of itself):
* tilt: the largest angle of any box away from lying flat on a side (0 .. pi/4, radians);
* toppled: a column whose top box ended more than a box height below where it started;
* drift: how far any box moved from its start (the stack's settling, Box2D's skin included),
  and from 1 s to the end (creep once settled: a standing stack's should be 0);
* overlap: the deepest interpenetration of any two shapes (separating-axis depth of the convex
  polygons, discs by centre distance), the largest over samples every 0.5 s and at the end;
* energy: kinetic + potential at the end over the start (the tilted drop: the box's centre
  height at the end over a flat box's, 1 when lying flat);
* wall: the engine's own stepping time (the metrics' sampling excluded).
"""

from __future__ import annotations

import math
import random
import time

import engine_scenes as S
from engine_scenes import Block, Disc, Scene, Wall

BOX = 0.25            # half side of every box, m (a 0.5 m box, as in issue 34)
FLOOR = (Wall((-20.0, 0.0), (20.0, 0.0), e=0.0),)
SAMPLE = 0.5          # seconds of simulated time between overlap samples


def box(x: float, y: float, angle: float = 0.0) -> Block:
    return Block(S.square(BOX), m=1.0, x=x, y=y, angle=angle, e=0.0)


def lowest(b: Block) -> float:
    """The lowest vertex's height above the box's centre (negative)."""
    c, s = math.cos(b.angle), math.sin(b.angle)
    return min(vx * s + vy * c for vx, vy in b.vertices)


def tilted_drop(angle: float, e: float, mu: float) -> Scene:
    """A 0.5 m box tilted `angle` rad, its lowest corner 1 cm above the floor (issue 34)."""
    b = box(0.0, 0.0, angle)
    b = box(0.0, 0.01 - lowest(b), angle)
    return Scene(f"tilted drop {angle:g} rad, e {e:g}, mu {mu:g}", (b,), FLOOR, (0.0, -S.G),
                 friction=mu, restitution=e, rest=True)


def column(n: int = 10, jitter: bool = False, seed: int = 7) -> Scene:
    """n boxes stacked on the floor. Jittered: each box offset up to 3 mm sideways and tilted up to
    0.02 rad, its lowest corner 1 mm above the box below's highest (issue 34 item 4)."""
    rng = random.Random(seed)
    bodies: list[Block] = []
    top = 0.0
    for _ in range(n):
        if jitter:
            angle, x = rng.uniform(-0.02, 0.02), rng.uniform(-0.003, 0.003)
            b = box(x, 0.0, angle)
            b = box(x, top + 0.001 - lowest(b), angle)
            top = b.y - lowest(b)
        else:
            b = box(0.0, top + BOX)
            top += 2 * BOX
        bodies.append(b)
    name = f"column of {n}" + (" jittered (3 mm, 0.02 rad)" if jitter else "")
    return Scene(name, tuple(bodies), FLOOR, (0.0, -S.G), friction=0.5, restitution=0.0, rest=True)


def pyramid(rows: int = 4, gap: float = 0.01) -> Scene:
    """rows + (rows - 1) + ... boxes (10 for 4 rows), `gap` apart in a row, each row centred on
    the one below and resting on it."""
    bodies = []
    for r in range(rows):
        count = rows - r
        x0 = -(count - 1) * (2 * BOX + gap) / 2
        bodies += [box(x0 + k * (2 * BOX + gap), BOX + 2 * BOX * r) for k in range(count)]
    return Scene(f"pyramid of {len(bodies)}", tuple(bodies), FLOOR, (0.0, -S.G), friction=0.5,
                 restitution=0.0, rest=True)


def collapse(n: int = 200, seed: int = 1) -> Scene:
    """bench/contact.py's dense inelastic collapse: n discs (r 0.15, 1 kg) dropped into a 10 m
    bin, restitution 0.8 for every contact, no friction."""
    import contact

    top = contact.wall_top(n)
    walls = tuple(Wall(a, b, e=0.0) for a, b in (((0.0, 0.0), (contact.WIDTH, 0.0)),
                                                  ((0.0, 0.0), (0.0, top)),
                                                  ((contact.WIDTH, 0.0), (contact.WIDTH, top))))
    bodies = tuple(Disc(contact.RADIUS, m=1.0, x=x, y=y, vx=vx, vy=vy)
                   for x, y, vx, vy in contact.starts(n, seed))
    return Scene(f"dense collapse, {n} discs, e 0.8", bodies, walls, (0.0, -S.G), friction=0.0,
                 restitution=0.8, rest=True)


def scenes(quick: bool) -> list[tuple[Scene, float]]:
    """(scene, simulated seconds) of the measure."""
    out = [(tilted_drop(a, e, mu), 3.0) for a, e, mu in
           ((0.2, 0.0, 0.5), (0.6, 0.0, 0.5), (1.2, 0.0, 0.5), (0.6, 0.5, 0.5), (0.6, 0.0, 0.0))]
    long = 3.0 if quick else 10.0
    out += [(column(), long), (column(jitter=True), long), (pyramid(), long)]
    out.append((collapse(60 if quick else 200), 3.0 if quick else 20.0))
    return out


# --- geometry: what the states say, measured independently of every engine ---------------------

def shape(body: Disc | Block, state) -> tuple:
    x, y, a = state[:3]
    if isinstance(body, Disc):
        return ("disc", (x, y), body.r)
    c, s = math.cos(a), math.sin(a)
    return ("poly", tuple((x + vx * c - vy * s, y + vx * s + vy * c) for vx, vy in body.vertices))


def _axes(poly):
    for k in range(len(poly)):
        (x0, y0), (x1, y1) = poly[k - 1], poly[k]
        dx, dy = x1 - x0, y1 - y0
        n = math.hypot(dx, dy)
        if n > 0:
            yield (dy / n, -dx / n)


def _span(poly, axis) -> tuple[float, float]:
    d = [px * axis[0] + py * axis[1] for px, py in poly]
    return min(d), max(d)


def polygon_depth(p, q) -> float:
    """Separating-axis depth of two convex polygons (a segment is a polygon of two vertices):
    over every edge normal, the shorter push along it that would part their projections, and the
    least of those; 0 when an axis separates them. (The push, not the projections' common
    length: a segment's projection on its own normal is a point.)"""
    depth = math.inf
    for axis in (*_axes(p), *_axes(q)):
        (a0, a1), (b0, b1) = _span(p, axis), _span(q, axis)
        depth = min(depth, a1 - b0, b1 - a0)
        if depth <= 0:
            return 0.0
    return depth


def _point_segment(pt, a, b) -> float:
    (px, py), (ax, ay), (bx, by) = pt, a, b
    dx, dy = bx - ax, by - ay
    L = dx * dx + dy * dy
    u = 0.0 if L == 0 else max(0.0, min(1.0, ((px - ax) * dx + (py - ay) * dy) / L))
    return math.hypot(px - ax - u * dx, py - ay - u * dy)


def _inside(pt, poly) -> bool:
    """Inside a convex polygon of either winding (a segment has no inside)."""
    if len(poly) < 3:
        return False
    signs = set()
    for k in range(len(poly)):
        (x0, y0), (x1, y1) = poly[k - 1], poly[k]
        cross = (x1 - x0) * (pt[1] - y0) - (y1 - y0) * (pt[0] - x0)
        signs.add(cross > 0)
    return len(signs) == 1


def disc_polygon_depth(centre, r: float, poly) -> float:
    d = min(_point_segment(centre, poly[k - 1], poly[k]) for k in range(len(poly)))
    return r + d if _inside(centre, poly) else max(0.0, r - d)


def depth(s, t) -> float:
    """How deep two shapes interpenetrate, m (0: apart or touching)."""
    if s[0] == "disc" and t[0] == "disc":
        return max(0.0, s[2] + t[2] - math.dist(s[1], t[1]))
    if s[0] == "disc":
        return disc_polygon_depth(s[1], s[2], t[1])
    if t[0] == "disc":
        return disc_polygon_depth(t[1], t[2], s[1])
    return polygon_depth(s[1], t[1])


def _box(s) -> tuple[float, float, float, float]:
    if s[0] == "disc":
        (x, y), r = s[1], s[2]
        return x - r, y - r, x + r, y + r
    xs, ys = [p[0] for p in s[1]], [p[1] for p in s[1]]
    return min(xs), min(ys), max(xs), max(ys)


def deepest(scene: Scene, states) -> float:
    """The deepest interpenetration among the bodies and against the walls (every pair whose
    bounding boxes meet)."""
    shapes = [shape(b, st) for b, st in zip(scene.bodies, states)]
    shapes += [("poly", (w.a, w.b)) for w in scene.walls]
    boxes = [_box(s) for s in shapes]
    worst = 0.0
    for i in range(len(shapes)):
        a = boxes[i]
        for j in range(i + 1, len(shapes)):
            b = boxes[j]
            if a[0] <= b[2] and b[0] <= a[2] and a[1] <= b[3] and b[1] <= a[3]:
                worst = max(worst, depth(shapes[i], shapes[j]))
    return worst


def tilt(angle: float) -> float:
    """How far a box's angle is from lying on a side: 0 .. pi/4."""
    a = math.fmod(angle, math.pi / 2)
    a = a + math.pi / 2 if a < 0 else a
    return min(a, math.pi / 2 - a)


# --- the measure -------------------------------------------------------------------------------

def run_scene(engine, scene: Scene, seconds: float) -> dict:
    sim = engine.build(scene)
    start = sim.states()
    e0 = S.energy(scene, start)
    wall, worst, at_one = 0.0, 0.0, None
    t = 0.0
    while t < seconds - 1e-12:
        t = min(seconds, t + SAMPLE)
        t0 = time.perf_counter()
        sim.advance(t)
        wall += time.perf_counter() - t0
        states = sim.states()
        worst = max(worst, deepest(scene, states))
        if at_one is None and t >= 1.0:
            at_one = states
    end = sim.states()
    blocks = [k for k, b in enumerate(scene.bodies) if isinstance(b, Block)]
    out = {"seconds": seconds, "wall": wall, "overlap": worst,
           "energy": S.energy(scene, end) / e0 if e0 else None}
    if len(blocks) == 1:        # the tilted drop: its tilt, its centre's height over a flat box's
        out["tilt"] = tilt(end[0][2])
        out["height"] = end[0][1] / BOX
    elif blocks:                # stacks
        out["tilt"] = max(tilt(end[k][2]) for k in blocks)
        out["drift"] = max(math.dist(end[k][:2], start[k][:2]) for k in blocks)
        out["creep"] = max(math.dist(end[k][:2], at_one[k][:2]) for k in blocks) if at_one else None
        if scene.name.startswith("column"):
            out["toppled"] = end[blocks[-1]][1] < start[blocks[-1]][1] - 2 * BOX
    else:                       # the collapse: discs that left the bin
        width = scene.walls[0].b[0]
        r = scene.bodies[0].r
        out["left"] = sum(not (-r < st[0] < width + r and st[1] > -r) for st in end)
    events = getattr(sim, "events", None)
    if events is not None:
        out["events"] = events
    return out


def stacking(engine, quick: bool) -> dict:
    out = {}
    for scene, seconds in scenes(quick):
        try:
            out[scene.name] = run_scene(engine, scene, seconds)
        except Exception as exc:   # said in the table, not hidden (e.g. an engine's 'stuck')
            out[scene.name] = {"error": f"{type(exc).__name__}: {exc}".splitlines()[0]}
    return out


# --- the table ---------------------------------------------------------------------------------

def _g(v) -> str:
    return "–" if v is None else ("0" if v == 0 else f"{v:.2g}")


# (result key, what the row says, cell format), in the order they are shown under each scene
METRICS = (
    ("toppled", "toppled", lambda v: "yes" if v else "no"),
    ("tilt", "final tilt, rad (0: lying on a side)", _g),
    ("height", "centre height / a flat box's", lambda v: f"{v:.3f}"),
    ("drift", "drift from the start, m", _g),
    ("creep", "drift from 1 s to the end, m", _g),
    ("left", "discs that left the bin", str),
    ("overlap", "worst overlap, m", _g),
    ("energy", "energy end / start", lambda v: "–" if v is None else f"{v:.3f}"),
    ("wall", "wall s", lambda v: f"{v:.3g}"),
)


def table(by: dict, labels: list[str]) -> list[str]:
    """One row per scene and metric, one column per engine; a scene an engine failed on says so."""
    first = next((by[label]["stacking"] for label in labels if "error" not in by[label]["stacking"]), {})
    lines = [f"| scene | measure | {' | '.join(labels)} |", "|---" * (len(labels) + 2) + "|"]
    for scene, some in first.items():
        for key, text, fmt in METRICS:
            if key not in some:
                continue
            cells = []
            for label in labels:
                r = by[label]["stacking"].get(scene, {})
                cells.append("failed: " + r["error"][:60] if "error" in r else fmt(r[key]) if key in r else "–")
            lines.append(f"| {scene} | {text} | {' | '.join(cells)} |")
        base = by.get("pymunk 1/60", {}).get("stacking", {}).get(scene, {}).get("wall")
        if base:
            cells = [f"{by[label]['stacking'][scene]['wall'] / base:.3g}x"
                     if "wall" in by[label]["stacking"].get(scene, {}) else "–" for label in labels]
            lines.append(f"| {scene} | wall time / pymunk 1/60's | {' | '.join(cells)} |")
    return lines


def main() -> int:
    """`python bench/engine_stacking.py`: the stacking measure alone, every engine in one run,
    its table printed (the rows of bench/results/engine.md's stacking section). The smallest run
    that answers a question about stacking: `python bench/engine.py` runs every measure (minutes)
    and writes the results files."""
    import engine_anchors
    import engine_ours

    chosen = list(engine_anchors.anchors())
    reason = engine_ours.unavailable()
    if reason is None:
        chosen.append(engine_ours.Ours())
    else:
        print(f"bench/engine_stacking: ours not run: {reason}")
    by = {engine.label: {"stacking": stacking(engine, quick=False)} for engine in chosen}
    print("\n".join(table(by, list(by))))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
