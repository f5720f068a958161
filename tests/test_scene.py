"""`max2code scene`: the cheapest variant and the lowest expansion order per pair, verified.

On the three example scenes: every predicted first collision is within the scene's tolerance of
the exact one (mpmath on the true trigonometric motion), and so is "no collision"; the solves
ran at the degrees the scene needs (no octic where nothing rotates). The time saved against
always solving the general octic is measured by the benchmark (`python bench/roots.py`, table in
bench/results/), never asserted here: a timed assertion fails on a loaded machine.
"""
from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import ROOT

pytest.importorskip("mpmath")

SCENES = ROOT / "examples" / "scenes"


@pytest.fixture(scope="module")
def scene_mod(maxima_exe: str):
    from max2code import scene
    return scene


@pytest.fixture(scope="module")
def reports(scene_mod) -> dict:
    out = {}
    for name in ("billiards-break", "paddles", "mixed"):
        sc = scene_mod.load_scene(SCENES / f"{name}.json")
        out[name] = scene_mod.run(sc, check=True)
    return out


@pytest.mark.parametrize("name", ["billiards-break", "paddles", "mixed"])
def test_within_tolerance_of_exact(name: str, reports) -> None:
    r = reports[name]
    tol = r.scene.tolerance
    assert all(p.resolved for p in r.predictions)
    bad = [(p.a, p.b, p.time, e) for p, e in zip(r.predictions, r.exact) if not
           (p.time is None and e is None or p.time is not None and e is not None and abs(p.time - e) <= tol)]
    assert not bad, bad
    # the proved bound holds too, and says no more than the tolerance
    assert all(p.bound <= tol / 2 for p in r.predictions)
    assert any(p.time is not None for p in r.predictions), "a scene without collisions tests little"


def test_degrees_follow_the_scene(reports) -> None:
    billiards = reports["billiards-break"].solves()
    assert set(billiards) <= {2, 4} and billiards[4] == 15  # only the decelerating cue ball's pairs
    paddles = reports["paddles"]
    assert paddles.solves()[8] > 0 and paddles.solves()[2] == 6  # ball-ball pairs: no rotation
    assert all(p.windows > 1 for p in paddles.predictions if p.rotating), "6 rad over the horizon"
    assert sum(p.skipped for p in paddles.predictions) > 0
    mixed = reports["mixed"]
    assert set(mixed.solves()) >= {2, 4, 8}
    axle = [p for p in mixed.predictions if p.a == "axle" and p.b in ("dart", "wall")
            or p.b == "axle" and p.a in ("dart", "wall")]
    assert len(axle) == 2 and not any(p.rotating for p in axle), "a zero offset makes the spin irrelevant"
    # the general octic over the whole horizon is not accurate where rotation is fast
    assert sum(e > paddles.scene.tolerance for e in paddles.baseline_errors()) > 0


def test_lowest_order_meeting_the_tolerance(scene_mod) -> None:
    """A slow orbit over a short horizon needs only order 2 (degree 4), and the answer is still
    within the tolerance."""
    Body = scene_mod.Body
    a = Body("slow", (0.0, 0.0), 0.1, offset=(0.5, 0.0), omega=0.1)
    b = Body("ball", (1.0, 0.05), 0.1, velocity=(-1.0, 0.0))
    p = scene_mod.predict_pair(a, b, 1.0, 1e-3)
    assert set(p.orders) == {2} and set(p.solves) == {4}
    exact = scene_mod.exact_first_contact(a, b, 1.0)
    assert p.time is not None and abs(p.time - exact) <= 1e-3


def test_cli(maxima_exe: str) -> None:
    r = subprocess.run([sys.executable, "-m", "max2code", "scene", str(SCENES / "mixed.json"), "--json"],
                       capture_output=True, text=True, cwd=ROOT, timeout=600)
    assert r.returncode == 0, r.stderr
    d = json.loads(r.stdout)
    assert d["pairs"] == 52 and d["collisions"] and d["unresolved"] == 0
    assert all(math.isfinite(c["time"]) for c in d["collisions"])
    bad = subprocess.run([sys.executable, "-m", "max2code", "scene", "/nonexistent.json"],
                         capture_output=True, text=True, cwd=ROOT, timeout=60)
    assert bad.returncode == 1 and "error" in bad.stderr and "Traceback" not in bad.stderr
