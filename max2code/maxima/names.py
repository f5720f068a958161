"""Names Maxima already gives a value, and renaming a program's symbols token by token.

In Maxima a name like `fpprec`, `expop`, `linel`, `float` or `__` is not a free symbol: it
evaluates to its value (16, 0, 79, false, the expression being read). A parameter so named was
replaced by that value with exit status 0 -- `fpprec` made a coefficient 16.0, `expop` dropped
the t^2 term -- and the oracle, running the same program, agreed. So such a name is refused
where it stands: declared (`parameters`, `variable`), or read as a value in the program (not
called, `float(x)`; not assigned, `fpprec: 30`; not quoted, `'linel`; a flag not given to `ev`
after a comma, `e, numer`). The list, `maxima_variables.txt`, is Maxima's own answer
(`scripts/maxima-variables` writes it; a test compares it with the Maxima installed).

The oracle renames the parameters (`rename`) before it runs the program, so it never reads a
parameter as Maxima's variable even where this check would miss one.
"""

from __future__ import annotations

import functools
import re
from pathlib import Path

from ..diagnostics import Pos, error
from .text import advance, comment_end, string_end
from ..front.spec import Statement

LIST = Path(__file__).with_name("variables.txt")

_KINDS = {"number": "a numeric option variable", "flag": "a flag (true or false)",
          "other": "a system variable"}
_TOKEN = re.compile(r'"|/\*|(?<![\w%])[A-Za-z_%][\w%]*')
_BLANK = re.compile(r"\s*")


@functools.cache
def variables() -> dict[str, str]:
    """Maxima's names that have a value -> the kind of value (number, flag, other)."""
    out = {}
    for line in LIST.read_text().splitlines():
        if line and not line.startswith("#"):
            name, kind = line.split()
            out[name] = kind
    return out


def why(name: str) -> str:
    """Why `name` cannot be a symbol of the equation."""
    return (f"'{name}' is {_KINDS[variables()[name]]} of Maxima: in a program it stands for its "
            f"value, not for a symbol, so the equation would silently use that value; rename it")


def check_declared(names: list[tuple[str, Pos]]) -> None:
    """A declared name (a parameter, the variable) that Maxima gives a value is an error at it."""
    for name, pos in names:
        if name in variables():
            raise error(pos, why(name))


def tokens(text: str):
    """(start, name) of each name in Maxima text, outside strings and comments."""
    i = 0
    while (m := _TOKEN.search(text, i)) is not None:
        token = m.group()
        if token == '"':
            i = string_end(text, m.start())
        elif token == "/*":
            i = comment_end(text, m.start())
        else:
            yield m.start(), token
            i = m.end()
        if i < 0:
            return


def _read_as_value(text: str, start: int, name: str) -> bool:
    """Is the name at `start` evaluated: not called, assigned, subscripted or quoted (and, for
    a flag, not an evaluation flag after a comma)?"""
    j = _BLANK.match(text, start + len(name)).end()  # type: ignore[union-attr]
    after = text[j:j + 1]
    k = start - 1
    while k >= 0 and text[k].isspace():
        k -= 1
    before = text[k] if k >= 0 else ""
    if after in ("(", ":", "[") or before == "'":
        return False
    return not (variables()[name] == "flag" and before == ",")


def check_program(statements: tuple[Statement, ...]) -> None:
    """A name of Maxima's with a value, read as a value in the program, is an error at it."""
    known = variables()
    for stmt in statements:
        for start, name in tokens(stmt.text):
            if name in known and _read_as_value(stmt.text, start, name):
                raise error(advance(stmt.pos, stmt.text[:start]), why(name))


def rename(statements: tuple[Statement, ...], mapping: dict[str, str]) -> tuple[Statement, ...]:
    """The statements with every name of `mapping` that is not called (`f(`) renamed, outside
    strings and comments; positions are kept per statement."""
    out = []
    for stmt in statements:
        text, parts, last = stmt.text, [], 0
        for start, name in tokens(text):
            end = start + len(name)
            if name in mapping and not text.startswith("(", _BLANK.match(text, end).end()):  # type: ignore[union-attr]
                parts += [text[last:start], mapping[name]]
                last = end
        out.append(Statement("".join(parts) + text[last:], stmt.pos))
    return tuple(out)
