"""The language registry: an entry per language. The CLI, runtime discovery and the CMake package
take their languages from here; `max2code check` also needs the language's harness
(max2code/harness/), and runtime discovery knows build flags for the four shipped ones only."""

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
