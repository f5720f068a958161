"""Timers are a heap (issue 33, item 8): adding and firing are O(log n).

The sorted array they replace shifted every pending timer on each firing (and on each
insertion out of order): 300,000 timers took minutes, 10^6 did not finish."""

from __future__ import annotations

import gc
import random
import time


def test_many_timers_fire_in_order_quickly(engine):
    w = engine.World()
    w.add_circle((0, 0), 1.0)
    rng = random.Random(7)
    n = 300_000
    times = [rng.uniform(0, 100) for _ in range(n)]
    times[10:20] = [50.0] * 10  # ties fire in the order they were set
    gc.disable()  # (Python's collector, not the engine, dominates with this many objects)
    try:
        start = time.perf_counter()
        ids = [w.add_timer(t) for t in times]
        fired = [(e.time, e.a) for e in w.step_to(101)]
        seconds = time.perf_counter() - start
    finally:
        gc.enable()
    assert fired == sorted(zip(times, ids))
    assert seconds < 30, f"{n} timers took {seconds:.1f} s"


def test_cancelled_timers_never_fire(engine):
    w = engine.World()
    w.add_circle((0, 0), 1.0)
    ids = [w.add_timer(float(k % 17)) for k in range(200)]
    gone = set(ids[::3])
    for k in gone:
        w.cancel_timer(k)
    fired = [e.a for e in w.step_to(20)]
    assert sorted(fired) == sorted(set(ids) - gone)
    assert [e for e in fired] == sorted(fired, key=lambda k: (k % 17, k))
