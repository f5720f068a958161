"""Scene files: every kind of bad input gets `file:line:col: error: key.path: ...` at the right
place, through the API and through `max2code sim` (exit status 1, no output written)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from conftest import ROOT
from max2code.engine.scenefile import SceneError, load

GOOD = """\
name = "ok"
gravity = [0, -10]

[[bodies]]
kind = "static"
shape = "segment"
points = [[-1, 0], [1, 0]]

[[bodies]]
name = "ball"
shape = "circle"
position = [0, 1]
radius = 0.1
"""

# (what is wrong, the TOML, the line and column, words the message must hold)
BAD_TOML = [
    ("unknown top-level key", GOOD.replace('gravity = [0, -10]', 'gravty = [0, -10]'),
     2, 1, ["gravty", "unknown key", "did you mean 'gravity'"]),
    ("unknown body key", GOOD.replace("radius = 0.1", "radius = 0.1\nmas = 2"),
     14, 1, ["bodies[1].mas", "unknown key", "mass"]),
    ("negative radius", GOOD.replace("radius = 0.1", "radius = -0.1"),
     13, 1, ["bodies[1].radius", "must not be negative"]),
    ("missing radius", GOOD.replace("radius = 0.1\n", ""),
     9, 3, ["bodies[1]", "missing field 'radius'"]),
    ("missing position", GOOD.replace("position = [0, 1]\n", ""),
     9, 3, ["bodies[1]", "missing field 'position'"]),
    ("missing shape", GOOD.replace('shape = "circle"\n', ""),
     9, 3, ["bodies[1]", "missing field 'shape'"]),
    ("starts overlapping", GOOD.replace("position = [0, 1]", "position = [0, 0.05]"),
     9, 3, ["bodies[1]", "overlapping", "by 0.05"]),
    ("a box across a thin wall", GOOD.replace('shape = "circle"\nposition = [0, 1]\nradius = 0.1',
                                              'shape = "box"\nposition = [0, 0.1]\nsize = [0.4, 0.4]'),
     9, 3, ["bodies[1]", "overlapping", "by 0.1"]),
    ("negative friction", GOOD.replace("radius = 0.1", "radius = 0.1\nfriction = -0.5"),
     14, 1, ["bodies[1].friction", "must not be negative"]),
    ("a wrong type", GOOD.replace("radius = 0.1", 'radius = "big"'),
     13, 1, ["bodies[1].radius", "expected a finite number"]),
    ("restitution above 1", GOOD.replace("radius = 0.1", "radius = 0.1\nrestitution = 1.5"),
     14, 1, ["bodies[1].restitution", "between 0 and 1"]),
    ("two bodies with one name", GOOD.replace('kind = "static"', 'name = "ball"\nkind = "static"'),
     11, 1, ["bodies[1].name", "second body named 'ball'"]),
    ("clockwise polygon", GOOD.replace('shape = "circle"\nposition = [0, 1]\nradius = 0.1',
                                       'shape = "polygon"\nposition = [0, 1]\nvertices = [[0, 0], [0, 0.1], [0.1, 0]]'),
     13, 1, ["bodies[1].vertices", "clockwise"]),
    ("concave polygon", GOOD.replace('shape = "circle"\nposition = [0, 1]\nradius = 0.1',
                                     'shape = "polygon"\nposition = [0, 1]\n'
                                     'vertices = [[0, 0], [0.2, 0], [0.1, 0.05], [0.2, 0.2], [0, 0.2]]'),
     13, 1, ["bodies[1].vertices", "not convex"]),
    ("a key of another shape", GOOD.replace("radius = 0.1", "radius = 0.1\nvertices = [[0, 0]]"),
     14, 1, ["bodies[1].vertices", "belongs to a polygon"]),
    ("a static body with a velocity", GOOD.replace('kind = "static"', 'kind = "static"\nvelocity = [1, 0]'),
     6, 1, ["bodies[0].velocity", "does not move"]),
    ("unknown kind", GOOD.replace('kind = "static"', 'kind = "solid"'),
     5, 1, ["bodies[0].kind", "must be one of"]),
    ("bad colour", GOOD.replace("radius = 0.1", 'radius = 0.1\ncolor = "red"'),
     14, 1, ["bodies[1].color", "#rrggbb"]),
    ("negative tolerance", "tolerance = -1\n" + GOOD, 1, 1, ["tolerance", "must be positive"]),
    ("TOML syntax", GOOD.replace("radius = 0.1", "radius = = 0.1"), 13, 10, ["error"]),
    ("no bodies", 'name = "x"\n', 1, 1, ["missing field 'bodies'"]),
    ("an infinite view", "view = [-inf, -1, inf, 1]\n" + GOOD, 1, 1, ["view", "finite"]),
    ("a view too wide for a float", "view = [-1e308, -1, 1e308, 1]\n" + GOOD, 1, 1,
     ["view", "finite"]),
    ("max_events not whole", GOOD + "\n[engine]\nmax_events = 0.5\n", 16, 1,
     ["engine.max_events", "whole number"]),
    ("max_events beyond the core's count", GOOD + "\n[engine]\nmax_events = 1e30\n", 16, 1,
     ["engine.max_events", "whole number"]),
    ("an int no float holds", GOOD + "\n[engine]\nmax_events = 1" + "0" * 400 + "\n", 16, 1,
     ["engine.max_events", "expected a finite number", "..."]),
]


def first_error(path: Path, text: str) -> str:
    path.write_text(text)
    with pytest.raises(SceneError) as info:
        load(path)
    return info.value.diagnostics[0]


@pytest.mark.parametrize("what,text,line,col,words", BAD_TOML, ids=[b[0] for b in BAD_TOML])
def test_bad_toml(tmp_path: Path, what: str, text: str, line: int, col: int, words: list[str]) -> None:
    path = tmp_path / "scene.toml"
    first = first_error(path, text)
    assert first.startswith(f"{path}:{line}:{col}: error: "), first
    assert all(word in first for word in words), (words, first)


BAD_JSON = [
    ("unknown key", '{"bodies": [{"shape": "circle", "position": [0, 0], "radius": 1,\n'
                    '  "colour": "#ff0000"}]}', 2, 3, ["bodies[0].colour", "did you mean 'color'"]),
    ("negative radius", '{"bodies": [\n {"shape": "circle",\n  "position": [0, 0],\n  "radius": -2}]}',
     4, 3, ["bodies[0].radius", "must not be negative"]),
    ("overlap", '{"bodies": [{"shape": "circle", "position": [0, 0], "radius": 1},\n'
                ' {"shape": "circle", "position": [1.5, 0], "radius": 1}]}', 2, 2,
     ["bodies[1]", "overlapping", "bodies[0]"]),
    ("a vector of three", '{"gravity": [0, -10, 0], "bodies": []}', 1, 2, ["gravity", "expected [x, y]"]),
    ("JSON syntax", '{"bodies": [\n  {"shape": "circle",, "radius": 1}]}', 2, 22, ["expected a key"]),
    ("duplicate key", '{"bodies": [], "bodies": []}', 1, 16, ["duplicate key 'bodies'"]),
    ("trailing text", '{"bodies": []} x', 1, 16, ["after the end"]),
]


@pytest.mark.parametrize("what,text,line,col,words", BAD_JSON, ids=[b[0] for b in BAD_JSON])
def test_bad_json(tmp_path: Path, what: str, text: str, line: int, col: int, words: list[str]) -> None:
    path = tmp_path / "scene.json"
    first = first_error(path, text)
    assert first.startswith(f"{path}:{line}:{col}: error: "), first
    assert all(word in first for word in words), (words, first)


def test_every_problem_reported(tmp_path: Path) -> None:
    text = GOOD.replace("radius = 0.1", "radius = -1\nfoo = 2").replace('gravity = [0, -10]', "gravity = 3")
    path = tmp_path / "s.toml"
    path.write_text(text)
    with pytest.raises(SceneError) as info:
        load(path)
    d = info.value.diagnostics
    assert any("gravity" in x for x in d) and any(".foo" in x for x in d) and any(".radius" in x for x in d)


def test_good_scene_loads(tmp_path: Path) -> None:
    path = tmp_path / "s.toml"
    path.write_text(GOOD)
    scene = load(path)
    assert [b.name for b in scene.bodies] == ["body0", "ball"]
    assert scene.gravity == (0.0, -10.0) and scene.bodies[0].kind == "static"
    assert scene.bodies[1].vertices == ((0.0, 0.0),) and scene.bodies[1].radius == 0.1


def test_cli_bad_scene_exit_status(tmp_path: Path) -> None:
    path = tmp_path / "s.toml"
    path.write_text(GOOD.replace("radius = 0.1", "radius = -0.1"))
    events = tmp_path / "events.jsonl"
    events.write_text("previous\n")
    proc = subprocess.run([sys.executable, "-m", "max2code", "sim", str(path), "--events", str(events)],
                          capture_output=True, text=True, cwd=ROOT)
    assert proc.returncode == 1
    assert f"{path}:13:1: error: bodies[1].radius: must not be negative" in proc.stderr
    assert "Traceback" not in proc.stderr
    assert events.read_text() == "previous\n"  # existing output untouched


@pytest.mark.parametrize("scene", sorted((ROOT / "examples" / "scenes").glob("*.toml")), ids=lambda p: p.name)
def test_example_scenes_load(scene: Path) -> None:
    assert load(scene).bodies


def test_hostile_files_are_located_errors(tmp_path: Path) -> None:
    """Input made to break the reader: nesting deeper than the parser's recursion (JSON and
    TOML), and an endless device (/dev/zero: the reader stops at 64 MiB) -- each a located
    error with exit 1, never an internal error (exit 2) or all the memory there is."""
    deep_json = tmp_path / "deep.json"
    deep_json.write_text("[" * 100_000 + "]" * 100_000)
    deep_toml = tmp_path / "deep.toml"
    deep_toml.write_text("x = " + "[" * 100_000 + "]" * 100_000 + "\n")
    for path, words in ((deep_json, "nested too deeply"), (deep_toml, "error"),
                        (Path("/dev/zero"), "larger than 64 MiB")):
        proc = subprocess.run([sys.executable, "-m", "max2code", "sim", str(path)],
                              capture_output=True, text=True, cwd=ROOT, timeout=120)
        assert proc.returncode == 1, (path, proc.stderr)
        assert proc.stderr.startswith(f"{path}:") and ": error: " in proc.stderr, proc.stderr
        assert words in proc.stderr and "Traceback" not in proc.stderr, proc.stderr


def test_near_pairs_finds_every_touching_pair() -> None:
    """The overlap check's grids against all pairs: random circles of mixed sizes, a column on
    one x (the case a sweep along x made quadratic), two large ones, circles that just touch,
    two sizes far apart (one grid of the median size put each large circle in thousands of
    cells), and radii so small beside their coordinates that no cell can be numbered."""
    import math
    import random

    from max2code.engine.scenefile import near_pairs

    rng = random.Random(5)
    circles = [(rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(0.01, 0.5)) for _ in range(300)]
    circles += [(0.0, 0.3 * k, 0.16) for k in range(100)]          # a column, neighbours overlap
    circles += [(0.0, 0.0, 1e4), (5.0, -3.0, 3000.0)]              # much larger
    circles += [(30.0 + 0.002 * k, 0.0, 0.001) for k in range(50)]  # small ones, touching
    circles += [(30.0 + 0.1 * k, 0.2, 0.06) for k in range(20)]      # and a row of larger
    circles += [(0.0, 0.0, 1e-300), (1e9, 0.0, 1e-300)]            # no numbered cell
    circles += [(20.0, 0.0, 1.0), (22.0, 0.0, 1.0)]                # touching exactly
    want = {(i, j) for i in range(len(circles)) for j in range(i + 1, len(circles))
            if math.hypot(circles[i][0] - circles[j][0], circles[i][1] - circles[j][1])
            <= circles[i][2] + circles[j][2]}
    got = list(near_pairs(circles))
    assert len(got) == len(set(got)) and set(got) == want
    assert (len(circles) - 2, len(circles) - 1) in want
