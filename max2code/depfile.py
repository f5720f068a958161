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
from typing import TYPE_CHECKING

from .diagnostics import Pos, error, visible

if TYPE_CHECKING:
    from .spec import Statement

LOAD_CALL = re.compile(r"\b(?:load|batchload|batch)\s*\(\s*\"((?:[^\"\\]|\\.)*)\"")
ANY_LOAD = re.compile(r"\b(?:load|batchload|batch)\s*\(")
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
    name = name.replace('\\"', '"').replace("\\\\", "\\")
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


# A load whose file is named in the text: a string, or a symbol (a package of Maxima's library,
# unless the program assigns the symbol a value).
LITERAL_LOAD = re.compile(r'\b(?:load|batchload|batch)\s*\(\s*(?:"(?:[^"\\]|\\.)*"|([A-Za-z_%][\w%]*))\s*[,)]')


def all_loads_literal(statements: tuple[Statement, ...]) -> bool:
    """Whether every load of the program, and of the files it loads, names its file literally.
    Otherwise the files it reads are unknown, and no cache entry can be keyed to them."""
    texts = [s.text for s in statements]
    for path in loaded_files(statements):
        if os.path.splitext(path)[1].lower() in _TEXT_EXTENSIONS:
            try:
                with open(path, encoding="utf-8", errors="replace") as f:
                    texts.append(f.read())
            except OSError:
                return False
    everything = "\n".join(texts)
    for text in texts:
        literal = list(LITERAL_LOAD.finditer(text))
        if len(literal) != len(ANY_LOAD.findall(text)):
            return False
        for m in literal:
            if m.group(1) and re.search(rf"(?<![\w%]){re.escape(m.group(1))}\s*::?(?!=)", everything):
                return False
    return True


def loaded_files_of_source(path: str) -> tuple[str, ...] | None:
    """The same from the raw .mxm text, without parsing it: a superset (loads in comments count
    too), which is what a cache key needs. None if the file cannot be read."""
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            text = f.read()
    except OSError:
        return None
    return _scan([(text, os.path.dirname(path))])


def _scan(texts: list[tuple[str, str]]) -> tuple[str, ...]:
    found: list[str] = []
    seen: set[str] = set()
    while texts and len(found) < _MAX_FILES:
        text, where = texts.pop(0)
        for m in LOAD_CALL.finditer(text):
            path = _resolve(m.group(1), where or ".")
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
