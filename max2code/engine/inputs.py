"""Input events (the paper's first event class): keys and the mouse, queued in the World at
their time like collisions, so that the same timed input gives the same run.

Live, a game turns pygame's events into `Input`s at the world's current time
(`from_pygame`); headless, a JSON-lines script gives them (`read_script`), one object a line:

    {"t": 0.5, "type": "key_down", "key": "left"}
    {"t": 0.9, "type": "mouse_down", "pos": [0.2, 0.4], "button": 1}

`write_script` writes what a live session received, for a headless replay of it.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path

TYPES = ("key_down", "key_up", "mouse_down", "mouse_up", "mouse_move")
FIELDS = {"t", "type", "key", "pos", "button"}


class InputError(ValueError):
    """A bad input script (the message is `file:line:col: error: ...`)."""


@dataclass(frozen=True)
class Input:
    """One input event: `key` (pygame's key name: "left", "space", "a") for key events, `pos`
    (world coordinates) and `button` for mouse events."""
    time: float
    type: str
    key: str | None = None
    pos: tuple[float, float] | None = None
    button: int | None = None

    def to_json(self) -> dict:
        out: dict = {"t": self.time, "type": self.type}
        if self.key is not None:
            out["key"] = self.key
        if self.pos is not None:
            out["pos"] = list(self.pos)
        if self.button is not None:
            out["button"] = self.button
        return out


def _number(v: object) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def _problem(obj: object) -> str | None:
    """Why obj is not an input line, or None."""
    if not isinstance(obj, dict):
        return "each line must be a JSON object"
    unknown = sorted(set(obj) - FIELDS)
    if unknown:
        return f"unknown field {unknown[0]!r} (known: {', '.join(sorted(FIELDS))})"
    if not _number(obj.get("t")) or obj["t"] < 0:
        return "'t' must be a finite time >= 0"
    if obj.get("type") not in TYPES:
        return f"'type' must be one of {', '.join(TYPES)}"
    kind = obj["type"]
    if kind.startswith("key") and not isinstance(obj.get("key"), str):
        return "a key event needs 'key' (a key name)"
    if kind.startswith("mouse"):
        pos = obj.get("pos")
        if not (isinstance(pos, list) and len(pos) == 2 and all(_number(c) for c in pos)):
            return "a mouse event needs 'pos': [x, y]"
    button = obj.get("button")
    if button is not None and not (isinstance(button, int) and not isinstance(button, bool)):
        return "'button' must be an integer"
    return None


def parse_script(text: str, name: str = "<input>") -> list[Input]:
    """The inputs of a JSON-lines script, in time order (equal times keep the file's order).
    Every bad line is reported at once, located."""
    out, errors = [], []
    for number, line in enumerate(text.splitlines(), 1):
        if not line.strip():
            continue
        try:
            obj = json.loads(line)
        except json.JSONDecodeError as e:
            errors.append(f"{name}:{number}:{e.colno}: error: not JSON: {e.msg}")
            continue
        problem = _problem(obj)
        if problem:
            errors.append(f"{name}:{number}:1: error: {problem}")
            continue
        pos = tuple(float(c) for c in obj["pos"]) if "pos" in obj else None
        out.append(Input(float(obj["t"]), obj["type"], obj.get("key"), pos, obj.get("button")))
    if errors:
        raise InputError("\n".join(errors))
    return sorted(out, key=lambda i: i.time)


def read_script(path: str | Path) -> list[Input]:
    return parse_script(Path(path).read_text(encoding="utf-8"), str(path))


def write_script(inputs: list[Input], path: str | Path) -> None:
    Path(path).write_text("".join(json.dumps(i.to_json()) + "\n" for i in inputs), encoding="utf-8")


def from_pygame(event, time: float, to_world=lambda p: p) -> Input | None:
    """pygame's KEYDOWN/KEYUP/MOUSEBUTTONDOWN/MOUSEBUTTONUP/MOUSEMOTION event as an Input at
    `time` (the world's time when it arrived); `to_world` maps pixels to world coordinates.
    Other events: None."""
    import pygame
    kinds = {pygame.KEYDOWN: "key_down", pygame.KEYUP: "key_up",
             pygame.MOUSEBUTTONDOWN: "mouse_down", pygame.MOUSEBUTTONUP: "mouse_up",
             pygame.MOUSEMOTION: "mouse_move"}
    kind = kinds.get(event.type)
    if kind is None:
        return None
    if kind.startswith("key"):
        return Input(time, kind, key=pygame.key.name(event.key))
    pos = to_world(event.pos)
    return Input(time, kind, pos=(float(pos[0]), float(pos[1])), button=getattr(event, "button", None))
