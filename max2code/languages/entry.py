"""One language's registry entry: everything max2code knows of a language is reached from it.

A language lives in one folder, `max2code/languages/<lang>/`: its printer (the `Language`),
its harness for `max2code check`, and the build flags `max2code runtime` prints; its templates
are `templates/<lang>/` and its runtime `runtime/<lang>/`. The harness is named, not imported,
so that generating code never loads the machinery that compiles and runs it."""

from __future__ import annotations

import importlib
from collections.abc import Callable
from dataclasses import dataclass

from .base import Language


@dataclass(frozen=True)
class Entry:
    """`harness`: the class name in the folder's `harness` module, or None when the language is
    generated but not checked. `runtime`: the answers of `max2code runtime --lang` (one line of
    text each), or None when no build flags are known (the runtime folder alone is printed)."""

    language: Language
    package: str
    harness: str | None = None
    runtime: Callable[[], dict[str, str]] | None = None

    def load_harness(self) -> object | None:
        if self.harness is None:
            return None
        return getattr(importlib.import_module(f"{self.package}.harness"), self.harness)()
