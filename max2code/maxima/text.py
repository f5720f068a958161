"""Lexical handling of Maxima program text: statements, comments, strings.

We split the program into statements ourselves so that a Maxima error can be traced to the .mxm
line of the statement that raised it, and so that the original tool's `//` comments (not Maxima
syntax) and a trailing `quit();` (which would end the session before we ask for coefficients) can
be removed without disturbing line and column numbers.
"""

from __future__ import annotations

import re

from ..diagnostics import Pos, error
from ..front.spec import Statement

_QUIT = re.compile(r"^\s*quit\s*\(\s*\)\s*[;$]\s*$", re.DOTALL)


def advance(pos: Pos, text: str) -> Pos:
    """The position just after `text` when it starts at `pos`."""
    newlines = text.count("\n")
    if newlines == 0:
        return Pos(pos.file, pos.line, pos.col + len(text))
    return Pos(pos.file, pos.line + newlines, len(text) - text.rfind("\n"))


_SIGNIFICANT = re.compile(r'"|/\*|//|[;$]')
_NEST = re.compile(r"/\*|\*/")


class _Locator:
    """Positions of increasing offsets into `text` that starts at `start`: each call counts
    only the newlines since the previous one, so locating every statement stays linear."""

    def __init__(self, text: str, start: Pos) -> None:
        self.text, self.start = text, start
        self.offset, self.line, self.line_start = 0, start.line, -1  # -1: on the first line

    def __call__(self, offset: int) -> Pos:
        if offset < self.offset:  # not expected, but never wrong
            return advance(self.start, self.text[:offset])
        newlines = self.text.count("\n", self.offset, offset)
        if newlines:
            self.line += newlines
            self.line_start = self.text.rfind("\n", self.offset, offset)
        self.offset = offset
        if self.line_start < 0:
            return Pos(self.start.file, self.line, self.start.col + offset)
        return Pos(self.start.file, self.line, offset - self.line_start)


def split_statements(text: str, start: Pos) -> tuple[Statement, ...]:
    """Split Maxima text into statements ending in `;` or `$`.

    `//` comments become spaces (columns survive); `/* */` comments nest as in Maxima and stay;
    strings may hold anything. Text after the last terminator must be blank, otherwise the
    statement is unterminated and Maxima would wait for more input. Linear in the text's length
    (one pass over its significant characters; a statement is a slice unless it holds `//`).
    """
    out: list[Statement] = []
    locate = _Locator(text, start)
    blanks: list[tuple[int, int]] = []  # the `//` comments of the current statement
    stmt_start = i = 0
    for m in _SIGNIFICANT.finditer(text):
        if m.start() < i:
            continue  # inside a string or comment already passed
        token = m.group()
        if token == '"':
            i = string_end(text, m.start())
            if i < 0:
                raise error(locate(m.start()), "unterminated string in the Maxima program")
        elif token == "/*":
            i = comment_end(text, m.start())
            if i < 0:
                raise error(locate(m.start()), "unterminated /* comment in the Maxima program")
        elif token == "//":
            i = text.find("\n", m.start())
            i = len(text) if i < 0 else i
            blanks.append((m.start(), i))
        else:
            i = m.end()
            statement = _statement(text, stmt_start, i, blanks, locate)
            if statement is not None:
                out.append(statement)
            blanks = []
            stmt_start = i
    rest = _blanked(text, stmt_start, len(text), blanks)
    if not _only_comments(rest):
        lead = len(rest) - len(_skip_comments(rest))
        raise error(locate(stmt_start + lead), "Maxima statement is not terminated by ';' or '$'")
    return tuple(s for s in out if not _QUIT.match(s.text))


def _blanked(text: str, start: int, end: int, blanks: list[tuple[int, int]]) -> str:
    """text[start:end] with the given spans (inside it) turned into spaces."""
    if not blanks:
        return text[start:end]
    parts, at = [], start
    for a, b in blanks:
        parts += [text[at:a], " " * (b - a)]
        at = b
    parts.append(text[at:end])
    return "".join(parts)


def _statement(text: str, start: int, end: int, blanks: list[tuple[int, int]],
               locate: _Locator) -> Statement | None:
    body = _blanked(text, start, end, blanks)
    stripped = body.lstrip()
    if _only_comments(stripped[:-1]):
        return None
    lead = len(body) - len(stripped)
    if stripped.startswith("/*"):
        # the statement starts after its leading comments, in its text as at its position:
        # Maxima's syntax errors are located by counting lines and columns from there
        stripped = _skip_comments(body)
        lead = len(body) - len(stripped)
    return Statement(stripped, locate(start + lead))


def string_end(text: str, start: int) -> int:
    """The offset after the string opening at `start` (a backslash escapes any character);
    -1 if it never closes. A loop over quotes, not a regular expression: Python's engine keeps
    a frame per repetition, and a string of a million escapes would cost gigabytes."""
    i = start + 1
    while True:
        j = text.find('"', i)
        if j < 0:
            return -1
        k = j
        while text[k - 1] == "\\":
            k -= 1
        if (j - k) % 2 == 0:
            return j + 1
        i = j + 1


def comment_end(text: str, start: int) -> int:
    """The offset after the nested comment opened at `start`; -1 if it never closes."""
    depth = 0
    for m in _NEST.finditer(text, start):
        depth += 1 if m.group() == "/*" else -1
        if depth == 0:
            return m.end()
    return -1


def _skip_comments(text: str) -> str:
    """Text from its first character that is neither blank nor inside a leading comment."""
    return re.sub(r"^(?:\s|/\*[\s\S]*?\*/)*", "", text)


def _only_comments(text: str) -> bool:
    if "/*" not in text:
        return text.strip() == ""
    return re.sub(r"/\*[\s\S]*?\*/", "", text).strip() == ""
