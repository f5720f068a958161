"""`max2code scene FILE`: every pair's first collision in a frozen scene, predicted by the engine.

    max2code scene examples/frozen/billiards-break.json [--check] [--json]

A frozen scene (JSON, or TOML on Python >= 3.11) holds circles and their motions, a time horizon
and a tolerance on collision times:

    {"horizon": 2.0, "tolerance": 1e-4,
     "bodies": [{"name": "cue", "centre": [0, 0], "velocity": [3, 0], "acceleration": [0, 0],
                 "offset": [0, 0], "omega": 0, "radius": 0.03, "group": "..."}]}

Every field but `centre` and `radius` defaults to zero. A body's centre is at
centre + velocity t + acceleration t^2/2 + R(omega t) offset (an orbit about a moving centre);
bodies sharing a `group` (the circles of one paddle) are not tested against each other. Nothing
responds: each pair is predicted as if it were alone (`max2code sim` runs scenes that bounce).

Each pair's prediction is the engine's own (max2code.engine, the C core): the cheapest
generated variant, exact polynomials where nothing rotates, and for rotation the lowest Taylor
order whose remainder bound meets the budget, in windows re-expanded from the exact state, the
contact bracketed by inflated and deflated models and refined on the exact motion (README, "The
predictive engine"). The report gives the solves by polynomial degree and the rotating windows
per pair.

`--check` compares every prediction with the exact first contact (mpmath on the true
trigonometric motion; mpmath is needed only for that).
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from collections import Counter
from dataclasses import dataclass, field, replace
from pathlib import Path

from ..jsonsafe import json_safe


# ---------------------------------------------------------------------------
# Scenes
# ---------------------------------------------------------------------------

@dataclass(frozen=True)
class Body:
    name: str
    centre: tuple[float, float]
    radius: float
    velocity: tuple[float, float] = (0.0, 0.0)
    acceleration: tuple[float, float] = (0.0, 0.0)
    offset: tuple[float, float] = (0.0, 0.0)
    omega: float = 0.0
    group: str | None = None

    def at(self, t: float) -> Body:
        """The same motion, restarted at time t (exact trigonometry)."""
        (cx, cy), (vx, vy), (ax, ay), (ox, oy) = self.centre, self.velocity, self.acceleration, self.offset
        c, s = math.cos(self.omega * t), math.sin(self.omega * t)
        return replace(self, centre=(cx + vx * t + ax * t * t / 2, cy + vy * t + ay * t * t / 2),
                       velocity=(vx + ax * t, vy + ay * t), offset=(ox * c - oy * s, ox * s + oy * c))

    def position(self, t: float) -> tuple[float, float]:
        b = self.at(t)
        return b.centre[0] + b.offset[0], b.centre[1] + b.offset[1]

    def simplified(self) -> Body:
        """No more motion than there is: a zero offset makes omega irrelevant, a zero omega
        makes the offset part of the centre. Exact, and it zeroes parameters for the variants."""
        if self.omega == 0.0 or self.offset == (0.0, 0.0):
            return replace(self, centre=(self.centre[0] + self.offset[0], self.centre[1] + self.offset[1]),
                           offset=(0.0, 0.0), omega=0.0)
        return self

    @property
    def rho(self) -> float:
        return math.hypot(*self.offset)


@dataclass(frozen=True)
class Scene:
    bodies: tuple[Body, ...]
    horizon: float
    tolerance: float
    name: str = "scene"


FROZEN_KEYS = {"name", "comment", "horizon", "tolerance", "bodies"}
FROZEN_BODY_KEYS = {"name", "centre", "radius", "velocity", "acceleration", "offset", "omega",
                    "group"}


def load_scene(path: str | Path) -> Scene:
    """Read and check a frozen scene, as `max2code sim` checks its scenes (the same reader and
    checker: every problem a `file:line:col: error:` line, raised together as SceneError):
    known keys only, finite numbers, positive radii, unique names, and no two bodies of
    different groups overlapping at 0 -- a contact already under way has no first time."""
    from ..engine.scenefile import SceneError, Checker, read_located

    path = Path(path)
    shown = str(path)
    doc = read_located(path)
    c = Checker(shown, doc)
    data = doc.data
    if not isinstance(data, dict):
        raise SceneError([f"{shown}:1:1: error: a frozen scene is a table (JSON object) of fields"])
    c.keys(data, FROZEN_KEYS, ())
    name = c.string(data, "name", (), path.stem)
    c.string(data, "comment", ())
    horizon = c.number(data, "horizon", (), None, positive=True, required=True)
    tol = c.number(data, "tolerance", (), None, positive=True, required=True)
    bodies: list[tuple[int, Body]] = []
    names: set[str] = set()
    for i, b in enumerate(c.bodies(data)):
        where = ("bodies", i)
        if not isinstance(b, dict):
            c.error(where, f"expected a table of body fields, got {b!r}")
            continue
        before = len(c.errors)
        c.keys(b, FROZEN_BODY_KEYS, where)
        body = Body(name=c.name(b, where, i, names),
                    centre=c.vec(b, "centre", where, None, required=True),
                    radius=c.number(b, "radius", where, None, positive=True, required=True),
                    velocity=c.vec(b, "velocity", where, (0.0, 0.0)),
                    acceleration=c.vec(b, "acceleration", where, (0.0, 0.0)),
                    offset=c.vec(b, "offset", where, (0.0, 0.0)),
                    omega=c.number(b, "omega", where, 0.0),
                    group=c.string(b, "group", where))
        if len(c.errors) == before:
            bodies.append((i, body))
    if not c.errors:
        _overlapping(c, bodies)
    if c.errors:
        raise SceneError(c.diagnostics())
    return Scene(tuple(b for _, b in bodies), horizon, tol, name)


def _overlapping(c, bodies: list[tuple[int, Body]]) -> None:
    """Bodies of different groups (or none) overlapping at 0, located at the later one (their
    positions at 0 are centre + offset; the circles near each other by the grid of
    engine.scenefile.near_pairs)."""
    from ..engine.scenefile import MAX_OVERLAPS, near_pairs, report_overlaps

    circles = [(*b.position(0.0), b.radius) for _, b in bodies]
    found = []
    for ka, kb in near_pairs(circles, [b.group for _, b in bodies]):
        (ia, a), (ib, b) = bodies[ka], bodies[kb]
        (xa, ya, ra), (xb, yb, rb) = circles[ka], circles[kb]
        gap = math.hypot(xb - xa, yb - ya) - (ra + rb)
        # (circles placed to touch may round into each other: a few ulps of the figures, as
        # sim's check allows its tolerance)
        if gap < -16 * sys.float_info.epsilon * (abs(xa) + abs(ya) + abs(xb) + abs(yb) + ra + rb):
            found.append(((ia, a.name), (ib, b.name), -gap))
            if len(found) == MAX_OVERLAPS:
                c.stopped = f"the overlap check stopped after {MAX_OVERLAPS} overlapping pairs"
                break
    report_overlaps(c, found, ": a contact under way has no first time")


# ---------------------------------------------------------------------------
# Predicting every pair, with the engine
# ---------------------------------------------------------------------------

@dataclass
class Prediction:
    i: int                      # indices of the two bodies in the scene
    j: int
    a: str
    b: str
    time: float | None          # predicted first contact in (0, horizon], None if none
    rotating: bool
    solves: Counter = field(default_factory=Counter)   # degree -> solves
    windows: int = 0            # rotating-model windows solved
    gave_up: str = ""           # the engine's reason when its search gave up (time is None)


def pairs(scene: Scene):
    """Every pair of bodies that can collide (parts of one rigid group cannot), with indices."""
    bodies = scene.bodies
    for i in range(len(bodies)):
        for j in range(i + 1, len(bodies)):
            a, b = bodies[i], bodies[j]
            if a.group is None or a.group != b.group:
                yield i, j, a, b


def bisect_crossing(f, lo, hi, digits: int = 30):
    """Where f crosses zero between lo (f > 0) and hi (f <= 0), to `digits` relative digits."""
    import mpmath

    lo, hi = mpmath.mpf(lo), mpmath.mpf(hi)
    for _ in range(4 * digits + 40):
        mid = (lo + hi) / 2
        if f(mid) > 0:
            lo = mid
        else:
            hi = mid
        if hi - lo <= hi * mpmath.mpf(10) ** -digits:
            break
    return (lo + hi) / 2


def world(scene: Scene):
    """The scene as an engine World: each circle a kinematic body at its centre of rotation."""
    from ..engine import World

    w = World()
    for b in scene.bodies:
        w.add_body([b.offset], radius=b.radius, kind="kinematic", position=b.centre,
                   velocity=b.velocity, omega=b.omega, gravity=b.acceleration, name=b.name,
                   group=b.group)
    return w


def predict(scene: Scene) -> tuple[list[Prediction], float]:
    """Every pair's first contact, and the seconds the engine spent on them."""
    from ..engine import EngineError

    w = world(scene)
    out = []
    seconds = 0.0
    for i, j, a, b in pairs(scene):
        before = w.stats()
        start = time.perf_counter()
        gave_up = ""
        try:
            t = w.first_contact(i, j, scene.horizon)
        except EngineError as exc:  # the search gave up: said, never reported as no contact
            t, gave_up = None, str(exc)
        seconds += time.perf_counter() - start
        after = w.stats()
        solves = Counter({d: n - before["solves_by_degree"].get(d, 0)
                          for d, n in after["solves_by_degree"].items()})
        out.append(Prediction(i, j, a.name, b.name, t,
                              (a.omega != 0 and a.rho > 0) or (b.omega != 0 and b.rho > 0),
                              +solves, after["windows_solved"] - before["windows_solved"], gave_up))
    return out, seconds


# ---------------------------------------------------------------------------
# The exact answer (mpmath on the true trigonometric motion)
# ---------------------------------------------------------------------------

def exact_first_contact(b1: Body, b2: Body, horizon: float, grid: int = 4000) -> float | None:
    """First t in (0, horizon] where the true distance reaches r1 + r2: a grid in doubles finds
    the first sign change of the gap, or a local minimum that could hide a touch (refined by
    golden section); mpmath bisects at 40 digits."""
    import mpmath

    R = b1.radius + b2.radius

    def gap_mp(t: mpmath.mpf) -> mpmath.mpf:
        xs = []
        for b in (b1, b2):
            c, s = mpmath.cos(b.omega * t), mpmath.sin(b.omega * t)
            xs.append((b.centre[0] + b.velocity[0] * t + b.acceleration[0] * t * t / 2
                       + b.offset[0] * c - b.offset[1] * s,
                       b.centre[1] + b.velocity[1] * t + b.acceleration[1] * t * t / 2
                       + b.offset[0] * s + b.offset[1] * c))
        return mpmath.sqrt((xs[0][0] - xs[1][0]) ** 2 + (xs[0][1] - xs[1][1]) ** 2) - R

    def gap(t: float) -> float:
        p, q = b1.position(t), b2.position(t)
        return math.hypot(p[0] - q[0], p[1] - q[1]) - R

    # the gap changes at most this fast: relative speed bound over the horizon
    speed = (math.hypot(b1.velocity[0] - b2.velocity[0], b1.velocity[1] - b2.velocity[1])
             + math.hypot(b1.acceleration[0] - b2.acceleration[0],
                          b1.acceleration[1] - b2.acceleration[1]) * horizon
             + abs(b1.omega) * b1.rho + abs(b2.omega) * b2.rho)
    step = horizon / grid
    with mpmath.workdps(40):
        ts = [horizon * i / grid for i in range(grid + 1)]
        gs = [gap(t) for t in ts]
        if gs[0] <= 0:
            return 0.0
        hit = None
        for i in range(1, grid + 1):
            if gs[i] <= 0:
                hit = (ts[i - 1], ts[i])
                break
            if i < grid and gs[i] < gs[i - 1] and gs[i] <= gs[i + 1] and gs[i] <= speed * step:
                # a dip close enough to zero that the gap could reach it between grid points
                lo, hi = ts[i - 1], ts[i + 1]
                for _ in range(80):
                    m1, m2 = lo + (hi - lo) * 0.382, lo + (hi - lo) * 0.618
                    if gap_mp(mpmath.mpf(m1)) < gap_mp(mpmath.mpf(m2)):
                        hi = m2
                    else:
                        lo = m1
                m = (lo + hi) / 2
                if gap_mp(mpmath.mpf(m)) <= 0:
                    hit = (ts[i - 1], m)
                    break
        if hit is None:
            return None
        return float(bisect_crossing(gap_mp, hit[0], hit[1], 30))


# ---------------------------------------------------------------------------
# Report
# ---------------------------------------------------------------------------

@dataclass
class Report:
    scene: Scene
    predictions: list[Prediction]
    seconds: float
    exact: list[float | None] | None = None

    def solves(self) -> Counter:
        total: Counter = Counter()
        for p in self.predictions:
            total.update(p.solves)
        return total

    def errors(self) -> list[float]:
        """|predicted - exact| per pair (0 when both say no contact; inf when only one does)."""
        assert self.exact is not None
        return [_diff(p.time, e) for p, e in zip(self.predictions, self.exact)]

    def as_dict(self) -> dict:
        d: dict = {
            "scene": self.scene.name, "pairs": len(self.predictions),
            "horizon": self.scene.horizon, "tolerance": self.scene.tolerance,
            "solves_by_degree": {str(k): v for k, v in sorted(self.solves().items())},
            "rotating_windows": sum(p.windows for p in self.predictions),
            "seconds": self.seconds,
            "collisions": [{"a": p.a, "b": p.b, "time": p.time, "rotating": p.rotating,
                            "windows": p.windows} for p in self.predictions if p.time is not None],
            "gave_up": [{"a": p.a, "b": p.b, "reason": p.gave_up}
                        for p in self.predictions if p.gave_up],
        }
        if self.exact is not None:
            errs = self.errors()
            d["max_error"] = max(errs, default=0.0)
            d["within_tolerance"] = all(e <= self.scene.tolerance for e in errs)
        return d

    def text(self) -> str:
        s = self.scene
        lines = [f"scene {s.name}: {len(s.bodies)} bodies, {len(self.predictions)} pairs, horizon "
                 f"{s.horizon:g}, tolerance {s.tolerance:g}"]
        exact = self.exact or [None] * len(self.predictions)
        for p, e in zip(self.predictions, exact):
            if p.time is None and e is None and not p.gave_up:
                continue
            shown = f"gave up ({p.gave_up})" if p.gave_up else _fmt(p.time)
            line = (f"  {p.a:>10s} - {p.b:<10s} t = {shown}  "
                    f"{'rotating, ' + str(p.windows) + ' windows' if p.rotating else 'exact'}; "
                    f"solves {dict(sorted(p.solves.items()))}")
            if self.exact is not None:
                line += f"; exact {_fmt(e)}, error {_diff(p.time, e):.1e}"
            lines.append(line)
        solves = self.solves()
        lines.append("  solves by degree: " + ", ".join(f"degree {k}: {v}" for k, v in sorted(solves.items())))
        lines.append(f"  prediction time: {self.seconds * 1e3:.3f} ms (the engine's C core)")
        if self.exact is not None:
            errs = self.errors()
            ok = all(x <= s.tolerance for x in errs)
            lines.append(f"  against the exact motion: max error {max(errs, default=0):.1e} "
                         f"({'within' if ok else 'NOT within'} the tolerance {s.tolerance:g})")
        return "\n".join(lines)


def _fmt(t: float | None) -> str:
    return "none" if t is None else f"{t:.10f}"


def _diff(a: float | None, b: float | None) -> float:
    if a is None and b is None:
        return 0.0
    if a is None or b is None:
        return math.inf
    return abs(a - b)


def run(scene: Scene, check: bool = False) -> Report:
    predictions, seconds = predict(scene)
    report = Report(scene, predictions, seconds)
    if check:
        report.exact = [exact_first_contact(scene.bodies[p.i], scene.bodies[p.j], scene.horizon)
                        for p in predictions]
    return report


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(prog="max2code scene", description=__doc__.split("\n\n")[0])
    ap.add_argument("scene", metavar="FILE", help="a frozen scene (.json, or .toml)")
    ap.add_argument("--check", action="store_true",
                    help="compare with the exact motion (mpmath)")
    ap.add_argument("--json", action="store_true", help="print the report as JSON")
    args = ap.parse_args(argv)
    from ..engine.scenefile import SceneError

    try:
        scene = load_scene(args.scene)
    except SceneError as exc:
        for d in exc.diagnostics:
            print(d, file=sys.stderr)
        return 1
    report = run(scene, check=args.check)
    print(json.dumps(json_safe(report.as_dict()), indent=1, allow_nan=False) if args.json
          else report.text())
    if args.check and not report.as_dict()["within_tolerance"]:
        return 1
    for p in report.predictions:
        if p.gave_up:
            print(f"{args.scene}:1:1: error: pair {p.a} - {p.b}: {p.gave_up}", file=sys.stderr)
    return 1 if any(p.gave_up for p in report.predictions) else 0
