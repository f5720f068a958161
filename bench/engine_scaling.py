"""The engine's broad phase, measured: cost per event as N grows, with and without cells.

    python bench/engine_scaling.py [--until S] [--out bench/results/engine_scaling.md]

A gas of discs (radius 1, mass 1, elastic, no gravity) in a square box, sparse (2 % of the
area, speed 4) or dense (25 %, speed 5.5): the scenes of bench/engine.py, whose contact rates
match DESIGN.md section 8 (sparse 2 / 10 / 74, dense 29 / 216 / 1840 per simulated second for
N = 10 / 100 / 1000). For each N, the engine runs with its cell list (cells chosen from the
bodies) and with one cell (every body tested against every other): events per simulated
second (collisions, cell crossings), wall seconds per simulated second, microseconds per event
and pairs tested per event. Constant cost per event means the microseconds stay flat as N grows.
Absolute times are noisy on a shared machine; ratios within one run are what to read.
"""

from __future__ import annotations

import argparse
import math
import random
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

GAS = {"sparse": (0.02, 4.0), "dense": (0.25, 5.5)}


def gas_world(World, n: int, kind: str, cell_size: float, seed: int = 5):
    fraction, speed = GAS[kind]
    rng = random.Random(seed * 7919 + n)
    side = math.sqrt(n * math.pi / fraction)
    w = World(cell_size=cell_size)
    corners = [(0.0, 0.0), (side, 0.0), (side, side), (0.0, side)]
    for k in range(4):
        w.add_segment(corners[k], corners[(k + 1) % 4])
    placed: dict[tuple[int, int], list[tuple[float, float]]] = {}
    count = 0
    while count < n:
        x, y = rng.uniform(1.01, side - 1.01), rng.uniform(1.01, side - 1.01)
        ci, cj = int(x // 2.02), int(y // 2.02)
        if any((x - px) ** 2 + (y - py) ** 2 < 2.02 ** 2 for di in (-1, 0, 1) for dj in (-1, 0, 1)
               for px, py in placed.get((ci + di, cj + dj), ())):
            continue
        placed.setdefault((ci, cj), []).append((x, y))
        heading = rng.uniform(0, 2 * math.pi)
        w.add_circle((x, y), 1.0, mass=1.0, velocity=(speed * math.cos(heading), speed * math.sin(heading)))
        count += 1
    return w


def measure(World, n: int, kind: str, cells: bool, until: float) -> dict:
    w = gas_world(World, n, kind, 0.0 if cells else -1.0)
    w.step_to(0.0)  # build the grid, first predictions (not timed: set-up)
    start = time.perf_counter()
    w.step_to(until, events=False)
    wall = time.perf_counter() - start
    s = w.stats()
    return {"n": n, "kind": kind, "cells": cells, "until": until, "wall": wall,
            "events": s["events"], "collisions": s["collisions"], "crossings": s["cell_crossings"],
            "pairs": s["pair_tests"], "grid": f"{s['ncells_x']}x{s['ncells_y']}"}


def table(rows: list[dict]) -> str:
    out = ["| gas | N | broad phase | grid | collisions / s | events / s | wall s / simulated s | "
           "µs / event | pairs / event |", "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        out.append(f"| {r['kind']} | {r['n']} | {'cells' if r['cells'] else 'one cell'} | {r['grid']} | "
                   f"{r['collisions'] / r['until']:.0f} | {r['events'] / r['until']:.0f} | "
                   f"{r['wall'] / r['until']:.2g} | {1e6 * r['wall'] / max(r['events'], 1):.2f} | "
                   f"{r['pairs'] / max(r['events'], 1):.1f} |")
    return "\n".join(out)


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--until", type=float, default=None,
                    help="simulated seconds (default: sparse 1000 / 200 / 50, dense 100 / 20 / 5 "
                         "for N = 10 / 100 / 1000: a few thousand events or more each)")
    ap.add_argument("--out", default=str(ROOT / "bench" / "results" / "engine_scaling.md"))
    ap.add_argument("--no-one-cell-1000", action="store_true", help="skip the slow N=1000 one-cell runs")
    args = ap.parse_args(argv)
    from max2code.engine import World

    rows = []
    for kind in ("sparse", "dense"):
        for n in (10, 100, 1000):
            until = args.until or {10: 100.0, 100: 20.0, 1000: 5.0}[n] * (10 if kind == "sparse" else 1)
            for cells in (True, False):
                if not cells and n == 1000 and args.no_one_cell_1000:
                    continue
                r = measure(World, n, kind, cells, until)
                rows.append(r)
                print(table([r]).splitlines()[-1], flush=True)
    text = (f"# The engine's broad phase\n\nCommand: `python bench/engine_scaling.py`. "
            f"Machine shared with other work: read ratios, not absolute times.\n\n{table(rows)}\n")
    Path(args.out).parent.mkdir(parents=True, exist_ok=True)
    Path(args.out).write_text(text)
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
