"""How long one call of the core can keep Python (and its signals) waiting: two bodies turning
under gravity, thrown at each other above a floor, stepped 0.05 s at a time; the longest step.
The prediction of a turning pair pairs every vertex of one with every edge of the other in one
go, so this is what bounds a moving body's vertices (engine.h MAX_MOVING_VERTICES,
docs/game-api.md). Sizes past the limit are refused here; --large times them on a build from
before the limit (its package first on PYTHONPATH, as bench/engine_ab.py runs a baseline):

    python bench/turning_pairs.py                  # up to the limit (and just past it: refused)
    git worktree add /tmp/before 5c94755           # the commit before the limit
    PYTHONPATH=/tmp/before python bench/turning_pairs.py --large
"""

from __future__ import annotations

import argparse
import math
import time

from max2code.engine import EngineError, World


def gon(n: int, r: float, cx: float = 0.0, cy: float = 0.0) -> list[tuple[float, float]]:
    return [(cx + r * math.cos(2 * math.pi * k / n), cy + r * math.sin(2 * math.pi * k / n))
            for k in range(n)]


def polygon(n: int) -> list[tuple[list, float]]:
    """One convex n-gon of radius 3."""
    return [(gon(n, 3.0), 0.0)]


def ring(parts: int) -> list[tuple[list, float]]:
    """A ring of radius 3 of `parts` octagons (8 vertices each)."""
    return [(gon(8, 0.05, *gon(parts, 3.0)[k]), 0.0) for k in range(parts)]


def worst_step(parts: list[tuple[list, float]], until: float = 2.0) -> float:
    """The longest step_to of 0.05 s while the two bodies fly, meet and turn."""
    w = World(gravity=(0, -10))
    w.add_segment((-100, 0), (100, 0))
    w.add_compound(parts, position=(-4, 4), velocity=(5, 0), omega=3)
    w.add_compound(parts, position=(4, 4), velocity=(-5, 0), omega=-2)
    worst, t = 0.0, 0.0
    while t < until:
        t = min(until, t + 0.05)
        start = time.perf_counter()
        w.step_to(t, events=False)
        worst = max(worst, time.perf_counter() - start)
    return worst


CASES = [("polygon", n, polygon) for n in (32, 64, 128, 129)] + [
    ("ring of octagons", k, ring) for k in (8, 16, 17)]
LARGE = [("polygon", 512, polygon)] + [("ring of octagons", k, ring) for k in (64, 256)]


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--large", action="store_true", help="past the limit (a build without it)")
    args = ap.parse_args()
    print("| body | size | vertices | longest step of 0.05 s |")
    print("|---|---|---|---|")
    for name, size, make in CASES + (LARGE if args.large else []):
        parts = make(size)
        vertices = sum(len(v) for v, _ in parts)
        try:
            cell = f"{worst_step(parts):.3f} s"
        except EngineError as exc:
            cell = f"refused: {exc}"
        print(f"| {name} | {size} | {vertices} | {cell} |")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
