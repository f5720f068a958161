"""`max2code scene`: every pair's first contact in a frozen scene, predicted by the engine.

On the three example scenes every predicted first collision agrees with the exact one (mpmath
on the true trigonometric motion) far inside the scene's tolerance, and so does "no collision";
the solves run at the degrees the scene needs (nothing above degree 4 where nothing rotates,
the Taylor models where something does). Speed is measured by the benchmarks, never here.
"""
from __future__ import annotations

import json
import math
import subprocess
import sys

import pytest

from conftest import ROOT

pytest.importorskip("mpmath")

SCENES = ROOT / "examples" / "frozen"


@pytest.fixture(scope="module")
def scene_mod(maxima_exe: str):
    from max2code.commands import scene
    return scene


@pytest.fixture(scope="module")
def reports(scene_mod) -> dict:
    return {name: scene_mod.run(scene_mod.load_scene(SCENES / f"{name}.json"), check=True)
            for name in ("billiards-break", "paddles", "mixed")}


@pytest.mark.parametrize("name", ["billiards-break", "paddles", "mixed"])
def test_agrees_with_exact(name: str, reports) -> None:
    r = reports[name]
    bad = [(p.a, p.b, p.time, e) for p, e in zip(r.predictions, r.exact)
           if not (p.time is None and e is None
                   or p.time is not None and e is not None and abs(p.time - e) <= 1e-8 * max(1, e))]
    assert not bad, bad
    assert any(p.time is not None for p in r.predictions), "a scene without collisions tests little"


def test_degrees_follow_the_scene(reports) -> None:
    billiards = reports["billiards-break"].solves()
    assert set(billiards) <= {2, 4}  # nothing rotates: exact polynomials, no Taylor model
    paddles = reports["paddles"]
    assert max(paddles.solves()) >= 6 and paddles.solves()[2] > 0
    rotating = [p for p in paddles.predictions if p.rotating and p.time is not None]
    assert rotating and all(p.windows >= 1 for p in rotating)
    assert all(p.windows == 0 for p in paddles.predictions if not p.rotating)
    mixed = reports["mixed"]
    axle = [p for p in mixed.predictions if {p.a, p.b} in ({"axle", "dart"}, {"axle", "wall"})]
    assert len(axle) == 2 and not any(p.rotating or p.windows for p in axle), \
        "a zero offset makes the spin irrelevant"


def test_slow_orbit_uses_a_low_order(scene_mod) -> None:
    """A slow orbit over a short horizon: the lowest Taylor order meeting the budget is below
    4 (degree below 8), and the answer is still exact to rounding."""
    Body = scene_mod.Body
    a = Body("slow", (0.0, 0.0), 0.1, offset=(0.5, 0.0), omega=0.1)
    b = Body("ball", (1.0, 0.05), 0.1, velocity=(-1.0, 0.0))
    sc = scene_mod.Scene((a, b), 1.0, 1e-3, "slow")
    r = scene_mod.run(sc, check=True)
    (p,) = r.predictions
    assert p.rotating and max(p.solves) < 8
    assert p.time is not None and abs(p.time - r.exact[0]) <= 1e-12


def test_cli(maxima_exe: str) -> None:
    r = subprocess.run([sys.executable, "-m", "max2code", "scene", str(SCENES / "mixed.json"), "--json"],
                       capture_output=True, text=True, cwd=ROOT, timeout=600)
    assert r.returncode == 0, r.stderr
    d = json.loads(r.stdout)
    assert d["pairs"] == 52 and d["collisions"]
    assert all(math.isfinite(c["time"]) for c in d["collisions"])
    bad = subprocess.run([sys.executable, "-m", "max2code", "scene", "/nonexistent.json"],
                         capture_output=True, text=True, cwd=ROOT, timeout=60)
    assert bad.returncode == 1 and "error" in bad.stderr and "Traceback" not in bad.stderr


FROZEN_BAD = [
    ("a negative radius", '{"horizon": 1, "tolerance": 1e-6, "bodies": [\n'
                           ' {"centre": [0, 0], "radius": -1}]}', 2, 21, "bodies[0].radius: must be positive"),
    ("a body that is no table", '{"horizon": 1, "tolerance": 1e-6,\n "bodies": ["x"]}', 2, 13,
     "bodies[0]: expected a table"),
    ("a string for a number", '{"horizon": 1, "tolerance": 1e-6, "bodies": [\n'
                              ' {"centre": [0, 0], "radius": "1"}]}', 2, 21,
     "bodies[0].radius: expected a finite number"),
    ("an unknown key", '{"horizon": 1, "tolerance": 1e-6, "bodies": [\n'
                       ' {"centre": [0, 0], "radios": 1}]}', 2, 21, "did you mean 'radius'"),
    ("NaN", '{"horizon": 1, "tolerance": 1e-6, "bodies": [\n {"centre": [0, NaN], "radius": 1}]}',
     2, 17, "expected a value"),
    ("a file cut short", '{"horizon": 1,\n', 2, 1, "expected a key"),
    ("bodies overlapping at 0", '{"horizon": 1, "tolerance": 1e-6, "bodies": [\n'
                                ' {"centre": [0, 0], "radius": 1},\n {"centre": [0.5, 0], "radius": 1}]}',
     3, 2, "bodies[1]: body 'body1' starts overlapping body 'body0'"),
]


@pytest.mark.parametrize("what,text,line,col,words", FROZEN_BAD, ids=[b[0] for b in FROZEN_BAD])
def test_bad_frozen_scene(tmp_path: Path, what: str, text: str, line: int, col: int, words: str) -> None:
    """A frozen scene is checked as `max2code sim` checks its scenes: a located error and exit
    1, never an internal error (exit 2) nor a silent run."""
    path = tmp_path / "frozen.json"
    path.write_text(text)
    r = subprocess.run([sys.executable, "-m", "max2code", "scene", str(path)],
                       capture_output=True, text=True, cwd=ROOT, timeout=60)
    assert r.returncode == 1, r.stderr
    assert r.stderr.startswith(f"{path}:{line}:{col}: error: "), r.stderr
    assert words in r.stderr and "Traceback" not in r.stderr, r.stderr


def test_frozen_circles_placed_to_touch_are_accepted(tmp_path: Path) -> None:
    """Circles of radius 0.1 at x = 0.1 and 0.3 touch; their centres' distance rounds to 2.8e-17
    less than the radii's sum.  sim's check allows its tolerance; the frozen scene's allows a
    few ulps of its figures (a reviewer's case was refused as an overlap)."""
    from max2code.commands import scene as scene_mod

    path = tmp_path / "touch.json"
    path.write_text('{"horizon": 1, "tolerance": 1e-6, "bodies": [{"centre": [0.1, 0], "radius": 0.1},'
                    ' {"centre": [0.3, 0], "radius": 0.1, "velocity": [1, 0]}]}')
    assert len(scene_mod.load_scene(path).bodies) == 2


def test_a_search_that_gives_up_says_so(tmp_path) -> None:
    """Issue 33, item 6: two fast orbits closing slowly over a long horizon take more rotation
    windows than the search allows. It said "none" (no contact, exit 0) after 16 million
    solves; now the pair says "gave up", the JSON lists it, and the exit status is 1."""
    import json as _json
    import subprocess as _sp
    import sys as _sys

    scene = tmp_path / "giveup.json"
    scene.write_text(_json.dumps({
        "name": "giveup", "horizon": 40000, "tolerance": 1e-6,
        "bodies": [{"name": "spinner", "centre": [0, 0], "offset": [0.1, 0], "omega": 1e6,
                    "radius": 0.05},
                   {"name": "other", "centre": [0.35, 0.001], "offset": [0, 0.1],
                    "velocity": [-1e-5, 0], "omega": -7e5, "radius": 0.05}]}))
    text = _sp.run([_sys.executable, "-m", "max2code", "scene", str(scene)], capture_output=True,
                   text=True, timeout=600)
    assert text.returncode == 1
    assert "t = gave up (first_contact: gave up at t = " in text.stdout
    assert f"{scene}:1:1: error: pair spinner - other: first_contact: gave up" in text.stderr
    js = _sp.run([_sys.executable, "-m", "max2code", "scene", str(scene), "--json"],
                 capture_output=True, text=True, timeout=600)
    report = _json.loads(js.stdout)
    assert js.returncode == 1 and report["collisions"] == []
    assert [(g["a"], g["b"]) for g in report["gave_up"]] == [("spinner", "other")]
