"""Dependency files for Make and Ninja, and the files a Maxima program loads.

A generated file depends on its .mxm and on whatever the .mxm's Maxima program loads with a
literal file name: `load("x.mac")`, `batchload("x.mac")`, `batch("x.mac")`, found (as Maxima
will find them, see maxima.program_script) relative to the .mxm's folder, with Maxima's usual
extensions tried when the name has none. Loaded Maxima files are scanned for their own loads.
Package loads by symbol (`load(format)`) name Maxima's own library and are not dependencies.

The depfile has the gcc form, `target [target2]: dep dep ...`, with Make's escapes (which Ninja
reads too). A Modula-2 module has two outputs (NAME.mod and NAME.def); Make takes both as
targets of one rule, and so does Ninja from version 1.10 on when both are outputs of the edge.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass
from typing import TYPE_CHECKING

from ..diagnostics import Pos, error, visible

if TYPE_CHECKING:
    from ..front.spec import Statement

ANY_LOAD = re.compile(r"\b(?:load|batchload|batch)\s*\(")
_SYMBOL_ARG = re.compile(r"\s*([A-Za-z_%][\w%]*)\s*[,)]")
_STRING_ARG = re.compile(r'\s*"')
_ARG_END = re.compile(r"\s*[,)]")


@dataclass(frozen=True)
class LoadCall:
    """One `load(...)`, `batchload(...)` or `batch(...)` in Maxima text: its argument is a
    string (`name`, unescaped), a symbol (`symbol`), or computed (both None)."""

    start: int  # of the function's name
    end: int  # of what was read of the call
    name: str | None
    symbol: str | None


def load_calls(text: str) -> list[LoadCall]:
    """Every load call of `text`."""
    return [call for m in ANY_LOAD.finditer(text) if (call := load_call_at(text, m.start()))]


def load_call_at(text: str, start: int) -> LoadCall | None:
    """The load call whose name starts at `start`, or None if there is none. Its string is
    read with maxima_text.string_end: a regular expression over a long string of escapes would
    cost memory per character."""
    from .text import string_end

    m = ANY_LOAD.match(text, start)
    if m is None:
        return None
    s = _STRING_ARG.match(text, m.end())
    if s is not None:
        close = string_end(text, s.end() - 1)
        after = _ARG_END.match(text, close) if close > 0 else None
        if after is not None:
            return LoadCall(start, after.end(), _unescape(text[s.end():close - 1]), None)
    sym = _SYMBOL_ARG.match(text, m.end())
    if sym is not None:
        return LoadCall(start, sym.end(), None, sym.group(1))
    return LoadCall(start, m.end(), None, None)


def _unescape(raw: str) -> str:
    """A Maxima string's text: a backslash escapes the character after it."""
    return re.sub(r"\\(.)", r"\1", raw, flags=re.S)
MAXIMA_EXTENSIONS = (".mac", ".mc", ".wxm")
LISP_EXTENSIONS = (".lisp", ".lsp")
_TEXT_EXTENSIONS = MAXIMA_EXTENSIONS + ("",)
_MAX_FILES = 1000


def source_folder(statements: tuple[Statement, ...]) -> str | None:
    """The folder of the .mxm the statements come from (absolute), or None."""
    if not statements:
        return None
    return os.path.dirname(os.path.abspath(statements[0].pos.file))


def _resolve(name: str, folder: str) -> str | None:
    base = name if os.path.isabs(name) else os.path.join(folder, name)
    candidates = [base]
    if not os.path.splitext(name)[1]:
        candidates += [base + ext for ext in MAXIMA_EXTENSIONS + LISP_EXTENSIONS]
    for candidate in candidates:
        if os.path.isfile(candidate):
            return candidate
    return None


def loaded_files(statements: tuple[Statement, ...]) -> tuple[str, ...]:
    """Files the program loads by literal name, transitively, in first-seen order.

    Paths are as the user would write them: joined to the .mxm's folder as given (relative
    when the .mxm path is relative). Names that resolve to nothing are left to Maxima to report.
    """
    if not statements:
        return ()
    folder = os.path.dirname(statements[0].pos.file)
    return _scan([(s.text, folder) for s in statements])


def all_loads_literal(statements: tuple[Statement, ...]) -> bool:
    """Whether every load of the program, and of the files it loads, names its file literally:
    a string, or a symbol the program never assigns (a package of Maxima's library). Otherwise
    the files it reads are unknown, and no cache entry can be keyed to them."""
    return _literal([s.text for s in statements], loaded_files(statements))


def _literal(texts: list[str], loaded: tuple[str, ...]) -> bool:
    """all_loads_literal for `texts` and the files they load (which are read here)."""
    texts = list(texts)
    for path in loaded:
        if os.path.splitext(path)[1].lower() in _TEXT_EXTENSIONS:
            try:
                with open(path, encoding="utf-8", errors="replace") as f:
                    texts.append(f.read())
            except OSError:
                return False
    everything = "\n".join(texts)
    return all(call.name is not None or (call.symbol is not None and not assigned(call.symbol, everything))
               for text in texts for call in load_calls(text))


def assigned(symbol: str, text: str) -> bool:
    """Whether Maxima text gives `symbol` a value (`symbol: ...` or `symbol :: ...`)."""
    return re.search(rf"(?<![\w%]){re.escape(symbol)}\s*::?(?!=)", text) is not None


def loaded_files_of_source(path: str) -> tuple[str, ...] | None:
    """The same from the raw .mxm text, without parsing it: a superset (loads in comments count
    too), which is what a cache key needs. None if the file cannot be read, or if a load's file
    is computed (then no key can cover what it reads)."""
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            text = f.read()
    except OSError:
        return None
    found = _scan([(text, os.path.dirname(path))])
    return found if _literal([text], found) else None


def _scan(texts: list[tuple[str, str]]) -> tuple[str, ...]:
    found: list[str] = []
    seen: set[str] = set()
    while texts and len(found) < _MAX_FILES:
        text, where = texts.pop(0)
        for call in load_calls(text):
            path = _resolve(call.name, where or ".") if call.name is not None else None
            if path is None:
                continue
            path = os.path.normpath(path)
            real = os.path.realpath(path)
            if real in seen:
                continue
            seen.add(real)
            found.append(path)
            if os.path.splitext(path)[1].lower() in _TEXT_EXTENSIONS:
                try:
                    with open(path, encoding="utf-8", errors="replace") as f:
                        # Maxima looks for a nested load where it looked for this one (its
                        # search path: the .mxm's folder), not beside the file that loads it.
                        texts.append((f.read(), where))
                except OSError:
                    pass
    return tuple(found)


# Characters Make and Ninja both read back as themselves once escaped (GNU Make 4.3 and Ninja
# 1.11, measured): a space and '#' behind a backslash, '$' doubled, ':' behind a backslash.
_ESCAPES = {" ": "\\ ", "#": "\\#", "$": "$$", ":": "\\:"}
# Characters one of them cannot take in a path at all: Ninja ends a path at them whatever the
# escaping, or Make reads them as a recipe (';'), a variable assignment ('='), an order-only
# list ('|'), a wildcard ('*?[]'), a pattern ('%': a target, and with -MP every dependency),
# or a line end.
_UNSAYABLE = set(";=|&'\"*?[]^`<>%")


def escape(path: str) -> str:
    """A path as a Make (and Ninja) depfile word; a path neither can express is a diagnostic
    (the build would otherwise depend on other files, or run what the path spells)."""
    bad = _unsayable(path)
    if bad is not None:
        raise error(Pos(path, 1, 1), f"this path cannot be written in a dependency file: {bad} "
                    f"(rename it, or do without -MD/-MF)")
    out = "".join(_ESCAPES.get(ch, ch) for ch in path)
    return "./" + out if out.startswith("~") else out  # Make would expand ~user


def _unsayable(path: str) -> str | None:
    """Why a depfile cannot hold `path`; None when it can."""
    for i, ch in enumerate(path):
        if ch in _UNSAYABLE or ord(ch) < 0x20 or ord(ch) == 0x7F:
            return f"Make and Ninja have no escape for {ch!r}"
        if 0xDC80 <= ord(ch) <= 0xDCFF:
            return f"the byte {visible(ch)} is not UTF-8"
        if ch == "\\" and (i + 1 == len(path) or path[i + 1] in _ESCAPES):
            return "Make and Ninja read a backslash before " + (
                repr(path[i + 1]) if i + 1 < len(path) else "the end") + " differently"
    if path.endswith(")") and "(" in path:
        return "Make reads a name ending in ')' as an archive member, 'lib(member)'"
    return None


def text(targets: list[str], deps: list[str], phony: bool = False) -> str:
    """A depfile: `targets: deps`, with `dep:` lines for each dependency when `phony` (gcc -MP),
    so that Make does not fail when a dependency is deleted."""
    line = " ".join(escape(t) for t in targets) + ":"
    for dep in deps:
        line += " \\\n  " + escape(dep)
    out = line + "\n"
    if phony:
        out += "".join(f"\n{escape(d)}:\n" for d in deps[1:])
    return out


def default_name(output: str) -> str:
    """`-MD` names the depfile after the output: OUTPUT.d (circles.h -> circles.h.d)."""
    return output + ".d"
