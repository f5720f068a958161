"""Interleaved A/B timing of the C runtime against a named baseline.

    python bench/roots_ab.py BASE [--count N] [--sweeps S] [--families f,g,...]

BASE is a git revision (its runtime/c/max2code_roots.c and .h) or a path to a runtime .c
file; B is the working tree's runtime.  Both are built with gcc -O2 into one harness
(bench/roots_ab.c) and timed on bench/roots.py's polynomials, call by call, alternating.

Why a tool of its own: on a shared machine (a VM here) the benchmark's absolute times move by
up to 1.7x between two runs of the same code, which is more than most changes to the solver.
Timed side by side in one run, both builds see the same bursts, so their ratio holds still
enough to tell a 5 % change.  It is the "before / after" number to put in a note; the
evaluations column of bench/roots.py stays the figure for the README.

It also compares the answers of A and B (status, graze flag, root bit for bit) and lists the
polynomials where they differ: a change meant to be faster only should differ nowhere.
"""

from __future__ import annotations

import argparse
import shutil
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "bench"))

import roots  # noqa: E402  (the benchmark's polynomial families)

C_DIR = ROOT / "runtime" / "c"
PUBLIC = ("m2c_first_root", "m2c_first_root_ex", "m2c_first_root_skin", "m2c_first_root_method",
          "m2c_first_roots")
RENAMED = {"m2c_first_root_ex": "ex"}  # the harness calls A_ex / B_ex


def _defines(tag: str) -> list[str]:
    """-D flags renaming every public symbol of one runtime build (A_... or B_...)."""
    return [f"-D{name}={tag}_{RENAMED.get(name, name)}" for name in PUBLIC]


def base_sources(base: str, into: Path) -> Path:
    """The baseline's runtime source in `into`: a file path as given (with the working tree's
    header unless one is beside it), else a git revision's runtime/c files."""
    path = Path(base)
    if path.suffix == ".c" and path.is_file():
        src = into / "max2code_roots.c"
        shutil.copyfile(path, src)
        header = path.parent / "max2code_roots.h"
        shutil.copyfile(header if header.is_file() else C_DIR / "max2code_roots.h",
                        into / "max2code_roots.h")
        return src
    for name in ("max2code_roots.c", "max2code_roots.h"):
        r = subprocess.run(["git", "-C", str(ROOT), "show", f"{base}:runtime/c/{name}"],
                           capture_output=True)
        if r.returncode != 0:
            sys.exit(f"roots_ab: {base!r} is neither a runtime .c file nor a git revision with "
                     f"runtime/c/{name}: {r.stderr.decode(errors='replace').strip()}")
        (into / name).write_bytes(r.stdout)
    return into / "max2code_roots.c"


def build(base: str, work: Path) -> Path:
    gcc = shutil.which("gcc")
    if gcc is None:
        sys.exit("roots_ab: gcc not found (run 'make setup')")
    a_dir = work / "a"
    a_dir.mkdir()
    a_src = base_sources(base, a_dir)
    objects = []
    for tag, src, inc in (("A", a_src, a_dir), ("B", C_DIR / "max2code_roots.c", C_DIR)):
        obj = work / f"{tag}.o"
        cmd = [gcc, "-O2", "-std=c11", "-I", str(inc), *_defines(tag), "-c", str(src), "-o", str(obj)]
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit(f"roots_ab: compiling {tag} failed:\n{' '.join(cmd)}\n{r.stderr}")
        objects.append(str(obj))
    exe = work / "roots_ab"
    cmd = [gcc, "-O2", "-std=c11", "-Wall", "-Wextra", str(ROOT / "bench" / "roots_ab.c"), *objects,
           "-o", str(exe), "-lgsl", "-lgslcblas", "-lm"]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"roots_ab: linking the harness failed:\n{' '.join(cmd)}\n{r.stderr}")
    return exe


def run(exe: Path, polys: list[tuple[str, tuple[float, ...], float]], sweeps: int
        ) -> tuple[float, list[str], list[tuple[str, float, float]]]:
    """(Horner unit in ns, the differing-answer lines, per polynomial (family, ns A, ns B))."""
    lines = [" ".join([f, t.hex(), str(len(c) - 1), *(x.hex() for x in c)]) for f, c, t in polys]
    r = subprocess.run([str(exe), str(sweeps)], input="\n".join(lines) + "\n",
                       capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"roots_ab: the harness failed ({r.returncode}): {r.stderr.strip()}")
    unit, differ, rows = float("nan"), [], []
    for line in r.stdout.splitlines():
        if line.startswith("# differ "):
            differ.append(line[2:])
        elif line.startswith("# horner8_ns"):
            unit = float(line.split()[2])
        else:
            fam, a, b = line.split()
            rows.append((fam, float(a), float(b)))
    return unit, differ, rows


def report(base: str, command: str, unit: float, differ: list[str],
           rows: list[tuple[str, float, float]], polys: list) -> str:
    out = [f"A = {base}, B = the working tree; command: `{command}`; one degree-8 Horner "
           f"evaluation = {unit:.1f} ns in this run.", "",
           "| family | A median (evaluations) | B median (evaluations) | B / A median | "
           "B / A mean |", "|---|---:|---:|---:|---:|"]
    for fam in dict.fromkeys(f for f, _, _ in rows):
        xs = [(a, b) for f, a, b in rows if f == fam]
        ma, mb = statistics.median(a for a, _ in xs), statistics.median(b for _, b in xs)
        ea, eb = statistics.mean(a for a, _ in xs), statistics.mean(b for _, b in xs)
        out.append(f"| {fam} | {ma / unit:.1f} | {mb / unit:.1f} | {mb / ma:.2f} | {eb / ea:.2f} |")
    out += ["", f"Answers (status, graze flag, root bit for bit): {len(differ)} of {len(polys)} "
            "differ." + ("" if not differ else " First ones (index, A: status root graze, "
                         "B: status root graze):")]
    out += [f"    {d}" for d in differ[:10]]
    return "\n".join(out)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("base", help="git revision, or a path to a runtime .c file")
    ap.add_argument("--count", type=int, default=250, help="polynomials per family (default 250)")
    ap.add_argument("--sweeps", type=int, default=15, help="timing sweeps (default 15)")
    ap.add_argument("--families", default=",".join(f for f, _ in roots.TABLE),
                    help="comma-separated bench/roots.py families (default: issue 10's table)")
    args = ap.parse_args(argv)
    fams = [f for f in args.families.split(",") if f]
    unknown = [f for f in fams if f not in roots.MAKERS]
    if unknown:
        ap.error(f"unknown families {unknown}; known: {', '.join(roots.MAKERS)}")
    if not 1 <= args.sweeps <= 101 or args.count < 1:
        ap.error("--sweeps must be 1..101 and --count positive")
    polys = [p for p in roots.polynomials(args.count) if p[0] in fams]
    command = "python bench/roots_ab.py " + " ".join(argv if argv is not None else sys.argv[1:])
    with tempfile.TemporaryDirectory(prefix="roots_ab-") as tmp:
        exe = build(args.base, Path(tmp))
        unit, differ, rows = run(exe, polys, args.sweeps)
    print(report(args.base, command, unit, differ, rows, polys))
    return 0


if __name__ == "__main__":
    sys.exit(main())
