"""bench/games.py plays each game in pymunk as well as in our engine; a frame's cost is only
comparable when both play the same game.  Checked here: the pymunk platformer, driven by the
same timed keys, collects the coins and reaches the goal as ours does, and stops there."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

BENCH = Path(__file__).resolve().parent.parent / "bench" / "games.py"


def load_bench():
    """bench/games.py by its path, under a name of its own: `games` is also tests/games."""
    spec = importlib.util.spec_from_file_location("bench_games", BENCH)
    mod = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = mod
    spec.loader.exec_module(mod)
    return mod


def test_the_pymunk_platformer_plays_the_scripted_run_as_ours_does() -> None:
    games = load_bench()
    for seconds, coins in ((3.0, 1), (8.0, 2)):
        ours, theirs = games.ours_platformer(seconds), games.pymunk_platformer(seconds)
        assert ours["outcome"] == theirs["outcome"] == f"no goal, {coins} coins"
    ours, theirs = games.ours_platformer(30.0), games.pymunk_platformer(30.0)
    assert ours["outcome"] == theirs["outcome"] == "goal, 3 coins"
    # both stop at the goal (not at 30 s), within a few frames of each other
    assert ours["frames"] < 30 * games.FPS and abs(ours["frames"] - theirs["frames"]) <= 6
