"""The language registry: one line per language; nothing else in the tool names a language."""

from __future__ import annotations

from .base import Language
from .c import C
from .m2 import Modula2
from .python import Python
from .rust import Rust

LANGUAGES: dict[str, Language] = {
    "c": C(),
    "python": Python(),
    "m2": Modula2(),
    "rust": Rust(),
}


def get(name: str) -> Language:
    return LANGUAGES[name]
