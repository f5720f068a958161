#!/usr/bin/env python3
"""The paper's "pedagogical platform game", on max2code.engine: a player that walks, jumps and
lands, one-way platforms, a lift (a kinematic platform), coins to collect and a goal.

    python platformer.py                    # play: Left/Right walk, Up or Space jumps, Escape quits
    python platformer.py --headless --input run.jsonl --gif platformer.gif

Every rule is an event at its exact time, never a check made at frames:
* the player (a ball: it rolls over edges and rests on floors by the engine's rest rule) keeps
  walking while a key is held; a wall stops it, and it walks on at the instant its jump lifts
  it above that wall's top (a timer at that root of its flight);
* it may jump while it stands on something: from the landing (a collision or rest event with
  the support below it) until its centre passes the support's end (a timer);
* a one-way platform is in place only while the player's feet are above it: it is moved in
  (World.set_pose) at the instant the rising feet pass its top, and parked out of the world
  when they drop below it (timers at the roots of the feet's height);
* coins and the goal are sensors: bodies that never collide with the player (one group), whose
  first touch is predicted after every change of its path: the smallest root of
  |p(s) - c|^2 - (r + rc)^2, a quartic in s for the player's path p(s) as the engine holds it
  (World.motions: while it stands or walks, its acceleration is 0), by max2code's own root
  finder (max2code_runtime.first_root);
* the lift is kinematic, turned around by timers at the ends of its travel.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from dataclasses import dataclass, field
from pathlib import Path

from max2code.engine import World, loop
from max2code.render.items import Frame, Item, body_item

HERE = Path(__file__).resolve().parent
SCRIPT = HERE / "run.jsonl"
SIDE = 16.0
G = 20.0
RADIUS, WALK, JUMP = 0.4, 3.0, 11.0
PARKED = lambda k: (100.0 + 10 * k, -100.0)  # noqa: E731 (where a passable one-way platform waits)
SKIN = 1e-6              # a one-way platform appears this far under the feet that rise past it
LIFT_LOW, LIFT_HIGH, LIFT_SPEED = 1.0, 6.0, 1.25
COLOURS = {"ground": (110, 80, 40, 255), "platform": (150, 110, 60, 255),
           "oneway": (200, 170, 90, 255), "lift": (230, 160, 40, 255), "coin": (250, 210, 40, 255),
           "goal": (60, 200, 90, 255), "player": (90, 150, 255, 255)}

# the level: (kind, x0, y0, x1, y1) boxes, and the sensors' centres
BOXES = [("ground", 0, 0, SIDE, 1), ("ground", -1, 0, 0, SIDE), ("ground", SIDE, 0, SIDE + 1, SIDE),
         ("oneway", 2.5, 2.7, 5.5, 3.0), ("platform", 10.5, 6.2, 13.0, 6.5),
         ("oneway", 12.0, 8.7, 15.0, 9.0), ("platform", 5.5, 1.0, 6.0, 1.8)]
LIFT = (7.5, 9.5, 0.3)   # x0, x1, thickness; its top runs from LIFT_LOW to LIFT_HIGH and back
COINS = [(4.0, 3.8), (11.7, 7.3), (8.6, 3.5)]
# the lift's timetable: (velocity, seconds), round and round (it waits at the bottom first)
LIFT_PHASES = ((0.0, 4.0), (LIFT_SPEED, (LIFT_HIGH - LIFT_LOW) / LIFT_SPEED), (0.0, 2.0),
               (-LIFT_SPEED, (LIFT_HIGH - LIFT_LOW) / LIFT_SPEED), (0.0, 2.0))
GOAL = (14.2, 9.8)


def rect(x0: float, y0: float, x1: float, y1: float) -> list[tuple[float, float]]:
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


ROUND = 0.05   # platforms' corners are rounded: a ball walking off an edge rolls over it


def platform(world: World, box, **kw) -> int:
    """A box with rounded corners (a polygon shrunk by ROUND, with radius ROUND)."""
    x0, y0, x1, y1 = box
    return world.add_polygon(rect(x0 + ROUND, y0 + ROUND, x1 - ROUND, y1 - ROUND), radius=ROUND,
                             **kw)


def feet_roots(y: float, vy: float, ay: float, level: float) -> list[float]:
    """Times s >= 0 at which feet at height y, rising at vy, accelerated by ay, reach `level`:
    y + vy s + ay s^2 / 2 = level."""
    if ay == 0:
        return [s for s in ([(level - y) / vy] if vy else []) if s >= 0]
    disc = vy * vy - 2 * ay * (y - level)
    if disc < 0:
        return []
    r = math.sqrt(disc)
    return sorted(s for s in ((-vy - r) / ay, (-vy + r) / ay) if s >= 0)


def touch_time(e: tuple[float, float], v: tuple[float, float], a: tuple[float, float],
               reach: float, horizon: float) -> float | None:
    """The first s in [0, horizon] at which a point at offset e from a centre, moving at v with
    acceleration a, comes within `reach` of it: the smallest root of |e + v s + a s^2/2|^2 -
    reach^2 (0 when it is within already)."""
    from max2code_runtime import first_root

    (ex, ey), (vx, vy), (hx, hy) = e, v, (a[0] / 2, a[1] / 2)
    c = [ex * ex + ey * ey - reach * reach, 2 * (ex * vx + ey * vy),
         vx * vx + vy * vy + 2 * (ex * hx + ey * hy), 2 * (vx * hx + vy * hy), hx * hx + hy * hy]
    if c[0] <= 0:
        return 0.0
    return first_root(c, horizon)


@dataclass
class Platformer:
    world: World = field(default_factory=lambda: World(gravity=(0.0, -G)))
    kinds: dict[int, str] = field(default_factory=dict)
    oneway: dict[int, tuple] = field(default_factory=dict)   # its number -> (box, body, in place)
    sensors: dict[int, str] = field(default_factory=dict)    # body -> "coin" | "goal"
    held: list[str] = field(default_factory=list)
    support: int | None = None
    blocked: int = 0            # the direction a wall stopped the walk in
    collected: int = 0
    won: bool = False
    riding: bool = False
    generation: int = 0         # the player's path: timers of an older path are stale
    log: list[dict] = field(default_factory=list)

    def __post_init__(self) -> None:
        w = self.world
        for k, (kind, *box) in enumerate(BOXES):
            body = platform(w, box, kind="static", name=f"{kind}-{k}")
            self.kinds[body] = kind
            if kind == "oneway":
                w.set_pose(body, PARKED(k))
                self.oneway[k] = (box, body, False)
        x0, x1, h = LIFT
        self.lift = platform(w, (x0, -h, x1, 0), kind="kinematic", position=(0, LIFT_LOW),
                             name="lift")
        self.kinds[self.lift] = "lift"
        self.phase = 0
        self.world.add_timer(LIFT_PHASES[0][1], self.turn_lift)
        for x, y in COINS:
            self.sensors[w.add_circle((x, y), 0.25, kind="static", group="sensors", name="coin")] = "coin"
        self.sensors[w.add_circle(GOAL, 0.5, kind="static", group="sensors", name="goal")] = "goal"
        self.kinds.update(self.sensors)
        self.player = w.add_circle((1.5, 1.0 + RADIUS), RADIUS, mass=1.0, restitution=0.0,
                                   group="sensors", name="player")
        self.kinds[self.player] = "player"
        w.on_collision(self.event)
        self.changed()

    # -- the lift ------------------------------------------------------------------------------

    def turn_lift(self, world: World, ev) -> None:
        """The next phase of the lift's timetable, now."""
        self.phase = (self.phase + 1) % len(LIFT_PHASES)
        v, seconds = LIFT_PHASES[self.phase]
        world.set_velocity(self.lift, (0.0, v))
        world.add_timer(world.time + seconds, self.turn_lift)
        if self.riding:
            world.set_velocity(self.player, (world.velocity(self.player)[0], v))
        self.changed()

    # -- input ---------------------------------------------------------------------------------

    def key(self, kind: str, key: str) -> None:
        """A key pressed (KEYDOWN) or released (KEYUP) now."""
        self.log.append({"t": self.world.time, "kind": "input", "type": kind, "key": key})
        if key in ("K_LEFT", "K_RIGHT"):
            if kind == "KEYDOWN" and key not in self.held:
                self.held.append(key)
            elif kind == "KEYUP" and key in self.held:
                self.held.remove(key)
            self.blocked = 0
            self.walk()
        elif key in ("K_UP", "K_SPACE") and kind == "KEYDOWN" and self.support is not None:
            vx, vy, _ = self.world.velocity(self.player)
            if self.riding:
                self.ride(False)
            self.support = None
            self.world.set_velocity(self.player, (vx, vy + JUMP))
        self.changed()

    def direction(self) -> int:
        return (1 if self.held[-1] == "K_RIGHT" else -1) if self.held else 0

    def walk(self) -> None:
        d = self.direction()
        vx, vy, _ = self.world.velocity(self.player)
        if (d and d == self.blocked) or abs(vx - WALK * d) < 1e-6:
            return   # (setting a velocity wakes a resting body: only a change is made)
        self.world.set_velocity(self.player, (WALK * d, vy))

    # -- events --------------------------------------------------------------------------------

    def event(self, world: World, ev) -> None:
        if ev.kind == "timer" or self.player not in (ev.a, ev.b):
            return
        other = ev.b if ev.a == self.player else ev.a
        if other < 0:   # (a wake, or a rest on several bodies: nothing new below the player)
            return
        # the normal, from the player towards the other body
        nx, ny = ev.normal if ev.a == self.player else (-ev.normal[0], -ev.normal[1])
        self.log.append({"t": ev.time, "kind": ev.kind, "with": world.bodies[other].name})
        if ev.kind == "rest" or ny < -0.7:
            if other != self.support:
                self.land(other)
        elif abs(nx) > 0.7 and self.direction() == (1 if nx > 0 else -1):
            self.blocked = self.direction()
            self.over_the_top(other)
        self.changed()

    def land(self, support: int) -> None:
        self.support = support
        self.blocked = 0
        if support == self.lift and not self.riding:
            self.ride(True)
        elif support != self.lift and self.riding:
            self.ride(False)
        self.walk()

    def ride(self, on: bool) -> None:
        """On the lift the player is kinematic, moving with it (and walking on it): the
        engine's rest rule keeps bodies at rest on static supports only, so a rider is carried
        the way many platformers carry one, by giving it the platform's motion; it is dynamic
        again when it jumps or walks off."""
        w = self.world
        self.riding = on
        vx, vy, _ = w.velocity(self.player)
        if on:
            w.set_kind(self.player, "kinematic")
            w.set_acceleration(self.player, (0.0, 0.0))
            w.set_velocity(self.player, (vx, w.velocity(self.lift)[1]))
        else:
            w.set_kind(self.player, "dynamic")
            w.set_mass(self.player, 1.0)
            w.set_acceleration(self.player, (0.0, -G))
            w.set_velocity(self.player, (vx, vy))

    def over_the_top(self, wall: int) -> None:
        """Walk on at the instant the jump lifts the feet above the wall's top."""
        w = self.world
        top = max(y for x, y in self.corners(wall))
        _, y, _ = w.pose(self.player)
        _, vy, _ = w.velocity(self.player)
        ay = w.motions()[0][self.player][8]
        for s in feet_roots(y - RADIUS, vy, ay, top + SKIN):
            if vy + ay * s > 0:   # (rising through it)
                gen = self.generation + 1
                w.add_timer(w.time + s, lambda world, ev: self.unblock(gen))
                return

    def unblock(self, gen: int) -> None:
        if gen == self.generation:
            self.blocked = 0
            self.walk()
            self.changed()

    def corners(self, body: int) -> list[tuple[float, float]]:
        x, y, a = self.world.pose(body)
        c, s = math.cos(a), math.sin(a)
        return [(x + c * u - s * v, y + s * u + c * v) for u, v in self.world.bodies[body].vertices]

    # -- predictions after every change of the player's path -----------------------------------

    def changed(self) -> None:
        """The player's path changed: predict its sensors, one-way platforms and support's end
        anew (timers of older paths see a new generation and do nothing)."""
        self.generation += 1
        gen, w = self.generation, self.world
        now = w.time
        x, y, _ = w.pose(self.player)
        vx, vy, _ = w.velocity(self.player)
        ay = w.motions()[0][self.player][8]   # (0 while it stands or walks: the rest rule)
        for body, what in self.sensors.items():
            if w.alive(body):
                cx, cy, _ = w.pose(body)
                s = touch_time((x - cx, y - cy), (vx, vy), (0.0, ay),
                               RADIUS + w.bodies[body].radius, 60.0)
                if s is not None:
                    w.add_timer(now + s, lambda world, ev, b=body: self.sensed(gen, b))
        for k, (box, body, placed) in self.oneway.items():
            top = box[3]
            if not placed and y - RADIUS < top + SKIN:
                roots = [s for s in feet_roots(y - RADIUS, vy, ay, top + SKIN) if vy + ay * s > 0]
                if roots:
                    w.add_timer(now + roots[0], lambda world, ev, k=k: self.solid(gen, k))
            elif placed:
                roots = [s for s in feet_roots(y - RADIUS, vy, ay, top - 1e-3) if vy + ay * s < 0]
                if roots:
                    w.add_timer(now + roots[0], lambda world, ev, k=k: self.passable(gen, k))
        if self.support is not None and vx and w.alive(self.support):
            xs = [cx for cx, _ in self.corners(self.support)]
            edge = max(xs) if vx > 0 else min(xs)
            s = (edge - x) / vx
            if s > 1e-9:
                w.add_timer(now + s, lambda world, ev: self.leave(gen))

    def leave(self, gen: int) -> None:
        """The player's centre passes its support's end: it is off it, and falls."""
        if gen != self.generation:
            return
        self.support = None
        if self.riding:
            self.ride(False)
        # (the engine's rest rule holds a ball resting on an edge at the edge's end, or slides
        # it on along the edge's line, depending on the grid: the player is moved 11 mm on,
        # clear of the flat edge, with its velocity set again, from where it rolls over the
        # rounded corner and falls, as a ball should)
        w = self.world
        x, y, _ = w.pose(self.player)
        vx, vy, _ = w.velocity(self.player)
        d = 1 if vx > 0 else -1
        w.set_pose(self.player, (x + d * 0.011, y))
        w.set_velocity(self.player, (vx, vy))
        self.changed()

    def sensed(self, gen: int, body: int) -> None:
        if gen != self.generation or not self.world.alive(body):
            return
        what = self.sensors[body]
        self.world.remove(body)
        self.log.append({"t": self.world.time, "kind": what})
        if what == "coin":
            self.collected += 1
        else:
            self.won = True

    def solid(self, gen: int, k: int) -> None:
        if gen == self.generation:
            box, body, _ = self.oneway[k]
            self.world.set_pose(body, (0.0, 0.0))
            self.oneway[k] = (box, body, True)
            self.changed()

    def passable(self, gen: int, k: int) -> None:
        if gen == self.generation:
            box, body, _ = self.oneway[k]
            self.world.set_pose(body, PARKED(k))
            self.oneway[k] = (box, body, False)
            self.changed()

    # -- frames --------------------------------------------------------------------------------

    def frame(self) -> Frame:
        w = self.world
        parked = {body for _, body, placed in self.oneway.values() if not placed}
        items = [body_item(info.vertices, info.radius, w.pose(i), COLOURS[self.kinds[i]])
                 for i, info in enumerate(w.bodies) if w.alive(i) and i not in parked]
        items += [Item("polygon", (200, 170, 90, 110), tuple(rect(*box)))
                  for box, body, placed in self.oneway.values() if not placed]
        items.append(Item("text", (255, 255, 255, 255), ((0.4, 15.6),),
                          text=f"coins {self.collected}/{len(COINS)}" + ("   GOAL!" if self.won else ""),
                          size=30))
        return Frame(w.time, tuple(items))


LIVE_KEYS = {"left": "K_LEFT", "right": "K_RIGHT", "up": "K_UP", "space": "K_SPACE"}


def play(game: Platformer, until: float, fps: float, keys, live: bool, frames: list | None) -> None:
    """Frames at 1/fps; scripted keys at their times, live keys after the frame they came in."""
    window = picture = None
    if live:
        from max2code.render.items import image
        from max2code.render.live import Window
        window = Window(640, 640, "platformer (max2code.engine)")
        picture = lambda f: image(f, 640, 640, (0.0, 0.0, SIDE))  # noqa: E731

    def from_window(e):
        import pygame
        name = LIVE_KEYS.get(pygame.key.name(e.key)) if e.type in (pygame.KEYDOWN, pygame.KEYUP) else None
        return ("KEYDOWN" if e.type == pygame.KEYDOWN else "KEYUP", name) if name else None

    shown = loop.play(game.world, game.frame, until=until, fps=fps, script=keys,
                      deliver=lambda item: game.key(*item), done=lambda: game.won,
                      keep=frames is not None, window=window, picture=picture,
                      from_window=from_window)
    if frames is not None:
        frames.extend(shown)
    if frames is not None and game.won:
        for j in range(1, int(fps)):   # a second on the goal
            game.world.step_to(game.world.time + 1 / fps)
            frames.append(game.frame())


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--headless", action="store_true")
    ap.add_argument("--until", type=float, default=120.0)
    ap.add_argument("--fps", type=float, default=60.0)
    ap.add_argument("--input", help="timed keys (JSON lines, as --events writes them)")
    ap.add_argument("--events", help="write the event log (JSON lines)")
    ap.add_argument("--gif", help="an animated GIF of the frames")
    ap.add_argument("--size", type=int, default=360)
    args = ap.parse_args(argv)
    game = Platformer()
    frames: list | None = [] if args.gif else None
    play(game, args.until, args.fps, loop.read_keys(args.input) if args.input else [],
         not args.headless, frames)
    if args.gif:
        from max2code.render.items import image
        from max2code.render.write import gif_of
        gif_of(args.gif, frames, lambda f: image(f, args.size, 640, (0.0, 0.0, SIDE)), args.fps)
    if args.events:
        with open(args.events, "w", encoding="utf-8") as f:
            f.writelines(json.dumps(r) + "\n" for r in game.log)
    print(f"platformer: {'goal' if game.won else 'no goal'} at t = {game.world.time:.3f} s, "
          f"coins {game.collected}/{len(COINS)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
