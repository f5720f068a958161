"""A minimal protocol client for the tests and the bench: the page's logic (client.js) in
Python: join, keep every body's segment, evaluate poses."""

from __future__ import annotations

import asyncio
import json

import msgpack
from websockets.asyncio.client import connect

from max2code.server import protocol, wire


class Client:
    def __init__(self, ws) -> None:
        self.ws = ws
        self.seq = 0
        self.segs: dict[int, tuple[list, float]] = {}
        self.world: dict = {}
        self.bodies: dict[int, dict] = {}
        self.messages: list[dict] = []
        self.n = 0
        self.g: tuple = (0, 0)   # the world's gravity: what a `fall` segment accelerates at
        self.enc = "json"      # (hello is JSON; later frames as hello asked)
        self.frames: list[str | bytes] = []   # every frame received, as it came
        # every body's segment as it stood after message n: a page that holds n messages is
        # compared with what the server said up to n, not with a message it has yet to get
        self.history: dict[int, dict[int, tuple[list, float]]] = {}

    def decode(self, frame: str | bytes) -> dict:
        """A server frame: JSON text, or MessagePack binary on a connection that asked for it
        (a frame of the other kind is a failure)."""
        self.frames.append(frame)
        if self.enc == "msgpack":
            assert isinstance(frame, bytes), frame
            return msgpack.unpackb(frame, raw=False)
        assert isinstance(frame, str), frame
        return json.loads(frame)

    @classmethod
    async def join(cls, url: str, room: str = "main", play: bool = True, events: bool = True,
                   enc: str | None = None, **kw) -> "Client":
        ws = await connect(f"{url}?room={room}", **kw)   # (the front routes by the URL's room)
        c = cls(ws)
        hello = {"type": "hello", "v": protocol.VERSION, "room": room, "play": play}
        if not events:
            hello["events"] = False
        if enc is not None:
            hello["enc"] = enc
        await c.send(hello)
        c.enc = enc or "json"
        c.start(c.decode(await ws.recv()))
        return c

    def start(self, world: dict) -> None:
        """Hold the world message's bodies and segments (what join does with it)."""
        assert world["type"] == "world", world
        self.world = world
        self.n = world["n"]
        self.bodies = {b["id"]: b for b in world["bodies"]}
        self.g = tuple(world.get("g", (0, 0)))
        self.segs = {seg[0]: (seg, world["t"]) for seg in wire.expanded(world, self.g)}
        self.history[self.n] = dict(self.segs)

    @classmethod
    def fed(cls, text: str) -> "Client":
        """A client fed in-process (no socket), from a world message's JSON text."""
        c = cls(None)
        c.start(json.loads(text))
        return c

    async def send(self, message: dict) -> None:
        message = {**message, "seq": self.seq}
        await self.ws.send(msgpack.packb(message) if self.enc == "msgpack" else json.dumps(message))
        self.seq += 1

    def apply(self, m: dict) -> None:
        self.messages.append(m)
        if m["type"] == "ev":
            assert m["n"] == self.n + 1, (m["n"], self.n)
            self.n = m["n"]
            for i in m.get("rm", []):     # as client.js: removals, then additions, then segments
                del self.bodies[i], self.segs[i]
            for b in m.get("add", []):
                self.bodies[b["id"]] = b
            for seg in wire.expanded(m, self.g):
                self.segs[seg[0]] = (seg, m["t"])
            self.history[self.n] = dict(self.segs)

    async def receive(self, seconds: float) -> list[dict]:
        """Every message within `seconds`, applied."""
        out = []
        loop = asyncio.get_running_loop()
        end = loop.time() + seconds
        while (left := end - loop.time()) > 0:
            try:
                text = await asyncio.wait_for(self.ws.recv(), left)
            except asyncio.TimeoutError:
                break
            m = self.decode(text)
            self.apply(m)
            out.append(m)
        return out

    async def until(self, predicate, seconds: float = 5.0) -> dict:
        loop = asyncio.get_running_loop()
        end = loop.time() + seconds
        while (left := end - loop.time()) > 0:
            m = self.decode(await asyncio.wait_for(self.ws.recv(), left))
            self.apply(m)
            if predicate(m):
                return m
        raise AssertionError("no such message")

    def pose(self, body: int, t: float, n: int | None = None) -> tuple[float, float, float]:
        """The body's pose at time t, from the segments held after message n (default: now)."""
        seg, t0 = (self.segs if n is None else self.history[n])[body]
        return wire.pose(seg, t, t0)
