"""A real server on 127.0.0.1, port 0, in a thread of its own (its own asyncio loop), so that
tests (plain pytest, or Playwright's synchronous API) talk to it over real sockets."""

from __future__ import annotations

import asyncio
import threading
from pathlib import Path

import pytest

from max2code.engine.scenefile import load
from max2code.server.app import Options, run

ROOT = Path(__file__).resolve().parents[2]
ARENA = ROOT / "examples" / "scenes" / "arena.toml"


class Running:
    """A server running in a background thread: `port`, `server` (rooms), and `call(f)` to
    run f() on the server's loop (rooms belong to that thread) and get its result."""

    def __init__(self, options: Options) -> None:
        # the engine's library first, here: when it must be (re)built (its cache key covers
        # max2code's own sources), a build inside the server's loop outlasts the clients'
        # 20 s keepalive on a loaded machine
        from max2code.engine.binding import load as load_engine

        load_engine()
        self.options = options
        self.loop = asyncio.new_event_loop()
        self.ready = threading.Event()
        self.server = None
        self.port = 0
        self.thread = threading.Thread(target=self._main, daemon=True)
        self.thread.start()
        if not self.ready.wait(60):
            raise RuntimeError("the server did not start")

    def _main(self) -> None:
        asyncio.set_event_loop(self.loop)

        def ready(server, port):
            self.server, self.port = server, port
            self.ready.set()

        self.task = self.loop.create_task(run(self.options, "127.0.0.1", 0, ready))
        try:
            self.loop.run_until_complete(self.task)
        except asyncio.CancelledError:
            pass

    def call(self, f):
        async def wrapped():
            return f()
        return asyncio.run_coroutine_threadsafe(wrapped(), self.loop).result(30)

    def stop(self) -> None:
        self.loop.call_soon_threadsafe(self.task.cancel)
        self.thread.join(30)

    @property
    def url(self) -> str:
        return f"ws://127.0.0.1:{self.port}/ws"


def start(scene_path, players=None, **kw) -> Running:
    scene = load(scene_path)
    if players is None:
        players = tuple(i for i, b in enumerate(scene.bodies) if b.name.startswith("player"))
    kw.setdefault("tolerance", 0.0)   # exact unless a test asks: the replays compare bit for bit
    return Running(Options(scene, players, **kw))


@pytest.fixture
def arena():
    running = start(ARENA)
    yield running
    running.stop()
