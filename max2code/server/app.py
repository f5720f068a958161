"""The server: rooms, the WebSocket endpoint (/ws) and the client page (/), on `websockets`.

One asyncio process: connections are handled as they come, every message is parsed and
checked (protocol.parse) before it reaches a room, and a connection that breaks the protocol
gets an error frame and is closed; the room and the other connections go on. A room is made
on the first join that names it, up to `max_rooms`.
"""

from __future__ import annotations

import asyncio
import socket
from dataclasses import dataclass
from typing import Callable
from importlib import resources
from urllib.parse import urlsplit

from websockets.asyncio.server import ServerConnection, serve
from websockets.datastructures import Headers
from websockets.exceptions import ConnectionClosed
from websockets.extensions.permessage_deflate import enable_server_permessage_deflate
from websockets.http11 import Request, Response
from websockets.server import ServerProtocol

from ..engine.scenefile import Scene
from ..engine.world import World
from . import protocol
from .protocol import Hello, Key, Ping, Point, ProtocolError, RateLimit
from .ahead import LOOKAHEAD
from .room import RATE as ROOM_RATE, Room
from . import workers as cluster

STATIC = {"/": ("index.html", "text/html; charset=utf-8"),
          "/client.js": ("client.js", "text/javascript; charset=utf-8"),
          "/style.css": ("style.css", "text/css; charset=utf-8")}
SECURITY_HEADERS = [("Content-Security-Policy", "default-src 'self'; connect-src 'self'; img-src 'self' data:"),
                    ("X-Content-Type-Options", "nosniff"), ("Cache-Control", "no-cache")]
HELLO_TIMEOUT = 10.0
# the WebSocket connections' settings (serve's, and an adopted connection's: run_worker)
MAX_QUEUE, CLOSE_TIMEOUT = 16, 1


@dataclass(frozen=True)
class Options:
    scene: Scene
    players: tuple[int, ...]
    max_rooms: int = 16
    max_clients: int = 256      # per room
    speed: float | None = None
    tolerance: float | None = 0.0    # 0: exact; None: a quarter pixel (room.AUTO_PIXELS)
    world: Callable[[], World] | None = None   # each room's world (a game's), else the scene's
    rate: float = ROOM_RATE     # most event messages a second per room (0: every step at once)
    lookahead: int = LOOKAHEAD  # solver ticks each room's copy of its world runs ahead (0: none)


class Server:
    """Rooms by name, and the connection handler. `shard` (index, count): this process runs
    the rooms workers.owner gives it (a worker of `max2code serve --workers`)."""

    def __init__(self, options: Options, shard: tuple[int, int] = (0, 1)) -> None:
        self.options = options
        self.shard = shard
        self.rooms: dict[str, Room] = {}
        self.files = {path: (resources.files(__package__).joinpath("static").joinpath(name).read_bytes(), kind)
                      for path, (name, kind) in STATIC.items()}

    def room(self, name: str) -> Room:
        room = self.rooms.get(name)
        if room is None:
            if len(self.rooms) >= self.options.max_rooms:
                raise ProtocolError(f"no room {name!r}, and no more rooms (at most {self.options.max_rooms})")
            make = self.options.world
            room = Room(name, self.options.scene, self.options.players, speed=self.options.speed,
                        tolerance=self.options.tolerance, world=make() if make else None,
                        rate=self.options.rate, lookahead=self.options.lookahead)
            room.start()
            self.rooms[name] = room
        return room

    async def close(self) -> None:
        for room in self.rooms.values():
            await room.stop()

    # -- HTTP: the page, and the origin check ------------------------------------------------

    def process_request(self, connection: ServerConnection, request: Request) -> Response | None:
        path = urlsplit(request.path).path
        if path == "/ws":
            origin = request.headers.get("Origin")
            host = request.headers.get("Host")
            if origin is not None and urlsplit(origin).netloc != host:
                return connection.respond(403, "cross-origin WebSocket refused\n")
            return None
        found = self.files.get(path)
        if found is None:
            return connection.respond(404, "not found\n")
        body, kind = found
        headers = Headers([("Content-Type", kind), ("Content-Length", str(len(body)))] + SECURITY_HEADERS)
        return Response(200, "OK", headers, body)

    # -- WebSocket ------------------------------------------------------------------------------

    async def handler(self, ws: ServerConnection) -> None:
        limit = RateLimit()
        loop = asyncio.get_running_loop()
        seq = 0
        room = client = None
        enc = "json"       # (hello is JSON text; after it, what hello asked for)
        try:
            try:
                first = await asyncio.wait_for(ws.recv(), HELLO_TIMEOUT)
            except asyncio.TimeoutError:
                raise ProtocolError("no hello within 10 s") from None
            msg = protocol.parse(first, seq)
            if not isinstance(msg, Hello):
                raise ProtocolError("the first message must be hello")
            seq += 1
            room = self.room(self._room_name(msg, ws))
            if len(room.clients) >= self.options.max_clients:
                raise ProtocolError(f"room {room.name!r} is full")
            client, world = room.join(_sender(ws), msg.name, msg.play, msg.events, msg.enc)
            enc = msg.enc
            await ws.send(world)
            async for frame in ws:
                if not limit.allow(loop.time()):
                    raise ProtocolError(f"more than {protocol.RATE:g} messages per second")
                msg = protocol.parse(frame, seq, enc)
                seq += 1
                reply = self._dispatch(room, client, msg)
                if reply is not None:
                    await ws.send(protocol.encode(reply, enc))
        except ProtocolError as exc:
            await _refuse(ws, exc, enc)
        except ConnectionClosed:
            pass
        finally:
            if room is not None and client is not None:
                room.leave(client)

    def _room_name(self, hello: Hello, ws: ServerConnection) -> str:
        """The room to join: hello's, else the URL's (/ws?room=NAME), else main. The two must
        agree, and a worker serves only its own rooms (the front routes by the URL's)."""
        url = cluster.room_of_path(ws.request.path) if ws.request else None
        if hello.room is not None and url is not None and hello.room != url:
            raise ProtocolError(f"hello's room {hello.room!r} is not the URL's ({url!r})")
        name = hello.room or url or "main"
        index, count = self.shard
        if cluster.owner(name, count) != index:
            raise ProtocolError(f"room {name!r} is served by another worker: connect to /ws?room={name}")
        return name

    def _dispatch(self, room: Room, client, msg) -> dict | None:
        """A checked message to its room; the message to answer with, if any."""
        if isinstance(msg, Ping):
            return {"type": "pong", "id": msg.id, "c": msg.c, "s": room.clock()}
        if isinstance(msg, Hello):
            raise ProtocolError("hello twice")
        if isinstance(msg, Key):
            why = room.key(client, msg.body, msg.key, msg.down)
        else:
            assert isinstance(msg, Point)
            why = room.point(client, msg.body, msg.x, msg.y)
        if why is None:
            return None
        return {"type": "refused", "seq": msg.seq, "reason": why}


def _sender(ws: ServerConnection):
    """A non-blocking send for the room's broadcasts: queued on the connection's transport
    (websockets.broadcast semantics), so a slow client never holds the world up."""
    from websockets.asyncio.server import broadcast

    return lambda frame: broadcast([ws], frame)


async def _refuse(ws: ServerConnection, exc: ProtocolError, enc: str) -> None:
    try:
        await ws.send(protocol.error(exc.reason, enc))
        await ws.close(exc.code, exc.reason[:120])
    except ConnectionClosed:
        pass


async def run(options: Options, host: str, port: int, ready=None) -> None:
    """Serve until cancelled; `ready(port)` is called once listening (port 0 picks one)."""
    server = Server(options)
    async with serve(server.handler, host, port, process_request=server.process_request,
                     max_size=protocol.HARD_MAX_MESSAGE, max_queue=MAX_QUEUE,
                     close_timeout=CLOSE_TIMEOUT) as ws_server:
        bound = ws_server.sockets[0].getsockname()[1]
        if ready is not None:
            ready(server, bound)
        try:
            await asyncio.Future()
        finally:
            await server.close()


async def run_worker(options: Options, index: int, count: int, channel: socket.socket) -> None:
    """One worker of `max2code serve --workers`: serve the connections the front hands over
    (workers.py) until the front closes the channel or SIGTERM comes."""
    server = Server(options, shard=(index, count))
    task = asyncio.current_task()
    cluster.worker_signals(task)
    # websockets' server on a socket nobody is told of (the front accepts): its handler runs
    # each adopted connection as if it had accepted it (handshake, keepalive, close). It
    # must be serving (else websockets answers 503); a Unix socket under an unused abstract
    # name, reachable only from this machine, as the TCP port on loopback is.
    placeholder = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    placeholder.bind("")        # (Linux: autobind to an unused abstract name)
    async with serve(server.handler, sock=placeholder, process_request=server.process_request,
                     max_size=protocol.HARD_MAX_MESSAGE, max_queue=MAX_QUEUE,
                     close_timeout=CLOSE_TIMEOUT) as ws_server:
        loop = asyncio.get_running_loop()

        def connection() -> ServerConnection:   # what serve() makes for each accepted socket
            proto = ServerProtocol(extensions=enable_server_permessage_deflate(None),
                                   max_size=protocol.HARD_MAX_MESSAGE)
            return ServerConnection(proto, ws_server, max_queue=MAX_QUEUE, close_timeout=CLOSE_TIMEOUT)

        def adopt(sock: socket.socket) -> None:
            sock.setblocking(False)
            loop.create_task(loop.connect_accepted_socket(connection, sock))

        adopter = cluster.Adopter(channel, adopt, task)
        adopter.ready()
        try:
            await asyncio.Future()
        except asyncio.CancelledError:
            pass
        finally:
            await server.close()
