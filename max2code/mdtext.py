"""Data (file names, paths, labels) as Markdown text that stays text.

A path is data, never markup: in a table cell a '|' would add a column, in any line a newline
would start a heading or a raw HTML block, and '<', '>', '&' would be HTML to a renderer (a
reviewer put `# injected <img src=x onerror=...>` into summary.md through a file name)."""

from __future__ import annotations

_ENTITIES = {"&": "&amp;", "<": "&lt;", ">": "&gt;"}


def inline(text: str) -> str:
    """`text` as one line of Markdown that holds no markup of its own: control characters as
    spaces, '|' (a table's column), '[' and ']' (a link) and '\\' escaped, HTML's special
    characters as entities. ('_' and '*' are left as they are: inside words they are no
    emphasis, and a name like no_orbit stays readable in the file.)"""
    out = []
    for ch in text:
        if ch in _ENTITIES:
            out.append(_ENTITIES[ch])
        elif ord(ch) < 0x20 or ord(ch) == 0x7F:
            out.append(" ")
        elif ch in "\\|[]":
            out.append("\\" + ch)
        else:
            out.append(ch)
    return "".join(out)
