"""One engine build against another on the same scenes, in one run: did a change to the C core
slow the single-shape paths? Each scene runs in its own process per checkout (the baseline's
with its own max2code package first on PYTHONPATH, so its binding and its library agree; each
builds its engine on first use), the two alternating, best of --repeat; the ratio is this
checkout's time over the baseline's (< 1: faster).

    git worktree add /tmp/base origin/main
    python bench/engine_ab.py --base /tmp/base [--repeat 3]
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
    elif name.startswith("capsules"):
        w.add_body([(-0.35, 0.0), (0.35, 0.0)], radius=0.2, position=(x, y), velocity=v,
                   omega=rng.uniform(-3, 3), restitution=0.95)
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
# compound bodies against their single-shape baseline, this checkout only: 60 dumbbells (two
# balls on a bar, three parts) and 60 capsules of the same reach, as many events
COMPOUND = (("capsules", 6.0), ("dumbbells", 6.0))


def run(checkout: Path, name: str, T: float) -> dict:
    env = dict(os.environ)
    env.pop("MAX2CODE_ENGINE_LIB", None)
    env["PYTHONPATH"] = os.pathsep.join([str(checkout)] + ([env["PYTHONPATH"]] if env.get("PYTHONPATH") else []))
    proc = subprocess.run([sys.executable, "-c", SCENE, name, str(T)], capture_output=True,
                          text=True, env=env, cwd=checkout)
    if proc.returncode != 0:
        raise SystemExit(f"{checkout}: scene {name} failed:\n{proc.stderr[-2000:]}")
    return json.loads(proc.stdout.splitlines()[-1])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--base", required=True, type=Path,
                    help="a checkout of the baseline commit (git worktree add DIR COMMIT)")
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    print(f"{'scene':16} {'events':>8} {'base s':>8} {'this s':>8} {'this/base':>9}")
    for name, T in SCENES:
        base, this = [], []
        for _ in range(args.repeat):
            base.append(run(args.base.resolve(), name, T))
            this.append(run(ROOT, name, T))
        b = min(r["seconds"] for r in base)
        t = min(r["seconds"] for r in this)
        assert base[0]["events"] == this[0]["events"], (name, base[0], this[0])
        print(f"{name:16} {this[0]['events']:>8} {b:8.3f} {t:8.3f} {t / b:9.3f}")
    print(f"\n{'this checkout':16} {'events':>8} {'seconds':>8} {'us/event':>9}")
    rows = {}
    for _ in range(args.repeat):
        for name, T in COMPOUND:
            r = run(ROOT, name, T)
            rows[name] = min(rows.get(name, r), r, key=lambda x: x["seconds"])
    for name, _ in COMPOUND:
        r = rows[name]
        print(f"{name:16} {r['events']:>8} {r['seconds']:8.3f} {1e6 * r['seconds'] / r['events']:9.1f}")
    per = [rows[n]["seconds"] / rows[n]["events"] for n, _ in COMPOUND]
    print(f"a dumbbell's event costs {per[1] / per[0]:.2f} x a capsule's")


if __name__ == "__main__":
    main()
