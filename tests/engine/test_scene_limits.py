"""Scene numbers the engine's arithmetic cannot hold, hostile text and scenes made to blow up
the checker (issue 33, items 5, 7 and 8): each is a located error with exit status 1, never an
internal error (exit 2), a NaN in the output or minutes of work."""

from __future__ import annotations

import json
import math
import subprocess
import sys
import time
from pathlib import Path

import pytest

from conftest import ROOT
from max2code.engine.scenefile import (MAX_ERRORS, BodySpec, Scene, SceneError, build_world,
                                       load, near_pairs)

FLOOR = '''\
gravity = [0, -10]

[[bodies]]
name = "floor"
kind = "static"
shape = "segment"
points = [[-5, 0], [5, 0]]

[[bodies]]
name = "ball"
shape = "circle"
position = [0, 1]
radius = 0.1
'''


def polygon(vertices: list[tuple[float, float]]) -> str:
    listed = ", ".join(f"[{x!r}, {y!r}]" for x, y in vertices)
    return f'[[bodies]]\nshape = "polygon"\nposition = [0, 0]\nvertices = [{listed}]\n'


STAR = [(math.cos(math.pi / 2 + k * 4 * math.pi / 5), math.sin(math.pi / 2 + k * 4 * math.pi / 5))
        for k in range(5)]
# a spiral of two turns (80 degrees a corner, 1% wider each) whose every corner turns left, its
# closing corners too
SPIRAL = [((1 + 0.01 * k) * math.cos(k * 4 * math.pi / 9), (1 + 0.01 * k) * math.sin(k * 4 * math.pi / 9))
          for k in range(9)]

# (what, file name, text, line, col, words in the first error)
CASES = [
    ("a mass of 1e308 (an infinite impulse, a NaN floor)", "s.toml",
     FLOOR + "mass = 1e308\n", 14, 1, ["bodies[1].mass", "too large", "1e+30"]),
    ("a density whose mass overflows", "s.toml",
     '[[bodies]]\nshape = "circle"\nposition = [0, 0]\nradius = 100\ndensity = 1e30\n', 5, 1,
     ["bodies[0].density", "mass (density x area) 3.14e+34"]),
    ("a box 5e-324 wide (ZeroDivisionError)", "s.toml",
     '[[bodies]]\nshape = "box"\nposition = [0, 1]\nsize = [5e-324, 1]\n', 4, 1,
     ["bodies[0].size[0]", "too small"]),
    ("capsule points at 1e308 (OverflowError)", "s.toml",
     '[[bodies]]\nshape = "segment"\nradius = 0.1\npoints = [[-1e308, 0], [1e308, 0]]\n', 4, 1,
     ["bodies[0].points[0][0]", "too large"]),
    ("a capsule 1e15 long at tolerance 1e-9 (hung)", "s.toml",
     '[[bodies]]\nshape = "segment"\nradius = 0.1\npoints = [[-5e14, 0], [5e14, 0]]\n', 1, 3,
     ["bodies[0]", "2^45 tolerances", "raise the tolerance"]),
    ("gravity of 1e308", "s.toml", FLOOR.replace("[0, -10]", "[0, -1e308]"), 1, 1,
     ["gravity[1]", "too large"]),
    ("omega of 1e308", "s.toml", FLOOR + "omega = 1e308\n", 14, 1, ["bodies[1].omega", "too large"]),
    ("a subnormal velocity", "s.toml", FLOOR + "velocity = [5e-324, 0]\n", 14, 1,
     ["bodies[1].velocity", "too small"]),
    ("a lone surrogate in a name (UnicodeEncodeError)", "s.json",
     '{"bodies": [{"name": "a\\ud800", "shape": "circle", "position": [0, 0], "radius": 1}]}',
     1, 22, ["unpaired surrogate", "\\ud800"]),
    ("a lone surrogate in a key", "s.json", '{"\\udc00": 1, "bodies": []}', 1, 2,
     ["unpaired surrogate"]),
    ("a 100,000-digit integer in JSON (ValueError)", "s.json",
     '{"bodies": [{"shape": "circle", "position": [0, 0], "radius": 1' + "0" * 100_000 + "}]}",
     1, 53, ["bodies[0].radius", "finite"]),
    ("a 100,000-digit integer in TOML (ValueError)", "s.toml",
     '[[bodies]]\nshape = "circle"\nposition = [0, 0]\nradius = 1' + "0" * 100_000 + "\n",
     4, 10, ["too long to read"]),
    ("a pentagram", "s.toml", polygon(STAR), 4, 1, ["bodies[0].vertices", "winds 2 times"]),
    ("a square wound twice", "s.toml", polygon([(0, 0), (1, 0), (1, 1), (0, 1)] * 2), 4, 1,
     ["bodies[0].vertices", "winds 2 times"]),
    ("a spiral", "s.toml", polygon(SPIRAL), 4, 1, ["bodies[0].vertices", "winds 2 times"]),
]


@pytest.mark.parametrize("what,name,text,line,col,words", CASES, ids=[c[0] for c in CASES])
def test_located(tmp_path: Path, what: str, name: str, text: str, line: int, col: int,
                 words: list[str]) -> None:
    path = tmp_path / name
    path.write_text(text)
    with pytest.raises(SceneError) as info:
        load(path)
    first = info.value.diagnostics[0]
    assert first.startswith(f"{path}:{line}:{col}: error: "), first
    assert all(w in first for w in words), (words, first)


def run_sim(*args: str, timeout: float = 120) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "max2code", "sim", *args], capture_output=True,
                          text=True, cwd=ROOT, timeout=timeout)


@pytest.mark.parametrize("case", [c for c in CASES if "Error" in c[0]], ids=lambda c: c[0])
def test_cli_exit_1_not_internal(tmp_path: Path, case) -> None:
    """The cases that were internal errors (exit 2) through `max2code sim`."""
    what, name, text, line, col, words = case
    path = tmp_path / name
    path.write_text(text)
    proc = run_sim(str(path), "--until", "0.1", "--json")
    assert proc.returncode == 1, proc.stderr
    assert proc.stderr.startswith(f"{path}:{line}:{col}: error: "), proc.stderr
    assert "internal error" not in proc.stderr and not proc.stdout


def test_fps_too_low_for_pictures(tmp_path: Path) -> None:
    """--fps 1e-300 with a GIF overflowed the GIF's delay field (OverflowError, exit 2)."""
    path = tmp_path / "s.toml"
    path.write_text(FLOOR)
    gif = tmp_path / "x.gif"
    proc = run_sim(str(path), "--until", "1", "--fps", "1e-300", "--gif", str(gif))
    assert proc.returncode == 1 and "--fps 1e-300 is below 0.01" in proc.stderr, proc.stderr
    assert not gif.exists()


def strict_json(text: str) -> object:
    def refuse(name: str) -> object:
        raise ValueError(f"{name} is not JSON")
    return json.loads(text, parse_constant=refuse)


def test_json_has_no_nan(tmp_path: Path) -> None:
    """The summary and the event log are JSON that a strict reader accepts; what cannot be a
    number there (an energy that overflowed) is null."""
    from max2code.jsonsafe import json_safe

    assert json_safe({"a": [math.nan, 1.5, (math.inf,)], "b": -math.inf, "c": "x"}) == \
        {"a": [None, 1.5, [None]], "b": None, "c": "x"}
    path = tmp_path / "s.toml"
    path.write_text(FLOOR)
    events = tmp_path / "e.jsonl"
    proc = run_sim(str(path), "--until", "1", "--json", "--events", str(events))
    assert proc.returncode == 0, proc.stderr
    assert strict_json(proc.stdout)["bodies"] == 2
    assert all(strict_json(line) for line in events.read_text().splitlines())


def test_engine_refusal_is_located(tmp_path: Path) -> None:
    """A body the engine refuses (here one the checker would have refused, built directly) is a
    SceneError at the body's place in the file, with the engine's reason."""
    path = tmp_path / "s.toml"
    path.write_text(FLOOR)
    scene = load(path)
    bad = BodySpec("odd", "dynamic", "circle", ((0.0, 0.0),), 0.1, (0.0, 1.0), restitution=2.0)
    broken = Scene(scene.name, (scene.bodies[0], bad), scene.gravity, path=str(path),
                   places=scene.places)
    with pytest.raises(SceneError) as info:
        build_world(broken)
    assert info.value.diagnostics == [f"{path}:9:3: error: bodies[1]: the engine refused this "
                                      f"body: restitution: must be between 0 and 1, got 2"]


def test_many_overlaps_bounded(tmp_path: Path) -> None:
    """3000 bodies at one spot: 4.5 million overlapping pairs gave 4.5 million lines (2.8 GB,
    59 s); now the first MAX_ERRORS and notes saying there are more, within seconds."""
    path = tmp_path / "spot.json"
    path.write_text(json.dumps({"bodies": [{"shape": "circle", "position": [0, 0], "radius": 1}
                                           for _ in range(3000)]}))
    start = time.monotonic()
    proc = run_sim(str(path), "--until", "0.1")
    seconds = time.monotonic() - start
    lines = proc.stderr.splitlines()
    assert proc.returncode == 1 and seconds < 30, seconds
    assert len(lines) == MAX_ERRORS + 2, lines[-3:]
    assert lines[0] == (f"{path}:1:67: error: bodies[1]: body 'body1' starts overlapping body "
                        f"'body0' (bodies[0]) by 2")
    assert "more errors not listed" in lines[-2] and "stopped after 100" in lines[-1]


def test_many_errors_counted(tmp_path: Path) -> None:
    path = tmp_path / "bad.json"
    path.write_text(json.dumps({"bodies": [{"shape": "circle", "position": [3 * k, 0],
                                            "radius": -1} for k in range(500)]}))
    with pytest.raises(SceneError) as info:
        load(path)
    d = info.value.diagnostics
    assert len(d) == MAX_ERRORS + 1 and d[-1] == (f"{path}: note: {500 - MAX_ERRORS} more errors "
                                                  f"not listed (the first {MAX_ERRORS} are)")


@pytest.mark.parametrize("extra", [{"group": "g"}, {"kind": "static"}], ids=["grouped", "static"])
def test_crowds_that_cannot_collide_are_fast(tmp_path: Path, extra: dict) -> None:
    """5000 bodies of one group (or 5000 static ones) at one spot never collide with each other:
    the overlap check took 32 s over their 12.5 million pairs."""
    path = tmp_path / "crowd.json"
    path.write_text(json.dumps({"bodies": [{"shape": "circle", "position": [0, 0], "radius": 1,
                                            **extra} for _ in range(5000)]}))
    start = time.monotonic()
    scene = load(path)
    assert len(scene.bodies) == 5000 and time.monotonic() - start < 8


def test_near_pairs_only_pairs_that_can_collide() -> None:
    """near_pairs with teams and fixed bodies against all pairs: touching, of different teams
    (None: a team of its own), not both fixed."""
    import random

    rng = random.Random(7)
    n = 400
    circles = [(rng.uniform(-3, 3), rng.uniform(-3, 3), rng.choice([0.05, 0.3, 1.0]))
               for _ in range(n)]
    teams = [rng.choice([None, None, "a", "b"]) for _ in range(n)]
    fixed = [rng.random() < 0.3 for _ in range(n)]
    want = {(i, j) for i in range(n) for j in range(i + 1, n)
            if math.hypot(circles[i][0] - circles[j][0], circles[i][1] - circles[j][1])
            <= circles[i][2] + circles[j][2]
            and (teams[i] is None or teams[i] != teams[j]) and not (fixed[i] and fixed[j])}
    got = list(near_pairs(circles, teams, fixed))
    assert len(got) == len(set(got)) and set(got) == want and len(want) > 1000
