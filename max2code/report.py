"""`max2code report`: what variant generation produced, in Markdown, JSON and HTML.

For each equation: its variants under both strategies (conditions, degree, operation counts),
lines of generated code per language, Maxima's time; and, when a shipped equation is among the
inputs or on request, the paper's figure 6 table (lines of .mxm, of Maxima output, of generated
Modula-2) reproduced for this tool beside the paper's. The HTML page has the same tables as
HTML tables and a chart per equation, and no script.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from dataclasses import asdict, dataclass
from html import escape
from pathlib import Path

from .diagnostics import Max2CodeError
from .generate import generate, load
from .languages import LANGUAGES
from .mdtext import inline
from .output import write_if_changed
from .paths import ROOT, display, inputs_or_folder, no_inputs
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


@dataclass(frozen=True)
class Table:
    headers: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]


@dataclass(frozen=True)
class Section:
    """A heading (level 2 or 3), paragraphs, a table, and for an equation its chart."""

    level: int
    title: str
    paragraphs: tuple[str, ...] = ()
    table: Table | None = None
    chart: EquationReport | None = None


FIGURE_6_TEXT = (
    "Lines of .mxm input, of Maxima output (at Maxima's 79 columns: the equation as the program "
    "leaves it for `optimised`, the expanded polynomial for `expanded`) and of the generated "
    "Modula-2 module for the general polynomial (`.def` + `.mod`, without variants, as the paper "
    "had). Lines flatter the expanded form, whose coefficients are one long line each (gm2 "
    "numbers continuation lines, so Modula-2 expressions are never wrapped) while the optimised "
    "form is one shared subexpression per line: the operation count says what each costs.")


def sections(equations: list[EquationReport], fig6: list[Figure6Row]) -> list[Section]:
    """The report's content, once, for the Markdown and the HTML pages alike."""
    out = []
    if fig6:
        out.append(Section(2, "The paper's figure 6, reproduced", (FIGURE_6_TEXT,), Table(
            ("expression", ".mxm", "Maxima (optimised / expanded)",
             "Modula-2 (optimised / expanded)", "operations (optimised / expanded)",
             "paper: max2code / maxima / Modula-2"),
            tuple((r.label, str(r.mxm_lines),
                   f"{r.maxima_lines['optimised']} / {r.maxima_lines['expanded']}",
                   f"{r.m2_lines['optimised']} / {r.m2_lines['expanded']}",
                   f"{r.ops['optimised']} / {r.ops['expanded']}",
                   " / ".join(map(str, r.paper))) for r in fig6))))
    for eq in equations:
        out.append(Section(2, eq.source, (
            f"Degree {eq.degree}, {len(eq.parameters)} parameters, Maxima "
            f"{eq.maxima_seconds:.2f} s (all role combinations in one session).",),
            chart=eq))
        for strategy in STRATEGIES:
            rows = eq.variants[strategy]
            out.append(Section(3, f"{strategy}: {len(rows)} variants", (), Table(
                ("#", "variant", "zero parameters", "degree", "add", "mul", "div", "total"),
                tuple((str(v.index), v.label, ", ".join(v.zeros) or "-", str(v.degree),
                       str(v.add), str(v.mul), str(v.div), str(v.add + v.mul + v.div))
                      for v in rows))))
        langs = sorted(next(iter(eq.lines.values())))
        out.append(Section(3, "Lines of generated code", (
            "Module form, with variants, per strategy and language.",), Table(
            ("strategy", *langs),
            tuple((strategy, *(str(per_lang[lang]) for lang in langs))
                  for strategy, per_lang in eq.lines.items()))))
    return out


def markdown(equations: list[EquationReport], fig6: list[Figure6Row]) -> str:
    out = ["# max2code variant report", ""]
    for sec in sections(equations, fig6):
        out += ["#" * sec.level + " " + inline(sec.title), ""]
        for paragraph in sec.paragraphs:
            out += [paragraph, ""]
        if sec.table:
            out.append("| " + " | ".join(inline(h) for h in sec.table.headers) + " |")
            out.append("|" + "---|" * len(sec.table.headers))
            out += ["| " + " | ".join(inline(c) for c in row) + " |" for row in sec.table.rows]
            out.append("")
    return "\n".join(out)


def chart(eq: EquationReport) -> str:
    """An SVG bar chart of the operations of each variant under both strategies: largest first,
    ties by label (a set's order differs from run to run, and an unchanged report must be the
    same bytes); the label column as wide as the longest label needs (about 6.2 px a character
    at 11 px: long role names were cut off at the left edge)."""
    rows = {s: {v.label: v.add + v.mul + v.div for v in eq.variants[s]} for s in STRATEGIES}
    labels = sorted(set(rows["optimised"]) | set(rows["expanded"]),
                    key=lambda l: (-max(rows["expanded"].get(l, 0), rows["optimised"].get(l, 0)), l))
    top = max(max(r.values()) for r in rows.values()) or 1
    x0 = max(330, math.ceil(6.2 * max(len(l) for l in labels)) + 15)
    width_all = x0 + 490
    height = 22 * len(labels) + 30
    bars = []
    for i, label in enumerate(labels):
        y = 20 + 22 * i
        for j, (strategy, colour) in enumerate((("expanded", "#c0504d"), ("optimised", "#4f81bd"))):
            value = rows[strategy].get(label)
            if value is None:
                continue
            width = 420 * value / top
            bars.append(f'<rect class="{strategy}" x="{x0}" y="{y + 9 * j}" width="{width:.1f}" '
                        f'height="8" fill="{colour}"><title>{escape(label)}, {strategy}: {value} '
                        f'operations</title></rect>'
                        f'<text x="{x0 + 5 + width:.1f}" y="{y + 8 + 9 * j}" font-size="9">{value}</text>')
        bars.append(f'<text x="{x0 - 5}" y="{y + 13}" font-size="11" text-anchor="end">'
                    f'{escape(label)}</text>')
    return (f'<figure><svg role="img" width="{width_all}" height="{height}" '
            f'viewBox="0 0 {width_all} {height}" '
            f'xmlns="http://www.w3.org/2000/svg"><title>Operations per variant of '
            f'{escape(eq.source)}</title>'
            f'<text x="{x0}" y="12" font-size="11"><tspan fill="#c0504d">expanded</tspan> / '
            f'<tspan fill="#4f81bd">optimised</tspan> (add + mul + div)</text>'
            + "".join(bars) + "</svg><figcaption>Operations per variant (add + mul + div), "
            "expanded and optimised.</figcaption></figure>")


def _inline(text: str) -> str:
    """Markdown's `code` spans as <code>, the rest escaped."""
    parts = escape(text).split("`")
    return "".join(f"<code>{p}</code>" if i % 2 else p for i, p in enumerate(parts))


def html(equations: list[EquationReport], fig6: list[Figure6Row]) -> str:
    """One self-contained page (no script): a heading, and per section its paragraphs, an HTML
    table and, for an equation, the SVG chart of its variants' operations."""
    body = ["<h1>max2code variant report</h1>"]
    for sec in sections(equations, fig6):
        body.append(f"<h{sec.level}>{escape(sec.title)}</h{sec.level}>")
        body += [f"<p>{_inline(p)}</p>" for p in sec.paragraphs]
        if sec.chart is not None:
            body.append(chart(sec.chart))
        if sec.table:
            head = "".join(f"<th scope=\"col\">{escape(h)}</th>" for h in sec.table.headers)
            rows = "".join("<tr>" + "".join(f"<td>{escape(c)}</td>" for c in row) + "</tr>"
                           for row in sec.table.rows)
            body.append(f"<table><thead><tr>{head}</tr></thead><tbody>{rows}</tbody></table>")
    style = ("body{font-family:sans-serif;max-width:62em;margin:1em auto;padding:0 1em}"
             "table{border-collapse:collapse;margin:0.5em 0 1.5em}"
             "th,td{border:1px solid #bbb;padding:0.2em 0.5em;text-align:left}"
             "th{background:#eee}td:not(:nth-child(2)){font-variant-numeric:tabular-nums}"
             "figure{margin:0}figcaption{font-size:0.85em;color:#555}")
    return ("<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
            "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
            "<title>max2code variant report</title>\n"
            f"<style>{style}</style>\n</head>\n<body>\n" + "\n".join(body)
            + "\n</body>\n</html>\n")


def wants_figure6(inputs: list[str], flag: bool | None) -> bool:
    """Figure 6 compares the shipped equations with the paper: shown when an input is one of
    them, or on request (--figure6); --no-figure6 leaves it out."""
    if flag is not None:
        return flag
    shipped = (ROOT / "equations").resolve()
    return any(shipped in Path(p).resolve().parents for p in inputs)


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(prog="max2code report", description=__doc__.splitlines()[0])
    ap.add_argument("inputs", nargs="*", metavar="FILE.mxm",
                    help="equations (default: the .mxm files of the current folder)")
    ap.add_argument("-o", "--out", default="build/report", help="folder (default build/report)")
    ap.add_argument("--figure6", action=argparse.BooleanOptionalAction, default=None,
                    help="the paper's figure 6 table (default: when a shipped equation is among "
                         "the inputs)")
    from .options import add_maxima_options, apply_maxima_options
    add_maxima_options(ap)
    opts = ap.parse_args(argv)
    apply_maxima_options(opts)
    inputs = inputs_or_folder(opts.inputs)
    if not inputs:
        ap.error(no_inputs("report"))
    try:
        equations = [equation_report(p, opts.timeout) for p in inputs]
        fig6 = [figure6_row(label, path, paper, opts.timeout)
                for label, path, paper in FIGURE_6_ROWS] if wants_figure6(inputs, opts.figure6) else []
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
    write_if_changed(str(out / "report.html"), html(equations, fig6))
    print(md)
    return 0
