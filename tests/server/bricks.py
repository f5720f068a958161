"""A world whose bodies come and go while it runs, for the protocol's rm/add tests: a ball in a
box of walls hits a row of bricks; each brick hit is removed in the collision callback and a
"chip" (a small dynamic circle) is added where it was, falling; a timer adds a second ball at
a known time and removes the first chip some time after it appeared. Everything through the
engine's game API (docs/game-api.md), so the same function builds the server's world and the
tests' independent reference."""

from __future__ import annotations

from max2code.engine import World
from max2code.engine.scenefile import Scene

SQUARE = [(-0.2, -0.1), (0.2, -0.1), (0.2, 0.1), (-0.2, 0.1)]
VIEW = (-3.0, -3.0, 3.0, 3.0)
BRICKS = 5
ADD_BALL_AT = 0.7
REMOVE_CHIP_AFTER = 0.4


def build() -> World:
    w = World(gravity=(0.0, -2.0))
    for a, b in (((-3, -3), (3, -3)), ((3, -3), (3, 3)), ((3, 3), (-3, 3)), ((-3, 3), (-3, -3))):
        w.add_segment(a, b, name="wall")
    bricks = {w.add_polygon(SQUARE, kind="static", position=(-2 + k, 2.0), name=f"brick{k}")
              for k in range(BRICKS)}
    w.add_circle((-2.0, -1.0), 0.15, velocity=(0.3, 6.0), name="ball", restitution=1.0)
    chips: list[int] = []

    def remove_chip(world: World, ev) -> None:
        if chips and world.alive(chips[0]):
            world.remove(chips[0])

    def hit(world: World, ev) -> None:
        for i in (ev.a, ev.b):
            if i in bricks and world.alive(i):
                x, y, _ = world.pose(i)
                world.remove(i)
                chips.append(world.add_circle((x, y), 0.05, name=f"chip{len(chips)}", restitution=0.5))
                if len(chips) == 1:
                    world.add_timer(world.time + REMOVE_CHIP_AFTER, remove_chip)

    def add_ball(world: World, ev) -> None:
        world.add_circle((1.5, -2.0), 0.15, velocity=(-0.5, 5.0), name="ball2", restitution=1.0)

    w.on_collision(hit)
    w.add_timer(ADD_BALL_AT, add_ball)
    return w


def scene() -> Scene:
    """The room's scene: only its view (the world comes from build)."""
    return Scene(name="bricks", bodies=(), view=VIEW)


def alive(world: World) -> set[int]:
    return {i for i in range(len(world.bodies)) if world.bodies[i].alive}
