"""`max2code report`: what variant generation produced, in Markdown, JSON and HTML.

For each equation: its variants under both strategies (conditions, degree, operation counts),
lines of generated code per language, Maxima's time; and the paper's figure 6 table (lines of
.mxm, of Maxima output, of generated Modula-2) reproduced for this tool beside the paper's.
"""

from __future__ import annotations

import argparse
import json
import sys
from dataclasses import asdict, dataclass
from html import escape
from pathlib import Path

from . import maxima
from .diagnostics import Max2CodeError
from .generate import generate, load
from .languages import LANGUAGES
from .output import write_if_changed
from .paths import ROOT, display, shipped_equations
from .variants import STRATEGIES, family

# The paper's figure 6: lines of max2code input, of Maxima output, of generated Modula-2.
PAPER_FIGURE_6 = {"circle-circle": (33, 835, 977), "point-line": (34, 18, 24)}
# Which of our equations correspond to the paper's two rows.
FIGURE_6_ROWS = (
    ("Two circles (paper's figures 5+7, verbatim)", "equations/paper/circle-circle.mxm", "circle-circle"),
    ("Two circles (corrected: circles-orbit.mxm)", "equations/circles-orbit.mxm", "circle-circle"),
    ("Point and line (paper's figures 9+10, verbatim)", "equations/paper/point-line.mxm", "point-line"),
    ("Point and line (corrected: point-orbit-line.mxm)", "equations/point-orbit-line.mxm", "point-line"),
)


@dataclass(frozen=True)
class VariantRow:
    index: int
    label: str
    zeros: list[str]
    degree: int
    add: int
    mul: int
    div: int


@dataclass(frozen=True)
class EquationReport:
    source: str
    degree: int
    parameters: list[str]
    maxima_seconds: float
    variants: dict[str, list[VariantRow]]
    lines: dict[str, dict[str, int]]  # strategy -> language -> lines (with variants)


@dataclass(frozen=True)
class Figure6Row:
    label: str
    mxm_lines: int
    maxima_lines: dict[str, int]
    m2_lines: dict[str, int]  # general polynomial only, as the paper had
    paper: tuple[int, int, int]
    ops: dict[str, int]  # floating-point operations of the general polynomial


def _lines(result) -> int:
    return result.text.count("\n") + sum(t.count("\n") for _, t in result.companions)


def equation_report(path: str, timeout: float) -> EquationReport:
    spec, poly = load(path, timeout)
    variants = {}
    lines: dict[str, dict[str, int]] = {}
    for strategy in STRATEGIES:
        variants[strategy] = [VariantRow(v.index, v.label, list(v.zeros), v.degree, v.ops.add,
                                         v.ops.mul, v.ops.div) for v in family(poly, strategy)]
        lines[strategy] = {
            name: _lines(generate(spec, poly, lang, "module", f"out{lang.extension}", strategy))
            for name, lang in sorted(LANGUAGES.items())}
    return EquationReport(path, poly.degree, list(poly.parameters), round(poly.maxima_seconds, 3),
                          variants, lines)


def figure6_row(label: str, path: str, paper: str, timeout: float) -> Figure6Row:
    """`path` is relative to the shipped data (the checkout, or the installed package)."""
    source = ROOT / path
    spec, poly = load(display(source), timeout)
    m2 = LANGUAGES["m2"]
    m2_lines = {s: _lines(generate(spec, poly, m2, "module", "out.mod", s, with_variants=False))
                for s in STRATEGIES}
    ops = {s: family(poly, s, with_variants=False)[0].ops.total for s in STRATEGIES}
    return Figure6Row(label, source.read_text().count("\n"),
                      {"optimised": poly.maxima_lines, "expanded": poly.maxima_lines_expanded},
                      m2_lines, PAPER_FIGURE_6[paper], ops)


def markdown(equations: list[EquationReport], fig6: list[Figure6Row]) -> str:
    out = ["# max2code variant report", ""]
    if fig6:
        out += ["## The paper's figure 6, reproduced", "",
                "Lines of .mxm input, of Maxima output (at Maxima's 79 columns: the equation as "
                "the program leaves it for `optimised`, the expanded polynomial for `expanded`) "
                "and of the generated Modula-2 module for the general polynomial (`.def` + "
                "`.mod`, without variants, as the paper had). Lines flatter the expanded form, whose "
                "coefficients are one long line each (gm2 numbers continuation lines, so "
                "Modula-2 expressions are never wrapped) while the optimised form is one "
                "shared subexpression per line: the operation count says what each costs.", "",
                "| expression | .mxm | Maxima (optimised / expanded) | Modula-2 (optimised / "
                "expanded) | operations (optimised / expanded) | paper: max2code / maxima / "
                "Modula-2 |", "|---|---|---|---|---|---|"]
        for r in fig6:
            out.append(f"| {r.label} | {r.mxm_lines} | {r.maxima_lines['optimised']} / "
                       f"{r.maxima_lines['expanded']} | {r.m2_lines['optimised']} / "
                       f"{r.m2_lines['expanded']} | {r.ops['optimised']} / {r.ops['expanded']} | "
                       f"{' / '.join(map(str, r.paper))} |")
        out.append("")
    for eq in equations:
        out += [f"## {eq.source}", "",
                f"Degree {eq.degree}, {len(eq.parameters)} parameters, Maxima {eq.maxima_seconds:.2f} s "
                f"(all role combinations in one session).", ""]
        for strategy in STRATEGIES:
            rows = eq.variants[strategy]
            out += [f"### {strategy}: {len(rows)} variants", "",
                    "| # | variant | zero parameters | degree | add | mul | div | total |",
                    "|---|---|---|---|---|---|---|---|"]
            for v in rows:
                out.append(f"| {v.index} | {v.label} | {', '.join(v.zeros) or '-'} | {v.degree} | "
                           f"{v.add} | {v.mul} | {v.div} | {v.add + v.mul + v.div} |")
            out.append("")
        langs = sorted(next(iter(eq.lines.values())))
        out += ["Lines of generated code (module, with variants):", "",
                "| strategy | " + " | ".join(langs) + " |", "|---" * (len(langs) + 1) + "|"]
        for strategy, per_lang in eq.lines.items():
            out.append(f"| {strategy} | " + " | ".join(str(per_lang[l]) for l in langs) + " |")
        out.append("")
    return "\n".join(out)


def html(equations: list[EquationReport], md: str) -> str:
    """One page: an SVG chart of operations per variant and strategy, then the tables."""
    charts = []
    for eq in equations:
        rows = {s: {v.label: v.add + v.mul + v.div for v in eq.variants[s]} for s in STRATEGIES}
        labels = sorted(set(rows["optimised"]) | set(rows["expanded"]),
                        key=lambda l: -max(rows["expanded"].get(l, 0), rows["optimised"].get(l, 0)))
        top = max(max(r.values()) for r in rows.values())
        height = 22 * len(labels) + 30
        bars = []
        for i, label in enumerate(labels):
            y = 20 + 22 * i
            for j, (strategy, colour) in enumerate((("expanded", "#c0504d"), ("optimised", "#4f81bd"))):
                value = rows[strategy].get(label)
                if value is None:
                    continue
                width = 420 * value / top
                bars.append(f'<rect x="330" y="{y + 9 * j}" width="{width:.1f}" height="8" fill="{colour}"/>'
                            f'<text x="{335 + width:.1f}" y="{y + 8 + 9 * j}" font-size="9">{value}</text>')
            bars.append(f'<text x="325" y="{y + 13}" font-size="11" text-anchor="end">{escape(label)}</text>')
        charts.append(f"<h2>{escape(eq.source)}: operations per variant</h2>"
                      f'<svg width="820" height="{height}" xmlns="http://www.w3.org/2000/svg">'
                      f'<text x="330" y="12" font-size="11"><tspan fill="#c0504d">expanded</tspan> / '
                      f'<tspan fill="#4f81bd">optimised</tspan> (add + mul + div)</text>'
                      + "".join(bars) + "</svg>")
    return ("<!doctype html><meta charset=utf-8><title>max2code variant report</title>"
            "<style>body{font-family:sans-serif;max-width:60em;margin:auto}"
            "pre{white-space:pre-wrap}</style>" + "".join(charts) +
            "<h2>Tables</h2><pre>" + escape(md) + "</pre>")


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(prog="max2code report", description=__doc__.splitlines()[0])
    ap.add_argument("inputs", nargs="*", metavar="FILE.mxm",
                    help="equations (default: the shipped equations/*.mxm)")
    ap.add_argument("-o", "--out", default="build/report", help="folder (default build/report)")
    ap.add_argument("--timeout", type=float, default=maxima.DEFAULT_TIMEOUT)
    ap.add_argument("--no-figure6", action="store_true", help="skip the paper's figure 6 table")
    opts = ap.parse_args(argv)
    inputs = opts.inputs or shipped_equations()
    try:
        equations = [equation_report(p, opts.timeout) for p in inputs]
        fig6 = [] if opts.no_figure6 else [figure6_row(label, path, paper, opts.timeout)
                                           for label, path, paper in FIGURE_6_ROWS]
    except Max2CodeError as exc:
        for diag in exc.diagnostics:
            print(diag, file=sys.stderr)
        return 1
    out = Path(opts.out)
    out.mkdir(parents=True, exist_ok=True)
    md = markdown(equations, fig6)
    write_if_changed(str(out / "report.md"), md)
    write_if_changed(str(out / "report.json"), json.dumps(
        {"equations": [asdict(e) for e in equations], "figure6": [asdict(r) for r in fig6]},
        indent=1, sort_keys=True) + "\n")
    write_if_changed(str(out / "report.html"), html(equations, md))
    print(md)
    return 0
