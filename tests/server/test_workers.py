"""`max2code serve --workers N`: rooms spread over worker processes by their name's hash, the
front hands each connection to its room's worker, and stopping leaves no process behind."""

from __future__ import annotations

import asyncio
import json
import os
import re
import signal
import subprocess
import sys
import time
import urllib.request
import zlib
from pathlib import Path

from websockets.asyncio.client import connect

from max2code.server import protocol
from max2code.server.workers import owner, room_of_head, room_of_path

from .client import Client
from .conftest import ARENA


def descendants(pid: int) -> set[int]:
    """Every process below pid (children, their children, ...), from /proc."""
    parents: dict[int, list[int]] = {}
    for d in Path("/proc").iterdir():
        if d.name.isdigit():
            try:
                ppid = int((d / "stat").read_text().rsplit(")", 1)[1].split()[1])
            except (OSError, IndexError, ValueError):
                continue
            parents.setdefault(ppid, []).append(int(d.name))
    out, todo = set(), [pid]
    while todo:
        for child in parents.get(todo.pop(), []):
            out.add(child)
            todo.append(child)
    return out


def alive(pid: int) -> bool:
    """Running (a zombie, exited but not yet reaped, counts as gone)."""
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state != "Z"


def serve(*extra: str, session: bool = False) -> tuple[subprocess.Popen, int]:
    proc = subprocess.Popen([sys.executable, "-m", "max2code", "serve", str(ARENA), "--port", "0", *extra],
                            stderr=subprocess.PIPE, text=True, start_new_session=session)
    line = proc.stderr.readline()
    m = re.search(r"http://127\.0\.0\.1:(\d+)/ .*on 2 worker processes", line)
    if not m:
        proc.kill()
        raise AssertionError(line + proc.stderr.read())
    return proc, int(m.group(1))


def rooms_of_each_worker(count: int = 2) -> list[str]:
    """A room name that hashes to each worker."""
    names = {}
    for k in range(100):
        names.setdefault(owner(f"r{k}", count), f"r{k}")
    return [names[i] for i in range(count)]


def test_owner_is_a_stable_hash():
    # CRC-32, the same in every process and run (Python's hash() of a str is salted per process)
    assert [owner(n, 2) for n in ("main", "one", "two", "r0", "r1")] == \
        [zlib.crc32(n.encode()) % 2 for n in ("main", "one", "two", "r0", "r1")]
    spread = [owner(f"room-{k}", 4) for k in range(400)]
    assert all(60 < spread.count(i) < 140 for i in range(4)), [spread.count(i) for i in range(4)]
    assert owner("anything", 1) == 0


def test_the_room_a_request_names():
    assert room_of_head(b"GET /ws?room=one HTTP/1.1\r\nHost: x\r\n\r\n") == "one"
    assert room_of_head(b"GET /?room=two&name=a HTTP/1.1\r\n") == "two"
    assert room_of_head(b"GET /ws HTTP/1.1\r\n") == "main"
    assert room_of_head(b"GET /ws?room=../../etc HTTP/1.1\r\n") == "main"   # not a room name
    assert room_of_head(b"\x16\x03\x01garbage") == "main"
    assert room_of_path("/ws?room=Upper") is None


def test_two_rooms_on_two_workers_then_sigint_leaves_no_process():
    proc, port = serve("--workers", "2")
    url = f"ws://127.0.0.1:{port}/ws"
    try:
        kids = descendants(proc.pid)
        assert len(kids) >= 2, kids     # two workers (and multiprocessing's resource tracker)
        a_room, b_room = rooms_of_each_worker()

        async def go():
            a = await Client.join(url, room=a_room)
            b = await Client.join(url, room=b_room)
            late = await Client.join(url, room=a_room)   # the same room: the same worker's world
            assert a.world["room"] == a_room and b.world["room"] == b_room
            assert a.world["you"] == b.world["you"] == [4] and late.world["you"] == [5]
            await a.send({"type": "key", "body": 4, "key": "right", "down": True})
            m = await a.until(lambda m: m["type"] == "ev" and [5, 4, -1] in m["ev"])
            seen = await late.until(lambda m: m["type"] == "ev" and [5, 4, -1] in m["ev"])
            got_b = await b.receive(0.3)
            pong = None
            await b.send({"type": "ping", "id": 1, "c": 0.0})
            pong = await b.until(lambda m: m["type"] == "pong")
            # a hello for a room of the other worker, on a connection routed to this one
            wrong = await connect(f"{url}?room={a_room}")
            await wrong.send(json.dumps({"type": "hello", "v": protocol.VERSION, "seq": 0, "room": b_room}))
            refusal = json.loads(await wrong.recv())
            # no room in the URL: routed as main, so a hello naming another worker's room is refused
            other = b_room if owner("main", 2) != owner(b_room, 2) else a_room
            bare = await connect(url)
            await bare.send(json.dumps({"type": "hello", "v": protocol.VERSION, "seq": 0, "room": other}))
            bare_refusal = json.loads(await bare.recv())
            return m, seen, got_b, pong, refusal, bare_refusal, [a, b, late]

        m, seen, got_b, pong, refusal, bare_refusal, clients = asyncio.run(go())
        assert seen["n"] == m["n"] and seen["seg"] == m["seg"]   # one world for both of room a
        assert not any([5, 4, -1] in x.get("ev", []) for x in got_b)   # room b is another world
        assert pong["s"] > 0
        assert refusal["type"] == "error" and "is not the URL's" in refusal["reason"]
        assert bare_refusal["type"] == "error" and "another worker" in bare_refusal["reason"]
        with urllib.request.urlopen(f"http://127.0.0.1:{port}/?room={b_room}") as r:   # the page too
            assert r.status == 200 and b"<canvas" in r.read()

        kids = descendants(proc.pid)   # (clients connected: the workers hold rooms now)
        t0 = time.monotonic()
        proc.send_signal(signal.SIGINT)
        assert proc.wait(20) == 128 + signal.SIGINT
        while any(alive(k) for k in kids) and time.monotonic() - t0 < 10:
            time.sleep(0.05)
        assert not [k for k in kids if alive(k)], "left behind after SIGINT"
    finally:
        proc.kill()
        proc.wait()


def test_ctrl_c_to_the_process_group_leaves_no_process():
    """A terminal's ^C: SIGINT to every process of the group at once (the workers ignore it,
    the front stops them)."""
    proc, port = serve("--workers", "2", session=True)
    try:
        kids = descendants(proc.pid)
        assert len(kids) >= 2
        asyncio.run(Client.join(f"ws://127.0.0.1:{port}/ws", room="one"))
        os.killpg(proc.pid, signal.SIGINT)
        assert proc.wait(20) == 128 + signal.SIGINT
        end = time.monotonic() + 10
        while any(alive(k) for k in kids) and time.monotonic() < end:
            time.sleep(0.05)
        assert not [k for k in kids if alive(k)]
        assert "Traceback" not in proc.stderr.read()    # no KeyboardInterrupt in any worker
    finally:
        proc.kill()
        proc.wait()


def test_workers_stop_when_the_front_is_killed():
    proc, port = serve("--workers", "2")
    try:
        kids = descendants(proc.pid)
        asyncio.run(Client.join(f"ws://127.0.0.1:{port}/ws", room="one"))
        proc.kill()          # no handler runs: each worker reads its channel's end
        proc.wait(10)
        end = time.monotonic() + 10
        while any(alive(k) for k in kids) and time.monotonic() < end:
            time.sleep(0.05)
        assert not [k for k in kids if alive(k)]
    finally:
        proc.kill()
        proc.wait()


def test_a_dead_worker_stops_the_server():
    proc, port = serve("--workers", "2")
    try:
        workers = [k for k in descendants(proc.pid)
                   if "resource_tracker" not in Path(f"/proc/{k}/cmdline").read_text()]
        assert len(workers) == 2
        os.kill(workers[0], signal.SIGKILL)
        assert proc.wait(20) == 1
        assert "exited" in proc.stderr.read()
        end = time.monotonic() + 10
        while alive(workers[1]) and time.monotonic() < end:
            time.sleep(0.05)
        assert not alive(workers[1])
    finally:
        proc.kill()
        proc.wait()


def test_bad_worker_count():
    r = subprocess.run([sys.executable, "-m", "max2code", "serve", str(ARENA), "--workers", "0"],
                       capture_output=True, text=True)
    assert r.returncode == 2 and "--workers" in r.stderr
