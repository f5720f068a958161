"""Time the generated C coefficient code of both evaluation strategies, in one run.

    python bench/strategies.py            # writes bench/results/strategies.md

For each shipped equation's general polynomial: the operation counts, and the median ns per
`NAME_coefficients` call (and per `NAME_first_root`) over random game-scale parameters, with
`expanded` (the paper's fully expanded coefficients) as the named baseline. Plus the digits each
keeps for two bodies near x = 1e8 (orbiting circles).
"""

from __future__ import annotations

import platform
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tests"))

from max2code.codegen.emit import module_name  # noqa: E402
from max2code.codegen.generate import generate, load  # noqa: E402
from max2code.languages import LANGUAGES  # noqa: E402
from max2code.codegen.variants import STRATEGIES, family  # noqa: E402
from oracle import random_samples  # noqa: E402

HARNESS = r"""
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <time.h>
#include "{header}"
#define N {n}
static double P[N][{name}_NPARAMS];
static double now(void) {{ struct timespec ts; clock_gettime(CLOCK_MONOTONIC, &ts); return ts.tv_sec * 1e9 + ts.tv_nsec; }}
static int cmp(const void *a, const void *b) {{ double x = *(const double *)a, y = *(const double *)b; return (x > y) - (x < y); }}
#include <stdlib.h>
int main(void) {{
    for (int i = 0; i < N; i++) for (int j = 0; j < {name}_NPARAMS; j++) if (scanf("%la", &P[i][j]) != 1) return 1;
    double c[{name}_DEGREE + 1], sink = 0.0, coef[31], root[31];
    for (int r = 0; r < 31; r++) {{
        double t0 = now();
        for (int i = 0; i < N; i++) {{ {name}_coefficients(P[i], c); sink += c[0]; }}
        double t1 = now();
        for (int i = 0; i < N; i++) {{ double t = 0.0; if ({name}_first_root(P[i], 10.0, &t) == 1) sink += t; }}
        double t2 = now();
        coef[r] = (t1 - t0) / N; root[r] = (t2 - t1) / N;
    }}
    qsort(coef, 31, sizeof coef[0], cmp); qsort(root, 31, sizeof root[0], cmp);
    printf("%.2f %.2f %g\n", coef[15], root[15], sink);
    return 0;
}}
"""


def measure(path: str, tmp: Path) -> list[tuple[str, int, float, float]]:
    spec, poly = load(path)
    name = module_name(spec)
    samples = random_samples(poly.parameters, 4096, seed=7)
    stdin = "\n".join(" ".join(float.hex(v) for v in s) for s in samples) + "\n"
    rows = []
    for strategy in STRATEGIES:
        header = tmp / f"{name}_{strategy}.h"
        header.write_text(generate(spec, poly, LANGUAGES["c"], "module", header.name, strategy,
                                   with_variants=False).text)
        main = tmp / f"main_{strategy}.c"
        main.write_text(HARNESS.format(header=header.name, name=name, n=len(samples)))
        exe = tmp / f"bench_{strategy}"
        runtime = ROOT / "runtime" / "c"
        subprocess.run(["gcc", "-std=c11", "-O2", f"-I{runtime}", f"-I{tmp}", str(main),
                        str(runtime / "max2code_roots.c"), "-o", str(exe), "-lgsl", "-lgslcblas",
                        "-lm"], check=True)
        coef_ns, root_ns, _ = subprocess.run([str(exe)], input=stdin, capture_output=True,
                                             text=True, check=True).stdout.split()
        ops = family(poly, strategy, with_variants=False)[0].ops.total
        rows.append((strategy, ops, float(coef_ns), float(root_ns)))
    return rows


def cpu() -> str:
    for line in Path("/proc/cpuinfo").read_text().splitlines():
        if line.startswith("model name"):
            return line.split(":", 1)[1].strip()
    return platform.machine()


def main() -> int:
    equations = sorted(str(p.relative_to(ROOT)) for p in (ROOT / "equations").glob("*.mxm"))
    lines = ["# Evaluation strategies: generated C, general polynomial, gcc -O2", "",
             f"Machine: {cpu()}, 2 cores; command: "
             "`python bench/strategies.py`. Median of 31 runs over 4096 parameter sets; ratios "
             "against `expanded` (the paper's) in the same run.", "",
             "| equation | strategy | operations | ns per coefficients() | ratio | ns per first_root() | ratio |",
             "|---|---|---|---|---|---|---|"]
    with tempfile.TemporaryDirectory() as tmp:
        for path in equations:
            rows = measure(path, Path(tmp))
            base = {r[0]: r for r in rows}["expanded"]
            for strategy, ops, coef_ns, root_ns in rows:
                lines.append(f"| {path} | {strategy} | {ops} | {coef_ns:.1f} | "
                             f"{coef_ns / base[2]:.2f} | {root_ns:.1f} | {root_ns / base[3]:.2f} |")
    text = "\n".join(lines) + "\n"
    out = ROOT / "bench" / "results" / "strategies.md"
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(text)
    print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
