"""The language registry: one line per language. Everything else about a language lives in its
folder `max2code/languages/<lang>/` (printer, harness, build flags; entry.py), its templates in
`templates/<lang>/` and its runtime in `runtime/<lang>/`. The CLI, `max2code check`, runtime
discovery and the CMake package take their languages from here (docs/adding-a-language.md)."""

from __future__ import annotations

from . import c, m2, python, rust
from .base import Language
from .entry import Entry

REGISTRY: dict[str, Entry] = {
    "c": c.ENTRY,
    "python": python.ENTRY,
    "m2": m2.ENTRY,
    "rust": rust.ENTRY,
}

LANGUAGES: dict[str, Language] = {name: entry.language for name, entry in REGISTRY.items()}


def get(name: str) -> Language:
    return LANGUAGES[name]


def harnesses() -> dict[str, object]:
    """The harness of every registered language that has one, in registry order."""
    found = {name: entry.load_harness() for name, entry in REGISTRY.items()}
    return {name: h for name, h in found.items() if h is not None}
