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

from ..diagnostics import Max2CodeError
from ..codegen.generate import generate, load
from ..languages import LANGUAGES
from ..mdtext import inline
from ..output import write_if_changed
from ..paths import ROOT, display, inputs_or_folder, no_inputs
from ..codegen.variants import STRATEGIES, family

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


CHART_FONT = 13          # px, every text of the chart
CHART_CHAR = 7.4         # px a character at 13 px (sans-serif, generous): the label column's room
STRATEGY_COLOURS = (("expanded", "#c0504d"), ("optimised", "#4f81bd"))
HATCH = ('<defs><pattern id="nov" width="6" height="6" patternUnits="userSpaceOnUse" '
         'patternTransform="rotate(45)"><path d="M0 0V6" stroke="#888" stroke-width="2"/>'
         '</pattern></defs>')


def chart(eq: EquationReport, made: str | None = None) -> str:
    """An SVG bar chart of the operations of each variant under both strategies: largest first,
    ties by label (a set's order differs from run to run, and an unchanged report must be the
    same bytes). Each row says the variant's degree; a strategy without that variant gets a
    hatched 'no variant' mark, never an empty place that reads as zero operations. Title, then
    the machine and date (`made`, default machine.machine_and_date()); every text 13 px, the
    label column as wide as the longest label needs (long role names were cut off)."""
    from ..machine import machine_and_date
    made = machine_and_date() if made is None else made
    rows = {s: {v.label: v for v in eq.variants[s]} for s in STRATEGIES}

    def cost(v: VariantRow | None) -> int:
        return 0 if v is None else v.add + v.mul + v.div

    labels = sorted(set(rows["optimised"]) | set(rows["expanded"]),
                    key=lambda l: (-max(cost(rows[s].get(l)) for s in STRATEGIES), l))
    top = max(cost(v) for r in rows.values() for v in r.values()) if labels else 1
    top = top or 1
    degrees = {l: sorted({rows[s][l].degree for s in STRATEGIES if l in rows[s]}) for l in labels}
    x0 = max(330, math.ceil(CHART_CHAR * max((len(l) for l in labels), default=0)) + 15)
    xd = x0 + 8                       # the degree column
    xb = xd + 80                      # the bars
    span = 420
    width_all = xb + span + 60
    head = 3 * (CHART_FONT + 7) + 10
    row_h = 2 * (CHART_FONT + 3) + 10
    height = head + row_h * len(labels) + 8
    out = []
    for i, label in enumerate(labels):
        y = head + row_h * i
        out.append(f'<text x="{x0 - 5}" y="{y + CHART_FONT + 8}" font-size="{CHART_FONT}" '
                   f'text-anchor="end">{escape(label)}</text>')
        out.append(f'<text class="degree" x="{xd}" y="{y + CHART_FONT + 8}" '
                   f'font-size="{CHART_FONT}">degree {"/".join(map(str, degrees[label]))}</text>')
        for j, (strategy, colour) in enumerate(STRATEGY_COLOURS):
            v = rows[strategy].get(label)
            yb = y + j * (CHART_FONT + 3)
            if v is None:
                out.append(f'<rect class="missing" x="{xb}" y="{yb}" width="90" '
                           f'height="{CHART_FONT + 1}" fill="url(#nov)" stroke="{colour}">'
                           f'<title>{escape(label)}: no {strategy} variant</title></rect>'
                           f'<text x="{xb + 96}" y="{yb + CHART_FONT - 1}" font-size="{CHART_FONT}" '
                           f'fill="#555">no {strategy} variant</text>')
                continue
            value = cost(v)
            width = span * value / top
            out.append(f'<rect class="{strategy}" x="{xb}" y="{yb}" width="{width:.1f}" '
                       f'height="{CHART_FONT + 1}" fill="{colour}"><title>{escape(label)}, '
                       f'{strategy}: {value} operations, degree {v.degree}</title></rect>'
                       f'<text x="{xb + 5 + width:.1f}" y="{yb + CHART_FONT - 1}" '
                       f'font-size="{CHART_FONT}">{value}</text>')
    legend = " ".join(f'<tspan fill="{c}">&#9632; {s}</tspan>' for s, c in STRATEGY_COLOURS)
    title = f"Operations per variant (add + mul + div): {eq.source}"
    return (f'<figure><svg role="img" width="{width_all}" height="{height}" '
            f'viewBox="0 0 {width_all} {height}" font-family="sans-serif" '
            f'xmlns="http://www.w3.org/2000/svg"><title>{escape(title)}</title>{HATCH}'
            f'<text class="title" x="8" y="{CHART_FONT + 4}" font-size="{CHART_FONT + 2}" '
            f'font-weight="bold">{escape(title)}</text>'
            f'<text class="made" x="8" y="{2 * (CHART_FONT + 7)}" font-size="{CHART_FONT}" '
            f'fill="#555">{escape(made)}</text>'
            f'<text x="{xb}" y="{3 * (CHART_FONT + 7)}" font-size="{CHART_FONT}">{legend} '
            f'<tspan fill="#555">(hatched: the strategy has no such variant)</tspan></text>'
            + "".join(out) + "</svg><figcaption>Operations per variant (add + mul + div), "
            "expanded and optimised, with each variant's degree; a hatched mark where a "
            "strategy has no such variant.</figcaption></figure>")


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
