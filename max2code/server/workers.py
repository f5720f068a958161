"""Rooms over worker processes, one per core: a front process hands each connection to the
worker that owns its room.

The pattern is Node.js cluster's round-robin mode and socket.io's sticky sessions: the front
process alone listens; it accepts a connection, peeks at its HTTP request line (MSG_PEEK: the
bytes stay in the kernel for the worker to read), picks the worker that owns the room the path
names (`/ws?room=NAME`, `/?room=NAME`; any other path: the room `main`) and passes the
connected socket to it over a Unix socket (SCM_RIGHTS, the standard library's socket.send_fds).
The worker adopts it (asyncio's connect_accepted_socket) as a WebSocket or HTTP connection of
its own; from then on the front never sees its bytes. Each worker is a process of its own
(multiprocessing, spawned: a fresh interpreter with its own engine and asyncio loop) and runs
the rooms whose names hash to it (`owner`: CRC-32, stable across processes and runs, unlike
Python's salted hash()).

Stopping: SIGINT, SIGTERM or SIGHUP to the front closes the listening socket and the channels;
a worker reads the end of its channel and stops (its rooms with it), and the front waits for
each, then terminates and finally kills what is left. Workers ignore SIGINT (a terminal's ^C
reaches the whole process group: the front coordinates) and stop on SIGTERM or when the front
dies (the channel's end). A worker that dies stops the whole server (exit 1): its rooms would
otherwise be unreachable.
"""

from __future__ import annotations

import asyncio
import multiprocessing
import os
import signal
import socket
import zlib
from dataclasses import dataclass
from typing import Callable
from urllib.parse import parse_qs, urlsplit

from . import protocol

PEEK_BYTES = 2048      # the request line must fit (the path is at most a few hundred bytes)
PEEK_TIMEOUT = 5.0     # seconds a client has to send its request line
STOP_WAIT = 5.0        # seconds a worker has to stop before it is terminated, then killed
READY_WAIT = 120.0     # seconds a worker has to start (its engine may be built first)
READY, ADOPT = b"r", b"c"


def owner(room: str, workers: int) -> int:
    """The worker (0..workers-1) that runs `room`: CRC-32 of its name, modulo the count."""
    return zlib.crc32(room.encode()) % workers


def cores() -> int:
    """The cores this process may run on (the default worker count)."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:   # (not Linux)
        return max(1, os.cpu_count() or 1)


def room_of_path(path: str) -> str | None:
    """The room a request's path names (`?room=NAME`, checked as hello's room is), else None."""
    names = parse_qs(urlsplit(path).query).get("room")
    if not names or not protocol.ROOM.fullmatch(names[0]):
        return None
    return names[0]


def room_of_head(head: bytes) -> str:
    """The room a peeked request names in its request line (`GET PATH HTTP/1.1`), else main."""
    line = head.split(b"\r\n", 1)[0].decode("latin-1")
    parts = line.split(" ")
    return (room_of_path(parts[1]) if len(parts) == 3 else None) or "main"


# -- the front process ----------------------------------------------------------------------


@dataclass(frozen=True)
class Worker:
    process: multiprocessing.Process
    channel: socket.socket       # the front's end (SOCK_SEQPACKET: one message per hand-off)


def start_workers(count: int, target: Callable, args: tuple) -> list[Worker]:
    """`count` spawned processes running target(index, count, channel, *args)."""
    ctx = multiprocessing.get_context("spawn")
    workers = []
    for index in range(count):
        mine, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_SEQPACKET)
        p = ctx.Process(target=target, args=(index, count, theirs, *args), daemon=False,
                        name=f"max2code-serve-worker-{index}")
        p.start()
        theirs.close()
        workers.append(Worker(p, mine))
    return workers


def wait_ready(workers: list[Worker], timeout: float = READY_WAIT) -> None:
    """Block until every worker said it serves (its READY byte), or raise RuntimeError."""
    for w in workers:
        w.channel.settimeout(timeout)
        try:
            got = w.channel.recv(16)
        except socket.timeout:
            got = b""
        if got != READY:
            raise RuntimeError(f"worker {w.process.name} did not start (exit code {w.process.exitcode})")
        w.channel.setblocking(False)


def stop_workers(workers: list[Worker]) -> None:
    """Close the channels (each worker stops on their end), wait, terminate, kill."""
    for w in workers:
        w.channel.close()
    for w in workers:
        w.process.join(STOP_WAIT)
        if w.process.is_alive():
            w.process.terminate()
            w.process.join(STOP_WAIT)
        if w.process.is_alive():
            w.process.kill()
            w.process.join()


async def _socket_ready(loop: asyncio.AbstractEventLoop, sock: socket.socket, writing: bool = False) -> None:
    """Until sock is readable (or writable): the loop's own watch on a non-blocking socket."""
    add, remove = (loop.add_writer, loop.remove_writer) if writing else (loop.add_reader, loop.remove_reader)
    fut = loop.create_future()
    add(sock, lambda: fut.done() or fut.set_result(None))
    try:
        await fut
    finally:
        remove(sock)


async def _peek_head(loop: asyncio.AbstractEventLoop, conn: socket.socket) -> bytes | None:
    """The start of the request (up to its first line), left unread; None if it never came."""
    end = loop.time() + PEEK_TIMEOUT
    while loop.time() < end:
        try:
            head = conn.recv(PEEK_BYTES, socket.MSG_PEEK)
        except BlockingIOError:
            try:
                await asyncio.wait_for(_socket_ready(loop, conn), end - loop.time())
            except asyncio.TimeoutError:
                return None
            continue
        except OSError:
            return None
        if not head:
            return None                      # closed before a request
        if b"\r\n" in head or len(head) >= PEEK_BYTES:
            return head
        await asyncio.sleep(0.01)            # a partial line: readable stays true while peeking
    return None


async def _send_fd(loop: asyncio.AbstractEventLoop, channel: socket.socket, fd: int) -> None:
    while True:
        try:
            socket.send_fds(channel, [ADOPT], [fd])
            return
        except BlockingIOError:
            await _socket_ready(loop, channel, writing=True)


async def _hand_off(loop: asyncio.AbstractEventLoop, conn: socket.socket, workers: list[Worker]) -> None:
    try:
        head = await _peek_head(loop, conn)
        if head is not None:
            w = workers[owner(room_of_head(head), len(workers))]
            await _send_fd(loop, w.channel, conn.fileno())
    except OSError:
        pass       # a worker gone: the server is stopping (front() notices its exit)
    finally:
        conn.close()   # (the worker holds its own descriptor of the connection now)


async def front(listener: socket.socket, workers: list[Worker]) -> None:
    """Accept connections and hand each to its room's worker, until cancelled or until a
    worker exits (then RuntimeError)."""
    loop = asyncio.get_running_loop()
    listener.setblocking(False)
    died = loop.create_future()
    for w in workers:
        loop.add_reader(w.process.sentinel, lambda w=w: died.done() or died.set_result(w))
    tasks: set[asyncio.Task] = set()

    async def accept() -> None:
        while True:
            conn, _ = await loop.sock_accept(listener)
            conn.setblocking(False)
            task = loop.create_task(_hand_off(loop, conn, workers))
            tasks.add(task)
            task.add_done_callback(tasks.discard)

    acceptor = loop.create_task(accept())
    try:
        await asyncio.wait([acceptor, died], return_when=asyncio.FIRST_COMPLETED)
        if died.done():
            w = died.result()
            raise RuntimeError(f"worker {w.process.name} exited (code {w.process.exitcode})")
        acceptor.result()
    finally:
        acceptor.cancel()
        for task in list(tasks):
            task.cancel()
        for w in workers:
            loop.remove_reader(w.process.sentinel)


# -- a worker process -----------------------------------------------------------------------


class Adopter:
    """A worker's end of its channel: connections the front hands over, adopted into `adopt`;
    the channel's end (the front stopped or died) cancels `task`."""

    def __init__(self, channel: socket.socket, adopt: Callable[[socket.socket], None],
                 task: asyncio.Task) -> None:
        self.channel, self.adopt, self.task = channel, adopt, task
        channel.setblocking(False)
        self.loop = asyncio.get_running_loop()
        self.loop.add_reader(channel, self._ready)

    def _ready(self) -> None:
        while True:
            try:
                msg, fds, _, _ = socket.recv_fds(self.channel, 16, 16)
            except BlockingIOError:
                return
            except OSError:
                msg, fds = b"", []
            if not msg:
                self.loop.remove_reader(self.channel)
                self.task.cancel()
                return
            for fd in fds:
                self.adopt(socket.socket(fileno=fd))

    def ready(self) -> None:
        self.channel.send(READY)


def worker_signals(task: asyncio.Task) -> None:
    """A worker ignores SIGINT (the front coordinates) and stops its loop on SIGTERM."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    asyncio.get_running_loop().add_signal_handler(signal.SIGTERM, task.cancel)


def listen(host: str, port: int) -> socket.socket:
    """The front's listening socket (as asyncio's create_server makes one: SO_REUSEADDR)."""
    return socket.create_server((host, port), reuse_port=False, backlog=1024,
                                family=socket.AF_INET6 if ":" in host else socket.AF_INET)
