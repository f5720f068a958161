"""MessagePack frames (hello's `enc: "msgpack"`): the same messages as the JSON form, fewer
bytes; and the binary path's checks: malformed, oversized, out-of-order or mixed frames get an
error frame (in MessagePack) and a close, and the world goes on."""

from __future__ import annotations

import asyncio
import json
import math
from pathlib import Path

import msgpack
import pytest
from hypothesis import given, settings, strategies as st
from websockets.asyncio.client import connect
from websockets.exceptions import ConnectionClosed

from max2code.engine.scenefile import load
from max2code.server import protocol
from max2code.server.protocol import ProtocolError
from max2code.server.room import Room

from .client import Client
from .test_hostile import world_goes_on

ROOT = Path(__file__).resolve().parents[2]
HELLO = {"type": "hello", "v": protocol.VERSION, "seq": 0, "enc": "msgpack"}


def run(coro):
    return asyncio.run(coro)


def replay(name: str, until: float):
    """A room of the scene waking at each queued event (as bench/serve.py replays it), with a
    JSON client, a MessagePack client, and a MessagePack page (no event lists)."""
    clock = [0.0]
    room = Room("r", load(ROOT / "examples" / "scenes" / f"{name}.toml"), (), clock=lambda: clock[0])
    got = {"json": [], "msgpack": [], "page": []}
    worlds = [room.join(got["json"].append, "j")[1], room.join(got["msgpack"].append, "m", enc="msgpack")[1],
              room.join(got["page"].append, "p", events=False, enc="msgpack")[1]]
    while (t := room.next_wake()) <= until:
        clock[0] = t
        room.advance(t)
    return worlds, got


@pytest.mark.parametrize("name,until", [("pile", 1.0), ("bullet", 0.5), ("pinball", 3.0)])
def test_the_same_messages_in_fewer_bytes(name, until):
    worlds, got = replay(name, until)
    assert isinstance(worlds[1], bytes) and msgpack.unpackb(worlds[1]) == json.loads(worlds[0])
    assert msgpack.unpackb(worlds[2]) == json.loads(worlds[0])
    assert len(got["json"]) == len(got["msgpack"]) == len(got["page"]) > 5
    for text, packed, page in zip(got["json"], got["msgpack"], got["page"]):
        m = json.loads(text)
        assert isinstance(packed, bytes) and msgpack.unpackb(packed) == m   # value for value
        assert msgpack.unpackb(page) == {k: v for k, v in m.items() if k != "ev"}
        # a float is the same double (the segment the client evaluates is the same number)
        back = msgpack.unpackb(packed)
        for a, b in zip(m["seg"] + m.get("fall", []), back["seg"] + back.get("fall", [])):
            assert all(type(x) is type(y) and x == y for x, y in zip(a, b))
    json_bytes = sum(len(t.encode()) for t in got["json"])
    packed_bytes = sum(map(len, got["msgpack"]))
    assert packed_bytes < 0.75 * json_bytes, (packed_bytes, json_bytes)


def test_a_msgpack_client_plays_alongside_a_json_one(arena):
    async def go():
        text = await Client.join(arena.url)
        packed = await Client.join(arena.url, enc="msgpack")
        assert isinstance(packed.frames[0], bytes) and isinstance(text.frames[0], str)
        assert packed.world["you"] == [5] and text.world["you"] == [4]
        await packed.send({"type": "key", "body": 5, "key": "left", "down": True})
        m = await packed.until(lambda m: m["type"] == "ev" and [5, 5, -1] in m["ev"])
        seen = await text.until(lambda m: m["type"] == "ev" and [5, 5, -1] in m["ev"])
        await packed.send({"type": "ping", "id": 7, "c": 1.5})
        pong = await packed.until(lambda m: m["type"] == "pong")
        await packed.send({"type": "key", "body": 4, "key": "up", "down": True})   # not its body
        refused = await packed.until(lambda m: m["type"] == "refused")
        return m, seen, pong, refused, packed
    m, seen, pong, refused, packed = run(go())
    assert m == seen        # one message, two encodings: the same value
    assert pong["id"] == 7 and pong["c"] == 1.5 and pong["s"] > 0
    assert refused["seq"] == 3 and "not yours" in refused["reason"]
    assert all(isinstance(f, bytes) for f in packed.frames)


async def refused_msgpack(url: str, frames: list) -> tuple[dict | None, int | None]:
    """hello (JSON, asking for msgpack), then the frames; the error the server answers with
    (a MessagePack binary frame) and the close code."""
    ws = await connect(url)
    await ws.send(json.dumps(HELLO))
    world = await ws.recv()
    assert isinstance(world, bytes) and msgpack.unpackb(world)["type"] == "world"
    for f in frames:
        await ws.send(f)
    got = None
    try:
        while True:
            frame = await asyncio.wait_for(ws.recv(), 5)
            assert isinstance(frame, bytes), frame
            m = msgpack.unpackb(frame)
            if m["type"] == "error":
                got = m
    except ConnectionClosed:
        pass
    return got, ws.close_code


PING = {"type": "ping", "seq": 1, "id": 1, "c": 0.0}
BAD = {
    "malformed": b"\xc1",
    "truncated": msgpack.packb(PING)[:-3],
    "two values": msgpack.packb(PING) + msgpack.packb(PING),
    "text frame": json.dumps(PING),
    "out of order": msgpack.packb({**PING, "seq": 5}),
    "repeated seq": msgpack.packb({**PING, "seq": 0}),
    "hello twice": msgpack.packb({**HELLO, "seq": 1}),
    "extension type": msgpack.packb({**PING, "c": msgpack.ExtType(5, b"xyz")}),
    "timestamp": msgpack.packb({**PING, "c": msgpack.Timestamp(1, 0)}),
    "bin for a string": msgpack.packb({**PING, "type": b"ping"}),
    "NaN": msgpack.packb({**PING, "c": math.nan}),
    "integer key": msgpack.packb({1: 2, **PING}),
    "deep nesting": b"\x91" * 900 + b"\xc0",
    "array": msgpack.packb([1, 2]),
    "unknown field": msgpack.packb({**PING, "admin": True}),
    "body huge": msgpack.packb({"type": "key", "seq": 1, "body": 2 ** 40, "key": "left", "down": True}),
    "float seq": msgpack.packb({**PING, "seq": 1.0}),
}


@pytest.mark.parametrize("name", sorted(BAD))
def test_bad_binary_message(arena, name):
    run(Client.join(arena.url))   # the room exists: its world must go on
    error, code = run(refused_msgpack(arena.url, [BAD[name]]))
    assert error is not None and error["reason"], name
    assert code == protocol.CLOSE_POLICY
    world_goes_on(arena)


def test_oversized_binary_message(arena):
    big = msgpack.packb({**PING, "c": 0.0, "id": 1, "type": "ping"}) + b"\x00" * protocol.MAX_MESSAGE
    error, code = run(refused_msgpack(arena.url, [big]))
    assert "larger than" in error["reason"] and code == protocol.CLOSE_TOO_BIG
    world_goes_on(arena)


@pytest.mark.parametrize("enc", ["cbor", 1, None, "MSGPACK"])
def test_hello_asks_for_an_unknown_encoding(enc):
    with pytest.raises(ProtocolError, match="enc must be one of json, msgpack"):
        protocol.parse(json.dumps({**HELLO, "enc": enc}), 0)


def test_hello_itself_is_json_text():
    with pytest.raises(ProtocolError, match="binary frames"):
        protocol.parse(msgpack.packb(HELLO), 0)


@settings(max_examples=300, deadline=None)
@given(st.binary(max_size=200))
def test_parse_arbitrary_bytes(frame):
    """Any bytes on a MessagePack connection: a checked message or ProtocolError, never
    another exception."""
    try:
        m = protocol.parse(frame, 1, "msgpack")
    except ProtocolError as e:
        assert e.reason and e.code in (protocol.CLOSE_POLICY, protocol.CLOSE_TOO_BIG)
        return
    assert m.seq == 1


values = st.recursive(
    st.none() | st.booleans() | st.integers(-2 ** 63, 2 ** 64 - 1) | st.floats() | st.text(max_size=10)
    | st.binary(max_size=5),
    lambda inner: st.lists(inner, max_size=4) | st.dictionaries(st.text(max_size=6), inner, max_size=5),
    max_leaves=15)
packed_messages = st.fixed_dictionaries(
    {"type": st.sampled_from(["ping", "key", "point", "hello"]), "seq": st.integers(0, 2)},
    optional={"id": values, "c": values, "body": values, "key": values, "down": values,
              "x": values, "y": values})


@settings(max_examples=300, deadline=None)
@given(packed_messages)
def test_parse_packed_values(value):
    """What the checks promise holds for every value that passes (the same checks as JSON's)."""
    try:
        m = protocol.parse(msgpack.packb(value), 1, "msgpack")
    except ProtocolError:
        return
    assert m.seq == 1 and not isinstance(m, protocol.Hello)
    if isinstance(m, protocol.Key):
        assert type(m.body) is int and m.key in protocol.KEYS and type(m.down) is bool
    if isinstance(m, (protocol.Point,)):
        assert all(isinstance(v, float) and math.isfinite(v) for v in (m.x, m.y))
    if isinstance(m, protocol.Ping):
        assert type(m.id) is int and math.isfinite(m.c)
