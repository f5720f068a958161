"""Our engine's side of bench/engine.py: builds an engine_scenes.Scene with max2code.engine's Python
API and drives it like the anchors (advance to a time, read the states, the contacts with their
times, the number of events).

This file is the only place that knows the engine's API: when the API changes, only `OursSim`
changes. Until max2code.engine is importable, `unavailable()` says why and bench/engine.py leaves
our column empty ("not run"), never filled with made-up numbers.
"""

from __future__ import annotations

import importlib


def unavailable() -> str | None:
    """None when max2code.engine can be used; else the reason it cannot."""
    try:
        importlib.import_module("max2code.engine")
    except ImportError as exc:
        return f"max2code.engine is not importable ({exc})"
    if not hasattr(importlib.import_module("max2code.engine"), "World"):
        return "max2code.engine has no World"
    return None


class OursSim:
    """Adapter: written against the engine's documented API once it is on main."""

    def __init__(self, scene, record: bool, fps: float | None) -> None:
        raise NotImplementedError("max2code.engine adapter: the engine's API is not on main yet")


class Ours:
    name = "ours"
    label = "ours"
    dt = None

    def __init__(self, fps: float | None = 60.0) -> None:
        self.fps = fps

    def build(self, scene, record: bool = False) -> OursSim:
        return OursSim(scene, record, self.fps)
