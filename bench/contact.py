"""Dense inelastic collapse (issue 34): the contact solver on and off against pymunk, one run.

    python bench/contact.py [--discs N] [--seconds S] [--large M] [--large_seconds T] [--seed K]
                            [--off 0|1]

N discs (radius 0.15, restitution 0.8 for every contact: sqrt(0.8) on each side, as both
engines multiply) dropped into a 10 m wide bin under gravity settle for S simulated seconds;
then M discs (the large case, 0: none) for T seconds, fewer than S so that its time stays
bounded (M = 2,000 start up to 180 m high and take about 6 s to land).
Rows: ours with the solver off (the rest rule decides), ours with it on (contact_step 1/240 s),
pymunk at dt = 1/60 (10 iterations, its defaults); --off 0 leaves out the solver-off row (it costs
the most: a quicker measurement of the solver). Reported: wall and CPU (process) time
and their ratios to pymunk's, events, the discs that left the bin (through its floor or walls), the worst overlap
at the end among those in it (exact: centre distances), the energy at the end over the start,
how many discs sleep, and whether contact forces can hold the sleepers (the residual of
tests/engine/force_oracle.py, an NNLS fit of non-negative contact forces to the weights: 0 when
they are held, about 1 when nothing holds them), over the contacts within the world's slop (or
1e-6 m, with the solver off): the solver's pairs may rest that far apart or in, and at 1e-6 m
the oracle missed contacts that hold a sleeper (seed 2: 2.9 at 1e-6 m, 0 at the slop's 1e-5 m). Results: bench/results/contact.md (a smoke
run, MAX2CODE_BENCH_SMOKE=1, writes into MAX2CODE_BENCH_RESULTS or nowhere under bench/).
"""

from __future__ import annotations

import argparse
import math
import random
import sys
import time
from dataclasses import dataclass
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from benchtools import command_line, machine_and_date, publish, results_dir, smoke  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
G = 9.81
RADIUS = 0.15
E = math.sqrt(0.8)          # per side: a contact's restitution is the product, 0.8
WIDTH = 10.0
DEFAULTS = {"discs": 200, "seconds": 20.0, "large": 2000, "large_seconds": 8.0, "seed": 1, "off": 1}


@dataclass(frozen=True)
class Row:
    engine: str
    wall: float
    cpu: float              # process time: what a loaded shared machine moves least
    events: int | None
    escaped: int            # discs outside the bin at the end
    overlap: float          # the deepest overlap at the end among the others, m (0: none)
    energy_ratio: float     # energy at the end / at the start
    asleep: int | None
    held: float | None      # the oracle's residual over the sleepers (force / weight)


def height(n: int) -> float:
    """How high the n discs start (at most): room for each to be 0.05 m from the others."""
    return max(4.0, 2.5 * n * (2 * RADIUS) ** 2 / WIDTH * 4)


def wall_top(n: int) -> float:
    """The bin's walls: above every start, so that no disc flies over them (100 m up to about
    1,100 discs)."""
    return max(100.0, 1.2 * height(n))


def starts(n: int, seed: int) -> list[tuple[float, float, float, float]]:
    """n disc centres 0.05 m apart at least, in the bin up to the height they need, and their
    velocities (uniform in [-1, 1] m/s)."""
    rng = random.Random(seed)
    top = height(n)
    out: list[tuple[float, float, float, float]] = []
    while len(out) < n:
        x, y = rng.uniform(RADIUS + 0.05, WIDTH - RADIUS - 0.05), rng.uniform(RADIUS + 0.05, top)
        if all((x - a) ** 2 + (y - b) ** 2 > (2 * RADIUS + 0.05) ** 2 for a, b, _, _ in out):
            out.append((x, y, rng.uniform(-1, 1), rng.uniform(-1, 1)))
    return out


def energy(pos, vel) -> float:
    """Kinetic plus potential (mass 1 each: both engines are given it)."""
    return sum(0.5 * (vx * vx + vy * vy) + G * y for (x, y), (vx, vy) in zip(pos, vel))


def inside(p) -> bool:
    return -RADIUS < p[0] < WIDTH + RADIUS and p[1] > -RADIUS


def deepest(pos) -> float:
    """The deepest overlap among the discs in the bin and against its floor and walls."""
    worst = 0.0
    pos = [p for p in pos if inside(p)]
    for k, (x, y) in enumerate(pos):
        worst = max(worst, RADIUS - y, RADIUS - x, x - (WIDTH - RADIUS))
        for a, b in pos[k + 1:]:
            if abs(a - x) < 2 * RADIUS and abs(b - y) < 2 * RADIUS:
                worst = max(worst, 2 * RADIUS - math.hypot(a - x, b - y))
    return worst


def ours(discs, seconds: float, step: float) -> Row:
    from max2code.engine import World

    w = World(gravity=(0.0, -G), contact_step=step)
    top = wall_top(len(discs))
    for a, b in (((0.0, 0.0), (WIDTH, 0.0)), ((0.0, 0.0), (0.0, top)), ((WIDTH, 0.0), (WIDTH, top))):
        w.add_segment(a, b, restitution=E)
    ids = [w.add_circle((x, y), RADIUS, velocity=(vx, vy), mass=1.0, restitution=E)
           for x, y, vx, vy in discs]
    e0 = energy([(x, y) for x, y, _, _ in discs], [(vx, vy) for _, _, vx, vy in discs])
    t0, c0 = time.perf_counter(), time.process_time()
    w.step_to(seconds, events=False)
    wall, cpu = time.perf_counter() - t0, time.process_time() - c0
    pos = [w.pose(i)[:2] for i in ids]
    vel = [w.velocity(i)[:2] for i in ids]
    name = f"ours, solver on (h = 1/{round(1 / step)})" if step > 0 else "ours, solver off"
    sys.path.insert(0, str(ROOT / "tests" / "engine"))
    from force_oracle import sleeping_residual

    asleep = sum(w.asleep(i) for i in ids)
    return Row(name, wall, cpu, int(w.stats()["events"]), sum(not inside(p) for p in pos),
               deepest(pos), energy(pos, vel) / e0, asleep,
               sleeping_residual(w, max(w.contact_slop, 1e-6)) if asleep else None)


def theirs(discs, seconds: float) -> Row:
    import pymunk

    space = pymunk.Space()
    space.gravity = (0.0, -G)
    top = wall_top(len(discs))
    for a, b in (((0.0, 0.0), (WIDTH, 0.0)), ((0.0, 0.0), (0.0, top)), ((WIDTH, 0.0), (WIDTH, top))):
        seg = pymunk.Segment(space.static_body, a, b, 0.0)
        seg.elasticity = E
        space.add(seg)
    bodies = []
    for x, y, vx, vy in discs:
        body = pymunk.Body(1.0, pymunk.moment_for_circle(1.0, 0, RADIUS))
        body.position = (x, y)
        body.velocity = (vx, vy)
        shape = pymunk.Circle(body, RADIUS)
        shape.elasticity = E
        space.add(body, shape)
        bodies.append(body)
    e0 = energy([(x, y) for x, y, _, _ in discs], [(vx, vy) for _, _, vx, vy in discs])
    steps = round(seconds * 60)
    t0, c0 = time.perf_counter(), time.process_time()
    for _ in range(steps):
        space.step(1 / 60)
    wall, cpu = time.perf_counter() - t0, time.process_time() - c0
    pos = [tuple(b.position) for b in bodies]
    vel = [tuple(b.velocity) for b in bodies]
    return Row(f"pymunk {pymunk.version}, dt = 1/60", wall, cpu, None,
               sum(not inside(p) for p in pos), deepest(pos), energy(pos, vel) / e0, None, None)


def table(discs, seconds: float, off: bool = True) -> list[str]:
    """One size: ours with the solver off (unless not `off`) and on, and pymunk, in one run."""
    rows = ([ours(discs, seconds, 0.0)] if off else []) + [ours(discs, seconds, 1 / 240),
                                                           theirs(discs, seconds)]
    base, cbase = rows[-1].wall, rows[-1].cpu
    lines = [f"**{len(discs)} discs, {seconds:g} s**", "",
             "| engine | wall s | x pymunk | CPU s | x pymunk | events | left the bin | worst overlap m | "
             "energy end/start | asleep | sleepers' force residual |",
             "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        ev = "-" if r.events is None else str(r.events)
        asleep = "-" if r.asleep is None else f"{r.asleep}/{len(discs)}"
        held = "-" if r.held is None else f"{r.held:.2g}"
        lines.append(f"| {r.engine} | {r.wall:.3f} | {r.wall / base:.2f} | {r.cpu:.3f} | "
                     f"{r.cpu / cbase:.2f} | {ev} | {r.escaped} | "
                     f"{r.overlap:.2e} | {r.energy_ratio:.4f} | {asleep} | {held} |")
    return lines + [""]


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--discs", type=int, default=DEFAULTS["discs"])
    ap.add_argument("--seconds", type=float, default=DEFAULTS["seconds"])
    ap.add_argument("--large", type=int, default=DEFAULTS["large"])
    ap.add_argument("--large_seconds", type=float, default=DEFAULTS["large_seconds"])
    ap.add_argument("--seed", type=int, default=DEFAULTS["seed"])
    ap.add_argument("--off", type=int, choices=(0, 1), default=DEFAULTS["off"],
                    help="1: the solver-off row too (the default); 0: not")
    args = ap.parse_args(argv)
    if smoke():
        args.discs, args.seconds, args.large, args.large_seconds = 12, 1.0, 20, 0.5
    lines = ["# Dense inelastic collapse: the contact solver on and off, and pymunk "
             "(bench/contact.py)", "",
             f"`{command_line('bench/contact.py', args, DEFAULTS)}`: discs (r = {RADIUS}, "
             f"e = 0.8 per contact) settling in a {WIDTH:g} m bin; {machine_and_date()}. "
             "Wall and CPU (process) times on a shared machine: read the ratios, measured in one "
             "run; the CPU ones move least with its load.", ""]
    lines += table(starts(args.discs, args.seed), args.seconds, bool(args.off))
    if args.large > 0:
        lines += table(starts(args.large, args.seed), args.large_seconds, bool(args.off))
    out = results_dir(ROOT / "bench" / "results")
    if smoke() and out == ROOT / "bench" / "results":
        print("\n".join(lines))
        return 0
    publish(out, "contact.md", "\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())
