"""What evaluating a polynomial at several points at once costs, in degree-8 Horner evaluations.

    python bench/horner_points.py [--regions N]

Builds bench/horner_points.c with gcc -O2 (the flags the benchmark's runtime uses), checks
that every k-point kernel gives the one-point kernel's bits, times them interleaved and writes
the table to bench/results/horner_points.md (and stdout).  Issue 10 asks whether evaluating
at several points at once would make the solver cheaper: this is the measured price of that,
against which any rearrangement of the solver's evaluations can be judged before it is built.
"""

from __future__ import annotations

import argparse
import datetime
import os
import platform
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
RESULTS = ROOT / "bench" / "results"
sys.path.insert(0, str(Path(__file__).resolve().parent))

from benchtools import compile_c, publish  # noqa: E402  (bench/benchtools.py, beside this script)


def build(into: Path) -> Path:
    exe = into / "horner_points"
    compile_c("horner_points", "compiling", [
        "-O2", "-std=c11", "-Wall", "-Wextra", str(ROOT / "bench" / "horner_points.c"), "-o",
        str(exe)])
    return exe


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--regions", type=int, default=2001, help="timed regions per kernel (default 2001)")
    ap.add_argument("-o", "--out", type=Path, default=RESULTS, help="directory for horner_points.md")
    args = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        exe = build(Path(tmp))
        check = subprocess.run([str(exe), "check"], capture_output=True, text=True, timeout=120)
        if check.returncode != 0 or check.stdout.strip() != "ok":
            sys.exit(f"horner_points: the kernels disagree: {check.stdout.strip()}")
        r = subprocess.run([str(exe), str(args.regions)], capture_output=True, text=True,
                           timeout=600, check=True)
    command = "python bench/horner_points.py" + ("" if args.regions == 2001 else f" --regions {args.regions}")
    text = "\n".join([
        f"# Evaluations at several points at once ({datetime.date.today().isoformat()})", "",
        f"Machine: {platform.machine()}, {os.cpu_count()} cores (shared: absolute times are noisy; "
        f"the ratios come from one run, kernels interleaved). Command: `{command}`. gcc -O2, a "
        "degree-8 polynomial, each call waiting for the last call's values (as a solve's "
        "evaluations do); the unit is bench/timing.h's one-point Horner evaluation.", "",
        r.stdout.strip(), ""])
    publish(args.out, "horner_points.md", text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
