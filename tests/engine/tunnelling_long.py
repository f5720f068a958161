"""The long run of the no-tunnelling fuzz (issue 33, "how to make it stay fixed"): the worlds of
test_no_tunnelling_fuzz, as many as asked, each checked at every collision and checkpoint in
exact geometry, with the counts at the end.

    PYTHONPATH=.:tests python -m tests.engine.tunnelling_long --count 2000 [--seed 0]

`make fuzz` runs it with 2000 worlds. Exit status 1 on the first world that fails (printed).
"""
from __future__ import annotations

import argparse
import time

from hypothesis import HealthCheck, Phase, given, seed, settings

from max2code.engine.binding import load
from max2code.engine.world import World

from . import test_no_tunnelling_fuzz as fz


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--count", type=int, default=2000)
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args()
    load()
    totals = {"worlds": 0, "events": 0, "checks": 0}
    failed: list = []
    start = time.monotonic()

    @seed(args.seed)
    @settings(max_examples=args.count, deadline=None, database=None,
              suppress_health_check=list(HealthCheck), phases=(Phase.generate,))
    @given(world=fz.worlds())
    def run(world) -> None:
        try:
            counts = fz.run_world(World, world)
        except AssertionError:
            failed.append(world)
            raise
        totals["worlds"] += 1
        totals["events"] += counts["events"]
        totals["checks"] += counts["checks"]

    try:
        run()
    except AssertionError as exc:
        print(f"FAILED after {totals['worlds']} worlds: {exc}")
        if failed:
            print(f"the world (gravity, bodies, checkpoints): {failed[0]!r}")
        return 1
    print(f"{totals['worlds']} worlds held: {totals['events']} collisions, "
          f"{totals['checks']} exact checks, {time.monotonic() - start:.0f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
