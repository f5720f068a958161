"""`max2code pge GAME.py`: run a PGE game, unmodified, on the predictive engine.

    max2code pge GAME.py [--until T] [--headless] [--gif F | --mp4 F | --png-dir D]
                         [--input EVENTS.jsonl] [--events LOG.jsonl] [--fps F] [--size N]

The game's `import pge` gets max2code.pge. Live (the default) it plays in a pygame window, its
handlers getting keyboard and mouse events; --headless draws nothing on screen and takes its
input from --input, one JSON object a line: {"t": 1.5, "type": "MOUSEBUTTONDOWN", "pos":
[400, 300], "button": 1} or {"t": 2, "type": "KEYDOWN", "key": "K_LEFT"}, t in simulated
seconds. --events writes what happened (collisions, removals, timers, input; JSON lines), and
its input lines are a valid --input: a live game replays headless. Exit status: the game's own
(sys.exit), or 1 after `GAME.py:line:col: error: ...` when it failed (an unsupported call names
itself), and then no output file is touched.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import runpy
import sys
import time
import traceback

from ..diagnostics import Pos, error
from ..output import write_if_changed
from .game import INPUT_TYPES, GameOver, Options

DEFAULT_SIZE = 400
MAX_FRAMES = 100_000


def _located(pos: Pos, message: str) -> str:
    return str(error(pos, message).diagnostics[0])


def read_inputs(path: str) -> list[tuple[float, str, dict]]:
    """The scripted input, checked: (time, pygame type name, attributes) in file order; an event
    log's other lines (collisions, timers) are skipped, so a log replays."""
    import pygame

    out = []
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            if not line.strip():
                continue
            here = Pos(path, n, 1)
            try:
                rec = json.loads(line)
            except json.JSONDecodeError as exc:
                raise error(Pos(path, n, exc.colno), f"not JSON: {exc.msg}") from None
            if not isinstance(rec, dict):
                raise error(here, "expected an object {\"t\": ..., \"type\": ...}")
            if rec.get("kind", "input") != "input":
                continue
            t = rec.get("t")
            if isinstance(t, bool) or not isinstance(t, (int, float)) or not (0 <= t < math.inf):
                raise error(here, f"'t' must be a finite time >= 0, not {t!r}")
            kind = rec.get("type")
            if kind not in INPUT_TYPES:
                raise error(here, f"'type' must be one of {', '.join(INPUT_TYPES)}, not {kind!r}")
            attrs = {k: v for k, v in rec.items() if k not in ("t", "type", "kind")}
            key = attrs.get("key")
            if isinstance(key, str):
                if not key.startswith("K_") or not isinstance(getattr(pygame, key, None), int):
                    raise error(here, f"unknown key {key!r} (pygame's names: K_LEFT, K_SPACE, K_a, ...)")
                attrs["key"] = getattr(pygame, key)
            for name in ("pos", "rel"):
                v = attrs.get(name)
                if v is not None and not (isinstance(v, list) and len(v) == 2
                                          and all(isinstance(c, (int, float)) for c in v)):
                    raise error(here, f"'{name}' must be [x, y] in window pixels, not {v!r}")
            out.append((float(t), kind, attrs))
    return out


def game_error(path: str, exc: BaseException) -> str:
    """`GAME.py:line:col: error: ...` at the game's innermost line in the traceback."""
    where = Pos(path, 1, 1)
    real = os.path.realpath(path)
    for fs in traceback.extract_tb(exc.__traceback__):
        if os.path.realpath(fs.filename) == real:
            where = Pos(path, fs.lineno or 1, (fs.colno or 0) + 1)
    from .physics import PgeError
    text = str(exc) if isinstance(exc, PgeError) else f"{type(exc).__name__}: {exc}"
    return _located(where, text)


def _exit_code(exc: SystemExit) -> int:
    if exc.code is None:
        return 0
    if isinstance(exc.code, int):
        return exc.code
    print(exc.code, file=sys.stderr)
    return 1


def run_game(path: str, options: Options) -> tuple[int, object]:
    """Run the program at path with `import pge` resolving to max2code.pge; returns (exit status,
    the Game). Exceptions from the game propagate."""
    from .. import pge
    from .game import init_type_names

    game = pge._start(options)
    init_type_names()
    saved = sys.modules.get("pge"), sys.argv[:], sys.path[:]
    sys.modules["pge"] = pge
    sys.argv[:] = [path]
    sys.path.insert(0, os.path.dirname(os.path.abspath(path)))
    try:
        runpy.run_path(path, run_name="__main__")
        code = 0
    except GameOver as over:
        code = over.code
    except SystemExit as exc:
        code = _exit_code(exc)
    finally:
        if saved[0] is None:
            sys.modules.pop("pge", None)
        else:
            sys.modules["pge"] = saved[0]
        sys.argv[:], sys.path[:] = saved[1], saved[2]
    return code, game


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(prog="max2code pge", description=__doc__.split("\n\n")[0])
    ap.add_argument("game", metavar="GAME.py", help="a PGE program")
    ap.add_argument("--until", type=float, metavar="T", help="stop at simulated time T")
    ap.add_argument("--headless", action="store_true", help="no window; input from --input")
    out = ap.add_mutually_exclusive_group()
    out.add_argument("--gif", metavar="FILE", help="an animated GIF of the frames")
    out.add_argument("--mp4", metavar="FILE", help="an MP4 video of the frames")
    out.add_argument("--png-dir", metavar="DIR", help="one PNG per frame in DIR")
    ap.add_argument("--input", metavar="EVENTS.jsonl", help="scripted input (JSON lines)")
    ap.add_argument("--events", metavar="LOG.jsonl", help="write the event log (JSON lines)")
    ap.add_argument("--fps", type=float, metavar="F",
                    help="frames per simulated second (default: the game's pge.fps, else 100)")
    ap.add_argument("--size", type=int, default=DEFAULT_SIZE, metavar="N",
                    help=f"picture size in pixels, square as PGE's window (default {DEFAULT_SIZE})")
    args = ap.parse_args(argv)
    if args.until is not None and not (0 <= args.until < math.inf):
        ap.error("--until must be finite and >= 0")
    if args.fps is not None and not (0 < args.fps < math.inf):
        ap.error("--fps must be finite and > 0")
    if not 16 <= args.size <= 4096:
        ap.error("--size must be 16 to 4096 pixels")
    if not os.path.isfile(args.game):
        print(_located(Pos(args.game, 1, 1), "no such game file"), file=sys.stderr)
        return 1
    pictures = args.gif or args.mp4 or args.png_dir
    if args.headless:
        os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
        os.environ.setdefault("SDL_AUDIODRIVER", "dummy")
    os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
    try:
        import pygame  # noqa: F401  (PGE games import pygame.locals themselves)
    except ImportError:
        print("max2code pge: error: PGE games need pygame: pip install 'max2code[live]'",
              file=sys.stderr)
        return 1
    from ..diagnostics import Max2CodeError
    try:
        inputs = read_inputs(args.input) if args.input else []
    except Max2CodeError as exc:
        for d in exc.diagnostics:
            print(d, file=sys.stderr)
        return 1
    except OSError as exc:
        print(_located(Pos(args.input, 1, 1), f"cannot read: {exc.strerror}"), file=sys.stderr)
        return 1
    options = Options(headless=args.headless, until=args.until, fps=args.fps,
                      record=bool(pictures), inputs=inputs)
    start = time.perf_counter()
    try:
        code, game = run_game(args.game, options)
    except Exception as exc:  # the game's own failure, or a PGE call it got wrong
        print(game_error(args.game, exc), file=sys.stderr)
        return 1
    seconds = time.perf_counter() - start
    if pictures:
        rc = _pictures(args, game)
        if rc:
            return rc
    if args.events:
        write_if_changed(args.events, "".join(json.dumps(r, separators=(",", ":")) + "\n"
                                              for r in game.log))
    removed = sum(1 for r in game.log if r["kind"] == "rm")
    collisions = sum(1 for r in game.log if r["kind"] == "collision")
    print(f"max2code pge: {args.game}: {game.now:g} s simulated in {seconds:.3f} s, "
          f"{game.frame_no} frames, {collisions} collisions, {removed} objects removed, "
          f"exit status {code}", file=sys.stderr)
    return code


def _pictures(args, game) -> int:
    from ..diagnostics import Max2CodeError
    from ..render import write
    from ..render.items import image

    size, window = args.size, game.resolution or args.size
    draw = lambda frame: image(frame, size, window)  # noqa: E731
    try:
        if args.gif:
            # (shown as PGE shows them: slow_down times slower than simulated time)
            write.gif_of(args.gif, game.frames, draw, game.fps / game.slow)
        elif args.mp4:
            write.mp4_of(args.mp4, game.frames, draw, game.fps / game.slow)
        else:
            write.png_dir_of(args.png_dir, game.frames, draw)
    except Max2CodeError as exc:
        for d in exc.diagnostics:
            print(d, file=sys.stderr)
        return 1
    except OSError as exc:
        print(f"{getattr(exc, 'filename', None) or 'max2code pge'}: error: cannot write output: "
              f"{exc.strerror or exc}", file=sys.stderr)
        return 1
    except (write.RenderModelError, write.RenderUnavailable) as exc:
        print(f"max2code pge: error: {exc}", file=sys.stderr)
        return 1
    return 0
