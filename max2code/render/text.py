"""Text that ends up in a picture: labels made safe to draw and to write into XML, time stamps."""

from __future__ import annotations

import re

# XML 1.0 allows tab, newline, carriage return and these ranges; anything else (other control
# characters, lone surrogates, U+FFFE/U+FFFF) cannot appear in an SVG even escaped, and Pillow
# cannot draw it either.
_NOT_XML = re.compile("[^\t\n\r\u0020-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]")
MAX_LABEL = 200


def printable(label: str) -> str:
    """A label as it is shown: characters XML and fonts cannot take become U+FFFD, line breaks
    and tabs become spaces (a label is one line), and it is cut at MAX_LABEL characters."""
    text = _NOT_XML.sub("\ufffd", label)
    text = text.replace("\t", " ").replace("\r", " ").replace("\n", " ")
    return text if len(text) <= MAX_LABEL else text[:MAX_LABEL - 1] + "\u2026"


def time_stamp(t: float) -> str:
    return f"t = {t:.3f} s"
