"""Lexical handling of Maxima program text: statements, comments, strings.

We split the program into statements ourselves so that a Maxima error can be traced to the .mxm
line of the statement that raised it, and so that the original tool's `//` comments (not Maxima
syntax) and a trailing `quit();` (which would end the session before we ask for coefficients) can
be removed without disturbing line and column numbers.
"""

from __future__ import annotations

import re

from .diagnostics import Pos, error
from .spec import Statement

_QUIT = re.compile(r"^\s*quit\s*\(\s*\)\s*[;$]\s*$", re.DOTALL)


def advance(pos: Pos, text: str) -> Pos:
    """The position just after `text` when it starts at `pos`."""
    newlines = text.count("\n")
    if newlines == 0:
        return Pos(pos.file, pos.line, pos.col + len(text))
    return Pos(pos.file, pos.line + newlines, len(text) - text.rfind("\n"))


def split_statements(text: str, start: Pos) -> tuple[Statement, ...]:
    """Split Maxima text into statements ending in `;` or `$`.

    `//` comments become spaces (columns survive); `/* */` comments nest as in Maxima and stay;
    strings may hold anything. Text after the last terminator must be blank, otherwise the
    statement is unterminated and Maxima would wait for more input.
    """
    out: list[Statement] = []
    buf: list[str] = []
    stmt_start = 0
    i = 0
    n = len(text)
    while i < n:
        ch = text[i]
        if ch == '"':
            j = i + 1
            while j < n and text[j] != '"':
                j += 2 if text[j] == "\\" else 1
            if j >= n:
                raise error(advance(start, text[:i]), "unterminated string in the Maxima program")
            buf.append(text[i : j + 1])
            i = j + 1
        elif text.startswith("/*", i):
            depth, j = 1, i + 2
            while j < n and depth:
                if text.startswith("/*", j):
                    depth, j = depth + 1, j + 2
                elif text.startswith("*/", j):
                    depth, j = depth - 1, j + 2
                else:
                    j += 1
            if depth:
                raise error(advance(start, text[:i]), "unterminated /* comment in the Maxima program")
            buf.append(text[i:j])
            i = j
        elif text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            buf.append(" " * (j - i))
            i = j
        elif ch in ";$":
            buf.append(ch)
            body = "".join(buf)
            stripped = body.lstrip()
            lead = body[: len(body) - len(_skip_comments(body))]
            pos = advance(advance(start, text[:stmt_start]), lead)
            if not _only_comments(stripped[:-1]):
                out.append(Statement(stripped, pos))
            buf = []
            i += 1
            stmt_start = i
        else:
            buf.append(ch)
            i += 1
    rest = "".join(buf)
    if not _only_comments(rest):
        lead = rest[: len(rest) - len(_skip_comments(rest))]
        raise error(
            advance(advance(start, text[:stmt_start]), lead),
            "Maxima statement is not terminated by ';' or '$'",
        )
    return tuple(s for s in out if not _QUIT.match(s.text))


def _skip_comments(text: str) -> str:
    """Text from its first character that is neither blank nor inside a leading comment."""
    return re.sub(r"^(?:\s|/\*[\s\S]*?\*/)*", "", text)


def _only_comments(text: str) -> bool:
    return re.sub(r"/\*[\s\S]*?\*/", "", text).strip() == ""
