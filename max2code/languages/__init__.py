"""The language registry: one line per language; nothing else in the tool names a language."""

from __future__ import annotations

from .base import Language
from .c import C
from .python import Python

LANGUAGES: dict[str, Language] = {
    "c": C(),
    "python": Python(),
}


def get(name: str) -> Language:
    return LANGUAGES[name]
