"""`max2code serve SCENE_OR_GAME`: a scene's world (or a PGE game's), authoritative on this machine, played from browsers.

    max2code serve examples/scenes/arena.toml            # then open http://127.0.0.1:8036/
    max2code serve SCENE_OR_GAME [--host 127.0.0.1] [--port 8036] [--player NAME ...] [--rooms N] [--workers N] [--speed V] [--tolerance EPS] [--rate HZ] [--lookahead TICKS]

Each browser that joins a room (the page's ?room=NAME, default "main") gets the world and then
only events (docs/server.md). A joining client controls the first player body nobody else
controls: --player names them (default: the scene's bodies named player...); the others watch.
The server binds to loopback unless --host says otherwise. A GAME.py is a PGE program
(server/pgegame.py): its objects are the bodies, its handlers get the keys.
"""

from __future__ import annotations

import argparse
import asyncio
import contextlib
import io
import signal
import sys


def _game(path: str, player: list[str]):
    """A PGE program: run once here to check it builds (its error as GAME.py:line:col and exit
    1 if not), then again for each room. Players: --player names its objects (box-3,
    circle-31), default its dynamic ones; their keys go to the game's handlers."""
    import os

    from ..engine.scenefile import Scene
    from ..pge.command import game_error
    from ..server.pgegame import UNIT_VIEW, GameWorld, load as load_game

    if not os.path.isfile(path):
        print(f"{path}:1:1: error: no such game file", file=sys.stderr)
        return 1
    try:
        first = GameWorld(load_game(path))
    except Exception as exc:   # the game's own failure, located in its file
        print(game_error(path, exc), file=sys.stderr)
        return 1
    names = {b.name: b.id for b in first.bodies}
    wanted = player or [b.name for b in first.bodies if b.kind == "dynamic"]
    bad = [n for n in wanted if n not in names]
    if bad:
        print(f"{path}: error: --player {bad[0]!r}: no object of that name", file=sys.stderr)
        return 1
    scene = Scene(name=os.path.basename(path), bodies=(), view=UNIT_VIEW)
    return scene, tuple(names[n] for n in wanted), lambda: GameWorld(load_game(path)), wanted


def _parser() -> argparse.ArgumentParser:
    from ..server.ahead import LOOKAHEAD

    ap = argparse.ArgumentParser(prog="max2code serve", description=__doc__.split("\n\n")[0])
    ap.add_argument("scene", metavar="SCENE_OR_GAME",
                    help="a scene file (.toml or .json), or a PGE program (GAME.py)")
    ap.add_argument("--host", default="127.0.0.1",
                    help="address to listen on (default 127.0.0.1: this machine only)")
    ap.add_argument("--port", type=int, default=8036, help="TCP port (default 8036; 0: any free)")
    ap.add_argument("--player", action="append", default=[], metavar="NAME",
                    help="a body clients may control (repeat; default: bodies named player*)")
    ap.add_argument("--rooms", type=int, default=16, metavar="N",
                    help="most rooms at once in each process (default 16)")
    ap.add_argument("--workers", type=int, metavar="N",
                    help="worker processes, each running the rooms whose names hash to it "
                         "(default: one per core; 1: one process, no front)")
    ap.add_argument("--speed", type=float, metavar="V",
                    help="input speed in scene units per second (default: a quarter of the view's width)")
    ap.add_argument("--tolerance", type=float, metavar="EPS",
                    help="a change whose drift stays below EPS scene units is sent when it would "
                         "exceed it (dead reckoning; docs/server.md); default 0: every change at "
                         "once, exact; -1: a quarter of a pixel of the page's canvas")
    ap.add_argument("--rate", type=float, default=60.0, metavar="HZ",
                    help="most event messages a second per room (default 60: changes within 1/60 s "
                         "of the last message wait for the next, each body's latest segment only); "
                         "0: every step's changes at once")
    ap.add_argument("--lookahead", type=int, default=LOOKAHEAD, metavar="TICKS",
                    help="contact solver ticks a copy of each room's world runs ahead, to fit "
                         f"held bodies' segments to (default {LOOKAHEAD}: fewer bytes for about twice the "
                         "engine's CPU; 0: no copy; never for a PGE game)")
    return ap


def _options(args):
    """The server's Options from the command line, with the scene's name and the players'
    names; or an exit code (the error printed)."""
    from ..engine.scenefile import SceneError, load
    from ..server.app import Options

    tolerance = None if args.tolerance == -1 else (args.tolerance or 0.0)
    if args.scene.endswith(".py"):   # a PGE program (docs/server.md, "Serving a PGE game")
        made = _game(args.scene, args.player)
        if isinstance(made, int):
            return made
        scene, players, make, wanted = made
        return Options(scene, players, max_rooms=args.rooms, tolerance=tolerance, world=make,
                       rate=args.rate, lookahead=args.lookahead), scene.name, wanted
    try:
        scene = load(args.scene)
    except SceneError as exc:
        for d in exc.diagnostics:
            print(d, file=sys.stderr)
        return 1
    names = {b.name: i for i, b in enumerate(scene.bodies)}
    wanted = args.player or [b.name for b in scene.bodies
                             if b.name.startswith("player") and b.kind == "dynamic"]
    bad = [n for n in wanted if n not in names or scene.bodies[names[n]].kind != "dynamic"]
    if bad:
        print(f"{args.scene}: error: --player {bad[0]!r}: no dynamic body of that name", file=sys.stderr)
        return 1
    return Options(scene, tuple(names[n] for n in wanted), max_rooms=args.rooms, speed=args.speed,
                   tolerance=tolerance, rate=args.rate, lookahead=args.lookahead), scene.name, wanted


async def _until_signal(coro) -> int:
    """Run coro until SIGTERM, SIGINT or SIGHUP (then 128 + the signal), with asyncio's own
    signal handlers: the CLI's raise an exception in whatever runs when the signal comes,
    which inside a task only ends that task (the server went on)."""
    loop, task, got = asyncio.get_running_loop(), asyncio.current_task(), []
    for sig in (signal.SIGTERM, signal.SIGINT, signal.SIGHUP):
        loop.add_signal_handler(sig, lambda s=sig: (got.append(s), task.cancel()))
    try:
        await coro
    except asyncio.CancelledError:
        if not got:
            raise
    return 128 + got[0] if got else 0


def _worker(index: int, count: int, channel, argv: list[str]) -> None:
    """A worker process (spawned by the front, server/workers.py): the same options, its
    share of the rooms."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)   # (before anything slow: the front coordinates)
    from ..server.app import run_worker

    with contextlib.redirect_stderr(io.StringIO()):   # (a bad scene: the front says so, once)
        made = _options(_parser().parse_args(argv))
    if isinstance(made, int):
        sys.exit(made)
    asyncio.run(run_worker(made[0], index, count, channel))


def main(argv: list[str]) -> int:
    args = _parser().parse_args(argv)
    from ..server import workers as cluster

    count = cluster.cores() if args.workers is None else args.workers
    if not 0 <= args.port <= 65535 or args.rooms < 1 or (args.speed is not None and not 0 < args.speed < 1e300) \
            or (args.tolerance is not None and args.tolerance != -1 and not 0 <= args.tolerance < 1e300) \
            or not 0 <= args.rate < 1e300 or not 0 <= args.lookahead <= 2400 or not 1 <= count <= 256:
        print("max2code serve: error: --port must be 0..65535, --rooms at least 1, --speed positive, "
              "--tolerance finite and >= 0 (or -1), --rate finite and >= 0, --lookahead 0..2400, "
              "--workers 1..256",
              file=sys.stderr)
        return 2
    if count == 1:
        made = _options(args)
        if isinstance(made, int):
            return made
    else:
        try:
            listener = cluster.listen(args.host, args.port)
        except OSError as exc:
            return _cannot_listen(args, exc)
        # the workers first: a PGE program, loaded below to check it, runs as __main__ in a
        # thread of its own, and a process spawned then would load it as its own main module
        workers = cluster.start_workers(count, _worker, (argv,))
        try:
            made = _options(args)
            if isinstance(made, int):
                return made
            cluster.wait_ready(workers)
            _say(args, made, f"on {count} worker processes", listener.getsockname()[1])
            return asyncio.run(_until_signal(cluster.front(listener, workers)))
        except RuntimeError as exc:
            print(f"max2code serve: error: {exc}", file=sys.stderr)
            return 1
        finally:
            listener.close()
            cluster.stop_workers(workers)
    from ..server.app import run

    try:
        return asyncio.run(_until_signal(run(made[0], args.host, args.port,
                                             lambda server, port: _say(args, made, "in one process", port))))
    except OSError as exc:
        return _cannot_listen(args, exc)


def _say(args, made, how: str, port: int) -> None:
    _, name, wanted = made
    print(f"max2code serve: {name} on http://{args.host}:{port}/ "
          f"(players: {', '.join(wanted) or 'none'}) {how}", file=sys.stderr, flush=True)


def _cannot_listen(args, exc: OSError) -> int:
    print(f"max2code serve: error: cannot listen on {args.host}:{args.port}: {exc.strerror or exc}",
          file=sys.stderr)
    return 1
