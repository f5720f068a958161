"""A game frame's cost: the predictive engine against pymunk at dt = 1/60, on the same scenes.

    python bench/games.py [--seconds S] [-o bench/results/games.md]

Scenes: the breakout of examples/games/breakout (45 bricks removed as they are hit, a kinematic
paddle on autopilot), the platformer of examples/games/platformer (its scripted run to the
goal), and PGE's snooker table (../shared/corpus/pge-python/examples/snooker-snooker.py: a ball
under gravity among two triangles, elastic; without the game's 1.15 speed-up at the triangles,
which makes any engine's speed grow without bound). A frame is what a game loop does 60 times a
second: ours steps the World to the frame's time (every event before it, at its time) and
reads every pose; pymunk makes one step of 1/60 s and reads every pose. Per frame: the events
ours processed (all kinds: collisions, timers, cell crossings, ...) and the wall time.

Churn: a box of N bouncing discs where every frame one disc is removed and a new one added:
the cost per event stays flat in N (the prediction of a body is against its cell's neighbours,
and a removal or an addition re-predicts only the bodies it touches).
"""

from __future__ import annotations

import argparse
import importlib.util
import math
import platform
import random
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
FPS = 60.0


def load_example(name: str):
    path = ROOT / "examples" / "games" / name / f"{name}.py"
    spec = importlib.util.spec_from_file_location(f"example_{name}", path)
    mod = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = mod
    spec.loader.exec_module(mod)
    return mod


def frames_of(step, seconds: float, events=None) -> dict:
    """Run step(k) for every frame k of `seconds` at FPS; the wall time of each frame and, when
    `events()` counts them, the events between frames."""
    walls, counts = [], []
    last = events() if events else 0
    n = int(seconds * FPS)
    for k in range(1, n + 1):
        t0 = time.perf_counter()
        if step(k) is False:
            break
        walls.append(time.perf_counter() - t0)
        if events:
            e = events()
            counts.append(e - last)
            last = e
    return {"frames": len(walls), "walls": walls, "events": counts}


# -- breakout -----------------------------------------------------------------------------------

def ours_breakout(seconds: float) -> dict:
    bo = load_example("breakout")
    game = bo.Breakout(autopilot=True)
    game.aim()
    w = game.world

    def step(k: int):
        w.step_to(k / FPS)
        w.poses()
        return not game.lost and bool(game.bricks)

    r = frames_of(step, seconds, lambda: w.stats()["events"])
    r["outcome"] = f"{45 - len(game.bricks)} bricks" + (", ball lost" if game.lost else "")
    return r


def pymunk_breakout(seconds: float) -> dict:
    import pymunk

    bo = load_example("breakout")
    space = pymunk.Space()
    space.gravity = (0, 0)
    walls = [((0, 0), (0, bo.HEIGHT)), ((bo.WIDTH, 0), (bo.WIDTH, bo.HEIGHT)),
             ((0, bo.HEIGHT), (bo.WIDTH, bo.HEIGHT))]
    for a, b in walls:
        s = pymunk.Segment(space.static_body, a, b, 0.0)
        s.elasticity = 1.0
        space.add(s)
    bricks = set()
    bw = bo.WIDTH / bo.COLS
    for row in range(bo.ROWS):
        for col in range(bo.COLS):
            body = pymunk.Body(body_type=pymunk.Body.STATIC)
            body.position = ((col + 0.5) * bw, bo.HEIGHT - 1.5 - row * bo.BRICK_H)
            s = pymunk.Poly(body, bo.box(bw - 0.1, bo.BRICK_H - 0.1))
            s.elasticity, s.collision_type = 1.0, 2
            space.add(body, s)
            bricks.add(s)
    paddle = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    paddle.position = (bo.WIDTH / 2, bo.PADDLE_Y)
    ps = pymunk.Poly(paddle, bo.box(bo.PADDLE_W, bo.PADDLE_H))
    ps.elasticity, ps.collision_type = 1.0, 3
    space.add(paddle, ps)
    ball = pymunk.Body(1.0, pymunk.moment_for_circle(1.0, 0, bo.BALL_R))
    ball.position = (bo.WIDTH / 2, 2.0)
    ball.velocity = (bo.BALL_SPEED * 0.6, bo.BALL_SPEED * 0.8)
    bs = pymunk.Circle(ball, bo.BALL_R)
    bs.elasticity, bs.collision_type = 1.0, 1
    space.add(ball, bs)

    def hit_brick(arbiter, space, data):
        brick = arbiter.shapes[1]
        if brick in bricks:
            bricks.discard(brick)
            space.add_post_step_callback(lambda sp, key, s: sp.remove(s.body, s), brick, brick)

    def hit_paddle(arbiter, space, data):
        u = max(-0.8, min(0.8, (ball.position.x - paddle.position.x) / (bo.PADDLE_W / 2)))
        ball.velocity = (bo.BALL_SPEED * u, bo.BALL_SPEED * math.sqrt(1 - u * u))

    space.on_collision(1, 2, post_solve=hit_brick)
    space.on_collision(1, 3, post_solve=hit_paddle)

    def step(k: int):
        # the same autopilot, checked every frame (pymunk has no event to hang it on)
        vx, vy = ball.velocity
        target = paddle.position.x
        if vy < 0:
            t = (ball.position.y - bo.BALL_R - bo.PADDLE_Y - bo.PADDLE_H / 2) / -vy
            span = bo.WIDTH - 2 * bo.BALL_R
            x = (ball.position.x + vx * t - bo.BALL_R) % (2 * span)
            x = bo.BALL_R + (x if x <= span else 2 * span - x)
            y_hit = bo.PADDLE_Y + bo.PADDLE_H / 2 + bo.BALL_R
            if bricks:   # aimed at the lowest brick left, as the example's autopilot does
                tx, ty = min((tuple(b.body.position) for b in bricks), key=lambda p: (p[1], abs(p[0] - x)))
                k = (tx - x) / (ty - y_hit)
                u = max(-0.75, min(0.75, k / math.sqrt(1 + k * k)))
                x -= u * bo.PADDLE_W / 2
            target = min(max(x, bo.PADDLE_W / 2), bo.WIDTH - bo.PADDLE_W / 2)
        d = target - paddle.position.x
        paddle.velocity = (math.copysign(min(bo.PADDLE_SPEED, abs(d) * FPS), d), 0)
        space.step(1 / FPS)
        [b.position for b in space.bodies]
        return ball.position.y > -1.0 and bool(bricks)

    r = frames_of(step, seconds)
    r["outcome"] = f"{45 - len(bricks)} bricks" + (", ball lost" if ball.position.y <= -1.0 else "")
    return r


# -- snooker (PGE's table) ----------------------------------------------------------------------

BORDER, BALL_R = 0.01, 0.05
TRIANGLES = (((0.2, 0.3), (0.4, 0.3), (0.3, 0.4)), ((0.6, 0.3), (0.8, 0.3), (0.7, 0.4)))


def _borders():
    t = BORDER
    return [(0.0, 0.0, 1.0, t), (0.0, 0.0, t, 1.0), (1.0 - t, 0.0, t, 1.0), (0.0, 1.0 - t, 1.0, t)]


def _rect(x, y, w, h):
    return [(x, y), (x + w, y), (x + w, y + h), (x, y + h)]


def ours_snooker(seconds: float) -> dict:
    from max2code.engine import World

    w = World(gravity=(0.0, -9.81))
    for b in _borders():
        w.add_polygon(_rect(*b), kind="static")
    for tri in TRIANGLES:
        w.add_polygon(list(tri), kind="static")
    w.add_circle((0.19, 0.8), BALL_R, mass=1.25, restitution=1.0)

    def step(k: int):
        w.step_to(k / FPS)
        w.poses()

    r = frames_of(step, seconds, lambda: w.stats()["events"])
    r["outcome"] = f"{w.stats()['collisions']} bounces"
    return r


def pymunk_snooker(seconds: float) -> dict:
    import pymunk

    space = pymunk.Space()
    space.gravity = (0, -9.81)
    for poly in [_rect(*b) for b in _borders()] + [list(t) for t in TRIANGLES]:
        s = pymunk.Poly(space.static_body, poly)
        s.elasticity = 1.0
        space.add(s)
    ball = pymunk.Body(1.25, pymunk.moment_for_circle(1.25, 0, BALL_R))
    ball.position = (0.19, 0.8)
    s = pymunk.Circle(ball, BALL_R)
    s.elasticity = 1.0
    space.add(ball, s)
    hits = [0]
    space.on_collision(None, None, begin=lambda a, sp, d: hits.__setitem__(0, hits[0] + 1))

    def step(k: int):
        space.step(1 / FPS)
        [b.position for b in space.bodies]

    r = frames_of(step, seconds)
    r["outcome"] = f"{hits[0]} bounces" + ("" if 0 < ball.position.x < 1 and 0 < ball.position.y < 1
                                          else ", ball left the table")
    return r


# -- platformer ---------------------------------------------------------------------------------

def ours_platformer(seconds: float) -> dict:
    pf = load_example("platformer")
    game = pf.Platformer()
    from max2code.engine import loop
    script = loop.read_keys(str(pf.SCRIPT))
    w = game.world
    queue = list(script)

    def step(k: int):
        t = k / FPS
        while queue and queue[0][0] <= t:
            tk, (kind, key) = queue.pop(0)
            w.step_to(tk)
            game.key(kind, key)
        w.step_to(t)
        w.poses()
        return not game.won

    r = frames_of(step, seconds, lambda: w.stats()["events"])
    r["outcome"] = ("goal" if game.won else "no goal") + f", {game.collected} coins"
    return r


def pymunk_platformer(seconds: float) -> dict:
    """The platformer's level in pymunk at 1/60, played by the same timed keys (applied at the
    first frame at or after their time): a walk sets the player's horizontal speed every frame
    while a key is held, a jump adds JUMP to its vertical speed when a contact holds it from
    below, a one-way platform's pre-solve rejects the contact unless the feet come down onto
    it, coins and the goal are sensors, and the lift is a kinematic body on the same
    timetable."""
    import pymunk
    from max2code.engine import loop

    pf = load_example("platformer")
    space = pymunk.Space()
    space.gravity = (0, -pf.G)
    PLAYER, GROUND, ONEWAY, SENSOR = 1, 2, 3, 4

    def box_shape(body, box, offset=(0.0, 0.0)):
        x0, y0, x1, y1 = box
        r = pf.ROUND
        pts = [(x - offset[0], y - offset[1])
               for x, y in pf.rect(x0 + r, y0 + r, x1 - r, y1 - r)]
        return pymunk.Poly(body, pts, radius=r)

    tops = {}
    for kind, *box in pf.BOXES:
        s = box_shape(space.static_body, box)
        s.friction, s.collision_type = 0.0, (ONEWAY if kind == "oneway" else GROUND)
        space.add(s)
        tops[s] = box[3]
    x0, x1, h = pf.LIFT
    lift = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    lift.position = (0.0, pf.LIFT_LOW)
    ls = box_shape(lift, (x0, -h, x1, 0))
    ls.friction, ls.collision_type = 0.0, GROUND
    space.add(lift, ls)
    sensors = {}
    for (x, y), what, r in [(c, "coin", 0.25) for c in pf.COINS] + [(pf.GOAL, "goal", 0.5)]:
        s = pymunk.Circle(space.static_body, r, (x, y))
        s.sensor, s.collision_type = True, SENSOR
        space.add(s)
        sensors[s] = what
    player = pymunk.Body(1.0, pymunk.moment_for_circle(1.0, 0, pf.RADIUS))
    player.position = (1.5, 1.0 + pf.RADIUS)
    ps = pymunk.Circle(player, pf.RADIUS)
    ps.friction, ps.elasticity, ps.collision_type = 0.0, 0.0, PLAYER
    space.add(player, ps)
    state = {"coins": 0, "won": False, "held": []}

    def sensed(arbiter, space, data):
        s = arbiter.shapes[1]
        if sensors.get(s) == "coin":
            state["coins"] += 1
            del sensors[s]
            space.add_post_step_callback(lambda sp, key: sp.remove(key), s)
        elif sensors.get(s) == "goal":
            state["won"] = True

    def one_way(arbiter, space, data):
        top = tops[arbiter.shapes[1]]
        arbiter.process_collision = (player.velocity.y <= 0
                                     and player.position.y - pf.RADIUS >= top - 0.05)

    space.on_collision(PLAYER, SENSOR, begin=sensed)
    space.on_collision(PLAYER, ONEWAY, pre_solve=one_way)

    def standing() -> bool:
        below = []
        player.each_arbiter(lambda arb: below.append(
            arb.process_collision and not arb.is_removal
            and arb.contact_point_set.normal.y * (1 if arb.shapes[0] is ps else -1) < -0.7))
        return any(below)

    cycle = sum(s for _, s in pf.LIFT_PHASES)

    def lift_speed(t: float) -> float:
        t %= cycle
        for v, s in pf.LIFT_PHASES:
            if t < s:
                return v
            t -= s
        return 0.0

    queue = loop.read_keys(str(pf.SCRIPT))   # (the reader ours_platformer uses)

    def step(k: int):
        t = k / FPS
        while queue and queue[0][0] <= t:
            _, (kind, key) = queue.pop(0)
            held = state["held"]
            if key in ("K_LEFT", "K_RIGHT"):
                if kind == "KEYDOWN" and key not in held:
                    held.append(key)
                elif kind == "KEYUP" and key in held:
                    held.remove(key)
            elif key in ("K_UP", "K_SPACE") and kind == "KEYDOWN" and standing():
                player.velocity = (player.velocity.x, player.velocity.y + pf.JUMP)
        held = state["held"]
        d = (1 if held[-1] == "K_RIGHT" else -1) if held else 0
        player.velocity = (pf.WALK * d, player.velocity.y)
        lift.velocity = (0.0, lift_speed(t - 1 / FPS))
        space.step(1 / FPS)
        [b.position for b in space.bodies]
        return not state["won"]

    r = frames_of(step, seconds)
    r["outcome"] = ("goal" if state["won"] else "no goal") + f", {state['coins']} coins"
    return r


# -- churn --------------------------------------------------------------------------------------

def ours_churn(n: int, seconds: float, seed: int = 1) -> dict:
    """N discs in a 20 x 20 box; every frame the oldest disc is removed and a new one added."""
    from max2code.engine import World

    rng = random.Random(seed)
    side = 20.0
    w = World(gravity=(0.0, 0.0))
    for a, b in (((0, 0), (side, 0)), ((side, 0), (side, side)), ((side, side), (0, side)),
                 ((0, side), (0, 0))):
        w.add_segment(a, b)
    r = 0.05
    alive: list[int] = []
    # a grid of places, one per disc, spaced so no two start overlapping
    cols = math.ceil(math.sqrt(2 * n))
    places = [((i + 0.5) * side / cols, (j + 0.5) * side / cols) for i in range(cols) for j in range(cols)]

    def add(p):
        v = (rng.uniform(-2, 2), rng.uniform(-2, 2))
        alive.append(w.add_circle(p, r, velocity=v, restitution=1.0))

    for p in places[:n]:
        add(p)

    walls, counts = [], []
    last = w.stats()["events"]
    for k in range(1, int(seconds * FPS) + 1):
        # the new disc's place (not timed: the game's own choice, a scan of every disc here):
        # the farthest of a few random points from every alive disc at the frame's time
        t = k / FPS
        poses = w.poses()
        best, gap = None, -1.0
        for _ in range(8):
            p = (rng.uniform(1, side - 1), rng.uniform(1, side - 1))
            d = min(math.hypot(p[0] - poses[i][0], p[1] - poses[i][1]) for i in alive)
            if d > gap:
                best, gap = p, d
        t0 = time.perf_counter()
        w.step_to(t)
        w.remove(alive.pop(0))
        if gap > 4 * r + 2 * 2 * math.sqrt(2) / FPS:  # (clear of every disc's reach in a frame)
            add(best)
        w.poses()
        walls.append(time.perf_counter() - t0)
        e = w.stats()["events"]
        counts.append(e - last)
        last = e
    return {"frames": len(walls), "walls": walls, "events": counts, "n": n}


def slope_us(r: dict) -> float:
    """The cost of one more event in a frame: the least-squares slope of a frame's wall time
    over its events (the frame's fixed costs, its removal and addition, in the intercept)."""
    xs, ys = r["events"], r["walls"]
    mx, my = statistics.fmean(xs), statistics.fmean(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    return 1e6 * sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx else float("nan")


# -- report -------------------------------------------------------------------------------------

def summary(r: dict) -> dict:
    ms = [1e3 * x for x in r["walls"]]
    ms_sorted = sorted(ms)
    out = {"frames": r["frames"], "ms_mean": statistics.fmean(ms), "ms_p99": ms_sorted[int(0.99 * (len(ms) - 1))],
           "ms_max": ms_sorted[-1], "outcome": r.get("outcome", "")}
    if r["events"]:
        out["ev_mean"] = statistics.fmean(r["events"])
        out["ev_max"] = max(r["events"])
        total = sum(r["events"])
        out["us_per_event"] = 1e6 * sum(r["walls"]) / total if total else float("nan")
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seconds", type=float, default=30.0, help="simulated seconds per scene")
    ap.add_argument("--churn", default="16,64,256,1024", help="disc counts of the churn scene")
    ap.add_argument("-o", "--output", default=str(ROOT / "bench" / "results" / "games.md"))
    args = ap.parse_args(argv)
    import pymunk

    rows = []
    scenes = [("breakout", ours_breakout, pymunk_breakout), ("snooker (PGE)", ours_snooker, pymunk_snooker)]
    if (ROOT / "examples" / "games" / "platformer" / "platformer.py").exists():
        scenes.append(("platformer", ours_platformer, pymunk_platformer))
    for name, ours, theirs in scenes:
        rows.append((name, "ours (predictive)", summary(ours(args.seconds))))
        if theirs:
            rows.append((name, "pymunk 1/60", summary(theirs(args.seconds))))
    churn = []
    for n in args.churn.split(","):
        r = ours_churn(int(n), min(args.seconds, 10.0))
        churn.append(summary(r) | {"n": int(n), "slope": slope_us(r)})
    lines = ["# A game frame's cost (bench/games.py)", "",
             f"`python bench/games.py --seconds {args.seconds:g} --churn {args.churn}` on "
             f"{platform.machine()}, Python {platform.python_version()}, pymunk {pymunk.version}. "
             "A frame: ours steps the World to the frame's time and reads every pose; pymunk steps "
             "1/60 s and reads every pose. Events: everything ours processed between two frames "
             "(collisions, timers, cell crossings, window ends).", "",
             "| scene | engine | frames | events/frame mean | max | wall ms/frame mean | p99 | max | us/event | outcome |",
             "|---|---|---:|---:|---:|---:|---:|---:|---:|---|"]
    for name, engine, s in rows:
        ev = (f"{s['ev_mean']:.2f} | {s['ev_max']} " if "ev_mean" in s else "- | - ")
        per = f"{s['us_per_event']:.1f}" if "us_per_event" in s else "-"
        lines.append(f"| {name} | {engine} | {s['frames']} | {ev}| {s['ms_mean']:.3f} | {s['ms_p99']:.3f} | "
                     f"{s['ms_max']:.3f} | {per} | {s['outcome']} |")
    lines += ["", "## Churn: one disc removed and one added every frame", "",
              "Timed: the step to the frame, the removal, the addition and the poses' reading "
              "(not the choice of a free place). us/event: wall time over events; marginal: the "
              "least-squares slope of a frame's time over its events (the frame's fixed costs "
              "are the intercept).", "",
              "| discs | frames | events/frame mean | wall ms/frame mean | us/event | marginal us/event |",
              "|---:|---:|---:|---:|---:|---:|"]
    for s in churn:
        lines.append(f"| {s['n']} | {s['frames']} | {s['ev_mean']:.1f} | {s['ms_mean']:.3f} | "
                     f"{s['us_per_event']:.1f} | {s['slope']:.1f} |")
    text = "\n".join(lines) + "\n"
    Path(args.output).write_text(text)
    print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
