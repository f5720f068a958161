"""Count the C runtime's answers on the fuzz vectors by exact_roots.judge verdict (issue 12 figures).

    PYTHONPATH=.:runtime/python:tests python -m tests.runtime.judge_c --count 5000 [--seed 12]
        [--method 0] [--source DIR]

--source: a folder holding max2code_roots.c/.h (default runtime/c; `git show main:...` into a
folder to measure another version).  Prints the valid vectors, the verdicts, the wrong answers
(first ten), the time and the peak memory.
"""
from __future__ import annotations

import argparse
import resource
import subprocess
import tempfile
import time
from collections import Counter
from pathlib import Path

from . import exact_roots as ex
from . import fuzz
from . import test_fuzz_runtimes as tf


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--count", type=int, default=2000)
    ap.add_argument("--seed", type=int, default=12)
    ap.add_argument("--method", default="0", help="driver method: 0, 1 or 0:EPS (skin)")
    ap.add_argument("--source", type=Path, default=tf.C_DIR)
    args = ap.parse_args()
    eps = float(args.method.split(":")[1]) if ":" in args.method else 0.0
    start = time.monotonic()
    with tempfile.TemporaryDirectory() as tmp:
        exe = Path(tmp) / "driver"
        subprocess.run(["gcc", "-std=c11", "-O2", "-I", str(args.source), str(args.source / "max2code_roots.c"),
                        str(tf.C_DIR / "max2code_roots_driver.c"), "-o", str(exe), "-lgsl", "-lgslcblas", "-lm"],
                       check=True)
        counts: Counter = Counter()
        wrong: list[str] = []
        valid = 0
        for vecs in fuzz.batches(args.count, 10000, seed=args.seed):
            vecs = [v for v in vecs if not fuzz.is_invalid(*v)]
            valid += len(vecs)
            answers = tf.run_timed(exe, [tf.c_line(args.method, c, t) for c, t in vecs])
            for (c, tmax), (st, t, g, _) in zip(vecs, answers):
                verdict = ex.judge(c, tmax, st, t, g, eps)
                counts[verdict] += 1
                if not verdict.startswith("ok"):
                    wrong.append(f"{verdict}: status {st}, t={t!r}, c={c!r}, tmax={tmax!r}")
    print(f"{args.count} vectors, {valid} valid, method {args.method}, source {args.source}")
    for k, v in sorted(counts.items()):
        print(f"  {k}: {v}")
    print(f"wrong: {len(wrong)}")
    for w in wrong[:10]:
        print("  " + w)
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    print(f"time {time.monotonic() - start:.0f} s, peak memory {peak / 1024:.0f} MB (this process)")


if __name__ == "__main__":
    main()
