"""Who hears about a contact: callbacks for every event, per body, per pair of bodies, and per
pair of collision types (pymunk's handlers, with begin / pre_solve / post_solve / separate).

The core reports events; this module only decides which callbacks an event goes to, and which
bodies need the core's help (a pre-solve callback before the response, separate events): the
World turns those needs into body flags (`flags_for`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

FLAG_SENSOR, FLAG_PRESOLVE, FLAG_SEPARATE = 1, 2, 4

Callback = Callable[..., object]


@dataclass
class CollisionHandler:
    """Callbacks for contacts between bodies of collision types `a` and `b` (b None: any).
    Each is called as callback(world, event); `begin` and `pre_solve` run before the
    response and may return False to veto it (the pair then passes through each other until
    they meet again: a one-way platform); `post_solve` runs after it (the collision event);
    `separate` when a sustained contact ends (a body resting or sliding on the other leaves
    it: a bounce is its own end). A sensor's contacts go to `begin` and cannot be vetoed; its leaves
    ("sensor_leave") to `separate`."""
    a: int
    b: int | None
    begin: Callback | None = None
    pre_solve: Callback | None = None
    post_solve: Callback | None = None
    separate: Callback | None = None

    def matches(self, ta: int, tb: int) -> bool:
        return (self.a == ta and self.b in (None, tb)) or (self.a == tb and self.b in (None, ta))


@dataclass
class Handlers:
    """Every registered callback, kept in registration order."""
    every: list[Callback] = field(default_factory=list)
    per_body: dict[int, list[Callback]] = field(default_factory=dict)
    per_pair: dict[tuple[int, int], list[Callback]] = field(default_factory=dict)
    pre_solve_body: dict[int, list[Callback]] = field(default_factory=dict)
    typed: list[CollisionHandler] = field(default_factory=list)

    def any(self) -> bool:
        return bool(self.every or self.per_body or self.per_pair or self.typed)

    def flags_for(self, body: int, ctype: int) -> int:
        """The core's flags body needs for these callbacks (sensor flags come from the body)."""
        flags = FLAG_PRESOLVE if body in self.pre_solve_body else 0
        for h in self.typed:
            if ctype in (h.a, h.b) or (h.b is None and h.a == ctype):
                if h.begin or h.pre_solve:
                    flags |= FLAG_PRESOLVE
                if h.separate:
                    flags |= FLAG_SEPARATE
        return flags

    def pre_solve(self, world, event, types: tuple[int, int]) -> bool:
        """Before a response: False when any callback vetoes it."""
        keep = True
        for cb in self.pre_solve_body.get(event.a, []) + self.pre_solve_body.get(event.b, []):
            keep = cb(world, event) is not False and keep
        for h in self.typed:
            if h.matches(*types):
                for cb in (h.begin, h.pre_solve):
                    if cb is not None:
                        keep = cb(world, event) is not False and keep
        return keep

    def dispatch(self, world, event, types: tuple[int, int]) -> None:
        """After the core reported an event (not a timer): everything it concerns."""
        for cb in self.every:
            cb(world, event)
        if event.b >= 0:
            for cb in self.per_body.get(event.a, []) + self.per_body.get(event.b, []):
                cb(world, event)
            key = (min(event.a, event.b), max(event.a, event.b))
            for cb in self.per_pair.get(key, []):
                cb(world, event)
        else:
            for cb in self.per_body.get(event.a, []):
                cb(world, event)
        slot = {"collision": "post_solve", "separate": "separate", "sensor": "begin",
                "sensor_leave": "separate"}.get(event.kind)
        if slot is None or event.b < 0:
            return
        for h in self.typed:
            cb = getattr(h, slot)
            if cb is not None and h.matches(*types):
                cb(world, event)
