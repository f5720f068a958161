"""Every numeric field of a scene times every hostile value (tests/engine/numeric_fuzz.py):
how many are refused with a location, how many run to their end, and anything else.

    python bench/scene_numeric_fuzz.py [--timeout 60] [--jobs 2] [-o bench/results/scene-numeric-fuzz.md]
"""

from __future__ import annotations

import argparse
import collections
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests" / "engine"))
from numeric_fuzz import cases, run_case  # noqa: E402


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("-o", "--output", default="bench/results/scene-numeric-fuzz.md")
    args = ap.parse_args()
    todo = cases()

    def one(case):
        with tempfile.TemporaryDirectory() as d:
            return run_case(Path(d), *case, timeout=args.timeout)

    with ThreadPoolExecutor(args.jobs) as pool:
        outcomes = list(pool.map(one, todo))
    counts = collections.Counter(o.status for o in outcomes)
    slowest = max(outcomes, key=lambda o: o.seconds)
    lines = ["# Numeric-field fuzz of scene files", "",
             f"`python bench/scene_numeric_fuzz.py --timeout {args.timeout:g}`: "
             f"{len(outcomes)} cases ({len({o.field for o in outcomes})} fields x "
             f"{len({o.value for o in outcomes})} values, JSON and TOML).", "",
             "| outcome | cases |", "|---|---|"]
    lines += [f"| {k} | {v} |" for k, v in sorted(counts.items())]
    lines += ["", f"Slowest case: {slowest.field} = {slowest.value} ({slowest.fmt}), "
              f"{slowest.seconds:.1f} s.", ""]
    bad = [o for o in outcomes if o.status not in ("refused", "ran")]
    if bad:
        lines += ["Cases that were neither:", ""]
        lines += [f"- {o.field} = {o.value} ({o.fmt}): {o.status} {o.detail!r}" for o in bad]
    text = "\n".join(lines) + "\n"
    Path(args.output).write_text(text)
    print(text)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
