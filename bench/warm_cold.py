"""Cold versus warm `max2code build` over every shipped equation.

Cold: a fresh, empty cache folder and a fresh output folder, so Maxima runs for every equation.
Warm: the same command again with the cache filled and the outputs in place: nothing changed,
so nothing should be parsed, run or rendered. Prints both times (best of --repeat warm runs,
each cold run with a new empty cache) and their ratio; exits 1 if warm is above --max-ratio of
cold. Run from anywhere:

    python bench/warm_cold.py [--repeat 3] [--jobs 1] [--max-ratio 0.1]

The interpreter is run directly (sys.executable), not through a shim such as pyenv's, whose
own start-up would be measured too.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def timed_build(out: Path, cache: Path, jobs: int) -> float:
    env = {**os.environ, "MAX2CODE_CACHE": str(cache), "PYTHONPATH": str(ROOT)}
    env.pop("MAX2CODE_NO_CACHE", None)
    start = time.perf_counter()
    equations = [str(p) for p in sorted((ROOT / "equations").glob("*.mxm"))]
    proc = subprocess.run([sys.executable, "-m", "max2code", "build", "-o", str(out), "-j", str(jobs),
                           *equations], cwd=ROOT, env=env, capture_output=True, text=True)
    seconds = time.perf_counter() - start
    if proc.returncode != 0:
        sys.exit(f"max2code build failed:\n{proc.stderr}")
    return seconds


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--max-ratio", type=float, default=0.1)
    opts = ap.parse_args()
    colds, warms = [], []
    with tempfile.TemporaryDirectory(prefix="max2code-bench-") as tmp:
        for i in range(opts.repeat):
            cache, out = Path(tmp) / f"cache{i}", Path(tmp) / f"out{i}"
            colds.append(timed_build(out, cache, opts.jobs))
            warms.append(min(timed_build(out, cache, opts.jobs) for _ in range(opts.repeat)))
    cold, warm = min(colds), min(warms)
    equations = len(list((ROOT / "equations").glob("*.mxm")))
    print(f"max2code build, {equations} equations, --jobs {opts.jobs}, best of {opts.repeat}:")
    print(f"  cold (empty cache): {cold:.3f} s")
    print(f"  warm (unchanged):   {warm:.3f} s")
    print(f"  warm / cold:        {warm / cold:.3f}  (limit {opts.max_ratio:g})")
    return 0 if warm <= opts.max_ratio * cold else 1


if __name__ == "__main__":
    sys.exit(main())
