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
  collision8     orbiting circles (the shipped circles-orbit equation: rotation to order 4): two
                 bodies with random game-like states, |d(t)|^2 - (r1 + r2)^2 over the window
                 where the expansion holds (|w| t <= 0.5); about half of them collide in it
  noroot8_near   no root in the window, complex pairs close to it (real part inside, imaginary
                 part 1e-3..1e-1 of it)
  noroot8_inf    no positive real root at all, tmax infinite
  generic12/16   generic8's construction at degrees 12 and 16 (the order-6 and order-8 orbit
                 models' degrees)

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
import statistics
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ProcessPoolExecutor
from fractions import Fraction
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tests"))
sys.path.insert(0, str(ROOT / "bench"))

from benchtools import compile_c, results_dir, smoke  # noqa: E402  (bench/benchtools.py, beside this script)
from runtime import cases  # noqa: E402  (tests/runtime/cases.py: builders and the oracle)

RESULTS = results_dir(ROOT / "bench" / "results")
CACHE = ROOT / "bench" / ".cache"
C_DIR = ROOT / "runtime" / "c"
METHODS = ("interval", "interval-nograze", "gsl", "closed")  # C numbering 0..3
LABELS = {"interval": "INTERVAL (default)", "interval-nograze": "INTERVAL_NOGRAZE", "gsl": "GSL",
          "closed": "CLOSED", "numpy": "numpy.roots (Python)"}
FAMILIES = ("generic2", "generic4", "generic8", "noroot8", "graze8", "cluster8", "drop8",
            "scale8", "near0_8", "collision8", "noroot8_near", "noroot8_inf", "generic12", "generic16")
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


def _rot4(w: Fraction, o: tuple[Fraction, Fraction]) -> tuple[list[Fraction], list[Fraction]]:
    """R(w t) o with cos and sin expanded to order 4 in t, as polynomials in t (low first)."""
    cos = [Fraction(1), Fraction(0), -w**2 / 2, Fraction(0), w**4 / 24]
    sin = [Fraction(0), w, Fraction(0), -w**3 / 6, Fraction(0)]
    x = [cos[i] * o[0] - sin[i] * o[1] for i in range(5)]
    y = [sin[i] * o[0] + cos[i] * o[1] for i in range(5)]
    return x, y


def _collision(rng: random.Random) -> tuple[tuple[float, ...], float]:
    """|d(t)|^2 - R^2 for two orbiting circles (centre c + v t + a t^2/2, a point offset o
    rotating at w), multiplied out exactly from the double parameters, rounded once."""
    def f(lo: float, hi: float) -> Fraction:
        return Fraction(rng.uniform(lo, hi))
    R = f(0.2, 0.8) + f(0.2, 0.8)
    ws = [f(0.3, 4) * rng.choice((1, -1)) for _ in range(2)]
    h = 0.5 / float(max(abs(w) for w in ws))  # the order-4 model's window
    # relative state: closing at a speed that meets within about the window half the time
    dist = float(R) + rng.uniform(0.05, 3.0)
    ang = rng.uniform(0, 2 * math.pi)
    speed = (dist - float(R)) / h * rng.uniform(0.3, 2.0)
    dc = (Fraction(dist * math.cos(ang)), Fraction(dist * math.sin(ang)))
    dv = (Fraction(-speed * math.cos(ang + rng.uniform(-0.3, 0.3))),
          Fraction(-speed * math.sin(ang + rng.uniform(-0.3, 0.3))))
    da = (f(-1, 1), f(-1, 1))
    dx = [dc[0], dv[0], da[0] / 2, Fraction(0), Fraction(0)]
    dy = [dc[1], dv[1], da[1] / 2, Fraction(0), Fraction(0)]
    for sign, w in zip((1, -1), ws):
        rx, ry = _rot4(w, (f(-0.6, 0.6), f(-0.6, 0.6)))
        dx = [dx[i] + sign * rx[i] for i in range(5)]
        dy = [dy[i] + sign * ry[i] for i in range(5)]
    c = [Fraction(0)] * 9
    for i in range(5):
        for j in range(5):
            c[i + j] += dx[i] * dx[j] + dy[i] * dy[j]
    c[0] -= R * R
    return tuple(float(x) for x in c), h


def _noroot_near(rng: random.Random) -> tuple[tuple[float, ...], float]:
    tmax = _mag(rng, -1, 0.5)
    npairs = rng.randint(1, 4)
    pairs = []
    for _ in range(npairs):
        re = tmax * rng.uniform(0.05, 0.95)
        pairs.append((re, re * 10 ** rng.uniform(-3, -1)))
    reals = [-_mag(rng) if rng.random() < 0.5 else tmax * rng.uniform(1.1, 20)
             for _ in range(8 - 2 * npairs)]
    return cases.poly_from_roots(reals, pairs, lead=_lead(rng)), tmax


def _noroot_inf(rng: random.Random) -> tuple[tuple[float, ...], float]:
    npairs = rng.randint(1, 4)
    reals = [-_mag(rng) for _ in range(8 - 2 * npairs)]
    return cases.poly_from_roots(reals, _pairs(rng, npairs), lead=_lead(rng)), math.inf


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
    "collision8": _collision,
    "noroot8_near": _noroot_near,
    "noroot8_inf": _noroot_inf,
    "generic12": lambda rng: _generic(rng, 12),
    "generic16": lambda rng: _generic(rng, 16),
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
    exe = workdir / "roots_harness"
    compile_c("bench", "compiling the harness", [
        "-O2", "-std=c11", "-Wall", "-Wextra", "-I", str(C_DIR),
        str(ROOT / "bench" / "roots_harness.c"), str(C_DIR / "max2code_roots.c"),
        "-o", str(exe), "-lgsl", "-lgslcblas", "-lm"])
    return exe


def run_c(exe: Path, polys: list[tuple[str, tuple[float, ...], float]], sweeps: int) -> dict:
    lines = [" ".join([t.hex(), str(len(c) - 1), *(x.hex() for x in c)]) for _, c, t in polys]
    r = subprocess.run([str(exe), str(sweeps)], input="\n".join(lines) + "\n", capture_output=True,
                       text=True, check=True)
    out: dict[tuple[int, str], tuple[int, float, bool, float]] = {}
    overhead = horner = math.nan
    for line in r.stdout.splitlines():
        if line.startswith("#"):
            words = line.split()
            if words[1] == "overhead_ns":
                overhead = float(words[2])
            elif words[1] == "horner8_ns":
                horner = float(words[2])
            continue
        i, m, st, t, g, ns = line.split()
        out[(int(i), METHODS[int(m)])] = (int(st), float.fromhex(t) if t != "nan" and "nan" not in t
                                          else math.nan, g == "1", float(ns))
    out["overhead"] = overhead  # type: ignore[index]
    out["horner8"] = horner  # type: ignore[index]
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


def time_calls(polys: list, sweeps: int, solve, seed: int) -> dict[int, tuple[int, float, float]]:
    """In-process timing, as the harnesses do it: every call on its own (perf_counter_ns, the
    median empty region subtracted), polynomials in an order shuffled anew per sweep;
    {index: (status, t, median ns)} with solve(c, tmax) -> (status, t)."""
    clock = time.perf_counter_ns
    empty = []
    for _ in range(2001):
        a = clock()
        empty.append(clock() - a)
    overhead = sorted(empty)[1000]
    samples: dict[int, list[float]] = {i: [] for i in range(len(polys))}
    answers = {}
    order = list(range(len(polys)))
    rng = random.Random(seed)
    for _ in range(sweeps):
        rng.shuffle(order)
        for i in order:
            _, c, tmax = polys[i]
            a = clock()
            answers[i] = solve(c, tmax)
            samples[i].append(clock() - a - overhead)
    return {i: (*answers[i], sorted(v)[len(v) // 2]) for i, v in samples.items()}


def run_numpy(polys: list[tuple[str, tuple[float, ...], float]], sweeps: int) -> dict:
    import numpy as np
    got = time_calls(polys, sweeps, lambda c, tmax: numpy_first_root(np, c, tmax), 5)
    return {(i, "numpy"): (st, t, False, ns) for i, (st, t, ns) in got.items()}


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
    colours = dict(zip(FAMILIES, plt.get_cmap("tab20").colors))
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
    ap.add_argument("--rounds", type=int, default=3, help="C/Rust alternations (default 3)")
    ap.add_argument("--pure-share", type=int, default=5,
                    help="pure Python times every Nth polynomial (default 5)")
    ap.add_argument("--only-runtimes", action="store_true",
                    help="only the runtime comparison (roots_runtimes.md)")
    args = ap.parse_args(argv)
    if args.quick:
        args.count, args.sweeps = 60, 5
    if smoke():  # tests/test_docs.py: every step, the least work
        args.count, args.sweeps, args.rounds, args.quick = 4, 1, 1, True
    start = time.time()
    polys = polynomials(args.count)
    cmd = " ".join(["python bench/roots.py", *(argv if argv is not None else sys.argv[1:])])
    meta = {"date": datetime.date.today().isoformat(), "machine": machine(),
            "cores": os.cpu_count(), "count": args.count, "sweeps": args.sweeps, "command": cmd,
            "rounds": args.rounds, "pure_share": args.pure_share}
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        exe = build_harness(Path(tmp))
        cmp = runtime_comparison(polys, args.sweeps, args.rounds, exe, args.pure_share)
        cmp["batch"] = batch_comparison(polys)
        cmp["counts"] = cost_counts(polys, Path(tmp))
        (out / "roots_runtimes.md").write_text(runtime_table(cmp, meta) + counts_table(cmp["counts"], cmp))
        (out / "roots_runtimes.json").write_text(json.dumps({"meta": meta, **cmp}, indent=1))
        print((out / "roots_runtimes.md").read_text(), flush=True)
        if args.only_runtimes:
            return 0
        truths = oracles(polys, args.jobs)
        answers = run_c(exe, polys, args.sweeps)
    methods = list(METHODS)
    if not args.no_numpy:
        answers.update(run_numpy(polys, args.sweeps))
        methods.append("numpy")
    summary = summarise(polys, truths, answers, methods)
    meta["overhead_ns"] = answers["overhead"]
    meta["horner8_ns"] = answers["horner8"]
    meta["targets"] = targets(summary)
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


# ---------------------------------------------------------------------------
# The runtimes side by side (issue 10's table)
# ---------------------------------------------------------------------------

RUST_DIR = ROOT / "runtime" / "rust"
TABLE = (("generic8", "generic octic"), ("noroot8", "no root in window"),
         ("noroot8_near", "no root, complex roots near the window"),
         ("noroot8_inf", "no root, tmax = inf"), ("collision8", "collision polynomials (orbiting circles)"),
         ("generic4", "generic quartic"), ("graze8", "grazing"), ("generic12", "generic, degree 12"),
         ("generic16", "generic, degree 16"))
# Yuksel's cyPolynomial (HPG 2022) as issue 10 measured it (not measured here, not vendored):
# its time over the C INTERVAL solver's of that day, finest / default accuracy.
CY_REFERENCE = {"generic8": (3.0, 1.46), "noroot8": (2.1, 1.3), "collision8": (1.5, 0.84),
                "generic4": (1.0, 0.61), "graze8": (1.2, 0.55)}
# ... and that day's INTERVAL in units of one degree-8 Horner evaluation (23 ns there).
ISSUE_INTERVAL_EVALS = {"generic8": 792 / 23, "noroot8": 311 / 23, "collision8": 511 / 23,
                        "generic4": 491 / 23, "graze8": 3600 / 23}
TARGET_EVALS = {"generic8": 15, "noroot8": 6, "noroot8_near": 6, "noroot8_inf": 6, "graze8": 40,
                "collision8": 0.84 * 511 / 23, "generic4": 0.61 * 491 / 23}


def build_rust_bench() -> Path | None:
    cargo = shutil.which("cargo") or str(Path.home() / ".cargo" / "bin" / "cargo")
    if not Path(cargo).exists():
        print("bench: cargo not found: the Rust column is left out", flush=True)
        return None
    env = dict(os.environ, CARGO_TARGET_DIR=str(RUST_DIR / "target"))
    r = subprocess.run([cargo, "build", "--quiet", "--release", "--example", "roots_bench"],
                       cwd=RUST_DIR, env=env, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"bench: building the Rust harness failed:\n{r.stderr}")
    return RUST_DIR / "target" / "release" / "examples" / "roots_bench"


def run_rust(exe: Path, polys: list, sweeps: int) -> dict[int, tuple[int, float, float]]:
    lines = [" ".join([repr(t), str(len(c) - 1), *(repr(x) for x in c)]) for _, c, t in polys]
    r = subprocess.run([str(exe), str(sweeps)], input="\n".join(lines) + "\n", capture_output=True,
                       text=True, check=True)
    out = {}
    for line in r.stdout.splitlines():
        if line.startswith("#"):
            continue
        i, st, t, ns = line.split()
        out[int(i)] = (int(st), float(t), float(ns))
    return out


def run_python(polys: list, sweeps: int, backend) -> dict[int, tuple[int, float, float]]:
    """Per call, through the public first_root_status with the given backend (None: pure
    Python)."""
    sys.path.insert(0, str(ROOT / "runtime" / "python"))
    import max2code_runtime as rt
    saved = rt._C
    rt._C = backend
    try:
        return time_calls(polys, sweeps, lambda c, tmax: rt.first_root_status(c, tmax)[:2], 7)
    finally:
        rt._C = saved


def c_backend():
    """max2code_runtime's cffi backend, or None -- then said on stderr, with the reason (a stale
    build is refused: the Python (C backend) column would otherwise be empty without a word)."""
    sys.path.insert(0, str(ROOT / "runtime" / "python"))
    if os.environ.get("MAX2CODE_PURE_PYTHON"):
        print("bench/roots.py: MAX2CODE_PURE_PYTHON is set: no C backend to time", file=sys.stderr)
        return None
    try:
        from max2code_runtime import _cbackend
    except ImportError as exc:
        print(f"bench/roots.py: the C backend is not in use: {exc}", file=sys.stderr)
        return None
    return _cbackend


def runtime_comparison(polys: list, sweeps: int, rounds: int, exe_c: Path, pure_share: int) -> dict:
    """C and Rust alternately for `rounds` rounds (ratios per round, then their median), Python
    through cffi and pure Python after; answers compared with C's bit for bit."""
    fams = [f for f, _ in TABLE]
    idx = [i for i, (f, _, _) in enumerate(polys) if f in fams]
    sub = [polys[i] for i in idx]
    rust_exe = build_rust_bench()
    rounds_c, rounds_r, horner = [], [], []
    for _ in range(rounds):
        ans = run_c_interval(exe_c, sub, sweeps)
        rounds_c.append(ans)
        horner.append(ans["horner8"])
        if rust_exe is not None:
            rounds_r.append(run_rust(rust_exe, sub, sweeps))
    cffi = c_backend()
    py_c = run_python(sub, sweeps, cffi) if cffi is not None else None
    pure_idx = [k for k in range(len(sub)) if k % pure_share == 0]
    py_pure = run_python([sub[k] for k in pure_idx], 1, None)
    py_pure = {pure_idx[k]: v for k, v in py_pure.items()}

    def fam_median(ans: dict, fam: str, keys=None) -> float:
        ks = [k for k in range(len(sub)) if sub[k][0] == fam and (keys is None or k in keys)]
        return quantile([ans[k][-1] for k in ks], 0.5)

    out = {"horner8_ns": statistics_median(horner), "families": {}, "mismatch": {}}
    c0 = rounds_c[0]
    for fam in fams:
        row = {}
        cs = [fam_median(a, fam) for a in rounds_c]
        row["c_ns"] = statistics_median(cs)
        row["c_evals"] = row["c_ns"] / out["horner8_ns"]
        # the mean too: a family with two modes (solves settled at 0, and the rest) has its
        # median between them, where a change moves it more than the family's total
        means = [statistics.mean(a[k][-1] for k in range(len(sub)) if sub[k][0] == fam)
                 for a in rounds_c]
        row["c_mean_evals"] = statistics_median(means) / out["horner8_ns"]
        if rounds_r:
            row["rust_ratio"] = statistics_median([fam_median(r, fam) / c for r, c in zip(rounds_r, cs)])
        if py_c is not None:
            row["py_c_ratio"] = fam_median(py_c, fam) / row["c_ns"]
        keys = set(pure_idx)
        row["py_pure_ratio"] = fam_median(py_pure, fam, keys) / statistics_median(
            [fam_median(a, fam, keys) for a in rounds_c])
        out["families"][fam] = row
    for name, ans in (("rust", rounds_r[0] if rounds_r else None), ("python-c", py_c), ("python", py_pure)):
        if ans is None:
            continue
        bad = 0
        for k, v in ans.items():
            st, t = c0[k][0], c0[k][1]
            if v[0] != st or (st == 1 and v[1] != t):
                bad += 1
        out["mismatch"][name] = (bad, len(ans))
    return out


def batch_comparison(polys: list, repeats: int = 7) -> dict:
    """first_roots on an (M, 9) array against M calls of first_root, per backend: ns per
    polynomial, best of `repeats` (the collision family, one tmax: the smallest of the family's
    windows, so that every row has the same window)."""
    import numpy as np
    sys.path.insert(0, str(ROOT / "runtime" / "python"))
    import max2code_runtime as rt
    rows = [c for f, c, _ in polys if f == "collision8"]
    tmax = min(t for f, _, t in polys if f == "collision8")
    arr = np.array(rows)
    out = {"M": len(rows)}
    saved = rt._C
    try:
        for name, backend in (("c", c_backend()), ("python", None)):
            if name == "c" and backend is None:
                continue
            rt._C = backend
            single, batch = [], []
            for _ in range(repeats if name == "c" else 1):
                a = time.perf_counter_ns()
                loop = [rt.first_root(r, tmax) for r in rows]
                single.append(time.perf_counter_ns() - a)
                a = time.perf_counter_ns()
                got = rt.first_roots(arr, tmax)
                batch.append(time.perf_counter_ns() - a)
            same = all((x is None and math.isnan(y)) or x == y for x, y in zip(loop, got))
            out[name] = {"single_ns": min(single) / len(rows), "batch_ns": min(batch) / len(rows),
                         "same": same}
    finally:
        rt._C = saved
    return out


def cost_counts(polys: list, workdir: Path) -> dict:
    """The C runtime's own accounting (-DM2C_COUNT) per family: mean multiply-adds by phase in
    units of a degree-8 Horner evaluation (8 multiply-adds), Newton steps, Taylor points and
    derivative-method calls per solve: where the evaluations go, and so what a target takes."""
    exe = workdir / "roots_count"
    cmd = [shutil.which("gcc") or "gcc", "-O2", "-std=c11", "-DM2C_COUNT", "-I", str(C_DIR),
           str(ROOT / "bench" / "roots_harness.c"), str(C_DIR / "max2code_roots.c"), "-o", str(exe),
           "-lgsl", "-lgslcblas", "-lm"]
    subprocess.run(cmd, check=True, capture_output=True)
    fams = [f for f, _ in TABLE]
    sub = [p for p in polys if p[0] in fams]
    lines = [" ".join([t.hex(), str(len(c) - 1), *(x.hex() for x in c)]) for _, c, t in sub]
    r = subprocess.run([str(exe), "count"], input="\n".join(lines) + "\n", capture_output=True,
                       text=True, check=True)
    rows = [list(map(float, ln.split()[1:])) for ln in r.stdout.splitlines()]
    out = {}
    for fam in fams:
        mine = [row for (f, _, _), row in zip(sub, rows) if f == fam]
        mean = [sum(col) / len(mine) for col in zip(*mine)]
        out[fam] = {"prep": mean[0] / 8, "isolate": mean[1] / 8, "newton": mean[2] / 8,
                    "derivative": mean[3] / 8, "plain_steps": mean[4], "precise_steps": mean[5],
                    "taylor_points": mean[6], "derivative_calls": mean[7], "bernstein_tests": mean[9],
                    "share_derivative": sum(1 for row in mine if row[7] > 0) / len(mine)}
    return out


def counts_table(counts: dict, cmp: dict) -> str:
    lines = ["", "## Where the evaluations go", "",
             "The C runtime's own accounting (built with `-DM2C_COUNT`, one solve per polynomial): "
             "mean multiply-adds per solve by phase, in degree-8 Horner evaluations (8 multiply-adds; "
             "a compensated Horner step counted as 10; an addition of the Bernstein sums or a halving "
             "counted as one), beside the measured time in the same unit (the counts overstate the "
             "work that runs in parallel: the Bernstein sums and the Taylor shift are many "
             "independent chains, Horner one). Isolation: the Bernstein tests (n rounds of running "
             "sums), the exclusion by halving, the Taylor coefficients at the window's points of the "
             "Budan-Fourier counts ((n+1)(n+2) multiply-adds a point: 11 evaluations at degree 8) "
             "and the bounds; Newton: the guess's plain steps and the polishing.", "",
             "| family | measured (evaluations) | counted: isolation | Newton | derivative method | Bernstein tests | Taylor points | Newton steps plain / compensated | solves using the derivative method |",
             "|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for fam, label in TABLE:
        c = counts[fam]
        lines.append(f"| {label} | {cmp['families'][fam]['c_evals']:.1f} | {c['isolate']:.1f} | "
                     f"{c['newton']:.1f} | {c['derivative']:.1f} | {c['bernstein_tests']:.2f} | "
                     f"{c['taylor_points']:.2f} | "
                     f"{c['plain_steps']:.1f} / {c['precise_steps']:.1f} | {100 * c['share_derivative']:.0f} % |")
    return "\n".join(lines) + "\n"


def statistics_median(xs: list[float]) -> float:
    return quantile(xs, 0.5) if len(xs) % 2 else 0.5 * (sorted(xs)[len(xs) // 2 - 1] + sorted(xs)[len(xs) // 2])


def run_c_interval(exe: Path, polys: list, sweeps: int) -> dict:
    """The C harness on INTERVAL alone: {k: (status, t, ns)} and the Horner unit."""
    lines = [" ".join([t.hex(), str(len(c) - 1), *(x.hex() for x in c)]) for _, c, t in polys]
    r = subprocess.run([str(exe), str(sweeps), "1"], input="\n".join(lines) + "\n", capture_output=True,
                       text=True, check=True)
    out: dict = {}
    for line in r.stdout.splitlines():
        words = line.split()
        if words[0] == "#":
            if words[1] == "horner8_ns":
                out["horner8"] = float(words[2])
            continue
        i, _m, st, t, _g, ns = words
        out[int(i)] = (int(st), float.fromhex(t) if "nan" not in t else math.nan, float(ns))
    return out


def runtime_table(cmp: dict, meta: dict) -> str:
    h = cmp["horner8_ns"]
    lines = [
        f"# The runtimes side by side ({meta['date']})", "",
        f"Machine: {meta['machine']}, {meta['cores']} cores, shared with other work (absolute times "
        f"are noisy; the ratios come from one run). Command: `{meta['command']}`. C: gcc -O2; Rust: "
        f"cargo --release; Python 3: the public `first_root_status`, per call.", "",
        f"Unit: one degree-8 Horner evaluation, timed like the solves in the same C run: "
        f"**{h:.1f} ns**. C and Rust ran alternately, {meta['rounds']} rounds of {meta['sweeps']} "
        f"sweeps; ratios are the median over rounds of the per-round ratio. Each solve's time is its "
        f"median over the sweeps; a family's is the median over its polynomials (the targets' "
        f"measure), beside their mean. Python (C backend) is the "
        f"C runtime through cffi; Python (pure) is the pure-Python port, on every {meta['pure_share']}th "
        f"polynomial. cyPolynomial: issue 10's measurement of Yuksel's cyPolynomial (HPG 2022), as "
        f"its time over that day's C INTERVAL (finest / default accuracy) -- quoted as the reference, "
        f"not measured here.", "",
        "| family | C INTERVAL | in Horner evaluations | target | mean | cyPolynomial (issue 10) finest / default | Rust runtime | Python (C backend) | Python (pure) |",
        "|---|---:|---:|---:|---:|---|---:|---:|---:|",
    ]
    for fam, label in TABLE:
        r = cmp["families"][fam]
        cy = CY_REFERENCE.get(fam)
        cy_s = (f"{cy[0]:.2g}× / {cy[1]:.2g}× of that day's {ISSUE_INTERVAL_EVALS[fam]:.0f} evaluations "
                f"(= {cy[0] * ISSUE_INTERVAL_EVALS[fam]:.0f} / {cy[1] * ISSUE_INTERVAL_EVALS[fam]:.0f})"
                if cy else "–")
        tgt = TARGET_EVALS.get(fam)
        tgt_s = "–" if tgt is None else (f"≤ {tgt:.0f}" if fam not in ("collision8", "generic4") else f"< {tgt:.1f}")
        met = "" if tgt is None else (" ✓" if r["c_evals"] <= tgt else " ✗")
        py_c = f"{r['py_c_ratio']:.1f}×" if "py_c_ratio" in r else "not in use"
        lines.append(
            f"| {label} | {r['c_ns']:.0f} ns | {r['c_evals']:.1f}{met} | {tgt_s} | "
            f"{r.get('c_mean_evals', math.nan):.1f} | {cy_s} | "
            f"{r.get('rust_ratio', math.nan):.2f}× | {py_c} | "
            f"{r['py_pure_ratio']:.0f}× |")
    lines += ["", "Answers against C's (status and root, bit for bit): " + ", ".join(
        f"{name} {bad} different of {n}" for name, (bad, n) in cmp["mismatch"].items()) + "."]
    b = cmp.get("batch")
    if b:
        lines += ["", f"Batches (`first_roots`, an ({b['M']}, 9) numpy array of the collision family, one "
                  f"window) against the same {b['M']} `first_root` calls, ns per polynomial (best of 7 "
                  "for the C backend, one run for pure Python):", "",
                  "| Python backend | one call each | one `first_roots` call | speed-up | same answers |",
                  "|---|---:|---:|---:|---|"]
        for name in ("c", "python"):
            if name in b:
                r = b[name]
                lines.append(f"| {name} | {r['single_ns']:.0f} | {r['batch_ns']:.0f} | "
                             f"{r['single_ns'] / r['batch_ns']:.1f}× | {'yes' if r['same'] else 'NO'} |")
        lines += ["", "The C backend hands the whole array to `m2c_first_roots` (one call into C, no "
                  "copy); the pure-Python fallback solves the rows one by one (nothing to vectorise: "
                  "each row's solve branches on its own data)."]
    return "\n".join(lines) + "\n"


def scenes_report(meta: dict) -> str:
    """`max2code scene --check` on the example frozen scenes, as a table."""
    sys.path.insert(0, str(ROOT))
    from max2code.commands import scene
    lines = [f"# Example scenes ({meta['date']}, {meta['machine']})", "",
             "`max2code scene FILE --check`: every pair's first contact predicted by the engine "
             "(C core), solves by polynomial degree, rotating-model windows, the prediction time, "
             "and the largest error against the exact motion (mpmath).", "",
             "| scene | pairs | tolerance | solves by degree | rotating windows | time | max error |",
             "|---|---:|---:|---|---:|---:|---:|"]
    for f in sorted((ROOT / "examples" / "frozen").glob("*.json")):
        r = scene.run(scene.load_scene(f), check=True)
        d = r.as_dict()
        solves = ", ".join(f"{k}: {v}" for k, v in sorted(r.solves().items()))
        lines.append(f"| {f.name} | {d['pairs']} | {d['tolerance']:g} | {solves} | "
                     f"{d['rotating_windows']} | {r.seconds * 1e3:.2f} ms | {d['max_error']:.1e} |")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    sys.exit(main())
