"""Parse time against size: the .mxm parser must be linear on every input.

Six families of input, each scaled from 10 kB to 50 MB: a valid program of many statements;
the input that used to blow up (an unbalanced '{' near the top of a header full of // comments:
a 1.7 kB file took 3.3 s); 10,000 to 25 million levels of nested braces; an unterminated string
of escaped quotes in a block; unterminated comment openers and a run of quotes in the program.
Each input is parsed (`max2code.front.parse.parse_text`, which takes any size; the command line
refuses files above 4 MiB) in a fresh interpreter, which reports the time and its peak memory.

    python bench/parse.py [--max-mb 50] [--checkout DIR]   # DIR: another checkout, e.g. a baseline

Writes bench/results/parse.md (and parse.png with matplotlib).
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
RESULTS = ROOT / "bench" / "results"
SIZES_MB = (0.01, 0.1, 1.0, 10.0, 50.0)

HEADER = "".join(f"// comment line {k} with a brace {{ in it\n" for k in range(40))


def family(name: str, size: int) -> str:
    """An input of about `size` characters."""
    if name == "valid program":
        stmt = "x: a*t + b*t^2/2 - c;\n"
        return "function f\nbegin\n" + stmt * (size // len(stmt)) + "(t - x)^2;\nend\n"
    if name == "unbalanced { near the top":
        return "// x\n{\n" + HEADER * max(1, size // len(HEADER)) + "begin\n(t-1)^2;\nend\n"
    if name == "nested braces":
        depth = size // 2
        return "initialise {" + "{" * depth + "}" * depth + "}\nbegin\n(t-1)^2;\nend\n"
    if name == "unterminated string in a block":
        return 'initialise { "' + '\\"' * (size // 2) + "\nbegin\n(t-1)^2;\nend\n"
    if name == "comment openers in the program":
        return "begin\n" + "/*" * (size // 2) + "\n(t-1)^2;\nend\n"
    if name == "quotes in the program":
        return "begin\n" + '"' * (size - (size % 2)) + ";\n(t-1)^2;\nend\n"
    raise ValueError(name)


FAMILIES = ("valid program", "unbalanced { near the top", "nested braces",
            "unterminated string in a block", "comment openers in the program",
            "quotes in the program")

CHILD = """
import json, sys, time
from max2code.diagnostics import Max2CodeError
from max2code.front.parse import parse_text
text = open(sys.argv[1], encoding="utf-8").read()
parse_text("begin\\n(t - 1)^2;\\nend\\n", "warm-up.mxm")  # the grammar is built once, not timed
start = time.perf_counter()
try:
    parse_text(text, "bench.mxm")
    outcome = "parsed"
except Max2CodeError as exc:
    outcome = str(exc.diagnostics[0]).split(": error: ")[1][:60]
seconds = time.perf_counter() - start
# VmHWM, not ru_maxrss: Linux carries ru_maxrss over exec from the parent that made the input.
peak = int(next(l for l in open("/proc/self/status") if l.startswith("VmHWM")).split()[1]) / 1024
print(json.dumps({"seconds": seconds, "peak_mb": peak, "outcome": outcome}))
"""


def measure(text: str, checkout: Path) -> dict:
    with tempfile.NamedTemporaryFile("w", suffix=".mxm", delete=False, encoding="utf-8") as f:
        f.write(text)
    try:
        proc = subprocess.run([sys.executable, "-c", CHILD, f.name], capture_output=True, text=True,
                              env={**os.environ, "PYTHONPATH": str(checkout)}, timeout=3600)
    finally:
        os.unlink(f.name)
    if proc.returncode != 0:
        sys.exit(f"the timing child failed:\n{proc.stderr}")
    return json.loads(proc.stdout)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--max-mb", type=float, default=50.0)
    ap.add_argument("--checkout", type=Path, default=ROOT, help="the max2code checkout to time")
    ap.add_argument("--chart-only", action="store_true",
                    help="redraw parse.png from bench/results/parse.json, run nothing")
    opts = ap.parse_args()
    if opts.chart_only:
        data = json.loads((RESULTS / "parse.json").read_text())
        chart(data["rows"] if isinstance(data, dict) else data,
              data.get("made", "machine and date not recorded") if isinstance(data, dict) else
              "measured 2026-12-01 (machine not recorded)")
        return 0
    rows = []
    for name in FAMILIES:
        for mb in SIZES_MB:
            if mb > opts.max_mb:
                continue
            text = family(name, int(mb * 1_000_000))
            r = measure(text, opts.checkout)
            rows.append({"family": name, "bytes": len(text.encode()), **r})
            print(f"{name:32s} {len(text) / 1e6:9.3f} MB {r['seconds']:9.3f} s "
                  f"{r['peak_mb']:8.0f} MB peak  {r['outcome']}", flush=True)
    write(rows, opts)
    return 0


def write(rows: list[dict], opts: argparse.Namespace) -> None:
    RESULTS.mkdir(parents=True, exist_ok=True)
    from max2code.machine import machine_and_date
    made = machine_and_date()
    (RESULTS / "parse.json").write_text(json.dumps({"made": made, "rows": rows}, indent=1) + "\n")
    lines = ["# Parse time against size", "",
             f"`python bench/parse.py --max-mb {opts.max_mb:g}`; each input parsed once in a fresh "
             "interpreter (`parse_text`, no size limit; the command line refuses files above "
             "4 MiB). Absolute times are noisy on a shared machine; the ratio per byte is the "
             "point: it must not grow with size.", "",
             "| input | size | seconds | µs per byte | peak memory | outcome |", "|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['family']} | {r['bytes'] / 1e6:.2f} MB | {r['seconds']:.3f} | "
                     f"{r['seconds'] / r['bytes'] * 1e6:.3f} | {r['peak_mb']:.0f} MB | {r['outcome']} |")
    (RESULTS / "parse.md").write_text("\n".join(lines) + "\n")
    chart(rows, made)


def chart(rows: list[dict], made: str) -> None:
    """parse.png: time against size per input family, log-log; `made`: machine and date."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for name in FAMILIES:
        pts = [(r["bytes"], r["seconds"]) for r in rows if r["family"] == name]
        if pts:
            ax.loglog(*zip(*pts), marker="o", label=name)
    ax.set_xlabel("input size (bytes)")
    ax.set_ylabel("parse time (s)")
    ax.set_title("max2code .mxm parser: time against size (log-log; slope 1 is linear)\n"
                 + made, fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(RESULTS / "parse.png", dpi=110)


if __name__ == "__main__":
    sys.exit(main())
