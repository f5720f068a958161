"""Resource blow-ups (issue 12): each gets a clear diagnostic within the timeout and the memory
limit, never a machine-wide swap storm. Measured end to end, as a user runs them: the wall time
of `max2code --lang=c FILE.mxm` and the peak resident memory of its whole process tree (max2code
and every Maxima it waited for: `wait4`'s rusage, which includes reaped descendants).

    python bench/blowups.py [--timeout 120] [--memory 2048]

Writes bench/results/blowups.md. The inputs are made here, in a temporary folder:
- `expand((a+b+c+d)^60)` (39,711 terms, coefficients of up to 35 digits) as a statement, and
  as the equation itself (no `t` in it: an error, once Maxima has expanded and printed it);
- `polynomial terms 100000` on a quadratic;
- a 50 MB .mxm (a valid program of a million statements);
- a 300 MiB heap exhaustion (`makelist(10^i, i, 1, 40000)`, tests/bad/maxima-out-of-memory)
  run under `--maxima-memory 300`.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
RESULTS = ROOT / "bench" / "results"


@dataclass(frozen=True)
class Case:
    name: str
    text: str
    extra: tuple[str, ...] = ()


def cases() -> list[Case]:
    stmt = "x: a*t + b*t^2/2 - c;\n"
    big = "function f\nbegin\n" + stmt * (50_000_000 // len(stmt)) + "(t - x)^2;\nend\n"
    return [
        Case("expand((a+b+c+d)^60), a statement", "begin\nexpand((a+b+c+d)^60);\n(t - a)^2;\nend\n"),
        Case("expand((a+b+c+d)^60), the equation", "begin\nexpand((a+b+c+d)^60);\nend\n"),
        Case("polynomial terms 100000", "polynomial terms 100000\nbegin\n(t - a)^2;\nend\n"),
        Case("a 50 MB .mxm", big),
        Case("heap exhausted (300 MiB limit)",
             (ROOT / "tests/bad/maxima-out-of-memory.mxm").read_text(), ("--maxima-memory", "300")),
    ]


@dataclass(frozen=True)
class Result:
    case: str
    status: int
    seconds: float
    peak_mib: float
    message: str


def measure(case: Case, folder: Path, timeout: float, memory: int) -> Result:
    mxm = folder / "input.mxm"
    mxm.write_text(case.text)
    extra = case.extra or ("--maxima-memory", str(memory))
    argv = [sys.executable, "-m", "max2code", "--lang=c", "--no-cache", "--timeout", str(timeout),
            *extra, str(mxm), "-o", str(folder / "out.h")]
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    start = time.perf_counter()
    proc = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=env)
    assert proc.stderr is not None
    err = proc.stderr.read().decode(errors="replace")
    _, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = os.waitstatus_to_exitcode(status)
    seconds = time.perf_counter() - start
    first = err.strip().splitlines()[0] if err.strip() else "(nothing on stderr)"
    return Result(case.name, proc.returncode, seconds, usage.ru_maxrss / 1024,
                  first.replace(str(mxm), "input.mxm"))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--timeout", type=float, default=120.0, help="max2code --timeout (s)")
    ap.add_argument("--memory", type=int, default=2048, help="max2code --maxima-memory (MiB)")
    opts = ap.parse_args()
    with tempfile.TemporaryDirectory(prefix="m2c-blowups-") as tmp:
        rows = []
        for case in cases():
            r = measure(case, Path(tmp), opts.timeout, opts.memory)
            print(f"{r.case}: exit {r.status}, {r.seconds:.1f} s, {r.peak_mib:.0f} MiB: {r.message}",
                  flush=True)
            rows.append(r)
    lines = [f"# Resource blow-ups: `python bench/blowups.py --timeout {opts.timeout:g} "
             f"--memory {opts.memory}`", "",
             "| input | exit | wall time | peak memory (process tree) | diagnostic |",
             "|---|---|---|---|---|"]
    lines += [f"| {r.case} | {r.status} | {r.seconds:.1f} s | {r.peak_mib:.0f} MiB | "
              f"`{r.message.replace('|', '/')}` |" for r in rows]
    RESULTS.mkdir(parents=True, exist_ok=True)
    (RESULTS / "blowups.md").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
