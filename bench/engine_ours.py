"""Our engine's side of bench/engine.py: builds an engine_scenes.Scene with max2code.engine's Python
API and drives it like the anchors (advance to a time, read the states, the contacts with their
times, the number of events).

This file is the only place that knows the engine's API (max2code/engine/__init__.py's docstring:
World, add_segment / add_circle / add_polygon, step_to, pose, velocity, poses, stats): when the
API changes, only `OursSim` changes. Until max2code.engine is importable, `unavailable()` says why and bench/engine.py leaves
our column empty ("not run"), never filled with made-up numbers.
"""

from __future__ import annotations

import importlib


def version() -> str:
    """Where max2code.engine was loaded from, and the git commit of that checkout if it is one."""
    import subprocess
    from pathlib import Path
    folder = Path(importlib.import_module("max2code.engine").__file__).resolve().parent.parent.parent
    try:
        commit = subprocess.run(["git", "-C", str(folder), "rev-parse", "--short", "HEAD"],
                                capture_output=True, text=True, timeout=10).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        commit = ""
    return f"{folder}" + (f" at {commit}" if commit else " (not a git checkout)")


def unavailable() -> str | None:
    """None when max2code.engine can be used; else the reason it cannot."""
    try:
        importlib.import_module("max2code.engine")
    except ImportError as exc:
        return f"max2code.engine is not importable ({exc})"
    if not hasattr(importlib.import_module("max2code.engine"), "World"):
        return "max2code.engine has no World"
    return None


TOLERANCE = 1e-9   # the engine's default tolerance on contact times (World(tolerance=))


def contact_step() -> float:
    """The contact solver's step for the stacking scenes: the World's default when it has one
    (the solver on by default), else 1/240 s."""
    import inspect
    from max2code.engine import World
    return inspect.signature(World).parameters["contact_step"].default or 1 / 240


class OursSim:
    """A scene in max2code.engine.World, driven like the anchors.

    Walls are static segments, discs circles, blocks polygons, all with the scene's mass,
    moment of inertia and restitution (the engine multiplies two bodies' restitutions: 1 here).
    Contacts are the engine's collision events with their own (predicted) times."""

    def __init__(self, scene, record: bool) -> None:
        from max2code.engine import World
        from engine_scenes import Disc

        solver = {"contact_step": contact_step()} if scene.rest else {}
        self.world = w = World(gravity=scene.gravity, tolerance=TOLERANCE, **solver)
        self.index: dict[int, int] = {}
        for k, wall in enumerate(scene.walls):
            mu, e = scene.coefficients(wall.e, "sqrt", "product")
            self.index[w.add_segment(wall.a, wall.b, restitution=e, friction=mu)] = -(k + 1)
        self.ids = []
        for i, b in enumerate(scene.bodies):
            mu, e = scene.coefficients(b.e, "sqrt", "product")
            common = dict(angle=b.angle, velocity=(b.vx, b.vy), omega=b.w, mass=b.m, inertia=b.moment,
                          restitution=e, friction=mu)
            if isinstance(b, Disc):
                body = w.add_circle((b.x, b.y), b.r, **common)
            else:
                body = w.add_polygon(list(b.vertices), position=(b.x, b.y), **common)
            self.index[body] = i
            self.ids.append(body)
        self.record = record
        self.now = 0.0
        self.contacts: list[tuple[float, int, int]] = []

    def advance(self, t_end: float) -> None:
        """Every event up to t_end (no Event objects are made unless contacts are recorded)."""
        events = self.world.step_to(t_end, events=self.record)
        self.now = t_end
        if self.record:
            for ev in events:
                if ev.kind == "collision":
                    i, j = sorted((self.index[ev.a], self.index[ev.b]))
                    self.contacts.append((ev.time, i, j))

    @property
    def events(self) -> int:
        """Every event processed so far (collisions, cell crossings, windows, ...)."""
        return self.world.stats()["events"]

    def poses(self) -> list[tuple[float, float, float]]:
        """Every body's pose now: what a frame draws (walls included, as the engine has them)."""
        return self.world.poses(self.now)

    def states(self) -> list[tuple[float, float, float, float, float, float]]:
        w = self.world
        return [w.pose(i) + w.velocity(i) for i in self.ids]


class Ours:
    name = "ours"
    label = "ours"
    dt = None

    def build(self, scene, record: bool = False) -> OursSim:
        return OursSim(scene, record)
