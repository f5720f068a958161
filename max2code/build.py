"""`max2code build`: the main job. Every shipped equation, every language, and a summary.

Each equation is expanded by Maxima once and rendered for every registered language as a
module into OUT/<lang>/; a Markdown summary (degree, parameters, Maxima time, lines per
language) is written to OUT/summary.md and printed.
"""

from __future__ import annotations

import argparse
import os
import sys
from dataclasses import dataclass
from pathlib import Path

from . import maxima
from .diagnostics import Max2CodeError
from .emit import module_name
from .generate import generate, load
from .languages import LANGUAGES
from .output import write_if_changed
from .paths import ROOT


@dataclass(frozen=True)
class Row:
    source: str
    name: str
    degree: int
    nparams: int
    seconds: float
    lines: tuple[tuple[str, int], ...]


def build_one(path: str, out: Path, langs: list[str], timeout: float) -> Row:
    spec, poly = load(path, timeout)
    name = module_name(spec)
    lines = []
    for lang_name in langs:
        lang = LANGUAGES[lang_name]
        folder = out / lang_name
        folder.mkdir(parents=True, exist_ok=True)
        target = folder / f"{name}{lang.extension}"
        result = generate(spec, poly, lang, "module", str(target))
        for warning in result.warnings:
            print(warning, file=sys.stderr)
        for companion, text in result.companions:
            write_if_changed(companion, text)
        write_if_changed(str(target), result.text)
        lines.append((lang_name, result.text.count("\n") + sum(t.count("\n") for _, t in result.companions)))
    return Row(path, name, poly.degree, len(poly.parameters), poly.maxima_seconds, tuple(lines))


def _display(path: Path) -> str:
    """A path as short as it can be: relative to the working folder when it lies below it."""
    rel = os.path.relpath(path)
    return str(path) if rel.startswith("..") else rel


def summary(rows: list[Row], failed: list[str], langs: list[str]) -> str:
    head = "| equation | function | degree | parameters | Maxima s | " + " | ".join(
        f"{lang} lines" for lang in langs) + " |"
    rule = "|" + "---|" * (5 + len(langs))
    body = [f"| {r.source} | {r.name} | {r.degree} | {r.nparams} | {r.seconds:.2f} | "
            + " | ".join(str(n) for _, n in r.lines) + " |" for r in rows]
    text = "# max2code build summary\n\n" + "\n".join([head, rule, *body]) + "\n"
    if failed:
        text += "\nFailed:\n\n" + "\n".join(f"- {f}" for f in failed) + "\n"
    return text


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(prog="max2code build", description=__doc__.splitlines()[0])
    ap.add_argument("inputs", nargs="*", metavar="FILE.mxm",
                    help="equations (default: the shipped equations/*.mxm)")
    ap.add_argument("-o", "--out", default="build", help="output folder (default: build)")
    ap.add_argument("--lang", action="append", choices=sorted(LANGUAGES),
                    help="only these languages (repeatable; default: all)")
    ap.add_argument("--timeout", type=float, default=maxima.DEFAULT_TIMEOUT)
    opts = ap.parse_args(argv)
    inputs = opts.inputs or sorted(_display(p) for p in (ROOT / "equations").glob("*.mxm"))
    langs = opts.lang or sorted(LANGUAGES)
    out = Path(opts.out)
    rows, failed = [], []
    for path in inputs:
        try:
            rows.append(build_one(path, out, langs, opts.timeout))
        except Max2CodeError as exc:
            for diag in exc.diagnostics:
                print(diag, file=sys.stderr)
            failed.append(path)
    text = summary(rows, failed, langs)
    out.mkdir(parents=True, exist_ok=True)
    write_if_changed(str(out / "summary.md"), text)
    print(text, end="")
    return 1 if failed else 0
