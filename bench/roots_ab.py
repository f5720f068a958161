"""Interleaved A/B timing of the C runtime against a named baseline.

    python bench/roots_ab.py BASE [--count N] [--sweeps S] [--families f,g,...]
    python bench/roots_ab.py BASE --instructions [--reps R] [--count N] [--families f,g,...]
    python bench/roots_ab.py HEAD --warm K      # (working tree = HEAD) warm solves over cold ones

BASE is a git revision (its runtime/c folder: max2code_roots.c, .h and the parts in roots/)
or a path to a runtime .c file; B is the working tree's runtime.  Both are built with gcc -O2
into one harness (bench/roots_ab.c) and timed on bench/roots.py's polynomials, call by call, alternating.

Why a tool of its own: on a shared machine (a VM here) the benchmark's absolute times move by
up to 1.7x between two runs of the same code, which is more than most changes to the solver.
Timed side by side in one run, both builds see the same bursts, so their ratio holds still
enough to tell a 5 % change.  It is the "before / after" number to put in a note; the
evaluations column of bench/roots.py stays the figure for the README.

Code layout alone moves a family's time by up to 8 % here: generic degree 12 and 16 ran 1.07
times slower after a change to the derivative method that they almost never reach, and 1.00
with both runtimes built with --cflags=-falign-functions=64 (the hot functions' starts aligned
alike in A and B).  When a family moves that the change cannot touch, check with that flag.

--families picks the stream as well as the rows: the chosen families' polynomials, shuffled
together, are all that is solved.  A family costs less in a stream of its own than in the
default mix of nine families and four degrees, whose other solves leave the branch predictors
and caches in their own state (generic octics, --families generic8 against the default, two
runs each, alternately: 27.2 and 29.0 evaluations against 39.7 and 39.3, column A).  Compare
absolute figures only between runs of the same families; the ratios B / A hold either way.

It also compares the answers of A and B (status, graze flag, root bit for bit) and lists the
polynomials where they differ: a change meant to be faster only should differ nowhere.

With --instructions it times nothing: it counts, under valgrind's cachegrind (branch
simulation on), the instructions and the simulated branch mispredicts per solve of each build,
family by family: the same harness solving every polynomial R times, less the same run solving
it 0 times (reading the input, starting up), over R times the polynomials.  Those counts are
the same from run to run to the instruction, on any load, so they tell apart changes of 1-2 %
that the timers here cannot (the same source built as A and as B counts within 0.1 % in
instructions, a few % in mispredicts: the simulated predictor sees the code's addresses); they
are not time (the Bernstein sums and Taylor shifts run many
independent chains at once, a Newton step waits on one), so a change that trades instructions
for latency needs the timed comparison too.

With --warm K, B's timed solve follows K untimed solves of the same polynomial by B: its
branch predictors and caches trained on that polynomial, as in a loop that solves one
polynomial over and over (bench/roots_kernels.py), where the benchmark's stream, shuffled
across families and degrees, leaves them cold.  With BASE the working tree's own code, B / A
is the warm solve's time over the cold one's: what the stream's cold state costs -- and part of
what it shows is this harness's own: A and B are two copies of the code, and each evicts the
other's from the instruction cache and the branch-target buffer.  A's cold solve costs more the
more of B's solves come between (measured with --families generic4,generic8,collision8,
--sweeps 15 and -falign-functions=64, column A: quartics 16.0 evaluations with one, 25.1 with
four, --warm 3; generic octics 21.7 and 32.8), while bench/roots.py times one build alone (quartics
18.0).  Read --warm's ratios as an upper bound on what the stream's cold state costs.
"""

from __future__ import annotations

import argparse
import math
import shlex
import shutil
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "bench"))

import roots  # noqa: E402  (the benchmark's polynomial families)
from benchtools import compile_c  # noqa: E402

C_DIR = ROOT / "runtime" / "c"
PUBLIC = ("m2c_first_root", "m2c_first_root_ex", "m2c_first_root_skin", "m2c_first_root_method",
          "m2c_first_roots")
RENAMED = {"m2c_first_root_ex": "ex"}  # the harness calls A_ex / B_ex


def _defines(tag: str) -> list[str]:
    """-D flags renaming every public symbol of one runtime build (A_... or B_...)."""
    return [f"-D{name}={tag}_{RENAMED.get(name, name)}" for name in PUBLIC]


def base_sources(base: str, into: Path) -> Path:
    """The baseline's runtime source in `into`: a file path as given (with the working tree's
    header and parts, runtime/c/roots/, unless they are beside it), else a git revision's
    runtime/c folder (whole: the file and the parts it includes, in either layout)."""
    path = Path(base)
    if path.suffix == ".c" and path.is_file():
        src = into / "max2code_roots.c"
        shutil.copyfile(path, src)
        header = path.parent / "max2code_roots.h"
        shutil.copyfile(header if header.is_file() else C_DIR / "max2code_roots.h",
                        into / "max2code_roots.h")
        parts = path.parent / "roots"
        parts = parts if parts.is_dir() else C_DIR / "roots"
        if parts.is_dir():
            shutil.copytree(parts, into / "roots")
        return src
    r = subprocess.run(["git", "-C", str(ROOT), "archive", "--format=tar", base, "runtime/c"],
                       capture_output=True)
    if r.returncode == 0:
        r = subprocess.run(["tar", "-x", "-C", str(into), "--strip-components=2"],
                           input=r.stdout, capture_output=True)
    if r.returncode != 0 or not (into / "max2code_roots.c").is_file():
        sys.exit(f"roots_ab: {base!r} is neither a runtime .c file nor a git revision with "
                 f"runtime/c/max2code_roots.c: {r.stderr.decode(errors='replace').strip()}")
    return into / "max2code_roots.c"


def build(base: str, work: Path, cflags: list[str]) -> Path:
    a_dir = work / "a"
    a_dir.mkdir()
    a_src = base_sources(base, a_dir)
    objects = []
    for tag, src, inc in (("A", a_src, a_dir), ("B", C_DIR / "max2code_roots.c", C_DIR)):
        obj = work / f"{tag}.o"
        compile_c("roots_ab", f"compiling {tag}", [
            "-O2", *cflags, "-std=c11", "-I", str(inc), *_defines(tag), "-c", str(src), "-o",
            str(obj)])
        objects.append(str(obj))
    exe = work / "roots_ab"
    compile_c("roots_ab", "linking the harness", [
        "-O2", "-std=c11", "-Wall", "-Wextra", str(ROOT / "bench" / "roots_ab.c"), *objects,
        "-o", str(exe), "-lgsl", "-lgslcblas", "-lm"])
    return exe


def input_lines(polys: list[tuple[str, tuple[float, ...], float]]) -> list[str]:
    """The harness's input: FAMILY TMAX DEGREE C0 .. CN, a line per polynomial (hex floats)."""
    return [" ".join([f, t.hex(), str(len(c) - 1), *(x.hex() for x in c)]) for f, c, t in polys]


def run(exe: Path, polys: list[tuple[str, tuple[float, ...], float]], sweeps: int, warm: int = 0
        ) -> tuple[float, list[str], list[tuple[str, float, float]], int]:
    """(Horner unit in ns, the differing-answer lines, per polynomial (family, ns A, ns B), the
    untimed solves before each of B's as the harness did them); with warm, B's timed solve
    follows that many untimed solves of the same polynomial."""
    lines = input_lines(polys)
    r = subprocess.run([str(exe), str(sweeps), str(warm)], input="\n".join(lines) + "\n",
                       capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"roots_ab: the harness failed ({r.returncode}): {r.stderr.strip()}")
    unit, differ, rows, done = float("nan"), [], [], 0
    for line in r.stdout.splitlines():
        if line.startswith("# differ "):
            differ.append(line[2:])
        elif line.startswith("# horner8_ns"):
            words = line.split()
            unit = float(words[2])
            done = int(words[words.index("warm") + 1])
        else:
            fam, a, b = line.split()
            rows.append((fam, float(a), float(b)))
    return unit, differ, rows, done


def valgrind_counts(valgrind: str, exe: Path, lines: list[str], which: str, reps: int
                    ) -> tuple[int, int]:
    """(instructions, simulated branch mispredicts) of one run of the harness's work mode."""
    r = subprocess.run([valgrind, "--tool=cachegrind", "--cache-sim=no", "--branch-sim=yes",
                        "--cachegrind-out-file=/dev/null", str(exe), "work", which, str(reps)],
                       input="\n".join(lines) + "\n", capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"roots_ab: the harness under valgrind failed ({r.returncode}): {r.stderr[-2000:]}")
    found: dict[str, int] = {}
    for line in r.stderr.splitlines():
        words = line.split()
        for key, label in (("I", ["I", "refs:"]), ("M", ["Mispredicts:"])):
            k = len(label) + 1
            if words[1:k] == label:
                found[key] = int(words[k].replace(",", ""))
    if set(found) != {"I", "M"}:
        sys.exit(f"roots_ab: no counts in valgrind's report: {r.stderr[-2000:]}")
    return found["I"], found["M"]


def instructions(valgrind: str, exe: Path, polys: list[tuple[str, tuple[float, ...], float]],
                 reps: int) -> tuple[float, dict[str, dict[str, tuple[float, float]]]]:
    """(instructions of one degree-8 Horner evaluation, {family: {"A"/"B": (instructions,
    mispredicts) per solve}}): each count is a run solving every polynomial `reps` times less
    one solving it 0 times (reading the input only: the same run whichever build, so made once
    per family), over reps times the polynomials."""
    out: dict[str, dict[str, tuple[float, float]]] = {}
    unit = math.nan
    for fam in dict.fromkeys(f for f, _, _ in polys):
        lines = input_lines([p for p in polys if p[0] == fam])
        i0, m0 = valgrind_counts(valgrind, exe, lines, "A", 0)

        def per_solve(which: str) -> tuple[float, float]:
            i1, m1 = valgrind_counts(valgrind, exe, lines, which, reps)
            return (i1 - i0) / (reps * len(lines)), (m1 - m0) / (reps * len(lines))
        out[fam] = {which: per_solve(which) for which in "AB"}
        if math.isnan(unit):
            unit = per_solve("H")[0]
    return unit, out


def instructions_report(base: str, command: str, unit: float,
                        counts: dict[str, dict[str, tuple[float, float]]]) -> str:
    out = [f"A = {base}, B = the working tree; command: `{command}`; counted by valgrind "
           f"(cachegrind, branch simulation), per solve; one degree-8 Horner evaluation = "
           f"{unit:.0f} instructions.", "",
           "| family | A instructions | B instructions | B / A | A mispredicts | B mispredicts | "
           "B / A |", "|---|---:|---:|---:|---:|---:|---:|"]
    for fam, ab in counts.items():
        (ia, ma), (ib, mb) = ab["A"], ab["B"]
        out.append(f"| {fam} | {ia:.0f} | {ib:.0f} | {ib / ia:.3f} | {ma:.1f} | {mb:.1f} | "
                   f"{(mb / ma if ma else math.nan):.3f} |")
    return "\n".join(out)


def report(base: str, command: str, unit: float, differ: list[str],
           rows: list[tuple[str, float, float]], polys: list, warm: int = 0) -> str:
    trained = (f" B's solves each timed after {warm} untimed solves of the same polynomial "
               "(warm), A's in the cold stream." if warm else "")
    out = [f"A = {base}, B = the working tree; command: `{command}`; one degree-8 Horner "
           f"evaluation = {unit:.1f} ns in this run.{trained}", "",
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
    ap.add_argument("--instructions", action="store_true",
                    help="count instructions and mispredicts under valgrind instead of timing")
    ap.add_argument("--cflags", default="",
                    help="more gcc flags for both runtimes, e.g. -falign-functions=64 (code layout "
                         "out of the comparison)")
    ap.add_argument("--reps", type=int, default=4,
                    help="solves of each polynomial counted with --instructions (default 4)")
    ap.add_argument("--warm", type=int, default=0,
                    help="B's timed solve follows this many untimed solves of the same polynomial "
                         "(predictors and caches trained on it); with BASE the working tree's "
                         "code, B / A is the warm solve's time over the cold one's (default 0)")
    args = ap.parse_args(argv)
    fams = [f for f in args.families.split(",") if f]
    unknown = [f for f in fams if f not in roots.MAKERS]
    if unknown:
        ap.error(f"unknown families {unknown}; known: {', '.join(roots.MAKERS)}")
    if not 1 <= args.sweeps <= 101 or args.count < 1 or args.reps < 1 or not 0 <= args.warm <= 100:
        ap.error("--sweeps must be 1..101, --count and --reps positive, --warm 0..100")
    polys = [p for p in roots.polynomials(args.count) if p[0] in fams]
    valgrind = shutil.which("valgrind")
    if args.instructions and valgrind is None:
        sys.exit("roots_ab: --instructions needs valgrind (run 'make setup')")
    command = "python bench/roots_ab.py " + " ".join(argv if argv is not None else sys.argv[1:])
    with tempfile.TemporaryDirectory(prefix="roots_ab-") as tmp:
        exe = build(args.base, Path(tmp), shlex.split(args.cflags))
        if args.instructions:
            assert valgrind is not None  # (checked above)
            iunit, counts = instructions(valgrind, exe, polys, args.reps)
            print(instructions_report(args.base, command, iunit, counts))
            return 0
        unit, differ, rows, warm = run(exe, polys, args.sweeps, args.warm)
    print(report(args.base, command, unit, differ, rows, polys, warm))
    return 0


if __name__ == "__main__":
    sys.exit(main())
