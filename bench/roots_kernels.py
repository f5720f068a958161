"""Where a certified solve's time goes, kernel by kernel, in degree-8 Horner evaluations.

    python bench/roots_kernels.py [--family generic8] [--count N] [--regions R] [-o DIR]

Builds bench/roots_kernels.c with gcc -O2 around the C runtime's source (its kernels are
static), feeds it one of bench/roots.py's families, checks that its replica of the solver's
path gives the public solve's roots bit for bit, and times the solves that the certified
guess settles: the whole solve, the guess (Laguerre from 0), its certificate (one Bernstein
test), the polish (one compensated Newton step, usually), and by difference the rest --
validation, the preparation, the bounds and tests at 0.  Then every polynomial of the family by
the path its solve takes (settled before the guess, the certified guess, a failed certificate,
a failed guess): each path's solves timed alike, and its share of the family's mean.  Writes
bench/results/roots_kernels_<family>.md (and stdout).

Why: issue 10's target for a generic octic is 15 evaluations, about half of today's median.
This shows what each part costs, so that a proposal can be judged by the part it shrinks
(bench/roots_ab.py then measures the change itself).
"""

from __future__ import annotations

import argparse
import datetime
import os
import platform
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent  # (roots_kernels.c and timing.h beside it)
ROOT = HERE.parent
RESULTS = ROOT / "bench" / "results"
sys.path.insert(0, str(ROOT / "bench"))
sys.path.insert(0, str(HERE))

import roots  # noqa: E402  (the benchmark's polynomial families)
from benchtools import command_line, kernel_harness, publish  # noqa: E402
from roots_ab import input_lines  # noqa: E402  (the harnesses' input format)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--family", default="generic8", choices=roots.FAMILIES,
                    help="bench/roots.py's family (default generic8)")
    ap.add_argument("--count", type=int, default=250, help="polynomials per family (default 250)")
    ap.add_argument("--regions", type=int, default=201, help="timed regions per kernel (default 201)")
    ap.add_argument("-o", "--out", type=Path, default=RESULTS, help="directory for the table")
    args = ap.parse_args(argv)
    if not 1 <= args.regions <= 100001 or args.count < 1:
        sys.exit("roots_kernels: --regions must be 1..100001 and --count positive")
    polys = [p for p in roots.polynomials(args.count) if p[0] == args.family]
    stdin = "\n".join(input_lines(polys)) + "\n"
    out = kernel_harness("roots_kernels", HERE / "roots_kernels.c", stdin, str(args.regions),
                         "the replica of the solver's path is off")
    command = command_line("bench/roots_kernels.py", args,
                           {"family": "generic8", "count": 250, "regions": 201})
    text = "\n".join([
        f"# Where a certified solve's time goes: {args.family} ({datetime.date.today().isoformat()})",
        "",
        f"Machine: {platform.machine()}, {os.cpu_count()} cores (shared: absolute times are noisy; "
        f"the kernels ran interleaved, region by region). Command: `{command}`. gcc -O2; every "
        "call waits for the last call's result, as a solve's kernels wait for each other; the "
        "unit is bench/timing.h's degree-8 Horner evaluation. Only the polynomials whose default "
        "solve the certified guess settles (the others go on to Taylor points and bisection); "
        "the second table has every polynomial of the family, by the path its solve takes.",
        "", out.strip(), ""])
    publish(args.out, f"roots_kernels_{args.family}.md", text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
