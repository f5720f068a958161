"""One engine build against another on the same scenes, in one run: did a change to the C core
slow the single-shape paths? Each scene runs in its own process per build (the library is chosen
with MAX2CODE_ENGINE_LIB), the builds alternating, best of --repeat; the ratio is this
checkout's time over the baseline's (< 1: faster).

    python bench/engine_ab.py --base /path/to/baseline/libmax2code_engine.so [--repeat 3]

A baseline library: a checkout of the commit to compare with, built by importing its
max2code.engine (the path is printed by `python -c "from max2code.engine.build import library;
print(library())"` run in that checkout).
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

# Each scene: a World built and stepped; prints the wall time of the stepping and the events.
SCENE = r"""
import json, math, random, sys, time
from max2code.engine import World
name, T = sys.argv[1], float(sys.argv[2])
rng = random.Random(1)
w = World(gravity=(0.0, -9.81) if name.endswith("gravity") else (0.0, 0.0))
H = 10.0
for a, b in (((-H, -H), (H, -H)), ((H, -H), (H, H)), ((H, H), (-H, H)), ((-H, H), (-H, -H))):
    w.add_segment(a, b)
for i in range(200 if name.startswith("balls") else 60):
    x, y = -H + 1 + (i % 14) * 1.3, -H + 1 + (i // 14) * 1.3
    v = (rng.uniform(-5, 5), rng.uniform(-5, 5))
    if name.startswith("balls"):
        w.add_circle((x, y), 0.3, velocity=v, restitution=0.95)
    elif name.startswith("boxes"):
        w.add_polygon([(-0.4, -0.3), (0.4, -0.3), (0.4, 0.3), (-0.4, 0.3)], position=(x, y),
                      velocity=v, omega=rng.uniform(-3, 3), restitution=0.95)
    else:
        w.add_compound([([(-0.35, 0.0)], 0.2), ([(0.35, 0.0)], 0.2), ([(-0.35, 0), (0.35, 0)], 0.05)],
                       position=(x, y), velocity=v, omega=rng.uniform(-3, 3), restitution=0.95)
t0 = time.perf_counter()
w.step_to(T, events=False)
print(json.dumps({"seconds": time.perf_counter() - t0, "events": w.stats()["events"]}))
"""

SCENES = (("balls", 60.0), ("boxes", 6.0), ("balls-gravity", 30.0))


def run(lib: str | None, name: str, T: float) -> dict:
    env = dict(os.environ)
    env.pop("MAX2CODE_ENGINE_LIB", None)
    if lib:
        env["MAX2CODE_ENGINE_LIB"] = lib
    out = subprocess.run([sys.executable, "-c", SCENE, name, str(T)], capture_output=True,
                         text=True, env=env, cwd=ROOT, check=True).stdout
    return json.loads(out.splitlines()[-1])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--base", required=True, help="the baseline build's libmax2code_engine.so")
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    print(f"{'scene':16} {'events':>8} {'base s':>8} {'this s':>8} {'this/base':>9}")
    for name, T in SCENES:
        base, this = [], []
        for _ in range(args.repeat):
            base.append(run(args.base, name, T))
            this.append(run(None, name, T))
        b = min(r["seconds"] for r in base)
        t = min(r["seconds"] for r in this)
        assert base[0]["events"] == this[0]["events"], (name, base[0], this[0])
        print(f"{name:16} {this[0]['events']:>8} {b:8.3f} {t:8.3f} {t / b:9.3f}")


if __name__ == "__main__":
    main()
