#!/usr/bin/env python3
"""`max2code serve` measured on loopback: bytes against 60 Hz snapshots, latency, CPU, capacity.

    python bench/serve.py            # ~2 minutes; writes bench/results/serve.md
    python bench/serve.py --quick    # shorter runs
    python bench/serve.py --bytes    # the exact bytes table alone (seconds), printed

1. bytes: every example scene (examples/scenes/*.toml) run for min(until, 10) simulated
   seconds through a Room (the server's own code: the messages it would send waking at each
   World.next_time), against a 60 Hz snapshot stream of the same run (every body's x, y, angle
   each frame) in the same encoding (protocol.encode, protocol.number); also after a
   permessage-deflate-like compression (one zlib stream per connection, a sync flush per
   message, as websockets does with context takeover). And PGE's breakout, served as
   `max2code serve GAME.py` serves it (read from the shared corpus, when it is there). The
   same messages in MessagePack (hello's enc), against snapshots in MessagePack, and where the
   dense scenes' bytes go (envelope, event lists, segments).
2. capacity: CPU seconds the Room spends per engine event, message and client (1 and 100
   listeners), so events per second one core serves.
3. load: `max2code serve` in a process of its own on 127.0.0.1; 1, 10 and 100 protocol
   clients (one asyncio process) joined to one room of a busy scene; per message, the latency
   from the event's time to its arrival (the clients estimate the server's clock as the page
   does: the least-round-trip ping); the clients' and the server's CPU seconds per second.
4. rooms per machine: `max2code serve --workers 1` and `--workers 2`, with 10, 40 and 80 fresh
   rooms of pinball at once, one watching client each: latency and the server's CPU.
Bounded in count and time: every run has a fixed duration; nothing listens beyond loopback.
"""
from __future__ import annotations

import argparse
import asyncio
import contextlib
import io
import json
import os
import re
import statistics
import subprocess
import sys
import time
import zlib
from pathlib import Path

import msgpack

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from max2code.engine.scenefile import Scene, build_world, load  # noqa: E402
from max2code.server import protocol  # noqa: E402
from max2code.server.room import Room  # noqa: E402

BREAKOUT = Path("/work/shared/corpus/pge-python/examples/breakout-breakout.py")


def ratio(r: float, sent: int) -> str:
    """A ratio as text: 0.07x below 1 (not 0x), 2.5x, 13x, 153x; "all" when nothing was sent."""
    if sent == 0:
        return "nothing sent"
    return f"{r:.2g}x" if r < 10 else f"{r:.0f}x"


def deflate_sizes(texts: list[str]) -> int:
    z = zlib.compressobj(6, zlib.DEFLATED, -15)
    return sum(len(z.compress(t.encode()) + z.flush(zlib.Z_SYNC_FLUSH)) - 4 for t in texts)


def exact_bound(page: list[str], g) -> int:
    """Bytes that no exact event stream in this encoding can go below, for what `page` (a page's
    messages, which carry each changed body's latest segment once a message, at most `rate`
    messages a second) showed: each body change a message carries, as its pose alone (x, y,
    angle: three of a segment's numbers, as a snapshot sends them), with no envelope, no id and
    no velocity. A thin client cannot draw a changed motion's later frames without at least
    that, so 60 Hz snapshots' bytes over this is the most any exact stream could gain."""
    from max2code.server import wire

    total = 0
    for m in map(json.loads, page):
        if m.get("type") == "ev":
            total += sum(len(protocol.encode(seg[1:4])) for seg in wire.expanded(m, g))
    return total


def replay(scene, until: float, listeners: int = 1, tolerance: float | None = None, world=None,
           rate: float | None = None, page: bool = True):
    """The messages a room sends over `until` seconds when it wakes exactly at each queued
    event; and the CPU seconds that took. `world`: a game's (else the scene's)."""
    clock = [0.0]
    kw = {} if rate is None else {"rate": rate}
    room = Room("bench", scene, (), clock=lambda: clock[0], tolerance=tolerance, world=world, **kw)
    sent: list[str] = []
    world_msg = room.join(sent.append, "bench")[1]
    room.page: list[str] = []    # what the page gets (hello's events: false)
    room.packed: list[bytes] = []    # the same as MessagePack (hello's enc: msgpack)
    room.packed_page: list[bytes] = []
    if page:
        room.join(room.page.append, "page", events=False)
        room.join(room.packed.append, "msgpack", enc="msgpack")
        room.join(room.packed_page.append, "msgpack page", events=False, enc="msgpack")
    for _ in range(listeners - 1):
        room.join(lambda text: None, "bench")
    cpu = time.process_time()
    while room.failed is None:   # (a failed room wakes at once for ever: stop with it)
        t = room.next_wake()
        if t > until:
            break
        clock[0] = t
        room.advance(t)
    clock[0] = until
    room.advance(until)
    cpu = time.process_time() - cpu
    return world_msg, sent, cpu, room


def snapshots(w, until: float, hz: float = 60.0) -> list[str]:
    """Every live body's pose 60 times a second, from a world of its own (a scene's, a game's),
    until `until` or the game's end."""
    from max2code.engine.world import EngineError

    out = []
    k = 0
    while k / hz <= until:
        t = k / hz
        try:
            w.step_to(t, events=False)
        except EngineError:     # a game that ended (its program's sys.exit): nothing to draw
            break
        poses = [w.pose(i, t) for i, b in enumerate(w.bodies) if b.alive]
        out.append(protocol.encode({"type": "snap", "t": t,
                                    "p": [[protocol.number(v) for v in p] for p in poses]}))
        k += 1
    return out


def runs(quick: bool):
    """(name, scene, seconds, make_world) for each example scene, then PGE's breakout."""
    for path in sorted((ROOT / "examples" / "scenes").glob("*.toml")):
        scene = load(path)
        yield scene.name, scene, min(scene.until or 10.0, 3.0 if quick else 10.0), lambda s=scene: build_world(s)
    if BREAKOUT.is_file():   # (until its program ends: run(10.0), out_of_time, or all bricks gone)
        from max2code.server.pgegame import UNIT_VIEW, GameWorld, load as load_game

        scene = Scene(name="breakout (PGE game)", bodies=(), view=UNIT_VIEW)
        def game():
            with contextlib.redirect_stdout(io.StringIO()):   # (its prints: "before run")
                return GameWorld(load_game(str(BREAKOUT)))
        yield scene.name, scene, 3.0 if quick else 9.5, game


def bytes_table(quick: bool, tolerance: float | None, rate: float | None = None) -> tuple[list[str], list[dict]]:
    rows = []
    for name, scene, until, make in runs(quick):
        world = make()
        world_msg, sent, cpu, room = replay(scene, until, tolerance=tolerance, world=world, rate=rate)
        if room.failed:         # a game that ended: both streams end with it
            until = room.world.time
        snaps = snapshots(make(), until)
        ev_bytes, snap_bytes = sum(map(len, sent)), sum(map(len, snaps))
        page_bytes = sum(map(len, room.page))
        bound = exact_bound(room.page, json.loads(world_msg).get("g", (0, 0)))
        ev_z, snap_z = deflate_sizes(sent), deflate_sizes(snaps)
        decoded = [m for m in map(json.loads, sent) if m["type"] == "ev"]
        events = sum(len(m["ev"]) for m in decoded)
        both = [m["seg"] + m.get("fall", []) for m in decoded]   # (protocol 4: seg and fall)
        segs = sum(map(len, both))
        # where the bytes go: the envelope (type, n, t, rm, add), the event lists, the segments
        parts = {"ev": sum(len(protocol.encode(m["ev"])) + 6 for m in decoded),
                 "seg": sum(len(protocol.encode(m["seg"])) + 7 + (len(protocol.encode(m["fall"])) + 8
                                                                  if "fall" in m else 0)
                            for m in decoded)}
        parts["envelope"] = ev_bytes - parts["ev"] - parts["seg"]
        snap_mp = sum(len(msgpack.packb(json.loads(t))) for t in snaps)
        ev_mp, page_mp = sum(map(len, room.packed)), sum(map(len, room.packed_page))
        rows.append({"scene": name, "bodies": len(world.bodies), "seconds": until,
                     "engine_events": room.stats.events,
                     "messages": len(sent), "events": events, "segments": segs,
                     "join_bytes": len(world_msg),
                     "event_Bps": ev_bytes / until, "snapshot_Bps": snap_bytes / until,
                     "ratio": snap_bytes / max(ev_bytes, 1), "sent": ev_bytes,
                     "event_Bps_deflate": ev_z / until, "snapshot_Bps_deflate": snap_z / until,
                     "ratio_deflate": snap_z / max(ev_z, 1),
                     "page_Bps": page_bytes / until, "page_ratio": snap_bytes / max(page_bytes, 1),
                     "bound_Bps": bound / until, "bound_ratio": snap_bytes / max(bound, 1),
                     "page_Bps_deflate": deflate_sizes(room.page) / until,
                     "page_ratio_deflate": snap_z / max(deflate_sizes(room.page), 1),
                     "bytes_per_message": ev_bytes / max(len(sent), 1),
                     "parts": parts, "segment_numbers": sum(len(g) - 1 for gs in both for g in gs),
                     "snapshot_numbers": sum(3 * len(json.loads(t)["p"]) for t in snaps),
                     "msgpack_Bps": ev_mp / until, "snapshot_msgpack_Bps": snap_mp / until,
                     "ratio_msgpack": snap_mp / max(ev_mp, 1), "ratio_msgpack_json_snapshots": snap_bytes / max(ev_mp, 1),
                     "page_msgpack_Bps": page_mp / until, "page_ratio_msgpack": snap_mp / max(page_mp, 1),
                     "room_cpu": cpu})
    lines = ["| scene | bodies | s | engine events | messages | segments | events sent | join B "
             "| events B/s | 60 Hz snapshots B/s | ratio "
             "| deflated: events B/s | snapshots B/s | ratio | B per message "
             "| page (no event lists) B/s | ratio | deflated B/s | ratio | exact bound B/s | best ratio "
             "| room CPU s |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['scene']} | {r['bodies']} | {r['seconds']:.3g} | {r['engine_events']} | "
                     f"{r['messages']} | {r['segments']} | {r['events']} | "
                     f"{r['join_bytes']} | {r['event_Bps']:.0f} | {r['snapshot_Bps']:.0f} | "
                     f"**{ratio(r['ratio'], r['sent'])}** | {r['event_Bps_deflate']:.0f} | "
                     f"{r['snapshot_Bps_deflate']:.0f} | {ratio(r['ratio_deflate'], r['sent'])} | "
                     f"{r['bytes_per_message']:.0f} | {r['page_Bps']:.0f} | "
                     f"{ratio(r['page_ratio'], r['sent'])} | {r['page_Bps_deflate']:.0f} | "
                     f"{ratio(r['page_ratio_deflate'], r['sent'])} | {r['bound_Bps']:.0f} | "
                     f"{ratio(r['bound_ratio'], r['sent'])} | {r['room_cpu']:.2f} |")
    lines += ["", "The same runs in MessagePack (hello's `enc: \"msgpack\"`: the same values, binary "
              "frames), against snapshots in MessagePack too (the same encoding) and in JSON:", "",
              "| scene | events JSON B/s | MessagePack B/s | MessagePack snapshots B/s | ratio "
              "| ratio to JSON snapshots | page (no event lists) MessagePack B/s | ratio |",
              "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['scene']} | {r['event_Bps']:.0f} | {r['msgpack_Bps']:.0f} | "
                     f"{r['snapshot_msgpack_Bps']:.0f} | **{ratio(r['ratio_msgpack'], r['sent'])}** | "
                     f"{ratio(r['ratio_msgpack_json_snapshots'], r['sent'])} | {r['page_msgpack_Bps']:.0f} | "
                     f"{ratio(r['page_ratio_msgpack'], r['sent'])} |")
    return lines, rows


def dense_text(rows: list[dict]) -> list[str]:
    """Which scenes are event-dense (fewer than 10x), from the measured rows, and why."""
    dense = [r for r in rows if r["sent"] and r["ratio"] < 10]
    if not dense:
        return ["Every scene sends at least 10x fewer bytes than 60 Hz snapshots."]
    items = ", ".join(f"{r['scene']} ({r['engine_events'] / r['seconds']:.0f} engine events/s for "
                      f"{r['bodies']} bodies, {r['messages'] / r['seconds']:.0f} messages/s, "
                      f"{r['segments'] / max(r['messages'], 1):.1f} segments a message: "
                      f"{ratio(r['ratio'], r['sent'])})" for r in dense)
    return [f"Event-dense here: {items}. In these the drawn motion of some body changes more often "
            "than 60 times a second (a bullet bouncing between walls, a pile's bodies touching "
            "each other, a ball that the game speeds up at every hit), so a message goes out every "
            "1/60 s as a snapshot would, and it costs more than a snapshot's share for the bodies it "
            "carries: a segment is up to 8 numbers (position, angle, velocity, spin, acceleration) "
            "where a pose is 3, and the message names the events (each kind and pair once, with a "
            "count). Snapshots win when most bodies change at every frame; events win by the "
            "fraction of bodies and frames in which nothing changes.", "",
            "The exact bound (bench/serve.py's exact_bound): each body change the page's stream "
            "carried, as its pose alone (three numbers, no envelope, no id, no velocity), is what "
            "no exact stream in this encoding can go below, since a thin client cannot draw a "
            "changed motion without it; 60 Hz snapshots over that bound is the best ratio any exact "
            "stream could reach. " + (
                "Below 10x even so, whatever the protocol: " + ", ".join(
                    f"{r['scene']} ({ratio(r['bound_ratio'], r['sent'])})" for r in dense
                    if r["bound_ratio"] < 10) + "." if any(r["bound_ratio"] < 10 for r in dense)
                else "Every scene's bound is 10x or more."), "",
            "Where their bytes go (JSON, after the join): " + "; ".join(
                f"{r['scene']}: envelope {100 * r['parts']['envelope'] / r['sent']:.0f} %, event lists "
                f"{100 * r['parts']['ev'] / r['sent']:.0f} %, segments {100 * r['parts']['seg'] / r['sent']:.0f} % "
                f"({r['segment_numbers']} numbers, against the snapshots' {r['snapshot_numbers']})"
                for r in dense) + "."]


def capacity_table(quick: bool) -> tuple[list[str], list[dict]]:
    rows = []
    for name in ("pinball", "billiards-break", "pile"):
        scene = load(ROOT / "examples" / "scenes" / f"{name}.toml")
        until = min(scene.until or 10.0, 3.0 if quick else 10.0)
        for listeners in (1, 100):
            _, sent, cpu, room = replay(scene, until, listeners, tolerance=0.0, page=False)
            rows.append({"scene": name, "listeners": listeners, "sim_seconds": until,
                         "engine_events": room.world.stats()["events"], "messages": len(sent),
                         "cpu": cpu, "events_per_cpu_s": room.world.stats()["events"] / cpu,
                         "messages_per_cpu_s": len(sent) / cpu,
                         "realtime_rooms_per_core": until / cpu})
    lines = ["| scene | listeners | engine events | messages | CPU s | engine events / CPU s "
             "| messages / CPU s | rooms of it one core runs in real time |", "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['scene']} | {r['listeners']} | {r['engine_events']} | {r['messages']} | "
                     f"{r['cpu']:.3f} | {r['events_per_cpu_s']:.0f} | {r['messages_per_cpu_s']:.0f} | "
                     f"{r['realtime_rooms_per_core']:.0f} |")
    return lines, rows


def _cpu_of(pid: int) -> float:
    fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


async def _load(port: int, clients: int, seconds: float, server_pid: int) -> dict:
    room = f"load-{clients}"   # a fresh room per run: the scene from its start
    from websockets.asyncio.client import ClientConnection, connect

    class Counted(ClientConnection):
        """Counts the bytes TCP delivers: frames as sent, permessage-deflate included."""
        wire = 0

        def data_received(self, data: bytes) -> None:
            self.wire += len(data)
            super().data_received(data)

    async def one(k: int, lat: list, counts: list):
        ws = await connect(f"ws://127.0.0.1:{port}/ws?room={room}", max_queue=None, create_connection=Counted)
        await ws.send(json.dumps({"type": "hello", "v": protocol.VERSION, "seq": 0, "play": False, "room": room}))
        json.loads(await ws.recv())
        seq, best = 1, None
        for i in range(8):     # the page's clock estimate: the least round trip wins
            c = time.monotonic()
            await ws.send(json.dumps({"type": "ping", "seq": seq, "id": i, "c": c}))
            seq += 1
            while True:
                m = json.loads(await ws.recv())
                if m["type"] == "pong":
                    break
            now = time.monotonic()
            if best is None or now - c < best[0]:
                best = (now - c, m["s"] - (c + now) / 2)
        offset = best[1]
        end = time.monotonic() + seconds
        n = 0
        wire0 = ws.wire
        while (left := end - time.monotonic()) > 0:
            try:
                text = await asyncio.wait_for(ws.recv(), left)
            except asyncio.TimeoutError:
                break
            m = json.loads(text)
            if m["type"] == "ev":
                lat.append(time.monotonic() + offset - m["t"])
                n += len(text)
        counts.append((n, ws.wire - wire0))
        await ws.close()

    lat: list[float] = []
    counts: list[int] = []
    cpu0, scpu0, t0 = time.process_time(), _tree_cpu(server_pid), time.monotonic()
    await asyncio.gather(*(one(k, lat, counts) for k in range(clients)))
    wall = time.monotonic() - t0
    cpu, scpu = time.process_time() - cpu0, _tree_cpu(server_pid) - scpu0
    lat.sort()
    q = lambda p: lat[min(len(lat) - 1, int(p * len(lat)))] if lat else float("nan")  # noqa: E731
    return {"clients": clients, "messages": len(lat), "p50_ms": 1e3 * q(0.5), "p99_ms": 1e3 * q(0.99),
            "max_ms": 1e3 * lat[-1] if lat else float("nan"),
            "client_cpu_per_s_per_client": cpu / wall / clients, "server_cpu_per_s": scpu / wall,
            "Bps_per_client": sum(n for n, _ in counts) / len(counts) / seconds,
            "wire_Bps_per_client": sum(w for _, w in counts) / len(counts) / seconds}


def load_table(quick: bool, scene: str = "pinball") -> tuple[list[str], list[dict]]:
    proc = subprocess.Popen([sys.executable, "-m", "max2code", "serve",
                             str(ROOT / "examples" / "scenes" / f"{scene}.toml"), "--port", "0",
                             "--rooms", "8", "--workers", "1"], stderr=subprocess.PIPE, text=True)
    try:
        port = int(re.search(r":(\d+)/", proc.stderr.readline()).group(1))
        rows = [asyncio.run(_load(port, n, 2.0 if quick else 6.0, proc.pid)) for n in (1, 10, 100)]
    finally:
        proc.terminate()
        proc.wait(30)
    lines = [f"Scene {scene}, a fresh room per run (the scene from its start), clients watching "
             "(no input), one asyncio process of clients:",
             "", "| clients | messages received | latency p50 | p99 | max | client CPU s per s (each) "
             "| server CPU s per s | B/s per client (text) | on the wire (deflated, framed) |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['clients']} | {r['messages']} | {r['p50_ms']:.2f} ms | {r['p99_ms']:.2f} ms | "
                     f"{r['max_ms']:.1f} ms | {r['client_cpu_per_s_per_client']:.4f} | "
                     f"{r['server_cpu_per_s']:.3f} | {r['Bps_per_client']:.0f} | "
                     f"{r['wire_Bps_per_client']:.0f} |")
    return lines, rows


def _tree_cpu(pid: int) -> float:
    """CPU seconds of pid and every process below it (the front, its workers)."""
    kids: dict[int, list[int]] = {}
    for d in Path("/proc").iterdir():
        if d.name.isdigit():
            with contextlib.suppress(OSError, IndexError, ValueError):
                kids.setdefault(int((d / "stat").read_text().rsplit(")", 1)[1].split()[1]), []).append(int(d.name))
    total, todo = 0.0, [pid]
    while todo:
        p = todo.pop()
        with contextlib.suppress(OSError):
            total += _cpu_of(p)
        todo += kids.get(p, [])
    return total


async def _rooms(port: int, rooms: int, seconds: float, tag: str, server_pid: int, expected: int) -> dict:
    """`rooms` fresh rooms with one watching client each (one asyncio process), all joined at
    once (each room starts at its first join); per message of each room's first `seconds`
    (room time), the latency from its time to its arrival on the client's estimate of its
    room's clock (every room has its own); the server's CPU (front and workers) per second."""
    from websockets.asyncio.client import connect

    async def one(name: str, lat: list):
        ws = await connect(f"ws://127.0.0.1:{port}/ws?room={name}", max_queue=None)
        await ws.send(json.dumps({"type": "hello", "v": protocol.VERSION, "seq": 0, "play": False,
                                  "events": False}))
        json.loads(await ws.recv())
        seq, best, held = 1, (float("inf"), 0.0), []
        end = None
        while end is None or time.monotonic() < end:
            # a ping every 0.2 s all along: the least round trip's offset, applied at the end
            # (while 80 rooms join, round trips are long, and so is the offset's error)
            c = time.monotonic()
            await ws.send(json.dumps({"type": "ping", "seq": seq, "id": seq, "c": c}))
            seq += 1
            while True:
                try:
                    m = json.loads(await asyncio.wait_for(ws.recv(), 0.2))
                except asyncio.TimeoutError:
                    break
                if m["type"] == "pong":
                    now = time.monotonic()
                    if now - m["c"] < best[0]:
                        best = (now - m["c"], m["s"] - (m["c"] + now) / 2)
                else:
                    held.append((time.monotonic(), m))
            if end is None:   # its room's time `seconds`, plus 2 s for what is late
                end = time.monotonic() + seconds + 2.0 - (time.monotonic() + best[1])
        lat.extend(arrived + best[1] - m["t"] for arrived, m in held if m["type"] == "ev" and m["t"] < seconds)
        await ws.close()

    lat: list[float] = []
    cpu0, wall0, ccpu, fcpu = _tree_cpu(server_pid), time.monotonic(), time.process_time(), _cpu_of(server_pid)
    await asyncio.gather(*(one(f"{tag}-{k}", lat) for k in range(rooms)))
    scpu, wall = _tree_cpu(server_pid) - cpu0, time.monotonic() - wall0
    fcpu = _cpu_of(server_pid) - fcpu
    ccpu = time.process_time() - ccpu
    lat.sort()
    q = lambda p: lat[min(len(lat) - 1, int(p * len(lat)))] if lat else float("nan")  # noqa: E731
    return {"rooms": rooms, "messages": len(lat), "p50_ms": 1e3 * q(0.5), "p99_ms": 1e3 * q(0.99),
            "late_50ms": sum(x > 0.05 for x in lat) / max(len(lat), 1),
            "expected": rooms * expected,
            "server_cpu_per_s": scpu / wall, "server_cpu_per_room": scpu / wall / rooms,
            "wall": wall, "client_cpu_per_s": ccpu / wall, "front_cpu_per_s": fcpu / wall, "load": os.getloadavg()[0]}


def rooms_table(quick: bool, scene: str = "pinball") -> tuple[list[str], list[dict]]:
    """Rooms of `scene` per machine with 1 and 2 worker processes: levels of rooms at once."""
    levels = (3, 6) if quick else (10, 40, 80)
    seconds = 2.0 if quick else 4.0
    # what one room sends the page over its first seconds (a replay waking at each event)
    expected = len(replay(load(ROOT / "examples" / "scenes" / f"{scene}.toml"), seconds)[3].page)
    rows = []
    for workers in (1, 2):
        proc = subprocess.Popen([sys.executable, "-m", "max2code", "serve",
                                 str(ROOT / "examples" / "scenes" / f"{scene}.toml"), "--port", "0",
                                 "--rooms", "200", "--workers", str(workers)],
                                stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        try:
            port = int(re.search(r":(\d+)/", proc.stderr.readline()).group(1))
            for k in levels:   # fresh rooms each level: every scene from its start, all at once
                r = asyncio.run(_rooms(port, k, seconds, f"w{workers}-n{k}", proc.pid, expected))
                rows.append({"workers": workers, **r})
        finally:
            proc.send_signal(2)
            proc.wait(30)
    lines = [f"Scene {scene}: that many fresh rooms at once (the scenes from their start, their "
             "busiest seconds), one watching client each (the page's hello: no event lists), all "
             "clients in one asyncio process; `max2code serve --workers 1` (one process) and "
             "`--workers 2` (a front and two workers):", "",
             "| workers | rooms | messages received (a replay's count) | latency p50 | p99 | later than 50 ms "
             "| server CPU s per s (front + workers) | of which the front | per room "
             "| clients' CPU s per s | machine load (1 min) |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['workers']} | {r['rooms']} | {r['messages']} ({r['expected']}) | {r['p50_ms']:.1f} ms | "
                     f"{r['p99_ms']:.1f} ms | {100 * r['late_50ms']:.1f} % | {r['server_cpu_per_s']:.3f} | "
                     f"{(format(r['front_cpu_per_s'], '.3f') if r['workers'] > 1 else '-')} | {r['server_cpu_per_room']:.4f} | "
                     f"{r['client_cpu_per_s']:.2f} | {r['load']:.1f} |")
    return lines, rows


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("-o", default=str(ROOT / "bench" / "results" / "serve.md"))
    ap.add_argument("--bytes", action="store_true",
                    help="only the exact bytes table (every scene and game, seconds): print it, "
                         "write nothing")
    ap.add_argument("--tolerance", type=float, default=0.0,
                    help="with --bytes: the rooms' tolerance in metres (0: exact, the default; "
                         "-1: a quarter of a pixel of the page's canvas, as `serve --tolerance -1`)")
    args = ap.parse_args()
    if args.bytes:   # (the smallest run that gives every scene's ratio and exact bound)
        load0 = os.getloadavg()
        tol = None if args.tolerance == -1 else args.tolerance
        b_lines, b_rows = bytes_table(args.quick, tol)
        print(f"{time.strftime('%Y-%m-%d %H:%M')} UTC; load average {load0[0]:.1f} before, "
              f"{os.getloadavg()[0]:.1f} after; {'--quick' if args.quick else 'full'} bytes table, "
              f"tolerance {args.tolerance:g}",
              "", *b_lines, "", *dense_text(b_rows), sep="\n")
        return 0
    b_lines, b_rows = bytes_table(args.quick, 0.0)
    r_lines, r_rows = bytes_table(args.quick, 0.0, rate=0.0)
    t_lines, t_rows = bytes_table(args.quick, None)
    c_lines, c_rows = capacity_table(args.quick)
    l_lines, l_rows = load_table(args.quick)
    m_lines, m_rows = rooms_table(args.quick)
    text = "\n".join([
        "# max2code serve: events against 60 Hz snapshots (bench/serve.py)", "",
        f"Machine: {os.cpu_count()} cores (shared), Python {sys.version.split()[0]}; "
        f"{time.strftime('%Y-%m-%d')}; {'--quick' if args.quick else 'full'} run.", "",
        "## Bytes per client: event messages against 60 Hz snapshots, same JSON encoding", "",
        "Events: what the server sends after the join (segments of changed bodies and the events). "
        "Snapshots: every live body's (x, y, angle) 60 times a second, the same number format. "
        "Join B: the one world message a client gets first (not in either rate). Deflated: after "
        "a per-connection zlib stream with a sync flush per message, as permessage-deflate "
        "(negotiated by websockets and browsers by default) sends them; the load table below "
        "counts the real bytes on the wire. Page: what the browser page gets, which asks for "
        "no event lists (hello's events: false; it draws from segments only). "
        "Engine events: what the engine reported; events sent: entries in the messages' lists.", "",
        "Exact (the default, --tolerance 0): every change exact from its event's time on; at most "
        "60 messages a second (an isolated event at once, a burst's changes at the end of its "
        "1/60 s, each body's latest segment); a contact that changes nothing drawn sends nothing; "
        "each event kind and pair once a message, with a count (docs/server.md).", "",
        *b_lines, "", *dense_text(b_rows), "",
        "Without the rate limit (Room(rate=0): every step's changes at once, as protocol version 2 "
        "sent them; version 2 also listed every event and re-sent unchanged segments, see "
        "docs/server.md for its numbers):", "", *r_lines, "",
        "With --tolerance -1 (a quarter of a pixel of the page's 800-pixel canvas: a change is sent "
        "when the held segment would drift that far, at once when within 50 ms; docs/server.md):",
        "", *t_lines, "",
        "## Server capacity (CPU per event, message and listener)", "",
        "The room's own loop (engine step, change detection, encoding, sending to every listener) "
        "over the run, waking at each queued event as the server does.", "", *c_lines, "",
        "## Loopback load: latency and CPU", "", *l_lines, "",
        "Latency is measured from the message's time (its latest change's exact time, the "
        "engine's) to its arrival, on the clients' estimate of the server clock (a change earlier "
        "in a burst waited up to 1/60 s more for its message); it includes the server's wake-up lateness "
        "(asyncio's timer), encoding, the send to every client and the clients' own queueing "
        "(100 clients share one Python process here).", "",
        "## Rooms per machine: one process against two workers", "", *m_lines, "",
        "Fewer messages than the replay's (which wakes exactly at each event): a wake-up late by "
        "a few milliseconds steps over several events and sends them in one message. "
        "A room keeps real time while its messages arrive within a frame or two of their time; "
        "CPU per room times rooms is what the cores must give (docs/server.md, \"Rooms across "
        "cores and machines\").", ""])
    Path(args.o).write_text(text)
    (Path(args.o).with_suffix(".json")).write_text(json.dumps(
        {"bytes": b_rows, "bytes_every_step": r_rows, "bytes_quarter_pixel": t_rows, "capacity": c_rows, "load": l_rows,
         "rooms": m_rows}, indent=1))
    print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
