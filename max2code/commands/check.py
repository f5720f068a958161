"""`max2code check`: do the four languages agree with the oracle on the shared test vectors?

    max2code check [FILE.mxm ...] [--vectors V.jsonl] [--lang L ...] [--json OUT]

For each equation (default: every shipped one, equations/*.mxm) the generated module (module
form, default strategy, with variants) is built in every language by its harness
(its folder's harness.py, max2code/languages/<lang>/) and run on the equation's vectors (default tests/vectors/<stem>.jsonl: exact
parameters, the exact coefficients and first root from an independent oracle). Reported per
language and vector family: the worst coefficient error (relative to the largest exact
coefficient), the worst relative error of the first root, how much of its bound the worst root
used, and how many roots were missed or spurious. Exit status 0 when every language met
TOLERANCES on every vector, 1 otherwise (a failed build or a missing tool included).

The tolerances (TOLERANCES below):
* coefficients: max_k |c_k - c*_k| <= COEF * max_k |c*_k|, with COEF = 32 eps (7.1e-15): the
  coefficients are short sums of products of rounded differences.
* first root t*: |t - t*| <= ROOT_REL t* + the most that changing every coefficient by
  COEF max_k |c*_k| can move the root: COEF S / |p'(t*)| for a simple root, and
  sqrt(COEF S / |p''(t*)/2|) for a graze (a double root), where S = max_k |c*_k| sum_k t*^k.
  ROOT_REL = 64 eps (1.4e-14): the runtimes polish a root to full relative accuracy.
  So a root that the equation itself determines poorly (bodies 1e-9 apart: t* ~ 1e-9 is set by
  c0, a difference of O(1) terms) is held to what its coefficients allow, no more.
* a root missed is a failure unless t* is within that bound of tmax; a root where the oracle has
  none (spurious) is always a failure.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import tempfile
from dataclasses import asdict, dataclass, field
from fractions import Fraction
from pathlib import Path

from .. import cache
from ..maxima import session as maxima
from ..diagnostics import Max2CodeError
from ..paths import ROOT, inputs_or_folder, no_inputs
from .vectors import Vector, VectorError, cached_vectors, load_vectors, parse_double

__all__ = ["Vector", "VectorError", "load_vectors", "parse_double", "check", "judge", "Report"]

EPS = 2.0 ** -52


@dataclass(frozen=True)
class Tolerances:
    coef: float  # coefficient error, relative to the largest exact coefficient
    root_rel: float  # relative root error on top of what the coefficient error allows


TOLERANCES = Tolerances(coef=32 * EPS, root_rel=64 * EPS)


# ---------------------------------------------------------------------------------------------
# Vectors
# ---------------------------------------------------------------------------------------------

def default_vectors(mxm: Path) -> Path:
    """A shipped equation's hand-made vectors (tests/vectors/<stem>.jsonl)."""
    return ROOT / "tests" / "vectors" / f"{mxm.stem}.jsonl"


def is_shipped(mxm: Path) -> bool:
    try:
        return mxm.resolve().parent == (ROOT / "equations").resolve()
    except OSError:
        return False


def vectors_for(mxm: Path, scratch: Path, timeout: float) -> tuple[Path, str]:
    """The vector file of an equation and where it came from: a shipped equation's own, else
    the oracle's generic vectors, made once per content and cached (vectors.py)."""
    if is_shipped(mxm) and default_vectors(mxm).exists():
        return default_vectors(mxm), "shipped"
    path, made = cached_vectors(str(mxm), scratch, timeout)
    return path, "made by the oracle" if made else "the oracle's, cached"


# ---------------------------------------------------------------------------------------------
# Comparison
# ---------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Verdict:
    """One language on one vector."""

    vector: Vector
    coef_err: float
    root_err: float | None  # relative; None when no root on either side (or one side)
    bound_use: float  # |t - t*| / bound (0 when there is nothing to compare)
    missed: bool
    spurious: bool

    @property
    def ok(self) -> bool:
        return (self.coef_err <= TOLERANCES.coef and not self.missed and not self.spurious
                and self.bound_use <= 1.0)


def _poly(cs: tuple[Fraction, ...], t: Fraction, derivative: int) -> Fraction:
    total = Fraction(0)
    for k in range(len(cs) - 1, derivative - 1, -1):
        factor = math.perm(k, derivative)
        total = total * t + cs[k] * factor
    return total


def root_bound(v: Vector, tol: Tolerances = TOLERANCES) -> float:
    """The absolute error allowed for the vector's first root (see the module docstring)."""
    assert v.first_root is not None
    t = v.first_root
    scale = max(abs(c) for c in v.coefficients)
    spread = float(scale * sum(t ** k for k in range(len(v.coefficients))))
    if v.graze:
        curvature = abs(float(_poly(v.coefficients, t, 2))) / 2
        move = math.sqrt(tol.coef * spread / curvature) if curvature else math.inf
    else:
        slope = abs(float(_poly(v.coefficients, t, 1)))
        move = tol.coef * spread / slope if slope else math.inf
    return tol.root_rel * float(t) + move


def judge(v: Vector, coefficients: tuple[float, ...], root: float | None) -> Verdict:
    exact = list(v.coefficients)
    n = max(len(exact), len(coefficients))
    exact += [Fraction(0)] * (n - len(exact))
    got = list(coefficients) + [0.0] * (n - len(coefficients))
    scale = max(abs(c) for c in exact)
    worst = max(abs(Fraction(g) - e) for g, e in zip(got, exact)) if n else Fraction(0)
    coef_err = float(worst / scale) if scale else (0.0 if worst == 0 else math.inf)
    if v.first_root is None:
        return Verdict(v, coef_err, None, 0.0, False, root is not None)
    bound = root_bound(v)
    if root is None:
        near_end = float(Fraction(v.tmax) - v.first_root) <= bound
        return Verdict(v, coef_err, None, 0.0, not near_end, False)
    err = abs(Fraction(root) - v.first_root)
    return Verdict(v, coef_err, float(err / v.first_root), float(err) / bound, False, False)


# ---------------------------------------------------------------------------------------------
# The report
# ---------------------------------------------------------------------------------------------

@dataclass
class Row:
    """The worst of one language on one family of one equation."""

    equation: str
    lang: str
    family: str
    count: int = 0
    coef_err: float = 0.0
    root_err: float = 0.0
    bound_use: float = 0.0
    missed: int = 0
    spurious: int = 0
    failed: int = 0

    def add(self, v: Verdict) -> None:
        self.count += 1
        self.coef_err = max(self.coef_err, v.coef_err)
        self.root_err = max(self.root_err, v.root_err or 0.0)
        self.bound_use = max(self.bound_use, v.bound_use)
        self.missed += v.missed
        self.spurious += v.spurious
        self.failed += not v.ok


@dataclass
class Report:
    rows: list[Row] = field(default_factory=list)
    failures: list[str] = field(default_factory=list)  # one line per failed vector or build
    errors: list[str] = field(default_factory=list)  # builds, tools, vector files
    sources: list[str] = field(default_factory=list)  # where each equation's vectors came from

    @property
    def ok(self) -> bool:
        return not self.errors and bool(self.rows) and all(r.failed == 0 for r in self.rows)

    def text(self) -> str:
        t = TOLERANCES
        out = [f"tolerances: coefficients {t.coef:.2g} of the largest; first root "
               f"{t.root_rel:.2g} relative + what that coefficient error allows "
               f"(max2code/commands/check.py); missed 0, spurious 0", *self.sources, ""]
        header = (f"{'equation':<18} {'lang':<7} {'family':<12} {'n':>3} {'coef err':>9} "
                  f"{'root rel err':>12} {'of bound':>9} {'missed':>6} {'spurious':>8}  result")
        out += [header, "-" * len(header)]
        for r in self.rows:
            out.append(f"{r.equation:<18} {r.lang:<7} {r.family:<12} {r.count:>3} "
                       f"{r.coef_err:>9.2g} {r.root_err:>12.2g} {r.bound_use:>9.2g} "
                       f"{r.missed:>6} {r.spurious:>8}  {'ok' if not r.failed else 'FAIL'}")
        for line in self.errors + self.failures[:40]:
            out.append(line)
        if len(self.failures) > 40:
            out.append(f"... and {len(self.failures) - 40} more failed vectors")
        out.append("check: " + ("every language met the tolerances" if self.ok else "FAILED"))
        return "\n".join(out) + "\n"

    def json(self) -> dict:
        return {"ok": self.ok, "tolerances": asdict(TOLERANCES), "sources": self.sources,
                "rows": [asdict(r) for r in self.rows],
                "failures": self.failures, "errors": self.errors}


def shipped_equations() -> list[Path]:
    return sorted((ROOT / "equations").glob("*.mxm"))


def languages() -> list[str]:
    from ..languages import harnesses
    return list(harnesses())


def build_directory() -> Path:
    """Kept between checks (Cargo's target folder): under the max2code cache folder."""
    return cache.directory() / "check"


def check(equations: list[Path], vectors: dict[Path, Path] | None = None,
          langs: list[str] | None = None, build_dir: Path | None = None,
          timeout: float = maxima.DEFAULT_TIMEOUT) -> Report:
    """Build every language's module for each equation, run it on the vectors, compare.

    `vectors` maps an equation to its vector file (default: `vectors_for`). No language is
    built for an equation without vectors (an error in the report instead)."""
    from ..languages import harnesses

    report = Report()
    langs = langs or list(harnesses())
    build_dir = build_dir or build_directory()
    build_dir.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="max2code-check-") as tmp:
        _check(equations, vectors, langs, build_dir, timeout, Path(tmp), report)
    report.rows.sort(key=lambda r: (r.equation, langs.index(r.lang)))
    return report


def _check(equations: list[Path], vectors: dict[Path, Path] | None, langs: list[str],
           build_dir: Path, timeout: float, tmp: Path, report: Report) -> None:
    from ..codegen.generate import load
    from ..languages import harnesses
    from ..languages.harness import Case, HarnessError, Unit

    units, by_name = [], {}
    for mxm in equations:
        spec, poly = load(str(mxm), timeout)
        if vectors and mxm in vectors:
            path, origin = vectors[mxm], "given"
        else:
            path, origin = vectors_for(mxm, tmp / "vectors", timeout)
        report.sources.append(f"{mxm}: vectors {path} ({origin})")
        try:
            vs = load_vectors(path, poly.parameters)
        except VectorError as exc:
            report.errors.append(f"{mxm}: {exc}")
            continue
        if not vs:
            report.errors.append(f"{mxm}: {path}: no vectors (nothing to check; no module "
                                 f"built)")
            continue
        unit = Unit(spec, poly, tuple(Case(v.params, v.tmax) for v in vs))
        units.append(unit)
        by_name[unit.name] = (mxm, path, vs)
    if not units:
        return
    harness = harnesses()
    for lang in langs:
        workdir = tmp / lang
        workdir.mkdir()
        try:
            outcomes = harness[lang].run(units, workdir, build_dir)
        except HarnessError as exc:
            report.errors.append(f"{lang}: {exc}")
            continue
        for unit in units:
            mxm, path, vs = by_name[unit.name]
            rows: dict[str, Row] = {}
            for v, o in zip(vs, outcomes[unit.name]):
                verdict = judge(v, o.coefficients, o.root)
                rows.setdefault(v.family, Row(mxm.stem, lang, v.family)).add(verdict)
                if not verdict.ok:
                    report.failures.append(_failure(path, lang, verdict, o.root))
            report.rows += rows.values()


def _failure(path: Path, lang: str, v: Verdict, root: float | None) -> str:
    vec = v.vector
    what = []
    if v.coef_err > TOLERANCES.coef:
        what.append(f"coefficient error {v.coef_err:.3g}")
    if v.missed:
        what.append(f"missed the root {float(vec.first_root):.17g}")  # type: ignore[arg-type]
    if v.spurious:
        what.append(f"spurious root {root!r} (the oracle has none in (0, {vec.tmax:g}])")
    if v.bound_use > 1:
        what.append(f"root {root!r}, exact {float(vec.first_root):.17g} "  # type: ignore[arg-type]
                    f"(relative error {v.root_err:.3g}, {v.bound_use:.3g} times its bound)")
    return (f"{path}:{vec.line}: {lang}: {vec.family} ({vec.note}): "
            + "; ".join(what))


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(
        prog="max2code check",
        description="Build every language's module for each equation, run it on the shared "
                    "oracle vectors and report the worst errors; exit 0 when all languages meet "
                    "the tolerances.")
    ap.add_argument("inputs", nargs="*", metavar="FILE.mxm",
                    help="equations (default: the .mxm files of the current folder)")
    ap.add_argument("--vectors", metavar="V.jsonl",
                    help="the vector file (with one equation; default: a shipped equation's "
                         "own, else the oracle's, made once and cached: max2code vectors)")
    ap.add_argument("--lang", action="append", choices=languages(), metavar="LANG",
                    help=f"a language to check (repeatable; default all: "
                         f"{', '.join(languages())})")
    ap.add_argument("--build-dir", metavar="DIR",
                    help=f"kept between runs (Cargo's target folder); default "
                         f"{build_directory()}")
    ap.add_argument("--json", metavar="FILE", help="also write the report as JSON")
    from .options import add_maxima_options, apply_maxima_options
    add_maxima_options(ap)
    opts = ap.parse_args(argv)
    apply_maxima_options(opts)
    equations = [Path(p) for p in inputs_or_folder(opts.inputs)]
    if not equations:
        ap.error(no_inputs("check"))
    if opts.vectors and len(equations) != 1:
        ap.error("--vectors needs exactly one FILE.mxm")
    vectors = {equations[0]: Path(opts.vectors)} if opts.vectors else None
    try:
        report = check(equations, vectors, opts.lang,
                       Path(opts.build_dir) if opts.build_dir else None, opts.timeout)
    except Max2CodeError as exc:
        for diag in exc.diagnostics:
            print(diag, file=sys.stderr)
        return 1
    sys.stdout.write(report.text())
    if opts.json:
        Path(opts.json).write_text(json.dumps(report.json(), indent=1) + "\n")
    return 0 if report.ok else 1
