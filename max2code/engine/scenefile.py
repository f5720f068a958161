"""Scene files: TOML or JSON, checked strictly, into a World.

    name = "pinball"                 # optional; default: the file's stem
    gravity = [0.0, -9.81]           # every dynamic body's acceleration unless it has its own
    tolerance = 1e-9                 # lengths: contact slack, overlap allowed, Taylor budget
    until = 10.0                     # optional: how long `max2code sim` runs by default
    fps = 30                         # optional: frames per second of the pictures
    view = [-1.0, -1.0, 1.0, 1.0]    # optional: what the pictures show (xmin, ymin, xmax, ymax)

    [engine]                         # optional tuning (README: the rest rule)
    cell_size = 0.0                  # 0: chosen from the bodies; < 0: one cell (no broad phase)
    rest_speed = 0.0                 # the rest rule's v_r; 0: automatic; < 0: the rules off
    collapse_time = 0.0              # the collapse rules' t_c; 0: automatic (1e-3 s); < 0: off
    max_events = 0                   # a step processing more fails (0: no limit): the whole run
                                     # without pictures, one frame with them
    contact_step = 0.004166666666666667   # the sustained-contact solver's step h (default
                                     # 1/240 s); 0: off, exact impacts and the rest rule only
                                     # (docs/engine-contact.md)

    [[bodies]]
    name = "ball"                    # optional, unique; default body<N>
    kind = "dynamic"                 # dynamic (default) | static | kinematic
    shape = "circle"                 # circle | segment | polygon | box | compound
    position = [0.0, 1.0]            # required for circle, polygon, box; default [0, 0]
    radius = 0.1                     # circle: required, > 0; others: rounding, >= 0
    offset = [0.0, 0.0]              # circle only: its centre's offset from position
    points = [[-1, 0], [1, 0]]       # segment: its two ends (offsets from position)
    vertices = [[0, 0], [1, 0], [0, 1]]   # polygon: convex, anticlockwise (offsets)
    size = [1.0, 0.5]                # box: width and height, centred on position
    parts = [{shape = "circle", radius = 0.2, offset = [-1, 0]},   # compound: several shapes
             {shape = "box", size = [2, 0.1]}]                     # on one rigid body, each
                                     # with its own keys above (offsets from position; a
                                     # box part may have an offset too)
    angle = 0.0                      # radians
    velocity = [0.0, 0.0]
    omega = 0.0                      # angular velocity, radians per second, anticlockwise
    gravity = [0.0, 0.0]             # this body's own acceleration
    mass = 1.0                       # or density (default 1, per unit area); not both
    inertia = 0.5                    # optional: default from the shape
    restitution = 1.0                # 0..1; a contact uses the product of the two bodies'
    friction = 0.0                   # Coulomb coefficient >= 0, at impacts; a contact uses sqrt(fa fb)
    group = "paddle"                 # bodies of one group never collide with each other
    color = "#c03030"                # optional, for the pictures
    comment = "..."                  # ignored (also at the top level)

JSON has the same keys (`"bodies": [{...}, ...]`). Every error names the file, line and
column of the offending key or value and the key path (`bodies[2].radius`): an unknown key, a
wrong type, a missing field, a value out of range, a non-convex or clockwise polygon, two
bodies with one name, and a body that starts overlapping another by more than the tolerance.
"""

from __future__ import annotations

import difflib
import math
import re
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path as FilePath

from .geometry import gap, transform
from . import limits
from .located import Located, TextError, parse_json, parse_toml
from .shapes import compound_mass_properties, mass_properties

TOP_KEYS = {"name", "gravity", "tolerance", "until", "fps", "view", "engine", "bodies", "comment"}
ENGINE_KEYS = {"cell_size", "rest_speed", "collapse_time", "max_events", "contact_step"}
BODY_KEYS = {"name", "kind", "shape", "position", "radius", "offset", "points", "vertices", "size",
             "angle", "velocity", "omega", "gravity", "mass", "density", "inertia",
             "restitution", "friction", "group", "color", "comment", "parts"}
SHAPE_KEYS = {"circle": {"radius", "offset"}, "segment": {"points", "radius"},
              "polygon": {"vertices", "radius"}, "box": {"size", "radius"},
              "compound": {"parts"}}
PART_KEYS = {"shape", "radius", "offset", "points", "vertices", "size", "comment"}
PART_SHAPE_KEYS = {"circle": {"radius", "offset"}, "segment": {"points", "radius"},
                   "polygon": {"vertices", "radius"}, "box": {"size", "radius", "offset"}}
KINDS = ("dynamic", "static", "kinematic")

Vec = tuple[float, float]


@dataclass(frozen=True)
class BodySpec:
    name: str
    kind: str
    shape: str
    vertices: tuple[Vec, ...]        # offsets from position, in the body frame
    radius: float
    position: Vec
    angle: float = 0.0
    velocity: Vec = (0.0, 0.0)
    omega: float = 0.0
    gravity: Vec | None = None
    mass: float | None = None
    density: float = 1.0
    inertia: float | None = None
    restitution: float = 1.0
    group: str | None = None
    color: str | None = None
    friction: float = 0.0
    parts: tuple[tuple[tuple[Vec, ...], float], ...] = ()   # a compound's (vertices, radius)

    @property
    def shapes(self) -> tuple[tuple[tuple[Vec, ...], float], ...]:
        """Every convex shape of the body, (vertices, radius): a compound's parts, or the one."""
        return self.parts or ((self.vertices, self.radius),)


@dataclass(frozen=True)
class Scene:
    name: str
    bodies: tuple[BodySpec, ...]
    gravity: Vec = (0.0, 0.0)
    tolerance: float = 1e-9
    until: float | None = None
    fps: float | None = None
    view: tuple[float, float, float, float] | None = None
    cell_size: float = 0.0
    rest_speed: float = 0.0
    collapse_time: float = 0.0
    max_events: int = 0
    contact_step: float = limits.CONTACT_STEP  # the contact solver's h; 0: off (engine-contact.md)
    path: str = ""
    places: tuple[str, ...] = ()     # each body's `file:line:col`, for the engine's refusals


class SceneError(ValueError):
    """Every problem found, as `file:line:col: error: key.path: message` lines."""

    def __init__(self, diagnostics: list[str]) -> None:
        super().__init__("\n".join(diagnostics))
        self.diagnostics = diagnostics


def path_text(path: tuple) -> str:
    out = ""
    for p in path:
        out += f"[{p}]" if isinstance(p, int) else (f".{p}" if out else str(p))
    return out or "(top level)"


_shown = limits.shown


@dataclass
class Checker:
    file: str
    doc: Located
    errors: list[str] = field(default_factory=list)
    stopped: str = ""   # why a check stopped early (it found enough)

    def diagnostics(self) -> list[str]:
        """The errors, at most MAX_ERRORS of them, then a note counting the rest and one
        saying where a check stopped early."""
        out = self.errors[:MAX_ERRORS]
        if len(self.errors) > MAX_ERRORS:
            out.append(f"{self.file}: note: {len(self.errors) - MAX_ERRORS} more errors not "
                       f"listed (the first {MAX_ERRORS} are)")
        if self.stopped:
            out.append(f"{self.file}: note: {self.stopped}; there may be more")
        return out

    def error(self, path: tuple, message: str) -> None:
        line, col = self.doc.where(path)
        self.errors.append(f"{self.file}:{line}:{col}: error: {path_text(path)}: {message}")

    def keys(self, table: dict, allowed: set[str], path: tuple) -> None:
        for key in table:
            if key not in allowed:
                close = difflib.get_close_matches(key, sorted(allowed), n=1)
                hint = f" (did you mean '{close[0]}'?)" if close else ""
                self.error(path + (key,), f"unknown key '{key}'{hint}; allowed: "
                           f"{', '.join(sorted(allowed))}")

    def number(self, table: dict, key: str, path: tuple, default=None, *, positive=False,
               nonneg=False, lo=None, hi=None, required=False):
        if key not in table:
            if required:
                self.error(path, f"missing field '{key}'")
            return default
        v = table[key]
        problem = limits.number_problem(v, positive=positive, nonneg=nonneg, lo=lo, hi=hi)
        if problem:
            self.error(path + (key,), problem)
            return default
        return float(v)

    def vector(self, value: object, path: tuple) -> Vec | None:
        if (not isinstance(value, list) or len(value) != 2 or
                any(isinstance(x, bool) or not isinstance(x, (int, float)) or not limits.finite(x)
                    for x in value)):
            self.error(path, f"expected [x, y] (two finite numbers), got {_shown(value)}")
            return None
        for k, x in enumerate(value):
            problem = limits.magnitude_problem(float(x))
            if problem:
                self.error(path + (k,), problem)
                return None
        return (float(value[0]), float(value[1]))

    def vec(self, table: dict, key: str, path: tuple, default=None, required=False) -> Vec | None:
        if key not in table:
            if required:
                self.error(path, f"missing field '{key}'")
            return default
        return self.vector(table[key], path + (key,))

    def bodies(self, data: dict) -> list:
        """The scene's list of bodies (empty after an error: missing, or not a non-empty
        list)."""
        raw = data.get("bodies")
        if raw is None:
            self.error((), "missing field 'bodies'")
        elif not isinstance(raw, list) or not raw:
            self.error(("bodies",), "expected a non-empty list of bodies")
        else:
            return raw
        return []

    def name(self, raw: dict, path: tuple, index: int, names: set[str]) -> str:
        """A body's name (default body<index>), unique among `names`, which it joins."""
        name = self.string(raw, "name", path, f"body{index}")
        if name in names:
            self.error(path + ("name",), f"a second body named '{name}'")
        names.add(name)
        return name

    def string(self, table: dict, key: str, path: tuple, default=None, choices=None):
        if key not in table:
            return default
        v = table[key]
        if not isinstance(v, str):
            self.error(path + (key,), f"expected a string, got {v!r}")
            return default
        if choices and v not in choices:
            self.error(path + (key,), f"must be one of {', '.join(choices)}, got '{v}'")
            return default
        return v


def _polygon_problem(vertices: list[Vec]) -> str | None:
    n = len(vertices)
    for k in range(n):
        (x0, y0), (x1, y1), (x2, y2) = vertices[k], vertices[(k + 1) % n], vertices[(k + 2) % n]
        if (x0, y0) == (x1, y1):
            return f"vertices {k} and {(k + 1) % n} coincide"
        turn = (x1 - x0) * (y2 - y1) - (y1 - y0) * (x2 - x1)
        if turn <= 0:
            area = sum(vertices[i][0] * vertices[(i + 1) % n][1]
                       - vertices[(i + 1) % n][0] * vertices[i][1] for i in range(n))
            if area < 0:
                return "the vertices go clockwise: list them anticlockwise"
            return f"not convex (or three vertices in a line) at vertex {(k + 1) % n}"
    turns = _turns(vertices)
    if turns != 1:
        return (f"not convex: the outline winds {turns} times around its inside (it crosses "
                f"itself); a convex polygon goes round once")
    return None


def _turns(vertices: list[Vec]) -> int:
    """How many times the outline of a polygon whose every corner turns left goes round: the
    sum of its exterior angles over 2 pi (1 for a convex polygon; a pentagram, a square listed
    twice, a spiral closing on itself turn 2 or more times, and every corner still turns
    left). The sum is a multiple of 2 pi up to rounding, so rounding it is exact."""
    n = len(vertices)
    total = 0.0
    for k in range(n):
        (x0, y0), (x1, y1), (x2, y2) = vertices[k - 1], vertices[k], vertices[(k + 1) % n]
        ax, ay, bx, by = x1 - x0, y1 - y0, x2 - x1, y2 - y1
        total += math.atan2(ax * by - ay * bx, ax * bx + ay * by)
    return round(total / (2 * math.pi))


def _shape(c: Checker, raw: dict, path: tuple, shape: str) -> tuple[float, list[Vec]]:
    """One convex shape's radius and vertices (offsets) from its keys; [] after an error."""
    radius = c.number(raw, "radius", path, 0.0, nonneg=True, required=shape == "circle")
    vertices: list[Vec] = []
    if shape == "circle":
        if raw.get("radius") == 0 and not isinstance(raw.get("radius"), bool):
            c.error(path + ("radius",), "a circle's radius must be positive")
        vertices = [c.vec(raw, "offset", path, (0.0, 0.0)) or (0.0, 0.0)]
    elif shape == "segment":
        pts = raw.get("points")
        if pts is None:
            c.error(path, "missing field 'points' (the segment's two ends)")
        elif not isinstance(pts, list) or len(pts) != 2:
            c.error(path + ("points",), f"expected two points [[x, y], [x, y]], got {pts!r}")
        else:
            vs = [c.vector(p, path + ("points", k)) for k, p in enumerate(pts)]
            if all(vs):
                vertices = vs  # type: ignore[assignment]
                if vertices[0] == vertices[1]:
                    c.error(path + ("points",), "the two ends coincide")
    elif shape == "polygon":
        vs_raw = raw.get("vertices")
        if vs_raw is None:
            c.error(path, "missing field 'vertices'")
        elif not isinstance(vs_raw, list) or len(vs_raw) < 3:
            c.error(path + ("vertices",), f"a polygon needs at least 3 vertices, got {vs_raw!r}")
        else:
            vs = [c.vector(p, path + ("vertices", k)) for k, p in enumerate(vs_raw)]
            if all(vs):
                vertices = vs  # type: ignore[assignment]
                problem = _polygon_problem(vertices)
                if problem:
                    c.error(path + ("vertices",), problem)
    else:  # box
        size = c.vec(raw, "size", path, required=True)
        if size is not None:
            if not (size[0] > 0 and size[1] > 0):
                c.error(path + ("size",), f"width and height must be positive, got {list(size)}")
            else:
                hw, hh = size[0] / 2, size[1] / 2
                vertices = [(-hw, -hh), (hw, -hh), (hw, hh), (-hw, hh)]
    return radius, vertices


def _parts(c: Checker, raw: dict, path: tuple) -> list[tuple[list[Vec], float]]:
    """A compound's parts, each a table with a shape's keys (errors at parts[k].key); [] after
    an error."""
    parts_raw = raw.get("parts")
    if parts_raw is None:
        c.error(path, "missing field 'parts' (the compound's shapes)")
        return []
    if not isinstance(parts_raw, list) or not parts_raw:
        c.error(path + ("parts",), f"expected a non-empty list of parts, got {_shown(parts_raw)}")
        return []
    before = len(c.errors)
    out = []
    for k, part in enumerate(parts_raw):
        where = path + ("parts", k)
        if not isinstance(part, dict):
            c.error(where, f"expected a table of part fields, got {_shown(part)}")
            continue
        c.keys(part, PART_KEYS, where)
        if "shape" not in part:
            c.error(where, "missing field 'shape' (circle, segment, polygon or box)")
            continue
        shape = c.string(part, "shape", where, None, tuple(PART_SHAPE_KEYS))
        if shape is None:
            continue
        for other, keys in PART_SHAPE_KEYS.items():
            for key in keys - PART_SHAPE_KEYS[shape]:
                if key in part:
                    c.error(where + (key,), f"'{key}' belongs to a {other}, not a {shape}")
        radius, vertices = _shape(c, part, where, shape)
        if shape == "box" and vertices:
            dx, dy = c.vec(part, "offset", where, (0.0, 0.0)) or (0.0, 0.0)
            vertices = [(x + dx, y + dy) for x, y in vertices]
        out.append((vertices, float(radius or 0.0)))
    return out if len(c.errors) == before and all(v for v, _ in out) else []


def _body(c: Checker, raw: object, index: int, names: set[str],
          tolerance: float) -> BodySpec | None:
    path = ("bodies", index)
    if not isinstance(raw, dict):
        c.error(path, f"expected a table of body fields, got {raw!r}")
        return None
    before = len(c.errors)
    c.keys(raw, BODY_KEYS, path)
    name = c.name(raw, path, index, names)
    kind = c.string(raw, "kind", path, "dynamic", KINDS)
    if "shape" not in raw:
        c.error(path, "missing field 'shape' (circle, segment, polygon, box or compound)")
        return None
    shape = c.string(raw, "shape", path, None, tuple(SHAPE_KEYS))
    if shape is None:
        return None
    told: set[str] = set()
    for other, keys in SHAPE_KEYS.items():
        for key in keys - SHAPE_KEYS[shape]:
            if key in raw and key not in told:
                told.add(key)
                c.error(path + (key,), f"'{key}' belongs to a {other}, not a {shape}"
                        if shape != "compound" else
                        f"'{key}' belongs to a compound's parts (parts[k].{key}), not to it")
    parts: list[tuple[list[Vec], float]] = []
    if shape == "compound":
        parts = _parts(c, raw, path)
        vertices = [v for vs, _ in parts for v in vs]
        radius = 0.0
    else:
        radius, vertices = _shape(c, raw, path, shape)
    position = c.vec(raw, "position", path, (0.0, 0.0), required=shape != "segment")
    angle = c.number(raw, "angle", path, 0.0)
    velocity = c.vec(raw, "velocity", path, (0.0, 0.0))
    omega = c.number(raw, "omega", path, 0.0)
    gravity = c.vec(raw, "gravity", path, None)
    mass = c.number(raw, "mass", path, None, positive=True)
    density = c.number(raw, "density", path, 1.0, positive=True)
    if "mass" in raw and "density" in raw:
        c.error(path + ("density",), "give mass or density, not both")
    inertia = c.number(raw, "inertia", path, None, positive=True)
    restitution = c.number(raw, "restitution", path, 1.0, lo=0.0, hi=1.0)
    friction = c.number(raw, "friction", path, 0.0, nonneg=True)
    group = c.string(raw, "group", path, None)
    color = c.string(raw, "color", path, None)
    if color is not None and not re.fullmatch(r"#[0-9a-fA-F]{6}([0-9a-fA-F]{2})?", color):
        c.error(path + ("color",), f"expected a colour '#rrggbb' or '#rrggbbaa', got '{color}'")
        color = None
    if kind == "static" and ("velocity" in raw or "omega" in raw or "gravity" in raw):
        key = next(k for k in ("velocity", "omega", "gravity") if k in raw)
        c.error(path + (key,), "a static body does not move (make it kinematic)")
    if kind == "dynamic" and shape == "segment" and not radius and mass is None:
        c.error(path, "a dynamic thin segment has no area: give it a radius (a capsule) or a mass")
    if (kind == "dynamic" and shape == "compound" and mass is None and parts
            and all(len(v) == 2 and not r for v, r in parts)):
        c.error(path, "a dynamic compound of thin segments has no area: give a part a radius "
                "or the body a mass")
    if len(c.errors) > before or not vertices:
        return None
    shapes = parts or [(vertices, float(radius or 0.0))]
    if kind == "dynamic":
        _mass_check(c, raw, path, shapes, mass, density, inertia)
    reach = max(max(abs(x), abs(y)) + r for vs, r in shapes for x, y in transform(
        vs, (*(position or (0.0, 0.0)), angle)))
    problem = limits.span_problem(reach, tolerance)
    if problem:
        c.error(path, problem)
    if len(c.errors) > before:
        return None
    return BodySpec(name, kind, shape, tuple(vertices), float(radius or 0.0), position or (0.0, 0.0),
                    angle, velocity or (0.0, 0.0), omega, gravity, mass, density, inertia,
                    restitution, group, color, friction,
                    tuple((tuple(v), r) for v, r in parts))


def _mass_check(c: Checker, raw: dict, path: tuple, shapes: list[tuple[list[Vec], float]],
                mass: float | None, density: float, inertia: float | None) -> None:
    """A dynamic body's mass and inertia, as World.add_body derives them, within what the
    engine's arithmetic holds (limits.MASS, limits.INERTIA), located at the key they come from
    (mass, density, inertia, else the body: the default density times the shape's area)."""
    try:
        props = (mass_properties(*shapes[0]) if len(shapes) == 1 and "parts" not in raw
                 else compound_mass_properties(shapes))
    except ZeroDivisionError:  # an area that rounds to 0
        c.error(path, "the shape's area rounds to 0 (too thin for its coordinates)")
        return
    m = mass if mass is not None else density * props.area
    where = path + (("mass",) if "mass" in raw else ("density",) if "density" in raw else ())
    problem = limits.range_problem("mass" if mass is not None else "mass (density x area)", m,
                                   limits.MASS)
    if problem:
        c.error(where, problem)
        return
    i = inertia if inertia is not None else m * props.inertia_per_mass
    problem = limits.range_problem("moment of inertia", i, limits.INERTIA)
    if problem:
        c.error(path + (("inertia",) if "inertia" in raw else ()), problem)


def near_pairs(circles: list[tuple[float, float, float]], teams: list | None = None,
               fixed: list[bool] | None = None) -> Iterator[tuple[int, int]]:
    """The pairs (i < j) of circles (cx, cy, r) that overlap or touch, each once: a grid per
    size class (radii within a factor of 2), cells twice the class's largest radius, so that a
    circle lies in at most 2 x 2 cells of its own grid, and one of a smaller class meets a
    larger class's circles in at most 2 x 2 of that grid's cells (two circles that touch have
    boxes that share a point, which some cell of either grid holds).  Near linear however the
    bodies line up or differ in size: a sweep along x alone was quadratic on a column (29 s for
    20 000 circles), and one grid of the median size on a scene of two sizes.  Circles whose
    cells the floats cannot number (huge coordinates for their size) are tested against every
    other one instead.

    Only pairs that can collide are looked at: of different `teams` (a group; None is a team
    of its own) and not both `fixed` (static or kinematic). A cell keeps its circles by team,
    so 5000 bodies of one group at one spot cost 5000 steps, not the 12.5 million pairs they
    make (32 s before)."""
    n = len(circles)
    team = [("#", k) if teams is None or teams[k] is None else ("g", teams[k]) for k in range(n)]
    still = fixed or [False] * n
    classes: dict[int, list[int]] = {}
    odd: list[int] = []
    for k, (x, y, r) in enumerate(circles):
        if r > 0 and math.isfinite(r) and math.isfinite(x) and math.isfinite(y):
            classes.setdefault(math.frexp(r)[1], []).append(k)
        else:
            odd.append(k)
    # a grid's cell: (team -> its moving members, team -> its fixed members)
    Cell = tuple[dict[tuple, list[int]], dict[tuple, list[int]]]
    grids: list[tuple[float, dict[tuple[int, int], Cell]]] = []
    for e in sorted(classes):
        size = 2 * max(circles[k][2] for k in classes[e])
        grid: dict[tuple[int, int], Cell] = {}
        for k in classes[e]:
            cells = _cells(circles[k], size)
            if cells is None:
                odd.append(k)
                continue
            for cell in cells:
                grid.setdefault(cell, ({}, {}))[still[k]].setdefault(team[k], []).append(k)
        grids.append((size, grid))
    seen: set[tuple[int, int]] = set()

    def touching(i: int, j: int) -> bool:
        (xi, yi, ri), (xj, yj, rj) = circles[i], circles[j]
        return math.hypot(xi - xj, yi - yj) <= ri + rj

    def pair(i: int, j: int) -> tuple[int, int] | None:
        p = (i, j) if i < j else (j, i)
        if i == j or p in seen or not touching(*p):
            return None
        seen.add(p)
        return p

    def partners(i: int, cell: Cell) -> Iterator[int]:
        """The members of a cell that can collide with i: other teams' moving members, and
        their fixed ones too when i moves (a fixed i never walks the fixed teams)."""
        for teams_of in cell[:1] if still[i] else cell:
            for t, members in teams_of.items():
                if t != team[i]:
                    yield from members

    for g, (size, grid) in enumerate(grids):
        for cell in grid.values():  # within the class: each pair from its moving member
            for moving in cell[0].values():
                for i in moving:
                    for j in partners(i, cell):
                        if (p := pair(i, j)) is not None:
                            yield p
        for cell in grid.values():  # against the larger classes
            for members in (*cell[0].values(), *cell[1].values()):
                for i in members:
                    for big_size, big in grids[g + 1:]:
                        for c in _cells(circles[i], big_size) or ():
                            for j in partners(i, big.get(c, ({}, {}))):
                                if (p := pair(i, j)) is not None:
                                    yield p
    for i in odd:
        for j in range(n):
            if team[i] != team[j] and not (still[i] and still[j]) and (p := pair(i, j)) is not None:
                yield p


def _cells(circle: tuple[float, float, float], size: float) -> list[tuple[int, int]] | None:
    """The cells of a grid of that size that the circle's box covers; None where the floats
    cannot number them."""
    x, y, r = circle
    try:
        x0, x1 = math.floor((x - r) / size), math.floor((x + r) / size)
        y0, y1 = math.floor((y - r) / size), math.floor((y + r) / size)
    except (OverflowError, ValueError):
        return None
    if (x1 - x0 + 1) * (y1 - y0 + 1) > 9:
        return None  # (never for a circle of the grid's class or a smaller one)
    return [(gx, gy) for gx in range(x0, x1 + 1) for gy in range(y0, y1 + 1)]


def _overlaps(c: Checker, bodies: list[tuple[int, BodySpec]], tolerance: float) -> None:
    """Bodies that start overlapping (by more than the tolerance): exact geometry, pairs that can
    collide (a dynamic one, different groups), near pairs only (bounding circles)."""
    shapes = []
    for index, b in bodies:
        pose = (b.position[0], b.position[1], b.angle)
        parts = [(transform(vs, pose), r) for vs, r in b.shapes]
        pts = [p for ps, _ in parts for p in ps]
        cx = sum(p[0] for p in pts) / len(pts)
        cy = sum(p[1] for p in pts) / len(pts)
        r = max(math.hypot(p[0] - cx, p[1] - cy) + rp for ps, rp in parts for p in ps)
        shapes.append((index, b, parts, cx, cy, r))
    found = []
    for ka, kb in near_pairs([(cx, cy, r) for _, _, _, cx, cy, r in shapes],
                             [b.group for _, b, *_ in shapes],
                             [b.kind != "dynamic" for _, b, *_ in shapes]):
        ia, a, pa = shapes[ka][:3]
        ib, b, pb = shapes[kb][:3]
        g = min(gap(p, rp, q, rq) for p, rp in pa for q, rq in pb)   # (a compound: its parts)
        if g < -tolerance:
            found.append(((ia, a.name), (ib, b.name), -g))
            if len(found) == MAX_OVERLAPS:
                c.stopped = f"the overlap check stopped after {MAX_OVERLAPS} overlapping pairs"
                break
    report_overlaps(c, found)


def report_overlaps(c: Checker, found: list[tuple[tuple[int, str], tuple[int, str], float]],
                    why: str = "") -> None:
    """Each overlap ((index, name) of both bodies, depth) as an error at the later body of the
    file, in file order whatever order near_pairs found them in."""
    rows = []
    for one, other, depth in found:
        (first, first_name), (second, second_name) = sorted((one, other))
        rows.append((second, first, f"body '{second_name}' starts overlapping body "
                     f"'{first_name}' (bodies[{first}]) by {depth:.3g}{why}"))
    for second, _, message in sorted(rows):
        c.error(("bodies", second), message)


# The overlapping pairs looked for before the check stops (3000 bodies at one spot make 4.5
# million: 2.8 GB of messages and a minute), and the errors a scene's check reports at most
# (the rest are counted).
MAX_OVERLAPS = 100
MAX_ERRORS = 20

# max_events goes to the core as a long long: a whole number below 2^62 (a limit that large
# is no limit in practice, and no closer to overflowing its count)
MAX_EVENTS_LIMIT = limits.MAX_EVENTS

# The largest scene file read: a scene is data a person or a tool wrote, and a device such as
# /dev/zero must end in an error, not in all the memory there is.
MAX_SCENE_BYTES = 64 * 2**20


def read_located(path: str | FilePath) -> Located:
    """A scene file (JSON, or TOML by its suffix) parsed with the position of every value;
    SceneError with `file:line:col: error:` when it cannot be read or parsed -- too large,
    not UTF-8, malformed, or nested too deeply for the parser."""
    path = FilePath(path)
    shown = str(path)
    try:
        with open(path, "rb") as f:
            raw = f.read(MAX_SCENE_BYTES + 1)
        if len(raw) > MAX_SCENE_BYTES:
            raise SceneError([f"{shown}:1:1: error: the scene is larger than "
                              f"{MAX_SCENE_BYTES // 2**20} MiB"])
        text = raw.decode("utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise SceneError([f"{shown}:1:1: error: cannot read the scene: {exc}"]) from exc
    try:
        return parse_toml(text) if path.suffix.lower() == ".toml" else parse_json(text)
    except TextError as exc:
        raise SceneError([f"{shown}:{exc.line}:{exc.col}: error: {exc.message}"]) from exc
    except RecursionError:
        raise SceneError([f"{shown}:1:1: error: the scene is nested too deeply to read"]) from None


def load(path: str | FilePath) -> Scene:
    """Read and check a scene file; raises SceneError with every problem found."""
    doc = read_located(path)
    return check(doc, str(FilePath(path)), FilePath(path).stem)


def check(doc: Located, shown: str, stem: str = "scene") -> Scene:
    c = Checker(shown, doc)
    data = doc.data
    if not isinstance(data, dict):
        raise SceneError([f"{shown}:1:1: error: a scene is a table (JSON object) of fields"])
    c.keys(data, TOP_KEYS, ())
    name = c.string(data, "name", (), stem)
    gravity = c.vec(data, "gravity", (), (0.0, 0.0)) or (0.0, 0.0)
    tolerance = c.number(data, "tolerance", (), 1e-9, positive=True)
    until = c.number(data, "until", (), None, positive=True)
    fps = c.number(data, "fps", (), None, positive=True)
    view = None
    if "view" in data:
        v = data["view"]
        if (isinstance(v, list) and len(v) == 4 and all(isinstance(x, (int, float)) and
                                                        not isinstance(x, bool) for x in v)
                and v[0] < v[2] and v[1] < v[3]
                and all(limits.finite(x) for x in (*v, v[2] - v[0], v[3] - v[1]))):
            view = tuple(float(x) for x in v)
            problem = next(filter(None, map(limits.magnitude_problem, view)), None)
            if problem:
                c.error(("view",), problem)
                view = None
        else:
            c.error(("view",), f"expected [xmin, ymin, xmax, ymax], finite, with xmin < xmax, "
                    f"ymin < ymax, got {_shown(v)}")
    eng = data.get("engine", {})
    if not isinstance(eng, dict):
        c.error(("engine",), "expected a table")
        eng = {}
    c.keys(eng, ENGINE_KEYS, ("engine",))
    cell_size = c.number(eng, "cell_size", ("engine",), 0.0)
    rest_speed = c.number(eng, "rest_speed", ("engine",), 0.0)
    collapse_time = c.number(eng, "collapse_time", ("engine",), 0.0)
    max_events = c.number(eng, "max_events", ("engine",), 0.0, nonneg=True)
    if max_events != int(max_events) or max_events > MAX_EVENTS_LIMIT:
        c.error(("engine", "max_events"), f"expected a whole number of events from 0 to "
                f"{MAX_EVENTS_LIMIT}, got {max_events:g}")
        max_events = 0.0
    contact_step = c.number(eng, "contact_step", ("engine",), limits.CONTACT_STEP, nonneg=True)
    bodies: list[tuple[int, BodySpec]] = []
    names: set[str] = set()
    for k, raw in enumerate(c.bodies(data)):
        b = _body(c, raw, k, names, tolerance)
        if b is not None:
            bodies.append((k, b))
    if not c.errors:
        _overlaps(c, bodies, tolerance)
    if c.errors:
        raise SceneError(c.diagnostics())
    places = tuple("{}:{}:{}".format(shown, *doc.where(("bodies", k))) for k, _ in bodies)
    return Scene(name, tuple(b for _, b in bodies), gravity, tolerance, until, fps, view,
                 cell_size, rest_speed, collapse_time, int(max_events), contact_step, shown,
                 places)


def build_world(scene: Scene):
    """The scene's World, bodies in file order (body i of the file is id i). A body the engine
    refuses is a SceneError at its place in the file (the message is the engine's)."""
    from .world import EngineError, World

    w = World(gravity=scene.gravity, tolerance=scene.tolerance, cell_size=scene.cell_size,
              rest_speed=scene.rest_speed, collapse_time=scene.collapse_time,
              max_events=scene.max_events, contact_step=scene.contact_step)
    for k, b in enumerate(scene.bodies):
        shape = dict(parts=b.parts) if b.parts else dict(vertices=b.vertices, radius=b.radius)
        try:
            w.add_body(**shape, kind=b.kind, position=b.position,
                       angle=b.angle, velocity=b.velocity, omega=b.omega, gravity=b.gravity,
                       mass=b.mass, density=b.density, inertia=b.inertia,
                       restitution=b.restitution, friction=b.friction, group=b.group,
                       name=b.name, color=b.color)
        except EngineError as exc:
            place = scene.places[k] if k < len(scene.places) else f"{scene.path}:1:1"
            raise SceneError([f"{place}: error: bodies[{k}]: the engine refused this body: "
                              f"{exc}"]) from exc
    return w
