#!/usr/bin/env python3
"""Root-method benchmark: speed against accuracy of the C runtime's methods.

    python bench/roots.py            # everything (~4 minutes on 2 cores; the oracle is cached)
    python bench/roots.py --quick    # a smaller root benchmark (for trying things out)
    python bench/roots.py --only-roots

The one command also runs bench/model_error.py (Taylor orders against the exact orbit:
model_error.md/.png) and the example scenes (`max2code scene --check`: scenes.md).

Builds bench/roots_harness.c with ``gcc -O2`` against runtime/c/max2code_roots.c and GSL, feeds
it the benchmark polynomials, and compares every answer with the mpmath/Sturm oracle of
tests/runtime/cases.py (60 digits, computed from the *double* coefficients the solvers receive).
numpy.roots (companion matrix eigenvalues, called from Python) is timed beside them as a
reference point.  Writes bench/results/roots.md (table), roots.png (chart) and roots.json (raw
summary).  Needs numpy and matplotlib (``pip install .[bench]``); the runtime itself does not.

Families (degree 8 unless named otherwise), each built from exact roots multiplied out in
rationals and rounded once to double:

  generic2/4/8   random real roots and complex pairs, magnitudes 0.1..10, at least one real root
                 in the window (tmax infinite or finite)
  noroot8        no root in (0, tmax]: every real root negative or beyond tmax, the rest complex
                 (the engine's common case: the bodies do not meet in this window)
  graze8         a double first root (grazing contact), later simple roots in the window
  cluster8       the first root in a cluster of three, relative spacing 1e-5..1e-3
  drop8          a quartic with a root in the window, padded to degree 8 with leading
                 coefficients 0 or 1e-30..1e-12 relative (no relative rotation, rounding)
  scale8         generic8 scaled by 10^-8..10^8 in t, with leading coefficient 10^-30..10^30
  near0_8        first root 1e-14..1e-6, the others of order 1

Per method and family: median ns per solve (each call timed on its own, in shuffled order; the
median over sweeps per polynomial, then the median over the family) and its ratio to GSL in the
same run; relative error of the first root (median, 99.9 % quantile, max) over the polynomials
where both the oracle and the method report a root; miss rate (a collision exists and the method
reports none or a later one, beyond 1e-6 relative) and false-collision rate (the method reports
a collision earlier than the first true one, or one that does not exist), "beyond" meaning more
than max(1e-6, 4 n u kappa) relative with kappa the root's condition number in the double
coefficients (what any backward-stable method can promise);
NaN count (a status other than 0/1, or a non-finite time).  A grazing method may stop at a near
touch (a complex pair within 1e-6 relative of the real axis): within rounding that is a double
root, and counts as correct.
"""
from __future__ import annotations

import argparse
import datetime
import json
import math
import os
import platform
import random
import shutil
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ProcessPoolExecutor
from fractions import Fraction
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tests"))

from runtime import cases  # noqa: E402  (tests/runtime/cases.py: builders and the oracle)

RESULTS = ROOT / "bench" / "results"
CACHE = ROOT / "bench" / ".cache"
C_DIR = ROOT / "runtime" / "c"
METHODS = ("interval", "interval-nograze", "gsl", "closed")  # C numbering 0..3
LABELS = {"interval": "INTERVAL (default)", "interval-nograze": "INTERVAL_NOGRAZE", "gsl": "GSL",
          "closed": "CLOSED", "numpy": "numpy.roots (Python)"}
FAMILIES = ("generic2", "generic4", "generic8", "noroot8", "graze8", "cluster8", "drop8",
            "scale8", "near0_8")
REL = 1e-6  # what counts as "the same root" for miss / false-collision


# ---------------------------------------------------------------------------
# The polynomials
# ---------------------------------------------------------------------------

def _mag(rng: random.Random, lo: float = -1, hi: float = 1) -> float:
    return 10 ** rng.uniform(lo, hi)


def _pairs(rng: random.Random, k: int, lo: float = -1, hi: float = 1) -> list[tuple[float, float]]:
    out = []
    for _ in range(k):
        r, ang = _mag(rng, lo, hi), rng.uniform(0.05, math.pi - 0.05)
        out.append((r * math.cos(ang), r * math.sin(ang)))
    return out


def _lead(rng: random.Random) -> float:
    return _mag(rng, -2, 2) * rng.choice((1, -1))


def _generic(rng: random.Random, deg: int) -> tuple[tuple[float, ...], float]:
    """At least one positive real root; tmax infinite or above the first root."""
    npairs = rng.randint(0, (deg - 1) // 2)
    nreal = deg - 2 * npairs
    reals = [_mag(rng)] + [_mag(rng) * rng.choice((1, -1)) for _ in range(nreal - 1)]
    first = min(r for r in reals if r > 0)
    tmax = math.inf if rng.random() < 0.5 else first * rng.uniform(1.05, 20)
    return cases.poly_from_roots(reals, _pairs(rng, npairs), lead=_lead(rng)), tmax


def _noroot(rng: random.Random, deg: int = 8) -> tuple[tuple[float, ...], float]:
    npairs = rng.randint(0, deg // 2)
    nreal = deg - 2 * npairs
    tmax = math.inf if rng.random() < 0.3 else _mag(rng, -1, 0.5)
    reals = []
    for _ in range(nreal):
        if math.isfinite(tmax) and rng.random() < 0.5:
            reals.append(tmax * rng.uniform(1.1, 50))  # beyond the window
        else:
            reals.append(-_mag(rng))
    return cases.poly_from_roots(reals, _pairs(rng, npairs), lead=_lead(rng)), tmax


def _graze(rng: random.Random) -> tuple[tuple[float, ...], float]:
    d = _mag(rng)
    npairs = rng.randint(0, 2)
    rest = [d * rng.uniform(1.3, 10) for _ in range(rng.randint(1, 6 - 2 * npairs))]
    rest += [-_mag(rng) for _ in range(6 - 2 * npairs - len(rest))]
    tmax = math.inf if rng.random() < 0.5 else max(rest) * 2
    return cases.poly_from_roots([d, d, *rest], _pairs(rng, npairs), lead=_lead(rng)), tmax


def _cluster(rng: random.Random) -> tuple[tuple[float, ...], float]:
    s, eps = _mag(rng), 10 ** rng.uniform(-5, -3)
    cl = [s, s * (1 + eps), s * (1 + 2 * eps)]
    npairs = rng.randint(0, 2)
    rest = [_mag(rng) * rng.choice((1, -1)) for _ in range(5 - 2 * npairs)]
    rest = [r if r < 0 or r > 1.5 * s else -r for r in rest]  # the cluster comes first
    return cases.poly_from_roots(cl + rest, _pairs(rng, npairs), lead=_lead(rng)), math.inf


def _drop(rng: random.Random) -> tuple[tuple[float, ...], float]:
    c, tmax = _generic(rng, 4)
    top = max(abs(x) for x in c)
    pad = [0.0 if rng.random() < 0.3 else top * 10 ** rng.uniform(-30, -12) * rng.choice((1, -1))
           for _ in range(4)]
    if pad[-1] == 0.0:
        pad[-1] = top * 1e-20
    return tuple(c) + tuple(pad), tmax


def _scale(rng: random.Random) -> tuple[tuple[float, ...], float]:
    c, tmax = _generic(rng, 8)
    k = rng.randint(-8, 8)
    s = Fraction(10) ** k  # roots times s: c_i -> c_i s^(n-i), then a leading scale
    lead = Fraction(10) ** rng.randint(-30, 30)
    n = len(c) - 1
    cc = tuple(float(Fraction(x) * s ** (n - i) * lead) for i, x in enumerate(c))
    return cc, tmax * float(s)


def _near0(rng: random.Random) -> tuple[tuple[float, ...], float]:
    r0 = 10 ** rng.uniform(-14, -6)
    npairs = rng.randint(0, 3)
    rest = [_mag(rng, -0.5, 1) * rng.choice((1, -1)) for _ in range(7 - 2 * npairs)]
    return cases.poly_from_roots([r0, *rest], _pairs(rng, npairs), lead=_lead(rng)), math.inf


MAKERS = {
    "generic2": lambda rng: _generic(rng, 2),
    "generic4": lambda rng: _generic(rng, 4),
    "generic8": lambda rng: _generic(rng, 8),
    "noroot8": _noroot,
    "graze8": _graze,
    "cluster8": _cluster,
    "drop8": _drop,
    "scale8": _scale,
    "near0_8": _near0,
}


def polynomials(count: int, seed: int = 1729) -> list[tuple[str, tuple[float, ...], float]]:
    out = []
    for fi, fam in enumerate(FAMILIES):
        rng = random.Random(seed * 100 + fi)
        for _ in range(count):
            c, tmax = MAKERS[fam](rng)
            out.append((fam, tuple(float(x) for x in c), float(tmax)))
    return out


# ---------------------------------------------------------------------------
# The oracle (cached on disk: it is most of the run time)
# ---------------------------------------------------------------------------

def _key(c: tuple[float, ...], tmax: float) -> str:
    return tmax.hex() + ":" + ",".join(x.hex() for x in c)


def _truth(item: tuple[tuple[float, ...], float]) -> dict:
    import mpmath

    c, tmax = item
    o = cases.oracle(c, tmax)
    # 40 digits: str() of an mpf outside the oracle's working precision keeps only 15, which
    # would hide every error below ~4e-15.
    return {"root": None if o.root is None else mpmath.nstr(o.root, 40), "kind": o.kind,
            "touches": [mpmath.nstr(x, 40) for x in o.touches], "kappa": o.kappa, "degree": len(c) - 1}


def oracles(polys: list[tuple[str, tuple[float, ...], float]], jobs: int) -> list[dict]:
    CACHE.mkdir(parents=True, exist_ok=True)
    path = CACHE / "oracle-v3.json"
    cache = json.loads(path.read_text()) if path.exists() else {}
    keys = [_key(c, t) for _, c, t in polys]
    todo = sorted({k: (c, t) for k, (_, c, t) in zip(keys, polys) if k not in cache}.items())
    if todo:
        print(f"oracle: {len(todo)} polynomials at 60 digits ({jobs} processes)...", flush=True)
        with ProcessPoolExecutor(max_workers=jobs) as ex:
            for (k, _), res in zip(todo, ex.map(_truth, [v for _, v in todo], chunksize=8)):
                cache[k] = res
        tmp = path.with_suffix(".tmp")
        tmp.write_text(json.dumps(cache))
        os.replace(tmp, path)
    return [cache[k] for k in keys]


# ---------------------------------------------------------------------------
# Running the methods
# ---------------------------------------------------------------------------

def build_harness(workdir: Path) -> Path:
    gcc = shutil.which("gcc")
    if gcc is None:
        sys.exit("bench: gcc not found (run 'make setup')")
    exe = workdir / "roots_harness"
    cmd = [gcc, "-O2", "-std=c11", "-Wall", "-Wextra", "-I", str(C_DIR),
           str(ROOT / "bench" / "roots_harness.c"), str(C_DIR / "max2code_roots.c"),
           "-o", str(exe), "-lgsl", "-lgslcblas", "-lm"]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"bench: compiling the harness failed:\n{' '.join(cmd)}\n{r.stderr}")
    return exe


def run_c(exe: Path, polys: list[tuple[str, tuple[float, ...], float]], sweeps: int) -> dict:
    lines = [" ".join([t.hex(), str(len(c) - 1), *(x.hex() for x in c)]) for _, c, t in polys]
    r = subprocess.run([str(exe), str(sweeps)], input="\n".join(lines) + "\n", capture_output=True,
                       text=True, check=True)
    out: dict[tuple[int, str], tuple[int, float, bool, float]] = {}
    overhead = math.nan
    for line in r.stdout.splitlines():
        if line.startswith("#"):
            overhead = float(line.split()[2])
            continue
        i, m, st, t, g, ns = line.split()
        out[(int(i), METHODS[int(m)])] = (int(st), float.fromhex(t) if t != "nan" and "nan" not in t
                                          else math.nan, g == "1", float(ns))
    out["overhead"] = overhead  # type: ignore[index]
    return out


def numpy_first_root(np, c: tuple[float, ...], tmax: float) -> tuple[int, float]:
    """What the original tool did with GSL, with numpy: all roots, then the smallest real one in
    (0, tmax] (|imag| <= sqrt(eps) |z|, as the runtime's GSL method)."""
    z = np.roots(c[::-1])
    best = math.inf
    for w in z:
        re, im = float(w.real), float(w.imag)
        if 0 < re <= tmax and abs(im) <= 1.4901161193847656e-08 * abs(w) and re < best:
            best = re
    return (1, best) if best < math.inf else (0, math.nan)


def run_numpy(polys: list[tuple[str, tuple[float, ...], float]], sweeps: int) -> dict:
    import numpy as np
    out = {}
    clock = time.perf_counter_ns
    empty = []
    for _ in range(2001):
        a = clock()
        empty.append(clock() - a)
    overhead = sorted(empty)[1000]
    samples: dict[int, list[float]] = {i: [] for i in range(len(polys))}
    order = list(range(len(polys)))
    rng = random.Random(5)
    for _ in range(sweeps):
        rng.shuffle(order)
        for i in order:
            _, c, tmax = polys[i]
            a = clock()
            st, t = numpy_first_root(np, c, tmax)
            samples[i].append(clock() - a - overhead)
            out[i] = (st, t, False)
    return {(i, "numpy"): (*out[i], sorted(s)[len(s) // 2]) for i, s in samples.items()}


# ---------------------------------------------------------------------------
# Judging
# ---------------------------------------------------------------------------

def judge(truth: dict, family: str, st: int, t: float, grazing: bool) -> dict:
    """error (None if not comparable), miss, false, nan for one answer.

    "The same root" means within max(1e-6, 4 n u kappa) relative: kappa is the root's condition
    number in the double coefficients, so no backward-stable method can promise better
    (clusters 1e-5 apart have kappa ~ 1e10)."""
    import mpmath
    res = {"error": None, "miss": False, "false": False, "nan": False}
    kappa = truth.get("kappa", 0.0)
    rel = max(REL, 4 * truth.get("degree", 8) * 2.0**-53 * kappa) if math.isfinite(kappa) else REL
    if st not in (0, 1) or (st == 1 and not math.isfinite(t)):
        res["nan"] = True
        return res
    with mpmath.workdps(60):
        root = None if truth["root"] is None else mpmath.mpf(truth["root"])
        touches = [mpmath.mpf(x) for x in truth["touches"]]
        # a touch (near-double root) before the first root is the graze a physical engine
        # wants reported; a method that does not look for touches is judged against it too
        # on the grazing family, where the touch is the constructed double root.
        target = root
        if family == "graze8" and touches:
            target = touches[0]
        near_touch = st == 1 and any(abs(mpmath.mpf(t) - x) <= REL * x for x in touches)
        if st == 1 and near_touch and (grazing or family == "graze8"):
            res["error"] = float(min(abs(mpmath.mpf(t) - x) / x for x in touches))
            return res
        if target is None:
            res["false"] = st == 1
            return res
        if st == 0:
            res["miss"] = True
            return res
        err = abs(mpmath.mpf(t) - target) / target
        res["error"] = float(err)
        if err > rel:
            res["miss" if mpmath.mpf(t) > target else "false"] = True
        return res


def quantile(xs: list[float], q: float) -> float:
    if not xs:
        return math.nan
    xs = sorted(xs)
    k = min(len(xs) - 1, max(0, math.ceil(q * len(xs)) - 1))
    return xs[k]


def summarise(polys, truths, answers, methods) -> dict:
    summary: dict[str, dict[str, dict]] = {}
    for fam in FAMILIES:
        idx = [i for i, (f, _, _) in enumerate(polys) if f == fam]
        for m in methods:
            errs, miss, false, nan, ns = [], 0, 0, 0, []
            for i in idx:
                st, t, _g, tns = answers[(i, m)]
                j = judge(truths[i], fam, st, t, m in ("interval", "closed", "gsl", "numpy"))
                if j["error"] is not None:
                    errs.append(j["error"])
                miss += j["miss"]
                false += j["false"]
                nan += j["nan"]
                ns.append(tns)
            with_root = sum(1 for i in idx if truths[i]["root"] is not None or truths[i]["touches"])
            summary.setdefault(fam, {})[m] = {
                "n": len(idx), "with_root": with_root, "ns": quantile(ns, 0.5),
                "err_median": quantile(errs, 0.5), "err_999": quantile(errs, 0.999),
                "err_max": max(errs) if errs else math.nan, "compared": len(errs),
                "miss": miss, "false": false, "nan": nan,
            }
        g = summary[fam]["gsl"]["ns"]
        for m in methods:
            summary[fam][m]["ratio_gsl"] = summary[fam][m]["ns"] / g
    return summary


# ---------------------------------------------------------------------------
# Output
# ---------------------------------------------------------------------------

def machine() -> str:
    try:
        out = subprocess.run(["lscpu"], capture_output=True, text=True).stdout
        for line in out.splitlines():
            if line.startswith("Model name:"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


def _e(x: float) -> str:
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "–"
    return "0" if x == 0 else f"{x:.1e}"


def table(summary: dict, methods, meta: dict) -> str:
    lines = [
        f"# Root-method benchmark ({meta['date']})",
        "",
        f"Machine: {meta['machine']}, {meta['cores']} cores; gcc -O2; {meta['count']} polynomials "
        f"per family, {meta['sweeps']} timing sweeps; command: `{meta['command']}`.",
        "",
        "ns: median time per solve; ×GSL: that over GSL's median in the same run; errors: "
        "relative error of the first root against the mpmath oracle (over the solves where both "
        "report a root); miss / false: collisions missed (or a later one reported) / reported "
        "earlier than the first true one or where there is none; NaN: non-finite answers or "
        "status -1 on valid input.",
        "",
        "| family | method | ns | ×GSL | err median | err 99.9 % | err max | miss | false | NaN |",
        "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for fam in FAMILIES:
        for m in methods:
            s = summary[fam][m]
            lines.append(
                f"| {fam} | {LABELS[m]} | {s['ns']:.0f} | {s['ratio_gsl']:.2f} | "
                f"{_e(s['err_median'])} | {_e(s['err_999'])} | {_e(s['err_max'])} | "
                f"{s['miss']}/{s['with_root']} | {s['false']} | {s['nan']} |")
    lines += ["", "## Targets (INTERVAL at degree 8)", ""]
    for name, ok, why in meta["targets"]:
        lines.append(f"* {'met' if ok else '**NOT met**'}: {name} — {why}")
    return "\n".join(lines) + "\n"


def targets(summary: dict) -> list[tuple[str, bool, str]]:
    g8 = summary["generic8"]
    n8 = summary["noroot8"]
    gz = summary["graze8"]["interval"]
    r1 = g8["gsl"]["ns"] / g8["interval"]["ns"]
    r2 = n8["gsl"]["ns"] / n8["interval"]["ns"]
    nans = sum(summary[f]["interval"]["nan"] for f in FAMILIES)
    return [
        ("≥ 5× faster than GSL, generic degree 8", r1 >= 5,
         f"{g8['interval']['ns']:.0f} ns vs {g8['gsl']['ns']:.0f} ns: {r1:.1f}×"),
        ("≥ 30× faster than GSL, no root in the window", r2 >= 30,
         f"{n8['interval']['ns']:.0f} ns vs {n8['gsl']['ns']:.0f} ns: {r2:.1f}×"),
        ("no misses on the grazing family", gz["miss"] == 0,
         f"{gz['miss']} of {gz['with_root']} missed"),
        ("no NaN anywhere", nans == 0, f"{nans} non-finite answers or -1 on valid input"),
    ]


def chart(summary: dict, methods, meta: dict, path: Path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    markers = {"interval": "o", "interval-nograze": "s", "closed": "^", "gsl": "D", "numpy": "P"}
    colours = dict(zip(FAMILIES, plt.get_cmap("tab10").colors))
    floor = 1e-18
    fig, axes = plt.subplots(1, 2, figsize=(15, 6.5), sharex=True, sharey=True)
    for ax, key, title in ((axes[0], "err_median", "median error"),
                           (axes[1], "err_999", "99.9 % quantile of the error")):
        for fam in FAMILIES:
            for m in methods:
                s = summary[fam][m]
                y = s[key]
                if y is None or math.isnan(y):
                    continue
                bad = s["miss"] or s["false"] or s["nan"]
                ax.scatter(s["ns"], max(y, floor), marker=markers[m], s=70 if m != "numpy" else 60,
                           facecolors=colours[fam] if not bad else "none",
                           edgecolors=colours[fam], linewidths=1.8)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.axhline(floor, color="grey", lw=0.5, ls=":")
        ax.set_xlabel("median time per solve (ns, log)")
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.25)
    axes[0].set_ylabel(f"relative error of the first root (log; exact shown at {floor:g})")
    from matplotlib.lines import Line2D
    h1 = [Line2D([], [], marker=markers[m], ls="", color="k", label=LABELS[m]) for m in methods]
    h2 = [Line2D([], [], marker="o", ls="", color=colours[f], label=f) for f in FAMILIES]
    h3 = [Line2D([], [], marker="o", ls="", mfc="none", color="k",
                 label="hollow: misses, false collisions or NaN")]
    axes[1].legend(handles=h1 + h2 + h3, loc="upper left", bbox_to_anchor=(1.01, 1), fontsize=9)
    fig.suptitle(f"Smallest positive root: time against error, one point per method × family\n"
                 f"{meta['machine']}, {meta['date']}, `{meta['command']}`", fontsize=11)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--count", type=int, default=250, help="polynomials per family (default 250)")
    ap.add_argument("--sweeps", type=int, default=9, help="timing sweeps (default 9)")
    ap.add_argument("--quick", action="store_true", help="60 polynomials, 5 sweeps")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--no-numpy", action="store_true", help="leave numpy.roots out")
    ap.add_argument("-o", "--out", default=str(RESULTS), help="results folder")
    ap.add_argument("--only-roots", action="store_true",
                    help="skip the model-error study and the scenes")
    args = ap.parse_args(argv)
    if args.quick:
        args.count, args.sweeps = 60, 5
    start = time.time()
    polys = polynomials(args.count)
    truths = oracles(polys, args.jobs)
    with tempfile.TemporaryDirectory() as tmp:
        exe = build_harness(Path(tmp))
        answers = run_c(exe, polys, args.sweeps)
    methods = list(METHODS)
    if not args.no_numpy:
        answers.update(run_numpy(polys, args.sweeps))
        methods.append("numpy")
    summary = summarise(polys, truths, answers, methods)
    cmd = "python bench/roots.py" + (" --quick" if args.quick else "")
    meta = {"date": datetime.date.today().isoformat(), "machine": machine(),
            "cores": os.cpu_count(), "count": args.count, "sweeps": args.sweeps, "command": cmd,
            "overhead_ns": answers["overhead"]}
    meta["targets"] = targets(summary)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    (out / "roots.md").write_text(table(summary, methods, meta))
    (out / "roots.json").write_text(json.dumps({"meta": meta, "summary": summary}, indent=1))
    chart(summary, methods, meta, out / "roots.png")
    print((out / "roots.md").read_text())
    print(f"wrote {out}/roots.md, roots.png, roots.json in {time.time() - start:.0f} s", flush=True)
    if not (args.only_roots or args.quick):
        sys.path.insert(0, str(ROOT / "bench"))
        import model_error
        model_error.main()
        (out / "scenes.md").write_text(scenes_report(meta))
        print((out / "scenes.md").read_text())
    print(f"done in {time.time() - start:.0f} s")
    return 0


def scenes_report(meta: dict) -> str:
    """`max2code scene --check` on the example frozen scenes, as a table."""
    sys.path.insert(0, str(ROOT))
    from max2code import scene
    lines = [f"# Example scenes ({meta['date']}, {meta['machine']})", "",
             "`max2code scene FILE --check`: every pair's first contact predicted by the engine "
             "(C core), solves by polynomial degree, rotating-model windows, the prediction time, "
             "and the largest error against the exact motion (mpmath).", "",
             "| scene | pairs | tolerance | solves by degree | rotating windows | time | max error |",
             "|---|---:|---:|---|---:|---:|---:|"]
    for f in sorted((ROOT / "examples" / "scenes").glob("*.json")):
        r = scene.run(scene.load_scene(f), check=True)
        d = r.as_dict()
        solves = ", ".join(f"{k}: {v}" for k, v in sorted(r.solves().items()))
        lines.append(f"| {f.name} | {d['pairs']} | {d['tolerance']:g} | {solves} | "
                     f"{d['rotating_windows']} | {r.seconds * 1e3:.2f} ms | {d['max_error']:.1e} |")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    sys.exit(main())
