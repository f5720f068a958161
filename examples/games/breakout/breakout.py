#!/usr/bin/env python3
"""Breakout on max2code.engine, written as a pymunk user would write it: a World, static walls and
bricks, a dynamic ball, a kinematic paddle steered by the keys, a collision callback that
removes the brick the ball hit. Nothing is checked frame by frame: every bounce happens at its
predicted time, and the paddle stops at a wall by a timer set for the instant it gets there.

    python breakout.py                       # play: Left/Right move the paddle, Escape quits
    python breakout.py --headless --autopilot --until 60 --gif breakout.gif
    python breakout.py --headless --input keys.jsonl --events log.jsonl

--autopilot steers the paddle itself: whenever the ball changes course it works out where the
ball will cross the paddle's line (straight flight, folded at the side walls) and sends the
paddle there. --input takes timed keys, one JSON object a line: {"t": 1.5, "type": "KEYDOWN",
"key": "K_LEFT"} (KEYUP releases); the run's --events log replays with --input.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from dataclasses import dataclass, field

from max2code.engine import World, loop
from max2code.render.items import Frame, Item, body_item

WIDTH, HEIGHT = 10.0, 10.0
PADDLE_Y, PADDLE_W, PADDLE_H, PADDLE_SPEED = 0.6, 1.6, 0.25, 8.0
BALL_R, BALL_SPEED = 0.15, 7.0
ROWS, COLS, BRICK_H = 5, 9, 0.4
COLOURS = {"wall": (120, 90, 40, 255), "brick": (40, 80, 200, 255), "paddle": (230, 160, 40, 255),
           "ball": (240, 240, 240, 255)}


def box(w: float, h: float) -> list[tuple[float, float]]:
    return [(-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2)]


@dataclass
class Breakout:
    """The game's state around its World: which body is what, the score, the paddle's plan."""
    world: World = field(default_factory=lambda: World(gravity=(0.0, 0.0)))
    bricks: set[int] = field(default_factory=set)
    kinds: dict[int, str] = field(default_factory=dict)
    score: int = 0
    lost: bool = False
    stop_timer: int | None = None
    autopilot: bool = False
    log: list[dict] = field(default_factory=list)

    def __post_init__(self) -> None:
        w = self.world
        for a, b in (((0, 0), (0, HEIGHT)), ((WIDTH, 0), (WIDTH, HEIGHT)), ((0, HEIGHT), (WIDTH, HEIGHT))):
            self.kinds[w.add_segment(a, b, name="wall")] = "wall"
        self.floor = w.add_segment((0, -1.0), (WIDTH, -1.0), name="floor")
        self.kinds[self.floor] = "floor"
        bw = WIDTH / COLS
        for row in range(ROWS):
            for col in range(COLS):
                i = w.add_polygon(box(bw - 0.1, BRICK_H - 0.1), kind="static",
                                  position=((col + 0.5) * bw, HEIGHT - 1.5 - row * BRICK_H),
                                  name=f"brick-{row}-{col}")
                self.bricks.add(i)
                self.kinds[i] = "brick"
        self.paddle = w.add_polygon(box(PADDLE_W, PADDLE_H), kind="kinematic",
                                    position=(WIDTH / 2, PADDLE_Y), name="paddle")
        self.kinds[self.paddle] = "paddle"
        self.ball = w.add_circle((WIDTH / 2, 2.0), BALL_R, name="ball",
                                 velocity=(BALL_SPEED * 0.6, BALL_SPEED * 0.8), restitution=1.0)
        self.kinds[self.ball] = "ball"
        w.on_collision(self.collided)

    # -- the rules ---------------------------------------------------------------------------

    def collided(self, world: World, ev) -> None:
        if ev.kind != "collision":
            return
        other = ev.b if ev.a == self.ball else ev.a
        kind = self.kinds.get(other)
        self.log.append({"t": ev.time, "kind": "collision", "with": world.bodies[other].name})
        if kind == "brick":
            world.remove(other)           # gone at once: the ball's next prediction skips it
            self.bricks.discard(other)
            self.score += 1
        elif kind == "paddle":
            # where it hit the paddle sets the angle, as in every breakout
            px = world.pose(self.paddle)[0]
            bx, _, _ = world.pose(self.ball)
            u = max(-0.8, min(0.8, (bx - px) / (PADDLE_W / 2)))
            world.set_velocity(self.ball, (BALL_SPEED * u, BALL_SPEED * math.sqrt(1 - u * u)))
        elif kind == "floor":
            self.lost = True
        if self.autopilot:
            self.aim()

    # -- the paddle --------------------------------------------------------------------------

    def steer(self, direction: int) -> None:
        """Move the paddle left (-1), right (+1) or stop (0) now; it stops at the walls by a
        timer at the instant it reaches them."""
        w = self.world
        if self.stop_timer is not None:
            w.cancel_timer(self.stop_timer)
            self.stop_timer = None
        w.set_velocity(self.paddle, (PADDLE_SPEED * direction, 0.0))
        if direction:
            x = w.pose(self.paddle)[0]
            edge = (WIDTH - PADDLE_W / 2) if direction > 0 else PADDLE_W / 2
            self.go_until(w.time + abs(edge - x) / PADDLE_SPEED)

    def go_until(self, t: float) -> None:
        def stop(world, ev):
            self.stop_timer = None
            world.set_velocity(self.paddle, (0.0, 0.0))
        self.stop_timer = self.world.add_timer(t, stop)

    def aim(self) -> None:
        """Autopilot (after every bounce of the ball): send the paddle to where the ball will
        come down, placed so that the bounce sends the ball towards the lowest brick left."""
        w = self.world
        bx, by, _ = w.pose(self.ball)
        vx, vy, _ = w.velocity(self.ball)
        if vy >= 0 or not self.bricks:
            return
        y_hit = PADDLE_Y + PADDLE_H / 2 + BALL_R
        t = (by - y_hit) / -vy
        span = WIDTH - 2 * BALL_R
        x = (bx + vx * t - BALL_R) % (2 * span)
        x = BALL_R + (x if x <= span else 2 * span - x)   # folded at the side walls
        tx, ty, _ = min((w.pose(b) for b in self.bricks), key=lambda p: (p[1], abs(p[0] - x)))
        k = (tx - x) / (ty - y_hit)
        u = max(-0.75, min(0.75, k / math.sqrt(1 + k * k)))
        target = min(max(x - u * PADDLE_W / 2, PADDLE_W / 2), WIDTH - PADDLE_W / 2)
        px = w.pose(self.paddle)[0]
        if self.stop_timer is not None:
            w.cancel_timer(self.stop_timer)
            self.stop_timer = None
        if abs(target - px) < 1e-9:
            w.set_velocity(self.paddle, (0.0, 0.0))
            return
        direction = 1 if target > px else -1
        w.set_velocity(self.paddle, (PADDLE_SPEED * direction, 0.0))
        self.go_until(w.time + abs(target - px) / PADDLE_SPEED)

    # -- frames ------------------------------------------------------------------------------

    def frame(self) -> Frame:
        w = self.world
        items = [body_item(info.vertices, info.radius, w.pose(i), COLOURS[self.kinds[i]])
                 for i, info in enumerate(w.bodies) if w.alive(i) and self.kinds[i] != "floor"]
        items.append(Item("text", (255, 255, 255, 255), ((0.3, 9.7),), text=f"score {self.score}",
                          size=28))
        return Frame(w.time, tuple(items))


def play(game: Breakout, until: float, fps: float, keys, autopilot: bool, live: bool,
         frames: list[Frame] | None) -> None:
    """Frames at 1/fps; key events at their times (scripted) or the frame after they came (live)."""
    pressed = {"K_LEFT": -1, "K_RIGHT": 1}
    held: list[str] = []
    game.autopilot = autopilot
    if autopilot:
        game.aim()
    window = picture = None
    if live:
        from max2code.render.items import image
        from max2code.render.live import Window
        window = Window(640, 640, "breakout (max2code.engine)")
        picture = lambda f: image(f, 640, 640, (0.0, 0.0, WIDTH))  # noqa: E731

    def from_window(e):
        import pygame
        if e.type in (pygame.KEYDOWN, pygame.KEYUP) and e.key in (pygame.K_LEFT, pygame.K_RIGHT):
            return pygame.event.event_name(e.type).upper(), "K_" + pygame.key.name(e.key).upper()
        return None

    shown = loop.play(game.world, game.frame, until=until, fps=fps, script=keys,
                      deliver=lambda item: handle_key(game, held, pressed, *item),
                      done=lambda: game.lost or not game.bricks, keep=frames is not None,
                      window=window, picture=picture, from_window=from_window)
    if frames is not None:
        frames.extend(shown)


def handle_key(game: Breakout, held: list[str], pressed: dict, kind: str, key: str) -> None:
    if key not in pressed:
        return
    game.log.append({"t": game.world.time, "kind": "input", "type": kind, "key": key})
    if kind == "KEYDOWN" and key not in held:
        held.append(key)
    elif kind == "KEYUP" and key in held:
        held.remove(key)
    game.steer(pressed[held[-1]] if held else 0)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--headless", action="store_true")
    ap.add_argument("--autopilot", action="store_true")
    ap.add_argument("--until", type=float, default=120.0)
    ap.add_argument("--fps", type=float, default=60.0)
    ap.add_argument("--input", help="timed keys (JSON lines)")
    ap.add_argument("--events", help="write the event log (JSON lines)")
    ap.add_argument("--gif", help="an animated GIF of the frames")
    args = ap.parse_args(argv)
    game = Breakout()
    frames: list[Frame] | None = [] if args.gif else None
    play(game, args.until, args.fps, loop.read_keys(args.input) if args.input else [], args.autopilot,
         not args.headless, frames)
    if args.gif:
        from max2code.render.items import image
        from max2code.render.write import gif_of
        gif_of(args.gif, frames, lambda f: image(f, 320, 640, (0.0, 0.0, WIDTH)), args.fps)
    if args.events:
        with open(args.events, "w", encoding="utf-8") as f:
            f.writelines(json.dumps(r) + "\n" for r in game.log)
    outcome = "cleared" if not game.bricks else ("lost" if game.lost else "time up")
    print(f"breakout: {outcome} at t = {game.world.time:.3f} s, score {game.score}, "
          f"{game.world.stats()['collisions']} collisions")
    return 0


if __name__ == "__main__":
    sys.exit(main())
