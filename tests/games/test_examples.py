"""examples/games: the platformer's scripted run reaches the goal, the breakout's autopilot clears
the wall; both checked on their event logs (exact times from the engine)."""

from __future__ import annotations

import importlib.util
import json
import math
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def load(name: str):
    path = ROOT / "examples" / "games" / name / f"{name}.py"
    spec = importlib.util.spec_from_file_location(f"example_{name}", path)
    mod = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = mod
    spec.loader.exec_module(mod)
    return mod


def test_the_platformer_run_collects_every_coin_and_reaches_the_goal(tmp_path: Path) -> None:
    pf = load("platformer")
    log = tmp_path / "log.jsonl"
    assert pf.main(["--headless", "--input", str(pf.SCRIPT), "--events", str(log), "--until", "30"]) == 0
    records = [json.loads(x) for x in log.read_text().splitlines()]
    kinds = [r["kind"] for r in records]
    assert kinds.count("coin") == len(pf.COINS) and kinds.count("goal") == 1
    # the first coin is sensed at the exact instant the jumping player reaches it: the player
    # (radius 0.4) leaves the ground at x = 1.5 + 3 * 0.4 with (3, 11) at t = 0.9
    coin = next(r for r in records if r["kind"] == "coin")
    cx, cy = pf.COINS[0]
    s = coin["t"] - 0.9
    x, y = 2.7 + 3 * s, 1.4 + 11 * s - pf.G * s * s / 2
    assert math.hypot(x - cx, y - cy) == pytest.approx(pf.RADIUS + 0.25, abs=1e-9)
    # it lands on the one-way platform it jumped up through (solid only once above it)
    assert {"kind": "collision", "with": "oneway-3"} in [{k: r[k] for k in ("kind", "with")}
                                                        for r in records if "with" in r]


def test_the_platformer_one_way_platform_is_passable_from_below() -> None:
    pf = load("platformer")
    g = pf.Platformer()
    w = g.world
    w.step_to(0.5)
    g.key("KEYDOWN", "K_RIGHT")
    w.step_to(0.9)
    g.key("KEYDOWN", "K_UP")
    hit = []
    w.on_collision(lambda world, ev: hit.append((ev.kind, world.bodies[ev.b].name, ev.normal)))
    w.step_to(1.3)
    # rising through it: no collision with it on the way up (its top is 3.0; the feet pass
    # it at 0.9 + 0.2299), and it is in place once the feet are above
    assert not [h for h in hit if h[1].startswith("oneway")]
    assert g.oneway[3][2] is True


def test_breakout_autopilot_clears_every_brick_without_losing_the_ball(tmp_path: Path) -> None:
    bo = load("breakout")
    log = tmp_path / "log.jsonl"
    assert bo.main(["--headless", "--autopilot", "--until", "200", "--events", str(log)]) == 0
    records = [json.loads(x) for x in log.read_text().splitlines()]
    bricks = [r["with"] for r in records if r["with"].startswith("brick")]
    assert sorted(bricks) == sorted({f"brick-{r}-{c}" for r in range(bo.ROWS) for c in range(bo.COLS)})
    assert not [r for r in records if r["with"] == "floor"]


def test_breakout_steering_stops_the_paddle_at_the_wall_by_a_timer() -> None:
    bo = load("breakout")
    g = bo.Breakout()
    g.steer(+1)
    g.world.step_to(5.0)
    x = g.world.pose(g.paddle)[0]
    assert x == pytest.approx(bo.WIDTH - bo.PADDLE_W / 2, abs=1e-12)
    assert g.world.velocity(g.paddle)[:2] == (0.0, 0.0)
