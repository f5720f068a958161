"""`max2code build`: the main job. Every equation, every language, and a summary.

The equations are the files named, else the .mxm files of the current folder (never the
shipped ones: `make` names those).

Each equation is expanded by Maxima once and rendered for every registered language as a
module into OUT/<lang>/; a Markdown summary (degree, parameters, Maxima time, lines per
language) is written to OUT/summary.md and printed.

`--jobs N` runs up to N equations at once (Maxima is a subprocess, so threads suffice); output
files, diagnostics and the summary come out in input order whatever finishes first. An equation
whose .mxm, loaded files, Maxima and max2code are unchanged since a successful build is served
from the results cache (cache.py) without parsing or rendering: the heavy modules (Lark, Jinja)
are imported only when something has to be generated.
"""

from __future__ import annotations

import argparse
import os
import re
import sys
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

from .. import cache
from ..maxima import depfile, session as maxima
from ..mdtext import inline
from ..diagnostics import Max2CodeError, Pos
from .options import add_maxima_options, add_quiet_option, apply_maxima_options
from ..output import write_if_changed
from ..paths import inputs_or_folder, no_inputs


@dataclass(frozen=True)
class Row:
    source: str
    name: str
    degree: int
    nparams: int
    seconds: float
    lines: tuple[tuple[str, int], ...]


@dataclass(frozen=True)
class Outcome:
    """One equation's result: its row (None on failure), what to print, what was written."""

    row: Row | None
    messages: tuple[str, ...]
    outputs: tuple[tuple[str, str], ...] = ()
    notes: tuple[str, ...] = ()  # advice, printed unless -q


def build_one(path: str, out: Path, langs: list[str] | None, timeout: float) -> Outcome:
    from ..codegen.emit import module_name
    from ..codegen.generate import generate, load
    from ..languages import LANGUAGES

    langs = langs or sorted(LANGUAGES)
    spec, poly = load(path, timeout)
    name = module_name(spec)
    lines = []
    messages: list[str] = []
    notes: list[str] = []
    outputs: list[tuple[str, str]] = []
    for lang_name in langs:
        lang = LANGUAGES[lang_name]
        folder = out / lang_name
        target = folder / f"{name}{lang.extension}"
        result = generate(spec, poly, lang, "module", str(target))
        for w in result.warnings:
            kept = notes if w.severity == "note" else messages
            if str(w) not in kept:
                kept.append(str(w))
        outputs += [*result.companions, (str(target), result.text)]
        lines.append((lang_name, result.text.count("\n") + sum(t.count("\n") for _, t in result.companions)))
    row = Row(path, name, poly.degree, len(poly.parameters), poly.maxima_seconds, tuple(lines))
    return Outcome(row, tuple(messages), tuple(outputs), tuple(notes))


def _result_key(path: str, out: Path, langs: list[str] | None) -> str | None:
    """The results-cache key of one equation, or None when it cannot be cached (no Maxima,
    unreadable file): then the full path runs and reports the problem."""
    if not cache.enabled():
        return None
    try:
        exe = maxima.maxima_executable()
    except Max2CodeError:
        return None
    loads = depfile.loaded_files_of_source(path)
    if loads is None:
        return None
    return cache.result_key("build", path, str(out), ",".join(langs or ["*"]),
                            cache.executable_identity(exe), f"unsafe={maxima.policy().allow_unsafe}",
                            inputs=(path, *loads))


def _cached(key: str | None, out: Path) -> Outcome | None:
    """A stored outcome, its outputs placed in `out`; None unless every output is a plain
    `LANG/FILE` name inside it (an entry never chooses where `build` writes)."""
    obj = cache.get_json(key, "results") if key else None
    if obj is None:
        return None
    try:
        r = obj["row"]
        row = Row(r["source"], r["name"], int(r["degree"]), int(r["nparams"]), float(r["seconds"]),
                  tuple((str(a), int(b)) for a, b in r["lines"]))
        outputs = []
        for rel, text in obj["outputs"]:
            parts = str(rel).split("/")
            if len(parts) != 2 or any(p in ("", ".", "..") or "\\" in p for p in parts):
                return None
            outputs.append((str(out / parts[0] / parts[1]), str(text)))
        return Outcome(row, tuple(str(m) for m in obj["messages"]), tuple(outputs),
                       tuple(str(m) for m in obj["notes"]))
    except (KeyError, TypeError, ValueError):
        return None


def _store(key: str | None, outcome: Outcome, out: Path) -> None:
    if key is None or outcome.row is None:
        return
    r = outcome.row
    relative = []
    for target, text in outcome.outputs:
        rel = Path(target).relative_to(out)
        relative.append([f"{rel.parent.name}/{rel.name}", text])
    cache.put_json(key, {"row": {"source": r.source, "name": r.name, "degree": r.degree,
                                 "nparams": r.nparams, "seconds": r.seconds,
                                 "lines": [list(x) for x in r.lines]},
                         "messages": list(outcome.messages), "notes": list(outcome.notes),
                         "outputs": relative}, "results")


def _run(path: str, out: Path, langs: list[str] | None, timeout: float) -> Outcome:
    key = _result_key(path, out, langs)
    hit = _cached(key, out)
    if hit is not None:
        return hit
    try:
        outcome = build_one(path, out, langs, timeout)
    except Max2CodeError as exc:
        return Outcome(None, tuple(str(d) for d in exc.diagnostics))
    _store(key, outcome, out)
    return outcome


def _clashes(inputs: list[str], outcomes: list[Outcome]) -> dict[str, str]:
    """Equations that would write the same output (the same `function`, or the same file stem):
    neither is written, and the later one gets a diagnostic naming both. Maps each such input
    to its diagnostic ('' for the first of a pair, which is reported with the second)."""
    owner: dict[str, tuple[str, str]] = {}
    clashes: dict[str, str] = {}
    for path, outcome in zip(inputs, outcomes):
        if outcome.row is None:
            continue
        for target, _ in outcome.outputs:
            first = owner.setdefault(target, (path, outcome.row.name))
            if first[0] != path and path not in clashes:
                name = outcome.row.name
                clashes.setdefault(first[0], "")
                clashes[path] = (f"{_declaration(path, name)}: error: function '{name}' is also "
                                 f"generated from {_declaration(first[0], name)}: both would write "
                                 f"{target}; give one of them another 'function' name")
    return clashes


def _declaration(path: str, name: str) -> Pos:
    """Where `function NAME` is declared in `path` (its first line when the name comes from
    the file's name)."""
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            for number, line in enumerate(f, start=1):
                m = re.match(rf"(\s*)function\s+{re.escape(name)}\b", line, re.I)
                if m:
                    return Pos(path, number, len(m.group(1)) + 1)
    except OSError:
        pass
    return Pos(path, 1, 1)


def summary(rows: list[Row], failed: list[str], langs: list[str]) -> str:
    head = "| equation | function | degree | parameters | Maxima s | " + " | ".join(
        f"{lang} lines" for lang in langs) + " |"
    rule = "|" + "---|" * (5 + len(langs))
    body = [f"| {inline(r.source)} | {inline(r.name)} | {r.degree} | {r.nparams} | "
            f"{r.seconds:.2f} | " + " | ".join(str(n) for _, n in r.lines) + " |" for r in rows]
    text = "# max2code build summary\n\n" + "\n".join([head, rule, *body]) + "\n"
    if failed:
        text += "\nFailed:\n\n" + "\n".join(f"- {inline(f)}" for f in failed) + "\n"
    return text


def _languages() -> list[str]:
    from ..languages import LANGUAGES
    return sorted(LANGUAGES)


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(prog="max2code build", description=__doc__.splitlines()[0])
    ap.add_argument("inputs", nargs="*", metavar="FILE.mxm",
                    help="equations (default: the .mxm files of the current folder)")
    ap.add_argument("-o", "--out", default="build", help="output folder (default: build)")
    ap.add_argument("--lang", action="append", metavar="LANG",
                    help="only this language (repeatable; default: all registered ones)")
    ap.add_argument("-j", "--jobs", type=int, default=1, metavar="N",
                    help="run up to N equations at once (default 1; 0: one per CPU)")
    add_maxima_options(ap)
    add_quiet_option(ap)
    opts = ap.parse_args(argv)
    apply_maxima_options(opts)
    if opts.jobs < 0:
        ap.error("--jobs must be 0 or more")
    jobs = opts.jobs or os.cpu_count() or 1
    inputs = inputs_or_folder(opts.inputs)
    if not inputs:
        ap.error(no_inputs("build"))
    langs: list[str] | None = None  # None: every registered language (looked up only if needed)
    if opts.lang:
        known = _languages()
        for lang in opts.lang:
            if lang not in known:
                ap.error(f"argument --lang: invalid choice: {lang!r} (choose from {', '.join(known)})")
        langs = sorted(set(opts.lang), key=opts.lang.index)
    out = Path(opts.out)

    def task(path: str) -> Outcome:
        return _run(path, out, langs, opts.timeout)

    if jobs > 1 and len(inputs) > 1:
        with ThreadPoolExecutor(max_workers=jobs) as pool:
            outcomes = list(pool.map(task, inputs))
    else:
        outcomes = [task(p) for p in inputs]
    rows, failed = [], []
    clashes = _clashes(inputs, outcomes)
    for path, outcome in zip(inputs, outcomes):
        for message in (*outcome.messages, *(() if opts.quiet else outcome.notes)):
            print(message, file=sys.stderr)
        if path in clashes:
            if clashes[path]:
                print(clashes[path], file=sys.stderr)
            failed.append(path)
            continue
        if outcome.row is None:
            failed.append(path)
            continue
        try:
            for target, text in outcome.outputs:
                Path(target).parent.mkdir(parents=True, exist_ok=True)
                write_if_changed(target, text)
        except (Max2CodeError, OSError) as exc:
            print(exc if isinstance(exc, Max2CodeError) else f"{out}:1:1: error: {exc}",
                  file=sys.stderr)
            failed.append(path)
            continue
        rows.append(outcome.row)
    if langs is None:
        langs = [name for name, _ in rows[0].lines] if rows else _languages()
    text = summary(rows, failed, langs)
    out.mkdir(parents=True, exist_ok=True)
    write_if_changed(str(out / "summary.md"), text)
    print(text, end="")
    return 1 if failed else 0
