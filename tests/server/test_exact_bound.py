"""The bytes no exact event stream can go below (bench/serve.py's exact_bound), and the claim
docs/server.md makes with it: in `bullet` no exact stream can send 10x fewer bytes than 60 Hz
snapshots, whatever its protocol, because the bullet's drawn motion changes in nearly every
frame. Checked against a world of the scene's own, stepped frame by frame, not against the
room's stream."""

from __future__ import annotations

import json
import sys
from pathlib import Path

from max2code.engine.scenefile import build_world, load
from max2code.server import protocol

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "bench"))

import serve  # noqa: E402  (bench/serve.py)


def test_the_bound_is_one_pose_per_carried_change() -> None:
    g = [0, -9.81]
    page = [json.dumps({"type": "world", "n": 0}),
            json.dumps({"type": "ev", "n": 1, "t": 0.5, "seg": [[3, 1.5, 2, 0.25, 1, 0]],
                        "fall": [[4, 0, 1, 0, 0, -1]]}),
            json.dumps({"type": "ev", "n": 2, "t": 0.75, "seg": [], "rm": [3]}),
            json.dumps({"type": "pong", "n": 3})]
    # poses as a snapshot writes them: "[1.5,2,0.25]" and "[0,1,0]"
    assert serve.exact_bound(page, g) == len("[1.5,2,0.25]") + len("[0,1,0]")


def test_no_exact_stream_reaches_10x_in_bullet() -> None:
    scene = load(ROOT / "examples" / "scenes" / "bullet.toml")
    until = scene.until
    world = build_world(scene)
    bullet = next(i for i, b in enumerate(world.bodies) if b.kind == "dynamic")
    hz, frames, changed, needed = 60.0, 0, 0, 0
    before = world.velocity(bullet)
    k = 1
    while k / hz <= until:
        world.step_to(k / hz, events=False)
        now = world.velocity(bullet)
        frames += 1
        if now != before:        # its motion changed since the last frame: the client must learn it
            changed += 1
            needed += len(protocol.encode([protocol.number(v) for v in world.pose(bullet, k / hz)]))
        before = now
        k += 1
    assert changed >= 0.9 * frames      # (bounces ~15 times a frame)
    snaps = serve.snapshots(build_world(scene), until)
    ratio_at_best = sum(map(len, snaps)) / needed
    assert ratio_at_best < 10
    # and the room's page stream, exact, does not go below it (the bound is a bound)
    world_msg, _sent, _cpu, room = serve.replay(scene, until)
    assert sum(map(len, room.page)) >= needed
    # the bench's bound, counted from the stream, says the same
    bound = serve.exact_bound(room.page, json.loads(world_msg).get("g", (0, 0)))
    assert sum(map(len, snaps)) / bound < 10
