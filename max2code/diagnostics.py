"""Diagnostics in the gcc form `file:line:col: error: message`, so editors and build logs link them."""

from __future__ import annotations

import unicodedata
from dataclasses import dataclass

# Characters a reader must never receive raw: they end a line, reorder what is displayed
# (bidi controls), or stand for a byte of a file name that is not UTF-8.
_HIDDEN = frozenset({"Cc", "Cf", "Cs", "Co", "Cn", "Zl", "Zp"})
_SHORT = {"\n": "\\n", "\r": "\\r", "\t": "\\t"}


def visible(text: str) -> str:
    """`text` with every character that could end a line, reorder the display or fail to encode
    written as a backslash escape (`\\n`, `\\x1b`, `\\u202e`; an undecodable byte of a file
    name as `\\xff`). Used where a path or a name lands in a comment or a diagnostic: it is
    shown to a reader, and can never be obeyed by a compiler or a terminal."""
    out = []
    for ch in text:
        code = ord(ch)
        if ch in _SHORT:
            out.append(_SHORT[ch])
        elif 0xDC80 <= code <= 0xDCFF:  # os.fsdecode's stand-in for a byte that is not UTF-8
            out.append(f"\\x{code - 0xDC00:02x}")
        elif unicodedata.category(ch) in _HIDDEN:
            out.append(f"\\x{code:02x}" if code < 0x100 else
                       f"\\u{code:04x}" if code < 0x10000 else f"\\U{code:08x}")
        else:
            out.append(ch)
    return "".join(out)


@dataclass(frozen=True)
class Pos:
    """A place in a source file; line and column count from 1 like gcc's."""

    file: str
    line: int = 1
    col: int = 1

    def __str__(self) -> str:
        return f"{visible(self.file)}:{self.line}:{self.col}"


@dataclass(frozen=True)
class Diagnostic:
    pos: Pos
    message: str
    severity: str = "error"

    def __str__(self) -> str:
        return f"{self.pos}: {self.severity}: {self.message}"


class Max2CodeError(Exception):
    """Raised with one or more diagnostics; the CLI prints them and exits non-zero."""

    def __init__(self, *diagnostics: Diagnostic) -> None:
        super().__init__("\n".join(str(d) for d in diagnostics))
        self.diagnostics = diagnostics


def error(pos: Pos, message: str) -> Max2CodeError:
    return Max2CodeError(Diagnostic(pos, message))
